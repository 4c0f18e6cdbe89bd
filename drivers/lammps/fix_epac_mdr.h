/* fix ID group epac/mdr: MDR radius growth, (37)-(39), for pair_style epac/mdr (plugin;
   drivers/lammps/README.md). The fix holds the per-atom state the growth needs between steps, the
   initial radius R_o and the volume V of (39), in an internal fix property/atom (so it migrates
   with atoms, reaches ghosts at borders and goes into restart files, as LAMMPS's
   fix_granular_mdr.cpp does), and forward-communicates the grown radius and V to ghosts; with
   pair_coeff psi_b > 0 also Part II's psi, V_geo and A_con (a second internal fix property/atom)
   and, before each force pass, the mean surface displacement. The
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
  // Part II's bulk response (pair_coeff psi_b > 0): psi, V_geo, A_con,0 between passes and this
  // pass's d delta-bar, per atom (new atoms: psi 1, V_geo V_o, A_con,0 0)
  double* psi() const;
  double* vgeo() const;
  double* acon0() const;
  double* ddelta_bar() const;
  // What the next forward_comm sends: R and V; R, V and Part II's psi, V_geo, A_con,0; or the
  // mean surface displacement d delta-bar alone.
  enum class Stage { growth, growth_and_bulk, mean_surface_displacement };
  void forward_stage(Stage s) { stage_ = s; }

  static constexpr const char* state_id = "EPAC_MDR_PARTICLE_STATE";
  static constexpr const char* bulk_state_id = "EPAC_MDR_BULK_STATE";

 private:
  int index_ro_ = -1, index_v_ = -1;
  int index_psi_ = -1, index_vgeo_ = -1, index_acon0_ = -1, index_ddbar_ = -1;
  bool state_fix_made_ = false, bulk_fix_made_ = false;
  Stage stage_ = Stage::growth;
  void find_state();
};

}  // namespace LAMMPS_NS

#endif
