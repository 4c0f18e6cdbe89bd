#pragma once
// Device cell list: particles binned into a uniform grid of cells at least as wide as the
// largest interaction distance, so every partner of a particle lies in its own or one of the
// 26 neighbouring cells. Built in three passes: count per cell (atomics), exclusive prefix sum,
// fill (atomics), then each cell's slice is sorted by particle index so that the contact lists
// built from it come out in the same order on every backend and thread count.
// Periodic axes (p.box.length > 0): the grid covers the box [lo, lo + L) with n = floor(L / min_cell)
// cells of edge L / n, positions are binned modulo L (they may lie slightly outside the box
// between wraps), and the neighbours of an edge cell are across the face. With fewer than 3
// cells along a periodic axis the -1 and +1 neighbours coincide (n = 2) or are the cell itself
// (n = 1): each distinct cell is visited once, so every partner is found exactly once (the
// host keeps every interaction distance below L / 2, so one image at most is in range).
// The grid is in the positions' type (double whatever T, state/particles.hpp).
#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace epac {
namespace driver {

template <class T, class Device>
struct CellList {
  using P = typename Particles<T, Device>::position_type;
  Vec3<P> lo;                   // lower corner of the grid
  Vec3<P> h{P(1), P(1), P(1)};  // cell edge per axis
  int nx = 1, ny = 1, nz = 1;
  bool px = false, py = false, pz = false;  // periodic axes
  Kokkos::View<int*, Device> start;         // ncells + 1: particles of cell c are sorted(start(c) .. start(c+1)-1)
  Kokkos::View<int*, Device> sorted;        // particle indices, cell-major, ascending within a cell

  int ncells() const { return nx * ny * nz; }

  // Cell coordinate along one axis, clamped into the grid (a NaN coordinate lands in cell 0;
  // the host has already refused non-finite positions).
  // Periodic axis: the cell modulo n_d (the coordinate may be outside the box by a little, or by
  // any amount for a particle that ran away: the fold is exact either way).
  KOKKOS_INLINE_FUNCTION static int axis_cell(P x, P lo_d, P h_d, int n_d, bool periodic) {
    const P f = (x - lo_d) / h_d;  // h_d > 0 (checked on the host)
    if (periodic) {
      const P nf = P(n_d);
      P g = f - nf * math::floor(f / nf);  // in [0, n_d]
      const int c = static_cast<int>(g);
      return c < n_d ? (c >= 0 ? c : 0) : n_d - 1;
    }
    return f > P(0) ? (f < P(n_d) ? static_cast<int>(f) : n_d - 1) : 0;
  }
  KOKKOS_INLINE_FUNCTION int cell_of(const Vec3<P>& x) const {
    const int cx = axis_cell(x.x, lo.x, h.x, nx, px), cy = axis_cell(x.y, lo.y, h.y, ny, py),
              cz = axis_cell(x.z, lo.z, h.z, nz, pz);
    return (cz * ny + cy) * nx + cx;
  }

  // Neighbour range along one axis as offsets [o0, o1] from the cell: clamped at the faces of a
  // non-periodic axis; on a periodic one -1..1, without repeats when n < 3.
  KOKKOS_INLINE_FUNCTION static void axis_range(int c, int n_d, bool periodic, int& o0, int& o1) {
    if (periodic) {
      o0 = n_d >= 3 ? -1 : 0;
      o1 = n_d >= 2 ? 1 : 0;
    } else {
      o0 = c > 0 ? -1 : 0;
      o1 = c + 1 < n_d ? 1 : 0;
    }
  }
  KOKKOS_INLINE_FUNCTION static int axis_wrap(int c, int n_d) { return c < 0 ? c + n_d : (c >= n_d ? c - n_d : c); }

