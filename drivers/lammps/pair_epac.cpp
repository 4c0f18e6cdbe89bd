/* PairEpac: epac's contact laws inside LAMMPS (drivers/lammps/README.md).
   Per force pass: LAMMPS's atoms are copied into epac's particle views, the half neighbour list
   (rebuilt by LAMMPS) into an epac contact list with the history rows of fix NEIGH_HISTORY, epac's
   kernel runs, and forces, torques and history go back. Conventions follow the GRANULAR styles
   (pair_granular.cpp): history is not advanced in setup passes, ghost forces are added only with
   newton_pair on (reverse communication sums them), the cutoff reaches the adhesive range.
   With fix epac/mdr (epac/mdr only, newton off) the engine grows radii, MDR (37)-(39): R_o and V
   come from the fix, each non-setup pass's growth is applied to local atoms and forwarded to ghosts
   (grow_radii). */
#include "pair_epac.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_epac_mdr.h"
#include "fix_epac_wall.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <epac/core/kokkos_compat.hpp>
#include <epac/params/validation.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using epac::lammps::Law;

namespace {
const char* dummy_id = "NEIGH_HISTORY_EPAC_DUMMY";
const char* history_id = "NEIGH_HISTORY_EPAC";
}  // namespace

PairEpac::PairEpac(LAMMPS* lmp, Law law, const char* style) : Pair(lmp), law_(law), style_(style) {
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  beyond_contact = (law != Law::hertz_mindlin);  // adhesive laws act beyond contact
  nondefault_history_transfer = 1;
  // placeholder for fix NEIGH_HISTORY, replaced in init_style (keeps the input's fix order)
  modify->add_fix(std::string(dummy_id) + " all DUMMY");
  if (!Kokkos::is_initialized()) {
    // the host did not initialise Kokkos: epac does, once per process, with LAMMPS's OpenMP
    // thread count (package omp / OMP_NUM_THREADS); finalised at exit
    static std::unique_ptr<Kokkos::ScopeGuard> guard = epac::start_kokkos(comm->nthreads);
  }
}

PairEpac::~PairEpac() {
  if (copymode) return;
  if (fix_history_)
    modify->delete_fix(history_id);
  else
    modify->delete_fix(dummy_id);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
  delete[] onerad_;
  delete[] maxrad_;
}

void PairEpac::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  onerad_ = new double[n + 1];
  maxrad_ = new double[n + 1];
  materials_.assign(n, epac::Material{});
  have_material_.assign(n, 0);
  kt_.assign(n, 0.0);
  psi_b_.assign(n, 0.0);
}

// pair_style epac/<law> [pair_split equal_pair|balanced|geometric|geometric_authors] [delta_max paper_19|running_max]
// [damping restitution_exact|authors] [friction mindlin|authors] [yield_onset elastic_law|hertz_40]
// [surface_energy_share series|each_side_full] [adhesive_radius paper|authors]
// [release critical_overlap|zero_overlap] [contact_penalty off|on] (epac/mdr only): pair_split
// makes each side a side of the equivalent equal pair (equal_pair, the default: Hertz with E* and
// R*, same-material similarity, passive), each particle's own sphere where the sides' scaled forces
// balance (balanced, the default until 0.x) or the authors' radical plane (geometric; not
// passive; geometric_authors: with the authors' own unloading path), epac::MdrPairSplit; delta_max is MDR (19)
// (default) or the running maximum of the apparent overlap (the authors' code), epac::MdrDeltaMax;
// damping and friction: epac's conventions or the authors' code's (epac::MdrDamping, MdrFriction;
// friction authors = LAMMPS's `tangential linear_history kt 0 mu`, k_t from pair_coeff's kt);
// yield_onset: where the elastic regime ends (epac::MdrYieldOnset; hertz_40 = MDR (41) read
// literally, as the authors' code does); surface_energy_share: a pair's Delta gamma shared by the
// sides in series (JKR between the spheres) or in full on each side (the authors' code);
// adhesive_radius: the stored adhesive radius a_na (paper) or 0.99 a_na (the authors' code);
// release: an adhesive contact ends at its critical overlap (epac) or at zero overlap (the
// authors' code); contact_penalty: LAMMPS's MDR contact penalty (epac::MdrOptions::contact_penalty,
// off by default; LAMMPS's granular mdr always applies it; needs newton off). All set to the
// authors' choices for comparisons with granular mdr.
void PairEpac::settings(int narg, char** arg) {
  pair_split_ = 0;
  delta_max_ = 0;
  damping_ = 0;
  friction_ = 0;
  yield_onset_ = 0;
  energy_share_ = 0;
  adhesive_radius_ = 0;
  release_ = 0;
  contact_penalty_ = 0;
  struct Keyword {
    const char* name;
    int* value;
    std::vector<const char*> choices;
  };
  const Keyword keys[] = {{"pair_split", &pair_split_, {"equal_pair", "balanced", "geometric", "geometric_authors"}},
                          {"delta_max", &delta_max_, {"paper_19", "running_max"}},
                          {"damping", &damping_, {"restitution_exact", "authors"}},
                          {"friction", &friction_, {"mindlin", "authors"}},
                          {"yield_onset", &yield_onset_, {"elastic_law", "hertz_40"}},
                          {"surface_energy_share", &energy_share_, {"series", "each_side_full"}},
                          {"adhesive_radius", &adhesive_radius_, {"paper", "authors"}},
                          {"release", &release_, {"critical_overlap", "zero_overlap"}},
                          {"contact_penalty", &contact_penalty_, {"off", "on"}}};
  for (int k = 0; k < narg; k += 2) {
    const Keyword* key = nullptr;
    for (const auto& kw : keys)
      if (std::strcmp(arg[k], kw.name) == 0) key = &kw;
    if (!key || law_ != Law::mdr || k + 1 >= narg)
      error->all(FLERR, "Illegal pair_style {} command: {} (valid: {})", style_, arg[k],
                 law_ == Law::mdr
                     ? "pair_split equal_pair|balanced|geometric|geometric_authors, delta_max paper_19|running_max, "
                       "damping restitution_exact|authors, friction mindlin|authors, "
                       "yield_onset elastic_law|hertz_40, surface_energy_share series|each_side_full, "
                       "adhesive_radius paper|authors, release critical_overlap|zero_overlap, "
                       "contact_penalty off|on"
                     : "no arguments");
    int found = -1;
    for (std::size_t q = 0; q < key->choices.size(); q++)
      if (std::strcmp(arg[k + 1], key->choices[q]) == 0) found = static_cast<int>(q);
    if (found < 0) {
      std::string valid;
      for (const char* c : key->choices) valid += (valid.empty() ? "" : ", ") + std::string(c);
      error->all(FLERR, "pair_style {}: {} {} is not valid (valid: {})", style_, key->name, arg[k + 1], valid);
    }
    *key->value = found;
  }
}

