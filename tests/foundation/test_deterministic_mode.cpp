// Deterministic mode (compute/deterministic_pass.hpp) for every law and effect set, pairs and
// walls: shuffling both contact lists and swapping (i, j) in every pair, or running on one
// thread (Serial) instead of the OpenMP pool, changes no bit of forces, torques, positions,
// velocities, radii (MDR growth) or contact history over several steps.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/deterministic_pass.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <epac/state/walls.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>
#include <type_traits>
#include <vector>

using namespace epac;

namespace {

// Laws: the model template and how it is built from materials.
struct HmLaw {
  template <class T, unsigned B, class D>
  using model = HertzMindlin<T, Effects<B>, D>;
  template <class M>
  static M create(const std::vector<Material>& m) {
    return M::create(m);
  }
};
struct LsLaw {
  template <class T, unsigned B, class D>
  using model = LinearSpring<T, Effects<B>, D>;
  template <class M>
  static M create(const std::vector<Material>& m) {
    return M::create(m, 3e4);
  }  // ~ Hertz stiffness here
};
struct JkrLaw {
  template <class T, unsigned B, class D>
  using model = Jkr<T, Effects<B>, D>;
  template <class M>
  static M create(const std::vector<Material>& m) {
    return M::create(m);
  }
};
struct NanLaw {
  template <class T, unsigned B, class D>
  using model = Nan2022<T, Effects<B>, D>;
  template <class M>
  static M create(const std::vector<Material>& m) {
    return M::create(m);
  }
};
struct MdrLaw {
  template <class T, unsigned B, class D>
  using model = Mdr<T, Effects<B>, D>;
  template <class M>
  static M create(const std::vector<Material>& m) {
    return M::create(m);
  }
};

template <class Law, unsigned Bits>
struct Case {
  using law = Law;
  static constexpr unsigned bits = Bits;
};

// Two deformable materials (different moduli, radii, densities: asymmetric pair constants) and a
// rigid wall. E/Y = 50 and 40: the lattice's overlaps of about 0.1 R yield.
std::vector<Material> materials() {
  Material a;
  a.name = "a";
  a.youngs_modulus = 1e8;
  a.poisson_ratio = 0.3;
  a.density = 2500;
  a.restitution = 0.6;
  a.friction = 0.4;
  a.surface_energy = 0.05;
  a.yield_stress = 2e6;
  Material b;
  b.name = "b";
  b.youngs_modulus = 2e8;
  b.poisson_ratio = 0.25;
  b.density = 2000;
  b.restitution = 0.7;
  b.friction = 0.3;
  b.surface_energy = 0.08;
  b.yield_stress = 5e6;
  Material w;
  w.name = "wall";
  w.rigid = true;
  w.poisson_ratio = 0.25;
  w.restitution = 0.5;
  w.friction = 0.3;
  w.surface_energy = 0.05;
  return {a, b, w};
}

// A jittered 4 x 4 x 3 lattice of spacing 1.9 R (face neighbours overlap by about 0.1 R), random
// velocities and spins, global ids a random permutation of the indices; a floor and a side wall
// that the first layers overlap. Pairs: face neighbours, listed (lower index, higher index).
struct Setup {
  int n = 0;
  std::vector<double> x, v, w, r, m;
  std::vector<int> mat;
  std::vector<std::int64_t> gid;
  std::vector<int> pi, pj;  // pairs
  std::vector<int> wi, ww;  // wall contacts (particle, wall)
};

Setup make_setup() {
  const double R = 1e-3, s = 1.9 * R;
  const int nx = 4, ny = 4, nz = 3;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Setup st;
  st.n = nx * ny * nz;
  auto idx = [&](int a, int b, int c) { return (c * ny + b) * nx + a; };
  st.x.resize(3 * st.n);
  st.v.resize(3 * st.n);
  st.w.resize(3 * st.n);
  st.r.resize(st.n);
  st.m.resize(st.n);
  st.mat.resize(st.n);
  st.gid.resize(st.n);
  for (int c = 0; c < nz; ++c)
    for (int b = 0; b < ny; ++b)
      for (int a = 0; a < nx; ++a) {
        const int i = idx(a, b, c);
        st.mat[i] = (a + b + c) % 2;
        st.r[i] = R * (1.0 + 0.04 * u(rng));
        st.x[3 * i + 0] = a * s + 0.02 * R * u(rng);
        st.x[3 * i + 1] = b * s + 0.02 * R * u(rng);
        st.x[3 * i + 2] = c * s + 0.02 * R * u(rng);
        for (int d = 0; d < 3; ++d) {
          st.v[3 * i + d] = 0.05 * u(rng);
          st.w[3 * i + d] = 20.0 * u(rng);
        }
        st.m[i] = (st.mat[i] == 0 ? 2500.0 : 2000.0) * 4.0 / 3.0 * M_PI * st.r[i] * st.r[i] * st.r[i];
        if (a + 1 < nx) {
          st.pi.push_back(i);
          st.pj.push_back(idx(a + 1, b, c));
        }
        if (b + 1 < ny) {
          st.pi.push_back(i);
          st.pj.push_back(idx(a, b + 1, c));
        }
        if (c + 1 < nz) {
          st.pi.push_back(i);
          st.pj.push_back(idx(a, b, c + 1));
        }
        if (c == 0) {
          st.wi.push_back(i);
          st.ww.push_back(0);
        }  // floor z = -0.9 R
        if (a == 0) {
          st.wi.push_back(i);
          st.ww.push_back(1);
        }  // side wall x = -0.9 R
      }
  std::iota(st.gid.begin(), st.gid.end(), std::int64_t(0));
  std::shuffle(st.gid.begin(), st.gid.end(), rng);
  return st;
}

// Host copies of everything a run produces.
template <class T>
struct Result {
  std::vector<T> force, torque, v, w, radius, pair_hist, wall_hist;
  std::vector<double> x;  // positions are double for any T (mixed precision)
  int pair_fields = 0, wall_fields = 0;
};

template <class M, class = void>
struct has_update_radii : std::false_type {};
template <class M>
struct has_update_radii<M, std::void_t<decltype(std::declval<const M&>().update_radii())>> : std::true_type {};

template <class V>
std::vector<typename V::non_const_value_type> flat(const V& view) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  std::vector<typename V::non_const_value_type> out;
  for (std::size_t i = 0; i < h.extent(0); ++i)
    for (std::size_t d = 0; d < (V::rank > 1 ? h.extent(1) : 1); ++d) out.push_back(h.access(i, d));
  return out;
}

