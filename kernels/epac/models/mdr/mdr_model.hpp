#pragma once
// The MDR contact model (Zunker & Kamrin, Part I) with the interface of models/hertz_mindlin.hpp:
// `normal(g, row)` for the generic contact kernel (compute/contact_forces.hpp), a per-pair table
// indexed by g.pair, history fields only for enabled effects.
//
// - Wall contact (g.j == -1): one side, particle i against the wall as a rigid flat.
// - Pair: two sides split by the rigid flat at the contact plane, placed where the sides' scaled
//   forces balance (mdr_pair_balance.hpp; the geometric split of mdr_pair_split.hpp is the first
//   guess); side 0 is the particle with the smaller global id; the pair force is the mean of the
//   sides' forces.
// - Each side is mdr_side_force (elastic, fully plastic, adhesive) with E_eff = E/(1-nu^2) of its
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
//   (mdr_parameters.hpp) for comparisons with LAMMPS's `granular mdr`.
// - A contact is inactive (its history reset, tangential history too) once the apparent overlap is
//   <= 0 and no side holds an adhesive radius, or once the surfaces are apart by more than the
//   contact's critical overlap (mdr_detachment.hpp), whatever the sides' histories; the reset
//   happens in the step that releases it, so a re-approach starts as a new contact. The grown
//   radius stays.
// - Radius growth: each side's terms go to the particle sums (mdr_radius_growth.hpp; per-thread
//   copies on host backends, atomics on GPUs); call bind(particles) once and update_radii() after
//   every force pass (docs/design.md section 4 step 4); update_radii also clears the copies for the
//   next pass, so no begin call is needed. Deterministic mode (compute/deterministic_pass.hpp):
//   the terms are stored per contact side (growth_terms) and added per particle in key order.
#include <epac/compute/contact_side_sums.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/effects.hpp>
#include <epac/models/mdr/mdr_detachment.hpp>
#include <epac/models/mdr/mdr_pair_balance.hpp>
#include <epac/models/mdr/mdr_pair_split.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>
#include <epac/models/mdr/mdr_radius_growth.hpp>
#include <epac/models/mdr/mdr_side_force.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/particles.hpp>

#include <array>
#include <vector>

namespace epac {

// Per-contact outputs (issue item 6). Pair values are means over the two sides.
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

template <class T, class Eff = AllEffects, class Device = DefaultDevice>
struct Mdr {
  using scalar_type = T;
  using effects = Eff;
  using device_type = Device;
  static constexpr const char* name = "mdr";
  static constexpr bool uses_side_order = true;  // sides ordered by global id (g.i_is_first)

  // --- history layout: [pair fields][side 0][side 1] ---
  static constexpr int kPlasticFields = Eff::plasticity ? 4 : 0;  // delta_o,max, yielded, c_A, delta_p
  static constexpr int kAdhesionFields = Eff::adhesion ? 1 : 0;   // a
  static constexpr int kGrowthFields = Eff::radius_growth ? 2 : 0;  // delta_o,prev, eps_c,prev
  static constexpr int side_fields = kPlasticFields + kAdhesionFields + kGrowthFields;
  // largest total delta_o (19); once a side yielded, the last pass's d_0, delta and
  // w = d d_0/d delta (the balance's first guess d_0 + w (delta_now - delta), mdr_pair_balance.hpp)
  static constexpr int pair_fields = Eff::plasticity ? 4 : 0;
  static constexpr int normal_history_size = pair_fields + 2 * side_fields;
  static constexpr int history_size = normal_history_size + (Eff::friction ? 3 : 0);

