// The models mdr, nan2022 and jkr through the driver: small scenes run end to end (scene text ->
// parse -> run_scene -> CSV), and the wall force of a driven sphere pressed into a rising rigid
// flat and pulled back says what the model's law says (Hertz at small overlap, pull-off forces,
// detachment at negative overlap, plastic residual overlap, radius growth); the scene checks
// (option ranges, adhesive range against the skin).
#include <catch2/catch.hpp>

#include "driver_test_util.hpp"

#include <epac/params/nan2022/nan2022_parameters.hpp>
#include <epac/models/nan2022/detail/nan2022_unloading.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

using namespace epac;
using namespace epac::driver;
using namespace epac::test;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A driven sphere of radius R at the origin (at rest) and a rigid floor that starts touching it
// (z = -R, normal +z), rises by `load` in steps of `inc` and then goes back down by `unload`.
// The floor's normal displacement is the overlap; force_floor > 0 is compression.
std::string press_scene(const std::string& model, const std::string& material, double R, double load, double unload,
                        double inc, const std::string& run_extra = "") {
  const double dt = 1e-4;
  const double v = inc / dt;
  const long n_load = std::lround(load / inc), n_unload = std::lround(unload / inc);
  auto num = [](double x) {
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", x);
    return std::string(b);
  };
  return "[materials.ball]\n" + material + "\ndensity = 1000\n[materials.plate]\nrigid = true\n[model]\n" + model +
         "\n[[particles.list]]\nposition = [0, 0, 0]\nradius = " + num(R) +
         "\nmaterial = \"ball\"\ndriven = true\n[[walls]]\nname = \"floor\"\npoint = [0, 0, " + num(-R) +
         "]\nnormal = [0, 0, 1]\nmaterial = \"plate\"\nmotion = [{duration = " + num(n_load * dt) +
         ", velocity = [0, 0, " + num(v) + "]}, {duration = " + num(n_unload * dt) + ", velocity = [0, 0, " + num(-v) +
         "]}]\n[run]\ndt = " + num(dt) + "\nsteps = " + std::to_string(n_load + n_unload) + "\noutput_interval = 1\n" +
         run_extra;
}

double min_of(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Index of the last sample with a nonzero force.
std::size_t last_touch(const std::vector<double>& f) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i] != 0.0) k = i;
  return k;
}

}  // namespace

TEST_CASE("jkr in the driver: displacement-controlled pull-off and detachment at delta_c", "[driver][models][jkr]") {
  // R = 1 mm, E = 1e8 Pa, nu = 0.3, rigid flat (E* = E/(1-nu^2)), Gamma = 0.05 J/m^2.
  // Pull-off (the force minimum on the displacement-controlled path) -1.5 pi Gamma R; the contact
  // breaks at delta_c = -(3/4)(pi^2 Gamma^2 R/E*^2)^(1/3) (Nan (B1)-(B5)). Increment delta_s/200.
  const double R = 1e-3, E = 1e8, nu = 0.3, G = 0.05;
  const double Es = E / (1 - nu * nu);
  const double f_ce = 1.5 * kPi * G * R;
  const double delta_c = -0.75 * std::cbrt(kPi * kPi * G * G * R / (Es * Es));
  const std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nsurface_energy = 0.05";
  const std::string text = press_scene("name = \"jkr\"", mat, R, 1e-6, 2e-6, 1e-9);
  for (const std::string precision : {"double", "float"}) {
    SECTION(precision) {
      const fs::path dir = fresh_out_dir("jkr");
      const RunSummary s = run_scene_text(text, dir, precision);
      CHECK(s.effects == "adhesion");
      CHECK(s.history_fields == 2);  // the radius root and R*^(1/3)
      const auto c = read_csv_columns(dir / "timeseries.csv");
      const auto& f = c.at("force_floor");
      const auto& d = c.at("displacement_floor");
      CHECK(min_of(f) == Approx(-f_ce).epsilon(precision == "double" ? 2e-4 : 2e-3));
      const std::size_t k = last_touch(f);
      REQUIRE(k + 1 < f.size());
      // the contact breaks between the samples k and k + 1 (1e-9 apart) at delta_c
      CHECK(d[k] >= delta_c - 2e-9);
      CHECK(d[k + 1] <= delta_c + 2e-9);
      // just before the break the force lies between the pull-off and the break force -5/9 f_ce
      // (it tends to -5/9 f_ce with an infinite slope at delta_c, so one increment matters)
      CHECK(f[k] < -5.0 / 9.0 * f_ce);
      CHECK(f[k] > -f_ce);
      fs::remove_all(dir);
    }
  }
}

