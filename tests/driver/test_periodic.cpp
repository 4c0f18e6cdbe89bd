// Periodic boxes, affine box deformation and the fcc lattice fill of the driver:
//  - the periodic cell list finds exactly the pairs of an O(N^2) minimum-image search (particles
//    at every face, edge and corner, some just outside the box as between wraps; 2 and >= 3
//    cells along an axis);
//  - a contact across a periodic face gives the same forces as the same pair inside the box;
//  - [box.deform]: the edge after k steps and the affine positions (remap x); a particle
//    crossing a face keeps moving as in an unbounded domain (wrap at rebuilds);
//  - [particles.lattice]: count, positions, no overlaps, same radii for a seed;
//  - the new keys' rejections; --phase-times and particle_steps_per_second in the summary.
#include <backends.hpp>
#include <catch2/catch.hpp>

#include "driver/contact_detection.hpp"
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"
#include "driver/spatial_sort.hpp"
#include "driver_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

using namespace epac;
using namespace epac::driver;

namespace {

struct HostPacking {
  std::vector<double> x[3], r;
  int n() const { return static_cast<int>(r.size()); }
};

// Random positions in [0, L)^3 plus particles at every face, edge and corner (just inside and
// just outside: positions between two wraps), radii in [r0, r1].
HostPacking periodic_packing(int n, double L, double r0, double r1, double skin, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  HostPacking h;
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) h.x[d].push_back(L * u(rng));
    h.r.push_back(r0 + (r1 - r0) * u(rng));
  }
  // 3^3 - 1 face/edge/corner spots, each at 0 + e and L - e (e in (-skin/4, skin/4)).
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        if (a == 1 && b == 1 && c == 1) continue;
        const int k[3] = {a, b, c};
        for (int side = 0; side < 2; ++side) {
          for (int d = 0; d < 3; ++d) {
            const double e = (u(rng) - 0.5) * 0.5 * skin;
            const double at = k[d] == 1 ? L * u(rng) : (k[d] == 0 ? e : L + e);
            h.x[d].push_back(at);
          }
          h.r.push_back(r0 + (r1 - r0) * u(rng));
        }
      }
  return h;
}

template <class D>
Particles<double, D> to_device(const HostPacking& h, double L) {
  Particles<double, D> p(h.n());
  auto x = Kokkos::create_mirror_view(p.x);
  auto r = Kokkos::create_mirror_view(p.radius);
  auto g = Kokkos::create_mirror_view(p.gid);
  for (int i = 0; i < h.n(); ++i) {
    for (int d = 0; d < 3; ++d) x(i, d) = h.x[d][i];
    r(i) = h.r[i];
    g(i) = i;
  }
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.radius, r);
  Kokkos::deep_copy(p.gid, g);
  p.box.lo = Vec3<double>(0, 0, 0);
  p.box.length = Vec3<double>(L, L, L);
  return p;
}

double image(double s, double L) { return s - L * std::round(s / L); }

std::set<std::pair<int, int>> brute_force_periodic(const HostPacking& h, double L, double skin) {
  std::set<std::pair<int, int>> s;
  for (int i = 0; i < h.n(); ++i)
    for (int j = i + 1; j < h.n(); ++j) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double s1 = image(h.x[d][i] - h.x[d][j], L);
        d2 += s1 * s1;
      }
      const double cut = h.r[i] + h.r[j] + skin;
      if (d2 < cut * cut) s.insert({i, j});
    }
  return s;
}

driver::RunSummary run_text(const std::string& text, const std::filesystem::path& dir, bool phase_times = false) {
  driver::RunOptions opt;
  opt.out_dir = dir.string();
  opt.quiet = true;
  opt.phase_times = phase_times;
  return driver::run(driver::parse_scene_string(text, "test.toml"), opt);
}

const std::string kBead = R"(
[materials.bead]
youngs_modulus = 1.0e7
poisson_ratio = 0.3
density = 1000.0
restitution = 0.5
friction = 0.3
)";

