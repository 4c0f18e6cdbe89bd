#pragma once
// CSV column headers carry their units, "name [unit]" (e.g. "time [s]", "force_top [N]"); counts
// and ids have none. Programs that read the files look columns up by the name alone.
#include <string>

namespace epac {
namespace driver {

// "time [s]" -> "time"; a header without a unit is returned as it is.
inline std::string csv_column_name(const std::string& header) {
  const auto k = header.find(" [");
  return k == std::string::npos ? header : header.substr(0, k);
}

}  // namespace driver
}  // namespace epac
