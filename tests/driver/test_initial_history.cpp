// [run] initial_history and the growth-guard warning: a periodic fcc packing of MDR spheres with
// radius growth, compressed to overlaps up to 0.21 R, run 400 steps. From overlaps (the
// default) the run stays finite and compact; with fresh history ("zero") the growth guards act
// and the run says so (stderr and summary.json "warnings").
#include <catch2/catch.hpp>

#include "driver_test_util.hpp"

#include <epac/compute/history_from_overlaps.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

using namespace epac;
using namespace epac::test;

namespace {

// fcc cell a = sqrt(2) nn, nearest neighbours at nn = 1.81 mm (jitter 0.01 mm per coordinate),
// radii 0.98-1.0 mm, so every nearest-neighbour contact overlaps, the largest by 0.20 R. E/Y = 100.
// Measured (double, 2 threads, default pair split equal_pair): from overlaps R/R_o = 1.057, no
// guard hit, no rebuild; with fresh history ("zero": each overlap one plastic increment) R/R_o =
// 1.096, still without a guard hit. At nn = 1.8 mm (0.21 R) even the quasi-static load trips the
// denominator guard twice (R/R_o 1.096); at nn = 1.75 mm (0.26 R) fresh history trips it 184 times
// (R/R_o 1.28) and the warning names initial_history. (With the previous default split the
// quasi-static load grew the radii less, 1.061 at 0.21 R: a side's delta_o then took half of the
// neighbours' growth, so sides left plastic loading and skipped (37) increments.)
std::string packed_scene(const std::string& initial_history, double nn = 1.81e-3) {
  const double a = nn * std::sqrt(2.0), edge = 3 * a;
  std::ostringstream geometry;
  geometry.precision(17);
  geometry << "[box]\nlo = [0.0, 0.0, 0.0]\nhi = [" << edge << ", " << edge << ", " << edge
           << "]\nperiodic = [true, true, true]\n\n[particles]\nallow_overlap = true\n\n[particles.lattice]\n"
           << "type = \"fcc\"\na = " << a << "\n";
  return std::string(R"(
[materials.powder]
youngs_modulus = 1.0e7
poisson_ratio = 0.3
density = 1000.0
restitution = 0.5
yield_stress = 1.0e5

[model]
name = "mdr"

)") + geometry.str() +
         R"(cells = [3, 3, 3]
radius_min = 0.98e-3
radius_max = 1.0e-3
material = "powder"
seed = 3
jitter = 1.0e-5

[run]
dt = 5.0e-6
steps = 400
output_interval = 20
)" + initial_history;
}

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("driver: a packing at 0.2 R starts from a quasi-static load and stays compact", "[driver][initial_history]") {
  const auto dir = fresh_out_dir("initial-history");
  const driver::RunSummary s = run_scene_text(packed_scene(""), dir);  // default: from_overlaps
  CHECK(s.initial_history.mode == "from_overlaps");
  CHECK(s.initial_history.applied);
  CHECK(s.initial_history.overlapping_contacts == 108 * 12 / 2);  // every nearest-neighbour pair
  CHECK(s.initial_history.max_overlap_ratio > 0.19);
  CHECK(s.initial_history.max_overlap_ratio < 0.22);
  CHECK(s.initial_history.increments == kHistoryFromOverlapsIncrements);
  CHECK(s.initial_history.max_radius_ratio > 1.0);  // the load grew the radii
  CHECK(s.initial_history.guard_hits == 0);
  // no guard acted, no warning
  CHECK(counter_of(s, "mdr_guard_denominator") == 0.0);
  CHECK(counter_of(s, "mdr_guard_radius_cap") == 0.0);
  CHECK(counter_of(s, "mdr_guard_volume") == 0.0);
  CHECK(s.warnings.empty());
  // radii well below the cap (1.5); overlaps below R at every sample; the list is not rebuilt
  // every step (the particles hardly move: a handful of rebuilds at most)
  const double ratio = counter_of(s, "mdr_max_radius_ratio");
  CHECK(ratio < 1.1);
  CHECK(ratio >= s.initial_history.max_radius_ratio);
  CHECK(s.rebuilds < s.steps / 10);
  const auto ts = read_csv_columns(dir / "timeseries.csv");
  REQUIRE(ts.at("step").size() == 21u);
  for (std::size_t k = 0; k < ts.at("step").size(); ++k) {
    INFO("step " << ts.at("step")[k]);
    CHECK(std::isfinite(ts.at("ke_translational")[k]));
    CHECK(ts.at("max_overlap_ratio")[k] < 0.5);
    CHECK(ts.at("pair_contacts")[k] >= 648);
  }
  const auto j = read_json(dir / "summary.json");
  CHECK(j.at("initial_history").at("mode") == "from_overlaps");
  CHECK(j.at("initial_history").at("overlapping_contacts") == 648);
  CHECK(j.at("warnings").empty());
  std::filesystem::remove_all(dir);
}

