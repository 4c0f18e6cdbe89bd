// Scene files that are valid: what the parser makes of them.
#include <catch2/catch.hpp>

#include "driver/effect_selection.hpp"
#include "driver/scene.hpp"

#include <cmath>

using namespace epac;
using namespace epac::driver;

namespace {
const char* kMaterials = R"(
[materials.glass]
youngs_modulus = 7.0e10
poisson_ratio = 0.22
density = 2500
restitution = 0.9
friction = 0.4

[materials.steel]
youngs_modulus = 2.0e11
density = 7800

[materials.wall]
rigid = true
)";
}  // namespace

TEST_CASE("explicit particles, walls and run keys are read as written", "[driver][scene]") {
  const std::string text = std::string("gravity = [0, 0, -9.81]\n") + kMaterials + R"(
[particles]
[[particles.list]]
position = [0.0, 0.0, 0.01]
radius = 0.001
material = "glass"
velocity = [0.5, 0, 0]

[[particles.list]]
position = [0.01, 0.0, 0.01]
radius = 0.002
material = "steel"
driven = true
angular_velocity = [0, 0, 3]

[[walls]]
name = "slope"
point = [0, 0, 0]
normal = [1, 1, 0]
material = "wall"

[[walls]]
point = [0, 0, 0.05]
normal = [0, 0, -2]
material = "wall"
velocity = [0, 0, -0.1]

[run]
dt = 1e-6
steps = 500
skin = 1e-4
)";
  const Scene s = parse_scene_string(text);
  REQUIRE(s.materials.size() == 3);
  CHECK(s.materials[s.material_index.at("glass")].youngs_modulus == 7.0e10);
  CHECK(s.materials[s.material_index.at("steel")].poisson_ratio == 0.3);  // Material's default
  CHECK(s.materials[s.material_index.at("wall")].rigid);
  REQUIRE(s.particles.size() == 2);
  CHECK(s.particles[0].radius == 0.001);
  CHECK(s.particles[0].velocity[0] == 0.5);
  CHECK_FALSE(s.particles[0].driven);
  CHECK(s.particles[0].material == s.material_index.at("glass"));
  CHECK(s.particles[1].driven);
  CHECK(s.particles[1].angular_velocity[2] == 3.0);
  CHECK(s.particles[1].material == s.material_index.at("steel"));
  REQUIRE(s.walls.size() == 2);
  CHECK(s.walls[0].name == "slope");
  CHECK(s.walls[1].name == "wall1");
  // normals normalised on input
  CHECK(s.walls[0].normal[0] == Approx(1.0 / std::sqrt(2.0)).epsilon(1e-15));
  CHECK(s.walls[0].normal[1] == Approx(1.0 / std::sqrt(2.0)).epsilon(1e-15));
  CHECK(s.walls[1].normal[2] == -1.0);
  CHECK(s.walls[1].velocity[2] == -0.1);
  CHECK(s.walls[1].displacement(0.0, 0.5)[2] == Approx(-0.05).epsilon(1e-15));
  CHECK(s.gravity[2] == -9.81);
  CHECK(s.run.dt == 1e-6);
  CHECK(s.run.steps == 500);
  CHECK(s.run.output_interval == 5);  // default: steps / 100
  CHECK(s.run.skin == 1e-4);
  // friction 0.4 and restitution 0.9 on glass: both effects derived; steel-steel alone has neither
  CHECK(s.model.name == "hertz_mindlin");
  CHECK(s.model.effects == (kFriction | kDamping));
}

TEST_CASE("piecewise wall motion integrates to the prescribed displacement", "[driver][scene]") {
  const std::string text = std::string(kMaterials) + R"(
[[particles.list]]
position = [0, 0, 0.01]
radius = 0.001
material = "glass"

[[walls]]
point = [0, 0, 0]
normal = [0, 0, 1]
material = "wall"
motion = [{duration = 0.1, velocity = [0, 0, 0.002]}, {duration = 0.05, velocity = [0, 0, -0.004]}]

[run]
dt = 1e-5
steps = 10
)";
  const Scene s = parse_scene_string(text);
  REQUIRE(s.walls.size() == 1);
  const WallSpec& w = s.walls[0];
  REQUIRE(w.segments.size() == 2);
  CHECK(w.segments[1].duration == 0.05);
  // load for 0.1 s at 2 mm/s (0.2 mm up), then unload at 4 mm/s for 0.05 s (back to 0), then rest
  CHECK(w.displacement(0.0, 0.05)[2] == Approx(1e-4).epsilon(1e-12));
  CHECK(w.displacement(0.0, 0.1)[2] == Approx(2e-4).epsilon(1e-12));
  CHECK(w.displacement(0.05, 0.125)[2] == Approx(0.05 * 0.002 - 0.025 * 0.004).margin(1e-15));
  CHECK(w.displacement(0.0, 0.15)[2] == Approx(0.0).margin(1e-15));
  CHECK(w.displacement(0.0, 1.0)[2] == Approx(0.0).margin(1e-15));  // still after the last segment
  CHECK(w.displacement(0.2, 0.3)[2] == 0.0);
}

