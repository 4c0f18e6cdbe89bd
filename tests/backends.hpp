#pragma once
// The execution spaces each test body runs on: every enabled backend, so a test is written once.
// Use as TEMPLATE_LIST_TEST_CASE("...", "[tag]", epac::test::Backends).
#include <Kokkos_Core.hpp>

#include <tuple>

namespace epac {
namespace test {

template <class Exec>
using DeviceOf = Kokkos::Device<Exec, typename Exec::memory_space>;

using Backends = decltype(std::tuple_cat(
#ifdef KOKKOS_ENABLE_SERIAL
    std::tuple<DeviceOf<Kokkos::Serial>>{},
#endif
#ifdef KOKKOS_ENABLE_OPENMP
    std::tuple<DeviceOf<Kokkos::OpenMP>>{},
#endif
#ifdef KOKKOS_ENABLE_CUDA
    std::tuple<DeviceOf<Kokkos::Cuda>>{},
#endif
#ifdef KOKKOS_ENABLE_HIP
    std::tuple<DeviceOf<Kokkos::Experimental::HIP>>{},
#endif
    std::tuple<>{}));

// Backends x scalar types.
template <class D, class T>
struct Config {
  using device = D;
  using scalar = T;
};
template <class... D>
struct with_scalars;
template <class... D>
struct with_scalars<std::tuple<D...>> {
  using type = std::tuple<Config<D, double>..., Config<D, float>...>;
};
using BackendsAndScalars = typename with_scalars<Backends>::type;

// Copies a device view to the host and returns the mirror.
template <class View>
auto to_host(const View& v) {
  auto h = Kokkos::create_mirror_view(v);
  Kokkos::deep_copy(h, v);
  return h;
}

}  // namespace test
}  // namespace epac
