// Precision-correct math for kernels: float stays float on both compilers, double stays double.
// (Unqualified ::sqrt(float) would silently widen to double on the host.)
#pragma once
#include <cmath>
#include <cstdint>
#include "blaze/config.hpp"

namespace blaze {

BLAZE_HD inline float sqrt_r(float x) { return ::sqrtf(x); }
BLAZE_HD inline double sqrt_r(double x) { return ::sqrt(x); }
BLAZE_HD inline float sin_r(float x) { return ::sinf(x); }
BLAZE_HD inline double sin_r(double x) { return ::sin(x); }
BLAZE_HD inline float cos_r(float x) { return ::cosf(x); }
BLAZE_HD inline double cos_r(double x) { return ::cos(x); }
BLAZE_HD inline float floor_r(float x) { return ::floorf(x); }
BLAZE_HD inline double floor_r(double x) { return ::floor(x); }
BLAZE_HD inline float abs_r(float x) { return ::fabsf(x); }
BLAZE_HD inline double abs_r(double x) { return ::fabs(x); }

// Machine epsilon of the precision (1 ulp at 1).
template <class T>
BLAZE_HD constexpr T epsilon_r();
template <>
BLAZE_HD constexpr float epsilon_r<float>() { return 1.1920929e-07f; }
template <>
BLAZE_HD constexpr double epsilon_r<double>() { return 2.220446049250313e-16; }

template <class T>
BLAZE_HD constexpr T min_r(T a, T b) { return b < a ? b : a; }
template <class T>
BLAZE_HD constexpr T max_r(T a, T b) { return a < b ? b : a; }
template <class T>
BLAZE_HD constexpr T clamp_r(T x, T lo, T hi) { return min_r(max_r(x, lo), hi); }
// The Hertzian contact radius a = sqrt(R* delta) (m) of an overlap delta (m, negative taken as 0)
// and an effective radius R* (m). The one expression every law writes it as: a normal law and a
// tangential spring that both need it compute it once (the compiler merges the identical pure
// computations; the Mindlin contact kernel had 10 square roots per contact).
template <class T>
BLAZE_HD_INLINE T contact_radius(T delta, T r_eff) { return sqrt_r(r_eff * max_r(delta, T(0))); }
// Index of the lowest set bit of x != 0 (bit sets of polyhedron features).
BLAZE_HD inline int lowest_bit(std::uint64_t x) {
#if defined(__CUDA_ARCH__)
  return __ffsll(static_cast<long long>(x)) - 1;
#else
  return __builtin_ctzll(x);
#endif
}
// False for NaN and +-Inf (x - x is NaN for both); valid without -ffast-math, which Blaze never uses.
template <class T>
BLAZE_HD constexpr bool finite_r(T x) { return (x - x) == T(0); }

}  // namespace blaze
