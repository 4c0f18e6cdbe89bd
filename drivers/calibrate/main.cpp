// epac-calibrate CURVES.csv [more.csv ...] --E-star .. --R-star .. --surface-energy ..
//                --yield-pressure .. [--unloading-law ..] [--json OUT] ...
// Calibrates the Nan et al. 2022 model from measured loading/unloading curves (Nan Sec. 3.3) and
// prints the [model] keys of an epac-run scene. Exit status: 0 success, 2 invalid input (the
// message names the file, option or value), 1 any other failure; command-line errors use CLI11's.
#include "calibrate/calibration_report.hpp"
#include "calibrate/curve_calibration.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{
      "epac-calibrate: Nan et al. 2022 k_e, k_p, k_el, alpha_y, alpha_0, k_el/k_cl from loading/unloading "
      "curves (Nan Sec. 3.3)"};
  epac::calibrate::CalibrationRequest q;
  std::string json_path;
  bool no_scene = false;
  app.add_option("curves", q.files,
                 "CSV files: overlap,force (one curve), or overlap_1,force_1,overlap_2,force_2,... (one curve per "
                 "column pair); each curve loads then unloads past pull-off")
      ->required();
  // Numbers are validated by run_calibration (messages name the option and its value), not by
  // CLI11 checks, so a negative or NaN value gets the same message as from the library.
  app.add_option("--E-star", q.E_star,
                 "effective modulus E* of the tested contact [Pa] (particle on a rigid wall: "
                 "E/(1-nu^2))")
      ->required();
  app.add_option("--R-star", q.R_star, "effective radius R* of the tested contact [m]")->required();
  app.add_option("--surface-energy", q.surface_energy, "surface energy Gamma [J/m^2] (>= 0)")->required();
  app.add_option("--yield-pressure", q.yield_pressure, "yield pressure p_y [Pa]")->required();
  app.add_option("--unloading-law", q.unloading_law,
                 "sqrt_max_overlap: k_e = k_el sqrt(a_max/a_y), Nan (45) (default); plastic_offset: Nan (49)");
  app.add_option("--unloading-fit", q.unloading_fit,
                 "k_e per curve: secant f_max/(a_max - a_p), Nan (50) (default); least_squares: line through the "
                 "unloading samples with f >= 0");
  app.add_option("--plastic-fit", q.plastic_fit,
                 "k_p: secants, mean of consecutive peak secants, Nan (51) (default); least_squares through the peaks");
  app.add_option("--overlap-unit", q.overlap_unit, "unit of the overlap column: m (default), mm, um, nm");
  app.add_option("--force-unit", q.force_unit, "unit of the force column: N (default), mN, uN, nN");
  app.add_option("--json", json_path, "also write the results as JSON (SI units) to this file");
  app.add_flag("--no-scene-keys", no_scene, "do not print the epac-run [model] keys");
  CLI11_PARSE(app, argc, argv);

  epac::calibrate::CalibrationResult r;
  try {
    r = epac::calibrate::run_calibration(q);
  } catch (const epac::ParameterError& e) {
    std::fprintf(stderr, "epac-calibrate: invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epac-calibrate: error: %s\n", e.what());
    return 1;
  }
  std::cout << epac::calibrate::format_report(r);
  if (!no_scene) std::cout << "\n" << epac::calibrate::format_scene_keys(r);
  if (!json_path.empty()) {
    std::ofstream f(json_path);
    if (!f) {
      std::fprintf(stderr, "epac-calibrate: error: cannot write --json = %s\n", json_path.c_str());
      return 1;
    }
    f << epac::calibrate::to_json(r).dump(2) << "\n";
    if (!f) {
      std::fprintf(stderr, "epac-calibrate: error: writing --json = %s failed\n", json_path.c_str());
      return 1;
    }
    std::cout << "\nwrote " << json_path << "\n";
  }
  return 0;
}
