/* epacplugin.so: registers epac's contact laws with LAMMPS (`plugin load epacplugin.so`), and fix
   epac/mdr (MDR radius growth for pair_style epac/mdr) and fix epac/wall (region walls). */
#include "fix_epac_mdr.h"
#include "fix_epac_wall.h"
#include "lammpsplugin.h"
#include "pair_epac.h"
#include "version.h"

#include <epac/version.hpp>

using namespace LAMMPS_NS;
using epac::lammps::Law;

namespace {
template <Law L>
Pair* make_pair(LAMMPS* lmp);
template <>
Pair* make_pair<Law::hertz_mindlin>(LAMMPS* lmp) {
  return new PairEpac(lmp, Law::hertz_mindlin, "epac/hertz_mindlin");
}
template <>
Pair* make_pair<Law::jkr>(LAMMPS* lmp) {
  return new PairEpac(lmp, Law::jkr, "epac/jkr");
}
template <>
Pair* make_pair<Law::nan2022>(LAMMPS* lmp) {
  return new PairEpac(lmp, Law::nan2022, "epac/nan2022");
}
template <>
Pair* make_pair<Law::mdr>(LAMMPS* lmp) {
  return new PairEpac(lmp, Law::mdr, "epac/mdr");
}
Fix* make_fix_mdr(LAMMPS* lmp, int narg, char** arg) { return new FixEpacMdr(lmp, narg, arg); }
Fix* make_fix_wall(LAMMPS* lmp, int narg, char** arg) { return new FixEpacWall(lmp, narg, arg); }
}  // namespace

extern "C" void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  auto reg = (lammpsplugin_regfunc)regfunc;
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.author = "the epac authors";
  plugin.handle = handle;
  struct Entry {
    const char *name, *info;
    lammpsplugin_factory1* make;
  };
  const Entry entries[] = {
      {"epac/hertz_mindlin", "epac " EPAC_VERSION_STRING ": Hertz-Mindlin",
       (lammpsplugin_factory1*)&make_pair<Law::hertz_mindlin>},
      {"epac/jkr", "epac " EPAC_VERSION_STRING ": JKR adhesion (Hertz-JKR + Mindlin)",
       (lammpsplugin_factory1*)&make_pair<Law::jkr>},
      {"epac/nan2022", "epac " EPAC_VERSION_STRING ": Nan et al. 2022 linear elasto-plastic adhesive",
       (lammpsplugin_factory1*)&make_pair<Law::nan2022>},
      {"epac/mdr", "epac " EPAC_VERSION_STRING ": MDR (Zunker & Kamrin, Part I)",
       (lammpsplugin_factory1*)&make_pair<Law::mdr>},
  };
  for (const auto& e : entries) {
    plugin.name = e.name;
    plugin.info = e.info;
    plugin.creator.v1 = e.make;
    (*reg)(&plugin, lmp);
  }
  plugin.style = "fix";
  plugin.name = "epac/mdr";
  plugin.info = "epac " EPAC_VERSION_STRING ": MDR radius growth (37)-(39) for pair_style epac/mdr";
  plugin.creator.v2 = (lammpsplugin_factory2*)&make_fix_mdr;
  (*reg)(&plugin, lmp);
  plugin.name = "epac/wall";
  plugin.info = "epac " EPAC_VERSION_STRING ": a region's surface as a rigid wall for pair_style epac/*";
  plugin.creator.v2 = (lammpsplugin_factory2*)&make_fix_wall;
  (*reg)(&plugin, lmp);
}
