/* fix ID group epac/mdr: MDR radius growth, (37)-(39), for pair_style epac/mdr (plugin;
   drivers/lammps/README.md). The fix holds the per-atom state the growth needs between steps, the
   initial radius R_o and the volume V of (39), in an internal fix property/atom (so it migrates
   with atoms, reaches ghosts at borders and goes into restart files, as LAMMPS's
   fix_granular_mdr.cpp does), and forward-communicates the grown radius and V to ghosts. The
   pair style does the work (PairEpac::compute): it compiles its engine with the growth effect
   when this fix exists, applies the growth of each force pass to local atoms and calls
   forward_comm(this).
   Neighbour lists: radii reach radius_cap (1.5) R_o. The pair's cutoff (ghosts, bins) is scaled by
   the cap and LAMMPS's size lists test the radii of each rebuild, but the rebuild trigger sees only
   displacements: the skin must also cover the growth between rebuilds (pair epac/mdr warns when
   skin < (cap - 1) times the largest radius; LAMMPS's own MDR examples use large skins too). */
#ifndef EPAC_LAMMPS_FIX_EPAC_MDR_H
#define EPAC_LAMMPS_FIX_EPAC_MDR_H

#include "fix.h"

namespace LAMMPS_NS {

class FixEpacMdr : public Fix {
 public:
  FixEpacMdr(class LAMMPS*, int, char**);
  ~FixEpacMdr() override;
  int setmask() override;
  void post_constructor() override;
  void init() override;
  int pack_forward_comm(int, int*, double*, int, int*) override;
  void unpack_forward_comm(int, int, double*) override;

  // Sets R_o = radius and V = 4/3 pi R_o^3 for atoms (local and ghost) whose R_o is 0 (new).
  void initialize_new_atoms();
  double* initial_radius() const;  // R_o per atom (local and ghost)
  double* volume() const;          // V of MDR (39) per atom

  static constexpr const char* state_id = "EPAC_MDR_PARTICLE_STATE";

 private:
  int index_ro_ = -1, index_v_ = -1;
  bool state_fix_made_ = false;
};

}  // namespace LAMMPS_NS

#endif