// Coefficients, per law (the order of LAMMPS's granular mdr where one exists):
//   epac/hertz_mindlin: E nu e mu
//   epac/jkr:           E nu e mu gamma
//   epac/nan2022:       E nu e mu gamma Y
//   epac/mdr:           E nu Y gamma psi_b e [mu MU] [kt KT]
// E [Pa], nu, e the normal restitution coefficient (1: no damping), mu the sliding friction
// coefficient (0: no friction), gamma the surface energy [J/m^2] (0: no adhesion), Y the yield
// stress [Pa] (inf: none), psi_b Part II's bulk-response threshold (0: none; > 0 needs fix
// epac/mdr and one value for every type),
// kt the constant tangential stiffness [N/m] of pair_style epac/mdr friction authors.
// Every law also takes `rolling sds K_R GAMMA_R MU_R` after its coefficients: LAMMPS's rolling
// resistance (models/rolling_resistance.hpp), k_r [N/m], gamma_r [N s/m], mu_r.
int PairEpac::coefficient_count() const {
  switch (law_) {
    case Law::hertz_mindlin:
      return 4;
    case Law::jkr:
      return 5;
    case Law::nan2022:
      return 6;
    case Law::mdr:
      return 6;
  }
  return 0;
}

epac::Material PairEpac::material_from(char** arg, int type) const {
  epac::Material m;
  m.name = "type " + std::to_string(type);
  m.density = 1.0;  // unused: masses come from the atoms' rmass
  auto num = [&](int k) { return utils::numeric(FLERR, arg[k], false, lmp); };
  m.youngs_modulus = num(0);
  m.poisson_ratio = num(1);
  switch (law_) {
    case Law::hertz_mindlin:
      m.restitution = num(2);
      m.friction = num(3);
      break;
    case Law::jkr:
      m.restitution = num(2);
      m.friction = num(3);
      m.surface_energy = num(4);
      break;
    case Law::nan2022:
      m.restitution = num(2);
      m.friction = num(3);
      m.surface_energy = num(4);
      m.yield_stress = num(5);
      break;
    case Law::mdr: {
      m.yield_stress = num(2);
      m.surface_energy = num(3);
      m.restitution = num(5);
      break;
    }
  }
  return m;
}

