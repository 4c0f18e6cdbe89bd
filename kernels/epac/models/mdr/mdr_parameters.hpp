#pragma once
// MDR (Zunker & Kamrin, Part I) constants and options, host side: per-material "side" constants
// (one particle against a rigid flat), per-material-pair constants (adhesion, damping, friction),
// the options where the paper and the authors' implementation differ, and validation.
//
// Every side of an MDR contact is a particle against a rigid flat (docs/models.md "MDR conventions"), so a
// side uses E_eff = E/(1 - nu^2) of its own particle, never the composite modulus of two bodies.
#include <epac/core/root_solve.hpp>
#include <epac/models/mdr/detail/mdr_ellipse.hpp>
#include <epac/params/material.hpp>
#include <epac/params/restitution_damping.hpp>
#include <epac/params/validation.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace epac {

// Which contacts feed the apparent-radius update MDR (37).
enum class MdrGrowthRule {
  plastic_loading,  // authors' implementation (default): sides in plastic loading with a
                    // positive MDR force; each side's Delta V^e from its own Christoffersen term
  // Appendix E's sum over the touching sides, restricted to the yielded ones (an elastic side
  // never grows R: mdr_radius_growth.hpp; the literal rule ratchets elastic contacts, issue 10);
  // Delta V^e from the particle's volume. Called all_contacts until 0.x.
  yielded_contacts
};

// Where the elastic regime ends (Section 5.6.5).
enum class MdrYieldOnset {
  // Default. The mean pressure of the elastic law itself, F_el(delta) / (pi delta R) with F_el
  // the ellipse force (30)-(31) and pi delta R the elastic area (42), meets p_Y. It equals the
  // Hertz mean pressure (40) to first order in delta/R (they differ by a factor 1 - 0.075 delta/R)
  // and, with c_A from (43), makes force, area and mean pressure exactly continuous at delta_Y.
  elastic_law,
  // The paper's (41) read literally: the Hertz mean pressure (40) meets p_Y. Mean pressure and
  // area are continuous, but the force jumps at delta_Y by the difference between the Hertz force
  // and the ellipse force (relative 0.075 delta_Y/R: 6.5e-5 at E/Y = 200, 2% at E/Y = 6.25).
  hertz_40
};

// Where a pair's rigid flat sits and what each side sees (detail/mdr_pair_equal.hpp,
// mdr_pair_balance.hpp, mdr_pair_split.hpp). MDR Part I builds the law for one sphere against a
// rigid flat; how two unequal spheres share it is left open (docs/models.md, "MDR conventions").
enum class MdrPairSplit {
  // Default. Each side is a side of the equivalent equal pair (detail/mdr_pair_equal.hpp): a
  // sphere of radius R'_s = R* E_s/E* (one material: 2 R*) of its own material against the flat,
  // the flat where the two sides' forces are equal, F_0(d_0) = F_1(delta - d_0). The elastic root
  // is d_s = delta E*/E_s (one material: delta/2, exact in every regime, so no solve; with radius
  // growth each side adds its own particle's growth). Hertz with E*
  // and R* at any radius and modulus ratio, the plastic similarity of same-material spheres
  // (the pair is the equal pair of radius 2 R* at every overlap), JKR of R* and E*; passive.
  equal_pair,
  // Until 0.x: the default. Each particle's own sphere against the flat where the sides' scaled
  // forces balance, lambda_0 F_0 = lambda_1 F_1 (R_0 F_0 = R_1 F_1 once plastic): passive, Hertz
  // with E* and R* for one material, but unequal plastic pairs are up to 51% softer than the equal
  // pair with the same R*, and unequal moduli miss Hertz (docs/models.md's table).
  balanced,
  // The authors' choice: the radical plane while loading (epac's repaired interpolation towards the
  // residuals below the largest overlap), with the mean of the two side forces. Not work-conjugate:
  // yielded pairs of unequal spheres returned more work than they took on ~0.5% of random cycles.
  // For comparisons with the authors' implementation (LAMMPS `granular mdr`).
  geometric,
  // geometric with the authors' own unloading path (LAMMPS gran_sub_mod_normal.cpp and
  // fix_granular_mdr.cpp): below the largest overlap each side moves linearly in delta from its
  // radical-plane height to its residual, both reached when delta is the summed residuals, and
  // beyond that by the same line (mdr_pair_split.hpp, defects (a) and (b): where the residuals sum
  // to the largest overlap or more, epac's path of geometric is taken). Differs from geometric
  // only for unequal spheres. For like-with-like comparisons with LAMMPS: on the MDR tableting
  // example (in.tableting.200, polydisperse) geometric moves the compaction peak 2.4% and the
  // ejected tablet's grip 38% away from LAMMPS's, outside LAMMPS's own nudged spread.
  geometric_authors
};

