#pragma once
// The MDR contact model (Zunker & Kamrin, Part I) with the interface of models/model_interface.hpp:
// `normal(g, row)` for the generic contact kernel (compute/contact_forces.hpp), a per-pair table
// indexed by g.pair, history fields only for enabled effects.
//
// - Wall contact (g.j == -1): one side, particle i against the wall as a rigid flat.
// - Pair: two sides split by the rigid flat at the contact plane, placed where the sides' scaled
//   forces balance (detail/mdr_pair_balance.hpp; the geometric split of detail/mdr_pair_split.hpp
//   is the first guess); side 0 is the particle with the smaller global id; the pair force is the mean of the
//   sides' forces.
// - Each side is mdr_side_force (detail/mdr_side_force.hpp: elastic, fully plastic, adhesive) with E_eff = E/(1-nu^2) of its
//   own particle.
// - Adhesion of a pair: the flat at the contact plane is fictitious, so the surface energy Delta
//   gamma of the real interface is shared by the two sides in proportion to their share of the
//   edge springs' elastic energy: the sides' springs are in series (extensions ~ 1/E_eff,s), so
//   side s gets gamma_s = Delta gamma E*/E_eff,s (equal spheres: Delta gamma / 2 each; a wall,
//   where E* = E_eff: Delta gamma). With it an elastic pair reproduces JKR between the two spheres
//   exactly (delta = a^2/R* - sqrt(2 pi a Delta gamma/E*), pull-off 3/2 pi Delta gamma R*); giving
//   each side the full Delta gamma (as the authors' code appears to do) doubles the pull-off force
//   of two equal spheres.
// - Damping: NormalForce::damping = c from the restitution by the exact Hertz relation
//   (params/restitution_damping.hpp), with k_n = 2 E* a-bar, E* the pair's composite modulus (rigid
//   wall: the particle's E_eff) and a-bar the mean of the sides' MDR contact half-widths. In the
//   elastic regime this is Hertz's tangent stiffness 2 E* sqrt(R* delta) (same a for both sides of
//   a pair), so an elastic MDR impact has exactly the requested restitution; after yield it is the
//   flat-punch unloading stiffness of the MDR springs. Damping only while the force is compressive
//   (damp_compressive_only). The authors' code uses k_n = E* R* instead.
// - Friction: the foundation's tangential spring with k_t = (4 G*/E*) k_n = 8 G* a-bar (Mindlin,
//   Nan (22)); its Coulomb limit mu |f| uses the MDR force including adhesive tension.
// - MdrDamping::authors and MdrFriction::authors replace both by the authors' code's conventions
//   (mdr_parameters.hpp) for comparisons with LAMMPS's `granular mdr`; those the kernel applies
//   around the normal force come from contact_conventions<Mdr> (end of this file).
// - A contact is inactive (its history reset, tangential history too) once the apparent overlap is
//   <= 0 and no side holds an adhesive radius, or once the surfaces are apart by more than the
//   contact's critical overlap (detail/mdr_detachment.hpp), whatever the sides' histories; the reset
//   happens in the step that releases it, so a re-approach starts as a new contact. The grown
//   radius stays.
// - Radius growth: each side's terms go to the particle sums (mdr_radius_growth.hpp; per-thread
//   copies on host backends, atomics on GPUs); call bind(particles) once and update_radii() after
//   every force pass (docs/design.md section 4 step 4); update_radii also clears the copies for the
//   next pass, so no begin call is needed. Deterministic mode (compute/deterministic_pass.hpp):
//   the terms are stored per contact side (growth_terms) and added per particle in key order.
// - Contact penalty (MdrOptions::contact_penalty, off by default; mdr_contact_penalty.hpp): a pair
//   contact's MDR force, its damping and its growth terms are multiplied by the weight w that
//   compute_contact_penalty(particles, pairs) computed before the pass, as in LAMMPS's MDR.
// - Bulk response (Part II, effect kBulkResponse with MdrOptions::psi_b > 0; mdr_bulk_response.hpp):
//   each side's law sees delta_MDR, its force gains F_BULK; the host calls bind(particles), then
//   per step compute_mean_surface_displacement before the force pass and update_radii after it.
//   Defined on the authors' flat placement (MdrPairSplit::geometric), where a side's overlap is a
//   closed form of the positions that the pre-pass can evaluate before the force pass.
#include <epac/compute/contact_side_sums.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/models/mdr/detail/mdr_detachment.hpp>
#include <epac/models/mdr/detail/mdr_evaluation.hpp>
#include <epac/models/mdr/detail/mdr_pair_balance.hpp>
#include <epac/models/mdr/detail/mdr_pair_equal.hpp>
#include <epac/models/mdr/detail/mdr_pair_split.hpp>
#include <epac/models/mdr/detail/mdr_side_lane.hpp>
#include <epac/models/mdr/detail/mdr_split_lane.hpp>
#include <epac/models/mdr/detail/mdr_side_force.hpp>
#include <epac/models/mdr/mdr_bulk_response.hpp>
#include <epac/models/mdr/mdr_contact_penalty.hpp>
#include <epac/models/mdr/mdr_history_layout.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>
#include <epac/models/mdr/mdr_radius_growth.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/particles.hpp>

#include <array>
#include <type_traits>
#include <vector>

namespace epac {

// Per-contact outputs (Mdr::outputs). Pair values are means over the two sides.
template <class T>
struct MdrContactOutput {
  T force = 0;            // MDR force on i along n (no damping), positive = compressive
  T area = 0;             // contact area (42) with c_A
  T mean_pressure = 0;    // force / area (0 without area)
  T delta_max = 0;        // pair: largest total apparent overlap; wall: the side's delta_max
  int yielded = 0;        // number of yielded sides
  T adhesive_radius = 0;  // stored adhesive contact radius
  int sides = 0;
  T side_force[2] = {0, 0}, side_overlap[2] = {0, 0}, side_area[2] = {0, 0};
  T side_delta_max[2] = {0, 0}, side_delta_p[2] = {0, 0}, side_radius[2] = {0, 0};
  bool active = false;
};

// Default effects: everything MDR Part I models; rolling resistance (kRolling) is opt-in, as for
// every law, and so is Part II's bulk response (kBulkResponse).
template <class T, class Eff = Effects<kAllEffects & ~kRolling & ~kBulkResponse>, class Device = DefaultDevice>
struct Mdr {
  static_assert(!Eff::bulk_response || Eff::plasticity,
                "epac: MDR's bulk response (kBulkResponse) needs kPlasticity (A_c and delta_max,MDR of Part II)");
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "mdr";
  static constexpr bool uses_side_order = true;  // sides ordered by global id (g.i_is_first)

  // --- history layout: [pair fields][side 0][side 1] (mdr_history_layout.hpp) ---
  // The plastic shape kept in the history (MdrSideState::shape_*: 5 fields per side) on host
  // backends, where it saves each unloading side an exp, two roots and two divisions (the fcc
  // hold: 0.82-0.85 of the step with plasticity, 0.94-0.96 as LAMMPS runs it, docs/performance.md);
  // GPUs recompute it rather than move 80 more bytes per contact.
  static constexpr bool stores_shape =
      Eff::plasticity && std::is_same<typename Device::memory_space, Kokkos::HostSpace>::value;
  using PairField = MdrPairFields<Eff>;
  using SideField = MdrSideFields<Eff, stores_shape>;
  static constexpr int kPlasticFields = SideField::plastic_count;    // delta_o,max, yielded, c_A, delta_p
  static constexpr int kAdhesionFields = SideField::adhesion_count;  // a
  static constexpr int kGrowthFields = SideField::growth_count;      // delta_o,prev, eps_c,prev
  static constexpr int side_fields = SideField::count;
  static constexpr int pair_fields = PairField::count;
  static constexpr int normal_history_size = pair_fields + 2 * side_fields;
  // the tangential spring's 3 fields, then rolling resistance's 3 (compute/contact_forces.hpp)
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0) + (Eff::rolling ? 3 : 0);

