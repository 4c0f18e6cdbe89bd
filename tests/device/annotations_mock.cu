// Compiled by cmake/check-device-annotations.sh with nvcc, against the host (OpenMP) Kokkos: no
// CUDA Kokkos is needed. Kokkos's function annotations are redefined as __host__ __device__
// after Kokkos is included, so nvcc checks epac's own headers as a CUDA build would: a host
// function called from a host-device one (20011/20013/20014), an annotation on a defaulted
// function (20012). The calls into Kokkos's math (host-only in this Kokkos, device functions in a
// CUDA one) are the expected noise the script filters out. Not built by CMake.
#include <Kokkos_Core.hpp>
#undef KOKKOS_INLINE_FUNCTION
#undef KOKKOS_FORCEINLINE_FUNCTION
#undef KOKKOS_FUNCTION
#define KOKKOS_INLINE_FUNCTION __host__ __device__ inline
#define KOKKOS_FORCEINLINE_FUNCTION __host__ __device__ inline
#define KOKKOS_FUNCTION __host__ __device__
#include <epac/core/root_solve.hpp>
#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/mdr/detail/mdr_adhesion.hpp>
#include <epac/models/mdr/mdr_bulk_response.hpp>
#include <epac/models/mdr/mdr_contact_penalty.hpp>
#include <epac/models/mdr/mdr_parameters.hpp>
#include <epac/models/rolling_resistance.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>

template <class T>
__global__ void device_paths(T* out, T* row) {
  epac::Vec3<T> a, b(T(1), T(2), T(3));  // the defaulted constructor on the device (20012)
  a += b;
  const epac::HistoryRow<T, epac::DefaultDevice> h(row, 1);
  h(0) = epac::norm(epac::cross(a, b));
  // MDR adhesion's device root solves (bracketed_newton with device lambdas)
  out[0] = epac::mdr_critical_radius<T>(T(1e9), T(0.1), T(1), T(4e-3), T(2e-3));
  out[1] = epac::mdr_peeling_radius<T>(T(1e9), T(0.1), T(4e-3), T(2e-3), T(1e-6), T(1e-4), T(1e-3));
  out[2] = T(epac::pair_key(3, 7) + epac::wall_key(3, 1));
  // rolling resistance's spring-dashpot-slider (every law's kRolling)
  const epac::RollingPair<T> rp{T(1e3), T(1e-3), T(0.1)};
  out[3] = epac::rolling_sds_force(rp, b, a, T(1), T(1e-6), h).x;
  // MDR's contact penalty: a triangle's term and the longest-side order
  out[4] = epac::mdr_penalty_shorter(T(1), 3u, T(2), 5u) ? epac::mdr_penalty_term(T(2)) : T(0);
  // MDR Part II: the increment split, A_c and F_BULK
  epac::MdrBulkSide<T> bs;
  const T d_mdr = epac::mdr_bulk_split(T(0.01), T(0.4), T(0.5), T(0.002), bs);
  // contacts in lanes (compute/pair_lanes.hpp, one lane per thread on GPUs): the laws' lane
  // forms, the exact selects, the sticking step and the sliding correction
  const epac::HertzMindlinPair<T> hp{T(1e9), T(0.8), T(0.1), T(0.3), T(0.9)};
  const auto nf = epac::HertzMindlin<T>::normal_lane(hp, T(1e-6), T(1e-3));
  const epac::LinearSpringPair<T> lp{T(1e5), T(0.8), T(0.1), T(0.3), T(0.9)};
  const auto nl = epac::LinearSpring<T>::normal_lane(lp, T(1e-6), T(1e-3));
  auto tt = epac::tangential_trial(a, b, a, nf.k_t, T(0.1), T(1e-6));
  epac::coulomb_slide(tt.ft, tt.xi, epac::lane_max(nf.f, nl.f), epac::dot(tt.ft, tt.ft), nf.k_t);
  out[6] = epac::lane_select(nf.active, tt.ft.x, T(0));
  out[5] = epac::mdr_bulk_force(T(1e9), T(1), T(2), bs.delta_bulk, epac::mdr_bulk_area(d_mdr, T(1), true, T(-0.1)));
}

int main() {
  // MDR's host-only yield solve (bracketed_newton_host with std:: maths)
  epac::Material m{"m", 1e9, 0.3, 1000, 0.5, 0.3, 0.1, 1e7};
  const auto c = epac::mdr_side_constants<double>(m, epac::MdrYieldOnset::elastic_law);
  const auto c40 = epac::mdr_side_constants<float>(m, epac::MdrYieldOnset::hertz_40);
  device_paths<double><<<1, 1>>>(nullptr, nullptr);
  device_paths<float><<<1, 1>>>(nullptr, nullptr);
  return c.x_yield > 0 && c40.x_yield > 0 ? 0 : 1;
}
