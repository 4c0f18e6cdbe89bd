// Bad scenes are refused on the host, before anything runs or is written, with a message that
// names the key (with its table), the value and the valid range.
#include <catch2/catch.hpp>

#include "driver_test_util.hpp"
#include "driver/model_registry.hpp"
#include "driver/scene.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

using namespace epac;
using namespace epac::driver;
namespace fs = std::filesystem;

namespace {

const std::string kGlass = "youngs_modulus = 1.0e7\npoisson_ratio = 0.25\ndensity = 2500";

// kGlass with one key's line replaced (or a new line appended).
std::string glass_with(const std::string& key, const std::string& line) {
  std::string s = kGlass;
  const auto at = s.find(key + " =");
  if (at == std::string::npos) return s + "\n" + line;
  const auto end = s.find('\n', at);
  return s.replace(at, end == std::string::npos ? std::string::npos : end - at, line);
}

// A valid scene, unless one of its parts is replaced by a bad one.
std::string base_scene(const std::string& material_extra, const std::string& second_particle,
                       const std::string& run_extra = "", const std::string& wall_normal = "[0, 0, 1]") {
  const std::string material = material_extra.empty() ? kGlass : material_extra;
  return R"(
[materials.glass]
)" + material +
         R"(

[materials.wall]
rigid = true

[[particles.list]]
position = [0, 0, 0.002]
radius = 0.001
material = "glass"

[[particles.list]]
)" + second_particle +
         R"(
material = "glass"

[[walls]]
point = [0, 0, 0]
normal = )" +
         wall_normal + R"(
material = "wall"

[run]
dt = 1e-6
steps = 10
)" + run_extra +
         "\n";
}

const std::string kSecond = "position = [0.003, 0, 0.002]\nradius = 0.001";

std::string with_dt(const std::string& dt) {
  std::string s = base_scene("", kSecond);
  return s.replace(s.find("dt = 1e-6"), 9, "dt = " + dt);
}

std::string with_wall_point(const std::string& point) {
  std::string s = base_scene("", kSecond);
  const std::string old = "point = [0, 0, 0]";
  return s.replace(s.find(old), old.size(), "point = " + point);
}

struct BadCase {
  const char* what;
  std::string text;
  std::vector<std::string> must_contain;  // key, value, range
};

std::vector<BadCase> bad_cases() {
  return {
      {"negative modulus",
       base_scene(glass_with("youngs_modulus", "youngs_modulus = -1.0e7"), kSecond),
       {"materials.glass.youngs_modulus", "= -1e+07", "(0, inf)"}},
      {"Poisson ratio 0.5",
       base_scene(glass_with("poisson_ratio", "poisson_ratio = 0.5"), kSecond),
       {"materials.glass.poisson_ratio", "= 0.5", "(-1, 0.5)"}},
      {"Poisson ratio above 0.5",
       base_scene(glass_with("poisson_ratio", "poisson_ratio = 0.7"), kSecond),
       {"materials.glass.poisson_ratio", "= 0.7", "(-1, 0.5)"}},
      {"radius 0",
       base_scene("", "position = [0.003, 0, 0.002]\nradius = 0.0"),
       {"particles.list[1].radius", "= 0", "[1e-07, 100]"}},
      {"negative radius",
       base_scene("", "position = [0.003, 0, 0.002]\nradius = -0.001"),
       {"particles.list[1].radius", "= -0.001", "[1e-07, 100]"}},
      {"NaN density",
       base_scene(glass_with("density", "density = nan"), kSecond),
       {"materials.glass.density", "= nan", "(0, inf)"}},
      {"NaN position",
       base_scene("", "position = [0.003, 0, nan]\nradius = 0.001"),
       {"particles.list[1].position[2]", "= nan", "[-1e+06, 1e+06]"}},
      {"NaN skin", base_scene("", kSecond, "skin = nan"), {"run.skin", "= nan", "[0, inf)"}},
      {"NaN time step", with_dt("nan"), {"run.dt", "= nan", "(0, inf)"}},
      {"unknown material key",
       base_scene(glass_with("densty", "densty = 2500"), kSecond),
       {"unknown key 'densty'", "[materials.glass]", "valid keys:", "density"}},
      {"unknown run key", base_scene("", kSecond, "stepz = 3"), {"unknown key 'stepz'", "[run]"}},
      {"unknown particle key",
       base_scene("", kSecond + "\nradis = 0.001"),
       {"unknown key 'radis'", "[particles.list[1]]"}},
      {"overlapping explicit particles",
       base_scene("", "position = [0.0015, 0, 0.002]\nradius = 0.001"),
       {"particles.list[0] and particles.list[1] overlap by 0.0005", "R_i + R_j = 0.002", "allow_overlap"}},
      {"zero wall normal",
       base_scene("", kSecond, "", "[0, 0, 0]"),
       {"walls[0].normal = [0, 0, 0]", "length 0", "(0, inf)"}},
      {"negative time step", with_dt("-1.0"), {"run.dt", "= -1", "(0, inf)"}},
      // Values inside the old (0, inf) / finite checks that ran into "the simulation diverged":
      // refused with the physical range, its unit and the line.
      {"radius 1e-300",
       base_scene("", "position = [0.003, 0, 0.002]\nradius = 1e-300"),
       {"particles.list[1].radius = 1e-300", "[1e-07, 100]", "(m;", "[line 17]"}},
      {"radius 1e300",
       base_scene("", "position = [0.003, 0, 0.002]\nradius = 1e300"),
       {"particles.list[1].radius = 1e+300", "[1e-07, 100]", "[line 17]"}},
      {"density 1e-300",
       base_scene(glass_with("density", "density = 1e-300"), kSecond),
       {"materials.glass.density = 1e-300", "[0.1, 100000]", "kg/m^3", "[line 5]"}},
      {"density 1e300",
       base_scene(glass_with("density", "density = 1e300"), kSecond),
       {"materials.glass.density = 1e+300", "[0.1, 100000]"}},
      {"Young's modulus 1e300",
       base_scene(glass_with("youngs_modulus", "youngs_modulus = 1e300"), kSecond),
       {"materials.glass.youngs_modulus = 1e+300", "[1000, 1e+13]", "Pa", "[line 3]"}},
      {"gravity 1e300",
       "gravity = [0, 0, 1e300]\n" + base_scene("", kSecond),
       {"gravity[2] = 1e+300", "[-100000, 100000]", "m/s^2", "[line 1]"}},
      {"velocity 1e300",
       base_scene("", kSecond + "\nvelocity = [1e300, 0, 0]"),
       {"particles.list[1].velocity[0] = 1e+300", "[-10000, 10000]", "m/s"}},
      {"angular velocity 1e300",
       base_scene("", kSecond + "\nangular_velocity = [0, -1e300, 0]"),
       {"particles.list[1].angular_velocity[1] = -1e+300", "[-1e+09, 1e+09]", "rad/s"}},
      {"position 1e300",
       base_scene("", "position = [1e300, 0, 0.002]\nradius = 0.001"),
       {"particles.list[1].position[0] = 1e+300", "[-1e+06, 1e+06]"}},
      {"wall point 1e300", with_wall_point("[0, 0, 1e300]"), {"walls[0].point[2] = 1e+300", "[-1e+06, 1e+06]"}},
  };
}

}  // namespace

