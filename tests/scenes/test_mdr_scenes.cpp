// The MDR validation scenes of drivers/scenes/ (docs/driver.md) run through the driver, and what
// their CSV outputs must show:
//  - two flats, E/Y = 6.25 ... 200: peak force at delta_o/R_o = 0.5 and residual displacement as
//    the side law gives them (numbers of the MDR kernel's own integration, growth on), both flats
//    see the same force, and halving the speed changes neither (quasi-static);
//  - adhesion: the elastic pull-off is JKR's, plastic loading raises it, contacts separate;
//  - die compaction: the four fixed flats see a force only once R has grown, and it persists;
//  - pairs: equal sides, equal and opposite forces, and in the elastic range the pair at d per
//    sphere equals one sphere against a flat at d;
//  - the 10^4-sphere compaction packing runs (reduced steps) without NaN.
#include <catch2/catch.hpp>

#include "driver_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace epac;
using namespace epac::driver;
using namespace epac::test;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 1e-3, kE = 1e8;  // R_o and E of every single-sphere scene

std::string scene_path(const std::string& stem) { return std::string(EPAC_SCENES_DIR) + "/" + stem + ".toml"; }

// A CSV with string columns kept as strings (contacts.csv has wall_name).
struct Table {
  std::map<std::string, std::vector<std::string>> cols;
  std::size_t rows = 0;
  std::vector<double> num(const std::string& c) const {
    std::vector<double> out;
    for (const auto& s : cols.at(c)) out.push_back(std::stod(s));
    return out;
  }
};
Table read_table(const fs::path& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream hs(line);
  std::string c;
  while (std::getline(hs, c, ',')) names.push_back(driver::csv_column_name(c));  // without the unit
  Table t;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    for (const auto& n : names) {
      std::getline(s, c, ',');
      t.cols[n].push_back(c);
    }
    ++t.rows;
  }
  return t;
}
// Rows of contacts.csv for one wall (by name) or for pairs (wall name empty).
Table rows_of(const Table& t, const std::string& wall) {
  Table out;
  for (std::size_t k = 0; k < t.rows; ++k) {
    if (t.cols.at("wall_name")[k] != wall) continue;
    for (const auto& kv : t.cols) out.cols[kv.first].push_back(kv.second[k]);
    ++out.rows;
  }
  return out;
}

RunSummary run_scene(const Scene& s, const fs::path& dir, std::int64_t steps = -1) {
  RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.steps = steps;
  return run(s, o);
}

// The same scene with every motion (walls and driven particles) at half the speed: durations x 2,
// velocities / 2, steps x 2, output interval x 2 (so samples fall at the same displacements).
Scene half_speed(Scene s) {
  for (auto& w : s.walls)
    for (auto& g : w.segments) {
      g.duration *= 2;
      for (double& v : g.velocity) v *= 0.5;
    }
  for (auto& p : s.particles)
    for (auto& g : p.motion) {
      g.duration *= 2;
      for (double& v : g.velocity) v *= 0.5;
    }
  s.run.steps *= 2;
  s.run.output_interval *= 2;
  return s;
}

struct TwoFlatResult {
  double peak_force = 0;      // F/(E R_o^2) at the largest displacement
  double peak_disp = 0;       // delta_o/R_o there
  double residual = 0;        // delta_o/R_o of the last sample with a force, after the peak
  double max_top_bottom = 0;  // max |F_top - F_bottom| / max F
};
TwoFlatResult two_flat_result(const fs::path& dir) {
  const auto c = read_csv_columns(dir / "timeseries.csv");
  const auto& f = c.at("force_top");
  const auto& fb = c.at("force_bottom");
  const auto& d = c.at("displacement_top");
  TwoFlatResult r;
  const std::size_t k = static_cast<std::size_t>(std::max_element(d.begin(), d.end()) - d.begin());
  r.peak_force = f[k] / (kE * kR * kR);
  r.peak_disp = d[k] / kR;
  for (std::size_t i = k; i < f.size(); ++i)
    if (f[i] != 0.0) r.residual = d[i] / kR;
  const double fmax = *std::max_element(f.begin(), f.end());
  for (std::size_t i = 0; i < f.size(); ++i)
    r.max_top_bottom = std::max(r.max_top_bottom, std::fabs(f[i] - fb[i]) / fmax);
  return r;
}

}  // namespace

