#pragma once
// The working set of one MDR contact evaluation (Mdr::evaluate): the contact's sides in global-id
// order, and what each step of the evaluation leaves for the next.
#include <epac/models/contact_geometry.hpp>
#include <epac/models/mdr/detail/mdr_side_force.hpp>
#include <epac/models/mdr/mdr_bulk_response.hpp>

namespace epac {
namespace detail {

template <class T>
struct MdrEvaluation {
  bool is_pair = false;
  int nsides = 1;                 // 2 for a pair, 1 for a wall
  bool swap = false;              // side 0 is g.j (g.i has the larger global id)
  int part[2] = {0, -1};          // particle of each side
  T Rs[2] = {T(0), T(0)};         // current radius of each side
  T R0s[2] = {T(0), T(0)};        // R_o of each side (Rs without radius growth)
  T growth_of[2] = {T(0), T(0)};  // R - R_o of each side, the shift of delta_max (MdrDeltaMax)
  T a_adh_old[2] = {T(0), T(0)};  // adhesive radii at the start of the step
  MdrSideState<T> st[2];          // side states: the step's start, then advanced by the law
  MdrSideState<T> before[2];      // the states the side law started from (store_changed)
  MdrSideResult<T> res[2];        // the sides' results
  T dside[2] = {T(0), T(0)};      // the sides' apparent overlaps
  T R_cap[2] = {T(0), T(0)};      // MdrPairSplit::equal_pair: the sides' radii R'_s (growth caps)
  // bulk response (Part II): the sides' bulk history, F_BULK and A_c at the total overlap
  MdrBulkSide<T> bulk[2];
  T f_bulk[2] = {T(0), T(0)};
  T area_c[2] = {T(0), T(0)};
};

// Sides ordered by global id; a wall has one side (side 0 = particle i).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrEvaluation<T> mdr_order_sides(const ContactGeometry<T>& g) {
  MdrEvaluation<T> e;
  e.is_pair = g.j >= 0;
  e.nsides = e.is_pair ? 2 : 1;
  e.swap = e.is_pair && !g.i_is_first;
  e.part[0] = e.swap ? g.j : g.i;
  e.part[1] = e.swap ? g.i : g.j;
  e.Rs[0] = e.swap ? g.R_j : g.R_i;
  e.Rs[1] = e.swap ? g.R_i : g.R_j;
  e.R0s[0] = e.Rs[0];
  e.R0s[1] = e.Rs[1];
  return e;
}

}  // namespace detail
}  // namespace epac
