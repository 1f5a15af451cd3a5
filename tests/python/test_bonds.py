"""Parallel bonds from Python (docs/python.md, "Bonds"): Scene.bonds, sim.bonds, its new_breaks(),
sim.add_bond. Spheres r = 1 mm, 2500 kg/m^3, bonds lambda = 1, E_b = 1 GPa, k_n/k_s = 2.5:
- the bonded cantilever of tests/contact/test_bonds.cpp (11 touching spheres, the first fixed,
  1 mN across the tip with add_force, damped to rest): the tip deflects by the discrete chain's
  closed form y = F l^3 N (4 N^2 - 1) / (12 E I) + N kappa F l / (E A) within 1e-3 and by
  Euler-Bernoulli's F L^3 / (3 E I) = 3.395 um within 3 %; every bond carries the shear F and bond
  m the moment F l (N - m - 1/2) (1e-3);
- a bonded pair pulled apart by a rising load breaks once in tension, sigma >= tensile_strength,
  reported once by new_breaks() and in bonds_broken.csv;
- a bond added between steps holds a pair apart: the pull F stretches it by F L / (E A) (1e-3);
- errors for a bad add_bond, None without [bonds]."""

import csv
import math

import numpy as np
import pytest

import mpdem

R, RHO = 1e-3, 2500.0  # m, kg/m^3
E_B, KAPPA = 1e9, 2.5  # Pa, k_n / k_s
N = 10  # bonds of the cantilever
ELL = 2.0 * R  # m, bond length
AREA = math.pi * R * R  # m^2
I = AREA * R * R / 4.0  # m^4
F = 1e-3  # N
DT = 2e-7  # s


def bonded(x, ids, fixed, output=None, **bond_keys):
    """Spheres at x (rows) with ids, bonded by [bonds] with bond_keys, no gravity."""
    s = mpdem.Scene(name="bonded")
    s.time(duration=1.0, dt=DT, integrator="verlet")
    s.gravity([0.0, 0.0, 0.0])
    s.material("glass", density=RHO, young=1e8, poisson=0.3)
    s.bonds(young=E_B, radius_ratio=1.0, stiffness_ratio=KAPPA, **bond_keys)
    s.particles(np.asarray(x, dtype=float), R, id=ids, material="glass", fixed=fixed)
    s.domain(min=[-0.01, -0.02, -0.02], max=[0.03, 0.02, 0.02])
    if output is not None:
        s.output(dir=str(output), log_every=50, bonds_every=1e-4)
    return s


def chain():
    x = np.zeros((N + 1, 3))
    x[:, 0] = ELL * np.arange(N + 1)
    s = bonded(x, np.arange(1, N + 2), [1] + [0] * N, damping=0.7, gap=1e-6)
    s.fields(drag=0.04)
    return s


def test_cantilever_deflects_by_the_discrete_chain_and_euler_bernoulli():
    sim = mpdem.Simulation(chain(), threads=1, write_output=False)
    assert len(sim.bonds) == N
    assert list(sim.bonds.id_i) == list(range(1, N + 1)) and list(sim.bonds.id_j) == list(range(2, N + 2))
    sim.particles.add_force([N + 1], [0.0, F, 0.0])
    sim.step(60000)  # 12 ms: the bending mode damped many times over
    y = sim.particles.position[N, 1]
    discrete = F * ELL**3 * N * (4 * N * N - 1) / (12.0 * E_B * I) + N * KAPPA * F * ELL / (E_B * AREA)
    euler_bernoulli = F * (N * ELL) ** 3 / (3.0 * E_B * I)
    assert abs(euler_bernoulli - 3.395e-6) < 1e-9
    assert abs(y - discrete) / discrete < 1e-3
    assert abs(y - euler_bernoulli) / euler_bernoulli < 0.03
    b = sim.bonds
    assert b.intact.dtype == bool and b.intact.all()
    assert b.shear_force.shape == (N, 3) and b.bending_moment.shape == (N, 3)
    # On particle j (outwards): each bond holds the tip's load back, -F along y.
    assert np.allclose(b.shear_force[:, 1], -F, rtol=1e-3, atol=0.0)
    moment = F * ELL * (N - np.arange(N) - 0.5)  # N m, about the bond's centre
    assert np.allclose(np.linalg.norm(b.bending_moment, axis=1), moment, rtol=1e-3, atol=0.0)
    # sigma = -F_n / A + |M_s| R / I, tau = |F_s| / A + |M_n| R / J, from the arrays themselves.
    assert np.allclose(b.sigma, -b.normal_force / AREA + np.linalg.norm(b.bending_moment, axis=1) * R / I,
                       rtol=1e-12, atol=0.0)
    assert np.allclose(b.tau, np.linalg.norm(b.shear_force, axis=1) / AREA + np.abs(b.twisting_moment) * R / (2 * I),
                       rtol=1e-12, atol=0.0)
    assert np.allclose(b.length, ELL, rtol=1e-12, atol=0.0)
    assert b.new_breaks()["id_i"].size == 0