  Kokkos::View<MdrSideConstants<T>*, Device> sides;  // per material
  Kokkos::View<MdrPairConstants<T>*, Device> pairs;  // per material pair, mat_i * nmat + mat_j
  int nmat = 0;
  T xi = T(1);
  bool geometric_split = false;  // MdrOptions::pair_split == geometric (the authors' flat)
  // MdrOptions::delta_max: 1 for MDR (19), delta_max shifted by R - R_o; 0 for the authors' running
  // maximum of delta (the sides then see no shift)
  T growth_in_max = T(1);
  bool authors_damping = false;   // MdrOptions::damping == authors (pc.c_damp is then beta, mdr_pair_constants)
  bool authors_friction = false;  // MdrOptions::friction == authors
  T k_t_authors = T(0);           // MdrOptions::tangential_stiffness
  T adhesive_radius_factor = T(1);  // MdrOptions::adhesive_radius: 1 (paper) or 0.99 (authors)
  bool release_at_zero_overlap = false;  // MdrOptions::release == zero_overlap
  MdrGrowthState<T, Device> growth;  // bound by bind() when Eff::radius_growth
  // Deterministic mode: the growth terms (columns of growth.sums) per contact side, enabled by
  // begin_deterministic_pass; side 0 of a pair is the particle with the smaller global id.
  ContactSideSums<T, 3, Device> growth_terms;

  // --- history access ---
  static KOKKOS_INLINE_FUNCTION int side_base(int s) { return pair_fields + s * side_fields; }

  static KOKKOS_INLINE_FUNCTION MdrSideState<T> load_side(const HistoryRow<T, Device>& row, int s) {
    MdrSideState<T> st;
    const int b = side_base(s);
    if (Eff::plasticity) {
      st.delta_o_max = row(b + 0); st.yielded = row(b + 1); st.c_A = row(b + 2); st.delta_p = row(b + 3);
    }
    if (Eff::adhesion) st.a_adh = row(b + kPlasticFields);
    if (Eff::radius_growth) {
      st.delta_o_prev = row(b + kPlasticFields + kAdhesionFields);
      st.eps_prev = row(b + kPlasticFields + kAdhesionFields + 1);
    }
    return st;
  }
  static KOKKOS_INLINE_FUNCTION void store_side(const HistoryRow<T, Device>& row, int s,
                                                const MdrSideState<T>& st) {
    const int b = side_base(s);
    if (Eff::plasticity) {
      row(b + 0) = st.delta_o_max; row(b + 1) = st.yielded; row(b + 2) = st.c_A; row(b + 3) = st.delta_p;
    }
    if (Eff::adhesion) row(b + kPlasticFields) = st.a_adh;
    if (Eff::radius_growth) {
      row(b + kPlasticFields + kAdhesionFields) = st.delta_o_prev;
      row(b + kPlasticFields + kAdhesionFields + 1) = st.eps_prev;
    }
  }

