// The Nan 2022 normal force traced by driving the overlap through the loops of Nan Fig. 2:
// force continuous at every branch switch, first contact at alpha = 0 with -f_0, detachment at
// alpha_jp with -5/9 f_cp, re-contact at alpha_c0 with -8/9 f_cp, alpha_max kept by unloading and
// reloading below it; energy of closed cycles; the reduced cases (Gamma = 0, no yield).
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include "overlap_driver.hpp"
#include "paper_materials.hpp"

#include <cmath>
#include <algorithm>
#include <random>

using namespace epac;

namespace {

constexpr double kR = 2.45e-6;  // Ning's particle radius (R* on a wall)

Nan2022Options ning_options() {
  Nan2022Options o;
  o.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  o.k_p_ratio = 0.8;  // k_p < k_el so that the plastic line is distinguishable
  return o;
}

// Tolerances: the law is evaluated in T; forces carry a relative round-off of a few eps of T
// times the magnitudes that cancel (k alpha ~ f_ce).
template <class T>
double force_tol(double f_scale) {
  return (sizeof(T) == 4 ? 2e-5 : 1e-10) * f_scale;
}

// Every pair of consecutive samples on which the contact stayed active changes the force by no
// more than the steepest branch allows: no jump at any branch switch.
void check_continuous(const test::OverlapTrace& t, double k_max, double tol) {
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    if (!t.active[k] || !t.active[k + 1]) continue;
    const double df = std::fabs(t.f[k + 1] - t.f[k]);
    const double bound = k_max * std::fabs(t.alpha[k + 1] - t.alpha[k]) * (1 + 1e-3) + tol;
    if (df > bound) {
      INFO("jump at sample " << k << ": alpha " << t.alpha[k] << " -> " << t.alpha[k + 1] << ", f " << t.f[k] << " -> "
                             << t.f[k + 1]);
      CHECK(df <= bound);
      return;
    }
  }
}

