// Contacts in lanes (compute/pair_lanes.hpp) against the one-contact kernel it replaces for
// Hertz-Mindlin, the linear spring, Nan 2022 and JKR (the last two: their common path in lanes,
// the rest from the one-contact code), on every backend, double and float: blocks of 8 and 16
// (the host forms: 16 for float with 512-bit vectors) and of 1 (the GPU form) give the one-contact
// kernel's forces, torques, history and outputs, whether or not this build vectorises them. The scene has what each stage must handle:
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
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>

using namespace epac;
using namespace epac::test;

namespace {

// The one-contact kernel, lanes of 8, 16 and 1, and compute_pair_forces' choice, each run through
// `run(kernel)` (a runner of passes taking the kernel form).
struct FormResults {
  PassResult scalar, lanes8, lanes16, lanes1, dispatched;
};
template <class Model, class T, class D, class Run>
FormResults run_forms(Run run) {
  return {run([](auto&&... a) { detail::pair_kernel<Model::effects::friction>(a..., ContactForceBuffer<T, D>{}); }),
          run([](auto&&... a) { detail::pair_kernel_lanes<8>(a...); }),
          run([](auto&&... a) { detail::pair_kernel_lanes<16>(a...); }),
          run([](auto&&... a) { detail::pair_kernel_lanes<1>(a...); }),
          run([](auto&&... a) { compute_pair_forces(a...); })};
}
// The lanes kernel refuses the model on the host, before any kernel runs, naming why.
template <class Model, class T, class D>
void check_lanes_refuse(const Model& model, const char* why) {
  auto s = pair_scene<T, D>(1.0, model.nmat);
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  const ForceSums<T, D, AtomicSums> sums(s.p);
  REQUIRE_THROWS_WITH(detail::pair_kernel_lanes<8>(model, s.p, s.c, h, T(1e-7), sums, ContactOutputs<T, D>{}),
                      Catch::Contains(why));
}

void check_forms_agree(const FormResults& r, double rel) {
  for (const auto* other : {&r.lanes8, &r.lanes16, &r.lanes1, &r.dispatched}) {
    check_close(r.scalar.force, other->force, rel, "force");
    check_close(r.scalar.torque, other->torque, rel, "torque");
    check_close(r.scalar.history, other->history, rel, "history");
    check_close(r.scalar.normal_force, other->normal_force, rel, "normal force output");
    check_close(r.scalar.overlap, other->overlap, rel, "overlap output");
  }
}

template <class Model, class T, class D>
void compare_forms(const Model& model, double speed, bool periodic = false, bool gid_ordered = false) {
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  const FormResults r = run_forms<Model, T, D>(
      [&](auto kernel) { return run_passes<Model, T, D>(model, speed, kernel, 0.0, periodic, gid_ordered); });
  const PassResult& scalar = r.scalar;
  // the scene has both touching and separated contacts, and real forces and torques
  const auto touching = std::count_if(scalar.overlap.begin(), scalar.overlap.end(), [](double d) { return d > 0; });
  REQUIRE(touching > 100);
  REQUIRE(touching < static_cast<long>(scalar.overlap.size()) - 100);
  REQUIRE(max_abs(scalar.force) > 0);
  if (Model::effects::friction) REQUIRE(max_abs(scalar.torque) > 0);
  if (periodic) {  // the pairs across the box's faces (listed before the last entry) touch as
                   // face neighbours do (most of them: radii +-5% about half the spacing)
    const int open = pair_scene<T, D>(speed, model.nmat).c.count;
    const int cross = static_cast<int>(scalar.overlap.size()) - open;
    REQUIRE(cross >= 40);
    const auto at = scalar.overlap.begin() + (open - 1);
    REQUIRE(std::count_if(at, at + cross, [](double d) { return d > 0; }) > cross / 2);
  }
  check_forms_agree(r, rel);
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
      SECTION("Hertz-Mindlin in a periodic box (contacts through the minimum image)") {
        compare_forms<HertzMindlin<T, Effects<kFriction | kDamping>, D>, T, D>(
            HertzMindlin<T, Effects<kFriction | kDamping>, D>::create(pair_materials<T>(mu)), speed, true);
      }
      SECTION("Hertz-Mindlin, a list ordered by global id (no id test in the lanes)") {
        compare_forms<HertzMindlin<T, Effects<kFriction | kDamping>, D>, T, D>(
            HertzMindlin<T, Effects<kFriction | kDamping>, D>::create(pair_materials<T>(mu)), speed, false, true);
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
  check_lanes_refuse<Model, T, D>(model, "model.nmat is 2");
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

namespace {

// Nan 2022's lane form covers the contacts in contact on a known line; the rest take the
// one-contact code in the same block. The packing is moved between passes (positions scaled
// about the origin) so that every branch occurs: first contact, plastic loading, the first
// unloading step after yield (line not yet kept), unloading on the kept line, the cohesive
// branch, detachment and re-loading after unloading.
const double nan_schedule[] = {1.0, 1.0, 1.0, 1.035, 1.0, 0.995, 0.995, 0.9952, 0.9955, 0.996, 0.996};

// A schedule's steps around the force pass (none for laws without per-particle state).
struct NoPassSteps {
  template <class S>
  void setup(S&) const {}
  template <class S, class H>
  void before_force(bool /*last*/, const S&, const H&) const {}
  void after_force() const {}
};

// Forces, torques and outputs of every pass, appended; the history after the last. whole_blocks:
// the list's last entries left out so that it fills blocks of 8 exactly (the scene's list ends in
// a part-full block). schedule: the positions' scale of each pass; steps: what runs around each
// force pass (setup(scene) first, before_force after the pass's positions are set).
template <class Model, class T, class D, class Kernel, std::size_t N = 11, class Steps = NoPassSteps>
PassResult run_schedule(const Model& model, Kernel kernel, std::vector<double>* history_before_last = nullptr,
                        bool whole_blocks = false, const double (&schedule)[N] = nan_schedule, const Steps& steps = {},
                        test::PairScene<T, D>* scene_after = nullptr) {
  auto s = pair_scene<T, D>(1.0, model.nmat);
  if (whole_blocks) s.c.count -= s.c.count % 8;
  steps.setup(s);
  auto x = Kokkos::create_mirror_view(s.p.x);  // on host backends: the positions themselves
  Kokkos::deep_copy(x, s.p.x);
  const std::vector<double> x0(x.data(), x.data() + x.span());
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  ContactOutputs<T, D> out{Kokkos::View<T*, D>("fn", s.c.count), Kokkos::View<T*, D>("delta", s.c.count)};
  const ForceSums<T, D, AtomicSums> sums(s.p);
  auto append = [](std::vector<double>& to, const auto& view) {
    auto hv = test::to_host(view);
    for (std::size_t e = 0; e < hv.span(); ++e) to.push_back(double(hv.data()[e]));
  };
  PassResult r;
  const int passes = static_cast<int>(N);
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t e = 0; e < x.span(); ++e) x.data()[e] = x0[e] * schedule[pass];
    Kokkos::deep_copy(s.p.x, x);
    if (pass == passes - 1 && history_before_last) {
      auto hh = test::to_host(h.data);
      history_before_last->assign(hh.data(), hh.data() + hh.span());
    }
    steps.before_force(pass == passes - 1, s, h);
    zero_forces(s.p);
    kernel(model, s.p, s.c, h, T(2e-7), sums, out);
    steps.after_force();
    append(r.force, s.p.force);
    append(r.torque, s.p.torque);
    append(r.normal_force, out.normal_force);
    append(r.overlap, out.overlap);
  }
  append(r.history, h.data);
  if (scene_after) *scene_after = s;
  return r;
}

// The law's constants for lanes, read on the host.
template <class T, class E, class D>
Nan2022LanePair<T> host_lane_pair(const Nan2022<T, E, D>& m) {
  return nan2022_lane_pair(test::to_host(m.pairs)(0), test::to_host(m.derived)(0));
}
template <class T, class E, class D>
JkrPair<T> host_lane_pair(const Jkr<T, E, D>& m) {
  return test::to_host(m.pairs)(0);
}

// A law with normal history in lanes against the one-contact kernel over the schedule, and the
// lane form's own verdict on the last pass: both kinds of lane occur (>= 100 common, >= 10 rare)
// and, where `pulling` is set, adhesive forces (all from rare lanes for Nan 2022). The last block of
// the list is part full (it loads and stores the history lane by lane, full blocks as vectors),
// unless whole_blocks.
template <class Model, class T, class D>
void compare_history_forms(const Model& model, bool pulling_expected, bool whole_blocks = false) {
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  REQUIRE(model.lane_form_applies());
  std::vector<double> h_last;  // the one-contact kernel's (the first run), before its last pass
  const FormResults r = run_forms<Model, T, D>([&](auto kernel) {
    return run_schedule<Model, T, D>(model, kernel, h_last.empty() ? &h_last : nullptr, whole_blocks);
  });
  const PassResult& scalar = r.scalar;
  const int count = static_cast<int>(h_last.size()) / Model::history_size;
  REQUIRE((count % 8 == 0) == whole_blocks);
  const std::size_t last = scalar.overlap.size() - static_cast<std::size_t>(count);
  const auto lp = host_lane_pair(model);
  auto scene = pair_scene<T, D>(1.0);
  auto radius = test::to_host(scene.p.radius);
  auto first = test::to_host(scene.c.first);
  auto second = test::to_host(scene.c.second);
  int common = 0, rare = 0, pulling = 0;
  for (int k = 0; k < count; ++k) {
    const T R_i = radius(first(k)), R_j = radius(second(k));
    LaneHistory<T, Model::normal_history_size> lh;
    for (int f = 0; f < Model::normal_history_size; ++f) lh.v[f] = T(h_last[static_cast<std::size_t>(f) * count + k]);
    lh.rare = false;
    // R* as the kernel takes it (the scene's radii are fixed; the expression is symmetric)
    Model::normal_lane(lp, T(scalar.overlap[last + k]), R_i * R_j / (R_i + R_j), lh);
    (lh.rare ? rare : common) += 1;
  }
  for (double f : scalar.normal_force) pulling += f < 0;
  CAPTURE(common, rare, pulling);
  CHECK(common >= 100);
  CHECK(rare >= 10);
  if (pulling_expected) CHECK(pulling >= 5);
  check_forms_agree(r, rel);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("contacts in lanes: Nan 2022's common path and its rare contacts", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Full = Nan2022<T, Effects<kAdhesion | kPlasticity | kFriction | kDamping>, D>;
  STATIC_REQUIRE(detail::runs_in_lanes<Full>::value);
  STATIC_REQUIRE(detail::runs_in_lanes<Nan2022<T, Effects<kAdhesion>, D>>::value);
  // without adhesion every step takes the detached state's path: no lane form
  STATIC_REQUIRE_FALSE(detail::runs_in_lanes<Nan2022<T, Effects<kPlasticity | kFriction>, D>>::value);
  auto mats = pair_materials<T>(0.5);
  mats[0].surface_energy = 50.0;
  mats[0].yield_stress = 2e8;
  SECTION("the full model") { compare_history_forms<Full, T, D>(Full::create(mats), true); }
  SECTION("the full model, a list of whole blocks") {
    compare_history_forms<Full, T, D>(Full::create(mats), true, true);
  }
  SECTION("adhesion alone (no plasticity, friction or damping)") {
    // elastic lines leave almost no room for the cohesive branch in this scene: no pulling required
    using Model = Nan2022<T, Effects<kAdhesion>, D>;
    compare_history_forms<Model, T, D>(Model::create(mats), false);
  }
  SECTION("a fixed k_el keeps the one-contact kernel") {
    Nan2022Options opt;
    opt.k_el_from = Nan2022ElasticStiffnessFrom::fixed;
    opt.k_el = 1e5;
    const auto model = Full::create(mats, opt);
    CHECK_FALSE(model.lane_form_applies());
    check_lanes_refuse<Full, T, D>(model, "lane_form_applies");
  }
}

TEMPLATE_LIST_TEST_CASE("contacts in lanes: JKR's warm-started root and its rare contacts", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Full = Jkr<T, Effects<kAdhesion | kFriction | kDamping>, D>;
  STATIC_REQUIRE(detail::runs_in_lanes<Full>::value);
  STATIC_REQUIRE(detail::runs_in_lanes<Jkr<T, Effects<kAdhesion>, D>>::value);
  STATIC_REQUIRE_FALSE(detail::runs_in_lanes<Jkr<T, Effects<kFriction | kDamping>, D>>::value);
  auto mats = pair_materials<T>(0.5);
  mats[0].surface_energy = 50.0;
  SECTION("friction and damping") { compare_history_forms<Full, T, D>(Full::create(mats), true); }
  SECTION("friction and damping, a list of whole blocks") {
    compare_history_forms<Full, T, D>(Full::create(mats), true, true);
  }
  SECTION("adhesion alone") {
    using Model = Jkr<T, Effects<kAdhesion>, D>;
    compare_history_forms<Model, T, D>(Model::create(mats), true);
  }
  SECTION("no surface energy keeps the one-contact kernel") {
    CHECK_FALSE(Full::create(pair_materials<T>(0.5)).lane_form_applies());
  }
}

namespace {

// MDR as LAMMPS runs it (the side-by-side's like-with-like options): its lane form covers a pair
// whose sides both hold below their delta_max on their stored shapes; loading, first contact,
// separation and elastic sides take the one-contact code in the same block. A run is the driver's
// step: the contact penalty, Part II's pre-pass, the force pass, the radius update. Each form
// gets a model of its own (the model holds the per-particle state the passes advance).
const double mdr_schedule[] = {1.0, 0.998, 0.997, 0.9972, 0.9975, 0.9975, 0.9973, 0.9965, 0.9978, 0.998, 0.9968};

template <class T>
MdrOptions mdr_authors_options(double psi_b) {
  MdrOptions o;
  o.pair_split = MdrPairSplit::geometric;
  o.psi_b = psi_b;
  o.contact_penalty = true;
  o.delta_max = MdrDeltaMax::running_max;
  o.damping = MdrDamping::authors;
  o.friction = MdrFriction::authors;
  o.tangential_stiffness = 2e5;
  o.yield_onset = MdrYieldOnset::hertz_40;
  return o;
}

struct MdrPassResult {
  PassResult r;
  std::vector<double> radius, psi;
};

// The driver's steps around MDR's force pass: the contact penalty and Part II's pre-pass before
// it, the radius update after; setup binds the model to the scene's particles (R_o: their radii).
// before_last(model, scene, history): called before the last pass's force pass.
template <class Model, class T, class D, class BeforeLast>
struct MdrPassSteps {
  Model& model;
  BeforeLast before_last;
  void setup(test::PairScene<T, D>& s) const {
    Kokkos::deep_copy(s.p.radius0, s.p.radius);
    model.bind(s.p);
  }
  void before_force(bool last, const test::PairScene<T, D>& s, const ContactHistory<T, D>& h) const {
    model.compute_contact_penalty(s.p, s.c);
    model.compute_mean_surface_displacement(s.p, s.c, h, Walls<T, D>(), ContactList<D>(), ContactHistory<T, D>());
    if (last) before_last(model, s, h);
  }
  void after_force() const { model.update_radii(); }
};

template <class Model, class T, class D, class Kernel, class BeforeLast>
MdrPassResult run_mdr_schedule(const std::vector<Material>& mats, const MdrOptions& opt, Kernel kernel,
                               BeforeLast before_last) {
  Model model = Model::create(mats, opt);
  const MdrPassSteps<Model, T, D, BeforeLast> steps{model, before_last};
  test::PairScene<T, D> s;
  MdrPassResult res;
  res.r = run_schedule<Model, T, D>(model, kernel, nullptr, false, mdr_schedule, steps, &s);
  auto flat = [](const auto& view) {
    auto hv = test::to_host(view);
    return std::vector<double>(hv.data(), hv.data() + hv.span());
  };
  res.radius = flat(s.p.radius);
  res.psi = flat(model.bulk.psi);
  return res;
}

}  // namespace

namespace {
template <class Model, class T, class D>
void compare_mdr_lanes(const std::vector<Material>& mats, const MdrOptions& opt) {
  if constexpr (detail::runs_in_lanes<Model>::value) {
    CHECK(Model::create(mats, opt).lane_form_applies() == false);  // unbound: growth and Part II unread
    // the lane form's verdict on the last pass (on a host backend: stores_shape), from the
    // one-contact kernel's run just before its force pass, geometry as the lanes kernel takes it
    int common = 0, rare = 0, yielded = 0;
    auto verdict = [&](const Model& model, const test::PairScene<T, D>& s, const ContactHistory<T, D>& h) {
      REQUIRE(model.lane_form_applies());
      const auto pc = model.pairs(0);
      for (int k = 0; k < s.c.count; ++k) {
        int i = s.c.first(k), j = s.c.second(k);
        if (s.p.gid(j) < s.p.gid(i)) std::swap(i, j);
        T nh[Model::normal_history_size][1], sums[Model::lane_sum_count][1];
        for (int f = 0; f < Model::normal_history_size; ++f) nh[f][0] = h.data(k, f);
        yielded += nh[Model::side_base(0) + Model::SideField::yielded][0] != T(0);
        const T R_i = s.p.radius(i), R_j = s.p.radius(j);
        double dx[3], dist2 = 0;
        for (int d = 0; d < 3; ++d) {
          dx[d] = s.p.x(i, d) - s.p.x(j, d);
          dist2 += dx[d] * dx[d];
        }
        const double delta = double(R_i) + double(R_j) - std::sqrt(dist2);
        const LaneContact<T, int> lc{i, j, k, T(delta), R_i, R_j, R_i * R_j / (R_i + R_j)};
        T lane_rare = T(0);
        model.contact_lane(pc, lc, LaneColumn<T, 1>{nh, 0}, LaneColumn<T, 1>{sums, 0}, lane_rare);
        (lane_rare != T(0) ? rare : common) += 1;
      }
    };
    auto no_verdict = [](const Model&, const test::PairScene<T, D>&, const ContactHistory<T, D>&) {};
    auto run = [&](auto kernel) { return run_mdr_schedule<Model, T, D>(mats, opt, kernel, no_verdict); };
    const MdrPassResult scalar = run_mdr_schedule<Model, T, D>(
        mats, opt, [](auto&&... a) { detail::pair_kernel<true>(a..., ContactForceBuffer<T, D>{}); }, verdict);
    const MdrPassResult lanes8 = run([](auto&&... a) { detail::pair_kernel_lanes<8>(a...); });
    const MdrPassResult lanes16 = run([](auto&&... a) { detail::pair_kernel_lanes<16>(a...); });
    const MdrPassResult dispatched = run([](auto&&... a) { compute_pair_forces(a...); });
    CAPTURE(common, rare, yielded);
    CHECK(yielded >= 100);
    CHECK(common >= 100);
    CHECK(rare >= 10);
    // what each psi_b is for: bulk overlaps (psi_b 1), radius growth (psi_b 0.5)
    double bulk_max = 0, grown = 0;
    const int count = static_cast<int>(scalar.r.overlap.size() / (sizeof(mdr_schedule) / sizeof(mdr_schedule[0])));
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < count; ++k)
        bulk_max = std::max(
            bulk_max,
            scalar.r
                .history[static_cast<std::size_t>(Model::side_base(side) + Model::SideField::bulk_delta_bulk) * count +
                         k]);
    auto r0 = test::to_host(pair_scene<T, D>(1.0, 1).p.radius);
    for (std::size_t i = 0; i < scalar.radius.size(); ++i)
      grown = std::max(grown, scalar.radius[i] / double(r0(i)) - 1);
    CAPTURE(bulk_max, grown);
    if (opt.psi_b == 1.0) {
      CHECK(bulk_max > 0);
      CHECK(grown == 0);
    } else {
      CHECK(bulk_max == 0);
      CHECK(grown > 1e-3);
    }
    // a few ulp per side law (lane_two_asin_sqrt against libm's asin), carried over 11 passes
    const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-11;
    for (const auto* other : {&lanes8, &lanes16, &dispatched}) {
      check_close(scalar.r.force, other->r.force, rel, "force");
      check_close(scalar.r.torque, other->r.torque, rel, "torque");
      check_close(scalar.r.history, other->r.history, rel, "history");
      check_close(scalar.r.normal_force, other->r.normal_force, rel, "normal force output");
      check_close(scalar.r.overlap, other->r.overlap, rel, "overlap output");
      check_close(scalar.radius, other->radius, rel, "radii");
      check_close(scalar.psi, other->psi, rel, "psi");
    }
  }
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("contacts in lanes: MDR as LAMMPS runs it, its common path and its rare contacts", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Mdr<T, Effects<kPlasticity | kRadiusGrowth | kFriction | kDamping | kBulkResponse>, D>;
  // GPUs keep no plastic shape in the history (Mdr::stores_shape): the lane form needs it
  STATIC_REQUIRE(detail::runs_in_lanes<Model>::value == Model::stores_shape);
  STATIC_REQUIRE_FALSE(detail::runs_in_lanes<Mdr<T, Effects<kAllEffects & ~kRolling>, D>>::value);  // adhesion
  auto mats = pair_materials<T>(0.5);
  mats[0].yield_stress = 1e8;
  // psi_b 0.5 (LAMMPS's): this packing's particles keep psi above it, so they grow; psi_b 1: every
  // particle in contact takes Part II's bulk response (F_BULK, delta_BULK), and none grows
  for (double psi_b : {0.5, 1.0}) {
    CAPTURE(psi_b);
    const MdrOptions opt = mdr_authors_options<T>(psi_b);
    compare_mdr_lanes<Model, T, D>(mats, opt);
  }
}
