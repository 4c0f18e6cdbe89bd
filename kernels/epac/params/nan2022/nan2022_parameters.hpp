#pragma once
// Host-side parameter derivation for the Nan et al. 2022 model (Nan Sec. 3): yield pressure from
// yield stress (Nan (32)-(34)), the loading stiffness k_el (Nan (52), or from a measured unloading
// line by iterating Nan (29) with (45)/(49)), k_p, the per-pair constants table entry, its
// validation, and a per-pair report at a given R* (f_y, alpha_y, k_cl, CY of Nan (81), the
// adhesion-induced yield criterion Nan (80)).
#include <epac/models/nan2022/detail/nan2022_unloading.hpp>
#include <epac/params/material.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/params/validation.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace epac {

// p_y from the compressive yield stress sigma_y.
enum class Nan2022YieldPressureFrom {
  jackson_green,   // p_y = 1.295 exp(0.736 nu) sigma_y          Nan (32), default
  chang,           // p_y = (0.454 + 0.41 nu) 2.8 sigma_y        Nan (33)
  given_pressure,  // Material::yield_stress already holds p_y
};

// Where k_el comes from.
enum class Nan2022ElasticStiffnessFrom {
  yield_pressure,      // k_el = pi R* p_y, Nan (52) (default; needs a finite p_y)
  stiffness_pressure,  // k_el = pi R* p_k with p_k = Nan2022Options::stiffness_pressure (Nan (52)
                       // form for pairs that do not yield, e.g. Nan Table 10's no-yield runs)
  fixed,               // k_el = Nan2022Options::k_el [N/m] for every contact
  unloading_line,      // measured (k_e0, alpha_max0) at R* = reference_radius: Nan (29) with (45)
                       // (or (49) with the plastic_offset unloading law), iterated
};

struct Nan2022Options {
  Nan2022YieldPressureFrom yield_pressure_from = Nan2022YieldPressureFrom::jackson_green;
  // Strain-rate yield stress, Nan (34): sigma_y = sigma_y^s (1 + Y ln(V_i/V_0)). Off when Y = 0.
  double strain_rate_Y = 0.0, strain_rate_V_i = 1.0, strain_rate_V_0 = 1.0;
  Nan2022ElasticStiffnessFrom k_el_from = Nan2022ElasticStiffnessFrom::yield_pressure;
  double stiffness_pressure = 0.0;                              // [Pa], for stiffness_pressure
  double k_el = 0.0;                                            // [N/m], for fixed
  double k_e0 = 0.0, alpha_max0 = 0.0, reference_radius = 0.0;  // for unloading_line [N/m, m, m]
  double k_p_ratio = 1.0;  // k_p = k_p_ratio k_el (Nan Sec. 3.3: k_p = k_el when unmeasured)
  double k_p = 0.0;        // [N/m]; > 0 overrides k_p_ratio with a fixed k_p
  Nan2022UnloadingLaw unloading_law = Nan2022UnloadingLaw::sqrt_max_overlap;
  Nan2022PullOffLaw pull_off_law = Nan2022PullOffLaw::work_balance;
  double beta_yielded = 0.1;  // damping factor after yield, Nan Sec. 2.3
};

// Nan (32) / (33).
inline double nan2022_yield_pressure_from_stress(double sigma_y, double nu, Nan2022YieldPressureFrom how) {
  if (how == Nan2022YieldPressureFrom::given_pressure) return sigma_y;
  if (how == Nan2022YieldPressureFrom::chang) return (0.454 + 0.41 * nu) * 2.8 * sigma_y;
  return 1.295 * std::exp(0.736 * nu) * sigma_y;
}

// Nan (34). Domain: V_i, V_0 > 0, and the result must stay positive.
inline double nan2022_strain_rate_yield_stress(double sigma_s, double Y, double V_i, double V_0) {
  require_positive("strain_rate_V_i", V_i);
  require_positive("strain_rate_V_0", V_0);
  const double s = sigma_s * (1.0 + Y * std::log(V_i / V_0));
  require_positive("strain-rate yield stress sigma_s (1 + Y ln(V_i/V_0))", s, /*allow_inf=*/true);
  return s;
}

