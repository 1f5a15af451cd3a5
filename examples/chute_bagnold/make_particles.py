"""Writes the particles of the periodic chute (examples/chute_bagnold): a rough base of fixed
spheres and a loose lattice of free spheres above it. Standard library only.

    python3 make_particles.py [--nx 10 --ny 12 --layers 34 --base random --v-surface 0.7
                               --out particles.csv --seed 1]

Geometry (SI units, d = 1 mm the mean diameter). The periods are L_x = nx a, L_y = ny a sqrt(3)/2
with a = 1.05 d (ny even), the size of a hexagonal layer:
- base (fixed = 1), equal spheres of diameter d: `--base random` (run.sh) places them by random
  sequential addition in the periodic slab 0 <= z <= 0.6 d, centres >= d apart, until 20000
  tries in a row fail; `--base hex` (default) is the hexagonal layer, centres a apart, each
  lifted by a random height in [0, 0.3 d] (it lets the flow slip and layer: README);
- flow: a simple lattice of nx' x ny' x layers sites (nx' = floor(L_x / 1.15 d), the same along
  y, vertical spacing 1.15 d, first layer 1.4 d (hex) or 1.7 d (random) above z = 0), radii uniform in
  [0.45, 0.55] mm (+-10 %: no crystallisation), each centre jittered by up to 0.02 d (fixed = 0);
  at rest, or with --v-surface V a guess of the steady profile, v_x = V [1 - (1 - k/layers)^1.5]
  for layer k (V in m/s), which shortens the transient (on the hex base, starts with V = 0.5 and
  1.2 m/s reached the same mean velocity). Sites are at least 1.15 d apart, more than the
  largest diameter (1.1 d), so
  nothing overlaps, also across the periodic faces.
Prints the period and the counts as shell assignments (for run.sh and the scene).
"""
import argparse
import math
import random

D = 1.0e-3          # m, mean diameter
A_BASE = 1.05 * D   # m, base lattice spacing
SPACING = 1.15 * D  # m, flow lattice spacing (> largest diameter 1.1 d)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nx", type=int, default=10)
    ap.add_argument("--ny", type=int, default=12)
    ap.add_argument("--layers", type=int, default=34)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="particles.csv")
    ap.add_argument("--v-surface", type=float, default=0.0, help="m/s, initial surface velocity")
    ap.add_argument("--base", choices=["hex", "random"], default="hex")
    args = ap.parse_args()
    if args.ny % 2:
        raise SystemExit("--ny must be even (hexagonal rows repeat every two)")
    rng = random.Random(args.seed)
    lx = args.nx * A_BASE
    ly = args.ny * A_BASE * math.sqrt(3.0) / 2.0
    rows = []
    pid = 0
    if args.base == "random":
        # random sequential addition in the periodic slab 0 <= z <= 0.6 d, centres >= d apart in
        # 3D, tried until 20000 tries in a row fail: nearly saturated, so that no hole lets a
        # sphere through
        pts = []
        fails = 0
        while fails < 20000:
            x, y, z = rng.uniform(0.0, lx), rng.uniform(0.0, ly), rng.uniform(0.0, 0.6 * D)
            ok = True
            for (px, py, pz) in pts:
                dx = (x - px) - lx * round((x - px) / lx)
                dy = (y - py) - ly * round((y - py) / ly)
                if dx * dx + dy * dy + (z - pz) ** 2 < D * D:
                    ok = False
                    break
            if ok:
                pts.append((x, y, z))
                fails = 0
            else:
                fails += 1
        for (x, y, z) in pts:
            rows.append((pid, x, y, z, 0.0, 0.5 * D, 1))
            pid += 1
    for j in range(args.ny if args.base == "hex" else 0):
        for i in range(args.nx):
            x = (i + 0.5 * (j % 2) + 0.25) * A_BASE
            y = (j + 0.5) * A_BASE * math.sqrt(3.0) / 2.0
            z = rng.uniform(0.0, 0.3 * D)
            rows.append((pid, x, y, z, 0.0, 0.5 * D, 1))
            pid += 1
    n_base = pid
    z0 = 1.4 * D if args.base == "hex" else 1.7 * D  # m, first flow layer (clear of the base)
    mx = int(lx / SPACING)
    my = int(ly / SPACING)
    sx, sy = lx / mx, ly / my
    for k in range(args.layers):
        for j in range(my):
            for i in range(mx):
                x = (i + 0.5) * sx + rng.uniform(-0.02, 0.02) * D
                y = (j + 0.5) * sy + rng.uniform(-0.02, 0.02) * D
                z = z0 + k * SPACING + rng.uniform(-0.02, 0.02) * D
                r = rng.uniform(0.45, 0.55) * D
                vx = args.v_surface * (1.0 - (1.0 - k / args.layers) ** 1.5)
                rows.append((pid, x, y, z, vx, r, 0))
                pid += 1
    with open(args.out, "w") as f:
        f.write("# periodic chute: rough base (fixed = 1) and a loose lattice of free spheres\n")
        f.write("id,x,y,z,vx,radius,fixed\n")
        for r in rows:
            f.write("%d,%.9g,%.9g,%.9g,%.9g,%.9g,%d\n" % r)
    print("LX=%.9g LY=%.9g N_BASE=%d N_FLOW=%d" % (lx, ly, n_base, pid - n_base))


if __name__ == "__main__":
    main()
