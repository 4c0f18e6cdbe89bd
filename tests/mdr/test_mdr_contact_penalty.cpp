// MDR's contact penalty (models/mdr/mdr_contact_penalty.hpp, LAMMPS's calculate_contact_penalty):
// the weight of a triangle's longest side in closed form (alpha = pi/2 gives exactly 1/2), the
// clamp at 0, no weight without a mutual overlap, independence of the list's order and
// orientation, periodic images, every weight of a dense random cluster against a brute-force
// enumeration of its triangles (coincident centres included: finite, in [0, 1]), and the MDR force
// and damping of a weighted contact scaled by w while unweighted contacts stay bitwise unchanged.
#include <backends.hpp>
#include <catch2/catch.hpp>
#include <epac/compute/contact_forces.hpp>
#include <epac/models/mdr/mdr_model.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace epac;

namespace {

Material grain(double restitution = 1.0) {
  Material m;
  m.name = "grain";
  m.youngs_modulus = 1e8;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  m.yield_stress = 1e6;  // E/Y 100: yields at about 0.002 R
  m.restitution = restitution;
  return m;
}

struct Scene {
  std::vector<std::array<double, 3>> x;
  std::vector<double> R;
  std::vector<std::array<double, 3>> v;
};

template <class T, class D>
Particles<T, D> particles_of(const Scene& s, double box = 0.0) {
  const int n = static_cast<int>(s.x.size());
  Particles<T, D> p(n);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto g = Kokkos::create_mirror_view(p.gid);
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      double xi = s.x[i][d];
      if (box > 0.0) xi -= box * std::floor(xi / box);  // wrapped into [0, box)
      x(i, d) = xi;
      v(i, d) = s.v.empty() ? T(0) : T(s.v[i][d]);
    }
    r(i) = T(s.R[i]);
    g(i) = 10 + 3 * i;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.mass, T(1e-6));
  Kokkos::deep_copy(p.inertia, T(1e-12));
  Kokkos::deep_copy(p.material, 0);
  Kokkos::deep_copy(p.omega, T(0));
  if (box > 0.0) p.box.length = Vec3<double>(box, box, box);
  return p;
}

template <class D>
ContactList<D> list_of(const std::vector<std::array<int, 2>>& pairs) {
  ContactList<D> c(static_cast<int>(pairs.size()));
  auto f = Kokkos::create_mirror_view(c.first);
  auto s = Kokkos::create_mirror_view(c.second);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    f(k) = pairs[k][0];
    s(k) = pairs[k][1];
  }
  Kokkos::deep_copy(c.first, f);
  Kokkos::deep_copy(c.second, s);
  return c;
}

// The weights of `pairs` (penalty on).
template <class T, class D>
std::vector<double> weights(const Scene& s, const std::vector<std::array<int, 2>>& pairs, double box = 0.0,
                            int nlocal = -1) {
  MdrOptions o;
  o.contact_penalty = true;
  auto m = Mdr<T, Effects<kPlasticity>, D>::create({grain()}, o);
  const auto p = particles_of<T, D>(s, box);
  const auto c = list_of<D>(pairs);
  m.compute_contact_penalty(p, c, nlocal);
  auto w = test::to_host(m.penalty.weight);
  std::vector<double> out;
  for (std::size_t k = 0; k < pairs.size(); ++k) out.push_back(double(w(k)));
  return out;
}

double logistic(double alpha) { return 1.0 / (1.0 + std::exp(-50.0 * (alpha / M_PI - 0.5))); }

// a = 0, b on x at L, c above the middle at height h; radii R.
Scene triangle(double R, double L, double h) {
  Scene s;
  s.x = {{0.0, 0.0, 0.0}, {L, 0.0, 0.0}, {0.5 * L, h, 0.0}};
  s.R = {R, R, R};
  return s;
}

