/* FixEpacWall: a region's surface as a rigid wall for epac's pair styles (fix_epac_wall.h).
   The bookkeeping of the per-atom contact history follows fix_wall_gran_region.cpp (contacts
   matched by the region's surface id, zeroed when new, dropped when left). */
#include "fix_epac_wall.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "region.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

FixEpacWall::FixEpacWall(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  if (narg < 5 || std::strcmp(arg[3], "region") != 0)
    error->all(FLERR,
               "Illegal fix {} command: use fix ID group epac/wall region REGION-ID [mu MU] [gamma G] "
               "[e E] [contacts]",
               style);
  if (!atom->radius_flag || !atom->omega_flag)
    error->all(FLERR, "Fix epac/wall requires atom attributes radius and omega (atom_style sphere)");
  idregion_ = utils::strdup(arg[4]);
  region_ = domain->get_region_by_id(idregion_);
  if (!region_) error->all(FLERR, "Fix epac/wall: region {} does not exist", idregion_);
  tmax_ = region_->tmax;
  for (int k = 5; k < narg; k++) {
    if (std::strcmp(arg[k], "contacts") == 0) {
      output_ = true;
      continue;
    }
    double* value = std::strcmp(arg[k], "mu") == 0      ? &mu_
                    : std::strcmp(arg[k], "gamma") == 0 ? &gamma_
                    : std::strcmp(arg[k], "e") == 0     ? &e_
                                                        : nullptr;
    if (!value || k + 1 >= narg)
      error->all(FLERR, "Illegal fix {} command: {} (valid: mu MU, gamma G, e E, contacts)", style, arg[k]);
    *value = utils::numeric(FLERR, arg[++k], false, lmp);
  }
  // validated here, before any run: the ranges of epac::Material (NaN: not given)
  if (!std::isnan(mu_) && !(mu_ >= 0.0 && std::isfinite(mu_)))
    error->all(FLERR, "Fix epac/wall: mu = {} is not valid (valid: 0 <= mu < inf)", mu_);
  if (!std::isnan(gamma_) && !(gamma_ >= 0.0 && std::isfinite(gamma_)))
    error->all(FLERR, "Fix epac/wall: gamma = {} is not valid (valid: 0 <= gamma < inf, J/m^2)", gamma_);
  if (!std::isnan(e_) && !(e_ >= 0.0 && e_ <= 1.0))
    error->all(FLERR, "Fix epac/wall: e = {} is not valid (valid: 0 <= e <= 1)", e_);
  restart_peratom = 1;
  create_attribute = 1;
  if (output_) {
    peratom_flag = 1;
    size_peratom_cols = 8;
    peratom_freq = 1;
  }
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  slot_.resize(tmax_);
}

FixEpacWall::~FixEpacWall() {
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  delete[] idregion_;
  memory->destroy(ncontact_);
  memory->destroy(walls_);
  memory->destroy(history_);
  memory->destroy(array_atom);
}

epac::Material FixEpacWall::wall_material(const epac::Material& particle, int type) const {
  epac::Material w = particle;
  w.rigid = true;
  w.name = std::string("fix ") + id + " wall, type " + std::to_string(type);
  w.own_surface_properties =
      !std::isnan(mu_) || !std::isnan(gamma_) || !std::isnan(e_);  // the unset ones stay the particle's
  if (!std::isnan(mu_)) w.friction = mu_;
  if (!std::isnan(gamma_)) w.surface_energy = gamma_;
  if (!std::isnan(e_)) w.restitution = e_;
  return w;
}

// No per-step hook: pair styles epac/* evaluate the wall contacts in their force pass.
int FixEpacWall::setmask() { return 0; }

void FixEpacWall::init() {
  region_ = domain->get_region_by_id(idregion_);
  if (!region_) error->all(FLERR, "Fix epac/wall: region {} does not exist", idregion_);
  if (region_->tmax != tmax_)
    error->all(FLERR, "Fix epac/wall: region {} changed its number of surfaces between runs", idregion_);
  if (!force->pair || !utils::strmatch(force->pair_style, "^epac/"))
    error->all(FLERR, "Fix epac/wall requires a pair_style epac/* (found {})",
               force->pair_style ? force->pair_style : "none");
}

