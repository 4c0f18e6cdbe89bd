// Rolling resistance (models/rolling_resistance.hpp, LAMMPS `rolling sds`): the closed-form stick
// torque R* n x (-k_r xi - gamma_r v_rl) with xi = sum dt v_rl, the slip at mu_r |f|, Newton's third
// law for torques, independence of the list's orientation, no torque from spin about the normal,
// no force on the centres, passivity of a spinning sphere on a plane, and the edges of its
// divisions (k_r = 0, f = 0, a first pass with dt = 0).
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include <cmath>

using namespace epac;

namespace {
Material grain(double mu_r, double k_r, double gamma_r) {
  Material m;
  m.name = "grain";
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.friction = 0.5;
  m.rolling_friction = mu_r;
  m.rolling_stiffness = k_r;
  m.rolling_damping = gamma_r;
  return m;
}
Material wall() {
  Material m;
  m.name = "wall";
  m.rigid = true;
  return m;
}

// Two spheres of radii R0, R1 along x with overlap delta; sphere `spinner` turns at omega.
template <class T, class D>
Particles<T, D> pair_of(double R0, double R1, double delta, int spinner, const Vec3<double>& omega) {
  Particles<T, D> p(2);
  auto x = Kokkos::create_mirror_view(p.x);
  Kokkos::deep_copy(x, 0.0);
  x(1, 0) = R0 + R1 - delta;
  Kokkos::deep_copy(p.x, x);
  auto w = Kokkos::create_mirror_view(p.omega);
  Kokkos::deep_copy(w, T(0));
  w(spinner, 0) = T(omega.x);
  w(spinner, 1) = T(omega.y);
  w(spinner, 2) = T(omega.z);
  Kokkos::deep_copy(p.omega, w);
  auto r = Kokkos::create_mirror_view(p.radius);
  r(0) = T(R0);
  r(1) = T(R1);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.mass, T(1e-6));
  Kokkos::deep_copy(p.material, 0);
  auto g = Kokkos::create_mirror_view(p.gid);
  g(0) = 0;
  g(1) = 1;
  Kokkos::deep_copy(p.gid, g);
  return p;
}

