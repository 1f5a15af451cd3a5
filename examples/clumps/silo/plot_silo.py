"""Plot and tabulate the silo example (examples/clumps/silo): the mass discharged through the
orifice against time and the discharge rates (silo_rate.py) of tetrahedral clumps and of spheres
of the same volume, for each orifice.

Usage: /usr/bin/python3 plot_silo.py --t-open T --width L TIMES_FILE RUN_DIR:SHAPE:D0 ...
(writes silo.png, prints results)
"""

import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from silo_rate import SKIP, measure

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from shapes import R_EQ, REACH  # noqa: E402

C_BEV, K_BEV = 0.58, 1.5  # Beverloo et al. 1961's constants for spheres


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--t-open", type=float, required=True)
    p.add_argument("--width", type=float, required=True)
    p.add_argument("times")
    p.add_argument("runs", nargs="+")
    a = p.parse_args()
    times = dict(line.split(":", 1) for line in open(a.times).read().split("\n") if ":" in line)
    d_eq = 2.0 * R_EQ
    res = {}  # (shape, D0) -> [(numbers, run folder)], one per fill
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = {"tetra": "tab:red", "sphere": "tab:blue"}
    styles = ["-", "--", ":", "-."]
    d0s = sorted({float(r.split(":")[2]) for r in a.runs})
    for run in a.runs:
        run_dir, shape, d0 = run.split(":")
        d0 = float(d0)
        m = measure(run_dir, a.t_open, width=a.width)
        first = (shape, d0) not in res
        res.setdefault((shape, d0), []).append((m, run_dir))
        t = np.array(m["t"]) - a.t_open
        ax1.plot(t, np.array(m["m"]) / m["total"], styles[d0s.index(d0) % 4], color=colours[shape], lw=1,
                 label=f"{shape}, D0 = {d0 * 1e3:.0f} mm" if first else None)
        if m.get("window"):
            tw = np.array(m["window"])
            ax1.plot(tw - a.t_open, (m["rate"] * tw + m["intercept"]) / m["total"], color="k", lw=0.6)
    ax1.axvspan(SKIP, max(t), color="0.92")
    ax1.set_xlim(-0.05, max(t))
    ax1.set_xlabel("time after the lid is removed [s]")
    ax1.set_ylabel("mass below the orifice / total")
    ax1.set_title("Discharge of each fill (grey: the fitted window; black: fits)")
    ax1.legend(fontsize=8)
    lines = [f"flat-bottomed square silo, width {a.width * 1e3:.0f} mm; lid removed at t = {a.t_open} s; "
             f"equal-volume sphere diameter d = {d_eq * 1e3:.3f} mm, tetra reach (bounding diameter) "
             f"{2 * REACH * 1e3:.1f} mm",
             f"W: slope of the mass below the orifice plane from {SKIP} s after the opening to the end; "
             "+- = std / 2 of the slopes of the window's quarters",
             f"Beverloo: W_B = {C_BEV} rho_b sqrt(g) (D0 - {K_BEV} d)^(5/2) with the fill's bulk density rho_b "
             "and d the equal-volume diameter",
             "",
             "| D0 (mm) | D0 / d | shape | run | bulk density (kg/m^3) | W (kg/s) | +- | W / W_B | "
             "window (s after opening) | discharged at the end | jammed | wall time (s) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    means = {}
    for d0 in d0s:
        for shape in ("tetra", "sphere"):
            for m, run_dir in res.get((shape, d0), []):
                win = (f"{m['window'][0] - a.t_open:.3f}-{m['window'][1] - a.t_open:.3f}" if m.get("window")
                       else "-")
                jam = f"at {m['jam'] - a.t_open:.3f} s" if m["jam"] is not None else "no"
                name = os.path.basename(run_dir)
                w_b = C_BEV * m["bulk"] * math.sqrt(9.81) * (d0 - K_BEV * d_eq) ** 2.5
                lines.append(f"| {d0 * 1e3:.0f} | {d0 / d_eq:.2f} | {shape} | {name} | {m['bulk']:.0f} | "
                             f"{m['rate']:.4f} | {m['err']:.4f} | {m['rate'] / w_b:.2f} | {win} | {m['reached']:.0%} | "
                             f"{jam} | {times.get(name, '?').strip()} |")
                ax2.plot([d0 * 1e3], [m["rate"]], ".", color=colours[shape], alpha=0.5)
            if (shape, d0) in res:
                # Mean over the fills; its +- from the spread of the fills (std / sqrt(n)) and the
                # windows' own errors, whichever is larger.
                rates = [m["rate"] for m, _ in res[(shape, d0)]]
                n = len(rates)
                mean = sum(rates) / n
                spread = math.sqrt(sum((r - mean) ** 2 for r in rates) / (n - 1) / n) if n > 1 else 0.0
                own = math.sqrt(sum(m["err"] ** 2 for m, _ in res[(shape, d0)])) / n
                means[(shape, d0)] = (mean, max(spread, own), n)
                ax2.errorbar([d0 * 1e3], [mean], yerr=[max(spread, own)], fmt="o", color=colours[shape], capsize=3,
                             label=f"{shape} (mean of the fills)" if d0 == d0s[0] else None)
    lines.append("")
    for d0 in d0s:
        if ("tetra", d0) in means and ("sphere", d0) in means:
            (wt, et, nt), (ws, es, ns) = means[("tetra", d0)], means[("sphere", d0)]
            ratio = wt / ws
            err = ratio * math.hypot(et / wt, es / ws)
            lines.append(f"D0 = {d0 * 1e3:.0f} mm: mean W tetra {wt:.4f} +- {et:.4f} kg/s ({nt} fills), sphere "
                         f"{ws:.4f} +- {es:.4f} kg/s ({ns} fills); W(tetra) / W(sphere) = {ratio:.3f} +- {err:.3f}")
    ax2.set_xlabel("orifice diameter D0 [mm]")
    ax2.set_ylabel("discharge rate W [kg/s]")
    ax2.set_title("Discharge rate (dots: each fill)")
    ax2.legend()
    fig.tight_layout()
    fig.savefig("silo.png", dpi=110)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