// fix_wall_gran_region.cpp's update_contacts: slot_[ic] = history slot of region contact ic.
void FixEpacWall::update_slots(int i, int nc) {
  int iold = 0;
  while (iold < ncontact_[i]) {  // drop contacts no longer touched (copy the last over them)
    int m = 0;
    while (m < nc && region_->contact[m].iwall != walls_[i][iold]) m++;
    if (m >= nc) {
      const int last = ncontact_[i] - 1;
      for (int q = 0; q < kMaxHistory; q++) history_[i][iold][q] = history_[i][last][q];
      walls_[i][iold] = walls_[i][last];
      ncontact_[i]--;
    } else {
      iold++;
    }
  }
  const int nold = ncontact_[i];
  for (int ic = 0; ic < nc; ic++) {
    const int iwall = region_->contact[ic].iwall;
    int m = 0;
    while (m < nold && walls_[i][m] != iwall) m++;
    if (m < nold) {
      slot_[ic] = m;
    } else {
      const int add = ncontact_[i]++;
      slot_[ic] = add;
      walls_[i][add] = iwall;
      for (int q = 0; q < kMaxHistory; q++) history_[i][add][q] = 0.0;
    }
  }
}

void FixEpacWall::find_contacts(const double* range, std::vector<Contact>& out) {
  const bool moving = region_->dynamic_check() != 0;
  if (moving) {
    region_->prematch();
    region_->set_velocity();  // once per step (the region keeps the step it was set at)
  }
  double** x = atom->x;
  double* radius = atom->radius;
  int *mask = atom->mask, *type = atom->type;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (!region_->match(x[i][0], x[i][1], x[i][2])) continue;  // outside: no force, history kept (as LAMMPS)
    const int nc = region_->surface(x[i][0], x[i][1], x[i][2], radius[i] + range[type[i]]);
    if (nc > tmax_)
      error->one(FLERR, "Fix epac/wall: atom touches {} surfaces of region {} (at most {})", nc, idregion_, tmax_);
    update_slots(i, nc);
    for (int ic = 0; ic < nc; ic++) {
      const auto& rc = region_->contact[ic];
      if (!(rc.r > 0.0)) continue;  // centre on the surface: no normal (the law would see delta = R)
      Contact c;
      c.atom = i;
      c.history = history_[i][slot_[ic]];
      // LAMMPS's wall R* = R R_w / (R + R_w) (GranularModel::check_contact); a concave radius
      // closer than 2 R (R* > 2 R; infinite at R_w = -R) is outside the kernel's domain
      // (epac::detail::wall_effective_radius): refused, not clamped
      c.curvature = rc.radius;
      if (c.curvature < 0.0 && !(-c.curvature >= 2.0 * radius[i]))
        error->one(FLERR,
                   "Fix epac/wall: region {} has the concave contact radius {} at atom {} of radius {} (valid: "
                   "-contact radius >= 2 x the atom's radius)",
                   idregion_, c.curvature, atom->tag[i], radius[i]);
      const double del[3] = {rc.delx, rc.dely, rc.delz};
      for (int d = 0; d < 3; d++) {
        c.normal[d] = del[d] / rc.r;
        c.point[d] = x[i][d] - del[d];
      }
      if (moving)
        region_->velocity_contact(c.velocity, x[i], ic);
      else
        c.velocity[0] = c.velocity[1] = c.velocity[2] = 0.0;
      out.push_back(c);
    }
  }
}

void FixEpacWall::clear_contact_output() {
  if (!output_) return;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < size_peratom_cols; m++) array_atom[i][m] = 0.0;
}

void FixEpacWall::record_contact(const Contact& c, const double* force, double radius) {
  if (!output_) return;
  double* a = array_atom[c.atom];
  a[0] = 1.0;
  for (int d = 0; d < 3; d++) {
    a[1 + d] += force[d];  // an atom touching two surfaces of the region: the sum
    a[4 + d] = c.point[d];
  }
  a[7] = radius;
}

