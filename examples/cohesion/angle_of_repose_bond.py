"""Angle of repose of a cohesive powder against the granular Bond number (tilting box, JKR).

Bo = F_c / (m g): the JKR pull-off force of two equal beads, F_c = 3/2 pi w r* with r* = R/2,
over a bead's weight m g = 4/3 pi R^3 rho g (Nase et al. 2001; Castellanos 2005), for the mean
radius R. So Bo = 9 w / (16 rho g R^2) and the surface energy of a given Bo is w = 16 rho g R^2 Bo / 9.

A box of length L (x) holds N beads (radius 1.8-2.2 mm, rho = 2500 kg/m^3, E = 20 MPa, mu = 0.5,
rolling friction 0.05, e = 0.3), periodic across y (period 20 mm: no side walls to lean on). The
beads attract each other with JKR (`cohesion = "jkr"`, physics.md section 15); the floor and the two
end walls have no cohesion, so the bed cannot hang from them. The beads settle; gravity is then
turned about the y axis by 3 degrees at a time from 21 degrees, g = 9.81 (sin a, 0, -cos a) m/s^2,
each tilt held 0.1 s, until the mean speed at the end of a hold exceeds 5 mm/s (the avalanche): that
tilt is the angle of stability. The bed is left to come to rest at that tilt; the slope of its free
surface, measured from the horizontal of the tilted gravity, is the angle of repose. The same
settling, tilting and fit for every Bo.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/cohesion/angle_of_repose_bond.py [--short] [OUTPUT_DIR]
Writes angle_of_repose_bond.png and angle_of_repose_bond.txt (--short: *_short.*) and exits 1
unless the angle of repose at the largest Bo exceeds the cohesionless one by MARGIN degrees.
"""

import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "python"))
from box_walls import open_box  # noqa: E402

W, H = 0.02, 0.08  # m, box width (y) and height
R_MIN, R_MAX = 1.8e-3, 2.2e-3  # m, bead radii (uniform)
R_MEAN = 0.5 * (R_MIN + R_MAX)
RHO = 2500.0  # kg/m^3
G = 9.81  # m/s^2
HOLD = 0.1  # s per tilt
STEP = 3.0  # deg per tilt
FIRST, LAST = 21.0, 72.0  # deg, first tilt and the largest tried
FLOWING = 5e-3  # m/s, mean speed of a bed that flows
AT_REST = 2e-3  # m/s, mean speed of a bed come to rest
MARGIN = 10.0  # deg, the check: repose(Bo_max) - repose(0) must exceed this

FULL = dict(count=600, length=0.08, bonds=[0.0, 2.0, 4.0, 8.0, 16.0])
SHORT = dict(count=300, length=0.06, bonds=[0.0, 3.0])


def surface_energy(bo):
    """J/m^2: the w whose JKR pull-off between two beads of the mean radius is Bo times the weight."""
    return 16.0 * RHO * G * R_MEAN**2 * bo / 9.0


def scene(count, length, w):
    s = mpdem.Scene()
    s.time(duration=100.0, dt=1e-5, integrator="verlet")  # about 1/11 of the smallest bead's Rayleigh time
    s.gravity([0.0, 0.0, -G])
    law = dict(restitution=0.3, mu_static=0.5, mu_dynamic=0.5, mu_rolling=0.05)
    beads = dict(law, cohesion="jkr", surface_energy=w) if w > 0 else law
    s.contact(particle_particle=beads, particle_barrier=law)
    s.material("beads", density=RHO, young=2e7, poisson=0.3)
    s.particles(generate=dict(region="box", min=[0.002, 0.0, 0.002], max=[length - 0.002, W, 0.07],
                              count=count, radius=dict(distribution="uniform", min=R_MIN, max=R_MAX), seed=3),
                material="beads")
    s.barriers(open_box((0.0, 0.0, 0.0), (length, W, H))[:6], material="beads", group="box")  # floor, x walls
    s.domain(min=[-0.01, 0.0, -0.01], max=[length + 0.01, W, H + 0.02], periodic=["y"])
    return s


def mean_speed(sim):
    return float(np.linalg.norm(sim.particles.velocity, axis=1).mean())


def come_to_rest(sim, least, most):
    """Run at least `least` s, then in 0.05 s pieces until the bed is at rest or `most` s passed."""
    sim.run(duration=least)
    t = least
    while mean_speed(sim) > AT_REST and t < most:
        sim.run(duration=0.05)
        t += 0.05


def surface_slope(sim, length, bins):
    """Slope (box frame) of a line fitted to the top of the bed in `bins` columns, walls left out."""
    x = sim.particles.position
    top = x[:, 2] + sim.particles.radius
    edges = np.linspace(0.0, length, bins + 1)
    centres = 0.5 * (edges[1:] + edges[:-1])
    h = np.array([top[(x[:, 0] >= a) & (x[:, 0] < b)].max(initial=0.0) for a, b in zip(edges[:-1], edges[1:])])
    fit = np.polyfit(centres[1:-1], h[1:-1], 1)
    return fit, centres, h


