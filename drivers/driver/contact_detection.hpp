#pragma once
// Contact detection on the device with a skin (Verlet-list style), and the history remap that
// follows each rebuild (docs/design.md section 4, steps 1-2).
//  - pairs (i < j) with |x_i - x_j| < R_i + R_j + skin, from the cell list;
//  - particle-wall contacts with signed distance to the plane < R_i + skin.
// Lists come out ordered by i (then by cell, then by j; walls by wall index), the same on every
// backend. Entries with negative overlap are kept: the model reports them inactive.
//
// Rebuild rule: a contact missing from the list needs d_i + g_i + d_j + g_j > skin (pairs) or
// d_i + g_i + d_w > skin (walls), with d the displacement and g the radius growth since the last
// build, d_w a wall's displacement along its normal. So the lists stay complete while
// max_i (d_i + g_i) <= skin/2 and max_w d_w <= skin/2; ContactDetector::update rebuilds when
// either exceeds it. Growing radii (MDR) thus eat into the same margin.
// In a box deformed affinely since the build (the driver's [box.deform], remap x) d may be
// measured from the reference positions mapped by that deformation, at a smaller allowance:
// ContactDetector::shift_allowance. Only the motion relative to the deformation then counts,
// for wall contacts too where, as in the driver, the deformed axes are periodic and walls bound
// only the others (the deformation then changes no particle's distance to a wall).
// Distances and the reference positions are double whatever T (positions are, state/particles.hpp).
#include "driver/cell_list.hpp"

#include <epac/compute/history_remap.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <functional>

namespace epac {
namespace driver {

namespace detail {
// Returns a list with room for `count` entries: `old` if large enough, else a new one with 25%
// headroom (so a slowly growing contact count does not reallocate at every rebuild).
template <class Device>
ContactList<Device> list_with_room(const ContactList<Device>& old, int count, const char* label) {
  ContactList<Device> l = old;
  if (old.capacity() < count) l = ContactList<Device>(count + count / 4 + 16, label);
  l.count = count;
  return l;
}
}  // namespace detail

// The largest radius (0 for no particles).
template <class T, class Device>
T max_radius(const Particles<T, Device>& p) {
  T rmax = T(0);
  auto r = p.radius;
  Kokkos::parallel_reduce(
      "epac::driver::max_radius", Kokkos::RangePolicy<typename Device::execution_space>(0, p.n),
      KOKKOS_LAMBDA(int i, T& m) {
        if (r(i) > m) m = r(i);
      },
      Kokkos::Max<T>(rmax));
  return rmax;
}

// Pairs within R_i + R_j + skin (minimum-image distance on p.box's periodic axes), each once,
// stored with gid(first) < gid(second). `reuse` donates its storage if large enough.
// rows (optional): set to the list's row offsets over i = min(first, second) (n + 1 entries:
// the pairs found from particle i are entries rows(i) .. rows(i+1)-1), for remap_by_rows.
// The count pass keeps up to kPairScratch partners per particle, so the fill pass copies them
// instead of searching the cells again (the same list in the same order; a particle with more
// partners searches again). Its rows have one more slot, where candidates that are not partners
// land once the row is full.
constexpr int kPairScratch = 16;
template <class T, class Device>
ContactList<Device> find_pairs(const Particles<T, Device>& p, const CellList<T, Device>& cells, T skin,
                               const ContactList<Device>& reuse = {}, Kokkos::View<int*, Device>* rows = nullptr) {
  using exec = typename Device::execution_space;
  using P = typename Particles<T, Device>::position_type;
  const int n = p.n;
  auto x = p.x;
  auto r = p.radius;
  const PeriodicBox<P> box = p.box;  // distances by minimum image on its periodic axes
  const bool periodic = box.periodic();
  const T rmax = max_radius(p);  // every partner of i is within ri + rmax + skin: cells farther away are not searched
  Kokkos::View<int*, Device> offset("epac::driver::pair_offset", n + 1);
  constexpr int K = kPairScratch;
  Kokkos::View<int*, Device> scratch(Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::pair_scratch"),
                                     static_cast<std::size_t>(n) * (K + 1));
  Kokkos::parallel_for(
      "epac::driver::pair_count", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        const Vec3<P> xi = load3(x, i);
        const T ri = r(i);
        int c = 0;
        const std::size_t row = static_cast<std::size_t>(i) * (K + 1);
        // Branch-free: every candidate is stored at the next free slot and kept by counting it
        // (a partner in about 1 of 4 candidates, at random, is a branch the CPU mispredicts).
        // A full row's candidates land in its spare slot K, which is never read: the fill pass
        // copies slots below c <= K, and searches again for c > K.
        cells.for_each_near_above(xi, i, P(ri) + P(rmax) + P(skin), [&](int j) {
          Vec3<P> d = xi - load3(x, j);
          if (periodic) d = box.minimum_image(d);
          const P cut = P(ri) + P(r(j)) + P(skin);
          scratch(row + (c < K ? c : K)) = j;
          c += dot(d, d) < cut * cut ? 1 : 0;
        });
        offset(i) = c;
      });
  int total = 0;
  Kokkos::parallel_scan(
      Kokkos::RangePolicy<exec>(0, n + 1),
      KOKKOS_LAMBDA(int i, int& upd, bool final) {
        const int k = i < n ? offset(i) : 0;
        if (final) offset(i) = upd;
        upd += k;
      },
      total);
  ContactList<Device> list = detail::list_with_room(reuse, total, "pairs");
  auto first = list.first;
  auto second = list.second;
  auto gid = p.gid;
  Kokkos::parallel_for(
      "epac::driver::pair_fill", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        int k = offset(i);
        const int c = offset(i + 1) - k;
        if (c <= K) {  // the count pass's partners, in its order
          for (int m = 0; m < c; ++m) {
            const int j = scratch(static_cast<std::size_t>(i) * (K + 1) + m);
            const bool swap = gid(j) < gid(i);  // oriented by global id (below)
            first(k + m) = swap ? j : i;
            second(k + m) = swap ? i : j;
          }
          return;
        }
        const Vec3<P> xi = load3(x, i);
        const T ri = r(i);
        cells.for_each_near_above(xi, i, P(ri) + P(rmax) + P(skin), [&](int j) {
          Vec3<P> d = xi - load3(x, j);
          if (periodic) d = box.minimum_image(d);
          const P cut = P(ri) + P(r(j)) + P(skin);
          if (dot(d, d) < cut * cut) {
            // Oriented by global id: pair history that has a direction (the tangential spring's
            // displacement of first relative to second) keeps its meaning when a spatial sort
            // changes which of the two has the smaller index. Without a sort gid order is index order.
            const bool swap = gid(j) < gid(i);
            first(k) = swap ? j : i;
            second(k) = swap ? i : j;
            ++k;
          }
        });
      });
  list.gid_ordered = true;  // the fill pass orients every pair by global id
  if (rows) *rows = offset;
  return list;
}