  // Calls g(c) for every cell c around position x (its own and the up to 26 neighbours, across
  // the faces of periodic axes) that holds points closer to x than `reach`, each distinct cell
  // once, z slowest and x fastest. A neighbour is skipped when x's distance to it (to the near
  // face, edge or corner: from x's offset in its own cell) is at least reach; with a cell edge of
  // reach that is about a quarter of the 26 (edge and corner cells beyond a sphere of radius
  // reach). The cells visited keep their order, so the pairs found keep theirs. reach <= 0, NaN
  // or inf: no cell is skipped. Along a periodic axis of fewer than 3 cells the neighbour is on both
  // sides, so it is never skipped.
  template <class G>
  KOKKOS_INLINE_FUNCTION void for_each_near_cell(const Vec3<P>& x, P reach, G&& g) const {
    const int cx = axis_cell(x.x, lo.x, h.x, nx, px), cy = axis_cell(x.y, lo.y, h.y, ny, py),
              cz = axis_cell(x.z, lo.z, h.z, nz, pz);
    int x0, x1, y0, y1, z0, z1;
    axis_range(cx, nx, px, x0, x1);
    axis_range(cy, ny, py, y0, y1);
    axis_range(cz, nz, pz, z0, z1);
    // Squared distances from x to the neighbour slabs below and above along each axis. The
    // margin (relative 1e-6 on reach^2) keeps round-off in the offsets from skipping a cell
    // that holds a partner; a skip is only ever of a cell that could hold none.
    const bool skip_none = !(reach > P(0)) || !(reach - reach == P(0));  // <= 0, NaN or inf
    const P reach2 = skip_none ? P(0) : reach * reach * P(1.000001);
    P bx[2], by[2], bz[2];
    axis_gaps(x.x, lo.x, h.x, nx, px, cx, bx);
    axis_gaps(x.y, lo.y, h.y, ny, py, cy, by);
    axis_gaps(x.z, lo.z, h.z, nz, pz, cz, bz);
    for (int oz = z0; oz <= z1; ++oz) {
      const int z = axis_wrap(cz + oz, nz);
      const P dz2 = oz == 0 ? P(0) : bz[oz > 0];
      if (!skip_none && !(dz2 < reach2)) continue;
      for (int oy = y0; oy <= y1; ++oy) {
        const int y = axis_wrap(cy + oy, ny);
        const P dyz2 = dz2 + (oy == 0 ? P(0) : by[oy > 0]);
        if (!skip_none && !(dyz2 < reach2)) continue;
        for (int ox = x0; ox <= x1; ++ox) {
          if (!skip_none && !(dyz2 + (ox == 0 ? P(0) : bx[ox > 0]) < reach2)) continue;
          g((z * ny + y) * nx + axis_wrap(cx + ox, nx));
        }
      }
    }
  }

  // Squared distances from coordinate x (in cell c of the axis) to the slab of cell c - 1
  // (gap[0]) and of cell c + 1 (gap[1]). The offset in the cell is taken after the periodic
  // fold, as axis_cell bins; a coordinate outside a non-periodic grid (clamped into an edge
  // cell) gets its true distance to the inner neighbour and 0 on the outer side. Periodic axes
  // with fewer than 3 cells: 0 (the neighbour lies on both sides).
  KOKKOS_INLINE_FUNCTION static void axis_gaps(P x, P lo_d, P h_d, int n_d, bool periodic, int c, P gap[2]) {
    P f = (x - lo_d) / h_d;  // h_d > 0 (checked on the host)
    if (periodic) {
      const P nf = P(n_d);
      f = f - nf * math::floor(f / nf);
    }
    const P below = (f - P(c)) * h_d, above = (P(c + 1) - f) * h_d;
    const bool both_sides = periodic && n_d < 3;
    gap[0] = both_sides || below < P(0) ? P(0) : below * below;
    gap[1] = both_sides || above < P(0) ? P(0) : above * above;
  }

