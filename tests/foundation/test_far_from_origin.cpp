// Mixed precision (state/particles.hpp): positions are double for every T, and the contact
// geometry is taken from them in double, so a scene 1, 10, 100 or 1000 m from the origin gives the
// forces and trajectories it gives at the origin. With float positions the driven pair below
// never touches at 1 m: its 5 nm steps are below float's 0.12 um spacing there.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/hertz_mindlin.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

using namespace epac;

namespace {

constexpr std::array<double, 5> kOffsets = {0.0, 1.0, 10.0, 100.0, 1000.0};

// Spacing of doubles at |x| (the rounding unit of one coordinate there, twice its bound).
double spacing(double x) {
  x = std::fabs(x);
  return std::nextafter(x, std::numeric_limits<double>::infinity()) - x;
}

Material grain() {
  Material m;
  m.name = "grain";
  m.youngs_modulus = 1e9;
  m.poisson_ratio = 0.3;
  m.density = 2500;
  m.restitution = 0.5;
  m.friction = 0.3;
  return m;
}

using Eff = Effects<kFriction | kDamping>;
constexpr double kR = 1e-3;

// The offset applied to every coordinate: X along x, X/2 along y, X/4 along z (every axis far
// from the origin, none exactly like another).
std::array<double, 3> offset_vector(double X) { return {X, 0.5 * X, 0.25 * X}; }

// What one step of a run records: per particle, force, torque and position minus the offset.
struct Frame {
  std::vector<double> f, t, x;
};

template <class T, class D>
Frame record(const Particles<T, D>& p, const std::array<double, 3>& o) {
  auto f = test::to_host(p.force);
  auto t = test::to_host(p.torque);
  auto x = test::to_host(p.x);
  Frame fr;
  for (int i = 0; i < p.n; ++i)
    for (int d = 0; d < 3; ++d) {
      fr.f.push_back(double(f(i, d)));
      fr.t.push_back(double(t(i, d)));
      fr.x.push_back(x(i, d) - o[d]);  // exact: x and o are within a factor 2 of each other (Sterbenz)
    }
  return fr;
}

double norm3(const std::vector<double>& a, int i) {
  return std::sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]);
}
double diff3(const std::vector<double>& a, const std::vector<double>& b, int i) {
  double s = 0;
  for (int d = 0; d < 3; ++d) s += (a[3 * i + d] - b[3 * i + d]) * (a[3 * i + d] - b[3 * i + d]);
  return std::sqrt(s);
}

// Drift in double, as the driver does (driver/integrator.hpp): x += dt v.
template <class T, class D>
void drift(const Particles<T, D>& p, double dt) {
  auto x = p.x;
  auto v = p.v;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, p.n), KOKKOS_LAMBDA(int i) {
        for (int d = 0; d < 3; ++d) x(i, d) += dt * double(v(i, d));
      });
}

// Half kick in T: v += dt/2 F/m, omega += dt/2 torque/I. A function of its own, not a lambda:
// nvcc does not allow an extended (device) lambda inside another lambda.
template <class T, class D>
void half_kick(const Particles<T, D>& p, T dt) {
  auto pv = p.v, pw = p.omega, pf = p.force, pt = p.torque;  // (n x 3) views
  auto pm = p.mass, pI = p.inertia;                          // scalar views
  const T half = T(0.5) * dt;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, p.n), KOKKOS_LAMBDA(int i) {
        for (int d = 0; d < 3; ++d) {
          pv(i, d) += half * pf(i, d) / pm(i);
          pw(i, d) += half * pt(i, d) / pI(i);
        }
      });
}