  // Evaluates the contact; Write = true advances history and adds growth terms (the force pass),
  // Write = false only reads (outputs). A second evaluation at the same geometry right after a
  // force pass returns the same force (the state reached is a fixed point of the law).
  // Hot path: one pair-table load (both sides' constants), history fields loaded only where the
  // regime reads them and stored only where they change.
  template <bool Write>
  KOKKOS_FORCEINLINE_FUNCTION MdrContactOutput<T> evaluate(const ContactGeometry<T>& g,
                                                           const HistoryRow<T, Device>& row,
                                                           NormalForce<T>* nf_out) const {
    MdrContactOutput<T> o;
    const bool is_pair = g.j >= 0;
    const int nsides = is_pair ? 2 : 1;
    o.sides = nsides;
    // sides ordered by global id; a wall has one side (side 0 = particle i)
    const bool swap = is_pair && !g.i_is_first;
    const int part[2] = {swap ? g.j : g.i, swap ? g.i : g.j};
    const T Rs[2] = {swap ? g.R_j : g.R_i, swap ? g.R_i : g.R_j};

    // adhesive hold: an open contact stays while a side keeps an adhesive radius, unless the
    // surfaces are apart by more than its critical overlap (asked only at delta <= 0: there it
    // cannot depend on how the split shares a positive overlap, and compressed contacts pay nothing;
    // a critical overlap above 0, heavy plastic flow with weak adhesion, is reached by the side law)
    T a_adh_old[2] = {T(0), T(0)};
    bool adhesive_hold = false;
    if (Eff::adhesion)
      for (int s = 0; s < nsides; ++s) {
        a_adh_old[s] = row(side_base(s) + kPlasticFields);
        adhesive_hold = adhesive_hold || a_adh_old[s] > T(0);
      }
    // (MdrRelease::zero_overlap, the authors' code: no hold, released at delta <= 0)
    if (release_at_zero_overlap) adhesive_hold = false;
    if ((!(g.delta > T(0)) && !adhesive_hold) ||
        (Eff::adhesion && adhesive_hold && !(g.delta > T(0)) && g.delta < critical_overlap(g, row)))
      return released<Write>(g, row, nf_out);
    o.active = true;

    const MdrPairConstants<T>& pc = pairs(g.pair);  // reference: load only the fields used
    const bool grows = Eff::radius_growth && growth.bound();

    // growth of each side's radius, R - R_o (0 without radius growth): delta_o = delta - growth
    T R0s[2] = {Rs[0], Rs[1]};
    T growth_of[2] = {T(0), T(0)};
    if (grows)
      for (int s = 0; s < nsides; ++s) {
        R0s[s] = growth.radius0(part[s]);
        growth_of[s] = growth_in_max * (Rs[s] - R0s[s]);  // delta_max's shift (MdrDeltaMax)
      }

    // per-side history: the fields every regime needs (delta_p: below)
    MdrSideState<T> st[2];
    for (int s = 0; s < nsides; ++s) {
      const int b = side_base(s);
      if (Eff::plasticity) {
        st[s].delta_o_max = row(b + 0);
        st[s].yielded = row(b + 1);
        if (st[s].yielded != T(0)) st[s].c_A = row(b + 2);  // read only once plastic
        if (!Write) st[s].delta_p = row(b + 3);             // outputs report it
      }
      if (Eff::adhesion) st[s].a_adh = a_adh_old[s];
      if (Eff::radius_growth) {
        st[s].delta_o_prev = row(b + kPlasticFields + kAdhesionFields);
        st[s].eps_prev = row(b + kPlasticFields + kAdhesionFields + 1);
      }
    }

    T dside[2] = {g.delta, T(0)};
    if (is_pair) {
      // largest total overlap by (19): running maximum of the total delta_o, plus both growths
      // (MdrDeltaMax::running_max: of the total delta itself, the authors' code)
      const T shift = growth_of[0] + growth_of[1];
      T dmax = g.delta;
      if (Eff::plasticity) {
        const T old = row(0);
        const T dmax_o = math::max(old, g.delta - shift);
        if (Write && dmax_o != old) row(0) = dmax_o;
        dmax = dmax_o + shift;
      }
      // the residual overlaps enter the geometric split only below dmax (mdr_split_overlap)
      if (Write && Eff::plasticity && dmax > T(0) && !(g.delta >= dmax))
        for (int s = 0; s < 2; ++s) st[s].delta_p = row(side_base(s) + 3);
      const MdrSideOverlaps<T> so = mdr_split_overlap(g.delta, dmax, Rs[0], Rs[1], st[0].delta_p, st[1].delta_p);
      dside[0] = so.d0;
      dside[1] = so.d1;
      o.delta_max = dmax;
    }

    // the sides' results: a pair's from the balanced split (mdr_pair_balance.hpp, the geometric
    // split as its first guess), a wall's side directly
    MdrSideState<T> before[2] = {st[0], st[1]};
    MdrSideResult<T> res[2];
    if (is_pair) {
      MdrPairSides<T, Eff::plasticity, Eff::adhesion> ps;
      for (int s = 0; s < 2; ++s) {
        const bool side_b = (s == 0) == swap;  // side 0 is material b when swapped; side 1 unless
        ps.c[s] = side_b ? &pc.side_b : &pc.side_a;
        // Each side's share of the surface energy: gamma_s = Delta gamma E* / E_eff,s (see the header)
        ps.gamma[s] = Eff::adhesion ? (side_b ? pc.gamma_b : pc.gamma_a) : T(0);
        ps.R[s] = Rs[s];
        ps.growth[s] = growth_of[s];
        ps.start[s] = st[s];
      }
      ps.xi = xi;
      ps.a_fac = adhesive_radius_factor;
      ps.delta = g.delta;
      ps.set_weights();
      // first guess: the geometric split; once a side yielded, the last pass's ratio (see
      // mdr_pair_balance.hpp: elastic pairs keep a deterministic guess)
      // (MdrPairSplit::geometric: the sides at the geometric split itself, one evaluation, and no
      // warm start to read or keep)
      T d0 = dside[0];
      if (geometric_split) {
        ps(d0);
      } else {
        T guess = dside[0];
        const bool plastic_pair = Eff::plasticity && (st[0].yielded != T(0) || st[1].yielded != T(0));
        if (Eff::plasticity && plastic_pair) {
          const T delta_last = row(2);
          if (delta_last != T(0)) guess = row(1) + row(3) * (g.delta - delta_last);
        }
        d0 = mdr_balance_split(ps, g.delta, guess, Rs[0] + Rs[1]);
      }
      for (int s = 0; s < 2; ++s) {
        dside[s] = ps.d[s];
        st[s] = ps.st[s];
        res[s] = ps.r[s];
      }
      if (Write && Eff::plasticity && !geometric_split) {
        if (st[0].yielded != T(0) || st[1].yielded != T(0)) {
          // w = lambda_1 k_1 / (lambda_0 k_0 + lambda_1 k_1) at the root (in [0, 1] while both
          // stiffnesses are positive; the geometric 1/2 otherwise)
          const T k0 = ps.lambda[0] * res[0].stiffness, k1 = ps.lambda[1] * res[1].stiffness;
          const T w = (k0 > T(0) && k1 > T(0)) ? k1 / (k0 + k1) : T(0.5);
          row(1) = d0;
          row(2) = g.delta != T(0) ? g.delta : T(1e-30) * (Rs[0] + Rs[1]);  // 0 marks "no last pass"
          row(3) = w;
        }
      }
    } else {
      const T gamma_w = Eff::adhesion ? pc.gamma_a : T(0);
      res[0] = mdr_side_force<Eff::plasticity, Eff::adhesion>(pc.side_a, gamma_w, xi, dside[0], Rs[0], growth_of[0], st[0],
                                                              adhesive_radius_factor);
    }

    T F = T(0), a_sum = T(0), area_sum = T(0), a_adh_sum = T(0);
    for (int s = 0; s < nsides; ++s) {
      const bool side_b = (s == 0) == swap;  // as above
      const MdrSideConstants<T>& c = side_b ? pc.side_b : pc.side_a;
      const MdrSideResult<T>& r = res[s];
      F += r.F;
      a_sum += r.a;
      area_sum += r.area;
      a_adh_sum += st[s].a_adh;
      o.yielded += st[s].yielded != T(0) ? 1 : 0;
      o.side_force[s] = r.F;
      o.side_overlap[s] = dside[s];
      o.side_area[s] = r.area;
      o.side_delta_max[s] = r.delta_max;
      o.side_delta_p[s] = st[s].delta_p;
      o.side_radius[s] = r.a;
      if (Write) {
        if (grows) {
          const bool plastic_loading = r.plastic && r.loading && r.F > T(0);
          if (growth_terms.enabled)  // deterministic mode: this side's slot (s is the global-id order)
            mdr_growth_add_side(growth, growth_terms.access(is_pair, g.contact, s), part[s], R0s[s], c.inv_3kappa,
                                r.F, dside[s], Rs[s], plastic_loading, r.plastic, st[s].delta_o_prev, st[s].eps_prev);
          else
            mdr_growth_add_side(growth, growth.sums.scatter.access(), part[s], R0s[s], c.inv_3kappa, r.F, dside[s],
                                Rs[s], plastic_loading, r.plastic, st[s].delta_o_prev, st[s].eps_prev);
        }
        store_changed(row, s, before[s], st[s], r.plastic);
      }
    }
    // every side separated at a gap this step: released now, not at the next evaluation
    if (Eff::adhesion && !(g.delta > T(0)) && a_adh_sum == T(0)) return released<Write>(g, row, nf_out);
    const T inv = is_pair ? T(0.5) : T(1);  // 1 / nsides
    o.force = F * inv;
    o.area = area_sum * inv;
    o.mean_pressure = o.area > T(0) ? o.force / o.area : T(0);
    o.adhesive_radius = a_adh_sum * inv;
    if (!is_pair) o.delta_max = o.side_delta_max[0];

    if (nf_out) {
      NormalForce<T> nf;
      nf.active = true;
      nf.f = o.force;
      nf.k_n = T(2) * pc.E_star * a_sum * inv;
      if (Eff::damping) {
        nf.damping = pc.c_damp;
        nf.damping_t = authors_friction ? T(0) : pc.c_damp;
        nf.damp_compressive_only = true;
      }
      if (Eff::friction) {
        nf.k_t = authors_friction ? k_t_authors : pc.kt_over_kn * nf.k_n;
        nf.mu = pc.mu;
        nf.coulomb_on_damped = authors_friction;
        nf.full_radius_arms = authors_friction;
      }
      if (Eff::damping && authors_damping) {
        // MdrDamping::authors: k_n = E* R* with the current radii (after k_t, which uses MDR's)
        nf.k_n = pc.E_star * g.R_eff;
        nf.damp_may_pull = true;
      }
      *nf_out = nf;
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
  // side's), mdr_detachment.hpp. Below it (more apart) the contact is released whatever its
  // history; hosts can size neighbour lists with it. Needs Eff::adhesion for a value below the
  // residual overlaps.
  KOKKOS_INLINE_FUNCTION T critical_overlap(const ContactGeometry<T>& g, const HistoryRow<T, Device>& row) const {
    const bool is_pair = g.j >= 0;
    const bool swap = is_pair && !g.i_is_first;
    const int part[2] = {swap ? g.j : g.i, swap ? g.i : g.j};
    const T Rs[2] = {swap ? g.R_j : g.R_i, swap ? g.R_i : g.R_j};
    const MdrPairConstants<T>& pc = pairs(g.pair);
    const bool grows = Eff::radius_growth && growth.bound();
    T critical = T(0);
    for (int s = 0; s < (is_pair ? 2 : 1); ++s) {
      const bool side_b = (s == 0) == swap;  // as in evaluate
      const int b = side_base(s);
      MdrSideState<T> st;
      if (Eff::plasticity) {
        st.delta_o_max = row(b + 0);
        st.yielded = row(b + 1);
        st.c_A = row(b + 2);
      }
      const T grown = grows ? growth_in_max * (Rs[s] - growth.radius0(part[s])) : T(0);
      const T gamma_s = Eff::adhesion ? (side_b ? pc.gamma_b : pc.gamma_a) : T(0);
      critical += mdr_side_critical_overlap<Eff::plasticity>(side_b ? pc.side_b : pc.side_a, gamma_s, Rs[s], grown, st);
    }
    return critical;
  }

  // Stores the side's fields that the step changed (a plastic step always rewrites delta_p).
  static KOKKOS_FORCEINLINE_FUNCTION void store_changed(const HistoryRow<T, Device>& row, int s,
                                                        const MdrSideState<T>& was, const MdrSideState<T>& st,
                                                        bool plastic) {
    const int b = side_base(s);
    if (Eff::plasticity) {
      if (st.delta_o_max != was.delta_o_max) row(b + 0) = st.delta_o_max;
      if (st.yielded != was.yielded) {
        row(b + 1) = st.yielded;
        row(b + 2) = st.c_A;
      }
      if (plastic) row(b + 3) = st.delta_p;
    }
    if (Eff::adhesion && st.a_adh != was.a_adh) row(b + kPlasticFields) = st.a_adh;
    if (Eff::radius_growth) {
      row(b + kPlasticFields + kAdhesionFields) = st.delta_o_prev;
      row(b + kPlasticFields + kAdhesionFields + 1) = st.eps_prev;
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

  // --- host ---

  // Builds the tables. Materials used by particles must be deformable; rigid ones serve walls.
  static Mdr create(const std::vector<Material>& materials, const MdrOptions& opt = {}) {  // host
    opt.validate();
    Mdr m;
    m.nmat = static_cast<int>(materials.size());
    m.xi = T(opt.xi);
    m.geometric_split = opt.pair_split == MdrPairSplit::geometric;
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
    return m;
  }

  // Attaches the particles' R_o and R and allocates V and the growth sums (radius growth only).
  void bind(const Particles<T, Device>& p) {
    if (Eff::radius_growth) growth.attach(p.radius0, p.radius);
  }

  // Applies the growth sums of the last force pass: new R and V per particle, sums reset (the
  // per-thread copies of the pass are added first and cleared after: mdr_radius_growth.hpp).
  // count >= 0 updates only particles [0, count) and clears every particle's sums (count 0
  // discards the pass's sums); default: all.
  void update_radii(int count = -1) const {
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
};

}  // namespace epac
