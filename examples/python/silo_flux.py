"""Coarse-grained mass flux of a discharging silo against the sink's measured flow rate.

A square silo 65 x 65 mm with a 30 mm square orifice in its floor holds 1500 beads (radius
2.25-2.75 mm); a lid closes the orifice until t = 0.3 s, then the silo discharges into a [[sink]]
below. A [[coarse_grain]] profile along z over the silo's cross-section (Gaussian, w = 2.5 mm,
averaged over the window 0.45-0.75 s, 150 samples) gives the momentum density p_z(z): the mass
flow rate through the horizontal plane at z is -p_z(z) times the cross-section's area. Averaged
over the planes 0-8 mm above the orifice (the bed's surface falls from ~40 to ~25 mm during the
window: planes near it see less flux, as the mass above them drains) it is compared with the
sink's flow rate over the same window, from log.csv (removed mass difference / time).

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/python/silo_flux.py [OUTPUT_DIR]
Writes silo_flux.png and silo_flux.txt; exits 1 if the two rates differ by more than 2 %.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem
from box_walls import quad

L = 0.065  # m, silo side (centred on x = y = 0)
D = 0.03  # m, orifice side
H = 0.2  # m, wall height
OPEN = 0.3  # s, the lid opens
WINDOW = (0.45, 0.75)  # s, averaging window
W = 2.5e-3  # m, kernel width
PLANES = (0.0, 0.008)  # m above the orifice: below the falling free surface (and its kernel) all along the window


def silo():
    """(walls, floor with the orifice, lid): triangle arrays, normals into the silo."""
    a, h = L / 2, D / 2
    walls = []
    walls += quad((-a, -a, 0), (-a, a, 0), (-a, a, H), (-a, -a, H))
    walls += quad((a, -a, 0), (a, -a, H), (a, a, H), (a, a, 0))
    walls += quad((-a, -a, 0), (-a, -a, H), (a, -a, H), (a, -a, 0))
    walls += quad((-a, a, 0), (a, a, 0), (a, a, H), (-a, a, H))
    floor = []
    floor += quad((-a, -a, 0), (a, -a, 0), (a, -h, 0), (-a, -h, 0))
    floor += quad((-a, h, 0), (a, h, 0), (a, a, 0), (-a, a, 0))
    floor += quad((-a, -h, 0), (-h, -h, 0), (-h, h, 0), (-a, h, 0))
    floor += quad((h, -h, 0), (a, -h, 0), (a, h, 0), (h, h, 0))
    lid = quad((-h, -h, 0), (h, -h, 0), (h, h, 0), (-h, h, 0))
    return (np.array(t, dtype=float) for t in (walls, floor, lid))


def scene(out):
    s = mpdem.Scene()
    s.time(duration=WINDOW[1], dt=1.7e-5, integrator="verlet")
    s.gravity([0.0, 0.0, -9.81])
    law = dict(restitution=0.3, mu_static=0.5, mu_dynamic=0.5)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("beads", density=2500.0, young=2e6, poisson=0.3)
    walls, floor, lid = silo()
    s.barriers(walls, material="beads", group="walls")
    s.barriers(floor, material="beads", group="floor")
    s.barriers(lid, material="beads", group="lid", active=[0.0, OPEN])
    a = L / 2 - 0.003
    s.particles(generate=dict(region="box", min=[-a, -a, 0.003], max=[a, a, 0.19], count=1500,
                              radius=dict(distribution="uniform", min=2.25e-3, max=2.75e-3), seed=4),
                material="beads")
    s.sink(name="out", region="box", min=[-0.2, -0.2, -0.3], max=[0.2, 0.2, -0.03])
    s.domain(min=[-0.2, -0.2, -0.3], max=[0.2, 0.2, 0.3], on_exit="remove")
    s.checks(max_overlap=0.3, energy_drift=0.0)
    s.output(log_every=10, progress_every=0)
    span = WINDOW[1] - WINDOW[0]
    s.coarse_grain(name="flux", profile=dict(axis="z", min=-0.01, max=0.05, bins=120, extent_min=[-L / 2, -L / 2, 0],
                                              extent_max=[L / 2, L / 2, 0]),
                   kernel="gaussian", width=W, every=WINDOW[1], average=span, samples=150)
    return s


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    run = out / "silo_flux_run"
    sim = mpdem.Simulation(scene(out), threads=2, output_dir=str(run), progress=False)
    sim.run(duration=WINDOW[1])
    cg = np.genfromtxt(run / "cg_flux.csv", delimiter=",", names=True)
    log = np.genfromtxt(run / "log.csv", delimiter=",", names=True)
    z, pz = cg["z"], cg["momentum_z"]
    flux = -pz * L * L  # kg/s through the plane at z (downwards positive)
    planes = (z >= PLANES[0]) & (z <= PLANES[1])
    cg_rate = float(flux[planes].mean())
    t, removed = log["time"], log["outremoved_mass"]
    m0, m1 = np.interp(WINDOW[0], t, removed), np.interp(WINDOW[1], t, removed)
    sink_rate = float((m1 - m0) / (WINDOW[1] - WINDOW[0]))
    diff = abs(cg_rate - sink_rate) / sink_rate
    text = (f"# square silo {L * 1e3:.0f} mm, orifice {D * 1e3:.0f} mm, 1500 beads r = 2.25-2.75 mm; lid opens at "
            f"{OPEN} s; window {WINDOW[0]}-{WINDOW[1]} s\n"
            f"coarse-grained mass flux through the planes {PLANES[0] * 1e3:.0f}-{PLANES[1] * 1e3:.0f} mm above the "
            f"orifice (mean): {cg_rate:.5f} kg/s\n"
            f"sink's measured flow rate over the window: {sink_rate:.5f} kg/s\n"
            f"relative difference: {diff:.2e}\n")
    (out / "silo_flux.txt").write_text(text)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.5))
    ax1.plot(flux, z * 1e3, label="coarse-grained -p_z A")
    ax1.axvline(sink_rate, color="r", ls="--", label="sink's flow rate")
    ax1.axhspan(PLANES[0] * 1e3, PLANES[1] * 1e3, color="grey", alpha=0.2, label="planes compared")
    ax1.set_xlabel("mass flow rate through the plane [kg/s]")
    ax1.set_ylabel("height above the orifice z [mm]")
    ax1.set_title(f"Window {WINDOW[0]}-{WINDOW[1]} s: difference {diff * 100:.2f} %")
    ax1.legend(fontsize=8)
    ax2.plot(t, removed * 1e3)
    ax2.axvspan(*WINDOW, color="grey", alpha=0.2)
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("mass removed by the sink [g]")
    ax2.set_title("Discharge")
    fig.tight_layout()
    fig.savefig(out / "silo_flux.png", dpi=120)
    print(text, end="")
    return 0 if diff < 0.02 else 1


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent))
