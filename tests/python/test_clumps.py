"""Rigid clumps from Python: sim.bodies' arrays against the closed forms of a dumbbell (mass,
principal moments, the body CSV's orientation), free fall of the centre of mass, velocities set
between steps (the members follow), and the edits a clump scene refuses."""

import math

import numpy as np
import pytest

import mpdem

R = 1.0e-3  # m, member radius
RHO = 2500.0  # kg/m^3
G = -9.81  # m/s^2, along z
DT = 1.0e-5  # s

# Body CSV rows: id, centre of mass (m), orientation q0..q3 (template as written -> world),
# velocity (m/s), angular velocity (rad/s). Far apart: no contact, free flight.
BODIES = [
    (7, (0.0, 0.0, 0.05), (0.8, 0.2, -0.4, 0.4), (0.1, 0.0, 0.0), (0.0, 0.0, 0.0)),
    (3, (0.02, 0.02, 0.05), (math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)), (0.0, 0.0, 0.0),
     (3.0, -2.0, 5.0)),
]
SPHERE = (100, (-0.02, 0.02, 0.05))  # a free sphere (id, position m)


def scene_text(integrator):
    return f"""
[time]
duration = 0.1
dt = {DT!r}
integrator = "{integrator}"

[gravity]
vector = [0.0, 0.0, {G!r}]

[[material]]
name = "glass"
density = {RHO!r}
young = 1e7
poisson = 0.3

[[clump]]
name = "dumbbell"
members = [[0.0, -0.001, 0.0, 0.001], [0.0, 0.001, 0.0, 0.001]]

[[particles]]
file = "bodies.csv"
clump = "dumbbell"
material = "glass"

[[particles]]
file = "spheres.csv"
material = "glass"

[domain]
min = [-0.1, -0.1, -0.1]
max = [0.1, 0.1, 0.1]
"""


def make(tmp_path, integrator="verlet"):
    rows = ["id,x,y,z,q0,q1,q2,q3,vx,vy,vz,wx,wy,wz"]
    for i, x, q, v, w in BODIES:
        rows.append(",".join([str(i)] + [repr(float(c)) for c in (*x, *q, *v, *w)]))
    (tmp_path / "bodies.csv").write_text("\n".join(rows) + "\n")
    i, x = SPHERE
    (tmp_path / "spheres.csv").write_text(f"id,x,y,z,radius\n{i},{x[0]!r},{x[1]!r},{x[2]!r},{R!r}\n")
    (tmp_path / "scene.toml").write_text(scene_text(integrator))
    return mpdem.Simulation(mpdem.Scene.from_toml(tmp_path / "scene.toml"), threads=1, write_output=False)


def rotate(q, d):
    """d (3,) turned by the unit quaternion q = (w, x, y, z)."""
    w, u, d = q[0], np.asarray(q[1:]), np.asarray(d, dtype=float)
    return d + 2.0 * np.cross(u, np.cross(u, d) + w * d)


def members_of(sim, k):
    """The particle rows of body row k's members: the spheres within 1.5 r of its centre."""
    x = sim.particles.position
    return np.nonzero(np.linalg.norm(x - sim.bodies.position[k], axis=1) < 1.5 * R)[0]


