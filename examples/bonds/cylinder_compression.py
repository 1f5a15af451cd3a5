"""Uniaxial compression of a bonded cylinder between two plates, to failure: the stress-strain
curve, the peak strength and the apparent Young's modulus, for two bond moduli E_b.

The specimen: spheres of radii uniform in 0.8-1.2 mm, 2500 kg/m^3, packed at a solid fraction
of 0.55 in a closed cylinder 20 mm across and 40 mm high (`mpdem mesh cylinder` -> STL ->
`mpdem agglomerate --stl`, seed 5: 1584 spheres) and bonded where their surfaces are closer than
50 um: Potyondy-Cundall parallel bonds (docs/physics.md "Parallel bonds") with lambda = 1,
k_n/k_s = 2.5, tensile and shear strengths 2 MPa, damping 0.2 of critical. Contacts: linear
springs (PFC's choice beside parallel bonds) with k_n = E_b pi (1 mm) / 2, the bond stiffness
k_n A of a pair of 1 mm spheres, and k_t = k_n / 2.5, restitution 0.5, friction 0.5 between the
spheres and none with the plates (steel), so that the plates do not confine the ends. The lower
plate rests; the upper one moves down at 0.02 m/s from the specimen's top (a strain rate of
0.5 /s: the time to the peak is 70-100 times the time a wave takes through the specimen).
The same tests are run with Hertz-Mindlin contacts (E_c = 10 E_b, nu 0.25) for comparison.

Stress: the mean of the two plates' forces over the cylinder's cross-section pi R^2. Strain:
(a) the plates' approach over the initial height; (b) a gauge strain, the shortening of the
distance between the mean heights of the spheres in two bands (at 20-30 % and 70-80 % of the
height), as a laboratory's axial gauges measure it away from the plates (the plates' seating on
the rough ends adds compliance to (a)). The apparent modulus E_app is the slope of stress
against gauge strain between 10 % and 50 % of the peak stress (least squares).

The check: with lambda, kappa, the strengths and the contacts' stiffness over E_b held, E_app is
proportional to E_b (Potyondy & Cundall 2004 report the bonded-particle model's modulus set by
the bond and contact moduli at fixed ratios of the other parameters), so E_app / E_b must be the
same for E_b = 1 GPa and 2 GPa within 2 % with the linear contacts. With Hertz contacts the
contacts' share of the stiffness does not scale with E_b (F ~ E_c delta^(3/2)): their spread is
reported, not checked.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/bonds/cylinder_compression.py [OUTPUT_DIR] [--short]
Writes cylinder_compression.png and cylinder_compression.txt (--short: cylinder_compression_short.*)
in OUTPUT_DIR (default this folder); about 2 minutes on one core. Exits 1 when the two E_app / E_b
with linear contacts differ by more than 2 % (relative) or a specimen shows no failure (the stress
at the end above half the peak). --short (the test): a cylinder 10 mm across and 20 mm high
(seed 2: 202 spheres), linear contacts only, the same checks; about 10 s.
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
from bonded import agglomerate, draw_view, fragment_colours, fragments, run_tool  # noqa: E402

RHO = 2500.0  # kg/m^3
STRENGTH, ZETA = 2e6, 0.2  # Pa (tensile and shear), bond damping ratio
E_BONDS = (1e9, 2e9)  # Pa
HERTZ_RATIO = 10.0  # E_c / E_b of the Hertz variant
LINEAR_K = 1e-3 * math.pi / 2.0  # m: the linear contacts' k_n = E_b A / L of a 1 mm pair, over E_b
SPEED = 0.02  # m/s, the upper plate
DT_1GPA = 2.5e-7  # s at E_b = 1 GPa (E_c = 10 GPa), scaled by sqrt(1 GPa / E_b)
SAMPLE = 100  # steps between samples
FIT = (0.1, 0.5)  # the part of the rise, in fractions of the peak stress, that E_app is fitted to
TOLERANCE = 0.02  # relative, between the two E_app / E_b


def square(z, up, half):
    """Two triangles of a square plate at height z (m), normal +z when `up`, else -z."""
    a, b, c, d = [-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]
    return [[a, b, c], [a, c, d]] if up else [[a, c, b], [a, d, c]]


def compress(ids, x, r, bond_file, e_b, law, radius, strain_end):
    """One test with contacts of `law` ("linear" or "hertz"): samples of (platen strain, gauge strain, stress Pa, top and bottom stresses Pa,
    broken fraction) and the state at the end."""
    dt = DT_1GPA * math.sqrt(1e9 / e_b)
    z_lo, z_hi = (x[:, 2] - r).min(), (x[:, 2] + r).max()
    h0 = z_hi - z_lo
    duration = strain_end * h0 / SPEED
    s = mpdem.Scene(name=f"cylinder_{law}_{e_b:g}")
    s.time(duration=duration, dt=dt, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    s.material("grain", density=RHO, young=HERTZ_RATIO * e_b, poisson=0.25)
    s.material("steel", density=7800.0, young=2e11, poisson=0.3)
    # Linear: k_n = E_b A / L of a 1 mm pair, k_t = k_n / 2.5 (PFC's linear contacts beside the
    # parallel bonds), the same on the plates. Hertz: from the materials' young.
    k = dict(law="linear", stiffness_normal=LINEAR_K * e_b, stiffness_tangential=LINEAR_K * e_b / 2.5)
    keys = k if law == "linear" else dict(law="hertz")
    s.contact(particle_particle=dict(restitution=0.5, mu_static=0.5, mu_dynamic=0.5, **keys),
              particle_barrier=dict(restitution=0.5, mu_static=0.0, mu_dynamic=0.0, **keys))
    s.bonds(young=e_b, radius_ratio=1.0, stiffness_ratio=2.5, tensile_strength=STRENGTH, shear_strength=STRENGTH,
            damping=ZETA, file=str(bond_file))
    s.particles(x, r, id=ids, material="grain")
    s.barriers(square(z_lo, True, 3 * radius), group="bottom", material="steel")
    s.barriers(square(z_hi, False, 3 * radius), group="top", material="steel", motion={"a": [0.0, 0.0, -SPEED]})
    s.domain(min=[-10 * radius, -10 * radius, z_lo - h0], max=[10 * radius, 10 * radius, z_hi + h0])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    area = math.pi * radius**2
    z0 = sim.particles.position[:, 2]
    low = (z0 > z_lo + 0.2 * h0) & (z0 < z_lo + 0.3 * h0)
    high = (z0 > z_lo + 0.7 * h0) & (z0 < z_lo + 0.8 * h0)
    gauge0 = z0[high].mean() - z0[low].mean()
    rows = [(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)]
    started = time.process_time()
    while sim.time < duration * (1.0 - 1e-12):
        sim.step(SAMPLE)
        z = sim.particles.position[:, 2]
        top, bottom = sim.barriers.force("top")[2] / area, -sim.barriers.force("bottom")[2] / area
        rows.append((sim.time * SPEED / h0, 1.0 - (z[high].mean() - z[low].mean()) / gauge0, 0.5 * (top + bottom),
                     top, bottom, 1.0 - sim.bonds.intact.mean()))
    b = sim.bonds
    labels, _ = fragments(sim.particles.id, b.id_i, b.id_j, b.intact)
    return dict(e_b=e_b, law=law, dt=dt, h0=h0, gauge0=gauge0, n_gauge=(int(low.sum()), int(high.sum())),
                data=np.array(rows), bonds=len(b), x=sim.particles.position, r=sim.particles.radius, labels=labels,
                cpu=time.process_time() - started)


def analyse(run):
    """Peak, strains at the peak, E_app (gauge and platen) and the stress left at the end."""
    eps, gauge, stress = run["data"][:, 0], run["data"][:, 1], run["data"][:, 2]
    k = int(np.argmax(stress))
    peak = stress[k]
    rise = (stress[:k] > FIT[0] * peak) & (stress[:k] < FIT[1] * peak)
    run.update(peak=peak, eps_peak=eps[k], gauge_peak=gauge[k], broken_peak=run["data"][k, 5],
               e_app=np.polyfit(gauge[:k][rise], stress[:k][rise], 1)[0],
               e_platen=np.polyfit(eps[:k][rise], stress[:k][rise], 1)[0], fit_points=int(rise.sum()),
               end_stress=stress[-1], broken_end=run["data"][-1, 5])
    run["ratio"] = run["e_app"] / run["e_b"]
    return run


def main(out, short):
    out.mkdir(parents=True, exist_ok=True)
    stem = "cylinder_compression_short" if short else "cylinder_compression"
    work = out / "output" / stem
    work.mkdir(parents=True, exist_ok=True)
    radius, height = (5e-3, 20e-3) if short else (10e-3, 40e-3)  # m
    run_tool("mesh", "cylinder", "--radius", radius, "--height", height, "--segments", 64, "--closed", "-o",
             work / "cylinder.stl")
    ids, x, r, bond_file, report = agglomerate(
        work / "cylinder", "--stl", work / "cylinder.stl", "--scale", 1, "-f", 0.55, "--distribution", "uniform",
        "--rmin", 0.8e-3, "--rmax", 1.2e-3, "--gap", 50e-6, "--seed", 2 if short else 5)
    runs = []
    for law in ("linear",) if short else ("linear", "hertz"):
        for e_b in E_BONDS:
            # the peak comes near a plate strain of 3.5e-3 at E_b = 1 GPa: run to twice that
            runs.append(analyse(compress(ids, x, r, bond_file, e_b, law, radius, 7e-3 * 1e9 / e_b)))
            k = runs[-1]
            print(f"{law} contacts, E_b = {e_b:g} Pa: peak {k['peak'] / 1e6:.4f} MPa, E_app {k['e_app'] / 1e6:.1f} MPa "
                  f"(E_app / E_b {k['ratio']:.4f}), {k['cpu']:.1f} s CPU", flush=True)
    spread = {law: pair[1]["ratio"] / pair[0]["ratio"] - 1.0
              for law, pair in (("linear", runs[:2]), ("hertz", runs[2:4])) if pair}
    checks = [(f"linear contacts: E_app / E_b the same for both E_b within {TOLERANCE:.0%}: {spread['linear']:+.2%}",
               abs(spread["linear"]) <= TOLERANCE)]
    for k in runs:
        checks.append((f"{k['law']}, E_b = {k['e_b']:g}: failed (stress at the end {k['end_stress'] / k['peak']:.3f} of "
                       "the peak, below 0.5)", k["end_stress"] < 0.5 * k["peak"]))
    ok = all(c for _, c in checks)
    lines = [f"# cylinder {2e3 * radius:g} mm across, {1e3 * height:g} mm high: {len(ids)} spheres r = 0.8-1.2 mm, "
             f"{RHO:g} kg/m^3, {runs[0]['bonds']} bonds (lambda 1, k_n/k_s 2.5, sigma_c = tau_c = {STRENGTH:g} Pa, "
             f"damping {ZETA}); contacts linear (k_n = E_b pi (1 mm) / 2, k_t = k_n / 2.5) or Hertz (E_c = "
             f"{HERTZ_RATIO:g} E_b), e = 0.5, mu = 0.5, frictionless plates; plate speed {SPEED} m/s",
             "# " + report.strip().replace("\n", "\n# "),
             f"# stress = mean plate force / (pi R^2); gauge strain between the sphere bands at 20-30 % and 70-80 % of "
             f"the height; E_app fitted to the stress rising from {FIT[0]:.0%} to {FIT[1]:.0%} of the peak",
             "contacts,E_b_Pa,dt_s,peak_stress_MPa,platen_strain_at_peak,gauge_strain_at_peak,E_app_gauge_MPa,"
             "E_app_over_E_b,E_app_platen_MPa,fit_points,broken_at_peak,broken_at_end,cpu_s"]
    for k in runs:
        lines.append(f"{k['law']},{k['e_b']:g},{k['dt']:.4g},{k['peak'] / 1e6:.4f},{k['eps_peak']:.5f},"
                     f"{k['gauge_peak']:.5f},{k['e_app'] / 1e6:.1f},{k['ratio']:.4f},{k['e_platen'] / 1e6:.1f},"
                     f"{k['fit_points']},{k['broken_peak']:.4f},{k['broken_end']:.4f},{k['cpu']:.1f}")
    for law, d in spread.items():
        pair = [k for k in runs if k["law"] == law]
        lines.append(f"# {law} contacts: E_app / E_b at {E_BONDS[1]:g} over {E_BONDS[0]:g}: {1 + d:.4f} ({d:+.2%}); "
                     f"peak strength {pair[1]['peak'] / pair[0]['peak']:.4f}; gauge strain at the peak "
                     f"{pair[1]['gauge_peak'] / pair[0]['gauge_peak']:.4f}")
    for name, passed in checks:
        lines.append(f"# check: {name}: {'yes' if passed else 'NO'}")
    lines.append(f"# {'all checks pass' if ok else 'FAILED: a check does not hold'}")
    text = "\n".join(lines) + "\n"
    (out / f"{stem}.txt").write_text(text)

    fig, axs = plt.subplots(1, 4, figsize=(20, 5), gridspec_kw=dict(width_ratios=[1.2, 1.2, 1.0, 0.7]))
    for n, k in enumerate(runs):
        d, c = k["data"], f"C{n}"
        if k["law"] != "linear":
            axs[1].plot(d[:, 1] * k["e_b"] / 1e6, d[:, 2] / 1e6, c + "--", lw=0.9,
                        label=f"Hertz contacts, E_b = {k['e_b'] / 1e9:g} GPa: E_app / E_b = {k['ratio']:.4f}")
            continue
        axs[0].plot(1e3 * d[:, 1], d[:, 2] / 1e6, c + "-", label=f"E_b = {k['e_b'] / 1e9:g} GPa, gauge strain")
        axs[0].plot(1e3 * d[:, 0], d[:, 2] / 1e6, c + ":", label=f"E_b = {k['e_b'] / 1e9:g} GPa, plate strain")
        g = np.linspace(0.0, k["gauge_peak"], 10)
        axs[0].plot(1e3 * g, k["e_app"] * g / 1e6, "k--", lw=0.8)
        axs[1].plot(d[:, 1] * k["e_b"] / 1e6, d[:, 2] / 1e6, c + "-",
                    label=f"linear contacts, E_b = {k['e_b'] / 1e9:g} GPa: E_app / E_b = {k['ratio']:.4f}")
        axs[2].plot(1e3 * d[:, 0], d[:, 5], c + "-", label=f"E_b = {k['e_b'] / 1e9:g} GPa")
    axs[0].set_xlabel("strain [1e-3]")
    axs[0].set_ylabel("stress [MPa]")
    axs[0].set_title(f"(a) linear contacts, to failure: peaks {runs[0]['peak'] / 1e6:.3f} and {runs[1]['peak'] / 1e6:.3f} "
                     "MPa (dashed: E_app);\npast the peak the part between the gauges unloads: it fails at the upper end",
                     fontsize=9)
    axs[0].set_xlim(0.0, 1e3 * max(k["eps_peak"] for k in runs) * 1.6)
    axs[0].legend(fontsize=7)
    axs[1].set_xlabel("gauge strain x E_b [MPa]")
    axs[1].set_ylabel("stress [MPa]")
    axs[1].set_title("(b) strain x E_b: E_app / E_b differ by " + ", ".join(f"{d:+.2%} ({law})" for law, d in spread.items()),
                     fontsize=9)
    axs[1].set_xlim(0.0, max(k["gauge_peak"] * k["e_b"] for k in runs) / 1e6 * 1.3)
    axs[1].set_ylim(0.0, max(k["peak"] for k in runs) / 1e6 * 1.1)
    axs[1].legend(fontsize=7)
    axs[2].set_xlabel("plate strain [1e-3]")
    axs[2].set_ylabel("broken bonds / initial bonds")
    axs[2].set_title("(c) bonds broken, linear contacts", fontsize=9)
    axs[2].legend(fontsize=7)
    for a in axs[:3]:
        a.grid(alpha=0.3)
    k = runs[0]
    draw_view(axs[3], k["x"], k["r"], fragment_colours(k["labels"]),
              f"(d) linear, E_b = {k['e_b'] / 1e9:g} GPa at the end, by fragment", top=False)
    axs[3].set_xlim(-3e3 * radius, 3e3 * radius)
    axs[3].set_ylim(-0.1e3 * height, 1.1e3 * height)
    fig.tight_layout()
    fig.savefig(out / f"{stem}.png", dpi=120)
    plt.close(fig)
    print(text, end="")
    return ok


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    sys.exit(0 if main(Path(args[0]) if args else Path(__file__).parent, "--short" in sys.argv[1:]) else 1)
