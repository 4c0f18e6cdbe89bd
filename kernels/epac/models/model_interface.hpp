#pragma once
// The interface a contact law (model) offers the kernels, checked at compile time.
//
// Required (compute/contact_forces.hpp, compute/history_from_overlaps.hpp; models/hertz_mindlin.hpp
// is the smallest law that has them all):
//   using effects = Effects<...>;                    compile-time effect set (models/effects.hpp)
//   static constexpr int normal_history_size;        the law's own history fields, >= 0
//   static constexpr int history_size;               normal_history_size + 3 with friction + 3 with
//                                                    rolling (the tangential spring's fields follow
//                                                    the law's, then rolling resistance's)
//   with effects::rolling: RollingTable<T, Device, true> rolling;   (models/rolling_resistance.hpp)
//   int nmat;                                        materials: the pair table is nmat x nmat
//   KOKKOS_INLINE_FUNCTION NormalForce<T> normal(const ContactGeometry<T>&,
//                                                const HistoryRow<T, Device>&) const;
//   and, where declared, `using scalar_type = T;` equal to the particles' T.
// Optional (a default where absent):
//   static constexpr bool uses_side_order;          per-side history in global-id order (MDR)
//   static constexpr bool inactive_apart;           no force and no normal history where delta <= 0
//   void update_radii() const;                       particle update after each pass (MDR growth)
//   guard_hits() const;                              counters summed by history_from_overlaps
//   begin_deterministic_pass(int, int),
//   end_deterministic_pass(p, pairs, pair_incidence, wall_incidence) const
//                                                    per-particle sums of the model's own
//                                                    (compute/deterministic_pass.hpp)
//   contact_conventions<Model>                      law-specific kernel conventions
//                                                    (models/contact_conventions.hpp)
// The kernel entry points call check_contact_model<Model, T, Device>(), whose static_asserts name
// the missing member and its expected form; is_contact_model<Model, T, Device> is the same test
// as a value (tests/core/test_model_interface.cpp).
#include <epac/models/contact_geometry.hpp>
#include <epac/state/contact_history.hpp>

#include <type_traits>
#include <utility>

namespace epac {

namespace detail {

// --- required members ---

template <class M, class = void>
struct has_effects : std::false_type {};
template <class M>
struct has_effects<M, std::void_t<typename M::effects>> : std::true_type {};

// The flags the kernels branch on, as constant expressions.
template <class M, class = void>
struct has_effect_flags : std::false_type {};
template <class M>
struct has_effect_flags<M, std::void_t<std::integral_constant<bool, M::effects::friction>,
                                       std::integral_constant<bool, M::effects::damping>,
                                       std::integral_constant<bool, M::effects::radius_growth>>> : std::true_type {};

// Rolling resistance is on when the effects say `rolling = true` (an effects type without the
// member, written before the effect existed, has it off).
template <class M, class = void>
struct rolling_on : std::false_type {};
template <class M>
struct rolling_on<M, std::void_t<std::integral_constant<bool, M::effects::rolling>>>
    : std::integral_constant<bool, M::effects::rolling> {};

template <class M, class = void>
struct has_normal_history_size : std::false_type {};
template <class M>
struct has_normal_history_size<M, std::void_t<std::integral_constant<int, M::normal_history_size>>> : std::true_type {};

template <class M, class = void>
struct has_history_size : std::false_type {};
template <class M>
struct has_history_size<M, std::void_t<std::integral_constant<int, M::history_size>>> : std::true_type {};

// history_size leaves room for the tangential spring after the law's fields; true where a size
// or the effects are missing (reported by their own checks).
template <class M, class = void>
struct history_sizes_fit : std::true_type {};
template <class M>
struct history_sizes_fit<
    M, std::enable_if_t<has_normal_history_size<M>::value && has_history_size<M>::value && has_effect_flags<M>::value>>
    : std::integral_constant<bool, (M::normal_history_size >= 0 &&
                                    M::history_size >= M::normal_history_size + (M::effects::friction ? 3 : 0) +
                                                           (rolling_on<M>::value ? 3 : 0))> {};

template <class M, class = void>
struct has_nmat : std::false_type {};
template <class M>
struct has_nmat<M, std::enable_if_t<std::is_convertible<decltype(std::declval<const M&>().nmat), int>::value>>
    : std::true_type {};

// What `model.normal(g, row)` returns (void where it cannot be called so).
template <class M, class T, class Device, class = void>
struct normal_result {
  using type = void;
};
template <class M, class T, class Device>
struct normal_result<M, T, Device,
                     std::void_t<decltype(std::declval<const M&>().normal(
                         std::declval<const ContactGeometry<T>&>(), std::declval<const HistoryRow<T, Device>&>()))>> {
  using type = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<const M&>().normal(
      std::declval<const ContactGeometry<T>&>(), std::declval<const HistoryRow<T, Device>&>()))>>;
};
template <class M, class T, class Device>
struct has_normal : std::is_same<typename normal_result<M, T, Device>::type, NormalForce<T>> {};

// scalar_type, where declared, is the particles' T.
template <class M, class T, class = void>
struct scalar_type_matches : std::true_type {};
template <class M, class T>
struct scalar_type_matches<M, T, std::void_t<typename M::scalar_type>> : std::is_same<typename M::scalar_type, T> {};

// --- optional members ---

// Models whose sides are ordered by global id (MDR) declare `uses_side_order = true`; the
// others load the 64-bit ids only for friction (orientation of the tangential history).
template <class M, class = void>
struct uses_side_order : std::false_type {};
template <class M>
struct uses_side_order<M, std::void_t<decltype(M::uses_side_order)>>
    : std::integral_constant<bool, M::uses_side_order> {};

// Models whose normal() is inactive wherever the overlap is <= 0, whatever the history, and that
// keep no normal history (Hertz-Mindlin, linear spring, JKR without adhesion) declare
// `inactive_apart = true`: the pair kernel then skips everything after the distance for list
// entries that do not touch (a list built with a skin holds many; docs/performance.md).
template <class M, class = void>
struct inactive_apart : std::false_type {};
template <class M>
struct inactive_apart<M, std::void_t<decltype(M::inactive_apart)>>
    : std::integral_constant<bool, M::inactive_apart && M::normal_history_size == 0> {};

// The model's particle update after each pass (MDR: radius growth), if it has one.
template <class M, class = void>
struct has_update_radii : std::false_type {};
template <class M>
struct has_update_radii<M, std::void_t<decltype(std::declval<const M&>().update_radii())>> : std::true_type {};

template <class M, class = void>
struct has_guard_hits : std::false_type {};
template <class M>
struct has_guard_hits<M, std::void_t<decltype(std::declval<const M&>().guard_hits())>> : std::true_type {};

// Models with MDR's growth state (Mdr::growth: radius0, radius, volume and the sums).
template <class M, class = void>
struct has_growth_state : std::false_type {};
template <class M>
struct has_growth_state<
    M, std::void_t<decltype(std::declval<const M&>().growth.volume), decltype(std::declval<const M&>().growth.bound())>>
    : std::true_type {};

// Models with per-particle sums of their own declare begin_deterministic_pass(pairs, walls) and
// end_deterministic_pass(p, pairs, pair_incidence, wall_incidence) (models/mdr/mdr_model.hpp).
template <class M, class = void>
struct has_deterministic_hooks : std::false_type {};
template <class M>
struct has_deterministic_hooks<M, std::void_t<decltype(std::declval<M&>().begin_deterministic_pass(0, 0))>>
    : std::true_type {};

// With rolling on: a member `rolling` with the per-pair view `pairs` (models/rolling_resistance.hpp).
template <class M, class = void>
struct has_rolling_table : std::false_type {};
template <class M>
struct has_rolling_table<M, std::void_t<decltype(std::declval<const M&>().rolling.pairs)>> : std::true_type {};

}  // namespace detail

