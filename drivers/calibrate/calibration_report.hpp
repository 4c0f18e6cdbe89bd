#pragma once
// epac-calibrate's outputs: the printed table, the JSON document and the [model] keys of an
// epac-run scene that use the calibrated stiffnesses.
#include "calibrate/curve_calibration.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace epac {
namespace calibrate {

// Human-readable report: inputs, Table 2 style per-curve numbers, Table 3 style results.
std::string format_report(const CalibrationResult& r);

// (key, value) of the epac-run scene's [model] table for model nan2022 (strings and numbers).
std::vector<std::pair<std::string, nlohmann::json>> scene_model_keys(const CalibrationResult& r);

// The [model] table as TOML text, with a comment on the materials it assumes.
std::string format_scene_keys(const CalibrationResult& r);

// Everything in SI units (see drivers/calibrate/README.md for the layout).
nlohmann::json to_json(const CalibrationResult& r);

}  // namespace calibrate
}  // namespace epac
