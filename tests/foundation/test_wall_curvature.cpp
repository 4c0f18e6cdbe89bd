// A wall's curvature (Walls::curvature, LAMMPS's region contact radius R_w: 0 flat, < 0 concave,
// -2 R_cyl inside a cylinder): the wall contact's R* is R R_w / (R + R_w) (LAMMPS's Reff,
// GranularModel::check_contact), R at a flat wall. Hertz's force and every law's rolling arm see
// it; MDR's normal law (damping included) keeps the rigid flat, as LAMMPS's granular mdr does.
// Concave radii closer than 2 R are clamped by the kernel (R* = 2 R) and refused by validate.
// The plugin's fix epac/wall against LAMMPS's fix wall/gran/region: tests/lammps/lammps_checks.py
// wall_curvature.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/params/state_validation.hpp>

#include <cmath>
#include <limits>

using namespace epac;

namespace {

Material grain() {
  Material m;
  m.name = "grain";
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.friction = 0;  // the rolling torque alone
  m.restitution = 0.5;
  m.yield_stress = std::numeric_limits<double>::infinity();  // MDR: elastic
  m.rolling_friction = 0.2;
  m.rolling_stiffness = 20.0;
  m.rolling_damping = 1e-5;
  return m;
}
Material wall() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  return m;
}

struct Pass {
  double fn;
  Vec3<double> torque;
};

// One sphere (R, at the origin, approaching at 0.01 m/s, spinning at omega) on a wall below it
// (normal +z, overlap delta) of curvature R_w; one force pass of dt from a fresh history.
template <class Model>
Pass wall_pass(const Model& model, double R, double delta, double R_w, const Vec3<double>& omega, double dt) {
  using T = typename Model::scalar_type;
  using D = typename Model::device_type;
  Particles<T, D> p(1);
  auto w = Kokkos::create_mirror_view(p.omega);
  w(0, 0) = T(omega.x);
  w(0, 1) = T(omega.y);
  w(0, 2) = T(omega.z);
  Kokkos::deep_copy(p.omega, w);
  auto v = Kokkos::create_mirror_view(p.v);
  Kokkos::deep_copy(v, T(0));
  v(0, 2) = T(-0.01);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.radius, T(R));
  Kokkos::deep_copy(p.radius0, T(R));
  const double mass = 1000 * 4.0 / 3.0 * M_PI * R * R * R;
  Kokkos::deep_copy(p.mass, T(mass));
  Kokkos::deep_copy(p.inertia, T(0.4 * mass * R * R));
  Kokkos::deep_copy(p.material, 0);
  Walls<T, D> wl(1);
  auto wp = Kokkos::create_mirror_view(wl.point);
  Kokkos::deep_copy(wp, 0.0);
  wp(0, 2) = -(R - delta);
  Kokkos::deep_copy(wl.point, wp);
  auto wn = Kokkos::create_mirror_view(wl.normal);
  Kokkos::deep_copy(wn, T(0));
  wn(0, 2) = T(1);
  Kokkos::deep_copy(wl.normal, wn);
  Kokkos::deep_copy(wl.material, 1);
  Kokkos::deep_copy(wl.curvature, T(R_w));
  ContactList<D> c(1);
  Kokkos::deep_copy(c.first, 0);
  Kokkos::deep_copy(c.second, 0);
  ContactHistory<T, D> h(1, Model::history_size);
  ContactOutputs<T, D> out;
  out.normal_force = Kokkos::View<T*, D>("fn", 1);
  zero_forces(p);
  compute_wall_forces(model, p, wl, c, h, T(dt), out);
  const auto fn = test::to_host(out.normal_force);
  const auto M = test::to_host(p.torque);
  return {double(fn(0)), {double(M(0, 0)), double(M(0, 1)), double(M(0, 2))}};
}

double norm(const Vec3<double>& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

}  // namespace

TEST_CASE("wall_effective_radius: LAMMPS's Reff of a wall contact, clamped at R* = 2 R for close concave radii",
          "[walls][curvature]") {
  using detail::wall_effective_radius;
  CHECK(wall_effective_radius(1.0, 0.0) == 1.0);                        // flat
  CHECK(wall_effective_radius(1.0, 3.0) == 1.0 * 3.0 / (1.0 + 3.0));    // convex: 0.75 R
  CHECK(wall_effective_radius(1.0, -8.0) == 1.0 * -8.0 / (1.0 - 8.0));  // inside a cylinder of 4 R: 8/7 R
  CHECK(wall_effective_radius(1.0, -2.0) == 2.0);                       // the domain's edge
  for (const double R_w : {-1.5, -1.0, -0.5, -1e-300})                  // closer: clamped, finite
    CHECK(wall_effective_radius(1.0, R_w) == 2.0);
  CHECK(wall_effective_radius(2.75e-4f, -4e-3f) == Approx(2.75e-4 * 4e-3 / (4e-3 - 2.75e-4)).epsilon(1e-6));
}