// What delta_max is once the radius grows (MdrOptions::delta_max).
enum class MdrDeltaMax {
  // Default. MDR (19): delta_max = delta_o,max + R - R_o, delta_o,max the running maximum of
  // delta_o = delta - (R - R_o). Growth itself never counts as loading; converges with the step.
  paper_19,
  // The authors' code (Appendix E): the running maximum of the apparent overlap delta, so a side
  // whose overlap rises because R grew is loading (plastic loading, more growth). For comparisons
  // with LAMMPS's `granular mdr`. Identical without growth.
  running_max
};

// How an MDR contact is damped (MdrOptions::damping; only with a restitution below 1).
enum class MdrDamping {
  // Default. c from the restitution by the exact Hertz relation, with k_n = 2 E* a-bar
  // (mdr_model.hpp header), while the MDR force is compressive, never turning a push into a pull.
  restitution_exact,
  // The authors' code (LAMMPS gran_sub_mod_normal.cpp): F_d = -beta sqrt(m* k_n) v_n with
  // beta = -ln e / sqrt(ln^2 e + pi^2) and k_n = E* R* (the pair's composite modulus; a wall:
  // the particle's E_eff and R), while the mean MDR force is positive; F + F_d may pull. For
  // comparisons with LAMMPS's `granular mdr`.
  authors
};
// The tangential law of an MDR contact (MdrOptions::friction; only with friction mu > 0).
enum class MdrFriction {
  // Default. Mindlin's spring k_t = (4 G*/E*) k_n = 8 G* a-bar, damped with the normal
  // coefficient, Coulomb bound mu |f| on the undamped MDR force.
  mindlin,
  // The authors' examples (LAMMPS `tangential linear_history k_t 0 mu`): a constant k_t
  // (MdrOptions::tangential_stiffness), no tangential damping, Coulomb bound on the damped normal
  // force, and LAMMPS's kinematics: the rolling part of the contact-point velocity with the full
  // radii, a wall's torque arm R.
  authors
};

// How a pair's surface energy Delta gamma is shared by its two sides (MdrOptions::surface_energy_share).
enum class MdrSurfaceEnergyShare {
  // Default. gamma_s = Delta gamma E*/E_eff,s: the sides' edge springs act in series, so an elastic
  // pair reproduces JKR between the two spheres (mdr_model.hpp header).
  series,
  // The authors' code: each side gets the full Delta gamma (twice JKR's pull-off for two equal
  // spheres). For comparisons with LAMMPS's `granular mdr`. Walls: Delta gamma either way.
  each_side_full
};

// The adhesive contact radius a stored while no spring is in tension (MdrOptions::adhesive_radius,
// mdr_adhesion.hpp).
enum class MdrAdhesiveRadius {
  // Default. a = a_na, the non-adhesive half-width: tension starts as soon as the contact unloads
  // (the paper's rule; the pull-off force converges as the step shrinks).
  paper,
  // The authors' code: a = 0.99 a_na, used at most as 0.99 a_max, so unloading is free of tension
  // until a_na has dropped by 1%. For comparisons with LAMMPS's `granular mdr`.
  authors
};

// When an adhesive contact ends (MdrOptions::release).
enum class MdrRelease {
  // Default. Held while a side keeps an adhesive radius, released once the surfaces are apart by
  // more than the contact's critical overlap (mdr_detachment.hpp): the neck of Section 6.
  critical_overlap,
  // The authors' code (LAMMPS `granular mdr` has no pull-off distance): released as soon as the
  // apparent overlap is <= 0, adhesive or not. For comparisons with LAMMPS.
  zero_overlap
};

