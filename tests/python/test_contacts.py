"""Simulation.contacts(): the contact list of the last evaluation (force chains)."""

import numpy as np
import pytest

import mpdem
from conftest import build_bed


def settled(tmp_path, integrator, record=True):
    sim = mpdem.Simulation(build_bed(tmp_path, integrator, duration=0.02), threads=1, write_output=False)
    sim.record_contacts = record
    sim.run(duration=0.008)
    return sim


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_listed_forces_sum_to_each_particles_contact_force(tmp_path, integrator):
    sim = settled(tmp_path, integrator)
    c = sim.contacts()
    log = sim.log()
    pairs, walls = c["j"] >= 0, c["element"] >= 0
    assert pairs.sum() == log["contacts_pp"] >= 4 and walls.sum() == log["contacts_pb"] >= 4
    assert np.all(pairs != walls)
    p = sim.particles
    row = {int(i): k for k, i in enumerate(p.id)}
    summed = np.zeros((len(p.id), 3))
    f = c["normal_force"] + c["tangential_force"]
    for k in range(len(f)):
        summed[row[int(c["i"][k])]] += f[k]
        if c["j"][k] >= 0:
            summed[row[int(c["j"][k])]] -= f[k]  # Newton's third law
    contact_force = p.force - p.mass[:, None] * np.array([0.0, 0.0, -9.81])
    scale = np.abs(contact_force).max()
    assert scale > 0.0
    assert np.allclose(summed, contact_force, rtol=0, atol=1e-12 * scale)


def test_contact_geometry(tmp_path):
    sim = settled(tmp_path, "verlet")
    c = sim.contacts()
    n, fn, ft = c["normal"], c["normal_force"], c["tangential_force"]
    assert np.allclose(np.linalg.norm(n, axis=1), 1.0, rtol=0, atol=1e-14)
    assert np.all(c["overlap"] > 0.0)
    assert np.all(np.einsum("ij,ij->i", fn, n) > 0.0)  # repulsive (Hertz, damped: net normal force)
    assert np.allclose(np.einsum("ij,ij->i", ft, n), 0.0, rtol=0, atol=1e-12 * np.abs(fn).max())
    p = sim.particles
    x = {int(i): p.position[k] for k, i in enumerate(p.id)}
    r = {int(i): p.radius[k] for k, i in enumerate(p.id)}
    for k in np.flatnonzero(c["j"] >= 0):
        i, j = int(c["i"][k]), int(c["j"][k])
        d = x[i] - x[j]
        assert np.allclose(n[k], d / np.linalg.norm(d), rtol=0, atol=1e-12)
        assert c["overlap"][k] == pytest.approx(r[i] + r[j] - np.linalg.norm(d), rel=1e-9)
    walls = c["element"] >= 0
    assert set(c["element"][walls]) <= {0, 1}  # the floor's two triangles
    assert np.allclose(c["normal"][walls], [0.0, 0.0, 1.0], atol=1e-12)
    assert np.allclose(c["point"][walls][:, 2], 0.0, atol=1e-15)


def test_plain_scene_contacts_touch_and_hold_no_bridges(tmp_path):
    # Without cohesion every listed row is a contact (a law acts) and none is a liquid bridge.
    c = settled(tmp_path, "verlet").contacts()
    for key in ("touching", "bridge"):
        assert c[key].dtype == np.bool_ and c[key].shape == c["sliding"].shape
    assert len(c["touching"]) > 0 and np.all(c["touching"]) and not np.any(c["bridge"])


def test_recording_changes_nothing_and_is_needed(tmp_path):
    a = settled(tmp_path, "trapezoidal", record=True)
    b = settled(tmp_path, "trapezoidal", record=False)
    for name in ("position", "velocity", "angular_velocity"):
        assert np.array_equal(getattr(a.particles, name), getattr(b.particles, name))
    with pytest.raises(RuntimeError, match="record_contacts"):
        b.contacts()
    b.record_contacts = True
    with pytest.raises(RuntimeError, match="take a step"):
        b.contacts()
    b.step(1)
    assert len(b.contacts()["i"]) == b.log()["contacts_pp"] + b.log()["contacts_pb"]


CLUMP_SCENE = """[time]
duration = 6e-4
integrator = "verlet"
dt = 2e-6
[gravity]
vector = [0.0, 0.0, 0.0]
[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.4
[[material]]
name = "glass"
density = 2500.0
young = 1e7
poisson = 0.3
[[clump]]
name = "ell"
members = [[0.0, 0.0, 0.0, 0.001], [0.002, 0.0, 0.0, 0.001], [0.0, 0.0018, 0.0, 0.0007]]
[[particles]]
file = "bodies.csv"
clump = "ell"
[[particles]]
file = "spheres.csv"
[checks]
max_overlap = 0.3
"""


def test_contacts_name_the_members_bodies(tmp_path):
    """With clumps, contacts() adds body_i and body_j: each the body of the member sphere i or j
    (sim.particles.body of that id), -1 for the free sphere. Two L-shaped clumps (body 7 runs into
    body 1) and a free sphere running into body 1 (tests/output/test_body_csv.cpp's scene)."""
    (tmp_path / "bodies.csv").write_text(
        "id,x,y,z,vx,vy,vz,wx,wy,wz\n1,0.01,0.01,0.01,0,0,0,0,0,0\n7,0.00599,0.01,0.01,0.5,0,0,0,0,3\n")
    (tmp_path / "spheres.csv").write_text("id,x,y,z,vx,radius\n100,0.0131564,0.0097365,0.01,-0.5,0.001\n")
    (tmp_path / "scene.toml").write_text(CLUMP_SCENE)
    sim = mpdem.Simulation(mpdem.Scene.from_toml(tmp_path / "scene.toml"), threads=1, write_output=False)
    sim.record_contacts = True
    sim.step(50)
    c = sim.contacts()
    body_of = dict(zip(sim.particles.id.tolist(), sim.particles.body.tolist()))
    assert len(c["i"]) == 2  # body 7 - body 1, sphere 100 - body 1
    assert c["body_i"].dtype == np.int64
    assert [body_of[i] for i in c["i"].tolist()] == c["body_i"].tolist()
    assert [body_of[j] for j in c["j"].tolist()] == c["body_j"].tolist()
    pairs = {frozenset(p) for p in zip(c["body_i"].tolist(), c["body_j"].tolist())}
    assert pairs == {frozenset((1, 7)), frozenset((-1, 1))}
