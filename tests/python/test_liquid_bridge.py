"""Scene.liquid_bridge: the [liquid_bridge] table from Python, read by the engine as the TOML
file's (Willett's force between two prescribed spheres, docs/physics.md section 20), its
to_toml text, and an InputError naming the table's key."""

import math

import numpy as np
import pytest

import mpdem

R, GAMMA, VOLUME = 2.381e-3, 20.6e-3, 74.2e-12  # m, N/m, m^3: Willett et al. (2000)'s case


def willett(gap):
    """N, Willett's equal-sphere closed form (theta = 0), written out independently here."""
    s = 0.5 * gap * math.sqrt(R / VOLUME)
    return 2.0 * math.pi * R * GAMMA / (1.0 + 2.1 * s + 10.0 * s * s)


def two_spheres(**bridge):
    s = mpdem.Scene()
    s.time(duration=1.0, dt=1e-5, integrator="trapezoidal")
    s.gravity([0.0, 0.0, 0.0])
    s.checks(max_overlap=0.0)
    s.material("glass", density=2500.0, young=1e7, poisson=0.3)
    s.liquid_bridge(**bridge)
    # touching (1 nm overlap), sphere 2 prescribed moving away at 1 mm/s
    s.particles([[-R, 0.0, 0.0], [R - 1e-9, 0.0, 0.0]], R, velocity=[[0, 0, 0], [1e-3, 0, 0]], id=[1, 2],
                material="glass", fixed=True)
    s.domain(min=[-0.01, -0.01, -0.01], max=[0.01, 0.01, 0.01])
    return s


def test_liquid_bridge_table_gives_willetts_force():
    scene = two_spheres(model="willett", surface_tension=GAMMA, contact_angle=0.0, volume=VOLUME)
    assert scene.data["liquid_bridge"] == dict(model="willett", surface_tension=GAMMA, contact_angle=0.0,
                                               volume=VOLUME)
    sim = mpdem.Simulation(scene, threads=1, write_output=False)
    sim.step(5000)  # 0.05 mm
    x = sim.particles.position
    gap = x[1, 0] - x[0, 0] - 2.0 * R
    f = sim.particles.force
    assert sim.log()["bridges"] == 1
    assert abs(gap - 5e-5) < 2e-9  # 5000 steps of 10 nm from a 1 nm overlap
    # attraction: sphere 1 pulled towards +x, sphere 2 towards -x
    assert f[0, 0] > 0.0 and f[1, 0] == -f[0, 0]
    assert abs(f[0, 0] - willett(gap)) / willett(gap) < 1e-9


def test_liquid_bridge_is_written_as_its_table(tmp_path):
    scene = two_spheres(model="rabinovich", surface_tension=GAMMA, liquid_fraction=0.01, viscosity=1e-3)
    text = scene.to_toml(tmp_path / "wet.toml")
    assert "[liquid_bridge]" in text and 'model = "rabinovich"' in text and "liquid_fraction = 0.01" in text
    again = mpdem.Simulation(mpdem.Scene.from_toml(tmp_path / "wet.toml"), threads=1, write_output=False)
    built = mpdem.Simulation(scene, threads=1, write_output=False)
    again.step(100)
    built.step(100)
    assert again.log()["bridges"] == 1
    assert np.array_equal(again.particles.force, built.particles.force)


def test_bad_liquid_bridge_key_names_it():
    scene = two_spheres(model="willett", surface_tension=-1.0, volume=VOLUME)
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Simulation(scene, write_output=False)
    assert e.value.key == "liquid_bridge.surface_tension"


def test_contact_list_shows_the_bridge_across_its_gap():
    """contacts(): a bridge across a gap is listed with its negative overlap, bridge True and
    touching False, and its force is the particles' force (Newton's third law)."""
    scene = two_spheres(model="willett", surface_tension=GAMMA, contact_angle=0.0, volume=VOLUME)
    sim = mpdem.Simulation(scene, threads=1, write_output=False)
    sim.record_contacts = True
    sim.step(10000)  # 0.1 mm apart
    c = sim.contacts()
    assert len(c["i"]) == 1 and c["j"][0] >= 0
    assert bool(c["bridge"][0]) and not bool(c["touching"][0])
    x = sim.particles.position
    gap = x[1, 0] - x[0, 0] - 2.0 * R
    assert c["overlap"][0] == pytest.approx(-gap, rel=1e-9)
    f = c["normal_force"][0] + c["tangential_force"][0]
    first = 0 if int(c["i"][0]) == 1 else 1  # the listed force acts on the entry's first particle
    assert np.allclose(f, sim.particles.force[first], rtol=0, atol=1e-12 * abs(f[0]))
    assert abs(abs(f[0]) - willett(gap)) / willett(gap) < 1e-9
    assert np.allclose(c["tangential_force"][0], 0.0, atol=0)
    assert sim.log()["contacts_pp"] == 0 and sim.log()["bridges"] == 1
