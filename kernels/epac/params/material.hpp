#pragma once
// A material (host side) and the effective pair properties every law builds on.
#include <epac/params/validation.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace epac {

struct Material {
  std::string name = "material";  // host
  double youngs_modulus = 0;      // E [Pa]
  double poisson_ratio = 0.3;     // nu, in (-1, 0.5)
  double density = 0;             // [kg/m^3]
  double restitution = 1;         // e0 in [0, 1]; 1 = no damping
  double friction = 0;            // sliding friction coefficient mu >= 0; 0 = no friction
  double surface_energy = 0;      // Gamma (Nan) = Delta gamma (MDR) [J/m^2]; 0 = no adhesion
  double yield_stress = std::numeric_limits<double>::infinity();  // Y or sigma_y [Pa]; inf = no yield
  bool rigid = false;                                             // rigid body (walls): contributes no compliance
  // Rigid only: its own restitution, friction and surface energy for its contacts (default: a
  // rigid wall takes the particle's). E.g. a die wall with less friction than the powder.
  bool own_surface_properties = false;
  // Rolling resistance (models/rolling_resistance.hpp; LAMMPS `rolling sds k_r gamma_r mu_r`):
  // rolling_friction mu_r > 0 turns it on. Last, so that positional initialisers of the fields
  // above keep their meaning.
  double rolling_stiffness = 0;  // k_r [N/m] >= 0
  double rolling_damping = 0;    // gamma_r [N s/m] >= 0
  double rolling_friction = 0;   // mu_r >= 0; 0 = no rolling resistance

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }

  // Throws ParameterError naming the key, the value and the valid range.
  void validate() const {
    const std::string p = "material '" + name + "': ";  // host
    if (!rigid) require_positive(p + "youngs_modulus", youngs_modulus);
    require_range(p + "poisson_ratio", poisson_ratio, -1.0, Bound::open, 0.5, Bound::open);
    if (!rigid) require_positive(p + "density", density);
    require_range(p + "restitution", restitution, 0.0, Bound::closed, 1.0, Bound::closed);
    require_range(p + "friction", friction, 0.0, Bound::closed, std::numeric_limits<double>::infinity(), Bound::open);
    require_range(p + "surface_energy", surface_energy, 0.0, Bound::closed, std::numeric_limits<double>::infinity(),
                  Bound::open);
    require_positive(p + "yield_stress", yield_stress, /*allow_inf=*/true);
    const double inf = std::numeric_limits<double>::infinity();
    require_range(p + "rolling_stiffness", rolling_stiffness, 0.0, Bound::closed, inf, Bound::open);
    require_range(p + "rolling_damping", rolling_damping, 0.0, Bound::closed, inf, Bound::open);
    require_range(p + "rolling_friction", rolling_friction, 0.0, Bound::closed, inf, Bound::open);
  }
};

// Effective properties of two bodies in contact (Hertz theory).
struct PairProperties {
  double E_star = 0;  // 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
  double G_star = 0;  // 1/G* = (2-nu1)/G1 + (2-nu2)/G2
  double restitution = 1, friction = 0, surface_energy = 0;
  double yield_stress = std::numeric_limits<double>::infinity();  // the softer body's
  double rolling_stiffness = 0, rolling_damping = 0, rolling_friction = 0;
};

inline PairProperties pair_properties(const Material& a, const Material& b) {
  auto cE = [](const Material& m) {
    return m.rigid ? 0.0 : (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  };
  auto cG = [](const Material& m) { return m.rigid ? 0.0 : (2 - m.poisson_ratio) / m.shear_modulus(); };
  if (a.rigid && b.rigid)
    throw ParameterError("pair '" + a.name + "'-'" + b.name + "': two rigid bodies cannot be in contact");  // host
  PairProperties p;
  p.E_star = 1.0 / (cE(a) + cE(b));
  p.G_star = 1.0 / (cG(a) + cG(b));
  // Rigid walls take the particle's value (their own with own_surface_properties); otherwise the
  // lower restitution / mean friction / combined surface energy (Dupre: the same material gives
  // Gamma).
  auto pick = [&](double va, double vb, bool use_min) {
    if (a.rigid) return a.own_surface_properties ? va : vb;
    if (b.rigid) return b.own_surface_properties ? vb : va;
    return use_min ? std::min(va, vb) : 0.5 * (va + vb);
  };
  p.restitution = pick(a.restitution, b.restitution, true);
  p.friction = pick(a.friction, b.friction, false);
  p.surface_energy = (a.rigid || b.rigid) ? pick(a.surface_energy, b.surface_energy, false)
                                          : std::sqrt(a.surface_energy * b.surface_energy);
  p.yield_stress = pick(a.yield_stress, b.yield_stress, true);
  // Rolling: the geometric mean for two particles (LAMMPS's mix_geom), so that either at 0 turns
  // the pair's rolling resistance off.
  auto geom = [&](double va, double vb) {
    if (a.rigid || b.rigid) return pick(va, vb, false);
    return std::sqrt(va * vb);
  };
  p.rolling_stiffness = geom(a.rolling_stiffness, b.rolling_stiffness);
  p.rolling_damping = geom(a.rolling_damping, b.rolling_damping);
  p.rolling_friction = geom(a.rolling_friction, b.rolling_friction);
  return p;
}

}  // namespace epac