TEST_CASE("MDR two-flat scenes: peak force and residual displacement per E/Y, quasi-static", "[scenes][mdr]") {
  // Reference: the MDR side law integrated on its own (kernel, growth on): F/(E R_o^2) at
  // delta_o/R_o = 0.5 and the residual delta_o/R_o after unloading. The scene moves each flat by
  // 2.5e-4 R_o per step and samples every step, so the residual (last sample with a force) is
  // resolved to one increment: tolerance 2 increments = 5e-4 R_o. Peak force: 1e-3 relative (the
  // reference's own increment differs from the scene's).
  const double ey[] = {6.25, 12.5, 25, 50, 100, 200};
  const double peak_ref[] = {0.4643, 0.2887, 0.1578, 0.08172, 0.04136, 0.02077};
  const double residual_ref[] = {0.3978, 0.4580, 0.4818, 0.4917, 0.4960, 0.4981};
  for (int k = 0; k < 6; ++k) {
    char stem[64];
    std::snprintf(stem, sizeof stem, "mdr_two_flats_EY%g", ey[k]);
    INFO(stem);
    const Scene s = parse_scene_file(scene_path(stem));
    CHECK(s.model.effects == (kPlasticity | kRadiusGrowth));
    const fs::path dir = fresh_out_dir(stem);
    const RunSummary sum = run_scene(s, dir);
    const TwoFlatResult r = two_flat_result(dir);
    CHECK(r.peak_disp == Approx(0.5).epsilon(1e-9));
    CHECK(r.peak_force == Approx(peak_ref[k]).epsilon(1e-3));
    CHECK(r.residual == Approx(residual_ref[k]).margin(5e-4));
    CHECK(r.max_top_bottom < 1e-12);  // symmetric loading
    CHECK(counter_of(sum, "mdr_guard_denominator") == 0);
    CHECK(counter_of(sum, "mdr_guard_radius_cap") == 0);
    CHECK(counter_of(sum, "mdr_guard_volume") == 0);
    const double ratio = counter_of(sum, "mdr_max_radius_ratio");
    CHECK(ratio > 1.1);  // plastic flow grew the apparent radius ...
    CHECK(ratio < 1.5);  // ... below the cap
    // the per-contact outputs: area and mean pressure of the top contact at the peak
    const Table top = rows_of(read_table(dir / "contacts.csv"), "top");
    REQUIRE(top.rows > 0);
    const auto area = top.num("area"), p = top.num("mean_pressure"), fm = top.num("mdr_force");
    const std::size_t kp = static_cast<std::size_t>(std::max_element(fm.begin(), fm.end()) - fm.begin());
    CHECK(p[kp] == Approx(fm[kp] / area[kp]).epsilon(1e-9));
    // pi a^2 of the MDR half-width equals (42) on plastic loading ((36)), and vanishes with the force
    const auto a_area = top.num("area_from_radius");
    CHECK(a_area[kp] == Approx(area[kp]).epsilon(1e-9));
    for (std::size_t i = kp; i < fm.size(); ++i)
      if (fm[i] == 0.0) CHECK(a_area[i] == 0.0);
    const double Y = kE / ey[k];
    // after yield the mean pressure follows the hardening curve p_Y(delta_max/R) of (16), (21)
    CHECK(p[kp] / Y > 1.0);
    CHECK(p[kp] / Y < 2.75);
    // V of (39) is positive and below V_o under compression
    const auto V = read_csv_columns(dir / "particles.csv").at("volume");
    CHECK(*std::min_element(V.begin(), V.end()) > 0.5 * 4.0 / 3.0 * kPi * kR * kR * kR);
    fs::remove_all(dir);

    if (ey[k] == 6.25 || ey[k] == 200) {  // quasi-static: half the speed, same curve
      const fs::path d2 = fresh_out_dir(std::string(stem) + "-half");
      run_scene(half_speed(s), d2);
      const TwoFlatResult h = two_flat_result(d2);
      CHECK(h.peak_force == Approx(r.peak_force).epsilon(1e-3));
      CHECK(h.residual == Approx(r.residual).margin(5e-4));
      fs::remove_all(d2);
    }
  }
}