struct MdrOptions {
  // xi of MDR (15): 1 = displacement control (Appendix E's choice), 3 = force control.
  int xi = 1;
  MdrGrowthRule growth_rule = MdrGrowthRule::plastic_loading;
  MdrYieldOnset yield_onset = MdrYieldOnset::elastic_law;
  MdrPairSplit pair_split = MdrPairSplit::equal_pair;
  MdrDeltaMax delta_max = MdrDeltaMax::paper_19;
  MdrDamping damping = MdrDamping::restitution_exact;
  MdrFriction friction = MdrFriction::mindlin;
  MdrSurfaceEnergyShare surface_energy_share = MdrSurfaceEnergyShare::series;
  MdrAdhesiveRadius adhesive_radius = MdrAdhesiveRadius::paper;
  MdrRelease release = MdrRelease::critical_overlap;
  // k_t [N/m] of MdrFriction::authors (the same for every pair); unused otherwise.
  double tangential_stiffness = 0.0;
  // The contact penalty of LAMMPS's MDR (mdr_contact_penalty.hpp): a pair whose longest-side
  // triangle with a third overlapping particle puts that particle between them is weighted down.
  // Off by default: it is later work (Zunker et al. 2025), not MDR Part I. The host then calls
  // Mdr::compute_contact_penalty before every force pass.
  bool contact_penalty = false;
  // Part II's bulk response (mdr_bulk_response.hpp): a particle whose free surface fraction psi
  // is below psi_b takes its mean surface displacement as bulk overlap. 0 (default): off, Part I.
  // psi_b > 0 needs the kBulkResponse effect and pair_split = geometric (Mdr::create checks).
  double psi_b = 0.0;
  // R never exceeds radius_cap * R_o (the authors' implementation stops growth at 1.5 R_o).
  double radius_cap = 1.5;
  // Guard of the denominator of MDR (37), D = 2 pi R sum(delta_o + R - R_o) - 4 pi R^2, which is
  // negative in normal use and reaches 0 under high confinement (Appendix C). D is kept at or below
  // -denominator_floor * 4 pi R^2, i.e. the guard acts once the contributing apparent overlaps sum
  // to more than 2 R (1 - denominator_floor). Each use is counted (MdrGrowthState::guard_hits).
  double denominator_floor = 0.05;
  // V of MDR (39) is kept at or above volume_floor * V_o (counted as well).
  double volume_floor = 0.1;

  void validate() const {
    if (xi != 1 && xi != 3)
      throw ParameterError("mdr: xi = " + std::to_string(xi) + " is outside the valid set {1, 3}");  // host
    require_range("mdr: radius_cap", radius_cap, 1.0, Bound::closed, 10.0, Bound::closed);
    require_range("mdr: denominator_floor", denominator_floor, 0.0, Bound::open, 1.0, Bound::open);
    require_range("mdr: volume_floor", volume_floor, 0.0, Bound::open, 1.0, Bound::open);
    require_range("mdr: psi_b", psi_b, 0.0, Bound::closed, 1.0, Bound::closed);
    if (psi_b > 0.0 && pair_split != MdrPairSplit::geometric && pair_split != MdrPairSplit::geometric_authors)
      throw ParameterError(
          "mdr: psi_b = " + std::to_string(psi_b) +
          " (Part II's bulk response) needs pair_split = geometric or geometric_authors (the authors' flat placement: "
          "the mean surface "
          "displacement is computed before the force pass from each side's overlap, a closed form only there)");
    if (friction == MdrFriction::authors)
      require_range("mdr: tangential_stiffness (friction authors)", tangential_stiffness, 0.0, Bound::open,
                    std::numeric_limits<double>::max(), Bound::closed);
  }
};

// One particle's constants as a side of a contact (a particle against a rigid flat).
template <class T>
struct MdrSideConstants {
  T E_eff;    // E/(1 - nu^2): the side's plane strain modulus against a rigid flat
  T G;        // shear modulus, MDR (34)
  T nu;       // Poisson ratio, MDR (34)
  T kappa;    // bulk modulus, MDR (38)
  T Y;        // yield stress, MDR (16) and (21); +inf: never yields
  T x_yield;  // delta_Y / R, the root of the yield equation (41) (see MdrYieldOnset); +inf: never
  // Precomputed for the hot path (mdr_side_force); all depend on the material only.
  T Y_hard;       // 1.75 Y: p_Y = Y + Y_hard exp(-4.4 delta_max/R), MDR (16) with (21)
  T four_over_E;  // 4 / E_eff: A = (4 p_Y / E_eff) a_max, MDR (28)
  T cA_over_R2;   // c_A / R^2 = pi (x_y^2 - x_y) at the switch, MDR (43); 0 if never yields
  T r_rho, r_z;   // E_eff (nu-1)/(2G) and E_eff/(4G): delta_R/(A/2) of MDR (34), see mdr_plastic_shape
  T inv_3kappa;   // 1 / (3 kappa), MDR (38)
};

// Fills the precomputed fields of c from its base fields (host).
template <class T>
void mdr_fill_derived(MdrSideConstants<T>& c) {
  const double E = double(c.E_eff), nu = double(c.nu), G = double(c.G), xy = double(c.x_yield);
  c.Y_hard = T(1.75 * double(c.Y));
  c.four_over_E = T(4.0 / E);
  c.cA_over_R2 = std::isfinite(xy) ? T(constants<double>::pi * (xy * xy - xy)) : T(0);
  c.r_rho = T(E * (nu - 1.0) / (2.0 * G));
  c.r_z = T(E / (4.0 * G));
  c.inv_3kappa = T(1.0 / (3.0 * double(c.kappa)));
}

