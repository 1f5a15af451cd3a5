"""Simulation: a scene run step by step from Python (docs/python.md, "Running").

Stepping happens in the engine with the GIL released; Python runs only between accepted steps
(callbacks, Ctrl-C), never inside a step's fixed-point iterations.
"""

import math
import operator
import tempfile
from pathlib import Path

import numpy as np

from . import _core
from .bodies import Bodies
from .scene import _scene_of, input_error, integers, numbers

__all__ = ["Simulation", "Particles", "Bonds"]


class Particles:
    """The particles' arrays (docs/python.md, "State").

    Attributes (position, velocity, ...) are copies in ascending id order, the same order every
    time whatever the engine's storage order; assigning one (all particles, id order) or calling
    set(name, values, ids) changes the state before the next step. view(name) is a zero-copy,
    read-only array in the engine's storage order, valid until the next step.
    """

    def __init__(self, core):
        self._core = core

    def __len__(self):
        return self._core.count

    def view(self, name):
        """Zero-copy, read-only, storage order (pair it with view("id")); valid until the next step."""
        return self._core.view(name)

    def set(self, name, values, ids=None):
        """Sets `name` (position, velocity, angular_velocity, temperature) for the particles
        `ids` (values in that order), or for all particles in id order when ids is None."""
        self._core.set(name, numbers(name, values, None), None if ids is None else integers("ids", ids))

    def add_force(self, ids, force=None, torque=None):
        """Adds force (N) and torque (N m, about the centre) to the particles `ids` at every
        evaluation from now on, on top of contacts and fields, until set again or cleared: rows of
        (3,) in the order of `ids` (one row: the same for all). A zero row removes a particle's
        load. Their work enters the energy balance (log: total_energy). Not in checkpoints."""
        ids = np.atleast_1d(integers("ids", ids))
        n = len(ids)
        f = np.zeros((n, 3)) if force is None else numbers("force", force, (n, 3))
        t = np.zeros((n, 3)) if torque is None else numbers("torque", torque, (n, 3))
        self._core.add_loads(ids, np.ascontiguousarray(f), np.ascontiguousarray(t))

    def clear_forces(self):
        """Removes every force and torque added with add_force."""
        self._core.clear_loads()

    def as_dict(self):
        """Every array, id-ordered copies."""
        return {name: self._core.get(name) for name in _core.particle_arrays}


def _array_property(name, doc):
    def get(self):
        return self._core.get(name)

    def put(self, values):
        self.set(name, values)

    settable = name in _core.settable_arrays
    return property(get, put if settable else None, doc=doc)


# The attributes are the engine's particle column table (src/state/particle_columns.hpp): name,
# shape, unit and whether it can be assigned.
for _name in _core.particle_arrays:
    _doc = _core.particle_array_docs[_name]
    setattr(Particles, _name, _array_property(_name, _doc))


class Barriers:
    """The barrier groups (docs/python.md, "Barriers"): loads of the last evaluation, motion, and
    a constant velocity set between steps."""

    def __init__(self, core):
        self._core = core

    @property
    def groups(self):
        """The groups' names, in the order of barrier_groups.csv."""
        return list(self._core.barrier_groups)

    def load(self, group):
        """dict: force (3,) N, moment (3,) N m about the origin, axis_torque N m, power W (what the
        group's prescribed motion puts into the particles), area m^2."""
        return self._core.group_load(group)

    def force(self, group):
        """(3,) N, the particles' force on the group (last evaluation)."""
        return self._core.group_load(group)["force"]

    def motion(self, group):
        """(displacement (3,) m, velocity (3,) m/s) of the group's translation now."""
        return self._core.group_motion(group)

    def set_velocity(self, group, velocity):
        """From now on the group translates at `velocity` (m/s), its position continuous; only for
        groups without sine, cosine or rotation terms in their law."""
        self._core.set_group_velocity(group, _vector("velocity", velocity))