  Kokkos::View<MdrSideConstants<T>*, Device> sides;  // per material
  Kokkos::View<MdrPairConstants<T>*, Device> pairs;  // per material pair, mat_i * nmat + mat_j
  int nmat = 0;
  RollingTable<T, Device, Eff::rolling> rolling;  // per material pair; empty unless Eff::rolling
  T xi = T(1);
  bool geometric_split = false;    // MdrOptions::pair_split == geometric[_authors] (the authors' flat)
  bool authors_unloading = false;  // MdrOptions::pair_split == geometric_authors (their unloading path)
  bool equal_pair_split = false;   // MdrOptions::pair_split == equal_pair (detail/mdr_pair_equal.hpp)
  // MdrOptions::delta_max: 1 for MDR (19), delta_max shifted by R - R_o; 0 for the authors' running
  // maximum of delta (the sides then see no shift)
  T growth_in_max = T(1);
  bool authors_damping = false;          // MdrOptions::damping == authors (pc.c_damp is then beta, mdr_pair_constants)
  bool authors_friction = false;         // MdrOptions::friction == authors
  T k_t_authors = T(0);                  // MdrOptions::tangential_stiffness
  T adhesive_radius_factor = T(1);       // MdrOptions::adhesive_radius: 1 (paper) or 0.99 (authors)
  bool release_at_zero_overlap = false;  // MdrOptions::release == zero_overlap
  MdrGrowthState<T, Device> growth;      // bound by bind() when Eff::radius_growth
  MdrContactPenalty<T, Device> penalty;  // weights of the pair contacts (MdrOptions::contact_penalty)
  MdrBulkState<T, Device> bulk;          // Part II's per-particle state, bound by bind() with kBulkResponse
  // Deterministic mode: the growth terms (columns of growth.sums) per contact side, enabled by
  // begin_deterministic_pass; side 0 of a pair is the particle with the smaller global id.
  ContactSideSums<T, 3, Device> growth_terms;

  // --- history access ---
  static KOKKOS_INLINE_FUNCTION int side_base(int s) { return pair_fields + s * side_fields; }

  static KOKKOS_INLINE_FUNCTION MdrSideState<T> load_side(const HistoryRow<T, Device>& row, int s) {
    MdrSideState<T> st;
    const int b = side_base(s);
    if (Eff::plasticity) {
      st.delta_o_max = row(b + SideField::delta_o_max);
      st.yielded = row(b + SideField::yielded);
      st.c_A = row(b + SideField::c_A);
      st.delta_p = row(b + SideField::delta_p);
      if (stores_shape) load_shape(row, b, st);
    }
    if (Eff::adhesion) st.a_adh = row(b + SideField::a_adh);
    if (Eff::radius_growth) {
      st.delta_o_prev = row(b + SideField::delta_o_prev);
      st.eps_prev = row(b + SideField::eps_prev);
    }
    return st;
  }
  static KOKKOS_INLINE_FUNCTION void store_side(const HistoryRow<T, Device>& row, int s, const MdrSideState<T>& st) {
    const int b = side_base(s);
    if (Eff::plasticity) {
      row(b + SideField::delta_o_max) = st.delta_o_max;
      row(b + SideField::yielded) = st.yielded;
      row(b + SideField::c_A) = st.c_A;
      row(b + SideField::delta_p) = st.delta_p;
      if (stores_shape) store_shape(row, b, st);
    }
    if (Eff::adhesion) row(b + SideField::a_adh) = st.a_adh;
    if (Eff::radius_growth) {
      row(b + SideField::delta_o_prev) = st.delta_o_prev;
      row(b + SideField::eps_prev) = st.eps_prev;
    }
  }

  // The stored plastic shape (MdrSideState::shape_*), where stores_shape.
  static KOKKOS_FORCEINLINE_FUNCTION void load_shape(const HistoryRow<T, Device>& row, int b, MdrSideState<T>& st) {
    st.shape_delta_max = row(b + SideField::shape_delta_max);
    st.shape_R = row(b + SideField::shape_R);
    st.shape_A = row(b + SideField::shape_A);
    st.shape_a_max = row(b + SideField::shape_a_max);
    st.shape_ratio = row(b + SideField::shape_ratio);
  }
  static KOKKOS_FORCEINLINE_FUNCTION void store_shape(const HistoryRow<T, Device>& row, int b,
                                                      const MdrSideState<T>& st) {
    row(b + SideField::shape_delta_max) = st.shape_delta_max;
    row(b + SideField::shape_R) = st.shape_R;
    row(b + SideField::shape_A) = st.shape_A;
    row(b + SideField::shape_a_max) = st.shape_a_max;
    row(b + SideField::shape_ratio) = st.shape_ratio;
  }

