// MDR Part II's bulk response (models/mdr/mdr_bulk_response.hpp): each piece in closed form (the
// increment split, A_c, F_BULK, psi and V_geo with their guards), and a sphere squeezed evenly by
// six walls: its mean surface displacement equals each wall's approach, so once psi < psi_b the
// MDR overlap stops (delta_MDR constant to round-off), delta_BULK takes the whole increment, the
// MDR force stays put and F_BULK = kappa A_con,0 delta_BULK A_c / V_geo carries the rest; the
// radius stops growing. psi_b = 0 reproduces Part I. Host validation names the bad option.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/mdr/mdr_model.hpp>

#include "mdr_test_helpers.hpp"

#include <cmath>
#include <random>
#include <vector>

using namespace epac;
using test::mdr_material;
using test::rigid_wall_material;

namespace {

// E/Y 100: yields at about 0.002 R
Material grain() { return mdr_material(1e8, 0.3, 1e6); }

constexpr unsigned kBulkSet = kPlasticity | kRadiusGrowth | kBulkResponse;
constexpr unsigned kPartISet = kPlasticity | kRadiusGrowth;

MdrOptions options(double psi_b) {
  MdrOptions o;
  o.pair_split = MdrPairSplit::geometric;
  o.psi_b = psi_b;
  return o;
}

// One sphere of radius R at the origin in a cube of six walls, each at distance R - d.
template <class Model, class D>
struct Box {
  using T = typename Model::scalar_type;
  Model model;
  Particles<T, D> p{1};
  Walls<T, D> w{6};
  ContactList<D> c{6};
  ContactHistory<T, D> h{6, Model::history_size};
  ContactList<D> no_pairs{0};
  ContactHistory<T, D> no_history{0, Model::history_size};
  ContactOutputs<T, D> out;
  double R;

  Box(const MdrOptions& o, double radius) : model(Model::create({grain(), rigid_wall_material()}, o)), R(radius) {
    Kokkos::deep_copy(p.radius, T(R));
    Kokkos::deep_copy(p.radius0, T(R));
    Kokkos::deep_copy(p.mass, T(1e-6));
    auto mat = Kokkos::create_mirror_view(w.material);
    auto f = Kokkos::create_mirror_view(c.first);
    auto s = Kokkos::create_mirror_view(c.second);
    auto n = Kokkos::create_mirror_view(w.normal);
    for (int k = 0; k < 6; ++k) {
      mat(k) = 1;
      f(k) = 0;
      s(k) = k;
      for (int a = 0; a < 3; ++a) n(k, a) = T(0);
      n(k, k / 2) = T(k % 2 == 0 ? 1 : -1);  // pointing into the box
    }
    Kokkos::deep_copy(w.material, mat);
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, s);
    Kokkos::deep_copy(w.normal, n);
    out.normal_force = Kokkos::View<T*, D>("fn", 6);
    out.overlap = Kokkos::View<T*, D>("delta", 6);
    model.bind(p);
  }
  // One step at wall approach d (each wall at R - d from the centre, in the sphere's current R
  // frame: the apparent overlap is d + R - R_now... walls are placed from R_o, the grown sphere
  // sees more overlap). Returns the normal force on wall contact 0.
  double step(double d) {
    auto pt = Kokkos::create_mirror_view(w.point);
    for (int k = 0; k < 6; ++k) {
      for (int a = 0; a < 3; ++a) pt(k, a) = 0.0;
      pt(k, k / 2) = (k % 2 == 0 ? -1.0 : 1.0) * (R - d);
    }
    Kokkos::deep_copy(w.point, pt);
    model.compute_contact_penalty(p, no_pairs);
    model.compute_mean_surface_displacement(p, no_pairs, no_history, w, c, h);
    compute_wall_forces(model, p, w, c, h, T(1e-9), out);
    return double(test::to_host(out.normal_force)(0));
  }
  double field(int col) const { return double(test::to_host(h.data)(0, col)); }
};

}  // namespace

