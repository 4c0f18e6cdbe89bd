// JKR detachment from the contact's state alone, whatever the host's neighbour list keeps: from
// deep adhesive contact, one step beyond the displacement-controlled critical overlap delta_c =
// -(3/4) (pi^2 Gamma^2 R* / E*^2)^(1/3) (jkr/detail/jkr_contact_radius.hpp; dd/dx = 0 of (B3))
// gives exactly zero force and a reset history, and a re-approach is a new contact (it forms at
// delta >= 0); one step to just inside delta_c still pulls with about -5/9 f_ce (the force
// approaches it like the square root of the distance to delta_c).
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/jkr/jkr.hpp>

#include "../mdr/contact_stepper.hpp"

#include <cmath>

using namespace epac;

namespace {
Material jkr_material(double E, double nu, double gamma) {
  Material m;
  m.name = "p";
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.density = 1350;
  m.surface_energy = gamma;
  m.friction = 0.3;
  return m;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("jkr detachment: one step past delta_c releases and resets, pair and wall", "[jkr][detach]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Jkr<T, Effects<kAdhesion | kFriction | kDamping>, D>;
  Material wall;
  wall.name = "wall";
  wall.rigid = true;
  const Material a = jkr_material(1.2e9, 0.3, 0.2), b = jkr_material(5e9, 0.25, 0.5);
  const M model = M::create({a, b, wall});
  const double R0 = 2.45e-6, R1 = 7e-6;
  const double eps = sizeof(T) >= 8 ? 1e-6 : 2e-3;  // float: position round-off ~1e-4 |delta_c| here
  for (const bool pair : {true, false}) {
    INFO((pair ? "pair" : "wall"));
    const PairProperties pp = pair_properties(a, pair ? b : wall);
    const double R_star = pair ? R0 * R1 / (R0 + R1) : R0;
    const JkrScales<double> sc = jkr_scales(pp.surface_energy, R_star, pp.E_star);
    const double dc = jkr_critical_overlap_ratio<double>() * sc.delta_s;
    CHECK(dc == Approx(-0.75 * std::cbrt(M_PI * M_PI * pp.surface_energy * pp.surface_energy * R_star /
                                         (pp.E_star * pp.E_star)))
                    .epsilon(1e-12));
    CAPTURE(dc);
    auto fresh = [&] { return test::ContactStepper<M>(model, R0, pair ? R1 : -1.0, 0, pair ? 1 : 2); };
    std::vector<double> load;
    for (int k = 0; k <= 40; ++k) load.push_back(5.0 * sc.delta_s * k / 40.0);  // deep: 5 delta_s
    const double back = 0.5 * sc.delta_s;
    test::ContactStepper<M> ref = fresh();
    ref.step(0.0);
    const double F_fresh_back = ref.step(back);
    for (const double target : {-200.0 * R0, dc * (1 + eps), dc * (1 - eps)}) {
      INFO("jump to " << target);
      test::ContactStepper<M> s = fresh();
      for (double d : load) s.step(d);
      {  // in contact: the last root and the contact's R*^(1/3), taken when it formed
        const auto h = s.history();
        CHECK(h[M::root_field] > 0.0);
        CHECK(h[M::r13_field] == Approx(std::cbrt(R_star)).epsilon(sizeof(T) >= 8 ? 1e-14 : 1e-6));
      }
      const double F = s.step(target);
      const double seen = s.overlap();
      CHECK((seen < dc) == (target < dc));  // the kernel saw the intended side of delta_c
      if (seen < dc) {
        CHECK(F == 0.0);
        for (double x : s.history()) CHECK(x == 0.0);  // contact state, R*^(1/3) and tangential history
        CHECK(s.step(-0.5 * std::fabs(dc)) == 0.0);    // a new contact: not formed at a gap
        CHECK(s.step(back) == F_fresh_back);
      } else {
        CHECK(F == Approx(-5.0 / 9.0 * sc.f_ce).epsilon(sizeof(T) >= 8 ? 5e-3 : 0.1));
      }
    }
  }
}
