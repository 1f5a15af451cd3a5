"""Restitution sweep: two equal spheres collide head-on at 0.5 m/s for ten restitution
coefficients e_in; the measured e_out = -(relative normal velocity after) / (before) is plotted
against e_in with the analytic line e_out = e_in (the damping of the Hertz law is calibrated so
that a collision restitutes exactly e_in: docs/contact_model.md).

Run:  PYTHONPATH=build/python /usr/bin/python3 examples/python/restitution_sweep.py [OUTPUT_DIR]
Writes restitution_sweep.png and restitution_sweep.txt (in OUTPUT_DIR, default this folder).
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import mpdem

R = 1e-3  # m
V = 0.5  # m/s, each sphere's approach speed


def collide(e, integrator):
    s = mpdem.Scene()
    s.time(duration=2e-3, dt=2e-7, integrator=integrator)
    s.gravity([0.0, 0.0, 0.0])
    law = dict(restitution=e, mu_static=0.0, mu_dynamic=0.0)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("glass", density=2500.0, young=1e8, poisson=0.3)
    # 0.1 mm apart, approaching along x: they meet after 0.1 ms.
    s.particles([[-R - 5e-5, 0.0, 0.0], [R + 5e-5, 0.0, 0.0]], [R, R], velocity=[[V, 0, 0], [-V, 0, 0]],
                id=[1, 2], material="glass")
    s.domain(min=[-0.01, -0.01, -0.01], max=[0.01, 0.01, 0.01])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.run()
    v = sim.particles.velocity
    assert sim.log()["contacts_pp"] == 0  # separated again
    return (v[1, 0] - v[0, 0]) / (2 * V)  # -(after) / (before): before = -2V


def main(out):
    out.mkdir(parents=True, exist_ok=True)
    e_in = np.round(np.linspace(0.05, 0.95, 10), 3)
    rows = {integ: np.array([collide(e, integ) for e in e_in]) for integ in ("trapezoidal", "verlet")}
    with open(out / "restitution_sweep.txt", "w") as f:
        f.write("# two glass spheres R = 1 mm, E = 1e8 Pa, head-on at 2 x 0.5 m/s, dt = 2e-7 s\n")
        f.write("e_in,e_out_trapezoidal,e_out_verlet\n")
        for k, e in enumerate(e_in):
            f.write(f"{e},{rows['trapezoidal'][k]:.6f},{rows['verlet'][k]:.6f}\n")
        for integ, r in rows.items():
            f.write(f"# {integ}: largest |e_out - e_in| = {np.abs(r - e_in).max():.2e}\n")
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4.5))
    ax.plot([0, 1], [0, 1], "k-", lw=1, label="analytic: $e_{out} = e_{in}$")
    ax.plot(e_in, rows["trapezoidal"], "o", mfc="none", label="mpdem, trapezoidal")
    ax.plot(e_in, rows["verlet"], "x", label="mpdem, velocity Verlet")
    ax.set_xlabel("restitution coefficient of the scene, $e_{in}$ [-]")
    ax.set_ylabel("measured restitution, $e_{out}$ [-]")
    ax.set_title("Two spheres head-on (Hertz, calibrated damping)", fontsize=10)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    ax2.axhline(0.0, color="k", lw=1)
    ax2.plot(e_in, rows["trapezoidal"] - e_in, "o-", mfc="none", label="trapezoidal")
    ax2.plot(e_in, rows["verlet"] - e_in, "x-", label="velocity Verlet")
    ax2.set_xlabel("$e_{in}$ [-]")
    ax2.set_ylabel("$e_{out} - e_{in}$ [-]")
    ax2.set_title("Deviation at dt = 2e-7 s (about 1/400 of the contact time)", fontsize=10)
    ax2.legend()
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "restitution_sweep.png", dpi=120)
    print((out / "restitution_sweep.txt").read_text(), end="")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent)