TEST_CASE("nan2022 in the driver: pull-off f_cp and detachment at alpha_jp", "[driver][models][nan2022]") {
  // R = 1 mm, E = 1e8 Pa, Gamma = 0.5 J/m^2, rigid flat, loaded in steps of 4e-9 m and pulled
  // back to -5e-6 m. The minimum force is -f_cp and the contact detaches at alpha_jp (force
  // -5/9 f_cp) of the unloading line of alpha_max (Nan (10)-(16), (59)), computed here on the
  // host from the same parameter derivation.
  //  - plastic: sigma_y = 2e6 Pa, loaded to 2e-5 m (past yield): f_cp > f_ce, and the flattened
  //    contact detaches at a positive overlap;
  //  - elastic: no yield, k_el = pi R p_k with p_k = 3.2e6 Pa, loaded to 2e-6 m: f_cp = f_ce and it
  //    detaches at the negative alpha_je (the list keeps the pair across the gap).
  const double R = 1e-3, inc = 4e-9;
  for (const bool plastic : {true, false}) {
    SECTION(plastic ? "plastic" : "elastic") {
      const double load = plastic ? 2e-5 : 2e-6;
      Material ball;
      ball.name = "ball";
      ball.youngs_modulus = 1e8;
      ball.poisson_ratio = 0.3;
      ball.density = 1000;
      ball.surface_energy = 0.5;
      std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nsurface_energy = 0.5";
      std::string model = "name = \"nan2022\"";
      Nan2022Options opt;
      if (plastic) {
        ball.yield_stress = 2e6;
        mat += "\nyield_stress = 2e6";
      } else {
        opt.k_el_from = Nan2022ElasticStiffnessFrom::stiffness_pressure;
        opt.stiffness_pressure = 3.2e6;
        model += "\nk_el_from = \"stiffness_pressure\"\nstiffness_pressure = 3.2e6";
      }
      Material plate;
      plate.name = "plate";
      plate.rigid = true;
      const Nan2022PairConstants<double> pc = nan2022_pair_constants(ball, plate, opt);
      const Nan2022ContactConstants<double> cc = nan2022_contact_constants<double>(pc, R);
      REQUIRE(cc.yields == plastic);
      if (plastic) REQUIRE(cc.alpha_y < 0.5 * load);
      const Nan2022Unloading<double> u = nan2022_unloading(cc, plastic ? load : 0.0, pc.unloading_law, pc.pull_off_law);
      REQUIRE(u.alpha_jp > -5e-6);
      if (plastic)
        REQUIRE(u.alpha_jp > 0.0);
      else
        REQUIRE(u.alpha_jp < -10 * inc);

      const fs::path dir = fresh_out_dir("nan");
      const RunSummary s = run_scene_text(press_scene(model, mat, R, load, load + 5e-6, inc), dir);
      CHECK(s.effects == (plastic ? "adhesion, plasticity" : "adhesion"));
      const auto c = read_csv_columns(dir / "timeseries.csv");
      const auto& f = c.at("force_floor");
      const auto& d = c.at("displacement_floor");
      // the force minimum is the corner -f_cp of the piecewise-linear law: the samples straddle it
      const double f_ce = 1.5 * kPi * 0.5 * R;
      CHECK(min_of(f) >= -u.f_cp * (1 + 1e-9));
      CHECK(min_of(f) <= -u.f_cp + u.k_e * inc);
      if (plastic)
        CHECK(u.f_cp > 1.05 * f_ce);  // plastic flattening raised the pull-off
      else
        CHECK(u.f_cp == Approx(f_ce).epsilon(1e-12));
      const std::size_t k = last_touch(f);
      REQUIRE(k + 1 < f.size());
      CHECK(d[k] >= u.alpha_jp - 1.5 * inc);
      CHECK(d[k + 1] <= u.alpha_jp + 1.5 * inc);
      CHECK(f[k] == Approx(-5.0 / 9.0 * u.f_cp).epsilon(0.02));  // Nan (14): detachment at -5/9 f_cp
      fs::remove_all(dir);
    }
  }
}

