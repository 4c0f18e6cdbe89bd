"""What compare_mdr_triaxial.py and compare_mdr_tableting.py share: running one of the MDR authors'
example inputs shipped with LAMMPS (examples/granular/), epac's MDR settings that reproduce the
authors' conventions, and the diagnostic build of LAMMPS without its contact penalty."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from mpi_session import run_lammps

DEFAULT_LMP = os.path.expanduser("~/.cache/epac/lammps/4Feb2025/build/lmp")
DEFAULT_EXAMPLES = os.path.expanduser("~/.cache/epac/lammps/4Feb2025/src/lammps-4Feb2025/examples/granular")

# pair_style epac/mdr's documented conventions set to the authors' choices (drivers/lammps/README.md),
# and epac's defaults
AUTHORS = {"pair_split": "geometric_authors", "delta_max": "running_max", "damping": "authors",
           "friction": "authors", "yield_onset": "hertz_40", "surface_energy_share": "each_side_full",
           "adhesive_radius": "authors", "release": "zero_overlap"}
DEFAULTS = {"pair_split": "equal_pair", "delta_max": "paper_19", "damping": "restitution_exact",
            "friction": "mindlin", "yield_onset": "elastic_law", "surface_energy_share": "series",
            "adhesive_radius": "paper", "release": "critical_overlap"}

NO_PENALTY_SOURCE = """// Diagnostic (tests/lammps/authors_examples.py): LAMMPS's MDR without its contact penalty.
#include "fix_granular_mdr.h"
void LAMMPS_NS::FixGranularMDR::calculate_contact_penalty() {}
"""


# Diagnostic (tests/lammps/compare_mdr_tableting.py --lammps-fixes): LAMMPS 4Feb2025's pair granular
# with two of its defects repaired, preloaded (LD_PRELOAD) into lmp:
#  (1) GranSubModNormalMDR::calculate_forces (gran_sub_mod_normal.cpp) tests its adhesive peeling's
#      Newton iteration with an unqualified abs(fa) that resolves to the C library's int abs(int):
#      |fa| < 1 truncates to 0, the loop stops before its first update, and the adhesive radius never
#      shrinks; a stretched adhesive MDR contact then keeps its full-radius springs, in tension
#      growing linearly until the overlap reaches zero (an adhesive pair, E 5 MPa, gamma 2 J/m^2, R 1 mm
#      unloaded from 0.4 R: 1.4 N of tension, where peeling detaches below 0.07 N). Repaired by
#      compiling that file with std::abs.
#  (2) PairGranular::transfer_history negates every history value of a tangential or rolling model
#      when a neighbour rebuild names a pair the other way round; the rolling displacement
#      (R* (omega_i - omega_j) x n integrated) is symmetric in i and j, so its negation reverses the
#      rolling torque. Repaired by not negating the rolling model's values.
LAMMPS_FIX_ROLLING_SOURCE = """// Diagnostic (tests/lammps/authors_examples.py): rolling history kept on reordered pairs.
#include "gran_sub_mod.h"
#include "granular_model.h"
#include "pair_granular.h"
using namespace LAMMPS_NS;
using namespace Granular_NS;
void PairGranular::transfer_history(double *source, double *target, int itype, int jtype) {
  GranularModel *model = models_list[types_indices[itype][jtype]];
  int start = 0, roll0 = -1, roll1 = -1;
  for (int k = 0; k < NSUBMODELS; k++) {
    const int n = model->sub_models[k] ? model->sub_models[k]->size_history : 0;
    if (k == ROLLING) { roll0 = start; roll1 = start + n; }
    start += n;
  }
  for (int i = 0; i < model->size_history; i++) {
    double f = model->nondefault_history_transfer ? model->transfer_history_factor[i] : -1.0;
    if (i >= roll0 && i < roll1) f = 1.0;
    target[i] = f * source[i];
  }
}
"""


def build_lammps_fixes(args):
    """Compiles the two repairs above against LAMMPS's sources (args.lammps_src), linked to the
    liblammps next to args.lmp; returns the LD_PRELOAD value."""
    cxx = shutil.which("mpicxx") or shutil.which("mpic++")
    if not cxx:
        sys.exit("--lammps-fixes needs mpicxx (the MPI compiler that built LAMMPS)")
    with open(os.path.join(args.lammps_src, "GRANULAR", "gran_sub_mod_normal.cpp")) as f:
        normal = f.read()
    fixed, n = re.subn(r"(?<![\w:.])abs\(fa", "std::abs(fa", normal)
    if n != 2:
        sys.exit(f"gran_sub_mod_normal.cpp: expected 2 'abs(fa' calls, found {n}; LAMMPS changed, update this script")
    libdir = os.path.dirname(os.path.realpath(args.lmp))
    libs = []
    for name, text in (("lammps_fix_mdr_abs", fixed), ("lammps_fix_rolling_transfer", LAMMPS_FIX_ROLLING_SOURCE)):
        src = os.path.join(args.workdir, name + ".cpp")
        lib = os.path.join(args.workdir, name + ".so")
        with open(src, "w") as f:
            f.write(text)
        cmd = [cxx, "-shared", "-fPIC", "-O2", "-DLAMMPS_SMALLBIG", "-I", args.lammps_src,
               "-I", os.path.join(args.lammps_src, "GRANULAR"), src, "-o", lib, "-L", libdir, "-llammps",
               "-Wl,-rpath," + libdir]
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if r.returncode != 0:
            sys.exit(f"building {name} failed:\n{' '.join(cmd)}\n{r.stdout[-3000:]}")
        libs.append(lib)
    return ":".join(libs)


def add_common_arguments(ap):
    ap.add_argument("--lmp", default=DEFAULT_LMP)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--examples", default=DEFAULT_EXAMPLES, help="LAMMPS's examples/granular folder")
    ap.add_argument("--workdir", default=None)


def prepare(args, input_name, prefix):
    """Absolute plugin path, a work folder; returns the shipped input's text."""
    args.plugin = os.path.abspath(args.plugin)
    if args.workdir is None:
        args.workdir = tempfile.mkdtemp(prefix=prefix)
    os.makedirs(args.workdir, exist_ok=True)
    with open(os.path.join(args.examples, input_name)) as f:
        return f.read()


