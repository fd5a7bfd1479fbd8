// Triangle meshes as walls (issue 20): the host-side description a CAD file becomes, and its
// repair. A mesh is a vertex list and triangles of three vertex indices, counter-clockwise seen
// from the side its normal n = (b - a) x (c - a) / |.| points to.
//   weld:      STL repeats every vertex per triangle; vertices closer than a tolerance (1e-9 of the
//              mesh's size unless given) become one, so neighbours share edges.
//   repair:    drops degenerate triangles (two equal vertices, or an area below 1e-12 of the
//              mesh's size squared) and repeated ones (the same three vertices in any order),
//              then orients each connected piece consistently: across every edge shared by two
//              triangles they run the edge in opposite directions. Each piece keeps the
//              orientation most of its triangles had in the file (the fewest flips). An edge
//              used by one triangle is open (a wall need not be closed); by three or more,
//              non-manifold (a fin on a surface), allowed and counted; a piece that cannot be
//              oriented (a Moebius strip) is an error.
// Everything dropped or flipped is counted in a MeshReport that names the first few triangles
// by their number in the file (1-based), for the user's message.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct TriangleMesh {
  std::vector<Vec3<double>> vertices;       // m
  std::vector<std::array<int, 3>> triangles;
  std::vector<long> file_index;             // per triangle: its number in the file (1-based)

  std::size_t size() const { return triangles.size(); }
  Vec3<double> corner(std::size_t t, int k) const { return vertices[static_cast<std::size_t>(triangles[t][static_cast<std::size_t>(k)])]; }
  // (b - a) x (c - a): twice the area along the normal.
  Vec3<double> area_vector(std::size_t t) const { return cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0)); }
  // The largest extent of the vertices' bounding box (m).
  double extent() const {
    if (vertices.empty()) return 0;
    Vec3<double> lo = vertices[0], hi = vertices[0];
    for (const auto& v : vertices) {
      lo = {std::fmin(lo.x, v.x), std::fmin(lo.y, v.y), std::fmin(lo.z, v.z)};
      hi = {std::fmax(hi.x, v.x), std::fmax(hi.y, v.y), std::fmax(hi.z, v.z)};
    }
    return std::fmax(hi.x - lo.x, std::fmax(hi.y - lo.y, hi.z - lo.z));
  }
  // Signed volume enclosed (m^3; divergence theorem): positive for a closed mesh whose normals
  // point out.
  double signed_volume() const {
    double v = 0;
    for (std::size_t t = 0; t < size(); ++t) v += dot(corner(t, 0), cross(corner(t, 1), corner(t, 2)));
    return v / 6;
  }
};

struct MeshReport {
  long welded = 0;        // vertices merged into others
  long degenerate = 0;    // triangles dropped: two equal vertices or no area
  long duplicate = 0;     // triangles dropped: the same three vertices as an earlier one
  long flipped = 0;       // triangles turned to agree with their neighbours
  long open_edges = 0;    // edges of one triangle
  long non_manifold_edges = 0;  // edges of three or more triangles
  long pieces = 0;        // connected pieces (through shared edges)
  std::vector<long> degenerate_examples, duplicate_examples, flipped_examples;  // file numbers, the first few
  bool closed() const { return open_edges == 0 && non_manifold_edges == 0; }
  // One line for the run's notes ("" when there is nothing to say).
  std::string summary() const {
    std::string s;
    const auto add = [&](long n, const char* what, const std::vector<long>* ex) {
      if (n == 0) return;
      if (!s.empty()) s += "; ";
      s += std::to_string(n) + " " + what;
      if (ex && !ex->empty()) {
        s += " (triangle";
        s += ex->size() > 1 ? "s " : " ";
        for (std::size_t k = 0; k < ex->size(); ++k) s += (k ? ", " : "") + std::to_string((*ex)[k]);
        s += n > static_cast<long>(ex->size()) ? ", ...)" : ")";
      }
    };
    add(degenerate, "degenerate triangles dropped", &degenerate_examples);
    add(duplicate, "repeated triangles dropped", &duplicate_examples);
    add(flipped, "triangles flipped to agree with their neighbours", &flipped_examples);
    add(open_edges, "open edges", nullptr);
    add(non_manifold_edges, "edges shared by three or more triangles", nullptr);
    return s;
  }
};

namespace mesh_detail {
constexpr std::size_t kExamples = 5;
inline void example(std::vector<long>& ex, long file_index) {
  if (ex.size() < kExamples) ex.push_back(file_index);
}
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}
}  // namespace mesh_detail