TEST_CASE("mdr in the driver: Hertz at small overlap, yield, residual overlap and radius growth",
          "[driver][models][mdr]") {
  // R_o = 1 mm, E = 1e8 Pa, nu = 0.3, Y = 2e6 Pa (E/Y = 50), rigid flat; to delta/R = 0.1 and back.
  const double R = 1e-3, E = 1e8, nu = 0.3;
  const double Ee = E / (1 - nu * nu);
  const std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nyield_stress = 2e6";
  const std::string text = press_scene("name = \"mdr\"", mat, R, 1e-4, 1e-4, 2e-7);
  double residual[2] = {0, 0};
  int idx = 0;
  for (const std::string precision : {"double", "float"}) {
    const fs::path dir = fresh_out_dir("mdr");
    const RunSummary s = run_scene_text(text, dir, precision);
    INFO(precision);
    CHECK(s.effects == "plasticity, radius_growth");
    // guard counters and the largest R/R_o are reported (summary.json: model_counters)
    CHECK(counter_of(s, "mdr_guard_denominator") == 0);
    CHECK(counter_of(s, "mdr_guard_radius_cap") == 0);
    CHECK(counter_of(s, "mdr_guard_volume") == 0);
    const double ratio = counter_of(s, "mdr_max_radius_ratio");
    CHECK(ratio > 1.0);
    CHECK(ratio < 1.1);
    const auto c = read_csv_columns(dir / "timeseries.csv");
    const auto& f = c.at("force_floor");
    const auto& d = c.at("displacement_floor");
    // elastic start: Hertz MDR (25) within 1e-3 (the ellipse law differs by O(delta/R) < 1e-3 here)
    int hertz_checked = 0;
    for (std::size_t k = 1; k < f.size() && d[k] < 1e-6 * 1.0001 && d[k] > 0; ++k) {
      CHECK(f[k] == Approx(4.0 / 3.0 * Ee * std::sqrt(R) * std::pow(d[k], 1.5)).epsilon(1e-3));
      ++hertz_checked;
    }
    CHECK(hertz_checked == 5);
    // loading: the force grows; unloading: it reaches zero while the flat is still pushed in
    const std::size_t peak = static_cast<std::size_t>(std::max_element(f.begin(), f.end()) - f.begin());
    CHECK(d[peak] == Approx(1e-4).epsilon(1e-6));
    const std::size_t k = last_touch(f);
    REQUIRE(k > peak);
    residual[idx++] = d[k];
    CHECK(d[k] > 0.5e-4);  // residual overlap: more than half of delta_max stays plastic at E/Y = 50
    CHECK(f.back() == 0.0);
    fs::remove_all(dir);
  }
  CHECK(residual[1] == Approx(residual[0]).epsilon(1e-2));
}

TEST_CASE("mdr in the driver: elastic adhesive pull-off equals JKR, skin covers the adhesive range",
          "[driver][models][mdr]") {
  // E R / Delta gamma ~ 2.2e4 (Fig. 13(a)): R = 1 mm, E = 1e8 Pa, nu = 0.3, Delta gamma = 5 J/m^2,
  // no yield. xi = 1 (displacement control). The force minimum along the path is the JKR
  // pull-off 1.5 pi Delta gamma R (MDR kernel tests: within 1%).
  const double R = 1e-3, G = 5.0;
  const std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nsurface_energy = 5.0";
  const std::string text = press_scene("name = \"mdr\"", mat, R, 2.2e-5, 2.6e-5, 2e-8);
  const fs::path dir = fresh_out_dir("mdr-adh");
  const RunSummary s = run_scene_text(text, dir);
  CHECK(s.effects == "adhesion");
  const auto c = read_csv_columns(dir / "timeseries.csv");
  const auto& f = c.at("force_floor");
  const auto& d = c.at("displacement_floor");
  CHECK(min_of(f) == Approx(-1.5 * kPi * G * R).epsilon(0.01));
  const std::size_t k = last_touch(f);
  REQUIRE(k + 1 < f.size());
  CHECK(d[k] < 0.0);  // still attached at a gap
  CHECK(f.back() == 0.0);
  fs::remove_all(dir);
}

