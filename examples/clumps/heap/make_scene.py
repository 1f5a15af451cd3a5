"""Write the heap scene (examples/clumps/heap): a rough disk of fixed spheres, a cylinder around it
lifted after the bodies settle, and the bodies: tetrahedral clumps or spheres of the same volume.

Usage: make_scene.py SHAPE OUT_TOML OUT_DIR [--rb M] [--count N] [--height M] [--seed S]
SHAPE is tetra or sphere. Writes base.csv (the fixed spheres) beside the scene. Units SI.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from shapes import R, bodies_toml, physics_toml  # noqa: E402


def write_base(path, rb, r):
    """Fixed spheres of radius r, touching, on a hexagonal grid at z = 0 within the disk of radius rb."""
    rows = []
    n = int(rb / (2.0 * r)) + 2
    for j in range(-2 * n, 2 * n + 1):
        for i in range(-2 * n, 2 * n + 1):
            x = 2.0 * r * (i + 0.5 * (j % 2))
            y = math.sqrt(3.0) * r * j
            if math.hypot(x, y) <= rb - r:
                rows.append((x, y))
    with open(path, "w") as f:
        f.write("id,x,y,z,radius\n")
        for k, (x, y) in enumerate(rows):
            f.write(f"{k},{x!r},{y!r},0.0,{r!r}\n")
    return len(rows)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("shape", choices=["tetra", "sphere"])
    p.add_argument("toml")
    p.add_argument("outdir")
    p.add_argument("--rb", type=float, default=0.036, help="m, radius of the disk and the cylinder")
    p.add_argument("--count", type=int, default=880, help="bodies")
    p.add_argument("--height", type=float, default=0.07, help="m, height of the generation region")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--settle", type=float, default=0.3, help="s, the cylinder is lifted from then on")
    p.add_argument("--lift", type=float, default=0.1, help="m/s, lifting speed")
    p.add_argument("--duration", type=float, default=1.0, help="s")
    p.add_argument("--dt", type=float, default=1e-5, help="s")
    a = p.parse_args()
    nbase = write_base("base.csv", a.rb, R)
    gen = (f'region = "cylinder", base = [0.0, 0.0, {2.0 * R!r}], axis = [0.0, 0.0, {a.height!r}], '
           f"cylinder_radius = {0.995 * a.rb!r}, count = {a.count}, seed = {a.seed}")
    bodies = bodies_toml(a.shape, gen)
    text = f"""# Heap on a rough disk (examples/clumps/heap, written by make_scene.py): {a.count} {a.shape} bodies
# generated in a cylinder of radius {a.rb} m settle, the cylinder is lifted at {a.lift} m/s from
# t = {a.settle} s, the material slumps and what passes the disk's edge falls to a floor below.
# Units SI: m, s, kg, Pa.

{physics_toml(a.duration, a.dt)}
[[particles]]
file = "base.csv"         # {nbase} fixed spheres of radius {R} m, touching: the rough disk
material = "grain"
fixed = true

{bodies}
[[barriers]]
file = "cylinder.csv"     # holds the bodies while they settle
material = "grain"
active = [0.0, {a.settle!r}]

[[barriers]]
file = "cylinder_lift.csv"  # the same cylinder, lifted
material = "grain"
active = [{a.settle!r}]
motion_from = "start"
motion = {{ a = [0.0, 0.0, {a.lift!r}] }}

[[barriers]]
file = "floor.csv"        # an open box 6 cm below the disk catches what falls off it
material = "grain"

[domain]
min = [-0.2, -0.2, -0.07]
max = [0.2, 0.2, 0.3]

[checks]
max_overlap = 0.2

[output]
dir = "{a.outdir}"
log_every = 1000
particle_csv_every = {a.duration / 10!r}
body_csv_every = {a.duration / 10!r}
progress_every = 30
"""
    open(a.toml, "w").write(text)


if __name__ == "__main__":
    main()