// A CSV with a header line as rows of numbers (string columns are read as NaN).
std::vector<std::vector<double>> csv_rows(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string c;
    while (std::getline(s, c, ',')) row.push_back(c.empty() ? NAN : std::stod(c));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("the periodic cell list finds exactly the pairs of an O(N^2) minimum-image search",
                        "[driver][detection][periodic]", test::Backends) {
  using D = TestType;
  const double r0 = 0.8e-3, r1 = 1.2e-3, skin = 0.2e-3;
  const double reach = 2.0 * r1 + skin;
  double L = 0;
  int n = 0;
  SECTION("many cells per axis") {
    L = 9.3 * reach;
    n = 2500;
  }
  SECTION("2 cells per axis (the -1 and +1 neighbours are one cell)") {
    L = 2.4 * reach;
    n = 60;
  }
  const HostPacking h = periodic_packing(n, L, r0, r1, skin, 5);
  const auto p = to_device<D>(h, L);
  const CellList<double, D> cells = build_cell_list(p, reach);
  if (L < 3 * reach) CHECK(cells.nx == 2);
  const ContactList<D> list = find_pairs(p, cells, skin);
  const auto expected = brute_force_periodic(h, L, skin);
  auto a = test::to_host(list.first);
  auto b = test::to_host(list.second);
  std::set<std::pair<int, int>> found;
  for (int k = 0; k < list.count; ++k) {
    REQUIRE(a(k) < b(k));
    found.insert({a(k), b(k)});
  }
  CHECK(static_cast<std::size_t>(list.count) == found.size());  // each pair exactly once
  CHECK(found == expected);
  // across-face pairs are there (the test would be vacuous without them)
  int across = 0;
  for (const auto& pr : expected)
    for (int d = 0; d < 3; ++d)
      if (std::fabs(h.x[d][pr.first] - h.x[d][pr.second]) > 0.5 * L) {
        ++across;
        break;
      }
  CHECK(across > 0);
}

TEST_CASE("a contact across a periodic face gives the same forces as inside the box", "[driver][periodic]") {
  // Two spheres (R = 1 mm) overlapping by 0.1 mm, approaching at 0.01 m/s each along x, with a
  // tangential velocity: once across the face x = 0 / x = L, once in the middle of the box.
  auto scene = [](double xa, double xb) {
    return kBead + R"(
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.01, 0.01, 0.01]
periodic = [true, false, false]

[particles]
allow_overlap = true

[[particles.list]]
position = [)" +
           std::to_string(xa) + R"(, 0.005, 0.005]
radius = 0.001
material = "bead"
velocity = [0.01, 0.002, 0.0]

[[particles.list]]
position = [)" +
           std::to_string(xb) + R"(, 0.005, 0.005]
radius = 0.001
material = "bead"
velocity = [-0.01, 0.0, 0.0]

[run]
dt = 1.0e-6
steps = 40
output_interval = 10
contact_output = true
particle_output = true
)";
  };
  // gap 1.9 mm: a at L - 0.95 mm, b at 0.95 mm (across); a at 4.05 mm, b at 5.95 mm (inside).
  const auto d1 = test::fresh_out_dir("across");
  const auto d2 = test::fresh_out_dir("inside");
  run_text(scene(0.01 - 0.00095, 0.00095), d1);
  run_text(scene(0.00405, 0.00595), d2);
  const auto c1 = csv_rows(d1 / "contacts.csv");
  const auto c2 = csv_rows(d2 / "contacts.csv");
  REQUIRE(c1.size() == 5);  // steps 0, 10, 20, 30, 40
  REQUIRE(c1.size() == c2.size());
  for (std::size_t k = 0; k < c1.size(); ++k) {
    CHECK(c1[k][6] == Approx(c2[k][6]).epsilon(1e-9));  // overlap
    CHECK(c1[k][7] == Approx(c2[k][7]).epsilon(1e-9));  // normal force
    CHECK(c1[k][7] > 0);
  }
  const auto t1 = test::read_csv_columns(d1 / "timeseries.csv");
  const auto t2 = test::read_csv_columns(d2 / "timeseries.csv");
  for (std::size_t k = 0; k < t1.at("step").size(); ++k) {
    CHECK(t1.at("ke_translational")[k] == Approx(t2.at("ke_translational")[k]).epsilon(1e-9));
    CHECK(t1.at("ke_rotational")[k] == Approx(t2.at("ke_rotational")[k]).epsilon(1e-9));
  }
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
}