// Driven pair: R = 1 mm, E = 1 GPa, closing at 5 mm/s each along x with the centres 0.2 R apart
// along y (an oblique contact: friction and torques too), 2 um apart at the start, dt = 1e-6 s,
// 1000 steps (about 8 um of overlap at the end). Velocities are prescribed (never kicked).
template <class T, class D>
std::vector<Frame> driven_pair(double X) {
  const auto o = offset_vector(X);
  const Material g = grain();
  auto model = HertzMindlin<T, Eff, D>::create({g});
  const double m = g.density * 4.0 / 3.0 * M_PI * kR * kR * kR;
  const double gap = 2e-6, dy = 0.2 * kR;
  const double dx = std::sqrt((2 * kR + gap) * (2 * kR + gap) - dy * dy);
  Particles<T, D> p(2, "pair");
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  for (int d = 0; d < 3; ++d) {
    x(0, d) = o[d];
    x(1, d) = o[d];
    v(0, d) = v(1, d) = T(0);
  }
  x(0, 0) += -0.5 * dx;
  x(1, 0) += 0.5 * dx;
  x(0, 1) += -0.5 * dy;
  x(1, 1) += 0.5 * dy;
  v(0, 0) = T(5e-3);
  v(1, 0) = T(-5e-3);
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, T(0));
  Kokkos::deep_copy(p.mass, T(m));
  Kokkos::deep_copy(p.inertia, T(0.4 * m * kR * kR));
  Kokkos::deep_copy(p.radius, T(kR));
  Kokkos::deep_copy(p.radius0, T(kR));
  Kokkos::deep_copy(p.material, 0);
  auto gid = Kokkos::create_mirror_view(p.gid);
  gid(0) = 0;
  gid(1) = 1;
  Kokkos::deep_copy(p.gid, gid);
  ContactList<D> c(1, "pair");
  Kokkos::deep_copy(c.first, 0);
  Kokkos::deep_copy(c.second, 1);
  ContactHistory<T, D> h(1, HertzMindlin<T, Eff, D>::history_size);
  const T dt = T(1e-6);
  std::vector<Frame> frames;
  for (int k = 0; k < 1000; ++k) {
    drift(p, double(dt));
    zero_forces(p);
    compute_pair_forces(model, p, c, h, dt);
    frames.push_back(record(p, o));
  }
  return frames;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a driven pair far from the origin touches and pushes as at the origin", "[mixed]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const auto ref = driven_pair<T, D>(0.0);
  const int steps = static_cast<int>(ref.size());
  // The reference touches: the pair overlaps by about 7.8 um at the end, with a force of 0.39 N.
  const double f_end = norm3(ref.back().f, 0);
  REQUIRE(f_end > 0.3);
  for (double X : kOffsets) {
    if (X == 0.0) continue;
    INFO("offset " << X << " m");
    const auto run = driven_pair<T, D>(X);
    // Bounds. Positions: the start rounds each coordinate by half a spacing u of the coordinates
    // there, each drift by at most another half, and (x - offset) is exact: |dx| <= (k + 1) u per
    // coordinate after k + 1 drifts (u of twice the largest offset, to cover the binade).
    // Forces: the overlap then differs by at most 2 sqrt(3) (k + 1) u; Hertz goes as
    // delta^(3/2), so the force by 1.5 of that relative to the overlap, plus the law's own rounding
    // in T (inputs rounded to T, a few tens of operations, the tangential spring summed over the
    // steps in contact: 2e3 eps of T, 2.4e-4 in float, where a float position at 1 m is 0.12 um
    // off, 1.5% of the final overlap, and the motion does not happen at all).
    const double u = spacing(2.0 * X);
    const double eps = std::numeric_limits<T>::epsilon();
    double worst_x = 0, worst_f = 0;
    for (int k = 0; k < steps; ++k) {
      const double dx_bound = (k + 1) * u;
      for (int i = 0; i < 2; ++i) {
        const double e = diff3(run[k].x, ref[k].x, i) / std::sqrt(3.0);
        worst_x = std::max(worst_x, e / dx_bound);
        CHECK(e <= dx_bound);
      }
      const double f0 = norm3(ref[k].f, 0);
      if (f0 < 1e-3 * f_end) continue;  // before contact and the first nanometres of it
      const double delta = 2 * kR - diff3(ref[k].x, std::vector<double>(ref[k].x.begin() + 3, ref[k].x.end()), 0);
      const double tol = 1.5 * 2.0 * std::sqrt(3.0) * (k + 1) * u / delta + 2e3 * eps;
      for (int i = 0; i < 2; ++i) {
        const double ef = diff3(run[k].f, ref[k].f, i) / f0;
        const double et = diff3(run[k].t, ref[k].t, i) / (f0 * kR);
        worst_f = std::max(worst_f, std::max(ef, et) / tol);
        CHECK(ef <= tol);
        CHECK(et <= tol);
      }
    }
    // measured: at most 0.14 of the bound for positions, 0.14 for forces (double and float)
    INFO("worst position error / bound " << worst_x << ", worst force error / bound " << worst_f);
    CHECK(worst_f <= 1.0);
  }
}

