// Host-side parameter derivation of Nan et al. 2022 (Sec. 3): Table 3, the Nan (80) constant,
// CY of Sec. 5, yield pressure, time step, pull-off laws and validation.
#include <catch2/catch.hpp>
#include <epac/params/nan2022/nan2022_parameters.hpp>
#include <epac/params/nan2022/nan2022_time_step.hpp>

#include "paper_materials.hpp"

#include <cmath>

using namespace epac;

namespace {
Nan2022Options table3_options(Nan2022UnloadingLaw law, double k_e0, double alpha_max0, double R, double k_p) {
  Nan2022Options o;
  o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  o.k_el_from = Nan2022ElasticStiffnessFrom::unloading_line;
  o.k_e0 = k_e0;
  o.alpha_max0 = alpha_max0;
  o.reference_radius = R;
  o.unloading_law = law;
  o.k_p = k_p;
  return o;
}
struct Table3Row {
  double k_el, alpha_y, alpha_0, el_over_cl, k_hertz;
};
void check_table3(const Material& particle, double R, double k_e0, double alpha_max0, double k_p,
                  Nan2022UnloadingLaw law, const Table3Row& paper) {
  const auto pc = nan2022_pair_constants(particle, test::rigid_wall(), table3_options(law, k_e0, alpha_max0, R, k_p));
  const auto r = nan2022_pair_report(pc, R);
  INFO("k_el " << r.k_el << " alpha_y " << r.alpha_y << " alpha_0 " << r.alpha_0 << " k_el/k_cl " << r.el_over_cl
               << " k_H(alpha_y) " << r.k_hertz_at_yield);
  // Table 3 prints 2-3 significant digits: 2% covers the rounding and the digitised inputs.
  CHECK(r.k_el == Approx(paper.k_el).epsilon(0.02));
  CHECK(r.alpha_y == Approx(paper.alpha_y).epsilon(0.02));
  CHECK(r.alpha_0 == Approx(paper.alpha_0).epsilon(0.02));
  // k_el/k_cl is printed with 2 digits (1.8 for Ning is 1.74 by Nan (35)-(37)): 5%.
  CHECK(r.el_over_cl == Approx(paper.el_over_cl).epsilon(0.05));
  if (paper.k_hertz > 0) CHECK(r.k_hertz_at_yield == Approx(paper.k_hertz).epsilon(0.02));
  // the iteration's fixed point satisfies Nan (45)/(49) and (29) together
  const double root = std::sqrt(r.alpha_y / alpha_max0);
  const double k45 = law == Nan2022UnloadingLaw::plastic_offset ? k_p + (k_e0 - k_p) * root : k_e0 * root;
  CHECK(r.k_el == Approx(k45).epsilon(1e-10));
}
}  // namespace

TEST_CASE("nan2022 Table 3: k_el, alpha_y, alpha_0, k_el/k_cl from the measured unloading line",
          "[nan2022][params][paper]") {
  const double Rn = 2.45e-6, Rd = 4e-6;
  SECTION("Ning, Nan (44)-(45)") {
    check_table3(test::ning_particle(), Rn, 1274, 210.5e-9, 0, Nan2022UnloadingLaw::sqrt_max_overlap,
                 {283, 10.4e-9, 7.3e-9, 1.8, 416});
  }
  SECTION("Du, Nan (44)-(45)") {
    check_table3(test::du_particle(), Rd, 4.2e5, 53.7e-9, 0, Nan2022UnloadingLaw::sqrt_max_overlap,
                 {6.7e4, 1.35e-9, 0.25e-9, 3.9, 0});
  }
  SECTION("Ning, Nan (48)-(49)") {
    check_table3(test::ning_particle(), Rn, 1274, 210.5e-9, 217, Nan2022UnloadingLaw::plastic_offset,
                 {418, 7.5e-9, 4.9e-9, 2.7, 353});
  }
  SECTION("Du, Nan (48)-(49)") {
    // alpha_0 = 0.08 nm is printed with one digit (0.0807 by the model): 2% of 0.08 still holds
    check_table3(test::du_particle(), Rd, 4.2e5, 53.7e-9, 1.8e5, Nan2022UnloadingLaw::plastic_offset,
                 {2.1e5, 0.71e-9, 0.08e-9, 12.6, 0});
  }
  SECTION("Nan (52): k_el = pi R* p_y = 2 E* sqrt(R* alpha_y0), Table 1's pi R* p_y") {
    Nan2022Options o;
    o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
    const auto pn = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), o);
    const auto pd = nan2022_pair_constants(test::du_particle(), test::rigid_wall(), o);
    CHECK(nan2022_pair_report(pn, Rn).k_el == Approx(272).epsilon(0.005));
    CHECK(nan2022_pair_report(pd, Rd).k_el == Approx(6.94e4).epsilon(0.005));
    const double ay0 = M_PI * M_PI * Rn * 35.3e6 * 35.3e6 / (4 * pn.E_star * pn.E_star);  // Nan (31)
    CHECK(2 * pn.E_star * std::sqrt(Rn * ay0) == Approx(M_PI * Rn * 35.3e6).epsilon(1e-12));
  }
}

