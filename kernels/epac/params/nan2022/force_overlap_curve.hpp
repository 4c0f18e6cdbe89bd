#pragma once
// One measured force-overlap curve (host), the input of the Nan 2022 calibration
// (nan2022_calibration.hpp). Reading curves from files is the tool's job
// (drivers/calibrate/force_overlap_csv.hpp), not the library's.
#include <vector>

namespace epac {

struct ForceOverlapCurve {
  std::vector<double> overlap;  // host
  std::vector<double> force;    // host
};

}  // namespace epac
