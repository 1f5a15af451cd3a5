"""Settle a bed, then tilt gravity in steps until it avalanches: the angle of stability (the tilt
at which the surface starts to flow) and the angle of repose of the surface it leaves.

A box 120 x 20 mm holds 1000 glass-like beads (radius 1.8-2.2 mm, mu = 0.5, rolling friction 0.05).
After settling, gravity is turned about the y axis by 3 degrees at a time, g = 9.81 (sin a, 0,
-cos a) m/s^2, each tilt held 0.1 s; the bed has avalanched when the mean speed at the end of a
hold exceeds 5 mm/s. The bed is then left to come to rest at that tilt and the slope of its free
surface, measured from the horizontal of the tilted gravity, is the angle of repose.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/python/angle_of_repose.py [OUTPUT_DIR]
Writes angle_of_repose.png and angle_of_repose.txt.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem
from box_walls import open_box

L, W, H = 0.12, 0.02, 0.08  # m, box
G = 9.81
HOLD = 0.1  # s per tilt
FLOWING = 5e-3  # m/s, mean speed of a bed that flows


def scene():
    s = mpdem.Scene()
    s.time(duration=10.0, dt=6e-6, integrator="verlet")
    s.gravity([0.0, 0.0, -G])
    law = dict(restitution=0.3, mu_static=0.5, mu_dynamic=0.5, mu_rolling=0.05)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("beads", density=2500.0, young=2e7, poisson=0.3)
    s.particles(generate=dict(region="box", min=[0.002, 0.002, 0.002], max=[L - 0.002, W - 0.002, 0.07],
                              count=1000, radius=dict(distribution="uniform", min=1.8e-3, max=2.2e-3), seed=3),
                material="beads")
    s.barriers(open_box((0.0, 0.0, 0.0), (L, W, H)), material="beads", group="box")
    s.domain(min=[-0.01, -0.01, -0.01], max=[L + 0.01, W + 0.01, H + 0.02])
    return s


def mean_speed(sim):
    return float(np.linalg.norm(sim.particles.velocity, axis=1).mean())


def surface(sim, bins=12):
    """Box x of bin centres and the height of the top of the bed in each (m, box frame)."""
    x = sim.particles.position
    top = x[:, 2] + sim.particles.radius
    edges = np.linspace(0.0, L, bins + 1)
    centres = 0.5 * (edges[1:] + edges[:-1])
    h = np.array([top[(x[:, 0] >= a) & (x[:, 0] < b)].max() for a, b in zip(edges[:-1], edges[1:])])
    return centres, h


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    sim = mpdem.Simulation(scene(), threads=2, write_output=False)
    sim.run(duration=0.4)  # settle
    history = [(0.0, sim.time, mean_speed(sim))]
    tilt = 12.0
    while True:
        tilt += 3.0
        a = np.radians(tilt)
        sim.gravity = [G * np.sin(a), 0.0, -G * np.cos(a)]
        sim.run(duration=HOLD, callback=lambda s: history.append((tilt, s.time, mean_speed(s))), every=500)
        if history[-1][2] > FLOWING or tilt >= 60.0:
            break
    stability = tilt
    sim.run(duration=0.6)  # the avalanche comes to rest at this tilt
    x, h = surface(sim)
    inner = slice(1, -1)  # leave out the bins at the walls
    fit = np.polyfit(x[inner], h[inner], 1)
    slope = fit[0]
    final_positions = sim.particles.position
    repose = stability - np.degrees(np.arctan(slope))
    text = (f"# 1000 beads r = 1.8-2.2 mm, mu = 0.5, mu_rolling = 0.05, box {L * 1e3:.0f} x {W * 1e3:.0f} mm\n"
            f"tilt steps: 3 deg, held {HOLD} s; flowing: mean speed > {FLOWING * 1e3:.0f} mm/s\n"
            f"angle of stability (tilt at the avalanche): {stability:.0f} deg\n"
            f"angle of repose of the surface left: {repose:.1f} deg (surface slope in the box {np.degrees(np.arctan(slope)):.1f} deg)\n"
            f"final mean speed {mean_speed(sim):.2e} m/s at t = {sim.time:.2f} s\n")
    (out / "angle_of_repose.txt").write_text(text)
    h_arr = np.array(history)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.semilogy(h_arr[:, 1], h_arr[:, 2], ".-", ms=3)
    ax1.axhline(FLOWING, color="r", lw=1, ls="--", label="flowing")
    for t in np.unique(h_arr[:, 0]):
        if t > 0:
            first = h_arr[h_arr[:, 0] == t][0, 1]
            ax1.annotate(f"{t:.0f}°", (first, h_arr[:, 2].max()), fontsize=7, ha="left", va="top")
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("mean speed [m/s]")
    ax1.set_title("Tilting in 3° steps")
    ax1.legend()
    # Side view in the frame of the tilted gravity: its horizontal is horizontal in the picture.
    c, sn = np.cos(np.radians(stability)), np.sin(np.radians(stability))
    p = final_positions
    xr, zr = c * p[:, 0] + sn * p[:, 2], -sn * p[:, 0] + c * p[:, 2]
    ax2.scatter(xr * 1e3, zr * 1e3, s=6, c="tab:blue", label=f"at rest after the avalanche ({stability:.0f}° tilt)")
    x0 = np.array([0.0, L])
    xs, zs = c * x0 + sn * np.polyval(fit, x0), -sn * x0 + c * np.polyval(fit, x0)
    ax2.plot(xs * 1e3, zs * 1e3, "r-", label=f"surface fit: {repose:.1f}° from horizontal")
    ax2.set_aspect("equal")
    ax2.set_xlabel("horizontal [mm]")
    ax2.set_ylabel("vertical [mm]")
    ax2.set_title(f"Angle of repose {repose:.1f}° (stability {stability:.0f}°)")
    ax2.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "angle_of_repose.png", dpi=120)
    print(text, end="")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent)
