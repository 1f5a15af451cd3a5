"""Write one run of the silo example (examples/clumps/silo): a square flat-bottomed silo filled with
generated bodies (tetrahedral clumps or spheres of the same volume) that settle on a lid over the
orifice; the lid is removed at T_OPEN and the bodies fall through the orifice into an open box
well below. Needs the meshes run.sh makes (walls.csv, floor_D.csv, lid_D.csv, catcher.csv).

Usage: make_scene.py SHAPE D0 OUT_TOML OUT_DIR [options]      (SHAPE tetra or sphere; D0 in m)
Units SI.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from shapes import R_EQ, bodies_toml, physics_toml  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("shape", choices=["tetra", "sphere"])
    p.add_argument("d0", type=float, help="m, orifice diameter")
    p.add_argument("toml")
    p.add_argument("outdir")
    p.add_argument("--width", type=float, default=0.06, help="m, silo width L (square)")
    p.add_argument("--count", type=int, default=2000, help="bodies")
    p.add_argument("--height", type=float, default=0.2, help="m, top of the generation region")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--t-open", type=float, default=0.4, help="s, the lid is removed then")
    p.add_argument("--duration", type=float, default=0.9, help="s")
    p.add_argument("--dt", type=float, default=1e-5, help="s")
    p.add_argument("--every", type=float, default=0.005, help="s, body (clumps) or particle (spheres) CSV interval")
    a = p.parse_args()
    h = a.width / 2.0 - 0.0005
    gen = (f'region = "box", min = [{-h!r}, {-h!r}, 0.002], max = [{h!r}, {h!r}, {a.height!r}], '
           f"count = {a.count}, seed = {a.seed}")
    name = f"{round(a.d0 * 1e3):d}"
    # Spheres have no body CSV: their particle CSV series gives the flow; clumps write only the
    # (smaller) body CSV series, and one particle CSV at the end.
    series = (f"body_csv_every = {a.every!r}\nparticle_csv_every = {a.duration!r}" if a.shape == "tetra"
              else f"particle_csv_every = {a.every!r}")
    text = f"""# Flat-bottomed silo (examples/clumps/silo, written by make_scene.py): {a.count} {a.shape} bodies
# settle on a lid over a {a.d0} m orifice, the lid is removed at t = {a.t_open} s and the bodies fall
# into an open box 0.1 m below. Units SI: m, s, kg, Pa.

{physics_toml(a.duration, a.dt)}
{bodies_toml(a.shape, gen)}
[[barriers]]
file = "walls.csv"        # four side walls, x, y in [-L/2, L/2], z in [0, 0.25] m
material = "grain"

[[barriers]]
file = "floor_{name}.csv"   # the floor, z = 0, with a circular orifice of diameter {a.d0} m
material = "grain"

[[barriers]]
file = "lid_{name}.csv"     # a square lid over the orifice, flush with the floor, removed at t_open
material = "grain"
active = [0.0, {a.t_open!r}]

[[barriers]]
file = "catcher.csv"      # open box, floor at z = -0.1 m: the discharged bodies come to rest here
material = "grain"

[domain]
min = [-0.26, -0.26, -0.11]
max = [0.26, 0.26, 0.27]

[checks]
max_overlap = 0.3         # soft grains: the first of the fill hit the lid at ~2 m/s
energy_drift = 0.5

[output]
dir = "{a.outdir}"
log_every = 1000
{series}
progress_every = 30
"""
    open(a.toml, "w").write(text)
    print(f"{a.toml}: {a.shape}, D0 = {a.d0} m, equal-volume sphere radius {R_EQ:.6g} m")


if __name__ == "__main__":
    main()
