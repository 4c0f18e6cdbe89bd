// Device contact detection: the cell list finds exactly the pairs and wall contacts an O(N^2)
// search finds; the rebuild rule; history of persisting contacts survives a rebuild + remap.
#include <backends.hpp>
#include <catch2/catch.hpp>

#include "driver/contact_detection.hpp"
#include "driver/spatial_sort.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace epac;
using namespace epac::driver;

namespace {

struct HostPacking {
  std::vector<double> x, y, z, r;
  int n() const { return static_cast<int>(r.size()); }
};

// n particles at uniformly random positions in a cube (overlaps allowed: detection must not
// care), radii in [r0, r1]. Solid fraction ~0.3 gives ~3-4 candidate partners per particle.
HostPacking random_packing(int n, double r0, double r1, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double mean_r3 = r1 > r0 ? 0.25 * (r1 * r1 * r1 * r1 - r0 * r0 * r0 * r0) / (r1 - r0) : r0 * r0 * r0;
  const double L = std::cbrt(n * 4.0 / 3.0 * M_PI * mean_r3 / 0.3);
  HostPacking h;
  for (int i = 0; i < n; ++i) {
    h.x.push_back(L * u(rng));
    h.y.push_back(L * u(rng));
    h.z.push_back(L * u(rng));
    h.r.push_back(r0 + (r1 - r0) * u(rng));
  }
  return h;
}

template <class D>
Particles<double, D> to_device(const HostPacking& h) {
  Particles<double, D> p(h.n());
  auto x = Kokkos::create_mirror_view(p.x);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto g = Kokkos::create_mirror_view(p.gid);
  auto m = Kokkos::create_mirror_view(p.mass);
  for (int i = 0; i < h.n(); ++i) {
    x(i, 0) = h.x[i];
    x(i, 1) = h.y[i];
    x(i, 2) = h.z[i];
    r(i) = h.r[i];
    g(i) = 1000 + 3 * i;  // global ids need not equal indices
    m(i) = 1.0;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.radius0, r);
  Kokkos::deep_copy(p.gid, g);
  Kokkos::deep_copy(p.mass, m);
  return p;
}

std::set<std::pair<int, int>> brute_force_pairs(const HostPacking& h, double skin) {
  std::set<std::pair<int, int>> s;
  for (int i = 0; i < h.n(); ++i)
    for (int j = i + 1; j < h.n(); ++j) {
      const double dx = h.x[i] - h.x[j], dy = h.y[i] - h.y[j], dz = h.z[i] - h.z[j];
      const double cut = h.r[i] + h.r[j] + skin;
      if (dx * dx + dy * dy + dz * dz < cut * cut) s.insert({i, j});
    }
  return s;
}

template <class D>
std::vector<std::pair<int, int>> list_pairs(const ContactList<D>& c) {
  auto a = test::to_host(c.first);
  auto b = test::to_host(c.second);
  std::vector<std::pair<int, int>> v;
  for (int k = 0; k < c.count; ++k) v.push_back({a(k), b(k)});
  return v;
}

template <class D>
Walls<double, D> box_walls(double L) {
  // floor, ceiling and one tilted plane cutting through the packing
  Walls<double, D> w(3);
  auto pt = Kokkos::create_mirror_view(w.point);
  auto nr = Kokkos::create_mirror_view(w.normal);
  const double normals[3][3] = {{0, 0, 1}, {0, 0, -1}, {0.6, 0.0, 0.8}};
  const double points[3][3] = {{0, 0, 0}, {0, 0, L}, {0.3 * L, 0, 0.3 * L}};
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) {
      pt(k, d) = points[k][d];
      nr(k, d) = normals[k][d];
    }
  Kokkos::deep_copy(w.point, pt);
  Kokkos::deep_copy(w.normal, nr);
  return w;
}

// Device-side edits (in named functions: CUDA forbids device lambdas inside lambdas).
template <class D>
void shift_particle(const Particles<double, D>& p, int i, int d, double by) {
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) { p.x(i, d) += by; });
}
template <class D>
void grow_particle(const Particles<double, D>& p, int i, double by) {
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) { p.radius(i) += by; });
}
template <class D>
void shift_wall(const Walls<double, D>& w, int k, int d, double by) {
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1), KOKKOS_LAMBDA(int) { w.point(k, d) += by; });
}
// Writes each contact's identity (global ids, or gid and -1 - wall) into its history row.
template <class D>
void tag_history(const ContactList<D>& c, const ContactHistory<double, D>& hist, const Particles<double, D>& pp,
                 bool walls) {
  auto d = hist.data;
  Kokkos::parallel_for(
      Kokkos::RangePolicy<typename D::execution_space>(0, c.count), KOKKOS_LAMBDA(int k) {
        d(k, 0) = double(pp.gid(c.first(k)));
        d(k, 1) = walls ? -1.0 - c.second(k) : double(pp.gid(c.second(k)));
        d(k, 2) = 0.5;
      });
}