TEST_CASE("the random fill places non-overlapping particles inside the box, reproducibly", "[driver][scene]") {
  auto scene = [](int seed) {
    return std::string(kMaterials) + R"(
[[particles.list]]
position = [0.005, 0.005, 0.005]
radius = 0.002
material = "steel"

[particles.fill]
box_min = [0, 0, 0]
box_max = [0.01, 0.01, 0.02]
count = 300
radius_min = 0.0004
radius_max = 0.0006
material = "glass"
seed = )" + std::to_string(seed) +
           R"(
[run]
dt = 1e-6
steps = 1
)";
  };
  const Scene s = parse_scene_string(scene(7));
  REQUIRE(s.particles.size() == 301);  // the listed one first, then the fill
  CHECK(s.particles[0].radius == 0.002);
  for (std::size_t i = 1; i < s.particles.size(); ++i) {
    const auto& p = s.particles[i];
    CHECK(p.radius >= 0.0004);
    CHECK(p.radius <= 0.0006);
    CHECK(p.material == s.material_index.at("glass"));
    const double hi[3] = {0.01, 0.01, 0.02};
    for (int d = 0; d < 3; ++d) {
      CHECK(p.position[d] - p.radius >= 0.0);
      CHECK(p.position[d] + p.radius <= hi[d]);
    }
  }
  int overlaps = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    for (std::size_t j = i + 1; j < s.particles.size(); ++j) {
      const auto& a = s.particles[i];
      const auto& b = s.particles[j];
      const double dx = a.position[0] - b.position[0], dy = a.position[1] - b.position[1],
                   dz = a.position[2] - b.position[2];
      if (std::sqrt(dx * dx + dy * dy + dz * dz) < a.radius + b.radius) ++overlaps;
    }
  CHECK(overlaps == 0);
  const Scene again = parse_scene_string(scene(7));
  const Scene other = parse_scene_string(scene(8));
  CHECK(again.particles[150].position == s.particles[150].position);
  CHECK(other.particles[150].position != s.particles[150].position);
}

TEST_CASE("the effect set is derived from the materials and can be overridden", "[driver][scene]") {
  auto scene = [](const std::string& mat, const std::string& model) {
    return "[materials.a]\nyoungs_modulus = 1e7\ndensity = 1000\n" + mat + "\n[model]\n" + model + R"(
[[particles.list]]
position = [0, 0, 0]
radius = 0.001
material = "a"
[run]
dt = 1e-6
steps = 1
)";
  };
  CHECK(parse_scene_string(scene("", "name = \"hertz_mindlin\"")).model.effects == 0u);  // e = 1, mu = 0
  CHECK(parse_scene_string(scene("friction = 0.5", "")).model.effects == unsigned(kFriction));
  CHECK(parse_scene_string(scene("restitution = 0.7", "")).model.effects == unsigned(kDamping));
  // adhesion is derived, but hertz_mindlin has none: dropped with a note
  const Scene adh = parse_scene_string(scene("surface_energy = 0.1", ""));
  CHECK(adh.model.derived_effects == unsigned(kAdhesion));
  CHECK(adh.model.effects == 0u);
  CHECK(adh.model.notes.size() == 1);
  // the override wins
  const Scene o = parse_scene_string(scene("friction = 0.5", "effects = [\"damping\"]"));
  CHECK(o.model.effects_overridden);
  CHECK(o.model.effects == unsigned(kDamping));
  // model-specific keys
  const Scene lin = parse_scene_string(scene("", "name = \"linear_spring\"\nstiffness = 2500.0"));
  CHECK(lin.model.name == "linear_spring");
  CHECK(lin.model.params.at("stiffness") == 2500.0);
  // rolling resistance: from rolling_friction > 0, with friction; alone it is refused by name
  const Scene roll = parse_scene_string(
      scene("friction = 0.5\nrolling_friction = 0.1\nrolling_stiffness = 40.0\nrolling_damping = 1e-4", ""));
  CHECK(roll.model.effects == unsigned(kFriction | kRolling));
  CHECK(roll.materials[0].rolling_friction == 0.1);
  CHECK(roll.materials[0].rolling_stiffness == 40.0);
  CHECK(roll.materials[0].rolling_damping == 1e-4);
  CHECK(effect_names(kRolling) == "rolling");
  CHECK(effect_bit("rolling") == unsigned(kRolling));
  // without sliding friction: the friction effect comes with it (mu = 0), with a note
  const Scene roll0 = parse_scene_string(scene("rolling_friction = 0.1", ""));
  CHECK(roll0.model.effects == unsigned(kFriction | kRolling));
  CHECK(roll0.model.notes.size() == 1);
  try {
    parse_scene_string(scene("rolling_friction = 0.1", "effects = [\"rolling\"]"));
    FAIL("an override of rolling without friction accepted");
  } catch (const SceneError& e) { CHECK(std::string(e.what()).find("rolling without friction") != std::string::npos); }
  try {
    parse_scene_string(scene("friction = 0.5\nrolling_damping = -1", ""));
    FAIL("negative rolling_damping accepted");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()).find("materials.a.rolling_damping") != std::string::npos);
  }
  CHECK(effect_names(kFriction | kDamping) == "friction, damping");
  CHECK(bytes_per_contact(3, 8) == 3 * 8 + 8 + 8);
  CHECK(bytes_per_contact(0, 4) == 8);
}
