#include "calibrate/curve_calibration.hpp"
#include "calibrate/force_overlap_csv.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace epac {
namespace calibrate {

namespace {

double unit_factor(const std::string& option, const std::string& unit,
                   const std::vector<std::pair<std::string, double>>& table) {
  std::string valid;
  for (const auto& u : table) {
    if (u.first == unit) return u.second;
    valid += (valid.empty() ? "" : ", ") + u.first;
  }
  throw ParameterError(option + " = " + unit + " is not a known unit (valid: " + valid + ")");
}

// Every material input must be finite and in range; the message uses the option's name.
void validate_request(const CalibrationRequest& r) {
  const double inf = std::numeric_limits<double>::infinity();
  if (r.files.empty()) throw ParameterError("no curve files given (CURVES.csv ...)");
  require_positive("--E-star", r.E_star);
  require_positive("--R-star", r.R_star);
  require_range("--surface-energy", r.surface_energy, 0.0, Bound::closed, inf, Bound::open);
  require_positive("--yield-pressure", r.yield_pressure);
  if (r.unloading_law != "sqrt_max_overlap" && r.unloading_law != "plastic_offset")
    throw ParameterError("--unloading-law = " + r.unloading_law +
                         " is not valid (valid: sqrt_max_overlap, plastic_offset)");
  if (r.unloading_fit != "secant" && r.unloading_fit != "least_squares")
    throw ParameterError("--unloading-fit = " + r.unloading_fit + " is not valid (valid: secant, least_squares)");
  if (r.plastic_fit != "secants" && r.plastic_fit != "least_squares")
    throw ParameterError("--plastic-fit = " + r.plastic_fit + " is not valid (valid: secants, least_squares)");
}

}  // namespace

double overlap_unit_factor(const std::string& unit) {
  return unit_factor("--overlap-unit", unit, {{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}});
}

double force_unit_factor(const std::string& unit) {
  return unit_factor("--force-unit", unit, {{"N", 1.0}, {"mN", 1e-3}, {"uN", 1e-6}, {"nN", 1e-9}});
}

CalibrationResult run_calibration(const CalibrationRequest& request) {
  validate_request(request);
  const double ou = overlap_unit_factor(request.overlap_unit);
  const double fu = force_unit_factor(request.force_unit);

  CalibrationResult out;
  out.request = request;
  Nan2022CalibrationInput& in = out.input;
  in.E_star = request.E_star;
  in.R_star = request.R_star;
  in.surface_energy = request.surface_energy;
  in.yield_pressure = request.yield_pressure;
  in.unloading_law = request.unloading_law == "plastic_offset" ? Nan2022UnloadingLaw::plastic_offset
                                                               : Nan2022UnloadingLaw::sqrt_max_overlap;
  in.unloading_fit =
      request.unloading_fit == "least_squares" ? Nan2022UnloadingFit::least_squares : Nan2022UnloadingFit::secant;
  in.plastic_fit =
      request.plastic_fit == "least_squares" ? Nan2022PlasticFit::least_squares : Nan2022PlasticFit::secants;

  // Read and reduce each curve here (not inside nan2022_calibrate) so that errors and the report
  // name the file and column pair rather than a running index.
  std::vector<Nan2022UnloadingSummary> summaries;
  std::vector<double> fitted;
  std::vector<CurveSource> sources;
  for (const auto& path : request.files) {
    const std::vector<ForceOverlapCurve> curves = read_force_overlap_csv(path);
    for (std::size_t c = 0; c < curves.size(); ++c) {
      CurveSource src;
      src.label = curves.size() > 1 ? path + ", column pair " + std::to_string(c + 1) : path;
      ForceOverlapCurve si = curves[c];
      for (double& a : si.overlap) a *= ou;
      for (double& f : si.force) f *= fu;
      src.samples = si.overlap.size();
      try {
        summaries.push_back(nan2022_summarize_curve(si, 0));
        if (in.unloading_fit == Nan2022UnloadingFit::least_squares) fitted.push_back(nan2022_unloading_slope_fit(si));
      } catch (const ParameterError& e) {
        // nan2022_summarize_curve says "curve 1: ..."; say which file instead
        std::string msg = e.what();
        const std::string generic = "curve 1: ";
        if (msg.compare(0, generic.size(), generic) == 0) msg = msg.substr(generic.size());
        throw ParameterError(src.label + ": " + msg);
      }
      sources.push_back(src);
    }
  }
  if (summaries.size() < 2)
    throw ParameterError("the calibration needs at least 2 unloading curves (k_p, Nan (51)); got " +
                         std::to_string(summaries.size()));

  // Sort by alpha_max (largest first) here, as nan2022_calibrate does, to keep the labels aligned.
  std::vector<std::size_t> order(summaries.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return summaries[a].alpha_max > summaries[b].alpha_max; });
  std::vector<Nan2022UnloadingSummary> sorted;
  std::vector<double> sorted_fit;
  for (std::size_t i : order) {
    sorted.push_back(summaries[i]);
    out.sources.push_back(sources[i]);
    if (!fitted.empty()) sorted_fit.push_back(fitted[i]);
  }
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i)
    if (!(sorted[i].alpha_max > sorted[i + 1].alpha_max))
      throw ParameterError(out.sources[i].label + " and " + out.sources[i + 1].label + " have the same alpha_max = " +
                           std::to_string(sorted[i].alpha_max) + " m: k_p (Nan (51)) needs distinct peaks");
  out.result = nan2022_calibrate(sorted, in, sorted_fit);
  return out;
}

}  // namespace calibrate
}  // namespace epac