// True when Model has every required member for particles of scalar T on Device.
template <class Model, class T, class Device>
struct is_contact_model
    : std::integral_constant<
          bool, detail::has_effects<Model>::value && detail::has_effect_flags<Model>::value &&
                    detail::has_normal_history_size<Model>::value && detail::has_history_size<Model>::value &&
                    detail::history_sizes_fit<Model>::value && detail::has_nmat<Model>::value &&
                    (!detail::rolling_on<Model>::value || detail::has_rolling_table<Model>::value) &&
                    detail::scalar_type_matches<Model, T>::value && detail::has_normal<Model, T, Device>::value> {};

// The kernels' compile-time check: one message per missing or ill-formed member.
template <class Model, class T, class Device>
constexpr bool check_contact_model() {
  static_assert(detail::has_effects<Model>::value,
                "epac: a contact model must define `using effects = Effects<...>;` (its compile-time effect set, "
                "models/effects.hpp; see models/hertz_mindlin.hpp)");
  static_assert(!detail::has_effects<Model>::value || detail::has_effect_flags<Model>::value,
                "epac: the contact model's `effects` must have `static constexpr bool` members friction, damping and "
                "radius_growth (use Effects<Bits> of models/effects.hpp)");
  static_assert(detail::has_normal_history_size<Model>::value,
                "epac: a contact model must define `static constexpr int normal_history_size` (its own history "
                "fields per contact, 0 if none; see models/hertz_mindlin.hpp)");
  static_assert(detail::has_history_size<Model>::value,
                "epac: a contact model must define `static constexpr int history_size = normal_history_size + "
                "(effects::friction ? 3 : 0);` (see models/hertz_mindlin.hpp)");
  static_assert(detail::history_sizes_fit<Model>::value,
                "epac: the contact model's history_size must be at least normal_history_size + 3 with friction + 3 "
                "with rolling (the tangential spring's 3 fields follow the law's, then rolling's), and "
                "normal_history_size >= 0");
  static_assert(!detail::rolling_on<Model>::value || detail::has_rolling_table<Model>::value,
                "epac: a contact model with effects::rolling must have a member `RollingTable<T, Device, true> "
                "rolling` (models/rolling_resistance.hpp; see models/hertz_mindlin.hpp)");
  static_assert(detail::has_nmat<Model>::value,
                "epac: a contact model must have a member `int nmat` (the number of materials; the kernels index "
                "its pair table by mat_i * nmat + mat_j; see models/hertz_mindlin.hpp)");
  static_assert(detail::scalar_type_matches<Model, T>::value,
                "epac: the contact model's scalar_type differs from the particles' scalar type T (build the model "
                "with the same T as Particles<T, Device>)");
  static_assert(!detail::scalar_type_matches<Model, T>::value || detail::has_normal<Model, T, Device>::value,
                "epac: a contact model must define `KOKKOS_INLINE_FUNCTION NormalForce<T> normal(const "
                "ContactGeometry<T>&, const HistoryRow<T, Device>&) const` for the particles' T and Device (see "
                "models/hertz_mindlin.hpp)");
  return true;
}

}  // namespace epac