def check_members(sim):
    """Every member sits where the body's orientation puts its template (members written at
    (0, -+r, 0)) and moves with the body: v + w x d."""
    b = sim.bodies
    x, v = sim.particles.position, sim.particles.velocity
    for k in range(len(b)):
        m = members_of(sim, k)
        assert len(m) == 2
        d = x[m] - b.position[k]
        want = np.array([rotate(b.orientation[k], [0.0, s * R, 0.0]) for s in (-1.0, 1.0)])
        if np.linalg.norm(d[0] - want[0]) > np.linalg.norm(d[0] - want[1]):
            want = want[::-1]
        assert np.allclose(d, want, rtol=0, atol=1e-15)
        moving = b.velocity[k] + np.cross(b.angular_velocity[k], d)
        assert np.allclose(v[m], moving, rtol=0, atol=1e-14)


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_body_arrays_against_the_dumbbell(tmp_path, integrator):
    sim = make(tmp_path, integrator)
    b = sim.bodies
    assert len(b) == 2 and len(sim.particles) == 5  # 2 x 2 members and the sphere
    assert list(b.id) == [3, 7]  # ascending id order, not the CSV's
    assert list(b.template) == ["dumbbell", "dumbbell"]
    for name, shape in (("position", (2, 3)), ("orientation", (2, 4)), ("principal_orientation", (2, 4)),
                        ("velocity", (2, 3)), ("angular_velocity", (2, 3)), ("mass", (2,)), ("inertia", (2, 3)),
                        ("force", (2, 3)), ("torque", (2, 3)), ("temperature", (2,)), ("fixed", (2,))):
        assert getattr(b, name).shape == shape, name
    by_id = {row[0]: row for row in BODIES}
    rows = [by_id[i] for i in b.id]
    mass = 2.0 * (4.0 / 3.0) * math.pi * R**3 * RHO
    assert np.allclose(b.mass, mass, rtol=1e-12, atol=0)
    assert np.allclose(b.inertia, np.array([0.4, 1.4, 1.4]) * mass * R**2, rtol=1e-9, atol=0)
    assert np.array_equal(b.position, [r[1] for r in rows])
    assert np.allclose(b.orientation, [r[2] for r in rows], rtol=0, atol=1e-15)  # the CSV's q back
    assert np.array_equal(b.velocity, [r[3] for r in rows])
    assert np.array_equal(b.angular_velocity, [r[4] for r in rows])
    assert list(b.fixed) == [0, 0]
    # The principal frame's x axis (the smallest moment) is the dumbbell's axis, written along y.
    for k in range(2):
        axis = rotate(b.principal_orientation[k], [1.0, 0.0, 0.0])
        assert abs(abs(axis @ rotate(b.orientation[k], [0.0, 1.0, 0.0])) - 1.0) < 1e-15
    check_members(sim)
    assert set(b.as_dict()) == set(mpdem._core.body_arrays)


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_free_fall_and_velocities_set_between_steps(tmp_path, integrator):
    sim = make(tmp_path, integrator)
    x0, v0 = sim.bodies.position, sim.bodies.velocity
    sim.step(1000)
    t = sim.time
    g = np.array([0.0, 0.0, G])
    assert np.allclose(sim.bodies.position, x0 + v0 * t + 0.5 * g * t * t, rtol=0, atol=1e-9)
    assert np.allclose(sim.bodies.velocity, v0 + g * t, rtol=0, atol=1e-12)
    assert np.allclose(sim.bodies.force, np.outer(sim.bodies.mass, g), rtol=1e-12, atol=0)
    assert np.allclose(sim.bodies.torque, 0.0, rtol=0, atol=1e-30)
    check_members(sim)
    # Set body 7's velocity and spin (world): the members follow at once, and the centre of mass
    # flies on from the new velocity.
    v_new, w_new = np.array([-0.2, 0.05, 0.3]), np.array([10.0, 0.0, -4.0])
    sim.bodies.set("velocity", v_new, ids=[7])
    sim.bodies.set("angular_velocity", [w_new], ids=7)
    assert np.array_equal(sim.bodies.velocity[1], v_new) and np.array_equal(sim.bodies.angular_velocity[1], w_new)
    check_members(sim)
    x1, v1, t1 = sim.bodies.position, sim.bodies.velocity, sim.time
    sim.step(500)
    t = sim.time - t1
    assert np.allclose(sim.bodies.position, x1 + v1 * t + 0.5 * g * t * t, rtol=0, atol=1e-9)
    check_members(sim)
    # Assigning the whole array (id order).
    sim.bodies.velocity = np.zeros((2, 3))
    assert np.array_equal(sim.bodies.velocity, np.zeros((2, 3)))
    check_members(sim)