// Brute force over every triple: p of each listed pair (longest side, ties by the larger key).
std::vector<double> brute_force(const Scene& s, const std::vector<std::array<int, 2>>& pairs, double box) {
  const int n = static_cast<int>(s.x.size());
  auto d = [&](int i, int j, int k) {
    double v = s.x[j][k] - s.x[i][k];
    if (box > 0.0) v -= box * std::round(v / box);
    return v;
  };
  auto dist = [&](int i, int j) {
    return std::sqrt(d(i, j, 0) * d(i, j, 0) + d(i, j, 1) * d(i, j, 1) + d(i, j, 2) * d(i, j, 2));
  };
  auto key = [&](int i, int j) { return pair_key(10 + 3 * i, 10 + 3 * j); };
  std::vector<double> out;
  for (const auto& pr : pairs) {
    const int a = pr[0], b = pr[1];
    double p = 0.0;
    const double rab = dist(a, b);
    if (!(s.R[a] + s.R[b] - rab < 0.0))
      for (int c = 0; c < n; ++c) {
        if (c == a || c == b) continue;
        const double rac = dist(a, c), rbc = dist(b, c);
        if (s.R[a] + s.R[c] - rac < 0.0 || s.R[b] + s.R[c] - rbc < 0.0) continue;
        auto shorter = [&](double r, std::uint64_t k) { return r < rab || (r == rab && k < key(a, b)); };
        if (!shorter(rac, key(a, c)) || !shorter(rbc, key(b, c))) continue;
        if (!(rac > 0.0) || !(rbc > 0.0)) continue;
        double cosv = 0.0;
        for (int k = 0; k < 3; ++k) cosv += d(c, a, k) * d(c, b, k);
        cosv /= rac * rbc;
        p += logistic(std::acos(std::max(-1.0, std::min(1.0, cosv))));
      }
    out.push_back(std::max(1.0 - p, 0.0));
  }
  return out;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("contact penalty: a triangle's longest side in closed form", "[mdr][penalty]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  const double R = 1e-3, L = 1.9e-3;
  const double tol = std::is_same<T, float>::value ? 1e-6 : 1e-12;
  SECTION("alpha = pi/2: w = 1/2 on the longest side, 1 on the others") {
    const auto w = weights<T, D>(triangle(R, L, 0.5 * L), {{0, 1}, {0, 2}, {1, 2}});
    CHECK(w[0] == Approx(0.5).margin(tol));
    CHECK(w[1] == 1.0);
    CHECK(w[2] == 1.0);
  }
  SECTION("any alpha: w = 1 - 1/(1 + exp(-50 (alpha/pi - 1/2))), alpha = 2 atan(L / 2h)") {
    for (double h : {0.05 * L, 0.3 * L, 0.45 * L, 0.55 * L}) {
      const double alpha = 2.0 * std::atan(0.5 * L / h);
      const auto w = weights<T, D>(triangle(R, L, h), {{0, 1}, {0, 2}, {1, 2}});
      CHECK(w[0] == Approx(1.0 - logistic(alpha)).margin(tol));
    }
  }
  SECTION("a tie for the longest side: the larger pair key takes the term, in either orientation") {
    // |ac| = |bc| to the last bit (c above the middle of ab) and longer than |ab|: the triangles'
    // lanes leave the tie to the ids (the brute force's rule); the angle at b (or a) is the same
    // for both sides
    const double h = 0.9 * L;
    const Scene s = triangle(R, 0.9 * L, h);
    for (const auto& pairs : {std::vector<std::array<int, 2>>{{0, 1}, {0, 2}, {1, 2}},
                              std::vector<std::array<int, 2>>{{1, 0}, {2, 0}, {2, 1}}}) {
      const auto w = weights<T, D>(s, pairs);
      const auto ref = brute_force(s, pairs, 0.0);
      CHECK(w[0] == 1.0);                   // ab: the shortest side
      CHECK((w[1] < 1.0) != (w[2] < 1.0));  // one of the tied sides, not both
      for (int k = 0; k < 3; ++k) CHECK(w[k] == Approx(ref[k]).margin(tol));
    }
  }
  SECTION("no mutual overlap: no weight") {
    // c touches neither end (h large), or a and b apart (L > 2R) with c touching both
    CHECK(weights<T, D>(triangle(R, L, 1.8 * R), {{0, 1}, {0, 2}, {1, 2}})[0] == 1.0);
    const auto apart = weights<T, D>(triangle(R, 2.05 * R, 0.2 * R), {{0, 1}, {0, 2}, {1, 2}});
    CHECK(apart[0] == 1.0);  // ab open: its contact is not penalised
    CHECK(apart[1] == 1.0);
    CHECK(apart[2] == 1.0);
  }
  SECTION("two obstructing particles: the terms add; the weight stops at 0") {
    Scene s = triangle(R, L, 0.5 * L);
    s.x.push_back({0.5 * L, -0.5 * L, 0.0});
    s.R.push_back(R);
    const auto w = weights<T, D>(s, {{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3}, {2, 3}});
    CHECK(w[0] == Approx(0.0).margin(tol));  // 1/2 + 1/2
    s.x[2][1] = 0.3 * L;
    s.x[3][1] = -0.3 * L;  // each alpha > pi/2: p > 1
    CHECK(weights<T, D>(s, {{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3}, {2, 3}})[0] == 0.0);
  }
  SECTION("the same weights whatever the list's order and orientation, and across a periodic boundary") {
    const Scene s = triangle(R, L, 0.4 * L);
    const auto ref = weights<T, D>(s, {{0, 1}, {0, 2}, {1, 2}});
    const auto other = weights<T, D>(s, {{2, 1}, {1, 0}, {2, 0}});
    CHECK(other[1] == ref[0]);
    CHECK(other[2] == ref[1]);
    CHECK(other[0] == ref[2]);
    Scene shifted = s;
    for (auto& x : shifted.x) x[0] -= 0.5 * L;  // a and c wrap to the far side of a 10 R box
    const auto wrapped = weights<T, D>(shifted, {{0, 1}, {0, 2}, {1, 2}}, 10 * R);
    for (int k = 0; k < 3; ++k) CHECK(wrapped[k] == Approx(ref[k]).margin(tol));
  }
}

TEMPLATE_LIST_TEST_CASE("contact penalty: many triangles on one contact", "[mdr][penalty]", test::Backends) {
  using D = TestType;
  // a and b on x, N particles on a ring in the middle plane: N triangles on ab, each at the same
  // alpha = 2 atan((L/2) / rho): w = 1 - N term(alpha).
  const double R = 1e-3, L = 1.98e-3, rho = 1.414e-3;
  const double alpha = 2.0 * std::atan(0.5 * L / rho);
  for (int N : {6, 12}) {
    Scene s;
    s.x = {{0.0, 0.0, 0.0}, {L, 0.0, 0.0}};
    s.R = {R, R};
    std::vector<std::array<int, 2>> pairs = {{0, 1}};
    for (int q = 0; q < N; ++q) {
      const double phi = 2.0 * M_PI * q / N;
      s.x.push_back({0.5 * L, rho * std::cos(phi), rho * std::sin(phi)});
      s.R.push_back(0.8e-3);
    }
    for (int i = 0; i < 2 + N; ++i)  // every pair listed, as a neighbour list would (ring neighbours overlap too)
      for (int j = i + 1; j < 2 + N; ++j)
        if (i > 0 || j > 1) pairs.push_back({(i + j) % 2 ? j : i, (i + j) % 2 ? i : j});
    const auto w = weights<double, D>(s, pairs);
    INFO("N = " << N);
    CHECK(w[0] == Approx(1.0 - N * logistic(alpha)).margin(1e-14));
    CHECK(w[0] < 1.0 - 5 * logistic(alpha));
    const auto ref = brute_force(s, pairs, 0.0);
    for (std::size_t k = 0; k < pairs.size(); ++k) CHECK(w[k] == Approx(ref[k]).margin(1e-14));
  }
}

TEMPLATE_LIST_TEST_CASE("contact penalty: a dense random cluster against brute force, coincident centres included",
                        "[mdr][penalty]", test::Backends) {
  using D = TestType;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double box : {0.0, 4.5e-3}) {  // (periodic: every overlap below L/2)
    Scene s;
    const int n = 60;
    for (int i = 0; i < n; ++i) {
      s.x.push_back({4e-3 * u(rng), 4e-3 * u(rng), 4e-3 * u(rng)});
      s.R.push_back(0.5e-3 + 0.5e-3 * u(rng));
    }
    s.x[5] = s.x[4];  // coincident centres
    s.x[6] = s.x[4];
    std::vector<std::array<int, 2>> pairs;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if ((i + j) % 5 != 0)
          pairs.push_back({i, j});  // some listed pairs are apart (a neighbour list)
        else
          pairs.push_back({j, i});
    const auto w = weights<double, D>(s, pairs, box);
    const auto ref = brute_force(s, pairs, box);
    int weighted = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      REQUIRE(std::isfinite(w[k]));
      CHECK(w[k] >= 0.0);
      CHECK(w[k] <= 1.0);
      CHECK(w[k] == Approx(ref[k]).margin(1e-13));
      weighted += w[k] < 1.0 ? 1 : 0;
    }
    CHECK(weighted > 20);  // the cluster is dense enough to test something
  }
}

