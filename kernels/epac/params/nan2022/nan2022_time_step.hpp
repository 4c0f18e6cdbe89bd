#pragma once
// Time step for the Nan et al. 2022 model, Nan Sec. 3.5 (host side).
#include <epac/params/validation.hpp>

#include <cmath>

namespace epac {

// Nan (68): critical step of a mass m on a spring k_e.
inline double nan2022_critical_time_step(double mass, double k_e) {
  require_positive("mass", mass);
  require_positive("k_e", k_e);
  return 2.0 * std::sqrt(mass / k_e);
}

// Nan (70): Nan (68) with the Hertz bound k_e <= 2 E R sqrt(alpha_max/R) (Nan (69)) and
// m = 4/3 pi R^3 rho.
inline double nan2022_critical_time_step_hertz_bound(double R, double density, double E, double alpha_max) {
  require_positive("R", R);
  require_positive("density", density);
  require_positive("E", E);
  require_positive("alpha_max", alpha_max);
  return M_PI * R * std::sqrt(density / E) * std::sqrt(8.0 / (3.0 * M_PI)) * std::pow(alpha_max / R, -0.25);
}

// Nan (71): Rayleigh time step.
inline double nan2022_rayleigh_time_step(double R, double density, double G, double nu) {
  require_positive("R", R);
  require_positive("density", density);
  require_positive("G", G);
  require_range("poisson_ratio", nu, -1.0, Bound::open, 0.5, Bound::open);
  return M_PI * R / (0.1631 * nu + 0.8766) * std::sqrt(density / G);
}

// Nan (72): (70)/(71) with G = E / (2 (1 + nu)), since
// sqrt(8/(3 pi)) / sqrt(2 (1 + nu)) = sqrt(4/(3 pi)) / sqrt(1 + nu).
inline double nan2022_critical_to_rayleigh_ratio(double nu, double alpha_max_over_R) {
  require_range("poisson_ratio", nu, -1.0, Bound::open, 0.5, Bound::open);
  require_positive("alpha_max / R", alpha_max_over_R);
  return (0.1631 * nu + 0.8766) / std::sqrt(1.0 + nu) * std::sqrt(4.0 / (3.0 * M_PI)) *
         std::pow(alpha_max_over_R, -0.25);
}

}  // namespace epac
