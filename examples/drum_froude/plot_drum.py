#!/usr/bin/env python3
"""Rotating drum: the results table and plots from the runs that run.sh lists in RUNS
(one line per speed: name, omega rad/s, first snapshot time used s, output folder).

    plot_drum.py --drum-radius R --length L output/runs.txt

Prints the table (run.sh writes it to results.txt) and writes
  drum_angle_vs_froude.png   dynamic angle against Fr = omega^2 R / g (log x, +- one std)
  drum_angle_time.png        angle of every snapshot against the angle turned (transient, steadiness)
  drum_surface.png           the beads of the central slab, the surface points and the fit, last
                             snapshot of every speed
The angle measurement is drum_angle.py's (standard library); matplotlib only draws.
"""
import argparse
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import drum_angle as da

HERE = os.path.dirname(os.path.abspath(__file__))


def energy(folder):
    """(drift of the energy balance over the run, energy dissipated, drum work), J, from log.csv."""
    with open(os.path.join(folder, "log.csv")) as f:
        rows = [line.strip().split(",") for line in f if line.strip()]
    col = {h: i for i, h in enumerate(rows[0])}
    first, last = rows[1], rows[-1]
    drift = float(last[col["total_energy"]]) - float(first[col["total_energy"]])
    diss = float(last[col["damping_dissipated"]]) + float(last[col["friction_dissipated"]])
    return drift, diss, float(last[col["barrier_work"]])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs")
    ap.add_argument("--drum-radius", type=float, required=True)
    ap.add_argument("--length", type=float, required=True)
    a = ap.parse_args()
    runs = []
    with open(a.runs) as f:
        for line in f:
            if line.strip():
                name, w, t_from, folder = line.split()
                runs.append((name, float(w), float(t_from), os.path.join(HERE, folder)))

    rows = []
    print(f"# Rotating drum R = {a.drum_radius} m, L = {a.length} m: dynamic angle of repose of the free "
          f"surface (central |x| <= 0.6 R, |y| <= L/2 - 1.5 d),")
    print("# mean and sample std over the particle CSV snapshots after the transient; drift = mean of the "
          "second half of the snapshots - mean of the first half")
    print("# energy: drift of the engine's energy balance over the run / energy dissipated (damping + friction)")
    print(f"# {'omega rad/s':>11} {'Fr':>9} {'angle deg':>9} {'std deg':>7} {'snapshots':>9} {'drift deg':>9} {'energy':>7}")
    for name, w, t_from, folder in runs:
        series, skipped = da.analyse(folder, a.drum_radius, a.length, w, t_from)
        if skipped:
            raise SystemExit(f"{folder}: snapshots without a surface after the transient at t = {skipped}")
        mean, std, n, drift = da.summary(series)
        fr = w * w * a.drum_radius / da.G
        rows.append((name, w, fr, mean, std, n, drift, t_from, series, folder))
        e_drift, e_diss, _ = energy(folder)
        print(f"  {w:11.4f} {fr:9.2e} {mean:9.2f} {std:7.2f} {n:9d} {drift:+9.2f} {e_drift / e_diss:+7.2%}")

    # angle against Fr
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.errorbar([r[2] for r in rows], [r[3] for r in rows], yerr=[r[4] for r in rows], fmt="o-",
                capsize=4, label="mpdem (mean +- std over snapshots)")
    ax.set_xscale("log")
    ax.set_xlim(5e-5, 2e-2)
    ax.axvspan(1e-4, 1e-2, color="0.92", zorder=0, label="rolling regime (Mellmann 2001)")
    ax.set_xlabel("Froude number Fr = omega^2 R / g")
    ax.set_ylabel("dynamic angle of repose (deg)")
    lo = min(r[3] - r[4] for r in rows)
    hi = max(r[3] + r[4] for r in rows)
    ax.set_ylim(math.floor(lo / 5) * 5 - 5, math.ceil(hi / 5) * 5 + 5)
    ax.set_title(f"drum D = {2 * a.drum_radius:g} m, {a.length * 1e3:g} mm long, "
                 f"beads d = {2e3 * da.bead_radius(rows[0][-1]):g} mm", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "drum_angle_vs_froude.png"), dpi=120)

    # angle of every snapshot against the angle turned since the restart
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for name, w, fr, mean, std, n, drift, t_from, series, folder in rows:
        whole, _ = da.analyse(folder, a.drum_radius, a.length, w, 0.0)  # transient included
        ax.plot([s[0] * w for s in whole], [s[1] for s in whole], "o-", ms=2, lw=0.8, label=f"Fr = {fr:.1e}")
    ax.axvline(rows[0][7] * rows[0][1], color="k", lw=0.8, ls="--")
    ax.text(rows[0][7] * rows[0][1], ax.get_ylim()[0], " measurement", fontsize=8, va="bottom")
    ax.set_xlabel("angle turned by the drum (rad)")
    ax.set_ylabel("surface angle of the snapshot (deg)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "drum_angle_time.png"), dpi=120)

    # the surface of the last snapshot of every speed
    fig, axes = plt.subplots(1, len(rows), figsize=(3.6 * len(rows), 3.8), squeeze=False)
    half = a.length / 2
    for ax, (name, w, fr, mean, std, n, drift, t_from, series, folder) in zip(axes[0], rows):
        cols = da.read_snapshot(da.snapshot_files(folder)[-1])
        angle, ia, ib, pts = da.snapshot_angle(cols, a.drum_radius, a.length, w)  # has a surface: checked above
        d = 2 * max(cols["radius"])
        sel = [i for i, y in enumerate(cols["y"]) if abs(y) <= half - 1.5 * d]
        ax.scatter([cols["x"][i] * 1e3 for i in sel], [cols["z"][i] * 1e3 for i in sel], s=4, c="0.6")
        ax.plot([p[0] * 1e3 for p in pts], [p[1] * 1e3 for p in pts], "r.", ms=6)
        xm = 0.6 * a.drum_radius
        ax.plot([-xm * 1e3, xm * 1e3], [(ia - ib * xm) * 1e3, (ia + ib * xm) * 1e3], "r-", lw=1)
        t = [2 * math.pi * k / 200 for k in range(201)]
        ax.plot([a.drum_radius * 1e3 * math.cos(s) for s in t], [a.drum_radius * 1e3 * math.sin(s) for s in t], "k-", lw=1)
        xa = -1.12 * a.drum_radius * 1e3  # arrow just outside the rising wall (-x side for omega > 0)
        ax.annotate("", xy=(xa, 0.3 * a.drum_radius * 1e3), xytext=(xa, -0.3 * a.drum_radius * 1e3),
                    arrowprops=dict(arrowstyle="->", color="b"))
        ax.set_xlim(-1.25 * a.drum_radius * 1e3, 1.1 * a.drum_radius * 1e3)
        ax.set_aspect("equal")
        ax.set_title(f"Fr = {fr:.1e}, t = {cols['time'][0]:.2f} s: {angle:.1f} deg", fontsize=9)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("z (mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "drum_surface.png"), dpi=120)


if __name__ == "__main__":
    main()
