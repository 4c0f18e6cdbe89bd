#pragma once
// The epac side of the LAMMPS plugin: a host-side interface (one virtual call per force pass,
// never inside a kernel) over one compiled contact law, chosen at `init_style` from the law and the
// effects its coefficients call for. Each implementation owns the law's model, epac's particle
// views and the per-backend force sums; the pair style only copies LAMMPS's arrays in and out.
#include <epac/compute/contact_forces.hpp>
#include <epac/params/material.hpp>
#include <epac/state/contact_history.hpp>
#include <epac/state/contact_list.hpp>
#include <epac/state/particles.hpp>
#include <epac/state/walls.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace epac {
namespace lammps {

enum class Law { hertz_mindlin, jkr, nan2022, mdr };

// The wall contacts of one force pass (fix epac/wall): one tangent plane per contact, contact k
// is (particle list.first(k), plane list.second(k) = k), its history row k, its force and torque
// stored per contact in `buffer` (the host adds them and reports them per wall).
struct WallPass {
  Walls<double> walls;
  ContactList<> list;
  ContactHistory<double> history;
  ContactForceBuffer<double, DefaultDevice> buffer;
};

class ContactEngine {
 public:
  virtual ~ContactEngine() = default;
  virtual int history_size() const = 0;
  virtual unsigned effects() const = 0;
  // Particle views sized for `n` (local + ghost) atoms; reallocated only when n grows.
  virtual Particles<double>& particles(int n) = 0;
  // One force pass over `pairs` with `history` (one row per pair): adds into particles().force
  // and .torque (zeroed here first). With `buffer` allocated, the per-contact forces are stored
  // there instead (for the virial).
  // `walls` (may be null): wall contacts evaluated in the same pass (the same growth sums).
  virtual void compute(const ContactList<>& pairs, const ContactHistory<double>& history, double dt,
                       const ContactForceBuffer<double, DefaultDevice>& buffer, const WallPass* walls = nullptr) = 0;
  // Before compute(), with particles() filled: per-pass work of the law on the pair list (MDR's
  // contact penalty weights; nothing for the other laws). Atoms past nlocal are ghosts;
  // list_stamp changes whenever the list does.
  virtual void prepare_pass(const ContactList<>& /*pairs*/, int /*nlocal*/, std::int64_t /*list_stamp*/) {}
  // --- MDR Part II, the bulk response (engines made with MdrChoices::psi_b > 0) ---
  // The per-particle state, one entry per particles() slot: psi, V_geo and A_con,0 (the host
  // writes each atom's values before the pass and reads the local ones back after update_radii),
  // and d delta-bar (computed by mean_surface_displacement; the host copies the owners' values to
  // the ghosts before compute()).
  struct BulkViews {
    Kokkos::View<double*, DefaultDevice> psi, vgeo, acon0, ddelta_bar;
  };
  virtual bool bulk_response() const { return false; }
  virtual BulkViews bulk_views() { return {}; }
  // After prepare_pass, with the pass's history and wall contacts: d delta-bar of every atom
  // (complete on local atoms); advance false (setup passes): 0, as LAMMPS's fix does.
  virtual void mean_surface_displacement(const ContactList<>& /*pairs*/, const ContactHistory<double>& /*history*/,
                                         const WallPass* /*walls*/, bool /*advance*/) {}
  // The largest separation at which the law still holds two spheres of radii Ri, Rj of
  // materials a, b together (0 without adhesion): the neighbour cutoff must reach it.
  virtual double critical_separation(int a, int b, double Ri, double Rj) const = 0;

  // --- MDR radius growth, (37)-(39) (engines made with radius_growth; fix epac/mdr) ---
  virtual bool radius_growth() const { return false; }
  // The growth state's V view of (39), one entry per particles() slot (empty without growth): the
  // host writes each atom's V here before compute() and reads it back after update_radii().
  virtual Kokkos::View<double*, DefaultDevice> growth_volume() { return {}; }
  // After compute(): applies the pass's growth sums to particles [0, count) (new radius and V)
  // and clears the sums of every particle (count 0: the pass's sums are discarded).
  virtual void update_radii(int /*count*/) {}
  // R never exceeds this multiple of R_o (1 without growth).
  virtual double radius_cap() const { return 1.0; }
};

// Throws epac::ParameterError (naming the coefficient, its value and the valid range) for
// materials the law rejects. radius_growth (MDR only, else std::invalid_argument) compiles the
// law with epac::kRadiusGrowth. MDR only (MdrChoices): pair_split, an epac::MdrPairSplit value
// (where a pair's flat sits), delta_max, an epac::MdrDeltaMax value, damping and friction
// (pair_style epac/mdr pair_split ... delta_max ... damping ... friction ...).
// MDR only: epac::MdrPairSplit, MdrDeltaMax, MdrDamping, MdrFriction, MdrYieldOnset and
// MdrSurfaceEnergyShare, MdrAdhesiveRadius and MdrRelease values, kt
// the k_t of MdrFriction::authors.
// materials may end with rigid wall materials (fix epac/wall).
struct MdrChoices {
  int pair_split = 0, delta_max = 0, damping = 0, friction = 0, yield_onset = 0, surface_energy_share = 0,
      adhesive_radius = 0, release = 0;
  double kt = 0.0;
  bool contact_penalty = false;  // MdrOptions::contact_penalty
  double psi_b = 0.0;            // MdrOptions::psi_b (> 0: Part II's bulk response; needs radius growth)
};
std::unique_ptr<ContactEngine> make_engine(Law law, const std::vector<Material>& materials, bool radius_growth = false,
                                           const MdrChoices& mdr = {});

}  // namespace lammps
}  // namespace epac
