"""One LAMMPS run of a test, with an MPI session directory of its own.

Open MPI 4 (Debian 12's) creates its session directory, /tmp/ompi.<host>.<uid>, by a test for
the directory followed by a mkdir. Two runs that start together can both find it missing, and
the second mkdir then fails: "Directory: /tmp/ompi.vm.0  Error: File exists", orte_session_dir
failed (seen in CI, `ctest -j 2`; open-mpi/ompi#8510). Each run here gets its own, short
temporary directory (TMPDIR, and the session base that Open MPI reads) and removes it after.
"""
import shutil
import subprocess
import tempfile


def run_lammps(cmd, cwd, env):
    """subprocess.run(cmd) in cwd with env, stdout and stderr together as text."""
    tmp = tempfile.mkdtemp(prefix="epac-mpi-")
    try:
        env = dict(env, TMPDIR=tmp, OMPI_MCA_orte_tmpdir_base=tmp)
        return subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
