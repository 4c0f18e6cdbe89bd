// history_from_overlaps (compute/history_from_overlaps.hpp): the history of a quasi-static load to
// the present overlaps. Compared with the same load done by the force kernel in many small steps
// (single wall contact, single pair, an fcc cluster whose particles share contacts), and with a
// fresh start (the jump it avoids); Nan 2022, JKR and Hertz-Mindlin states; input rejection.
#include "mdr_test_helpers.hpp"

#include <catch2/catch.hpp>
#include <epac/compute/history_from_overlaps.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include <cmath>
#include <functional>
#include <vector>

using namespace epac;
using namespace epac::test;

namespace {

// A small system: particles (material 0), pairs, walls (material 1) and their wall contacts.
template <class T, class D>
struct System {
  Particles<T, D> p;
  Walls<T, D> w;
  ContactList<D> pairs, wall_contacts;
  ContactHistory<T, D> ph, wh;
  std::vector<std::array<double, 3>> x;  // host positions (to scale)

  System(const std::vector<std::array<double, 3>>& pos, const std::vector<double>& radii,
         const std::vector<std::pair<int, int>>& pair_list, const std::vector<std::array<double, 6>>& wall_planes,
         const std::vector<std::pair<int, int>>& wall_list, int fields)
      : p(static_cast<int>(pos.size())),
        w(static_cast<int>(wall_planes.size())),
        pairs(static_cast<int>(pair_list.size())),
        wall_contacts(static_cast<int>(wall_list.size())),
        ph(static_cast<int>(pair_list.size()), fields),
        wh(static_cast<int>(wall_list.size()), fields),
        x(pos) {
    const int n = p.n;
    auto r = Kokkos::create_mirror_view(p.radius0);
    auto m = Kokkos::create_mirror_view(p.mass);
    auto g = Kokkos::create_mirror_view(p.gid);
    for (int i = 0; i < n; ++i) {
      r(i) = T(radii[i]);
      m(i) = T(1);
      g(i) = 1000 - 3 * i;
    }  // gids unrelated to order
    Kokkos::deep_copy(p.radius0, r);
    Kokkos::deep_copy(p.radius, r);
    Kokkos::deep_copy(p.mass, m);
    Kokkos::deep_copy(p.gid, g);
    set_positions(1.0);
    auto wp = Kokkos::create_mirror_view(w.point);
    auto wn = Kokkos::create_mirror_view(w.normal);
    auto wm = Kokkos::create_mirror_view(w.material);
    for (int k = 0; k < w.n; ++k) {
      for (int d = 0; d < 3; ++d) {
        wp(k, d) = T(wall_planes[k][d]);
        wn(k, d) = T(wall_planes[k][3 + d]);
      }
      wm(k) = 1;
    }
    Kokkos::deep_copy(w.point, wp);
    Kokkos::deep_copy(w.normal, wn);
    Kokkos::deep_copy(w.material, wm);
    fill(pairs, pair_list);
    fill(wall_contacts, wall_list);
  }
  static void fill(ContactList<D>& c, const std::vector<std::pair<int, int>>& l) {
    auto f = Kokkos::create_mirror_view(c.first);
    auto s = Kokkos::create_mirror_view(c.second);
    for (std::size_t k = 0; k < l.size(); ++k) {
      f(k) = l[k].first;
      s(k) = l[k].second;
    }
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, s);
  }
  // positions scaled about the origin by `scale` (affine)
  void set_positions(double scale) {
    auto hx = Kokkos::create_mirror_view(p.x);
    for (int i = 0; i < p.n; ++i)
      for (int d = 0; d < 3; ++d) hx(i, d) = T(scale * x[i][d]);
    Kokkos::deep_copy(p.x, hx);
  }
  void set_position(int i, const std::array<double, 3>& xi) {
    x[i] = xi;
    set_positions(1.0);
  }
};

