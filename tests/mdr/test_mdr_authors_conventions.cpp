// MdrDamping::authors and MdrFriction::authors (mdr_parameters.hpp): the damping and tangential
// conventions of the authors' code (LAMMPS gran_sub_mod_normal.cpp, gran_sub_mod_tangential.cpp
// linear_history, granular_model.cpp), each checked in closed form against one pass of the
// generic pair and wall kernels, next to epac's defaults.
#include "contact_stepper.hpp"
#include "mdr_test_helpers.hpp"

#include <epac/state/walls.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace epac;
using namespace epac::test;

namespace {

// Two spheres on the x axis (i = 0 at the origin, j = 1 at +x; n points from j to i, -x) with
// overlap delta, or one sphere against a wall at x = R - delta with normal -x (R1 <= 0).
// Velocities v0, v1 along x and spins w0 about z; one force pass of dt. Returns the force and the
// torque on particle 0 and the normal force the kernel reports (law + damping).
template <class Model>
struct OnePass {
  using T = typename Model::scalar_type;
  Vec3<double> force, torque;
  double fn = 0;
};

template <class Model>
OnePass<Model> one_pass(const Model& model, double R0, double R1, double delta, double v0x, double v0y, double w0z,
                        double dt, std::vector<double>* history = nullptr) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  const bool pair = R1 > 0;
  Particles<T, D> p(pair ? 2 : 1);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto w = Kokkos::create_mirror_view(p.omega);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto g = Kokkos::create_mirror_view(p.gid);
  auto mat = Kokkos::create_mirror_view(p.material);
  for (int k = 0; k < p.n; ++k)
    for (int d = 0; d < 3; ++d) {
      x(k, d) = T(0);
      v(k, d) = T(0);
      w(k, d) = T(0);
    }
  v(0, 0) = T(v0x);
  v(0, 1) = T(v0y);
  w(0, 2) = T(w0z);
  r(0) = T(R0);
  m(0) = T(2);
  g(0) = 0;
  mat(0) = 0;
  if (pair) {
    x(1, 0) = T(R0 + R1 - delta);
    r(1) = T(R1);
    m(1) = T(3);
    g(1) = 1;
    mat(1) = 0;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, w);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.gid, g);
  Kokkos::deep_copy(p.material, mat);
  ContactList<D> c(1);
  auto f = Kokkos::create_mirror_view(c.first);
  auto s = Kokkos::create_mirror_view(c.second);
  f(0) = 0;
  s(0) = pair ? 1 : 0;
  Kokkos::deep_copy(c.first, f);
  Kokkos::deep_copy(c.second, s);
  ContactHistory<T, D> h(1, Model::history_size);
  if (history) {
    auto hh = Kokkos::create_mirror_view(h.data);
    for (int q = 0; q < Model::history_size; ++q) hh(0, q) = T((*history)[q]);
    Kokkos::deep_copy(h.data, hh);
  }
  ContactOutputs<T, D> out;
  out.normal_force = Kokkos::View<T*, D>("fn", 1);
  zero_forces(p);
  if (pair) {
    compute_pair_forces(model, p, c, h, T(dt), out);
  } else {
    Walls<T, D> wl(1);
    auto wp = Kokkos::create_mirror_view(wl.point);
    auto wn = Kokkos::create_mirror_view(wl.normal);
    auto wv = Kokkos::create_mirror_view(wl.velocity);
    auto wm = Kokkos::create_mirror_view(wl.material);
    for (int d = 0; d < 3; ++d) {
      wp(0, d) = T(0);
      wn(0, d) = T(0);
      wv(0, d) = T(0);
    }
    wp(0, 0) = T(R0 - delta);
    wn(0, 0) = T(-1);
    wm(0) = 1;
    Kokkos::deep_copy(wl.point, wp);
    Kokkos::deep_copy(wl.normal, wn);
    Kokkos::deep_copy(wl.velocity, wv);
    Kokkos::deep_copy(wl.material, wm);
    compute_wall_forces(model, p, wl, c, h, T(dt), out);
  }
  OnePass<Model> o;
  auto F = to_host(p.force);
  auto Tq = to_host(p.torque);
  o.force = Vec3<double>(F(0, 0), F(0, 1), F(0, 2));
  o.torque = Vec3<double>(Tq(0, 0), Tq(0, 1), Tq(0, 2));
  o.fn = to_host(out.normal_force)(0);
  if (history) {
    auto hh = to_host(h.data);
    for (int q = 0; q < Model::history_size; ++q) (*history)[q] = hh(0, q);
  }
  return o;
}

double authors_beta(double e) {
  const double pi = 3.14159265358979323846, l = std::log(e);
  return -l / std::sqrt(l * l + pi * pi);
}

}  // namespace

