#pragma once
// Viscous damping coefficient c from a restitution coefficient e0 (host side). The damping
// force is F_d = c sqrt(m* k_n) d(delta)/dt with k_n the law's current stiffness.
#include <epac/params/validation.hpp>

#include <cmath>

namespace epac {

// Linear spring: Nan (24)-(26) with beta = 1, c = 2 gamma,
// gamma = -ln e0 / sqrt(pi^2 + ln^2 e0). A damped linear oscillator that separates when the
// overlap returns to zero rebounds with exactly e0. e0 = 0 is the limit gamma = 1 (critical).
inline double linear_damping_ratio(double e0) {
  require_range("restitution", e0, 0.0, Bound::closed, 1.0, Bound::closed);
  if (e0 <= 0.0) return 1.0;
  const double l = std::log(e0);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

// Hertz: with k_n = dF/d(delta) = 2 E* sqrt(R* delta) the damped Hertz impact, scaled by
// delta_0 = (m v0^2 / K)^(2/5), becomes
//   x'' = -max(x^(3/2) + c sqrt(3/2) x^(1/4) x', 0),  x(0) = 0, x'(0) = 1,
// so the restitution depends on c alone (not on the impact speed). The max(.., 0) is the
// kernel's rule for Hertz: the total normal force never pulls (without it the x^(1/4) damping
// term outlasts the x^(3/2) spring near separation and the spheres never part). We integrate
// that equation (RK4) and invert e(c) = e0 by bisection: the exact relation, not a fit.
inline double hertz_restitution_for(double c) {
  const double a = c * std::sqrt(1.5);
  double x = 0.0, v = 1.0;
  const double h = 2e-3;  // the undamped contact lasts ~3.2 time units
  auto acc = [a](double xx, double vv) {
    const double xp = xx > 0 ? xx : 0.0;
    const double f = xp * std::sqrt(xp) + a * std::sqrt(std::sqrt(xp)) * vv;
    return f > 0 ? -f : 0.0;
  };
  for (int s = 0; s < 200000; ++s) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0.0 && s > 0) {
      // linear interpolation of v at the crossing
      const double t = x / (x - xn);
      return -(v + t * (vn - v));
    }
    x = xn;
    v = vn;
  }
  return 0.0;
}

inline double hertz_damping_coefficient(double e0) {
  require_range("restitution", e0, 0.0, Bound::closed, 1.0, Bound::closed);
  if (e0 >= 1.0) return 0.0;
  double lo = 0.0, hi = 8.0;  // e(8) ~ 0: strongly overdamped
  if (e0 <= hertz_restitution_for(hi)) return hi;
  for (int it = 0; it < 60 && hi - lo > 1e-10; ++it) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution_for(mid) > e0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace epac
