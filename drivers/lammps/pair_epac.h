/* epac contact laws as LAMMPS pair styles (plugin; drivers/lammps/README.md).
   One class serves every law: the law is fixed by the style name, its compiled model is chosen in
   init_style from the effects the coefficients call for (contact_engine.hpp). */
#ifndef EPAC_LAMMPS_PAIR_EPAC_H
#define EPAC_LAMMPS_PAIR_EPAC_H

#include "contact_engine.hpp"
#include "fix_epac_wall.h"
#include "pair.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixNeighHistory;
class FixEpacMdr;

class PairEpac : public Pair {
 public:
  PairEpac(class LAMMPS* lmp, epac::lammps::Law law, const char* style);
  ~PairEpac() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  void write_restart(FILE* fp) override;
  void read_restart(FILE* fp) override;
  void write_restart_settings(FILE* fp) override;
  void read_restart_settings(FILE* fp) override;
  // epac keeps every history field in the frame of the contact's smaller atom ID, so a row
  // moves between the two atoms' lists unchanged (LAMMPS's default negates it).
  void transfer_history(double* source, double* target, int, int) override;
  double memory_usage() override;

 protected:
  void allocate();
  void gather_atoms(int nall);
  void grow_radii(int nlocal, bool advance);
  void mean_surface_displacement(const epac::ContactHistory<double>& h, const epac::lammps::WallPass* wp, bool advance);
  void build_contacts();
  void add_forces(int nlocal, bool with_ghosts);
  int coefficient_count() const;
  epac::Material material_from(char** arg, int type) const;

  epac::lammps::Law law_;
  std::string style_;
  std::vector<epac::Material> materials_;  // index: atom type - 1
  std::vector<int> have_material_;
  std::unique_ptr<epac::lammps::ContactEngine> engine_;
  FixNeighHistory* fix_history_ = nullptr;
  int history_size_ = 0;
  int pair_split_ = 0;           // pair_style epac/mdr pair_split: epac::MdrPairSplit
  int delta_max_ = 0;            // pair_style epac/mdr delta_max: epac::MdrDeltaMax
  int damping_ = 0;              // pair_style epac/mdr damping: epac::MdrDamping
  int friction_ = 0;             // pair_style epac/mdr friction: epac::MdrFriction
  int yield_onset_ = 0;          // pair_style epac/mdr yield_onset: epac::MdrYieldOnset
  int energy_share_ = 0;         // pair_style epac/mdr surface_energy_share: epac::MdrSurfaceEnergyShare
  int adhesive_radius_ = 0;      // pair_style epac/mdr adhesive_radius: epac::MdrAdhesiveRadius
  int release_ = 0;              // pair_style epac/mdr release: epac::MdrRelease
  int contact_penalty_ = 0;      // pair_style epac/mdr contact_penalty off|on: MdrOptions::contact_penalty
  std::int64_t list_stamp_ = 0;  // counts build_contacts() (the contact penalty's index follows it)
  std::vector<double> kt_;       // per type: pair_coeff keyword kt (MdrFriction::authors' k_t)
  std::vector<double> psi_b_;    // per type: pair_coeff psi_b (epac/mdr; one value for all types)
  bool bulk_ = false;            // the engine has Part II's bulk response (psi_b > 0)
  // fix epac/wall: their contacts are evaluated in this pass; the engine's materials then end with
  // one rigid copy per wall fix and type (index ntypes + f ntypes + type - 1) for the wall side
  std::vector<FixEpacWall*> wall_fixes_;
  std::vector<double> wall_range_;  // per type (1..ntypes): the law's adhesive reach at a wall
  std::vector<FixEpacWall::Contact> wall_contacts_;
  std::vector<int> wall_owner_;   // per wall contact: its fix in wall_fixes_
  epac::lammps::WallPass walls_;  // views kept between passes, reallocated only when they must grow
  void collect_walls();
  void apply_walls(bool advance);
  bool history_fix_made_ = false;
  double *onerad_ = nullptr, *maxrad_ = nullptr;  // per type: largest radius (local, global)
  // fix epac/mdr (MDR radius growth, epac/mdr only): its R_o and V feed the engine; null without it
  FixEpacMdr* growth_fix_ = nullptr;
  bool growth_ = false;  // the engine grows radii (fix present and the law can yield)

  // the contact list of the current neighbour list: pair k is (i, j) = (first, second) and its
  // history row lives at LAMMPS's fix NEIGH_HISTORY slot hist_[k] with touch flag touch_[k]
  epac::ContactList<> contacts_;
  epac::ContactHistory<double> history_;
  std::vector<double*> hist_;
  std::vector<int*> touch_;
  std::vector<int> first_, second_;
  void* last_list_ = nullptr;
  bigint last_build_ = -1;
};

}  // namespace LAMMPS_NS

#endif
