#pragma once
// The columns of an MDR contact's history row: [pair fields][side 0][side 1], then the
// tangential spring's 3 fields (with friction). Only enabled effects have columns, so the
// offsets depend on the effect set. Side 0 of a pair is the particle with the smaller global id;
// a wall contact has side 0 only (its side 1 columns stay zero).

namespace epac {

// Pair columns (with plasticity): the largest total delta_o of MDR (19), and, once a side
// yielded, the last pass's balanced split, the warm start of the next one
// (detail/mdr_pair_balance.hpp: first guess d_0 + w (delta_now - delta)).
template <class Eff>
struct MdrPairFields {
  static constexpr int delta_o_max = 0;  // running maximum of the total delta_o
  static constexpr int split_d0 = 1;     // d_0 of the last pass
  static constexpr int split_delta = 2;  // delta of the last pass; 0 marks "no last pass"
  static constexpr int split_slope = 3;  // w = d d_0 / d delta at the last pass's root
  static constexpr int count = Eff::plasticity ? 4 : 0;
};

// Side columns, offsets from the side's first column (MdrSideState's fields). StoresShape: the
// plastic shape's columns (Mdr::stores_shape: with plasticity, on host backends).
template <class Eff, bool StoresShape = Eff::plasticity>
struct MdrSideFields {
  // with plasticity
  static constexpr int delta_o_max = 0;
  static constexpr int yielded = 1;
  static constexpr int c_A = 2;
  static constexpr int delta_p = 3;
  static constexpr int plastic_count = Eff::plasticity ? 4 : 0;
  // with adhesion: the adhesive contact radius
  static constexpr int a_adh = plastic_count;
  static constexpr int adhesion_count = Eff::adhesion ? 1 : 0;
  // with radius growth: delta_o and the Christoffersen term of the last step, MDR (37)-(38)
  static constexpr int delta_o_prev = plastic_count + adhesion_count;
  static constexpr int eps_prev = delta_o_prev + 1;
  static constexpr int growth_count = Eff::radius_growth ? 2 : 0;
  // with the bulk response (Part II, mdr_bulk_response.hpp: MdrBulkSide)
  static constexpr int bulk_delta_last = plastic_count + adhesion_count + growth_count;
  static constexpr int bulk_delta_mdr = bulk_delta_last + 1;
  static constexpr int bulk_delta_bulk = bulk_delta_last + 2;
  static constexpr int bulk_area_w = bulk_delta_last + 3;
  static constexpr int bulk_count = Eff::bulk_response ? 4 : 0;
  // with plasticity on host backends: the stored plastic shape (MdrSideState::shape_*,
  // detail/mdr_side_force.hpp)
  static constexpr int shape_delta_max = plastic_count + adhesion_count + growth_count + bulk_count;
  static constexpr int shape_R = shape_delta_max + 1;
  static constexpr int shape_A = shape_delta_max + 2;
  static constexpr int shape_a_max = shape_delta_max + 3;
  static constexpr int shape_ratio = shape_delta_max + 4;
  static constexpr int shape_count = (Eff::plasticity && StoresShape) ? 5 : 0;
  static constexpr int count = plastic_count + adhesion_count + growth_count + bulk_count + shape_count;
};

}  // namespace epac
