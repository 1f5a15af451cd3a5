"""mpdem.Scene: TOML scenes and their Python-built twins, to_toml, InputError."""

import numpy as np
import pytest

import mpdem
from conftest import build_bed, write_bed_toml

STATE = ("position", "velocity", "angular_velocity", "orientation", "force", "torque")


def final_state(scene, **run):
    sim = mpdem.Simulation(scene, threads=1, write_output=False)
    sim.run(**run)
    log = sim.log()
    return {name: getattr(sim.particles, name) for name in STATE}, log


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_python_built_twin_gives_bitwise_the_toml_trajectory(tmp_path, integrator):
    toml, log_a = final_state(mpdem.Scene.from_toml(write_bed_toml(tmp_path / "toml", integrator)))
    built, log_b = final_state(build_bed(tmp_path / "built", integrator))
    assert log_a["contacts_pp"] > 0 and log_a["contacts_pb"] > 0  # the bed collides: not a trivial check
    for name in STATE:
        assert np.array_equal(toml[name], built[name]), name
    assert log_a == log_b


def test_to_toml_reads_back_as_the_same_scene(tmp_path):
    built = build_bed(tmp_path)
    text = built.to_toml(tmp_path / "written.toml")
    assert "[[particles]]" in text and 'file = "written.particles0.csv"' in text
    again, _ = final_state(mpdem.Scene.from_toml(tmp_path / "written.toml"))
    direct, _ = final_state(built)
    for name in STATE:
        assert np.array_equal(again[name], direct[name]), name


def test_to_toml_of_a_read_scene_keeps_its_tables(bed_toml):
    scene = mpdem.Scene.from_toml(bed_toml)
    text = scene.to_toml()
    assert "[contact.particle_particle]" in text and "mu_rolling = 0.01" in text
    assert mpdem.Scene.from_dict(scene.data).data == scene.data


def test_a_changed_scene_runs_with_its_change(bed_toml):
    scene = mpdem.Scene.from_toml(bed_toml)
    scene.data["time"]["duration"] = 0.001
    sim = mpdem.Simulation(scene, write_output=False)
    assert sim.end_time == 0.001
    assert sim.run() is True and sim.time == 0.001


def test_input_error_names_the_key(tmp_path):
    s = build_bed(tmp_path)
    s.time(dt=-1.0)
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Simulation(s, write_output=False)
    assert e.value.key == "time.dt" and "'time.dt'" in str(e.value)
    assert isinstance(e.value, ValueError)

    s = build_bed(tmp_path)
    s.time(dtt=1e-6)
    with pytest.raises(mpdem.InputError, match="dtt") as e:
        s.check()
    assert e.value.key == "time.dtt"


def test_input_error_of_a_file_names_file_and_line(tmp_path, bed_toml):
    text = bed_toml.read_text().replace("poisson = 0.3", "poisson = 0.7")
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    for csv in ("particles.csv", "floor.csv"):
        (tmp_path / csv).write_text((bed_toml.parent / csv).read_text())
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Scene.from_toml(bad)
    assert e.value.file.endswith("bad.toml") and e.value.line == text.splitlines().index("poisson = 0.7") + 1
    assert e.value.key == "material.poisson"


def test_check_reports_the_problems_mpdem_check_finds(tmp_path):
    s = build_bed(tmp_path)
    ids, pos, vel, radius = (np.array([100, 101]), np.array([[0.005, 0.005, 0.02], [0.0055, 0.005, 0.02]]),
                             np.zeros((2, 3)), np.array([1e-3, 1e-3]))
    s.particles(pos, radius, id=ids, material="glass")  # two spheres 0.5 mm apart: deep overlap
    problems = s.check()
    assert any(stops and "overlap" in msg for stops, msg in problems)


def test_scene_keys_unknown_to_the_builder_pass_through(tmp_path):
    s = build_bed(tmp_path)
    s.neighbor(skin=2e-4)
    assert "[neighbor]\nskin = 0.0002" in s.to_toml(tmp_path / "n.toml")
    mpdem.Simulation(s, write_output=False).step(3)


def coasting_sphere(tmp_path, **integrator):
    """One sphere coasting against viscous drag, the integrator named or not: 20 steps."""
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-4, **integrator).gravity([0.0, 0.0, 0.0]).fields(drag=1e-3)
    s.material("glass", density=2500.0, young=1e7, poisson=0.3)
    s.particles([[0.0, 0.0, 0.0]], [1e-2], velocity=[[1.0, 0.5, 0.0]], id=[1], material="glass")
    s.domain(min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.step(20)
    return s, sim


def test_the_default_integrator_is_verlet(tmp_path):
    """A Scene that does not name its integrator runs velocity Verlet: bitwise the run that names
    it, one evaluation a step and no iterations; the trapezoidal rule's run differs."""
    scene, default = coasting_sphere(tmp_path)
    assert "integrator" not in scene.data["time"]
    _, verlet = coasting_sphere(tmp_path, integrator="verlet")
    _, trapezoidal = coasting_sphere(tmp_path, integrator="trapezoidal")
    for name in ("position", "velocity"):
        assert np.array_equal(getattr(default.particles, name), getattr(verlet.particles, name)), name
    assert default.log()["iterations"] == 0 and default.log()["evaluations_total"] == 21
    assert trapezoidal.log()["iterations"] > 0
    assert not np.array_equal(default.particles.velocity, trapezoidal.particles.velocity)


def test_trapezoidal_keys_need_the_trapezoidal_rule(tmp_path):
    """A key only the trapezoidal rule reads is refused when the integrator is (by default) Verlet."""
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-4, adaptive=True).material("glass", density=2500.0, young=1e7, poisson=0.3)
    s.particles([[0.0, 0.0, 0.0]], [1e-2], id=[1], material="glass")
    s.domain(min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    with pytest.raises(mpdem.InputError, match='integrator = "trapezoidal"') as e:
        mpdem.Simulation(s, threads=1, write_output=False)
    assert e.value.key == "time.adaptive" and 'the default integrator is "verlet"' in str(e.value)
    s.time(integrator="trapezoidal")
    mpdem.Simulation(s, threads=1, write_output=False)  # read
