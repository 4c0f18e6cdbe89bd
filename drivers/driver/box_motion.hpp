#pragma once
// The periodic box of a run ([box] in the scene): sets Particles::box for the kernels, wraps
// positions into the box at rebuilds, and applies the affine deformation of [box.deform].
//  - Wrapping happens only at rebuilds (as LAMMPS wraps only when it re-neighbours): between
//    rebuilds a particle leaves the box by at most skin/2, so raw separations stay well inside
//    the (-1.5 L, 1.5 L) that PeriodicBox::minimum_image assumes. The driver wraps first and
//    then records the rebuild rule's reference positions, so a wrap never counts as motion.
//  - Deformation (LAMMPS `fix deform ... scale s ... remap x`): the edge along a deformed axis is
//    L(k) = L0 (1 + (s - 1) min(k, N) / N) at step k, about the fixed box centre c; at each step
//    the positions are mapped affinely, x' = c + (L(k) / L(k-1)) (x - c), velocities untouched.
//    The map runs before the drift of the step, so the rebuild measure (|x - x_build|) sees it
//    like any other displacement: the lists stay complete (LAMMPS checks the same way).
//    Box edge at step k's force pass: L(k). (LAMMPS deforms at the end of a step, so its force
//    pass of step k sees L(k-1): one step apart, 2.4e-4 of the strain per step here.)
// Edges are kept on the host in double and copied into p.box (double, like the positions, for
// any T) when they change.
#include "driver/scene.hpp"

#include <epac/state/particles.hpp>

#include <array>
#include <cstdint>

namespace epac {
namespace driver {

// One deformation step's map of the positions, x' = c + r (x - c) along each axis; when any edge
// changed it maps all three (an unchanged axis has r = 1), as LAMMPS's remap x does.
template <class P>
struct AffineRemap {
  bool active = false;
  P ratio[3] = {P(1), P(1), P(1)};
  P centre[3] = {P(0), P(0), P(0)};
  KOKKOS_INLINE_FUNCTION P operator()(P x, int d) const { return centre[d] + ratio[d] * (x - centre[d]); }
};

template <class T, class Device>
class BoxMotion {
 public:
  using P = typename Particles<T, Device>::position_type;
  explicit BoxMotion(const BoxSpec& spec) : spec_(spec) {
    for (int d = 0; d < 3; ++d) edge_[d] = spec.enabled ? spec.edge0(d) : 0.0;
  }

  bool enabled() const { return spec_.enabled; }
  bool periodic() const { return spec_.enabled && spec_.any_periodic(); }
  // Current edges [m] (the scene's box; zeros without a box).
  const std::array<double, 3>& edge() const { return edge_; }

  // Writes the periodic axes into p.box (non-periodic axes keep length 0: not periodic).
  void apply(Particles<T, Device>& p) const {
    P lo[3] = {P(0), P(0), P(0)}, len[3] = {P(0), P(0), P(0)};
    for (int d = 0; d < 3; ++d)
      if (spec_.enabled && spec_.periodic[d]) {
        lo[d] = P(spec_.centre(d) - 0.5 * edge_[d]);
        len[d] = P(edge_[d]);
      }
    p.box.lo = Vec3<P>(lo[0], lo[1], lo[2]);
    p.box.length = Vec3<P>(len[0], len[1], len[2]);
  }

  // Wraps positions into [lo, lo + L) along the periodic axes (at a rebuild).
  void wrap(const Particles<T, Device>& p) const {
    if (!periodic()) return;
    const PeriodicBox<P> box = p.box;
    auto x = p.x;
    Kokkos::parallel_for(
        "epac::driver::wrap_positions", Kokkos::RangePolicy<exec>(0, p.n), KOKKOS_LAMBDA(int i) {
          x(i, 0) = PeriodicBox<P>::wrap(x(i, 0), box.lo.x, box.length.x);
          x(i, 1) = PeriodicBox<P>::wrap(x(i, 1), box.lo.y, box.length.y);
          x(i, 2) = PeriodicBox<P>::wrap(x(i, 2), box.lo.z, box.length.z);
        });
  }

  // The affine map from a box of edges `then` to the current one: the composition of the remaps
  // since then. Inactive where no edge changed.
  AffineRemap<P> map_since(const std::array<double, 3>& then) const {
    AffineRemap<P> map;
    if (!spec_.enabled || !spec_.deform) return map;
    for (int d = 0; d < 3; ++d) {
      map.ratio[d] = P(edge_[d] / then[d]);  // edges > 0 (host validation)
      map.centre[d] = P(spec_.centre(d));
      if (edge_[d] != then[d]) map.active = true;
    }
    return map;
  }

  // Deforms the box to its edges at `step` (p.box included) and returns the affine map of the
  // positions (remap x), which the caller applies: the driver's kick_drift, in the pass that
  // drifts them, instead of a pass of its own. Inactive when nothing changed.
  AffineRemap<P> deform_to(Particles<T, Device>& p, std::int64_t step) {
    AffineRemap<P> map;
    if (!spec_.enabled || !spec_.deform) return map;
    std::array<double, 3> next;
    bool changed = false;
    for (int d = 0; d < 3; ++d) {
      next[d] = spec_.edge(d, step);
      map.ratio[d] = P(next[d] / edge_[d]);
      map.centre[d] = P(spec_.centre(d));
      if (next[d] != edge_[d]) changed = true;
    }
    if (!changed) return AffineRemap<P>{};
    edge_ = next;
    apply(p);
    map.active = true;
    return map;
  }

 private:
  using exec = typename Device::execution_space;
  const BoxSpec& spec_;
  std::array<double, 3> edge_{0, 0, 0};
};

}  // namespace driver
}  // namespace epac
