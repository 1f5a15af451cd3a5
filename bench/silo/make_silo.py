#!/usr/bin/env python3
"""Writes the flowing benchmark's start state for both codes (docs/benchmark.md, "Flowing silo").

Usage: make_silo.py OUTDIR [--particles N] [--seed S]
       make_silo.py OUTDIR --from-snapshot particles_NNNNNN.csv

The silo is `mpdem mesh funnel` (run by scripts/bench_silo_vs_liggghts.sh): a cone from the
outlet (z = 0, radius OUTLET_R) to the top of the cone (z = CONE_H, radius R), a cylinder above.
The spheres (diameter D, all equal, as in the settled-bed benchmark) start at rest on a square
lattice of spacing SPACING with a small random shift each, filling the cone and the cylinder from
the bottom up, each at least GAP_WALL from the walls. The benchmark lets them settle on a closed
outlet in mpdem first; --from-snapshot then reads that run's last particle CSV (ids, positions)
and writes the settled bed for both codes, at rest. Writes, with the same ids and numbers:
  OUTDIR/particles.data  LAMMPS/LIGGGHTS data file (atom_style granular: id type diameter density x y z)
  OUTDIR/particles.csv   mpdem particle CSV (id, x, y, z, radius)
Only the standard library: the same seed gives the same file on every machine.
"""
import argparse
import math
import os
import random

D = 0.002  # m, sphere diameter
DENSITY = 2500.0  # kg/m^3
R = 0.025  # m, radius of the cylinder (top of the cone)
OUTLET_R = 0.01  # m, outlet radius: orifice diameter 20 mm = 10 d
CONE_H = 0.03  # m, cone height (half-angle atan(15/30) = 26.6 deg from the axis)
SPACING = 0.0021  # m, lattice spacing
JITTER = 0.00004  # m, largest shift per coordinate (spheres stay >= 2.02 mm apart)
GAP_WALL = 0.0002  # m, least gap between a sphere and a wall at the start
BOX = (-0.03, 0.03, -0.03, 0.03, -0.02, 0.25)  # m, the domain (spheres below z = -0.02 leave)


def lattice(n, seed):
    """The first n lattice sites inside the silo, bottom up, each with its random shift."""
    rng = random.Random(seed)
    r = D / 2
    tan_half = (R - OUTLET_R) / CONE_H
    cos_half = 1.0 / math.sqrt(1.0 + tan_half * tan_half)
    half = int(R / SPACING) + 1
    out = []
    k = 0
    while len(out) < n:
        z = r + GAP_WALL + k * SPACING
        if z + r > BOX[5] - 0.01:
            raise SystemExit(f"make_silo.py: only {len(out)} spheres fit below z = {BOX[5] - 0.01} m")
        for j in range(-half, half + 1):
            for i in range(-half, half + 1):
                x, y = i * SPACING, j * SPACING
                rho = math.hypot(x, y)
                # Distance to the wall: the cylinder above the cone, the slanted cone below
                # (measured square to the cone's surface).
                wall = R - rho if z >= CONE_H else (OUTLET_R + tan_half * z - rho) * cos_half
                if wall < r + GAP_WALL + 2 * JITTER:
                    continue
                out.append((x + rng.uniform(-JITTER, JITTER), y + rng.uniform(-JITTER, JITTER),
                            z + rng.uniform(-JITTER, JITTER)))
                if len(out) == n:
                    return out
        k += 1
    return out


def read_snapshot(path):
    """(id, x, y, z) of every sphere of an mpdem particle CSV snapshot, by id."""
    with open(path) as f:
        rows = [line.strip() for line in f if line.strip() and not line.startswith("#")]
    head = [c.strip() for c in rows[0].split(",")]
    col = {name: head.index(name) for name in ("id", "x", "y", "z")}
    out = []
    for row in rows[1:]:
        v = row.split(",")
        out.append((int(v[col["id"]]), float(v[col["x"]]), float(v[col["y"]]), float(v[col["z"]])))
    return [p[1:] for p in sorted(out)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--particles", type=int, default=20000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--from-snapshot", help="an mpdem particle CSV: write its spheres, at rest")
    a = ap.parse_args()
    pts = read_snapshot(a.from_snapshot) if a.from_snapshot else lattice(a.particles, a.seed)
    os.makedirs(a.outdir, exist_ok=True)
    with open(os.path.join(a.outdir, "particles.data"), "w") as f:
        f.write("flowing silo benchmark (scripts/bench_silo_vs_liggghts.sh)\n\n")
        f.write(f"{len(pts)} atoms\n1 atom types\n\n")
        f.write(f"{BOX[0]} {BOX[1]} xlo xhi\n{BOX[2]} {BOX[3]} ylo yhi\n{BOX[4]} {BOX[5]} zlo zhi\n\nAtoms\n\n")
        for i, (x, y, z) in enumerate(pts):
            f.write(f"{i + 1} 1 {D!r} {DENSITY!r} {x!r} {y!r} {z!r}\n")
    with open(os.path.join(a.outdir, "particles.csv"), "w") as f:
        f.write("id,x,y,z,radius\n")
        for i, (x, y, z) in enumerate(pts):
            f.write(f"{i + 1},{x!r},{y!r},{z!r},{D / 2!r}\n")
    top = max(p[2] for p in pts) + D / 2
    print(f"make_silo.py: {len(pts)} spheres, top of the fill z = {top:.4f} m")


if __name__ == "__main__":
    main()
