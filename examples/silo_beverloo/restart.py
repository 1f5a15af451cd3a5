#!/usr/bin/env python3
"""Seed the discharge runs with the settled fill: writes a particle input CSV (docs/scene.md
"Particle CSV") from the last particle CSV snapshot of a run.

    restart.py OUTPUT_DIR OUT.csv

Standard library only.
"""
import csv
import glob
import os
import sys

KEEP = ["id", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "radius", "material"]


def main(argv):
    folder, out = argv
    files = sorted(glob.glob(os.path.join(folder, "particles_csv", "particles_*.csv")))
    if not files:
        print(f"no particle CSV snapshot in {folder}/particles_csv", file=sys.stderr)
        return 1
    with open(files[-1], newline="") as f:
        rows = list(csv.DictReader(line for line in f if line.strip() and not line.startswith("#")))
    with open(out, "w", newline="") as f:
        f.write(f"# from {os.path.relpath(files[-1])} at t = {rows[0]['time'].strip()} s\n")
        f.write(",".join(KEEP) + "\n")
        for r in rows:
            r = {k.strip(): v.strip() for k, v in r.items()}
            f.write(",".join(r[k] for k in KEEP) + "\n")
    print(f"{out}: {len(rows)} particles from {os.path.relpath(files[-1])}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