// `steps` steps (symplectic Euler) with the deterministic mode. pair_order / wall_order: list
// entry k is the setup's contact order[k]; swap: every pair listed as (j, i).
template <class Law, unsigned Bits, class T, class D>
Result<T> run(const Setup& st, const std::vector<int>& pair_order, const std::vector<int>& wall_order, bool swap,
              int steps) {
  using Model = typename Law::template model<T, Bits, D>;
  using exec = typename D::execution_space;
  const int n = st.n;
  Particles<T, D> p(n);
  {
    auto x = Kokkos::create_mirror_view(p.x);  // double positions: a declaration of its own
    auto v = Kokkos::create_mirror_view(p.v), w = Kokkos::create_mirror_view(p.omega);
    auto m = Kokkos::create_mirror_view(p.mass), I = Kokkos::create_mirror_view(p.inertia);
    auto r0 = Kokkos::create_mirror_view(p.radius0);
    auto mat = Kokkos::create_mirror_view(p.material);  // int view: its own declaration
    auto gid = Kokkos::create_mirror_view(p.gid);
    for (int i = 0; i < n; ++i) {
      for (int d = 0; d < 3; ++d) {
        x(i, d) = T(st.x[3 * i + d]);
        v(i, d) = T(st.v[3 * i + d]);
        w(i, d) = T(st.w[3 * i + d]);
      }
      m(i) = T(st.m[i]);
      I(i) = T(0.4 * st.m[i] * st.r[i] * st.r[i]);
      r0(i) = T(st.r[i]);
      mat(i) = st.mat[i];
      gid(i) = st.gid[i];
    }
    Kokkos::deep_copy(p.x, x);
    Kokkos::deep_copy(p.v, v);
    Kokkos::deep_copy(p.omega, w);
    Kokkos::deep_copy(p.mass, m);
    Kokkos::deep_copy(p.inertia, I);
    Kokkos::deep_copy(p.radius0, r0);
    Kokkos::deep_copy(p.radius, r0);
    Kokkos::deep_copy(p.material, mat);
    Kokkos::deep_copy(p.gid, gid);
  }
  Walls<T, D> walls(2);
  {
    auto pt = Kokkos::create_mirror_view(walls.point);  // double, the normal T
    auto nr = Kokkos::create_mirror_view(walls.normal);
    auto wm = Kokkos::create_mirror_view(walls.material);
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 3; ++d) {
        pt(k, d) = T(0);
        nr(k, d) = T(0);
      }
    pt(0, 2) = T(-0.9e-3);
    nr(0, 2) = T(1);  // floor
    pt(1, 0) = T(-0.9e-3);
    nr(1, 0) = T(1);  // side wall
    wm(0) = wm(1) = 2;
    Kokkos::deep_copy(walls.point, pt);
    Kokkos::deep_copy(walls.normal, nr);
    Kokkos::deep_copy(walls.material, wm);
  }
  const int np = static_cast<int>(pair_order.size()), nwc = static_cast<int>(wall_order.size());
  ContactList<D> pairs(np, "pairs"), wl(nwc, "walls");
  {
    auto f = Kokkos::create_mirror_view(pairs.first), s = Kokkos::create_mirror_view(pairs.second);
    for (int k = 0; k < np; ++k) {
      const int a = st.pi[pair_order[k]], b = st.pj[pair_order[k]];
      f(k) = swap ? b : a;
      s(k) = swap ? a : b;
    }
    Kokkos::deep_copy(pairs.first, f);
    Kokkos::deep_copy(pairs.second, s);
    auto wf = Kokkos::create_mirror_view(wl.first), ws = Kokkos::create_mirror_view(wl.second);
    for (int k = 0; k < nwc; ++k) {
      wf(k) = st.wi[wall_order[k]];
      ws(k) = st.ww[wall_order[k]];
    }
    Kokkos::deep_copy(wl.first, wf);
    Kokkos::deep_copy(wl.second, ws);
  }
  Model model = Law::template create<Model>(materials());
  if constexpr (has_update_radii<Model>::value) model.bind(p);
  ContactHistory<T, D> ph(np, Model::history_size, "pair_hist"), wh(nwc, Model::history_size, "wall_hist");
  DeterministicPass<T, D> det;
  det.rebuild(p, pairs, wl);
  const T dt = T(2e-6);
  for (int step = 0; step < steps; ++step) {
    zero_forces(p);
    det.begin(model);
    compute_pair_forces(model, p, pairs, ph, dt, {}, det.pair_buffer);
    compute_wall_forces(model, p, walls, wl, wh, dt, {}, det.wall_buffer);
    det.end(model, p);
    if constexpr (has_update_radii<Model>::value) model.update_radii();
    if (step + 1 == steps) break;  // keep the last pass's forces
    const auto pp = p;
    Kokkos::parallel_for(
        Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
          for (int d = 0; d < 3; ++d) {
            pp.v(i, d) += dt * pp.force(i, d) / pp.mass(i);
            pp.omega(i, d) += dt * pp.torque(i, d) / pp.inertia(i);
            pp.x(i, d) += dt * pp.v(i, d);
          }
        });
  }
  Result<T> r;
  r.force = flat(p.force);
  r.torque = flat(p.torque);
  r.x = flat(p.x);
  r.v = flat(p.v);
  r.w = flat(p.omega);
  r.radius = flat(p.radius);
  r.pair_fields = Model::history_size;
  r.wall_fields = Model::history_size;
  if (Model::history_size > 0) {
    // rows back in the setup's contact order
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ph.data);
    r.pair_hist.assign(static_cast<std::size_t>(np) * r.pair_fields, T(0));
    for (int k = 0; k < np; ++k)
      for (int f = 0; f < r.pair_fields; ++f) r.pair_hist[pair_order[k] * r.pair_fields + f] = h(k, f);
    auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wh.data);
    r.wall_hist.assign(static_cast<std::size_t>(nwc) * r.wall_fields, T(0));
    for (int k = 0; k < nwc; ++k)
      for (int f = 0; f < r.wall_fields; ++f) r.wall_hist[wall_order[k] * r.wall_fields + f] = hw(k, f);
  }
  return r;
}