TEST_CASE("adhesive models: the skin must exceed the adhesive range", "[driver][models][scene]") {
  const std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nsurface_energy = 5.0";
  // default skin 0.2 R = 2e-4 m is above every range here; a tiny skin is refused with a message
  for (const std::string model : {"mdr", "jkr", "nan2022"}) {
    INFO(model);
    const std::string extra_model = model == "nan2022" ? "\nk_el_from = \"fixed\"\nk_el = 1e4" : "";
    const Scene ok =
        parse_scene_string(press_scene("name = \"" + model + "\"" + extra_model, mat, 1e-3, 1e-5, 1e-5, 1e-7));
    CHECK(ok.run.skin == Approx(2e-4));
    try {
      parse_scene_string(
          press_scene("name = \"" + model + "\"" + extra_model, mat, 1e-3, 1e-5, 1e-5, 1e-7, "skin = 1e-9\n"));
      FAIL("a skin below the adhesive range was accepted");
    } catch (const SceneError& e) {
      const std::string m = e.what();
      CHECK(m.find("run.skin = 1e-09 is not larger than the adhesive range") != std::string::npos);
      CHECK(m.find(model) != std::string::npos);
    }
  }
  // a large surface energy on a small sphere: the default skin is raised above the range
  const std::string sticky = "youngs_modulus = 1e6\npoisson_ratio = 0.3\nsurface_energy = 50.0";
  const Scene big = parse_scene_string(press_scene("name = \"jkr\"", sticky, 1e-4, 1e-6, 1e-6, 1e-8));
  const double Es = 1e6 / 0.91;
  const double delta_c = 0.75 * std::cbrt(kPi * kPi * 50.0 * 50.0 * 1e-4 / (Es * Es));
  CHECK(delta_c > 0.2e-4);
  CHECK(big.run.skin == Approx(1.25 * delta_c).epsilon(1e-9));
}

TEST_CASE("mdr in the driver: contact_penalty = \"on\" weights a contact through a third particle",
          "[driver][models][mdr][penalty]") {
  // a and b (R = 1 mm) 1.98 mm apart, c (0.42 mm) between them at alpha = pi/2 (w = 1/2 exactly on
  // ab; models/mdr/mdr_contact_penalty.hpp); all driven at rest: step 0's forces in contacts.csv
  auto scene = [](const std::string& penalty) {
    return std::string(
               "[materials.ball]\nyoungs_modulus = 1e8\npoisson_ratio = 0.3\nyield_stress = 2e6\n"
               "density = 1000\n[model]\nname = \"mdr\"\n") +
           penalty +
           "\n[particles]\nallow_overlap = true\n[[particles.list]]\nposition = [0, 0, 0]\nradius = 1e-3\nmaterial = "
           "\"ball\"\ndriven = true\n"
           "[[particles.list]]\nposition = [1.98e-3, 0, 0]\nradius = 1e-3\nmaterial = \"ball\"\ndriven = true\n"
           "[[particles.list]]\nposition = [0.99e-3, 0.99e-3, 0]\nradius = 0.42e-3\nmaterial = \"ball\"\n"
           "driven = true\n[run]\ndt = 1e-7\nsteps = 1\noutput_interval = 1\ncontact_output = true\n";
  };
  std::map<std::pair<int, int>, double> force[2];
  for (int on = 0; on < 2; ++on) {
    const fs::path dir = fresh_out_dir("mdr_penalty");
    run_scene_text(scene(on ? "contact_penalty = \"on\"" : ""), dir);
    const auto c = read_csv_columns(dir / "contacts.csv");
    for (std::size_t k = 0; k < c.at("i").size(); ++k)
      if (c.at("step")[k] == 0.0) {
        const int i = int(c.at("i")[k]), j = int(c.at("j")[k]);
        force[on][{std::min(i, j), std::max(i, j)}] = c.at("force")[k];
      }
    fs::remove_all(dir);
  }
  REQUIRE(force[0].size() == 3);
  REQUIRE(force[1].size() == 3);
  CHECK(force[0].at({0, 1}) > 0.0);
  CHECK(force[1].at({0, 1}) == Approx(0.5 * force[0].at({0, 1})).epsilon(1e-12));
  CHECK(force[1].at({0, 2}) == force[0].at({0, 2}));
  CHECK(force[1].at({1, 2}) == force[0].at({1, 2}));
}