TEST_CASE("MDR adhesive scenes: JKR pull-off in the elastic regime, larger after plastic loading", "[scenes][mdr]") {
  const double gamma = kE / (1 - 0.09) * kR / 2.2e4;  // E_eff R_o / Delta gamma = 2.2e4
  const double f_jkr = 1.5 * kPi * gamma * kR;        // JKR pull-off, sphere on a rigid flat
  double pull_off[3] = {0, 0, 0};
  const char* stems[] = {"mdr_adhesive_elastic", "mdr_adhesive_plastic_0.1", "mdr_adhesive_plastic_0.4"};
  for (int k = 0; k < 3; ++k) {
    INFO(stems[k]);
    const Scene s = parse_scene_file(scene_path(stems[k]));
    CHECK(s.materials[s.material_index.at("sphere")].surface_energy == Approx(gamma).epsilon(1e-12));
    const fs::path dir = fresh_out_dir(stems[k]);
    run_scene(s, dir);
    const auto c = read_csv_columns(dir / "timeseries.csv");
    const auto& f = c.at("force_top");
    pull_off[k] = -*std::min_element(f.begin(), f.end());
    CHECK(f.back() == 0.0);  // separated at the end
    const Table top = rows_of(read_table(dir / "contacts.csv"), "top");
    const auto y = top.num("yielded_sides");
    const double yielded = *std::max_element(y.begin(), y.end());
    CHECK(yielded == (k == 0 ? 0.0 : 1.0));
    // the adhesive radius is held while the contact is in tension
    const auto a = top.num("adhesive_radius");
    CHECK(*std::max_element(a.begin(), a.end()) > 0.0);
    fs::remove_all(dir);
  }
  // elastic: JKR's pull-off (displacement control passes the force minimum) within 1%
  CHECK(pull_off[0] == Approx(f_jkr).epsilon(0.01));
  // plastic flattening raises the pull-off force, more after deeper loading
  CHECK(pull_off[1] > 1.05 * f_jkr);
  CHECK(pull_off[2] > 1.05 * pull_off[1]);
}

TEST_CASE("MDR die compaction: secondary contacts only through radius growth", "[scenes][mdr]") {
  const Scene s = parse_scene_file(scene_path("mdr_die_compaction"));
  const fs::path dir = fresh_out_dir("die");
  const RunSummary sum = run_scene(s, dir);
  CHECK(counter_of(sum, "mdr_guard_denominator") == 0);
  CHECK(counter_of(sum, "mdr_guard_volume") == 0);
  const auto c = read_csv_columns(dir / "timeseries.csv");
  const auto p = read_csv_columns(dir / "particles.csv");
  const auto& R = p.at("R");
  REQUIRE(R.size() == c.at("step").size());
  int with_force = 0, grown = 0;
  for (std::size_t k = 0; k < R.size(); ++k) {
    if (k > 0) CHECK(R[k] >= R[k - 1]);  // R never decreases
    for (const char* w : {"force_xminus", "force_xplus", "force_yminus", "force_yplus"}) {
      const double f = c.at(w)[k];
      CHECK(f >= 0.0);
      if (R[k] == kR) CHECK(f == 0.0);  // no growth, no lateral force
      if (f > 0) ++with_force;
    }
    if (R[k] > kR) ++grown;
    // the four secondary forces are equal (symmetry)
    CHECK(c.at("force_xplus")[k] == Approx(c.at("force_xminus")[k]).epsilon(1e-9).margin(1e-12));
    CHECK(c.at("force_yplus")[k] == Approx(c.at("force_xminus")[k]).epsilon(1e-9).margin(1e-12));
  }
  CHECK(grown > 0);
  CHECK(with_force > 0);
  // the secondary force persists after unloading (radial expansion is irreversible)
  CHECK(c.at("force_xminus").back() > 0.0);
  CHECK(c.at("force_top").back() == 0.0);
  fs::remove_all(dir);
}

