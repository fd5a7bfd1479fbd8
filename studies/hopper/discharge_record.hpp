// What a hopper discharge did, particle by particle: where each particle was when the gate opened
// and when it left (to the CSV interval), the discharged mass against time, and from them
//   - the steady mass flow rate W (kg/s): the least-squares slope of the discharged mass over the
//     part of the curve between 20% and 70% of the mass finally discharged (the start-up and the
//     tail of a flat-bottomed hopper left out), with the fit's R^2 (1: constant rate);
//   - the residual: the fraction of the bed still in the hopper at the end (a flat bottom keeps
//     dead zones in its corners, so its discharge is incomplete);
//   - the flow pattern: the median exit times of the particles that started in the top 30% of the
//     bed above the orifice (|x| <= its half-width) and of those that started in the bottom 30% at
//     the sides (|x| >= half the bed's half-width). In funnel flow (Nedderman, Statics and
//     Kinematics of Granular Materials, 1992, ch. 1) the core above the orifice drains first, so
//     the top-centre particles leave before the bottom-side ones (which may never leave); in mass
//     flow the bed descends as a whole and the bottom leaves first.
//   - arching: the flow has stopped (no particle left for a given span) while particles remain
//     over the orifice (|x| <= its half-width): an arch spans it (a clog, as in To, Lai & Pak, PRL
//     86 (2001) 71, and Zuriguel et al., PRE 71 (2005) 051303, whose statistic is the mass that
//     passes before one forms). A hopper that stopped with particles only in its dead zones at the
//     sides has drained, not arched.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>
#include "blaze/particles/particle_state.hpp"

namespace blaze::hopper {

struct DischargeSummary {
  std::size_t particles = 0, discharged = 0;
  double residual = 0;           // fraction of the bed left in the hopper
  double flow_rate = 0;          // kg/s, steady part
  double flow_r2 = 0;            // of the linear fit
  double t_top_centre = 0, t_bottom_side = 0;  // s from the opening, median exit; inf: most never left
  bool funnel() const { return t_top_centre < t_bottom_side; }
  bool arched = false;           // the flow stopped with particles over the orifice (arch())
  double last_exit = 0;          // s from the opening: the last sample at which a particle had left
};

class DischargeRecord {
 public:
  static constexpr double kNever = std::numeric_limits<double>::infinity();

