#!/usr/bin/python3
"""Plots position and speed vs time of the charged sphere of e_field.toml, b_field.toml and
e_and_b.toml, simulated vs analytic. Run the three scenes first (see their headers).
Writes output/charged_particle.png.

Analytic motion in uniform E and B (B along z or zero), with a = q/m:
  v_z(t) = v_z0 + a E_z t
  B = 0:  v_perp(t) = v_perp0 + a E_perp t
  B != 0: v_perp = v_d + u,  v_d = E x B / B^2 (drift), and u = v_perp0 - v_d turns
          clockwise at omega = a B:  u(t) = exp(-i omega t) u0 (complex notation x + i y).
Positions are the time integrals of these velocities.
"""
import cmath
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


def load(case):
    scene = tomllib.load(open(os.path.join(here, case + ".toml"), "rb"))
    out = os.path.join(here, scene["output"]["dir"])
    files = sorted(glob.glob(os.path.join(out, "particles_csv", "particles_*.csv")))
    if not files:
        sys.exit(f"no snapshots in {out}; run: mpdem run examples/electromagnetic/{case}.toml")
    rows = [next(csv.DictReader(open(f))) for f in files]  # one particle
    t = [float(r["time"]) for r in rows]
    x = [[float(r[k]) for k in ("x", "y", "z")] for r in rows]
    v = [[float(r[k]) for k in ("vx", "vy", "vz")] for r in rows]
    R, q = float(rows[0]["radius"]), float(rows[0]["charge"])
    m = 4 / 3 * math.pi * R**3 * scene["material"][0]["density"]
    return scene, t, x, v, q / m


def exact(E, B, a, x0, v0, t):
    if B[0] != 0.0 or B[1] != 0.0:
        sys.exit("the analytic solution here assumes B along z")
    z = x0[2] + v0[2] * t + 0.5 * a * E[2] * t * t
    vz = v0[2] + a * E[2] * t
    X0, V0, Ep = complex(x0[0], x0[1]), complex(v0[0], v0[1]), complex(E[0], E[1])
    if B[2] == 0.0:
        V = V0 + a * Ep * t
        X = X0 + V0 * t + 0.5 * a * Ep * t * t
    else:
        w = a * B[2]
        vd = complex(E[1] * B[2], -E[0] * B[2]) / (B[2] * B[2])  # E x B / B^2
        u0 = V0 - vd
        V = vd + u0 * cmath.exp(-1j * w * t)
        X = X0 + vd * t + u0 * (1 - cmath.exp(-1j * w * t)) / (1j * w)
    return (X.real, X.imag, z), (V.real, V.imag, vz)


cases = [("e_field", "E only"), ("b_field", "B only"), ("e_and_b", "E and B")]
fig, axes = plt.subplots(2, 3, figsize=(13, 7), sharex=True)
for col, (case, title) in enumerate(cases):
    scene, t, x, v, a = load(case)
    E = scene["fields"]["electric"]
    B = scene["fields"]["magnetic"]
    ex = [exact(E, B, a, x[0], v[0], ti) for ti in t]
    worst_x = max(math.dist(xs, e[0]) for xs, e in zip(x, ex))
    worst_v = max(abs(math.hypot(*vs) - math.hypot(*e[1])) for vs, e in zip(v, ex))
    ax = axes[0][col]
    for k, name in enumerate("xyz"):
        line, = ax.plot(t, [p[k] for p in x], "o", ms=2, markevery=4, label=f"{name} simulated")
        ax.plot(t, [e[0][k] for e in ex], "-", lw=1, color=line.get_color(), label=f"{name} analytic")
    ax.set_title(f"{title}: E = {E} V/m, B = {B} T", fontsize=9)
    ax.set_ylabel("position [m]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax = axes[1][col]
    ax.plot(t, [math.hypot(*p) for p in v], "o", ms=2, markevery=4, label="|v| simulated")
    ax.plot(t, [math.hypot(*e[1]) for e in ex], "-", lw=1, label="|v| analytic")
    ax.set_ylim(0.0, 1.15 * max(math.hypot(*p) for p in v))  # a constant speed must look constant
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("speed |v| [m/s]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    print(f"{case}: max |x - x_exact| = {worst_x:.3g} m, max ||v| - |v|_exact| = {worst_v:.3g} m/s")
fig.suptitle("Charged sphere (q = 1 uC) in uniform fields, (41)-(42)")
fig.tight_layout()
png = os.path.join(here, "output", "charged_particle.png")
fig.savefig(png, dpi=110)
print(png)