void PairEpac::coeff(int narg, char** arg) {
  if (!allocated) allocate();
  const int nc = coefficient_count();
  const char* optional = law_ == Law::mdr ? " and optionally mu MU, kt KT, rolling sds K_R GAMMA_R MU_R"
                                          : " and optionally rolling sds K_R GAMMA_R MU_R";
  if (narg < 2 + nc)
    error->all(FLERR, "Incorrect args for pair_coeff {}: expected {} coefficients{}", style_, nc, optional);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  // epac mixes two materials itself (its pair tables); a pair_coeff sets one type's material
  if (!(ilo == jlo && ihi == jhi))
    error->all(FLERR,
               "pair_coeff {} sets a material per atom type: use 'I I' or '* *' (epac mixes unlike "
               "types from their materials)",
               style_);
  epac::Material m = material_from(arg + 2, ilo);
  double kt = 0.0;
  for (int k = 2 + nc; k < narg;) {
    if (std::strcmp(arg[k], "rolling") == 0) {
      // LAMMPS's `rolling sds k_r gamma_r mu_r` (models/rolling_resistance.hpp)
      if (k + 4 >= narg || std::strcmp(arg[k + 1], "sds") != 0)
        error->all(FLERR, "pair_coeff {}: rolling expects 'sds K_R GAMMA_R MU_R' (the only rolling model)", style_);
      m.rolling_stiffness = utils::numeric(FLERR, arg[k + 2], false, lmp);
      m.rolling_damping = utils::numeric(FLERR, arg[k + 3], false, lmp);
      m.rolling_friction = utils::numeric(FLERR, arg[k + 4], false, lmp);
      k += 5;
    } else if (law_ == Law::mdr && k + 1 < narg && std::strcmp(arg[k], "mu") == 0) {
      m.friction = utils::numeric(FLERR, arg[k + 1], false, lmp);
      k += 2;
    } else if (law_ == Law::mdr && k + 1 < narg && std::strcmp(arg[k], "kt") == 0) {
      kt = utils::numeric(FLERR, arg[k + 1], false, lmp);
      if (!(kt > 0.0) || !std::isfinite(kt))
        error->all(FLERR, "pair_coeff {}: kt = {} is not valid (valid: 0 < kt < inf, N/m)", style_, kt);
      k += 2;
    } else
      error->all(FLERR, "pair_coeff {}: unknown keyword or missing value {} (valid: {})", style_, arg[k],
                 law_ == Law::mdr ? "mu MU, kt KT, rolling sds K_R GAMMA_R MU_R" : "rolling sds K_R GAMMA_R MU_R");
  }
  try {
    m.validate();
  } catch (std::exception& e) { error->all(FLERR, "pair_coeff {}: {}", style_, e.what()); }
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    materials_[i - 1] = m;
    materials_[i - 1].name = "type " + std::to_string(i);
    have_material_[i - 1] = 1;
    kt_[i - 1] = kt;
    if (law_ == Law::mdr) psi_b_[i - 1] = utils::numeric(FLERR, arg[2 + 4], false, lmp);
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

void PairEpac::init_style() {
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "Pair {} requires atom attributes radius, rmass, omega, torque (atom_style sphere)", style_);
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair {} requires ghost atoms store velocity (comm_modify vel yes)", style_);
  for (int t = 0; t < atom->ntypes; t++)
    if (!have_material_[t])
      error->all(FLERR, "Pair {}: no pair_coeff {} {} (every type needs a material)", style_, t + 1, t + 1);

  // fix epac/mdr asks for MDR radius growth (37)-(39); without it epac/mdr runs without growth
  growth_fix_ = nullptr;
  for (auto* f : modify->get_fix_by_style("^epac/mdr$")) growth_fix_ = dynamic_cast<FixEpacMdr*>(f);
  if (growth_fix_ && law_ != Law::mdr)
    error->all(FLERR, "fix epac/mdr (radius growth) needs pair_style epac/mdr, not {}", style_);
  // fix epac/wall: per fix, one rigid copy of each type's material for the wall side (it takes the
  // particle's friction, restitution and surface energy unless the fix sets its own;
  // epac::pair_properties)
  wall_fixes_.clear();
  for (auto* f : modify->get_fix_by_style("^epac/wall$")) wall_fixes_.push_back(dynamic_cast<FixEpacWall*>(f));
  std::vector<epac::Material> mats = materials_;
  for (auto* wf : wall_fixes_)
    for (int t = 0; t < atom->ntypes; t++) mats.push_back(wf->wall_material(materials_[t], t + 1));
  epac::lammps::MdrChoices choices;
  choices.pair_split = pair_split_;
  choices.delta_max = delta_max_;
  choices.damping = damping_;
  choices.friction = friction_;
  choices.yield_onset = yield_onset_;
  choices.surface_energy_share = energy_share_;
  choices.adhesive_radius = adhesive_radius_;
  choices.release = release_;
  choices.contact_penalty = contact_penalty_ != 0;
  if (law_ == Law::mdr) {  // Part II's psi_b: epac's MdrOptions holds one value
    choices.psi_b = psi_b_[0];
    for (int t = 0; t < atom->ntypes; t++)
      if (psi_b_[t] != psi_b_[0] || !(psi_b_[t] >= 0.0 && psi_b_[t] <= 1.0))
        error->all(FLERR, "pair {}: psi_b must be one value in [0, 1] for every type (type {}: {}, type 1: {})", style_,
                   t + 1, psi_b_[t], psi_b_[0]);
    if (choices.psi_b > 0.0 && !growth_fix_)
      error->all(FLERR,
                 "pair {}: psi_b = {} (Part II's bulk response) needs fix epac/mdr (its psi gates radius growth, "
                 "as in LAMMPS's granular mdr)",
                 style_, choices.psi_b);
  }
  // the penalty walks each local atom's pairs: with newton on a pair with a ghost is listed by one
  // process only, so a local atom's list can miss an overlapping partner
  if (contact_penalty_ && force->newton_pair)
    error->all(FLERR,
               "Pair {} contact_penalty on requires newton off (newton_pair is on): each atom's "
               "overlapping partners must all be in its process's neighbour list, as for LAMMPS's granular mdr",
               style_);
  if (friction_ == 1) {  // MdrFriction::authors: one k_t for every pair
    choices.kt = kt_[0];
    for (int t = 0; t < atom->ntypes; t++)
      if (kt_[t] != kt_[0] || !(kt_[t] > 0.0))
        error->all(FLERR,
                   "pair {} friction authors: every type needs the same pair_coeff kt > 0 (type {}: {}, "
                   "type 1: {})",
                   style_, t + 1, kt_[t], kt_[0]);
  }
  try {
    engine_ = epac::lammps::make_engine(law_, mats, growth_fix_ != nullptr, choices);
  } catch (std::exception& e) { error->all(FLERR, "pair {}: {}", style_, e.what()); }
  growth_ = engine_->radius_growth();
  bulk_ = engine_->bulk_response();
  if (fix_history_ && engine_->history_size() != history_size_)
    error->all(FLERR,
               "pair {}: the coefficients or fix epac/mdr changed the history size ({} -> {}) after the "
               "first run; start a new pair_style",
               style_, history_size_, engine_->history_size());
  history_size_ = engine_->history_size();
  if (!wall_fixes_.empty() && history_size_ > FixEpacWall::kMaxHistory)
    error->all(FLERR, "pair {}: {} history fields per contact, fix epac/wall holds {}", style_, history_size_,
               FixEpacWall::kMaxHistory);

  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);
  if (fix_history_ == nullptr) {
    const int dnum = history_size_ > 0 ? history_size_ : 1;  // fix NEIGH_HISTORY needs >= 1 value
    fix_history_ = dynamic_cast<FixNeighHistory*>(
        modify->replace_fix(dummy_id, std::string(history_id) + " all NEIGH_HISTORY " + std::to_string(dnum), 1));
    fix_history_->pair = this;
  }

  // largest radius per type (cutoffs), as pair granular does
  double* radius = atom->radius;
  int* type = atom->type;
  for (int t = 1; t <= atom->ntypes; t++) onerad_[t] = 0.0;
  for (int i = 0; i < atom->nlocal; i++) onerad_[type[i]] = MAX(onerad_[type[i]], radius[i]);
  MPI_Allreduce(&onerad_[1], &maxrad_[1], atom->ntypes, MPI_DOUBLE, MPI_MAX, world);
  last_list_ = nullptr;
  // a wall's adhesive reach: the pair bound for two spheres of the type's largest radius (R* = R/2
  // and E* = E_eff/2 give a JKR range at least the wall's, R* <= 2 R (fix epac/wall refuses closer
  // concave radii), E* = E_eff: a bound)
  wall_range_.assign(atom->ntypes + 1, 0.0);
  for (int t = 1; t <= atom->ntypes; t++)
    for (std::size_t f = 0; f < wall_fixes_.size(); f++) {
      const int w = atom->ntypes * (1 + static_cast<int>(f)) + t - 1;  // the wall's own surface energy
      wall_range_[t] = MAX(wall_range_[t], engine_->critical_separation(w, w, maxrad_[t], maxrad_[t]) *
                                               (growth_ ? engine_->radius_cap() : 1.0));
    }

  // Growth: the size neighbour lists test radius_i + radius_j + skin with the radii of each
  // rebuild, and init_one scales the cutoff (ghost shell, bins) by the radius cap, so grown
  // partners are found at rebuilds. Between rebuilds LAMMPS's trigger sees displacements only:
  // growth since the last rebuild must fit in the skin too, hence the warning.
  if (growth_) {
    double rmax = 0.0;
    for (int t = 1; t <= atom->ntypes; t++) rmax = MAX(rmax, maxrad_[t]);
    const double cap = engine_->radius_cap();
    if (comm->me == 0 && neighbor->skin < (cap - 1.0) * rmax)
      error->warning(FLERR,
                     "pair {} with fix epac/mdr: neighbor skin {} is below (radius_cap - 1) * max radius "
                     "= {} (radius_cap {}): radius growth between neighbour-list rebuilds is not part of "
                     "LAMMPS's rebuild trigger, so contacts can be missed if radii grow by more than the skin "
                     "left over by the displacements; use a larger skin or neigh_modify every 1 delay 0 "
                     "with a margin",
                     style_, neighbor->skin, (cap - 1.0) * rmax, cap);
  }
}

