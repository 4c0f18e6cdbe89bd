"""A settling scene that mixes, written for both codes from one set of spheres.

Used by bench/peers/side_by_side.py --scene settling (issue 20, item 5: the fcc scene stays in
lattice order, real flows do not). Spheres of the fcc scene's beads (R uniform in [0.94, 0.99] mm,
density 1000, E 1e9 Pa, nu 0.3) start on a jittered cubic grid (spacing 2.3 mm, solid fraction
0.33) in a box periodic in x and y, with random velocities up to 1 m/s per component, and fall
under a strong gravity (default 2000 m/s^2) onto a rigid floor at z = 0: a dense bed forms within
a few thousand steps of 5e-7 s while the spheres keep rearranging. The spheres are numbered in a
random order (as a long mixing flow leaves them), the same order in both codes.

Written for epac as a scene (explicit [[particles.list]], a floor wall) and for LAMMPS as a data
file read by bench/peers/lammps/in.settling (fix wall/gran on the same floor). Both codes get the
same positions, radii, velocities, dt (5e-7 s), neighbour skin (0.2 mm) and gravity.
"""
import random

R_MIN, R_MAX = 0.94e-3, 0.99e-3
SPACING = 2.05e-3  # grid spacing: no initial overlap (2 R_MAX + 2 JITTER < SPACING)
JITTER = 0.03e-3
SPEED = 1.0  # m/s, uniform in [-SPEED, SPEED] per component
DENSITY = 1000.0


def settling_spheres(nxy=40, nz=25, seed=2026):
    """Spheres as (x, y, z, r, vx, vy, vz) in a random order, and the box edges (Lx = Ly, Lz)."""
    rng = random.Random(seed)
    spheres = []
    for k in range(nz):
        for j in range(nxy):
            for i in range(nxy):
                x = (i + 0.5) * SPACING + rng.uniform(-JITTER, JITTER)
                y = (j + 0.5) * SPACING + rng.uniform(-JITTER, JITTER)
                z = (k + 0.5) * SPACING + rng.uniform(-JITTER, JITTER)
                r = rng.uniform(R_MIN, R_MAX)
                v = [rng.uniform(-SPEED, SPEED) for _ in range(3)]
                spheres.append((x, y, z, r, *v))
    rng.shuffle(spheres)
    L = nxy * SPACING
    return spheres, L, 2.0 * nz * SPACING  # room above the fill: nothing reaches the top


def epac_scene(law_block, spheres, L, H, gravity, steps):
    """Scene text for epac-run: the law block (materials.bead + [model], side_by_side.law_block),
    a rigid floor of the same friction and restitution, the spheres, the run."""
    out = [f'description = "{len(spheres)} fcc-scene beads settling in a box periodic in x and y (side_by_side '
           f'--scene settling)"\n', f"gravity = [0.0, 0.0, {-gravity!r}]\n", law_block,
           "\n[materials.floor]\nrigid = true\npoisson_ratio = 0.3\nrestitution = 0.5\nfriction = 0.5\n",
           f"\n[box]\nlo = [0.0, 0.0, 0.0]\nhi = [{L!r}, {L!r}, {H!r}]\nperiodic = [true, true, false]\n",
           '\n[[walls]]\nname = "floor"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = "floor"\n',
           "\n[particles]\n"]
    for (x, y, z, r, vx, vy, vz) in spheres:
        out.append(f'[[particles.list]]\nposition = [{x!r}, {y!r}, {z!r}]\nradius = {r!r}\nmaterial = "bead"\n'
                   f"velocity = [{vx!r}, {vy!r}, {vz!r}]\n")
    out.append(f"\n[run]\ndt = 5.0e-7\nsteps = {steps}\nskin = 2.0e-4\noutput_interval = 100\n")
    return "".join(out)


def lammps_data(spheres, L, H):
    """LAMMPS data file (atom_style sphere: id type diameter density x y z; Velocities: id v w)."""
    out = [f"epac settling scene, {len(spheres)} spheres\n\n{len(spheres)} atoms\n1 atom types\n\n",
           f"0.0 {L!r} xlo xhi\n0.0 {L!r} ylo yhi\n0.0 {H!r} zlo zhi\n\nAtoms # sphere\n\n"]
    for n, (x, y, z, r, *_v) in enumerate(spheres, 1):
        out.append(f"{n} 1 {2.0 * r!r} {DENSITY!r} {x!r} {y!r} {z!r}\n")
    out.append("\nVelocities\n\n")
    for n, (_x, _y, _z, _r, vx, vy, vz) in enumerate(spheres, 1):
        out.append(f"{n} {vx!r} {vy!r} {vz!r} 0.0 0.0 0.0\n")
    return "".join(out)
