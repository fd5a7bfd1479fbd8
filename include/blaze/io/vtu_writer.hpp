// Minimal VTK XML UnstructuredGrid (.vtu) writer, ASCII, and a .pvd time-series collection.
// Spheres are points (VTK_VERTEX cells) with radius, velocity, angular velocity, id and material
// as point data; walls are polygons (VTK_POLYGON). Files are written to a temporary name and
// renamed, so a reader never sees half a file. (Binary appended output comes with the output issue.)
#pragma once
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "blaze/particles/particle_state.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

namespace vtu_detail {

inline void commit(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

inline std::ofstream open(const std::string& tmp) {
  std::ofstream out(tmp);
  if (!out) throw std::runtime_error("cannot write " + tmp);
  out << std::setprecision(9);
  return out;
}

template <class T, class F>
void data_array(std::ofstream& out, const char* type, const char* name, int components, std::size_t n, F value) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) out << value(i) << '\n';
  out << "        </DataArray>\n";
}

template <class Real>
std::string vec(const Vec3<Real>& v) {
  std::ostringstream s;
  s << std::setprecision(9) << v.x << ' ' << v.y << ' ' << v.z;
  return s.str();
}

}  // namespace vtu_detail

template <class Real>
void write_particles_vtu(const std::string& path, const ParticleState<Real>& s) {
  using namespace vtu_detail;
  const std::string tmp = path + ".tmp";
  {
    auto out = open(tmp);
    const std::size_t n = s.size();
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
        << "      <Points>\n";
    data_array<Real>(out, "Float64", "Points", 3, n, [&](std::size_t i) { return vec(s.position[i]); });
    out << "      </Points>\n      <Cells>\n";
    data_array<Real>(out, "Int64", "connectivity", 1, n, [](std::size_t i) { return i; });
    data_array<Real>(out, "Int64", "offsets", 1, n, [](std::size_t i) { return i + 1; });
    data_array<Real>(out, "UInt8", "types", 1, n, [](std::size_t) { return 1; });  // VTK_VERTEX
    out << "      </Cells>\n      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    data_array<Real>(out, "Float64", "radius", 1, n, [&](std::size_t i) { return s.radius[i]; });
    data_array<Real>(out, "Float64", "velocity", 3, n, [&](std::size_t i) { return vec(s.velocity[i]); });
    data_array<Real>(out, "Float64", "angular_velocity", 3, n, [&](std::size_t i) { return vec(s.angular_velocity[i]); });
    data_array<Real>(out, "Int32", "id", 1, n, [&](std::size_t i) { return s.id[i]; });
    data_array<Real>(out, "Int32", "material", 1, n, [&](std::size_t i) { return static_cast<int>(s.material[i]); });
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    if (!out) throw std::runtime_error("write failed: " + tmp);
  }
  commit(tmp, path);
}

template <class Real>
void write_world_vtu(const std::string& path, const World<Real>& w) {
  using namespace vtu_detail;
  std::vector<Vec3<Real>> points;
  std::vector<std::size_t> offsets;
  std::vector<int> material;
  for (const auto& p : w.polygons) {
    for (int k = 0; k < p.vertex_count; ++k) points.push_back(p.vertex[k]);
    offsets.push_back(points.size());
    material.push_back(p.material);
  }
  const std::string tmp = path + ".tmp";
  {
    auto out = open(tmp);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
        << offsets.size() << "\">\n      <Points>\n";
    data_array<Real>(out, "Float64", "Points", 3, points.size(), [&](std::size_t i) { return vec(points[i]); });
    out << "      </Points>\n      <Cells>\n";
    data_array<Real>(out, "Int64", "connectivity", 1, points.size(), [](std::size_t i) { return i; });
    data_array<Real>(out, "Int64", "offsets", 1, offsets.size(), [&](std::size_t i) { return offsets[i]; });
    data_array<Real>(out, "UInt8", "types", 1, offsets.size(), [](std::size_t) { return 7; });  // VTK_POLYGON
    out << "      </Cells>\n      <CellData Scalars=\"material\">\n";
    data_array<Real>(out, "Int32", "material", 1, material.size(), [&](std::size_t i) { return material[i]; });
    out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    if (!out) throw std::runtime_error("write failed: " + tmp);
  }
  commit(tmp, path);
}

// A ParaView time series: (time, file) entries, rewritten whole after each addition.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  void add(double time, const std::string& file) {
    entries_.emplace_back(time, file);
    const std::string tmp = path_ + ".tmp";
    {
      std::ofstream out(tmp);
      if (!out) throw std::runtime_error("cannot write " + tmp);
      out << std::setprecision(12)
          << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection>\n";
      for (const auto& [t, f] : entries_) out << "    <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
      out << "  </Collection>\n</VTKFile>\n";
    }
    vtu_detail::commit(tmp, path_);
  }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace blaze
