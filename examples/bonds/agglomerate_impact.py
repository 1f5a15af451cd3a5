"""A bonded agglomerate hitting a rigid wall at several speeds: the fraction of broken bonds (the
damage ratio) against the impact energy, and the fragments.

The agglomerate: 1000 spheres, radii uniform in 0.8-1.2 mm, 2500 kg/m^3, packed at a solid
fraction of 0.55 in a sphere of 12.4 mm (`mpdem agglomerate`, seed 3) and bonded where their
surfaces are closer than 50 um (5.5 bonds per particle): Potyondy-Cundall parallel bonds
(docs/physics.md "Parallel bonds") with lambda = 1, E_b = 1 GPa, k_n/k_s = 2.5, tensile and shear
strengths 2 MPa, damping 0.1 of critical; Hertz-Mindlin contacts (E = 10 GPa, nu = 0.25,
restitution 0.5, friction 0.3) between the spheres and with the wall (E = 100 GPa). It starts
50 um above the wall, moving at v straight down, without gravity, for the time it takes to
reach the wall plus 1 ms (the breaking is over within about 0.4 ms of the first touch).

What is compared with the literature is the shape of the damage curve, no number: little damage
below a threshold speed, then a steep rise of the damage ratio, then a slower growth towards
saturation as the agglomerate shatters; the largest fragment falls from the whole agglomerate
to a small part of it over the same range (README.md, "Sources", for what each paper reports).

The impact at one speed (5 m/s) also writes particle and bond VTU files (ParaView:
OUTPUT_DIR/output/agglomerate_impact/particles.pvd and bonds.pvd) and is drawn without ParaView
(matplotlib): side views before, during and after the impact, the fragments after it coloured
by the clusters of particles the intact bonds still hold together (a union-find over the bonds).

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/bonds/agglomerate_impact.py [OUTPUT_DIR] [--short]
Writes agglomerate_impact.png, agglomerate_impact_fragments.png and agglomerate_impact.txt
(--short: agglomerate_impact_short.*) in OUTPUT_DIR (default this folder); about 4 minutes on one
core. Exits 1 unless the damage grows with the speed (each speed's damage ratio at least the
previous one's less 0.02), stays below 0.05 at the lowest speed and exceeds 0.5 at the highest.
--short (the test): 300 particles at 1 and 8 m/s, 0.6 ms each; exits 1 unless the damage at 8 m/s
exceeds the damage at 1 m/s by more than 0.1 and the largest fragment is smaller.
"""

import math
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bonded import agglomerate, draw_view, fragment_colours, fragments  # noqa: E402

RHO = 2500.0  # kg/m^3
E_B, SIGMA_C, TAU_C, ZETA = 1e9, 2e6, 2e6, 0.1  # Pa, Pa, Pa, bond damping ratio
E_PARTICLE, E_WALL = 1e10, 1e11  # Pa, Hertz contacts
GAP = 50e-6  # m, start above the wall
DT = 2.5e-7  # s: 1/37 of the stiffest bond's critical step, 1/9 of the spheres' Rayleigh time
AFTER = 1e-3  # s, simulated after the first touch
SAMPLE = 200  # steps between samples of the broken count
SPEEDS = (0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0, 14.0)  # m/s
PICTURED = 5.0  # m/s, the speed written as VTU and drawn


