#pragma once
// Reads measured force-overlap curves from CSV (epac-calibrate; moved out of the library, which
// has no file formats of its own). Layouts:
//   overlap,force                         one curve
//   overlap_1,force_1,overlap_2,force_2   one curve per column pair; shorter curves leave cells empty
// Separators: comma, semicolon, tab or spaces. Lines starting with '#' are comments; a first line
// that is not numeric is a header. Units are whatever the caller uses consistently (SI: m, N).
// Errors throw epac::ParameterError naming the source and line.
#include <epac/params/nan2022/force_overlap_curve.hpp>

#include <istream>
#include <string>
#include <vector>

namespace epac {
namespace calibrate {

std::vector<ForceOverlapCurve> parse_force_overlap_csv(std::istream& in, const std::string& source = "csv");
std::vector<ForceOverlapCurve> read_force_overlap_csv(const std::string& path);

}  // namespace calibrate
}  // namespace epac
