"""Every float, count and vector a call takes is checked at the call: an mpdem.InputError (a
ValueError) whose key names the argument, nothing changed, instead of a diverged state steps
later or a value silently ignored. A scene built from arrays names the builder call and row."""

import math

import numpy as np
import pytest

import mpdem
from conftest import build_bed

NAN, INF = math.nan, math.inf


def refused(key, call):
    """call() raises an InputError (a ValueError) naming `key`, in its key and its message."""
    with pytest.raises(mpdem.InputError) as e:
        call()
    assert isinstance(e.value, ValueError)
    assert e.value.key == key and f"'{key}'" in str(e.value), str(e.value)
    assert not str(e.value).startswith(":"), str(e.value)  # no empty file name in front
    return str(e.value)


@pytest.fixture
def sim(tmp_path):
    s = mpdem.Simulation(build_bed(tmp_path), threads=1, write_output=False)
    s.step(3)
    return s


@pytest.mark.parametrize("name", ["position", "velocity", "angular_velocity", "temperature"])
@pytest.mark.parametrize("bad", [NAN, INF, -INF])
def test_state_arrays_refuse_non_finite_values(sim, name, bad):
    before = getattr(sim.particles, name)
    values = before.copy()
    values[2] = bad  # one row (all of its components for the vectors)
    message = refused(name, lambda: setattr(sim.particles, name, values))
    assert f"particle id {sim.particles.id[2]}" in message  # the row's particle
    refused(name, lambda: sim.particles.set(name, values[2:3], ids=sim.particles.id[2:3]))
    assert np.array_equal(getattr(sim.particles, name), before)  # nothing set


def test_negative_temperatures_are_refused(sim):
    before = sim.particles.temperature
    refused("temperature", lambda: setattr(sim.particles, "temperature", -np.ones(len(sim.particles))))
    assert np.array_equal(sim.particles.temperature, before)
    sim.particles.temperature = np.zeros(len(sim.particles))  # 0 K is allowed, as in a particle CSV
    refused("temperature", lambda: sim.add_particles([[0.015, 0.015, 0.02]], 1e-3, temperature=-1.0))


def test_run_and_step_counts_and_durations_are_checked(sim):
    steps, t = sim.steps, sim.time
    for every in (0, -1, 2.5, True, "3"):
        refused("every", lambda: sim.run(duration=1e-5, callback=lambda s: None, every=every))
    refused("every", lambda: sim.run(duration=1e-5, every=0))  # also without a callback
    for duration in (NAN, INF, -1e-5, "soon"):
        refused("duration", lambda: sim.run(duration=duration))
    for n in (-1, 1.5, NAN):
        refused("n", lambda: sim.step(n))
    assert (sim.steps, sim.time) == (steps, t)  # no step taken
    with pytest.raises(TypeError, match="'callback'"):
        sim.run(duration=1e-5, callback=3)
    sim.step(0)
    sim.run(duration=0.0)
    calls = []
    sim.run(duration=4e-6, callback=lambda s: calls.append(s.steps), every=np.int64(1))
    assert sim.steps == steps + 2 and calls == [steps + 1, steps + 2]


@pytest.mark.parametrize("threads", [0, -1, 1.5, NAN, True])
def test_thread_counts_are_checked(tmp_path, threads):
    refused("threads", lambda: mpdem.Simulation(build_bed(tmp_path), threads=threads, write_output=False))


def test_vectors_are_checked(sim):
    motion = sim.barriers.motion("floor")
    for v in ([NAN, 0.0, 0.0], [0.0, INF, 0.0], [1.0, 0.0], "up"):
        refused("velocity", lambda: sim.barriers.set_velocity("floor", v))
    assert all(np.array_equal(a, b) for a, b in zip(sim.barriers.motion("floor"), motion))
    g = sim.gravity
    for v in ([NAN, 0.0, 0.0], [0.0, 0.0, -INF], [0.0, -9.81]):
        refused("gravity", lambda: setattr(sim, "gravity", v))
    assert np.array_equal(sim.gravity, g)


def test_added_particles_and_forces_are_checked(sim):
    n = len(sim.particles)
    at = [[0.015, 0.015, 0.02], [0.015, 0.0, 0.02]]
    assert "row 1" in refused("velocity", lambda: sim.add_particles(at, 1e-3, velocity=[[0, 0, 0], [0, NAN, 0]]))
    refused("position", lambda: sim.add_particles([[0.015, INF, 0.02]], 1e-3))
    refused("radius", lambda: sim.add_particles(at, [1e-3, NAN]))
    refused("radius", lambda: sim.add_particles(at, [1e-3, 1e-300]))  # its mass underflows
    refused("fixed", lambda: sim.add_particles(at, 1e-3, fixed=[0, 2]))
    refused("charge", lambda: sim.add_particles(at, 1e-3, charge=[0, NAN]))
    assert len(sim.particles) == n  # nothing half-added
    ids = sim.particles.id[:2]
    refused("force", lambda: sim.particles.add_force(ids, [[0, 0, 1e-5], [NAN, 0, 0]]))
    refused("torque", lambda: sim.particles.add_force(ids, [0, 0, 1e-5], torque=[0, INF, 0]))