template <class D>
ContactList<D> one_pair(int a, int b) {
  ContactList<D> c(1);
  Kokkos::deep_copy(c.first, a);
  Kokkos::deep_copy(c.second, b);
  return c;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("rolling resistance: stick torque in closed form, slip at mu_r f, third law", "[rolling]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Rolling = HertzMindlin<T, Effects<kFriction | kRolling>, D>;
  using Plain = HertzMindlin<T, Effects<kFriction>, D>;
  static_assert(Rolling::history_size == Plain::history_size + 3, "rolling keeps 3 fields after the tangential 3");
  const double R0 = 1e-3, R1 = 2e-3, delta = 1e-5, w = 2.0, dt = 1e-5;
  const double k_r = 50.0, gamma_r = 1e-4, mu_r = 0.1;
  const auto rolling = Rolling::create({grain(mu_r, k_r, gamma_r)});
  const auto plain = Plain::create({grain(mu_r, k_r, gamma_r)});
  const double Rs = R0 * R1 / (R0 + R1);
  const double E_star = 1e7 / (2 * (1 - 0.09));
  const double f = 4.0 / 3.0 * E_star * std::sqrt(Rs) * std::pow(delta, 1.5);
  // Sphere 0 turns about +y; n points from 1 to 0 (-x): v_rl = R* (w_y e_y) x (-e_x) = R* w e_z.
  const double v_rl = Rs * w;
  const double tol = std::is_same<T, float>::value ? 2e-3 : 1e-9;
  for (int orientation = 0; orientation < 2; ++orientation) {
    DYNAMIC_SECTION("the list names the pair as " << (orientation == 0 ? "(0, 1)" : "(1, 0)")) {
      auto p = pair_of<T, D>(R0, R1, delta, 0, {0.0, w, 0.0});
      auto q = pair_of<T, D>(R0, R1, delta, 0, {0.0, w, 0.0});
      const auto c = orientation == 0 ? one_pair<D>(0, 1) : one_pair<D>(1, 0);
      ContactHistory<T, D> h(1, Rolling::history_size), hq(1, Plain::history_size);
      const int n_stick = static_cast<int>((mu_r * f - gamma_r * v_rl) / (k_r * v_rl * dt));
      REQUIRE(n_stick > 3);
      for (int s = 1; s <= 3 * n_stick; ++s) {
        zero_forces(p);
        zero_forces(q);
        compute_pair_forces(rolling, p, c, h, T(dt));
        compute_pair_forces(plain, q, c, hq, T(dt));
        const auto F = test::to_host(p.force), Fq = test::to_host(q.force);
        const auto M = test::to_host(p.torque), Mq = test::to_host(q.torque);
        for (int i = 0; i < 2; ++i)
          for (int d = 0; d < 3; ++d)  // a torque only: the forces are untouched
            CHECK(double(F(i, d)) == Approx(double(Fq(i, d))).epsilon(tol).margin(1e-12 * f));
        // the rolling part of the torques: R* n x F_r on 0, the opposite on 1 (F_r along -e_z)
        const double m0 = double(M(0, 1)) - double(Mq(0, 1));
        const double m1 = double(M(1, 1)) - double(Mq(1, 1));
        CHECK(m1 == Approx(-m0).epsilon(tol));
        CHECK(double(M(0, 0)) - double(Mq(0, 0)) == Approx(0).margin(1e-12 * Rs * mu_r * f));
        CHECK(double(M(0, 2)) - double(Mq(0, 2)) == Approx(0).margin(1e-12 * Rs * mu_r * f));
        // n x (-e_z) with n = -e_x: (-e_x) x (-e_z) = -e_y: the torque opposes the spin
        const double fr = s <= n_stick ? k_r * v_rl * dt * s + gamma_r * v_rl : mu_r * f;
        if (s <= n_stick || s >= n_stick + 2) CHECK(m0 == Approx(-Rs * fr).epsilon(tol));
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("rolling resistance: spin about the normal and a common rotation give no rolling torque",
                        "[rolling]", test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Rolling = HertzMindlin<T, Effects<kRolling | kFriction>, D>;
  const auto model = Rolling::create({grain(0.1, 50.0, 1e-4)});
  const auto c = one_pair<D>(0, 1);
  {
    auto p = pair_of<T, D>(1e-3, 1e-3, 1e-5, 0, {3.0, 0.0, 0.0});  // about n
    ContactHistory<T, D> h(1, Rolling::history_size);
    for (int s = 0; s < 5; ++s) {
      zero_forces(p);
      compute_pair_forces(model, p, c, h, T(1e-6));
    }
    const auto hh = test::to_host(h.data);
    for (int k = Rolling::history_size - 3; k < Rolling::history_size; ++k) CHECK(hh(0, k) == T(0));
  }
  {
    // both spheres turn together about y: omega_i - omega_j = 0
    auto p = pair_of<T, D>(1e-3, 1e-3, 1e-5, 0, {0.0, 2.0, 0.0});
    auto w = Kokkos::create_mirror_view(p.omega);
    Kokkos::deep_copy(w, p.omega);
    w(1, 1) = w(0, 1);
    Kokkos::deep_copy(p.omega, w);
    ContactHistory<T, D> h(1, Rolling::history_size);
    zero_forces(p);
    compute_pair_forces(model, p, c, h, T(1e-6));
    const auto hh = test::to_host(h.data);
    for (int k = Rolling::history_size - 3; k < Rolling::history_size; ++k) CHECK(hh(0, k) == T(0));
  }
}

// A sphere pressed on a plane (fixed centre) spins about an axis in the plane, with rolling
// resistance the only torque (friction 0). The spring loads to the slider, the slider stops the
// spin, and the sphere is left ringing on the spring with the energy it held at the slider,
// 0.5 (mu_r f)^2 / k_r (2% of the start here). The energy of the spin plus the spring's
// 0.5 k_r |xi|^2 never rises above the start (by more than the explicit steps' ripple) and ends
// at that; a torque of the wrong sign would feed the spin instead. (gamma_r is small: the slider
// stores -gamma_r v_rl / k_r in xi, LAMMPS's rule, which is not spring energy.)
TEMPLATE_LIST_TEST_CASE("rolling resistance is passive: a spinning sphere on a plane loses energy", "[rolling]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Rolling = HertzMindlin<T, Effects<kRolling | kFriction>, D>;
  const double R = 1e-3, delta = 1e-5, k_r = 20.0, gamma_r = 1e-5, mu_r = 0.2;
  Material g = grain(mu_r, k_r, gamma_r);
  g.friction = 0;  // the rolling torque alone
  const auto model = Rolling::create({g, wall()});
  Particles<T, D> p(1);
  auto x = Kokkos::create_mirror_view(p.x);
  Kokkos::deep_copy(x, 0.0);
  x(0, 2) = R - delta;
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.radius, T(R));
  const double mass = 1000 * 4.0 / 3.0 * M_PI * R * R * R, inertia = 0.4 * mass * R * R;
  Kokkos::deep_copy(p.mass, T(mass));
  Kokkos::deep_copy(p.material, 0);
  Walls<T, D> wl(1);
  auto wn = Kokkos::create_mirror_view(wl.normal);
  Kokkos::deep_copy(wn, T(0));
  wn(0, 2) = T(1);
  Kokkos::deep_copy(wl.normal, wn);
  Kokkos::deep_copy(wl.material, 1);
  const auto c = one_pair<D>(0, 0);
  ContactHistory<T, D> h(1, Rolling::history_size);
  double omega[3] = {3000.0, 1500.0, 0.0};
  const double E0 = 0.5 * inertia * (omega[0] * omega[0] + omega[1] * omega[1]);
  // the rolling spring's period is 2 pi sqrt(I / (k_r R^2))
  const double dt = 0.005 * std::sqrt(inertia / (k_r * R * R));
  const double f = 4.0 / 3.0 * 1e7 / (1 - 0.09) * std::sqrt(R) * std::pow(delta, 1.5);
  double E = E0, E_max = 0;
  bool slipped = false;
  for (int s = 0; s < 3000; ++s) {
    auto w = Kokkos::create_mirror_view(p.omega);
    for (int d = 0; d < 3; ++d) w(0, d) = T(omega[d]);
    Kokkos::deep_copy(p.omega, w);
    zero_forces(p);
    compute_wall_forces(model, p, wl, c, h, T(dt));
    const auto M = test::to_host(p.torque);
    for (int d = 0; d < 3; ++d) omega[d] += dt * double(M(0, d)) / inertia;
    const auto hh = test::to_host(h.data);
    const int r0 = Rolling::history_size - 3;
    double xi2 = 0;
    for (int d = 0; d < 3; ++d) xi2 += double(hh(0, r0 + d)) * double(hh(0, r0 + d));
    E = 0.5 * inertia * (omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]) + 0.5 * k_r * xi2;
    REQUIRE(std::isfinite(E));
    E_max = std::max(E_max, E);
    const double Mr = std::sqrt(double(M(0, 0)) * double(M(0, 0)) + double(M(0, 1)) * double(M(0, 1)));
    CHECK(Mr <= R * mu_r * f * 1.001);  // never beyond the slider
    slipped = slipped || Mr >= 0.999 * R * mu_r * f;
  }
  CHECK(E_max <= 1.02 * E0);
  CHECK(slipped);  // the run reached the slider, not only the spring
  const double E_slider = 0.5 * (mu_r * f) * (mu_r * f) / k_r;
  REQUIRE(E_slider < 0.05 * E0);
  CHECK(E <= 1.1 * E_slider);  // the spin was stopped by the slider
}

TEMPLATE_LIST_TEST_CASE("rolling resistance at the edges of its divisions: k_r = 0, f = 0, dt = 0", "[rolling]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Rolling = HertzMindlin<T, Effects<kRolling | kFriction>, D>;
  const auto c = one_pair<D>(0, 1);
  struct Case {
    double k_r, gamma_r, delta, dt;
  };
  // k_r = 0 while slipping; an overlap so small that mu_r f underflows against the damping; the
  // first pass with dt = 0 (the history is all zero, the dashpot alone exceeds the limit)
  for (const Case cs : {Case{0.0, 1.0, 1e-5, 1e-6}, Case{50.0, 1.0, 1e-30, 1e-6}, Case{50.0, 1.0, 1e-5, 0.0}}) {
    const auto model = Rolling::create({grain(0.1, cs.k_r, cs.gamma_r)});
    auto p = pair_of<T, D>(1e-3, 1e-3, cs.delta, 0, {0.0, 1e3, 0.0});
    ContactHistory<T, D> h(1, Rolling::history_size);
    for (int s = 0; s < 3; ++s) {
      zero_forces(p);
      compute_pair_forces(model, p, c, h, T(cs.dt));
      const auto M = test::to_host(p.torque);
      const auto hh = test::to_host(h.data);
      for (int d = 0; d < 3; ++d) {
        REQUIRE(std::isfinite(double(M(0, d))));
        REQUIRE(std::isfinite(double(hh(0, Rolling::history_size - 3 + d))));
      }
      // the overlap the kernel sees: the radii in T minus x_1 in double (round-off at delta = 1e-30)
      const double d = std::max(0.0, 2 * double(T(1e-3)) - (1e-3 + 1e-3 - cs.delta));
      const double f = 4.0 / 3.0 * 1e7 / (2 * (1 - 0.09)) * std::sqrt(0.5e-3) * std::pow(d, 1.5);
      const double Mr = std::abs(double(M(0, 1)));
      INFO("k_r " << cs.k_r << ", delta " << cs.delta << ", dt " << cs.dt << ", step " << s << ": |M_y| " << Mr
                  << ", f " << f);
      CHECK(Mr <= (0.5e-3 * 0.1 * f + 1e-3 * 0.5 * f) * 1.001 + 1e-300);  // R* mu_r f + R mu f
    }
  }
}

TEST_CASE("rolling keys are validated on the host with their name, value and range", "[rolling]") {
  for (const char* key : {"rolling_stiffness", "rolling_damping", "rolling_friction"}) {
    Material m = grain(0.1, 1, 1);
    const std::string k = key;
    (k == "rolling_stiffness" ? m.rolling_stiffness
     : k == "rolling_damping" ? m.rolling_damping
                              : m.rolling_friction) = -1;
    try {
      m.validate();
      FAIL("accepted " << k << " = -1");
    } catch (const ParameterError& e) {
      const std::string msg = e.what();
      CHECK(msg.find(k) != std::string::npos);
      CHECK(msg.find("-1") != std::string::npos);
    }
  }
  // the geometric mean: one material without rolling turns the pair's off
  Material a = grain(0.2, 10, 1), b = grain(0, 40, 1);
  CHECK(pair_properties(a, b).rolling_friction == 0);
  CHECK(pair_properties(a, a).rolling_stiffness == Approx(10));
  CHECK(pair_properties(a, grain(0.2, 40, 1)).rolling_stiffness == Approx(20));
  CHECK(pair_properties(a, wall()).rolling_friction == Approx(0.2));  // a rigid wall takes the particle's
}