TEST_CASE("mdr in the driver: psi_b > 0 (Part II) stiffens a confined sphere and stops its growth",
          "[driver][models][mdr][bulk]") {
  // A driven sphere (R = 1 mm, E/Y 100) squeezed evenly by six rigid walls to 8% of R: its free
  // surface fraction falls to about 0.76 (A_con = 6 pi R delta of 4 pi R^2), so psi_b = 0.9 turns
  // the bulk response on about halfway (models/mdr/mdr_bulk_response.hpp); psi_b = 0 is Part I.
  auto scene = [](double psi_b) {
    std::string walls;
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 6; ++k) {
      const int a = k / 2;
      const double sgn = k % 2 == 0 ? -1.0 : 1.0;
      double pt[3] = {0, 0, 0}, n[3] = {0, 0, 0}, v[3] = {0, 0, 0};
      pt[a] = sgn * 1e-3;
      n[a] = -sgn;
      v[a] = -sgn * 0.8;  // 8e-5 m over 1e-4 s
      char b[512];
      std::snprintf(b, sizeof b,
                    "[[walls]]\nname = \"%s%d\"\npoint = [%g, %g, %g]\nnormal = [%g, %g, %g]\nmaterial = \"plate\"\n"
                    "motion = [{duration = 1e-4, velocity = [%g, %g, %g]}]\n",
                    axes[a], k % 2, pt[0], pt[1], pt[2], n[0], n[1], n[2], v[0], v[1], v[2]);
      walls += b;
    }
    char m[256];
    std::snprintf(m, sizeof m, "[model]\nname = \"mdr\"\npair_split = \"geometric\"\npsi_b = %g\n", psi_b);
    return std::string(
               "[materials.ball]\nyoungs_modulus = 1e8\npoisson_ratio = 0.3\nyield_stress = 1e6\ndensity = 1000\n"
               "[materials.plate]\nrigid = true\n") +
           m + "[[particles.list]]\nposition = [0, 0, 0]\nradius = 1e-3\nmaterial = \"ball\"\ndriven = true\n" + walls +
           "[run]\ndt = 1e-8\nsteps = 10000\noutput_interval = 100\n";
  };
  double f_end[2], ratio[2];
  for (int on = 0; on < 2; ++on) {
    const fs::path dir = fresh_out_dir("mdr_bulk");
    const RunSummary s = run_scene_text(scene(on ? 0.9 : 0.0), dir);
    CHECK(s.effects == (on ? "plasticity, radius_growth, bulk_response" : "plasticity, radius_growth"));
    const auto c = read_csv_columns(dir / "timeseries.csv");
    const auto& f = c.at("force_x0");
    f_end[on] = f.back();
    for (double x : f) REQUIRE(std::isfinite(x));
    ratio[on] = counter_of(s, "mdr_max_radius_ratio");
    if (on) CHECK(counter_of(s, "mdr_guard_bulk_volume") == 0.0);  // V_geo never near its floor here
    fs::remove_all(dir);
  }
  CHECK(f_end[0] > 0.0);
  CHECK(f_end[1] > 1.5 * f_end[0]);  // the bulk force adds to the frozen MDR force
  CHECK(ratio[1] < ratio[0]);        // growth stopped once confined
  CHECK(ratio[1] > 1.0);             // but not before
}

