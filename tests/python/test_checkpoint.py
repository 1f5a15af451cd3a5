"""Simulation.save / Simulation.resume: a bitwise continuation, as the CLI's."""

import numpy as np
import pytest

import mpdem
from conftest import build_bed

STATE = ("position", "velocity", "angular_velocity", "orientation", "temperature")


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_save_and_resume_continue_bitwise(tmp_path, integrator):
    scene = build_bed(tmp_path, integrator)
    whole = mpdem.Simulation(scene, threads=1, write_output=False)
    whole.run()

    first = mpdem.Simulation(scene, threads=1, write_output=False)
    first.run(duration=0.0015)
    first.save(tmp_path / "half.bin")
    resumed = mpdem.Simulation.resume(tmp_path / "half.bin", scene, threads=1, write_output=False)
    assert resumed.time == first.time and resumed.steps == first.steps
    resumed.run()
    assert resumed.log()["contacts_pb"] > 0
    for name in STATE:
        assert np.array_equal(getattr(resumed.particles, name), getattr(whole.particles, name)), name
    assert resumed.log() == whole.log()


def test_resume_with_another_scene_is_refused(tmp_path):
    scene = build_bed(tmp_path)
    sim = mpdem.Simulation(scene, write_output=False)
    sim.step(10)
    sim.save(tmp_path / "c.bin")
    other = build_bed(tmp_path)
    other.material("steel", density=7800.0, young=2e8, poisson=0.3)
    with pytest.raises(mpdem.InputError):
        mpdem.Simulation.resume(tmp_path / "c.bin", other)
