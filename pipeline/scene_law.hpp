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

// The laws come in three families, each compiled where it is used (apps/blaze/run_*.cpp keep one
// family a translation unit): history-free friction (linear, Hertz), the tangential spring (the
// parser pairs Mindlin with Hertz and the linear spring with the linear law), and the spring with
// rolling resistance (spheres only).
enum class LawFamily { history_free, spring, rolling };

inline LawFamily law_family(const Scene& s) {
  if (s.rolling == RollingKind::none) return s.tangential == TangentialKind::history_free ? LawFamily::history_free : LawFamily::spring;
  if (s.tangential == TangentialKind::history_free)
    throw SceneError(s.place("simulation.rolling") + ": rolling resistance needs a tangential spring (simulation.tangential)");
  return LawFamily::rolling;
}

template <class Real, class F>
int with_history_free_law(const Scene& s, F&& f) {
  return s.law == LawKind::linear ? f(LawTag<LinearLaw<Real>>{}) : f(LawTag<HertzLaw<Real>>{});
}
template <class Real, class F>
int with_spring_law(const Scene& s, F&& f) {
  return s.law == LawKind::linear ? f(LawTag<LinearSpringLaw<Real>>{}) : f(LawTag<HertzMindlinLaw<Real>>{});
}
template <class Real, class F>
int with_rolling_law(const Scene& s, F&& f) {
  return s.law == LawKind::linear ? f(LawTag<LinearSpringRollingLaw<Real>>{}) : f(LawTag<HertzMindlinRollingLaw<Real>>{});
}

template <class Real, bool Spheres, class F>
int with_scene_law(const Scene& s, F&& f) {
  switch (law_family(s)) {
    case LawFamily::history_free:
      return with_history_free_law<Real>(s, f);
    case LawFamily::spring:
      return with_spring_law<Real>(s, f);
    case LawFamily::rolling:
      break;
  }
  if constexpr (Spheres) {
    return with_rolling_law<Real>(s, f);
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
