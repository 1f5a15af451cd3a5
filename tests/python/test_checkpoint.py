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


def test_a_python_checkpoint_resumes_in_the_cli_and_the_reverse(tmp_path):
    """The checkpoint format is the CLI's: Python's save resumes under `mpdem run --resume`, and
    the CLI's checkpoint under Simulation.resume, both to the uninterrupted run's final state."""
    import shutil

    from conftest import run_cli, write_bed_toml

    whole = write_bed_toml(tmp_path / "whole")
    assert run_cli("run", whole, "--quiet", "--threads", "1").returncode == 0
    final = (whole.parent / "output" / "particles_csv" / "particles_000004.csv").read_text()

    # Python first half, the CLI second.
    half = write_bed_toml(tmp_path / "py_then_cli")
    sim = mpdem.Simulation(mpdem.Scene.from_toml(half), threads=1)
    sim.run(duration=0.002)
    sim.save(half.parent / "output" / "checkpoint.bin")
    r = run_cli("run", half, "--quiet", "--threads", "1", "--resume", half.parent / "output" / "checkpoint.bin")
    assert r.returncode == 0, r.stderr
    assert (half.parent / "output" / "particles_csv" / "particles_000004.csv").read_text() == final

    # The CLI's checkpoint at step 1000 (checkpoint_every) of a run stopped at step 1050 (not at
    # 0.002 s: the CLI cuts the step that ends a run short), Python the rest.
    other = write_bed_toml(tmp_path / "cli_then_py")
    text = other.read_text().replace("[output]\n", "[output]\ncheckpoint_every = 1000\n")
    other.write_text(text.replace("duration = 0.004", "duration = 0.0021"))
    assert run_cli("run", other, "--quiet", "--threads", "1").returncode == 0
    other.write_text(text)
    shutil.copy(other.parent / "output" / "checkpoint.bin", tmp_path / "cli.bin")
    resumed = mpdem.Simulation.resume(tmp_path / "cli.bin", mpdem.Scene.from_toml(other), threads=1,
                                      write_output=False)
    assert resumed.steps == 1000
    resumed.run()
    rows = sorted(final.splitlines()[1:], key=lambda r: int(r.split(",")[1]))
    x = resumed.particles.position
    for k, row in enumerate(rows):
        assert [float(v) for v in row.split(",")[2:5]] == list(x[k])
