// Contacts in lanes (compute/pair_lanes.hpp) against the one-contact kernel it replaces for
// Hertz-Mindlin and the linear spring, on every backend, double and float: blocks of 8 (the host
// form) and of 1 (the GPU form) give the one-contact kernel's forces, torques, history and
// outputs, whether or not this build vectorises them. The scene has what each stage must handle:
// touching and separated pairs, pairs listed against the global-id order (the history frame), a
// list length that is no multiple of 8 (the last block's idle lanes), sticking and sliding
// contacts (mu = 0: every loaded contact slides), coincident centres (no normal). With two
// materials, compute_pair_forces takes the one-contact kernel and the lanes kernel refuses.
// Tolerance: each lane evaluates the same expressions in the same order, so per-contact values
// agree to the last bit unless the compiler fuses multiply-adds differently in the vectorised
// loop (-march=native): a few ulps, so 1e-12 (double) / 2e-5 (float) of the largest magnitude
// of each quantity, over 5 passes. The particle sums add in a thread-dependent order (atomics):
// the same bound (at most 7 terms per particle, as tests/foundation/test_backend_agreement.cpp).
#include "pair_kernel_scene.hpp"

#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/linear_spring.hpp>

using namespace epac;
using namespace epac::test;

namespace {

template <class Model, class T, class D>
void compare_forms(const Model& model, double speed) {
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  auto scalar = run_passes<Model, T, D>(model, speed, [](auto&&... a) {
    detail::pair_kernel<Model::effects::friction>(a..., ContactForceBuffer<T, D>{});
  });
  auto lanes8 = run_passes<Model, T, D>(model, speed, [](auto&&... a) { detail::pair_kernel_lanes<8>(a...); });
  auto lanes1 = run_passes<Model, T, D>(model, speed, [](auto&&... a) { detail::pair_kernel_lanes<1>(a...); });
  auto dispatched = run_passes<Model, T, D>(model, speed, [](auto&&... a) { compute_pair_forces(a...); });
  // the scene has both touching and separated contacts, and real forces and torques
  const auto touching = std::count_if(scalar.overlap.begin(), scalar.overlap.end(), [](double d) { return d > 0; });
  REQUIRE(touching > 100);
  REQUIRE(touching < static_cast<long>(scalar.overlap.size()) - 100);
  REQUIRE(max_abs(scalar.force) > 0);
  if (Model::effects::friction) REQUIRE(max_abs(scalar.torque) > 0);
  for (const auto* other : {&lanes8, &lanes1, &dispatched}) {
    check_close(scalar.force, other->force, rel, "force");
    check_close(scalar.torque, other->torque, rel, "torque");
    check_close(scalar.history, other->history, rel, "history");
    check_close(scalar.normal_force, other->normal_force, rel, "normal force output");
    check_close(scalar.overlap, other->overlap, rel, "overlap output");
  }
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("contacts in lanes give the one-contact kernel's results", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  STATIC_REQUIRE(detail::runs_in_lanes<HertzMindlin<T, Effects<kFriction | kDamping>, D>>::value);
  STATIC_REQUIRE(detail::runs_in_lanes<LinearSpring<T, Effects<kFriction | kDamping>, D>>::value);
  STATIC_REQUIRE_FALSE(detail::runs_in_lanes<HertzMindlin<T, Effects<kFriction | kRolling>, D>>::value);
  for (double mu : {0.5, 0.0}) {         // 0: every loaded contact slides
    for (double speed : {1.0, 100.0}) {  // slow: mostly sticking; fast: many slide at mu 0.5
      CAPTURE(mu, speed);
      SECTION("Hertz-Mindlin, friction and damping") {
        compare_forms<HertzMindlin<T, Effects<kFriction | kDamping>, D>, T, D>(
            HertzMindlin<T, Effects<kFriction | kDamping>, D>::create(pair_materials<T>(mu)), speed);
      }
      SECTION("Hertz alone") {
        compare_forms<HertzMindlin<T, Effects<0>, D>, T, D>(
            HertzMindlin<T, Effects<0>, D>::create(pair_materials<T>(mu)), speed);
      }
      SECTION("linear spring, friction and damping") {
        compare_forms<LinearSpring<T, Effects<kFriction | kDamping>, D>, T, D>(
            LinearSpring<T, Effects<kFriction | kDamping>, D>::create(pair_materials<T>(mu), 1e5), speed);
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("contacts in lanes: two materials take the one-contact kernel", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
  const auto model = Model::create(pair_materials<T>(0.5, 2));
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  auto scalar = run_passes<Model, T, D>(
      model, 1.0, [](auto&&... a) { detail::pair_kernel<true>(a..., ContactForceBuffer<T, D>{}); });
  auto dispatched = run_passes<Model, T, D>(model, 1.0, [](auto&&... a) { compute_pair_forces(a...); });
  REQUIRE(max_abs(scalar.force) > 0);
  check_close(scalar.force, dispatched.force, rel, "force");
  check_close(scalar.torque, dispatched.torque, rel, "torque");
  check_close(scalar.history, dispatched.history, rel, "history");
  // the lanes kernel itself refuses them, on the host, before any kernel runs
  auto s = pair_scene<T, D>(1.0, 2);
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  const ForceSums<T, D, AtomicSums> sums(s.p);
  REQUIRE_THROWS_WITH(detail::pair_kernel_lanes<8>(model, s.p, s.c, h, T(1e-7), sums, ContactOutputs<T, D>{}),
                      Catch::Contains("model.nmat is 2"));
}

TEMPLATE_LIST_TEST_CASE("contacts in lanes: the sliding lanes are the one-contact kernel's", "[lanes]",
                        test::BackendsAndScalars) {
  // A test that would pass with a sliding stage that never runs is no test: after one pass with
  // mu 0.3 and fast sliding (|v| spans 1e-2..1e4 m/s: the slowest few stick) nearly every loaded
  // contact must be on its Coulomb limit (measured: 1856 of 1924).
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = HertzMindlin<T, Effects<kFriction>, D>;
  const auto model = Model::create(pair_materials<T>(0.3));
  auto s = pair_scene<T, D>(1e4);
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  ContactOutputs<T, D> out{Kokkos::View<T*, D>("fn", s.c.count), Kokkos::View<T*, D>("delta", s.c.count)};
  const ForceSums<T, D, AtomicSums> sums(s.p);
  detail::pair_kernel_lanes<8>(model, s.p, s.c, h, T(1e-6), sums, out);
  // sliding: |xi| = f_lim / k_t = mu f / (kt_over_kn k_n) = mu (2/3) delta / kt_over_kn (Hertz: f / k_n = 2 delta / 3)
  auto hh = test::to_host(h.data);
  auto dd = test::to_host(out.overlap);
  auto pairs = test::to_host(model.pairs);
  auto first = test::to_host(s.c.first);
  int sliding = 0, loaded = 0;
  for (int k = 0; k < s.c.count; ++k) {
    if (!(dd(k) > 0) || first(k) < 2) continue;  // skip the coincident pair (0, 1)
    ++loaded;
    const auto& pp = pairs(0);
    const double len =
        std::sqrt(double(hh(k, 0)) * hh(k, 0) + double(hh(k, 1)) * hh(k, 1) + double(hh(k, 2)) * hh(k, 2));
    const double limit = double(pp.mu) * 2.0 / 3.0 * double(dd(k)) / double(pp.kt_over_kn);
    if (std::abs(len - limit) <= (std::is_same<T, float>::value ? 1e-4 : 1e-10) * limit) ++sliding;
  }
  REQUIRE(loaded > 100);
  CHECK(sliding > 9 * loaded / 10);
}
