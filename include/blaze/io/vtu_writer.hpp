// VTK XML UnstructuredGrid (.vtu) files with raw binary appended data, and .pvd time series.
// Format (VTK file formats, "XML File Formats"): the XML header lists each DataArray with
// format="appended" and its byte offset into the <AppendedData encoding="raw"> block, which
// follows a '_' and holds, per array, a UInt64 byte count then the little-endian values. Binary
// values read back exactly (verification/read_vtu.py checks with meshio and with VTK's reader).
//
//   particles  every particle as a point (VTK_VERTEX): radius, velocity, angular_velocity,
//              orientation (w, x, y, z), mass, id, type, material as point data
//   polyhedra  every polyhedral particle's faces as VTK_POLYGON cells in world position, with the
//              particle's id, type and velocity as cell data
//   world      planar polygons (VTK_POLYGON), cylinders (VTK_QUAD strips) and meshes
//              (VTK_TRIANGLE) with material, object index (within its kind) and kind (0 polygon,
//              1 cylinder, 2 mesh) as cell data
// Files are written to a temporary name and renamed, so a reader never sees half a file.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "blaze/particles/particle_state.hpp"
#include "blaze/shapes/convex_shape.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

namespace vtu_detail {

inline void commit(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

template <class T> constexpr const char* vtk_type();
template <> constexpr const char* vtk_type<double>() { return "Float64"; }
template <> constexpr const char* vtk_type<float>() { return "Float32"; }
template <> constexpr const char* vtk_type<std::int64_t>() { return "Int64"; }
template <> constexpr const char* vtk_type<std::int32_t>() { return "Int32"; }
template <> constexpr const char* vtk_type<std::uint8_t>() { return "UInt8"; }

}  // namespace vtu_detail

// One unstructured grid, assembled in memory and written at once.
class VtuFile {
 public:
  enum CellType : std::uint8_t { kVertex = 1, kTriangle = 5, kPolygon = 7, kQuad = 9 };

  template <class T>
  void points(const std::vector<T>& xyz) {
    point_count_ = xyz.size() / 3;
    points_ = make("Points", 3, xyz);
  }
  // Cells as VTK stores them: all point indices, the running end of each cell, each cell's type.
  void cells(const std::vector<std::int64_t>& connectivity, const std::vector<std::int64_t>& offsets,
             const std::vector<std::uint8_t>& types) {
    if (offsets.size() != types.size()) throw std::invalid_argument("vtu: offsets and types differ in length");
    cell_count_ = types.size();
    cells_ = {make("connectivity", 1, connectivity), make("offsets", 1, offsets), make("types", 1, types)};
  }
  template <class T>
  void point_data(const std::string& name, int components, const std::vector<T>& v) {
    check(name, components, v.size(), point_count_);
    point_data_.push_back(make(name, components, v));
  }
  template <class T>
  void cell_data(const std::string& name, int components, const std::vector<T>& v) {
    check(name, components, v.size(), cell_count_);
    cell_data_.push_back(make(name, components, v));
  }

  void write(const std::string& path) const {
    const std::string tmp = path + ".tmp";
    {
      std::ofstream out(tmp, std::ios::binary);
      if (!out) throw std::runtime_error("cannot write " + tmp);
      std::uint64_t offset = 0;
      auto header = [&](const Array& a) {
        out << "        <DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfComponents=\""
            << a.components << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
        offset += sizeof(std::uint64_t) + a.bytes.size();
      };
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\""
          << point_count_ << "\" NumberOfCells=\"" << cell_count_ << "\">\n      <Points>\n";
      header(points_);
      out << "      </Points>\n      <Cells>\n";
      for (const auto& a : cells_) header(a);
      out << "      </Cells>\n      <PointData>\n";
      for (const auto& a : point_data_) header(a);
      out << "      </PointData>\n      <CellData>\n";
      for (const auto& a : cell_data_) header(a);
      out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
      auto block = [&](const Array& a) {
        const std::uint64_t n = a.bytes.size();
        out.write(reinterpret_cast<const char*>(&n), sizeof n);
        out.write(a.bytes.data(), static_cast<std::streamsize>(n));
      };
      block(points_);
      for (const auto& a : cells_) block(a);
      for (const auto& a : point_data_) block(a);
      for (const auto& a : cell_data_) block(a);
      out << "\n  </AppendedData>\n</VTKFile>\n";
      if (!out) throw std::runtime_error("write failed: " + tmp);
    }
    vtu_detail::commit(tmp, path);
  }
  // The parallel file (.pvtu) of a grid written in pieces (a run over ranks: each writes its own
  // particles) that have this file's arrays: their names, types and components, and the pieces'
  // file names relative to the .pvtu's folder (VTK's "Parallel XML" format).
  void write_parallel(const std::string& path, const std::vector<std::string>& pieces) const {
    const std::string tmp = path + ".tmp";
    {
      std::ofstream out(tmp);
      if (!out) throw std::runtime_error("cannot write " + tmp);
      auto header = [&](const Array& a, bool named) {
        out << "      <PDataArray type=\"" << a.type << "\"";
        if (named) out << " Name=\"" << a.name << "\"";
        out << " NumberOfComponents=\"" << a.components << "\"/>\n";
      };
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPoints>\n";
      header(points_, false);
      out << "    </PPoints>\n    <PPointData>\n";
      for (const auto& a : point_data_) header(a, true);
      out << "    </PPointData>\n    <PCellData>\n";
      for (const auto& a : cell_data_) header(a, true);
      out << "    </PCellData>\n";
      for (const auto& piece : pieces) out << "    <Piece Source=\"" << piece << "\"/>\n";
      out << "  </PUnstructuredGrid>\n</VTKFile>\n";
      if (!out) throw std::runtime_error("write failed: " + tmp);
    }
    vtu_detail::commit(tmp, path);
  }

