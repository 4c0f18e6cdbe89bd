"""The fcc benchmark scene (bench/peers/fcc_compress.toml) with another law or size.

Used by bench/peers/side_by_side.py and bench/scaling/run_scaling.py. The scene file marks its
law block (materials + [model]) with '# --- law ---' / '# --- end law ---' lines; everything else
(periodic box, deformation, lattice, run) is shared by every law.
"""
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(ROOT, "bench", "peers", "fcc_compress.toml")
LATTICE_A = 2.0 * 2 ** 0.5 * 1e-3  # cubic cell edge: nearest-neighbour distance 2R, R = 1 mm


def fcc_scene(law_block=None, ncell=14, steps=None, deform_steps=None, output_interval=None, order=None,
              spatial_sort=None):
    """Scene text: law_block replaces the marked block; ncell resizes lattice and box.
    order: [particles] order ("shuffled": the mixed scene); spatial_sort: [run] spatial_sort
    (True, False or "auto"; None keeps the driver's default)."""
    text = open(SCENE).read()
    if law_block is not None:
        text, n = re.subn(r"(# --- law ---[^\n]*\n).*?(# --- end law ---\n)",
                          lambda m: m.group(1) + law_block.lstrip() + m.group(2), text, flags=re.S)
        if n != 1:
            raise SystemExit(f"{SCENE}: the '# --- law ---' / '# --- end law ---' markers are missing")
    if ncell != 14:
        L = ncell * LATTICE_A
        text, n1 = re.subn(r"cells\s*=\s*\[\s*14\s*,\s*14\s*,\s*14\s*\]", f"cells = [{ncell}, {ncell}, {ncell}]", text)
        text, n2 = re.subn(r"^hi\s*=\s*\[[^\]]*\]", f"hi = [{L!r}, {L!r}, {L!r}]", text, flags=re.M)
        if n1 != 1 or n2 != 1:
            raise SystemExit(f"{SCENE}: expected one 'cells = [14, 14, 14]' and one 'hi = [...]' line")
    if steps is not None:
        text = set_key(text, "run", "steps", steps)
    if deform_steps is not None:
        text = set_key(text, "box.deform", "steps", deform_steps)
    if output_interval is not None:
        text = set_key(text, "run", "output_interval", output_interval)
    if order is not None:
        text, n = re.subn(r"^\[particles\.lattice\]", f'[particles]\norder = "{order}"\n\n[particles.lattice]', text,
                          flags=re.M)
        if n != 1:
            raise SystemExit(f"{SCENE}: expected one [particles.lattice] table")
    if spatial_sort is not None:
        value = {True: "true", False: "false"}.get(spatial_sort, f'"{spatial_sort}"')
        text = text.replace("[run]\n", f"[run]\nspatial_sort = {value}\n", 1)
    return text


def set_key(text, table, key, value):
    """Sets `key = value` inside [table] (the key must be there)."""
    out, current, done = [], None, False
    for line in text.splitlines(keepends=True):
        m = re.match(r"^\[([^\]]+)\]\s*(#.*)?$", line)
        if m:
            current = m.group(1).strip()
        elif current == table and re.match(rf"^{re.escape(key)}\s*=", line):
            line = f"{key} = {value}\n"
            done = True
        out.append(line)
    if not done:
        raise SystemExit(f"{SCENE}: no '{key}' in [{table}]")
    return "".join(out)