// Constants of a material pair (particle-particle or particle-wall).
template <class T>
struct MdrPairConstants {
  T E_star;      // composite modulus of the two bodies (rigid wall: E_eff of the particle); k_n
  T kt_over_kn;  // 4 G*/E*: k_t = (4G*/E*) k_n = 8 G* a (Mindlin), Nan (22)
  T c_damp;      // viscous coefficient from the restitution (exact Hertz relation; MdrDamping::authors: beta)
  T mu;          // Coulomb friction coefficient
  T gamma;       // effective surface energy Delta gamma; 0 = no adhesion for this pair
  // The two materials' side constants (a: the row material, b: the column one; a rigid one is
  // left default) and each side's share of gamma, gamma E*/E_eff,s (mdr_model.hpp): one table
  // load per contact, no per-material lookups on the hot path.
  MdrSideConstants<T> side_a, side_b;
  T gamma_a, gamma_b;
  // One material on both sides (MdrPairSplit::equal_pair: the sides are the same side of the equal
  // pair at delta_o/2, no balance solve and no warm start).
  bool same_material = false;
};

// --- yield onset, host --------------------------------------------------------------------------

// delta_Y / R for a side with plane strain modulus E_eff and yield stress Y: the root of the
// yield equation, solved by bracketed_newton_host in s = sqrt(delta_Y / R). Depends on E_eff/Y only.
// Returns +inf when the side never yields (Y infinite, or the elastic pressure never reaches p_Y
// before the ellipse is fully submerged, which needs E_eff/Y below about 2).
inline double mdr_yield_ratio(double E_eff, double Y, MdrYieldOnset onset) {
  const double inf = std::numeric_limits<double>::infinity();
  if (!std::isfinite(Y)) return inf;
  const double r = E_eff / Y;
  const double pi = constants<double>::pi;
  // p_Y / Y = 1.75 exp(-4.4 x) + 1, MDR (16) with delta_o/R_o -> delta_max/R (21); x = s^2.
  auto hardening = [](double s) { return 1.75 * std::exp(-4.4 * s * s) + 1.0; };
  auto dhardening = [](double s) { return -1.75 * 8.8 * s * std::exp(-4.4 * s * s); };
  RootResult<double> res{};
  if (onset == MdrYieldOnset::hertz_40) {
    // MDR (41) over Y: (4 r / (3 pi)) s - p_Y/Y = 0. Increasing in s; p_Y/Y in [1, 2.75], so the
    // root lies in [3 pi/(4 r), 2.75 * 3 pi/(4 r)].
    auto f = [&](double s, double& fv, double& df) {
      fv = 4.0 * r / (3.0 * pi) * s - hardening(s);
      df = 4.0 * r / (3.0 * pi) - dhardening(s);
    };
    res = bracketed_newton_host<double>(f, 3.0 * pi / (4.0 * r), 2.75 * 3.0 * pi / (4.0 * r), 1e-15, 200);
  } else {
    // Mean pressure of the ellipse law over Y: F_el / (pi x R^2 Y) with F_el = E A B/4 * bracket,
    // A = 4R, B = 2R: (2 r / pi) bracket(theta) / s^2, theta = 2 asin(s/2). It is increasing in s
    // on (0, 2] (s = 2: the ellipse is fully submerged) and tends to (4 r/(3 pi)) s as s -> 0.
    auto f = [&](double s, double& fv, double& df) {
      const double th = 2.0 * std::asin(0.5 * s);
      const double br = mdr_ellipse_bracket(th);
      const double dth = 1.0 / std::sqrt(std::max(1.0 - 0.25 * s * s, 1e-300));  // d theta / ds
      const double dbr = 2.0 * std::sin(th) * std::sin(th) * dth;                // d bracket / ds
      fv = 2.0 * r / pi * br / (s * s) - hardening(s);
      df = 2.0 * r / pi * (dbr / (s * s) - 2.0 * br / (s * s * s)) - dhardening(s);
    };
    double fl, fh, d;
    const double lo = 1e-12, hi = 2.0;
    f(hi, fh, d);
    if (fh < 0.0) return inf;  // never reaches the hardening curve (E_eff/Y below about 2)
    f(lo, fl, d);
    res = bracketed_newton_host<double>(f, lo, hi, 1e-15, 200);
  }
  if (!res.bracketed) return inf;
  return res.x * res.x;
}

