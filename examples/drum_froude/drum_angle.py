#!/usr/bin/env python3
"""Dynamic angle of repose of the free surface in a rotating drum, from mpdem particle CSV
snapshots (`[output] particle_csv_every`, docs/output.md). Standard library only, so that the test
suite can run it without numpy (check.sh).

Geometry (must match the scene): drum axis along y through the origin, y in [-L/2, L/2], gravity
-z, drum turning at omega about +y (right-handed, omega > 0: the wall at -x rises, the bed is
carried up on the -x side and the free surface falls towards +x).

Per snapshot:
  1. keep the beads in the central slab |y| <= L/2 - y_margin (away from the end walls);
  2. keep the beads in contact with something: the total force of a bead in free flight is its
     weight m g, so a bead with |F - m g| <= 1e-6 m g is airborne (a bouncing bead above the
     surface) and is skipped;
  3. split the central part of the surface, |x| <= x_frac R, into bins of one bead diameter along
     x (the horizontal axis perpendicular to the drum axis) and take the centre of the highest
     bead in each bin;
  4. fit a straight line z = a + b x to those points (least squares); the angle is
     atan(-b sign(omega)) in degrees: positive when the surface is raised on the rising wall's
     side, i.e. inclined in the direction the drum turns.
The angles of the snapshots from t_from on are averaged (mean, sample standard deviation).

Command line (used by check.sh):
  drum_angle.py OUTPUT_DIR --drum-radius R --length L --omega W --t-from T [--density RHO]
                [--y-margin DIAMETERS] [--expect-min DEG --expect-max DEG]
prints one line per snapshot and a summary; with --expect-min/--expect-max it exits 1 when the
mean angle is outside [min, max] or any snapshot's angle is not positive.
"""
import argparse
import csv
import glob
import math
import os
import statistics
import sys

G = 9.81  # m/s^2, |gravity| of the scene (along -z)


def read_snapshot(path):
    """Columns of one particle CSV snapshot as lists of floats (keyed by the header names)."""
    with open(path, newline="") as f:
        rows = csv.reader(line for line in f if line.strip() and not line.startswith("#"))
        header = [h.strip() for h in next(rows)]
        cols = {h: [] for h in header}
        for row in rows:
            for h, v in zip(header, row):
                cols[h].append(float(v))
    return cols


def snapshot_files(folder):
    """The particle CSV snapshots of an output folder, in time order."""
    return sorted(glob.glob(os.path.join(folder, "particles_csv", "particles_*.csv")))


def surface_points(cols, drum_radius, length, density=2500.0, x_frac=0.6, y_margin=None):
    """(x, z) of the highest bead in contact per bin of one diameter, |x| <= x_frac R,
    |y| <= L/2 - y_margin (default 1.5 diameters)."""
    radii = cols["radius"]
    d = 2.0 * max(radii)
    if y_margin is None:
        y_margin = 1.5 * d
    half = length / 2.0 - y_margin
    x_max = x_frac * drum_radius
    nbins = max(1, int(round(2.0 * x_max / d)))
    width = 2.0 * x_max / nbins
    best = [None] * nbins
    for x, y, z, r, fx, fy, fz in zip(cols["x"], cols["y"], cols["z"], radii, cols["fx"], cols["fy"], cols["fz"]):
        if abs(y) > half or abs(x) >= x_max:
            continue
        mg = 4.0 / 3.0 * math.pi * r ** 3 * density * G
        if math.sqrt(fx * fx + fy * fy + (fz + mg) ** 2) <= 1e-6 * mg:
            continue  # free flight: the force is the weight alone
        k = min(nbins - 1, int((x + x_max) / width))
        if best[k] is None or z > best[k][1]:
            best[k] = (x, z)
    return [p for p in best if p is not None]


def bead_radius(folder):
    """The largest bead radius of the run's first snapshot (m)."""
    return max(read_snapshot(snapshot_files(folder)[0])["radius"])


def fit_line(points):
    """Least-squares z = a + b x: (a, b)."""
    n = len(points)
    mx = sum(p[0] for p in points) / n
    mz = sum(p[1] for p in points) / n
    sxx = sum((p[0] - mx) ** 2 for p in points)
    sxz = sum((p[0] - mx) * (p[1] - mz) for p in points)
    b = sxz / sxx
    return mz - b * mx, b


