// List entries that do not touch (compute/contact_forces.hpp): for laws that declare
// `inactive_apart` (no force and no normal history where delta <= 0: Hertz-Mindlin, the linear
// spring, JKR without adhesion), the pair kernel stops after the distance. It must give exactly
// the full path's results, on every backend, double and float: the same per-contact forces and
// torques (the deterministic mode's buffer), history and outputs, bit for bit (the skipped work
// only fed a contact the law then drops; the separation is computed once and shared). The
// particle sums add in a thread-dependent order (atomics), so they agree to the order's
// round-off: 1e-12 (double) / 2e-5 (float) of the largest magnitude, as test_pair_lanes.cpp.
// The history starts nonzero in every entry, so the separated entries must forget their
// springs, and the scene has both kinds of entry and a pair of coincident centres
// (pair_kernel_scene.hpp). Laws with adhesion or normal history keep the full path (checked at
// compile time). Contacts in lanes (compute/pair_lanes.hpp) compute every entry: skipping the
// loads of the entries apart measured 4-5% slower on the settling scene (docs/performance.md).
#include "pair_kernel_scene.hpp"

#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>

using namespace epac;
using namespace epac::test;

namespace {

// The same law without the declaration: the kernel's full path for every entry.
template <class M>
struct FullPath : M {
  static constexpr bool inactive_apart = false;
  explicit FullPath(const M& m) : M(m) {}
};

void check_equal(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  INFO(what);
  REQUIRE(a.size() == b.size());
  std::size_t differ = 0;
  for (std::size_t e = 0; e < a.size(); ++e) differ += a[e] != b[e];
  CHECK(differ == 0);
}

template <class Model, class T, class D>
void compare_paths(const Model& model, double speed) {
  STATIC_REQUIRE(detail::inactive_apart<Model>::value);
  STATIC_REQUIRE_FALSE(detail::inactive_apart<FullPath<Model>>::value);
  const double start = 1e-9;  // m: every spring stretched before the first pass
  auto kernel = [](auto&&... a) { detail::pair_kernel<true>(a..., ContactForceBuffer<T, D>{}); };
  auto early = run_passes<Model, T, D>(model, speed, kernel, start);
  auto full = run_passes<FullPath<Model>, T, D>(FullPath<Model>(model), speed, kernel, start);
  // per contact, through the buffer: one pass after the same four
  const int count = pair_scene<T, D>(speed, model.nmat).c.count;
  ContactForceBuffer<T, D> buf_early(count), buf_full(count);
  int pass = 0;
  auto buffered = [&pass](const ContactForceBuffer<T, D>& buf) {
    return [&pass, buf](auto&&... a) {
      detail::pair_kernel<true>(a..., ++pass % 5 == 0 ? buf : ContactForceBuffer<T, D>{});
    };
  };
  run_passes<Model, T, D>(model, speed, buffered(buf_early), start);
  pass = 0;
  run_passes<FullPath<Model>, T, D>(FullPath<Model>(model), speed, buffered(buf_full), start);
  // both kinds of entry, and real forces
  const auto touching = std::count_if(full.overlap.begin(), full.overlap.end(), [](double d) { return d > 0; });
  REQUIRE(touching > 100);
  REQUIRE(touching < static_cast<long>(full.overlap.size()) - 100);
  REQUIRE(max_abs(full.force) > 0);
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  check_close(early.force, full.force, rel, "force sums");
  check_close(early.torque, full.torque, rel, "torque sums");
  auto flat = [](const auto& view) {
    auto hv = to_host(view);
    return std::vector<double>(hv.data(), hv.data() + hv.span());
  };
  REQUIRE(max_abs(flat(buf_full.force)) > 0);
  check_equal(flat(buf_early.force), flat(buf_full.force), "force per contact");
  check_equal(flat(buf_early.torque_i), flat(buf_full.torque_i), "torque on i per contact");
  check_equal(flat(buf_early.torque_j), flat(buf_full.torque_j), "torque on j per contact");
  check_equal(early.history, full.history, "history");
  check_equal(early.normal_force, full.normal_force, "normal force output");
  check_equal(early.overlap, full.overlap, "overlap output");
  // a separated entry forgot its spring, and reports its (negative) overlap and no force
  const std::size_t n = early.overlap.size();
  const int fields = Model::history_size;
  std::size_t apart = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (early.overlap[k] > 0) continue;
    ++apart;
    CHECK(early.overlap[k] < 0);
    CHECK(early.normal_force[k] == 0);
    for (int f = 0; f < fields; ++f) CHECK(early.history[f * n + k] == 0);  // LayoutLeft: field-major
  }
  REQUIRE(apart > 100);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("list entries that do not touch: the early exit gives the full path's results", "[apart]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using HM = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
  using HMR = HertzMindlin<T, Effects<kFriction | kDamping | kRolling>, D>;
  using LS = LinearSpring<T, Effects<kFriction | kDamping>, D>;
  using JkrHertz = Jkr<T, Effects<kFriction | kDamping>, D>;
  // adhesion (a pull at negative overlap) or normal history: always the full path
  STATIC_REQUIRE_FALSE(detail::inactive_apart<Jkr<T, Effects<kAdhesion | kFriction | kDamping>, D>>::value);
  STATIC_REQUIRE_FALSE(detail::inactive_apart<Nan2022<T, Effects<kPlasticity | kFriction | kDamping>, D>>::value);
  STATIC_REQUIRE_FALSE(detail::inactive_apart<Mdr<T, Effects<kPlasticity | kFriction | kDamping>, D>>::value);
  for (double speed : {1.0, 100.0}) {
    CAPTURE(speed);
    SECTION("Hertz-Mindlin") { compare_paths<HM, T, D>(HM::create(pair_materials<T>(0.5)), speed); }
    SECTION("Hertz-Mindlin with rolling resistance") {
      auto mats = pair_materials<T>(0.5);
      mats[0].rolling_friction = 0.1;
      mats[0].rolling_stiffness = 1e3;
      compare_paths<HMR, T, D>(HMR::create(mats), speed);
    }
    SECTION("linear spring") { compare_paths<LS, T, D>(LS::create(pair_materials<T>(0.5), 1e5), speed); }
    SECTION("JKR without adhesion") { compare_paths<JkrHertz, T, D>(JkrHertz::create(pair_materials<T>(0.5)), speed); }
  }
}