// Side constants of a (non-rigid) material, validated.
template <class T>
MdrSideConstants<T> mdr_side_constants(const Material& m, MdrYieldOnset onset) {
  m.validate();
  if (m.rigid)
    throw ParameterError("mdr: material '" + m.name + "' is rigid; MDR particles must be deformable");  // host
  const double nu = m.poisson_ratio;
  const double E_eff = m.youngs_modulus / (1.0 - nu * nu);
  MdrSideConstants<T> c;
  c.E_eff = T(E_eff);
  c.G = T(m.shear_modulus());
  c.nu = T(nu);
  c.kappa = T(m.youngs_modulus / (3.0 * (1.0 - 2.0 * nu)));
  c.Y = T(m.yield_stress);
  const double xy = mdr_yield_ratio(E_eff, m.yield_stress, onset);
  c.x_yield = std::isfinite(xy) ? T(xy) : std::numeric_limits<T>::infinity();
  mdr_fill_derived(c);
  // every constant the kernels use must be a normal number of T (float: moduli and yield stresses
  // between about 1e-38 and 3e38, after the factors below)
  const std::string n = "mdr: material '" + m.name + "': ",
                    from = "its modulus, Poisson ratio and yield stress";  // host
  const double G = m.shear_modulus(), kappa = m.youngs_modulus / (3.0 * (1.0 - 2.0 * nu));
  require_representable<T>(n + "E_eff", E_eff, from);
  require_representable<T>(n + "G", G, from);
  require_representable<T>(n + "kappa", kappa, from);
  require_representable<T>(n + "4 / E_eff", 4.0 / E_eff, from);
  require_representable<T>(n + "1 / (3 kappa)", 1.0 / (3.0 * kappa), from);
  require_representable<T>(n + "E_eff (nu - 1) / (2 G)", E_eff * (nu - 1.0) / (2.0 * G), from);
  if (std::isfinite(m.yield_stress)) {
    require_representable<T>(n + "yield_stress", m.yield_stress, from);
    require_representable<T>(n + "1.75 yield_stress", 1.75 * m.yield_stress, from);
  }
  return c;
}

// Pair constants of two materials (either may be a rigid wall material). Side constants: see
// mdr_side_constants (onset: where the elastic regime ends).
template <class T>
MdrPairConstants<T> mdr_pair_constants(const Material& a, const Material& b,
                                       MdrYieldOnset onset = MdrYieldOnset::elastic_law,
                                       MdrSurfaceEnergyShare share = MdrSurfaceEnergyShare::series,
                                       MdrDamping damping = MdrDamping::restitution_exact) {
  const PairProperties pp = pair_properties(a, b);  // host: rejects two rigid bodies
  MdrPairConstants<T> p;
  p.E_star = T(pp.E_star);
  p.kt_over_kn = T(4.0 * pp.G_star / pp.E_star);
  // MdrDamping::authors: beta = -ln e / sqrt(ln^2 e + pi^2), the linear-spring ratio of Nan (26)
  p.c_damp = T(damping == MdrDamping::authors ? linear_damping_ratio(pp.restitution)
                                              : hertz_damping_coefficient(pp.restitution));
  p.mu = T(pp.friction);
  p.gamma = T(pp.surface_energy);
  p.side_a = a.rigid ? MdrSideConstants<T>{} : mdr_side_constants<T>(a, onset);
  p.side_b = b.rigid ? MdrSideConstants<T>{} : mdr_side_constants<T>(b, onset);
  // gamma_s = Delta gamma E* / E_eff,s (mdr_model.hpp header); E_eff > 0 for deformable sides
  // (MdrSurfaceEnergyShare::each_side_full: Delta gamma on each side, the authors' code)
  const bool full = share == MdrSurfaceEnergyShare::each_side_full;
  p.gamma_a = a.rigid ? T(0) : T(full ? pp.surface_energy : pp.surface_energy * pp.E_star / double(p.side_a.E_eff));
  p.gamma_b = b.rigid ? T(0) : T(full ? pp.surface_energy : pp.surface_energy * pp.E_star / double(p.side_b.E_eff));
  const std::string n = "mdr: pair '" + a.name + "'-'" + b.name + "': ";      // host
  const std::string from = "the two materials' moduli and surface energies";  // host
  require_representable<T>(n + "E_star", pp.E_star, from);
  require_representable<T>(n + "surface_energy", pp.surface_energy, from);
  if (!a.rigid)
    require_representable<T>(n + "side a surface energy", pp.surface_energy * pp.E_star / double(p.side_a.E_eff), from);
  if (!b.rigid)
    require_representable<T>(n + "side b surface energy", pp.surface_energy * pp.E_star / double(p.side_b.E_eff), from);
  return p;
}

}  // namespace epac