TEMPLATE_LIST_TEST_CASE("contact penalty: ghost copies (a host's particles past nlocal) against brute force",
                        "[mdr][penalty]", test::Backends) {
  using D = TestType;
  // A host with ghosts lists only the pairs with a local end, so a ghost's range of partners is
  // partial: a contact with a ghost end must walk its local end (and measure the ghost side
  // itself); a contact with two local ends finds its triangles in both ranges. Every weight must
  // still be the brute force's over all particles.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  const int n = 60, nlocal = 35;
  for (int i = 0; i < n; ++i) {
    s.x.push_back({4e-3 * u(rng), 4e-3 * u(rng), 4e-3 * u(rng)});
    s.R.push_back(0.5e-3 + 0.5e-3 * u(rng));
  }
  std::vector<std::array<int, 2>> pairs;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (i < nlocal || j < nlocal) pairs.push_back((i + j) % 3 ? std::array<int, 2>{j, i} : std::array<int, 2>{i, j});
  const auto w = weights<double, D>(s, pairs, 0.0, nlocal);
  const auto ref = brute_force(s, pairs, 0.0);
  int weighted_ghost = 0, weighted_local = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    INFO("pair " << pairs[k][0] << " " << pairs[k][1]);
    CHECK(w[k] == Approx(ref[k]).margin(1e-13));
    const bool ghost = pairs[k][0] >= nlocal || pairs[k][1] >= nlocal;
    (ghost ? weighted_ghost : weighted_local) += w[k] < 1.0 ? 1 : 0;
  }
  CHECK(weighted_ghost > 10);  // both paths weigh something
  CHECK(weighted_local > 10);
  // every pair listed and no ghosts (nlocal -1): the same weights on the pairs of both lists, bit
  // for bit (both paths meet the same triangles in the same order)
  std::vector<std::array<int, 2>> every = pairs;
  for (int i = nlocal; i < n; ++i)
    for (int j = i + 1; j < n; ++j) every.push_back({i, j});
  const auto all_local = weights<double, D>(s, every, 0.0, -1);
  for (std::size_t k = 0; k < pairs.size(); ++k) CHECK(all_local[k] == w[k]);
}