TEST_CASE("MDR pair scenes: equal sides, equal and opposite forces, elastic pair equals sphere on flat",
          "[scenes][mdr]") {
  for (const std::string stem : {"mdr_pair", "mdr_pair_adhesive"}) {
    INFO(stem);
    const fs::path dir = fresh_out_dir(stem);
    run_scene(parse_scene_file(scene_path(stem)), dir);
    const auto ts = read_csv_columns(dir / "timeseries.csv");
    const Table pairs = rows_of(read_table(dir / "contacts.csv"), "");
    REQUIRE(pairs.rows > 10);
    const auto f = pairs.num("force"), s0 = pairs.num("side0_force"), s1 = pairs.num("side1_force");
    const double fmax = *std::max_element(f.begin(), f.end());
    CHECK(fmax > 0.0);
    for (std::size_t k = 0; k < f.size(); ++k) CHECK(std::fabs(s0[k] - s1[k]) <= 1e-12 * fmax);
    // the total force on the two driven spheres: the pair forces cancel
    for (const char* c : {"driven_fx", "driven_fy", "driven_fz"})
      for (double v : ts.at(c)) CHECK(std::fabs(v) <= 1e-12 * fmax);
    if (stem == "mdr_pair_adhesive") {
      CHECK(*std::min_element(f.begin(), f.end()) < 0.0);  // adhesive tension before separation
      CHECK(ts.at("pair_contacts").back() == 0.0);
    } else {
      // before the first yield, the pair at d per sphere = one sphere against a flat at d (same
      // material E/Y = 50, same increments, the two-flat scene's force on one flat)
      const fs::path d2 = fresh_out_dir("flat50");
      run_scene(parse_scene_file(scene_path("mdr_two_flats_EY50")), d2);
      const auto flat = read_csv_columns(d2 / "timeseries.csv");
      const auto steps = pairs.num("step"), ys = pairs.num("yielded_sides");
      int compared = 0;
      for (std::size_t k = 0; k < steps.size() && ys[k] == 0.0; ++k) {
        const std::size_t s = static_cast<std::size_t>(steps[k]);  // the flat scene samples every step
        REQUIRE(flat.at("step")[s] == steps[k]);
        CHECK(f[k] == Approx(flat.at("force_top")[s]).epsilon(1e-9));
        ++compared;
      }
      CHECK(compared >= 5);
      fs::remove_all(d2);
    }
    fs::remove_all(dir);
  }
}

TEST_CASE("MDR compaction packing: 10^4 spheres run (reduced steps) without NaN", "[scenes][mdr]") {
  const Scene s = parse_scene_file(scene_path("mdr_compaction_packing"));
  CHECK(s.particles.size() == 10000);
  const fs::path dir = fresh_out_dir("packing");
  const RunSummary sum = run_scene(s, dir, 400);
  CHECK(sum.steps == 400);
  CHECK(sum.contact_steps_per_second > 0);
  const auto c = read_csv_columns(dir / "timeseries.csv");
  for (double v : c.at("max_overlap_ratio")) CHECK(std::isfinite(v));
  for (double v : c.at("ke_translational")) CHECK(std::isfinite(v));
  CHECK(c.at("wall_contacts").back() > 0);  // the piston and the walls touch the packing
  fs::remove_all(dir);
}
