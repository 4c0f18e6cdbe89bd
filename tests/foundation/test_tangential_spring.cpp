// The tangential spring, Nan (21)-(23): stick below the Coulomb limit (F_t = -k_t delta_t),
// slip at it (|F_t| = mu f), force opposite to the displacement, history rotated into the new
// tangent plane with its length kept.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include "verlet_stepper.hpp"

#include <cmath>

using namespace epac;

namespace {
Material soft(double mu) {
  Material m;
  m.name = "soft";
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.friction = mu;
  return m;
}
Material rigid() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  return m;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("tangential spring sticks, slips at mu f, and opposes the displacement", "[tangential]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = HertzMindlin<T, Effects<kFriction>, D>;
  const double mu = 0.3, R = 1e-3, delta = 1e-5, vt = 1e-3, dt = 1e-6;
  auto model = Model::create({soft(mu), rigid()});
  // One sphere resting on the plane z = 0 with a fixed overlap, sliding along +y.
  Particles<T, D> p(1);
  auto x = Kokkos::create_mirror_view(p.x);
  Kokkos::deep_copy(x, T(0));
  x(0, 2) = T(R - delta);
  auto v = Kokkos::create_mirror_view(p.v);
  Kokkos::deep_copy(v, T(0));
  v(0, 1) = T(vt);
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.radius, T(R));
  Kokkos::deep_copy(p.mass, T(1e-6));
  Kokkos::deep_copy(p.material, 0);
  Walls<T, D> w(1);
  auto wn = Kokkos::create_mirror_view(w.normal);
  Kokkos::deep_copy(wn, T(0));
  wn(0, 2) = T(1);
  Kokkos::deep_copy(w.normal, wn);
  Kokkos::deep_copy(w.material, 1);
  ContactList<D> c(1);
  Kokkos::deep_copy(c.first, 0);
  Kokkos::deep_copy(c.second, 0);
  ContactHistory<T, D> h(1, Model::history_size);

  const double E_star = 1e7 / (1 - 0.09), G = 1e7 / 2.6, G_star = G / (2 - 0.3);
  const double f = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(delta, 1.5);
  const double kt = 4 * G_star / E_star * 2 * E_star * std::sqrt(R * delta);
  const double ttol = std::is_same<T, float>::value ? 2e-3 : 1e-9;  // float: delta from R - x
  const int n_stick = static_cast<int>(0.5 * mu * f / (kt * vt * dt));
  REQUIRE(n_stick > 3);
  for (int s = 1; s <= 4 * n_stick; ++s) {
    zero_forces(p);
    compute_wall_forces(model, p, w, c, h, T(dt));
    auto F = test::to_host(p.force);
    const double ft = F(0, 1);
    CHECK(ft <= 0);  // opposes the +y displacement
    if (s <= n_stick) {
      CHECK(-ft == Approx(kt * vt * dt * s).epsilon(ttol));  // stick: Nan (21)
    } else if (s >= 3 * n_stick) {
      CHECK(-ft == Approx(mu * f).epsilon(ttol));  // slip: Nan (23)
    }
    CHECK(F(0, 0) == T(0));
  }
  // Reverse the motion: the force unloads elastically from the slip limit by k_t v dt per step.
  Kokkos::deep_copy(v, T(0));
  v(0, 1) = T(-vt);
  Kokkos::deep_copy(p.v, v);
  zero_forces(p);
  compute_wall_forces(model, p, w, c, h, T(dt));
  auto F = test::to_host(p.force);
  CHECK(-F(0, 1) == Approx(mu * f - kt * vt * dt).epsilon(ttol));
}

TEMPLATE_LIST_TEST_CASE("tangential history is rotated into the new tangent plane, length kept", "[tangential]",
                        test::Backends) {
  using D = TestType;
  using T = double;
  Kokkos::View<T*, D> out("out", 4);
  typename ContactHistory<T, D>::data_view data("h", 1, 3);
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) {
        data(0, 0) = 2;
        data(0, 1) = 0;
        data(0, 2) = 0;
        HistoryRow<T, D> row{data, 0, 0};
        NormalForce<T> nf;
        nf.f = 1;
        nf.k_t = 1;
        nf.mu = 100;                     // stick
        const T s = T(0.6), c = T(0.8);  // normal tilted towards x
        const Vec3<T> n(s, 0, c);
        const Vec3<T> ft = tangential_spring_force(nf, n, Vec3<T>(), T(0), T(1e-6), row);  // no damping
        out(0) = norm(Vec3<T>(data(0, 0), data(0, 1), data(0, 2)));
        out(1) = dot(Vec3<T>(data(0, 0), data(0, 1), data(0, 2)), n);
        out(2) = norm(ft);
        out(3) = dot(ft, n);
      });
  auto o = test::to_host(out);
  CHECK(o(0) == Approx(2).epsilon(1e-14));
  CHECK(std::abs(o(1)) < 1e-14);
  CHECK(o(2) == Approx(2).epsilon(1e-14));
  CHECK(std::abs(o(3)) < 1e-14);
}

