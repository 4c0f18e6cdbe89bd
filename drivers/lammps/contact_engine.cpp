// make_engine: the runtime (law, effects) -> compiled model dispatch of the plugin. Only the
// effect sets a law supports are instantiated (as in drivers/driver/dispatch.hpp), so a scene
// without adhesion, plasticity, friction or damping runs a kernel without them.
#include "contact_engine.hpp"

#include <epac/models/hertz_mindlin.hpp>
#include <epac/models/jkr/jkr.hpp>
#include <epac/models/mdr/mdr_model.hpp>
#include <epac/models/nan2022/nan2022.hpp>
#include <epac/params/validation.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace epac {
namespace lammps {
namespace {

template <class Model>
void bind_model(Model&, const Particles<double>&) {}
template <class Eff>
void bind_model(Mdr<double, Eff>& m, const Particles<double>& p) {
  m.bind(p);
}

// MDR growth hooks (no-ops for the other laws and for MDR compiled without growth)
template <class Model>
struct GrowthOf {
  static constexpr bool enabled = false;
  static Kokkos::View<double*, DefaultDevice> volume(Model&) { return {}; }
  static void update(const Model&, int) {}
  static double cap(const Model&) { return 1.0; }
};
template <class Eff>
struct GrowthOf<Mdr<double, Eff>> {
  static constexpr bool enabled = Eff::radius_growth;
  static Kokkos::View<double*, DefaultDevice> volume(Mdr<double, Eff>& m) {
    if constexpr (Eff::radius_growth) return m.growth.volume;
    return {};
  }
  static void update(const Mdr<double, Eff>& m, int count) { m.update_radii(count); }
  static double cap(const Mdr<double, Eff>& m) { return Eff::radius_growth ? double(m.growth.radius_cap) : 1.0; }
};

// MDR's contact penalty (a no-op for the other laws and with the option off)
template <class Model>
void prepare_model(Model&, const Particles<double>&, const ContactList<>&, int, std::int64_t) {}
template <class Eff>
void prepare_model(Mdr<double, Eff>& m, const Particles<double>& p, const ContactList<>& pairs, int nlocal,
                   std::int64_t stamp) {
  m.compute_contact_penalty(p, pairs, nlocal, stamp);
}

// MDR Part II's bulk response (nothing for the other laws and for MDR without it)
template <class Model>
struct BulkOf {
  static constexpr bool enabled = false;
  static ContactEngine::BulkViews views(Model&) { return {}; }
  static void mean_surface_displacement(const Model&, const Particles<double>&, const ContactList<>&,
                                        const ContactHistory<double>&, const WallPass*, bool) {}
};
template <class Eff>
struct BulkOf<Mdr<double, Eff>> {
  static constexpr bool enabled = Eff::bulk_response;
  static ContactEngine::BulkViews views(Mdr<double, Eff>& m) {
    if (!m.bulk.bound()) return {};
    return {m.bulk.psi, m.bulk.vgeo, m.bulk.acon0, m.bulk.ddelta_bar};
  }
  static void mean_surface_displacement(const Mdr<double, Eff>& m, const Particles<double>& p,
                                        const ContactList<>& pairs, const ContactHistory<double>& history,
                                        const WallPass* walls, bool advance) {
    if (!(Eff::bulk_response && m.bulk.bound())) return;
    if (!advance) {  // setup passes: no mean surface displacement (fix GRANULAR/MDR)
      Kokkos::deep_copy(m.bulk.ddelta_bar, 0.0);
      return;
    }
    if (walls && walls->list.count > 0)
      m.compute_mean_surface_displacement(p, pairs, history, walls->walls, walls->list, walls->history);
    else  // no walls: empty (unallocated) views, nothing built per pass
      m.compute_mean_surface_displacement(p, pairs, history, Walls<double>(), ContactList<>(),
                                          ContactHistory<double>());
  }
};

template <class Model>
class EngineFor final : public ContactEngine {
 public:
  EngineFor(Model m, std::vector<Material> mats) : model_(std::move(m)), materials_(std::move(mats)) {}
  int history_size() const override { return Model::history_size; }
  unsigned effects() const override { return Model::effects::bits; }
  Particles<double>& particles(int n) override {
    if (n > particles_.n || particles_.n == 0) {
      particles_ = Particles<double>(n > 0 ? n + n / 4 : 1);  // headroom: ghost counts drift
      sums_ = ForceSums<double, DefaultDevice>(particles_);
      bind_model(model_, particles_);
    }
    return particles_;
  }
  void prepare_pass(const ContactList<>& pairs, int nlocal, std::int64_t list_stamp) override {
    prepare_model(model_, particles_, pairs, nlocal, list_stamp);
  }
  void compute(const ContactList<>& pairs, const ContactHistory<double>& history, double dt,
               const ContactForceBuffer<double, DefaultDevice>& buffer, const WallPass* walls) override {
    zero_forces(particles_);
    sums_.begin();
    compute_pair_forces(model_, particles_, pairs, history, dt, sums_, {}, buffer);
    if (walls && walls->list.count > 0)
      compute_wall_forces(model_, particles_, walls->walls, walls->list, walls->history, dt, sums_, {}, walls->buffer);
    sums_.end();
  }
  // JKR's separation at detachment under displacement control, -delta_c = 3/4 (pi^2 w^2 R /
  // E*^2)^(1/3) ... (Johnson 1985, (5.19)-(5.21)), taken as the bound for every adhesive law,
  // doubled: Nan's and MDR's adhesive ranges are of the same order and the cutoff only has to
  // reach them (a longer one costs list entries, not accuracy).
  double critical_separation(int a, int b, double Ri, double Rj) const override {
    const Material& A = materials_[a];
    const Material& B = materials_[b];
    const double w = std::max(A.surface_energy, B.surface_energy);
    if (!(w > 0)) return 0.0;
    const double Es = 1.0 / ((1 - A.poisson_ratio * A.poisson_ratio) / A.youngs_modulus +
                             (1 - B.poisson_ratio * B.poisson_ratio) / B.youngs_modulus);
    const double R = Ri * Rj / (Ri + Rj);
    const double pi = 3.14159265358979323846;
    return 2.0 * 0.75 * std::cbrt(pi * pi * w * w * R / (Es * Es));
  }
  bool radius_growth() const override { return GrowthOf<Model>::enabled; }
  Kokkos::View<double*, DefaultDevice> growth_volume() override { return GrowthOf<Model>::volume(model_); }
  void update_radii(int count) override { GrowthOf<Model>::update(model_, count); }
  bool bulk_response() const override { return BulkOf<Model>::enabled; }
  BulkViews bulk_views() override { return BulkOf<Model>::views(model_); }
  void mean_surface_displacement(const ContactList<>& pairs, const ContactHistory<double>& history,
                                 const WallPass* walls, bool advance) override {
    BulkOf<Model>::mean_surface_displacement(model_, particles_, pairs, history, walls, advance);
  }
  double radius_cap() const override { return GrowthOf<Model>::cap(model_); }

