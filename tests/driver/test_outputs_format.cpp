// The driver's output formats a user opens elsewhere: ParaView/OVITO snapshots (particles.pvd +
// snapshots/*.vtp) parsed back and checked against particles.csv, CSV headers with units, and
// the versions in summary.json.
#include <catch2/catch.hpp>

#include "driver/scene.hpp"
#include "driver/snapshot_writer.hpp"
#include "driver_test_util.hpp"

#include <epac/core/build_info.hpp>
#include <epac/version.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace epac;
using namespace epac::driver;
using namespace epac::test;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

// A tiny reader of the .vtp the writer produces: each DataArray by Name, with its
// NumberOfComponents and values; the Piece's point and vertex counts.
struct Vtp {
  long points = -1, verts = -1;
  std::map<std::string, std::pair<int, std::vector<double>>> arrays;
};
Vtp parse_vtp(const std::string& text) {
  Vtp v;
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex("<VTKFile type=\"PolyData\"")));
  REQUIRE(std::regex_search(text, m, std::regex("<Piece NumberOfPoints=\"(\\d+)\" NumberOfVerts=\"(\\d+)\"")));
  v.points = std::stol(m[1]);
  v.verts = std::stol(m[2]);
  const std::regex array(
      "<DataArray type=\"(\\w+)\" Name=\"(\\w+)\"(?: NumberOfComponents=\"(\\d)\")? format=\"ascii\">"
      "([^<]*)</DataArray>");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), array); it != std::sregex_iterator(); ++it) {
    const auto& a = *it;
    std::vector<double> vals;
    std::istringstream s(a[4].str());
    double x;
    while (s >> x) vals.push_back(x);
    v.arrays[a[2]] = {a[3].matched ? std::stoi(a[3]) : 1, vals};
  }
  // Each closing tag balances an opening one (well-formed, as far as this layout goes).
  for (const char* tag : {"VTKFile", "PolyData", "Piece", "PointData", "Points", "Verts"}) {
    const std::regex open(std::string("<") + tag + "[ >]"), close(std::string("</") + tag + ">");
    const auto n_open = std::distance(std::sregex_iterator(text.begin(), text.end(), open), std::sregex_iterator());
    const auto n_close = std::distance(std::sregex_iterator(text.begin(), text.end(), close), std::sregex_iterator());
    CHECK(n_open == 1);
    CHECK(n_close == 1);
  }
  return v;
}

const char* kScene = R"(
[materials.sphere]
youngs_modulus = 1e8
poisson_ratio = 0.3
density = 1000.0
yield_stress = 2e6
[materials.steel]
youngs_modulus = 2e11
rigid = true
[model]
name = "mdr"
[[particles.list]]
position = [-0.001, 0.0, 0.0]
radius = 0.001
material = "sphere"
driven = true
velocity = [0.0005, 0.0, 0.0]
[[particles.list]]
position = [0.001, 0.0, 0.0]
radius = 0.001
material = "sphere"
driven = true
velocity = [-0.0005, 0.0, 0.0]
[[walls]]
name = "floor"
point = [0.0, -0.0015, 0.0]  # below the spheres, not touching
normal = [0.0, 1.0, 0.0]
material = "steel"
[run]
dt = 0.0005
steps = 40
output_interval = 10
contact_output = true
particle_output = true
snapshot_format = "vtp"
)";

}  // namespace

