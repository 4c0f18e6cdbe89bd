// The contact-model interface (models/model_interface.hpp): the traits accept every shipped law
// with any effect set and reject structs that lack a member, each through the check that names
// that member; law-specific kernel conventions (models/contact_conventions.hpp) are a
// compile-time default for the generic laws and MDR's options for MDR.
#include <catch2/catch.hpp>
#include <epac/models/contact_conventions.hpp>
#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/linear_spring.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/model_interface.hpp>
#include <epac/models/nan2022/nan2022.hpp>

#include <type_traits>

using namespace epac;

namespace {

using D = DefaultDevice;
constexpr unsigned kAll = kAllEffects;
constexpr unsigned kNone = 0u;

template <class M, class T = typename M::scalar_type>
constexpr bool accepted() {
  return is_contact_model<M, T, D>::value && check_contact_model<M, T, D>();
}

// every shipped law, no effect and every effect, double and float
static_assert(accepted<HertzMindlin<double>>() && accepted<HertzMindlin<float, Effects<kAll>>>() &&
                  accepted<HertzMindlin<double, Effects<kNone>>>(),
              "HertzMindlin");
static_assert(accepted<LinearSpring<double>>() && accepted<LinearSpring<float, Effects<kAll>>>() &&
                  accepted<LinearSpring<double, Effects<kNone>>>(),
              "LinearSpring");
static_assert(accepted<Jkr<double>>() && accepted<Jkr<float, Effects<kAll>>>() &&
                  accepted<Jkr<double, Effects<kNone>>>(),
              "Jkr");
static_assert(accepted<Nan2022<double>>() && accepted<Nan2022<float, Effects<kAll>>>() &&
                  accepted<Nan2022<double, Effects<kNone>>>(),
              "Nan2022");
static_assert(accepted<Mdr<double>>() && accepted<Mdr<float, Effects<kAll>>>() &&
                  accepted<Mdr<double, Effects<kNone>>>() &&
                  accepted<Mdr<double, Effects<kPlasticity | kRadiusGrowth | kFriction>>>(),
              "Mdr");

// A complete law, and copies each missing one member (or with it ill-formed).
struct Complete {
  using scalar_type = double;
  using effects = Effects<kFriction>;
  static constexpr int normal_history_size = 0;
  static constexpr int history_size = 3;
  int nmat = 1;
  KOKKOS_INLINE_FUNCTION NormalForce<double> normal(const ContactGeometry<double>&,
                                                    const HistoryRow<double, D>&) const {
    return {};
  }
};
static_assert(is_contact_model<Complete, double, D>::value, "the reference struct is complete");

struct NoNormal {
  using effects = Effects<kFriction>;
  static constexpr int normal_history_size = 0;
  static constexpr int history_size = 3;
  int nmat = 1;
};
struct NonConstNormal : NoNormal {
  NormalForce<double> normal(const ContactGeometry<double>&, const HistoryRow<double, D>&) { return {}; }
};
struct WrongResult : NoNormal {
  double normal(const ContactGeometry<double>&, const HistoryRow<double, D>&) const { return 0; }
};
struct NoEffects {
  static constexpr int normal_history_size = 0;
  static constexpr int history_size = 0;
  int nmat = 1;
  NormalForce<double> normal(const ContactGeometry<double>&, const HistoryRow<double, D>&) const { return {}; }
};
struct NoHistorySizes {
  using effects = Effects<kNone>;
  int nmat = 1;
  NormalForce<double> normal(const ContactGeometry<double>&, const HistoryRow<double, D>&) const { return {}; }
};
struct NoRoomForFriction : Complete {
  static constexpr int history_size = 0;  // friction needs 3
};
struct NoNmat {
  using effects = Effects<kNone>;
  static constexpr int normal_history_size = 0;
  static constexpr int history_size = 0;
  NormalForce<double> normal(const ContactGeometry<double>&, const HistoryRow<double, D>&) const { return {}; }
};

static_assert(!detail::has_normal<NoNormal, double, D>::value && !is_contact_model<NoNormal, double, D>::value,
              "no normal()");
static_assert(!detail::has_normal<NonConstNormal, double, D>::value, "normal() must be const");
static_assert(!detail::has_normal<WrongResult, double, D>::value, "normal() must return NormalForce<T>");
static_assert(!detail::has_effects<NoEffects>::value && !is_contact_model<NoEffects, double, D>::value, "no effects");
static_assert(!detail::has_normal_history_size<NoHistorySizes>::value &&
                  !detail::has_history_size<NoHistorySizes>::value &&
                  !is_contact_model<NoHistorySizes, double, D>::value,
              "no history sizes");
static_assert(!detail::history_sizes_fit<NoRoomForFriction>::value &&
                  !is_contact_model<NoRoomForFriction, double, D>::value,
              "history_size without the tangential fields");
static_assert(!detail::has_nmat<NoNmat>::value && !is_contact_model<NoNmat, double, D>::value, "no nmat");
// the particles' T must be the law's: Complete is a double law
static_assert(!is_contact_model<Complete, float, D>::value, "scalar type mismatch");
// each incomplete struct fails only the check that names its missing member
static_assert(detail::has_effects<NoNormal>::value && detail::has_nmat<NoNormal>::value &&
                  detail::history_sizes_fit<NoNormal>::value,
              "NoNormal lacks normal() only");

// Conventions: a compile-time default for the generic laws (nothing to carry or branch on), a
// run-time set for MDR.
static_assert(std::is_same<contact_conventions<HertzMindlin<double>>::type, GenericContactConventions>::value &&
                  std::is_same<contact_conventions<LinearSpring<double>>::type, GenericContactConventions>::value &&
                  std::is_same<contact_conventions<Jkr<double>>::type, GenericContactConventions>::value &&
                  std::is_same<contact_conventions<Nan2022<double>>::type, GenericContactConventions>::value &&
                  std::is_same<contact_conventions<Mdr<double>>::type, ContactConventions>::value,
              "conventions");
static_assert(!GenericContactConventions::damp_may_pull && !GenericContactConventions::coulomb_on_damped &&
                  !GenericContactConventions::full_radius_arms,
              "the generic conventions are all off");

}  // namespace

