"""A bonded cantilever: a chain of 11 touching spheres (r = 1 mm, 2500 kg/m^3) joined by 10
Potyondy-Cundall parallel bonds (lambda = 1, E_b = 1 GPa, k_n/k_s = 2.5; docs/physics.md
"Parallel bonds"), the first sphere fixed, loaded at the last one and damped to rest (the bonds'
dashpots at 0.7 of critical and a [fields] drag of 0.04 N s/m), set against beam theory:

- a 1 mN tip load across the chain (sim.particles.add_force): the deflection of every sphere
  against Euler-Bernoulli's y(x) = F x^2 (3 L - x) / (6 E I) (L = 20 mm, I = pi r^4 / 4: the tip
  F L^3 / (3 E I) = 3.395 um) and against the chain's own discrete closed form (README.md): bond
  m carries the moment F l (N - m - 1/2), which turns it by that l / (E I), and the shear F, which
  slides it by kappa F l / (E A); the tip y = F l^3 N (4 N^2 - 1) / (12 E I) + N kappa F l / (E A);
- a 1 mN pull along the chain: the stretch F L / (E A);
- a 1 uN m torque about the chain's axis: the twist T L / (G J), G = E / kappa, J = 2 I.

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/bonds/cantilever.py [OUTPUT_DIR]
Writes cantilever.png and cantilever.txt (in OUTPUT_DIR, default this folder); exits 1 when the
tip deflection differs from the discrete closed form by more than 1e-3 or from Euler-Bernoulli by
more than 3 %, or the stretch or the twist from theirs by more than 1e-3. About 5 s.
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

R, RHO = 1e-3, 2500.0  # m, kg/m^3
E_B, KAPPA, LAMBDA = 1e9, 2.5, 1.0  # Pa, k_n/k_s, bond radius / sphere radius
N = 10  # bonds
ELL = 2.0 * R  # m, bond length (touching spheres)
L = N * ELL  # m, cantilever length (fixed centre to tip centre)
AREA = math.pi * (LAMBDA * R) ** 2  # m^2
I = AREA * (LAMBDA * R) ** 2 / 4.0  # m^4
J = 2.0 * I  # m^4
G_B = E_B / KAPPA  # Pa
F = 1e-3  # N, tip load (bending and axial)
TORQUE = 1e-6  # N m
DT = 2e-7  # s, about 1/18 of the bond's critical step 2 sqrt(m* / (k_n A)) = 3.6 us
STEPS = 60000  # 12 ms: the slowest (bending) mode damped many times over
ZETA, DRAG = 0.7, 0.04  # bond damping ratio, N s/m


def chain_deflection():
    """m, (N + 1,) the discrete chain's static deflection of each sphere under the tip load.
    Bond m (0-based) bends by F l (N - m - 1/2) l / (E I), and the spheres turn with it; the
    centres of spheres m and m + 1 follow both spheres' rotations at the lever l / 2 each and the
    bond's shear slide kappa F l / (E A)."""
    turn = np.concatenate(([0.0], np.cumsum([F * ELL * (N - m - 0.5) * ELL / (E_B * I) for m in range(N)])))
    slide = KAPPA * F * ELL / (E_B * AREA)
    return np.concatenate(([0.0], np.cumsum(0.5 * ELL * (turn[:-1] + turn[1:]) + slide)))


def tip_closed_form():
    """m, the discrete chain's tip deflection in closed form (the sum above summed)."""
    return F * ELL**3 * N * (4 * N * N - 1) / (12.0 * E_B * I) + N * KAPPA * F * ELL / (E_B * AREA)


def euler_bernoulli(x):
    return F * x * x * (3.0 * L - x) / (6.0 * E_B * I)


