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
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/linear_spring.hpp>
#include <support/dense_packing.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

using namespace epac;

namespace {

template <class T, class D>
struct LanesScene {
  Particles<T, D> p;
  ContactList<D> c;
};

// The dense packing (face neighbours overlap) plus its xy-diagonal neighbours (apart: 2.69 R
// against 2 R), global ids shuffled, materials mixed, one pair of coincident centres.
template <class T, class D>
LanesScene<T, D> lanes_scene(double speed, int nmat = 1) {
  const int n_side = 9;
  auto pk = bench::make_dense_packing<T, D>(n_side);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto gid = Kokkos::create_mirror_view(pk.particles.gid);
  auto mat = Kokkos::create_mirror_view(pk.particles.material);
  auto v = Kokkos::create_mirror_view(pk.particles.v);
  auto x = Kokkos::create_mirror_view(pk.particles.x);
  Kokkos::deep_copy(v, pk.particles.v);
  Kokkos::deep_copy(x, pk.particles.x);
  const int n = pk.particles.n;
  std::vector<std::int64_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  for (int i = 0; i < n; ++i) {
    gid(i) = ids[i];
    mat(i) = static_cast<int>(rng() % static_cast<unsigned>(nmat));
    for (int d = 0; d < 3; ++d) v(i, d) = T(v(i, d) * speed * std::pow(10.0, 2.0 * u(rng)));
  }
  for (int d = 0; d < 3; ++d) x(1, d) = x(0, d);  // coincident centres: pair (0, 1) is listed
  Kokkos::deep_copy(pk.particles.gid, gid);
  Kokkos::deep_copy(pk.particles.material, mat);
  Kokkos::deep_copy(pk.particles.v, v);
  Kokkos::deep_copy(pk.particles.x, x);
  auto f0 = test::to_host(pk.contacts.first);
  auto s0 = test::to_host(pk.contacts.second);
  std::vector<int> fi, fj;
  for (int k = 0; k < pk.contacts.count; ++k) {
    fi.push_back(f0(k));
    fj.push_back(s0(k));
  }
  auto idx = [n_side](int a, int b, int c) { return (a * n_side + b) * n_side + c; };
  for (int a = 0; a + 1 < n_side; ++a)
    for (int b = 0; b + 1 < n_side; ++b)
      for (int c = 0; c < n_side; c += 2) {
        fi.push_back(idx(a, b, c));
        fj.push_back(idx(a + 1, b + 1, c));
      }
  fi.push_back(5);  // one more: no multiple of 8
  fj.push_back(idx(1, 1, 0));
  LanesScene<T, D> s{pk.particles, ContactList<D>(static_cast<int>(fi.size()))};
  auto hf = Kokkos::create_mirror_view(s.c.first);
  auto hs = Kokkos::create_mirror_view(s.c.second);
  for (std::size_t k = 0; k < fi.size(); ++k) {
    hf(k) = fi[k];
    hs(k) = fj[k];
  }
  Kokkos::deep_copy(s.c.first, hf);
  Kokkos::deep_copy(s.c.second, hs);
  return s;
}

template <class T>
std::vector<Material> lanes_materials(double mu, int nmat = 1) {
  Material a;
  a.name = "glass";
  a.youngs_modulus = 70e9;
  a.poisson_ratio = 0.25;
  a.density = 2500;
  a.restitution = 0.5;
  a.friction = mu;
  Material b = a;
  b.name = "steel";
  b.youngs_modulus = 200e9;
  b.poisson_ratio = 0.3;
  b.restitution = 0.7;
  b.friction = mu > 0 ? 0.3 : 0.0;
  if (nmat == 1) return {a};
  return {a, b};
}

// Forces, torques, history and per-contact outputs after 5 passes of one kernel form.
struct PassResult {
  std::vector<double> force, torque, history, normal_force, overlap;
};

template <class Model, class T, class D, class Kernel>
PassResult run_passes(const Model& model, double speed, Kernel kernel) {
  auto s = lanes_scene<T, D>(speed, model.nmat);
  ContactHistory<T, D> h(s.c.count, Model::history_size);
  ContactOutputs<T, D> out{Kokkos::View<T*, D>("fn", s.c.count), Kokkos::View<T*, D>("delta", s.c.count)};
  const ForceSums<T, D, AtomicSums> sums(s.p);
  for (int pass = 0; pass < 5; ++pass) {
    zero_forces(s.p);
    kernel(model, s.p, s.c, h, T(2e-7), sums, out);
  }
  auto flat = [](const auto& view) {
    auto hv = test::to_host(view);
    std::vector<double> r(hv.span());
    for (std::size_t e = 0; e < hv.span(); ++e) r[e] = double(hv.data()[e]);
    return r;
  };
  return {flat(s.p.force), flat(s.p.torque), h.data.span() ? flat(h.data) : std::vector<double>{},
          flat(out.normal_force), flat(out.overlap)};
}

double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

void check_close(const std::vector<double>& a, const std::vector<double>& b, double rel, const char* what) {
  INFO(what);
  REQUIRE(a.size() == b.size());
  const double scale = std::max(max_abs(a), max_abs(b));
  double diff = 0;
  for (std::size_t e = 0; e < a.size(); ++e) diff = std::max(diff, std::abs(a[e] - b[e]));
  CHECK(diff <= rel * scale);
}

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
            HertzMindlin<T, Effects<kFriction | kDamping>, D>::create(lanes_materials<T>(mu)), speed);
      }
      SECTION("Hertz alone") {
        compare_forms<HertzMindlin<T, Effects<0>, D>, T, D>(
            HertzMindlin<T, Effects<0>, D>::create(lanes_materials<T>(mu)), speed);
      }
      SECTION("linear spring, friction and damping") {
        compare_forms<LinearSpring<T, Effects<kFriction | kDamping>, D>, T, D>(
            LinearSpring<T, Effects<kFriction | kDamping>, D>::create(lanes_materials<T>(mu), 1e5), speed);
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("contacts in lanes: two materials take the one-contact kernel", "[lanes]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
  const auto model = Model::create(lanes_materials<T>(0.5, 2));
  const double rel = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  auto scalar = run_passes<Model, T, D>(
      model, 1.0, [](auto&&... a) { detail::pair_kernel<true>(a..., ContactForceBuffer<T, D>{}); });
  auto dispatched = run_passes<Model, T, D>(model, 1.0, [](auto&&... a) { compute_pair_forces(a...); });
  REQUIRE(max_abs(scalar.force) > 0);
  check_close(scalar.force, dispatched.force, rel, "force");
  check_close(scalar.torque, dispatched.torque, rel, "torque");
  check_close(scalar.history, dispatched.history, rel, "history");
  // the lanes kernel itself refuses them, on the host, before any kernel runs
  auto s = lanes_scene<T, D>(1.0, 2);
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
  const auto model = Model::create(lanes_materials<T>(0.3));
  auto s = lanes_scene<T, D>(1e4);
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
