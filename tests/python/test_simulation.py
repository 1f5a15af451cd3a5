"""mpdem.Simulation: running, state arrays against the CLI's output, setting state, callbacks,
the GIL and Ctrl-C."""

import csv
import os
import signal
import threading
import time
import traceback
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import mpdem
from conftest import build_bed, run_cli, write_bed_toml


def test_outputs_are_the_clis(tmp_path, bed_toml):
    r = run_cli("run", bed_toml, "--quiet", "--threads", "1")
    assert r.returncode == 0, r.stderr
    sim = mpdem.Simulation(mpdem.Scene.from_toml(bed_toml), threads=1, output_dir=tmp_path / "py")
    assert sim.run() is True
    cli = bed_toml.parent / "output"
    for name in ("log.csv", "particles_csv/particles_000004.csv", "barrier_groups.csv", "particles.pvd"):
        assert (cli / name).read_bytes() == (tmp_path / "py" / name).read_bytes(), name


def test_state_arrays_match_the_clis_csv(tmp_path, bed_toml):
    assert run_cli("run", bed_toml, "--quiet", "--threads", "1").returncode == 0
    with open(bed_toml.parent / "output" / "particles_csv" / "particles_000004.csv") as f:
        rows = sorted(csv.DictReader(f), key=lambda r: int(r["id"]))
    sim = mpdem.Simulation(mpdem.Scene.from_toml(bed_toml), threads=1, write_output=False)
    sim.run()
    p = sim.particles
    assert list(p.id) == [int(r["id"]) for r in rows]
    cols = {"position": "x y z", "velocity": "vx vy vz", "angular_velocity": "wx wy wz", "force": "fx fy fz",
            "radius": "radius", "temperature": "temperature", "charge": "charge"}
    for name, c in cols.items():
        expected = np.array([[float(r[k]) for k in c.split()] for r in rows]).squeeze()
        assert np.array_equal(getattr(p, name), expected), name  # the CSV prints round-trip digits


def cli_and_python_ends(bed_toml):
    """The bed run by the CLI and in Python: the CLI's last particle CSV rows (by id), its last
    particle VTU's arrays by name (in id order, read with meshio), and the Python simulation after
    its run."""
    import meshio

    assert run_cli("run", bed_toml, "--quiet", "--threads", "1").returncode == 0
    out = bed_toml.parent / "output"
    with open(out / "particles_csv" / "particles_000004.csv") as f:
        rows = sorted(csv.DictReader(f), key=lambda r: int(r["id"]))
    sim = mpdem.Simulation(mpdem.Scene.from_toml(bed_toml), threads=1, write_output=False)
    sim.run()
    vtu = meshio.read(out / "particles" / "particles_000004.vtu")
    order = np.argsort(np.asarray(vtu.point_data["id"]).ravel())
    return rows, lambda name: np.asarray(vtu.point_data[name])[order], sim


def test_torque_is_the_clis_csv_and_vtu_column(bed_toml):
    """The torque column (N m, one row of src/state/particle_columns.hpp): sim.particles.torque
    after the run equals the CLI's last particle CSV columns tx, ty, tz and its last particle VTU
    array "torque" (read with meshio), value for value (both print round-trip digits or bits)."""
    rows, vtu_array, sim = cli_and_python_ends(bed_toml)
    torque = sim.particles.torque
    assert torque.shape == (len(rows), 3) and torque.dtype == np.float64
    assert np.any(torque != 0.0)  # frictional contacts: real torques, not an empty column
    assert np.array_equal(torque, np.array([[float(r[k]) for k in ("tx", "ty", "tz")] for r in rows]))
    assert np.array_equal(vtu_array("torque"), torque)


def test_body_is_the_clis_csv_and_vtu_column(bed_toml):
    """The body column (int64, one row of src/state/particle_columns.hpp): sim.particles.body
    equals the CLI's last particle CSV column "body" and its last particle VTU array "body", -1 for
    every sphere of a scene without clumps."""
    rows, vtu_array, sim = cli_and_python_ends(bed_toml)
    body = sim.particles.body
    assert body.shape == (len(rows),) and body.dtype == np.int64
    assert np.array_equal(body, np.array([int(r["body"]) for r in rows]))
    assert np.all(body == -1)
    assert np.array_equal(vtu_array("body").ravel(), body)