TEST_CASE("box deformation: edge after k steps, affine positions, held after the last step",
          "[driver][periodic][deform]") {
  // Spheres far apart at rest (no contacts, no gravity): positions move only with the box.
  const double L0 = 0.02, lo = -0.004;
  const std::string text = kBead + R"(
[box]
lo = [-0.004, -0.004, -0.004]
hi = [0.016, 0.016, 0.016]
periodic = [true, true, false]

[box.deform]
scale = [0.5, 1.5, 1.0]
steps = 10

[[particles.list]]
position = [-0.003, 0.0, 0.0]
radius = 0.0005
material = "bead"

[[particles.list]]
position = [0.010, 0.0151, 0.012]
radius = 0.0005
material = "bead"

[[particles.list]]
position = [0.004, 0.006, 0.004]
radius = 0.0005
material = "bead"

[run]
dt = 1.0e-4
steps = 14
output_interval = 1
particle_output = true
)";
  const auto dir = test::fresh_out_dir("deform");
  const auto sum = run_text(text, dir);
  const auto t = test::read_csv_columns(dir / "timeseries.csv");
  REQUIRE(t.at("step").size() == 15);
  const double c = lo + 0.5 * L0;
  const double scale[3] = {0.5, 1.5, 1.0};
  const char* cols[3] = {"box_lx", "box_ly", "box_lz"};
  for (int k = 0; k <= 14; ++k) {
    const double f = std::min(k, 10) / 10.0;
    for (int d = 0; d < 3; ++d) CHECK(t.at(cols[d])[k] == Approx(L0 * (1.0 + (scale[d] - 1.0) * f)).epsilon(1e-9));
  }
  REQUIRE(sum.box_edge.size() == 3);
  CHECK(sum.box_edge[0] == Approx(0.5 * L0));
  CHECK(sum.box_edge[1] == Approx(1.5 * L0));
  CHECK(sum.box_edge[2] == Approx(L0));
  // particles.csv: step, time, id, x, y, z, ...; x' = c + (L(k)/L0) (x0 - c) per axis
  const double x0[3][3] = {{-0.003, 0.0, 0.0}, {0.010, 0.0151, 0.012}, {0.004, 0.006, 0.004}};
  const auto rows = csv_rows(dir / "particles.csv");
  REQUIRE(rows.size() == 15 * 3);
  for (const auto& r : rows) {
    const int k = static_cast<int>(r[0]), id = static_cast<int>(r[2]);
    const double f = std::min(k, 10) / 10.0;
    for (int d = 0; d < 3; ++d) {
      const double ratio = 1.0 + (scale[d] - 1.0) * f;
      CHECK(r[3 + d] == Approx(c + ratio * (x0[id][d] - c)).margin(1e-12));
    }
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("a particle crossing a periodic face moves on as in an unbounded domain", "[driver][periodic]") {
  // One sphere at 1 m/s along x through a 10 mm periodic box: 6 crossings in 60 mm; the skin
  // (0.1 mm) forces a rebuild (and a wrap) every 50 steps. x(t) mod L must follow x0 + v t.
  const std::string text = kBead + R"(
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.01, 0.01, 0.01]
periodic = [true, true, true]

[[particles.list]]
position = [0.009, 0.005, 0.005]
radius = 0.001
material = "bead"
velocity = [1.0, 0.0, 0.0]

[[particles.list]]
position = [0.004, 0.002, 0.002]
radius = 0.001
material = "bead"

[run]
dt = 1.0e-6
steps = 6000
skin = 1.0e-4
output_interval = 100
particle_output = true
)";
  const auto dir = test::fresh_out_dir("crossing");
  const auto sum = run_text(text, dir);
  CHECK(sum.rebuilds >= 100);
  const auto rows = csv_rows(dir / "particles.csv");
  int checked = 0;
  for (const auto& r : rows) {
    if (static_cast<int>(r[2]) != 0) continue;
    const double t = r[1];
    const double expect = std::fmod(0.009 + 1.0 * t, 0.01);
    double x = r[3];
    // wrapped only at rebuilds: within skin/2 outside the box
    CHECK(x >= -0.5e-4 - 1e-9);
    CHECK(x < 0.01 + 0.5e-4 + 1e-9);
    CHECK(image(x - expect, 0.01) == Approx(0.0).margin(1e-9));
    ++checked;
  }
  CHECK(checked == 61);
  std::filesystem::remove_all(dir);
}

TEST_CASE("fcc lattice: count, positions, no overlaps, deterministic for a seed", "[driver][scene][lattice]") {
  auto scene = [](const std::string& extra) {
    return kBead + R"(
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.0113137084989848, 0.0084852813742386, 0.0084852813742386]
periodic = [true, true, true]

[particles.lattice]
type = "fcc"
a = 2.8284271247461903e-3
cells = [4, 3, 3]
radius_min = 0.94e-3
radius_max = 0.99e-3
material = "bead"
)" + extra +
           R"(
[run]
dt = 1.0e-6
steps = 1
)";
  };
  const double a = 2.8284271247461903e-3;
  const Scene s = parse_scene_string(scene("seed = 7\n"));
  REQUIRE(s.particles.size() == 4u * 4 * 3 * 3);
  // LAMMPS create_atoms order: cells z, y, x, then the basis
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::size_t k = 0;
  for (int cz = 0; cz < 3; ++cz)
    for (int cy = 0; cy < 3; ++cy)
      for (int cx = 0; cx < 4; ++cx)
        for (int b = 0; b < 4; ++b, ++k) {
          const double cell[3] = {double(cx), double(cy), double(cz)};
          for (int d = 0; d < 3; ++d)
            CHECK(s.particles[k].position[d] == Approx(a * (cell[d] + basis[b][d])).margin(1e-15));
          CHECK(s.particles[k].radius >= 0.94e-3);
          CHECK(s.particles[k].radius <= 0.99e-3);
        }
  // no overlaps, images included: nearest neighbours at 2R = a / sqrt(2) > R_i + R_j
  const double L[3] = {4 * a, 3 * a, 3 * a};
  double min_gap = 1.0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    for (std::size_t j = i + 1; j < s.particles.size(); ++j) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double sd = image(s.particles[i].position[d] - s.particles[j].position[d], L[d]);
        d2 += sd * sd;
      }
      min_gap = std::min(min_gap, std::sqrt(d2) - s.particles[i].radius - s.particles[j].radius);
    }
  CHECK(min_gap > 0.0);
  // same seed: same radii; another seed: other radii
  const Scene s2 = parse_scene_string(scene("seed = 7\n"));
  const Scene s3 = parse_scene_string(scene("seed = 8\n"));
  bool same = true, differ = false;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    same = same && s.particles[i].radius == s2.particles[i].radius;
    differ = differ || s.particles[i].radius != s3.particles[i].radius;
  }
  CHECK(same);
  CHECK(differ);
  // jitter: within +-jitter of the lattice site (wrapped into the box)
  const Scene sj = parse_scene_string(scene("seed = 7\njitter = 5.0e-6\n"));
  double max_dev = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      CHECK(sj.particles[i].position[d] >= 0.0);
      CHECK(sj.particles[i].position[d] < L[d]);
      max_dev = std::max(max_dev, std::fabs(image(sj.particles[i].position[d] - s.particles[i].position[d], L[d])));
    }
  CHECK(max_dev <= 5.0e-6);
  CHECK(max_dev > 1.0e-6);
}

