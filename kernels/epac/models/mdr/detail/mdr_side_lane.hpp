#pragma once
// The common path of mdr_side_force (detail/mdr_side_force.hpp) without branches, for sides in
// lanes: part of MDR's lane form (Mdr::contact_lane, run by compute/pair_lanes.hpp).
//
// In a compressed packing's hold, 98.4% of the side evaluations take one branch: a yielded side
// below its delta_max, on the plastic shape of that delta_max kept in its history
// (MdrSideState::shape_*). This is that branch, without adhesion and without the balance solve's
// stiffness (the geometric split, Part II's bulk response, walls). Everything else is flagged
// rare and needs mdr_side_force: elastic sides, the yield switch, plastic loading (delta_o at or
// past delta_o,max), a shape whose key (R, delta_max) moved.
//
// The common path changes no state: delta_o,max, yielded, c_A, the shape and delta_p stay those
// of delta_max (mdr_side_force rewrites delta_p with the same value). So the lane form only reads.
//
// Its values are mdr_side_force's expressions in its order, except the ellipse's angle, which is
// lane_two_asin_sqrt (core/lane_math.hpp, within 2 ulp) instead of libm's asin. The two forms agree
// to a few ulp, not bit for bit (tests/mdr/test_mdr_side_lane.cpp).
#include <epac/core/simd_lanes.hpp>
#include <epac/models/mdr/detail/mdr_ellipse.hpp>
#include <epac/models/mdr/detail/mdr_side_force.hpp>

namespace epac {

// One side's results on the common path. rare = 1: not on it, and the other values are
// placeholders (finite for finite inputs); the caller takes mdr_side_force for that side.
// Flags as T, not bool: the lanes' vectors then have one element size.
template <class T>
struct MdrSideLane {
  T F;          // MDR force (30), positive = compressive
  T a;          // contact half-width in MDR space
  T area;       // contact area (42), plastic branch
  T d1De;       // delta_1D^e by (35), as A/2 + (delta - delta_max)/r
  T delta_max;  // (19)
  T rare;
};

// c: the side's constants; delta: its overlap; R: its radius; growth: R - R_o (0 without radius
// growth, and with MdrDeltaMax::running_max); s: its state at the start of the step.
// Divisions: by the stored ratio r (>= mdr_min_recovery_ratio where the shape is stored; 1 on rare
// lanes) and by A (> 0 where the side touches; 1 elsewhere). Roots: of x and 1 - x with x in
// [0, 1], and of d (A - d) >= 0 for 0 < d < A/2.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrSideLane<T> mdr_side_force_lane(const MdrSideConstants<T>& c, T delta, T R, T growth,
                                                               const MdrSideState<T>& s) {
  const T pi = constants<T>::pi;
  const T delta_o = delta - growth;
  const bool loading = delta_o >= s.delta_o_max;
  const T below_max = delta_o - s.delta_o_max;  // < 0 on the common path
  const T delta_max = s.delta_o_max + growth;   // (19)
  const bool stored = (s.shape_R == R) & (s.shape_delta_max == delta_max);
  const bool common = (s.yielded != T(0)) & !loading & stored;
  const MdrPlasticShape<T> sh = mdr_stored_shape(s);  // the one-side law's reading of the stored shape
  const T A = sh.A;
  const T B = sh.B;
  const T ratio = lane_select(common, sh.ratio, T(1));  // >= mdr_min_recovery_ratio where stored
  MdrSideLane<T> out;
  out.delta_max = delta_max;
  out.d1De = T(0.5) * A + below_max / ratio;                                   // (35), as mdr_side_force
  out.area = lane_max(pi * (T(2) * delta * R - delta * delta) + s.c_A, T(0));  // (42)
  // mdr_ellipse_force and mdr_ellipse_contact_radius at d = d1De: 0 where d <= 0 (or A <= 0)
  const T d = out.d1De;
  const bool touching = (d > T(0)) & (A > T(0));
  const T A_g = lane_select(touching, A, T(1));
  const T d_g = lane_select(touching, d, T(0));
  const T x = lane_min(d_g / A_g, T(1));
  out.F = lane_select(touching, c.E_eff * A * B * T(0.25) * mdr_ellipse_bracket_of_depth_lane(x), T(0));
  const bool past_equator = d_g >= T(0.5) * A_g;
  const T width = B / A_g * math::sqrt(lane_max(d_g * (A_g - d_g), T(0)));  // sqrt_nonneg's guard
  out.a = lane_select(touching, lane_select(past_equator, T(0.5) * B, width), T(0));
  out.rare = lane_select(common, T(0), T(1));
  return out;
}

}  // namespace epac
