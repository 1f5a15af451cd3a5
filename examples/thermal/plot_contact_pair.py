#!/usr/bin/python3
"""Plots T vs time of the two touching spheres of contact_pair.toml, simulated vs analytic.

Run `mpdem run examples/thermal/contact_pair.toml` first. Writes output/contact_pair/temperature.png.
Analytic: T1 - T2 decays at lambda = G (1/C1 + 1/C2), G = K A / d (physics.md (88)-(90)),
towards the capacity-weighted mean; A is the lens area of the spheres at their (fixed) distance.
"""
import csv
import glob
import math
import os
import sys
import tomllib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
scene = tomllib.load(open(os.path.join(here, "contact_pair.toml"), "rb"))
out = os.path.join(here, scene["output"]["dir"])
files = sorted(glob.glob(os.path.join(out, "particles_csv", "particles_*.csv")))
if not files:
    sys.exit(f"no snapshots in {out}; run: mpdem run examples/thermal/contact_pair.toml")

series = {}  # id -> list of (t, x, radius, material, T)
for f in files:
    for r in csv.DictReader(open(f)):
        series.setdefault(int(float(r["id"])), []).append(
            (float(r["time"]), (float(r["x"]), float(r["y"]), float(r["z"])), float(r["radius"]),
             int(float(r["material"])), float(r["temperature"])))
ids = sorted(series)
mats = scene["material"]

# Closed form from the first snapshot (geometry, temperatures) and the materials.
first = {i: series[i][0] for i in ids}
(_, x1, R1, m1, T10), (_, x2, R2, m2, T20) = first[ids[0]], first[ids[1]]
d = math.dist(x1, x2)
xc = (d * d + R1 * R1 - R2 * R2) / (2 * d)
A = math.pi * (R1 * R1 - xc * xc)
k1, k2 = mats[m1]["conductivity"], mats[m2]["conductivity"]
K = 2 * k1 * k2 / (k1 + k2)
C1 = 4 / 3 * math.pi * R1**3 * mats[m1]["density"] * mats[m1]["heat_capacity"]
C2 = 4 / 3 * math.pi * R2**3 * mats[m2]["density"] * mats[m2]["heat_capacity"]
lam = K * A / d * (1 / C1 + 1 / C2)
Tm = (C1 * T10 + C2 * T20) / (C1 + C2)

fig, ax = plt.subplots(figsize=(7, 4.5))
worst = 0.0
for i, (C, T0) in zip(ids, ((C1, T10), (C2, T20))):
    t = [s[0] for s in series[i]]
    T = [s[4] for s in series[i]]
    exact = [Tm + (T0 - Tm) * math.exp(-lam * ti) for ti in t]
    worst = max(worst, max(abs(a - b) / abs(T10 - T20) for a, b in zip(T, exact)))
    name = mats[series[i][0][3]]["name"]
    line, = ax.plot(t, T, "o", ms=3, label=f"particle {i} ({name}), simulated")
    ax.plot(t, exact, "-", lw=1, color=line.get_color(), label=f"particle {i} ({name}), analytic")
ax.axhline(Tm, color="grey", ls=":", lw=1, label=f"capacity-weighted mean {Tm:.2f} K")
ax.set_xlabel("time t [s]")
ax.set_ylabel("temperature T [K]")
ax.set_title(f"Conduction between two touching spheres (lambda = {lam:.4g} 1/s)")
ax.legend(fontsize=8)
ax.grid(alpha=0.3)
fig.tight_layout()
png = os.path.join(out, "temperature.png")
fig.savefig(png, dpi=120)
print(f"{png}: max |T - T_exact| / |T1 - T2|(0) = {worst:.3g}")
