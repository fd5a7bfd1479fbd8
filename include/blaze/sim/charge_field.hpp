// The time-averaged charge of a tumbling mill in its cross-section (issue 19; the thesis's profile
// figures 4.3-4.12), from samples of the particles' positions and velocities. In the plane normal
// to the drum's axis a through its centre c, with w the upward direction (against gravity,
// projected) and u = w x a (for a = +z and gravity along -y: u = +x, w = +y, the drum seen from
// +z), the square [-R, R]^2 is cut into cells of side h. Over the samples, each cell keeps
//   occupancy     the mean number of particle centres in it per sample              [-]
//   v_u, v_w      the mean in-plane velocity of the particles that were in it       [m/s]
// (a cell no particle visited has occupancy 0 and no velocity). Its CSV (write_csv) has one row
// per visited cell: u_m, w_m (the cell's centre), occupancy, v_u_m_per_s, v_w_m_per_s, which
// plots/mill_profile.gp draws as a density map with velocity arrows.
#pragma once
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

class ChargeField {
 public:
  ChargeField(const Vec3<double>& centre, const Vec3<double>& axis, const Vec3<double>& gravity, double radius, double cell)
      : c_(centre), R_(radius), h_(cell) {
    if (!(radius > 0 && cell > 0 && cell <= radius)) throw std::invalid_argument("charge field: need 0 < cell <= radius");
    a_ = axis * (1 / norm(axis));
    Vec3<double> up = gravity * -1.0;
    if (!(norm(up) > 0) || std::fabs(dot(up, a_)) > 0.99 * norm(up)) up = std::fabs(a_.y) < 0.9 ? Vec3<double>{0, 1, 0} : Vec3<double>{1, 0, 0};
    w_ = up - a_ * dot(up, a_);
    w_ = w_ * (1 / norm(w_));
    u_ = cross(w_, a_);
    n_ = static_cast<int>(std::ceil(2 * R_ / h_));
    count_.assign(static_cast<std::size_t>(n_) * n_, 0);
    vu_.assign(count_.size(), 0), vw_.assign(count_.size(), 0);
  }

  // One sample: every particle's position and velocity.
  template <class Real>
  void add(const std::vector<Vec3<Real>>& x, const std::vector<Vec3<Real>>& v) {
    if (x.size() != v.size()) throw std::invalid_argument("charge field: positions and velocities differ in number");
    for (std::size_t k = 0; k < x.size(); ++k) {
      const Vec3<double> r = vec_cast<double>(x[k]) - c_;
      const int i = static_cast<int>(std::floor((dot(r, u_) + R_) / h_)), j = static_cast<int>(std::floor((dot(r, w_) + R_) / h_));
      if (i < 0 || j < 0 || i >= n_ || j >= n_) continue;
      const std::size_t cell = static_cast<std::size_t>(j) * n_ + i;
      const Vec3<double> vk = vec_cast<double>(v[k]);
      count_[cell] += 1, vu_[cell] += dot(vk, u_), vw_[cell] += dot(vk, w_);
    }
    ++samples_;
  }

  long samples() const { return samples_; }
  // The cell holding in-plane coordinates (u, w) (m): occupancy and mean velocity; -1 outside.
  int cell_of(double u, double w) const {
    const int i = static_cast<int>(std::floor((u + R_) / h_)), j = static_cast<int>(std::floor((w + R_) / h_));
    return i < 0 || j < 0 || i >= n_ || j >= n_ ? -1 : j * n_ + i;
  }
  double occupancy(int cell) const { return samples_ ? count_.at(static_cast<std::size_t>(cell)) / samples_ : 0; }
  Vec3<double> mean_velocity(int cell) const {  // (v_u, v_w, 0)
    const double n = count_.at(static_cast<std::size_t>(cell));
    return n > 0 ? Vec3<double>{vu_[static_cast<std::size_t>(cell)] / n, vw_[static_cast<std::size_t>(cell)] / n, 0} : Vec3<double>{0, 0, 0};
  }

  void write_csv(const std::string& path) const {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw std::runtime_error("charge field: cannot write " + path);
    std::fprintf(f, "u_m,w_m,occupancy,v_u_m_per_s,v_w_m_per_s\n");
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        const int cell = j * n_ + i;
        if (count_[static_cast<std::size_t>(cell)] == 0) continue;
        const Vec3<double> v = mean_velocity(cell);
        std::fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g\n", -R_ + (i + 0.5) * h_, -R_ + (j + 0.5) * h_, occupancy(cell), v.x, v.y);
      }
    std::fclose(f);
  }

 private:
  Vec3<double> c_, a_, u_, w_;
  double R_, h_;
  int n_ = 0;
  long samples_ = 0;
  std::vector<double> count_, vu_, vw_;
};

}  // namespace blaze