// p_y of one body; +inf for a rigid body or one that does not yield.
inline double nan2022_material_yield_pressure(const Material& m, const Nan2022Options& o) {
  if (m.rigid || std::isinf(m.yield_stress)) return std::numeric_limits<double>::infinity();
  double sigma = m.yield_stress;
  if (o.strain_rate_Y != 0.0 && o.yield_pressure_from != Nan2022YieldPressureFrom::given_pressure)
    sigma = nan2022_strain_rate_yield_stress(sigma, o.strain_rate_Y, o.strain_rate_V_i, o.strain_rate_V_0);
  return nan2022_yield_pressure_from_stress(sigma, m.poisson_ratio, o.yield_pressure_from);
}

// k_el from a measured unloading line (k_e0 at alpha_max0), Nan (45) (sqrt law) or (49)
// (plastic_offset law, needs k_p), iterated with Nan (29) from alpha_y = alpha_y0 (Nan (31)).
struct Nan2022ElasticFromUnloading {
  double k_el = 0, alpha_y = 0, alpha_0 = 0;
  int iterations = 0;
  bool converged = false;
};

inline Nan2022ElasticFromUnloading nan2022_k_el_from_unloading(double E_star, double R_star, double gamma, double p_y,
                                                               double k_e0, double alpha_max0, Nan2022UnloadingLaw law,
                                                               double k_p = 0.0, int max_iter = 1000,
                                                               double rel_tol = 1e-13) {
  require_positive("E_star", E_star);
  require_positive("R_star", R_star);
  require_range("surface_energy", gamma, 0.0, Bound::closed, std::numeric_limits<double>::infinity(), Bound::open);
  require_positive("yield_pressure (unloading_line needs a finite p_y)", p_y);
  require_positive("k_e0", k_e0);
  require_positive("alpha_max0", alpha_max0);
  if (law == Nan2022UnloadingLaw::plastic_offset)
    require_range("k_p (Nan (49) needs 0 < k_p < k_e0)", k_p, 0.0, Bound::open, k_e0, Bound::open);
  Nan2022PairConstants<double> p{};
  p.E_star = E_star;
  p.surface_energy = gamma;
  p.yield_pressure = p_y;
  p.yields = 1;
  p.kel_fixed = 1;
  p.kp_fixed = 0;
  p.kp_value = 1.0;
  Nan2022ElasticFromUnloading r;
  double alpha_y = M_PI * M_PI * R_star * p_y * p_y / (4.0 * E_star * E_star);  // Nan (31)
  for (int it = 1; it <= max_iter; ++it) {
    const double root = std::sqrt(alpha_y / alpha_max0);
    p.kel_value = law == Nan2022UnloadingLaw::plastic_offset ? k_p + (k_e0 - k_p) * root : k_e0 * root;
    const Nan2022ContactConstants<double> c = nan2022_contact_constants<double>(p, R_star);
    const double change = std::fabs(c.alpha_y - alpha_y);
    alpha_y = c.alpha_y;
    r.k_el = c.k_el;
    r.alpha_y = c.alpha_y;
    r.alpha_0 = c.alpha_0;
    r.iterations = it;
    if (change <= rel_tol * alpha_y) {
      r.converged = true;
      break;
    }
  }
  if (!r.converged)                                                                                  // host
    throw ParameterError("k_el from unloading line: Nan (29)/(45) iteration did not converge in " +  // host
                         std::to_string(max_iter) + " iterations (k_e0 = " + std::to_string(k_e0) +  // host
                         ", alpha_max0 = " + std::to_string(alpha_max0) + ")");                      // host
  return r;
}

