#pragma once
// Contact history from the current overlaps: the state a quasi-static, monotonic load from first
// touch to the present overlaps would have reached, for a host that starts from a packing made
// elsewhere (positions with overlaps, no history).
//
// Why: a fresh history sees the whole present overlap as one loading increment. For MDR with
// radius growth the growth sums (37) then take the whole overlap as one plastic increment
// (d(delta_o) = delta_o), R jumps, the apparent overlaps jump with it, and a packing at 0.18 R
// runs to the radius cap within a few steps. Hertz-Mindlin, JKR and Nan 2022 are not unstable
// from a fresh start, but their hysteretic state (Nan's alpha_max, the adhesive contact state)
// is that of a contact that never loaded.
//
// How: the law's own code is driven through K increments with zero velocity and dt = 0, so the
// state is consistent with the law by construction (yield switch, c_A of MDR (43), the pair
// split, adhesion states, Nan's branch logic, whatever a law keeps):
//   for k = 1..K: every contact at once is evaluated (Model::normal) at the overlap of s_k = k/K
//   of its path, then the model's particle update runs (MDR: Mdr::update_radii, (37)-(39)).
// The path of a contact is in terms of delta_o, the overlap of the initial spheres R_o
// (MDR (19): delta = delta_o + (R_i - R_o,i) [+ (R_j - R_o,j)]):
//   - delta_o > 0: delta_o,k = s_k delta_o, the centres approaching from first touch;
//   - delta_o <= 0: delta_o,k = delta_o (the centre distance held; only growth can close the gap).
//   The apparent overlap handed to the law is delta_o,k plus the present growth of each side.
// Scaling every contact at once is a quasi-static proportional load of the whole packing: a
// particle's growth in increment k comes from all its contacts at s_k (MDR (37) sums over the
// particle's contacts), and the apparent overlap of each of its contacts includes that growth in
// increment k + 1, as in a time-stepped compaction whose contacts all advance at the same rate.
// After the last increment delta_o of every contact equals its present value, so the next force
// pass at the same positions is at delta_max (a zero loading increment): no jump.
//
// Effects on the state:
//   - every row of both histories is overwritten (rows of contacts with delta_o <= 0 that growth
//     never closes end as a fresh contact's: zero); tangential history is zero;
//   - MDR with radius growth: R and V restart from R_o and V_o and end at the grown values of
//     the load (the packing is given by positions and R_o); the growth guards count their hits
//     during the load as in a run (Mdr::guard_hits);
//   - forces, torques, positions and velocities are not touched.
// Preconditions: histories with the model's fields for the lists' contacts (rows >= count,
// fields = Model::history_size), as for compute_pair_forces; call between force passes (MDR:
// after update_radii, or before the first pass). Contacts that only the grown radii bring within
// reach are not in the lists: a host rebuilds its lists afterwards if R grew by more than its skin.
//
// Error of the path: MDR's growth sums integrate (37) explicitly over the increments, so R and
// the growth-dependent state carry an O(1/K) error: with the default K = 100 a single wall or
// pair contact at 0.2 R_o matches a load in 4000 force-kernel steps to about 1% of the growth
// R - R_o. In a packing the time-stepped load is itself increment-sensitive at a few percent of
// the growth (a side feeds (37) only in steps where its delta_o is at its maximum, which the
// neighbours' growth flips): an fcc cluster at 0.2 R_o loaded in 500-4000 steps spreads by 3% of
// the growth, and K = 100 lies within that (tests/mdr/test_mdr_initial_history.cpp). Without
// growth the state does not depend on K (MDR: delta_o,max, c_A at delta_Y; Nan: alpha_max).
#include <epac/compute/contact_forces.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/params/validation.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <string>
#include <type_traits>
#include <utility>