TEST_CASE("nan2022 Table 3 k_cl: the model's adhesive work equals W_JKR (Nan (35)-(37))", "[nan2022][params]") {
  Nan2022Options o;
  o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), o);
  for (double R : {1e-7, 2.45e-6, 1e-4, 1e-2}) {
    const auto r = nan2022_pair_report(pc, R);
    CHECK_FALSE(r.cohesive_ratio_clamped);
    CHECK(r.W_0 == Approx(r.W_jkr).epsilon(1e-12));
    // the paper's rounded form (38), read right side up: 0.92 k_el/(Gamma^1/3 E*^2/3 R*^2/3) - 0.3
    const double approx = 0.92 * r.k_el / std::cbrt(0.2 * std::pow(pc.E_star * R, 2)) - 0.3;
    CHECK(r.el_over_cl == Approx(approx).epsilon(0.01 + 0.01 / r.el_over_cl));
  }
}

TEST_CASE("nan2022 Nan (80): adhesion-induced yield at p_y/E* = 0.90 (Gamma/(E* R*))^(1/3)",
          "[nan2022][params][paper]") {
  CHECK(nan2022_adhesion_yield_coefficient() == Approx(0.90).margin(0.005));  // printed to 2 digits
  // Independently: bisect on p_y for f_y(p_y) = f_0 with k_el by Nan (52), using the model's own
  // f_y (Nan (28)) and f_0 (Nan (4)).
  const double E = 1.3e9, R = 2.45e-6, G = 0.24;
  Nan2022PairConstants<double> p{};
  p.E_star = E;
  p.surface_energy = G;
  p.yields = 1;
  p.kel_fixed = 0;
  p.kp_value = 1;
  auto excess = [&](double py) {
    p.yield_pressure = py;
    p.kel_value = M_PI * py;
    const auto c = nan2022_contact_constants<double>(p, R);
    return c.f_y - c.f_0;
  };
  double lo = 1e5, hi = 1e9;
  REQUIRE(excess(lo) < 0);
  REQUIRE(excess(hi) > 0);
  for (int it = 0; it < 200; ++it) {
    const double m = std::sqrt(lo * hi);
    (excess(m) < 0 ? lo : hi) = m;
  }
  const double coef = lo / E / std::cbrt(G / (E * R));
  CHECK(coef == Approx(nan2022_adhesion_yield_coefficient()).epsilon(1e-9));
  // and the report agrees: just below it, adhesion-induced yield; just above, not
  p.yield_pressure = 0.99 * lo;
  p.kel_value = M_PI * p.yield_pressure;
  CHECK(nan2022_pair_report(p, R).adhesion_induced_yield);
  CHECK(nan2022_pair_report(p, R).critical_yield_pressure == Approx(lo).epsilon(1e-9));
  p.yield_pressure = 1.01 * lo;
  p.kel_value = M_PI * p.yield_pressure;
  CHECK_FALSE(nan2022_pair_report(p, R).adhesion_induced_yield);
  // at the threshold CY = coefficient^3 = 0.74 (CY < 1 is the paper's rounded criterion)
  CHECK(nan2022_cohesion_yield_number(lo, R, E, G) ==
        Approx(std::pow(nan2022_adhesion_yield_coefficient(), 3)).epsilon(1e-9));
}

