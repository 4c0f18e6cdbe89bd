#pragma once
// Contacts in lanes: the pair kernel of compute/contact_forces.hpp for laws whose normal force is
// a branch-free function of the pair's constants, the overlap and R* (a `normal_lane` member,
// e.g. models/hertz_mindlin.hpp), that keep no normal history or rolling resistance, in scenes
// of one material (the pair's constants are then the same for every lane; with several, the
// lanes' gathered constants have no vector load and the one-contact kernel is faster).
//
// One work item takes a block of W contacts (core/simd_lanes.hpp: 8 on host backends that
// vectorise the block, 1 on GPUs, where this is one thread per contact). Four stages per block:
//   1. gather (scalar): the list entries, both particles' state and the tangential history into
//      lane arrays;
//   2. the common path (one loop over the lanes, vectorised by the host compiler): geometry, the
//      law, damping and the sticking spring, with selects in place of tests;
//   3. the rare path (scalar): Coulomb sliding, only for the lanes that slide;
//   4. scatter (scalar): history, outputs and the particle sums.
// The divisions and roots of one contact (the latency chains that bound the scalar kernel,
// docs/performance.md) then run side by side for W contacts. Each lane computes the scalar
// kernel's expressions in its order with exact selects (lane_select), so without FMA
// contraction the results are its bits; with contraction (-march=native) the compiler may fuse
// the two forms differently (tests/foundation/test_pair_lanes.cpp compares them).
#include <epac/compute/contact_outputs.hpp>
#include <epac/compute/particle_sums.hpp>
#include <epac/core/simd_lanes.hpp>
#include <epac/core/vec3.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/contact_geometry.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/models/tangential_spring.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace epac {
namespace detail {

template <class M, class = void>
struct has_normal_lane : std::false_type {};
template <class M>
struct has_normal_lane<M, std::void_t<typename M::lane_constants,
                                      decltype(M::normal_lane(std::declval<const typename M::lane_constants&>(),
                                                              std::declval<typename M::scalar_type>(),
                                                              std::declval<typename M::scalar_type>()))>>
    : std::true_type {};

// Laws the lanes kernel computes exactly as the scalar kernel: a normal_lane, no normal history,
// no rolling resistance, no side order, the generic conventions around the normal force.
template <class M>
struct runs_in_lanes
    : std::integral_constant<
          bool, has_normal_lane<M>::value && M::normal_history_size == 0 && !rolling_on<M>::value &&
                    !uses_side_order<M>::value &&
                    std::is_same<typename contact_conventions<M>::type, GenericContactConventions>::value> {};

// One block's lane arrays (stage 1 fills them, stage 2 reads and overwrites them).

template <int W, class Model, class T, class Device, class Policy>
void pair_kernel_lanes(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                       const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,
                       const ContactOutputs<T, Device>& out) {
  static_assert(runs_in_lanes<Model>::value, "epac: this law has no branch-free lane form");
  static_assert(W >= 1, "epac: pair_kernel_lanes: at least one lane");
  if (model.nmat != 1)  // host: compute_pair_forces takes this kernel only for one material
    throw std::invalid_argument("epac: pair_kernel_lanes: model.nmat is " + std::to_string(model.nmat) +
                                "; contacts in lanes take one material (nmat = 1)");
  using exec = typename Device::execution_space;
  using Eff = typename Model::effects;
  using Pair = typename Model::lane_constants;
  constexpr bool friction = Eff::friction;
  const int count = c.count;
  const auto fsum = sums.force.scatter;
  const auto tsum = sums.torque.scatter;
  const auto first = c.first;
  const auto second = c.second;
  const auto pairs = model.pairs;
  T* const hist = h.data.data();
  const std::size_t hstride = friction ? h.data.stride(1) : 0;
  const auto out_fn = out.normal_force;
  const auto out_delta = out.overlap;
  Kokkos::parallel_for(
      "epac::compute_pair_forces_lanes", Kokkos::RangePolicy<exec>(0, (count + W - 1) / W), KOKKOS_LAMBDA(int b) {
        const int k0 = b * W;
        const int lanes = count - k0 < W ? count - k0 : W;
        int L_i[W], L_j[W];
        double L_dx[W], L_dy[W], L_dz[W];
        T L_R_i[W], L_R_j[W], L_m_i[W], L_m_j[W];
        T L_vx[W], L_vy[W], L_vz[W];
        T L_wix[W], L_wiy[W], L_wiz[W], L_wjx[W], L_wjy[W], L_wjz[W];
        T L_hx[W], L_hy[W], L_hz[W];
        T L_nx[W], L_ny[W], L_nz[W], L_delta[W], L_fn[W];
        T L_ftx[W], L_fty[W], L_ftz[W], L_f_lim[W], L_ft2[W], L_k_t[W];
        T L_arm_i[W], L_arm_j[W];
        T L_active[W], L_slides[W];  // flags as T (1 or 0): the vectors' element size
        // 1. gather; lanes past the list's end repeat the block's first contact (finite
        //    arithmetic, nothing stored)
        for (int l = 0; l < W; ++l) {
          const int k = k0 + (l < lanes ? l : 0);
          int i = first(k), j = second(k);
          if (friction && p.gid(j) < p.gid(i)) {  // history in the frame of the smaller global id
            const int t = i;
            i = j;
            j = t;
          }
          L_i[l] = i;
          L_j[l] = j;
          Vec3<double> d = load3(p.x, i) - load3(p.x, j);
          if (p.box.periodic()) d = p.box.minimum_image(d);
          L_dx[l] = d.x;
          L_dy[l] = d.y;
          L_dz[l] = d.z;
          L_R_i[l] = p.radius(i);
          L_R_j[l] = p.radius(j);
          L_m_i[l] = p.mass(i);
          L_m_j[l] = p.mass(j);
          L_vx[l] = p.v(i, 0) - p.v(j, 0);
          L_vy[l] = p.v(i, 1) - p.v(j, 1);
          L_vz[l] = p.v(i, 2) - p.v(j, 2);
          L_wix[l] = p.omega(i, 0);
          L_wiy[l] = p.omega(i, 1);
          L_wiz[l] = p.omega(i, 2);
          L_wjx[l] = p.omega(j, 0);
          L_wjy[l] = p.omega(j, 1);
          L_wjz[l] = p.omega(j, 2);
          if (friction) {
            L_hx[l] = hist[k];
            L_hy[l] = hist[k + hstride];
            L_hz[l] = hist[k + 2 * hstride];
          }
        }
        // 2. the common path, vectorised on host backends
        const Pair pair = pairs(0);  // one material
        for (int l = 0; l < W; ++l) {
          const double dist = math::sqrt(L_dx[l] * L_dx[l] + L_dy[l] * L_dy[l] + L_dz[l] * L_dz[l]);
          // coincident centres have no normal: x, as pair_geometry_exact (the 1 keeps 1/dist finite)
          const bool apart = dist > 0.0;
          const double inv = 1.0 / lane_select(apart, dist, 1.0);
          const Vec3<T> n(lane_select(apart, T(inv * L_dx[l]), T(1)), lane_select(apart, T(inv * L_dy[l]), T(0)),
                          lane_select(apart, T(inv * L_dz[l]), T(0)));
          const double delta = double(L_R_i[l]) + double(L_R_j[l]) - dist;
          const T R_eff = L_R_i[l] * L_R_j[l] / (L_R_i[l] + L_R_j[l]);  // radii > 0 (host validation)
          const T m_eff = L_m_i[l] * L_m_j[l] / (L_m_i[l] + L_m_j[l]);  // masses > 0 (host validation)
          const double half = 0.5 * delta;                              // contact point: middle of the overlap zone
          const T arm_i = T(double(L_R_i[l]) - half), arm_j = T(double(L_R_j[l]) - half);
          const Vec3<T> w_arm =
              arm_i * Vec3<T>(L_wix[l], L_wiy[l], L_wiz[l]) + arm_j * Vec3<T>(L_wjx[l], L_wjy[l], L_wjz[l]);
          const Vec3<T> v_c = Vec3<T>(L_vx[l], L_vy[l], L_vz[l]) - cross(w_arm, n);
          const T vn = dot(v_c, n);
          const NormalForce<T> nf = Model::normal_lane(pair, T(delta), R_eff);
          T fn = nf.f;
          T root_mkn = T(0);
          if (Eff::damping) {                                       // as finish_contact, with the generic conventions
            root_mkn = math::sqrt(lane_max(m_eff * nf.k_n, T(0)));  // sqrt_nonneg
            const T fd = nf.damping * root_mkn * (-vn);
            const T damped = fn + fd;
            fn = lane_select(nf.damp_compressive_only, lane_select(fn > T(0), lane_max(damped, T(0)), fn), damped);
          }
          TangentialTrial<T> tt;  // zero without friction
          T f_lim = T(0), ft2 = T(0);
          if (friction) {
            const Vec3<T> v_t = v_c - vn * n;
            // lane laws have k_t = kt_root_ratio^2 k_n (both 0 for a rigid pair): one root
            const T damp_t = Eff::damping ? nf.damping_t * root_mkn * nf.kt_root_ratio : T(0);
            tt = tangential_trial(Vec3<T>(L_hx[l], L_hy[l], L_hz[l]), n, v_t, nf.k_t, damp_t, dt);
            f_lim = nf.mu * math::fabs(nf.f);
            ft2 = dot(tt.ft, tt.ft);
          }
          L_nx[l] = n.x;
          L_ny[l] = n.y;
          L_nz[l] = n.z;
          L_delta[l] = T(delta);
          L_fn[l] = lane_select(nf.active, fn, T(0));
          L_active[l] = lane_select(nf.active, T(1), T(0));
          const T f_lim2 = f_lim * f_lim;
          L_slides[l] = lane_select(nf.active & (ft2 > f_lim2), T(1), T(0));  // & not &&: no branch
          L_ftx[l] = tt.ft.x;
          L_fty[l] = tt.ft.y;
          L_ftz[l] = tt.ft.z;
          L_f_lim[l] = f_lim;
          L_ft2[l] = ft2;
          L_k_t[l] = nf.k_t;
          L_arm_i[l] = arm_i;
          L_arm_j[l] = arm_j;
          // apart: the spring is forgotten (reset_tangential)
          L_hx[l] = lane_select(nf.active, tt.xi.x, T(0));
          L_hy[l] = lane_select(nf.active, tt.xi.y, T(0));
          L_hz[l] = lane_select(nf.active, tt.xi.z, T(0));
        }
        // 3. the rare path: Coulomb sliding, Nan (23)
        if (friction)
          for (int l = 0; l < lanes; ++l) {
            if (L_slides[l] == T(0)) continue;
            Vec3<T> ft(L_ftx[l], L_fty[l], L_ftz[l]), xi(L_hx[l], L_hy[l], L_hz[l]);
            coulomb_slide(ft, xi, L_f_lim[l], L_ft2[l], L_k_t[l]);
            L_ftx[l] = ft.x;
            L_fty[l] = ft.y;
            L_ftz[l] = ft.z;
            L_hx[l] = xi.x;
            L_hy[l] = xi.y;
            L_hz[l] = xi.z;
          }
        // 4. scatter
        auto fa = fsum.access();
        auto ta = tsum.access();
        for (int l = 0; l < lanes; ++l) {
          const int k = k0 + l;
          if (friction) {
            hist[k] = L_hx[l];
            hist[k + hstride] = L_hy[l];
            hist[k + 2 * hstride] = L_hz[l];
          }
          if (out_fn.extent(0) > 0) out_fn(k) = L_fn[l];
          if (out_delta.extent(0) > 0) out_delta(k) = L_delta[l];
          if (L_active[l] == T(0)) continue;
          const Vec3<T> n(L_nx[l], L_ny[l], L_nz[l]);
          Vec3<T> F = L_fn[l] * n;
          if (friction) {
            const Vec3<T> ft(L_ftx[l], L_fty[l], L_ftz[l]);
            F += ft;
            const Vec3<T> nxft = cross(n, ft);
            scatter_add3(ta, L_i[l], (-L_arm_i[l]) * nxft);
            scatter_add3(ta, L_j[l], (-L_arm_j[l]) * nxft);
          }
          scatter_add3(fa, L_i[l], F);
          scatter_add3(fa, L_j[l], T(-1) * F);
        }
      });
}

}  // namespace detail
}  // namespace epac
