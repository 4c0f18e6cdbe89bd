#pragma once
// Spatial sort at rebuilds ([run] spatial_sort): the particle arrays are reordered into cell-list
// order, so that the particles of a cell, and the partners of a contact, sit close together in
// memory (the pair kernel's gathers of x, v, omega, radius, mass hit fewer cache lines).
// A permutation `perm` gives the new order: new index k holds the particle of old index perm(k).
// Every view is permuted in place (gathered into a scratch view, then copied back), so every
// handle to it stays valid: the model's bindings (MDR's radius views), ForceSums' targets.
// Identity is kept by the global id (gid): contact histories are keyed by gid and survive; the
// driver writes particles.csv in gid order.
#include <epac/state/particles.hpp>

#include <string>

namespace epac {
namespace driver {

// [run] spatial_sort = "auto" sorts scenes of at least this many particles (drivers/README.md,
// "Spatial sort": below it a shuffled order cost under 5% and the particle arrays fit in one core's L2).
inline constexpr int kAutoSortMinParticles = 4096;

template <class T, class Device>
class Permuter {
 public:
  using exec = typename Device::execution_space;
  using vec_view = Kokkos::View<T* [3], Kokkos::LayoutLeft, Device>;

  Permuter() = default;
  explicit Permuter(const Kokkos::View<int*, Device>& perm) : perm_(perm), n_(static_cast<int>(perm.extent(0))) {}
  int size() const { return n_; }
  const Kokkos::View<int*, Device>& perm() const { return perm_; }

  // In-place gather of a per-particle view: v(k) <- v_old(perm(k)).
  template <class DataType, class... Props>
  void operator()(const Kokkos::View<DataType, Props...>& v) const {
    using V = Kokkos::View<DataType, Props...>;
    if (static_cast<int>(v.extent(0)) != n_) return;
    using value_type = typename V::non_const_value_type;
    const auto perm = perm_;
    if constexpr (V::rank == 1) {
      Kokkos::View<value_type*, Device> tmp(Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::sort_tmp"),
                                            n_);
      Kokkos::parallel_for(
          "epac::driver::sort_gather", Kokkos::RangePolicy<exec>(0, n_), KOKKOS_LAMBDA(int k) { tmp(k) = v(perm(k)); });
      Kokkos::deep_copy(v, tmp);
    } else {
      static_assert(V::rank == 2, "per-particle views are n or n x 3");
      Kokkos::View<value_type* [3], Kokkos::LayoutLeft, Device> tmp(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::sort_tmp3"), n_);
      Kokkos::parallel_for(
          "epac::driver::sort_gather3", Kokkos::RangePolicy<exec>(0, n_), KOKKOS_LAMBDA(int k) {
            for (int d = 0; d < 3; ++d) tmp(k, d) = v(perm(k), d);
          });
      Kokkos::deep_copy(v, tmp);
    }
  }

  // All of a particle set's views.
  void particles(const Particles<T, Device>& p) const {
    (*this)(p.x);
    (*this)(p.v);
    (*this)(p.omega);
    (*this)(p.force);
    (*this)(p.torque);
    (*this)(p.mass);
    (*this)(p.inertia);
    (*this)(p.radius0);
    (*this)(p.radius);
    (*this)(p.material);
    (*this)(p.gid);
  }

  // inverse(old index) = new index.
  Kokkos::View<int*, Device> inverse() const {
    Kokkos::View<int*, Device> inv(Kokkos::view_alloc(Kokkos::WithoutInitializing, "epac::driver::sort_inverse"), n_);
    const auto perm = perm_;
    Kokkos::parallel_for(
        "epac::driver::sort_inverse", Kokkos::RangePolicy<exec>(0, n_), KOKKOS_LAMBDA(int k) { inv(perm(k)) = k; });
    return inv;
  }

 private:
  Kokkos::View<int*, Device> perm_;
  int n_ = 0;
};

}  // namespace driver
}  // namespace epac