// Particle-wall contacts: signed distance from the plane < R_i + skin (particles behind a wall
// count too: they overlap it by more than their radius).
// rows (optional): the row offsets over the particle index (as find_pairs).
template <class T, class Device>
ContactList<Device> find_wall_contacts(const Particles<T, Device>& p, const Walls<T, Device>& w, T skin,
                                       const ContactList<Device>& reuse = {},
                                       Kokkos::View<int*, Device>* rows = nullptr) {
  using exec = typename Device::execution_space;
  using P = typename Particles<T, Device>::position_type;
  const int n = p.n, nw = w.n;
  auto x = p.x;
  auto r = p.radius;
  auto wp = w.point;
  auto wn = w.normal;
  Kokkos::View<int*, Device> offset("epac::driver::wall_offset", n + 1);
  if (nw > 0) {
    Kokkos::parallel_for(
        "epac::driver::wall_count", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
          const Vec3<P> xi = load3(x, i);
          int c = 0;
          for (int k = 0; k < nw; ++k)
            if (dot(xi - load3(wp, k), load3_as<P>(wn, k)) < P(r(i)) + P(skin)) ++c;
          offset(i) = c;
        });
  }
  int total = 0;
  Kokkos::parallel_scan(
      Kokkos::RangePolicy<exec>(0, n + 1),
      KOKKOS_LAMBDA(int i, int& upd, bool final) {
        const int k = i < n ? offset(i) : 0;
        if (final) offset(i) = upd;
        upd += k;
      },
      total);
  ContactList<Device> list = detail::list_with_room(reuse, total, "wall_contacts");
  auto first = list.first;
  auto second = list.second;
  if (nw > 0 && total > 0) {
    Kokkos::parallel_for(
        "epac::driver::wall_fill", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
          const Vec3<P> xi = load3(x, i);
          int c = offset(i);
          for (int k = 0; k < nw; ++k)
            if (dot(xi - load3(wp, k), load3_as<P>(wn, k)) < P(r(i)) + P(skin)) {
              first(c) = i;
              second(c) = k;
              ++c;
            }
        });
  }
  if (rows) *rows = offset;
  return list;
}

