// MDR adhesive detachment from the contact's state alone (detachment at the critical overlap, docs/stability.md): a pair or wall contact
// loaded plastically into adhesive contact and then moved in one step past its critical overlap
// (mdr_detachment.hpp) gives exactly zero force and a reset history, and a re-approach is a new
// contact; one step to just inside the critical overlap still pulls.
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace epac;
using namespace epac::test;

namespace {
template <class M, bool G>
double critical_overlap_of(const ContactStepper<M, G>& s) {
  return s.evaluate(CriticalOverlap{});
}

bool all_zero(const std::vector<double>& v) {
  for (double x : v)
    if (x != 0.0) return false;
  return true;
}

// JKR's critical overlap under displacement control for E (E* or E_eff), R (R* or R), gamma.
double jkr_delta_c(double E, double R, double gamma) {
  return -0.75 * std::cbrt(M_PI * M_PI * gamma * gamma * R / (E * E));
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR detachment: one step past the critical overlap releases and resets, pair and wall",
                        "[mdr][adhesion][detach]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion | kFriction>, D>;
  // Mixed materials (E 1e7 and 3e7 Pa, E/Y 20 and 40, surface energies 300 and 600 J/m^2), radii 1
  // and 2 mm: both sides yield on the way to 0.1 R0, and the critical overlap stays below 0.
  const double R0 = 1e-3, R1 = 2e-3;
  Material a = mdr_material(1e7, 0.3, 1e7 / 20, 300.0, 1.0), b = mdr_material(3e7, 0.25, 3e7 / 40, 600.0, 1.0);
  a.friction = 0.5;
  b.friction = 0.5;
  const M model = M::create({a, b, rigid_wall_material()});
  // float: the kernel's overlap carries ~1e-7 R0 of position round-off, ~1e-5 of |delta_c| here
  const double eps = sizeof(T) >= 8 ? 1e-6 : 1e-3;
  for (const bool pair : {true, false}) {
    INFO((pair ? "pair" : "wall"));
    auto fresh = [&] { return ContactStepper<M>(model, R0, pair ? R1 : -1.0, 0, pair ? 1 : 2); };
    std::vector<double> load;
    append_ramp(load, 0.0, 0.1 * R0, 60);
    const double back = 0.05 * R0;
    ContactStepper<M> ref = fresh();
    const double F_fresh_back = ref.step(back);  // a new contact at the re-approach overlap
    REQUIRE(F_fresh_back > 0);

    // the critical overlap after the load: below 0, inside the driver's adhesive range (sum over
    // the sides of sqrt(2 pi R gamma_s / E_eff), drivers/driver/models/mdr.cpp)
    ContactStepper<M> probe = fresh();
    for (double d : load) probe.step(d);
    const std::vector<double> loaded = probe.history();
    REQUIRE(loaded[M::side_base(0) + 1] != 0.0);  // side 0 yielded
    const double dc = critical_overlap_of(probe);
    CAPTURE(dc);
    REQUIRE(dc < 0);
    const PairProperties pp = pair_properties(a, pair ? b : rigid_wall_material());
    auto bound = [&](const Material& m, double R) {
      const double Eeff = m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio);
      return std::sqrt(2 * M_PI * R * pp.surface_energy * pp.E_star / Eeff / Eeff);
    };
    CHECK(-dc < bound(a, R0) + (pair ? bound(b, R1) : 0.0));

    // Where a single jump from the loaded state stops pulling. A wall's one side holds down to its
    // critical overlap. A pair's two sides are in series across a flat in (scaled) force balance
    // (mdr_pair_balance.hpp), so the pair lets go when its weaker side reaches its own critical
    // overlap, at or above the sum of the sides' (the release bound, which it must never pass):
    // found here by bisection over fresh jumps.
    double hold = dc;
    if (pair) {
      auto pulls = [&](double target) {
        ContactStepper<M> s = fresh();
        for (double d : load) s.step(d);
        return s.step(target) < 0.0;
      };
      double lo = dc, hi = 0.0;  // pulls at hi (just below contact), not at lo (released)
      REQUIRE(pulls(0.5 * dc));
      hi = 0.5 * dc;
      for (int it = 0; it < 60 && hi - lo > 1e-9 * -dc; ++it) {
        const double mid = 0.5 * (lo + hi);
        (pulls(mid) ? hi : lo) = mid;
      }
      hold = hi;
      CAPTURE(hold);
      CHECK(hold >= dc);  // never holds past the release bound
    }
    // a pair's letting go is decided by which equilibrium of the two sides the balance solve
    // reaches from a single jump (both attached, or the weaker side separated): sharp but not to
    // round-off, so the pair's "just inside" target keeps 1% of margin
    for (const double target : {-200.0 * R0, dc * (1 + eps), hold * (1 - (pair ? 1e-2 : eps))}) {
      INFO("jump to " << target);
      ContactStepper<M> s = fresh();
      for (double d : load) s.step(d);
      const double F = s.step(target);
      const double seen = s.overlap();
      CHECK((seen < dc) == (target < dc));  // the kernel saw the intended side of delta_c
      if (seen < dc) {
        CHECK(F == 0.0);
        CHECK(all_zero(s.history()));  // normal and tangential history: a new contact next time
        CHECK(s.step(back) == F_fresh_back);
      } else {
        CHECK(F < 0.0);  // still adhesive: pulls
        CHECK(!all_zero(s.history()));
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("MDR detachment: elastic critical overlaps are JKR's (sphere on a wall, two equal spheres)",
                        "[mdr][adhesion][detach]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kAdhesion>, D>;
  const double E = 1e7, nu = 0.3, R = 1e-3, Eeff = E / (1 - nu * nu), gamma = 2.0;
  const M model =
      M::create({mdr_material(E, nu, std::numeric_limits<double>::infinity(), gamma), rigid_wall_material()});
  // a_c / R ~ 0.03 here: the ellipse g_1D = 2R - 2 sqrt(R^2 - a^2) is JKR's a^2/R to (a/R)^2 ~ 1e-3
  const double tol = 3e-3;
  ContactStepper<M> wall(model, R, -1.0, 0, 1);
  wall.step(0.01 * R);
  CHECK(critical_overlap_of(wall) == Approx(jkr_delta_c(Eeff, R, gamma)).epsilon(tol));
  // two equal spheres: E* = E_eff/2, R* = R/2 (each side holds gamma/2 against E_eff)
  ContactStepper<M> pair(model, R, R, 0, 0);
  pair.step(0.01 * R);
  CHECK(critical_overlap_of(pair) == Approx(jkr_delta_c(Eeff / 2, R / 2, gamma)).epsilon(tol));
}

namespace {
// Random mixed pairs and walls (E 1e5-1e12 Pa, E/Y 1.6-1e5, radii 1e-7-1e-1 m with ratios to 100,
// surface energy 1e-3-1 E* R): load, partly unload, one step to 200 radii.
template <class D, class T, bool Growth>
void detachment_fuzz(int n) {
  using M = Mdr<T, Effects<kPlasticity | kAdhesion | (Growth ? kRadiusGrowth : 0u)>, D>;
  std::mt19937_64 rng(20240610);
  std::uniform_real_distribution<double> U(0, 1);
  auto lg = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * U(rng)); };
  int released = 0, cases = 0;
  for (int k = 0; k < n; ++k) {
    const bool pair = k % 2 == 0;
    const double Ea = lg(5, 12), Eb = lg(5, 12), R0 = lg(-7, -1), R1 = R0 * lg(0, 2);
    const double Es = 1 / (1 / Ea + 1 / Eb);
    const Material a = mdr_material(Ea, 0.3, Ea / lg(0.2, 5), lg(-3, 0) * Es * R0);
    const Material b = mdr_material(Eb, 0.3, Eb / lg(0.2, 5), lg(-3, 0) * Es * R0);
    const M model = M::create({a, b, rigid_wall_material()});
    ContactStepper<M, Growth> s(model, R0, pair ? R1 : -1.0, 0, pair ? 1 : 2);
    const double dm = 0.6 * R0 * U(rng);
    std::vector<double> path;
    append_ramp(path, 0.0, dm, 1 + int(40 * U(rng)));
    append_ramp(path, dm, dm * (1 - 2 * U(rng)), 1 + int(40 * U(rng)));
    bool finite = true;
    for (double d : path) finite = finite && std::isfinite(s.step(d));
    if (!finite || !s.radii_finite())
      continue;  // the path itself (MDR finite for every accepted input), not detachment
    ++cases;
    INFO("case " << k << (pair ? " pair" : " wall") << " E " << Ea << " " << Eb << " R " << R0 << " " << R1);
    // the critical overlap lies within the driver's adhesive range (drivers/driver/models/mdr.cpp:
    // sum over the sides of sqrt(2 pi R gamma_s / E_eff), radius cap 1 without growth)
    const PairProperties pp = pair_properties(a, pair ? b : rigid_wall_material());
    auto bound = [&](const Material& m, double R) {
      const double Eeff = m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio);
      return std::sqrt(2 * M_PI * R * pp.surface_energy * pp.E_star / Eeff / Eeff);
    };
    const double range = Growth ? 0.0 : bound(a, R0) + (pair ? bound(b, R1) : 0.0);
    if (!Growth) CHECK(-critical_overlap_of(s) <= range * (1 + (sizeof(T) >= 8 ? 1e-12 : 1e-5)));
    const double F = s.step(-200 * R0);
    CHECK(F == 0.0);
    CHECK(all_zero(s.history()));
    released += F == 0.0;
  }
  CHECK(cases > (Growth ? n / 2 : 3 * n / 4));
  CHECK(released == cases);
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("MDR detachment fuzz: random mixed pairs and walls, path, one step to 200 radii",
                        "[mdr][adhesion][detach][fuzz]", BackendsAndScalars) {
  detachment_fuzz<typename TestType::device, typename TestType::scalar, false>(200);
  // with radius growth (the setting); paths that go non-finite before the jump are item 0's
  detachment_fuzz<typename TestType::device, typename TestType::scalar, true>(200);
}

TEMPLATE_LIST_TEST_CASE(
    "MDR critical displacement at the edges: finite, in [-Delta l(B/2), 0], a side holds above it only",
    "[mdr][adhesion][detach][guard]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  // lambda = E A^2 / (pi gamma B) of the critical-radius cubic from 1e-12 (adhesion dominates: a_c
  // -> B/2) to 1e12 (a_c -> 0, d_c -> 0-), on an elastic (A = 2B) and a flat plastic (A = 0.01 B) ellipse
  const int n = 25;
  Kokkos::View<double**, Kokkos::LayoutRight, D> o("o", 2 * n, 5);
  Kokkos::View<double*, D> lam("lambda", n);
  {
    auto hl = Kokkos::create_mirror_view(lam);
    for (int k = 0; k < n; ++k) hl(k) = std::pow(10.0, -12.0 + 24.0 * k / (n - 1));
    Kokkos::deep_copy(lam, hl);
  }
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        for (int shape = 0; shape < 2; ++shape)
          for (int k = 0; k < n; ++k) {
            const T E = T(1), B = T(2), A = shape == 0 ? T(4) : T(0.02);
            const T lambda = T(lam(k));
            const T gamma = E * A * A / (constants<T>::pi * lambda * B);
            const T dc = mdr_critical_displacement(E, gamma, A, B);
            o(shape * n + k, 0) = dc;
            o(shape * n + k, 1) = mdr_critical_extension(E, gamma, T(0.5) * B);
            // the side law just above and just below d_c, from a stored a = B/2 (deepest contact)
            const T step = math::max(T(1e-3) * math::fabs(dc), T(1e-30));
            o(shape * n + k, 2) = mdr_adhesive_force(E, gamma, T(1), A, B, dc + step, T(0.5) * B).F;
            o(shape * n + k, 3) = mdr_adhesive_force(E, gamma, T(1), A, B, dc - step, T(0.5) * B).F;
            o(shape * n + k, 4) = mdr_adhesive_force(E, gamma, T(1), A, B, dc - step, T(0.5) * B).state;
          }
      });
  auto h = to_host(o);
  for (int r = 0; r < 2 * n; ++r) {
    INFO("row " << r << " d_c " << h(r, 0));
    REQUIRE(std::isfinite(h(r, 0)));
    CHECK(h(r, 0) <= 0.0);
    CHECK(h(r, 0) >= -h(r, 1) * (1 + 1e-5));  // d_c >= -Delta l(B/2): the driver's range bound
    CHECK(h(r, 3) == 0.0);                    // below d_c: separated, no force
    CHECK(h(r, 4) == kMdrSeparated);
    if (h(r, 0) < -1e-20) CHECK(h(r, 2) < 0.0);  // above d_c: still pulls
  }
}
