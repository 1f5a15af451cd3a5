"""A servo-controlled lid on a granular column: Janssen's silo measurement.

1300 beads settle in a square column (side D = 40 mm). A lid (barrier group "lid") then moves
down under a servo: after every step its velocity is set from the force the beads put on it,
v = -gain (P A - F), limited to 50 mm/s, so that it holds a target pressure P; the targets are
0.25, 0.5, 1 and 2 kPa, each held 0.2 s. The floor's pressure at each target (mean over the last
0.05 s) against the lid's is Janssen's law with an overload,

    p_floor = p_top exp(-H/lambda) + rho_b g lambda (1 - exp(-H/lambda)),  lambda = D / (4 mu_w K),

a straight line whose slope exp(-H/lambda) gives the Janssen coefficient K (mu_w = 0.5: the
beads' friction on the walls). The walls carry the rest (force balance checked below).

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/python/servo_wall.py [OUTPUT_DIR]
Writes servo_wall.png and servo_wall.txt.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem
from box_walls import open_box, quad

D, H = 0.04, 0.12  # m, column side and wall height
MU_W = 0.5
G = 9.81
GAIN = 0.05  # m/s per N
VMAX = 0.05  # m/s
TARGETS = [250.0, 500.0, 1000.0, 2000.0]  # Pa
HOLD, MEAN = 0.2, 0.05  # s


def scene():
    s = mpdem.Scene()
    s.time(duration=10.0, dt=6e-6, integrator="verlet")
    s.gravity([0.0, 0.0, -G])
    law = dict(restitution=0.3, mu_static=MU_W, mu_dynamic=MU_W, mu_rolling=0.02)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("beads", density=2500.0, young=2e7, poisson=0.3)
    s.particles(generate=dict(region="box", min=[0.002, 0.002, 0.002], max=[D - 0.002, D - 0.002, 0.11],
                              count=1300, radius=dict(distribution="uniform", min=1.8e-3, max=2.2e-3), seed=5),
                material="beads")
    box = open_box((0.0, 0.0, 0.0), (D, D, H))
    s.barriers(box[:2], material="beads", group="floor")
    s.barriers(box[2:], material="beads", group="walls")
    # The lid: a square just inside the walls at z = 0.115 m, its normal pointing down.
    e, z = 2e-4, 0.115
    lid = quad((e, e, z), (e, D - e, z), (D - e, D - e, z), (D - e, e, z))
    s.barriers(np.array(lid), material="beads", group="lid")
    s.domain(min=[-0.01, -0.01, -0.01], max=[D + 0.01, D + 0.01, H + 0.01])
    return s


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    sim = mpdem.Simulation(scene(), threads=2, write_output=False)
    sim.run(duration=0.35)  # fill and settle under the lid
    area = (D - 4e-4) ** 2
    mass = sim.particles.mass.sum()
    trace = []  # time, target, lid pressure, floor pressure, wall force z, lid height
    target = [0.0]
    # Approach: the lid comes down fast to 2 mm above the top of the bed.
    top = np.sort(sim.particles.position[:, 2] + sim.particles.radius)[-30:].mean()
    sim.barriers.set_velocity("lid", [0.0, 0.0, -0.2])
    sim.run(duration=(0.115 - top - 0.002) / 0.2)

    def servo(s):
        f_lid = s.barriers.force("lid")[2]  # N, the beads push the lid up
        v = float(np.clip(-GAIN * (target[0] * area - f_lid), -VMAX, VMAX))
        s.barriers.set_velocity("lid", [0.0, 0.0, v])
        if s.steps % 50 == 0:
            trace.append((s.time, target[0], f_lid / area, -s.barriers.force("floor")[2] / D**2,
                          s.barriers.force("walls")[2], 0.115 + s.barriers.motion("lid")[0][2]))

    rows = []
    for p in TARGETS:
        target[0] = p
        sim.run(duration=HOLD, callback=servo, every=1)
        t = np.array(trace)
        last = t[(t[:, 1] == p) & (t[:, 0] > sim.time - MEAN)]
        rows.append((p, last[:, 2].mean(), last[:, 2].std(), last[:, 3].mean(), last[:, 4].mean(), last[:, 5].mean()))
    rows = np.array(rows)
    top = np.sort(sim.particles.position[:, 2] + sim.particles.radius)[-30:].mean()
    # Janssen: p_floor = p_top e + rho_b g lambda (1 - e), e = exp(-H / lambda): a line in p_top.
    slope, icept = np.polyfit(rows[:, 1], rows[:, 3], 1)
    height = rows[:, 5].mean()  # m, the lid's height: the bed's
    lam = -height / np.log(slope)
    K = D / (4 * MU_W * lam)
    weight = mass * G
    lines = [f"# 1300 beads (r = 1.8-2.2 mm, mass {mass * 1e3:.1f} g), column {D * 1e3:.0f} x {D * 1e3:.0f} mm, "
             f"mu = {MU_W}; servo gain {GAIN} m/s/N, |v| <= {VMAX} m/s",
             "target_Pa,lid_Pa,lid_std_Pa,floor_Pa,walls_carry_N,lid_height_mm,balance_N"]
    for p, lid, sd, floor, walls, h in rows:
        # The beads' weight and the lid's push are carried by the floor and the walls (the beads'
        # force on the walls points down: walls < 0). balance: what is left, ~0 at rest.
        balance = lid * area + weight - floor * D**2 + walls
        lines.append(f"{p:.0f},{lid:.1f},{sd:.1f},{floor:.1f},{-walls:.4f},{h * 1e3:.2f},{balance:+.4f}")
    lines.append(f"Janssen fit: p_floor = {slope:.4f} p_lid + {icept:.1f} Pa; bed height {height * 1e3:.1f} mm "
                 f"(top of the beads {top * 1e3:.1f} mm): lambda = {lam * 1e3:.1f} mm, K = {K:.3f} "
                 f"(Jaky's 1 - sin(atan mu) = {1 - np.sin(np.arctan(MU_W)):.3f})")
    text = "\n".join(lines) + "\n"
    (out / "servo_wall.txt").write_text(text)

    t = np.array(trace)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.plot(t[:, 0], t[:, 2] / 1e3, lw=0.8, label="lid (servo)")
    ax1.plot(t[:, 0], t[:, 1] / 1e3, "k--", lw=1, label="target")
    ax1.plot(t[:, 0], t[:, 3] / 1e3, lw=0.8, label="floor")
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("pressure [kPa]")
    ax1.set_title("Servo-controlled lid")
    ax1.legend()
    x = np.linspace(0, rows[:, 1].max() * 1.05, 50)
    ax2.plot(rows[:, 1] / 1e3, rows[:, 3] / 1e3, "o", label="measured (mean of the last 0.05 s)")
    ax2.plot(x / 1e3, (slope * x + icept) / 1e3, "-",
             label=f"Janssen with overload: K = {K:.2f}, $\\lambda$ = {lam * 1e3:.0f} mm")
    ax2.plot(x / 1e3, (x + weight / D**2) / 1e3, ":", color="gray", label="no wall friction: lid + weight")
    ax2.set_xlabel("lid pressure [kPa]")
    ax2.set_ylabel("floor pressure [kPa]")
    ax2.set_title("Janssen: the walls carry part of the lid's push")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "servo_wall.png", dpi=120)
    print(text, end="")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent)