def snapshot_angle(cols, drum_radius, length, omega, density=2500.0, y_margin=None):
    """(angle in degrees, intercept a, slope b, surface points) of one snapshot; None when fewer than
    4 bins have a bead in contact."""
    pts = surface_points(cols, drum_radius, length, density, y_margin=y_margin)
    if len(pts) < 4:
        return None  # no surface: the beads still falling at t = 0, or an empty drum
    a, b = fit_line(pts)
    sign = 1.0 if omega > 0 else -1.0
    return math.degrees(math.atan(-b * sign)), a, b, pts


def analyse(folder, drum_radius, length, omega, t_from, density=2500.0, y_margin=None):
    """[(time, angle deg, surface points used)] of the snapshots at t >= t_from, and the times of
    those without a surface (fewer than 4 points)."""
    out, skipped = [], []
    for f in snapshot_files(folder):
        cols = read_snapshot(f)
        t = cols["time"][0] if cols["time"] else 0.0
        if t < t_from - 1e-4:  # snapshot times fall within a step of the nominal ones
            continue
        res = snapshot_angle(cols, drum_radius, length, omega, density, y_margin)
        if res is None:
            skipped.append(t)
        else:
            out.append((t, res[0], len(res[3])))
    return out, skipped


def summary(series):
    """mean, sample std, count, drift (mean of the second half - mean of the first half)."""
    angles = [s[1] for s in series]
    n = len(angles)
    mean = statistics.fmean(angles)
    std = statistics.stdev(angles) if n > 1 else 0.0
    h = n // 2
    drift = statistics.fmean(angles[n - h:]) - statistics.fmean(angles[:h]) if h >= 1 else 0.0
    return mean, std, n, drift


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folder", help="output folder of the run (holds particles_csv/)")
    ap.add_argument("--drum-radius", type=float, required=True, help="m")
    ap.add_argument("--length", type=float, required=True, help="m, drum length along y")
    ap.add_argument("--omega", type=float, required=True, help="rad/s about +y")
    ap.add_argument("--t-from", type=float, required=True, help="s, first snapshot time used")
    ap.add_argument("--density", type=float, default=2500.0, help="kg/m^3 of the beads")
    ap.add_argument("--y-margin", type=float, default=1.5,
                    help="bead diameters: the slab used is |y| <= L/2 - y_margin d (default 1.5)")
    ap.add_argument("--expect-min", type=float, help="deg: fail below this mean angle")
    ap.add_argument("--expect-max", type=float, help="deg: fail above this mean angle")
    a = ap.parse_args(argv)
    series = analyse(a.folder, a.drum_radius, a.length, a.omega, a.t_from, a.density,
                     a.y_margin * 2.0 * bead_radius(a.folder))
    series, skipped = series
    if skipped:
        print(f"{len(skipped)} snapshot(s) without a surface (fewer than 4 bins with a bead in contact), "
              f"first at t = {skipped[0]:.4f} s")
    if not series:
        print(f"no snapshots with a surface at t >= {a.t_from} s in {a.folder}/particles_csv", file=sys.stderr)
        return 1
    for t, angle, n in series:
        print(f"t = {t:.4f} s  angle = {angle:7.2f} deg  ({n} surface points)")
    mean, std, n, drift = summary(series)
    fr = a.omega ** 2 * a.drum_radius / G
    print(f"omega = {a.omega:.4g} rad/s  Fr = {fr:.3g}  angle = {mean:.2f} +- {std:.2f} deg "
          f"over {n} snapshots (drift second half - first half {drift:+.2f} deg)")
    if a.expect_min is not None or a.expect_max is not None:
        lo = a.expect_min if a.expect_min is not None else -90.0
        hi = a.expect_max if a.expect_max is not None else 90.0
        bad = [s for s in series if s[1] <= 0.0]
        if skipped:
            print("FAIL: snapshots without a surface in the measurement window")
            return 1
        if bad:
            print(f"FAIL: {len(bad)} snapshot(s) with the surface not inclined in the turning direction "
                  f"(angle <= 0, first at t = {bad[0][0]:.4f} s: {bad[0][1]:.2f} deg)")
            return 1
        if not lo <= mean <= hi:
            print(f"FAIL: mean angle {mean:.2f} deg outside the plausible range [{lo:g}, {hi:g}] deg")
            return 1
        print(f"PASS: mean angle {mean:.2f} deg in [{lo:g}, {hi:g}] deg, every snapshot inclined "
              f"in the turning direction")
    return 0


if __name__ == "__main__":
    sys.exit(main())