TEST_CASE("bad [box], [box.deform] and [particles.lattice] values are rejected",
          "[driver][scene][validation][periodic]") {
  struct Case {
    std::string box, lattice, walls, expect;
  };
  const std::string box_ok = "[box]\nlo = [0.0, 0.0, 0.0]\nhi = [0.02, 0.02, 0.02]\nperiodic = [true, true, false]\n";
  const std::string lat_ok =
      "[particles.lattice]\na = 0.003\ncells = [6, 6, 2]\nradius_min = 0.001\nmaterial = \"bead\"\n";
  const std::vector<Case> cases = {
      {"[box]\nlo = [0.0, 0.0, 0.0]\nhi = [0.004, 0.02, 0.02]\nperiodic = [true, false, false]\n",
       "[[particles.list]]\nposition = [0.002, 0.01, 0.01]\nradius = 0.001\nmaterial = \"bead\"\n", "",
       "the periodic edge along x"},
      {box_ok, lat_ok, "[[walls]]\npoint = [0, 0, 0]\nnormal = [1, 0, 1]\nmaterial = \"bead\"\n", "walls[0].normal"},
      {box_ok + "[box.deform]\nscale = [0.9, 0.9, 0.9]\nsteps = 10\n", lat_ok, "", "box.deform.scale[2] = 0.9"},
      {box_ok + "[box.deform]\nscale = [-0.9, 1.0, 1.0]\nsteps = 10\n", lat_ok, "", "box.deform.scale[0] = -0.9"},
      {box_ok + "[box.deform]\nscale = [0.9, 1.0, 1.0]\nsteps = 0\n", lat_ok, "", "box.deform.steps = 0"},
      {box_ok + "[box.deform]\nscale = [0.2, 1.0, 1.0]\nsteps = 10\n", lat_ok, "", "periodic edge along x"},
      {box_ok + "[box.deform]\nscale = [0.9, 1.0, 1.0]\nsteps = 10\nrate = 2\n", lat_ok, "",
       "unknown key 'rate' in [box.deform]"},
      {box_ok + "size = 3\n", lat_ok, "", "unknown key 'size' in [box]"},
      {"[box]\nlo = [0.0, 0.0, 0.0]\nhi = [0.02, 0.0, 0.02]\n", lat_ok, "", "box.hi[1] = 0"},
      {"[box]\nlo = [0.0, 0.0, 0.0]\nhi = [0.02, 0.02, 0.02]\nperiodic = [true, 1, false]\n", lat_ok, "",
       "box.periodic[1]"},
      {box_ok, lat_ok + "type = \"bcc\"\n", "", "particles.lattice.type = \"bcc\""},
      {box_ok, "[particles.lattice]\na = 0.003\ncells = [6, 0, 2]\nradius_min = 0.001\nmaterial = \"bead\"\n", "",
       "particles.lattice.cells[1] = 0"},
      {box_ok, lat_ok + "jitter = -1e-6\n", "", "particles.lattice.jitter"},
      {box_ok, lat_ok + "spacing = 1\n", "", "unknown key 'spacing' in [particles.lattice]"},
      {box_ok, "[particles.lattice]\na = 0.002\ncells = [6, 6, 2]\nradius_min = 0.001\nmaterial = \"bead\"\n", "",
       "overlap"},
  };
  for (const auto& c : cases) {
    const std::string text =
        kBead + c.box + "\n[particles]\n" + c.lattice + "\n" + c.walls + "\n[run]\ndt = 1e-6\nsteps = 1\n";
    INFO(text);
    try {
      parse_scene_string(text);
      FAIL("accepted: expected an error containing '" << c.expect << "'");
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      INFO(msg);
      CHECK(msg.find(c.expect) != std::string::npos);
    }
  }
  // the base of the cases is valid
  CHECK_NOTHROW(parse_scene_string(kBead + box_ok + "\n[particles]\n" + lat_ok + "\n[run]\ndt = 1e-6\nsteps = 1\n"));
}