// One force pass over both lists plus the model's particle update (what a host does per step).
template <class Model, class T, class D>
void force_pass(const Model& model, System<T, D>& s) {
  zero_forces(s.p);
  compute_pair_forces(model, s.p, s.pairs, s.ph, T(0));
  if (s.wall_contacts.count > 0) compute_wall_forces(model, s.p, s.w, s.wall_contacts, s.wh, T(0));
  model.update_radii();
}

template <class T, class D>
std::vector<double> host_vector(const Kokkos::View<T*, D>& v) {
  auto h = to_host(v);
  std::vector<double> out(h.extent(0));
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = h(k);
  return out;
}

template <class T, class D>
std::vector<std::vector<double>> host_rows(const ContactHistory<T, D>& h) {
  auto d = to_host(h.data);
  std::vector<std::vector<double>> out(d.extent(0), std::vector<double>(d.extent(1)));
  for (std::size_t k = 0; k < d.extent(0); ++k)
    for (std::size_t f = 0; f < d.extent(1); ++f) out[k][f] = d(k, f);
  return out;
}

// MDR history fields of one side (mdr_model.hpp layout with plasticity and growth, no adhesion):
// delta_o_max, yielded, c_A, delta_p, delta_o_prev, eps_prev.

double E = 1.0e8;  // and kNu (mdr_test_helpers.hpp)

}  // namespace