// Number of entries whose bits differ.
template <class T>
int bit_diffs(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return static_cast<int>(std::max(a.size(), b.size()));
  int d = 0;
  for (std::size_t k = 0; k < a.size(); ++k) d += std::memcmp(&a[k], &b[k], sizeof(T)) != 0;
  return d;
}

template <class T>
void require_same_bits(const Result<T>& a, const Result<T>& b) {
  CHECK(bit_diffs(a.force, b.force) == 0);
  CHECK(bit_diffs(a.torque, b.torque) == 0);
  CHECK(bit_diffs(a.x, b.x) == 0);
  CHECK(bit_diffs(a.v, b.v) == 0);
  CHECK(bit_diffs(a.w, b.w) == 0);
  CHECK(bit_diffs(a.radius, b.radius) == 0);
  CHECK(bit_diffs(a.pair_hist, b.pair_hist) == 0);
  CHECK(bit_diffs(a.wall_hist, b.wall_hist) == 0);
}

}  // namespace

TEMPLATE_TEST_CASE("deterministic mode: same bits for a shuffled, swapped list and on one thread", "[deterministic]",
                   (Case<HmLaw, kFriction | kDamping>), (Case<HmLaw, 0u>), (Case<LsLaw, kFriction | kDamping>),
                   (Case<JkrLaw, kAdhesion | kFriction | kDamping>), (Case<JkrLaw, kAdhesion>),
                   (Case<NanLaw, kAdhesion | kPlasticity | kFriction | kDamping>), (Case<NanLaw, kPlasticity>),
                   (Case<MdrLaw, kAllEffects>), (Case<MdrLaw, kPlasticity | kRadiusGrowth>),
                   (Case<MdrLaw, kPlasticity | kAdhesion | kRadiusGrowth>), (Case<MdrLaw, kPlasticity | kFriction>)) {
  using Law = typename TestType::law;
  constexpr unsigned Bits = TestType::bits;
  using T = double;
  using DH = test::DeviceOf<Kokkos::DefaultHostExecutionSpace>;
  const Setup st = make_setup();
  std::vector<int> po(st.pi.size()), wo(st.wi.size());
  std::iota(po.begin(), po.end(), 0);
  std::iota(wo.begin(), wo.end(), 0);
  std::vector<int> po_shuffled = po, wo_shuffled = wo;
  std::mt19937 rng(5);
  std::shuffle(po_shuffled.begin(), po_shuffled.end(), rng);
  std::shuffle(wo_shuffled.begin(), wo_shuffled.end(), rng);
  const int steps = 8;

  const Result<T> base = run<Law, Bits, T, DH>(st, po, wo, false, steps);
  // The runs must do real work, or equal bits would prove nothing.
  double fmax = 0, tmax = 0, growth = 0;
  for (std::size_t k = 0; k < base.force.size(); ++k) {
    fmax = std::max(fmax, std::abs(base.force[k]));
    tmax = std::max(tmax, std::abs(base.torque[k]));
  }
  for (int i = 0; i < st.n; ++i) growth = std::max(growth, base.radius[i] / st.r[i] - 1.0);
  for (double q : base.x) REQUIRE(std::isfinite(q));
  REQUIRE(fmax > 0);
  if (Bits & kFriction) REQUIRE(tmax > 0);
  if (std::is_same<Law, MdrLaw>::value && (Bits & kRadiusGrowth)) REQUIRE(growth > 1e-6);  // the radii grew

  SECTION("shuffled lists, every pair listed (j, i)") {
    require_same_bits(base, run<Law, Bits, T, DH>(st, po_shuffled, wo_shuffled, true, steps));
  }
  SECTION("every pair listed (j, i), list order kept") {
    require_same_bits(base, run<Law, Bits, T, DH>(st, po, wo, true, steps));
  }
#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
  SECTION("one thread (Serial) against the OpenMP pool, shuffled and swapped") {
    INFO("OpenMP threads: " << Kokkos::OpenMP().concurrency());
    if (Kokkos::OpenMP().concurrency() < 2) WARN("the OpenMP pool has one thread: 1 vs N threads not compared");
    const auto serial = run<Law, Bits, T, test::DeviceOf<Kokkos::Serial>>(st, po_shuffled, wo_shuffled, true, steps);
    const auto omp = run<Law, Bits, T, test::DeviceOf<Kokkos::OpenMP>>(st, po, wo, false, steps);
    require_same_bits(base, omp);
    require_same_bits(base, serial);
  }
#endif
}
