"""Angle of repose of a heap on a disk from a particle CSV snapshot (examples/clumps/heap).

The heap is every particle that is not fixed and lies above the disk (z > -R_DISK / 4; what fell
off the edge rests on the floor far below). Its surface profile is taken in N_SECTORS azimuthal
sectors: in radial bins of BIN m the top of the highest particle (z + radius). A straight line
fitted by least squares to each sector's profile between FIT_LO and FIT_HI times the disk radius
(clear of the rounded apex and of the toe at the disk's edge) gives that sector's angle,
atan(-slope); the angle of repose is the mean over the sectors and its +- the standard error
(std / sqrt(N_SECTORS)). A second estimate from the apex alone: atan((apex - base top) / R_disk),
with the apex the highest top within 2 BIN of the axis.

Python's standard library only (the test suite runs it). Usage as a script:
  heap_angle.py RUN_DIR R_DISK [--label L]            prints one line of numbers
"""

import csv
import glob
import math
import os
import sys

N_SECTORS = 8
FIT_LO, FIT_HI = 0.3, 0.9  # of the disk radius


def last_snapshot(run_dir):
    files = sorted(glob.glob(os.path.join(run_dir, "particles_csv", "particles_*.csv")))
    if not files:
        sys.exit(f"heap_angle.py: no particle CSV snapshot in {run_dir}/particles_csv")
    return files[-1]


def read_particles(path):
    """Rows of (x, y, z, radius, fixed, body, speed) of one snapshot, and its time (s)."""
    rows, t = [], None
    with open(path) as f:
        for r in csv.DictReader(f):
            t = float(r["time"])
            rows.append((float(r["x"]), float(r["y"]), float(r["z"]), float(r["radius"]), int(r["fixed"]),
                         int(r["body"]), math.hypot(float(r["vx"]), float(r["vy"]), float(r["vz"]))))
    return rows, t


def line_fit(xs, ys):
    """Least-squares slope and intercept."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    slope = sxy / sxx
    return slope, my - slope * mx


def profile(points, r_disk, bin_width, sector=None):
    """Bin centres (m) and the highest top (m) in each radial bin [of one sector] that holds a particle."""
    nb = int(math.ceil(r_disk / bin_width))
    top = [None] * nb
    for rho, phi, h in points:
        if sector is not None and int(phi / (2.0 * math.pi) * N_SECTORS) % N_SECTORS != sector:
            continue
        k = int(rho / bin_width)
        if k < nb and (top[k] is None or h > top[k]):
            top[k] = h
    return [((k + 0.5) * bin_width, h) for k, h in enumerate(top) if h is not None]


def measure(run_dir, r_disk, bin_width=None):
    """The heap's numbers (dict) from the last snapshot of run_dir."""
    bin_width = bin_width or r_disk / 12.0
    rows, t = read_particles(last_snapshot(run_dir))
    heap = [(x, y, z, r, b) for x, y, z, r, fixed, b, v in rows if not fixed and z > -r_disk / 4.0]
    speeds = [v for x, y, z, r, fixed, b, v in rows if not fixed and z > -r_disk / 4.0]
    base_top = max(z + r for x, y, z, r, fixed, b, v in rows if fixed)
    points = [(math.hypot(x, y), math.atan2(y, x) % (2.0 * math.pi), z + r) for x, y, z, r, b in heap]
    angles, fits = [], []
    for s in range(N_SECTORS):
        prof = [(p, h) for p, h in profile(points, r_disk, bin_width, s) if FIT_LO * r_disk <= p <= FIT_HI * r_disk]
        if len(prof) < 3:
            continue
        slope, icpt = line_fit([p for p, h in prof], [h for p, h in prof])
        angles.append(math.degrees(math.atan(-slope)))
        fits.append((slope, icpt))
    mean = sum(angles) / len(angles)
    sd = math.sqrt(sum((a - mean) ** 2 for a in angles) / max(len(angles) - 1, 1))
    apex = max(h for p, phi, h in points if p < 2.0 * bin_width)
    bodies = {b for x, y, z, r, b in heap if b >= 0}
    n_heap = len(bodies) if bodies else len(heap)
    return {"time": t, "angle": mean, "err": sd / math.sqrt(len(angles)), "sectors": angles,
            "apex_angle": math.degrees(math.atan((apex - base_top) / r_disk)), "apex": apex,
            "base_top": base_top, "bodies_on_disk": n_heap, "fits": fits, "points": points,
            "bin": bin_width, "max_speed": max(speeds), "mean_speed": sum(speeds) / len(speeds)}


def main():
    import argparse
    p = argparse.ArgumentParser()
    p.add_argument("run_dir")
    p.add_argument("r_disk", type=float)
    p.add_argument("--label", default="")
    a = p.parse_args()
    m = measure(a.run_dir, a.r_disk)
    print(f"{a.label} t = {m['time']:.3f} s: angle {m['angle']:.1f} +- {m['err']:.1f} deg (sectors "
          + " ".join(f"{x:.1f}" for x in m["sectors"]) + f"), apex angle {m['apex_angle']:.1f} deg, "
          f"{m['bodies_on_disk']} bodies on the disk, speeds mean {m['mean_speed']:.2g} max {m['max_speed']:.2g} m/s")


if __name__ == "__main__":
    main()