TEST_CASE("summary holds the phase times of --phase-times and particle_steps_per_second", "[driver][summary]") {
  const std::string text = kBead + R"(
[[particles.list]]
position = [0.0, 0.0, 0.0]
radius = 0.001
material = "bead"

[[particles.list]]
position = [0.0025, 0.0, 0.0]
radius = 0.001
material = "bead"
velocity = [-0.1, 0.0, 0.0]

[run]
dt = 1.0e-6
steps = 50
)";
  const auto d1 = test::fresh_out_dir("phases");
  const auto with = run_text(text, d1, true);
  REQUIRE(with.phases.size() == 6);
  const char* names[] = {"detection", "remap", "force", "growth", "integration", "output"};
  for (int k = 0; k < 6; ++k) {
    CHECK(with.phases[k].first == names[k]);
    CHECK(with.phases[k].second >= 0.0);
  }
  CHECK(with.particle_steps_per_second > 0.0);
  std::ifstream js(d1 / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(js)), std::istreambuf_iterator<char>());
  CHECK(json.find("\"phases\"") != std::string::npos);
  CHECK(json.find("\"particle_steps_per_second\"") != std::string::npos);
  const auto d2 = test::fresh_out_dir("nophases");
  const auto without = run_text(text, d2, false);
  CHECK(without.phases.empty());
  std::ifstream js2(d2 / "summary.json");
  const std::string json2((std::istreambuf_iterator<char>(js2)), std::istreambuf_iterator<char>());
  CHECK(json2.find("\"phases\"") == std::string::npos);
  CHECK(json2.find("box_edge") == std::string::npos);  // no [box]
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
}

namespace {
// particles.csv rows of two runs agree (same ids in the same order, values to `rel`).
void check_same_particles(const std::filesystem::path& a, const std::filesystem::path& b, double rel) {
  const auto ra = csv_rows(a / "particles.csv");
  const auto rb = csv_rows(b / "particles.csv");
  REQUIRE(ra.size() == rb.size());
  REQUIRE(!ra.empty());
  for (std::size_t k = 0; k < ra.size(); ++k) {
    REQUIRE(ra[k][2] == rb[k][2]);  // id
    for (int c = 3; c < 9; ++c) CHECK(ra[k][c] == Approx(rb[k][c]).epsilon(rel).margin(1e-12));
  }
}

// The fcc lattice of the compressed scenes below (a = 2.8284271247461903e-3 m, radii 0.94-0.99
// mm, jitter 5 um) with `cells`, from the box's corner at the origin.
std::string fcc_lattice(const std::string& cells) {
  return R"(
[particles.lattice]
type = "fcc"
origin = [0.0, 0.0, 0.0]
a = 2.8284271247461903e-3
cells = )" +
         cells +
         R"(
radius_min = 0.94e-3
radius_max = 0.99e-3
jitter = 5.0e-6
material = "bead"
seed = 4711
)";
}

// Compression scenes: `geometry` (their [box], [box.deform] and walls), the lattice of `cells`
// and 400 steps sampled every 50 with the given skin.
std::string compression_scene(const std::string& geometry, const std::string& cells, const std::string& skin) {
  return kBead + geometry + fcc_lattice(cells) + R"(
[run]
dt = 2.0e-6
steps = 400
output_interval = 50
particle_output = true
skin = )" +
         skin + "\n";
}

// Two runs of one scene compressed to 0.85 of the edge 6a (a = 2.8284271247461903e-3 m) along
// x and y (and z where `axes` is 3, else z is bounded by walls) in 300 steps, sampled every 50
// of 400 steps: the same pair and wall contacts at every sample, kinetic energy and the `walls`'
// forces to round-off (other lists: the sums run in another order), positions (minimum image
// on the periodic axes: the two runs wrap at other steps) and velocities to 1e-9.
void check_same_compression(const std::filesystem::path& d1, const std::filesystem::path& d2, std::size_t spheres,
                            int axes, const std::vector<std::string>& walls) {
  const auto t1 = test::read_csv_columns(d1 / "timeseries.csv");
  const auto t2 = test::read_csv_columns(d2 / "timeseries.csv");
  REQUIRE(t1.at("step").size() == 9);
  REQUIRE(t2.at("step").size() == 9);
  for (std::size_t k = 0; k < 9; ++k) {
    CHECK(t1.at("pair_contacts")[k] == t2.at("pair_contacts")[k]);
    CHECK(t1.at("wall_contacts")[k] == t2.at("wall_contacts")[k]);
    CHECK(t1.at("ke_translational")[k] == Approx(t2.at("ke_translational")[k]).epsilon(1e-6).margin(1e-15));
    for (const auto& w : walls)
      CHECK(t1.at("force_" + w)[k] == Approx(t2.at("force_" + w)[k]).epsilon(1e-6).margin(1e-12));
  }
  const auto ra = csv_rows(d1 / "particles.csv");
  const auto rb = csv_rows(d2 / "particles.csv");
  REQUIRE(ra.size() == rb.size());
  REQUIRE(ra.size() == 9u * spheres);
  int differ = 0;
  double worst = 0.0;
  for (std::size_t k = 0; k < ra.size(); ++k) {
    REQUIRE(ra[k][2] == rb[k][2]);  // id
    const double L = 0.016970562748477142 * (1.0 - 0.15 * std::min(ra[k][0], 300.0) / 300.0);
    for (int c = 3; c < 9; ++c) {
      double d = ra[k][c] - rb[k][c];
      if (c < 3 + axes) d -= L * std::round(d / L);
      const double scale = c < 6 ? L : std::max(std::fabs(ra[k][c]), 1e-9);
      worst = std::max(worst, std::fabs(d) / scale);
      differ += std::fabs(d) > 1e-9 * scale;
    }
  }
  CAPTURE(worst);
  CHECK(differ == 0);
}
}  // namespace