// Every coordinate moved by up to `by`.
void jiggle(HostPacking& h, double by, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < h.n(); ++i) {
    h.x[i] += by * u(rng);
    h.y[i] += by * u(rng);
    h.z[i] += by * u(rng);
  }
}

// The contacts of a list as global-id pairs (walls: (gid, -1 - wall)), in list order.
template <class D>
std::vector<std::pair<double, double>> gid_pairs(const ContactList<D>& c, const Particles<double, D>& p, bool walls) {
  const auto ij = list_pairs(c);
  auto g = test::to_host(p.gid);
  std::vector<std::pair<double, double>> v;
  for (const auto& e : ij) v.push_back({double(g(e.first)), walls ? -1.0 - e.second : double(g(e.second))});
  return v;
}

// A rebuilt list's history against the list before (global-id pairs, tagged by tag_history):
// a persisting contact carries its tags, a new one is zero; some persist, some are new, some
// vanished.
template <class D>
void check_carried_over(const ContactList<D>& c, const ContactHistory<double, D>& hist, const Particles<double, D>& p,
                        const std::vector<std::pair<double, double>>& old, bool walls) {
  const std::set<std::pair<double, double>> before(old.begin(), old.end());
  const auto now = gid_pairs(c, p, walls);
  auto d = test::to_host(hist.data);
  REQUIRE(static_cast<int>(d.extent(0)) == c.count);
  int kept = 0, fresh = 0, wrong = 0;
  for (int k = 0; k < c.count; ++k) {
    if (before.count(now[k])) {
      ++kept;
      if (d(k, 0) != now[k].first || d(k, 1) != now[k].second || d(k, 2) != 0.5) ++wrong;
    } else {
      ++fresh;
      if (d(k, 0) != 0.0 || d(k, 1) != 0.0 || d(k, 2) != 0.0) ++wrong;
    }
  }
  INFO((walls ? "walls" : "pairs") << ": kept " << kept << ", new " << fresh << ", old " << old.size());
  CHECK(kept > 0);
  CHECK(fresh > 0);
  CHECK(kept < static_cast<int>(old.size()));  // some vanished
  CHECK(wrong == 0);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("the cell list finds exactly the pairs of an O(N^2) search", "[driver][detection]",
                        test::Backends) {
  using D = TestType;
  const double r0 = 0.8e-3, r1 = 1.2e-3;
  HostPacking h = random_packing(3000, r0, r1, 11);
  SECTION("a compact random packing") {}
  SECTION("one particle far away (the grid widens its cells)") {
    h.x[17] += 10.0;  // 10 m off: ~1e4 cells of 2.6 mm per axis without the cap
  }
  SECTION("a cluster: particles with more partners than the count pass keeps (kPairScratch)") {
    for (int k = 1; k <= 3 * kPairScratch; ++k) {  // overlapping particle 0: the fill pass searches again
      h.x[k] = h.x[0] + 1e-5 * k;
      h.y[k] = h.y[0];
      h.z[k] = h.z[0];
    }
  }
  const double skin = 0.15 * r0;
  const auto p = to_device<D>(h);
  const CellList<double, D> cells = build_cell_list(p, 2.0 * r1 + skin);
  CHECK(cells.ncells() <= 2 * h.n() + 64);
  const ContactList<D> list = find_pairs(p, cells, skin);
  const auto expected = brute_force_pairs(h, skin);
  const auto got = list_pairs(list);
  REQUIRE(expected.size() > 3000u);  // a test with few pairs would prove little
  CHECK(got.size() == expected.size());
  for (const auto& ij : got) CHECK(ij.first < ij.second);
  const std::set<std::pair<int, int>> got_set(got.begin(), got.end());
  CHECK(got_set.size() == got.size());  // no duplicates
  CHECK(got_set == expected);
  // ordered by first index: a deterministic list
  CHECK(std::is_sorted(got.begin(), got.end(), [](auto a, auto b) { return a.first < b.first; }));
}

TEMPLATE_LIST_TEST_CASE("wall contacts are the particles within R + skin of each plane", "[driver][detection]",
                        test::Backends) {
  using D = TestType;
  const HostPacking h = random_packing(2000, 0.8e-3, 1.2e-3, 5);
  double L = 0;
  for (double z : h.z) L = std::max(L, z);
  const double skin = 1e-4;
  const auto p = to_device<D>(h);
  const auto w = box_walls<D>(L);
  const ContactList<D> list = find_wall_contacts(p, w, skin);
  auto pt = test::to_host(w.point);
  auto nr = test::to_host(w.normal);
  std::set<std::pair<int, int>> expected;
  for (int i = 0; i < h.n(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double dist =
          (h.x[i] - pt(k, 0)) * nr(k, 0) + (h.y[i] - pt(k, 1)) * nr(k, 1) + (h.z[i] - pt(k, 2)) * nr(k, 2);
      if (dist < h.r[i] + skin) expected.insert({i, k});
    }
  const auto got = list_pairs(list);
  REQUIRE(expected.size() > 100u);
  CHECK(got.size() == expected.size());
  CHECK(std::set<std::pair<int, int>>(got.begin(), got.end()) == expected);
}

TEMPLATE_LIST_TEST_CASE("the lists are rebuilt when the skin is used up", "[driver][detection]", test::Backends) {
  using D = TestType;
  const HostPacking h = random_packing(500, 1e-3, 1e-3, 3);
  const double skin = 2e-4;
  auto p = to_device<D>(h);
  auto w = box_walls<D>(0.01);
  ContactDetector<double, D> det(skin, 3, 3);
  CHECK(det.needs_rebuild(p, w));  // never built
  det.build(p, w);
  CHECK_FALSE(det.needs_rebuild(p, w));
  auto set_x = [&](int i, double dx) { shift_particle(p, i, 0, dx); };
  set_x(7, 0.49 * skin);
  CHECK_FALSE(det.needs_rebuild(p, w));  // within skin/2
  set_x(7, 0.02 * skin);
  CHECK(det.needs_rebuild(p, w));  // 0.51 skin
  det.build(p, w);
  CHECK_FALSE(det.needs_rebuild(p, w));
  // a growing radius uses up the same margin (MDR)
  grow_particle(p, 3, 0.3 * skin);
  shift_particle(p, 3, 1, 0.25 * skin);
  CHECK(det.needs_rebuild(p, w));
  det.build(p, w);
  // a wall moving along its normal, but not one sliding in its plane
  shift_wall(w, 0, 0, 5 * skin);
  CHECK_FALSE(det.needs_rebuild(p, w));
  shift_wall(w, 0, 2, 0.6 * skin);
  CHECK(det.needs_rebuild(p, w));
  CHECK(det.builds == 3);
}

TEMPLATE_LIST_TEST_CASE("the allowance for shifts measured beyond an affine compression", "[driver][detection]",
                        test::Backends) {
  using D = TestType;
  const HostPacking h = random_packing(500, 1e-3, 1e-3, 3);  // radii 1 mm
  const double skin = 2e-4;
  auto p = to_device<D>(h);
  auto w = box_walls<D>(0.01);
  ContactDetector<double, D> det(skin, 3, 3);
  det.build(p, w);
  // no deformation, or an expansion (separations only grow): skin / 2
  CHECK(det.shift_allowance(1.0) == 0.5 * skin);
  CHECK(det.shift_allowance(1.3) == 0.5 * skin);
  // (l skin - (1 - l) 2 R_max) / 2 with R_max = 1 mm
  const double l = 0.97;
  const double expected = 0.5 * (l * skin - (1.0 - l) * 2.0 * 1e-3);
  CHECK(det.shift_allowance(l) == Approx(expected).epsilon(1e-14));
  // two spheres at the list's edge (R_i + R_j + skin apart), brought together by the compression
  // and each by the allowance towards the other, just touch: the allowance is the exact bound
  const double gap = l * (2e-3 + skin) - 2.0 * det.shift_allowance(l);
  CHECK(gap == Approx(2e-3).epsilon(1e-12));
  CHECK(det.needs_rebuild(0.99 * expected, 0.0, l) == false);
  CHECK(det.needs_rebuild(1.01 * expected, 0.0, l) == true);
  // the skin used up by the compression alone (1 - l > skin / (skin + 2 R_max)): every step
  const double l_edge = 1.0 - skin / (skin + 2e-3);
  CHECK(std::fabs(det.shift_allowance(l_edge)) < 1e-18);
  CHECK(det.shift_allowance(l_edge - 1e-3) < 0.0);
  CHECK(det.needs_rebuild(0.0, 0.0, l_edge - 1e-3));
  // walls keep skin / 2
  CHECK(det.needs_rebuild(0.0, 0.51 * skin, 1.0));
  CHECK_FALSE(det.needs_rebuild(0.0, 0.49 * skin, 1.0));
}

namespace {
// A packing whose lists were built and each contact's history tagged with its identity
// (tag_history, as a model would store state), then every particle moved by up to 2 skins:
// many contacts persist, some vanish, some appear.
template <class D>
struct MovedPacking {
  static constexpr double skin = 1e-4;
  HostPacking h;
  Particles<double, D> p;
  Walls<double, D> w = box_walls<D>(0.02);
  ContactDetector<double, D> det{skin, 3, 3};
  std::vector<std::pair<double, double>> old_pairs, old_walls;
  MovedPacking(unsigned packing_seed, unsigned move_seed)
      : h(random_packing(2000, 0.8e-3, 1.2e-3, packing_seed)), p(to_device<D>(h)) {
    det.build(p, w);
    tag_history(det.pairs, det.pair_history, p, false);
    tag_history(det.walls, det.wall_history, p, true);
    old_pairs = gid_pairs(det.pairs, p, false);
    old_walls = gid_pairs(det.walls, p, true);
    std::mt19937_64 rng(move_seed);
    jiggle(h, 2 * skin, rng);
    p = to_device<D>(h);
  }
  // After the caller's rebuild: the histories carried over (check_carried_over).
  void check() const {
    check_carried_over(det.pairs, det.pair_history, p, old_pairs, false);
    check_carried_over(det.walls, det.wall_history, p, old_walls, true);
  }
};
}  // namespace

TEMPLATE_LIST_TEST_CASE("a rebuild and remap keeps the history of persisting contacts", "[driver][detection]",
                        test::Backends) {
  MovedPacking<TestType> m(23, 99);
  REQUIRE(m.det.needs_rebuild(m.p, m.w));
  m.det.build(m.p, m.w);
  m.check();
}

TEMPLATE_LIST_TEST_CASE("a rebuild with spatial sorts carries the history over through the permutations",
                        "[driver][detection]", test::Backends) {
  using D = TestType;
  MovedPacking<D> m(31, 7);  // random order: the sorts move nearly everyone
  const double skin = m.skin;
  const int n = m.h.n();
  auto& p = m.p;
  auto& det = m.det;
  const auto& w = m.w;
  std::mt19937_64 rng(8);
  typename ContactDetector<double, D>::sort_callback sort = [&](const Kokkos::View<int*, D>& perm) {
    Permuter<double, D>(perm).particles(p);
  };
  // The global ids by index (a copy: on host backends a mirror view would be p.gid itself).
  auto gids = [&] {
    auto g = test::to_host(p.gid);
    return std::vector<int>(g.data(), g.data() + g.extent(0));
  };
  const auto g0 = gids();
  CHECK(det.detect(p, w, &sort));
  const auto g1 = gids();
  int moved = 0;  // particles the first sort gave another index
  for (int k = 0; k < n; ++k) moved += g0[k] != g1[k];
  // Two sorts before one remap: moves of up to a skin take some particles into other cells, so
  // the second sort reorders again and the remap must compose the two permutations.
  {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) x(k, d) += skin * u(rng);
    Kokkos::deep_copy(p.x, x);
  }
  CHECK(det.detect(p, w, &sort));
  const auto g2 = gids();
  int moved_again = 0;
  for (int k = 0; k < n; ++k) moved_again += g1[k] != g2[k];
  det.remap(p);
  INFO("reindexed by the sorts: " << moved << ", " << moved_again);
  REQUIRE(moved > n / 2);
  REQUIRE(moved_again > 0);

  m.check();
  // After the sorts indices no longer follow global ids, and the list is still oriented by them
  // (the lanes kernel then skips its per-contact id test: ContactList::gid_ordered).
  {
    REQUIRE(det.pairs.gid_ordered);
    REQUIRE(det.pairs.count > n);
    const auto first = test::to_host(det.pairs.first);
    const auto second = test::to_host(det.pairs.second);
    int against_index = 0;  // pairs whose smaller id is at the larger index
    for (int k = 0; k < det.pairs.count; ++k) {
      CHECK(g2[first(k)] < g2[second(k)]);
      against_index += first(k) > second(k);
    }
    CHECK(against_index > 0);
  }

  // SortWhen::if_grid_changed (the driver's auto rule between sort intervals): on the grid of the
  // last sort no sort; on a spread packing (other cell counts) a sort; SortWhen::now always.
  using When = typename ContactDetector<double, D>::SortWhen;
  CHECK_FALSE(det.detect(p, w, &sort, When::if_grid_changed));
  {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.x);
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) x(k, d) *= 1.5;
    Kokkos::deep_copy(p.x, x);
  }
  CHECK(det.detect(p, w, &sort, When::if_grid_changed));
  CHECK_FALSE(det.detect(p, w, &sort, When::if_grid_changed));
  CHECK(det.detect(p, w, &sort, When::now));
  CHECK_FALSE(det.detect(p, w, nullptr, When::now));
}

