/* fix ID group epac/wall region REGION-ID [mu MU] [gamma G] [e E] [contacts]: the surface of a
   LAMMPS region (plane,
   cylinder, block, ..., moving or rotating as the region does) as a rigid wall for epac's pair
   styles (plugin; drivers/lammps/README.md). The wall acts with the pair style's own law on each
   atom of the group that touches it: every contact is a particle against the region's tangent
   plane at the nearest surface point, with the particle-wall R* of LAMMPS's region walls (from the
   region's contact radius R_w: R R_w / (R + R_w), R at a flat surface; concave radii need
   -R_w >= 2 R) in the laws and the rolling arm, except MDR's normal law, which takes the wall as a
   rigid flat (as LAMMPS's `granular mdr` does), and with the particle type's material (the wall
   contributes no compliance; friction, restitution and surface energy are the particle's unless
   mu, gamma or e set the wall's own: epac::Material::own_surface_properties).
   The pair style does the work in its force pass (PairEpac::compute), so that with fix epac/mdr a
   wall contact feeds the same radius-growth sums, MDR (37)-(39), as the pair contacts of that step.
   This fix keeps the per-atom contact history (up to the region's number of touching surfaces per
   atom; it migrates with atoms and goes into restart files) and, with `contacts`, a per-atom array
   like fix wall/gran/region's: 1 if touching, force x y z on the atom, contact point x y z, radius. */
#ifndef EPAC_LAMMPS_FIX_EPAC_WALL_H
#define EPAC_LAMMPS_FIX_EPAC_WALL_H

#include "fix.h"

#include <epac/params/material.hpp>

#include <limits>
#include <vector>

namespace LAMMPS_NS {

class FixEpacWall : public Fix {
 public:
  // history fields per contact: MDR with every effect, rolling and Part II, on host backends (with
  // its stored plastic shape, 5 fields per side): 42
  static constexpr int kMaxHistory = 42;

  // One touching surface of one local atom in this pass.
  struct Contact {
    int atom;            // local atom index
    double* history;     // its kMaxHistory slots
    double point[3];     // nearest surface point
    double normal[3];    // unit normal from the wall towards the atom
    double velocity[3];  // the surface's velocity at that point
    double curvature;    // the region's contact radius there (Region::contact[].radius: 0 flat,
                         // < 0 concave, e.g. -2 R_cyl inside a cylinder): the contact's R*
  };

  FixEpacWall(class LAMMPS*, int, char**);
  ~FixEpacWall() override;
  int setmask() override;
  void init() override;
  // The wall's material against particles of `type` with material `particle`: rigid, with the
  // particle's properties where this fix sets none.
  epac::Material wall_material(const epac::Material& particle, int type) const;

  // The pass's contacts: every local atom of the group within radius + range[type] of the surface
  // (range: the law's adhesive reach per atom type, index 1..ntypes). Keeps the history of
  // surfaces still touched, zeroes it for new ones, forgets the ones left. Call once per pass.
  void find_contacts(const double* range, std::vector<Contact>& out);
  // With `contacts`: clears the per-atom array (call before recording a pass's forces).
  void clear_contact_output();
  void record_contact(const Contact& c, const double* force, double radius);

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double*) override;
  int unpack_exchange(int, double*) override;
  int pack_restart(int, double*) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 private:
  char* idregion_ = nullptr;
  class Region* region_ = nullptr;
  int tmax_ = 1;                 // most surfaces of the region one atom can touch
  int* ncontact_ = nullptr;      // per atom: touching surfaces stored
  int** walls_ = nullptr;        // per atom: the region's surface ids (iwall) of those contacts
  double*** history_ = nullptr;  // per atom, per contact: kMaxHistory fields
  bool output_ = false;
  // the wall's own values; NaN: the particle's
  double mu_ = std::numeric_limits<double>::quiet_NaN(), gamma_ = mu_, e_ = mu_;
  std::vector<int> slot_;  // scratch: history slot of each current contact
  void update_slots(int i, int nc);
};

}  // namespace LAMMPS_NS

#endif
