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
  comm_forward = 2;  // R, V
}

FixEpacMdr::~FixEpacMdr() {
  if (state_fix_made_ && modify->nfix && modify->get_fix_by_id(state_id)) modify->delete_fix(state_id);
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
  index_ro_ = atom->find_custom("epac_Ro", flag, cols);
  index_v_ = atom->find_custom("epac_V", flag, cols);
  if (index_ro_ < 0 || index_v_ < 0 || flag != 1 || cols != 0)
    error->all(FLERR, "Fix epac/mdr: per-atom vectors epac_Ro and epac_V are missing or not double vectors");
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
  int flag, cols;
  index_ro_ = atom->find_custom("epac_Ro", flag, cols);
  index_v_ = atom->find_custom("epac_V", flag, cols);
  if (index_ro_ < 0 || index_v_ < 0)
    error->all(FLERR, "Fix epac/mdr: its per-atom state (fix {}) was deleted", state_id);
}

double* FixEpacMdr::initial_radius() const { return atom->dvector[index_ro_]; }
double* FixEpacMdr::volume() const { return atom->dvector[index_v_]; }

void FixEpacMdr::initialize_new_atoms() {
  double* radius = atom->radius;
  double *ro = initial_radius(), *V = volume();
  const int nall = atom->nlocal + atom->nghost;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nall; i++)
    if (ro[i] == 0.0) {  // a new atom (property/atom starts at 0): its radius now is its R_o
      ro[i] = radius[i];
      V[i] = 4.0 / 3.0 * pi * radius[i] * radius[i] * radius[i];
    }
}

int FixEpacMdr::pack_forward_comm(int n, int* list, double* buf, int, int*) {
  double *radius = atom->radius, *V = volume();
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    buf[m++] = radius[j];
    buf[m++] = V[j];
  }
  return m;
}

void FixEpacMdr::unpack_forward_comm(int n, int first, double* buf) {
  double *radius = atom->radius, *V = volume();
  int m = 0;
  for (int i = first; i < first + n; i++) {
    radius[i] = buf[m++];
    V[i] = buf[m++];
  }
}