TEMPLATE_LIST_TEST_CASE("a curved wall: Hertz and the rolling arm take R*, MDR's normal law the rigid flat",
                        "[walls][curvature]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double tol = std::is_same<T, float>::value ? 2e-5 : 1e-12;
  const double R = 1e-3, delta = 1e-5, dt = 1e-6;
  const Vec3<double> omega{10.0, -5.0, 3.0};          // slow: the rolling spring and dashpot stick (linear in v_rl)
  for (const double R_w : {-8 * R, -2 * R, 3 * R}) {  // a cylinder's inside (R_cyl = 4 R), the edge, convex
    const double ratio = R_w / (R + R_w);             // R* / R
    INFO("R_w / R = " << R_w / R);
    {
      using Model = HertzMindlin<T, Effects<kFriction | kRolling>, D>;
      const auto model = Model::create({grain(), wall()});
      const Pass flat = wall_pass(model, R, delta, 0.0, omega, dt);
      const Pass curved = wall_pass(model, R, delta, R_w, omega, dt);
      REQUIRE(flat.fn > 0);
      REQUIRE(norm(flat.torque) > 0);
      CHECK(curved.fn == Approx(flat.fn * std::sqrt(ratio)).epsilon(tol));  // f ~ sqrt(R*)
      // stick: F_r = -k_r xi - gamma_r v_rl with xi, v_rl ~ R*, torque R* n x F_r: ~ R*^2
      CHECK(curved.torque.x == Approx(flat.torque.x * ratio * ratio).epsilon(tol));
      CHECK(curved.torque.y == Approx(flat.torque.y * ratio * ratio).epsilon(tol));
      CHECK(curved.torque.z == 0.0);  // spin about the normal: no rolling torque
    }
    {
      // MDR (elastic) with the authors' damping, whose k_n = E* R takes radi at a wall in LAMMPS
      using Model = Mdr<T, Effects<kDamping | kFriction | kRolling>, D>;
      MdrOptions authors;
      authors.damping = MdrDamping::authors;
      const auto model = Model::create({grain(), wall()}, authors);
      const Pass flat = wall_pass(model, R, delta, 0.0, omega, dt);
      const Pass curved = wall_pass(model, R, delta, R_w, omega, dt);
      REQUIRE(flat.fn > 0);
      CHECK(curved.fn == flat.fn);  // the same bits: the law never sees the curvature
      CHECK(curved.torque.x == Approx(flat.torque.x * ratio * ratio).epsilon(tol));
      CHECK(curved.torque.y == Approx(flat.torque.y * ratio * ratio).epsilon(tol));
    }
  }
}

TEMPLATE_LIST_TEST_CASE("validate: a concave wall needs -curvature >= 2 R_max, and a finite curvature",
                        "[walls][curvature][validation]", test::Backends) {
  using D = TestType;
  using Model = HertzMindlin<double, Effects<kFriction>, D>;
  const auto model = Model::create({grain(), wall()});
  Particles<double, D> p(2);
  auto r = Kokkos::create_mirror_view(p.radius);
  r(0) = 1e-3;
  r(1) = 2e-3;  // R_max
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.mass, 1e-6);
  Kokkos::deep_copy(p.inertia, 1e-12);
  auto g = Kokkos::create_mirror_view(p.gid);
  g(0) = 0;
  g(1) = 1;
  Kokkos::deep_copy(p.gid, g);
  Walls<double, D> w(1);
  auto n = Kokkos::create_mirror_view(w.normal);
  Kokkos::deep_copy(n, 0.0);
  n(0, 2) = 1.0;
  Kokkos::deep_copy(w.normal, n);
  Kokkos::deep_copy(w.material, 1);
  for (const double R_w : {0.0, 1e-6, 1.0, -4e-3, -1.0}) {
    Kokkos::deep_copy(w.curvature, R_w);
    CHECK_NOTHROW(validate(p, w, model));
  }
  for (const double R_w :
       {-3.9e-3, -2e-3, -1e-9, std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    Kokkos::deep_copy(w.curvature, R_w);
    CHECK_THROWS_AS(validate(p, w, model), ParameterError);
  }
}