TEST_CASE("nan2022 CY (Nan (81)) for the FT4 particles, Tables 7-8: 4.2 and 0.5", "[nan2022][params][paper]") {
  Material m;
  m.name = "ft4 particle";
  m.youngs_modulus = 63e6;
  m.poisson_ratio = 0.2;
  m.density = 2500;
  m.yield_stress = 0.5e6;
  Nan2022Options o;
  o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  const double R = 0.25e-3, R_star = R / 2;  // particle-particle
  m.surface_energy = 3.5e-3;
  const auto r1 = nan2022_pair_report(nan2022_pair_constants(m, m, o), R_star);
  m.surface_energy = 27e-3;
  const auto r2 = nan2022_pair_report(nan2022_pair_constants(m, m, o), R_star);
  INFO("CY " << r1.cohesion_yield_number << ", " << r2.cohesion_yield_number);
  // The paper prints 4.2 (we get 4.146: 1.3% below, rounding of its E* or R*) and 0.5 (one digit;
  // we get 0.54): 2% and the one-digit rounding interval.
  CHECK(r1.cohesion_yield_number == Approx(4.2).epsilon(0.02));
  CHECK(r2.cohesion_yield_number >= 0.45);
  CHECK(r2.cohesion_yield_number < 0.55);
  CHECK_FALSE(r1.adhesion_induced_yield);
  CHECK(r2.adhesion_induced_yield);
  // "close to f_y0/f_ce, which is 1.1 times CY" (Sec. 4): f_y0/f_ce = pi^2/9 CY exactly
  const double fy0 = std::pow(M_PI, 3) * R_star * R_star * std::pow(0.5e6, 3) / (6 * std::pow(63e6 / 1.92, 2));
  CHECK(fy0 / r1.f_ce == Approx(M_PI * M_PI / 9 * r1.cohesion_yield_number).epsilon(1e-12));
}

TEST_CASE("nan2022 yield pressure from yield stress, Nan (32)-(34) and Fig. 5", "[nan2022][params]") {
  for (double nu = 0.2; nu <= 0.4001; nu += 0.05) {
    const double jg = nan2022_yield_pressure_from_stress(1.0, nu, Nan2022YieldPressureFrom::jackson_green);
    const double ch = nan2022_yield_pressure_from_stress(1.0, nu, Nan2022YieldPressureFrom::chang);
    CHECK(jg == Approx(ch).epsilon(0.01));  // Fig. 5: "almost the same ratio"
    CHECK(jg >= 1.4);
    CHECK(jg <= 1.75);
  }
  CHECK(nan2022_yield_pressure_from_stress(7.0, 0.3, Nan2022YieldPressureFrom::given_pressure) == 7.0);
  CHECK(nan2022_strain_rate_yield_stress(100.0, 0.1, 2.0, 2.0) == Approx(100.0));
  CHECK(nan2022_strain_rate_yield_stress(100.0, 0.1, std::exp(1.0), 1.0) == Approx(110.0));
  CHECK_THROWS_AS(nan2022_strain_rate_yield_stress(100.0, 1.0, 1e-3, 1.0), ParameterError);  // negative
  CHECK_THROWS_AS(nan2022_strain_rate_yield_stress(100.0, 0.1, 0.0, 1.0), ParameterError);   // ln(0)
  // the strain-rate option flows into p_y
  Material m = test::ning_particle();
  Nan2022Options o;
  o.strain_rate_Y = 0.1;
  o.strain_rate_V_i = std::exp(1.0);
  o.strain_rate_V_0 = 1.0;
  CHECK(nan2022_material_yield_pressure(m, o) ==
        Approx(1.1 * nan2022_yield_pressure_from_stress(35.3e6, 0.3, Nan2022YieldPressureFrom::jackson_green)));
}

TEST_CASE("nan2022 time step, Nan (68)-(72)", "[nan2022][params]") {
  const double R = 1e-3, rho = 2500, E = 1e8;
  for (double nu : {0.2, 0.3, 0.4}) {
    const double G = E / (2 * (1 + nu));
    const double ratio =
        nan2022_critical_time_step_hertz_bound(R, rho, E, 0.1 * R) / nan2022_rayleigh_time_step(R, rho, G, nu);
    CHECK(ratio == Approx(nan2022_critical_to_rayleigh_ratio(nu, 0.1)).epsilon(1e-12));
    CHECK(ratio >= 0.9);  // Sec. 3.5: 0.9-1.0 at alpha_max/R = 0.1
    CHECK(ratio <= 1.0);
  }
  // (70) is (68) with the Hertz stiffness bound (69)
  const double m = 4.0 / 3.0 * M_PI * R * R * R * rho, a = 0.01 * R;
  CHECK(nan2022_critical_time_step(m, 2 * E * R * std::sqrt(a / R)) ==
        Approx(nan2022_critical_time_step_hertz_bound(R, rho, E, a)).epsilon(1e-12));
  CHECK_THROWS_AS(nan2022_critical_time_step(m, 0.0), ParameterError);
}

