#pragma once
// Copies the device state a particle snapshot needs to the host (snapshot_writer.hpp): positions,
// velocities, angular velocities, contact forces, radii, ids, materials, and the model's
// per-particle fields (MDR: the tracked volume V of MDR (39), with radius growth).
#include "driver/snapshot_writer.hpp"

#include <epac/state/particles.hpp>

namespace epac {
namespace driver {

template <class F, class Model, class T, class Device>
ParticleSnapshot capture_snapshot(const Model& model, const Particles<T, Device>& p, std::int64_t step, double time) {
  auto host = [](const auto& v) { return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v); };
  const auto x = host(p.x);  // double positions: one `auto` declares one type (nvcc enforces it)
  const auto v = host(p.v), w = host(p.omega), f = host(p.force);
  const auto R = host(p.radius), R0 = host(p.radius0);
  const auto gid = host(p.gid);
  const auto mat = host(p.material);
  const auto vol = host(F::template particle_volume<T, Device>(model));
  const std::size_t n = static_cast<std::size_t>(p.n);
  ParticleSnapshot s;
  s.step = step;
  s.time = time;
  s.x.resize(3 * n);
  s.v.resize(3 * n);
  s.omega.resize(3 * n);
  s.force.resize(3 * n);
  s.radius.resize(n);
  s.radius0.resize(n);
  s.id.resize(n);
  s.material.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      s.x[3 * i + d] = x(i, d);
      s.v[3 * i + d] = v(i, d);
      s.omega[3 * i + d] = w(i, d);
      s.force[3 * i + d] = f(i, d);
    }
    s.radius[i] = R(i);
    s.radius0[i] = R0(i);
    s.id[i] = gid(i);
    s.material[i] = mat(i);
  }
  if (vol.extent(0) == n) {
    std::vector<double> V(n);
    for (std::size_t i = 0; i < n; ++i) V[i] = vol(i);
    s.extras.emplace_back("volume", std::move(V));  // m^3
  }
  return s;
}

}  // namespace driver
}  // namespace epac