 private:
  Model model_;
  std::vector<Material> materials_;
  Particles<double> particles_;
  ForceSums<double, DefaultDevice> sums_;
};

// Instantiates ModelOf<Effects<Bits>> for every Bits within Supported that contains Required.
template <template <class> class ModelOf, unsigned Supported, unsigned Required = 0u, unsigned Bits = 0, class Create>
std::unique_ptr<ContactEngine> dispatch(unsigned want, const std::vector<Material>& mats, const Create& create) {
  if constexpr (Bits > kAllEffects) {
    throw std::logic_error("epac plugin: no compiled instance for effects " + std::to_string(want));
  } else if constexpr ((Bits & ~Supported) != 0u || (Bits & Required) != Required ||
                       ((Bits & kRolling) != 0u && (Bits & kFriction) == 0u)) {
    return dispatch<ModelOf, Supported, Required, Bits + 1>(want, mats, create);
  } else {
    if (want == Bits) {
      using Model = ModelOf<Effects<Bits>>;
      return std::make_unique<EngineFor<Model>>(create(static_cast<Model*>(nullptr)), mats);
    }
    return dispatch<ModelOf, Supported, Required, Bits + 1>(want, mats, create);
  }
}

template <class Eff>
using HM = HertzMindlin<double, Eff>;
template <class Eff>
using JKR = Jkr<double, Eff>;
template <class Eff>
using NAN22 = Nan2022<double, Eff>;
template <class Eff>
using MDR = Mdr<double, Eff>;

// The effects the coefficients call for (docs/design.md section 5).
unsigned effects_of(const std::vector<Material>& mats) {
  unsigned e = 0;
  for (const auto& m : mats) {
    if (m.surface_energy > 0) e |= kAdhesion;
    if (std::isfinite(m.yield_stress)) e |= kPlasticity;
    if (m.friction > 0) e |= kFriction;
    if (m.restitution < 1) e |= kDamping;
    if (m.rolling_friction > 0) e |= kRolling | kFriction;  // rolling is compiled with friction (mu 0: none)
  }
  return e;
}

}  // namespace

std::unique_ptr<ContactEngine> make_engine(Law law, const std::vector<Material>& mats, bool radius_growth,
                                           const MdrChoices& mdr) {
  if (radius_growth && law != Law::mdr)
    throw std::invalid_argument("epac plugin: radius growth is an MDR effect (fix epac/mdr needs pair_style epac/mdr)");
  if ((mdr.pair_split != 0 || mdr.delta_max != 0 || mdr.damping != 0 || mdr.friction != 0 || mdr.yield_onset != 0 ||
       mdr.surface_energy_share != 0 || mdr.adhesive_radius != 0 || mdr.release != 0 || mdr.contact_penalty) &&
      law != Law::mdr)
    throw std::invalid_argument(
        "epac plugin: pair_split, delta_max, damping, friction, yield_onset, "
        "surface_energy_share, adhesive_radius, release and contact_penalty are MDR options");
  const unsigned e = effects_of(mats);
  MdrOptions mdr_opt;
  mdr_opt.pair_split = static_cast<MdrPairSplit>(mdr.pair_split);
  mdr_opt.delta_max = static_cast<MdrDeltaMax>(mdr.delta_max);
  mdr_opt.damping = static_cast<MdrDamping>(mdr.damping);
  mdr_opt.friction = static_cast<MdrFriction>(mdr.friction);
  mdr_opt.tangential_stiffness = mdr.kt;
  mdr_opt.yield_onset = static_cast<MdrYieldOnset>(mdr.yield_onset);
  mdr_opt.surface_energy_share = static_cast<MdrSurfaceEnergyShare>(mdr.surface_energy_share);
  mdr_opt.adhesive_radius = static_cast<MdrAdhesiveRadius>(mdr.adhesive_radius);
  mdr_opt.release = static_cast<MdrRelease>(mdr.release);
  mdr_opt.contact_penalty = mdr.contact_penalty;
  mdr_opt.psi_b = mdr.psi_b;
  if (mdr.psi_b > 0.0 && law != Law::mdr) throw std::invalid_argument("epac plugin: psi_b is an MDR coefficient");
  switch (law) {
    case Law::hertz_mindlin:
      return dispatch<HM, kFriction | kDamping | kRolling>(e & (kFriction | kDamping | kRolling), mats, [&](auto* m) {
        return std::remove_pointer_t<decltype(m)>::create(mats);
      });
    case Law::jkr:
      return dispatch<JKR, kAdhesion | kFriction | kDamping | kRolling>(
          e & (kAdhesion | kFriction | kDamping | kRolling), mats,
          [&](auto* m) { return std::remove_pointer_t<decltype(m)>::create(mats); });
    case Law::nan2022:
      return dispatch<NAN22, kAdhesion | kPlasticity | kFriction | kDamping | kRolling>(
          e, mats, [&](auto* m) { return std::remove_pointer_t<decltype(m)>::create(mats); });
    case Law::mdr:
      // Radius growth (MDR (37)-(39)) only when fix epac/mdr keeps the per-atom R_o and V and
      // communicates them; without it the instances are the ones without growth, as before.
      // Growth is compiled only with plasticity: under the plastic_loading rule (mdr_radius_growth.hpp)
      // only yielded sides grow R, so without a yield stress R stays R_o and the plain instance is
      // exact (radius_growth() then reports false and the host skips the update).
      // Part II's bulk response (psi_b > 0): with growth (its psi gates (37)) and plasticity only,
      // as LAMMPS's granular mdr always has both
      if (mdr.psi_b > 0.0) {
        if (!radius_growth || !(e & kPlasticity))
          throw std::invalid_argument(
              "psi_b > 0 (Part II's bulk response) needs fix epac/mdr (radius growth) and a finite yield stress");
        return dispatch<MDR, kAdhesion | kPlasticity | kFriction | kDamping | kRadiusGrowth | kRolling | kBulkResponse,
                        kPlasticity | kRadiusGrowth | kBulkResponse>(
            e | kRadiusGrowth | kBulkResponse, mats,
            [&](auto* m) { return std::remove_pointer_t<decltype(m)>::create(mats, mdr_opt); });
      }
      if (radius_growth && (e & kPlasticity))
        return dispatch<MDR, kAdhesion | kPlasticity | kFriction | kDamping | kRadiusGrowth | kRolling,
                        kPlasticity | kRadiusGrowth>(e | kRadiusGrowth, mats, [&](auto* m) {
          return std::remove_pointer_t<decltype(m)>::create(mats, mdr_opt);
        });
      return dispatch<MDR, kAdhesion | kPlasticity | kFriction | kDamping | kRolling>(
          e, mats, [&](auto* m) { return std::remove_pointer_t<decltype(m)>::create(mats, mdr_opt); });
  }
  throw std::logic_error("epac plugin: unknown law");
}

}  // namespace lammps
}  // namespace epac