  // At the opening: the bed as it is (x measured from `axis_x`, the orifice's centre line), kept
  // in id order, so that the record (its sums, its CSV) does not depend on the state's order (one
  // process's store order, or the run over ranks gathered in id order).
  template <class Real>
  void open(const ParticleState<Real>& st, double axis_x, double orifice_half_width = 0) {
    axis_ = axis_x, orifice_ = orifice_half_width;
    std::vector<std::size_t> order(st.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return st.id[a] < st.id[b]; });
    for (std::size_t i : order) {
      index_[static_cast<std::int64_t>(st.id[i])] = entries_.size();
      entries_.push_back({static_cast<std::int64_t>(st.id[i]), vec_cast<double>(st.position[i]), static_cast<double>(st.mass[i]), kNever});
    }
  }
  // A sample at t (s from the opening): the particles of the bed no longer present left by t.
  template <class Real>
  void sample(double t, const ParticleState<Real>& st) {
    std::vector<char> present(entries_.size(), 0);
    for (std::size_t i = 0; i < st.size(); ++i) {
      const auto it = index_.find(static_cast<std::int64_t>(st.id[i]));
      if (it != index_.end()) present[it->second] = 1;
    }
    double mass = 0;
    if (curve_.empty()) last_exit_ = t;
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      if (!present[k] && entries_[k].t_out == kNever) entries_[k].t_out = t, last_exit_ = t;
      if (entries_[k].t_out != kNever) mass += entries_[k].mass;
    }
    curve_.push_back({t, mass});
    // the particles of the bed left over the orifice (|x| <= its half-width), counted at this sample
    over_orifice_ = 0;
    for (std::size_t i = 0; i < st.size(); ++i)
      if (index_.count(static_cast<std::int64_t>(st.id[i])) && std::fabs(static_cast<double>(st.position[i].x) - axis_) <= orifice_)
        ++over_orifice_;
  }
  // Has an arch formed by the last sample, at t: no particle has left for `span` s (> 0) while at
  // least `min_over` particles of the bed remain over the orifice?
  bool arch(double t, double span, std::size_t min_over = 3) const {
    return span > 0 && !curve_.empty() && t - last_exit_ >= span && over_orifice_ >= min_over;
  }
  std::size_t over_orifice() const { return over_orifice_; }
  double last_exit() const { return last_exit_; }  // s: the last sample at which a particle had left

  // `arch_span`: the span without an exit that counts as stopped (arch(); 0: arching not judged).
  DischargeSummary summary(double orifice_half_width, double arch_span = 0) const {
    DischargeSummary s;
    s.particles = entries_.size();
    double y_lo = kNever, y_hi = -kNever, half = 0;
    for (const auto& e : entries_) {
      y_lo = std::min(y_lo, e.x0.y), y_hi = std::max(y_hi, e.x0.y), half = std::max(half, std::fabs(e.x0.x - axis_));
      if (e.t_out != kNever) ++s.discharged;
    }
    s.residual = s.particles ? 1.0 - static_cast<double>(s.discharged) / static_cast<double>(s.particles) : 0;
    std::vector<double> top_centre, bottom_side;
    for (const auto& e : entries_) {
      const double dx = std::fabs(e.x0.x - axis_), h = (e.x0.y - y_lo) / std::max(y_hi - y_lo, 1e-300);
      if (h >= 0.7 && dx <= orifice_half_width) top_centre.push_back(e.t_out);
      if (h <= 0.3 && dx >= 0.5 * half) bottom_side.push_back(e.t_out);
    }
    s.t_top_centre = median(top_centre), s.t_bottom_side = median(bottom_side);
    // the steady rate: a line through the curve between 20% and 70% of the final mass
    const double final_mass = curve_.empty() ? 0 : curve_.back().second;
    double n = 0, st = 0, sm = 0, stt = 0, stm = 0, smm = 0;
    for (const auto& [t, m] : curve_)
      if (m >= 0.2 * final_mass && m <= 0.7 * final_mass) n += 1, st += t, sm += m, stt += t * t, stm += t * m, smm += m * m;
    const double vt = stt - st * st / std::max(n, 1.0), vm = smm - sm * sm / std::max(n, 1.0), c = stm - st * sm / std::max(n, 1.0);
    if (n >= 3 && vt > 0) s.flow_rate = c / vt, s.flow_r2 = vm > 0 ? c * c / (vt * vm) : 1;
    s.last_exit = last_exit_;
    s.arched = !curve_.empty() && arch(curve_.back().first, arch_span);
    return s;
  }

  // The record as text for a checkpoint (every double to 17 digits, so read back bitwise), and
  // back from `in` (a std::runtime_error when it is not what save() wrote).
  std::string save() const {
    std::string t = "discharge record 1\n" + text(axis_) + ' ' + text(orifice_) + ' ' + text(last_exit_) + ' ' +
                    std::to_string(over_orifice_) + ' ' + std::to_string(entries_.size()) + ' ' + std::to_string(curve_.size()) + '\n';
    for (const auto& e : entries_)
      t += std::to_string(e.id) + ' ' + text(e.x0.x) + ' ' + text(e.x0.y) + ' ' + text(e.x0.z) + ' ' + text(e.mass) + ' ' + text(e.t_out) + '\n';
    for (const auto& [time, mass] : curve_) t += text(time) + ' ' + text(mass) + '\n';
    return t;
  }
  void restore(std::istream& in) {
    std::string word;
    const auto next = [&]() -> const std::string& {
      if (!(in >> word)) throw std::runtime_error("the discharge record is truncated");
      return word;
    };
    const auto real = [&]() {
      char* end = nullptr;
      const double v = std::strtod(next().c_str(), &end);
      if (*end) throw std::runtime_error("the discharge record holds '" + word + "' where a number belongs");
      return v;
    };
    const auto count = [&]() { return static_cast<std::size_t>(real()); };
    if (next() != "discharge" || next() != "record" || next() != "1") throw std::runtime_error("no discharge record where one belongs");
    *this = DischargeRecord{};
    axis_ = real(), orifice_ = real(), last_exit_ = real(), over_orifice_ = count();
    const std::size_t entries = count(), samples = count();
    for (std::size_t k = 0; k < entries; ++k) {
      Entry e{};
      e.id = static_cast<std::int64_t>(real());
      e.x0.x = real(), e.x0.y = real(), e.x0.z = real(), e.mass = real(), e.t_out = real();
      index_[e.id] = entries_.size();
      entries_.push_back(e);
    }
    for (std::size_t k = 0; k < samples; ++k) {
      const double t = real();
      curve_.emplace_back(t, real());
    }
  }

  // id, x0_m, y0_m, z0_m, t_out_s (NaN: never left)
  void write_csv(const std::string& path) const {
    std::ofstream out(path);
    out << "id,x0_m,y0_m,z0_m,t_out_s\n";
    for (const auto& e : entries_) {
      out << e.id << ',' << e.x0.x << ',' << e.x0.y << ',' << e.x0.z << ',';
      if (e.t_out == kNever) out << "NaN\n";
      else out << e.t_out << '\n';
    }
  }

 private:
  struct Entry {
    std::int64_t id;
    Vec3<double> x0;
    double mass, t_out;
  };
  static std::string text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
  }
  static double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
  double axis_ = 0, orifice_ = 0;  // m
  double last_exit_ = 0;           // s
  std::size_t over_orifice_ = 0;
  std::vector<Entry> entries_;
  std::unordered_map<std::int64_t, std::size_t> index_;
  std::vector<std::pair<double, double>> curve_;
};

}  // namespace blaze::hopper
