// Every tolerance the verification suite uses, each with the reason for its size.
// Relative tolerances unless the name says otherwise.
#pragma once

namespace blaze::tol {

// --- acceptance targets (issue 2) ---
// Elastic head-on rebound speed: the target (the thesis reached 0.36%). Velocity Verlet
// at dt = t_c/200 leaves ~1e-6; the margin covers the force kink at first touch.
constexpr double rebound_speed_double = 1e-4;
// In float the positions (~1e-2 m) carry ~1e-9 m of rounding against overlaps of ~1e-5 m, and
// the velocity kicks ~1e-7 relative each step over ~200 steps of contact.
constexpr double rebound_speed_float = 1e-3;
// Contact duration against pi/omega (linear) and 2.9432 delta_max / v (Hertz): the 1%.
// Crossing times are interpolated linearly between steps, error O(dt^2/t_c^2).
constexpr double contact_duration = 1e-2;
// Static overlap mg/k under gravity: the 1%. After settling the residual oscillation is
// below 1e-6 of the overlap; float rounding of y ~ r is 0.3% of the overlap.
constexpr double static_overlap = 1e-2;
// "At rest" (m/s): the verification issue's 1e-6 m/s in double. In float the position is
// quantised to ulp(5e-3 m) = 4.7e-10 m, and a contact of angular frequency ~900 rad/s jitters
// across a few quanta: ~1e-6 m/s, so float is held to 1e-5 m/s.
constexpr double rest_speed_double = 1e-6;
constexpr double rest_speed_float = 1e-5;

// --- integrators ---
// Quaternion spin: the rotation is exact per step, so one revolution's angle error is rounding
// accumulated over 1e5 steps: ~1e5 * 1e-16 in double.
constexpr double spin_angle_double = 1e-9;
// Unit quaternion norm after 1e5 renormalised steps.
constexpr double quaternion_norm_drift = 1e-12;
// Ballistic flight: velocity Verlet integrates constant acceleration exactly; what is left is
// rounding of x + v dt over 1e4 steps.
constexpr double ballistic_position = 1e-10;
// Measured convergence order as dt halves: slopes over dt, dt/2, dt/4 of a harmonic contact
// oscillator, asserted within +-0.1 of the scheme's formal order (the verification issue's band).
constexpr double convergence_order = 0.1;

// --- force-law properties ---
// Newton's third law and angular momentum: both sides evaluate the same expressions with the
// operands exchanged; sums of ~5 terms differ by a few ulps.
constexpr double newton_third_law_double = 1e-12;
// In float the approach speed v_n = v_rel . n loses digits when |v_n| << |v_rel|, and the dashpot
// multiplies that error: 1.7e-5 of the force seen over 200 random contacts.
constexpr double newton_third_law_float = 1e-4;
// Restitution of the linear spring-dashpot: exact in continuous time, but the dashpot sees the
// half-step velocity of kick-drift-kick Verlet, a first-order lag of ~zeta*pi/steps-per-contact:
// 0.5% for e = 0.2 (zeta = 0.46) at t_c/400. The verification issue's bar is 1%.
constexpr double restitution_linear = 1e-2;

// --- backends ---
// CPU vs GPU, 1e4 spheres, 1000 steps, double: the two differ only by fused multiply-adds and the
// last bits of sin/cos, amplified by contact chaos. Measured on an H200 (2026-11-22): max |dx| =
// 7.9e-15 m = 4e-12 radii, max |dv| = 2.6e-11 m/s = 3e-11 of the largest speed. The bounds leave
// a factor ~250 for other devices and compiler versions while still catching any real divergence
// (a different force or neighbour would show at 1e-6 and above).
constexpr double cpu_gpu_position_over_radius = 1e-9;
constexpr double cpu_gpu_velocity_over_scale = 1e-7;

// --- shapes (issue 3) ---
// Mass properties of the shipped solids against closed forms: the 1e-10 relative. The
// tetrahedral sums are exact up to rounding of ~100 terms (1e-14); vertices are written to 17 digits.
constexpr double mass_properties = 1e-10;

// Polyhedron contact against the brute-force reference (issue 3, acceptance 3), all relative to
// the sum of the bounding radii: a contact deeper than 1e-6 must be found (the bound); a
// reported contact where the reference sees a gap beyond 1e-12 (rounding of O(1e-2) m coordinates in
// double) is false; overlaps agree to rounding of the projections (1e-9 of the size), and the
// reference "defines" a normal when its axis beats every other by more than that; normals within
// the 1 degree.
constexpr long contact_pairs_per_combination = 100000;
constexpr double contact_missed_depth = 1e-6;
constexpr double contact_false_gap = 1e-12;
constexpr double contact_axis_tie = 1e-9;
constexpr double contact_normal_degrees = 1.0;

// Torque-free tumbling box, 1e5 steps of 1e-4 s at |w| = 20 rad/s (issue 3, acceptance 5): L is
// carried exactly by the midpoint drift, so only rounding moves it; the energy error of the
// second-order rotation is ~(w dt)^2 = 4e-6 and bounded.
constexpr double tumbling_angular_momentum = 1e-6;
constexpr double tumbling_energy = 1e-4;
// Elastic polyhedron collisions (issue 3, acceptance 4): kinetic energy after separation within
// the 0.5%, over this many cases (half cube-cube, half octahedron-cube).
constexpr double polyhedron_collision_energy = 5e-3;
constexpr long polyhedron_collision_cases = 10000;
// Time step of those collisions: the force is conservative but jumps its lever arm where the
// least-penetration feature changes, which costs first-order energy errors: worst case measured
// 3% at t_c/100, 0.74% at t_c/400, 0.32% at t_c/1600 (2026-11-22).
constexpr double polyhedron_collision_steps_per_contact = 1600;

// Cube packing (issue 3, acceptance 6): the 1e5 cubes; 500 steps of t_c/25 let the loose
// lattice's random velocities bring every neighbour pair into contact at least once.
constexpr long cube_packing_count = 100000;
constexpr long cube_packing_steps = 500;

// --- geometry and bookkeeping ---
// Closed-form contact geometry in double: a handful of roundings of O(1) numbers.
constexpr double geometry_double = 1e-12;
// Sums of a few masses in double, in a different order than the reference.
constexpr double mass_sum_double = 1e-12;
// Power of the dissipative forces may be "positive" only by rounding of the two force evaluations
// it is the difference of (float: 1e-7 relative, times |v| <= 1.7 m/s).
constexpr double dissipation_rounding = 1e-6;
// ASCII VTU output carries 9 significant digits: sums of 500 values read back agree to ~1e-8;
// a sum of signed coordinates can cancel, so it gets one more digit of room.
constexpr double vtu_ascii = 1e-7;
constexpr double vtu_ascii_cancelling = 1e-6;

// --- issue 4: drag fall, quaternion spin, energy conservation (section A) ---
// (end of section A)

// --- issue 4: Hertz restitution, Chung & Ooi, hysteresis, law properties (section B) ---
// (end of section B)

// --- issue 4: octahedron on cube, cube at rest, oblique friction, incline (section C) ---
// (end of section C)

// --- issue 4: contact-type frequency (section D) ---
// (end of section D)

}  // namespace blaze::tol