  // Evaluates the contact; Write = true advances history and adds growth terms (the force pass),
  // Write = false only reads (outputs). A second evaluation at the same geometry right after a
  // force pass returns the same force (the state reached is a fixed point of the law).
  // Hot path: one pair-table load (both sides' constants), history fields loaded only where the
  // regime reads them and stored only where they change. The steps are the private members below.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION MdrContactOutput<T> evaluate(const ContactGeometry<T>& g,
                                                           const HistoryRow<T, Device>& row,
                                                           NormalForce<T>* nf_out) const {
    MdrContactOutput<T> o;
    detail::MdrEvaluation<T> e = detail::mdr_order_sides(g);
    o.sides = e.nsides;
    if (releases(g, row, e)) return released<Write>(g, row, nf_out);
    o.active = true;

    const MdrPairConstants<T>& pc = pairs(g.pair);  // reference: load only the fields used
    const bool grows = Eff::radius_growth && growth.bound();
    if (grows) load_growth(e);
    for (int s = 0; s < e.nsides; ++s) e.st[s] = load_side_at_step_start<Write>(row, s, e.a_adh_old[s]);
    e.dside[0] = g.delta;
    if (e.is_pair) o.delta_max = split_pair_overlap<Write>(g, row, e);
    // psi_b 0: Part I exactly, with the configured pair split (the bulk path is the geometric
    // split's, which Mdr::create requires only for psi_b > 0)
    const bool bulky = bulk_active();
    if (bulky) bulk_split(row, e);  // delta_MDR per side (e.bulk), Part II

    // the sides' results: a pair's from the balanced split (detail/mdr_pair_balance.hpp, the
    // geometric split as its first guess), a wall's side directly
    e.before[0] = e.st[0];
    e.before[1] = e.st[1];
    if (bulky)
      bulk_sides(g, pc, e);  // each side at its delta_MDR (the geometric split only)
    else if (e.is_pair)
      balance_pair_sides<Write>(g, row, pc, e);
    else
      wall_side(pc, e);
    if (bulky) bulk_forces(pc, e);

    // the contact penalty's weight (1 for walls, and without the option: one branch)
    const T w = e.is_pair ? penalty.weight_of(g.contact) : T(1);
    const SideSums sum = finish_sides<Write>(g, row, pc, grows, w, e, o);
    // every side separated at a gap this step: released now, not at the next evaluation
    if (Eff::adhesion && !(g.delta > T(0)) && sum.a_adh == T(0)) return released<Write>(g, row, nf_out);
    const T inv = e.is_pair ? T(0.5) : T(1);  // 1 / nsides
    contact_means(o, sum, inv, e.is_pair);
    o.force *= w;
    if (nf_out) {
      *nf_out = normal_force(g, pc, o.force, sum.a, inv);
      nf_out->damping *= w;  // LAMMPS: F += w F_damp
    }
    return o;
  }

  // A released contact (the surfaces apart, delta <= 0): no force, inactive (the kernel resets the
  // tangential history) and the normal history reset, as for a new contact.
  template <bool Write>
  KOKKOS_INLINE_FUNCTION MdrContactOutput<T> released(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                      NormalForce<T>* nf_out) const {
    if (Write)
      for (int k = 0; k < normal_history_size; ++k) row(k) = T(0);
    if (nf_out) *nf_out = NormalForce<T>();
    MdrContactOutput<T> o;
    o.sides = g.j >= 0 ? 2 : 1;
    return o;
  }

  // The contact's critical overlap for its stored state: the sum of its sides' (a wall: its one
  // side's), detail/mdr_detachment.hpp. Below it (more apart) the contact is released whatever its
  // history; hosts can size neighbour lists with it. Needs Eff::adhesion for a value below the
  // residual overlaps.
  KOKKOS_INLINE_FUNCTION T critical_overlap(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row) const {
    detail::MdrEvaluation<T> e = detail::mdr_order_sides(g);
    const MdrPairConstants<T>& pc = pairs(g.pair);
    // R_o and the shifts R - R_o as evaluate loads them (one helper, so the two cannot differ;
    // without growth e.R0s = e.Rs and no shift)
    if (Eff::radius_growth && growth.bound()) load_growth(e);
    T critical = T(0);
    T R[2] = {e.Rs[0], e.Rs[1]};
    if (e.is_pair && equal_pair_split) {
      // the equivalent equal pair's sides (detail/mdr_pair_equal.hpp)
      const bool b0 = e.swap;  // side 0 is material b when swapped
      const MdrEqualPair<T> q = mdr_equal_pair_grown(
          e.Rs[0], e.Rs[1], e.R0s[0], e.R0s[1], (b0 ? pc.side_b : pc.side_a).E_eff, (b0 ? pc.side_a : pc.side_b).E_eff);
      for (int s = 0; s < 2; ++s) R[s] = q.R[s];  // each side's own growth, as in equal_pair_sides
    }
    for (int s = 0; s < e.nsides; ++s) {
      const bool side_b = (s == 0) == e.swap;        // as in evaluate
      const MdrSideState<T> st = load_side(row, s);  // reads delta_o,max, yielded, c_A
      const T gamma_s = Eff::adhesion ? (side_b ? pc.gamma_b : pc.gamma_a) : T(0);
      critical +=
          mdr_side_critical_overlap<Eff::plasticity>(side_b ? pc.side_b : pc.side_a, gamma_s, R[s], e.growth_of[s], st);
    }
    return critical;
  }

  // Stores the side's fields that the step changed (a plastic step always rewrites delta_p).
  static KOKKOS_FORCEINLINE_FUNCTION void store_changed(const HistoryRow<T, Device>& row, int s,
                                                        const MdrSideState<T>& was, const MdrSideState<T>& st,
                                                        bool plastic) {
    const int b = side_base(s);
    if (Eff::plasticity) {
      if (st.delta_o_max != was.delta_o_max) row(b + SideField::delta_o_max) = st.delta_o_max;
      if (st.yielded != was.yielded) {
        row(b + SideField::yielded) = st.yielded;
        row(b + SideField::c_A) = st.c_A;
      }
      if (plastic) row(b + SideField::delta_p) = st.delta_p;
      // a new shape whenever its key moved (the same key holds the same shape)
      if (stores_shape && (st.shape_R != was.shape_R || st.shape_delta_max != was.shape_delta_max))
        store_shape(row, b, st);
    }
    if (Eff::adhesion && st.a_adh != was.a_adh) row(b + SideField::a_adh) = st.a_adh;
    if (Eff::radius_growth) {
      row(b + SideField::delta_o_prev) = st.delta_o_prev;
      row(b + SideField::eps_prev) = st.eps_prev;
    }
  }

  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>& g,
                                                    const HistoryRow<T, Device>& row) const {
    NormalForce<T> nf;
    evaluate<true>(g, row, &nf);
    return nf;
  }

  // Per-contact outputs from the history row, read-only (call after the force pass, before
  // update_radii, with the geometry the force pass saw).
  KOKKOS_INLINE_FUNCTION MdrContactOutput<T> outputs(const ContactGeometry<T>& g,
                                                     const HistoryRow<T, Device>& row) const {
    return evaluate<false>(g, row, nullptr);
  }

  // --- contacts in lanes (compute/pair_lanes.hpp) ---
  // The common path of a pair contact as the geometric split runs it (MdrPairSplit::geometric,
  // the side-by-side's like-with-like scene): both sides yielded, below their delta_max, on their
  // stored shapes (detail/mdr_side_lane.hpp), the pair between its summed residuals and its
  // largest overlap (detail/mdr_split_lane.hpp), with Part II and growth without plastic loading.
  // Every other contact is flagged rare and takes evaluate<true> from its stored history. Its
  // values are evaluate's expressions in its order, except the side law's ellipse angle
  // (lane_two_asin_sqrt, within 2 ulp of libm's): the two kernels agree to a few ulp.
  static constexpr bool lane_form = Eff::plasticity && !Eff::adhesion && stores_shape;
  static constexpr int lane_sum_count = 8;  // per side: eps_c (37)-(38), A_con, A_tot's sum, V_cap
  using lane_constants = MdrPairConstants<T>;
  KOKKOS_FORCEINLINE_FUNCTION lane_constants lane_pair(int k) const { return pairs(k); }
  // Host: the options the lane form covers. Growth and Part II bound (their views are read without
  // a test), the plastic_loading growth rule, no per-contact growth terms (deterministic mode),
  // the tangential damping either off or the authors' (k_t is not a fixed multiple of k_n).
  bool lane_form_applies() const {
    return geometric_split && !authors_unloading && !equal_pair_split && !growth_terms.enabled &&
           (!Eff::radius_growth || (growth.bound() && growth.rule == MdrGrowthRule::plastic_loading)) &&
           (!Eff::bulk_response || bulk_active()) && (!(Eff::friction && Eff::damping) || authors_friction) &&
           penalty.weight.extent(0) > 0;
  }

  // h: the lane's history fields (h[f]), rewritten where the common path holds and left as they
  // were where it does not (rare set to 1: the kernel then takes evaluate from the stored row);
  // sums[q]: the lane's per-particle sums, added by add_lane_sums. Side 0 is c.i, the smaller
  // global id (the lanes kernel orders each pair so), hence material a (set_pair_sides, unswapped).
  template <class Index, class Hist, class Sums>
  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> contact_lane(const lane_constants& pc, const LaneContact<T, Index>& c,
                                                          const Hist& h, const Sums& sums, T& rare) const {
    const T w = penalty.weight_of_lane(c.k);  // the contact penalty's weight (1 without it)
    // load_growth: R_o and the shift of delta_max of each side
    const T R0_i = Eff::radius_growth ? growth.radius0(c.i) : c.R_i;
    const T R0_j = Eff::radius_growth ? growth.radius0(c.j) : c.R_j;
    const T g_i = Eff::radius_growth ? growth_in_max * (c.R_i - R0_i) : T(0);
    const T g_j = Eff::radius_growth ? growth_in_max * (c.R_j - R0_j) : T(0);
    // split_pair_overlap: a pair past its largest overlap loads (rare: delta_o,max moves)
    const T shift = g_i + g_j;
    const T old = h[PairField::delta_o_max];
    const T dmax_o = lane_max(old, c.delta - shift);
    const MdrSplitLane<T> so =
        mdr_split_overlap_lane(c.delta, dmax_o + shift, c.R_i, c.R_j, h[side_base(0) + SideField::delta_p],
                               h[side_base(1) + SideField::delta_p]);
    const LaneSide s0 = lane_side(pc.side_a, h, side_base(0), c.i, so.d0, c.R_i, R0_i, g_i, w);
    const LaneSide s1 = lane_side(pc.side_b, h, side_base(1), c.j, so.d1, c.R_j, R0_j, g_j, w);
    const bool is_rare =
        !(c.delta > T(0)) | (dmax_o != old) | (so.rare != T(0)) | (s0.rare != T(0)) | (s1.rare != T(0));
    commit_lane_side(h, sums, 0, s0, is_rare);
    commit_lane_side(h, sums, 1, s1, is_rare);
    rare = lane_select(is_rare, T(1), T(0));
    return lane_normal_force(pc, (s0.F + s1.F) * T(0.5) * w, s0.a + s1.a, w, c.R_eff);
  }

  // The kernel's scatter of a common-path lane's sums (contact_lane's order: side 0, side 1).
  template <class Sums>
  KOKKOS_FORCEINLINE_FUNCTION void add_lane_sums(int i, int j, const Sums& sums) const {
    const int part[2] = {i, j};
    for (int s = 0; s < 2; ++s) {
      if (Eff::radius_growth) {
        auto acc = growth.sums.scatter.access();
        acc(part[s], int(MdrGrowthState<T, Device>::kEps)) += sums[4 * s];
      }
      if (Eff::bulk_response) {
        auto acc = bulk.sums.scatter.access();
        for (int q = 0; q < 3; ++q) acc(part[s], q) += sums[4 * s + 1 + q];
      }
    }
  }

  // --- host ---

  // Builds the tables. Materials used by particles must be deformable; rigid ones serve walls.
  static Mdr create(const std::vector<Material>& materials, const MdrOptions& opt = {}) {  // host
    opt.validate();
    Mdr m;
    m.nmat = static_cast<int>(materials.size());
    m.xi = T(opt.xi);
    m.geometric_split = opt.pair_split == MdrPairSplit::geometric || opt.pair_split == MdrPairSplit::geometric_authors;
    m.authors_unloading = opt.pair_split == MdrPairSplit::geometric_authors;
    m.equal_pair_split = opt.pair_split == MdrPairSplit::equal_pair;
    m.sides = Kokkos::View<MdrSideConstants<T>*, Device>("mdr.sides", m.nmat);
    m.pairs = Kokkos::View<MdrPairConstants<T>*, Device>("mdr.pairs", m.nmat * m.nmat);
    auto hs = Kokkos::create_mirror_view(m.sides);
    auto hp = Kokkos::create_mirror_view(m.pairs);
    for (int a = 0; a < m.nmat; ++a) {
      materials[a].validate();
      hs(a) = materials[a].rigid ? MdrSideConstants<T>{} : mdr_side_constants<T>(materials[a], opt.yield_onset);
    }
    for (int a = 0; a < m.nmat; ++a)
      for (int b = 0; b < m.nmat; ++b)
        hp(a * m.nmat + b) = (materials[a].rigid && materials[b].rigid)
                                 ? MdrPairConstants<T>{}
                                 : mdr_pair_constants<T>(materials[a], materials[b], opt.yield_onset,
                                                         opt.surface_energy_share, opt.damping);
    for (int a = 0; a < m.nmat; ++a) hp(a * m.nmat + a).same_material = true;
    m.growth_in_max = opt.delta_max == MdrDeltaMax::running_max ? T(0) : T(1);
    m.authors_friction = opt.friction == MdrFriction::authors;
    m.k_t_authors = T(opt.friction == MdrFriction::authors ? opt.tangential_stiffness : 0.0);
    m.authors_damping = opt.damping == MdrDamping::authors;
    m.adhesive_radius_factor = T(opt.adhesive_radius == MdrAdhesiveRadius::authors ? 0.99 : 1.0);
    m.release_at_zero_overlap = opt.release == MdrRelease::zero_overlap;
    Kokkos::deep_copy(m.sides, hs);
    Kokkos::deep_copy(m.pairs, hp);
    m.growth.rule = opt.growth_rule;
    m.growth.radius_cap = T(opt.radius_cap);
    m.growth.denominator_floor = T(opt.denominator_floor);
    m.growth.volume_floor = T(opt.volume_floor);
    m.rolling = RollingTable<T, Device, Eff::rolling>::create(materials);
    m.penalty.on = opt.contact_penalty;
    // one weight of 1 until the first weigh(): weight_of_lane's load stays in bounds, and an unweighed
    // list reads 1 from either form
    m.penalty.weight = Kokkos::View<T*, Device>("mdr.penalty.weight", 1);
    Kokkos::deep_copy(m.penalty.weight, T(1));
    if (opt.psi_b > 0.0 && !Eff::bulk_response)
      throw ParameterError("mdr: psi_b = " + std::to_string(opt.psi_b) +
                           " needs the bulk response compiled in (effect kBulkResponse); valid without it: psi_b = 0");
    m.bulk.psi_b = T(opt.psi_b);
    m.bulk.volume_floor = T(opt.volume_floor);
    return m;
  }

  // Contact penalty (MdrOptions::contact_penalty; a no-op without it): the weights of `pairs` for
  // the next force pass, from the positions and radii now; call it before every force pass on
  // that list. list_stamp: any number that changes whenever the list does (a rebuild count): the
  // per-particle index of the list is rebuilt only then (-1: always). nlocal: hosts with ghost
  // copies past nlocal (LAMMPS), else -1.
  void compute_contact_penalty(const Particles<T, Device>& p, const ContactList<Device>& pairs, int nlocal = -1,
                               std::int64_t list_stamp = -1) {
    if (!penalty.on) return;
    if (list_stamp < 0 || list_stamp != penalty.indexed_stamp || nlocal != penalty.indexed_nlocal) {
      penalty.index(pairs, p, nlocal);
      penalty.indexed_stamp = list_stamp;
    }
    penalty.weigh(p, pairs, nlocal);
  }

  // Attaches the particles' R_o and R and allocates V and the growth sums (radius growth only),
  // and Part II's per-particle state (bulk response only; psi = 1, V_geo = V_o).
  void bind(const Particles<T, Device>& p) {
    if (Eff::radius_growth) growth.attach(p.radius0, p.radius);
    if (Eff::bulk_response) {
      bulk.attach(p.radius0);
      bulk.radius = p.radius;
      bulk.radius0 = p.radius0;
      growth.psi = bulk.psi;  // the gate of (37): growth only while psi > psi_b
      growth.psi_b = bulk.psi_b;
    }
  }

  // Part II's mean surface displacement d delta-bar per particle for the next force pass (bulk
  // response only; else a no-op), from the positions now and the contacts' history: call it
  // before every force pass, after compute_contact_penalty, with the lists that pass evaluates.
  // nlocal: hosts with ghost copies past nlocal (their values are the owners', copied by the
  // host), else -1.
  void compute_mean_surface_displacement(const Particles<T, Device>& p, const ContactList<Device>& pairs,
                                         const ContactHistory<T, Device>& pair_history, const Walls<T, Device>& walls,
                                         const ContactList<Device>& wall_contacts,
                                         const ContactHistory<T, Device>& wall_history) const {
    if (!(Eff::bulk_response && bulk.bound())) return;
    using exec = typename Device::execution_space;
    const Mdr m = *this;
    const auto first = pairs.first, second = pairs.second;
    const auto ph = pair_history.data;
    const int nmat_ = nmat;
    Kokkos::parallel_for(
        "epac::mdr_mean_surface_displacement::pairs", Kokkos::RangePolicy<exec>(0, pairs.count), KOKKOS_LAMBDA(int k) {
          int i = first(k), j = second(k);
          if (p.gid(j) < p.gid(i)) {  // canonical orientation, as the force pass
            const int t = i;
            i = j;
            j = t;
          }
          // the overlap and radii are all it reads (the force pass's bits)
          m.add_mean_surface_displacement(detail::pair_overlap_geometry(p, i, j), HistoryRow<T, Device>{ph, k, 0});
        });
    if (wall_contacts.count > 0 && walls.n > 0) {
      const auto wfirst = wall_contacts.first, wsecond = wall_contacts.second;
      const auto wh = wall_history.data;
      Kokkos::parallel_for(
          "epac::mdr_mean_surface_displacement::walls", Kokkos::RangePolicy<exec>(0, wall_contacts.count),
          KOKKOS_LAMBDA(int k) {
            double delta;
            const ContactGeometry<T> g = detail::wall_geometry_exact(p, walls, wfirst(k), wsecond(k), nmat_, delta);
            m.add_mean_surface_displacement(g, HistoryRow<T, Device>{wh, k, 0});
          });
    }
    mdr_finish_mean_disp(bulk);
  }

  // One contact's terms of d delta-bar: each side's (w A_c of the last pass / A_con,0 of its
  // particle) (delta now - delta then), for touching contacts (LAMMPS skips the others).
  KOKKOS_FORCEINLINE_FUNCTION void add_mean_surface_displacement(const ContactGeometry<T>& g,
                                                                 const HistoryRow<T, Device>& row) const {
    if (!(g.delta > T(0))) return;
    detail::MdrEvaluation<T> e = detail::mdr_order_sides(g);
    if (Eff::radius_growth && growth.bound()) load_growth(e);
    e.dside[0] = g.delta;
    if (e.is_pair) {
      for (int s = 0; s < 2; ++s) e.st[s].delta_p = row(side_base(s) + SideField::delta_p);
      split_pair_overlap<false>(g, row, e);  // the force pass's geometric split, read-only
    }
    auto acc = bulk.mean_disp.scatter.access();
    for (int s = 0; s < e.nsides; ++s) {
      const int pp = e.part[s];
      const T acon0 = bulk.acon0(pp);
      if (acon0 == T(0)) continue;  // no contact area last pass: no weight (and no division)
      const int b = side_base(s);
      acc(pp) += row(b + SideField::bulk_area_w) / acon0 * (e.dside[s] - row(b + SideField::bulk_delta_last));
    }
  }

  // Applies the growth sums of the last force pass: new R and V per particle, sums reset (the
  // per-thread copies of the pass are added first and cleared after: mdr_radius_growth.hpp).
  // count >= 0 updates only particles [0, count) and clears every particle's sums (count 0
  // discards the pass's sums); default: all.
  // Part II first (psi, V_geo and A_con,0 from the pass's sums, with R before growth), then the
  // growth, gated by psi.
  void update_radii(int count = -1) const {
    if (Eff::bulk_response && bulk.bound()) mdr_update_bulk(bulk, bulk.radius, bulk.radius0, count);
    if (Eff::radius_growth && growth.bound()) mdr_update_radii(growth, count);
  }

  // Deterministic mode (compute/deterministic_pass.hpp calls these): before the pass's kernels,
  // room for the lists' contacts with every side's terms zero; after them, the terms added to
  // the growth sums per particle in key order (then update_radii as usual).
  void begin_deterministic_pass(int pair_contacts, int wall_contacts) {
    if (Eff::radius_growth && growth.bound()) growth_terms.begin(pair_contacts, wall_contacts);
  }
  void end_deterministic_pass(const Particles<T, Device>& p, const ContactList<Device>& pairs,
                              const ContactIncidence<Device>& pair_incidence,
                              const ContactIncidence<Device>& wall_incidence) const {
    if (Eff::radius_growth && growth.bound() && growth_terms.enabled)
      reduce_side_sums(p, growth_terms, pairs, pair_incidence, wall_incidence, growth.sums.target);
  }

  // Cumulative count of Part II's V_geo floor (mdr_bulk_response.hpp); 0 without the bulk response.
  int bulk_volume_floor_hits() const {
    if (!(Eff::bulk_response && bulk.bound())) return 0;
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), bulk.vgeo_floored);
    return h(0);
  }

  // Cumulative guard counts of the radius update (MdrGrowthGuard order); zeros without growth.
  std::array<int, kMdrGuardCount> guard_hits() const {
    std::array<int, kMdrGuardCount> out{};
    if (Eff::radius_growth && growth.bound()) {
      auto h = Kokkos::create_mirror_view(growth.guard_hits);
      Kokkos::deep_copy(h, growth.guard_hits);
      for (int k = 0; k < kMdrGuardCount; ++k) out[k] = h(k);
    }
    return out;
  }

 private:
  // --- contact_lane's steps ---

  // One side of a lane on the common path: its force and half-width, its new history values and
  // its terms of the per-particle sums.
  struct LaneSide {
    T F, a, rare;
    T delta, delta_mdr, delta_bulk, area_w;  // Part II's history (bulk_delta_last, _mdr, _bulk, area_w)
    T delta_o_prev, eps;                     // growth's history (eps: eps_prev and the sum's term)
    T acon, atot, vcap;                      // Part II's terms (mdr_bulk_add_side)
  };

  // The side's law at its split overlap d (Part II: at delta_MDR, bulk_split as selects), F_BULK
  // and A_c (bulk_forces; the side is yielded on the common path), and the terms of commit_side:
  // growth's Christoffersen term (mdr_growth_add_side; no plastic loading, so no terms of (37))
  // and Part II's (mdr_bulk_add_side). Division by V (>= volume_floor V_o > 0) and V_geo (same).
  template <class Hist, class Index>
  KOKKOS_FORCEINLINE_FUNCTION LaneSide lane_side(const MdrSideConstants<T>& sc, const Hist& h, int b, Index p, T d, T R,
                                                 T R0, T growth_of, T w) const {
    const T pi = constants<T>::pi;
    LaneSide o{};
    o.delta = d;
    T d_mdr = d, area_c = T(0), f_bulk = T(0);
    if (Eff::bulk_response) {
      const T ddelta = d - h[b + SideField::bulk_delta_last];
      const T ddelta_bar = bulk.ddelta_bar(p);
      const bool triggered = bulk.psi(p) < bulk.psi_b;
      const T dd_mdr =
          lane_select(triggered, lane_min(ddelta - ddelta_bar, d - h[b + SideField::bulk_delta_mdr]), ddelta);
      d_mdr = h[b + SideField::bulk_delta_mdr] + dd_mdr;
      o.delta_mdr = d_mdr;
      o.delta_bulk = lane_max(T(0), h[b + SideField::bulk_delta_bulk] + lane_select(triggered, ddelta_bar, T(0)));
    }
    MdrSideState<T> st;
    st.delta_o_max = h[b + SideField::delta_o_max];
    st.yielded = h[b + SideField::yielded];
    st.c_A = h[b + SideField::c_A];
    st.delta_p = h[b + SideField::delta_p];
    st.shape_delta_max = h[b + SideField::shape_delta_max];
    st.shape_R = h[b + SideField::shape_R];
    st.shape_A = h[b + SideField::shape_A];
    st.shape_a_max = h[b + SideField::shape_a_max];
    st.shape_ratio = h[b + SideField::shape_ratio];
    const MdrSideLane<T> r = mdr_side_force_lane(sc, d_mdr, R, growth_of, st);
    if (Eff::bulk_response) {
      area_c = lane_max(pi * (T(2) * d * R - d * d) + st.c_A, T(0));
      f_bulk = lane_select(o.delta_bulk > T(0), sc.kappa * bulk.acon0(p) * o.delta_bulk * area_c / bulk.vgeo(p), T(0));
    }
    o.F = Eff::bulk_response ? r.F + f_bulk : r.F;
    o.a = r.a;
    o.rare = r.rare;
    if (Eff::radius_growth) {
      const T V = growth.volume(p);
      const T arm = lane_max(R - d, T(0));  // the branch length
      o.eps = -w * o.F * arm * sc.inv_3kappa / V;
      o.delta_o_prev = d - (R - R0);
    }
    if (Eff::bulk_response) {
      o.area_w = w * area_c;
      o.acon = w * area_c;
      o.atot = w * (area_c - T(2) * pi * R * (r.delta_max + o.delta_bulk));
      o.vcap = pi / T(3) * d * d * (T(3) * R - d);
    }
    return o;
  }

  // The side's history (kept as it was on rare lanes) and sum terms.
  template <class Hist, class Sums>
  static KOKKOS_FORCEINLINE_FUNCTION void commit_lane_side(const Hist& h, const Sums& sums, int s, const LaneSide& o,
                                                           bool rare) {
    const int b = side_base(s);
    auto keep = [&](int f, T v) { h[b + f] = lane_select(rare, h[b + f], v); };
    if (Eff::radius_growth) {
      keep(SideField::delta_o_prev, o.delta_o_prev);
      keep(SideField::eps_prev, o.eps);
      sums[4 * s] = o.eps;
    }
    if (Eff::bulk_response) {
      keep(SideField::bulk_delta_last, o.delta);
      keep(SideField::bulk_delta_mdr, o.delta_mdr);
      keep(SideField::bulk_delta_bulk, o.delta_bulk);
      keep(SideField::bulk_area_w, o.area_w);
      sums[4 * s + 1] = o.acon;
      sums[4 * s + 2] = o.atot;
      sums[4 * s + 3] = o.vcap;
    }
  }

  // normal_force for a lane: force (the weighted mean), a_sum (both sides' half-widths), w.
  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> lane_normal_force(const MdrPairConstants<T>& pc, T force, T a_sum, T w,
                                                               T R_eff) const {
    NormalForce<T> nf;
    nf.active = true;
    nf.f = force;
    nf.k_n = T(2) * pc.E_star * a_sum * T(0.5);
    // normal_force's options as selects (a branch on them stops the vectoriser)
    if (Eff::damping) {
      nf.damping = pc.c_damp * w;
      nf.damping_t = lane_select(authors_friction, T(0), pc.c_damp);
      nf.damp_compressive_only = true;
    }
    if (Eff::friction) {
      nf.k_t = lane_select(authors_friction, k_t_authors, pc.kt_over_kn * nf.k_n);
      nf.mu = pc.mu;
    }
    if (Eff::damping) nf.k_n = lane_select(authors_damping, pc.E_star * R_eff, nf.k_n);
    return nf;
  }

  // --- the steps of evaluate, in order ---

  // Sums over the sides (finish_sides).
  struct SideSums {
    T F = T(0), a = T(0), area = T(0), a_adh = T(0);
  };

  // Release of an open contact: true when delta <= 0 and no side holds an adhesive radius, or
  // when the surfaces are apart by more than the critical overlap. The adhesive hold: an open
  // contact stays while a side keeps an adhesive radius, unless the surfaces are apart by more
  // than its critical overlap (asked only at delta <= 0: there it cannot depend on how the split
  // shares a positive overlap, and compressed contacts pay nothing; a critical overlap above 0,
  // heavy plastic flow with weak adhesion, is reached by the side law). Loads e.a_adh_old.
  KOKKOS_FORCEINLINE_FUNCTION bool releases(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                            detail::MdrEvaluation<T>& e) const {
    bool adhesive_hold = false;
    if (Eff::adhesion)
      for (int s = 0; s < e.nsides; ++s) {
        e.a_adh_old[s] = row(side_base(s) + SideField::a_adh);
        adhesive_hold = adhesive_hold || e.a_adh_old[s] > T(0);
      }
    // (MdrRelease::zero_overlap, the authors' code: no hold, released at delta <= 0)
    if (release_at_zero_overlap) adhesive_hold = false;
    return (!(g.delta > T(0)) && !adhesive_hold) ||
           (Eff::adhesion && adhesive_hold && !(g.delta > T(0)) && g.delta < critical_overlap(g, row));
  }

  // Growth of each side's radius, R - R_o (radius growth only): delta_o = delta - growth.
  KOKKOS_FORCEINLINE_FUNCTION void load_growth(detail::MdrEvaluation<T>& e) const {
    for (int s = 0; s < e.nsides; ++s) {
      e.R0s[s] = growth.radius0(e.part[s]);
      e.growth_of[s] = growth_in_max * (e.Rs[s] - e.R0s[s]);  // delta_max's shift (MdrDeltaMax)
    }
  }

  // load_side for the start of a step, reading only what every regime needs: once plastic, c_A,
  // the stored shape and its delta_p (which the plastic regime recomputes with a new shape); an
  // elastic side's delta_p for outputs only; a_adh: the value releases() loaded.
  template <bool Write>
  static KOKKOS_FORCEINLINE_FUNCTION MdrSideState<T> load_side_at_step_start(const HistoryRow<T, Device>& row, int s,
                                                                             T a_adh) {
    MdrSideState<T> st;
    const int b = side_base(s);
    if (Eff::plasticity) {
      st.delta_o_max = row(b + SideField::delta_o_max);
      st.yielded = row(b + SideField::yielded);
      if (st.yielded != T(0)) {  // read only once plastic
        st.c_A = row(b + SideField::c_A);
        st.delta_p = row(b + SideField::delta_p);
        if (stores_shape) load_shape(row, b, st);
      } else if (!Write) {
        st.delta_p = row(b + SideField::delta_p);  // outputs report it
      }
    }
    if (Eff::adhesion) st.a_adh = a_adh;
    if (Eff::radius_growth) {
      st.delta_o_prev = row(b + SideField::delta_o_prev);
      st.eps_prev = row(b + SideField::eps_prev);
    }
    return st;
  }

  // Pair: the largest total overlap by (19), running maximum of the total delta_o plus both
  // growths (MdrDeltaMax::running_max: of the total delta itself, the authors' code), and the
  // geometric split of delta into the sides' overlaps (e.dside). Returns the largest overlap.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION T split_pair_overlap(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                   detail::MdrEvaluation<T>& e) const {
    const T shift = e.growth_of[0] + e.growth_of[1];
    T dmax = g.delta;
    if (Eff::plasticity) {
      const T old = row(PairField::delta_o_max);
      const T dmax_o = math::max(old, g.delta - shift);
      if (Write && dmax_o != old) row(PairField::delta_o_max) = dmax_o;
      dmax = dmax_o + shift;
    }
    // the residual overlaps enter the geometric split only below dmax (mdr_split_overlap)
    if (Write && Eff::plasticity && dmax > T(0) && !(g.delta >= dmax))
      for (int s = 0; s < 2; ++s) e.st[s].delta_p = row(side_base(s) + SideField::delta_p);
    const MdrSideOverlaps<T> so =
        mdr_split_overlap(g.delta, dmax, e.Rs[0], e.Rs[1], e.st[0].delta_p, e.st[1].delta_p, authors_unloading);
    e.dside[0] = so.d0;
    e.dside[1] = so.d1;
    return dmax;
  }

  using PairSides = MdrPairSides<T, Eff::plasticity, Eff::adhesion>;

  // Pair: the sides at the balanced split (MdrPairSplit::geometric: at the geometric split itself,
  // one evaluation, and no warm start to read or keep); e.dside, e.st, e.res from its last
  // evaluation.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION void balance_pair_sides(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                      const MdrPairConstants<T>& pc,
                                                      detail::MdrEvaluation<T>& e) const {
    PairSides ps;
    set_pair_sides(ps, g, pc, e);
    if (equal_pair_split) {
      equal_pair_sides<Write>(g, row, pc, ps, e);
      return;
    }
    T d0 = e.dside[0];
    if (geometric_split) {
      ps.with_stiffness = false;  // no solve: the sides' stiffnesses are not read
      ps(d0);
    } else {
      const T guess = balance_guess(g, row, e);
      d0 = mdr_balance_split(ps, g.delta, guess, e.Rs[0] + e.Rs[1]);
      ps.forces_at_root(mdr_balance_tolerance<T>());  // the forces at the root (mdr_pair_balance.hpp)
    }
    for (int s = 0; s < 2; ++s) {
      e.dside[s] = ps.d[s];
      e.st[s] = ps.st[s];
      e.res[s] = ps.r[s];
    }
    if (Write && Eff::plasticity && !geometric_split) store_balance_warm_start(g, row, ps, e, d0);
  }

  // MdrPairSplit::equal_pair: the sides of the equivalent equal pair (detail/mdr_pair_equal.hpp),
  // radii R'_s. The approach delta_o = delta - both growths split by compliance, each particle's
  // own growth on its own side (MDR (19) per side, the flat staying put while the particle grows,
  // Appendix C). One material: that split itself (both sides are the same side of the equal pair:
  // F_0 = F_1 exactly without growth, and to the sides' own growths with it), one evaluation, no
  // warm start. Two materials: the flat where F_0 = F_1 (the balance solve with equal weights),
  // that split the first guess, once a side yielded the last pass's root moved along its tangent,
  // as for the balanced split. The growth caps (commit_side) are cut from the sides' spheres R'_s.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION void equal_pair_sides(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                    const MdrPairConstants<T>& pc, PairSides& ps,
                                                    detail::MdrEvaluation<T>& e) const {
    // (e.R0s: R_o with radius growth, else the radii: load_growth)
    const MdrEqualPair<T> q =
        mdr_equal_pair_grown(e.Rs[0], e.Rs[1], e.R0s[0], e.R0s[1], ps.c[0]->E_eff, ps.c[1]->E_eff);
    for (int s = 0; s < 2; ++s) {
      ps.R[s] = q.R[s];
      e.R_cap[s] = q.R[s];
      ps.lambda[s] = T(0.5);  // equal forces: the mean force is each side's
    }
    // (ps.growth[s] = e.growth_of[s], set_pair_sides: each side's own growth)
    e.dside[0] = q.w[0] * (g.delta - e.growth_of[0] - e.growth_of[1]) + e.growth_of[0];
    // One material: both sides are the same side of the equal pair, at the same delta_o/2, each
    // grown by its own particle; no solve (a solve here would move the sides' delta_o by its
    // tolerance from step to step, flipping the exact plastic-loading test delta_o >= delta_o,max
    // and with it the growth: round-off then grew to 1e-3 of a compaction's positions).
    T d0 = e.dside[0];
    if (pc.same_material) {
      ps.with_stiffness = false;  // no solve and no warm start: the stiffnesses are not read
      ps(d0);
    } else {
      d0 = mdr_balance_split(ps, g.delta, balance_guess(g, row, e), q.R[0] + q.R[1]);
      ps.forces_at_root(mdr_balance_tolerance<T>());  // the forces at the root (mdr_pair_balance.hpp)
    }
    for (int s = 0; s < 2; ++s) {
      e.dside[s] = ps.d[s];
      e.st[s] = ps.st[s];
      e.res[s] = ps.r[s];
    }
    if (Write && Eff::plasticity && !pc.same_material) store_balance_warm_start(g, row, ps, e, d0);
  }

  // The balance solve's two sides: constants, surface energy shares, radii, growths, states.
  KOKKOS_FORCEINLINE_FUNCTION void set_pair_sides(PairSides& ps, const ContactGeometry<T>& g,
                                                  const MdrPairConstants<T>& pc,
                                                  const detail::MdrEvaluation<T>& e) const {
    for (int s = 0; s < 2; ++s) {
      const bool side_b = (s == 0) == e.swap;  // side 0 is material b when swapped; side 1 unless
      ps.c[s] = side_b ? &pc.side_b : &pc.side_a;
      // Each side's share of the surface energy: gamma_s = Delta gamma E* / E_eff,s (see the header)
      ps.gamma[s] = Eff::adhesion ? (side_b ? pc.gamma_b : pc.gamma_a) : T(0);
      ps.R[s] = e.Rs[s];
      ps.growth[s] = e.growth_of[s];
      ps.start[s] = e.st[s];
    }
    ps.xi = xi;
    ps.a_fac = adhesive_radius_factor;
    ps.delta = g.delta;
    ps.set_weights();
  }

  // First guess of the balance: the geometric split; once a side yielded, the last pass's ratio
  // (see detail/mdr_pair_balance.hpp: elastic pairs keep a deterministic guess).
  static KOKKOS_FORCEINLINE_FUNCTION T balance_guess(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                     const detail::MdrEvaluation<T>& e) {
    T guess = e.dside[0];
    const bool plastic_pair = Eff::plasticity && (e.st[0].yielded != T(0) || e.st[1].yielded != T(0));
    if (Eff::plasticity && plastic_pair) {
      const T delta_last = row(PairField::split_delta);
      if (delta_last != T(0)) guess = row(PairField::split_d0) + row(PairField::split_slope) * (g.delta - delta_last);
    }
    return guess;
  }

  // Once a side yielded: the root d0, delta and the slope w for the next pass's first guess.
  static KOKKOS_FORCEINLINE_FUNCTION void store_balance_warm_start(const ContactGeometry<T>& g,
                                                                   const HistoryRow<T, Device>& row,
                                                                   const PairSides& ps,
                                                                   const detail::MdrEvaluation<T>& e, T d0) {
    if (e.st[0].yielded != T(0) || e.st[1].yielded != T(0)) {
      // w = lambda_1 k_1 / (lambda_0 k_0 + lambda_1 k_1) at the root (in [0, 1] while both
      // stiffnesses are positive; the geometric 1/2 otherwise)
      const T k0 = ps.lambda[0] * e.res[0].stiffness, k1 = ps.lambda[1] * e.res[1].stiffness;
      const T w = (k0 > T(0) && k1 > T(0)) ? k1 / (k0 + k1) : T(0.5);
      row(PairField::split_d0) = d0;
      row(PairField::split_delta) =
          g.delta != T(0) ? g.delta : T(1e-30) * (e.Rs[0] + e.Rs[1]);  // 0 marks "no last pass"
      row(PairField::split_slope) = w;
    }
  }

  // Wall: the one side against the wall as a rigid flat.
  KOKKOS_FORCEINLINE_FUNCTION void wall_side(const MdrPairConstants<T>& pc, detail::MdrEvaluation<T>& e) const {
    const T gamma_w = Eff::adhesion ? pc.gamma_a : T(0);
    e.res[0] = mdr_side_force<Eff::plasticity, Eff::adhesion>(pc.side_a, gamma_w, xi, e.dside[0], e.Rs[0],
                                                              e.growth_of[0], e.st[0], adhesive_radius_factor,
                                                              false);  // no stiffness: no solve
  }

  // Per side: the outputs and sums, then (Write) the growth terms and the changed history.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION SideSums finish_sides(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                                    const MdrPairConstants<T>& pc, bool grows, T w,
                                                    detail::MdrEvaluation<T>& e, MdrContactOutput<T>& o) const {
    SideSums sum;
    for (int s = 0; s < e.nsides; ++s) {
      report_side(o, sum, e, s);
      if (Write) commit_side(g, row, pc, grows, w, e, s);
    }
    return sum;
  }

  static KOKKOS_FORCEINLINE_FUNCTION void report_side(MdrContactOutput<T>& o, SideSums& sum,
                                                      const detail::MdrEvaluation<T>& e, int s) {
    const MdrSideResult<T>& r = e.res[s];
    const T F = Eff::bulk_response ? r.F + e.f_bulk[s] : r.F;  // F_MDR + F_BULK (Part II)
    sum.F += F;
    sum.a += r.a;
    sum.area += r.area;
    sum.a_adh += e.st[s].a_adh;
    o.yielded += e.st[s].yielded != T(0) ? 1 : 0;
    o.side_force[s] = F;
    o.side_overlap[s] = e.dside[s];
    o.side_area[s] = r.area;
    o.side_delta_max[s] = r.delta_max;
    o.side_delta_p[s] = e.st[s].delta_p;
    o.side_radius[s] = r.a;
  }

  // The side's growth terms (deterministic mode: its slot, s in global-id order) and history.
  KOKKOS_FORCEINLINE_FUNCTION void commit_side(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row,
                                               const MdrPairConstants<T>& pc, bool grows, T w,
                                               detail::MdrEvaluation<T>& e, int s) const {
    const MdrSideResult<T>& r = e.res[s];
    MdrSideState<T>& st = e.st[s];
    if (grows) {
      const bool side_b = (s == 0) == e.swap;  // as in set_pair_sides
      const MdrSideConstants<T>& c = side_b ? pc.side_b : pc.side_a;
      const bool plastic_loading = r.plastic && r.loading && r.F > T(0);
      // Part II: the Christoffersen term takes the side's whole force F_MDR + F_BULK, the loading
      // test F_MDR alone (LAMMPS's fix GRANULAR/MDR)
      const T F = Eff::bulk_response ? r.F + e.f_bulk[s] : r.F;
      if (growth_terms.enabled)
        mdr_growth_add_side(growth, growth_terms.access(e.is_pair, g.contact, s), e.part[s], e.R0s[s], c.inv_3kappa, F,
                            e.dside[s], e.Rs[s], plastic_loading, r.plastic, st.delta_o_prev, st.eps_prev, e.R_cap[s],
                            w);
      else
        mdr_growth_add_side(growth, growth.sums.scatter.access(), e.part[s], e.R0s[s], c.inv_3kappa, F, e.dside[s],
                            e.Rs[s], plastic_loading, r.plastic, st.delta_o_prev, st.eps_prev, e.R_cap[s], w);
    }
    if (bulk_active()) commit_bulk_side(row, w, e, s);
    store_changed(row, s, e.before[s], st, r.plastic);
  }

  // --- Part II, the bulk response (mdr_bulk_response.hpp) ---

  KOKKOS_FORCEINLINE_FUNCTION bool bulk_active() const {
    return Eff::bulk_response && bulk.bound() && bulk.psi_b > T(0);
  }

  // Each side's delta_MDR and delta_BULK from its total overlap e.dside and its particle's psi
  // and d delta-bar (e.bulk: the sides' bulk history, advanced).
  KOKKOS_FORCEINLINE_FUNCTION void bulk_split(const HistoryRow<T, Device>& row, detail::MdrEvaluation<T>& e) const {
    for (int s = 0; s < e.nsides; ++s) {
      const int b = side_base(s);
      MdrBulkSide<T>& k = e.bulk[s];
      k.delta_last = row(b + SideField::bulk_delta_last);
      k.delta_mdr = row(b + SideField::bulk_delta_mdr);
      k.delta_bulk = row(b + SideField::bulk_delta_bulk);
      const int p = e.part[s];
      mdr_bulk_split(e.dside[s], bulk.psi(p), bulk.psi_b, bulk.ddelta_bar(p), k);
    }
  }

  // The sides' laws at delta_MDR, each against its flat (the flat placed by the geometric split).
  KOKKOS_FORCEINLINE_FUNCTION void bulk_sides(const ContactGeometry<T>& g, const MdrPairConstants<T>& pc,
                                              detail::MdrEvaluation<T>& e) const {
    if (!e.is_pair) {
      const T gamma_w = Eff::adhesion ? pc.gamma_a : T(0);
      e.res[0] = mdr_side_force<Eff::plasticity, Eff::adhesion>(pc.side_a, gamma_w, xi, e.bulk[0].delta_mdr, e.Rs[0],
                                                                e.growth_of[0], e.st[0], adhesive_radius_factor,
                                                                false);  // no stiffness: no solve
      return;
    }
    PairSides ps;
    set_pair_sides(ps, g, pc, e);
    for (int s = 0; s < 2; ++s)
      e.res[s] = mdr_side_force<Eff::plasticity, Eff::adhesion>(*ps.c[s], ps.gamma[s], xi, e.bulk[s].delta_mdr, ps.R[s],
                                                                ps.growth[s], e.st[s], adhesive_radius_factor,
                                                                false);  // no stiffness: no solve
  }

  // F_BULK and A_c of each side (A_c at the total overlap; it replaces the reported area).
  KOKKOS_FORCEINLINE_FUNCTION void bulk_forces(const MdrPairConstants<T>& pc, detail::MdrEvaluation<T>& e) const {
    for (int s = 0; s < e.nsides; ++s) {
      const bool side_b = e.is_pair && ((s == 0) == e.swap);  // as in set_pair_sides; a wall: side_a
      const MdrSideConstants<T>& c = side_b ? pc.side_b : pc.side_a;
      const int p = e.part[s];
      e.area_c[s] = mdr_bulk_area(e.dside[s], e.Rs[s], e.st[s].yielded != T(0), e.st[s].c_A);
      e.f_bulk[s] = mdr_bulk_force(c.kappa, bulk.acon0(p), bulk.vgeo(p), e.bulk[s].delta_bulk, e.area_c[s]);
      e.res[s].area = e.area_c[s];
    }
  }

  // The side's terms of A_con, A_tot and V_cap, and its bulk history.
  KOKKOS_FORCEINLINE_FUNCTION void commit_bulk_side(const HistoryRow<T, Device>& row, T w, detail::MdrEvaluation<T>& e,
                                                    int s) const {
    const MdrBulkSide<T>& k = e.bulk[s];
    mdr_bulk_add_side(bulk.sums.scatter.access(), e.part[s], w, e.area_c[s], e.Rs[s], e.dside[s], e.res[s].delta_max,
                      k.delta_bulk);
    const int b = side_base(s);
    row(b + SideField::bulk_delta_last) = k.delta_last;
    row(b + SideField::bulk_delta_mdr) = k.delta_mdr;
    row(b + SideField::bulk_delta_bulk) = k.delta_bulk;
    row(b + SideField::bulk_area_w) = w * e.area_c[s];
  }

  // The contact's values: pair means over the two sides.
  static KOKKOS_FORCEINLINE_FUNCTION void contact_means(MdrContactOutput<T>& o, const SideSums& sum, T inv,
                                                        bool is_pair) {
    o.force = sum.F * inv;
    o.area = sum.area * inv;
    o.mean_pressure = o.area > T(0) ? o.force / o.area : T(0);
    o.adhesive_radius = sum.a_adh * inv;
    if (!is_pair) o.delta_max = o.side_delta_max[0];
  }

  // What the kernel applies: the force, k_n = 2 E* a-bar (a_sum inv: the sides' mean half-width),
  // damping and friction (see the header; the authors' conventions: contact_conventions below).
  KOKKOS_FORCEINLINE_FUNCTION NormalForce<T> normal_force(const ContactGeometry<T>& g, const MdrPairConstants<T>& pc,
                                                          T force, T a_sum, T inv) const {
    NormalForce<T> nf;
    nf.active = true;
    nf.f = force;
    nf.k_n = T(2) * pc.E_star * a_sum * inv;
    if (Eff::damping) {
      nf.damping = pc.c_damp;
      nf.damping_t = authors_friction ? T(0) : pc.c_damp;
      nf.damp_compressive_only = true;
    }
    if (Eff::friction) {
      nf.k_t = authors_friction ? k_t_authors : pc.kt_over_kn * nf.k_n;
      nf.mu = pc.mu;
    }
    if (Eff::damping && authors_damping) {
      // MdrDamping::authors: k_n = E* R* with the current radii (after k_t, which uses MDR's)
      nf.k_n = pc.E_star * g.R_eff;
    }
    return nf;
  }
};

// The authors' kernel conventions (MdrDamping::authors: the damped force may pull;
// MdrFriction::authors: Coulomb bound on the damped force, full-radius rolling arms), from the
// options Mdr::create was given.
template <class T, class Eff, class Device>
struct contact_conventions<Mdr<T, Eff, Device>> {
  using type = ContactConventions;
  static type of(const Mdr<T, Eff, Device>& m) {
    type c;
    c.damp_may_pull = Eff::damping && m.authors_damping;
    c.coulomb_on_damped = Eff::friction && m.authors_friction;
    c.full_radius_arms = Eff::friction && m.authors_friction;
    return c;
  }
};

}  // namespace epac