double PairEpac::init_one(int i, int j) {
  double cut = maxrad_[i] + maxrad_[j];
  if (cut <= 0.0) {  // no atoms of these types yet: the largest cutoff of the others
    for (int k = 1; k <= atom->ntypes; k++) cut = MAX(cut, 2.0 * maxrad_[k]);
  }
  // radius growth: radii reach radius_cap times their present value at most (R <= cap R_o, and
  // R >= R_o), so ghosts and bins reach every grown partner
  if (engine_ && growth_) cut *= engine_->radius_cap();
  if (engine_) cut += engine_->critical_separation(i - 1, j - 1, maxrad_[i], maxrad_[j]);
  return cut;
}

void PairEpac::gather_atoms(int nall) {
  auto& p = engine_->particles(nall);
  auto x = Kokkos::create_mirror_view(p.x);
  auto v = Kokkos::create_mirror_view(p.v);
  auto w = Kokkos::create_mirror_view(p.omega);
  auto R = Kokkos::create_mirror_view(p.radius);
  auto R0 = Kokkos::create_mirror_view(p.radius0);
  auto m = Kokkos::create_mirror_view(p.mass);
  auto I = Kokkos::create_mirror_view(p.inertia);
  auto mat = Kokkos::create_mirror_view(p.material);
  auto gid = Kokkos::create_mirror_view(p.gid);
  double **ax = atom->x, **av = atom->v, **aw = atom->omega;
  double *radius = atom->radius, *rmass = atom->rmass;
  // with growth, R_o is the fix's (the moment of inertia too: epac's convention (2/5) m R_o^2);
  // without, R_o = R as before
  double* ro = radius;
  if (growth_) {
    growth_fix_->initialize_new_atoms();
    ro = growth_fix_->initial_radius();
  }
  int* type = atom->type;
  tagint* tag = atom->tag;
  Kokkos::parallel_for("epac::lammps::gather", Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, nall),
                       [&](int i) {
                         for (int d = 0; d < 3; d++) {
                           x(i, d) = ax[i][d];
                           v(i, d) = av[i][d];
                           w(i, d) = aw[i][d];
                         }
                         R(i) = radius[i];
                         R0(i) = ro[i];
                         m(i) = rmass[i];
                         I(i) = 0.4 * rmass[i] * ro[i] * ro[i];
                         mat(i) = type[i] - 1;
                         gid(i) = static_cast<std::int64_t>(tag[i]);
                       });
  Kokkos::deep_copy(p.x, x);
  Kokkos::deep_copy(p.v, v);
  Kokkos::deep_copy(p.omega, w);
  Kokkos::deep_copy(p.radius, R);
  Kokkos::deep_copy(p.radius0, R0);
  Kokkos::deep_copy(p.mass, m);
  Kokkos::deep_copy(p.inertia, I);
  Kokkos::deep_copy(p.material, mat);
  Kokkos::deep_copy(p.gid, gid);
  if (growth_) {  // V of MDR (39), kept by the fix between passes
    auto Vd = engine_->growth_volume();
    auto V = Kokkos::create_mirror_view(Vd);
    const double* av_ = growth_fix_->volume();
    for (int i = 0; i < nall; i++) V(i) = av_[i];
    Kokkos::deep_copy(Vd, V);
  }
  if (bulk_) {  // Part II's psi, V_geo and A_con,0, kept by the fix between passes
    const auto b = engine_->bulk_views();
    auto psi = Kokkos::create_mirror_view(b.psi);
    auto vgeo = Kokkos::create_mirror_view(b.vgeo);
    auto acon0 = Kokkos::create_mirror_view(b.acon0);
    const double *fp = growth_fix_->psi(), *fv = growth_fix_->vgeo(), *fa = growth_fix_->acon0();
    for (int i = 0; i < nall; i++) {
      psi(i) = fp[i];
      vgeo(i) = fv[i];
      acon0(i) = fa[i];
    }
    Kokkos::deep_copy(b.psi, psi);
    Kokkos::deep_copy(b.vgeo, vgeo);
    Kokkos::deep_copy(b.acon0, acon0);
  }
}