TEST_CASE("snapshots: particles.pvd lists one .vtp per output step, each parses back to particles.csv",
          "[driver][outputs]") {
  const fs::path dir = fresh_out_dir("snapshots");
  run_scene_text(kScene, dir);
  const std::string pvd = slurp(dir / "particles.pvd");
  REQUIRE(pvd.find("<VTKFile type=\"Collection\"") != std::string::npos);
  const std::regex dataset("<DataSet timestep=\"([^\"]+)\" group=\"\" part=\"0\" file=\"([^\"]+)\"/>");
  std::vector<std::pair<double, std::string>> sets;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset); it != std::sregex_iterator(); ++it)
    sets.emplace_back(std::stod((*it)[1]), (*it)[2]);
  REQUIRE(sets.size() == 5);  // steps 0, 10, 20, 30, 40
  for (std::size_t k = 0; k < sets.size(); ++k) CHECK(sets[k].first == Approx(k * 10 * 0.0005));

  const auto csv = read_csv_columns(dir / "particles.csv");  // rows: (step, particle)
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const Vtp v = parse_vtp(slurp(dir / sets[k].second));
    CHECK(v.points == 2);
    CHECK(v.verts == 2);
    for (const char* name : {"radius", "radius0", "id", "material", "velocity", "angular_velocity", "contact_force",
                             "volume", "position", "connectivity", "offsets"}) {
      INFO(name);
      REQUIRE(v.arrays.count(name) == 1);
      const auto& a = v.arrays.at(name);
      CHECK(a.second.size() == static_cast<std::size_t>(a.first * 2));
    }
    CHECK(v.arrays.at("velocity").first == 3);
    CHECK(v.arrays.at("position").first == 3);
    for (int i = 0; i < 2; ++i) {
      const std::size_t row = 2 * k + i;
      CHECK(v.arrays.at("position").second[3 * i] == Approx(csv.at("x")[row]).epsilon(1e-9));
      CHECK(v.arrays.at("radius").second[i] == Approx(csv.at("R")[row]).epsilon(1e-9));
      CHECK(v.arrays.at("volume").second[i] == Approx(csv.at("volume")[row]).epsilon(1e-9));
      CHECK(v.arrays.at("velocity").second[3 * i] == Approx(i == 0 ? 0.0005 : -0.0005));
    }
    if (k > 0) {  // pressed together: equal and opposite contact forces along x
      const auto& f = v.arrays.at("contact_force").second;
      CHECK(f[0] < 0);
      CHECK(f[3] == Approx(-f[0]).epsilon(1e-9));
    }
  }
}

TEST_CASE("CSV headers carry units, summary.json records the epac and Kokkos versions", "[driver][outputs]") {
  const fs::path dir = fresh_out_dir("units");
  run_scene_text(kScene, dir);
  CHECK(first_line(dir / "timeseries.csv") ==
        "step,time [s],ke_translational [J],ke_rotational [J],pe_gravity [J],pair_contacts,wall_contacts,pair_list,"
        "wall_list,max_overlap_ratio [-],force_floor [N],displacement_floor [m],driven_fx [N],driven_fy [N],"
        "driven_fz [N]");
  CHECK(first_line(dir / "particles.csv") == "step,time [s],id,x [m],y [m],z [m],R [m],R0 [m],volume [m^3]");
  CHECK(first_line(dir / "contacts.csv") ==
        "step,time [s],i,j,wall,wall_name,overlap [m],force [N],mdr_force [N],area [m^2],mean_pressure [Pa],"
        "delta_max [m],yielded_sides,adhesive_radius [m],side0_force [N],side1_force [N],side0_overlap [m],"
        "side1_overlap [m],contact_radius [m],area_from_radius [m^2]");
  CHECK(csv_column_name("time [s]") == "time");
  CHECK(csv_column_name("pair_contacts") == "pair_contacts");

  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  CHECK(j.at("epac_version") == EPAC_VERSION_STRING);
  CHECK(j.at("kokkos_version") == kokkos_version_string());
  CHECK(j.at("kokkos_backends") == kokkos_backends());
  CHECK(std::regex_match(j.at("kokkos_version").get<std::string>(), std::regex("\\d+\\.\\d+\\.\\d+")));
  CHECK(j.at("kokkos_backends").get<std::string>().find("Serial") != std::string::npos);
}

TEST_CASE("snapshot_format is validated", "[driver][outputs]") {
  std::string text = kScene;
  text.replace(text.find("\"vtp\""), 5, "\"vtu\"");
  CHECK_THROWS_WITH(parse_scene_string(text, "t.toml"),
                    Catch::Contains("run.snapshot_format = \"vtu\"") && Catch::Contains("\"vtp\""));
}
