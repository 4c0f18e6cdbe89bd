#pragma once
// Per-particle accumulation of a force pass (design.md section 6): force, torque and any per-particle
// sum a model adds (the MDR growth sums). Each contact adds to two particles that other threads
// also add to, so the sums need one of two strategies, chosen at compile time from the execution
// space:
//  - host backends (OpenMP, Threads, HPX): per-thread duplicated copies, summed into the particle
//    views once after the pass (Kokkos::Experimental::ScatterView, ScatterDuplicated +
//    ScatterNonAtomic). No atomics: on a CPU core a `lock cmpxchg` per component costs as much
//    as the whole contact law (measured: 169 ns per Hertz-Mindlin contact with atomics, 99 ns
//    duplicated, 1 thread);
//  - Serial: plain adds into the particle views (one thread; nothing to duplicate);
//  - GPUs (CUDA, HIP, SYCL): atomics on the particle views (thousands of threads, duplicates
//    would not fit, and hardware float atomics are fast).
// This is exactly Kokkos' own DefaultDuplication/DefaultContribution for each space. A policy tag
// overrides it (template argument of ParticleSums, or -DEPAC_PARTICLE_SUMS=atomic|duplicated
// at compile time for the default).
//
// The deterministic mode (compute/deterministic_reduce.hpp) does not use these sums: it stores
// per-contact values and gathers them per particle in key order.
#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

#include <Kokkos_ScatterView.hpp>

#include <string>
#include <type_traits>

namespace epac {

// Policy tags.
struct AtomicSums {};      // atomic adds into the particle views (GPU default)
struct DuplicatedSums {};  // per-thread copies, reduced after the pass (host default)
struct DefaultSums {};     // what the execution space prefers (Kokkos' defaults, see above)

namespace detail {
namespace KE = Kokkos::Experimental;

template <class Exec, class Policy>
struct sums_traits;

template <class Exec>
struct sums_traits<Exec, AtomicSums> {
  using duplication = KE::ScatterNonDuplicated;
  using contribution = KE::ScatterAtomic;
};
template <class Exec>
struct sums_traits<Exec, DuplicatedSums> {
  using duplication = KE::ScatterDuplicated;
  using contribution = KE::ScatterNonAtomic;
};
template <class Exec>
struct sums_traits<Exec, DefaultSums> {
#if defined(EPAC_PARTICLE_SUMS_ATOMIC)
  using duplication = KE::ScatterNonDuplicated;
  using contribution = KE::ScatterAtomic;
#elif defined(EPAC_PARTICLE_SUMS_DUPLICATED)
  using duplication = KE::ScatterDuplicated;
  using contribution = KE::ScatterNonAtomic;
#else
  using duplication = typename Kokkos::Impl::Experimental::DefaultDuplication<Exec>::type;
  using contribution = typename Kokkos::Impl::Experimental::DefaultContribution<Exec, duplication>::type;
#endif
};
}  // namespace detail

// A ScatterView over a particle view (T* or T*[3], LayoutLeft) with the policy's strategy.
template <class DataType, class Device, class Policy = DefaultSums>
using particle_scatter_view =
    Kokkos::Experimental::ScatterView<DataType, Kokkos::LayoutLeft, Device, Kokkos::Experimental::ScatterSum,
                                      typename detail::sums_traits<typename Device::execution_space, Policy>::duplication,
                                      typename detail::sums_traits<typename Device::execution_space, Policy>::contribution>;

// True when the policy keeps per-thread copies (memory: threads x the particle view).
template <class Device, class Policy = DefaultSums>
constexpr bool sums_are_duplicated() {
  return std::is_same<typename detail::sums_traits<typename Device::execution_space, Policy>::duplication,
                      Kokkos::Experimental::ScatterDuplicated>::value;
}

// One per-particle sum (a scalar view or an n x 3 view) accumulated over a pass:
//   begin() -> kernels add through access() -> end() adds the pass's sums into `target`.
// For the atomic and Serial policies the scatter view aliases `target`, so begin/end cost nothing.
template <class DataType, class Device, class Policy = DefaultSums>
struct ParticleSum {
  using target_view = Kokkos::View<DataType, Kokkos::LayoutLeft, Device>;
  using scatter_view = particle_scatter_view<DataType, Device, Policy>;
  target_view target;
  scatter_view scatter;

  ParticleSum() = default;
  explicit ParticleSum(const target_view& t) : target(t), scatter(t) {}  // host

  // Clears the per-thread copies (the target keeps its values: the pass adds to them).
  void begin() {  // host
    if (target.extent(0) > 0) scatter.reset_except(target);
  }
  // Adds the copies into the target (no-op for the atomic and Serial policies).
  void end() {  // host
    if (target.extent(0) > 0) Kokkos::Experimental::contribute(target, scatter);
  }
  bool bound() const { return target.extent(0) > 0; }
};

// Force and torque sums of a force pass. Keep one per particle set (its per-thread copies are
// allocated once): begin(), then compute_pair_forces / compute_wall_forces with it, then end().
template <class T, class Device, class Policy = DefaultSums>
struct ForceSums {
  using policy = Policy;
  ParticleSum<T* [3], Device, Policy> force, torque;

  ForceSums() = default;
  explicit ForceSums(const Particles<T, Device>& p) : force(p.force), torque(p.torque) {}  // host

  void begin() { force.begin(); torque.begin(); }  // host
  void end() { force.end(); torque.end(); }        // host
  // True when bound to these particles' views (false after the particle arrays were reallocated).
  bool bound_to(const Particles<T, Device>& p) const {
    return force.target.data() == p.force.data() && torque.target.data() == p.torque.data() &&
           force.target.extent(0) == p.force.extent(0);
  }
};

// Device-side adds through a ScatterView access object (one per contact iteration).
template <class Access, class T>
KOKKOS_FORCEINLINE_FUNCTION void scatter_add3(const Access& a, int i, const Vec3<T>& v) {
  a(i, 0) += v.x;
  a(i, 1) += v.y;
  a(i, 2) += v.z;
}

}  // namespace epac