// Part II's mean surface displacement: computed for every atom, complete on local atoms (newton
// off: every pair of a local atom is in this process's list), then the owners' values copied to
// the ghosts (forward_comm), as fix GRANULAR/MDR does.
void PairEpac::mean_surface_displacement(const epac::ContactHistory<double>& h, const epac::lammps::WallPass* wp,
                                         bool advance) {
  engine_->mean_surface_displacement(contacts_, h, wp, advance);
  const auto dd = engine_->bulk_views().ddelta_bar;
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), dd);
  double* f = growth_fix_->ddelta_bar();
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  for (int i = 0; i < nlocal; i++) f[i] = host(i);
  growth_fix_->forward_stage(FixEpacMdr::Stage::mean_surface_displacement);
  comm->forward_comm(growth_fix_);
  for (int i = nlocal; i < nall; i++) host(i) = f[i];
  Kokkos::deep_copy(dd, host);
}

// MDR radius growth after a force pass: (37)-(39) applied to local atoms only (their sums are
// complete with newton off; the ghosts' partial sums are cleared), then R and V of the local atoms
// go back to LAMMPS and on to the ghosts. Setup passes discard their sums (no growth), as the
// authors' fix_granular_mdr.cpp does.
void PairEpac::grow_radii(int nlocal, bool advance) {
  engine_->update_radii(advance ? nlocal : 0);
  if (!advance) return;
  auto& p = engine_->particles(0);
  auto R = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.radius);
  auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), engine_->growth_volume());
  double *radius = atom->radius, *av = growth_fix_->volume();
  for (int i = 0; i < nlocal; i++) {
    radius[i] = R(i);
    av[i] = V(i);
  }
  if (bulk_) {  // Part II's psi, V_geo, A_con,0 of the local atoms (update_radii computed them)
    const auto b = engine_->bulk_views();
    auto psi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b.psi);
    auto vgeo = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b.vgeo);
    auto acon0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b.acon0);
    double *fp = growth_fix_->psi(), *fv = growth_fix_->vgeo(), *fa = growth_fix_->acon0();
    for (int i = 0; i < nlocal; i++) {
      fp[i] = psi(i);
      fv[i] = vgeo(i);
      fa[i] = acon0(i);
    }
  }
  growth_fix_->forward_stage(bulk_ ? FixEpacMdr::Stage::growth_and_bulk : FixEpacMdr::Stage::growth);
  comm->forward_comm(growth_fix_);
}

