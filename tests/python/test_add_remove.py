"""Particles added and removed between steps: unique ids, the others' contact history kept."""

import numpy as np
import pytest

import mpdem
from conftest import build_bed

FAR = [0.015, 0.015, 0.02]  # an isolated sphere, far from the bed


def settled(tmp_path, extra=False):
    s = build_bed(tmp_path, duration=0.02)
    if extra:
        s.particles([FAR], [1e-3], id=[1000], material="glass")
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    sim.run(duration=0.008)
    assert sim.log()["contacts_pp"] >= 4  # springs to keep
    return sim


def others(sim, ids):
    keep = np.isin(sim.particles.id, ids)
    return {n: getattr(sim.particles, n)[keep] for n in ("position", "velocity", "angular_velocity")}


def test_removing_a_particle_keeps_the_others_history(tmp_path):
    """A bed with an isolated extra sphere, removed at 8 ms, against the bed without it: the same
    trajectories to round-off (the removal rebuilds the lists in another order, so sums differ in
    the last bits; lost springs would differ by far more: the bed's friction contacts stick:
    re-adding every sphere, which drops all springs, moves the velocities by 2e-3 of their largest
    value in the same 2 ms). The sphere touched nobody, so its removal leaves the rates as they are
    (an evaluation at the end-of-step velocities would move them by about 1e-8)."""
    with_extra = settled(tmp_path, extra=True)
    plain = settled(tmp_path)
    bed_ids = plain.particles.id
    with_extra.remove_particles([1000])
    assert len(with_extra.particles) == len(plain.particles) and 1000 not in with_extra.particles.id
    with_extra.run(duration=0.002)
    plain.run(duration=0.002)
    a, b = others(with_extra, bed_ids), others(plain, bed_ids)
    for n in a:
        assert np.allclose(a[n], b[n], rtol=0, atol=1e-12 * np.abs(b[n]).max()), n


def test_adding_a_particle_keeps_the_others_history_and_ids_unique(tmp_path):
    plain = settled(tmp_path)
    added = settled(tmp_path)
    bed_ids = plain.particles.id
    new = added.add_particles([FAR, [0.015, 0.0, 0.02]], 1e-3, velocity=[[0.0, 0.0, -0.1]] * 2, material="glass")
    assert list(new) == [bed_ids.max() + 1, bed_ids.max() + 2]  # the next free ids
    assert len(np.unique(added.particles.id)) == len(bed_ids) + 2
    plain.particles.set("velocity", plain.particles.velocity)
    added.run(duration=0.002)
    plain.run(duration=0.002)
    a, b = others(added, bed_ids), others(plain, bed_ids)
    for n in a:
        assert np.array_equal(a[n], b[n]), n
    # The new spheres fell freely from rest + 0.1 m/s downwards.
    x = added.particles.position[np.isin(added.particles.id, new)]
    t = 0.002
    assert np.allclose(x[:, 2], 0.02 - 0.1 * t - 0.5 * 9.81 * t * t, rtol=0, atol=1e-12)


def test_taken_and_unknown_ids_are_refused(tmp_path):
    sim = settled(tmp_path)
    taken = int(sim.particles.id[0])
    with pytest.raises(mpdem.InputError, match=f"id {taken} exists"):
        sim.add_particles([FAR], 1e-3, id=[taken])
    with pytest.raises(mpdem.InputError, match="no particle with id 999"):
        sim.remove_particles([999])
    with pytest.raises(mpdem.InputError, match="no material 'steel'"):
        sim.add_particles([FAR], 1e-3, material="steel")
    with pytest.raises(mpdem.InputError) as e:
        sim.add_particles([FAR], -1e-3)
    assert e.value.key == "radius"
    n = len(sim.particles)
    sim.step(1)
    assert len(sim.particles) == n  # nothing half-added


def test_removed_particles_are_written_to_removed_csv(tmp_path):
    s = build_bed(tmp_path, duration=0.01)
    sim = mpdem.Simulation(s, threads=1, output_dir=tmp_path / "out")
    sim.step(10)
    gone = sim.particles.id[:2]
    sim.remove_particles(gone)
    sim.step(1)
    rows = np.loadtxt(tmp_path / "out" / "removed.csv", delimiter=",", skiprows=1, ndmin=2)
    assert sorted(rows[:, 1].astype(int)) == sorted(gone)