// Throws ParameterError naming the field, its value and the valid range.
inline void nan2022_validate(const Nan2022PairConstants<double>& p, const std::string& name) {  // host
  const double inf = std::numeric_limits<double>::infinity();
  const std::string n = name + ": ";  // host
  require_positive(n + "E_star", p.E_star);
  require_range(n + "surface_energy", p.surface_energy, 0.0, Bound::closed, inf, Bound::open);
  if (p.yields) require_positive(n + "yield_pressure", p.yield_pressure);
  require_positive(n + (p.kel_fixed ? "k_el" : "k_el / R* (pi p_y or pi p_k)"), p.kel_value);
  if (p.kp_fixed)
    require_positive(n + "k_p", p.kp_value);
  else
    require_range(n + "k_p_ratio", p.kp_value, 0.0, Bound::open, 1.0, Bound::closed);
  require_range(n + "unloading_law", p.unloading_law, 0, Bound::closed, 1, Bound::closed);
  require_range(n + "pull_off_law", p.pull_off_law, 0, Bound::closed, 2, Bound::closed);
  require_range(n + "kt_over_kn", p.kt_over_kn, 0.0, Bound::closed, inf, Bound::open);
  require_range(n + "damping_ratio", p.damping_ratio, 0.0, Bound::closed, 1.0, Bound::closed);
  require_range(n + "beta_yielded", p.beta_yielded, 0.0, Bound::closed, 1.0, Bound::closed);
  require_range(n + "friction", p.mu, 0.0, Bound::closed, inf, Bound::open);
}

// The pair-table entry for bodies a and b (validated).
inline Nan2022PairConstants<double> nan2022_pair_constants(const Material& a, const Material& b,
                                                           const Nan2022Options& o) {
  const std::string name = "nan2022 pair '" + a.name + "'-'" + b.name + "'";  // host
  a.validate();
  b.validate();
  require_range("beta_yielded", o.beta_yielded, 0.0, Bound::closed, 1.0, Bound::closed);
  const PairProperties pp = pair_properties(a, b);
  Nan2022PairConstants<double> p{};
  p.E_star = pp.E_star;
  p.surface_energy = pp.surface_energy;
  const double p_y = std::min(nan2022_material_yield_pressure(a, o), nan2022_material_yield_pressure(b, o));
  p.yields = std::isfinite(p_y) ? 1 : 0;
  p.yield_pressure = p.yields ? p_y : 0.0;
  switch (o.k_el_from) {
    case Nan2022ElasticStiffnessFrom::yield_pressure:
      if (!p.yields)  // host
        throw ParameterError(name +
                             ": k_el_from = yield_pressure (Nan (52)) needs a finite yield "              // host
                             "pressure, but this pair does not yield; use stiffness_pressure or fixed");  // host
      p.kel_fixed = 0;
      p.kel_value = M_PI * p_y;
      break;
    case Nan2022ElasticStiffnessFrom::stiffness_pressure:
      require_positive(name + ": stiffness_pressure", o.stiffness_pressure);
      p.kel_fixed = 0;
      p.kel_value = M_PI * o.stiffness_pressure;
      break;
    case Nan2022ElasticStiffnessFrom::fixed:
      require_positive(name + ": k_el", o.k_el);
      p.kel_fixed = 1;
      p.kel_value = o.k_el;
      break;
    case Nan2022ElasticStiffnessFrom::unloading_line: {
      require_positive(name + ": reference_radius", o.reference_radius);
      const auto r = nan2022_k_el_from_unloading(p.E_star, o.reference_radius, p.surface_energy, p_y, o.k_e0,
                                                 o.alpha_max0, o.unloading_law, o.k_p);
      p.kel_fixed = 1;
      p.kel_value = r.k_el;
      break;
    }
  }
  if (o.k_p > 0.0) {
    p.kp_fixed = 1;
    p.kp_value = o.k_p;
  } else {
    p.kp_fixed = 0;
    p.kp_value = o.k_p_ratio;
  }
  p.unloading_law = static_cast<int>(o.unloading_law);
  p.pull_off_law = static_cast<int>(o.pull_off_law);
  p.kt_over_kn = 4.0 * pp.G_star / pp.E_star;
  p.damping_ratio = linear_damping_ratio(pp.restitution);
  p.beta_yielded = o.beta_yielded;
  p.mu = pp.friction;
  nan2022_validate(p, name);
  return p;
}

// Nan (80): with k_el by Nan (52), f_y = f_0 at p_y/E* = c (Gamma/(E* R*))^(1/3),
// c = 2 pi^(-2/3) (5/6)^(1/6) = 0.9045 (the paper's 0.90).
inline double nan2022_adhesion_yield_coefficient() {
  return 2.0 * std::pow(M_PI, -2.0 / 3.0) * std::pow(5.0 / 6.0, 1.0 / 6.0);
}