// The half list as an epac contact list, with the history slots of fix NEIGH_HISTORY; rebuilt
// when LAMMPS rebuilt its list. Every listed pair is a contact (epac returns zero force and
// clears the history of pairs apart beyond the law's range).
void PairEpac::build_contacts() {
  first_.clear();
  second_.clear();
  hist_.clear();
  touch_.clear();
  const int inum = list->inum;
  int *ilist = list->ilist, *numneigh = list->numneigh, **firstneigh = list->firstneigh;
  int** firsttouch = fix_history_->firstflag;
  double** firstvalue = fix_history_->firstvalue;
  const int dnum = fix_history_->get_dnum();
  double* special_lj = force->special_lj;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int* jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      int j = jlist[jj];
      if (special_lj[sbmask(j)] == 0.0) continue;
      j &= NEIGHMASK;
      first_.push_back(i);
      second_.push_back(j);
      hist_.push_back(&firstvalue[i][dnum * jj]);
      touch_.push_back(&firsttouch[i][jj]);
    }
  }
  const int n = static_cast<int>(first_.size());
  contacts_ = epac::ContactList<>(n);
  auto f = Kokkos::create_mirror_view(contacts_.first);
  auto s = Kokkos::create_mirror_view(contacts_.second);
  for (int k = 0; k < n; k++) {
    f(k) = first_[k];
    s(k) = second_[k];
  }
  Kokkos::deep_copy(contacts_.first, f);
  Kokkos::deep_copy(contacts_.second, s);
  history_ = epac::ContactHistory<double>(n, history_size_, "lammps.history");
  if (history_size_ > 0) {
    auto h = Kokkos::create_mirror_view(history_.data);
    for (int k = 0; k < n; k++)
      for (int q = 0; q < history_size_; q++) h(k, q) = (*touch_[k]) ? hist_[k][q] : 0.0;
    Kokkos::deep_copy(history_.data, h);
  }
}