  // Calls f(j) for every particle j > i in the cells around position x that reach `reach`
  // (for_each_near_cell), cell by cell in its order and ascending within a cell. A cell's slice
  // is in ascending index, so a cell whose last index is <= i is skipped whole and the others
  // from their first index > i. After a spatial sort indices follow the cells, so about half the
  // cells around i hold only lower indices (the pair search visits each pair from its lower end).
  template <class F>
  KOKKOS_INLINE_FUNCTION void for_each_near_above(const Vec3<P>& x, int i, P reach, F&& f) const {
    for_each_near_cell(x, reach, [&](int c) {
      const int end = start(c + 1);
      if (end == start(c) || sorted(end - 1) <= i) return;
      int s = start(c);
      while (sorted(s) <= i) ++s;  // stops: the last entry is > i
      for (; s < end; ++s) f(sorted(s));
    });
  }
};

// Bins the particles into cells of edge >= min_cell. The number of cells is capped at about
// 2 N (+64) by widening the cells, so a particle far from the others cannot blow up memory.
// Throws std::runtime_error if a position is not finite (the simulation has diverged).
template <class T, class Device>
CellList<T, Device> build_cell_list(const Particles<T, Device>& p, T min_cell) {
  using exec = typename Device::execution_space;
  using P = typename CellList<T, Device>::P;
  const int n = p.n;
  CellList<T, Device> cl;
  P lo[3] = {P(0), P(0), P(0)}, hi[3] = {P(0), P(0), P(0)};
  if (n > 0) {
    auto x = p.x;
    // Min/max comparisons skip NaN, so count non-finite coordinates first.
    int bad = 0;
    Kokkos::parallel_reduce(
        "epac::driver::finite_positions", Kokkos::RangePolicy<exec>(0, n),
        KOKKOS_LAMBDA(int i, int& b) {
          for (int d = 0; d < 3; ++d)
            if (!(x(i, d) - x(i, d) == P(0))) ++b;  // NaN or inf
        },
        bad);
    if (bad > 0)
      throw std::runtime_error(std::to_string(bad) +
                               " particle coordinates are not finite: the simulation diverged "  // host
                               "(time step too large?)");                                        // host
    const P box_length[3] = {p.box.length.x, p.box.length.y, p.box.length.z};
    for (int d = 0; d < 3; ++d) {
      if (box_length[d] > P(0)) continue;  // periodic: the grid is the box (below)
      Kokkos::MinMaxScalar<P> mm;
      Kokkos::parallel_reduce(
          "epac::driver::bounding_box", Kokkos::RangePolicy<exec>(0, n),
          KOKKOS_LAMBDA(int i, Kokkos::MinMaxScalar<P>& v) {
            const P c = x(i, d);
            if (c < v.min_val) v.min_val = c;
            if (c > v.max_val) v.max_val = c;
          },
          Kokkos::MinMax<P>(mm));
      lo[d] = mm.min_val;
      hi[d] = mm.max_val;
    }
  }
  // Periodic axes: the grid is the box, whatever the particles' extent.
  const P box_len[3] = {p.box.length.x, p.box.length.y, p.box.length.z};
  const P box_lo[3] = {p.box.lo.x, p.box.lo.y, p.box.lo.z};
  bool per[3];
  for (int d = 0; d < 3; ++d) {
    per[d] = box_len[d] > P(0);
    if (per[d]) {
      lo[d] = box_lo[d];
      hi[d] = box_lo[d] + box_len[d];
    }
  }
  double h = static_cast<double>(min_cell) > 0 ? static_cast<double>(min_cell) : 1.0;
  auto cells_along = [&](int d) {
    const double ext = static_cast<double>(hi[d]) - static_cast<double>(lo[d]);
    if (per[d]) return std::max(1.0, std::floor(ext / h));  // cells of edge L / n >= h
    return static_cast<double>(std::floor(ext / h)) + 1.0;
  };
  const double max_cells = 2.0 * n + 64.0;
  while (cells_along(0) * cells_along(1) * cells_along(2) > max_cells) h *= 1.25;
  cl.lo = Vec3<P>(lo[0], lo[1], lo[2]);
  cl.nx = static_cast<int>(cells_along(0));
  cl.ny = static_cast<int>(cells_along(1));
  cl.nz = static_cast<int>(cells_along(2));
  const int nd[3] = {cl.nx, cl.ny, cl.nz};
  P hd[3];
  for (int d = 0; d < 3; ++d)
    hd[d] = per[d] ? static_cast<P>(static_cast<double>(box_len[d]) / nd[d]) : static_cast<P>(h);
  cl.h = Vec3<P>(hd[0], hd[1], hd[2]);
  cl.px = per[0];
  cl.py = per[1];
  cl.pz = per[2];
  const int nc = cl.ncells();

  Kokkos::View<int*, Device> count("epac::driver::cell_count", nc);
  Kokkos::View<int*, Device> particle_cell("epac::driver::particle_cell", n);
  cl.start = Kokkos::View<int*, Device>("epac::driver::cell_start", nc + 1);
  cl.sorted = Kokkos::View<int*, Device>("epac::driver::cell_sorted", n);
  const CellList<T, Device> grid = cl;  // the geometry, captured by value
  auto x = p.x;
  Kokkos::parallel_for(
      "epac::driver::cell_count", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        const int c = grid.cell_of(load3(x, i));
        particle_cell(i) = c;
        Kokkos::atomic_add(&count(c), 1);
      });
  auto start = cl.start;
  Kokkos::parallel_scan(
      "epac::driver::cell_scan", Kokkos::RangePolicy<exec>(0, nc + 1), KOKKOS_LAMBDA(int c, int& upd, bool final) {
        const int k = c < nc ? count(c) : 0;
        if (final) start(c) = upd;
        upd += k;
      });
  Kokkos::deep_copy(count, 0);  // reused as each cell's fill cursor
  auto sorted = cl.sorted;
  Kokkos::parallel_for(
      "epac::driver::cell_fill", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
        const int c = particle_cell(i);
        sorted(start(c) + Kokkos::atomic_fetch_add(&count(c), 1)) = i;
      });
  // Insertion sort of each cell's few entries: a deterministic order for any thread count.
  Kokkos::parallel_for(
      "epac::driver::cell_sort", Kokkos::RangePolicy<exec>(0, nc), KOKKOS_LAMBDA(int c) {
        for (int a = start(c) + 1; a < start(c + 1); ++a) {
          const int v = sorted(a);
          int b = a - 1;
          while (b >= start(c) && sorted(b) > v) {
            sorted(b + 1) = sorted(b);
            --b;
          }
          sorted(b + 1) = v;
        }
      });
  return cl;
}

}  // namespace driver
}  // namespace epac