// The rebuild rule in a compressing box counts only the motion beyond the deformation
// (ContactDetector::shift_allowance): the same run as with lists rebuilt at every step (a skin
// of 1e-8 m, which the compression uses up at once: every step rebuilds), with fewer rebuilds
// than one per skin/2 of affine drift (150 with the plain rule, measured 2026-12-05). The skin,
// 2e-5 m, is below the lattice's initial gaps (up to 1.2e-4 m): the contacts that form need
// rebuilds, so a rule that rebuilt too late would miss some (an allowance without the
// compression's term, l skin / 2, rebuilt 5 times and had 10 contacts at step 50 instead of 931).
TEST_CASE("box deformation: the lists last until the compression uses up the skin", "[driver][periodic][deform]") {
  auto scene = [](const std::string& skin) {
    return compression_scene(R"(
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.016970562748477142, 0.016970562748477142, 0.016970562748477142]
periodic = [true, true, true]

[box.deform]
scale = [0.85, 0.85, 0.85]
steps = 300
)",
                             "[6, 6, 6]", skin);
  };
  const auto d1 = test::fresh_out_dir("deform_rule");
  const auto d2 = test::fresh_out_dir("deform_every_step");
  const auto s1 = run_text(scene("2.0e-5"), d1);
  const auto s2 = run_text(scene("1.0e-8"), d2);
  // 15% compression, the skin's 2e-5 / (2e-5 + 2 R_max) = 1% used up by each 1% (22 measured)
  CHECK(s1.rebuilds >= 15);
  CHECK(s1.rebuilds <= 40);
  CHECK(s2.rebuilds == 400);
  CHECK(s1.contacts_mean > 1000.0);            // compressed into contact
  check_same_compression(d1, d2, 864, 3, {});  // 6^3 fcc cells of 4 spheres
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
}

// The same rule with walls: the box deforms only its periodic axes and walls bound only the
// others (both validated), so the deformation moves no particle towards a wall. A layer periodic
// in x and y between a floor and a lid, compressed by 15% in x and y: the spheres are squeezed
// against the walls, and the run with the rule (skin 2e-5 m) must match the run that rebuilds at
// every step (skin 1e-8 m) in its pair and wall contacts, energies, wall forces, positions and
// velocities. Until 2026-12-05 scenes with walls kept the plain rule, which rebuilds once per
// skin/2 of affine drift: 152 times here (measured), against 44 with this rule (2 threads); the
// bounds below take the one and refuse the other.
TEST_CASE("box deformation with walls: the lists last until the compression uses up the skin",
          "[driver][periodic][deform][walls]") {
  auto scene = [](const std::string& skin) {
    return compression_scene(R"(
[box]
lo = [0.0, 0.0, -0.0015]
hi = [0.016970562748477142, 0.016970562748477142, 0.0095]
periodic = [true, true, false]

[box.deform]
scale = [0.85, 0.85, 1.0]
steps = 300

[[walls]]
name = "floor"
point = [0.0, 0.0, -1.05e-3]
normal = [0.0, 0.0, 1.0]
material = "bead"

[[walls]]
name = "lid"
point = [0.0, 0.0, 8.121e-3]
normal = [0.0, 0.0, -1.0]
material = "bead"
)",
                             "[6, 6, 3]", skin);
  };
  const auto d1 = test::fresh_out_dir("deform_walls_rule");
  const auto d2 = test::fresh_out_dir("deform_walls_every_step");
  const auto s1 = run_text(scene("2.0e-5"), d1);
  const auto s2 = run_text(scene("1.0e-8"), d2);
  CAPTURE(s1.rebuilds);
  CHECK(s1.rebuilds >= 25);
  CHECK(s1.rebuilds <= 70);
  CHECK(s2.rebuilds == 400);
  const auto t1 = test::read_csv_columns(d1 / "timeseries.csv");
  REQUIRE(!t1.at("wall_contacts").empty());
  CHECK(t1.at("wall_contacts").back() > 50.0);               // squeezed against the walls
  check_same_compression(d1, d2, 432, 2, {"floor", "lid"});  // 6 x 6 x 3 fcc cells of 4 spheres
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
}