def build_no_penalty(args):
    """Compiles the no-penalty library against LAMMPS's headers (args.lammps_src); returns its path.
    Preloaded into lmp (LD_PRELOAD) it replaces FixGranularMDR::calculate_contact_penalty by a no-op."""
    src = os.path.join(args.workdir, "no_penalty.cpp")
    lib = os.path.join(args.workdir, "no_penalty.so")
    with open(src, "w") as f:
        f.write(NO_PENALTY_SOURCE)
    cxx = shutil.which("mpicxx") or shutil.which("mpic++")
    if not cxx:
        sys.exit("--lammps-src needs mpicxx (the MPI compiler that built LAMMPS)")
    cmd = [cxx, "-shared", "-fPIC", "-O2", "-DLAMMPS_SMALLBIG", "-I", args.lammps_src,
           "-I", os.path.join(args.lammps_src, "GRANULAR"), src, "-o", lib]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit(f"building the no-penalty diagnostic failed:\n{' '.join(cmd)}\n{r.stdout[-3000:]}")
    return lib


def read_rows(path):
    with open(path) as f:
        return [[float(x) for x in line.split()] for line in f if line.strip() and not line.startswith("#")]


def run_example(args, label, text, data, ranks=1, preload=None):
    """Runs `text` as in.run in workdir/label with the example's data file; returns that folder."""
    work = os.path.join(args.workdir, label)
    os.makedirs(work, exist_ok=True)
    shutil.copy(os.path.join(args.examples, data), work)
    with open(os.path.join(work, "in.run"), "w") as f:
        f.write(text)
    cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] if ranks > 1 else []
    cmd += [args.lmp, "-in", "in.run", "-log", "log.lammps", "-screen", "none"]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    if preload:
        env["LD_PRELOAD"] = preload
    r = run_lammps(cmd, work, env)
    if r.returncode != 0:
        log = os.path.join(work, "log.lammps")
        tail = open(log).read()[-3000:] if os.path.exists(log) else ""
        sys.exit(f"{label}: lmp failed ({r.returncode}):\n{r.stdout[-3000:]}\n{tail}")
    return work
