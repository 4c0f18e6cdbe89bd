// Nan 2022 detachment from the contact's state alone, whatever the host's list keeps: a contact
// loaded past yield and then moved in one step beyond its detachment overlap alpha_jp (Nan (14), on
// the unloading line of its alpha_max) gives exactly zero force and a reset history (the pair has
// separated, Nan Sec. 2.1), and a re-approach is a first contact; one step to just inside alpha_jp
// still pulls.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include "../mdr/contact_stepper.hpp"
#include "paper_materials.hpp"

#include <cmath>

using namespace epac;

TEMPLATE_LIST_TEST_CASE("nan2022 detachment: one step past alpha_jp releases and resets, pair and wall",
                        "[nan2022][law][detach]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Nan2022<T, AllEffects, D>;
  Nan2022Options opt;
  opt.yield_pressure_from = Nan2022YieldPressureFrom::given_pressure;
  opt.k_p_ratio = 0.8;
  const Material ning = test::ning_particle(), other = test::table5_particle(35.3e6), wall = test::rigid_wall();
  const M model = M::create({ning, other, wall}, opt);
  const double R = 2.45e-6;
  // float: the kernel's overlap carries ~1e-7 R of position round-off, ~1e-4 of |alpha_jp| here
  const double eps = sizeof(T) >= 8 ? 1e-6 : 2e-3;
  for (const bool pair : {true, false}) {
    INFO((pair ? "pair" : "wall"));
    const double R_star = pair ? R * R / (R + R) : R;
    const auto pc = nan2022_pair_constants(ning, pair ? other : wall, opt);
    const auto c = nan2022_contact_constants<double>(pc, R_star);
    REQUIRE(c.yields);
    const double a_max = c.alpha_y + 0.3 * (c.alpha_y - c.alpha_0);  // past yield
    const auto u = nan2022_unloading(c, a_max, pc.unloading_law, pc.pull_off_law);
    const double jp = u.alpha_jp;
    CAPTURE(jp);
    REQUIRE(jp < 0.0);
    auto fresh = [&] { return test::ContactStepper<M>(model, R, pair ? R : -1.0, 0, pair ? 1 : 2); };
    std::vector<double> load;
    for (int k = 1; k <= 50; ++k) load.push_back(a_max * k / 50.0);
    const double back = 0.5 * c.alpha_y;
    test::ContactStepper<M> ref = fresh();
    ref.step(-1e-3 * R);  // apart first: the contact forms at alpha >= 0 (first contact)
    const double F_fresh_back = ref.step(back);
    for (const double target : {-200.0 * R, jp * (1 + eps), jp * (1 - eps)}) {
      INFO("jump to " << target);
      test::ContactStepper<M> s = fresh();
      for (double d : load) s.step(d);
      REQUIRE(s.history()[M::alpha_max_field] > c.alpha_y);  // yielded
      const double F = s.step(target);
      const double seen = s.overlap();
      CHECK((seen < jp) == (target < jp));  // the kernel saw the intended side of alpha_jp
      const std::vector<double> h = s.history();
      if (seen < jp) {
        CHECK(F == 0.0);
        for (double x : h) CHECK(x == 0.0);  // alpha_max, state and tangential: a new contact
        CHECK(s.step(back) == F_fresh_back);
      } else {
        // the cohesive branch, Nan (19): between -f_cp (at alpha_cp) and -5/9 f_cp (at alpha_jp)
        CHECK(F < 0.0);
        CHECK(F == Approx(-5.0 / 9.0 * u.f_cp).epsilon(sizeof(T) >= 8 ? 1e-4 : 1e-2));
      }
    }
  }
}
