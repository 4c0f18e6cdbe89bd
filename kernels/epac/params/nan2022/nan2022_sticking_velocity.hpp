#pragma once
// Critical velocities of a particle hitting a flat (m* = m, R* = R), Nan Sec. 4, no damping:
//   V_s  = sqrt(2 W_0 / m)                   adhesive sticking velocity (JKR)      Nan (73)
//   V_y0 = sqrt(f_y^2 / (m k_el))            yield velocity without adhesion      Nan (74)
//   V_y  = sqrt((f_y^2 - f_0^2) / (m k_el))  yield velocity with adhesion         Nan (75)
//   V_ys                                     plastic-adhesive sticking velocity    Nan (78)-(79)
// If f_y < f_0 (adhesion-induced yield, Nan Sec. 4; CY below ~0.74 with Nan (52)) V_y^2 < 0: the
// contact yields at any impact speed; V_y is reported as 0 and always_yields is set. Every case
// of Nan Table 6 is of this kind.
#include <epac/models/nan2022/detail/nan2022_unloading.hpp>
#include <epac/params/nan2022/nan2022_parameters.hpp>

#include <cmath>

namespace epac {

struct Nan2022StickingVelocities {
  double V_s = 0;   // Nan (73), from the linear law's own adhesive work W_0 (= W_JKR)
  double V_y0 = 0;  // Nan (74); 0 (meaningless) when !yields
  double V_y = 0;   // Nan (75); 0 when always_yields or !yields
  double V_ys = 0;  // critical sticking velocity: V_s if the contact has not yielded at V_ys
  bool yields = false;
  bool always_yields = false;           // f_y < f_0: V_y^2 < 0
  bool yields_before_sticking = false;  // V_y < V_s: V_ys from the fixed point (78)-(79)
  double f_max = 0;                     // maximum force of the impact at V_ys (fixed point of (78))
  int iterations = 0;
  bool converged = true;
};

// Nan (73) in closed form, 1.84 (Gamma/R)^(5/6) / (rho^(1/2) E*^(1/3)) for a sphere on a flat.
inline double nan2022_adhesive_sticking_velocity_closed_form(double gamma, double R, double density, double E_star) {
  return std::sqrt(2.0 * 7.09 / (4.0 / 3.0 * M_PI)) * std::pow(gamma / R, 5.0 / 6.0) /
         (std::sqrt(density) * std::cbrt(E_star));
}

// p: the pair constants (particle-wall); R: particle radius (= R*); mass: particle mass (= m*).
// The fixed point of Nan (78)-(79) is iterated as the paper prescribes, from f_max = f_y:
// alpha_max by Nan (10), k_e and alpha_p and f_cp by the unloading line, then
// f_max = f_cp sqrt(1 + 56/81 k_e/k_c) from W_4 = W_5 + W_6 (Nan (78)). It converges linearly
// (tens of iterations); max_iter bounds it and `converged` reports the outcome.
inline Nan2022StickingVelocities nan2022_sticking_velocities(const Nan2022PairConstants<double>& p, double R,
                                                             double mass, int max_iter = 10000,
                                                             double rel_tol = 1e-12) {
  require_positive("R", R);
  require_positive("mass", mass);
  nan2022_validate(p, "sticking velocity pair");
  const Nan2022ContactConstants<double> c = nan2022_contact_constants<double>(p, R);
  Nan2022StickingVelocities v;
  // W_0: the linear law's adhesive work (A1), equal to W_JKR by construction of k_cl.
  const double W0 = (56.0 / 162.0 * c.el_over_cl + 17.0 / 162.0) * c.f_ce * c.f_ce / c.k_el;
  v.V_s = std::sqrt(2.0 * W0 / mass);
  v.yields = c.yields;
  if (!c.yields) {
    v.V_ys = v.V_s;
    return v;
  }
  v.V_y0 = std::sqrt(c.f_y * c.f_y / (mass * c.k_el));
  const double Vy2 = (c.f_y * c.f_y - c.f_0 * c.f_0) / (mass * c.k_el);  // Nan (75), may be < 0
  v.always_yields = Vy2 < 0;
  v.V_y = v.always_yields ? 0.0 : std::sqrt(Vy2);
  v.yields_before_sticking = v.V_y < v.V_s;  // Nan (77)
  if (!v.yields_before_sticking) {
    v.V_ys = v.V_s;
    v.f_max = 0;
    return v;
  }
  const double cohesive_factor = std::sqrt(1.0 + 56.0 / 81.0 * c.el_over_cl);  // k_e/k_c = k_el/k_cl
  double f_max = c.f_y;
  v.converged = false;
  for (int it = 1; it <= max_iter; ++it) {
    const double alpha_max = c.alpha_y + (f_max - c.f_y) / c.k_p;  // Nan (10)
    const Nan2022Unloading<double> u = nan2022_unloading(c, alpha_max, p.unloading_law, p.pull_off_law);
    const double next = u.f_cp * cohesive_factor;  // Nan (78)
    v.iterations = it;
    const double change = std::fabs(next - f_max);
    f_max = next;
    if (change <= rel_tol * f_max) {
      v.converged = true;
      break;
    }
  }
  v.f_max = f_max;
  // Nan (79): m V_ys^2 / 2 = m V_y^2 / 2 + (f_max^2 - f_y^2) / (2 k_p), with V_y^2 signed.
  const double V2 = Vy2 + (f_max * f_max - c.f_y * c.f_y) / (mass * c.k_p);
  v.V_ys = std::sqrt(V2 > 0 ? V2 : 0.0);
  return v;
}

}  // namespace epac