class Bonds:
    """The parallel bonds (docs/python.md, "Bonds"): copies of their state now, one entry per bond
    in ascending (id_i, id_j) order, broken bonds included (intact False); the breaks since the
    last look with new_breaks(). Forces and moments are those on particle id_j (id_i takes the
    opposite)."""

    _ARRAYS = {
        "id_i": "(n,) int64, the lower particle id of each bond",
        "id_j": "(n,) int64, the higher particle id",
        "intact": "(n,) bool, False once broken",
        "normal_force": "(n,) N, along the bond (> 0 compression, < 0 tension)",
        "shear_force": "(n, 3) N, normal to the bond",
        "twisting_moment": "(n,) N m, about the bond's axis",
        "bending_moment": "(n, 3) N m, normal to the bond",
        "sigma": "(n,) Pa, the largest tensile stress on the bond's rim now, -F_n / A + |M_s| R / I",
        "tau": "(n,) Pa, the largest shear stress on the bond's rim now, |F_s| / A + |M_n| R / J",
        "length": "(n,) m, the centre distance when the bond was made",
    }

    def __init__(self, core):
        self._core = core

    def __len__(self):
        return len(self._core.bond_arrays()["id_i"])

    def as_dict(self):
        """Every array at once (copies)."""
        return self._core.bond_arrays()

    def new_breaks(self):
        """The bonds broken since the last call (since the start at the first): a dict of numpy
        arrays, one entry per break in the order of bonds_broken.csv: time (s), id_i, id_j, mode
        ("tension" or "shear"), sigma and tau (Pa, the stresses that broke it)."""
        return self._core.new_bond_breaks()


def _bond_property(name, doc):
    return property(lambda self: self._core.bond_arrays()[name], doc=doc)


for _name, _doc in Bonds._ARRAYS.items():
    setattr(Bonds, _name, _bond_property(_name, _doc))


