"""A bonded agglomerate hitting a rigid wall at several speeds: the fraction of broken bonds (the
damage ratio) against the impact energy, and the fragments.

The agglomerates: 2000 spheres, radii uniform in 0.8-1.2 mm, 2500 kg/m^3, packed at a solid
fraction of 0.55 in a sphere of 15.6 mm (`mpdem agglomerate`, seeds 3, 4 and 5: three packings
of the same recipe) and bonded where their surfaces are closer than 50 um (5.5 bonds per
particle): Potyondy-Cundall parallel bonds (docs/physics.md "Parallel bonds") with lambda = 1,
E_b = 1 GPa, k_n/k_s = 2.5, tensile and shear strengths 2 MPa, damping 0.1 of critical;
Hertz-Mindlin contacts (E = 10 GPa, nu = 0.25, restitution 0.5, friction 0.3) between the spheres
and with the wall (E = 100 GPa). Each starts 50 um above the wall, moving at v straight down,
without gravity, for the time it takes to reach the wall plus 2 ms; 13 speeds from 0.25 to
20 m/s (at 28 m/s two spheres overlapped by more than 15 % of the radius: beyond Hertz).

What is compared with the literature is the shape of the damage curve, no number: little damage
below a threshold speed, then a steep rise of the damage ratio with the impact energy, then the
approach to complete breakage (an S on a logarithmic energy axis); the largest fragment falls from
the whole agglomerate to a small part of it over the same range (README.md, "Sources", says
what each paper reports).

The impact of the first agglomerate at 5 m/s also writes particle and bond VTU files (ParaView:
OUTPUT_DIR/output/agglomerate_impact/v5/particles.pvd and bonds.pvd) and is drawn without
ParaView (matplotlib): side views before, during and after the impact and a view from above,
coloured by fragment: the clusters of particles that the intact bonds still hold together (a
union-find over the bonds).

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/bonds/agglomerate_impact.py [OUTPUT_DIR] [--short]
Writes agglomerate_impact.png, agglomerate_impact_fragments.png and agglomerate_impact.txt
(--short: agglomerate_impact_short.*) in OUTPUT_DIR (default this folder); about 4 minutes on one
core. Exits 1 unless the mean damage ratio of the three agglomerates grows with the speed (each at
least the previous one's less 0.02), stays below 0.05 at the lowest speed and exceeds 0.8 at the
highest. --short (the test): one agglomerate of 300 particles at 1 and 8 m/s, 0.6 ms each; exits 1
unless the damage at 8 m/s exceeds the damage at 1 m/s by more than 0.1 and the largest fragment
is smaller. About 3 s.
"""

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
AFTER = 2e-3  # s, simulated after the first touch
SAMPLE = 200  # steps between samples of the broken count
SPEEDS = (0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 14.0, 20.0)  # m/s
SEEDS = (3, 4, 5)  # agglomerates: the same recipe, three packings
COUNT = 2000  # spheres per agglomerate
PICTURED = 5.0  # m/s, the speed written as VTU and drawn