TEST_CASE("MDR's kernel conventions follow its options", "[core][model_interface]") {
  const Material m{"m", 1e9, 0.3, 1000, 0.5, 0.3, 0.1, 1e7};
  using M = Mdr<double, Effects<kAll>>;
  const ContactConventions paper = contact_conventions<M>::of(M::create({m}));
  CHECK_FALSE(paper.damp_may_pull);
  CHECK_FALSE(paper.coulomb_on_damped);
  CHECK_FALSE(paper.full_radius_arms);

  MdrOptions opt;
  opt.damping = MdrDamping::authors;
  const ContactConventions damping = contact_conventions<M>::of(M::create({m}, opt));
  CHECK(damping.damp_may_pull);
  CHECK_FALSE(damping.coulomb_on_damped);
  CHECK_FALSE(damping.full_radius_arms);

  opt.friction = MdrFriction::authors;
  opt.tangential_stiffness = 1e3;
  const ContactConventions both = contact_conventions<M>::of(M::create({m}, opt));
  CHECK(both.damp_may_pull);
  CHECK(both.coulomb_on_damped);
  CHECK(both.full_radius_arms);

  // without the effects the conventions act on, none is set
  using Bare = Mdr<double, Effects<kPlasticity>>;
  const ContactConventions bare = contact_conventions<Bare>::of(Bare::create({m}, opt));
  CHECK_FALSE(bare.damp_may_pull);
  CHECK_FALSE(bare.coulomb_on_damped);
  CHECK_FALSE(bare.full_radius_arms);
}