TEMPLATE_TEST_CASE(
    "MdrDamping::authors: F_d = beta sqrt(m* E* R*) d(delta)/dt while the MDR force is positive, "
    "and it may pull",
    "[mdr][conventions]", double, float) {
  using T = TestType;
  const double tol = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  const double E = 1e9, nu = 0.3, e = 0.5, R0 = 1e-3, R1 = 2e-3, delta = 2e-6;  // elastic (Y inf)
  const Material m = mdr_material(E, nu, std::numeric_limits<double>::infinity(), 0.0, e);
  MdrOptions authors;
  authors.damping = MdrDamping::authors;
  using Damped = Mdr<T, Effects<kDamping>>;
  using Plain = Mdr<T, Effects<0>>;
  const Plain plain = Plain::create({m});
  const Damped ours = Damped::create({m});
  const Damped theirs = Damped::create({m}, authors);
  const double E_star = E / (2 * (1 - nu * nu)), R_star = R0 * R1 / (R0 + R1), m_star = 2.0 * 3.0 / 5.0;
  const double c = authors_beta(e) * std::sqrt(m_star * E_star * R_star);
  for (const double vx : {0.05, -0.05}) {  // particle 0 moves towards +x (approach) or away
    const double F_law = one_pass(plain, R0, R1, delta, vx, 0, 0, 0).fn;
    REQUIRE(F_law > 0);
    const double F_auth = one_pass(theirs, R0, R1, delta, vx, 0, 0, 0).fn;
    CHECK(F_auth == Approx(F_law + c * vx).epsilon(tol));  // d(delta)/dt = v0x here
    const double F_ours = one_pass(ours, R0, R1, delta, vx, 0, 0, 0).fn;
    CHECK(std::fabs(F_ours - F_law) > 0.0);                        // epac's default damps too,
    CHECK(std::fabs(F_ours - F_auth) > 1e-3 * std::fabs(c * vx));  // by another convention
  }
  // separating fast: the authors' damped force pulls, epac's default stops at 0
  const double fast = -100.0;
  CHECK(one_pass(theirs, R0, R1, delta, fast, 0, 0, 0).fn < 0.0);
  CHECK(one_pass(ours, R0, R1, delta, fast, 0, 0, 0).fn == 0.0);
  // restitution 0: beta's limit 1 (ln 0 is guarded); restitution 1 compiles no damping at all
  Material m0 = m;
  m0.restitution = 0.0;
  const double F0 = one_pass(Damped::create({m0}, authors), R0, R1, delta, 0.05, 0, 0, 0).fn;
  const double F_law = one_pass(plain, R0, R1, delta, 0.05, 0, 0, 0).fn;
  CHECK(std::isfinite(F0));
  CHECK(F0 == Approx(F_law + std::sqrt(m_star * E_star * R_star) * 0.05).epsilon(tol));
  // a wall: k_n = E_eff R with the particle's E_eff, m* = m
  const Material wall = rigid_wall_material();
  const double Fw_law = one_pass(Plain::create({m, wall}), R0, 0, delta, 0.05, 0, 0, 0).fn;
  const double Fw = one_pass(Damped::create({m, wall}, authors), R0, 0, delta, 0.05, 0, 0, 0).fn;
  CHECK(Fw == Approx(Fw_law + authors_beta(e) * std::sqrt(2.0 * E / (1 - nu * nu) * R0) * 0.05).epsilon(tol));
}

