#pragma once
// Per-particle accumulation of a force pass (docs/design.md section 6): force, torque and any per-particle
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
// This is Kokkos' own ScatterView choice (DefaultDuplication/DefaultContribution) for each space,
// implemented here with raw pointers so that a contact pays no View copy. A policy tag overrides
// it (template argument of ParticleSum/ForceSums), and -DEPAC_PARTICLE_SUMS_ATOMIC or
// -DEPAC_PARTICLE_SUMS_DUPLICATED changes the default at compile time. The per-thread sums are
// added in thread order, so a run on a fixed thread count and contact list is reproducible.
//
// The deterministic mode (compute/deterministic_reduce.hpp) does not use these sums: it stores
// per-contact values and gathers them per particle in key order.
#include <epac/core/vec3.hpp>
#include <epac/state/particles.hpp>

#include <Kokkos_ScatterView.hpp>

#include <cstddef>
#include <string>
#include <type_traits>

namespace epac {

// Policy tags.
struct AtomicSums {};      // atomic adds into the particle views (GPU default)
struct DuplicatedSums {};  // per-thread copies, reduced after the pass (host default)
struct PlainSums {};       // plain adds into the particle views: one thread only (Serial default)
struct DefaultSums {};     // what the execution space prefers (see above)

namespace detail {
// The strategy of a policy on an execution space: 0 plain, 1 duplicated, 2 atomic.
template <class Exec, class Policy>
struct sums_mode;
template <class Exec>
struct sums_mode<Exec, AtomicSums> : std::integral_constant<int, 2> {};
template <class Exec>
struct sums_mode<Exec, DuplicatedSums> : std::integral_constant<int, 1> {};
template <class Exec>
struct sums_mode<Exec, PlainSums> : std::integral_constant<int, 0> {};
template <class Exec>
struct sums_mode<Exec, DefaultSums>
#if defined(EPAC_PARTICLE_SUMS_ATOMIC)
    : std::integral_constant<int, 2> {
#elif defined(EPAC_PARTICLE_SUMS_DUPLICATED)
    : std::integral_constant<int, 1> {
#else
    // Kokkos' own choice for ScatterView: duplicated on OpenMP/Threads/HPX, plain on Serial,
    // atomic on device backends.
    : std::integral_constant<int, std::is_same<typename Kokkos::Impl::Experimental::DefaultDuplication<Exec>::type,
                                               Kokkos::Experimental::ScatterDuplicated>::value
                                      ? 1
                                      : (std::is_same<typename Kokkos::Impl::Experimental::DefaultContribution<
                                                          Exec, Kokkos::Experimental::ScatterNonDuplicated>::type,
                                                      Kokkos::Experimental::ScatterAtomic>::value
                                             ? 2
                                             : 0)> {
#endif
};
}  // namespace detail

// True when the policy keeps per-thread copies (memory: threads x the particle view).
template <class Device, class Policy = DefaultSums>
constexpr bool sums_are_duplicated() {
  return detail::sums_mode<typename Device::execution_space, Policy>::value == 1;
}

// Device-side handle of one sum for one contact: `a(i) += x` (scalar sums) or `a(i, c) += x`
// (vector sums). Raw pointers only, so making one per contact costs no View copy (a managed
// View copy checks its reference count on every construction).
template <class T, int Mode>
struct SumAccess {
  T* base;
  std::size_t stride;  // distance between components
  struct Ref {
    T* p;
    KOKKOS_FORCEINLINE_FUNCTION void operator+=(T v) const {
      if (Mode == 2)
        Kokkos::atomic_add(p, v);
      else
        *p += v;
    }
  };
  KOKKOS_FORCEINLINE_FUNCTION Ref operator()(int i) const { return {base + i}; }
  KOKKOS_FORCEINLINE_FUNCTION Ref operator()(int i, int c) const { return {base + i + c * stride}; }
};

// The per-thread storage of one sum (n x components x threads, each thread's block contiguous),
// empty for the plain and atomic strategies. `access()` is called inside the kernel.
namespace detail {
struct NoToken {  // the plain and atomic strategies need no thread id (and a device token allocates)
  KOKKOS_INLINE_FUNCTION int acquire() const { return 0; }
  int size() const { return 1; }
};
}  // namespace detail

template <class T, class Device, int Mode>
struct SumScatter {
  using exec = typename Device::execution_space;
  // Global scope on a host backend: acquire() is the calling thread's rank (its size is the pool
  // size), so release() is a no-op and is not called.
  using token_type =
      std::conditional_t<Mode == 1,
                         Kokkos::Experimental::UniqueToken<exec, Kokkos::Experimental::UniqueTokenScope::Global>,
                         detail::NoToken>;
  T* target = nullptr;     // the particle view's data
  std::size_t stride = 0;  // its component stride
  std::size_t block = 0;   // elements per thread copy (n x components)
  Kokkos::View<T*, Device> copies;
  int ncopies = 0;
  token_type token;

  KOKKOS_FORCEINLINE_FUNCTION SumAccess<T, Mode> access() const {
    if (Mode == 1) return {copies.data() + block * static_cast<std::size_t>(token.acquire()), stride};
    return {target, stride};
  }
  // Element (i, c) of the target plus the pass's per-thread copies, all cleared: for a kernel
  // that consumes the sums right after the pass (one kernel instead of end + use + begin).
  KOKKOS_FORCEINLINE_FUNCTION T take(int i, int c = 0) const {
    const std::size_t e = static_cast<std::size_t>(i) + static_cast<std::size_t>(c) * stride;
    T v = target[e];
    target[e] = T(0);
    if (Mode == 1)
      for (int t = 0; t < ncopies; ++t) {
        v += copies(e + t * block);
        copies(e + t * block) = T(0);
      }
    return v;
  }
};

// One per-particle sum (a scalar view T* or an n x 3 view T*[3], LayoutLeft) accumulated over a
// pass: begin() -> kernels add through scatter.access() -> end() adds the pass's sums into
// `target`. For the plain and atomic strategies the kernels add into `target` directly, so
// begin/end cost nothing.
template <class DataType, class Device, class Policy = DefaultSums>
struct ParticleSum {
  using target_view = Kokkos::View<DataType, Kokkos::LayoutLeft, Device>;
  using value_type = typename target_view::non_const_value_type;
  static constexpr int mode = detail::sums_mode<typename Device::execution_space, Policy>::value;
  target_view target;
  SumScatter<value_type, Device, mode> scatter;
  Kokkos::View<value_type*, Device> own_copies;  // the per-thread copies (scatter.copies unless direct)
  bool direct = false;                           // this pass adds into the target itself (begin)

  ParticleSum() = default;
  explicit ParticleSum(const target_view& t) : target(t) {  // host
    scatter.target = t.data();
    scatter.stride = target_view::rank > 1 ? t.stride(1) : 1;
    const std::size_t comps = target_view::rank > 1 ? t.extent(1) : 1;
    scatter.block = scatter.stride * (comps - 1) + t.extent(0);
    scatter.ncopies = mode == 1 ? static_cast<int>(scatter.token.size()) : 0;
    if (mode == 1)
      own_copies = Kokkos::View<value_type*, Device>(std::string("epac::sums.") + t.label(),  // host
                                                     scatter.block * static_cast<std::size_t>(scatter.ncopies));
    scatter.copies = own_copies;
  }

  // Clears the per-thread copies (the target keeps its values: the pass adds to them).
  // overwrite: the pass's end(true) will set the target to its sums. With a single copy (one
  // thread) the pass then adds into the target itself, cleared here, and end() has nothing to
  // do: no copy to clear and none to add up (the same bits as end(true)'s 0 + sum, but for the
  // sign of a zero sum). begin(true) must be followed by end(true).
  void begin(bool overwrite = false) {  // host
    if (mode != 1 || target.extent(0) == 0) return;
    direct = overwrite && own_copies.extent(0) == scatter.block;
    // direct: an unmanaged view of the target, and take() reads the target only
    scatter.copies = direct ? Kokkos::View<value_type*, Device>(scatter.target, scatter.block) : own_copies;
    scatter.ncopies = direct ? 0 : static_cast<int>(own_copies.extent(0) / scatter.block);
    Kokkos::deep_copy(scatter.copies, value_type(0));
  }
  // Adds the copies into the target, each element summing the threads in a fixed order.
  // overwrite: sets the target to that sum instead, dropping its values from before the pass
  // (the same bits as adding to a zeroed target), for a caller that would otherwise zero the
  // target before every pass. Only duplicated sums can: plain and atomic ones add into the
  // target during the pass, so their target must be zeroed (sums_are_duplicated says which).
  void end(bool overwrite = false) {  // host
    if (mode != 1 || target.extent(0) == 0 || direct) return;
    const SumScatter<value_type, Device, mode> s = scatter;
    const int copies = s.ncopies;
    Kokkos::parallel_for(
        "epac::sums_reduce", Kokkos::RangePolicy<typename Device::execution_space>(0, s.block),
        KOKKOS_LAMBDA(std::size_t e) {
          value_type sum = s.copies(e);
          for (int c = 1; c < copies; ++c) sum += s.copies(e + c * s.block);
          // overwrite: 0 + sum, the very operation of the add to a zeroed target
          s.target[e] = (overwrite ? value_type(0) : s.target[e]) + sum;
        });
  }
  bool bound() const { return target.extent(0) > 0; }
};

// Force and torque sums of a force pass. Keep one per particle set (its per-thread copies are
// allocated once): begin(), then compute_pair_forces / compute_wall_forces with it, then end().
template <class T, class Device, class Policy = DefaultSums>
struct ForceSums {
  using policy = Policy;
  ParticleSum<T*[3], Device, Policy> force, torque;

  ForceSums() = default;
  explicit ForceSums(const Particles<T, Device>& p) : force(p.force), torque(p.torque) {}  // host

  // overwrite: end(true) follows (ParticleSum::begin)
  void begin(bool overwrite = false) {
    force.begin(overwrite);
    torque.begin(overwrite);
  }  // host
  // overwrite: the forces and torques are set to the pass's sums (ParticleSum::end)
  void end(bool overwrite = false) {
    force.end(overwrite);
    torque.end(overwrite);
  }  // host
  // True when bound to these particles' views (false after the particle arrays were reallocated).
  bool bound_to(const Particles<T, Device>& p) const {
    return force.target.data() == p.force.data() && torque.target.data() == p.torque.data() &&
           force.target.extent(0) == p.force.extent(0);
  }
};

// Device-side adds of a 3-vector through an access object (one per contact iteration).
template <class Access, class T>
KOKKOS_FORCEINLINE_FUNCTION void scatter_add3(const Access& a, int i, const Vec3<T>& v) {
  a(i, 0) += v.x;
  a(i, 1) += v.y;
  a(i, 2) += v.z;
}

}  // namespace epac
