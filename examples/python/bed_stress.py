"""Coarse-grained stress in a settled bed: the vertical stress at each height is the weight of
the grains above it per unit area (the static momentum balance of MercuryCG's fields).

A periodic cell 16 x 16 mm (x and y periodic, no side walls to carry weight by friction) holds a
floor of fixed spheres and 1200 free beads (radius 0.9-1.1 mm) that settle under gravity. A
[[coarse_grain]] profile along z (Gaussian kernel, w = 1 mm, averaged over x and y and over a
window of 0.02 s) gives the density rho(z) and the stress sigma_zz(z). The weight above z per unit
area is g times the integral of rho from z to the top, from the same profile; the two agree to
within 1 % everywhere more than 3 w above the floor and 3 w below the free surface.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/python/bed_stress.py [OUTPUT_DIR]
Writes bed_stress.png and bed_stress.txt; exits 1 if the agreement is worse than 1 %.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

L = 0.016  # m, periodic cell side
G = 9.81  # m/s^2
W = 1e-3  # m, kernel width
R_FLOOR = 1e-3  # m, floor spheres
TOP = 0.05  # m, top of the profile (above the bed)
BINS = 500


def scene(out):
    s = mpdem.Scene()
    s.time(duration=0.22, dt=4e-6, integrator="verlet")
    s.gravity([0.0, 0.0, -G])
    law = dict(restitution=0.3, mu_static=0.5, mu_dynamic=0.5, mu_rolling=0.02)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("beads", density=2500.0, young=1e7, poisson=0.3)
    n = int(round(L / (2 * R_FLOOR)))
    g = (np.arange(n) + 0.5) * 2 * R_FLOOR
    fx, fy = np.meshgrid(g, g)
    floor = np.column_stack([fx.ravel(), fy.ravel(), np.full(fx.size, R_FLOOR)])
    s.particles(position=floor, radius=np.full(len(floor), R_FLOOR), material="beads",
                fixed=np.ones(len(floor), dtype=int))
    s.particles(generate=dict(region="box", min=[0.0, 0.0, 2.2 * R_FLOOR], max=[L, L, 0.06], count=1200,
                              radius=dict(distribution="uniform", min=0.9e-3, max=1.1e-3), seed=5),
                material="beads")
    s.domain(min=[0.0, 0.0, -0.01], max=[L, L, 0.08], periodic=["x", "y"])
    s.output(dir=str(out / "bed_stress_run"), log_every=5000, progress_every=0)
    s.coarse_grain(name="stress", profile=dict(axis="z", min=0.0, max=TOP, bins=BINS), kernel="gaussian", width=W,
                   every=0.22, average=0.02, samples=20)
    return s


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    sim = mpdem.Simulation(scene(out), threads=2, output_dir=str(out / "bed_stress_run"), progress=False)
    sim.run(duration=0.22)
    ke = sim.log()["kinetic"]
    data = np.genfromtxt(out / "bed_stress_run" / "cg_stress.csv", delimiter=",", names=True)
    last = data[data["time"] == data["time"].max()]
    z, rho, szz = last["z"], last["density"], last["stress_zz"]
    dz = z[1] - z[0]
    # g * integral of rho from z to the top (midpoint sums: the profile's bins are w / 10)
    weight = G * (np.cumsum(rho[::-1])[::-1] - 0.5 * rho) * dz
    free = sim.particles.fixed == 0
    zpos = sim.particles.position[free, 2]
    top = np.quantile(zpos + sim.particles.radius[free], 0.98)  # m, the free surface
    floor_top = 2 * R_FLOOR
    inside = (z > floor_top + 3 * W) & (z < top - 3 * W)
    rel = np.abs(szz[inside] - weight[inside]) / weight[inside]
    worst = float(rel.max())
    mass = sim.particles.mass[free].sum()
    text = (f"# 1200 beads r = 0.9-1.1 mm on a fixed floor, periodic cell {L * 1e3:.0f} x {L * 1e3:.0f} mm, "
            f"Gaussian w = {W * 1e3:.1f} mm, averaged over 0.02 s (20 samples)\n"
            f"free surface at {top * 1e3:.1f} mm; compared on {inside.sum()} bins from "
            f"{(floor_top + 3 * W) * 1e3:.1f} to {(top - 3 * W) * 1e3:.1f} mm\n"
            f"largest |sigma_zz - weight above / area| / (weight above / area): {worst:.2e}\n"
            f"weight of the free beads / area: {mass * G / L ** 2:.2f} Pa; sigma_zz just above the floor region: "
            f"{szz[inside][0]:.2f} Pa\n"
            f"kinetic energy at the end: {ke:.3e} J\n")
    (out / "bed_stress.txt").write_text(text)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.5), sharey=True)
    ax1.plot(rho, z * 1e3)
    ax1.set_xlabel("density rho [kg/m^3]")
    ax1.set_ylabel("height z [mm]")
    ax1.set_title("Coarse-grained density")
    ax2.plot(szz, z * 1e3, label="sigma_zz (coarse-grained stress)")
    ax2.plot(weight, z * 1e3, "--", label="g * integral of rho above z")
    for h in (floor_top + 3 * W, top - 3 * W):
        ax2.axhline(h * 1e3, color="grey", lw=0.8, ls=":")
    ax2.set_xlabel("vertical stress [Pa]")
    ax2.set_title(f"sigma_zz = weight above: worst {worst * 100:.2f} % (dotted: range)")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "bed_stress.png", dpi=120)
    print(text, end="")
    return 0 if worst < 0.01 else 1


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent))
