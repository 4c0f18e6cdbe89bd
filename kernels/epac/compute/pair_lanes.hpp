#pragma once
// Contacts in lanes: the pair kernel of compute/contact_forces.hpp for laws whose normal force has
// a branch-free form (a lane form), with no rolling resistance, in scenes of one material (the
// pair's constants are then the same for every lane; with several, the lanes' gathered constants
// have no vector load and the one-contact kernel is faster). Three kinds of lane form:
//   - without normal history, the whole law in the pair's constants, the overlap and R*
//     (`normal_lane`, models/hertz_mindlin.hpp);
//   - with normal history, the law's common path only (models/nan2022/nan2022.hpp: loading and
//     unloading in contact): the lane form rewrites the history fields and flags the lanes its
//     common path does not cover, which then take the one-contact kernel's code;
//   - a contact lane form (`contact_lane`, models/mdr/mdr_model.hpp): as the second, but it also
//     reads per-particle and per-contact state of its own (MDR's R_o, V, Part II's psi, the
//     contact penalty's weight) and returns per-particle sums that stage 6 adds through the
//     law's `add_lane_sums`; its sides are ordered by global id (each pair is taken smaller id
//     first) and its conventions (contact_conventions) are applied by selects.
// The law returns its constants for lanes from `lane_pair(0)`, and may declare
// `static constexpr bool lane_form` (false: no lanes for this effect set) and a host member
// `bool lane_form_applies() const` (false: no lanes for these parameters).
//
// One work item takes a block of W contacts (core/simd_lanes.hpp: 8 on host backends that
// vectorise the block, 1 on GPUs, where this is one thread per contact). The stages of a block:
//   1. gather (no branch: the host compiler vectorises its index work): the list entries and
//      the history into lane arrays (a full block's are contiguous: vector loads);
//   2. the common path (one loop over the lanes, vectorised by the host compiler): both
//      particles' state, the minimum image, geometry, the law, damping and the sticking spring,
//      with selects in place of tests; the rare lanes keep their stored history;
//   3. Coulomb sliding (scalar), only for the lanes that slide;
//   4. the history and the outputs of every lane stored (vector stores for a full block);
//   5. the law's rare lanes (scalar, laws with normal history): the one-contact kernel's
//      finish_contact from the stored history, which stores and adds that contact itself;
//   6. scatter (scalar): the particle sums of the active lanes the common path covers.
// The divisions and roots of one contact (the latency chains that bound the scalar kernel,
// docs/performance.md) then run side by side for W contacts. Each lane computes the scalar
// kernel's expressions in its order with exact selects (lane_select), so without FMA
// contraction the results are its bits; with contraction (-march=native) the compiler may fuse
// the two forms differently (tests/foundation/test_pair_lanes.cpp compares them).
#include <epac/compute/contact_outputs.hpp>
#include <epac/compute/finish_contact.hpp>
#include <epac/compute/pair_wall_geometry.hpp>
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

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace epac {
namespace detail {

// The lane history of law M (one unused field for laws without normal history).
template <class M>
using lane_history_t = LaneHistory<typename M::scalar_type, (M::normal_history_size > 0 ? M::normal_history_size : 1)>;

template <class M, class = void>
struct has_normal_lane : std::false_type {};
template <class M>
struct has_normal_lane<M, std::void_t<typename M::lane_constants,
                                      decltype(M::normal_lane(std::declval<const typename M::lane_constants&>(),
                                                              std::declval<typename M::scalar_type>(),
                                                              std::declval<typename M::scalar_type>()))>>
    : std::true_type {};
template <class M, class = void>
struct has_history_lane : std::false_type {};
template <class M>
struct has_history_lane<
    M, std::void_t<typename M::lane_constants,
                   decltype(M::normal_lane(
                       std::declval<const typename M::lane_constants&>(), std::declval<typename M::scalar_type>(),
                       std::declval<typename M::scalar_type>(), std::declval<lane_history_t<M>&>()))>>
    : std::true_type {};
// A lane form that reads state of its own (per particle, per contact) and adds per-particle
// sums: `contact_lane(pair, LaneContact, history, sums, rare) const` (history and sums: the
// lane's LaneColumn of the block's arrays) and `add_lane_sums(i, j, sums) const`, with
// `lane_sum_count` (models/mdr/mdr_model.hpp).
template <class M, class = void>
struct lane_sum_count : std::integral_constant<int, 0> {};
template <class M>
struct lane_sum_count<M, std::void_t<decltype(M::lane_sum_count)>> : std::integral_constant<int, M::lane_sum_count> {};
template <class M, class = void>
struct has_contact_lane : std::false_type {};
template <class M>
struct has_contact_lane<M, std::void_t<typename M::lane_constants,
                                       decltype(std::declval<const M&>().contact_lane(
                                           std::declval<const typename M::lane_constants&>(),
                                           std::declval<const LaneContact<typename M::scalar_type, int>&>(),
                                           std::declval<const LaneColumn<typename M::scalar_type, 1>&>(),
                                           std::declval<const LaneColumn<typename M::scalar_type, 1>&>(),
                                           std::declval<typename M::scalar_type&>())),
                                       decltype(std::declval<const M&>().add_lane_sums(
                                           0, 0, std::declval<const LaneColumn<typename M::scalar_type, 1>&>()))>>
    : std::true_type {};
template <class M, class = void>
struct lane_form_declared : std::true_type {};
template <class M>
struct lane_form_declared<M, std::void_t<decltype(M::lane_form)>> : std::integral_constant<bool, M::lane_form> {};

// Laws the lanes kernel computes as the scalar kernel: a lane form (of the kind its normal history
// needs), no rolling resistance; side order (each pair in global-id order) and conventions of
// their own only with a contact lane form (the kernel orders every pair by id for it).
template <class M>
struct runs_in_lanes
    : std::integral_constant<
          bool, lane_form_declared<M>::value &&
                    (has_contact_lane<M>::value ||
                     ((M::normal_history_size == 0 ? has_normal_lane<M>::value : has_history_lane<M>::value) &&
                      !uses_side_order<M>::value &&
                      std::is_same<typename contact_conventions<M>::type, GenericContactConventions>::value)) &&
                    !rolling_on<M>::value> {};

// The lane form of each kind (a struct: the kernel's lambda cannot hold an if constexpr). eval
// runs lane l of a block: nh, the block's normal history (nh[field][lane]), rewritten where the
// common path holds; sums, the block's per-particle sums of the law; rare: 1 where the law's
// common path does not hold (the lane's history is then left as it was).
template <class M, bool Contact = has_contact_lane<M>::value, bool History = (M::normal_history_size > 0)>
struct lane_law {
  template <class P, class C, class T, int N, int S, int W>
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> eval(const M&, const P& pair, const C& c, T (&)[N][W], int,
                                                         T (&)[S][W], T& rare) {
    rare = T(0);
    return M::normal_lane(pair, c.delta, c.R_eff);
  }
  template <class S>
  KOKKOS_FORCEINLINE_FUNCTION static void add_sums(const M&, int, int, const S&) {}
};
template <class M>
struct lane_law<M, false, true> {
  template <class P, class C, class T, int N, int S, int W>
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> eval(const M&, const P& pair, const C& c, T (&nh)[N][W], int l,
                                                         T (&)[S][W], T& rare) {
    lane_history_t<M> lh;
    for (int f = 0; f < M::normal_history_size; ++f) lh.v[f] = nh[f][l];
    lh.rare = false;
    const NormalForce<T> nf = M::normal_lane(pair, c.delta, c.R_eff, lh);
    // rare lanes keep the stored history (their one-contact code reads it back)
    for (int f = 0; f < M::normal_history_size; ++f) nh[f][l] = lane_select(lh.rare, nh[f][l], lh.v[f]);
    rare = lane_select(lh.rare, T(1), T(0));
    return nf;
  }
  template <class S>
  KOKKOS_FORCEINLINE_FUNCTION static void add_sums(const M&, int, int, const S&) {}
};
template <class M, bool History>
struct lane_law<M, true, History> {
  template <class P, class C, class T, int N, int S, int W>
  KOKKOS_FORCEINLINE_FUNCTION static NormalForce<T> eval(const M& model, const P& pair, const C& c, T (&nh)[N][W],
                                                         int l, T (&sums)[S][W], T& rare) {
    return model.contact_lane(pair, c, LaneColumn<T, W>{nh, l}, LaneColumn<T, W>{sums, l}, rare);
  }
  template <class S>
  KOKKOS_FORCEINLINE_FUNCTION static void add_sums(const M& model, int i, int j, const S& sums) {
    model.add_lane_sums(i, j, sums);
  }
};

// The tangential velocity at the contact: v_c minus its normal part; with the authors' full-radius
// arms (ContactConventions::full_radius_arms) the rolling part from R_i w_i + R_j w_j, as
// finish_contact, by selects (a generic law's conventions compile it away).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION Vec3<T> lane_tangential_velocity(const GenericContactConventions&, const Vec3<T>& v_c,
                                                             const Vec3<T>&, T vn, const Vec3<T>& n, const Vec3<T>&) {
  return v_c - vn * n;
}
template <class T>
KOKKOS_FORCEINLINE_FUNCTION Vec3<T> lane_tangential_velocity(const ContactConventions& conv, const Vec3<T>& v_c,
                                                             const Vec3<T>& v_rel, T vn, const Vec3<T>& n,
                                                             const Vec3<T>& w_full) {
  const Vec3<T> arms = v_c - vn * n;
  const Vec3<T> full = v_rel - vn * n - cross(w_full, n);
  const bool f = conv.full_radius_arms;
  return Vec3<T>(lane_select(f, full.x, arms.x), lane_select(f, full.y, arms.y), lane_select(f, full.z, arms.z));
}

// Host: whether the law's lane form holds for this model's parameters (default: always).
template <class M, class = void>
struct has_lane_form_applies : std::false_type {};
template <class M>
struct has_lane_form_applies<M, std::void_t<decltype(std::declval<const M&>().lane_form_applies())>> : std::true_type {
};
template <class M>
bool lane_form_applies(const M& model) {  // host
  if constexpr (has_lane_form_applies<M>::value)
    return model.lane_form_applies();
  else
    return true;
}

template <int W, class Model, class T, class Device, class Policy>
void pair_kernel_lanes(const Model& model, const Particles<T, Device>& p, const ContactList<Device>& c,
                       const ContactHistory<T, Device>& h, T dt, const ForceSums<T, Device, Policy>& sums,
                       const ContactOutputs<T, Device>& out) {
  static_assert(runs_in_lanes<Model>::value, "epac: this law has no branch-free lane form");
  static_assert(W >= 1, "epac: pair_kernel_lanes: at least one lane");
  if (model.nmat != 1)  // host: compute_pair_forces takes this kernel only for one material
    throw std::invalid_argument("epac: pair_kernel_lanes: model.nmat is " + std::to_string(model.nmat) +
                                "; contacts in lanes take one material (nmat = 1)");
  if (!lane_form_applies(model))  // host: nor for parameters outside the law's lane form
    throw std::invalid_argument(std::string("epac: pair_kernel_lanes: the ") + Model::name +
                                " lane form does not hold for this model's parameters (lane_form_applies)");
  using exec = typename Device::execution_space;
  using Eff = typename Model::effects;
  using Pair = typename Model::lane_constants;
  constexpr bool friction = Eff::friction;
  constexpr int NH = Model::normal_history_size;  // the tangential spring's fields follow
  constexpr int NHL = NH > 0 ? NH : 1;
  constexpr int NS = lane_sum_count<Model>::value;  // the law's per-particle sums per lane
  using Law = lane_law<Model>;
  // Host lanes' particle indices as wide as T where the lanes take 512-bit vectors
  // (kHostLanes512): the lane loop's elements are then all of one width (float's geometry in
  // double aside), and g++ takes one 512-bit vector for 8 lanes of double. With 4-byte indices
  // beside 8-byte values it falls back to two 256-bit halves (twice the divisions and roots
  // issued: 0.85-0.92 of the time with 8-byte ones). With 256-bit vectors 8-byte indices cost
  // more (1.13 of the time with AVX2, 1.21 with GCC's Skylake-SP tuning), and float with them is
  // not vectorised at all. GPUs (one lane): int, the fewer registers.
  using Index = std::conditional_t<(W > 1 && sizeof(T) == 8 && kHostLanes512), std::int64_t, int>;
  const int count = c.count;
  const auto fsum = sums.force.scatter;
  const auto tsum = sums.torque.scatter;
  const auto first = c.first;
  const auto second = c.second;
  // the history's frame (and a side-ordered law's sides) from the ids, per contact
  const bool by_gid = (friction || has_contact_lane<Model>::value) && !c.gid_ordered;
  const auto conv = contact_conventions<Model>::of(model);
  const ContactForceBuffer<T, Device> nobuf{};  // the rare lanes add into the sums, as the lanes
  const auto hdata = h.data;
  T* const hist = h.data.data();
  const std::size_t hstride = (friction || NH > 0) ? h.data.stride(1) : 0;
  T* const out_fn = out.normal_force.extent(0) > 0 ? out.normal_force.data() : nullptr;
  T* const out_delta = out.overlap.extent(0) > 0 ? out.overlap.data() : nullptr;
  Kokkos::parallel_for(
      "epac::compute_pair_forces_lanes", Kokkos::RangePolicy<exec>(0, (count + W - 1) / W), KOKKOS_LAMBDA(int b) {
        const int k0 = b * W;
        const int lanes = count - k0 < W ? count - k0 : W;
        Index L_i[W], L_j[W], L_k[W];  // L_k: the lanes' contacts (a contact lane form reads it)
        T L_hx[W], L_hy[W], L_hz[W];
        T L_nx[W], L_ny[W], L_nz[W], L_delta[W], L_fn[W];
        T L_ftx[W], L_fty[W], L_ftz[W], L_f_lim[W], L_ft2[W], L_k_t[W];
        T L_arm_i[W], L_arm_j[W];
        T L_active[W], L_slides[W];  // flags as T (1 or 0): the vectors' element size
        T L_nh[NHL][W], L_rare[W];
        T L_sums[NS > 0 ? NS : 1][W];
        // 1. gather; lanes past the list's end repeat the block's first contact (finite
        //    arithmetic, nothing stored). A full block reads contiguous entries: vector loads
        //    (the tail block's select would make the compiler assemble them from scalar loads)
        auto gather = [&](auto lane_k) {
          for (int l = 0; l < W; ++l) {
            const int k = lane_k(l);
            L_i[l] = first(k);
            L_j[l] = second(k);
            L_k[l] = k;
          }
          // history in the frame of the smaller global id: swapped by selects, in a loop of its
          // own (no branch in a loop: they vectorise); a list ordered by ids needs neither
          if (by_gid)
            for (int l = 0; l < W; ++l) {
              const Index a = L_i[l], e = L_j[l];
              const bool swap = p.gid(e) < p.gid(a);
              L_i[l] = lane_select(swap, e, a);
              L_j[l] = lane_select(swap, a, e);
            }
          // one field at a time, from the block's first entry: each loop is one contiguous load
          // per vector
          const T* const row = (friction || NH > 0) ? hist + k0 : hist;  // no history: no row
          for (int f = 0; f < NH; ++f)
            for (int l = 0; l < W; ++l) L_nh[f][l] = row[(lane_k(l) - k0) + f * hstride];
          if (friction) {
            for (int l = 0; l < W; ++l) L_hx[l] = row[(lane_k(l) - k0) + NH * hstride];
            for (int l = 0; l < W; ++l) L_hy[l] = row[(lane_k(l) - k0) + (NH + 1) * hstride];
            for (int l = 0; l < W; ++l) L_hz[l] = row[(lane_k(l) - k0) + (NH + 2) * hstride];
          }
        };
        if (lanes == W)
          gather([k0](int l) { return k0 + l; });
        else
          gather([k0, lanes](int l) { return k0 + (l < lanes ? l : 0); });
        // 2. the common path, vectorised on host backends. The particles' state is loaded here,
        //    not copied into lane arrays first: the compiler loads it straight into vector
        //    registers (about 5% of the force pass against the copy, measured 2026-12-05)
        const Pair pair = model.lane_pair(0);  // one material
        // periodic axes: the minimum image by selects (no branch, so this loop vectorises); open
        // axes have length 0
        const auto box = p.box;
        for (int l = 0; l < W; ++l) {
          const Index i = L_i[l], j = L_j[l];
          const double dx = box.image_select(p.x(i, 0) - p.x(j, 0), box.length.x);
          const double dy = box.image_select(p.x(i, 1) - p.x(j, 1), box.length.y);
          const double dz = box.image_select(p.x(i, 2) - p.x(j, 2), box.length.z);
          const T R_i = p.radius(i), R_j = p.radius(j), m_i = p.mass(i), m_j = p.mass(j);
          const double dist = math::sqrt(dx * dx + dy * dy + dz * dz);
          // coincident centres have no normal: x, as pair_geometry_exact (the 1 keeps 1/dist finite)
          const bool apart = dist > 0.0;
          const double inv = 1.0 / lane_select(apart, dist, 1.0);
          const Vec3<T> n(lane_select(apart, T(inv * dx), T(1)), lane_select(apart, T(inv * dy), T(0)),
                          lane_select(apart, T(inv * dz), T(0)));
          const double delta = double(R_i) + double(R_j) - dist;
          const T R_eff = R_i * R_j / (R_i + R_j);  // radii > 0 (host validation)
          const T m_eff = m_i * m_j / (m_i + m_j);  // masses > 0 (host validation)
          const double half = 0.5 * delta;          // contact point: middle of the overlap zone
          const T arm_i = T(double(R_i) - half), arm_j = T(double(R_j) - half);
          const Vec3<T> w_arm = arm_i * Vec3<T>(p.omega(i, 0), p.omega(i, 1), p.omega(i, 2)) +
                                arm_j * Vec3<T>(p.omega(j, 0), p.omega(j, 1), p.omega(j, 2));
          const Vec3<T> v_rel(p.v(i, 0) - p.v(j, 0), p.v(i, 1) - p.v(j, 1), p.v(i, 2) - p.v(j, 2));
          const Vec3<T> v_c = v_rel - cross(w_arm, n);
          const T vn = dot(v_c, n);
          const LaneContact<T, Index> lc{i, j, L_k[l], T(delta), R_i, R_j, R_eff};
          T rare_flag = T(0);  // rare lanes keep the stored history (their one-contact code reads it back)
          const NormalForce<T> nf = Law::eval(model, pair, lc, L_nh, l, L_sums, rare_flag);
          L_rare[l] = rare_flag;
          const bool rare = rare_flag != T(0);
          T fn = nf.f;
          T root_mkn = T(0);
          if (Eff::damping) {                                       // as finish_contact, with the generic conventions
            root_mkn = math::sqrt(lane_max(m_eff * nf.k_n, T(0)));  // sqrt_nonneg
            const T fd = nf.damping * root_mkn * (-vn);
            const T damped = fn + fd;
            const T pushed = lane_select(conv.damp_may_pull, damped, lane_max(damped, T(0)));
            fn = lane_select(nf.damp_compressive_only, lane_select(fn > T(0), pushed, fn), damped);
          }
          TangentialTrial<T> tt;  // zero without friction
          T f_lim = T(0), ft2 = T(0);
          if (friction) {
            const Vec3<T> w_full = R_i * Vec3<T>(p.omega(i, 0), p.omega(i, 1), p.omega(i, 2)) +
                                   R_j * Vec3<T>(p.omega(j, 0), p.omega(j, 1), p.omega(j, 2));
            const Vec3<T> v_t = lane_tangential_velocity(conv, v_c, v_rel, vn, n, w_full);
            // lane laws have k_t = kt_root_ratio^2 k_n (both 0 for a rigid pair): one root
            const T damp_t = Eff::damping ? nf.damping_t * root_mkn * nf.kt_root_ratio : T(0);
            tt = tangential_trial(Vec3<T>(L_hx[l], L_hy[l], L_hz[l]), n, v_t, nf.k_t, damp_t, dt);
            f_lim = nf.mu * math::fabs(lane_select(conv.coulomb_on_damped, fn, nf.f));  // the bound's force
            ft2 = dot(tt.ft, tt.ft);
          }
          L_nx[l] = n.x;
          L_ny[l] = n.y;
          L_nz[l] = n.z;
          L_delta[l] = T(delta);
          L_fn[l] = lane_select(nf.active, fn, T(0));
          L_active[l] = lane_select(nf.active & !rare, T(1), T(0));  // rare lanes: stage 5 adds theirs
          const T f_lim2 = f_lim * f_lim;
          L_slides[l] = lane_select(nf.active & !rare & (ft2 > f_lim2), T(1), T(0));  // & not &&: no branch
          L_ftx[l] = tt.ft.x;
          L_fty[l] = tt.ft.y;
          L_ftz[l] = tt.ft.z;
          L_f_lim[l] = f_lim;
          L_ft2[l] = ft2;
          L_k_t[l] = nf.k_t;
          L_arm_i[l] = arm_i;
          L_arm_j[l] = arm_j;
          // apart: the spring is forgotten (reset_tangential)
          L_hx[l] = lane_select(rare, L_hx[l], lane_select(nf.active, tt.xi.x, T(0)));
          L_hy[l] = lane_select(rare, L_hy[l], lane_select(nf.active, tt.xi.y, T(0)));
          L_hz[l] = lane_select(rare, L_hz[l], lane_select(nf.active, tt.xi.z, T(0)));
        }
        auto fa = fsum.access();
        auto ta = tsum.access();
        // 3. Coulomb sliding, Nan (23)
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
        // 4. the history, every lane at once (vector stores on host backends; the rare lanes store
        //    what they read, which the one-contact code below reads back). A full block stores W
        //    lanes, a compile-time count (vector stores); the list's last block its own count
        auto store = [&](auto stored) {
          T* const row = (friction || NH > 0) ? hist + k0 : hist;
          for (int f = 0; f < NH; ++f)
            for (int l = 0; l < stored; ++l) row[l + f * hstride] = L_nh[f][l];
          if (friction) {
            for (int l = 0; l < stored; ++l) row[l + NH * hstride] = L_hx[l];
            for (int l = 0; l < stored; ++l) row[l + (NH + 1) * hstride] = L_hy[l];
            for (int l = 0; l < stored; ++l) row[l + (NH + 2) * hstride] = L_hz[l];
          }
          // the outputs (contiguous; stage 5 rewrites the rare lanes')
          if (out_fn)
            for (int l = 0; l < stored; ++l) out_fn[k0 + l] = L_fn[l];
          if (out_delta)
            for (int l = 0; l < stored; ++l) out_delta[k0 + l] = L_delta[l];
        };
        if (lanes == W)
          store(LaneCount<W>());
        else
          store(lanes);
        // 5. the law's rare lanes: the one-contact kernel's code from the stored history (a plain
        //    if on a constant: nvcc's extended lambdas cannot first-capture inside if constexpr).
        //    One test per block first: a packing's blocks rarely hold a rare lane
        int rare_lanes = 0;
        if (NH > 0)
          for (int l = 0; l < W; ++l) rare_lanes += L_rare[l] != T(0);
        if (NH > 0 && rare_lanes > 0)
          for (int l = 0; l < lanes; ++l) {
            if (L_rare[l] == T(0)) continue;
            const int k = k0 + l, i = int(L_i[l]), j = int(L_j[l]);
            finish_pair_contact(model, conv, p, i, j, 1, pair_separation(p, i, j), dt,
                                HistoryRow<T, Device>{hdata, k, 0}, out, nobuf, k, fa, ta);
          }
        // 6. scatter (the rare lanes are done)
        for (int l = 0; l < lanes; ++l) {
          if (L_active[l] == T(0)) continue;  // inactive or rare
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
          if (NS > 0) Law::add_sums(model, int(L_i[l]), int(L_j[l]), LaneColumn<T, W>{L_sums, l});
        }
      });
}

}  // namespace detail
}  // namespace epac
