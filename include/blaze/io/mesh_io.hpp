// Reading triangle meshes (issue 20): STL, ASCII and binary, and Wavefront OBJ, into a
// TriangleMesh (blaze/world/triangle_mesh.hpp), welded and repaired by load_mesh().
//   STL binary: an 80-byte header, a little-endian uint32 triangle count n, then n records of
//     50 bytes (normal, three vertices: 12 float32; a uint16 attribute). Recognised by its size,
//     84 + 50 n bytes, even when the header begins with "solid" (some exporters write that).
//   STL ASCII: "solid [name]", then per triangle "facet normal nx ny nz", "outer loop", three
//     "vertex x y z", "endloop", "endfacet"; "endsolid". The stored normals are ignored: the
//     vertex order decides the side (right-hand rule), as every CAD program writes it.
//   OBJ: "v x y z" and "f i j k ..." (1-based, negative: relative, "i/t/n" forms accepted);
//     a face of more than three vertices is split into a fan from its first vertex.
// Errors name the file and the line (ASCII) or the triangle (binary).
#pragma once
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>
#include "blaze/world/triangle_mesh.hpp"

namespace blaze {

namespace mesh_io_detail {

inline bool ends_with(const std::string& s, const char* suffix) {
  const std::size_t n = std::strlen(suffix);
  if (s.size() < n) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - n + k])) != suffix[k]) return false;
  return true;
}

inline float read_float(const unsigned char* p) {
  std::uint32_t u = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                    static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

inline std::uint32_t binary_count(const std::string& bytes) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 | static_cast<std::uint32_t>(p[2]) << 16 |
         static_cast<std::uint32_t>(p[3]) << 24;
}

}  // namespace mesh_io_detail

inline bool is_binary_stl(const std::string& bytes) {
  return bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(mesh_io_detail::binary_count(bytes));
}

inline TriangleMesh parse_binary_stl(const std::string& bytes, const std::string& source) {
  using mesh_io_detail::read_float;
  if (!is_binary_stl(bytes))
    throw MeshError(source + ": not a binary STL (" + std::to_string(bytes.size()) + " bytes; a binary STL of n triangles has 84 + 50 n)");
  const std::uint32_t n = mesh_io_detail::binary_count(bytes);
  TriangleMesh m;
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + 84;
  for (std::uint32_t t = 0; t < n; ++t, p += 50) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const unsigned char* v = p + 12 + 12 * k;
      const Vec3<double> x{read_float(v), read_float(v + 4), read_float(v + 8)};
      if (!(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)))
        throw MeshError(source + ": triangle " + std::to_string(t + 1) + ": vertex " + std::to_string(k + 1) + " is not finite");
      tri[static_cast<std::size_t>(k)] = static_cast<int>(m.vertices.size());
      m.vertices.push_back(x);
    }
    m.triangles.push_back(tri);
    m.file_index.push_back(static_cast<long>(t) + 1);
  }
  return m;
}

inline TriangleMesh parse_ascii_stl(std::istream& in, const std::string& source) {
  TriangleMesh m;
  std::string line;
  int in_facet = -1;  // vertices read in the current facet, -1 outside one
  bool solid = false, open = false;  // a solid seen; one begun and not ended (several may follow each other)
  long facets = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    std::istringstream s(line);
    std::string key;
    if (!(s >> key)) continue;
    const auto fail = [&](const std::string& what) { throw MeshError(source + ":" + std::to_string(number) + ": " + what); };
    if (key == "solid") {
      if (open) fail("'solid' inside a solid (missing 'endsolid')");
      solid = open = true;
    } else if (key == "facet") {
      if (!solid) fail("'facet' before 'solid'");
      if (!open) fail("'facet' after 'endsolid'");
      if (in_facet >= 0) fail("'facet' inside a facet (missing 'endfacet')");
      in_facet = 0;
      ++facets;
    } else if (key == "vertex") {
      if (in_facet < 0) fail("'vertex' outside a facet");
      if (in_facet == 3) fail("a fourth vertex in a facet (STL facets are triangles)");
      Vec3<double> x;
      if (!(s >> x.x >> x.y >> x.z) || !(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)))
        fail("expected 'vertex x y z' with three finite numbers");
      m.vertices.push_back(x);
      ++in_facet;
    } else if (key == "endfacet") {
      if (in_facet != 3) fail("a facet needs three vertices, got " + std::to_string(std::max(in_facet, 0)));
      const int b = static_cast<int>(m.vertices.size()) - 3;
      m.triangles.push_back({b, b + 1, b + 2});
      m.file_index.push_back(facets);
      in_facet = -1;
    } else if (key == "endsolid") {
      if (in_facet >= 0) fail("'endsolid' inside facet " + std::to_string(facets) + " (missing 'endfacet')");
      open = false;
    } else if (key == "outer" || key == "endloop") {
      continue;
    } else {
      fail("unexpected '" + key + "' (an ASCII STL has solid, facet, outer loop, vertex, endloop, endfacet, endsolid)");
    }
  }
  if (!solid) throw MeshError(source + ": neither a binary STL (84 + 50 n bytes) nor an ASCII one (starting with 'solid')");
  if (in_facet >= 0) throw MeshError(source + ": the file ends inside facet " + std::to_string(facets));
  // Every ASCII STL ends its solid with 'endsolid': a file without it was cut short, at a facet's
  // end by chance, and holds only part of the surface.
  if (open) throw MeshError(source + ": the file ends without 'endsolid' after " + std::to_string(facets) +
                            " facet" + (facets == 1 ? "" : "s") + ": it is truncated (an ASCII STL closes its solid with 'endsolid')");
  return m;
}

