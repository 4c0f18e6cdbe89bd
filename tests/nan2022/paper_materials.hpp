#pragma once
// The materials of Nan et al. 2022 used by the tests.
#include <epac/params/material.hpp>

namespace epac {
namespace test {

// Ning (1995), Nan Table 1: ammonium fluorescein on a rigid wall (E* = E/(1-nu^2)).
inline Material ning_particle() {
  Material m;
  m.name = "ning";
  m.youngs_modulus = 1.2e9;
  m.poisson_ratio = 0.3;
  m.density = 1350;
  m.surface_energy = 0.2;
  m.yield_stress = 35.3e6;  // p_y (given_pressure)
  return m;
}
// Du et al. (2007), Nan Table 1: ruthenium on a rigid flat.
inline Material du_particle() {
  Material m;
  m.name = "du";
  m.youngs_modulus = 410e9;
  m.poisson_ratio = 0.3;
  m.density = 12450;
  m.surface_energy = 1.0;
  m.yield_stress = 5.52e9;  // p_y (given_pressure)
  return m;
}
inline Material rigid_wall() {
  Material m;
  m.name = "rigid wall";
  m.rigid = true;
  m.poisson_ratio = 0.3;
  return m;
}
// Nan Table 5: ammonium fluorescein particle (p_y varied) and silicon wall.
inline Material table5_particle(double p_y, double e0 = 1.0) {
  Material m;
  m.name = "fluorescein";
  m.youngs_modulus = 1.2e9;
  m.poisson_ratio = 0.33;
  m.density = 1350;
  m.surface_energy = 0.24;
  m.yield_stress = p_y;
  m.restitution = e0;
  return m;
}
inline Material table5_wall(double e0 = 1.0) {
  Material m;
  m.name = "silicon";
  m.youngs_modulus = 166e9;
  m.poisson_ratio = 0.28;
  m.density = 2330;
  // Nan Table 5 gives Gamma only once (0.24 J/m^2): it is the interface's, so both carry it
  // (pair_properties combines non-rigid bodies as sqrt(G1 G2)).
  m.surface_energy = 0.24;
  m.yield_stress = 120e6;
  m.restitution = e0;
  return m;
}

}  // namespace test
}  // namespace epac
