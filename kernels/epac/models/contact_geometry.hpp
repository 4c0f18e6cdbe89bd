#pragma once
// What a normal force law sees of one contact, and what it returns. The contact kernel
// (compute/contact_forces.hpp) fills ContactGeometry and applies damping, friction and
// accumulation around the law (law-specific conventions of that: models/contact_conventions.hpp).
#include <epac/core/vec3.hpp>

#include <cstdint>

namespace epac {

template <class T>
struct ContactGeometry {
  int i = 0;               // particle index
  int j = -1;              // other particle index, or -1 for a wall contact
  int wall = -1;           // wall index for a wall contact
  int pair = 0;            // index into the model's pair table
  T delta = 0;             // overlap R_i + R_j - distance (pairs) or R_i - distance (walls)
  T delta_dot = 0;         // d(delta)/dt, positive while approaching
  T R_i = 0, R_j = 0;      // current radii (R_j = 0 for walls)
  T R_eff = 0;             // R_i R_j / (R_i + R_j); walls: R_i R_w / (R_i + R_w) with the wall's
                           // curvature R_w (Walls::curvature), R_i at a flat wall
  T m_eff = 0;             // m_i m_j / (m_i + m_j), or m_i for walls
  bool i_is_first = true;  // gid_i < gid_j: fixes per-side history order for side-based laws
                           // (always true in the pair kernel, which evaluates pairs in that order)
  int contact = -1;        // index of the contact in its list (per-contact buffers of the deterministic mode)
  Vec3<T> n;               // unit normal, pointing from j (or the wall) to i
  T dt = 0;
};

template <class T>
struct NormalForce {
  T f = 0;                             // normal force of the law on particle i along n; positive = repulsive
  T k_n = 0;                           // normal stiffness used for damping and for k_t (the law's current branch)
  T damping = 0;                       // viscous coefficient: F_d = damping * sqrt(m_eff * k_n) * delta_dot
  bool damp_compressive_only = false;  // damp only while f > 0, and never let f + F_d pull (unless
                                       // the law's contact_conventions say damp_may_pull)
  T k_t = 0;                           // tangential stiffness
  T damping_t = 0;                     // tangential viscous coefficient: F_td = -damping_t sqrt(m_eff k_t) v_t
  T kt_root_ratio = 0;                 // sqrt(k_t/k_n) where the law's k_t is a fixed multiple of k_n: the
                                       // kernel then takes sqrt(m_eff k_t) as sqrt(m_eff k_n) times this (one
                                       // square root for both dampings); 0: it takes sqrt(m_eff k_t)
  T mu = 0;                            // Coulomb friction coefficient
  bool active = false;                 // false: the surfaces are apart; tangential history is reset
};

}  // namespace epac