TEST_CASE("nan2022 pull-off laws reduce to f_ce before yield and satisfy their equations after", "[nan2022][params]") {
  Nan2022Options o;
  o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  o.k_p_ratio = 0.8;
  auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), o);
  const double R = 2.45e-6;
  const auto c = nan2022_contact_constants<double>(pc, R);
  for (int law = 0; law < 3; ++law) {
    for (int ul = 0; ul < 2; ++ul) {
      const auto u0 = nan2022_unloading(c, 0.0, ul, law);
      CHECK(u0.f_cp == c.f_ce);
      CHECK(u0.alpha_c0 == Approx(0.0).margin(1e-12 * c.alpha_0));
      // just past yield the general forms join the unyielded ones continuously
      const auto ue = nan2022_unloading(c, c.alpha_y * (1 + 1e-9), ul, law);
      CHECK(ue.f_cp == Approx(c.f_ce).epsilon(1e-6));
      CHECK(ue.alpha_p == Approx(c.alpha_0).epsilon(1e-6));
      CHECK(ue.k_e == Approx(c.k_el).epsilon(1e-6));
    }
  }
  const double am = 10 * c.alpha_y;
  const auto u59 = nan2022_unloading(c, am, 0, 0);
  // Nan (58) in its dimensionless form (alpha_0 > 0 here)
  const double x = u59.f_cp / c.f_ce, kr = u59.k_e / c.k_el;
  CHECK(x * x + c.A * x - (u59.alpha_p / c.alpha_0 * c.A + 1) * kr == Approx(0.0).margin(1e-10 * x * x));
  CHECK(u59.f_cp > c.f_ce);
  CHECK(u59.k_e == Approx(c.k_el * std::sqrt(10 * c.alpha_y / c.alpha_y)).epsilon(1e-12));  // Nan (46)
  // Nan (16) = Nan (11)
  const double a11 =
      (1 - c.k_p / u59.k_e) * (am - c.alpha_y) + (1 - c.k_el / u59.k_e) * (c.alpha_y - c.alpha_0) + c.alpha_0;
  CHECK(u59.alpha_p == Approx(a11).epsilon(1e-12));
  const auto u64 = nan2022_unloading(c, am, 0, 1);
  CHECK(u64.f_cp ==
        Approx(c.f_ce * (c.f_y + u64.k_e * (am - c.alpha_y)) / (c.f_y + c.k_p * (am - c.alpha_y))).epsilon(1e-12));
  const auto u67 = nan2022_unloading(c, am, 0, 2);
  CHECK(u67.f_cp == Approx(c.f_ce * std::pow(u67.k_e / c.k_el, 1.5)).epsilon(1e-12));
  const auto u48 = nan2022_unloading(c, am, 1, 0);
  CHECK(u48.k_e == Approx(c.k_p + (c.k_el - c.k_p) * std::sqrt(10.0)).epsilon(1e-12));  // Nan (48)
}

TEST_CASE("nan2022 validation names the parameter, its value and the valid range", "[nan2022][params][validation]") {
  const Material p = test::ning_particle(), w = test::rigid_wall();
  Nan2022Options o;
  o.k_p_ratio = 1.5;
  CHECK_THROWS_WITH(nan2022_pair_constants(p, w, o),
                    Catch::Contains("k_p_ratio") && Catch::Contains("1.5") && Catch::Contains("(0, 1]"));
  o = Nan2022Options{};
  o.beta_yielded = -0.1;
  CHECK_THROWS_WITH(nan2022_pair_constants(p, w, o), Catch::Contains("beta_yielded"));
  o = Nan2022Options{};
  o.k_el_from = Nan2022ElasticStiffnessFrom::unloading_line;
  CHECK_THROWS_WITH(nan2022_pair_constants(p, w, o), Catch::Contains("reference_radius"));
  o.reference_radius = 2.45e-6;
  CHECK_THROWS_WITH(nan2022_pair_constants(p, w, o), Catch::Contains("k_e0"));
  o = Nan2022Options{};
  o.k_el_from = Nan2022ElasticStiffnessFrom::fixed;
  CHECK_THROWS_WITH(nan2022_pair_constants(p, w, o), Catch::Contains("k_el"));
  Material bad = p;
  bad.surface_energy = -1;
  CHECK_THROWS_WITH(nan2022_pair_constants(bad, w, Nan2022Options{}), Catch::Contains("surface_energy"));
  Nan2022PairConstants<double> pc = nan2022_pair_constants(p, w, Nan2022Options{});
  pc.pull_off_law = 5;
  CHECK_THROWS_WITH(nan2022_validate(pc, "x"), Catch::Contains("pull_off_law") && Catch::Contains("5"));
}
