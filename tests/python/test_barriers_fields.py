"""Barrier groups and gravity from Python: loads, a velocity set between steps, gravity changed."""

import numpy as np
import pytest

import mpdem

FLOOR = np.array([[[-0.01, -0.01, 0.0], [0.01, -0.01, 0.0], [0.01, 0.01, 0.0]],
                  [[-0.01, -0.01, 0.0], [0.01, 0.01, 0.0], [-0.01, 0.01, 0.0]]])
LID = FLOOR[:, :, [1, 0, 2]] + [0.0, 0.0, 0.005]  # swapped x, y: normal down, 5 mm up


def resting_sphere(tmp_path, integrator="verlet"):
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-6, integrator=integrator).gravity([0.0, 0.0, -9.81])
    law = dict(restitution=0.1, mu_static=0.5, mu_dynamic=0.5)
    s.contact(particle_particle=law, particle_barrier=law)
    s.material("glass", density=2500.0, young=1e8, poisson=0.3)
    s.particles([[0.0, 0.0, 1e-3]], [1e-3], id=[7], material="glass")
    s.barriers(FLOOR, material="glass", group="floor")
    s.barriers(LID, material="glass", group="lid")
    s.domain(min=[-0.02, -0.02, -0.02], max=[0.02, 0.02, 0.02])
    return mpdem.Simulation(s, threads=1, write_output=False)


def test_group_loads_balance_the_weight_at_rest(tmp_path):
    sim = resting_sphere(tmp_path)
    sim.run(duration=0.02)
    assert sim.barriers.groups == ["floor", "lid"]
    m = sim.particles.mass[0]
    load = sim.barriers.load("floor")
    # At rest on the floor: the floor carries the weight (the sphere's residual motion: 1e-6).
    assert load["force"] == pytest.approx([0.0, 0.0, -m * 9.81], rel=1e-6, abs=1e-6 * m * 9.81)
    assert load["area"] == pytest.approx(4e-4, rel=1e-12)
    assert np.allclose(sim.barriers.force("lid"), 0.0)
    # The particle's total force: its weight plus the floor's reaction, i.e. minus the load.
    assert np.allclose(sim.particles.force[0], [0.0, 0.0, -m * 9.81] - load["force"], rtol=0, atol=1e-12)
    with pytest.raises(ValueError, match="no barrier group 'roof'"):
        sim.barriers.load("roof")


def test_a_velocity_set_moves_the_group_on_from_where_it_is(tmp_path):
    sim = resting_sphere(tmp_path)
    sim.step(100)
    assert np.array_equal(sim.barriers.motion("lid")[0], [0.0, 0.0, 0.0])
    v = np.array([0.0, 0.0, -0.5])
    sim.barriers.set_velocity("lid", v)
    sim.step(1000)
    t = 1000 * 1e-6
    d, u = sim.barriers.motion("lid")
    assert np.allclose(d, v * t, rtol=0, atol=1e-15) and np.array_equal(u, v)
    sim.barriers.set_velocity("lid", [0.0, 0.0, 0.0])  # stops where it is
    sim.step(10)
    assert np.allclose(sim.barriers.motion("lid")[0], v * t, rtol=0, atol=1e-15)
    assert sim.barriers.force("lid")[2] == 0.0  # 0.5 mm above the sphere's top
    # Lowered onto the sphere (2.5 mm gap left) the lid is pushed up.
    sim.barriers.set_velocity("lid", [0.0, 0.0, -0.1])
    sim.run(duration=0.0251)  # 0.01 mm into the sphere: pressed, not crushed
    assert sim.barriers.force("lid")[2] > 0.0


def test_gravity_set_between_steps(tmp_path):
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-4, integrator="verlet")
    s.material("glass", density=2500.0, young=1e8, poisson=0.3)
    s.particles([[0.0, 0.0, 0.0]], [1e-3], id=[1], material="glass")
    s.domain(min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.step(10)
    x0, v0 = sim.particles.position[0], sim.particles.velocity[0]
    g = np.array([3.0, 0.0, -4.0])
    sim.gravity = g
    assert np.array_equal(sim.gravity, g)
    sim.step(100)
    t = 100 * 1e-4
    assert np.allclose(sim.particles.position[0], x0 + v0 * t + 0.5 * g * t * t, rtol=0, atol=1e-12)
    assert sim.log()["total_energy"] == pytest.approx(sim.log()["total_energy"])  # no energy jump raised
    with pytest.raises(mpdem.InputError):
        sim.gravity = [float("nan"), 0.0, 0.0]


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_added_forces_accelerate_and_their_work_is_in_the_balance(tmp_path, integrator):
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-4, integrator=integrator).gravity([0.0, 0.0, 0.0])
    s.material("glass", density=2500.0, young=1e8, poisson=0.3)
    s.particles([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0]], [1e-3, 1e-3], id=[1, 2], material="glass")
    s.domain(min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.step(5)
    before = sim.log()["total_energy"]
    f, t = np.array([2e-5, 0.0, -1e-5]), np.array([0.0, 3e-9, 0.0])
    sim.particles.add_force([2], f, t)
    sim.step(300)
    p = sim.particles
    m, inertia, time = p.mass[1], p.inertia[1], 300 * 1e-4
    assert np.allclose(p.position[1], [0.5, 0.0, 0.0] + 0.5 * f / m * time**2, rtol=0, atol=1e-12)
    assert np.allclose(p.angular_velocity[1], t / inertia * time, rtol=1e-12, atol=0)
    assert np.array_equal(p.position[0], [0.0, 0.0, 0.0])  # the other one is not pushed
    log = sim.log()
    assert log["kinetic"] + log["rotational"] > 0.0
    # total_energy takes off the forces' work: unchanged to round-off of the trapezoid of F.v.
    assert log["total_energy"] == pytest.approx(before, abs=1e-9 * (log["kinetic"] + log["rotational"]))
    sim.particles.clear_forces()
    v = p.velocity[1]
    sim.step(10)
    assert np.allclose(sim.particles.velocity[1], v, rtol=1e-14, atol=0)
    with pytest.raises(ValueError, match="no particle with id 3"):
        sim.particles.add_force([3], f)
