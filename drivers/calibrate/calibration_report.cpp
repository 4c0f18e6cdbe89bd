#include "calibrate/calibration_report.hpp"

#include <cstdio>
#include <sstream>

namespace epac {
namespace calibrate {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// A TOML float that round-trips (TOML floats need a '.' or an exponent).
std::string toml_float(double v) {
  std::string s = fmt("%.9g", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

std::string format_report(const CalibrationResult& r) {
  const auto& c = r.result;
  const auto& q = r.request;
  std::ostringstream o;
  o << "Nan et al. 2022 calibration (Nan Sec. 3.3)\n";
  o << "  E* = " << fmt("%.6g", q.E_star) << " Pa, R* = " << fmt("%.6g", q.R_star)
    << " m, Gamma = " << fmt("%.6g", q.surface_energy) << " J/m^2, p_y = " << fmt("%.6g", q.yield_pressure) << " Pa\n";
  o << "  unloading law " << q.unloading_law << (q.unloading_law == "plastic_offset" ? " (Nan (49))" : " (Nan (45))")
    << ", k_e by " << (q.unloading_fit == "secant" ? "Nan (50) secant" : "least-squares unloading line") << ", k_p by "
    << (q.plastic_fit == "secants" ? "Nan (51) mean secant" : "least-squares line through the peaks") << "\n\n";
  o << "Unloading curves (Table 2), largest alpha_max first:\n";
  o << "  #  f_max [uN]  alpha_max [nm]  alpha_p [nm]  f_cp [uN]   k_e [N/m]   samples  source\n";
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    const auto& s = c.curves[i];
    o << fmt("  %-2.0f", double(i + 1)) << fmt("%11.5g", s.f_max * 1e6) << fmt("%16.5g", s.alpha_max * 1e9)
      << fmt("%14.5g", s.alpha_p * 1e9) << fmt("%11.5g", s.f_cp * 1e6) << fmt("%12.5g", c.k_e[i])
      << fmt("%10.0f", double(r.sources[i].samples)) << "  " << r.sources[i].label << "\n";
  }
  o << "\nResults (Table 3):\n";
  o << "  k_p        = " << fmt("%.5g", c.k_p) << " N/m   (Nan (51))\n";
  o << "  k_e0       = " << fmt("%.5g", c.k_e0) << " N/m at alpha_max0 = " << fmt("%.5g", c.alpha_max0 * 1e9)
    << " nm (reference unloading line)\n";
  o << "  k_el       = " << fmt("%.5g", c.k_el) << " N/m   (Nan (29) with "
    << (q.unloading_law == "plastic_offset" ? "(49)" : "(45)") << ", " << c.iterations << " iterations)\n";
  o << "  alpha_y    = " << fmt("%.5g", c.alpha_y * 1e9) << " nm\n";
  o << "  alpha_0    = " << fmt("%.5g", c.alpha_0 * 1e9) << " nm\n";
  o << "  k_el/k_cl  = " << fmt("%.4g", c.el_over_cl) << "       (Nan (35)-(37))\n";
  return o.str();
}

std::vector<std::pair<std::string, nlohmann::json>> scene_model_keys(const CalibrationResult& r) {
  // Keys of drivers/driver/models/nan2022.cpp (named after Nan2022Options): k_el fixed for every
  // contact, k_p fixed (k_p > k_el is allowed, as for Du), the unloading law of the calibration.
  return {{"name", "nan2022"},    {"yield_pressure_from", "given_pressure"},
          {"k_el_from", "fixed"}, {"k_el", r.result.k_el},
          {"k_p", r.result.k_p},  {"unloading_law", r.request.unloading_law}};
}

std::string format_scene_keys(const CalibrationResult& r) {
  std::ostringstream o;
  o << "# epac-run scene keys (model nan2022) with the calibrated stiffnesses. k_el and k_p are\n"
    << "# those of the tested contact (R* = " << fmt("%.6g", r.request.R_star) << " m) and are used for every\n"
    << "# contact. The materials must give the tested pair: yield_stress = p_y = "
    << fmt("%.6g", r.request.yield_pressure) << " Pa\n"
    << "# (read as a pressure by yield_pressure_from = \"given_pressure\"), surface_energy = "
    << fmt("%.6g", r.request.surface_energy) << " J/m^2,\n"
    << "# and E* = " << fmt("%.6g", r.request.E_star) << " Pa.\n";
  o << "[model]\n";
  for (const auto& kv : scene_model_keys(r))
    o << kv.first << " = "
      << (kv.second.is_string() ? "\"" + kv.second.get<std::string>() + "\"" : toml_float(kv.second.get<double>()))
      << "\n";
  return o.str();
}

nlohmann::json to_json(const CalibrationResult& r) {
  const auto& c = r.result;
  const auto& q = r.request;
  nlohmann::json j;
  j["units"] = "SI (m, N, N/m, Pa, J/m^2)";
  j["input"] = {{"files", q.files},
                {"E_star", q.E_star},
                {"R_star", q.R_star},
                {"surface_energy", q.surface_energy},
                {"yield_pressure", q.yield_pressure},
                {"unloading_law", q.unloading_law},
                {"unloading_fit", q.unloading_fit},
                {"plastic_fit", q.plastic_fit},
                {"overlap_unit", q.overlap_unit},
                {"force_unit", q.force_unit}};
  nlohmann::json curves = nlohmann::json::array();
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    const auto& s = c.curves[i];
    curves.push_back({{"source", r.sources[i].label},
                      {"samples", r.sources[i].samples},
                      {"f_max", s.f_max},
                      {"alpha_max", s.alpha_max},
                      {"alpha_p", s.alpha_p},
                      {"f_cp", s.f_cp},
                      {"k_e", c.k_e[i]}});
  }
  j["curves"] = curves;
  j["k_p"] = c.k_p;
  j["k_e0"] = c.k_e0;
  j["alpha_max0"] = c.alpha_max0;
  j["k_el"] = c.k_el;
  j["alpha_y"] = c.alpha_y;
  j["alpha_0"] = c.alpha_0;
  j["k_el_over_k_cl"] = c.el_over_cl;
  j["iterations"] = c.iterations;
  nlohmann::json keys = nlohmann::json::object();
  for (const auto& kv : scene_model_keys(r)) keys[kv.first] = kv.second;
  j["scene_model_keys"] = keys;
  return j;
}

}  // namespace calibrate
}  // namespace epac
