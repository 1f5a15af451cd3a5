#!/usr/bin/python3
"""Plots T vs time of the spheres of convection.toml, one curve per air speed, simulated vs analytic.

Run `mpdem run examples/thermal/convection.toml` first. Writes output/convection/temperature.png.
Analytic (lumped): T - T_air = (T0 - T_air) exp(-t / tau), tau = rho c R / (3 h(v)),
h(v) = 12.15335 - 1.1630 v + 11.630 sqrt(v) W/(m^2 K), v clamped to [0, 20] m/s (physics.md (93)).
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
scene = tomllib.load(open(os.path.join(here, "convection.toml"), "rb"))
out = os.path.join(here, scene["output"]["dir"])
files = sorted(glob.glob(os.path.join(out, "particles_csv", "particles_*.csv")))
if not files:
    sys.exit(f"no snapshots in {out}; run: mpdem run examples/thermal/convection.toml")

series = {}  # id -> list of (t, |v|, radius, T)
for f in files:
    for r in csv.DictReader(open(f)):
        v = (float(r["vx"]), float(r["vy"]), float(r["vz"]))
        series.setdefault(int(float(r["id"])), []).append(
            (float(r["time"]), v, float(r["radius"]), float(r["temperature"])))

th = scene["thermal"]
Tair, vair = th["air_temperature"], th.get("air_velocity", [0.0, 0.0, 0.0])
mat = scene["material"][0]
rho, c = mat["density"], mat["heat_capacity"]

fig, ax = plt.subplots(figsize=(7, 4.5))
worst = 0.0
for i in sorted(series):
    s = series[i]
    t = [e[0] for e in s]
    T = [e[3] for e in s]
    v = math.dist(s[0][1], vair)
    vc = min(max(v, 0.0), 20.0)
    h = 12.15335 - 1.1630 * vc + 11.630 * math.sqrt(vc)
    tau = rho * c * s[0][2] / (3 * h)
    T0 = T[0]
    exact = [Tair + (T0 - Tair) * math.exp(-ti / tau) for ti in t]
    worst = max(worst, max(abs(a - b) / (T0 - Tair) for a, b in zip(T, exact)))
    line, = ax.plot(t, T, "o", ms=2.5, label=f"v = {v:g} m/s, simulated")
    ax.plot(t, exact, "-", lw=1, color=line.get_color(), label=f"v = {v:g} m/s, analytic (tau = {tau:.2f} s)")
ax.set_xlabel("time t [s]")
ax.set_ylabel("temperature T [K]")
ax.set_title(f"Convective cooling in air at {Tair:g} K, one sphere per relative air speed")
ax.legend(fontsize=7, ncol=2)
ax.grid(alpha=0.3)
fig.tight_layout()
png = os.path.join(out, "temperature.png")
fig.savefig(png, dpi=120)
print(f"{png}: max |T - T_exact| / (T0 - T_air) = {worst:.3g}")