TEST_CASE("bad scenes are rejected with key, value and range", "[driver][scene][validation]") {
  for (const auto& c : bad_cases()) {
    SECTION(c.what) {
      std::string message;
      try {
        parse_scene_string(c.text, "bad.toml");
      } catch (const ParameterError& e) { message = e.what(); }
      INFO("message: " << message);
      REQUIRE_FALSE(message.empty());
      for (const auto& part : c.must_contain) CHECK(message.find(part) != std::string::npos);
    }
  }
}

TEST_CASE("the base scene of the rejection cases is valid", "[driver][scene][validation]") {
  // Guards the test above: each bad case differs from a valid scene in one key only.
  const Scene s = parse_scene_string(base_scene("", kSecond));
  CHECK(s.particles.size() == 2);
  // overlapping particles are accepted when allowed
  const std::string overlap = base_scene("", "position = [0.0015, 0, 0.002]\nradius = 0.001");
  const Scene o = parse_scene_string("[particles]\nallow_overlap = true\n" + overlap);
  CHECK(o.particles.size() == 2);
}

TEST_CASE("a rejected scene runs nothing and writes nothing", "[driver][scene][validation]") {
  for (const auto& c : bad_cases()) {
    SECTION(c.what) {
      const fs::path dir = test::fresh_out_dir("in");
      fs::create_directories(dir);
      const fs::path scene = dir / "bad.toml";
      std::ofstream(scene) << c.text;
      RunOptions opt;
      opt.out_dir = (dir / "out").string();
      opt.quiet = true;
      CHECK_THROWS_AS(run_scene_file(scene.string(), opt), ParameterError);
      CHECK_FALSE(fs::exists(opt.out_dir));
      fs::remove_all(dir);
    }
  }
  SECTION("invalid precision on a valid scene") {
    const fs::path dir = test::fresh_out_dir("prec");
    fs::create_directories(dir);
    const fs::path scene = dir / "ok.toml";
    std::ofstream(scene) << base_scene("", kSecond);
    RunOptions opt;
    opt.out_dir = (dir / "out").string();
    opt.quiet = true;
    opt.precision = "half";
    CHECK_THROWS_WITH(run_scene_file(scene.string(), opt), Catch::Contains("--precision = half"));
    CHECK_FALSE(fs::exists(opt.out_dir));
    fs::remove_all(dir);
  }
}
