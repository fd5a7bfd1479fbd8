// The mill study over ranks (issue 21: "world objects replicated and their forces and mill power
// reduced across ranks"; studies/mill/mill_run.hpp, build/mpi/study_mill): the laboratory mill of
// thesis section 4.2.1 (studies/mill/lab_mill.toml: 168 balls, a 90 cm drum with eight lifters
// turning at 32 rpm) for two revolutions at full speed, with the linear tangential spring (contact
// history on the drum and between balls across the ranks' boxes), on however many ranks mpirun
// starts, against the same on one rank:
// - power.csv: the same revolutions; the charge's toe, shoulder, ball count and centrifuging balls
//   exactly (the trajectories are bitwise one rank's: canonical order); the powers by the torque
//   method (the drum's work), by the energy method and its split by contact class, the thesis's
//   estimate and the energies, each within 1e-12 of its column's largest value (the ranks' partial
//   sums are added in another order than one rank's);
// - the drum does work on the charge (power > 0) and the two methods agree to
//   tol::mill_power_methods_settling (the second revolution after a 0.5 s ramp is not yet steady;
//   the energy-ledger suite holds the balance at steady state).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include "blaze/scene/scene_file.hpp"
#include "studies/mill/mill_run.hpp"
#include "verification/mpi/run_files.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Runs over ranks (issue 21)";

// The study on `comm` (no run on a rank outside it), writing to `dir`.
void run_study(const Communicator* comm, const std::string& dir) {
  if (!comm) return;
  const Scene s = load_scene("studies/mill/lab_mill.toml",
                             {"output.directory=\"" + dir + "\"", "simulation.end_time=4.3", "simulation.steps_per_contact=15",
                              "simulation.tangential=\"linear_spring\""});
  const int status = mill::run_mill<LinearSpringLaw<double>, ContactPointVelocity>(s, comm);
  BOOST_TEST(status == 0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(distributed_mill_study)

BOOST_AUTO_TEST_CASE(the_mill_power_over_ranks_is_the_one_rank_power) {
  const Communicator comm;
  const int n = comm.size();
  const std::string base = scene_folder(comm, "");
  BOOST_TEST_REQUIRE(!base.empty());
  const Communicator one = comm.first(1);
  run_study(&comm, base + "/many");
  run_study(one.size() > 0 ? &one : nullptr, base + "/one");
  comm.barrier();
  if (comm.rank() != 0) return;

  std::vector<std::string> ha, hb;
  const auto ra = csv_rows(base + "/many/power.csv", ha), rb = csv_rows(base + "/one/power.csv", hb);
  BOOST_TEST_REQUIRE(rb.size() == 2u);  // revolutions 1 and 2 after the ramp
  const SeriesComparison c = compare_series(ha, ra, hb, rb, {"revolution", "t_end_s", "balls", "toe_deg", "shoulder_deg",
                                                            "centrifuging_balls", "centrifuging_layers"});
  BOOST_TEST_REQUIRE(c.same_shape);
  const auto column = [&](const char* name) { return static_cast<std::size_t>(std::find(hb.begin(), hb.end(), name) - hb.begin()); };
  const double torque = rb.back()[column("power_W")], energy = rb.back()[column("energy_method_W")];
  const std::string ranks = std::to_string(n) + " rank" + (n > 1 ? "s" : "");
  BOOST_TEST_MESSAGE("mill study, " << ranks << ": revolution 2: " << ra.back()[column("power_W")] << " W (one rank " << torque
                                    << " W, energy method " << energy << " W); worst column " << c.worst << " of its largest ("
                                    << c.worst_name << ")");
  BOOST_TEST(c.exact_wrong == 0);
  BOOST_TEST(torque > 0);
  BOOST_TEST(std::fabs(energy - torque) < tol::mill_power_methods_settling * torque);
  check_at_most({kCase, "the lab mill's power per revolution over ranks against one rank: worst column, of its largest value, " + ranks,
                 "-", "the ranks' sums in another order"},
                c.worst, tol::distributed_series);
  std::error_code ec;
  std::filesystem::remove_all(base, ec);
}

BOOST_AUTO_TEST_SUITE_END()