// remap_history (compute/history_remap.hpp) for a rebuilt list: a persisting contact was found
// from one particle in the old list (pairs: the lower index, walls: the particle), so its old row
// lies among the few of the old list's rows of that particle (old_rows, the old list's row
// offsets). A scan of those keys replaces the sort of all old keys and a binary search per
// contact, which cost about as much as the detection itself. The same rows are carried over
// (keys are unique), so the result equals remap_history's.
// old_index: empty if the particle indices are those of the old list; after a spatial sort, the
// old index of each particle (the sort's permutation: new index k was old_index(k)).
// The result holds `new_keys` itself (not a copy: the caller's keys are fresh, pair_contact_keys)
// and its rows are written once, each either carried over or zeroed (no zero fill before).
template <class T, class Device>
ContactHistory<T, Device> remap_by_rows(const ContactHistory<T, Device>& old,
                                        const Kokkos::View<int*, Device>& old_rows, const ContactList<Device>& list,
                                        bool pairs, const Kokkos::View<std::uint64_t*, Device>& new_keys, int fields,
                                        const Kokkos::View<int*, Device>& old_index = {}) {
  using exec = typename Device::execution_space;
  if (fields == 0 || old.rows() == 0 || list.count == 0) return ContactHistory<T, Device>(new_keys, fields, "history");
  ContactHistory<T, Device> fresh;
  fresh.fields = fields;
  fresh.keys = new_keys;
  fresh.data = typename ContactHistory<T, Device>::data_view(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, "history.data"), new_keys.extent(0), fields);
  auto okeys = old.keys;
  auto odata = old.data;
  auto ndata = fresh.data;
  auto first = list.first;
  auto second = list.second;
  const bool reindexed = old_index.extent(0) > 0;
  Kokkos::parallel_for(
      "epac::driver::remap_by_rows", Kokkos::RangePolicy<exec>(0, list.count), KOKKOS_LAMBDA(int k) {
        int a = first(k), b = second(k);
        if (reindexed) {
          a = old_index(a);
          if (pairs) b = old_index(b);  // walls: b is the wall
        }
        const int i = pairs && b < a ? b : a;
        const std::uint64_t key = new_keys(k);
        for (int s = old_rows(i); s < old_rows(i + 1); ++s)
          if (okeys(s) == key) {
            for (int f = 0; f < fields; ++f) ndata(k, f) = odata(s, f);
            return;
          }
        for (int f = 0; f < fields; ++f) ndata(k, f) = T(0);  // a new contact
      });
  return fresh;
}

// Owns the contact lists and their histories; rebuilds and remaps when the skin is used up.
template <class T, class Device>
class ContactDetector {
 public:
  using position_view = typename Particles<T, Device>::position_view;

  ContactList<Device> pairs, walls;
  ContactHistory<T, Device> pair_history, wall_history;
  std::int64_t builds = 0;

  ContactDetector() = default;
  ContactDetector(T skin, int pair_fields, int wall_fields)
      : skin_(skin), pair_fields_(pair_fields), wall_fields_(wall_fields) {}

  T skin() const { return skin_; }

  // Detects both lists from scratch and carries the history of persisting contacts over.
  void build(const Particles<T, Device>& p, const Walls<T, Device>& w) {
    detect(p, w);
    remap(p);
  }