def scene(ids, x, r, bond_file, v, duration, name):
    s = mpdem.Scene(name=name)
    s.time(duration=duration, dt=DT, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    # Single spheres meet the wall at up to 14 m/s: Hertz overlaps of up to ~12 % of the smaller
    # radius are resolved (the step is 1/9 of the Rayleigh time) and physical here.
    s.checks(max_overlap=0.15)
    s.material("grain", density=RHO, young=E_PARTICLE, poisson=0.25)
    s.material("wall", density=7800.0, young=E_WALL, poisson=0.25)
    law = dict(restitution=0.5, mu_static=0.3, mu_dynamic=0.3)
    s.contact(particle_particle=law, particle_barrier=law)
    s.bonds(young=E_B, radius_ratio=1.0, stiffness_ratio=2.5, tensile_strength=SIGMA_C, shear_strength=TAU_C,
            damping=ZETA, file=str(bond_file))
    velocity = np.zeros_like(x)
    velocity[:, 2] = -v
    s.particles(x, r, id=ids, velocity=velocity, material="grain")
    z0, w = (x[:, 2] - r).min() - GAP, 0.1  # m, the wall's height and half width
    s.barriers([[[-w, -w, z0], [w, -w, z0], [w, w, z0]], [[-w, -w, z0], [w, w, z0], [-w, w, z0]]], group="wall",
               material="wall")
    s.domain(min=[-0.2, -0.2, z0 - 0.01], max=[0.2, 0.2, 0.2])
    return s


def impact(ids, x, r, bond_file, v, after, out=None):
    """One impact at v (m/s): dict of the damage ratio over time, the breaks by mode, the fragments
    at the end, and the snapshots for the pictures (when `out` is given, the VTU series too)."""
    duration = GAP / v + after
    s = scene(ids, x, r, bond_file, v, duration, f"impact_{v:g}")
    if out is not None:
        s.output(particles_every=duration / 20, bonds_every=duration / 20, log_every=200)
    sim = mpdem.Simulation(s, threads=1, write_output=out is not None, output_dir=out)
    total = len(sim.bonds)
    t, broken, snaps = [0.0], [0.0], {}
    modes = {"tension": 0, "shear": 0}
    started = time.process_time()
    while sim.time < duration * (1.0 - 1e-12):
        sim.step(min(SAMPLE, max(1, round((duration - sim.time) / DT))))
        t.append(sim.time)
        broken.append(1.0 - sim.bonds.intact.mean())
        for m in sim.bonds.new_breaks()["mode"]:
            modes[str(m)] += 1
        if out is not None and not snaps.get("during") and sim.time >= GAP / v + 0.1e-3:
            snaps["during"] = (sim.time, sim.particles.position)
    cpu = time.process_time() - started
    if out is not None:
        sim.close()
    b = sim.bonds
    labels, sizes = fragments(sim.particles.id, b.id_i, b.id_j, b.intact)
    mass = sim.particles.mass
    largest = mass[labels == 0].sum() / mass.sum()
    return dict(v=v, energy=0.5 * mass.sum() * v * v, t=np.array(t) - GAP / v, broken=np.array(broken),
                total=total, modes=modes, largest=largest, pieces=int((sizes >= 2).sum()),
                singles=int((sizes == 1).sum()), labels=labels, x=sim.particles.position, r=sim.particles.radius,
                snaps=snaps, cpu=cpu, bond_energy=sim.log()["bond_break_energy"])


def main(out, short):
    out.mkdir(parents=True, exist_ok=True)
    stem = "agglomerate_impact_short" if short else "agglomerate_impact"
    work = out / "output" / stem
    work.mkdir(parents=True, exist_ok=True)
    count, speeds, after = (300, (1.0, 8.0), 0.6e-3) if short else (1000, SPEEDS, AFTER)
    ids, x, r, bond_file, report = agglomerate(
        work / "agglomerate", "-n", count, "--distribution", "uniform", "--rmin", 0.8e-3, "--rmax", 1.2e-3,
        "-f", 0.55, "--gap", 50e-6, "--seed", 3)
    runs = []
    for v in speeds:
        pictured = (not short and v == PICTURED) or (short and v == speeds[-1])
        runs.append(impact(ids, x, r, bond_file, v, after, work / f"v{v:g}" if pictured else None))
        k = runs[-1]
        print(f"v = {v:g} m/s: broken {k['broken'][-1]:.4f}, largest fragment {k['largest']:.4f}, "
              f"{k['cpu']:.1f} s CPU", flush=True)

    damage = np.array([k["broken"][-1] for k in runs])
    largest = np.array([k["largest"] for k in runs])
    if short:
        checks = [("damage at the higher speed exceeds the lower's by more than 0.1", damage[1] - damage[0] > 0.1),
                  ("the largest fragment is smaller at the higher speed", largest[1] < largest[0])]
    else:
        rises = bool(np.all(np.diff(damage) >= -0.02))
        checks = [("damage grows with the speed (each at least the previous less 0.02)", rises),
                  (f"damage at {speeds[0]:g} m/s below 0.05", damage[0] < 0.05),
                  (f"damage at {speeds[-1]:g} m/s above 0.5", damage[-1] > 0.5)]
    ok = all(c for _, c in checks)
    m_total = 4.0 / 3.0 * math.pi * RHO * (r**3).sum()
    lines = [f"# {len(ids)} spheres r = 0.8-1.2 mm, {RHO:g} kg/m^3, {m_total * 1e3:.4g} g; {runs[0]['total']} bonds "
             f"(lambda 1, E_b {E_B:g} Pa, k_n/k_s 2.5, sigma_c {SIGMA_C:g} Pa, tau_c {TAU_C:g} Pa, damping {ZETA}); "
             f"Hertz E {E_PARTICLE:g} Pa, wall {E_WALL:g} Pa, e 0.5, mu 0.3; dt {DT:g} s, "
             f"{after * 1e3:g} ms after the first touch",
             "# " + report.strip().replace("\n", "\n# "),
             "speed_m_s,impact_energy_J,broken_fraction,broken_tension,broken_shear,largest_fragment_mass_fraction,"
             "fragments_of_2_or_more,single_spheres,bond_energy_at_breaks_J,cpu_s"]
    for k in runs:
        lines.append(f"{k['v']:g},{k['energy']:.5g},{k['broken'][-1]:.4f},{k['modes']['tension']},"
                     f"{k['modes']['shear']},{k['largest']:.4f},{k['pieces']},{k['singles']},"
                     f"{k['bond_energy']:.4g},{k['cpu']:.1f}")
    for name, passed in checks:
        lines.append(f"# check: {name}: {'yes' if passed else 'NO'}")
    lines.append(f"# {'all checks pass' if ok else 'FAILED: a check does not hold'}")
    text = "\n".join(lines) + "\n"
    (out / f"{stem}.txt").write_text(text)

    # --- damage curve ---
    energy = np.array([k["energy"] for k in runs])
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 5))
    ax.semilogx(energy, damage, "C0o-", label="broken bonds / initial bonds (damage ratio)")
    ax.semilogx(energy, largest, "C3s--", mfc="none", label="largest fragment / agglomerate mass")
    for k in runs:
        ax.annotate(f"{k['v']:g} m/s", (k["energy"], k["broken"][-1]), textcoords="offset points", xytext=(4, -11),
                    fontsize=7)
    ax.set_xlabel("impact energy 1/2 M v^2 [J]")
    ax.set_ylabel("fraction")
    ax.set_ylim(-0.03, 1.03)
    ax.set_title(f"(a) {len(ids)} bonded spheres against a wall: damage and largest fragment", fontsize=10)
    ax.legend(fontsize=8, loc="center left")
    ax.grid(alpha=0.3, which="both")
    cmap = plt.get_cmap("viridis")
    for n, k in enumerate(runs):
        ax2.plot(k["t"] * 1e3, k["broken"], color=cmap(n / max(1, len(runs) - 1)), label=f"{k['v']:g} m/s")
    ax2.set_xlabel("time after the first touch [ms]")
    ax2.set_ylabel("broken bonds / initial bonds")
    ax2.set_title("(b) the damage over time: over within ~0.4 ms", fontsize=10)
    ax2.legend(fontsize=7, ncol=2)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / f"{stem}.png", dpi=120)
    plt.close(fig)

    # --- the pictured impact, without ParaView ---
    k = next(k for k in runs if (short and k["v"] == speeds[-1]) or (not short and k["v"] == PICTURED))
    fig, axs = plt.subplots(1, 4, figsize=(19, 5.4))
    colours = fragment_colours(k["labels"])
    grey = [(0.75, 0.75, 0.85)] * len(ids)
    td, xd = k["snaps"]["during"]
    states = (x, xd, k["x"])
    draw_view(axs[0], x, r, grey, f"t = 0: {len(ids)} spheres, {k['total']} bonds, moving down at {k['v']:g} m/s")
    draw_view(axs[1], xd, r, colours, f"{(td - GAP / k['v']) * 1e3:.2f} ms after the first touch")
    draw_view(axs[2], k["x"], r, colours,
              f"{k['t'][-1] * 1e3:.2f} ms: {k['pieces']} fragments of 2 or more, {k['singles']} single spheres")
    draw_view(axs[3], k["x"], r, colours, f"{k['t'][-1] * 1e3:.2f} ms seen from above; largest fragment "
              f"{k['largest']:.0%} of the mass", top=True)
    wall = 1e3 * ((x[:, 2] - r).min() - GAP)  # mm
    reach = 1e3 * max(np.abs(p[:, :2]).max() for p in states) + 1.5  # mm, every sphere in view
    height = 1e3 * max((p[:, 2] + r).max() for p in states) + 0.5
    for a in axs[:3]:
        a.axhline(wall, color="k", lw=2)
        a.set_xlim(-reach, reach)
        a.set_ylim(wall - 1.0, height)
    axs[3].set_xlim(-reach, reach)
    axs[3].set_ylim(-reach, reach)
    fig.suptitle(f"Impact at {k['v']:g} m/s, seen along y (wall: black line) and from above; colours: the 9 largest fragments, "
                 "light grey smaller pieces, dark grey single spheres", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / f"{stem}_fragments.png", dpi=120)
    plt.close(fig)
    print(text, end="")
    return ok


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    sys.exit(0 if main(Path(args[0]) if args else Path(__file__).parent, "--short" in sys.argv[1:]) else 1)