// The wall contacts of this pass (fix epac/wall): one tangent plane per contact, material: the
// fix's rigid copy of the atom type's (ntypes (1 + f) + type - 1), history rows from the fixes'
// per-atom slots.
void PairEpac::collect_walls() {
  epac::lammps::WallPass& pass = walls_;
  wall_contacts_.clear();
  wall_owner_.clear();
  for (std::size_t f = 0; f < wall_fixes_.size(); f++) {
    wall_fixes_[f]->find_contacts(wall_range_.data(), wall_contacts_);
    wall_owner_.resize(wall_contacts_.size(), static_cast<int>(f));
  }
  const int n = static_cast<int>(wall_contacts_.size());
  // the views outlive the pass (no allocation per step): grown with headroom when the contacts
  // outnumber them, the kernels read the first n rows (list.count)
  if (n > pass.list.capacity() || pass.history.fields != history_size_) {
    const int cap = n + n / 4 + 16;
    pass.walls = epac::Walls<double>(cap, "lammps.walls");
    pass.list = epac::ContactList<>(cap);
    pass.history = epac::ContactHistory<double>(cap, history_size_, "lammps.wall_history");
    pass.buffer = epac::ContactForceBuffer<double, epac::DefaultDevice>(cap);
  }
  pass.list.count = n;
  if (n == 0) return;
  auto pt = Kokkos::create_mirror_view(pass.walls.point);
  auto nv = Kokkos::create_mirror_view(pass.walls.normal);
  auto vel = Kokkos::create_mirror_view(pass.walls.velocity);
  auto mat = Kokkos::create_mirror_view(pass.walls.material);
  auto curv = Kokkos::create_mirror_view(pass.walls.curvature);
  auto first = Kokkos::create_mirror_view(pass.list.first);
  auto second = Kokkos::create_mirror_view(pass.list.second);
  auto h = Kokkos::create_mirror_view(pass.history.data);
  int* type = atom->type;
  for (int k = 0; k < n; k++) {
    const auto& c = wall_contacts_[k];
    for (int d = 0; d < 3; d++) {
      pt(k, d) = c.point[d];
      nv(k, d) = c.normal[d];
      vel(k, d) = c.velocity[d];
    }
    mat(k) = atom->ntypes * (1 + wall_owner_[k]) + type[c.atom] - 1;
    curv(k) = c.curvature;
    first(k) = c.atom;
    second(k) = k;
    for (int q = 0; q < history_size_; q++) h(k, q) = c.history[q];
  }
  Kokkos::deep_copy(pass.walls.point, pt);
  Kokkos::deep_copy(pass.walls.normal, nv);
  Kokkos::deep_copy(pass.walls.velocity, vel);
  Kokkos::deep_copy(pass.walls.material, mat);
  Kokkos::deep_copy(pass.walls.curvature, curv);
  Kokkos::deep_copy(pass.list.first, first);
  Kokkos::deep_copy(pass.list.second, second);
  if (history_size_ > 0) Kokkos::deep_copy(pass.history.data, h);
}

// Wall forces and torques onto the atoms, into the fixes' per-atom output, and (non-setup
// passes) the advanced history back into the fixes' slots.
void PairEpac::apply_walls(bool advance) {
  const epac::lammps::WallPass& pass = walls_;
  for (auto* f : wall_fixes_) f->clear_contact_output();
  const int n = static_cast<int>(wall_contacts_.size());
  if (n == 0) return;
  auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pass.buffer.force);
  auto T = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pass.buffer.torque_i);
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pass.history.data);
  double **f = atom->f, **t = atom->torque, *radius = atom->radius;
  for (int k = 0; k < n; k++) {
    const auto& c = wall_contacts_[k];
    const double fk[3] = {F(k, 0), F(k, 1), F(k, 2)};
    for (int d = 0; d < 3; d++) {
      f[c.atom][d] += fk[d];
      t[c.atom][d] += T(k, d);
    }
    wall_fixes_[wall_owner_[k]]->record_contact(c, fk, radius[c.atom]);
    if (advance)
      for (int q = 0; q < history_size_; q++) c.history[q] = h(k, q);
  }
}

void PairEpac::add_forces(int nlocal, bool with_ghosts) {
  auto& p = engine_->particles(0);
  auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.force);
  auto T = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.torque);
  double **f = atom->f, **t = atom->torque;
  const int n = with_ghosts ? nlocal + atom->nghost : nlocal;
  Kokkos::parallel_for("epac::lammps::scatter", Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, n),
                       [&](int i) {
                         for (int d = 0; d < 3; d++) {
                           f[i][d] += F(i, d);
                           t[i][d] += T(i, d);
                         }
                       });
}