TEMPLATE_TEST_CASE(
    "MdrFriction::authors: constant k_t, full-radius rolling velocity, wall torque arm R, Coulomb "
    "bound on the damped force",
    "[mdr][conventions]", double, float) {
  using T = TestType;
  const double tol = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  const double E = 1e9, nu = 0.3, R0 = 1e-3, R1 = 2e-3, delta = 2e-5, kt = 5e5, dt = 1e-7;
  Material m = mdr_material(E, nu, std::numeric_limits<double>::infinity());
  m.friction = 0.5;
  MdrOptions authors;
  authors.friction = MdrFriction::authors;
  authors.tangential_stiffness = kt;
  using Fric = Mdr<T, Effects<kFriction>>;
  const Fric theirs = Fric::create({m}, authors);
  const Fric ours = Fric::create({m});
  // sticking, from a fresh history: F_t = -k_t v_t dt. Particle 0's contact point lies at +x
  // (towards 1), so its velocity is v + w x (arm e_x) = (v_y + arm w_z) e_y; the authors' arm is R0.
  const double vy = 0.01, wz = 3.0;
  const OnePass<Fric> a = one_pass(theirs, R0, R1, delta, 0, vy, wz, dt);
  const double vt_full = vy + R0 * wz;
  CHECK(a.force.y == Approx(-kt * vt_full * dt).epsilon(tol));
  // torque on 0: arm R0 - delta/2 towards +x, r x F = (R0 - delta/2) e_x x F_y e_y
  CHECK(a.torque.z == Approx((R0 - 0.5 * delta) * a.force.y).epsilon(tol));
  // epac's default: Mindlin k_t = 8 G* a and the arm R0 - delta/2 in the velocity too
  const OnePass<Fric> b = one_pass(ours, R0, R1, delta, 0, vy, wz, dt);
  const double vt_ours = vy + (R0 - 0.5 * delta) * wz;
  CHECK(b.force.y < 0);
  CHECK(std::fabs(b.force.y / vt_ours - a.force.y / vt_full) > 1e-3 * std::fabs(a.force.y / vt_full));
  // the stiffness does not depend on the overlap (linear history)
  const OnePass<Fric> a2 = one_pass(theirs, R0, R1, 4 * delta, 0, vy, wz, dt);
  CHECK(a2.force.y == Approx(a.force.y).epsilon(tol));
  // a wall: the rolling velocity and the torque arm use R0 (LAMMPS: radi), not R0 - delta
  const Material wall = rigid_wall_material();
  const OnePass<Fric> w = one_pass(Fric::create({m, wall}, authors), R0, 0, delta, 0, vy, wz, dt);
  CHECK(w.force.y == Approx(-kt * vt_full * dt).epsilon(tol));
  CHECK(w.torque.z == Approx(R0 * w.force.y).epsilon(tol));
  // sliding with damping: |F_t| = mu |f + F_d| (the damped normal force), not mu |f|
  Material md = m;
  md.restitution = 0.5;
  MdrOptions both = authors;
  both.damping = MdrDamping::authors;
  using FricDamp = Mdr<T, Effects<kFriction | kDamping>>;
  const FricDamp fd = FricDamp::create({md}, both);
  std::vector<double> hist(FricDamp::history_size, 0.0);
  hist[FricDamp::normal_history_size + 1] = 1.0;  // a stretched spring (1 m along +y): sliding
  const OnePass<FricDamp> s = one_pass(fd, R0, R1, delta, 0.05, 0, 0, dt, &hist);
  REQUIRE(s.fn > 0);
  CHECK(std::fabs(s.force.y) == Approx(0.5 * s.fn).epsilon(tol));
  const double F_law = one_pass(Mdr<T, Effects<0>>::create({md}), R0, R1, delta, 0.05, 0, 0, 0).fn;
  CHECK(std::fabs(s.fn - F_law) > 1e-3 * F_law);  // the bound really saw the damping
  // the history was shortened to the spring that carries that force, along the old direction
  CHECK(hist[FricDamp::normal_history_size + 1] == Approx(0.5 * s.fn / kt).epsilon(tol));
}

TEST_CASE("MdrOptions: friction authors needs a finite positive tangential_stiffness", "[mdr][conventions]") {
  const Material m = mdr_material(1e9, 0.3, 5e6);
  MdrOptions o;
  o.friction = MdrFriction::authors;
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    o.tangential_stiffness = bad;
    CHECK_THROWS_AS(o.validate(), ParameterError);
    CHECK_THROWS_AS((Mdr<double, Effects<kFriction>>::create({m}, o)), ParameterError);
  }
  o.tangential_stiffness = 1e5;
  CHECK_NOTHROW(o.validate());
  o.friction = MdrFriction::mindlin;  // unused otherwise
  o.tangential_stiffness = 0.0;
  CHECK_NOTHROW(o.validate());
}

TEST_CASE("Material::own_surface_properties: a rigid wall with its own friction, restitution and surface energy",
          "[mdr][conventions]") {
  Material p = mdr_material(5e6, 0.4, 1.9e5, 2.0, 0.5);
  p.friction = 0.7;
  Material w = rigid_wall_material();
  w.friction = 0.1;
  w.surface_energy = 0.0;
  w.restitution = 0.9;
  for (const bool own : {false, true}) {
    w.own_surface_properties = own;
    for (const PairProperties& pp : {pair_properties(p, w), pair_properties(w, p)}) {
      CHECK(pp.friction == (own ? 0.1 : 0.7));
      CHECK(pp.surface_energy == (own ? 0.0 : 2.0));
      CHECK(pp.restitution == (own ? 0.9 : 0.5));
      CHECK(pp.E_star == Approx(5e6 / (1 - 0.16)).epsilon(1e-15));  // the wall stays rigid
    }
  }
}