TEST_CASE("driver: a denser packing with initial_history = \"zero\" is flagged by the growth-guard warning",
          "[driver][initial_history]") {
  const auto dir = fresh_out_dir("initial-history-zero");
  // overlaps to 0.26 R (nn 1.75 mm): at 0.21 R the default split's growth stays inside the guards
  const driver::RunSummary s = run_scene_text(packed_scene("initial_history = \"zero\"\n", 1.75e-3), dir);
  CHECK(s.initial_history.mode == "zero");
  CHECK_FALSE(s.initial_history.applied);
  CHECK(s.initial_history.overlapping_contacts == 648);
  // the whole overlap is one plastic increment: the guards act
  const double hits = counter_of(s, "mdr_guard_denominator") + counter_of(s, "mdr_guard_radius_cap") +
                      counter_of(s, "mdr_guard_volume");
  CHECK(hits > 0.0);
  REQUIRE(s.warnings.size() == 1u);
  CHECK_THAT(s.warnings[0], Catch::Contains("growth guards acted") && Catch::Contains("initial_history"));
  const auto j = read_json(dir / "summary.json");
  REQUIRE(j.at("warnings").size() == 1u);
  CHECK(j.at("warnings")[0].get<std::string>() == s.warnings[0]);
  std::filesystem::remove_all(dir);
}

TEST_CASE("driver: run.initial_history values", "[driver][initial_history][validation]") {
  CHECK(driver::parse_scene_string(packed_scene("")).run.initial_history == "from_overlaps");
  CHECK(driver::parse_scene_string(packed_scene("initial_history = \"zero\"\n")).run.initial_history == "zero");
  CHECK_THROWS_WITH(driver::parse_scene_string(packed_scene("initial_history = \"fresh\"\n")),
                    Catch::Contains("run.initial_history = \"fresh\"") && Catch::Contains("from_overlaps") &&
                        Catch::Contains("zero"));
}

namespace {

// Spheres of R = 1 mm placed exactly touching along x, starting at `offset` metres from the
// origin: a pair, or an n x n x n simple-cubic lattice (spacing 2R). The differences of the
// positions round to overlaps of a few ulps of the coordinates (1e-17 m in double at 0.1 m,
// 1e-7 m in float at 1 m), positive or negative: the start must accept either.
std::string touching_scene(const std::string& model, const std::string& material_extra, double offset, int n,
                           bool lattice) {
  std::ostringstream s;
  s.precision(17);
  s << "[materials.glass]\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\ndensity = 2500\n"
    << material_extra << "\n[model]\nname = \"" << model << "\"\n[particles]\nallow_overlap = false\n";
  const double R = 1e-3;
  const int ny = lattice ? n : 1, nz = lattice ? n : 1;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < ny; ++b)
      for (int c = 0; c < nz; ++c)
        s << "[[particles.list]]\nposition = [" << offset + 2 * R * a << ", " << 2 * R * b << ", " << 2 * R * c
          << "]\nradius = " << R << "\nmaterial = \"glass\"\n";
  s << "[run]\ndt = 1e-7\nsteps = 20\noutput_interval = 10\n";
  return s.str();
}

}  // namespace

TEST_CASE("driver: touching starts run at any offset, in both precisions, for laws with and without history",
          "[driver][initial_history][touching]") {
  // One rule for round-off overlaps at the start: a law without contact history starts its contacts
  // as they are; a law with history gets its rows (and, if they overlap, the quasi-static load).
  // Before, a law with no history fields stopped with "pair history has 0 rows for N contacts".
  struct Law {
    const char* model;
    const char* material_extra;
  };
  const Law laws[] = {{"hertz_mindlin", ""},                                // no history fields
                      {"hertz_mindlin", "friction = 0.3\n"},                // tangential history
                      {"mdr", "yield_stress = 1e7\nrestitution = 0.5\n"}};  // normal history, growth
  for (const Law& law : laws)
    for (const char* precision : {"double", "float"})
      for (const double offset : {0.0, 0.1, 1.0, 5.0})
        for (const bool lattice : {false, true}) {
          const std::string what = std::string(law.model) + (law.material_extra[0] ? " +history" : "") + ", " +
                                   precision + ", x0 = " + std::to_string(offset) +
                                   (lattice ? ", 4^3 lattice" : ", pair");
          INFO(what);
          const auto dir = fresh_out_dir("touching");
          driver::RunSummary s;
          REQUIRE_NOTHROW(
              s = run_scene_text(touching_scene(law.model, law.material_extra, offset, lattice ? 4 : 2, lattice), dir,
                                 precision));
          CHECK(s.status == "completed");
          CHECK(s.steps_completed == 20);
          // round-off overlaps only: at most a few ulps of the largest coordinate
          const double ulp = (std::string(precision) == "float" ? 1.2e-7 : 2.3e-16) * (offset + 0.01);
          CHECK(s.initial_history.max_overlap_ratio * 1e-3 <= 8 * ulp);
        }
}