TEST_CASE("spatial sort at rebuilds: the same run, outputs in global-id order", "[driver][sort]") {
  SECTION("hertz_mindlin, walls, a driven sphere with a motion") {
    auto scene = [](bool sort) {
      return kBead + R"(
[materials.steel]
rigid = true

[particles.fill]
box_min = [0.0, 0.0, 0.0]
box_max = [0.012, 0.012, 0.024]
count = 500
radius_min = 0.0005
radius_max = 0.0006
material = "bead"
seed = 3
velocity = [0.3, 0.0, -1.0]   # into the floor and a side wall: frictional contacts at once

[[particles.list]]
position = [0.006, 0.006, 0.026]
radius = 0.001
material = "bead"
driven = true
motion = [{duration = 0.004, velocity = [0.0, 0.0, -2.0]}]

[[walls]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "steel"

[[walls]]
point = [0.0, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]
material = "steel"

[[walls]]
point = [0.012, 0.0, 0.0]
normal = [-1.0, 0.0, 0.0]
material = "steel"

[run]
dt = 5.0e-6
steps = 600
output_interval = 200
particle_output = true
spatial_sort = )" +
             std::string(sort ? "true" : "false") + "\n";
    };
    const auto d1 = test::fresh_out_dir("sorted");
    const auto d2 = test::fresh_out_dir("unsorted");
    const std::string g = "gravity = [0.0, 0.0, -9.81]\n";
    const auto s1 = run_text(g + scene(true), d1);
    const auto s2 = run_text(g + scene(false), d2);
    CHECK(s1.rebuilds == s2.rebuilds);
    CHECK(s1.rebuilds > 2);
    check_same_particles(d1, d2, 1e-6);
    // the driven sphere (listed first: id 0) follows its motion exactly: its index moved with it
    for (const auto& r : csv_rows(d1 / "particles.csv"))
      if (r[2] == 0.0) CHECK(r[5] == Approx(0.026 - 2.0 * r[1]).margin(1e-12));
    std::filesystem::remove_all(d1);
    std::filesystem::remove_all(d2);
  }
  SECTION("mdr with radius growth (the model's per-particle state follows the sort)") {
    auto scene = [](bool sort) {
      return R"(
[materials.powder]
youngs_modulus = 1.0e7
poisson_ratio = 0.3
density = 1000.0
restitution = 0.5
friction = 0.3
yield_stress = 2.0e5

[materials.steel]
rigid = true

[model]
name = "mdr"

[particles.fill]
box_min = [0.0, 0.0, 0.0]
box_max = [0.008, 0.008, 0.012]
count = 300
radius_min = 0.0005
material = "powder"
seed = 7

[[walls]]
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "steel"

[[walls]]
name = "piston"
point = [0.0, 0.0, 0.012]
normal = [0.0, 0.0, -1.0]
material = "steel"
velocity = [0.0, 0.0, -2.0]

[run]
dt = 5.0e-6
steps = 700
output_interval = 350
skin = 0.00015
particle_output = true
spatial_sort = )" +
             std::string(sort ? "true" : "false") + "\n";
    };
    const auto d1 = test::fresh_out_dir("mdr_sorted");
    const auto d2 = test::fresh_out_dir("mdr_unsorted");
    const auto s1 = run_text(scene(true), d1);
    const auto s2 = run_text(scene(false), d2);
    CHECK(s1.rebuilds > 2);
    CHECK(test::counter_of(s1, "mdr_max_radius_ratio") > 1.0);  // the radii did grow
    CHECK(test::counter_of(s1, "mdr_max_radius_ratio") ==
          Approx(test::counter_of(s2, "mdr_max_radius_ratio")).epsilon(1e-6));
    check_same_particles(d1, d2, 1e-6);
    std::filesystem::remove_all(d1);
    std::filesystem::remove_all(d2);
  }
}

// [run] spatial_sort = "auto" (the default): which detections reorder the particles. A lattice
// in uniform motion through a periodic box has no contacts and rebuilds at fixed steps: v dt =
// skin / 9, so the shift passes skin / 2 after every 5th step and the rebuilds are at 5, 10, ...
TEST_CASE("spatial sort: the auto rule sorts large scenes at setup and every sort_interval steps", "[driver][sort]") {
  auto scene = [](int cz, const std::string& sort) {
    const double a = 2.8284271247461903e-3;
    char box[256];
    std::snprintf(box, sizeof box,
                  "[box]\nlo = [0.0, 0.0, 0.0]\nhi = [%.17g, %.17g, %.17g]\nperiodic = [true, true, true]\n", 10 * a,
                  10 * a, cz * a);
    return kBead + box + R"(
[particles.lattice]
a = 2.8284271247461903e-3
cells = [10, 10, )" +
           std::to_string(cz) +
           R"(]
radius_min = 0.9e-3
material = "bead"
velocity = [1.0, 0.0, 0.0]

[run]
dt = 1.0e-6
steps = 60
skin = 9.0e-6
output_interval = 60
)" + sort + "\n";
  };
  auto run = [](const std::string& text) {
    const auto dir = test::fresh_out_dir("sort_rule");
    const auto sum = run_text(text, dir);
    std::filesystem::remove_all(dir);
    return sum;
  };
  // 4400 particles (>= kAutoSortMinParticles): setup, then the first rebuild 20 steps after the last sort
  auto s = run(scene(11, "sort_interval = 20"));
  CHECK(s.particles == 4400);
  CHECK(s.particles >= driver::kAutoSortMinParticles);
  CHECK(s.rebuilds == 12);
  CHECK(s.sorts == 4);  // steps 0, 20, 40, 60
  s = run(scene(11, "sort_interval = 25"));
  CHECK(s.sorts == 3);  // steps 0, 25 (the rebuild at 25), 50
  s = run(scene(11, ""));
  CHECK(s.sorts == 1);  // the default interval (1000 steps): setup only
  s = run(scene(11, "spatial_sort = true"));
  CHECK(s.sorts == s.rebuilds + 1);  // every detection
  s = run(scene(11, "spatial_sort = false"));
  CHECK(s.sorts == 0);
  // 4000 particles (< kAutoSortMinParticles): auto never sorts; true still does
  s = run(scene(10, "sort_interval = 1"));
  CHECK(s.particles < driver::kAutoSortMinParticles);
  CHECK(s.rebuilds == 12);
  CHECK(s.sorts == 0);
  s = run(scene(10, "spatial_sort = true"));
  CHECK(s.sorts == 13);
}

