// Loading convex shapes from data/shapes/.
//
// Blaze shape format (.shape), '#' starts a comment, units m:
//   name <word>
//   vertices <V>          then V lines "x y z"
//   faces <F>             then F lines "k i_1 ... i_k" (0-based vertex indices, counter-clockwise
//                         seen from outside; clockwise faces are reversed and reported)
// Wavefront OBJ (.obj): "v x y z" and "f i j k ..." lines (1-based; "i/t/n" forms accepted);
// other statements are ignored. Errors name the file and line; geometric defects are reported by
// make_convex_shape() with the file name.
#pragma once
#include <fstream>
#include <sstream>
#include "blaze/shapes/convex_shape.hpp"

namespace blaze {

namespace shape_detail {

inline std::string strip_comment(std::string line) {
  const auto hash = line.find('#');
  if (hash != std::string::npos) line.erase(hash);
  return line;
}

inline std::string stem(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string s = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = s.find_last_of('.');
  return dot == std::string::npos ? s : s.substr(0, dot);
}

}  // namespace shape_detail

inline ConvexShape parse_blaze_shape(std::istream& in, const std::string& source) {
  using shape_detail::strip_comment;
  std::string name = shape_detail::stem(source), line;
  std::vector<Eigen::Vector3d> v;
  std::vector<std::vector<int>> faces;
  int number = 0;
  auto fail = [&](const std::string& what) { throw ShapeError(source + ":" + std::to_string(number) + ": " + what); };
  auto next_data_line = [&](std::istringstream& s) {
    while (std::getline(in, line)) {
      ++number;
      line = strip_comment(line);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      s.clear();  // reuse the stream (a move-assignment trips GCC 12's -Wstringop-overflow under ASan)
      s.str(line);
      return true;
    }
    return false;
  };
  std::istringstream s;
  bool have_vertices = false, have_faces = false;
  while (next_data_line(s)) {
    std::string key;
    s >> key;
    if (key == "name") {
      if (!(s >> name)) fail("'name' needs a word");
    } else if (key == "vertices" || key == "faces") {
      long count;
      if (!(s >> count) || count < 0) fail("'" + key + "' needs a non-negative count");
      const long cap = key == "vertices" ? kMaxVertices : kMaxFaces;
      if (count > cap) fail(std::to_string(count) + " " + key + ": more than the cap of " + std::to_string(cap));
      for (long k = 0; k < count; ++k) {
        if (!next_data_line(s)) fail("file ends after " + std::to_string(k) + " of " + std::to_string(count) + " " + key);
        if (key == "vertices") {
          Eigen::Vector3d p;
          std::string rest;
          if (!(s >> p.x() >> p.y() >> p.z()) || (s >> rest)) fail("expected a vertex 'x y z'");
          v.push_back(p);
        } else {
          int k_verts;
          if (!(s >> k_verts) || k_verts < 3) fail("expected a face 'k i_1 ... i_k' with k >= 3");
          std::vector<int> f(k_verts);
          for (int& i : f)
            if (!(s >> i)) fail("face lists fewer than its " + std::to_string(k_verts) + " vertices");
          std::string rest;
          if (s >> rest) fail("face lists more than its " + std::to_string(k_verts) + " vertices");
          faces.push_back(f);
        }
      }
      (key == "vertices" ? have_vertices : have_faces) = true;
    } else {
      fail("unknown keyword '" + key + "' (allowed: name, vertices, faces)");
    }
  }
  if (!have_vertices || !have_faces) throw ShapeError(source + ": needs both a 'vertices' and a 'faces' block");
  return make_convex_shape(name, v, faces, source);
}

inline ConvexShape parse_obj(std::istream& in, const std::string& source) {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::vector<int>> faces;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream s(shape_detail::strip_comment(line));
    std::string key;
    if (!(s >> key)) continue;
    auto fail = [&](const std::string& what) { throw ShapeError(source + ":" + std::to_string(number) + ": " + what); };
    if (key == "v") {
      Eigen::Vector3d p;
      if (!(s >> p.x() >> p.y() >> p.z())) fail("expected 'v x y z'");
      v.push_back(p);
    } else if (key == "f") {
      std::vector<int> f;
      for (std::string tok; s >> tok;) {
        const int i = std::atoi(tok.substr(0, tok.find('/')).c_str());
        if (i == 0) fail("bad vertex reference '" + tok + "'");
        f.push_back(i > 0 ? i - 1 : static_cast<int>(v.size()) + i);  // negative: relative
      }
      if (f.size() < 3) fail("a face needs at least 3 vertices");
      faces.push_back(f);
    }
  }
  return make_convex_shape(shape_detail::stem(source), v, faces, source);
}

inline ConvexShape load_shape(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ShapeError(path + ": cannot open shape file");
  const bool obj = path.size() > 4 && path.compare(path.size() - 4, 4, ".obj") == 0;
  return obj ? parse_obj(in, path) : parse_blaze_shape(in, path);
}

// A shape file scaled so its bounding radius is `bounding_radius` (m).
inline ConvexShape load_scaled_shape(const std::string& path, double bounding_radius) {
  const ConvexShape s = load_shape(path);
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : s.vertices) v.push_back(p * (bounding_radius / s.bounding_radius));
  return make_convex_shape(s.name, v, s.faces, path + " (scaled)");
}

}  // namespace blaze