// Tolerances of the comparisons below. Both paths integrate the growth sums of MDR (37)
// explicitly in delta_o, so each carries an O(1/n) error in R - R_o: measured at E/Y = 20 to
// delta_o = 0.2 R_o, R - R_o from K = 100 increments differs from the 4000-step load by
// about 0.5% of the growth in double (the error halves with K), so 2% of the growth leaves room
// for other parameters; quantities that depend on R (delta_p, V, the force of the next pass)
// inherit that error relative to their own change. delta_o_max, yielded and c_A do not depend
// on the path at all (delta_o_max = delta_o, c_A from delta_Y before any growth): round-off only.
TEMPLATE_LIST_TEST_CASE("history_from_overlaps, MDR wall contact: equals a load in 4000 small steps",
                        "[mdr][initial_history]", BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double R0 = 1e-3, target = 0.2 * R0;
  const double tol_growth = std::is_same<T, float>::value ? 0.05 : 0.02;
  const double eps = std::is_same<T, float>::value ? 1e-5 : 1e-12;
  for (double EY : {20.0, 200.0}) {
    INFO("E/Y = " << EY);
    auto make = [&]() {
      // the sphere's centre at R_o - delta_o above the floor
      return System<T, D>({{0.0, 0.0, R0 - target}}, {R0}, {}, {{0, 0, 0, 0, 0, 1}}, {{0, 0}}, M::history_size);
    };
    M ref_model = M::create({mdr_material(E, kNu, E / EY), rigid_wall_material()});
    System<T, D> ref = make();
    ref_model.bind(ref.p);
    const int n = 4000;
    for (int k = 1; k <= n; ++k) {
      ref.set_position(0, {0.0, 0.0, R0 - target * double(k) / n});
      force_pass(ref_model, ref);
    }
    M init_model = M::create({mdr_material(E, kNu, E / EY), rigid_wall_material()});
    System<T, D> init = make();
    init_model.bind(init.p);
    {
      auto f = Kokkos::create_mirror_view(init.p.force);
      f(0, 0) = T(1.5);
      f(0, 1) = T(-2.5);
      f(0, 2) = T(3.5);  // forces must stay untouched
      Kokkos::deep_copy(init.p.force, f);
    }
    const HistoryFromOverlapsReport rep =
        history_from_overlaps(init_model, init.p, init.pairs, init.ph, init.w, init.wall_contacts, init.wh);
    {
      auto f = to_host(init.p.force);
      CHECK(f(0, 0) == T(1.5));
      CHECK(f(0, 1) == T(-2.5));
      CHECK(f(0, 2) == T(3.5));
    }
    CHECK(rep.overlaps.wall_contacts == 1);
    CHECK(rep.overlaps.pair_contacts == 0);
    CHECK(rep.overlaps.max_overlap_ratio == Approx(0.2).epsilon(1e-5));
    CHECK(rep.increments == kHistoryFromOverlapsIncrements);
    CHECK(rep.guard_hits == 0);
    const double R_ref = host_vector(ref.p.radius)[0], R_init = host_vector(init.p.radius)[0];
    const double V_ref = host_vector(ref_model.growth.volume)[0], V_init = host_vector(init_model.growth.volume)[0];
    const double growth = R_ref - R0;
    REQUIRE(growth > 0.005 * R0);  // a load that grows R (else the comparison says nothing)
    CHECK(rep.max_radius_ratio == Approx(R_init / R0).epsilon(1e-6));
    CHECK(std::fabs(R_init - R_ref) < tol_growth * growth);
    const double V0 = 4.0 / 3.0 * M_PI * R0 * R0 * R0;
    CHECK(std::fabs(V_init - V_ref) < tol_growth * std::fabs(V_ref - V0) + eps * V0);
    // a wall row has the pair fields (unused) first, then the one side
    auto hr = host_rows(ref.wh)[0], hi = host_rows(init.wh)[0];
    hr.erase(hr.begin(), hr.begin() + M::pair_fields);
    hi.erase(hi.begin(), hi.begin() + M::pair_fields);
    CHECK(hi[0] == Approx(hr[0]).epsilon(eps * 10));  // delta_o_max = delta_o
    CHECK(hi[0] == Approx(target).epsilon(eps * 10));
    CHECK(hi[1] == 1.0);  // yielded
    CHECK(hr[1] == 1.0);
    CHECK(hi[2] == Approx(hr[2]).epsilon(eps * 10));  // c_A
    // delta_p = delta_max - (A/2) r: its change with R is that of delta_max = delta_o,max + growth
    CHECK(std::fabs(hi[3] - hr[3]) < tol_growth * growth + eps * R0);
    CHECK(hi[4] == Approx(hr[4]).epsilon(eps * 10));                        // delta_o_prev = delta_o
    CHECK(std::fabs(hi[5] - hr[5]) < tol_growth * std::fabs(hr[5]) + eps);  // eps_prev (38): F (R - delta) / V
    // The next force pass at the same position: the same force, and no jump of R
    force_pass(ref_model, ref);
    force_pass(init_model, init);
    const double F_ref = to_host(ref.p.force)(0, 2), F_init = to_host(init.p.force)(0, 2);
    CHECK(F_ref > 0.0);
    CHECK(std::fabs(F_init - F_ref) < 5.0 * tol_growth * F_ref);
    const double R_after = host_vector(init.p.radius)[0];
    CHECK(R_after - R_init < 1e-3 * growth + eps * R0);
  }
}

