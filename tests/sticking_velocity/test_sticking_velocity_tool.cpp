// epac-sticking-velocity's library: classification of driver timeseries (stick, rebound, too
// short), scene checks, and the simulated critical sticking velocity through the driver for
// Table 6's R = 2.45 um (p_y = 30 MPa, e0 = 0.81: 2.08 m/s within 5%), plus the undamped run
// against the analytic Nan (78)-(79).
#include <catch2/catch.hpp>

#include "driver/scene.hpp"
#include "sticking_velocity/impact_search.hpp"

#include <fstream>
#include <sstream>
#include <string>

using namespace epac;
using namespace epac::sticking;

namespace {

const std::string kScenes = EPAC_SCENES_DIR;  // drivers/scenes
const std::string kTmp = EPAC_STICKING_TMP;

ImpactScene scene_R245() {
  return make_impact_scene(driver::parse_scene_file(kScenes + "/nan2022_sticking_R2.45.toml"));
}

std::string csv(const std::string& name, const std::string& rows) {
  const std::string path = kTmp + "/" + name;
  std::ofstream(path) << "step,time [s],ke_translational [J],force_wall [N]\n" << rows;  // as the driver writes it
  return path;
}

}  // namespace

TEST_CASE("sticking velocity: timeseries classification", "[sticking_velocity]") {
  const ImpactScene s = scene_R245();
  SECTION("rebound: contact formed, force exactly 0 at the end; rebound speed from KE") {
    std::ostringstream ke;  // 0.5 m/s
    ke.precision(17);
    ke << 0.5 * s.mass * 0.25;
    const auto r = classify_timeseries(
        csv("rebound.csv", "0,0,1,0\n1,0,1,-1e-6\n2,0,1,2e-5\n3,0,1,-3e-6\n4,0," + ke.str() + ",0\n"), s, 1.0);
    CHECK(r.outcome == Outcome::rebound);
    CHECK(r.rebound_speed == Approx(0.5).epsilon(1e-5));
    CHECK(r.max_force == 2e-5);
    CHECK(r.min_force == -3e-6);
  }
  SECTION("stick: compressive, tensile, compressive again") {
    const auto r =
        classify_timeseries(csv("stick.csv", "0,0,1,0\n1,0,1,-1e-6\n2,0,1,2e-5\n3,0,1,-3e-6\n4,0,1,1e-7\n"), s, 1.0);
    CHECK(r.outcome == Outcome::stick);
    CHECK(r.rebound_speed == 0);
  }
  SECTION("still attached but not yet back in compression: too short, an error naming [run] steps") {
    CHECK_THROWS_WITH(classify_timeseries(csv("short.csv", "0,0,1,0\n1,0,1,2e-5\n2,0,1,-3e-6\n"), s, 1.0),
                      Catch::Contains("[run] steps"));
  }
  SECTION("never touched the wall") {
    CHECK_THROWS_WITH(classify_timeseries(csv("none.csv", "0,0,1,0\n1,0,1,0\n"), s, 1.0),
                      Catch::Contains("never reached the wall"));
  }
}

TEST_CASE("sticking velocity: scene checks name what is wrong", "[sticking_velocity]") {
  driver::Scene base = driver::parse_scene_file(kScenes + "/nan2022_sticking_R2.45.toml");
  auto two = base;
  two.particles.push_back(two.particles[0]);
  CHECK_THROWS_WITH(make_impact_scene(two), Catch::Contains("exactly one particle"));
  auto g = base;
  g.gravity = {0, 0, -9.81};
  CHECK_THROWS_WITH(make_impact_scene(g), Catch::Contains("gravity"));
  auto touching = base;
  touching.particles[0].position[2] = touching.particles[0].radius;  // gap 0
  CHECK_THROWS_WITH(make_impact_scene(touching), Catch::Contains("gap = 0"));
  const ImpactScene s = make_impact_scene(base);
  CHECK(s.scene.run.output_interval == 1);
  CHECK(s.mass == Approx(4.0 / 3.0 * M_PI * 2.45e-6 * 2.45e-6 * 2.45e-6 * 1350).epsilon(1e-12));
}

TEST_CASE("sticking velocity through the driver: Table 6, R = 2.45 um", "[sticking_velocity][paper]") {
  const ImpactScene s = scene_R245();
  const AnalyticSticking a = nan2022_analytic(s);
  REQUIRE(a.available);
  // Table 6, p_y = 30 MPa, e0 = 1 (analytic): 1.86 m/s; V_s = 0.66 m/s (printed to 2-3 digits)
  CHECK(a.v.V_ys == Approx(1.86).epsilon(0.02));
  CHECK(a.v.V_s == Approx(0.66).epsilon(0.02));
  CHECK(a.v.always_yields);

  SECTION("e0 = 0.81: Table 6's simulated 2.08 m/s within 5%") {
    const StickingSearch r = find_sticking_velocity(s, 0.5 * a.v.V_ys, 3.0 * a.v.V_ys, 1e-3, kTmp + "/run_e081");
    INFO("simulated V_ys = " << r.V_ys << " m/s in " << r.runs.size() << " runs");
    CHECK(r.V_ys == Approx(2.08).epsilon(0.05));
    CHECK(r.hi - r.lo <= 1e-3 * r.hi);
    // damping only removes energy: the damped impact needs more speed to escape than the undamped one
    CHECK(r.V_ys > a.v.V_ys);
  }
  SECTION("e0 = 1 (no damping): the analytic Nan (78)-(79) within 1%") {
    // Same physics as the analytic fixed point; 1% covers dt = 1% of the critical step and the
    // bisection's 0.1%.
    driver::Scene sc = s.scene;
    for (auto& m : sc.materials) m.restitution = 1.0;
    const ImpactScene undamped = make_impact_scene(sc);
    const StickingSearch r = find_sticking_velocity(undamped, 0.5 * a.v.V_ys, 3.0 * a.v.V_ys, 1e-3, kTmp + "/run_e1");
    INFO("simulated V_ys = " << r.V_ys << " m/s, analytic " << a.v.V_ys);
    CHECK(r.V_ys == Approx(a.v.V_ys).epsilon(0.01));
  }
}
