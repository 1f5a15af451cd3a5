"""Discharge rate of one silo run (examples/clumps/silo) from its CSV series.

The mass below the orifice plane, M(t) (kg), is summed over the bodies whose centre of mass is
below z = 0 in each snapshot: the body CSV series for clumps (its mass column), the particle CSV
series for spheres (mass rho 4/3 pi r^3). The discharge rate W (kg/s) is the slope of a
least-squares line through M(t) from SKIP s after the lid is removed (the flow is established) to
the end of the run; its +- is the standard error from the slopes of the window's four quarters
(std / 2). The runs end before the head above the orifice falls below about one orifice diameter.
A run whose M(t) stays constant for STALL s or more after the flow started has jammed (an arch
over the orifice): its window ends there, and the jam is reported.

Python's standard library only (the test suite runs it). Usage as a script:
  silo_rate.py RUN_DIR --t-open T [--width L] [--density RHO] [--label L]     prints one line
"""

import csv
import glob
import math
import os
import sys

SKIP = 0.1  # s
STALL = 0.1  # s


def series(run_dir, density=2500.0):
    """Times (s), the mass below z = 0 (kg) at each, and the total mass (kg), from the body CSV
    series if there is one, else from the particle CSV series."""
    files = sorted(glob.glob(os.path.join(run_dir, "bodies_csv", "bodies_*.csv")))
    bodies = bool(files)
    if not bodies:
        files = sorted(glob.glob(os.path.join(run_dir, "particles_csv", "particles_*.csv")))
    if len(files) < 3:
        sys.exit(f"silo_rate.py: no CSV series in {run_dir}")
    ts, below, total, zmean = [], [], 0.0, []
    for path in files:
        t, m_below, m_all, mz = None, 0.0, 0.0, 0.0
        with open(path) as f:
            for r in csv.DictReader(f):
                t = float(r["time"])
                m = float(r["mass"]) if bodies else density * 4.0 / 3.0 * math.pi * float(r["radius"]) ** 3
                m_all += m
                mz += m * float(r["z"])
                if float(r["z"]) < 0.0:
                    m_below += m
        ts.append(t)
        below.append(m_below)
        zmean.append(mz / m_all)
        total = m_all
    return ts, below, total, zmean


def slope(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def measure(run_dir, t_open, density=2500.0, width=None):
    """The run's numbers (dict). With the silo's width and the lid's removal time, also the settled
    fill's bulk density (kg/m^3): the mass over width^2 times twice the height of its centre of mass
    (a uniform fill from z = 0), from the last snapshot before t_open."""
    ts, m, total, zmean = series(run_dir, density)
    bulk = None
    if width:
        k = max(j for j, t in enumerate(ts) if t < t_open)
        bulk = total / (width * width * 2.0 * zmean[k])
    first = next((k for k, v in enumerate(m) if v > 0.0), None)
    out = {"t": ts, "m": m, "total": total, "jam": None, "reached": m[-1] / total, "bulk": bulk,
           "first": None if first is None else ts[first], "before": max(v for t, v in zip(ts, m) if t <= t_open)}
    if first is None:
        out.update(rate=0.0, err=0.0, window=None)
        return out
    lo = next(k for k, t in enumerate(ts) if t >= t_open + SKIP - 1e-9)
    hi = len(m) - 1
    # A jam: M unchanged for STALL s.
    for k in range(first, hi + 1):
        later = [j for j in range(k, len(m)) if ts[j] - ts[k] >= STALL]
        if later and m[later[0]] == m[k]:
            out["jam"] = ts[k]
            hi = k
            break
    if hi - lo < 8:
        out.update(rate=float("nan"), err=float("nan"), window=None)
        return out
    xs, ys = ts[lo:hi + 1], m[lo:hi + 1]
    w = slope(xs, ys)
    out["intercept"] = sum(ys) / len(ys) - w * sum(xs) / len(xs)  # kg, of the fitted line M = W t + b
    q = (hi - lo) // 4
    parts = [slope(ts[lo + i * q:lo + (i + 1) * q + 1], m[lo + i * q:lo + (i + 1) * q + 1]) for i in range(4)]
    mp = sum(parts) / 4.0
    sd = math.sqrt(sum((s - mp) ** 2 for s in parts) / 3.0)
    out.update(rate=w, err=sd / 2.0, window=(ts[lo], ts[hi]), parts=parts)
    return out


def main():
    import argparse
    p = argparse.ArgumentParser()
    p.add_argument("run_dir")
    p.add_argument("--density", type=float, default=2500.0)
    p.add_argument("--label", default="")
    p.add_argument("--width", type=float, default=None)
    p.add_argument("--t-open", type=float, required=True)
    a = p.parse_args()
    r = measure(a.run_dir, a.t_open, a.density, a.width)
    win = f"{r['window'][0]:.3f}-{r['window'][1]:.3f} s" if r.get("window") else "none"
    print(f"{a.label} W = {r['rate']:.4f} +- {r['err']:.4f} kg/s (window {win}), total {r['total']:.4f} kg, "
          f"discharged {100 * r['reached']:.0f} %, first below at {r['first']}, jam {r['jam']}, bulk density {r['bulk']}")


if __name__ == "__main__":
    main()