def run(force, torque):
    """The chain loaded at its tip by force and torque until rest: (positions (N+1, 3) m,
    orientations (N+1, 4), the tip's y over time as (t, y) arrays, the log at the end)."""
    s = mpdem.Scene(name="cantilever")
    s.time(duration=1.0, dt=DT, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    s.fields(drag=DRAG)
    s.material("glass", density=RHO, young=1e8, poisson=0.3)
    s.bonds(young=E_B, radius_ratio=LAMBDA, stiffness_ratio=KAPPA, damping=ZETA, gap=1e-6)  # touching: bonded
    x = np.zeros((N + 1, 3))
    x[:, 0] = ELL * np.arange(N + 1)
    s.particles(x, R, id=np.arange(1, N + 2), material="glass", fixed=[1] + [0] * N)
    s.domain(min=[-0.01, -0.02, -0.02], max=[0.03, 0.02, 0.02])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.particles.add_force([N + 1], force, torque)
    t, y = [0.0], [0.0]
    for _ in range(STEPS // 200):
        sim.step(200)
        t.append(sim.time)
        y.append(sim.particles.position[N, 1])
    assert sim.log()["bonds"] == N and sim.log()["bonds_broken"] == 0, sim.log()
    return sim.particles.position, sim.particles.orientation, np.array(t), np.array(y), sim.log()


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    xb, _, tb, yb, logb = run([0.0, F, 0.0], [0.0, 0.0, 0.0])
    xa, _, _, _, _ = run([F, 0.0, 0.0], [0.0, 0.0, 0.0])
    _, qt, _, _, _ = run([0.0, 0.0, 0.0], [TORQUE, 0.0, 0.0])

    y = xb[:, 1]
    discrete = chain_deflection()
    assert abs(discrete[-1] - tip_closed_form()) < 1e-12 * tip_closed_form()
    eb_tip = F * L**3 / (3.0 * E_B * I)
    stretch = xa[N, 0] - L
    twist = 2.0 * math.atan2(qt[N, 1], qt[N, 0])  # rad, about x
    rows = [  # quantity, measured, reference, reference's name, scale, unit, tolerance
        ("tip deflection (1 mN across)", y[N], discrete[-1], "discrete chain", 1e6, "um", 1e-3),
        ("tip deflection (1 mN across)", y[N], eb_tip, "Euler-Bernoulli F L^3/(3 E I)", 1e6, "um", 0.03),
        ("stretch (1 mN along)", stretch, F * L / (E_B * AREA), "F L/(E A)", 1e9, "nm", 1e-3),
        ("twist (1 uN m about the axis)", twist, TORQUE * L / (G_B * J), "T L/(G J)", 1e6, "urad", 1e-3),
    ]
    ok = True
    lines = [f"# chain of {N + 1} spheres r = {R * 1e3:g} mm, rho = {RHO:g} kg/m^3, {N} bonds lambda = {LAMBDA:g}, "
             f"E_b = {E_B:g} Pa, k_n/k_s = {KAPPA:g}; L = {L * 1e3:g} mm, A = {AREA:.6g} m^2, I = {I:.6g} m^4",
             f"# damped to rest: bond damping {ZETA} of critical, drag {DRAG} N s/m, dt = {DT:g} s, "
             f"{STEPS} steps; tip speed at the end {abs(yb[-1] - yb[-2]) / (tb[-1] - tb[-2]):.2e} m/s",
             "quantity,measured,reference,reference_value,unit,relative_error,tolerance,pass"]
    for name, m, c, ref, scale, unit, tol in rows:
        err = abs(m - c) / abs(c)
        ok &= err <= tol
        lines.append(f"{name},{m * scale:.6g},{ref},{c * scale:.6g},{unit},{err:.2e},{tol:g},"
                     f"{'yes' if err <= tol else 'NO'}")
    along = np.abs(y - discrete).max() / discrete[-1]
    ok &= along <= 1e-3
    lines.append(f"# every sphere against the discrete chain: largest |y - y_discrete| / y_tip = {along:.2e} "
                 f"(tolerance 1e-3): {'yes' if along <= 1e-3 else 'NO'}")
    lines.append(f"# the discrete chain's tip against Euler-Bernoulli: {discrete[-1] / eb_tip - 1:+.4%} "
                 f"(bending {F * ELL**3 * N * (4 * N * N - 1) / (12 * E_B * I) / eb_tip - 1:+.4%}, "
                 f"the bonds' shear {N * KAPPA * F * ELL / (E_B * AREA) / eb_tip:+.4%})")
    lines.append(f"# bond elastic energy at rest (bending): {logb['bond_energy']:.6g} J, half the work of the load "
                 f"F y_tip / 2 = {0.5 * F * y[N]:.6g} J")
    lines.append("# sphere,x_mm,y_um,discrete_um,euler_bernoulli_um")
    for k in range(N + 1):
        lines.append(f"# {k + 1},{ELL * k * 1e3:g},{y[k] * 1e6:.6f},{discrete[k] * 1e6:.6f},"
                     f"{euler_bernoulli(ELL * k) * 1e6:.6f}")
    lines.append(f"# {'all within tolerance' if ok else 'FAILED: a value is outside its tolerance'}")
    text = "\n".join(lines) + "\n"
    (out / "cantilever.txt").write_text(text)

    fig, (ax, ax1, ax2) = plt.subplots(1, 3, figsize=(16, 4.8))
    xs = np.linspace(0.0, L, 200)
    xk = ELL * np.arange(N + 1)
    ax.plot(xs * 1e3, euler_bernoulli(xs) * 1e6, "k-", lw=1.2, label=r"Euler-Bernoulli $F x^2 (3L - x) / (6 E I)$")
    ax.plot(xk * 1e3, discrete * 1e6, "C1s", ms=8, mfc="none", label="discrete chain, closed form")
    ax.plot(xk * 1e3, y * 1e6, "C0o", ms=4, label="mpdem, at rest")
    ax.set_xlabel("x along the chain [mm]")
    ax.set_ylabel("deflection y [um]")
    ax.set_title(f"(a) 1 mN tip load: tip {y[N] * 1e6:.4f} um (EB {eb_tip * 1e6:.4f}, "
                 f"discrete {discrete[-1] * 1e6:.4f})", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax1.axhline(0.0, color="k", lw=1.2, label="Euler-Bernoulli")
    ax1.plot(xk * 1e3, (discrete - euler_bernoulli(xk)) * 1e9, "C1s-", ms=8, mfc="none", lw=0.8,
             label="discrete chain, closed form")
    ax1.plot(xk * 1e3, (y - euler_bernoulli(xk)) * 1e9, "C0o", ms=4, label="mpdem")
    ax1.set_xlabel("x along the chain [mm]")
    ax1.set_ylabel("y - y_EB [nm]")
    ax1.set_title("(b) the chain less the beam: the bonds' shear and the discrete bending", fontsize=10)
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)
    ax2.plot(tb * 1e3, yb * 1e6, "C0-", lw=1.0, label="mpdem tip")
    ax2.axhline(discrete[-1] * 1e6, color="C1", ls="--", lw=1.0, label="discrete chain")
    ax2.axhline(eb_tip * 1e6, color="k", ls=":", lw=1.0, label="Euler-Bernoulli")
    ax2.set_xlabel("t [ms]")
    ax2.set_ylabel("tip deflection [um]")
    ax2.set_title("(c) the tip coming to rest (bond dashpots + drag)", fontsize=10)
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "cantilever.png", dpi=120)
    print(text, end="")
    return ok


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    sys.exit(0 if main(Path(args[0]) if args else Path(__file__).parent) else 1)