TEST_CASE("model keys are range-checked on parse", "[driver][models][scene]") {
  const std::string mat = "youngs_modulus = 1e8\npoisson_ratio = 0.3\nyield_stress = 2e6";
  auto message = [&](const std::string& model_block) {
    try {
      parse_scene_string(press_scene(model_block, mat, 1e-3, 1e-5, 1e-5, 1e-7));
    } catch (const SceneError& e) { return std::string(e.what()); }
    return std::string("accepted");
  };
  CHECK(message("name = \"mdr\"\nxi = 2") ==
        "model.xi = 2 is outside the valid set {1, 3} (MDR (15): 1 displacement "
        "control, 3 force control)");
  CHECK(message("name = \"mdr\"\nxi = 3") == "accepted");
  CHECK(
      message("name = \"mdr\"\ngrowth_rule = \"sometimes\"")
          .find("model.growth_rule = \"sometimes\" is not valid (valid: \"plastic_loading\", \"yielded_contacts\")") ==
      0);
  CHECK(message("name = \"mdr\"\ngrowth_rule = 1").find("model.growth_rule must be a string") == 0);
  CHECK(message("name = \"mdr\"\nradius_cap = 0.5").find("model.radius_cap = 0.5 is outside") == 0);
  CHECK(message("name = \"mdr\"\ncontact_penalty = \"on\"") == "accepted");
  CHECK(message("name = \"mdr\"\npsi_b = 1.5").find("model.psi_b = 1.5 is outside") == 0);
  CHECK(message("name = \"mdr\"\npsi_b = 0.5").find("pair_split = geometric") != std::string::npos);
  CHECK(message("name = \"mdr\"\npsi_b = 0.5\npair_split = \"geometric\"") == "accepted");
  CHECK(message("name = \"mdr\"\npsi_b = 0.5\npair_split = \"geometric\"\neffects = [\"plasticity\"]")
            .find("needs the bulk_response effect") != std::string::npos);
  CHECK(message("name = \"mdr\"\npair_split = \"geometric\"\neffects = [\"plasticity\", \"bulk_response\"]")
            .find("bulk_response needs model.psi_b > 0") != std::string::npos);
  CHECK(message("name = \"mdr\"\ncontact_penalty = \"yes\"")
            .find("model.contact_penalty = \"yes\" is not valid (valid: \"off\", \"on\")") == 0);
  CHECK(
      message("name = \"mdr\"\neffects = [\"radius_growth\"]").find("model.effects: radius_growth needs plasticity") ==
      0);
  CHECK(message("name = \"nan2022\"\nk_p_ratio = 1.5").find("model.k_p_ratio = 1.5 is outside") == 0);
  CHECK(message("name = \"nan2022\"\nunloading_law = \"plastic_offset\"\npull_off_law = \"stiffness_power\"") ==
        "accepted");
  CHECK(message("name = \"nan2022\"\nk_el_from = \"fixed\"").find("k_el") != std::string::npos);
  CHECK(message("name = \"jkr\"\nxi = 1").find("unknown key 'xi' in [model]") == 0);
  // the effect set: plasticity implies radius growth for mdr, not for nan2022
  CHECK(parse_scene_string(press_scene("name = \"mdr\"", mat, 1e-3, 1e-5, 1e-5, 1e-7)).model.effects ==
        (kPlasticity | kRadiusGrowth));
  CHECK(parse_scene_string(press_scene("name = \"mdr\"\neffects = [\"plasticity\"]", mat, 1e-3, 1e-5, 1e-5, 1e-7))
            .model.effects == kPlasticity);
  CHECK(parse_scene_string(press_scene("name = \"nan2022\"", mat, 1e-3, 1e-5, 1e-5, 1e-7)).model.effects ==
        kPlasticity);
  CHECK(parse_scene_string(press_scene("name = \"jkr\"", mat, 1e-3, 1e-5, 1e-5, 1e-7)).model.notes.size() == 1);
}