def test_an_error_in_an_array_source_names_the_builder_call_and_row(tmp_path):
    s = build_bed(tmp_path)  # particles entry 0 and barriers entry 0 are arrays
    s.particles([[0.005, 0.005, 0.02], [0.008, 0.005, 0.02]], [1e-3, 1e-3], material="glass")
    s.particles([[0.005, 0.005, 0.025], [0.008, 0.005, 0.025]], [1e-3, -1e-3], material="glass")
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Simulation(s, write_output=False)
    message = str(e.value)
    assert message.startswith("scene (built in Python): particles entry 2, row 1: 'radius': "), message
    assert ".csv" not in message and "/tmp" not in message
    assert (e.value.key, e.value.entry, e.value.row) == ("radius", ("particles", 2), 1)
    with pytest.raises(mpdem.InputError, match=r"particles entry 2, row 1: 'radius'"):
        s.check()

    s = build_bed(tmp_path)
    floor = np.array(s._arrays["barriers"][0]["vertices"])
    floor[1, 2, 0] = NAN
    s.barriers(floor, material="glass", group="second")
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Simulation(s, write_output=False)
    assert str(e.value).startswith("scene (built in Python): barriers entry 1, row 1: 'x3': "), str(e.value)


def test_check_names_array_sources_by_their_builder_call(tmp_path):
    s = build_bed(tmp_path)
    s.particles([[0.005, 0.005, 0.02], [0.0055, 0.005, 0.02]], [1e-3, 1e-3], material="glass")  # overlap
    problems = [msg for stops, msg in s.check() if stops and "overlap" in msg]
    assert problems and all("particles entry 1" in m and ".csv" not in m for m in problems), problems


def test_ids_and_flags_are_whole_numbers(sim, tmp_path):
    """An id or flag given as a float is refused, not truncated to another particle's id."""
    first = int(sim.particles.id[0])  # 5: 5.5 would be truncated to it
    n, v = len(sim.particles), sim.particles.velocity
    refused("ids", lambda: sim.particles.set("velocity", [[0.0, 0.0, 1.0]], ids=[first + 0.5]))
    refused("ids", lambda: sim.remove_particles([first + 0.5]))
    refused("ids", lambda: sim.particles.add_force([first + 0.5], [0.0, 0.0, 1e-5]))
    refused("ids", lambda: sim.remove_particles([NAN]))
    refused("id", lambda: sim.add_particles([[0.015, 0.015, 0.02]], 1e-3, id=[1000.5]))
    assert len(sim.particles) == n and np.array_equal(sim.particles.velocity, v)
    sim.remove_particles([float(first)])  # a whole float is a whole number
    assert len(sim.particles) == n - 1

    s = mpdem.Scene(dir=tmp_path)
    refused("id", lambda: s.particles([[0.0, 0.0, 0.0]], 1e-3, id=[1.5]))
    refused("fixed", lambda: s.particles([[0.0, 0.0, 0.0]], 1e-3, fixed=[0.5]))
    refused("id", lambda: s.barriers(np.zeros((1, 3, 3)), id=[0.25]))


def test_arrays_of_the_wrong_shape_or_not_numbers_name_their_argument(sim, tmp_path):
    at = [[0.015, 0.015, 0.02], [0.015, 0.0, 0.02]]
    refused("velocity", lambda: sim.add_particles(at, 1e-3, velocity=[[0, 0, 1]] * 3))
    refused("radius", lambda: sim.add_particles(at, [1e-3, 1e-3, 1e-3]))
    refused("position", lambda: sim.add_particles([0.0, 0.1], 1e-3))
    refused("material", lambda: sim.add_particles(at, 1e-3, material=[0, [1]]))
    refused("charge", lambda: sim.add_particles(at, 1e-3, charge="high"))
    refused("force", lambda: sim.particles.add_force(sim.particles.id[:2], [[0, 0, 1]] * 3))
    refused("velocity", lambda: sim.particles.set("velocity", "fast"))
    s = mpdem.Scene(dir=tmp_path)
    refused("radius", lambda: s.particles(at, [1e-3, 1e-3, 1e-3]))
    refused("velocity", lambda: s.particles(at, 1e-3, velocity=[1.0, 2.0]))
    refused("vertices", lambda: s.barriers(np.zeros((2, 3, 2))))


@pytest.mark.parametrize("under", ["afile/out", "afile"])
def test_output_folder_that_cannot_be_made_is_refused_at_the_call(tmp_path, under):
    """A path under a regular file (or the file itself) is one clean InputError when the Simulation
    is made, not a raw 'filesystem error' at the first output."""
    (tmp_path / "afile").write_text("not a folder\n")
    with pytest.raises(mpdem.InputError) as e:
        mpdem.Simulation(build_bed(tmp_path), threads=1, output_dir=tmp_path / under)
    message = str(e.value)
    assert isinstance(e.value, ValueError)
    assert "filesystem error" not in message, message
    assert str(tmp_path / under) in message and "output_dir=" in message, message
    assert ("a part of the path is a file" in message) or ("the output folder is a file" in message), message