TEMPLATE_LIST_TEST_CASE("history_from_overlaps, MDR pair of unequal spheres: equals a load in 4000 small steps",
                        "[mdr][initial_history]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double R0 = 1e-3, R1 = 0.6e-3, target = 0.2 * R1;
  const std::vector<Material> mats = {mdr_material(E, kNu, E / 20.0), rigid_wall_material()};
  auto make = [&]() {
    return System<T, D>({{0, 0, 0}, {R0 + R1 - target, 0, 0}}, {R0, R1}, {{1, 0}}, {}, {}, M::history_size);
  };
  M ref_model = M::create(mats);
  System<T, D> ref = make();
  ref_model.bind(ref.p);
  const int n = 4000;
  for (int k = 1; k <= n; ++k) {
    ref.set_position(1, {R0 + R1 - target * double(k) / n, 0, 0});
    force_pass(ref_model, ref);
  }
  M init_model = M::create(mats);
  System<T, D> init = make();
  init_model.bind(init.p);
  const HistoryFromOverlapsReport rep = history_from_overlaps(init_model, init.p, init.pairs, init.ph);
  CHECK(rep.overlaps.pair_contacts == 1);
  CHECK(rep.overlaps.max_overlap_ratio == Approx(0.2).epsilon(1e-9));  // over the smaller radius
  const auto Rr = host_vector(ref.p.radius), Ri = host_vector(init.p.radius);
  const double radii0[2] = {R0, R1};
  // one material, default split (equal_pair): both sides are the side of the equal pair (radius
  // 2 R*) at delta_o/2, so both yield together and both particles grow, on both paths (under the
  // previous default, the radical plane, only the smaller sphere yielded)
  REQUIRE(Rr[0] - R0 > 1e-5 * R0);  // 8.3e-5 R_o measured: its share spread over a larger sphere
  REQUIRE(Rr[1] - R1 > 2e-4 * R1);  // 7.5e-4 R_o measured
  for (int i = 0; i < 2; ++i) {
    INFO("particle " << i);
    const double growth = Rr[i] - radii0[i];
    // the load's 100 increments against the reference's 4000 steps: measured 3.7% (larger) and 3.2%
    // (smaller sphere) of the growth with the default split, where both spheres yield and share the
    // displaced volume (under the previous default only the smaller one grew, within 2%)
    CHECK(std::fabs(Ri[i] - Rr[i]) <= 0.05 * growth);
  }
  const auto hr = host_rows(ref.ph)[0], hi = host_rows(init.ph)[0];
  CHECK(hi[0] == Approx(target).epsilon(1e-12));  // largest total delta_o of the pair (19)
  CHECK(hr[0] == Approx(target).epsilon(1e-12));
  for (int s = 0; s < 2; ++s) {
    INFO("side " << s);
    const int b = M::side_base(s);
    const double growth = std::fabs(Rr[s == 0 ? 1 : 0] - radii0[s == 0 ? 1 : 0]);  // side 0: smaller gid
    CHECK(hi[b + 0] == Approx(hr[b + 0]).epsilon(0.02));  // the side's delta_o,max: split by the grown radii
    CHECK(hi[b + 1] == hr[b + 1]);
    CHECK(hi[b + 1] == 1.0);  // both sides yielded
    CHECK(hi[b + 2] == Approx(hr[b + 2]).epsilon(1e-9));
    CHECK(std::fabs(hi[b + 3] - hr[b + 3]) < 0.05 * growth + 1e-12);
  }
  // next pass at the same positions: equal forces (the share of the growth error), no jump
  force_pass(ref_model, ref);
  force_pass(init_model, init);
  const double F_ref = to_host(ref.p.force)(0, 0), F_init = to_host(init.p.force)(0, 0);
  CHECK(std::fabs(F_ref) > 0.0);
  CHECK(std::fabs(F_init - F_ref) < 0.1 * std::fabs(F_ref));
  const auto Ra = host_vector(init.p.radius);
  for (int i = 0; i < 2; ++i) CHECK(Ra[i] - Ri[i] <= 1e-3 * (Ri[i] - radii0[i]));
}

namespace {
// An fcc cluster of equal spheres (2 x 2 x 2 cells, 32 particles, centred on the origin) at
// nearest-neighbour distance 2 R_o - delta: every particle shares contacts with up to 12 others.
std::vector<std::array<double, 3>> fcc_cluster(double R, double delta, std::vector<std::pair<int, int>>& nn) {
  const double a = std::sqrt(2.0) * (2.0 * R - delta);
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<std::array<double, 3>> x;
  for (int cx = 0; cx < 2; ++cx)
    for (int cy = 0; cy < 2; ++cy)
      for (int cz = 0; cz < 2; ++cz)
        for (auto& b : basis) x.push_back({a * (cx + b[0] - 0.75), a * (cy + b[1] - 0.75), a * (cz + b[2] - 0.75)});
  const double dnn = a / std::sqrt(2.0);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += (x[i][d] - x[j][d]) * (x[i][d] - x[j][d]);
      if (std::sqrt(d2) < 1.2 * dnn) nn.push_back({int(j), int(i)});  // nearest neighbours; mixed order
    }
  return x;
}
}  // namespace

