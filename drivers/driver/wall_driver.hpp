#pragma once
// The scene's walls on the device and their prescribed motion ([[walls]] motion).
#include "driver/scene.hpp"

#include <epac/core/kokkos_compat.hpp>
#include <epac/state/walls.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace epac {
namespace driver {

// Wall positions are kept on the host in double (exact prescribed displacement) and copied to
// the device, where they are double too (Walls::point, any T), after each move; the velocity of a step is its displacement
// over dt, so damping and friction see the mean velocity of the step.
template <class T, class Device>
class WallDriver {
 public:
  WallDriver(const Scene& s, Walls<T, Device>& w) : specs_(s.walls), w_(w) {
    const int nw = static_cast<int>(specs_.size());
    w_ = Walls<T, Device>(nw);
    point_ = Kokkos::create_mirror_view(w_.point);
    vel_ = Kokkos::create_mirror_view(w_.velocity);
    auto nrm = Kokkos::create_mirror_view(w_.normal);
    auto mat = Kokkos::create_mirror_view(w_.material);
    pos_.resize(nw);
    at_build_.resize(nw);
    for (int k = 0; k < nw; ++k) {
      pos_[k] = specs_[k].point;
      for (int d = 0; d < 3; ++d) {
        point_(k, d) = pos_[k][d];
        nrm(k, d) = T(specs_[k].normal[d]);
        vel_(k, d) = T(0);
      }
      mat(k) = specs_[k].material;
    }
    Kokkos::deep_copy(w_.point, point_);
    Kokkos::deep_copy(w_.normal, nrm);
    Kokkos::deep_copy(w_.velocity, vel_);
    Kokkos::deep_copy(w_.material, mat);
  }

  // Moves the walls over [t0, t0 + dt].
  void advance(double t0, double dt) {
    bool changed = false;
    for (std::size_t k = 0; k < specs_.size(); ++k) {
      const Vec3d d = specs_[k].displacement(t0, t0 + dt);
      for (int c = 0; c < 3; ++c) {
        const T vel = T(d[c] / dt);
        if (d[c] != 0.0 || vel_(k, c) != vel) changed = true;
        pos_[k][c] += d[c];
        point_(k, c) = pos_[k][c];
        vel_(k, c) = vel;
      }
    }
    if (changed) {
      Kokkos::deep_copy(w_.point, point_);
      Kokkos::deep_copy(w_.velocity, vel_);
    }
  }

  // Displacement of wall k along its normal since t = 0.
  double normal_displacement(int k) const {
    double s = 0;
    for (int d = 0; d < 3; ++d) s += (pos_[k][d] - specs_[k].point[d]) * specs_[k].normal[d];
    return s;
  }

  // The rebuild rule's wall measure, on the host: max_w |normal displacement since mark_build()|.
  void mark_build() { at_build_ = pos_; }
  double max_shift_since_build() const {
    double m = 0;
    for (std::size_t k = 0; k < pos_.size(); ++k) {
      double s = 0;
      for (int d = 0; d < 3; ++d) s += (pos_[k][d] - at_build_[k][d]) * specs_[k].normal[d];
      m = std::max(m, std::fabs(s));
    }
    return m;
  }

 private:
  const std::vector<WallSpec>& specs_;
  Walls<T, Device>& w_;
  host_mirror_t<typename Walls<T, Device>::position_view> point_;
  host_mirror_t<typename Walls<T, Device>::vec_view> vel_;
  std::vector<Vec3d> pos_, at_build_;
};

}  // namespace driver
}  // namespace epac