double FixEpacWall::memory_usage() {
  const double nmax = atom->nmax;
  double bytes = nmax * sizeof(int) + nmax * tmax_ * sizeof(int) + nmax * tmax_ * kMaxHistory * sizeof(double);
  if (output_) bytes += nmax * size_peratom_cols * sizeof(double);
  return bytes;
}

void FixEpacWall::grow_arrays(int nmax) {
  memory->grow(ncontact_, nmax, "epac/wall:ncontact");
  memory->grow(walls_, nmax, tmax_, "epac/wall:walls");
  memory->grow(history_, nmax, tmax_, kMaxHistory, "epac/wall:history");
  if (output_) memory->grow(array_atom, nmax, size_peratom_cols, "epac/wall:array_atom");
}

void FixEpacWall::copy_arrays(int i, int j, int) {
  ncontact_[j] = ncontact_[i];
  for (int k = 0; k < ncontact_[i]; k++) {
    walls_[j][k] = walls_[i][k];
    for (int q = 0; q < kMaxHistory; q++) history_[j][k][q] = history_[i][k][q];
  }
  if (output_)
    for (int m = 0; m < size_peratom_cols; m++) array_atom[j][m] = array_atom[i][m];
}

void FixEpacWall::set_arrays(int i) {
  ncontact_[i] = 0;
  if (output_)
    for (int m = 0; m < size_peratom_cols; m++) array_atom[i][m] = 0.0;
}

int FixEpacWall::pack_exchange(int i, double* buf) {
  int n = 0;
  buf[n++] = ubuf(ncontact_[i]).d;
  for (int k = 0; k < ncontact_[i]; k++) {
    buf[n++] = ubuf(walls_[i][k]).d;
    for (int q = 0; q < kMaxHistory; q++) buf[n++] = history_[i][k][q];
  }
  if (output_)
    for (int m = 0; m < size_peratom_cols; m++) buf[n++] = array_atom[i][m];
  return n;
}

int FixEpacWall::unpack_exchange(int nlocal, double* buf) {
  int n = 0;
  ncontact_[nlocal] = static_cast<int>(ubuf(buf[n++]).i);
  for (int k = 0; k < ncontact_[nlocal]; k++) {
    walls_[nlocal][k] = static_cast<int>(ubuf(buf[n++]).i);
    for (int q = 0; q < kMaxHistory; q++) history_[nlocal][k][q] = buf[n++];
  }
  if (output_)
    for (int m = 0; m < size_peratom_cols; m++) array_atom[nlocal][m] = buf[n++];
  return n;
}

int FixEpacWall::pack_restart(int i, double* buf) {
  int n = 1;  // buf[0]: this fix's count, as every per-atom restart fix packs it
  buf[n++] = ubuf(ncontact_[i]).d;
  for (int k = 0; k < ncontact_[i]; k++) {
    buf[n++] = ubuf(walls_[i][k]).d;
    for (int q = 0; q < kMaxHistory; q++) buf[n++] = history_[i][k][q];
  }
  buf[0] = n;
  return n;
}

void FixEpacWall::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const int total = static_cast<int>(extra[nlocal][m++]);  // pack_restart's buf[0]
  ncontact_[nlocal] = static_cast<int>(ubuf(extra[nlocal][m++]).i);
  // the slots per contact of the build that wrote the file (kMaxHistory was 32 before the stored
  // MDR shape): its fields are read into the first slots, the rest zeroed (a law whose own layout
  // changed, as MDR's did then, does not carry over)
  const int written = ncontact_[nlocal] > 0 ? (total - 2) / ncontact_[nlocal] - 1 : kMaxHistory;
  for (int k = 0; k < ncontact_[nlocal]; k++) {
    walls_[nlocal][k] = static_cast<int>(ubuf(extra[nlocal][m++]).i);
    for (int q = 0; q < written; q++) {
      const double v = extra[nlocal][m++];
      if (q < kMaxHistory) history_[nlocal][k][q] = v;
    }
    for (int q = written; q < kMaxHistory; q++) history_[nlocal][k][q] = 0.0;
  }
}

int FixEpacWall::size_restart(int i) { return 2 + ncontact_[i] * (1 + kMaxHistory); }

int FixEpacWall::maxsize_restart() { return 2 + tmax_ * (1 + kMaxHistory); }
