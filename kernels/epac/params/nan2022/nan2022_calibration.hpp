#pragma once
// Calibration of the Nan et al. 2022 model from measured loading/unloading curves (host, Eigen),
// Nan Sec. 3.3: per unloading curve f_max, alpha_max, alpha_p, f_cp (Table 2) and k_e (Nan (50));
// k_p from the peaks (Nan (51)); then k_el, alpha_y, alpha_0 and k_el/k_cl (Table 3) from the
// curve with the largest alpha_max as (k_e0, alpha_max0), by Nan (29) with (45) (or (49)).
//
// A command-line tool needs: curves (drivers/calibrate reads them from CSV) -> nan2022_calibrate(curves, input)
// -> print Nan2022Calibration (and pass k_el, k_p as Nan2022Options::k_el / k_p, k_el_from = fixed).
#include <epac/params/nan2022/force_overlap_curve.hpp>
#include <epac/params/nan2022/nan2022_parameters.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace epac {

// One unloading curve reduced to the numbers of Nan Table 2.
struct Nan2022UnloadingSummary {
  double f_max = 0, alpha_max = 0, alpha_p = 0, f_cp = 0;
};

enum class Nan2022UnloadingFit {
  secant,         // k_e = f_max / (alpha_max - alpha_p), Nan (50)
  least_squares,  // slope of a least-squares line through the unloading samples with f >= 0
};
enum class Nan2022PlasticFit {
  secants,        // mean of the secants between consecutive peaks (sorted by alpha_max), Nan (51)
  least_squares,  // slope of a least-squares line through all peaks (alpha_max, f_max)
};

struct Nan2022CalibrationInput {
  double E_star = 0, R_star = 0, surface_energy = 0, yield_pressure = 0;      // of the tested contact
  Nan2022UnloadingLaw unloading_law = Nan2022UnloadingLaw::sqrt_max_overlap;  // (45) or (49)
  Nan2022UnloadingFit unloading_fit = Nan2022UnloadingFit::secant;
  Nan2022PlasticFit plastic_fit = Nan2022PlasticFit::secants;
};

struct Nan2022Calibration {
  std::vector<Nan2022UnloadingSummary> curves;                // host
  std::vector<double> k_e;                                    // host; per curve, Nan (50)
  double k_p = 0;                                             // Nan (51)
  double k_e0 = 0, alpha_max0 = 0;                            // the reference unloading line
  double k_el = 0, alpha_y = 0, alpha_0 = 0, el_over_cl = 0;  // Table 3
  int iterations = 0;
};

// Reduces a measured curve (loading then unloading, in sample order) to Table 2's numbers:
// the peak is the sample of largest overlap; alpha_p is where the unloading branch first crosses
// zero force (linear interpolation); f_cp is minus the most negative force after the peak.
inline Nan2022UnloadingSummary nan2022_summarize_curve(const ForceOverlapCurve& c, int index = 0) {
  const std::string name = "curve " + std::to_string(index + 1);  // host
  if (c.overlap.size() != c.force.size() || c.overlap.size() < 3)
    throw ParameterError(name + ": needs at least 3 (overlap, force) samples");  // host
  const std::size_t n = c.overlap.size();
  std::size_t peak = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (c.overlap[k] > c.overlap[peak]) peak = k;
  Nan2022UnloadingSummary s;
  s.alpha_max = c.overlap[peak];
  s.f_max = c.force[peak];
  require_positive(name + ": force at the largest overlap", s.f_max);
  bool crossed = false;
  for (std::size_t k = peak + 1; k < n; ++k) {
    if (c.force[k] <= 0) {
      const double f0 = c.force[k - 1], f1 = c.force[k];
      const double t = f0 > f1 ? f0 / (f0 - f1) : 0.0;  // f0 > 0 >= f1
      s.alpha_p = c.overlap[k - 1] + t * (c.overlap[k] - c.overlap[k - 1]);
      crossed = true;
      break;
    }
  }
  if (!crossed) throw ParameterError(name + ": the unloading branch never reaches zero force");  // host
  double fmin = 0;
  for (std::size_t k = peak; k < n; ++k) fmin = std::min(fmin, c.force[k]);
  s.f_cp = -fmin;
  require_range(name + ": alpha_max - alpha_p", s.alpha_max - s.alpha_p, 0.0, Bound::open,
                std::numeric_limits<double>::infinity(), Bound::open);
  return s;
}

// Least-squares slope of y against x (Eigen, QR on [x 1]).
inline double nan2022_fit_slope(const std::vector<double>& x, const std::vector<double>& y) {  // host
  require_range("points in the line fit", static_cast<double>(x.size()), 2, Bound::closed, 1e18, Bound::open);
  Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), 2);
  Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
  const double x0 = x.front();  // shift for conditioning (overlaps ~1e-9 m)
  for (std::size_t k = 0; k < x.size(); ++k) {
    A(static_cast<Eigen::Index>(k), 0) = x[k] - x0;
    A(static_cast<Eigen::Index>(k), 1) = 1.0;
    b(static_cast<Eigen::Index>(k)) = y[k];
  }
  const Eigen::VectorXd sol = A.colPivHouseholderQr().solve(b);
  return sol(0);
}

