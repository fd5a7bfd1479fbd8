// The scene's contact law as a type, for the programs that run scenes (studies, the blaze app):
// with_scene_law<Real, Spheres>(scene, f) calls f(LawTag<Law>{}) with the law that the scene's
// [simulation] keys law, tangential and rolling name (include/blaze/laws/standard_laws.hpp), and
// returns what f returns. The parser pairs Mindlin with Hertz and the linear spring with the linear
// law, and allows rolling resistance only with a spring on spheres; a program that runs polyhedra
// passes Spheres = false and so compiles no rolling law. A program must not drop a key it was given:
// one that cannot run a law says so (SceneError naming the key) instead of running another.
#pragma once
#include "blaze/laws/rolling_resistance.hpp"
#include "blaze/laws/standard_laws.hpp"
#include "blaze/scene/scene.hpp"

namespace blaze {

template <class L>
struct LawTag {
  using type = L;
};

template <class Real, bool Spheres, class F>
int with_scene_law(const Scene& s, F&& f) {
  const bool linear = s.law == LawKind::linear;
  if (s.tangential == TangentialKind::history_free) {
    if (s.rolling != RollingKind::none)
      throw SceneError(s.place("simulation.rolling") + ": rolling resistance needs a tangential spring (simulation.tangential)");
    return linear ? f(LawTag<LinearLaw<Real>>{}) : f(LawTag<HertzLaw<Real>>{});
  }
  if (s.rolling == RollingKind::none) return linear ? f(LawTag<LinearSpringLaw<Real>>{}) : f(LawTag<HertzMindlinLaw<Real>>{});
  if constexpr (Spheres) {
    return linear ? f(LawTag<LinearSpringRollingLaw<Real>>{}) : f(LawTag<HertzMindlinRollingLaw<Real>>{});
  } else {
    throw SceneError(s.place("simulation.rolling") + " = \"" + to_string(s.rolling) + "\": rolling resistance is for spheres");
  }
}

// "hertz + mindlin + epsd", "linear history-free": the law a run used, for its manifest.
inline std::string scene_law_name(const Scene& s) {
  std::string n = std::string(to_string(s.law)) + " + " + to_string(s.tangential);
  if (s.rolling != RollingKind::none) n += std::string(" + ") + to_string(s.rolling);
  return n;
}

}  // namespace blaze