TEST_CASE("bulk response: the split of a side's increment", "[mdr][bulk]") {
  MdrBulkSide<double> b;
  // psi >= psi_b: all of it MDR
  CHECK(mdr_bulk_split(0.01, 0.6, 0.5, 0.004, b) == 0.01);
  CHECK(b.delta_bulk == 0.0);
  CHECK(b.delta_last == 0.01);
  // psi < psi_b: d delta_MDR = d delta - d delta-bar, d delta_BULK = d delta-bar
  CHECK(mdr_bulk_split(0.015, 0.4, 0.5, 0.003, b) == Approx(0.012).epsilon(1e-14));
  CHECK(b.delta_bulk == Approx(0.003).epsilon(1e-14));
  // bounded by delta - delta_MDR,prev (delta_MDR never passes the total overlap)
  MdrBulkSide<double> c{0.01, 0.002, 0.0, 0.0};
  CHECK(mdr_bulk_split(0.011, 0.1, 0.5, -0.05, c) == Approx(0.011).epsilon(1e-14));
  // delta_BULK >= 0 (a receding mean surface empties it, no tension)
  CHECK(c.delta_bulk == 0.0);
  // boundary: psi == psi_b is not triggered (LAMMPS: psi < psi_b)
  MdrBulkSide<double> e;
  CHECK(mdr_bulk_split(0.01, 0.5, 0.5, 0.004, e) == 0.01);
}

TEST_CASE("bulk response: A_c and F_BULK in closed form, with their domains", "[mdr][bulk]") {
  const double pi = constants<double>::pi;
  CHECK(mdr_bulk_area(0.01, 1.0, false, 0.0) == Approx(pi * 0.01));
  CHECK(mdr_bulk_area(0.01, 1.0, true, -0.003) == Approx(pi * (0.02 - 1e-4) - 0.003));
  CHECK(mdr_bulk_area(-0.01, 1.0, false, 0.0) == 0.0);  // a gap: no area
  CHECK(mdr_bulk_area(1e-6, 1.0, true, -0.01) == 0.0);  // c_A below the cap: floored at 0
  CHECK(mdr_bulk_force(2.0, 3.0, 4.0, 0.5, 5.0) == Approx(2.0 * 3.0 * 0.5 * 5.0 / 4.0));
  CHECK(mdr_bulk_force(2.0, 3.0, 4.0, 0.0, 5.0) == 0.0);
  CHECK(mdr_bulk_force(2.0, 3.0, 0.0, 0.0, 5.0) == 0.0);  // no bulk overlap: no division
}

TEMPLATE_LIST_TEST_CASE("bulk response: psi and V_geo from the pass's sums, guards at their edges", "[mdr][bulk]",
                        test::Backends) {
  using D = TestType;
  using T = double;
  const double pi = constants<double>::pi;
  Particles<T, D> p(3);
  Kokkos::deep_copy(p.radius, 1.0);
  Kokkos::deep_copy(p.radius0, 1.0);
  MdrBulkState<T, D> bs;
  bs.attach(p.radius0);
  bs.volume_floor = 0.1;
  auto sums = Kokkos::create_mirror_view(bs.sums.target);
  // particle 0: A_con 2, A_tot's sum -1, V_cap 0.5
  sums(0, 0) = 2.0;
  sums(0, 1) = -1.0;
  sums(0, 2) = 0.5;
  // particle 1: A_tot <= 0 (no free surface): psi = 0
  sums(1, 0) = 1.0;
  sums(1, 1) = -5.0 * pi;
  sums(1, 2) = 0.0;
  // particle 2: caps larger than the sphere: V_geo floored at 0.1 V_o
  sums(2, 0) = 0.0;
  sums(2, 1) = 0.0;
  sums(2, 2) = 10.0;
  Kokkos::deep_copy(bs.sums.target, sums);
  mdr_update_bulk(bs, p.radius, p.radius0);
  auto psi = test::to_host(bs.psi);
  auto vgeo = test::to_host(bs.vgeo);
  auto acon0 = test::to_host(bs.acon0);
  const double atot = 4 * pi - 1.0, V0 = 4.0 / 3.0 * pi;
  CHECK(psi(0) == Approx((atot - 2.0) / atot).epsilon(1e-14));
  CHECK(vgeo(0) == Approx(V0 - 0.5).epsilon(1e-14));
  CHECK(acon0(0) == 2.0);
  CHECK(psi(1) == 0.0);
  CHECK(psi(2) == 1.0);
  CHECK(vgeo(2) == Approx(0.1 * V0).epsilon(1e-14));
  CHECK(test::to_host(bs.vgeo_floored)(0) == 1);
  // the sums were taken: a second update sees none
  mdr_update_bulk(bs, p.radius, p.radius0);
  CHECK(test::to_host(bs.psi)(0) == 1.0);
  CHECK(test::to_host(bs.acon0)(0) == 0.0);
}