// The tangential history is kept in the frame of the smaller global id, so a list that names the
// pair the other way round (a rebuild after the particles were renumbered) continues the same
// spring: the forces are exactly those of the unswapped run (the kernel is sign-symmetric: every
// difference of the swap is an exact negation).
TEMPLATE_LIST_TEST_CASE("tangential history survives a pair listed as (j, i)", "[tangential][orientation]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = HertzMindlin<T, Effects<kFriction | kDamping>, D>;
  Material m = soft(0.5);
  m.restitution = 0.7;
  auto model = Model::create({m});
  const double R = 1e-3, delta = 2e-5, dt = 1e-6;
  // two spheres overlapping along x, sliding and spinning against each other
  auto make = [&](bool swapped) {
    Particles<T, D> p(2);
    auto x = Kokkos::create_mirror_view(p.x);
    Kokkos::deep_copy(x, T(0));
    auto v = Kokkos::create_mirror_view(p.v);
    Kokkos::deep_copy(v, T(0));
    auto w = Kokkos::create_mirror_view(p.omega);
    Kokkos::deep_copy(w, T(0));
    auto gid = Kokkos::create_mirror_view(p.gid);
    // storage slot s holds global id s (unswapped) or 1 - s (swapped): the same two particles
    for (int s = 0; s < 2; ++s) {
      const int g = swapped ? 1 - s : s;
      gid(s) = 10 + g;
      x(s, 0) = T(g == 0 ? 0.0 : 2 * R - delta);
      v(s, 1) = T(g == 0 ? 2e-3 : -1e-3);
      v(s, 2) = T(g == 0 ? -0.5e-3 : 0.0);
      w(s, 2) = T(g == 0 ? 0.3 : -0.1);
    }
    Kokkos::deep_copy(p.x, x);
    Kokkos::deep_copy(p.v, v);
    Kokkos::deep_copy(p.omega, w);
    Kokkos::deep_copy(p.gid, gid);
    Kokkos::deep_copy(p.radius, T(R));
    Kokkos::deep_copy(p.mass, T(4e-6));
    Kokkos::deep_copy(p.material, 0);
    return p;
  };
  Particles<T, D> a = make(false), b = make(true);
  // a lists (gid 10, gid 11) as (0, 1); b stores them the other way round and lists (0, 1) too,
  // i.e. (gid 11, gid 10): the pair named the other way round.
  // Halfway, b's list turns round to (gid 10, gid 11), as after a rebuild: the history row
  // (keyed by the unordered pair) carries on.
  ContactList<D> c(1);
  Kokkos::deep_copy(c.first, 0);
  Kokkos::deep_copy(c.second, 1);
  ContactList<D> c_rev(1);
  Kokkos::deep_copy(c_rev.first, 1);
  Kokkos::deep_copy(c_rev.second, 0);
  ContactHistory<T, D> ha(1, Model::history_size), hb(1, Model::history_size);
  for (int s = 0; s < 50; ++s) {
    zero_forces(a);
    zero_forces(b);
    compute_pair_forces(model, a, c, ha, T(dt));
    compute_pair_forces(model, b, s < 25 ? c : c_rev, hb, T(dt));
    auto Fa = test::to_host(a.force), Fb = test::to_host(b.force);
    auto Ta = test::to_host(a.torque), Tb = test::to_host(b.torque);
    for (int d = 0; d < 3; ++d) {
      // slot 0 of a is gid 10, slot 1 of b is gid 10
      CHECK(Fa(0, d) == Fb(1, d));
      CHECK(Fa(1, d) == Fb(0, d));
      CHECK(Ta(0, d) == Tb(1, d));
      CHECK(Ta(1, d) == Tb(0, d));
    }
  }
  auto hA = test::to_host(ha.data), hB = test::to_host(hb.data);
  CHECK(std::abs(double(hA(0, 1))) + std::abs(double(hA(0, 2))) > 0);         // the spring did stretch
  for (int f = 0; f < Model::history_size; ++f) CHECK(hA(0, f) == hB(0, f));  // same stored history
}
