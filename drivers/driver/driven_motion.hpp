#pragma once
// The driven particles that follow a prescribed motion ([[particles.list]] motion).
#include "driver/scene.hpp"

#include <epac/state/particles.hpp>

#include <cstddef>
#include <vector>

namespace epac {
namespace driver {

// Driven particles with a motion (piecewise-constant velocity): the velocity of a step is the
// exact displacement of the step over dt (as for walls), written to the device when it changes.
template <class T, class Device>
class DrivenMotion {
 public:
  explicit DrivenMotion(const Scene& s) : specs_(s.particles) {
    for (std::size_t i = 0; i < specs_.size(); ++i)
      if (specs_[i].driven && !specs_[i].motion.empty()) idx_.push_back(static_cast<int>(i));
    const int n = static_cast<int>(idx_.size());
    d_idx_ = Kokkos::View<int*, Device>("epac::driver::moved", n);
    d_vel_ = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>("epac::driver::moved_velocity", n);
    h_vel_ = Kokkos::create_mirror_view(d_vel_);
    auto hi = Kokkos::create_mirror_view(d_idx_);
    for (int k = 0; k < n; ++k) hi(k) = idx_[k];
    Kokkos::deep_copy(d_idx_, hi);
    last_.assign(n, Vec3d{0, 0, 0});
  }
  bool empty() const { return idx_.empty(); }

  // After a spatial sort: the moved particles' device indices follow them (inv: old -> new).
  void reindex(const Kokkos::View<int*, Device>& inv) {
    if (idx_.empty()) return;
    const auto idx = d_idx_;
    Kokkos::parallel_for(
        "epac::driver::driven_reindex",
        Kokkos::RangePolicy<typename Device::execution_space>(0, static_cast<int>(idx_.size())),
        KOKKOS_LAMBDA(int k) { idx(k) = inv(idx(k)); });
  }

  // Sets the driven velocities for the step [t0, t0 + dt].
  void advance(const Particles<T, Device>& p, double t0, double dt) {
    if (idx_.empty()) return;
    bool changed = first_;
    first_ = false;
    for (std::size_t k = 0; k < idx_.size(); ++k) {
      const Vec3d d = segments_displacement(specs_[idx_[k]].motion, t0, t0 + dt);
      for (int c = 0; c < 3; ++c) {
        const double v = d[c] / dt;
        if (v != last_[k][c]) changed = true;
        last_[k][c] = v;
        h_vel_(k, c) = T(v);
      }
    }
    if (!changed) return;
    Kokkos::deep_copy(d_vel_, h_vel_);
    const auto idx = d_idx_;
    const auto vel = d_vel_;
    const auto v = p.v;
    Kokkos::parallel_for(
        "epac::driver::driven_motion",
        Kokkos::RangePolicy<typename Device::execution_space>(0, static_cast<int>(idx_.size())), KOKKOS_LAMBDA(int k) {
          for (int c = 0; c < 3; ++c) v(idx(k), c) = vel(k, c);
        });
  }

 private:
  const std::vector<ParticleSpec>& specs_;
  std::vector<int> idx_;
  Kokkos::View<int*, Device> d_idx_;
  Kokkos::View<T* [3], Kokkos::LayoutLeft, Device> d_vel_;
  typename Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>::HostMirror h_vel_;
  std::vector<Vec3d> last_;
  bool first_ = true;
};

}  // namespace driver
}  // namespace epac
