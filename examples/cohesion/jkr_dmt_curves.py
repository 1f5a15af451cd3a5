"""JKR and DMT force-separation curves of two equal spheres (E = 1e7 Pa, nu = 0.3, R = 1 mm,
w = 0.05 J/m^2: E* = 5.495 MPa, r* = 0.5 mm), simulated through the engine and set against the
closed forms of Johnson, Kendall & Roberts (1971) and Derjaguin, Muller & Toporov (1975)
(docs/physics.md sections 14-15):

(a) displacement control: both spheres fixed (prescribed motion), sphere 2 driven towards
    sphere 1 from a 0.2 um gap to a 1.5 um overlap and back until the contact breaks; the force on
    the fixed sphere 1 along the path. JKR: snap-in at delta = 0 to -8/9 F_c, the branch through
    -F_c, the break at delta_c = -0.557 um with -5/9 F_c; DMT: the jump at delta = 0 both ways.
    The work done on the cycle, the integral of F d delta, is what the contact dissipated.
(b) load control: sphere 1 fixed at rest, sphere 2 free (damped contact) set just touching: the
    adhesion pulls it in to the zero-load overlap (JKR delta_0 = 0.674 um), where it comes to rest;
    then a slowly rising force (sim.particles.add_force) pulls it until it parts: JKR at
    F_c = 3/2 pi w r* = 117.8 uN, DMT at 2 pi w r* = 157.1 uN.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/cohesion/jkr_dmt_curves.py [OUTPUT_DIR] [--short]
Writes jkr_dmt_curves.png and jkr_dmt_curves.txt (in OUTPUT_DIR, default this folder); exits 1
when a measured value differs from its closed form by more than 1 % (2 % for the cycle energy).
--short (the test) raises the pulling force 4 times faster (2e-4 N/s instead of 5e-5 N/s).
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

E, NU, R, RHO, W = 1e7, 0.3, 1e-3, 2500.0, 0.05  # Pa, -, m, kg/m^3, J/m^2
E_STAR = E / (2.0 * (1.0 - NU * NU))  # Pa, two equal materials
R_STAR = 0.5 * R  # m

# --- closed forms (JKR parametric in the contact radius a) --------------------------------------
F_C = 1.5 * math.pi * W * R_STAR  # N, JKR pull-off
A_0 = (9.0 * math.pi * W * R_STAR**2 / (2.0 * E_STAR)) ** (1 / 3)  # m, zero-load contact radius
A_C = (math.pi * W * R_STAR**2 / (8.0 * E_STAR)) ** (1 / 3)  # m, the fold: d delta / da = 0
DMT_PULL = 2.0 * math.pi * W * R_STAR  # N, DMT pull-off


def jkr_delta(a):
    return a * a / R_STAR - np.sqrt(2.0 * math.pi * W * a / E_STAR)


def jkr_force(a):
    return 4.0 * E_STAR * a**3 / (3.0 * R_STAR) - np.sqrt(8.0 * math.pi * W * E_STAR * a**3)


DELTA_0 = float(jkr_delta(A_0))  # m, JKR overlap at zero load
DELTA_C = float(jkr_delta(A_C))  # m, < 0: where a displacement-controlled contact breaks
F_DELTA_C = float(jkr_force(A_C))  # N, -5/9 F_c
F_SNAP = -8.0 / 9.0 * F_C  # N, the force the contact snaps to at touching
U_CYCLE = (2.0 / 15.0 + 0.8 * 2.0 ** (2 / 3)) * math.pi * W * R_STAR * abs(DELTA_C)  # J, JKR cycle loss
DMT_DELTA_0 = (DMT_PULL / (4.0 / 3.0 * E_STAR * math.sqrt(R_STAR))) ** (2 / 3)  # m, DMT at zero load


def dmt_force(delta):
    d = np.maximum(delta, 0.0)
    return np.where(delta > 0.0, 4.0 / 3.0 * E_STAR * math.sqrt(R_STAR) * d**1.5 - DMT_PULL, 0.0)


# --- the scene --------------------------------------------------------------------------------------


def make_scene(cohesion, x1, x2, v2, fixed2, dt, damped):
    s = mpdem.Scene(name=f"jkr_dmt_{cohesion}")
    s.time(duration=100.0, dt=dt, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    law = dict(law="hertz", cohesion=cohesion, surface_energy=W, mu_static=0.0, mu_dynamic=0.0)
    law.update(dict(restitution=0.3) if damped else dict(damping_ratio=0.0))
    s.contact(particle_particle=law, particle_barrier=law)
    s.checks(max_overlap=0.0)
    s.material("bead", density=RHO, young=E, poisson=NU)
    s.particles([[x1, 0.0, 0.0], [x2, 0.0, 0.0]], [R, R], velocity=[[0.0, 0.0, 0.0], [v2, 0.0, 0.0]], id=[1, 2],
                material="bead", fixed=[1, 1 if fixed2 else 0])
    s.domain(min=[-0.01, -0.01, -0.01], max=[0.01, 0.01, 0.01])
    return mpdem.Simulation(s, threads=1, write_output=False)


def overlap(sim):
    x = sim.particles.position
    return 2.0 * R - (x[1, 0] - x[0, 0])


def repulsion(sim):
    """N, the contact force on the fixed sphere 1 along -x: > 0 pushes the spheres apart."""
    return -sim.particles.force[0, 0]


def displacement_cycle(cohesion, speed, gap=0.2e-6, depth=1.5e-6):
    """Sphere 2 driven at `speed` from `gap` to `depth` overlap and back until the contact ends.
    Returns (delta, F) samples along the path (m, N), the cycle work (J) and the booked loss."""
    dt = 1e-11 / speed  # s: 1e-11 m of travel per step
    sim = make_scene(cohesion, -R - 0.5 * gap, R + 0.5 * gap, -speed, True, dt, damped=False)
    chunk = 20  # steps between samples: 2e-10 m
    d, f = [overlap(sim)], [repulsion(sim)]
    reversed_, fine = False, False
    while True:
        sim.step(1 if fine else chunk)
        d.append(overlap(sim))
        f.append(repulsion(sim))
        if not reversed_ and d[-1] >= depth:
            sim.particles.set("velocity", [[speed, 0.0, 0.0]], ids=[2])
            reversed_ = True
        if reversed_ and not fine and cohesion == "jkr" and d[-1] < DELTA_C + 5e-9:
            # Near the fold the force has an infinite slope: 1e-12 m per step there.
            sim.particles.set("velocity", [[0.1 * speed, 0.0, 0.0]], ids=[2])
            fine = True
        if reversed_ and f[-1] == 0.0 and d[-1] < 0.0:
            break
    d, f = np.array(d), np.array(f)
    work = float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(d)))  # J, the integral of F d delta
    return d, f, work, sim.log().get("cohesion_dissipated", 0.0)  # not logged for DMT: nothing to book


def pull_off(cohesion, rate, touch=0.05e-6, settle=40000, chunk=100):
    """Sphere 2 free, just touching (overlap `touch`), pulled in by the adhesion and damped to
    rest, then pulled along +x by a force rising at `rate` (N/s) in steps of `chunk` dt. Returns
    the rest overlap (m), the applied force when the contact ended (N) and the path (delta,
    F applied) in m, N."""
    dt = 1e-6
    sim = make_scene(cohesion, -R + 0.5 * touch, R - 0.5 * touch, 0.0, False, dt, damped=True)
    sim.step(settle)
    rest = overlap(sim)
    d, f = [rest], [0.0]
    applied = 0.0
    while repulsion(sim) != 0.0 or overlap(sim) > 0.0:
        applied += rate * chunk * dt
        sim.particles.add_force([2], [applied, 0.0, 0.0])
        sim.step(chunk)
        d.append(overlap(sim))
        f.append(applied)
        if applied > 2.0 * DMT_PULL:
            break
    return rest, applied, np.array(d), np.array(f)


def markers(d, spacing, shift):
    """Indices of the samples of the path d (m) at least `spacing` |delta_c| apart in overlap
    (offset by `shift` spacings, so that two curves' markers do not sit on each other)."""
    keep, last = [], None
    for k, x in enumerate(d / abs(DELTA_C) + shift * spacing):
        if last is None or abs(x - last) >= spacing:
            keep.append(k)
            last = x
    return np.array(keep, dtype=int)


def main(out, short):
    out.mkdir(parents=True, exist_ok=True)
    # m/s, displacement control: with both spheres prescribed only the travel per step matters.
    speed = 1e-5
    # N/s, load control: the contact parts a little after the load passes the pull-off (the
    # sphere needs time to run to the break), by about 0.7 % at 2e-4 N/s, falling as rate^(2/3).
    rate = 2e-4 if short else 5e-5
    runs = {c: displacement_cycle(c, speed) for c in ("jkr", "dmt")}
    pulls = {c: pull_off(c, rate) for c in ("jkr", "dmt")}

    dj, fj, work_j, booked_j = runs["jkr"]
    dd, fd, work_d, booked_d = runs["dmt"]
    held = np.nonzero(fj != 0.0)[0]
    last = held[-1]  # the last sample the JKR neck held
    first = held[0]  # the first sample in contact (snap-in)
    first_dmt = np.nonzero(fd != 0.0)[0]
    rows = [  # name, measured, closed form, unit scale, unit, tolerance
        ("JKR zero-load overlap delta_0 (load control, at rest)", pulls["jkr"][0], DELTA_0, 1e6, "um", 0.01),
        ("JKR pull-off force F_c (load control)", pulls["jkr"][1], F_C, 1e6, "uN", 0.01),
        ("JKR snap-in force at delta = 0 (-8/9 F_c)", fj[first], F_SNAP, 1e6, "uN", 0.01),
        ("JKR least force on unloading (-F_c)", fj.min(), -F_C, 1e6, "uN", 0.01),
        ("JKR break overlap delta_c (displacement control)", dj[last], DELTA_C, 1e6, "um", 0.01),
        ("JKR force at the break F(delta_c) (-5/9 F_c)", fj[last], F_DELTA_C, 1e6, "uN", 0.01),
        ("JKR cycle energy, integral of F d delta", work_j, U_CYCLE, 1e12, "pJ", 0.02),
        ("JKR cycle energy booked (log cohesion_dissipated)", booked_j, U_CYCLE, 1e12, "pJ", 0.02),
        ("DMT zero-load overlap (load control, at rest)", pulls["dmt"][0], DMT_DELTA_0, 1e6, "um", 0.01),
        ("DMT pull-off force 2 pi w r* (load control)", pulls["dmt"][1], DMT_PULL, 1e6, "uN", 0.01),
        ("DMT force at first contact (-2 pi w r*)", fd[first_dmt[0]], -DMT_PULL, 1e6, "uN", 0.01),
        ("DMT force at the last contact (-2 pi w r*)", fd[first_dmt[-1]], -DMT_PULL, 1e6, "uN", 0.01),
    ]
    ok = True
    lines = [f"# two equal spheres E = {E:g} Pa, nu = {NU}, R = {R * 1e3:g} mm, w = {W} J/m^2: "
             f"E* = {E_STAR / 1e6:.4f} MPa, r* = {R_STAR * 1e3:g} mm ({'short' if short else 'full'} run)",
             f"# displacement control: {speed * 1e6:g} um/s, 1e-11 m per step (1e-12 m near delta_c); "
             f"load control: dF/dt = {rate:g} N/s from rest",
             "quantity,measured,closed_form,unit,relative_error,tolerance,pass"]
    for name, m, c, scale, unit, tol in rows:
        err = abs(m - c) / abs(c)
        ok &= err <= tol
        lines.append(f"{name},{m * scale:.5g},{c * scale:.5g},{unit},{err:.2e},{tol:g},{'yes' if err <= tol else 'NO'}")
    lines.append(f"# DMT cycle: integral of F d delta = {work_d * 1e12:.4f} pJ (closed form 0: DMT's force is a "
                 f"potential's), booked {booked_d * 1e12:.4f} pJ")
    dmt_ok = abs(work_d) <= 0.01 * U_CYCLE
    ok &= dmt_ok
    lines.append(f"# {'all within tolerance' if ok else 'FAILED: a value is outside its tolerance'}")
    text = "\n".join(lines) + "\n"
    (out / "jkr_dmt_curves.txt").write_text(text)

    # --- plot ---
    a = np.linspace(1e-9, 1.6 * A_0, 2000)
    x_jkr, y_jkr = jkr_delta(a) / abs(DELTA_C), jkr_force(a) / F_C
    stable = a >= A_C
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 5))
    ax.axhline(0.0, color="k", lw=0.6)
    ax.axvline(0.0, color="k", lw=0.6)
    ax.plot(x_jkr[stable], y_jkr[stable], "C0-", lw=1.4, label="JKR closed form (stable branch)")
    ax.plot(x_jkr[~stable], y_jkr[~stable], "C0:", lw=1.0, label="JKR closed form (unstable, a < a_c)")
    xd = np.linspace(-1.2, 3.8, 600) * abs(DELTA_C)
    ax.plot(xd / abs(DELTA_C), dmt_force(xd) / F_C, "C3-", lw=1.4, label="DMT closed form")
    for d, f, col, name, shift in ((dj, fj, "C0", "JKR", 0.0), (dd, fd, "C3", "DMT", 0.5)):
        turn = int(np.argmax(d))
        ax.plot(d / abs(DELTA_C), f / F_C, "-", color=col, lw=0.5, alpha=0.6)  # the path, jumps included
        app, rec = markers(d[:turn], 0.1, shift), turn + markers(d[turn:], 0.1, shift)
        ax.plot(d[app] / abs(DELTA_C), f[app] / F_C, ">", ms=4.5, mfc="none", color=col,
                label=f"mpdem {name}, approaching")
        ax.plot(d[rec] / abs(DELTA_C), f[rec] / F_C, "<", ms=3.5, color=col, label=f"mpdem {name}, receding")
    ax.plot([dj[last] / abs(DELTA_C)], [fj[last] / F_C], "k*", ms=10, label="JKR break (last held)")
    ax.set_xlim(-1.3, 2.9)
    ax.set_ylim(-1.5, 2.2)
    ax.set_xlabel(r"overlap $\delta / |\delta_c|$  ($|\delta_c|$ = %.3f um)" % (abs(DELTA_C) * 1e6))
    ax.set_ylabel(r"force $F / F_c$ (> 0 repulsive; $F_c$ = %.1f uN)" % (F_C * 1e6))
    ax.set_title("(a) displacement control: both spheres prescribed", fontsize=10)
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(alpha=0.3)

    ax2.axhline(0.0, color="k", lw=0.6)
    ax2.axvline(0.0, color="k", lw=0.6)
    ax2.plot(x_jkr[stable], -y_jkr[stable], "C0-", lw=1.4, label="JKR closed form: applied pull = -F")
    ax2.plot(x_jkr[~stable], -y_jkr[~stable], "C0:", lw=1.0)
    ax2.plot(xd / abs(DELTA_C), -dmt_force(xd) / F_C, "C3-", lw=1.4, label="DMT closed form")
    for c, col in (("jkr", "C0"), ("dmt", "C3")):
        _, applied, d, f = pulls[c]
        k = markers(d, 0.04, 0.0)
        ax2.plot(d[k] / abs(DELTA_C), f[k] / F_C, "o", ms=3.5, mfc="none", color=col,
                 label=f"mpdem {c.upper()}: parted at {applied * 1e6:.2f} uN")
    ax2.axhline(1.0, color="C0", lw=0.6, ls="--")
    ax2.axhline(DMT_PULL / F_C, color="C3", lw=0.6, ls="--")
    ax2.set_xlim(-1.3, 2.9)
    ax2.set_ylim(-0.2, 1.6)
    ax2.set_xlabel(r"overlap $\delta / |\delta_c|$")
    ax2.set_ylabel(r"applied pull / $F_c$")
    ax2.set_title("(b) load control: sphere 2 free, pulled by a rising force", fontsize=10)
    ax2.legend(fontsize=7, loc="upper right")
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "jkr_dmt_curves.png", dpi=120)
    print(text, end="")
    return ok


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    ok = main(Path(args[0]) if args else Path(__file__).parent, "--short" in sys.argv[1:])
    sys.exit(0 if ok else 1)