TEMPLATE_LIST_TEST_CASE("contact penalty: the MDR force and damping of a weighted contact times w", "[mdr][penalty]",
                        test::BackendsAndScalars) {
  using D = typename TestType::device;
  using T = typename TestType::scalar;
  using Model = Mdr<T, Effects<kPlasticity | kDamping | kRadiusGrowth>, D>;
  const double R = 1e-3;
  // b closes in on a over 6 steps with c kept at alpha = pi/2 (w(ab) = 1/2 exactly), c in the
  // pocket (R_c = 0.42 R: every overlap about 0.02 R); approaching velocities: damped
  auto run = [&](bool penalty) {
    MdrOptions o;
    o.contact_penalty = penalty;
    auto m = Model::create({grain(0.5)}, o);
    Scene s = triangle(R, 1.99e-3, 0.5 * 1.99e-3);
    s.R[2] = 0.42e-3;
    s.v = {{0.01, 0.0, 0.0}, {-0.01, 0.0, 0.0}, {0.0, -0.02, 0.0}};
    auto p = particles_of<T, D>(s);
    m.bind(p);
    const auto c = list_of<D>({{0, 1}, {0, 2}, {1, 2}});
    ContactHistory<T, D> h(3, Model::history_size);
    ContactOutputs<T, D> out;
    out.normal_force = Kokkos::View<T*, D>("fn", 3);
    std::vector<std::array<double, 3>> fn;
    for (int step = 0; step < 6; ++step) {
      const double L = 1.99e-3 - 0.004e-3 * step;
      auto x = Kokkos::create_mirror_view(p.x);
      Kokkos::deep_copy(x, p.x);
      x(1, 0) = L;
      x(2, 0) = 0.5 * L;
      x(2, 1) = 0.5 * L;
      Kokkos::deep_copy(p.x, x);
      m.compute_contact_penalty(p, c);
      compute_pair_forces(m, p, c, h, T(1e-7), out);
      m.update_radii();
      auto f = test::to_host(out.normal_force);
      fn.push_back({double(f(0)), double(f(1)), double(f(2))});
    }
    auto r = test::to_host(p.radius);
    return std::make_pair(fn, std::array<double, 3>{double(r(0)), double(r(1)), double(r(2))});
  };
  const auto off = run(false), on = run(true);
  const double tol = std::is_same<T, float>::value ? 1e-6 : 1e-14;
  REQUIRE(off.first[0][0] > 0.0);
  // the first step: the same state, the law and the damping both halved on ab, the rest the same bits
  CHECK(on.first[0][0] == Approx(0.5 * off.first[0][0]).epsilon(tol));
  CHECK(on.first[0][1] == off.first[0][1]);
  CHECK(on.first[0][2] == off.first[0][2]);
  // a and b grew (yielded, loading); their ab terms counted half, so they grew differently
  REQUIRE(off.second[0] > R);
  CHECK(on.second[0] != off.second[0]);
}

TEST_CASE("contact penalty: off by default; no weights computed", "[mdr][penalty]") {
  auto m = Mdr<double>::create({grain()});
  CHECK_FALSE(m.penalty.on);
  const auto p = particles_of<double, DefaultDevice>(triangle(1e-3, 1.9e-3, 0.5 * 1.9e-3));
  m.compute_contact_penalty(p, list_of<DefaultDevice>({{0, 1}, {0, 2}, {1, 2}}));
  // nothing weighed: the weights stay Mdr::create's one placeholder entry (the in-bounds load of
  // weight_of_lane), and both forms read 1
  CHECK(m.penalty.weight.extent(0) == 1);
  CHECK(m.penalty.weight_of(0) == 1.0);
  CHECK(m.penalty.weight_of(2) == 1.0);
  if (Kokkos::SpaceAccessibility<Kokkos::HostSpace, DefaultDevice::memory_space>::accessible) {
    CHECK(m.penalty.weight_of_lane(0) == 1.0);  // the lane form loads the placeholder
    CHECK(m.penalty.weight_of_lane(2) == 1.0);
  }
}