namespace {
// Cells for_each_near_cell visits around x with this reach (counted on the device).
template <class D>
int cells_visited(const CellList<double, D>& cells, const Vec3<double>& x, double reach) {
  int visited = 0;
  Kokkos::parallel_reduce(
      Kokkos::RangePolicy<typename D::execution_space>(0, 1),
      KOKKOS_LAMBDA(int, int& v) { cells.for_each_near_cell(x, reach, [&](int) { ++v; }); }, visited);
  return visited;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE(
    "cells beyond a particle's reach are not searched; a pair just inside the cut-off across a "
    "cell corner is found",
    "[driver][detection]", test::Backends) {
  using D = TestType;
  const double r = 1e-3, skin = 1e-4, h = 2 * r + skin;  // cell edge = the largest cut-off
  // Particle 0 in cell (1, 1, 1) of a 4^3 grid (anchors 2 and 3 span it; 64 cells: within the
  // cap of 2 n + 64), placed so that the nearest corner of the diagonal cell (2, 2, 2) is
  // (1 - 2e-9) of the reach r + r + skin = h away; particle 1 on that diagonal at (1 - 1e-9) h,
  // just past the corner: a partner in a cell the search only just must not skip.
  const double c0 = 1 * h + h * (1 - (1 - 2e-9) / std::sqrt(3.0)), c1 = c0 + h * (1 - 1e-9) / std::sqrt(3.0);
  // Particles 4 and 5 (radius r / 4: reach r / 4 + r + skin < h, cut-off r / 2 + skin): 4 at 0.1 h
  // below the upper faces of cell (1, 1, 2), 5 in the diagonal cell (2, 2, 3) just inside the
  // cut-off. Here the lower and upper gaps differ (0.9 h and 0.1 h): taking one for the other
  // would skip 5's cell.
  const double rs = r / 4, cs = (2 * rs + skin) * (1 - 1e-9) / std::sqrt(3.0);
  HostPacking hp;
  hp.x = {c0, c1, 0.0, 3.5 * h, 1.9 * h, 1.9 * h + cs};
  hp.y = hp.x;
  hp.z = {c0, c1, 0.0, 3.5 * h, 2.9 * h, 2.9 * h + cs};
  hp.r = {r, r, r, r, rs, rs};
  const auto p = to_device<D>(hp);
  const CellList<double, D> cells = build_cell_list(p, h);
  REQUIRE(cells.nx == 4);
  REQUIRE(cells.h.x == Approx(h).epsilon(1e-12));
  REQUIRE(cells.cell_of(Vec3<double>(c1, c1, c1)) == (2 * 4 + 2) * 4 + 2);
  REQUIRE(cells.cell_of(Vec3<double>(hp.x[5], hp.y[5], hp.z[5])) == (3 * 4 + 2) * 4 + 2);
  // 0.95 h from the lower faces of its cell: the 7 cells below on two or three axes are beyond h
  const Vec3<double> x_high(1.95 * h, 1.95 * h, 1.95 * h);
  CHECK(cells_visited(cells, x_high, h) == 20);
  // the cell's centre: every corner cell is within sqrt(3)/2 h
  CHECK(cells_visited(cells, Vec3<double>(1.5 * h, 1.5 * h, 1.5 * h), h) == 27);
  // no reach (<= 0, NaN, inf): every neighbour
  CHECK(cells_visited(cells, x_high, 0.0) == 27);
  CHECK(cells_visited(cells, x_high, std::nan("")) == 27);
  CHECK(cells_visited(cells, x_high, HUGE_VAL) == 27);
  const auto expected = brute_force_pairs(hp, skin);
  REQUIRE(expected == std::set<std::pair<int, int>>{{0, 1}, {4, 5}});
  const auto got = list_pairs(find_pairs(p, cells, skin));
  CHECK(std::set<std::pair<int, int>>(got.begin(), got.end()) == expected);
}
