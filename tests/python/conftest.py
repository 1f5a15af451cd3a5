"""Shared scenes of the Python module's tests: a small frictional bed on a floor, written as a
TOML scene with its CSV files (what `mpdem run` reads) and built with mpdem.Scene (its twin)."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import mpdem

MPDEM = os.environ.get("MPDEM_BINARY", "mpdem")


def bed_arrays(n_side=3, seed=7):
    """n_side^3 spheres of radius 1 mm on a jittered lattice just above z = 0, moving."""
    rng = np.random.default_rng(seed)
    g = np.arange(n_side) * 2.02e-3
    pos = np.array([[x, y, 1.0e-3 + z] for z in g for y in g for x in g])
    pos[:, :2] += rng.uniform(-5e-5, 5e-5, size=(len(pos), 2))
    vel = rng.uniform(-0.05, 0.05, size=(len(pos), 3))
    radius = rng.uniform(0.95e-3, 1.0e-3, size=len(pos))
    ids = np.arange(len(pos), dtype=np.int64) * 3 + 5  # not 0..N-1: ids are not indices
    return ids, pos, vel, radius


FLOOR = np.array([[[-0.01, -0.01, 0.0], [0.02, -0.01, 0.0], [0.02, 0.02, 0.0]],
                  [[-0.01, -0.01, 0.0], [0.02, 0.02, 0.0], [-0.01, 0.02, 0.0]]])

CONTACT = dict(restitution=0.5, mu_static=0.5, mu_dynamic=0.4, mu_rolling=0.01)


def bed_tables(integrator="verlet", duration=0.004, dt=2e-6):
    """The scene's tables, shared by the TOML file and the builder."""
    return {
        "time": {"duration": duration, "dt": dt, "integrator": integrator},
        "gravity": {"vector": [0.0, 0.0, -9.81]},
        "domain": {"min": [-0.01, -0.01, -0.01], "max": [0.02, 0.02, 0.03], "on_exit": "remove"},
        "output": {"dir": "output", "particles_every": 0.001, "particle_csv_every": 0.001, "log_every": 100,
                   "barrier_log_every": 0.0005},
    }


def write_bed_toml(folder, integrator="verlet", **time):
    """The bed as a TOML scene file with particles.csv and floor.csv beside it."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    ids, pos, vel, radius = bed_arrays()
    with open(folder / "particles.csv", "w") as f:
        f.write("id,x,y,z,vx,vy,vz,radius\n")
        for k in range(len(ids)):
            f.write(",".join([str(ids[k])] + [repr(float(v)) for v in (*pos[k], *vel[k], radius[k])]) + "\n")
    with open(folder / "floor.csv", "w") as f:
        f.write("x1,y1,z1,x2,y2,z2,x3,y3,z3\n")
        for tri in FLOOR:
            f.write(",".join(repr(float(v)) for v in tri.reshape(9)) + "\n")
    t = bed_tables(integrator, **time)
    text = f"""
[time]
duration = {t['time']['duration']!r}
dt = {t['time']['dt']!r}
integrator = "{integrator}"

[gravity]
vector = [0.0, 0.0, -9.81]

[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.4
mu_rolling = 0.01

[contact.particle_barrier]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.4
mu_rolling = 0.01

[[material]]
name = "glass"
density = 2500.0
young = 1e7
poisson = 0.3

[[particles]]
file = "particles.csv"
material = "glass"

[[barriers]]
file = "floor.csv"
material = "glass"

[domain]
min = [-0.01, -0.01, -0.01]
max = [0.02, 0.02, 0.03]
on_exit = "remove"

[output]
dir = "output"
particles_every = 0.001
particle_csv_every = 0.001
log_every = 100
barrier_log_every = 0.0005
"""
    (folder / "scene.toml").write_text(text)
    return folder / "scene.toml"


def build_bed(folder, integrator="verlet", **time):
    """The same bed with mpdem.Scene: arrays instead of CSV files."""
    ids, pos, vel, radius = bed_arrays()
    t = bed_tables(integrator, **time)
    s = mpdem.Scene(dir=folder)
    s.time(**t["time"]).gravity([0.0, 0.0, -9.81])
    s.contact(particle_particle=CONTACT, particle_barrier=CONTACT)
    s.material("glass", density=2500.0, young=1e7, poisson=0.3)
    s.particles(pos, radius, velocity=vel, id=ids, material="glass")
    s.barriers(FLOOR, material="glass", group="floor")
    s.domain(**t["domain"]).output(**t["output"])
    return s


def run_cli(*args, cwd=None):
    return subprocess.run([MPDEM, *map(str, args)], cwd=cwd, capture_output=True, text=True)


@pytest.fixture
def bed_toml(tmp_path):
    return write_bed_toml(tmp_path / "toml")
