// The contact laws Blaze ships, as complete ContactLaw types: a normal law (linear spring-dashpot,
// thesis eq. 2.2; Hertz, eq. 3.6) with history-free friction (eq. 2.3), or with a tangential
// spring (tangential_spring.hpp: Cundall-Strack for the linear law, Mindlin for Hertz), which is
// contact history; the spring laws take rolling resistance too.
#pragma once
#include "blaze/laws/contact_law.hpp"
#include "blaze/laws/hertz.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "blaze/laws/linear_spring_dashpot.hpp"
#include "blaze/laws/tangential_spring.hpp"

namespace blaze {

template <class Real>
using LinearLaw = ContactLaw<Real, LinearSpringDashpot, HistoryFreeFriction>;
template <class Real>
using HertzLaw = ContactLaw<Real, Hertz, HistoryFreeFriction>;
template <class Real>
using LinearSpringLaw = ContactLaw<Real, LinearSpringDashpot, TangentialSpring>;
template <class Real>
using HertzMindlinLaw = ContactLaw<Real, Hertz, TangentialSpring>;
// ... and rolling resistance (rolling_resistance.hpp: constant torque or elastic-plastic spring).
template <class Real>
using LinearSpringRollingLaw = ContactLaw<Real, LinearSpringDashpot, TangentialSpring, RollingResistance>;
template <class Real>
using HertzMindlinRollingLaw = ContactLaw<Real, Hertz, TangentialSpring, RollingResistance>;

}  // namespace blaze