inline TriangleMesh parse_obj_mesh(std::istream& in, const std::string& source) {
  TriangleMesh m;
  std::string line;
  long faces = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream s(line);
    std::string key;
    if (!(s >> key)) continue;
    const auto fail = [&](const std::string& what) { throw MeshError(source + ":" + std::to_string(number) + ": " + what); };
    if (key == "v") {
      Vec3<double> x;
      if (!(s >> x.x >> x.y >> x.z) || !(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)))
        fail("expected 'v x y z' with three finite numbers");
      m.vertices.push_back(x);
    } else if (key == "f") {
      ++faces;
      std::vector<int> f;
      for (std::string tok; s >> tok;) {
        const std::string head = tok.substr(0, tok.find('/'));
        char* end = nullptr;
        const long i = std::strtol(head.c_str(), &end, 10);
        if (head.empty() || *end != '\0' || i == 0) fail("bad vertex reference '" + tok + "'");
        const long k = i > 0 ? i - 1 : static_cast<long>(m.vertices.size()) + i;
        if (k < 0 || k >= static_cast<long>(m.vertices.size()))
          fail("vertex reference '" + tok + "' outside the " + std::to_string(m.vertices.size()) + " vertices read so far");
        f.push_back(static_cast<int>(k));
      }
      if (f.size() < 3) fail("a face needs at least 3 vertices");
      for (std::size_t k = 1; k + 1 < f.size(); ++k) {
        m.triangles.push_back({f[0], f[k], f[k + 1]});
        m.file_index.push_back(faces);
      }
    }
  }
  return m;
}

// The file as it is (no welding or repair): by extension .stl (binary or ASCII by content) or .obj.
inline TriangleMesh read_mesh_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot open the mesh file");
  if (mesh_io_detail::ends_with(path, ".obj")) return parse_obj_mesh(in, path);
  if (!mesh_io_detail::ends_with(path, ".stl")) throw MeshError(path + ": a mesh file must be .stl (ASCII or binary) or .obj");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (is_binary_stl(bytes)) return parse_binary_stl(bytes, path);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || bytes.compare(first, 5, "solid") != 0) {
    // A binary STL's header count against its size: a file cut short (a failed copy) says so.
    std::string binary = "84 + 50 n bytes for n triangles; this file has " + std::to_string(bytes.size());
    if (bytes.size() >= 84) {
      const std::uint64_t n = mesh_io_detail::binary_count(bytes), want = 84 + 50 * n;
      binary += ", and its header announces " + std::to_string(n) + " triangles, " + std::to_string(want) + " bytes: " +
                (want > bytes.size() ? "truncated, or not an STL" : "bytes past the last triangle, or not an STL");
    }
    throw MeshError(path + ": neither a binary STL (" + binary + ") nor an ASCII one (starting with 'solid')");
  }
  std::istringstream text(bytes);
  return parse_ascii_stl(text, path);
}

// Read, welded and repaired (triangle_mesh.hpp); the report says what was changed.
inline TriangleMesh load_mesh(const std::string& path, MeshReport& report) {
  TriangleMesh m = read_mesh_file(path);
  if (m.triangles.empty()) throw MeshError(path + ": no triangles");
  weld(m, report);
  report = repair(m, path, report);
  return m;
}

// Writes a mesh as binary STL (tests, and meshes built in code for studies).
inline void write_binary_stl(const TriangleMesh& m, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw MeshError(path + ": cannot write");
  char header[80] = "binary STL written by Blaze";
  out.write(header, 80);
  const auto put32 = [&](std::uint32_t u) {
    const unsigned char b[4] = {static_cast<unsigned char>(u), static_cast<unsigned char>(u >> 8), static_cast<unsigned char>(u >> 16),
                                static_cast<unsigned char>(u >> 24)};
    out.write(reinterpret_cast<const char*>(b), 4);
  };
  const auto put_float = [&](double x) {
    const float f = static_cast<float>(x);
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    put32(u);
  };
  put32(static_cast<std::uint32_t>(m.size()));
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3<double> a = m.area_vector(t);
    const double len = norm(a);
    const Vec3<double> n = len > 0 ? a * (1 / len) : Vec3<double>{0, 0, 0};
    put_float(n.x), put_float(n.y), put_float(n.z);
    for (int k = 0; k < 3; ++k) {
      const Vec3<double> v = m.corner(t, k);
      put_float(v.x), put_float(v.y), put_float(v.z);
    }
    out.put(0), out.put(0);
  }
}

}  // namespace blaze