TEMPLATE_TEST_CASE("MdrSurfaceEnergyShare, MdrAdhesiveRadius, MdrRelease: the authors' adhesion conventions",
                   "[mdr][conventions]", double, float) {
  using T = TestType;
  using M = Mdr<T, Effects<kAdhesion>>;
  const double E = 1e9, nu = 0.3, gamma = 0.5, R = 1e-3;
  const Material m = mdr_material(E, nu, std::numeric_limits<double>::infinity(), gamma);
  MdrOptions full;
  full.surface_energy_share = MdrSurfaceEnergyShare::each_side_full;
  const double Eeff = E / (1 - nu * nu);
  // a pair of equal spheres: each side gets Delta gamma E*/E_eff = Delta gamma / 2 in series, the
  // full Delta gamma with each_side_full; a wall side gets Delta gamma either way
  const Material w = rigid_wall_material();
  for (const bool all : {false, true}) {
    const M model = all ? M::create({m, w}, full) : M::create({m, w});
    auto pc = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), model.pairs);
    CHECK(double(pc(0).gamma_a) == Approx(all ? gamma : gamma / 2).epsilon(1e-6));
    CHECK(double(pc(1).gamma_a) == Approx(gamma).epsilon(1e-6));  // particle (row 0) against the wall
  }
  // The pull-off of two equal elastic spheres: JKR's 3/2 pi Delta gamma R* in series, twice that
  // with the full surface energy on each side (each side is then JKR of one sphere on a flat
  // with Delta gamma, mean of the two: 3/2 pi Delta gamma R), measured by slow retraction.
  auto pull_off = [&](const M& model) {
    ContactStepper<M> s(model, R, R, 0, 0);
    double fmin = 0;
    for (int k = 0; k <= 200; ++k) s.step(2e-6 * k / 200);
    for (int k = 0; k <= 4000; ++k) fmin = std::min(fmin, s.step(2e-6 - 4e-6 * k / 4000));
    return -fmin;
  };
  const double pi = 3.14159265358979323846;
  const double series = pull_off(M::create({m}));
  const double each = pull_off(M::create({m}, full));
  CHECK(series == Approx(1.5 * pi * gamma * R / 2).epsilon(0.01));  // JKR between the spheres
  CHECK(each == Approx(1.5 * pi * gamma * R).epsilon(0.01));        // twice (the authors' code)

  // MdrAdhesiveRadius::authors: loading stores 0.99 a_na (the authors' a_fac); the paper: a_na.
  // Elastic wall contact, A = 4R, B = 2R: a_na = (B/A) sqrt(d (A - d)).
  MdrOptions fac;
  fac.adhesive_radius = MdrAdhesiveRadius::authors;
  const double d = 4e-5, a_na = 0.5 * std::sqrt(d * (4 * R - d));  // d/A = 1e-2: float resolves 1e-5 of F
  const double tol = std::is_same<T, float>::value ? 1e-5 : 1e-12;
  for (const bool authors : {false, true}) {
    ContactStepper<M> s(authors ? M::create({m, w}, fac) : M::create({m, w}), R, -1.0, 0, 1);
    for (int k = 1; k <= 10; ++k) s.step(d * k / 10);
    CHECK(s.history()[M::side_base(0)] == Approx((authors ? 0.99 : 1.0) * a_na).epsilon(tol));
    // unloading by 1.5% (a_na falls by 0.75%): with the paper's radius the edge springs are in
    // tension at once, F = F_el(d) - 2 E (0.015 d) a, below the non-adhesive law by a second-order
    // 8e-5 of it; the authors' 0.99 a_na keeps the contact free of tension until a_na has dropped
    // by 1%, so the force is the non-adhesive ellipse force exactly
    const double f = s.step(0.985 * d);
    const double f_na = mdr_ellipse_force(Eeff, 4 * R, 2 * R, 0.985 * d);
    if (authors)
      CHECK(f == Approx(f_na).epsilon(std::is_same<T, float>::value ? 1e-5 : 1e-10));
    else
      CHECK(f < f_na * (1 - 2e-5));
  }

  // MdrRelease::zero_overlap: an adhesive pair pulled just apart (delta < 0, above the critical
  // overlap) keeps its tension by default, and is released (no force, history cleared) by the
  // authors' rule.
  MdrOptions zero;
  zero.release = MdrRelease::zero_overlap;
  for (const bool authors : {false, true}) {
    ContactStepper<M> s(authors ? M::create({m}, zero) : M::create({m}), R, R, 0, 0);
    for (int k = 1; k <= 20; ++k) s.step(2e-6 * k / 20);
    for (int k = 19; k >= 0; --k) s.step(2e-6 * k / 20);
    const double f = s.step(-1e-9);
    if (authors) {
      CHECK(f == 0.0);
      for (const double h : s.history()) CHECK(h == 0.0);
    } else {
      CHECK(f < 0.0);  // still held by the neck
    }
  }
}