def test_clump_scene_refuses_what_would_break_a_body(tmp_path):
    sim = make(tmp_path)
    sim.step(10)
    member = int(sim.particles.id[members_of(sim, 0)[0]])
    with pytest.raises(mpdem.InputError, match="member of clump body") as e:
        sim.particles.set("velocity", [[1.0, 0.0, 0.0]], ids=[member])
    assert e.value.key == "velocity"
    with pytest.raises(mpdem.InputError, match="member"):
        sim.particles.position = sim.particles.position  # all particles: the members among them
    sim.particles.set("velocity", [[0.0, 0.0, 1.0]], ids=[SPHERE[0]])  # a free sphere's is fine
    with pytest.raises(mpdem.InputError, match="clumps") as e:
        sim.add_particles([[0.05, 0.05, 0.05]], 1e-3)
    assert e.value.key == "clump"
    with pytest.raises(mpdem.InputError, match="clumps") as e:
        sim.remove_particles([SPHERE[0]])
    assert e.value.key == "clump"
    with pytest.raises(ValueError, match="no body with id 5"):
        sim.bodies.set("velocity", [0.0, 0.0, 0.0], ids=[5])
    with pytest.raises(mpdem.InputError, match="finite") as e:
        sim.bodies.set("angular_velocity", [[0.0, np.nan, 0.0]], ids=[3])
    assert e.value.key == "angular_velocity"
    with pytest.raises(ValueError, match="cannot be set"):
        sim.bodies.set("position", [0.0, 0.0, 0.0], ids=[3])
    with pytest.raises(AttributeError):
        sim.bodies.position = np.zeros((2, 3))
    before = sim.bodies.as_dict()
    sim.step(1)  # nothing was set by the refused calls: the run goes on
    assert len(sim.bodies) == 2 and np.all(sim.bodies.position[:, 2] < before["position"][:, 2])


def test_a_scene_without_clumps_has_no_bodies(tmp_path):
    from conftest import build_bed

    sim = mpdem.Simulation(build_bed(tmp_path), threads=1, write_output=False)
    assert len(sim.bodies) == 0
    assert sim.bodies.position.shape == (0, 3) and sim.bodies.orientation.shape == (0, 4)
    assert sim.bodies.template.shape == (0,)


def test_the_builder_writes_clump_templates(tmp_path):
    make(tmp_path)  # the CSV files
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=0.1, dt=DT, integrator="trapezoidal").gravity([0.0, 0.0, G]).material("glass", density=RHO, young=1e7, poisson=0.3)
    s.clump("dumbbell", [[0.0, -R, 0.0, R], [0.0, R, 0.0, R]])
    s.particles(file="bodies.csv", clump="dumbbell", material="glass")
    s.domain(min=[-0.1, -0.1, -0.1], max=[0.1, 0.1, 0.1])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    assert list(sim.bodies.template) == ["dumbbell"] * 2
    ref = make(tmp_path)
    assert np.array_equal(sim.bodies.inertia, ref.bodies.inertia)


def test_velocities_set_are_part_of_the_checkpoint(tmp_path):
    """A body velocity set from Python is state: saved and resumed, the run goes on bitwise."""
    sim = make(tmp_path)
    sim.step(20)
    sim.bodies.set("velocity", [0.0, 0.3, 0.0], ids=[3])
    sim.bodies.angular_velocity = [[1.0, 2.0, 3.0], [-4.0, 0.5, 0.0]]
    sim.save(tmp_path / "cp.bin")
    resumed = mpdem.Simulation.resume(tmp_path / "cp.bin", mpdem.Scene.from_toml(tmp_path / "scene.toml"),
                                      threads=1, write_output=False)
    sim.step(50)
    resumed.step(50)
    for name in ("position", "orientation", "velocity", "angular_velocity"):
        assert np.array_equal(getattr(sim.bodies, name), getattr(resumed.bodies, name)), name
    assert np.array_equal(sim.particles.position, resumed.particles.position)
