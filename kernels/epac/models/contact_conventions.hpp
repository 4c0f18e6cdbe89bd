#pragma once
// Conventions of the contact kernel (compute/contact_forces.hpp) that only some laws' authors
// use: how damping, the Coulomb bound and the rolling velocity are applied around the law's
// normal force. They are not part of NormalForce, so a law without conventions of its own neither
// carries nor branches on them: the kernel reads contact_conventions<Model> once per launch,
// whose default is the generic behaviour with every flag a compile-time false (the branches
// compile to nothing). A law with conventions specializes contact_conventions with
// `type = ContactConventions` and `of(model)` (models/mdr/mdr_model.hpp: from MdrOptions, the
// conventions of the MDR authors' code, LAMMPS granular mdr).

#include <type_traits>

namespace epac {

// The generic behaviour, fixed at compile time.
struct GenericContactConventions {
  static constexpr bool damp_may_pull = false;
  static constexpr bool coulomb_on_damped = false;
  static constexpr bool full_radius_arms = false;
};

// Conventions chosen at run time (a law's options).
struct ContactConventions {
  bool damp_may_pull = false;      // with NormalForce::damp_compressive_only: f + F_d is not clamped at 0
  bool coulomb_on_damped = false;  // Coulomb bound mu |f + F_d| instead of mu |f|
  bool full_radius_arms = false;   // the rolling part of the contact-point velocity uses R_i w_i
                                   // + R_j w_j, and a wall's torque arm is R_i (not R_i - delta)
};

// A law's conventions: `type` (one of the two above) and `of(model)`, read on the host once per
// kernel launch.
template <class Model>
struct contact_conventions {
  using type = GenericContactConventions;
  static type of(const Model&) { return {}; }
};

// Laws whose normal law treats every wall as a rigid flat, whatever the wall's curvature
// (Walls::curvature): LAMMPS's granular mdr takes R = radi at a wall contact, in its damping's R*
// too. The kernel gives their normal() R_eff = R_i at a wall; its rolling arm keeps the wall's R*
// (LAMMPS's Reff, which its rolling sub-model uses with every normal law). The other laws see the
// wall's R* everywhere (LAMMPS's hertz, hertz/material, dmt and jkr take Reff from the wall's
// radius). Mdr is declared here, not included: its header includes this one.
template <class Model>
struct wall_normal_law_on_flat : std::false_type {};
template <class T, class Eff, class Device>
struct Mdr;
template <class T, class Eff, class Device>
struct wall_normal_law_on_flat<Mdr<T, Eff, Device>> : std::true_type {};

}  // namespace epac