// "Infinite" values of the report (no adhesion or no yield) are reported as this, not as inf.
constexpr double nan2022_unbounded = std::numeric_limits<double>::max();

// Cohesion-yield number, Nan (81), with the pair's E* and R*: CY = p_y^3 R* / (E*^2 Gamma).
inline double nan2022_cohesion_yield_number(double p_y, double R_star, double E_star, double gamma) {
  if (!(gamma > 0.0) || !std::isfinite(p_y)) return nan2022_unbounded;
  return p_y * p_y * p_y * R_star / (E_star * E_star * gamma);
}

// What the model does for a pair at one R*.
struct Nan2022PairReport {
  double R_star = 0;
  double f_ce = 0, f_0 = 0, k_el = 0, k_cl = 0, k_p = 0, f_y = 0;
  double alpha_0 = 0, alpha_y = 0, alpha_ce = 0, alpha_je = 0;
  double el_over_cl = 0;                // k_el/k_cl (0 without adhesion)
  bool cohesive_ratio_clamped = false;  // k_el/k_cl formula went negative (see nan2022_pair.hpp)
  double W_jkr = 0;                     // Nan (37)
  double W_0 = 0;                       // the linear law's adhesive work, Nan (35)/(A1): equals W_jkr
  double k_hertz_at_yield = 0;          // 2 E* sqrt(R* alpha_y), Nan (41) (Table 3)
  bool yields = false;
  double cohesion_yield_number = nan2022_unbounded;  // Nan (81)
  double critical_yield_pressure = 0;                // Nan (80) (k_el by (52)); 0 without adhesion
  bool adhesion_induced_yield = false;               // f_y < f_0: contact always yields once formed (CY < ~0.74)
};

inline Nan2022PairReport nan2022_pair_report(const Nan2022PairConstants<double>& p, double R_star) {
  require_positive("R_star", R_star);
  const Nan2022ContactConstants<double> c = nan2022_contact_constants<double>(p, R_star);
  Nan2022PairReport r;
  r.R_star = R_star;
  r.f_ce = c.f_ce;
  r.f_0 = c.f_0;
  r.k_el = c.k_el;
  r.k_p = c.k_p;
  r.f_y = c.f_y;
  r.alpha_0 = c.alpha_0;
  r.alpha_y = c.alpha_y;
  r.yields = c.yields;
  r.alpha_ce = c.alpha_0 - c.f_ce / c.k_el;  // Nan (8)
  r.el_over_cl = c.el_over_cl;
  r.k_cl = c.el_over_cl > 0 ? c.k_el / c.el_over_cl : 0.0;
  r.alpha_je = r.alpha_ce - 4.0 / 9.0 * c.f_ce / c.k_el * c.el_over_cl;  // Nan (9)
  const double g = p.surface_energy;
  if (g > 0) {
    const double raw = nan2022_detail::cohesive_ratio_coefficient<double>() * c.k_el /
                           (std::cbrt(g) * std::cbrt(p.E_star * R_star * p.E_star * R_star)) -
                       17.0 / 56.0;
    r.cohesive_ratio_clamped = raw < 0;
    r.W_jkr = 7.09 * std::cbrt(std::pow(g, 5) * std::pow(R_star, 4) / (p.E_star * p.E_star));
    r.W_0 = 56.0 / 162.0 * c.f_ce * c.f_ce / c.k_el * c.el_over_cl + 17.0 / 162.0 * c.f_ce * c.f_ce / c.k_el;
    r.critical_yield_pressure = nan2022_adhesion_yield_coefficient() * p.E_star * std::cbrt(g / (p.E_star * R_star));
  }
  r.k_hertz_at_yield = 2.0 * p.E_star * std::sqrt(R_star * c.alpha_y);
  if (c.yields) {
    r.cohesion_yield_number = nan2022_cohesion_yield_number(p.yield_pressure, R_star, p.E_star, g);
    r.adhesion_induced_yield = c.f_y < c.f_0;
  }
  return r;
}

}  // namespace epac