// Index of the first sample >= from at which `active` changes to `to`.
std::size_t next_switch(const test::OverlapTrace& t, std::size_t from, int to) {
  for (std::size_t k = std::max<std::size_t>(from, 1); k < t.size(); ++k)
    if (t.active[k] == to && t.active[k - 1] != to) return k;
  return t.size();
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("nan2022 Fig. 2(a)-(b): elastic-adhesive loop without yield", "[nan2022][law]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  const auto opt = ning_options();
  const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const auto rep = nan2022_pair_report(pc, kR);
  REQUIRE(c.yields);
  REQUIRE(rep.alpha_je < rep.alpha_ce);
  REQUIRE(rep.alpha_ce < 0.0);
  const double step = c.alpha_0 / 4000;
  std::vector<double> a{-0.5 * c.alpha_0};
  test::ramp(a, 0.0, step);                            // hits alpha = 0 exactly
  test::ramp(a, 0.5 * (c.alpha_0 + c.alpha_y), step);  // below yield
  const std::size_t peak = a.size() - 1;
  test::ramp(a, rep.alpha_je - 0.5 * std::fabs(rep.alpha_je), step);
  test::ramp(a, 0.5 * c.alpha_0, step);
  const auto t = test::drive_overlap(model, a, kR, /*pair=*/1);
  const double tol = force_tol<T>(c.f_ce);
  const double k_cl = rep.k_cl;

  check_continuous(t, std::max(c.k_el, k_cl), tol);
  for (std::size_t k = 0; k < t.size(); ++k) CHECK(t.history0[k] == 0);  // never yields

  // Fig. 2(a): nothing before alpha = 0, then -f_0 at alpha = 0.
  const std::size_t k1 = next_switch(t, 0, 1);
  REQUIRE(k1 < t.size());
  CHECK(t.alpha[k1] == 0.0);
  CHECK(t.f[k1] == Approx(-c.f_0).margin(tol));
  for (std::size_t k = 0; k < k1; ++k) CHECK(t.f[k] == 0);
  // elastic line k_el(alpha - alpha_0) up to the turning point
  CHECK(t.f[peak] == Approx(c.k_el * (t.alpha[peak] - c.alpha_0)).margin(tol));
  CHECK(t.k_n[peak] == Approx(c.k_el).epsilon(1e-5));

  // Fig. 2(b): pull-off -f_ce at alpha_ce, cohesive branch k_cl, detachment at alpha_je, -5/9 f_ce.
  double fmin = 0;
  for (double f : t.f) fmin = std::min(fmin, f);
  CHECK(fmin == Approx(-c.f_ce).margin(c.k_el * step + tol));
  const std::size_t kd = next_switch(t, peak, 0);
  REQUIRE(kd < t.size());
  CHECK(t.alpha[kd - 1] >= rep.alpha_je - 1e-6 * std::fabs(rep.alpha_je));
  CHECK(t.alpha[kd] < rep.alpha_je + 1e-6 * std::fabs(rep.alpha_je));
  CHECK(t.f[kd - 1] == Approx(-5.0 / 9.0 * c.f_ce).margin(k_cl * step + tol));
  CHECK(t.k_n[kd - 1] == Approx(k_cl).epsilon(1e-4));
  // reload: apart until alpha_c0 = 0, then -8/9 f_ce = -f_0 again
  const std::size_t kr = next_switch(t, kd, 1);
  REQUIRE(kr < t.size());
  CHECK(t.alpha[kr] == Approx(0.0).margin(step));
  CHECK(t.alpha[kr - 1] < 0.0);
  CHECK(t.f[kr] == Approx(-c.f_0).margin(c.k_el * step + tol));
}

TEMPLATE_LIST_TEST_CASE("nan2022 Fig. 2(c): yield, unloading with k_e(alpha_max), detachment at alpha_jp < 0",
                        "[nan2022][law]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  const auto opt = ning_options();
  const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const double a_max = c.alpha_y + 0.3 * (c.alpha_y - c.alpha_0);
  const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
  REQUIRE(u.alpha_jp < 0.0);  // this loop detaches at negative overlap
  REQUIRE(u.k_e > c.k_el);
  REQUIRE(u.f_cp > c.f_ce);  // Nan Sec. 3.4: plastic flattening raises the pull-off force
  const double step = c.alpha_0 / 4000;
  std::vector<double> a{-0.1 * c.alpha_0};
  test::ramp(a, a_max, step);
  const std::size_t peak = a.size() - 1;
  test::ramp(a, u.alpha_jp - 0.5 * std::fabs(u.alpha_jp), step);
  test::ramp(a, 0.5 * c.alpha_0, step);
  const auto t = test::drive_overlap(model, a, kR, 1);
  const double tol = force_tol<T>(u.f_cp);
  check_continuous(t, std::max(u.k_e, u.k_c), tol);

  // loading: k_el below alpha_y, k_p above, force continuous through f_y at alpha_y
  for (std::size_t k = 1; k <= peak; ++k) {
    if (!t.active[k]) continue;
    if (t.alpha[k] < c.alpha_y * (1 - 1e-5)) CHECK(t.k_n[k] == Approx(c.k_el).epsilon(1e-5));
    if (t.alpha[k] > c.alpha_y * (1 + 1e-5)) CHECK(t.k_n[k] == Approx(c.k_p).epsilon(1e-5));
  }
  CHECK(t.f[peak] == Approx(c.f_y + c.k_p * (a_max - c.alpha_y)).margin(tol));
  CHECK(t.history0[peak] == Approx(a_max).epsilon(1e-6));
  // unloading line: k_e, zero force at alpha_p (Nan (16)), pull-off -f_cp, detachment -5/9 f_cp
  CHECK(t.k_n[peak + 1] == Approx(u.k_e).epsilon(1e-4));
  std::size_t kz = peak;
  while (kz < t.size() && t.f[kz] > 0) ++kz;
  REQUIRE(kz < t.size());
  CHECK(t.alpha[kz] == Approx(u.alpha_p).margin(step));
  double fmin = 0;
  for (double f : t.f) fmin = std::min(fmin, f);
  CHECK(fmin == Approx(-u.f_cp).margin(u.k_e * step + tol));
  const std::size_t kd = next_switch(t, peak, 0);
  REQUIRE(kd < t.size());
  CHECK(t.alpha[kd - 1] >= u.alpha_jp - 1e-6 * std::fabs(u.alpha_jp));
  CHECK(t.alpha[kd] < u.alpha_jp + 1e-6 * std::fabs(u.alpha_jp));
  CHECK(t.f[kd - 1] == Approx(-5.0 / 9.0 * u.f_cp).margin(u.k_c * step + tol));
  // detached at negative overlap: the pair has separated, so the plastic history is dropped and
  // the next contact is a first contact again (alpha = 0, -f_0)
  CHECK(t.history0[kd] == 0);
  const std::size_t kr = next_switch(t, kd, 1);
  REQUIRE(kr < t.size());
  CHECK(t.alpha[kr] == Approx(0.0).margin(step));
  CHECK(t.f[kr] == Approx(-c.f_0).margin(c.k_el * step + tol));
}

TEMPLATE_LIST_TEST_CASE("nan2022 Fig. 2(d): detachment at alpha_jp > 0, re-contact at alpha_c0 with -8/9 f_cp",
                        "[nan2022][law]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  const auto opt = ning_options();
  const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const double a_max = 20 * c.alpha_y;
  const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
  REQUIRE(u.alpha_jp > 0.0);
  // ordering of the critical overlaps, Nan Fig. 1
  CHECK(u.alpha_jp < u.alpha_cp);
  CHECK(u.alpha_cp < u.alpha_c0);
  CHECK(u.alpha_c0 < u.alpha_p);
  CHECK(u.alpha_p < u.alpha_max);
  const double step = (a_max - u.alpha_jp) / 20000;
  std::vector<double> a{0.0};
  test::ramp(a, a_max, step);
  const std::size_t peak = a.size() - 1;
  // an unload-reload below alpha_max without detachment
  test::ramp(a, u.alpha_p, step);
  test::ramp(a, a_max, step);
  const std::size_t peak2 = a.size() - 1;
  test::ramp(a, 0.5 * u.alpha_jp, step);  // detaches, stays overlapping
  const std::size_t bottom = a.size() - 1;
  test::ramp(a, a_max, step);
  const std::size_t peak3 = a.size() - 1;
  const double a_max2 = a_max * 1.1;
  test::ramp(a, a_max2, step);  // yields again
  const auto t = test::drive_overlap(model, a, kR, 1);
  const double tol = force_tol<T>(u.f_cp + c.f_y);
  const auto u2 = nan2022_unloading(c, a_max2, pc.unloading_law, pc.pull_off_law);
  check_continuous(t, std::max(u2.k_e, u2.k_c), tol);

  const double amax_tol = 1e-6 * a_max;
  for (std::size_t k = peak; k <= peak3; ++k) CHECK(t.history0[k] == Approx(a_max).margin(amax_tol));
  CHECK(t.f[peak2] == Approx(t.f[peak]).margin(tol));  // elastic unload-reload is reversible
  const std::size_t kd = next_switch(t, peak2, 0);
  REQUIRE(kd <= bottom);
  CHECK(t.alpha[kd] > 0.0);
  CHECK(t.f[kd - 1] == Approx(-5.0 / 9.0 * u.f_cp).margin(u.k_c * step + tol));
  CHECK(t.alpha[kd - 1] == Approx(u.alpha_jp).margin(step + 1e-6 * u.alpha_jp));
  const std::size_t kr = next_switch(t, bottom, 1);
  REQUIRE(kr < peak3);
  for (std::size_t k = kd; k < kr; ++k) {
    CHECK(t.f[k] == 0);
    CHECK(t.active[k] == 0);
  }
  CHECK(t.alpha[kr] == Approx(u.alpha_c0).margin(step + 1e-6 * u.alpha_c0));
  CHECK(t.alpha[kr - 1] < u.alpha_c0 + 1e-6 * u.alpha_c0);
  CHECK(t.f[kr] == Approx(-8.0 / 9.0 * u.f_cp).margin(u.k_e * step + tol));
  CHECK(t.k_n[kr] == Approx(u.k_e).epsilon(1e-4));
  CHECK(t.f[peak3] == Approx(t.f[peak]).margin(tol));
  // past alpha_max: plastic again, alpha_max follows the overlap
  CHECK(t.history0.back() == Approx(a_max2).epsilon(1e-6));
  CHECK(t.k_n.back() == Approx(c.k_p).epsilon(1e-5));
  CHECK(t.f.back() == Approx(c.f_y + c.k_p * (a_max2 - c.alpha_y)).margin(tol));
}

TEMPLATE_LIST_TEST_CASE("nan2022 energy: closed cycles never return more work than was put in",
                        "[nan2022][law][energy]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  const auto opt = ning_options();
  const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const auto rep = nan2022_pair_report(pc, kR);

  SECTION("unyielded: the adhesive hysteresis is exactly W_0 = W_JKR (Nan (35))") {
    const double step = c.alpha_0 / 20000;
    std::vector<double> a{0.0};
    test::ramp(a, c.alpha_0, step);
    const std::size_t start = a.size() - 1;
    test::ramp(a, rep.alpha_je - 0.1 * std::fabs(rep.alpha_je), step);
    test::ramp(a, c.alpha_0, step);
    const auto t = test::drive_overlap(model, a, kR, 1);
    const double w = test::work_in(t, start);
    // discretisation: each jump costs at most f step (two jumps)
    CHECK(w == Approx(rep.W_jkr).margin(2 * c.f_ce * step + 1e-4 * rep.W_jkr));
    CHECK(w > 0);
  }
  SECTION("yielded: loop from alpha_max through detachment costs W_6 (Nan (A7)); reversals cost 0") {
    const double a_max = 20 * c.alpha_y;
    const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
    const double W6 = 56.0 / 162.0 * u.f_cp * u.f_cp / u.k_c + 17.0 / 162.0 * u.f_cp * u.f_cp / u.k_e;
    const double step = (a_max - u.alpha_jp) / 20000;
    std::vector<double> a{0.0};
    test::ramp(a, a_max, step);
    const std::size_t start = a.size() - 1;
    // random reversals inside [alpha_jp - ..., alpha_max], ending back at alpha_max; count the
    // detach-reattach loops, each of which must cost exactly W_6
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pick(u.alpha_jp - 0.2 * (u.alpha_cp - u.alpha_jp), a_max);
    REQUIRE(pick.min() > 0);  // stays overlapping: the plastic history is kept
    for (int r = 0; r < 12; ++r) test::ramp(a, pick(rng), step);
    test::ramp(a, u.alpha_jp - 0.1 * (u.alpha_cp - u.alpha_jp), step);  // at least one detachment
    test::ramp(a, a_max, step);
    const auto t = test::drive_overlap(model, a, kR, 1);
    int detachments = 0;
    for (std::size_t k = start + 1; k < t.size(); ++k) detachments += (t.active[k - 1] && !t.active[k]);
    REQUIRE(detachments >= 1);
    for (std::size_t k = start; k < t.size(); ++k) CHECK(t.history0[k] == Approx(a_max).epsilon(1e-6));
    const double w = test::work_in(t, start);
    CHECK(w >= -1e-6 * W6);
    CHECK(w == Approx(detachments * W6).margin(detachments * 2 * u.f_cp * step + 1e-4 * W6));
  }
  SECTION("first loading and unloading to alpha_p: net work W_2 - W_1 + W_3 (Nan (A2)-(A4))") {
    // W_1 is released at jump-in (here f_y < f_0, so W_2 - W_1 < 0); W_3 is the plastic work
    const double a_max = 5 * c.alpha_y;
    const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
    const double step = a_max / 40000;
    std::vector<double> a{0.0};
    test::ramp(a, a_max, step);
    test::ramp(a, u.alpha_p, step);
    const auto t = test::drive_overlap(model, a, kR, 1);
    const double f_max = c.f_y + c.k_p * (a_max - c.alpha_y);
    const double W1 = c.f_0 * c.f_0 / (2 * c.k_el), W2 = c.f_y * c.f_y / (2 * c.k_el);
    const double W3 = (f_max * f_max - c.f_y * c.f_y) / (2 * c.k_p) - f_max * f_max / (2 * u.k_e);
    CHECK(W3 > 0);
    CHECK(test::work_in(t) == Approx(W2 - W1 + W3).margin(1e-4 * (W2 + W1 + W3)));
  }
}

TEMPLATE_LIST_TEST_CASE("nan2022 damping and tangential stiffness follow the branch and the yield state",
                        "[nan2022][law]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  auto opt = ning_options();
  auto particle = test::ning_particle();
  particle.restitution = 0.5;
  const Model model = Model::create({particle, test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(particle, test::rigid_wall(), opt);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const double gamma = -std::log(0.5) / std::sqrt(M_PI * M_PI + std::log(0.5) * std::log(0.5));  // Nan (26)
  std::vector<double> a{0.0};
  test::ramp(a, 0.5 * c.alpha_y, c.alpha_y / 100);
  const std::size_t before = a.size() - 1;
  test::ramp(a, 3 * c.alpha_y, c.alpha_y / 100);
  test::ramp(a, 2 * c.alpha_y, c.alpha_y / 100);
  const auto t = test::drive_overlap(model, a, kR, 1);
  CHECK(t.damping[before] == Approx(2 * gamma).epsilon(1e-5));
  CHECK(t.damping.back() == Approx(2 * gamma * 0.1).epsilon(1e-5));
  for (std::size_t k = 0; k < t.size(); ++k) CHECK(t.k_t[k] == Approx(pc.kt_over_kn * t.k_n[k]).epsilon(1e-5));
  CHECK(pc.kt_over_kn == Approx(4 * (1.2e9 / 2.6 / 1.7) / (1.2e9 / 0.91)).epsilon(1e-12));  // 4 G*/E*, rigid wall
}

TEMPLATE_LIST_TEST_CASE("nan2022 reduced cases: Gamma = 0 and no yield give finite, simpler laws",
                        "[nan2022][law][edge]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const auto all_finite = [](const test::OverlapTrace& t) {
    for (std::size_t k = 0; k < t.size(); ++k)
      if (!std::isfinite(t.f[k]) || !std::isfinite(t.k_n[k]) || !std::isfinite(t.history0[k]) ||
          !std::isfinite(t.damping[k]) || !std::isfinite(t.k_t[k]))
        return false;
    return true;
  };
  SECTION("Gamma = 0: elasto-plastic, no tension, contact only while alpha >= alpha_p") {
    using Model = Nan2022<T, AllEffects, D>;
    auto particle = test::ning_particle();
    particle.surface_energy = 0;
    const auto opt = ning_options();
    const Model model = Model::create({particle, test::rigid_wall()}, opt);
    const auto pc = nan2022_pair_constants(particle, test::rigid_wall(), opt);
    const auto c = nan2022_contact_constants<double>(pc, kR);
    CHECK(c.f_ce == 0);
    CHECK(c.alpha_0 == 0);
    CHECK(std::isfinite(c.el_over_cl));
    CHECK(std::isfinite(c.A));
    const auto rep = nan2022_pair_report(pc, kR);
    CHECK(std::isfinite(rep.k_cl));
    CHECK(std::isfinite(rep.cohesion_yield_number));
    const double a_max = 10 * c.alpha_y;
    const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
    CHECK(u.f_cp == 0);
    CHECK(u.alpha_jp == u.alpha_p);
    CHECK(u.alpha_c0 == u.alpha_p);
    std::vector<double> a{-c.alpha_y};
    test::ramp(a, a_max, c.alpha_y / 200);
    test::ramp(a, -c.alpha_y, c.alpha_y / 200);
    test::ramp(a, a_max, c.alpha_y / 200);
    const auto t = test::drive_overlap(model, a, kR, 1);
    CHECK(all_finite(t));
    for (std::size_t k = 0; k < t.size(); ++k) {
      CHECK(t.f[k] >= -force_tol<T>(c.f_y));
      if (t.alpha[k] < 0) CHECK(t.active[k] == 0);
    }
    check_continuous(t, u.k_e, force_tol<T>(c.f_y));
  }
  SECTION("no yield (p_y infinite): one elastic-adhesive line, alpha_max never set") {
    using Model = Nan2022<T, AllEffects, D>;
    auto particle = test::ning_particle();
    particle.yield_stress = std::numeric_limits<double>::infinity();
    auto opt = ning_options();
    CHECK_THROWS_AS(Model::create({particle, test::rigid_wall()}, opt), ParameterError);  // (52) needs p_y
    opt.k_el_from = Nan2022ElasticStiffnessFrom::stiffness_pressure;
    opt.stiffness_pressure = 35.3e6;
    const Model model = Model::create({particle, test::rigid_wall()}, opt);
    const auto pc = nan2022_pair_constants(particle, test::rigid_wall(), opt);
    const auto c = nan2022_contact_constants<double>(pc, kR);
    CHECK_FALSE(c.yields);
    const auto rep = nan2022_pair_report(pc, kR);
    CHECK(rep.cohesion_yield_number == nan2022_unbounded);
    CHECK_FALSE(rep.adhesion_induced_yield);
    std::vector<double> a{-c.alpha_0};
    test::ramp(a, 1000 * c.alpha_0, c.alpha_0 / 10);
    test::ramp(a, -c.alpha_0, c.alpha_0 / 10);
    const auto t = test::drive_overlap(model, a, kR, 1);
    CHECK(all_finite(t));
    for (std::size_t k = 0; k < t.size(); ++k) {
      CHECK(t.history0[k] == 0);
      if (t.active[k] && t.alpha[k] > 0) CHECK(t.k_n[k] == Approx(c.k_el).epsilon(1e-5));
    }
    const std::size_t top =
        static_cast<std::size_t>(std::max_element(t.alpha.begin(), t.alpha.end()) - t.alpha.begin());
    CHECK(t.f[top] == Approx(c.k_el * (1000 * c.alpha_0 - c.alpha_0)).epsilon(1e-5));
  }
  SECTION("effects compiled out: no history, f = k_el alpha for alpha > 0") {
    using Model = Nan2022<T, Effects<0>, D>;
    static_assert(Model::history_size == 0, "no effect, no history");
    const auto opt = ning_options();
    const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
    const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
    const double k_el = M_PI * kR * pc.yield_pressure;
    std::vector<double> a{-1e-8};
    test::ramp(a, 1e-6, 1e-9);
    test::ramp(a, -1e-8, 1e-9);
    const auto t = test::drive_overlap(model, a, kR, 1);
    CHECK(all_finite(t));
    for (std::size_t k = 0; k < t.size(); ++k) {
      CHECK(t.active[k] == (t.alpha[k] >= 0 ? 1 : 0));
      CHECK(t.f[k] == Approx(t.active[k] ? k_el * t.alpha[k] : 0.0).margin(force_tol<T>(k_el * 1e-6)));
      CHECK(t.damping[k] == 0);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("nan2022 radii 1e-7 m to 1e-1 m: the device law in T agrees with the host law in double",
                        "[nan2022][law][edge]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  const auto opt = ning_options();
  const Model model = Model::create({test::ning_particle(), test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
  for (double R : {1e-7, 1e-5, 1e-3, 1e-1}) {
    const auto c = nan2022_contact_constants<double>(pc, R);
    const auto u = nan2022_unloading(c, 30 * c.alpha_y, pc.unloading_law, pc.pull_off_law);
    const double step = (30 * c.alpha_y - u.alpha_jp) / 3000;
    std::vector<double> a{-c.alpha_0};
    test::ramp(a, 30 * c.alpha_y, step);
    test::ramp(a, u.alpha_jp - 10 * step, step);
    test::ramp(a, 40 * c.alpha_y, step);
    const auto t = test::drive_overlap(model, a, R, 1);
    // reference: the same state machine on the host in double
    double amax = 0, cs = 0, worst = 0;
    const double f_scale = c.f_y + c.k_p * (40 * c.alpha_y - c.alpha_y);
    for (std::size_t k = 0; k < t.size(); ++k) {
      const auto s = nan2022_normal_step<double>(c, a[k], amax, cs, pc.unloading_law, pc.pull_off_law);
      REQUIRE(std::isfinite(t.f[k]));
      // a branch switch may fall one sample apart in float: compare away from the switch overlaps
      if (s.active != (t.active[k] != 0)) continue;
      worst = std::max(worst, std::fabs(t.f[k] - s.f) / f_scale);
    }
    INFO("R = " << R << ": worst |f_T - f_double| / f_max = " << worst);
    CHECK(worst < (sizeof(T) == 4 ? 1e-5 : 1e-12));  // float: ~100 eps of accumulated round-off
    check_continuous(t, std::max(u.k_e, u.k_c) * std::sqrt(40.0 / 30.0), force_tol<T>(f_scale));
  }
}

TEMPLATE_LIST_TEST_CASE("nan2022 clamped cohesive branch (k_el/k_cl formula < 0 at CY ~ 1e-4) stays finite",
                        "[nan2022][law][edge]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Nan2022<T, AllEffects, D>;
  auto particle = test::ning_particle();
  particle.yield_stress = 3.53e6;  // CY = 3e-4: the linear elastic branch alone exceeds W_JKR
  const auto opt = ning_options();
  const Model model = Model::create({particle, test::rigid_wall()}, opt);
  const auto pc = nan2022_pair_constants(particle, test::rigid_wall(), opt);
  const auto rep = nan2022_pair_report(pc, kR);
  REQUIRE(rep.cohesive_ratio_clamped);
  CHECK(rep.el_over_cl == 0);
  CHECK(rep.alpha_je == rep.alpha_ce);
  const auto c = nan2022_contact_constants<double>(pc, kR);
  const auto u = nan2022_unloading(c, 5 * c.alpha_y, pc.unloading_law, pc.pull_off_law);
  CHECK(u.alpha_jp == u.alpha_cp);
  CHECK(std::isfinite(u.k_c));
  const double step = 5 * c.alpha_y / 5000;
  std::vector<double> a{0.0};
  test::ramp(a, 5 * c.alpha_y, step);
  test::ramp(a, u.alpha_jp - 10 * step, step);
  const auto t = test::drive_overlap(model, a, kR, 1);
  for (std::size_t k = 0; k < t.size(); ++k) {
    CHECK(std::isfinite(t.f[k]));
    CHECK(std::isfinite(t.k_n[k]));
  }
  // without a cohesive branch the contact detaches at the pull-off point, -f_cp
  const std::size_t kd = next_switch(t, 1, 0);
  REQUIRE(kd < t.size());
  CHECK(t.f[kd - 1] == Approx(-u.f_cp).margin(u.k_e * step + force_tol<T>(u.f_cp)));
}

// Nan2022LineHistory keeps the unloading line (k_e, alpha_p) of the contact's alpha_max between
// steps; it must give exactly what the line taken anew gives (the same expression on the same
// inputs), always be the line of the present alpha_max when kept (so forgotten at every change of
// it), be known after an unloading step of a contact that was in contact, and leave a separated
// contact's history all zero (test_nan2022_detachment.cpp).
TEMPLATE_TEST_CASE("nan2022 unloading line kept in history equals the line taken anew, bitwise",
                   "[nan2022][law][history]", double, float) {
  using T = TestType;
  const auto opt = ning_options();
  for (int law : {static_cast<int>(Nan2022UnloadingLaw::plastic_offset),
                  static_cast<int>(Nan2022UnloadingLaw::sqrt_max_overlap)}) {
    auto pc = nan2022_pair_constants(test::ning_particle(), test::rigid_wall(), opt);
    pc.unloading_law = law;
    const auto cd = nan2022_contact_constants<double>(pc, kR);
    const Nan2022PairConstants<T> pt = nan2022_pair_constants_in<T>(pc);
    const Nan2022ContactConstants<T> c = nan2022_contact_constants<T>(pt, T(kR));
    // random load cycles: each to a peak (below or past the last alpha_max) and back to a trough
    // (still loaded, in the cohesive branch, past detachment, or apart), with jittered steps
    std::mt19937 rng(7 + law);
    std::uniform_real_distribution<double> u01(0, 1);
    std::vector<double> path{-cd.alpha_0};
    for (int cycle = 0; cycle < 300; ++cycle) {
      const double peak = (0.5 + 40 * u01(rng)) * cd.alpha_y;
      const auto line = nan2022_unloading(cd, std::max(peak, cd.alpha_y), pc.unloading_law, pc.pull_off_law);
      const double troughs[] = {line.alpha_p + 0.5 * (peak - line.alpha_p), 0.5 * (line.alpha_cp + line.alpha_jp),
                                line.alpha_jp - 0.1 * cd.alpha_y, -0.5 * cd.alpha_y};
      test::ramp(path, peak, (0.05 + 0.2 * u01(rng)) * cd.alpha_y);
      test::ramp(path, troughs[rng() % 4], (0.05 + 0.2 * u01(rng)) * cd.alpha_y);
    }
    T amax_a = 0, cs_a = 0, amax_b = 0, cs_b = 0, k_e = 0, alpha_p = 0;
    int forgotten = 0, kept = 0, reused = 0, branches[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < path.size(); ++k) {
      const T a = T(path[k] * (1 + 1e-3 * (u01(rng) - 0.5)));
      const T amax_before = amax_b;
      const T k_e_before = k_e;
      const T cs_before = cs_b;
      const auto sa = nan2022_normal_step<T>(c, a, amax_a, cs_a, pc.unloading_law, pc.pull_off_law);
      const auto sb =
          nan2022_normal_step<T>(c, a, amax_b, cs_b, pc.unloading_law, pc.pull_off_law,
                                 nan2022_detail::CohesiveConstantsGiven{}, Nan2022LineHistory<T>{k_e, alpha_p});
      REQUIRE(sa.f == sb.f);
      REQUIRE(sa.k_n == sb.k_n);
      REQUIRE(sa.active == sb.active);
      REQUIRE(sa.branch == sb.branch);
      REQUIRE(amax_a == amax_b);
      REQUIRE(cs_a == cs_b);
      if (amax_b != amax_before) ++forgotten;
      if (k_e > 0) {  // a kept line is always the line of the present alpha_max
        Nan2022Unloading<T> fresh;
        nan2022_unloading_line(c, amax_b, pc.unloading_law, fresh);
        REQUIRE(k_e == fresh.k_e);
        REQUIRE(alpha_p == fresh.alpha_p);
      }
      ++branches[sb.branch];
      if ((sb.branch == 2 || sb.branch == 3) && cs_before != 0) {
        REQUIRE(k_e > 0);  // an unloading step of a contact that was in contact knows its line
        ++kept;
        if (k_e_before > 0) ++reused;
      }
    }
    INFO("unloading law " << law << ": " << forgotten << " forgotten, " << kept << " unloading steps, " << reused
                          << " of them from history; steps apart / plastic / elastic / cohesive " << branches[0]
                          << " / " << branches[1] << " / " << branches[2] << " / " << branches[3]);
    for (int b = 0; b < 4; ++b) CHECK(branches[b] > 100);  // every branch of the state machine
    CHECK(forgotten > 100);
    CHECK(reused > 1000);
  }
}