 private:
  struct Array {
    std::string name;
    const char* type;
    int components;
    std::vector<char> bytes;
  };
  template <class T>
  static Array make(const std::string& name, int components, const std::vector<T>& v) {
    Array a{name, vtu_detail::vtk_type<T>(), components, std::vector<char>(v.size() * sizeof(T))};
    if (!v.empty()) std::memcpy(a.bytes.data(), v.data(), a.bytes.size());
    return a;
  }
  static void check(const std::string& name, int components, std::size_t values, std::size_t count) {
    if (values != count * static_cast<std::size_t>(components))
      throw std::invalid_argument("vtu: array " + name + " has " + std::to_string(values) + " values, expected " +
                                  std::to_string(count) + " x " + std::to_string(components));
  }
  std::size_t point_count_ = 0, cell_count_ = 0;
  Array points_;
  std::vector<Array> cells_, point_data_, cell_data_;
};

// `unwrapped`: periodic runs' unwrapped positions (Simulation::unwrapped_positions), written as
// "unwrapped_position" beside the wrapped points; empty: none.
template <class Real>
VtuFile particles_vtu(const ParticleState<Real>& s, const std::vector<Vec3<double>>& unwrapped = {}) {
  const std::size_t n = s.size();
  std::vector<Real> x, v, w, q, r(s.radius), m(s.mass);
  std::vector<std::int64_t> conn(n), offsets(n);
  std::vector<std::int32_t> id(s.id.begin(), s.id.end());
  for (std::size_t i = 0; i < n; ++i) {
    x.insert(x.end(), {s.position[i].x, s.position[i].y, s.position[i].z});
    v.insert(v.end(), {s.velocity[i].x, s.velocity[i].y, s.velocity[i].z});
    w.insert(w.end(), {s.angular_velocity[i].x, s.angular_velocity[i].y, s.angular_velocity[i].z});
    q.insert(q.end(), {s.orientation[i].w, s.orientation[i].x, s.orientation[i].y, s.orientation[i].z});
    conn[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  VtuFile f;
  f.points(x);
  f.cells(conn, offsets, std::vector<std::uint8_t>(n, VtuFile::kVertex));
  f.point_data("radius", 1, r);
  f.point_data("velocity", 3, v);
  f.point_data("angular_velocity", 3, w);
  f.point_data("orientation", 4, q);
  f.point_data("mass", 1, m);
  f.point_data("id", 1, id);
  f.point_data("type", 1, s.type);
  f.point_data("material", 1, s.material);
  if (!unwrapped.empty()) {
    std::vector<double> u;
    for (const auto& p : unwrapped) u.insert(u.end(), {p.x, p.y, p.z});
    f.point_data("unwrapped_position", 3, u);
  }
  return f;
}
template <class Real>
void write_particles_vtu(const std::string& path, const ParticleState<Real>& s, const std::vector<Vec3<double>>& unwrapped = {}) {
  particles_vtu(s, unwrapped).write(path);
}

// Faces of the polyhedral particles in world position; shapes[type] is that type's body-frame
// shape (no vertices: a sphere type, left out).
template <class Real>
VtuFile polyhedra_vtu(const ParticleState<Real>& s, const std::vector<ConvexShape>& shapes) {
  std::vector<Real> x, v;
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::int32_t> id;
  std::vector<std::uint8_t> type;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.type[i] >= shapes.size()) throw std::invalid_argument("vtu: particle type without a shape");
    const ConvexShape& shape = shapes[s.type[i]];
    if (shape.vertices.empty()) continue;
    const std::int64_t first = static_cast<std::int64_t>(x.size() / 3);
    // a particle scaled from its type's shape (a feed's size distribution): its radius over the shape's
    const double scale = static_cast<double>(s.radius[i]) / shape.bounding_radius;
    for (const auto& b : shape.vertices) {
      const Vec3<Real> p = s.position[i] + rotate(s.orientation[i], Vec3<Real>{Real(scale * b.x()), Real(scale * b.y()), Real(scale * b.z())});
      x.insert(x.end(), {p.x, p.y, p.z});
    }
    for (const auto& face : shape.faces) {
      for (int k : face) conn.push_back(first + k);
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      v.insert(v.end(), {s.velocity[i].x, s.velocity[i].y, s.velocity[i].z});
      id.push_back(s.id[i]);
      type.push_back(s.type[i]);
    }
  }
  VtuFile f;
  f.points(x);
  f.cells(conn, offsets, std::vector<std::uint8_t>(offsets.size(), VtuFile::kPolygon));
  f.cell_data("id", 1, id);
  f.cell_data("type", 1, type);
  f.cell_data("velocity", 3, v);
  return f;
}
template <class Real>
void write_polyhedra_vtu(const std::string& path, const ParticleState<Real>& s, const std::vector<ConvexShape>& shapes) {
  polyhedra_vtu(s, shapes).write(path);
}

// World surfaces; a cylinder becomes `segments` quads around its axis.
template <class Real>
void write_world_vtu(const std::string& path, const World<Real>& w, int segments = 64) {
  std::vector<double> x;
  std::vector<std::int64_t> conn, offsets;
  std::vector<std::uint8_t> types, material, kind;
  std::vector<std::int32_t> object;
  auto point = [&](const Vec3<double>& p) {
    x.insert(x.end(), {p.x, p.y, p.z});
    return static_cast<std::int64_t>(x.size() / 3 - 1);
  };
  for (std::size_t k = 0; k < w.polygons.size(); ++k) {
    const auto& p = w.polygons[k];
    for (int j = 0; j < p.vertex_count; ++j) conn.push_back(point(vec_cast<double>(p.vertex[j])));
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
    types.push_back(VtuFile::kPolygon);
    material.push_back(p.material);
    object.push_back(static_cast<std::int32_t>(k));
    kind.push_back(0);
  }
  for (std::size_t k = 0; k < w.cylinders.size(); ++k) {
    const auto& c = w.cylinders[k];
    const Vec3<double> o = vec_cast<double>(c.origin), a = vec_cast<double>(c.axis);
    const Vec3<double> any = std::fabs(a.x) < 0.9 ? Vec3<double>{1, 0, 0} : Vec3<double>{0, 1, 0};
    const Vec3<double> n = cross(a, any), u = n * (1 / norm(n)), v = cross(a, u);
    const std::int64_t first = static_cast<std::int64_t>(x.size() / 3);
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * 3.14159265358979323846 * j / segments;
      const Vec3<double> rim = (u * std::cos(phi) + v * std::sin(phi)) * double(c.radius);
      point(o + rim);
      point(o + rim + a * double(c.length));
    }
    for (int j = 0; j < segments; ++j) {
      const std::int64_t p0 = first + 2 * j, p1 = first + 2 * ((j + 1) % segments);
      conn.insert(conn.end(), {p0, p1, p1 + 1, p0 + 1});
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(VtuFile::kQuad);
      material.push_back(c.material);
      object.push_back(static_cast<std::int32_t>(k));
      kind.push_back(1);
    }
  }
  for (std::size_t k = 0; k < w.meshes.size(); ++k) {
    const TriangleMesh& m = w.meshes[k].mesh;
    const auto first = static_cast<std::int64_t>(x.size() / 3);
    for (const auto& v : m.vertices) point(v);
    for (const auto& t : m.triangles) {
      conn.insert(conn.end(), {first + t[0], first + t[1], first + t[2]});
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(VtuFile::kTriangle);
      material.push_back(w.meshes[k].material);
      object.push_back(static_cast<std::int32_t>(k));
      kind.push_back(2);
    }
  }
  VtuFile f;
  f.points(x);
  f.cells(conn, offsets, types);
  f.cell_data("material", 1, material);
  f.cell_data("object", 1, object);
  f.cell_data("kind", 1, kind);
  f.write(path);
}

// A ParaView time series: (time, file) entries, rewritten whole after each addition.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  // A restarted run: the entries of the existing file up to time t (none if there is no file).
  std::size_t resume(double t) {
    std::ifstream in(path_);
    std::string line;
    while (std::getline(in, line)) {
      const auto ts = line.find("timestep=\""), fs = line.find("file=\"");
      if (ts == std::string::npos || fs == std::string::npos) continue;
      const double time = std::stod(line.substr(ts + 10));
      const std::string file = line.substr(fs + 6, line.find('"', fs + 6) - fs - 6);
      if (time <= t) entries_.emplace_back(time, file);
    }
    return entries_.size();
  }
  void add(double time, const std::string& file) {
    entries_.emplace_back(time, file);
    const std::string tmp = path_ + ".tmp";
    {
      std::ofstream out(tmp);
      if (!out) throw std::runtime_error("cannot write " + tmp);
      out << std::setprecision(17)
          << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection>\n";
      for (const auto& [t, f] : entries_) out << "    <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
      out << "  </Collection>\n</VTKFile>\n";
      if (!out) throw std::runtime_error("write failed: " + tmp);
    }
    vtu_detail::commit(tmp, path_);
  }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace blaze