// Merges vertices closer than `tolerance` (m; <= 0: 1e-9 of the extent), keeping the first.
inline void weld(TriangleMesh& m, MeshReport& report, double tolerance = 0) {
  if (m.vertices.empty()) return;
  const double tol = tolerance > 0 ? tolerance : 1e-9 * std::fmax(m.extent(), 1e-300);
  // Hash by cells of the tolerance: a match lies in the same or a neighbouring cell.
  const double inv = 1 / tol;
  const auto cell = [&](const Vec3<double>& v) {
    return std::array<long long, 3>{static_cast<long long>(std::floor(v.x * inv)), static_cast<long long>(std::floor(v.y * inv)),
                                    static_cast<long long>(std::floor(v.z * inv))};
  };
  std::map<std::array<long long, 3>, std::vector<int>> cells;
  std::vector<int> remap(m.vertices.size());
  std::vector<Vec3<double>> kept;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Vec3<double> v = m.vertices[i];
    const auto c = cell(v);
    int found = -1;
    for (long long dx = -1; dx <= 1 && found < 0; ++dx)
      for (long long dy = -1; dy <= 1 && found < 0; ++dy)
        for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (int k : it->second)
            if (norm(kept[static_cast<std::size_t>(k)] - v) <= tol) {
              found = k;
              break;
            }
        }
    if (found < 0) {
      found = static_cast<int>(kept.size());
      kept.push_back(v);
      cells[c].push_back(found);
    } else {
      ++report.welded;
    }
    remap[i] = found;
  }
  for (auto& t : m.triangles)
    for (int& k : t) k = remap[static_cast<std::size_t>(k)];
  m.vertices = std::move(kept);
}

// Drops degenerate and repeated triangles and orients every piece consistently (see the top).
// Throws MeshError naming `source` and a triangle when a piece cannot be oriented, or when no
// triangle is left.
inline MeshReport repair(TriangleMesh& m, const std::string& source, MeshReport report = {}) {
  using mesh_detail::edge_key;
  using mesh_detail::example;
  if (m.file_index.size() != m.triangles.size()) {
    m.file_index.resize(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) m.file_index[t] = static_cast<long>(t) + 1;
  }
  const double size = m.extent();
  // 1. degenerate and repeated triangles
  std::map<std::array<int, 3>, long> seen;
  TriangleMesh kept;
  kept.vertices = m.vertices;
  for (std::size_t t = 0; t < m.size(); ++t) {
    const auto& tri = m.triangles[t];
    const bool repeated_vertex = tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
    if (repeated_vertex || !(norm(m.area_vector(t)) > 1e-12 * size * size)) {
      ++report.degenerate;
      example(report.degenerate_examples, m.file_index[t]);
      continue;
    }
    std::array<int, 3> sorted = tri;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.emplace(sorted, m.file_index[t]).second) {
      ++report.duplicate;
      example(report.duplicate_examples, m.file_index[t]);
      continue;
    }
    kept.triangles.push_back(tri);
    kept.file_index.push_back(m.file_index[t]);
  }
  if (kept.triangles.empty()) throw MeshError(source + ": no triangle with an area is left (" + report.summary() + ")");
  // 2. edges: which triangles use each, and in which direction
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, bool>>> edges;  // (triangle, runs low -> high)
  for (std::size_t t = 0; t < kept.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = kept.triangles[t][static_cast<std::size_t>(k)], b = kept.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      edges[edge_key(a, b)].push_back({static_cast<int>(t), a < b});
    }
  for (const auto& e : edges) {
    if (e.second.size() == 1) ++report.open_edges;
    if (e.second.size() > 2) ++report.non_manifold_edges;
  }
  // 3. orientation, piece by piece (breadth first over manifold edges): flip[t] relative to the
  // piece's first triangle; then flip the piece's minority.
  const std::size_t n = kept.size();
  std::vector<int> piece(n, -1);
  std::vector<char> flip(n, 0);
  std::vector<int> queue;
  for (std::size_t start = 0; start < n; ++start) {
    if (piece[start] >= 0) continue;
    const int id = static_cast<int>(report.pieces++);
    piece[start] = id;
    queue.assign(1, static_cast<int>(start));
    std::vector<int> members;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int t = queue[q];
      members.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int a = kept.triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
        const int b = kept.triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>((k + 1) % 3)];
        const auto& users = edges[edge_key(a, b)];
        if (users.size() != 2) continue;  // open or non-manifold: no orientation constraint
        const auto& other = users[0].first == t ? users[1] : users[0];
        const bool mine = (a < b) != (flip[static_cast<std::size_t>(t)] != 0);  // direction after my flip
        // Consistent: the neighbour runs the edge the other way.
        const bool want_flip = other.second == mine;
        const int o = other.first;
        if (piece[static_cast<std::size_t>(o)] < 0) {
          piece[static_cast<std::size_t>(o)] = id;
          flip[static_cast<std::size_t>(o)] = want_flip;
          queue.push_back(o);
        } else if ((flip[static_cast<std::size_t>(o)] != 0) != want_flip) {
          throw MeshError(source + ": triangle " + std::to_string(kept.file_index[static_cast<std::size_t>(o)]) +
                          " cannot be oriented consistently with its neighbours (a one-sided surface, like a Moebius "
                          "strip); a wall mesh must have two sides");
        }
      }
    }
    std::size_t flips = 0;
    for (int t : members) flips += flip[static_cast<std::size_t>(t)] != 0;
    const bool invert = 2 * flips > members.size();  // keep the majority's orientation
    for (int t : members) {
      auto& f = flip[static_cast<std::size_t>(t)];
      f = invert ? !f : f;
    }
  }
  for (std::size_t t = 0; t < n; ++t)
    if (flip[t]) {
      std::swap(kept.triangles[t][1], kept.triangles[t][2]);
      ++report.flipped;
      example(report.flipped_examples, kept.file_index[t]);
    }
  m = std::move(kept);
  return report;
}

}  // namespace blaze