def scene(ids, x, r, bond_file, v, duration, name):
    s = mpdem.Scene(name=name)
    s.time(duration=duration, dt=DT, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    # At 20 m/s spheres overlap each other by up to 13 % of the smaller radius (measured with
    # `mpdem run`: 9.5, 7.9 and 13 % for the three packings), above the default 5 % check but
    # resolved (the step is 1/9 of the Rayleigh time).
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
    count, speeds, seeds, after = (300, (1.0, 8.0), (3,), 0.6e-3) if short else (COUNT, SPEEDS, SEEDS, AFTER)
    runs, packed = {}, {}  # (seed, v) -> impact; seed -> the agglomerate
    for seed in seeds:
        packed[seed] = agglomerate(work / f"agglomerate_{seed}", "-n", count, "--distribution", "uniform", "--rmin",
                                   0.8e-3, "--rmax", 1.2e-3, "-f", 0.55, "--gap", 50e-6, "--seed", seed)
        ids, x, r, bond_file, _ = packed[seed]
        for v in speeds:
            pictured = seed == seeds[0] and v == (speeds[-1] if short else PICTURED)
            k = runs[seed, v] = impact(ids, x, r, bond_file, v, after, work / f"v{v:g}" if pictured else None)
            print(f"seed {seed}, v = {v:g} m/s: broken {k['broken'][-1]:.4f}, largest fragment {k['largest']:.4f}, "
                  f"{k['cpu']:.1f} s CPU", flush=True)

    # [speeds x seeds] damage ratio, largest fragment's mass fraction, impact energy (J)
    damage = np.array([[runs[s, v]["broken"][-1] for s in seeds] for v in speeds])
    largest = np.array([[runs[s, v]["largest"] for s in seeds] for v in speeds])
    energy = np.array([[runs[s, v]["energy"] for s in seeds] for v in speeds])
    mean = damage.mean(axis=1)
    if short:
        checks = [("damage at the higher speed exceeds the lower's by more than 0.1", mean[1] - mean[0] > 0.1),
                  ("the largest fragment is smaller at the higher speed", largest[1, 0] < largest[0, 0])]
    else:
        checks = [("the mean damage grows with the speed (each at least the previous less 0.02)",
                   bool(np.all(np.diff(mean) >= -0.02))),
                  (f"mean damage at {speeds[0]:g} m/s below 0.05", mean[0] < 0.05),
                  (f"mean damage at {speeds[-1]:g} m/s above 0.8", mean[-1] > 0.8)]
    ok = all(c for _, c in checks)
    lines = [f"# {count} spheres r = 0.8-1.2 mm, {RHO:g} kg/m^3, agglomerates of seeds {', '.join(map(str, seeds))}; "
             f"bonds lambda 1, E_b {E_B:g} Pa, k_n/k_s 2.5, sigma_c {SIGMA_C:g} Pa, tau_c {TAU_C:g} Pa, damping {ZETA}; "
             f"Hertz E {E_PARTICLE:g} Pa, wall {E_WALL:g} Pa, e 0.5, mu 0.3; dt {DT:g} s, "
             f"{after * 1e3:g} ms after the first touch"]
    for seed in seeds:
        lines.append(f"# seed {seed}: " + packed[seed][4].strip().replace("\n", "; "))
    lines.append("speed_m_s,impact_energy_J,broken_fraction_mean,broken_fraction_min,broken_fraction_max,"
                 "largest_fragment_mass_fraction_mean,fragments_of_2_or_more_mean,single_spheres_mean,"
                 "broken_in_tension_share,cpu_s_per_run")
    for n, v in enumerate(speeds):
        ks = [runs[s, v] for s in seeds]
        tension = sum(k["modes"]["tension"] for k in ks)
        breaks = tension + sum(k["modes"]["shear"] for k in ks)
        lines.append(f"{v:g},{energy[n].mean():.5g},{mean[n]:.4f},{damage[n].min():.4f},{damage[n].max():.4f},"
                     f"{largest[n].mean():.4f},{np.mean([k['pieces'] for k in ks]):.1f},"
                     f"{np.mean([k['singles'] for k in ks]):.1f},{tension / breaks if breaks else 0:.3f},"
                     f"{np.mean([k['cpu'] for k in ks]):.1f}")
    for name, passed in checks:
        lines.append(f"# check: {name}: {'yes' if passed else 'NO'}")
    lines.append(f"# {'all checks pass' if ok else 'FAILED: a check does not hold'}")
    text = "\n".join(lines) + "\n"
    (out / f"{stem}.txt").write_text(text)

    # --- damage curve ---
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 5))
    e = energy.mean(axis=1)
    ax.fill_between(e, damage.min(axis=1), damage.max(axis=1), color="C0", alpha=0.2, lw=0)
    ax.semilogx(e, mean, "C0o-", label=f"broken bonds / initial bonds (damage ratio), mean and range of {len(seeds)}")
    ax.fill_between(e, largest.min(axis=1), largest.max(axis=1), color="C3", alpha=0.15, lw=0)
    ax.semilogx(e, largest.mean(axis=1), "C3s--", mfc="none", label="largest fragment / agglomerate mass")
    mass = (e / (0.5 * np.asarray(speeds) ** 2)).mean()  # kg, the agglomerates' mean mass
    top = ax.secondary_xaxis("top", functions=(lambda en: np.sqrt(2.0 * np.maximum(en, 1e-30) / mass),
                                               lambda v: 0.5 * mass * np.asarray(v) ** 2))
    top.set_xticks([0.25, 0.5, 1, 2, 5, 10, 20])
    top.set_xticklabels(["0.25", "0.5", "1", "2", "5", "10", "20"])
    top.set_xlabel("impact speed [m/s]")
    ax.set_xlabel("impact energy 1/2 M v^2 [J]")
    ax.set_ylabel("fraction")
    ax.set_ylim(-0.03, 1.03)
    ax.set_title(f"(a) {count} bonded spheres against a wall: damage and largest fragment", fontsize=10, pad=28)
    ax.legend(fontsize=8, loc="center left")
    ax.grid(alpha=0.3, which="both")
    cmap = plt.get_cmap("viridis")
    for n, v in enumerate(speeds):
        k = runs[seeds[0], v]
        ax2.plot(k["t"] * 1e3, k["broken"], color=cmap(n / max(1, len(speeds) - 1)), label=f"{v:g} m/s")
    ax2.set_xlabel("time after the first touch [ms]")
    ax2.set_ylabel("broken bonds / initial bonds")
    ax2.set_title(f"(b) the damage over time (seed {seeds[0]})", fontsize=10)
    ax2.legend(fontsize=7, ncol=2)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / f"{stem}.png", dpi=120)
    plt.close(fig)

    # --- the pictured impact, without ParaView ---
    k = runs[seeds[0], speeds[-1] if short else PICTURED]
    ids, x, r = packed[seeds[0]][:3]
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