class Simulation:
    """A run of `scene` (an mpdem.Scene or a path to a TOML scene file).

    threads: OpenMP threads while stepping (None: all cores); output_dir: where the outputs go
    (None: the scene's [output] dir); write_output=False: no files; progress: the CLI's progress
    line on stderr.
    """

    def __init__(self, scene, threads=None, output_dir=None, write_output=True, progress=False, _resume=None):
        self.scene = _scene_of(scene)
        self._scratch = tempfile.TemporaryDirectory(prefix="mpdem-")  # CSV files of array sources
        threads = 0 if threads is None else _whole("threads", threads, 1)
        self._core, _ = self.scene._engine_call(
            self._scratch.name,
            lambda file, text, name: _core.Simulation(file, text, name, threads=threads,
                                                      output_dir=str(output_dir) if output_dir is not None else "",
                                                      write_output=write_output, progress=progress,
                                                      resume=str(_resume) if _resume is not None else ""))
        self.particles = Particles(self._core)
        self.bodies = Bodies(self._core)
        self.barriers = Barriers(self._core)
        #: the parallel bonds (None without [bonds] in the scene)
        self.bonds = Bonds(self._core) if self._core.bond_arrays() is not None else None

    @classmethod
    def resume(cls, path, scene, **options):
        """Continues the run checkpointed in `path` (Simulation.save or the CLI's checkpoint.bin) of
        `scene`, which must be the scene it was written from (InputError otherwise)."""
        return cls(scene, _resume=path, **options)

    # --- running ---

    def run(self, duration=None, callback=None, every=1):
        """Steps for `duration` s of simulated time (None: to the scene's [time] duration),
        calling callback(sim) after every `every` accepted steps. Returns True when the run
        reached the scene's end (its final outputs then written as `mpdem run` writes them)."""
        end = None if duration is None else self.time + _seconds("duration", duration)
        every = _whole("every", every, 1)
        if callback is not None and not callable(callback):
            raise TypeError(f"'callback': expected a function of the simulation, got {type(callback).__name__}")
        cb = None if callback is None else (lambda: callback(self))
        return self._core.run(end, cb, every)

    def step(self, n=1):
        """n accepted steps (n >= 0)."""
        self._core.step(_whole("n", n, 0))

    def close(self):
        """Writes the final outputs now (a run that stopped before the scene's end)."""
        self._core.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    # --- state ---

    @property
    def time(self):
        """s, simulated time"""
        return self._core.time

    @property
    def dt(self):
        """s, the step the next step takes"""
        return self._core.dt

    @property
    def end_time(self):
        """s, the scene's [time] duration"""
        return self._core.end_time

    @property
    def steps(self):
        return self._core.steps

    @property
    def output_dir(self):
        return Path(self._core.output_dir)

    @property
    def record_contacts(self):
        """True: every evaluation records each particle-particle contact's forces, so that
        contacts() can list them (off by default: the pair kernel then writes nothing extra)."""
        return self._core.record_contacts

    @record_contacts.setter
    def record_contacts(self, on):
        self._core.record_contacts = bool(on)

    def contacts(self):
        """The contacts of the last evaluation (the forces that made the particles' `force`), as a
        dict of numpy arrays, one row per contact: i (the particle the forces act on), j (the
        other particle's id, -1 for a barrier contact), element (the barrier element's id, -1 for
        a pair), point (M, 3) m, normal (M, 3) unit towards i, overlap (M,) m (< 0: a gap),
        normal_force and tangential_force (M, 3) N on i (j takes minus them), sliding (M,) bool,
        touching (M,) bool (a contact law acts: a contact), bridge (M,) bool (a liquid bridge
        acts; alone, not a contact). Needs record_contacts = True before the step (RuntimeError
        otherwise)."""
        return self._core.contacts()

    @property
    def gravity(self):
        """(3,) m/s^2; setting it acts from the next step (the rates re-evaluated)."""
        return np.array(self._core.gravity)

    @gravity.setter
    def gravity(self, g):
        self._core.gravity = _vector("gravity", g)

    @property
    def materials(self):
        """The materials' names; particles' `material` indexes this list."""
        return list(self._core.materials)

    def log(self):
        """The global log's quantities now, by log.csv's column names (docs/output.md)."""
        return self._core.log()

    def save(self, path):
        """A checkpoint of the whole state; Simulation.resume(path, scene) continues it bitwise."""
        self._core.save(str(path))

    # --- particles added and removed between steps ---

    def _material_indices(self, material, n):
        names = self._core.materials
        if material is None:
            return None
        m = np.asarray(material, dtype=object).reshape(-1)
        out = np.empty(len(m), dtype=float)
        for k, v in enumerate(m):
            if isinstance(v, str):
                if v not in names:
                    raise input_error(f"'material': no material '{v}' (materials: {', '.join(names)})", "material")
                out[k] = names.index(v)
            else:
                out[k] = numbers("material", v, ())
        return numbers("material", out, (n,))

    def add_particles(self, position, radius, velocity=None, angular_velocity=None, material=None, id=None,
                      temperature=None, charge=None, fixed=None):
        """Adds particles between steps and returns their ids (the next free ones unless `id`
        gives them; a taken id is an InputError). position (N, 3) m, radius (N,) m, velocity and
        angular_velocity (N, 3), material (a name or index, or N of them; default the first
        material), temperature (K) and charge (C) default to the material's, fixed (N,) 0/1.
        The others' contact history is kept; no overlap check is made."""
        position = numbers("position", position, (-1, 3), reshape=True)
        n = len(position)
        arrays = {"position": position, "radius": numbers("radius", radius, (n,))}
        for name, a, shape in (("velocity", velocity, (n, 3)), ("angular_velocity", angular_velocity, (n, 3)),
                               ("temperature", temperature, (n,)), ("charge", charge, (n,)), ("fixed", fixed, (n,))):
            if a is not None:
                arrays[name] = numbers(name, a, shape)
        if id is not None:
            arrays["id"] = numbers("id", id, (n,), whole=True, reshape=True)
        mats = self._material_indices(material, n)
        if mats is not None:
            arrays["material"] = mats
        return self._core.add_particles({k: np.ascontiguousarray(v) for k, v in arrays.items()})

    def add_bond(self, id_i, id_j):
        """Bonds the particles id_i and id_j between steps, at their present positions (no force
        yet; radius and law from [bonds] for their materials). An InputError (a ValueError) for a
        scene without [bonds], an unknown id, id_i == id_j or a pair bonded already."""
        self._core.add_bond(_whole("id_i", id_i, -2**63), _whole("id_j", id_j, -2**63))

    def remove_particles(self, ids):
        """Removes the particles `ids` between steps (written to removed.csv; an unknown id is an
        InputError); the others' contact history is kept."""
        self._core.remove_particles(np.atleast_1d(integers("ids", ids)))


# Arguments are checked at the call, each class of value alike: an InputError (a ValueError)
# naming the argument, rather than a diverged state or a silently ignored value steps later.

def _whole(key, value, least):
    """An integer >= least (not a bool, not a float: 2.5 steps is not rounded)."""
    try:
        n = operator.index(value)
    except TypeError:
        n = None
    if n is None or isinstance(value, (bool, np.bool_)) or n < least:
        raise input_error(f"'{key}': expected an integer >= {least}, got {value!r}", key)
    return n


def _seconds(key, value):
    """A finite number of seconds >= 0."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not (math.isfinite(v) and v >= 0.0):
        raise input_error(f"'{key}': expected a finite number of seconds >= 0, got {value!r}", key)
    return v


def _vector(key, value):
    """Three finite numbers, as a list."""
    try:
        v = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        v = np.full(1, np.nan)
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise input_error(f"'{key}': expected three finite numbers, got {value!r}", key)
    return [float(c) for c in v]