def tilt_test(bo, count, length):
    w = surface_energy(bo)
    sim = mpdem.Simulation(scene(count, length, w), threads=2, write_output=False)
    come_to_rest(sim, 0.3, 1.0)  # settle
    tilt = FIRST - STEP
    while tilt < LAST:
        tilt += STEP
        a = np.radians(tilt)
        sim.gravity = [G * np.sin(a), 0.0, -G * np.cos(a)]
        sim.run(duration=HOLD)
        if mean_speed(sim) > FLOWING:
            break
    avalanched = mean_speed(sim) > FLOWING
    come_to_rest(sim, 0.2, 0.8)  # the avalanche comes to rest at this tilt
    fit, _, _ = surface_slope(sim, length, bins=max(6, int(round(length / 0.01))))
    box_slope = np.degrees(np.arctan(fit[0]))
    log = sim.log()
    return dict(bo=bo, w=w, stability=tilt, avalanched=avalanched, repose=tilt - box_slope, box_slope=box_slope,
                breaks=log.get("breaks", 0), time=sim.time, length=length, positions=sim.particles.position.copy(), fit=fit)


def main(argv):
    short = "--short" in argv
    args = [a for a in argv if a != "--short"]
    cfg = dict(SHORT if short else FULL)
    if args and args[0].startswith("--bonds="):  # exploring: other Bond numbers, e.g. --bonds=0,1,2
        cfg["bonds"] = [float(b) for b in args.pop(0)[8:].split(",")]
    out = Path(args[0]) if args else Path(__file__).parent
    out.mkdir(parents=True, exist_ok=True)
    stem = "angle_of_repose_bond" + ("_short" if short else "")
    results = []
    for bo in cfg["bonds"]:
        t0 = time.time()
        r = tilt_test(bo, cfg["count"], cfg["length"])
        r["wall"] = time.time() - t0
        results.append(r)
        print(f"Bo {bo:5.1f}: w {r['w']:.3f} J/m^2, stability {r['stability']:.0f} deg"
              f"{'' if r['avalanched'] else ' (no avalanche)'}, repose {r['repose']:.1f} deg"
              f" ({r['time']:.2f} s simulated, {r['wall']:.0f} s wall)", flush=True)
    rise = results[-1]["repose"] - results[0]["repose"]
    ok = rise > MARGIN
    lines = [f"# {cfg['count']} beads r = {R_MIN * 1e3:.1f}-{R_MAX * 1e3:.1f} mm, rho = {RHO:.0f} kg/m^3, E = 20 MPa,"
             f" mu = 0.5, mu_rolling = 0.05, e = 0.3, box {cfg['length'] * 1e3:.0f} x {W * 1e3:.0f} mm",
             "# JKR between the beads (walls: no cohesion), periodic in y; Bo = F_c / (m g), F_c = 3/2 pi w r*, r* = R/2, R = 2 mm",
             f"# tilt steps {STEP:.0f} deg from {FIRST:.0f} deg, held {HOLD} s; avalanche: mean speed > {FLOWING * 1e3:.0f} mm/s",
             "#   Bo   w [J/m^2]  stability [deg]  repose [deg]  surface slope in box [deg]  necks broken"]
    for r in results:
        lines.append(f"{r['bo']:6.1f} {r['w']:10.4f} {r['stability']:12.0f}{'' if r['avalanched'] else '+'}"
                     f" {r['repose']:15.1f} {r['box_slope']:18.1f} {r['breaks']:21.0f}")
    lines.append(f"repose(Bo = {results[-1]['bo']:g}) - repose(Bo = 0) = {rise:.1f} deg;"
                 f" check: > {MARGIN:.0f} deg: {'passed' if ok else 'FAILED'}")
    text = "\n".join(lines) + "\n"
    (out / f"{stem}.txt").write_text(text)
    plot(results, out / f"{stem}.png")
    print(text, end="")
    return 0 if ok else 1


def plot(results, path):
    fig, axes = plt.subplots(1, 3, figsize=(14, 4), gridspec_kw=dict(width_ratios=[1.1, 1, 1]))
    bo = [r["bo"] for r in results]
    ax = axes[0]
    ax.plot(bo, [r["repose"] for r in results], "o-", label="angle of repose (surface left)")
    ax.plot(bo, [r["stability"] for r in results], "s--", label="angle of stability (tilt at the avalanche)")
    ax.set_xlabel("granular Bond number Bo = F_c / (m g)")
    ax.set_ylabel("angle [deg]")
    ax.set_title("Cohesive beads (JKR) in a tilting box")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    # Side views in the frame of the tilted gravity: its horizontal is horizontal in the picture.
    for ax, r in zip(axes[1:], (results[0], results[-1])):
        c, s = np.cos(np.radians(r["stability"])), np.sin(np.radians(r["stability"]))
        p = r["positions"]
        ax.scatter((c * p[:, 0] + s * p[:, 2]) * 1e3, (-s * p[:, 0] + c * p[:, 2]) * 1e3, s=5, c="tab:blue")
        x0 = np.array([0.0, r["length"]])
        z0 = np.polyval(r["fit"], x0) - R_MEAN  # the fit is to the beads' tops; the dots are centres
        ax.plot((c * x0 + s * z0) * 1e3, (-s * x0 + c * z0) * 1e3, "r-", label=f"surface fit (through the top centres): {r['repose']:.1f} deg")
        ax.set_aspect("equal")
        ax.set_xlabel("horizontal [mm]")
        ax.set_ylabel("vertical [mm]")
        ax.set_title(f"Bo = {r['bo']:g}: at rest after the avalanche at {r['stability']:.0f} deg tilt", fontsize=9)
        ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
