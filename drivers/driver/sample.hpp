#pragma once
// One row of timeseries.csv (host side). Columns are documented in drivers/README.md.
#include <array>
#include <cstdint>
#include <vector>

namespace epac {
namespace driver {

struct Sample {
  std::int64_t step = 0;
  double time = 0;
  double ke_translational = 0;                        // sum 1/2 m v^2 [J] (driven particles included)
  double ke_rotational = 0;                           // sum 1/2 I omega^2 [J]
  double pe_gravity = 0;                              // -sum m g . x [J] (zero at the origin)
  std::int64_t pair_contacts = 0, wall_contacts = 0;  // active: overlap > 0
  std::int64_t pair_list = 0, wall_list = 0;          // list entries (within the skin)
  double max_overlap_ratio = 0;                       // max delta / min(R_i, R_j) over pairs, delta / R_i over walls
  std::vector<double> wall_force;                     // per wall: sum of normal contact forces [N], > 0 pressing
  std::vector<double> wall_displacement;              // per wall: displacement along its normal since t = 0 [m]
  std::array<double, 3> driven_force{0, 0, 0};        // contact force on the driven particles [N]
  std::array<double, 3> box_edge{0, 0, 0};            // box edges [m] (columns only with a [box])
};

}  // namespace driver
}  // namespace epac