@pytest.mark.parametrize("integrator", ["verlet", "trapezoidal"])
def test_a_velocity_set_between_steps_gives_free_flight(tmp_path, integrator):
    s = mpdem.Scene(dir=tmp_path)
    s.time(duration=1.0, dt=1e-4, integrator=integrator).gravity([0.0, 0.0, -9.81])
    s.material("glass", density=2500.0, young=1e7, poisson=0.3)
    s.particles([[0.0, 0.0, 0.5], [0.3, 0.3, 0.5]], [1e-3, 1e-3], id=[1, 2], material="glass")
    s.domain(min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.step(10)
    x0 = sim.particles.position
    v = np.array([0.3, -0.2, 0.1])
    sim.particles.set("velocity", [v], ids=[2])
    assert np.array_equal(sim.particles.velocity[1], v)
    n = 200
    sim.step(n)
    t = n * 1e-4
    g = np.array([0.0, 0.0, -9.81])
    expected = x0[1] + v * t + 0.5 * g * t * t
    assert np.allclose(sim.particles.position[1], expected, rtol=0, atol=1e-12)
    # The other sphere kept falling from rest at step 10 (velocity -9.81 * 1e-3 m/s then).
    v1 = np.array([0.0, 0.0, -9.81 * 10 * 1e-4])
    assert np.allclose(sim.particles.position[0], x0[0] + v1 * t + 0.5 * g * t * t, rtol=0, atol=1e-12)
    assert np.allclose(sim.particles.velocity[1], v + g * t, rtol=0, atol=1e-12)


def test_positions_set_in_id_order(tmp_path):
    sim = mpdem.Simulation(build_bed(tmp_path), threads=1, write_output=False)
    sim.step(5)
    x = sim.particles.position
    x[:, 2] += 1e-3
    sim.particles.position = x
    assert np.array_equal(sim.particles.position, x)
    view, vid = sim.particles.view("position"), sim.particles.view("id")
    assert not view.flags.writeable
    assert np.array_equal(view[np.argsort(vid)], x)  # storage order, same values
    with pytest.raises(ValueError, match="cannot be set"):
        sim.particles.set("mass", np.ones(len(sim.particles)))
    with pytest.raises(ValueError, match="no particle with id 4"):
        sim.particles.set("temperature", [300.0], ids=[4])
    with pytest.raises(ValueError, match="rows of 3"):
        sim.particles.velocity = np.zeros((3, 3))


def test_callbacks_come_after_accepted_steps(tmp_path):
    sim = mpdem.Simulation(build_bed(tmp_path, "trapezoidal"), threads=1, write_output=False)
    seen = []
    sim.run(duration=0.001, callback=lambda s: seen.append((s.steps, s.time)), every=100)
    assert [k for k, _ in seen] == list(range(100, sim.steps + 1, 100)) and len(seen) == 5
    assert all(abs(t - k * 2e-6) < 1e-15 for k, t in seen)
    assert sim.time == pytest.approx(0.001, abs=1e-15)


def test_a_raising_callback_stops_the_run_with_complete_outputs(tmp_path):
    sim = mpdem.Simulation(build_bed(tmp_path), threads=1, output_dir=tmp_path / "out")

    def servo(s):
        if s.steps == 700:
            raise RuntimeError("servo lost")

    with pytest.raises(RuntimeError, match="servo lost") as e:
        sim.run(callback=servo, every=1)
    assert "servo" in "".join(traceback.format_tb(e.value.__traceback__))  # the Python traceback
    assert sim.steps == 700
    log = np.loadtxt(tmp_path / "out" / "log.csv", delimiter=",", skiprows=1)
    assert log[-1, 0] == 700 and log.shape[1] == len(sim.log())  # every row complete
    ET.parse(tmp_path / "out" / "particles.pvd")  # well-formed
    sim.run()  # goes on to the end
    assert sim.time == pytest.approx(sim.end_time)


def test_run_releases_the_gil(tmp_path):
    sim = mpdem.Simulation(build_bed(tmp_path, duration=0.2), threads=2, write_output=False)
    counter, running = [0], [True]

    def count():
        while running[0]:
            counter[0] += 1

    worker = threading.Thread(target=count)
    worker.start()
    time.sleep(0.05)
    before = counter[0]
    t0 = time.perf_counter()
    sim.run()
    elapsed = time.perf_counter() - t0
    during = counter[0] - before
    running[0] = False
    worker.join()
    assert elapsed > 0.1  # long enough for the thread to be scheduled many times
    assert during > 10000, f"the Python thread counted {during} in {elapsed:.2f} s of stepping"


def test_ctrl_c_stops_after_the_current_step(tmp_path):
    scene = build_bed(tmp_path, duration=1.0)
    sim = mpdem.Simulation(scene, threads=1, output_dir=tmp_path / "out")
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.run()
    timer.join()
    assert 0 < sim.time < 1.0
    log = np.loadtxt(tmp_path / "out" / "log.csv", delimiter=",", skiprows=1)
    assert log.ndim == 2 and log[-1, 1] <= sim.time
    # The checkpoint beside the outputs continues the run.
    again = mpdem.Simulation.resume(tmp_path / "out" / "checkpoint.bin", scene, write_output=False)
    assert again.time == sim.time
    assert np.array_equal(again.particles.position, sim.particles.position)


def test_csv_snapshots_are_in_id_order(tmp_path, bed_toml):
    """The engine stores its particles in spatial order; every particle CSV snapshot lists them in
    ascending id order all the same (as on several ranks, where they are gathered by id)."""
    assert run_cli("run", bed_toml, "--quiet", "--threads", "1").returncode == 0
    snapshots = sorted((bed_toml.parent / "output" / "particles_csv").glob("particles_*.csv"))
    assert len(snapshots) == 5
    sim = mpdem.Simulation(mpdem.Scene.from_toml(bed_toml), threads=1, write_output=False)
    sim.run()
    assert not np.array_equal(sim.particles.view("id"), sim.particles.id)  # storage order is not id order
    for f in snapshots:
        ids = np.loadtxt(f, delimiter=",", skiprows=1, usecols=1, dtype=np.int64)
        assert np.all(np.diff(ids) > 0), f.name
