/* FixEpacMdr: per-atom state of MDR radius growth for pair_style epac/mdr (fix_epac_mdr.h). */
#include "fix_epac_mdr.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;

FixEpacMdr::FixEpacMdr(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  if (narg != 3) error->all(FLERR, "Illegal fix {} command: it takes no arguments (fix ID group epac/mdr)", style);
  if (!atom->radius_flag) error->all(FLERR, "Fix epac/mdr requires atom attribute radius (atom_style sphere)");
  for (auto* f : modify->get_fix_by_style("^epac/mdr$"))
    if (std::string(f->id) != id)
      error->all(FLERR,
                 "Fix epac/mdr: fix {} is one already (only one may be defined: it holds every atom's "
                 "R_o and V)",
                 f->id);
  comm_forward = 5;  // R, V, and Part II's psi, V_geo, A_con,0 (Stage)
}

FixEpacMdr::~FixEpacMdr() {
  if (state_fix_made_ && modify->nfix && modify->get_fix_by_id(state_id)) modify->delete_fix(state_id);
  if (bulk_fix_made_ && modify->nfix && modify->get_fix_by_id(bulk_state_id)) modify->delete_fix(bulk_state_id);
}

// No per-step hook: the pair style applies the growth right after its force pass.
int FixEpacMdr::setmask() { return 0; }

// R_o and V as custom per-atom vectors of an internal fix property/atom (ghost yes: ghosts get
// them at borders; restart files carry them). The ID is fixed so a restarted input that defines
// fix epac/mdr again finds its state in the restart file.
void FixEpacMdr::post_constructor() {
  int flag, cols;
  if (atom->find_custom("epac_Ro", flag, cols) < 0) {
    modify->add_fix(fmt::format("{} all property/atom d_epac_Ro d_epac_V ghost yes", state_id));
    state_fix_made_ = true;
  }
  // Part II's state in a second fix property/atom (restart files written before it have only the
  // first; initialize_new_atoms then starts it from V_geo = 0)
  if (atom->find_custom("epac_psi", flag, cols) < 0) {
    modify->add_fix(
        fmt::format("{} all property/atom d_epac_psi d_epac_Vgeo d_epac_Acon0 d_epac_ddbar ghost yes", bulk_state_id));
    bulk_fix_made_ = true;
  }
  find_state();
}

void FixEpacMdr::find_state() {
  int flag, cols;
  index_ro_ = atom->find_custom("epac_Ro", flag, cols);
  index_v_ = atom->find_custom("epac_V", flag, cols);
  index_psi_ = atom->find_custom("epac_psi", flag, cols);
  index_vgeo_ = atom->find_custom("epac_Vgeo", flag, cols);
  index_acon0_ = atom->find_custom("epac_Acon0", flag, cols);
  index_ddbar_ = atom->find_custom("epac_ddbar", flag, cols);
  if (index_ro_ < 0 || index_v_ < 0 || index_psi_ < 0 || index_vgeo_ < 0 || index_acon0_ < 0 || index_ddbar_ < 0)
    error->all(FLERR, "Fix epac/mdr: its per-atom state (fix {} and {}) was deleted", state_id, bulk_state_id);
}

void FixEpacMdr::init() {
  // With newton off every process evaluates each pair that touches one of its own atoms, so an
  // atom's growth sums of (37)-(39) are complete on its owner and need no reverse communication
  // (the sums on ghosts are partial and dropped), as in LAMMPS's own MDR.
  if (force->newton_pair)
    error->all(FLERR,
               "Fix epac/mdr requires newton off (newton_pair is on): radius growth sums each atom's "
               "contacts on its owner, which sees them all only when every process evaluates the pairs "
               "of its own atoms with ghosts");
  if (!force->pair_match("epac/mdr", 1))
    error->all(FLERR, "Fix epac/mdr requires pair_style epac/mdr (found {})", force->pair_style);
  find_state();
}

double* FixEpacMdr::initial_radius() const { return atom->dvector[index_ro_]; }
double* FixEpacMdr::volume() const { return atom->dvector[index_v_]; }
double* FixEpacMdr::psi() const { return atom->dvector[index_psi_]; }
double* FixEpacMdr::vgeo() const { return atom->dvector[index_vgeo_]; }
double* FixEpacMdr::acon0() const { return atom->dvector[index_acon0_]; }
double* FixEpacMdr::ddelta_bar() const { return atom->dvector[index_ddbar_]; }

void FixEpacMdr::initialize_new_atoms() {
  double* radius = atom->radius;
  double *ro = initial_radius(), *V = volume();
  double *ps = psi(), *vg = vgeo(), *ac = acon0();
  const int nall = atom->nlocal + atom->nghost;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nall; i++) {
    if (ro[i] == 0.0) {  // a new atom (property/atom starts at 0): its radius now is its R_o
      ro[i] = radius[i];
      V[i] = 4.0 / 3.0 * pi * radius[i] * radius[i] * radius[i];
    }
    if (vg[i] == 0.0) {  // Part II's state of a new atom (V_geo > 0 once set): no contact yet
      ps[i] = 1.0;
      vg[i] = 4.0 / 3.0 * pi * ro[i] * ro[i] * ro[i];
      ac[i] = 0.0;
    }
  }
}

int FixEpacMdr::pack_forward_comm(int n, int* list, double* buf, int, int*) {
  double *radius = atom->radius, *V = volume();
  double *ps = psi(), *vg = vgeo(), *ac = acon0(), *dd = ddelta_bar();
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    if (stage_ == Stage::mean_surface_displacement) {
      buf[m++] = dd[j];
      continue;
    }
    buf[m++] = radius[j];
    buf[m++] = V[j];
    if (stage_ == Stage::growth_and_bulk) {
      buf[m++] = ps[j];
      buf[m++] = vg[j];
      buf[m++] = ac[j];
    }
  }
  return m;
}

void FixEpacMdr::unpack_forward_comm(int n, int first, double* buf) {
  double *radius = atom->radius, *V = volume();
  double *ps = psi(), *vg = vgeo(), *ac = acon0(), *dd = ddelta_bar();
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (stage_ == Stage::mean_surface_displacement) {
      dd[i] = buf[m++];
      continue;
    }
    radius[i] = buf[m++];
    V[i] = buf[m++];
    if (stage_ == Stage::growth_and_bulk) {
      ps[i] = buf[m++];
      vg[i] = buf[m++];
      ac[i] = buf[m++];
    }
  }
}