TEMPLATE_LIST_TEST_CASE("bulk response: a sphere squeezed evenly by six walls", "[mdr][bulk]", test::Backends) {
  using D = TestType;
  using M = Mdr<double, Effects<kBulkSet>, D>;
  using M1 = Mdr<double, Effects<kPartISet>, D>;
  const double R = 1e-3, psi_b = 0.9;
  Box<M, D> bulk(options(psi_b), R);
  Box<M1, D> part1(options(0.0), R);
  using SF = typename M::SideField;
  const int b0 = M::side_base(0);
  const double kappa = 1e8 / (3.0 * (1.0 - 2.0 * 0.3));
  const double dd = 1e-4 * R;
  bool triggered = false;
  int after = 0;
  double prev_mdr = 0, prev_bulk = 0, prev_R = R, mdr_part = 0;
  for (int k = 1; k <= 2000 && after < 200; ++k) {
    const double d = k * dd;
    const double psi_before = test::to_host(bulk.model.bulk.psi)(0);
    const double acon0 = test::to_host(bulk.model.bulk.acon0)(0);
    const double vgeo = test::to_host(bulk.model.bulk.vgeo)(0);
    const double R_before = test::to_host(bulk.p.radius)(0);
    const double f = bulk.step(d);
    const double ddbar = test::to_host(bulk.model.bulk.ddelta_bar)(0);
    const double f1 = part1.step(d);
    const double dmdr = bulk.field(b0 + SF::bulk_delta_mdr), dbulk = bulk.field(b0 + SF::bulk_delta_bulk);
    const double area_w = bulk.field(b0 + SF::bulk_area_w);
    REQUIRE(std::isfinite(f));
    if (psi_before >= psi_b) {
      // Part I until psi falls below psi_b (delta_MDR accumulates the increments: round-off)
      REQUIRE(f == Approx(f1).epsilon(1e-11));
      REQUIRE(dbulk == 0.0);
      REQUIRE(!triggered);
    } else {
      triggered = true;
      ++after;
      // six equal contacts that all touched last pass: the mean surface displacement is each
      // wall's approach, so delta_MDR stops and delta_BULK takes the increment
      REQUIRE(ddbar == Approx(dd).epsilon(1e-9));
      if (after > 1) {
        REQUIRE(std::abs(dmdr - prev_mdr) <= 1e-9 * dd);
        REQUIRE(dbulk - prev_bulk == Approx(ddbar).epsilon(1e-9));
        // confined: no growth
        REQUIRE(test::to_host(bulk.p.radius)(0) == R_before);
      }
      // F = F_MDR + F_BULK with F_BULK in closed form; F_MDR frozen with delta_MDR and R
      const double f_bulk = kappa * acon0 * dbulk * area_w / vgeo;  // w = 1 at walls: area_w = A_c
      if (after == 2) mdr_part = f - f_bulk;
      if (after > 2) REQUIRE(f - f_bulk == Approx(mdr_part).epsilon(1e-9));
      REQUIRE(f > 0.0);
    }
    prev_mdr = dmdr;
    prev_bulk = dbulk;
    bulk.model.update_radii();
    part1.model.update_radii();
    if (!triggered) {
      // psi in closed form from this pass: A_tot = 4 pi R^2 + 6 (A_c - 2 pi R delta_max), A_con = 6 A_c
      const double pi = constants<double>::pi;
      const double Rn = R_before, Ac = area_w;
      const double dmax = bulk.field(b0 + SF::delta_o_max) + (Rn - R);  // (19)
      const double atot = 4 * pi * Rn * Rn + 6 * (Ac - 2 * pi * Rn * dmax);
      REQUIRE(test::to_host(bulk.model.bulk.psi)(0) == Approx((atot - 6 * Ac) / atot).epsilon(1e-10));
    }
    prev_R = test::to_host(bulk.p.radius)(0);
  }
  CHECK(triggered);
  CHECK(after == 200);
  CHECK(prev_R > R);  // it grew before the bulk response set in
}

