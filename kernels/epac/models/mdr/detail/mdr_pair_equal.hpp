#pragma once
// Particle pairs in MDR as sides of the equivalent equal pair (MdrPairSplit::equal_pair, the
// default; chosen by measurement against the other splits, docs/mdr-pair-split-evaluation.md).
//
// MDR Part I builds the law for one sphere against a rigid flat (Section 5.2, Fig. 6); two equal
// spheres of one material are two such sides at delta/2 each. For two spheres of radii R_0, R_1
// and plane-strain moduli E_0, E_1 (E_eff of each side, mdr_parameters.hpp) the contact sees only
// the gap delta - r^2/(2 R*) and the composite compliance 1/E* = 1/E_0 + 1/E_1 as long as the
// contact is small against both radii (the half-space picture of MDR's Appendix A). Each body's
// surface then takes the share E*/E_s of the common normal displacement, so side s is a sphere of
// its own material against the flat with
//     depth    d_s  = w_s delta,          w_s = E*/E_s = E_o/(E_0 + E_1)   (w_0 + w_1 = 1)
//     radius   R'_s = R*/w_s = R* (E_0 + E_1)/E_o                          (one material: 2 R*)
// - elastic: the ellipse law (30)-(31) of side s is Hertz of R'_s, E_s at d_s to first order:
//   F_s = 4/3 E_s sqrt(R'_s) d_s^(3/2) = 4/3 E* sqrt(R*) delta^(3/2) on both sides, and the contact
//   radius a_s^2 = R'_s d_s = R* delta is the Hertz radius of the pair on both sides (the sides'
//   areas, (42) elastic, are pi R* delta: the pair's);
// - one material, any radius ratio: both sides are the equal pair of radius 2 R* at delta/2,
//   identically (same constants, same depth, same history): the pair is the equal pair with the
//   same R* in every regime, plastic (the similarity of same-material spheres), adhesive (JKR of
//   R*, E* with the series share of Delta gamma) and unloading alike;
// - per side, the cap cut by the flat holds the volume pi R'_s d_s^2 = (E*/E_s) pi R* delta^2 to
//   leading order: the pair's lens volume pi R* delta^2, shared by compliance (half each for one
//   material), and its plastic area pi (2 R'_s d_s - d_s^2) + c_A is the lens rim's 2 pi R* delta
//   on both sides.
// - radius growth, MDR (19) and (37): the compliance split applies to the approach
//   delta_o = delta - (R_0 - R_o,0) - (R_1 - R_o,1); each particle's own growth goes to its own
//   side (d_s = w_s delta_o + R_s - R_o,s, the flat staying put while the particle grows, as
//   Appendix C's rigid flats and the authors' sides), and (37)'s cap of side s is cut from the
//   sphere R'_s (Mdr::commit_side, mdr_growth_add_side's R_cap): the particle's compliance share of
//   the lens, its base the lens rim. The side's sphere is that of the initial radii grown by its own
//   particle's growth, R'_s = R'_s(R_o,0, R_o,1) + R_s - R_o,s (mdr_equal_pair_grown): its R_o is
//   fixed, as a side's must be, and the partner's growth does not enlarge it (with R'_s from the
//   current radii, a small particle's growth swelled the large particle's side and a pair pushed
//   harder while it was unloaded). Equal spheres of one material: R'_s = R, exactly (37) as the
//   authors apply it.
#include <epac/core/kokkos_compat.hpp>

namespace epac {

template <class T>
struct MdrEqualPair {
  T R[2];  // R'_s, the equivalent sides' radii
  T w[2];  // w_s = E*/E_s, each side's share of the overlap
};

// R_s > 0, E_s > 0 (Mdr::create validates both).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrEqualPair<T> mdr_equal_pair(T R0, T R1, T E0, T E1) {
  MdrEqualPair<T> q;
  const T inv_E = T(1) / (E0 + E1);
  q.w[0] = E1 * inv_E;
  q.w[1] = E0 * inv_E;
  const T R_star = R0 * R1 / (R0 + R1);
  // R*/w_s without dividing by a tiny w: R* (E_0 + E_1)/E_o
  q.R[0] = R_star * (E0 + E1) / E1;
  q.R[1] = R_star * (E0 + E1) / E0;
  return q;
}

// With radius growth: the sides of the initial radii R_o,s, each grown by its own particle's
// growth R_s - R_o,s (header). Without growth (R_s = R_o,s) mdr_equal_pair itself.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION MdrEqualPair<T> mdr_equal_pair_grown(T R0, T R1, T R0o, T R1o, T E0, T E1) {
  MdrEqualPair<T> q = mdr_equal_pair(R0o, R1o, E0, E1);
  q.R[0] += R0 - R0o;
  q.R[1] += R1 - R1o;
  return q;
}

}  // namespace epac