TEMPLATE_LIST_TEST_CASE("a step below the float spacing of the coordinates still moves the particle", "[mixed]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  // 5 nm per step at 1000 m, where a float coordinate's spacing is 61 um: x is double whatever T.
  for (double X : {1.0, 10.0, 1000.0}) {
    Particles<T, D> p(1, "one");
    Kokkos::deep_copy(p.x, X);
    Kokkos::deep_copy(p.v, T(5e-3));
    const double dt = 1e-6;
    for (int k = 0; k < 1000; ++k) drift(p, dt);
    auto x = test::to_host(p.x);
    const double moved = 1000 * dt * double(T(5e-3));  // about 5 um
    // each of the 1000 drifts rounds by at most half a spacing of the coordinate
    for (int d = 0; d < 3; ++d) CHECK(std::fabs((x(0, d) - X) - moved) <= 500 * spacing(2 * X));
  }
}

namespace {

// A small packing: 2 x 2 x 2 free spheres on a cubic lattice 4 um closer than touching, jittered
// by up to 0.5 um, random velocities up to 1 mm/s, velocity-Verlet (kicks in T, drift in double),
// 300 steps of 1e-6 s (about five periods of a contact's oscillation). Every pair is listed.
template <class T, class D>
std::vector<Frame> packing(double X) {
  const auto o = offset_vector(X);
  const Material g = grain();
  auto model = HertzMindlin<T, Eff, D>::create({g});
  const double m = g.density * 4.0 / 3.0 * M_PI * kR * kR * kR;
  const int n = 8;
  const double s = 2 * kR - 4e-6;
  Particles<T, D> p(n, "packing");
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto gid = Kokkos::create_mirror_view(p.gid);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const int a[3] = {i & 1, (i >> 1) & 1, (i >> 2) & 1};
    for (int d = 0; d < 3; ++d) {
      x(i, d) = o[d] + a[d] * s + 0.5e-6 * u(rng);
      v(i, d) = T(1e-3 * u(rng));
    }
    gid(i) = i;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.gid, gid);
  Kokkos::deep_copy(p.omega, T(0));
  Kokkos::deep_copy(p.mass, T(m));
  Kokkos::deep_copy(p.inertia, T(0.4 * m * kR * kR));
  Kokkos::deep_copy(p.radius, T(kR));
  Kokkos::deep_copy(p.radius0, T(kR));
  Kokkos::deep_copy(p.material, 0);
  ContactList<D> c(n * (n - 1) / 2, "pairs");
  {
    auto f = Kokkos::create_mirror_view(c.first);
    auto sc = Kokkos::create_mirror_view(c.second);
    int k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        f(k) = i;
        sc(k) = j;
        ++k;
      }
    Kokkos::deep_copy(c.first, f);
    Kokkos::deep_copy(c.second, sc);
  }
  ContactHistory<T, D> h(c.count, HertzMindlin<T, Eff, D>::history_size);
  const T dt = T(1e-6);
  auto kick = [&]() { half_kick(p, dt); };
  auto forces = [&]() {
    zero_forces(p);
    compute_pair_forces(model, p, c, h, dt);
  };
  std::vector<Frame> frames;
  forces();
  frames.push_back(record(p, o));
  for (int k = 0; k < 300; ++k) {
    kick();
    drift(p, double(dt));
    forces();
    kick();
    frames.push_back(record(p, o));
  }
  return frames;
}