TEST_CASE("bulk response: host validation", "[mdr][bulk]") {
  using M = Mdr<double, Effects<kBulkSet>>;
  using M1 = Mdr<double, Effects<kPartISet>>;
  MdrOptions o = options(1.5);
  CHECK_THROWS_WITH(M::create({grain()}, o), Catch::Contains("psi_b") && Catch::Contains("1.5"));
  o = options(0.5);
  o.pair_split = MdrPairSplit::balanced;
  CHECK_THROWS_WITH(M::create({grain()}, o), Catch::Contains("pair_split = geometric"));
  CHECK_THROWS_WITH(M1::create({grain()}, options(0.5)), Catch::Contains("kBulkResponse"));
  CHECK_NOTHROW(M::create({grain()}, options(0.5)));
  CHECK_NOTHROW(M1::create({grain()}, options(0.0)));
}

// The mean surface displacement's pre-pass reads only the overlap and the radii of a pair
// (pair_overlap_geometry, compute/pair_wall_geometry.hpp): they must be the force pass's bits
// (pair_geometry_exact), across periodic boundaries, in both orientations, or the pre-pass would
// measure a different split than the force pass applies. Random pairs near each other in a small
// periodic box (every separation below L/2), with coordinates wrapped into it.
TEMPLATE_LIST_TEST_CASE("bulk response: the pre-pass sees the force pass's overlap and radii", "[mdr][bulk]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const int n = 200;
  const double L = 5e-3, R = 1e-3;
  Particles<T, D> p(n);
  auto x = Kokkos::create_mirror_view(p.x);
  auto r = Kokkos::create_mirror_view(p.radius);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; i += 2) {
    for (int d = 0; d < 3; ++d) {
      const double a = L * u(rng);
      const double b = a + (u(rng) - 0.5) * 3.0 * R;  // within 1.5 R of a on each axis, often across the box edge
      x(i, d) = a;
      x(i + 1, d) = b - L * std::floor(b / L);
    }
    r(i) = T(R * (0.8 + 0.4 * u(rng)));
    r(i + 1) = T(R * (0.8 + 0.4 * u(rng)));
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.mass, T(1e-6));
  p.box.length = Vec3<double>(L, L, L);
  Kokkos::View<int*, D> bad("bad", 1);
  Kokkos::parallel_for(
      "mdr_test::overlap_geometry", Kokkos::RangePolicy<typename D::execution_space>(0, n), KOKKOS_LAMBDA(int k) {
        const int i = k, j = k % 2 == 0 ? k + 1 : k - 1;  // both orientations of each pair
        double delta;
        const ContactGeometry<T> full = detail::pair_geometry_exact<T, D, false>(p, i, j, 1, delta);
        const ContactGeometry<T> lean = detail::pair_overlap_geometry(p, i, j);
        if (!(lean.delta == full.delta && lean.R_i == full.R_i && lean.R_j == full.R_j && lean.i == full.i &&
              lean.j == full.j && lean.i_is_first == full.i_is_first))
          Kokkos::atomic_increment(&bad(0));
      });
  CHECK(test::to_host(bad)(0) == 0);
}
