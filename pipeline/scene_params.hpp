// A scene's [simulation] as the Simulation's parameters (pipeline/simulation.hpp), for every
// program that runs a scene file (blaze run and the studies): the step, gravity, domain, the skin
// in metres (the scene gives it per largest particle size), drag, how pairs are evaluated, the
// energy accounts by class ([output] energy_by_class) and the world lists.
#pragma once
#include <algorithm>
#include <string>
#include "blaze/scene/scene.hpp"
#include "pipeline/run_log.hpp"
#include "pipeline/simulation.hpp"

namespace blaze {

// pairs_once: the pair evaluation the program chose (the scene's pair_evaluation, resolved for
// its shape).
template <class Real>
SimulationParams<Real> simulation_params(const Scene& s, bool pairs_once = false) {
  double r_max = 0;
  for (const auto& t : s.types) r_max = std::max(r_max, t.size());
  SimulationParams<Real> p{static_cast<Real>(s.dt), vec_cast<Real>(s.gravity), vec_cast<Real>(s.domain_lo),
                           vec_cast<Real>(s.domain_hi), static_cast<Real>(s.skin * r_max), static_cast<Real>(s.drag),
                           pairs_once ? PairEvaluation::once : PairEvaluation::both_sides, s.output.energy_by_class};
  p.world_lists = s.world_lists == WorldListsKind::on ? WorldLists::on : s.world_lists == WorldListsKind::off ? WorldLists::off
                                                                                                              : WorldLists::automatic;
  // every type's size, the feeds' derived extremes among them: the grid holds what they insert
  p.max_radius = static_cast<Real>(r_max);
  p.periodic = s.periodic;
  return p;
}

// A study driver that places its particles itself runs no [[feed]]: a scene that has one is
// refused rather than run without it (blaze run feeds; pipeline/feeder.hpp).
inline void refuse_feeds(const Scene& s, const std::string& program) {
  if (!s.feeds.empty())
    throw SceneError(s.place("feed[0].rate") + ": " + program + " does not run [[feed]] tables (blaze run does); remove them");
}

// The world objects whose loads the time series reports (run_log.hpp): every [[mesh]] and every
// named [[wall]] (not the [mill]'s own parts), by their names.
inline LoadColumns reported_loads(const Scene& s) {
  LoadColumns c;
  for (std::size_t k = 0; k < s.walls.size(); ++k)
    if (!s.walls[k].name.empty() && s.walls[k].name.rfind("mill ", 0) != 0)
      c.names.push_back(s.walls[k].name), c.objects.push_back(static_cast<int>(k));
  for (std::size_t k = 0; k < s.meshes.size(); ++k)
    c.names.push_back(s.meshes[k].name), c.objects.push_back(static_cast<int>(s.walls.size() + s.cylinders.size() + k));
  return c;
}

}  // namespace blaze