def test_pulled_pair_breaks_once_in_tension(tmp_path):
    strength = 1e6  # Pa
    ramp = 1e4  # N/s: F / A reaches the strength at ~0.31 ms
    s = bonded([[0.0, 0.0, 0.0], [ELL, 0.0, 0.0]], [1, 2], [1, 0], output=tmp_path / "out", damping=0.5,
               gap=1e-6, tensile_strength=strength)
    sim = mpdem.Simulation(s, threads=1)
    assert sim.bonds.intact.tolist() == [True]
    breaks = []
    while sim.time < 4e-4:
        sim.particles.add_force([2], [ramp * (sim.time + DT), 0.0, 0.0])
        sim.step()
        new = sim.bonds.new_breaks()
        breaks += [(t, i, j, m, sg) for t, i, j, m, sg in zip(new["time"], new["id_i"], new["id_j"], new["mode"],
                                                              new["sigma"])]
    sim.close()
    assert len(breaks) == 1
    t, i, j, mode, sigma = breaks[0]
    assert (i, j, mode) == (1, 2, "tension")
    assert strength <= sigma < 1.05 * strength
    assert abs(t - strength * AREA / ramp) < 0.05 * strength * AREA / ramp
    assert sim.bonds.intact.tolist() == [False]
    assert sim.log()["bonds_broken"] == 1 and sim.log()["bonds"] == 0
    with open(tmp_path / "out" / "bonds_broken.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 1 and rows[0]["mode"] == "tension" and float(rows[0]["sigma_max"]) == sigma
    assert float(rows[0]["time"]) == t
    assert (tmp_path / "out" / "bonds.pvd").exists()


def test_bond_added_between_steps_holds_the_pair():
    gap = 2e-3  # m between the surfaces: the gap rule makes no bond
    s = bonded([[0.0, 0.0, 0.0], [2 * R + gap, 0.0, 0.0]], [4, 9], [1, 0], damping=0.7, gap=1e-6)
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    assert len(sim.bonds) == 0 and sim.bonds.shear_force.shape == (0, 3) and sim.bonds.id_i.dtype == np.int64
    sim.add_bond(9, 4)
    assert (sim.bonds.id_i.tolist(), sim.bonds.id_j.tolist()) == ([4], [9])
    length = 2 * R + gap
    assert abs(sim.bonds.length[0] - length) < 1e-15
    with pytest.raises(mpdem.InputError, match="bonded already"):
        sim.add_bond(4, 9)
    with pytest.raises(ValueError, match="two particles"):
        sim.add_bond(4, 4)
    with pytest.raises(mpdem.InputError, match="no particle with id 5"):
        sim.add_bond(4, 5)
    sim.particles.add_force([9], [F, 0.0, 0.0])
    sim.step(10000)  # 2 ms: the axial mode (period 23 us) damped at 0.7 of critical
    stretch = sim.particles.position[1, 0] - length
    assert abs(stretch - F * length / (E_B * AREA)) / (F * length / (E_B * AREA)) < 1e-3
    assert abs(sim.bonds.normal_force[0] + F) < 1e-3 * F  # tension on particle 9: -F


def test_bonds_table_from_the_builder(tmp_path):
    s = bonded([[0.0, 0.0, 0.0], [ELL, 0.0, 0.0]], [1, 2], [1, 0], gap=1e-6, shear_strength=2e6)
    s.bond_pair(materials=["glass", "glass"], damping=0.2)
    text = s.to_toml(tmp_path / "bonded.toml")
    assert "[bonds]" in text and "shear_strength = 2000000.0" in text and "[[bonds.pair]]" in text
    again = mpdem.Simulation(mpdem.Scene.from_toml(tmp_path / "bonded.toml"), threads=1, write_output=False)
    assert len(again.bonds) == 1


def test_no_bonds_without_the_table():
    s = mpdem.Scene()
    s.time(duration=1e-3, dt=1e-6, integrator="trapezoidal")
    s.material("glass", density=RHO, young=1e8, poisson=0.3)
    s.particles([[0.0, 0.0, 0.0], [ELL, 0.0, 0.0]], R, id=[1, 2], material="glass")
    sim = mpdem.Simulation(s, threads=1, write_output=False)
    assert sim.bonds is None
    assert not any("bond" in k for k in sim.log())
    with pytest.raises(mpdem.InputError, match="no \\[bonds\\]"):
        sim.add_bond(1, 2)