  // The two halves of build (timed apart by the driver's --phase-times): the lists and the
  // rebuild rule's reference state, then the history remap (needs the new lists).
  // on_sort (optional; the driver's [run] spatial_sort): called with the cell-order permutation
  // (new index k = old index perm(k)); it must reorder every per-particle array in place. The
  // lists are then built on the reordered particles, whose cell list is the identity.
  // when: sort now, or only if the cell grid's dimensions differ from those at the last sort
  // (the order then no longer follows the cells). Returns whether it sorted.
  using sort_callback = std::function<void(const Kokkos::View<int*, Device>&)>;
  enum class SortWhen { now, if_grid_changed };
  bool detect(const Particles<T, Device>& p, const Walls<T, Device>& w, const sort_callback* on_sort = nullptr,
              SortWhen when = SortWhen::now) {
    r_max_build_ = max_radius(p);
    CellList<T, Device> cells = build_cell_list(p, T(2) * r_max_build_ + skin_);
    const bool grid_changed = cells.nx != sort_grid_[0] || cells.ny != sort_grid_[1] || cells.nz != sort_grid_[2];
    const bool sort = on_sort && *on_sort && (when == SortWhen::now || grid_changed);
    if (sort) {
      sort_grid_[0] = cells.nx;
      sort_grid_[1] = cells.ny;
      sort_grid_[2] = cells.nz;
      (*on_sort)(cells.sorted);
      // The histories' rows are by the indices before the sort: remap() looks them up through
      // the permutation (composed with an earlier one not yet remapped).
      if (old_index_.extent(0) > 0) {
        const Kokkos::View<int*, Device> earlier = old_index_, perm = cells.sorted;
        Kokkos::View<int*, Device> both(Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::old_index"),
                                        p.n);
        Kokkos::parallel_for(
            "epac::driver::compose_sorts", Kokkos::RangePolicy<exec>(0, p.n),
            KOKKOS_LAMBDA(int k) { both(k) = earlier(perm(k)); });
        old_index_ = both;
      } else {
        old_index_ = cells.sorted;
      }
      Kokkos::View<int*, Device> identity(Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::cell_sorted"),
                                          p.n);
      Kokkos::parallel_for(
          "epac::driver::cell_identity", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int k) { identity(k) = k; });
      cells.sorted = identity;
    }
    pairs = find_pairs(p, cells, skin_, pairs, &pair_rows_);
    walls = find_wall_contacts(p, w, skin_, walls, &wall_rows_);
    // Reference state for the rebuild rule.
    if (static_cast<int>(x_build_.extent(0)) != p.n) {
      x_build_ = position_view("epac::driver::x_build", p.n);
      r_build_ = Kokkos::View<T*, Device>("epac::driver::r_build", p.n);
    }
    if (static_cast<int>(wall_build_.extent(0)) != w.n) wall_build_ = position_view("epac::driver::wall_build", w.n);
    Kokkos::deep_copy(x_build_, p.x);
    Kokkos::deep_copy(r_build_, p.radius);
    Kokkos::deep_copy(wall_build_, w.point);
    ++builds;
    return sort;
  }
  // By the old lists' rows (remap_by_rows, through the permutation of a spatial sort since), or
  // where those do not fit (the first build, another particle count, another history) by sorted
  // keys (remap_history): the same result.
  void remap(const Particles<T, Device>& p) {
    const bool rows_valid = static_cast<int>(hist_pair_rows_.extent(0)) == p.n + 1 &&
                            static_cast<int>(hist_wall_rows_.extent(0)) == p.n + 1 &&
                            (old_index_.extent(0) == 0 || static_cast<int>(old_index_.extent(0)) == p.n);
    auto by_rows = [&](const ContactHistory<T, Device>& h, int fields, int old_count) {
      return rows_valid && h.fields == fields && h.has_keys() && h.rows() == old_count;
    };
    if (by_rows(pair_history, pair_fields_, hist_pairs_))
      pair_history = remap_by_rows(pair_history, hist_pair_rows_, pairs, true, pair_contact_keys(p, pairs),
                                   pair_fields_, old_index_);
    else
      pair_history = remap_history(pair_history, pair_contact_keys(p, pairs), pair_fields_);
    if (by_rows(wall_history, wall_fields_, hist_walls_))
      wall_history = remap_by_rows(wall_history, hist_wall_rows_, walls, false, wall_contact_keys(p, walls),
                                   wall_fields_, old_index_);
    else
      wall_history = remap_history(wall_history, wall_contact_keys(p, walls), wall_fields_);
    hist_pair_rows_ = pair_rows_;
    hist_wall_rows_ = wall_rows_;
    hist_pairs_ = pairs.count;
    hist_walls_ = walls.count;
    old_index_ = {};
  }

  // max_i (|x_i - x_i,build| + max(0, R_i - R_i,build)).
  T particle_shift(const Particles<T, Device>& p) const {
    T m = T(0);
    auto x = p.x;
    auto r = p.radius;
    auto xb = x_build_;
    auto rb = r_build_;
    Kokkos::parallel_reduce(
        "epac::driver::particle_shift", Kokkos::RangePolicy<exec>(0, p.n),
        KOKKOS_LAMBDA(int i, T& v) {
          const T grow = r(i) - rb(i);
          const T s = T(norm(load3(x, i) - load3(xb, i))) + (grow > T(0) ? grow : T(0));
          // NaN (a diverged particle) forces a rebuild, whose bounding box check reports it.
          if (!(s == s))
            v = T(1e30);
          else if (s > v)
            v = s;
        },
        Kokkos::Max<T>(m));
    return m;
  }

  // max_w |(point_w - point_w,build) . normal_w|: only motion along the normal changes distances.
  T wall_shift(const Walls<T, Device>& w) const {
    if (w.n == 0) return T(0);
    T m = T(0);
    auto pt = w.point;
    auto nr = w.normal;
    auto pb = wall_build_;
    Kokkos::parallel_reduce(
        "epac::driver::wall_shift", Kokkos::RangePolicy<exec>(0, w.n),
        KOKKOS_LAMBDA(int k, T& v) {
          const T s = T(math::fabs(dot(load3(pt, k) - load3(pb, k), load3_as<double>(nr, k))));
          if (s > v) v = s;
        },
        Kokkos::Max<T>(m));
    return m;
  }

  bool needs_rebuild(const Particles<T, Device>& p, const Walls<T, Device>& w) const {
    if (builds == 0) return true;
    const T half = T(0.5) * skin_;
    return particle_shift(p) > half || wall_shift(w) > half;
  }
  // The same rule from shifts measured elsewhere (the driver's fused integration kernel), the
  // particles' from their reference positions mapped by an affine deformation of least ratio
  // `lambda` since the build (1: none; shift_allowance).
  bool needs_rebuild(T particle_shift_value, T wall_shift_value, double lambda = 1.0) const {
    return builds == 0 || particle_shift_value > shift_allowance(lambda) || wall_shift_value > T(0.5) * skin_;
  }
  // The particles' allowed shift, measured beyond an affine deformation since the build whose
  // ratios along the axes are >= lambda. A pair missing from the list was at least
  // R_i + R_j + skin apart in every periodic image; the deformation scales each separation by at
  // least min(1, lambda) = l, so the pair is still at least l (R_i + R_j + skin) - s_i - s_j
  // apart, with s the shift beyond it (growth included, as above). It cannot touch while
  // s_i + s_j <= l skin - (1 - l) (R_i + R_j): max s <= (l skin - (1 - l) 2 R_max) / 2 with R_max
  // at the build. skin/2 without a deformation (l = 1); below 0 (every step rebuilds) once the
  // compression since the build exceeds skin / (skin + 2 R_max). The allowance is computed in
  // double: its round-off is that of the shift's, as without a deformation.
  T shift_allowance(double lambda) const {
    const double l = lambda < 1.0 ? lambda : 1.0;
    return T(0.5 * (l * double(skin_) - (1.0 - l) * 2.0 * double(r_max_build_)));
  }
  // Positions and radii at the last build (the reference of particle_shift).
  const position_view& reference_positions() const { return x_build_; }
  const Kokkos::View<T*, Device>& reference_radii() const { return r_build_; }

  // Rebuilds if needed; returns whether it did.
  bool update(const Particles<T, Device>& p, const Walls<T, Device>& w) {
    if (!needs_rebuild(p, w)) return false;
    build(p, w);
    return true;
  }

 private:
  using exec = typename Device::execution_space;
  T skin_ = T(0);
  T r_max_build_ = T(0);  // the largest radius at the last build (shift_allowance)
  int pair_fields_ = 0, wall_fields_ = 0;
  position_view x_build_, wall_build_;
  Kokkos::View<T*, Device> r_build_;
  // Row offsets of the lists (find_pairs / find_wall_contacts) and of the lists the histories
  // belong to, with those lists' lengths; old_index_: empty, or after a sort since, each
  // particle's index in those lists.
  Kokkos::View<int*, Device> pair_rows_, wall_rows_, hist_pair_rows_, hist_wall_rows_;
  int hist_pairs_ = 0, hist_walls_ = 0;
  Kokkos::View<int*, Device> old_index_;
  int sort_grid_[3] = {0, 0, 0};  // the cell grid at the last sort
};

}  // namespace driver
}  // namespace epac