// max over steps and particles of |a - b| / scale, for forces (scale: the largest force of b).
double worst_force_difference(const std::vector<Frame>& a, const std::vector<Frame>& b, double scale) {
  double w = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    for (int i = 0; i < 8; ++i) {
      w = std::max(w, diff3(a[k].f, b[k].f, i) / scale);
      w = std::max(w, diff3(a[k].t, b[k].t, i) / (scale * kR));
    }
  return w;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a packing far from the origin moves and pushes as at the origin", "[mixed]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const auto ref = packing<T, D>(0.0);
  const auto exact = packing<double, D>(0.0);
  double f_max = 0, x_moved = 0;
  for (const auto& fr : ref)
    for (int i = 0; i < 8; ++i) {
      f_max = std::max(f_max, norm3(fr.f, i));
      x_moved = std::max(x_moved, diff3(fr.x, ref.front().x, i));
    }
  REQUIRE(f_max > 0.1);     // the packing is loaded (about 0.6 N per contact)
  REQUIRE(x_moved > 1e-7);  // and moves: 0.3 um at 1 mm/s over 300 steps, and by the contacts
  // Float's own accuracy on this scene: the same run at the origin in T against double.
  const double own = worst_force_difference(ref, exact, f_max);
  INFO("float's own accuracy (T against double at the origin): " << own);
  // (in double not 0 on threaded backends: atomic sums add in a varying order, and their rounding
  // grows through the motion like the coordinates' does; measured 1e-16)
  CHECK(own <= (std::is_same<T, float>::value ? 1e-3 : 1e-12));
  for (double X : kOffsets) {
    if (X == 0.0) continue;
    INFO("offset " << X << " m");
    const auto run = packing<T, D>(X);
    // Bound: T's own accuracy, plus the double coordinates' rounding: each coordinate rounds by
    // at most half a spacing u at the start and at each of the 300 drifts, so an overlap differs
    // by at most 2 sqrt(3) 301 u; Hertz's F ~ delta^1.5 gives 1.5 of that over the largest
    // overlap (4 um) relative to the largest force, per contact, up to 3 contacts a sphere. Both
    // terms times 4 for the free motion's feedback (measured: under 1).
    const double u = spacing(2.0 * X);
    const double rounding = 3 * 1.5 * 2.0 * std::sqrt(3.0) * 301 * u / 4e-6;
    const double bound = 4 * (own + rounding) + 16 * std::numeric_limits<T>::epsilon();
    const double err = worst_force_difference(run, ref, f_max);
    // measured: err 5e-8 (double) and 1.1e-7 (float) at 1000 m; own 3.1e-5 in float
    INFO("worst force difference / largest force " << err << ", bound " << bound);
    CHECK(err <= bound);
    // and the trajectories: positions (minus the offset) to the same relative accuracy of the motion
    double ex = 0;
    for (std::size_t k = 0; k < run.size(); ++k)
      for (int i = 0; i < 8; ++i) ex = std::max(ex, diff3(run[k].x, ref[k].x, i));
    // measured: 1.5e-11 m at 1000 m (bound 6e-8 m); float positions would not have moved at all
    INFO("worst position difference " << ex << " m, largest displacement " << x_moved << " m");
    CHECK(ex <= 4 * (own + rounding) * x_moved + 301 * u);
  }
}

TEST_CASE("bytes per particle: positions in double for either scalar type", "[mixed]") {
  // x (3 doubles) + v, omega, force, torque (12 T) + mass, inertia, radius0, radius (4 T) + int + int64
  STATIC_REQUIRE(Particles<double>::bytes_per_particle() == 24 + 16 * 8 + 4 + 8);
  STATIC_REQUIRE(Particles<float>::bytes_per_particle() == 24 + 16 * 4 + 4 + 8);  // 100 (was 88)
  STATIC_REQUIRE(std::is_same<Particles<float>::position_view::value_type, double>::value);
  STATIC_REQUIRE(std::is_same<Walls<float>::position_view::value_type, double>::value);
  STATIC_REQUIRE(std::is_same<decltype(Particles<float>::box), PeriodicBox<double>>::value);
}
