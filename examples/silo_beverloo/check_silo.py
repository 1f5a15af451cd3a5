#!/usr/bin/env python3
"""Assertions of the silo example's short check (check.sh; ctest -L examples). Standard library only.

    check_silo.py OUTPUT_DIR --t-open T

Reads log.csv (the inlets' and sinks' columns, docs/output.md), barrier_groups.csv and the last
particle CSV snapshot of a run with two silos: inlet feedA / lid lidA / sink outA (orifice 30 mm)
and feedB / lidB / outB (orifice 40 mm). Every failed assertion is printed; exit status 1 if any.

Tolerances and why:
- before the lids open (t < T): removed mass of both sinks exactly 0 and no bead left through the
  domain boundary (a lid that leaks or opens early fails); each lid is pushed down (fz < 0) by
  at least half the weight of a column of beads of its area as high as the settled bed less 2 d
  at t = T - 0.01 s (Janssen screening on the walls makes it less than the full column; a lid that
  does not act carries nothing);
- after T: the lids' force is exactly 0 (docs/scene.md: an inactive element takes part in nothing) in
  every barrier_groups.csv row from T + 2 ms on (each row is the mean over the 2 ms before it);
- first removal of each sink in (T, T + 0.1] s: the beads above the hole fall ~25 mm to the sink
  (~0.07 s); later than 0.1 s means the flow did not start;
- larger orifice faster: mass removed by the end of the run (0.12 s after T), B / A. Beverloo's
  5/2 law gives ((8 - k) / (6 - k))^(5/2) = 2.05 (k = 0) to 2.9 (k = 2) for 40 vs 30 mm; the
  bound [1.5, 5] is wide (the short, shallow run is still accelerating); a ratio near 1 (flow
  not set by the orifice) or above 5 fails;
- conservation: inserted = present + removed, counts exactly, masses to 1e-12 relative (the
  present beads' masses are recomputed here from radius and density, which can differ from the
  engine's in the last bit: 1e-12 is far above that and far below one bead, 1e-4 of the total).
"""
import argparse
import csv
import glob
import math
import os
import sys

RHO = 2500.0
G = 9.81


def rows(path):
    with open(path, newline="") as f:
        return [{k.strip(): v.strip() for k, v in r.items()}
                for r in csv.DictReader(l for l in f if l.strip() and not l.startswith("#"))]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--t-open", type=float, required=True)
    a = ap.parse_args()
    t_open = a.t_open
    log = rows(os.path.join(a.folder, "log.csv"))
    bar = rows(os.path.join(a.folder, "barrier_groups.csv"))
    snap = rows(sorted(glob.glob(os.path.join(a.folder, "particles_csv", "particles_*.csv")))[-1])
    fails = []

    def check(ok, what):
        print(("ok    " if ok else "FAIL  ") + what)
        if not ok:
            fails.append(what)

    t = [float(r["time"]) for r in log]
    for s in ("outA", "outB"):
        before = [float(r[s + ".removed_mass"]) for r, ti in zip(log, t) if ti < t_open]
        check(max(before) == 0.0, f"{s}: removed mass before t = {t_open} s is {max(before):.3g} kg (expected 0)")
        first = next((ti for r, ti in zip(log, t) if int(r[s + ".removed"]) > 0), math.inf)
        check(t_open < first <= t_open + 0.1, f"{s}: first removal logged at t = {first:.4f} s (expected in "
              f"({t_open:g}, {t_open + 0.1:g}])")
    check(all(int(r["removed"]) == 0 for r in log), "no bead left through the domain boundary")

    # lids: loaded before the opening, exactly unloaded after it
    d = 2 * sum(float(r["radius"]) for r in snap) / len(snap)
    tb = [float(r["time"]) for r in bar]
    i_before = max(i for i, ti in enumerate(tb) if ti <= t_open - 0.01)
    for s, side, x0 in (("A", 0.03, -0.05), ("B", 0.04, 0.05)):
        fz = float(bar[i_before][f"lid{s}.fz"])
        # settled bed height from the inserted mass (solid fraction ~0.6 over the 65 mm silo)
        m_in = float(log[-1][f"feed{s}.inserted_mass"])
        h = m_in / (0.6 * RHO * 0.065 ** 2)
        col = 0.6 * RHO * G * side * side * max(h - 2 * d, 0.0)
        check(fz < -0.5 * col, f"lid{s}: fz = {fz:.4g} N at t = {tb[i_before]:.3f} s (expected below "
              f"-{0.5 * col:.3g} N, half a {h * 1e3:.0f} - 2 d mm column's weight)")
        after = [abs(float(r[f"lid{s}.fz"])) + abs(float(r[f"lid{s}.fx"])) + abs(float(r[f"lid{s}.fy"]))
                 for r, ti in zip(bar, tb) if ti >= t_open + 0.001]  # rows are means over 2 ms before them
        check(len(after) > 0 and max(after) == 0.0, f"lid{s}: largest force after t = {t_open} s is "
              f"{max(after) if after else float('nan'):.3g} N (expected exactly 0)")

    # the larger orifice discharges faster
    ma = float(log[-1]["outA.removed_mass"])
    mb = float(log[-1]["outB.removed_mass"])
    ratio = mb / ma if ma > 0 else math.inf
    check(1.5 <= ratio <= 5.0, f"removed by t = {t[-1]:.3f} s: A (30 mm) {ma:.4g} kg, B (40 mm) {mb:.4g} kg, "
          f"ratio {ratio:.3f} (expected in [1.5, 5]; 5/2 law: 2.05-2.9)")

    # conservation: inserted = present + removed
    last = log[-1]
    n_in = int(last["feedA.inserted"]) + int(last["feedB.inserted"])
    n_out = int(last["outA.removed"]) + int(last["outB.removed"])
    check(n_in == len(snap) + n_out and int(last["particles"]) == len(snap),
          f"counts: inserted {n_in} = present {len(snap)} + removed {n_out}")
    m_in = float(last["feedA.inserted_mass"]) + float(last["feedB.inserted_mass"])
    m_now = math.fsum(4.0 / 3.0 * math.pi * float(r["radius"]) ** 3 * RHO for r in snap)
    m_out = ma + mb
    rel = abs(m_in - (m_now + m_out)) / m_in
    check(rel <= 1e-12, f"mass: inserted {m_in!r} kg, present {m_now!r} + removed {m_out!r} kg, relative "
          f"difference {rel:.3g} (expected <= 1e-12)")
    check(abs(float(snap[0]["time"]) - t[-1]) < 1e-9, "the snapshot is at the log's last time")
    if fails:
        print(f"{len(fails)} check(s) failed")
        return 1
    print("all silo checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
