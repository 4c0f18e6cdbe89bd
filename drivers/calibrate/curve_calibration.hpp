#pragma once
// epac-calibrate's library: measured loading/unloading curves (CSV files, any units) -> the
// Nan et al. 2022 calibration of Nan Sec. 3.3 (k_e per curve by Nan (50), k_p by Nan (51), then
// k_el, alpha_y, alpha_0 by Nan (29) with (45) or (49), and k_el/k_cl: Table 3). The command-line
// tool and the tests call the same function.
#include <epac/params/nan2022/nan2022_calibration.hpp>

#include <limits>
#include <string>
#include <vector>

namespace epac {
namespace calibrate {

// What the user asks for. Material inputs are of the tested contact, in SI units; the CSV cells
// are multiplied by overlap_unit [m] and force_unit [N].
struct CalibrationRequest {
  std::vector<std::string> files;                                    // one curve per file, or one curve per column pair
  double E_star = std::numeric_limits<double>::quiet_NaN();          // [Pa]
  double R_star = std::numeric_limits<double>::quiet_NaN();          // [m]
  double surface_energy = std::numeric_limits<double>::quiet_NaN();  // [J/m^2]
  double yield_pressure = std::numeric_limits<double>::quiet_NaN();  // [Pa]
  std::string unloading_law = "sqrt_max_overlap";                    // Nan (45), or plastic_offset: Nan (49)
  std::string unloading_fit = "secant";                              // Nan (50), or least_squares
  std::string plastic_fit = "secants";                               // Nan (51), or least_squares
  std::string overlap_unit = "m";                                    // m, mm, um, nm
  std::string force_unit = "N";                                      // N, mN, uN, nN
};

// One curve as read, with where it came from ("file.csv" or "file.csv, column pair 2").
struct CurveSource {
  std::string label;
  std::size_t samples = 0;
};

struct CalibrationResult {
  CalibrationRequest request;
  Nan2022CalibrationInput input;
  std::vector<CurveSource> sources;  // in the order of result.curves (largest alpha_max first)
  Nan2022Calibration result;         // SI units
};

// Unit factors; throw ParameterError naming the option and the valid names.
double overlap_unit_factor(const std::string& unit);
double force_unit_factor(const std::string& unit);

// Validates the request (every message names the option and its value), reads every curve,
// converts to SI and calibrates. Throws ParameterError on any bad input.
CalibrationResult run_calibration(const CalibrationRequest& request);

}  // namespace calibrate
}  // namespace epac