// The coupled case: each particle's growth comes from all its contacts at once. An affine
// compression of the cluster from first touch scales every contact's delta_o by the same s (all
// nearest-neighbour distances are equal), which is the proportional load of history_from_overlaps;
// done by the force kernel in 2000 steps, it must give the same radii. Tolerance 5% of each
// particle's growth: the time-stepped compression is itself increment-sensitive at this level
// (a side feeds (37) only in steps where its own delta_o is at its maximum, a binary test that the
// neighbours' growth flips): measured, loads in 500, 1000 and 4000 steps differ from the 2000-step
// one by 2.2%, 2.5% and 3.0% of the growth, and K = 100 increments by 3.1%.
TEMPLATE_LIST_TEST_CASE(
    "history_from_overlaps, MDR fcc cluster at 0.2 R: equals an affine quasi-static compression; "
    "a fresh start jumps",
    "[mdr][initial_history]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double R = 1e-3, target = 0.2 * R;
  std::vector<std::pair<int, int>> nn;
  const auto x = fcc_cluster(R, target, nn);
  const int np = static_cast<int>(x.size());
  REQUIRE(nn.size() == 108u);  // 2 x 2 x 2 fcc cells, free surfaces
  const std::vector<Material> mats = {mdr_material(E, kNu, E / 20.0), rigid_wall_material()};
  const std::vector<double> radii(np, R);

  M ref_model = M::create(mats);
  System<T, D> ref(x, radii, nn, {}, {}, M::history_size);
  ref_model.bind(ref.p);
  const int n = 2000;
  for (int k = 1; k <= n; ++k) {
    const double s = double(k) / n;  // delta_o = s target: distance 2R - s target
    ref.set_positions((2.0 * R - s * target) / (2.0 * R - target));
    force_pass(ref_model, ref);
  }
  M init_model = M::create(mats);
  System<T, D> init(x, radii, nn, {}, {}, M::history_size);
  init_model.bind(init.p);
  const HistoryFromOverlapsReport rep = history_from_overlaps(init_model, init.p, init.pairs, init.ph);
  CHECK(rep.overlaps.pair_contacts == 108);
  CHECK(rep.overlaps.max_overlap_ratio == Approx(0.2).epsilon(1e-9));
  CHECK(rep.guard_hits == 0);
  const auto Rr = host_vector(ref.p.radius), Ri = host_vector(init.p.radius);
  double max_growth = 0;
  for (int i = 0; i < np; ++i) {
    INFO("particle " << i);
    const double growth = Rr[i] - R;
    max_growth = std::max(max_growth, growth);
    CHECK(std::isfinite(Ri[i]));
    CHECK(Ri[i] < 1.5 * R);
    CHECK(std::fabs(Ri[i] - Rr[i]) < 0.05 * growth + 1e-12 * R);
  }
  REQUIRE(max_growth > 0.01 * R);
  // the largest ratio, within the per-particle bound above (5% of the growth: the balanced pair
  // split moves with the grown radii, K = 100 increments against 2000 steps)
  CHECK(rep.max_radius_ratio == Approx(1.0 + max_growth / R).epsilon(0.05 * max_growth / R));

  // The next passes at the same positions: no further growth to speak of. A fresh history at the
  // same positions takes the whole overlap as one plastic increment: R jumps by more than the
  // whole quasi-static growth in one pass (this is what history_from_overlaps prevents).
  // Bound: less than one load increment's share of the growth (1/K = 1%) over three passes. It is
  // not zero: the grown radii move the pair split's radical plane, so one side of a pair meets a
  // new maximum of its delta_o: measured 0.38% of the growth in three passes here, and 0.14% for
  // the 2000-step load held at rest.
  for (int k = 0; k < 3; ++k) force_pass(init_model, init);
  const auto Ra = host_vector(init.p.radius);
  for (int i = 0; i < np; ++i) CHECK(Ra[i] - Ri[i] < 0.01 * (Ri[i] - R) + 1e-12 * R);
  M fresh_model = M::create(mats);
  System<T, D> fresh(x, radii, nn, {}, {}, M::history_size);
  fresh_model.bind(fresh.p);
  force_pass(fresh_model, fresh);
  const auto Rf = host_vector(fresh.p.radius);
  double fresh_growth = 0;
  for (int i = 0; i < np; ++i) fresh_growth = std::max(fresh_growth, Rf[i] - R);
  CHECK(fresh_growth > 1.5 * max_growth);
  // overlaps after the load stay below R (apparent overlap: delta_o plus both growths)
  const double delta_after = target + 2.0 * max_growth;
  CHECK(delta_after < 0.5 * R);
}

