// Work-precision study (`make fig-work-precision`): error against wall time across time steps,
// float vs double and Euler vs Verlet, for three verification cases with exact references:
//   drag fall      (thesis 2.5.1)  max relative error of x(t), v(t) vs the closed form
//   head-on        (Hertz, e=0.5)  |e_out / e - 1| vs the exact restitution of the law
//   falling spheres (thesis 2.3.2) max relative drift of the total energy (elastic, 1 s)
// on the backend it is built for. Writes verification/results/work_precision_<backend>.dat (one
// gnuplot block per case and setting; committed, so the figure can show the GPU run beside the
// CPU one) and work_precision_<backend>.md: per case, the settings on the Pareto front (no other
// setting is both faster and more accurate) and where Blaze's default sits.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>
#include "blaze/exec/device_info.hpp"
#include "verification/cases/drag_fall.hpp"
#include "verification/cases/falling_particles.hpp"
#include "verification/cases/head_on.hpp"
#include "blaze/io/console.hpp"

using namespace blaze;
namespace cs = blaze::test::cases;

namespace {

struct Point {
  std::string case_name, precision, integrator;
  double dt, error, wall_s;
};

// One setting's run: (dt) -> {error, wall time}.
using Runner = std::function<std::pair<double, double>(double)>;

template <class Real, class Integrator>
void sweep(std::vector<Point>& out, const std::string& case_name, const std::vector<double>& dts, const Runner& run) {
  for (double dt : dts) {
    const auto [error, wall] = run(dt);
    out.push_back({case_name, sizeof(Real) == 4 ? "float" : "double", Integrator::name, dt, error, wall});
    std::printf("%-16s %-6s %-18s dt=%-9.3g error=%-10.3g wall=%.3g s\n", case_name.c_str(), out.back().precision.c_str(),
                Integrator::name, dt, error, wall);
    std::fflush(stdout);
  }
}

template <class Real, class Integrator>
void all_cases(std::vector<Point>& out, bool quick) {
  const std::vector<double> drag_dts = quick ? std::vector<double>{4e-3, 1e-3} : std::vector<double>{8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};
  sweep<Real, Integrator>(out, "drag-fall", drag_dts, [](double dt) {
    const auto r = cs::drag_fall<Real, Integrator>(dt);
    return std::make_pair(r.error, r.wall_s);
  });
  const cs::HeadOnSetup head_on;
  const double t_c = head_on.contact_time();
  std::vector<double> head_dts;
  for (double per : quick ? std::vector<double>{25, 100} : std::vector<double>{12.5, 25, 50, 100, 200, 400, 800})
    head_dts.push_back(t_c / per);
  sweep<Real, Integrator>(out, "head-on", head_dts, [&](double dt) {
    const auto r = cs::head_on_restitution<Real, Integrator>(head_on, dt);
    return std::make_pair(r.error, r.wall_s);
  });
  const std::vector<double> fall_dts = quick ? std::vector<double>{2e-4, 1e-4} : std::vector<double>{4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5};
  sweep<Real, Integrator>(out, "falling-spheres", fall_dts, [](double dt) {
    const auto r = cs::falling_particles<Real, Integrator>(dt);
    return std::make_pair(r.error, r.wall_s);
  });
}

// Settings no other setting beats in both error and wall time, cheapest first.
std::vector<Point> pareto_front(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.wall_s < b.wall_s; });
  std::vector<Point> front;
  double best = 1e300;
  for (const auto& p : pts)
    if (p.error < best) {
      front.push_back(p);
      best = p.error;
    }
  return front;
}

std::string label(const Point& p) {
  char b[96];
  std::snprintf(b, sizeof b, "%s %s dt=%.3g", p.integrator.c_str(), p.precision.c_str(), p.dt);
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  blaze::line_buffered_output();
  bool quick = false;
  std::string out_dir = "verification/results";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--quick") quick = true;
    else if (a == "--out" && k + 1 < argc) out_dir = argv[++k];
    else {
      std::fprintf(stderr, "usage: %s [--quick] [--out DIR]\n", argv[0]);
      return 2;
    }
  }
  const std::string backend = DefaultSpace::name;
  std::printf("work-precision study on %s: %s\n", backend.c_str(), device_name(DefaultSpace{}).c_str());
  std::vector<Point> pts;
  all_cases<float, ForwardEuler>(pts, quick);
  all_cases<float, VelocityVerlet>(pts, quick);
  all_cases<double, ForwardEuler>(pts, quick);
  all_cases<double, VelocityVerlet>(pts, quick);
  all_cases<double, HalfStepVerlet>(pts, quick);

  std::filesystem::create_directories(out_dir);
  std::ofstream dat(out_dir + "/work_precision_" + backend + ".dat");
  dat << "# work-precision on " << backend << " (" << device_name(DefaultSpace{}) << ")\n";
  const char* cases[] = {"drag-fall", "head-on", "falling-spheres"};
  const char* settings[][2] = {{"float", "forward-euler"}, {"float", "velocity-verlet"}, {"double", "forward-euler"},
                               {"double", "velocity-verlet"}, {"double", "half-step-verlet"}};
  // Blocks: case-major, then setting: index = 5 * case + setting (the .gp script relies on it).
  bool first = true;
  for (const char* c : cases)
    for (const auto& s : settings) {
      if (!first) dat << "\n\n";
      first = false;
      dat << "# " << c << " " << s[0] << " " << s[1] << "\n# dt_s error wall_s\n";
      for (const auto& p : pts)
        if (p.case_name == c && p.precision == s[0] && p.integrator == s[1])
          dat << p.dt << ' ' << p.error << ' ' << p.wall_s << '\n';
    }

  std::ofstream md(out_dir + "/work_precision_" + backend + ".md");
  md << "Work-precision on " << backend << " (" << device_name(DefaultSpace{}) << "), `make fig-work-precision`"
     << (quick ? " (quick)" : "") << ":\n\n| case | Pareto front, cheapest first (error, wall s) | Blaze default: velocity-verlet |\n|---|---|---|\n";
  for (const char* c : cases) {
    std::vector<Point> these;
    for (const auto& p : pts)
      if (p.case_name == c) these.push_back(p);
    std::string front;
    for (const auto& p : pareto_front(these)) {
      char b[64];
      std::snprintf(b, sizeof b, " (%.2g, %.2g s)", p.error, p.wall_s);
      front += (front.empty() ? "" : "; ") + label(p) + b;
    }
    std::string def;
    for (const auto& p : these)
      if (p.integrator == std::string("velocity-verlet")) {
        char b[96];
        std::snprintf(b, sizeof b, "%s%s dt=%.3g: %.2g", def.empty() ? "" : "; ", p.precision.c_str(), p.dt, p.error);
        def += b;
      }
    md << "| " << c << " | " << front << " | " << def << " |\n";
  }
  std::printf("wrote %s/work_precision_%s.{dat,md}\n", out_dir.c_str(), backend.c_str());
  return 0;
}