void PairEpac::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const bool newton = force->newton_pair != 0;
  gather_atoms(nall);
  if (list != last_list_ || neighbor->lastcall != last_build_) {
    build_contacts();
    ++list_stamp_;
    last_list_ = list;
    last_build_ = neighbor->lastcall;
  }
  const int n = contacts_.count;
  // Setup passes (run's first force evaluation) do not advance the history (pair_granular.cpp):
  // evaluate on a copy.
  const bool advance = update->setupflag == 0;
  epac::ContactHistory<double> h = history_;
  if (!advance && history_size_ > 0) {
    h = epac::ContactHistory<double>(n, history_size_, "lammps.history.setup");
    Kokkos::deep_copy(h.data, history_.data);
  }
  // dt = 0 in setup passes: the tangential spring is not stretched again, so the force equals the
  // one of the step that wrote the history (LAMMPS's history_update = 0); a run continued from a
  // restart or a new `run` then retraces an uninterrupted one.
  const double dt = advance ? update->dt : 0.0;
  const bool have_walls = !wall_fixes_.empty();
  if (have_walls) collect_walls();
  const epac::lammps::WallPass* wp = have_walls ? &walls_ : nullptr;
  engine_->prepare_pass(contacts_, nlocal, list_stamp_);
  if (bulk_) mean_surface_displacement(h, wp, advance);
  if (vflag_either) {
    epac::ContactForceBuffer<double, epac::DefaultDevice> buf(n);
    engine_->compute(contacts_, h, dt, buf, wp);
    auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), buf.force);
    auto Ti = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), buf.torque_i);
    auto Tj = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), buf.torque_j);
    double **f = atom->f, **t = atom->torque, **x = atom->x;
    for (int k = 0; k < n; k++) {
      const int i = first_[k], j = second_[k];
      for (int d = 0; d < 3; d++) {
        f[i][d] += F(k, d);
        t[i][d] += Ti(k, d);
      }
      if (j < nlocal || newton)
        for (int d = 0; d < 3; d++) {
          f[j][d] -= F(k, d);
          t[j][d] += Tj(k, d);
        }
      ev_tally_xyz(i, j, nlocal, force->newton_pair, 0.0, 0.0, F(k, 0), F(k, 1), F(k, 2), x[i][0] - x[j][0],
                   x[i][1] - x[j][1], x[i][2] - x[j][2]);
    }
  } else {
    engine_->compute(contacts_, h, dt, {}, wp);
    add_forces(nlocal, newton);
  }
  if (have_walls) apply_walls(advance);
  if (growth_) grow_radii(nlocal, advance);
  if (advance && history_size_ > 0) {
    auto hv = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), history_.data);
    Kokkos::parallel_for("epac::lammps::history_out", Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, n),
                         [&](int k) {
                           bool any = false;
                           for (int q = 0; q < history_size_; q++) {
                             hist_[k][q] = hv(k, q);
                             any = any || hv(k, q) != 0.0;
                           }
                           // fix NEIGH_HISTORY carries only flagged rows across rebuilds
                           *touch_[k] = any ? 1 : 0;
                         });
  }
}

void PairEpac::transfer_history(double* source, double* target, int, int) {
  for (int q = 0; q < history_size_; q++) target[q] = source[q];
}

void PairEpac::write_restart(FILE* fp) {
  for (int i = 1; i <= atom->ntypes; i++) {
    const epac::Material& m = materials_[i - 1];
    // 12 values per type (11 before psi_b, 8 before rolling resistance: restart files of earlier
    // versions do not read)
    const double v[12] = {m.youngs_modulus,
                          m.poisson_ratio,
                          m.restitution,
                          m.friction,
                          m.surface_energy,
                          m.yield_stress,
                          static_cast<double>(have_material_[i - 1]),
                          kt_[i - 1],
                          m.rolling_stiffness,
                          m.rolling_damping,
                          m.rolling_friction,
                          psi_b_[i - 1]};
    fwrite(v, sizeof(double), 12, fp);
  }
}

void PairEpac::read_restart(FILE* fp) {
  allocate();
  for (int i = 1; i <= atom->ntypes; i++) {
    double v[12];
    if (comm->me == 0) utils::sfread(FLERR, v, sizeof(double), 12, fp, nullptr, error);
    MPI_Bcast(v, 12, MPI_DOUBLE, 0, world);
    epac::Material& m = materials_[i - 1];
    m.name = "type " + std::to_string(i);
    m.density = 1.0;
    m.youngs_modulus = v[0];
    m.poisson_ratio = v[1];
    m.restitution = v[2];
    m.friction = v[3];
    m.surface_energy = v[4];
    m.yield_stress = v[5];
    have_material_[i - 1] = v[6] != 0.0;
    kt_[i - 1] = v[7];
    m.rolling_stiffness = v[8];
    m.rolling_damping = v[9];
    m.rolling_friction = v[10];
    psi_b_[i - 1] = v[11];
    for (int j = i; j <= atom->ntypes; j++) setflag[i][j] = have_material_[i - 1] && have_material_[j - 1];
  }
}

void PairEpac::write_restart_settings(FILE* fp) {
  const int v[9] = {pair_split_,   delta_max_,       damping_, friction_,       yield_onset_,
                    energy_share_, adhesive_radius_, release_, contact_penalty_};
  fwrite(v, sizeof(int), 9, fp);
}

void PairEpac::read_restart_settings(FILE* fp) {
  int v[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (comm->me == 0) utils::sfread(FLERR, v, sizeof(int), 9, fp, nullptr, error);
  MPI_Bcast(v, 9, MPI_INT, 0, world);
  pair_split_ = v[0];
  delta_max_ = v[1];
  damping_ = v[2];
  friction_ = v[3];
  yield_onset_ = v[4];
  energy_share_ = v[5];
  adhesive_radius_ = v[6];
  release_ = v[7];
  contact_penalty_ = v[8];
}

double PairEpac::memory_usage() {
  return static_cast<double>(first_.size()) * (2 * sizeof(int) + sizeof(double*) + sizeof(int*)) +
         static_cast<double>(history_.bytes());
}