// Laws without growth: their state depends only on the largest overlap and the contact's
// loading, so the state after the load must equal a load in small steps exactly (up to
// round-off); tangential history is zero whatever it held.
TEMPLATE_LIST_TEST_CASE("history_from_overlaps: Nan 2022, JKR, Hertz-Mindlin states equal a load in small steps",
                        "[initial_history][nan2022][jkr][hertz]", Backends) {
  using D = TestType;
  using T = double;
  const double R0 = 1e-3, R1 = 0.7e-3, target = 0.1 * R1;
  Material m = mdr_material(7e10, 0.3, 3e8, 0.5);  // adhesive, yields below the target overlap
  m.friction = 0.3;
  const std::vector<Material> mats = {m, rigid_wall_material()};
  // one pair and one wall contact (sphere 0 on the floor)
  auto make = [&](int fields) {
    return System<T, D>({{0, 0, R0 - target}, {R0 + R1 - target, 0, R0 - target}}, {R0, R1}, {{0, 1}},
                        {{0, 0, 0, 0, 0, 1}}, {{0, 0}}, fields);
  };
  auto check_model = [&](auto model, const char* name) {
    using M = decltype(model);
    INFO(name);
    System<T, D> ref = make(M::history_size);
    // reference: both contacts loaded in 500 steps (sphere 1 moves along x, sphere 0 along z;
    // the pair's overlap then moves only by the x motion: keep sphere 0 at its final height)
    System<T, D> init = make(M::history_size);
    const int n = 500;
    for (int k = 1; k <= n; ++k) {
      const double s = double(k) / n;
      ref.x[0] = {0, 0, R0 - s * target};
      ref.x[1] = {R0 + R1 - s * target, 0, R0 - s * target};
      ref.set_positions(1.0);
      zero_forces(ref.p);
      compute_pair_forces(model, ref.p, ref.pairs, ref.ph, T(1e-7));
      compute_wall_forces(model, ref.p, ref.w, ref.wall_contacts, ref.wh, T(1e-7));
    }
    // garbage in the rows: all overwritten
    Kokkos::deep_copy(init.ph.data, T(7));
    Kokkos::deep_copy(init.wh.data, T(7));
    history_from_overlaps(model, init.p, init.pairs, init.ph, init.w, init.wall_contacts, init.wh);
    const auto pr = host_rows(ref.ph)[0], pi = host_rows(init.ph)[0];
    const auto wr = host_rows(ref.wh)[0], wi = host_rows(init.wh)[0];
    for (int f = 0; f < M::normal_history_size; ++f) {
      INFO("field " << f);
      CHECK(pi[f] == Approx(pr[f]).epsilon(1e-12));
      CHECK(wi[f] == Approx(wr[f]).epsilon(1e-12));
    }
    for (int f = M::normal_history_size; f < M::history_size; ++f) {
      CHECK(pi[f] == 0.0);
      CHECK(wi[f] == 0.0);
    }
    return std::make_pair(pi, wi);
  };
  {
    using M = Nan2022<T, Effects<kAdhesion | kPlasticity | kFriction>, D>;
    const auto r = check_model(M::create(mats), "nan2022");
    CHECK(r.first[M::alpha_max_field] == Approx(target).epsilon(1e-12));  // alpha_max = delta
    CHECK(r.second[M::alpha_max_field] == Approx(target).epsilon(1e-12));
    CHECK(r.first[M::state_field] != 0.0);  // in contact (loaded), not a fresh contact
  }
  {
    using M = epac::Jkr<T, Effects<kAdhesion | kFriction>, D>;
    const auto r = check_model(M::create(mats), "jkr");
    CHECK(r.first[0] != 0.0);  // in adhesive contact
  }
  {
    using M = HertzMindlin<T, Effects<kFriction>, D>;
    check_model(M::create(mats), "hertz_mindlin");
  }
}

