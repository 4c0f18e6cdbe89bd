#pragma once
// Device cell list: particles binned into a uniform grid of cells at least as wide as the
// largest interaction distance, so every partner of a particle lies in its own or one of the
// 26 neighbouring cells. Built in three passes: count per cell (atomics), exclusive prefix sum,
// fill (atomics), then each cell's slice is sorted by particle index so that the contact lists
// built from it come out in the same order on every backend and thread count.
#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace epac {
namespace driver {

template <class T, class Device>
struct CellList {
  Vec3<T> lo;         // lower corner of the grid
  T h = T(1);         // cell edge
  int nx = 1, ny = 1, nz = 1;
  Kokkos::View<int*, Device> start;   // ncells + 1: particles of cell c are sorted(start(c) .. start(c+1)-1)
  Kokkos::View<int*, Device> sorted;  // particle indices, cell-major, ascending within a cell

  int ncells() const { return nx * ny * nz; }

  // Cell coordinate along one axis, clamped into the grid (a NaN coordinate lands in cell 0;
  // the host has already refused non-finite positions).
  KOKKOS_INLINE_FUNCTION static int axis_cell(T x, T lo_d, T h_d, int n_d) {
    const T f = (x - lo_d) / h_d;  // h_d > 0 (checked on the host)
    return f > T(0) ? (f < T(n_d) ? static_cast<int>(f) : n_d - 1) : 0;
  }
  KOKKOS_INLINE_FUNCTION int cell_of(const Vec3<T>& x) const {
    const int cx = axis_cell(x.x, lo.x, h, nx), cy = axis_cell(x.y, lo.y, h, ny), cz = axis_cell(x.z, lo.z, h, nz);
    return (cz * ny + cy) * nx + cx;
  }

  // Calls f(j) for every particle j in the cells around position x (its own and the up to 26
  // neighbours; the grid is not periodic).
  template <class F>
  KOKKOS_INLINE_FUNCTION void for_each_near(const Vec3<T>& x, F&& f) const {
    const int cx = axis_cell(x.x, lo.x, h, nx), cy = axis_cell(x.y, lo.y, h, ny), cz = axis_cell(x.z, lo.z, h, nz);
    const int x0 = cx > 0 ? cx - 1 : 0, x1 = cx + 1 < nx ? cx + 1 : nx - 1;
    const int y0 = cy > 0 ? cy - 1 : 0, y1 = cy + 1 < ny ? cy + 1 : ny - 1;
    const int z0 = cz > 0 ? cz - 1 : 0, z1 = cz + 1 < nz ? cz + 1 : nz - 1;
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int xx = x0; xx <= x1; ++xx) {
          const int c = (z * ny + y) * nx + xx;
          for (int s = start(c); s < start(c + 1); ++s) f(sorted(s));
        }
  }
};

// Bins the particles into cells of edge >= min_cell. The number of cells is capped at about
// 2 N (+64) by widening the cells, so a particle far from the others cannot blow up memory.
// Throws std::runtime_error if a position is not finite (the simulation has diverged).
template <class T, class Device>
CellList<T, Device> build_cell_list(const Particles<T, Device>& p, T min_cell) {
  using exec = typename Device::execution_space;
  const int n = p.n;
  CellList<T, Device> cl;
  T lo[3] = {T(0), T(0), T(0)}, hi[3] = {T(0), T(0), T(0)};
  if (n > 0) {
    auto x = p.x;
    // Min/max comparisons skip NaN, so count non-finite coordinates first.
    int bad = 0;
    Kokkos::parallel_reduce(
        "epac::driver::finite_positions", Kokkos::RangePolicy<exec>(0, n),
        KOKKOS_LAMBDA(int i, int& b) {
          for (int d = 0; d < 3; ++d)
            if (!(x(i, d) - x(i, d) == T(0))) ++b;  // NaN or inf
        },
        bad);
    if (bad > 0)
      throw std::runtime_error(std::to_string(bad) + " particle coordinates are not finite: the simulation diverged "  // host
                               "(time step too large?)");  // host
    for (int d = 0; d < 3; ++d) {
      Kokkos::MinMaxScalar<T> mm;
      Kokkos::parallel_reduce(
          "epac::driver::bounding_box", Kokkos::RangePolicy<exec>(0, n),
          KOKKOS_LAMBDA(int i, Kokkos::MinMaxScalar<T>& v) {
            const T c = x(i, d);
            if (c < v.min_val) v.min_val = c;
            if (c > v.max_val) v.max_val = c;
          },
          Kokkos::MinMax<T>(mm));
      lo[d] = mm.min_val;
      hi[d] = mm.max_val;
    }
  }
  double h = static_cast<double>(min_cell) > 0 ? static_cast<double>(min_cell) : 1.0;
  auto cells_along = [&](int d) {
    return static_cast<double>(std::floor((static_cast<double>(hi[d]) - static_cast<double>(lo[d])) / h)) + 1.0;
  };
  const double max_cells = 2.0 * n + 64.0;
  while (cells_along(0) * cells_along(1) * cells_along(2) > max_cells) h *= 1.25;
  cl.lo = Vec3<T>(lo[0], lo[1], lo[2]);
  cl.h = static_cast<T>(h);
  cl.nx = static_cast<int>(cells_along(0));
  cl.ny = static_cast<int>(cells_along(1));
  cl.nz = static_cast<int>(cells_along(2));
  const int nc = cl.ncells();

  Kokkos::View<int*, Device> count("epac::driver::cell_count", nc);
  Kokkos::View<int*, Device> particle_cell("epac::driver::particle_cell", n);
  cl.start = Kokkos::View<int*, Device>("epac::driver::cell_start", nc + 1);
  cl.sorted = Kokkos::View<int*, Device>("epac::driver::cell_sorted", n);
  const CellList<T, Device> grid = cl;  // the geometry, captured by value
  auto x = p.x;
  Kokkos::parallel_for("epac::driver::cell_count", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
    const int c = grid.cell_of(load3(x, i));
    particle_cell(i) = c;
    Kokkos::atomic_add(&count(c), 1);
  });
  auto start = cl.start;
  Kokkos::parallel_scan("epac::driver::cell_scan", Kokkos::RangePolicy<exec>(0, nc + 1),
                        KOKKOS_LAMBDA(int c, int& upd, bool final) {
                          const int k = c < nc ? count(c) : 0;
                          if (final) start(c) = upd;
                          upd += k;
                        });
  Kokkos::deep_copy(count, 0);  // reused as each cell's fill cursor
  auto sorted = cl.sorted;
  Kokkos::parallel_for("epac::driver::cell_fill", Kokkos::RangePolicy<exec>(0, n), KOKKOS_LAMBDA(int i) {
    const int c = particle_cell(i);
    sorted(start(c) + Kokkos::atomic_fetch_add(&count(c), 1)) = i;
  });
  // Insertion sort of each cell's few entries: a deterministic order for any thread count.
  Kokkos::parallel_for("epac::driver::cell_sort", Kokkos::RangePolicy<exec>(0, nc), KOKKOS_LAMBDA(int c) {
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
