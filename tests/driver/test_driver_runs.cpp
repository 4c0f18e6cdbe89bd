// Short end-to-end runs of the driver: outputs exist and say what the physics says.
#include <catch2/catch.hpp>

#include "driver_test_util.hpp"
#include "driver/csv_columns.hpp"
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

using namespace epac;
using namespace epac::driver;
namespace fs = std::filesystem;

TEST_CASE("a head-on linear-spring collision rebounds with the restitution coefficient", "[driver][run]") {
  // Two equal spheres, closing speed 0.2 m/s, no gravity, no friction. Linear spring-dashpot with
  // c from Nan (26): the rebound kinetic energy is e0^2 of the impact energy, exactly in the
  // continuous problem. ~230 steps per contact (t_c = pi sqrt(m*/k) ~ 1.6e-4 s, dt = 1e-6 s):
  // the discretisation error of the separation instant is O(dt / t_c) < 1%.
  const double e0 = 0.8;
  const std::string text = R"(
[materials.a]
youngs_modulus = 1e7
density = 2500
restitution = )" + std::to_string(e0) +
                           R"(
[model]
name = "linear_spring"
stiffness = 2000.0
[[particles.list]]
position = [0, 0, 0]
radius = 0.001
material = "a"
velocity = [0.1, 0, 0]
[[particles.list]]
position = [0.0021, 0, 0]
radius = 0.001
material = "a"
velocity = [-0.1, 0, 0]
[run]
dt = 1e-6
steps = 1500
output_interval = 10
)";
  for (const std::string precision : {"double", "float"}) {
    SECTION(precision) {
      const fs::path dir = test::fresh_out_dir("collide");
      const RunSummary s = test::run_scene_text(text, dir, precision);
      CHECK(s.particles == 2);
      CHECK(s.steps == 1500);
      CHECK(s.effects == "damping");
      CHECK(s.scalar == precision);
      CHECK(s.history_fields == 0);
      REQUIRE(fs::exists(dir / "summary.json"));
      const auto c = test::read_csv_columns(dir / "timeseries.csv");
      const auto& ke = c.at("ke_translational");
      REQUIRE(ke.size() == 151);
      const double ratio = ke.back() / ke.front();
      CHECK(ratio == Approx(e0 * e0).epsilon(0.01));
      // they were in contact during the run and are apart at its end
      double max_contacts = 0;
      for (double n : c.at("pair_contacts")) max_contacts = std::max(max_contacts, n);
      CHECK(max_contacts == 1);
      CHECK(c.at("pair_contacts").back() == 0);
      fs::remove_all(dir);
    }
  }
}

TEST_CASE("a driven sphere pressed into a moving wall feels the Hertz force", "[driver][run]") {
  // Sphere R = 1 mm driven down at 0.1 mm/s onto a rigid floor that rises at 0.1 mm/s for 0.2 s and
  // then stops. No damping or friction (e = 1, mu = 0), so the contact force is Hertz's
  // F = (4/3) E* sqrt(R) delta^(3/2) with E* = E / (1 - nu^2) against a rigid flat, and the driven
  // sphere's velocity is not changed by it.
  const std::string text = R"(
[materials.soft]
youngs_modulus = 1e6
poisson_ratio = 0.3
density = 1000
[materials.plate]
rigid = true
[[particles.list]]
position = [0, 0, 0.00101]
radius = 0.001
material = "soft"
velocity = [0, 0, -0.0001]
driven = true
[[walls]]
name = "floor"
point = [0, 0, 0]
normal = [0, 0, 1]
material = "plate"
motion = [{duration = 0.2, velocity = [0, 0, 0.0001]}]
[run]
dt = 1e-4
steps = 3000
output_interval = 100
skin = 5e-5
)";
  const fs::path dir = test::fresh_out_dir("press");
  test::run_scene_text(text, dir);
  const auto c = test::read_csv_columns(dir / "timeseries.csv");
  const double E_star = 1e6 / (1 - 0.09);
  int checked = 0;
  for (std::size_t k = 0; k < c.at("time").size(); ++k) {
    const double t = c.at("time")[k];
    const double wall = std::min(t, 0.2) * 0.0001;
    CHECK(c.at("displacement_floor")[k] == Approx(wall).margin(1e-15));
    const double delta = 0.001 - (0.00101 - 0.0001 * t - wall);
    const double hertz = delta > 0 ? 4.0 / 3.0 * E_star * std::sqrt(0.001) * delta * std::sqrt(delta) : 0.0;
    CHECK(c.at("driven_fz")[k] == Approx(hertz).epsilon(1e-9).margin(1e-15));
    CHECK(c.at("force_floor")[k] == Approx(hertz).epsilon(1e-9).margin(1e-15));
    if (delta > 0) ++checked;
  }
  CHECK(checked > 20);
  fs::remove_all(dir);
}