TEMPLATE_LIST_TEST_CASE("history_from_overlaps: rejected inputs leave every view unchanged",
                        "[initial_history][validation]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double R = 1e-3;
  M model = M::create({mdr_material(E, kNu, E / 20.0), rigid_wall_material()});
  System<T, D> s({{0, 0, 0}, {1.8 * R, 0, 0}}, {R, R}, {{0, 1}}, {}, {}, M::history_size);
  model.bind(s.p);
  Kokkos::deep_copy(s.ph.data, T(3));
  auto unchanged = [&]() {
    for (const auto& row : host_rows(s.ph))
      for (double v : row) CHECK(v == 3.0);
    for (double r : host_vector(s.p.radius)) CHECK(r == R);
  };
  CHECK_THROWS_WITH(history_from_overlaps(model, s.p, s.pairs, s.ph, 0),
                    Catch::Contains("increments") && Catch::Contains("0"));
  unchanged();
  ContactHistory<T, D> narrow(1, M::history_size - 1);
  CHECK_THROWS_WITH(history_from_overlaps(model, s.p, s.pairs, narrow),
                    Catch::Contains("fields") && Catch::Contains(std::to_string(M::history_size)));
  unchanged();
  ContactHistory<T, D> short_rows(0, M::history_size);
  CHECK_THROWS_WITH(history_from_overlaps(model, s.p, s.pairs, short_rows), Catch::Contains("rows"));
  unchanged();
}

// Contacts that do not overlap keep a fresh history; growth that closes their gap loads them
// (the centre distance is held; only growth moves their surfaces).
TEMPLATE_LIST_TEST_CASE("history_from_overlaps: open contacts stay fresh unless growth closes them",
                        "[mdr][initial_history]", Backends) {
  using D = TestType;
  using T = double;
  using M = Mdr<T, Effects<kPlasticity | kRadiusGrowth>, D>;
  const double R = 1e-3;
  M model = M::create({mdr_material(E, kNu, E / 20.0), rigid_wall_material()});
  // 0-1 overlap by 0.2 R; 1-2 apart by 0.5 R (never closed); 0 on a wall at 0.2 R
  System<T, D> s({{0, 0, 0.8 * R}, {1.8 * R, 0, 0.8 * R}, {4.3 * R, 0, 0.8 * R}}, {R, R, R}, {{0, 1}, {1, 2}},
                 {{0, 0, 0, 0, 0, 1}}, {{0, 0}}, M::history_size);
  model.bind(s.p);
  const HistoryFromOverlapsReport rep = history_from_overlaps(model, s.p, s.pairs, s.ph, s.w, s.wall_contacts, s.wh);
  CHECK(rep.overlaps.pair_contacts == 1);
  CHECK(rep.overlaps.wall_contacts == 1);
  const auto rows = host_rows(s.ph);
  CHECK(rows[0][0] == Approx(0.2 * R).epsilon(1e-12));
  for (double v : rows[1]) CHECK(v == 0.0);
  const auto Rs = host_vector(s.p.radius);
  CHECK(Rs[0] > Rs[1]);  // particle 0 has two plastic contacts, particle 1 one
  CHECK(Rs[1] > R);
  CHECK(Rs[2] == R);
}
