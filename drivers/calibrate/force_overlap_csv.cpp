#include "calibrate/force_overlap_csv.hpp"

#include <epac/params/validation.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace epac {
namespace calibrate {

namespace {
// Splits a line into cells; an empty cell between separators is kept (as "").
std::vector<std::string> split_cells(const std::string& line) {  // host
  std::vector<std::string> cells;                                // host
  std::string cur;                                               // host
  bool any = false;
  const bool has_delim = line.find_first_of(",;\t") != std::string::npos;  // host
  for (char ch : line) {
    const bool sep = has_delim ? (ch == ',' || ch == ';' || ch == '\t') : (ch == ' ');
    if (sep) {
      if (has_delim || !cur.empty()) cells.push_back(cur);
      cur.clear();
      any = true;
    } else if (ch != '\r' && !(has_delim && ch == ' ')) {
      cur += ch;
    }
  }
  if (!cur.empty() || (any && has_delim)) cells.push_back(cur);
  return cells;
}
bool parse_number(const std::string& s, double& v) {  // host
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == '\0';
}
}  // namespace

std::vector<ForceOverlapCurve> parse_force_overlap_csv(std::istream& in, const std::string& source) {  // host
  std::vector<ForceOverlapCurve> curves;                                                               // host
  std::string line;                                                                                    // host
  int lineno = 0;
  bool first_data = true;
  while (std::getline(in, line)) {
    ++lineno;
    const auto p = line.find_first_not_of(" \t\r");
    if (p == std::string::npos || line[p] == '#') continue;  // host
    const auto cells = split_cells(line);
    std::vector<double> vals(cells.size());   // host
    std::vector<bool> present(cells.size());  // host
    bool numeric = true;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      present[k] = parse_number(cells[k], vals[k]);
      if (!present[k] && !cells[k].empty()) numeric = false;
    }
    if (!numeric) {
      if (first_data && curves.empty()) {
        first_data = false;
        continue;
      }                                                                                                      // header
      throw ParameterError(source + ":" + std::to_string(lineno) + ": non-numeric cell in '" + line + "'");  // host
    }
    first_data = false;
    if (cells.size() < 2 || cells.size() % 2 != 0)
      throw ParameterError(source + ":" + std::to_string(lineno) +
                           ": expected an even number of columns "  // host
                           "(overlap, force pairs), got " +
                           std::to_string(cells.size()));  // host
    if (curves.empty()) curves.resize(cells.size() / 2);
    if (cells.size() / 2 != curves.size())
      throw ParameterError(source + ":" + std::to_string(lineno) + ": column count changed");  // host
    for (std::size_t c = 0; c < curves.size(); ++c) {
      const bool a = present[2 * c], b = present[2 * c + 1];
      if (a != b)
        throw ParameterError(source + ":" + std::to_string(lineno) + ": curve " + std::to_string(c + 1) +  // host
                             " has an overlap without a force or the reverse");                            // host
      if (a) {
        curves[c].overlap.push_back(vals[2 * c]);
        curves[c].force.push_back(vals[2 * c + 1]);
      }
    }
  }
  if (curves.empty()) throw ParameterError(source + ": no data");  // host
  return curves;
}

std::vector<ForceOverlapCurve> read_force_overlap_csv(const std::string& path) {  // host
  std::ifstream f(path);
  if (!f) throw ParameterError("cannot open force-overlap file '" + path + "'");  // host
  return parse_force_overlap_csv(f, path);
}

}  // namespace calibrate
}  // namespace epac