inline double nan2022_unloading_slope_fit(const ForceOverlapCurve& c) {  // host
  std::size_t peak = 0;
  for (std::size_t k = 1; k < c.overlap.size(); ++k)
    if (c.overlap[k] > c.overlap[peak]) peak = k;
  std::vector<double> x, y;  // host
  for (std::size_t k = peak; k < c.overlap.size() && c.force[k] >= 0; ++k) {
    x.push_back(c.overlap[k]);
    y.push_back(c.force[k]);
  }
  return nan2022_fit_slope(x, y);
}

// From Table 2's numbers (and optional per-curve fitted k_e).
inline Nan2022Calibration nan2022_calibrate(const std::vector<Nan2022UnloadingSummary>& curves,  // host
                                            const Nan2022CalibrationInput& in,
                                            const std::vector<double>& k_e_fitted = {}) {  // host
  require_positive("E_star", in.E_star);
  require_positive("R_star", in.R_star);
  require_range("surface_energy", in.surface_energy, 0.0, Bound::closed, std::numeric_limits<double>::infinity(),
                Bound::open);
  require_positive("yield_pressure", in.yield_pressure);
  require_range("number of unloading curves", static_cast<double>(curves.size()), 2, Bound::closed, 1e9, Bound::open);
  Nan2022Calibration r;
  r.curves = curves;
  std::sort(r.curves.begin(), r.curves.end(), [](const Nan2022UnloadingSummary& a, const Nan2022UnloadingSummary& b) {
    return a.alpha_max > b.alpha_max;
  });
  for (std::size_t i = 0; i < r.curves.size(); ++i) {
    const auto& s = r.curves[i];
    require_positive("curve alpha_max - alpha_p", s.alpha_max - s.alpha_p);
    r.k_e.push_back(s.f_max / (s.alpha_max - s.alpha_p));  // Nan (50)
  }
  if (!k_e_fitted.empty()) {
    require_range("fitted k_e count", static_cast<double>(k_e_fitted.size()), static_cast<double>(curves.size()),
                  Bound::closed, static_cast<double>(curves.size()), Bound::closed);
    // k_e_fitted follows the input order; re-sort with the curves
    std::vector<std::size_t> idx(curves.size());  // host
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(),
              [&](std::size_t a, std::size_t b) { return curves[a].alpha_max > curves[b].alpha_max; });
    for (std::size_t i = 0; i < idx.size(); ++i) r.k_e[i] = k_e_fitted[idx[i]];
  }
  // k_p, Nan (51): with the peaks sorted by alpha_max, the mean of consecutive secants
  if (in.plastic_fit == Nan2022PlasticFit::secants) {
    double sum = 0;
    for (std::size_t i = 0; i + 1 < r.curves.size(); ++i) {
      const auto& a = r.curves[i];
      const auto& b = r.curves[i + 1];
      require_positive("alpha_max spacing between unloading curves", a.alpha_max - b.alpha_max);
      sum += (a.f_max - b.f_max) / (a.alpha_max - b.alpha_max);
    }
    r.k_p = sum / static_cast<double>(r.curves.size() - 1);
  } else {
    std::vector<double> x, y;  // host
    for (const auto& s : r.curves) {
      x.push_back(s.alpha_max);
      y.push_back(s.f_max);
    }
    r.k_p = nan2022_fit_slope(x, y);
  }
  require_positive("k_p (loading peaks must rise with alpha_max)", r.k_p);
  r.k_e0 = r.k_e.front();
  r.alpha_max0 = r.curves.front().alpha_max;
  const auto el = nan2022_k_el_from_unloading(in.E_star, in.R_star, in.surface_energy, in.yield_pressure, r.k_e0,
                                              r.alpha_max0, in.unloading_law, r.k_p);
  r.k_el = el.k_el;
  r.alpha_y = el.alpha_y;
  r.alpha_0 = el.alpha_0;
  r.iterations = el.iterations;
  Nan2022PairConstants<double> p{};
  p.E_star = in.E_star;
  p.surface_energy = in.surface_energy;
  p.yield_pressure = in.yield_pressure;
  p.yields = 1;
  p.kel_fixed = 1;
  p.kel_value = r.k_el;
  p.kp_fixed = 1;
  p.kp_value = r.k_p;
  r.el_over_cl = nan2022_contact_constants<double>(p, in.R_star).el_over_cl;
  return r;
}

// From measured curves.
inline Nan2022Calibration nan2022_calibrate(const std::vector<ForceOverlapCurve>& curves,  // host
                                            const Nan2022CalibrationInput& in) {
  std::vector<Nan2022UnloadingSummary> s;  // host
  std::vector<double> fitted;              // host
  for (std::size_t i = 0; i < curves.size(); ++i) {
    s.push_back(nan2022_summarize_curve(curves[i], static_cast<int>(i)));
    if (in.unloading_fit == Nan2022UnloadingFit::least_squares)
      fitted.push_back(nan2022_unloading_slope_fit(curves[i]));
  }
  return nan2022_calibrate(s, in, fitted);
}

}  // namespace epac