// A shuffled scene ([particles] order = "shuffled") compressed in a periodic box: the auto sort
// (at setup and at rebuilds) changes the memory order only, so every particle ends where the
// unsorted run puts it (round-off apart: the per-particle sums run in another order).
TEST_CASE("spatial sort: a shuffled scene sorted by the auto rule runs as unsorted", "[driver][sort]") {
  auto scene = [](const std::string& sort) {
    return kBead + R"(
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.028284271247461903, 0.028284271247461903, 0.031112698372208092]
periodic = [true, true, true]

[box.deform]
scale = [0.9, 0.9, 0.9]
steps = 200

[particles]
order = "shuffled"
)" + fcc_lattice("[10, 10, 11]") +
           R"(
[run]
dt = 2.0e-6
steps = 200
output_interval = 100
skin = 2.0e-4
particle_output = true
sort_interval = 50
)" + sort + "\n";
  };
  const auto d1 = test::fresh_out_dir("shuffled_auto");
  const auto d2 = test::fresh_out_dir("shuffled_unsorted");
  const auto s1 = run_text(scene(""), d1);
  const auto s2 = run_text(scene("spatial_sort = false"), d2);
  CHECK(s1.sorts >= 2);  // setup and at least one rebuild
  CHECK(s2.sorts == 0);
  CHECK(s1.rebuilds == s2.rebuilds);
  CHECK(s1.contacts_mean > 1000.0);  // compressed into contact
  CHECK(s1.contacts_mean == Approx(s2.contacts_mean).margin(1.0));
  check_same_particles(d1, d2, 1e-6);
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
}

TEST_CASE("[particles] order = \"shuffled\": a seeded permutation of the scene's particles", "[driver][scene][sort]") {
  auto scene = [](const std::string& particles, const std::string& run) {
    return kBead + R"(
[particles]
)" + particles +
           R"(
[particles.lattice]
a = 0.003
cells = [4, 3, 3]
radius_min = 0.0009
radius_max = 0.001
material = "bead"
seed = 3

[run]
dt = 1e-6
steps = 1
)" + run;
  };
  const Scene built = parse_scene_string(scene("", ""));
  const Scene a = parse_scene_string(scene("order = \"shuffled\"\norder_seed = 5\n", ""));
  const Scene again = parse_scene_string(scene("order = \"shuffled\"\norder_seed = 5\n", ""));
  const Scene other = parse_scene_string(scene("order = \"shuffled\"\norder_seed = 6\n", ""));
  REQUIRE(a.particles.size() == built.particles.size());
  auto key = [](const ParticleSpec& p) {
    return std::make_tuple(p.position[0], p.position[1], p.position[2], p.radius);
  };
  std::multiset<std::tuple<double, double, double, double>> ka, kb;
  std::size_t moved = 0, same_again = 0, same_other = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    ka.insert(key(a.particles[i]));
    kb.insert(key(built.particles[i]));
    moved += key(a.particles[i]) != key(built.particles[i]);
    same_again += key(a.particles[i]) == key(again.particles[i]);
    same_other += key(a.particles[i]) == key(other.particles[i]);
  }
  CHECK(ka == kb);                                            // the same particles,
  CHECK(moved > a.particles.size() * 9 / 10);                 // in another order,
  CHECK(same_again == a.particles.size());                    // the same for a seed,
  CHECK(same_other < a.particles.size() / 10);                // another for another seed
  CHECK(built.run.spatial_sort == RunSpec::Sort::automatic);  // the default
  CHECK(built.run.sort_interval == 1000);
  CHECK(parse_scene_string(scene("", "spatial_sort = true\n")).run.spatial_sort == RunSpec::Sort::always);
  CHECK(parse_scene_string(scene("", "spatial_sort = false\n")).run.spatial_sort == RunSpec::Sort::never);
  CHECK(parse_scene_string(scene("", "spatial_sort = \"auto\"\nsort_interval = 7\n")).run.sort_interval == 7);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {scene("order = \"random\"\n", ""), "particles.order = \"random\""},
      {scene("order_seed = -1\n", ""), "particles.order_seed"},
      {scene("", "spatial_sort = \"sometimes\"\n"), "run.spatial_sort must be \"auto\", true"},
      {scene("", "spatial_sort = 1\n"), "run.spatial_sort must be"},
      {scene("", "sort_interval = 0\n"), "run.sort_interval = 0"},
  };
  for (const auto& [text, expect] : bad) {
    INFO(text);
    try {
      parse_scene_string(text);
      FAIL("accepted: expected an error containing '" << expect << "'");
    } catch (const SceneError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(expect) != std::string::npos);
    }
  }
}