namespace epac {

// Default number of load increments K (see the header comment for the error).
constexpr int kHistoryFromOverlapsIncrements = 100;

// Overlaps of the lists at the present positions, in terms of the initial radii R_o.
struct OverlapCensus {
  int pair_contacts = 0;         // pair contacts with delta_o > 0
  int wall_contacts = 0;         // wall contacts with delta_o > 0
  double max_overlap_ratio = 0;  // largest delta_o / min(R_o,i, R_o,j) (walls: delta_o / R_o,i); 0 if none
  int contacts() const { return pair_contacts + wall_contacts; }
};

// What history_from_overlaps did.
struct HistoryFromOverlapsReport {
  OverlapCensus overlaps;       // before the load (the contacts it loaded)
  int increments = 0;           // K
  double max_radius_ratio = 1;  // largest R / R_o after the load (1 without radius growth)
  long long guard_hits = 0;     // growth-guard hits during the load (models with guard_hits())
};

namespace detail {

// (the model's optional members: has_update_radii, has_guard_hits, has_growth_state in
// models/model_interface.hpp)
template <class M>
long long total_guard_hits(const M& m) {
  long long s = 0;
  if constexpr (has_guard_hits<M>::value)
    for (int h : m.guard_hits()) s += h;
  return s;
}

// R = R_o, V = V_o, sums cleared: growth restarts from the undeformed particles (host call).
template <class M>
void restart_growth(const M& m) {
  if constexpr (has_growth_state<M>::value) {
    if (!M::effects::radius_growth || !m.growth.bound()) return;
    using T = typename M::scalar_type;
    using exec = typename M::device_type::execution_space;
    const auto R0 = m.growth.radius0;
    const auto R = m.growth.radius;
    const auto V = m.growth.volume;
    const auto eps = m.growth.eps_sum, num = m.growth.numerator, den = m.growth.denominator;
    Kokkos::parallel_for(
        "epac::history_from_overlaps::restart_growth", Kokkos::RangePolicy<exec>(0, static_cast<int>(V.extent(0))),
        KOKKOS_LAMBDA(int p) {
          const T r = R0(p);
          R(p) = r;
          V(p) = T(4) / T(3) * constants<T>::pi * r * r * r;  // V_o, as MdrGrowthState::attach
          eps(p) = T(0);
          num(p) = T(0);
          den(p) = T(0);
        });
  }
}

// The overlap of the initial spheres, delta_o = delta - (R_i - R_o,i) - (R_j - R_o,j).
template <class T, class Device>
KOKKOS_INLINE_FUNCTION T initial_overlap(const Particles<T, Device>& p, const ContactGeometry<T>& g) {
  T d = g.delta - (g.R_i - p.radius0(g.i));
  if (g.j >= 0) d -= g.R_j - p.radius0(g.j);
  return d;
}

template <class T, class Device>
KOKKOS_INLINE_FUNCTION T overlap_scale_radius(const Particles<T, Device>& p, const ContactGeometry<T>& g) {
  return g.j >= 0 ? math::min(p.radius0(g.i), p.radius0(g.j)) : p.radius0(g.i);  // > 0 (host validation)
}

// A law without history fields needs no rows: ContactHistory allocates none for it, whatever the
// list's length (touching or barely overlapping starts reach here with such laws).
template <class Device>
void require_history_rows(const char* what, const ContactList<Device>& c, int rows, int fields, int needed) {  // host
  if (c.count > 0 && needed > 0 && rows < c.count)
    throw ParameterError(std::string("history_from_overlaps: ") + what + " history has " + std::to_string(rows) +
                         " rows for " + std::to_string(c.count) + " contacts (valid: rows >= contacts)");
  if (c.count > 0 && fields != needed)
    throw ParameterError(std::string("history_from_overlaps: ") + what + " history has " + std::to_string(fields) +
                         " fields (valid: the model's history_size = " + std::to_string(needed) + ")");
}

}  // namespace detail

// Counts the contacts with positive overlap of the initial spheres and the largest of them over
// the smaller initial radius. Reads only. walls / wall_contacts may be empty.
template <class T, class Device>
OverlapCensus overlap_census(const Particles<T, Device>& p, const ContactList<Device>& pairs,
                             const Walls<T, Device>& walls, const ContactList<Device>& wall_contacts) {
  using exec = typename Device::execution_space;
  OverlapCensus out;
  const auto first = pairs.first, second = pairs.second;
  int count = 0;
  double ratio = 0;
  Kokkos::parallel_reduce(
      "epac::overlap_census::pairs", Kokkos::RangePolicy<exec>(0, pairs.count),
      KOKKOS_LAMBDA(int k, int& n, double& r) {
        const ContactGeometry<T> g = pair_geometry<T, Device, false>(p, first(k), second(k), 1);
        const T d = detail::initial_overlap(p, g);
        if (d > T(0)) {
          ++n;
          const double q = double(d) / double(detail::overlap_scale_radius(p, g));
          if (q > r) r = q;
        }
      },
      count, Kokkos::Max<double>(ratio));
  out.pair_contacts = count;
  out.max_overlap_ratio = ratio;
  if (wall_contacts.count > 0 && walls.n > 0) {
    const auto wfirst = wall_contacts.first, wsecond = wall_contacts.second;
    int wcount = 0;
    double wratio = 0;
    Kokkos::parallel_reduce(
        "epac::overlap_census::walls", Kokkos::RangePolicy<exec>(0, wall_contacts.count),
        KOKKOS_LAMBDA(int k, int& n, double& r) {
          const ContactGeometry<T> g = wall_geometry(p, walls, wfirst(k), wsecond(k), 1);
          const T d = detail::initial_overlap(p, g);
          if (d > T(0)) {
            ++n;
            const double q = double(d) / double(detail::overlap_scale_radius(p, g));
            if (q > r) r = q;
          }
        },
        wcount, Kokkos::Max<double>(wratio));
    out.wall_contacts = wcount;
    out.max_overlap_ratio = ratio > wratio ? ratio : wratio;
  }
  return out;
}

// Initialises pair_history and wall_history from the present overlaps by a quasi-static
// proportional load in `increments` steps (header comment). walls / wall_contacts /
// wall_history may be empty. Throws ParameterError (before any kernel runs, nothing changed) for
// increments outside [1, 1e6] or histories that do not fit the lists and the model.
template <class Model, class T, class Device>
HistoryFromOverlapsReport history_from_overlaps(const Model& model, const Particles<T, Device>& p,
                                                const ContactList<Device>& pairs,
                                                const ContactHistory<T, Device>& pair_history,
                                                const Walls<T, Device>& walls, const ContactList<Device>& wall_contacts,
                                                const ContactHistory<T, Device>& wall_history,
                                                int increments = kHistoryFromOverlapsIncrements) {
  static_assert(check_contact_model<Model, T, Device>(), "epac: Model is not a contact model (see above)");
  using exec = typename Device::execution_space;
  require_range("history_from_overlaps: increments", increments, 1, Bound::closed, 1000000, Bound::closed);
  const int fields = Model::history_size;
  detail::require_history_rows("pair", pairs, pair_history.rows(), pair_history.fields, fields);
  const bool with_walls = wall_contacts.count > 0;
  if (with_walls) {
    if (walls.n <= 0)
      throw ParameterError("history_from_overlaps: " + std::to_string(wall_contacts.count) +
                           " wall contacts but no walls (valid: walls.n >= 1)");
    detail::require_history_rows("wall", wall_contacts, wall_history.rows(), wall_history.fields, fields);
  }

  HistoryFromOverlapsReport rep;
  if constexpr (Model::history_size == 0 && !detail::has_update_radii<Model>::value) {
    // Nothing to load: the contacts' whole state is their present geometry.
    rep.increments = 0;
    rep.overlaps = overlap_census(p, pairs, walls, wall_contacts);
    return rep;
  }
  rep.increments = increments;
  const long long guards_before = detail::total_guard_hits(model);
  detail::restart_growth(model);  // delta_o below is then delta at R = R_o
  rep.overlaps = overlap_census(p, pairs, walls, wall_contacts);

  // delta_o of each contact at the present positions (R = R_o now)
  const int nmat = model.nmat;
  Kokkos::View<T*, Device> pair_d0(Kokkos::view_alloc(Kokkos::WithoutInitializing, "history_from_overlaps.pair_d0"),
                                   pairs.count);
  Kokkos::View<T*, Device> wall_d0(Kokkos::view_alloc(Kokkos::WithoutInitializing, "history_from_overlaps.wall_d0"),
                                   with_walls ? wall_contacts.count : 0);
  const auto first = pairs.first, second = pairs.second;
  const auto wfirst = wall_contacts.first, wsecond = wall_contacts.second;
  Kokkos::parallel_for(
      "epac::history_from_overlaps::pair_d0", Kokkos::RangePolicy<exec>(0, pairs.count), KOKKOS_LAMBDA(int k) {
        pair_d0(k) = detail::initial_overlap(p, pair_geometry<T, Device, false>(p, first(k), second(k), nmat));
      });
  if (with_walls)
    Kokkos::parallel_for(
        "epac::history_from_overlaps::wall_d0", Kokkos::RangePolicy<exec>(0, wall_contacts.count),
        KOKKOS_LAMBDA(int k) {
          wall_d0(k) = detail::initial_overlap(p, wall_geometry(p, walls, wfirst(k), wsecond(k), nmat));
        });

  // every row starts as a fresh contact's (tangential fields stay zero: Model::normal never writes them)
  if (pairs.count > 0 && fields > 0)
    Kokkos::deep_copy(Kokkos::subview(pair_history.data, std::make_pair(0, pairs.count), Kokkos::ALL), T(0));
  if (with_walls && fields > 0)
    Kokkos::deep_copy(Kokkos::subview(wall_history.data, std::make_pair(0, wall_contacts.count), Kokkos::ALL), T(0));

  const auto pdata = pair_history.data;
  const auto wdata = wall_history.data;
  for (int inc = 1; inc <= increments; ++inc) {
    const T s = T(inc) / T(increments);  // s_K = 1 exactly
    Kokkos::parallel_for(
        "epac::history_from_overlaps::pairs", Kokkos::RangePolicy<exec>(0, pairs.count), KOKKOS_LAMBDA(int k) {
          // present radii (grown by the increments so far), so the law sees delta_o,k + growth
          ContactGeometry<T> g = pair_geometry<T, Device, true>(p, first(k), second(k), nmat);
          const T d0 = pair_d0(k);
          const T d0k = d0 > T(0) ? s * d0 : d0;
          g.delta = d0k + (g.R_i - p.radius0(g.i)) + (g.R_j - p.radius0(g.j));
          g.delta_dot = T(0);
          g.dt = T(0);
          (void)model.normal(g, HistoryRow<T, Device>{pdata, k, 0});
        });
    if (with_walls)
      Kokkos::parallel_for(
          "epac::history_from_overlaps::walls", Kokkos::RangePolicy<exec>(0, wall_contacts.count),
          KOKKOS_LAMBDA(int k) {
            ContactGeometry<T> g = wall_geometry(p, walls, wfirst(k), wsecond(k), nmat);
            const T d0 = wall_d0(k);
            const T d0k = d0 > T(0) ? s * d0 : d0;
            g.delta = d0k + (g.R_i - p.radius0(g.i));
            g.delta_dot = T(0);
            g.dt = T(0);
            (void)model.normal(g, HistoryRow<T, Device>{wdata, k, 0});
          });
    if constexpr (detail::has_update_radii<Model>::value) model.update_radii();
  }

  rep.guard_hits = detail::total_guard_hits(model) - guards_before;
  const auto R = p.radius, R0 = p.radius0;
  double ratio = 1.0;
  Kokkos::parallel_reduce(
      "epac::history_from_overlaps::max_radius_ratio", Kokkos::RangePolicy<exec>(0, p.n),
      KOKKOS_LAMBDA(int i, double& r) {
        const double q = double(R(i)) / double(R0(i));
        if (q > r) r = q;
      },
      Kokkos::Max<double>(ratio));
  rep.max_radius_ratio = ratio;
  return rep;
}

// Pairs only (no walls).
template <class Model, class T, class Device>
HistoryFromOverlapsReport history_from_overlaps(const Model& model, const Particles<T, Device>& p,
                                                const ContactList<Device>& pairs,
                                                const ContactHistory<T, Device>& pair_history,
                                                int increments = kHistoryFromOverlapsIncrements) {
  return history_from_overlaps(model, p, pairs, pair_history, Walls<T, Device>{}, ContactList<Device>{},
                               ContactHistory<T, Device>{}, increments);
}

}  // namespace epac
