"""Scene: a scene file's tables in Python (docs/python.md, "Scenes").

The builder's methods are the TOML scene's tables and keys (docs/scene.md): ``scene.time(dt=...)``
is ``[time] dt = ...``, ``scene.material(name=...)`` one ``[[material]]`` entry. The engine reads
a built scene through the same reader as ``mpdem run``, so it gets the same defaults, checks and
messages (an InputError naming the key).
"""

import copy
import os
import tomllib
from pathlib import Path

import numpy as np

from . import _core
from .toml_writer import dumps

__all__ = ["Scene"]

# Tables that appear once, and tables that repeat ([[name]]), as in docs/scene.md.
TABLES = ("time", "tolerance", "analysis", "gravity", "fields", "near_field", "contact", "liquid_bridge",
          "bonds", "thermal", "domain", "neighbor", "parallel", "checks", "output")
REPEATED = ("material", "particles", "barriers", "inlet", "sink")

# Particle CSV columns of the array sources (docs/scene.md, "Particle CSV"): (array, columns).
_PARTICLE_COLUMNS = (("id", ("id",)), ("position", ("x", "y", "z")), ("radius", ("radius",)),
                     ("velocity", ("vx", "vy", "vz")), ("angular_velocity", ("wx", "wy", "wz")),
                     ("material", ("material",)), ("temperature", ("temperature",)), ("charge", ("charge",)),
                     ("density", ("density",)), ("fixed", ("fixed",)))


def _merge(into, keys):
    for k, v in keys.items():
        if isinstance(v, dict) and isinstance(into.get(k), dict):
            _merge(into[k], v)
        else:
            into[k] = v


def _csv_field(v):
    if isinstance(v, (float, np.floating)):
        return repr(float(v))  # the shortest text that reads back as the same double
    if isinstance(v, (bool, np.bool_)):
        return "1" if v else "0"
    return str(v)


class Scene:
    """A scene under construction, or read from a TOML file (Scene.from_toml)."""

    def __init__(self, dir=None, name="scene"):
        #: the TOML document: table name -> dict, repeated table name -> list of dicts
        self.data = {}
        #: folder that relative paths (CSV, STL files, the output folder) resolve against
        self.dir = Path(dir) if dir is not None else Path.cwd()
        #: what messages call the scene
        self.name = name
        self._arrays = {"particles": {}, "barriers": {}}  # entry index -> arrays
        self._file = None  # the file it was read from
        self._as_read = None  # data as read from _file (a changed scene is passed as text)

    # --- reading and writing -------------------------------------------------------------------

    @classmethod
    def from_toml(cls, path):
        """The scene of a TOML file: loaded by the engine to check it (InputError as in mpdem
        check), and its tables kept in .data for changes and to_toml()."""
        path = Path(path).resolve()
        _core.parse(str(path))  # syntax, keys and values, named by file, line and key
        with open(path, "rb") as f:
            data = tomllib.load(f)
        scene = cls(dir=path.parent, name=str(path))
        scene.data = data
        scene._file = path
        scene._as_read = copy.deepcopy(data)
        return scene

    @classmethod
    def from_dict(cls, data, dir=None, name="scene"):
        scene = cls(dir=dir, name=name)
        scene.data = copy.deepcopy(data)
        return scene

    def to_toml(self, path=None):
        """The scene as TOML text; with `path`, also written there, with the particles and
        barriers given as arrays written as CSV files beside it (path stem + .particlesK.csv)."""
        if path is None:
            if any(self._arrays.values()):
                raise ValueError("a scene with particles or barriers given as arrays needs a path: "
                                 "to_toml(path) writes them as CSV files beside it")
            return dumps(self.data)
        path = Path(path)
        files = self._write_arrays(path.parent.resolve(), path.stem, relative=True)
        text = dumps(self._document(files))
        path.write_text(text)
        return text

    def _document(self, files):
        doc = copy.deepcopy(self.data)
        for kind, by_entry in files.items():
            for k, f in by_entry.items():
                doc[kind][k]["file"] = f
        return doc

    def _write_arrays(self, folder, stem, relative):
        files = {"particles": {}, "barriers": {}}
        for k, arrays in self._arrays["particles"].items():
            f = folder / f"{stem}.particles{k}.csv"
            _write_particle_csv(f, arrays)
            files["particles"][k] = f.name if relative else str(f)
        for k, arrays in self._arrays["barriers"].items():
            f = folder / f"{stem}.barriers{k}.csv"
            _write_barrier_csv(f, arrays)
            files["barriers"][k] = f.name if relative else str(f)
        return files

    def _engine_input(self, scratch):
        """(file, text, name, sources) for the engine: the file itself when the scene is as read,
        else the TOML text standing for a file in self.dir, its array sources written to
        `scratch` (sources: each such CSV file's path -> (table, entry index))."""
        if self._file is not None and self.data == self._as_read and not any(self._arrays.values()):
            return str(self._file), None, "", {}
        files = self._write_arrays(Path(scratch), "scene", relative=False)
        name = f"{self.name} (built in Python)" if self._file is None else f"{self._file} (changed in Python)"
        sources = {path: (kind, k) for kind, by_entry in files.items() for k, path in by_entry.items()}
        return str(self.dir / f"{Path(self.name).stem}.toml"), dumps(self._document(files)), name, sources

    def _engine_call(self, scratch, call):
        """(call(file, text, name), sources) on the engine's input (_engine_input). An InputError
        in an array source is raised again naming the builder call and row instead of the
        temporary CSV file it was passed in (which the user never saw, and which is deleted)."""
        file, text, name, sources = self._engine_input(scratch)
        try:
            return call(file, text, name), sources
        except _core.InputError as e:
            where = sources.get(getattr(e, "file", None))
            if where is None:
                raise
            raise _array_source_error(e, name, *where) from None

    def check(self):
        """The problems `mpdem check` reports, as (stops_run, message) pairs; raises InputError
        for bad input, as Simulation(scene) would. An array source is named as its builder call
        ("particles entry 1"), not by the temporary CSV file it was passed in."""
        import tempfile

        with tempfile.TemporaryDirectory() as scratch:
            problems, sources = self._engine_call(scratch, _core.check)
        for path, (table, entry) in sources.items():
            problems = [(stop, msg.replace(path, f"{table} entry {entry}")
                         .replace(f"'{Path(path).name}'", f"{table} entry {entry}")) for stop, msg in problems]
        return problems

    # --- tables ----------------------------------------------------------------------------------

    def _set(self, table, keys):
        _merge(self.data.setdefault(table, {}), keys)
        return self

    def _add(self, table, keys):
        self.data.setdefault(table, []).append({k: v for k, v in keys.items() if v is not None})
        return len(self.data[table]) - 1

    def time(self, **keys):
        """[time]: duration (s), dt (s), integrator ("verlet", the default, | "trapezoidal"), adaptive, ..."""
        return self._set("time", keys)

    def tolerance(self, **keys):
        return self._set("tolerance", keys)

    def analysis(self, **keys):
        return self._set("analysis", keys)

    def gravity(self, vector=None, **keys):
        """[gravity] vector = [gx, gy, gz] (m/s^2)."""
        if vector is not None:
            keys["vector"] = list(np.asarray(vector, dtype=float))
        return self._set("gravity", keys)

    def fields(self, **keys):
        return self._set("fields", keys)

    def near_field(self, **keys):
        return self._set("near_field", keys)

    def contact(self, particle_particle=None, particle_barrier=None, **keys):
        """[contact.particle_particle] and [contact.particle_barrier] as dicts of their keys."""
        if particle_particle is not None:
            keys["particle_particle"] = dict(particle_particle)
        if particle_barrier is not None:
            keys["particle_barrier"] = dict(particle_barrier)
        return self._set("contact", keys)

    def contact_pair(self, **keys):
        """One [[contact.pair]] entry: the coefficients of one pair of materials."""
        self.data.setdefault("contact", {}).setdefault("pair", []).append(keys)
        return self

    def liquid_bridge(self, **keys):
        """[liquid_bridge]: capillary bridges between every pair of materials: model ("willett" |
        "rabinovich" | "none"), surface_tension (N/m), contact_angle (deg), volume (m^3) or
        liquid_fraction, viscosity (Pa s), min_gap, barriers (docs/scene.md). A pair's own
        bridge is contact_pair(..., liquid_bridge={...})."""
        return self._set("liquid_bridge", keys)

    def bonds(self, **keys):
        """[bonds]: Potyondy-Cundall parallel bonds (docs/scene.md "[bonds]"): young (Pa, required),
        radius_ratio, stiffness_ratio, tensile_strength (Pa), shear_strength (Pa), damping (ratio of
        critical), gap (m: bonds made at t = 0 between particles closer than it), file (a bond CSV
        of id pairs, relative to the scene's dir). One pair of materials' own keys: bond_pair()."""
        return self._set("bonds", {k: str(v) if isinstance(v, os.PathLike) else v for k, v in keys.items()})

    def bond_pair(self, **keys):
        """One [[bonds.pair]] entry: materials=[a, b] and the [bonds] keys that differ for that pair
        (bonded=False: none between them)."""
        self.data.setdefault("bonds", {}).setdefault("pair", []).append(keys)
        return self

    def thermal(self, **keys):
        return self._set("thermal", keys)

    def domain(self, **keys):
        """[domain]: min, max (m), periodic (axes), on_exit."""
        return self._set("domain", keys)

    def neighbor(self, **keys):
        return self._set("neighbor", keys)

    def parallel(self, **keys):
        return self._set("parallel", keys)

    def checks(self, **keys):
        return self._set("checks", keys)

    def output(self, **keys):
        """[output]: dir (relative to Scene.dir), particles_every (s), log_every (steps), ..."""
        return self._set("output", keys)

    def material(self, name, **keys):
        """One [[material]]: name, density (kg/m^3), young (Pa), poisson, ..."""
        self._add("material", dict(name=name, **keys))
        return self

    def inlet(self, **keys):
        """One [[inlet]] (docs/scene.md: region, rates, start, end, radius, material, ...)."""
        self._add("inlet", keys)
        return self

    def sink(self, **keys):
        """One [[sink]]: region, min, max (box) or base, axis, radius, height (cylinder)."""
        self._add("sink", keys)
        return self

    def coarse_grain(self, **keys):
        """One [[coarse_grain]]: grid or profile, kernel, width (m), every (s), average (s), samples."""
        self._add("coarse_grain", keys)
        return self

    def clump(self, name, members, **keys):
        """One [[clump]] template: name, members (rows of x, y, z, radius in m, in the template's
        frame, or the name of a member CSV file), mass (kg) and inertia [I1, I2, I3] (kg m^2)
        overrides. particles(file=..., clump=name) reads its bodies from a body CSV."""
        if not isinstance(members, str):
            members = numbers("members", members, (-1, 4), reshape=True).tolist()
        self._add("clump", dict(name=name, members=members, **keys))
        return self

    def particles(self, position=None, radius=None, *, file=None, generate=None, material=None, fixed=None,
                  velocity=None, angular_velocity=None, id=None, temperature=None, charge=None, density=None,
                  **keys):
        """One [[particles]] source: a CSV `file`, a `generate` table, or arrays: position (N, 3)
        m, radius (N,) m, and optionally velocity, angular_velocity (N, 3), id, temperature,
        charge, density (N,), material (a name for all, or N names or indices), fixed (N,) 0/1."""
        arrays = None
        if position is not None:
            if file is not None or generate is not None:
                raise ValueError("particles: give arrays, a file or generate, not several")
            x = numbers("position", position, (-1, 3), reshape=True)
            n = len(x)
            arrays = {"position": x, "radius": numbers("radius", radius, (n,))}
            for name, a, shape in (("velocity", velocity, (n, 3)), ("angular_velocity", angular_velocity, (n, 3)),
                                   ("temperature", temperature, (n,)), ("charge", charge, (n,)),
                                   ("density", density, (n,))):
                if a is not None:
                    arrays[name] = numbers(name, a, shape)
            if id is not None:
                arrays["id"] = numbers("id", id, (n,), whole=True, reshape=True)
            if fixed is not None and not isinstance(fixed, bool):
                arrays["fixed"] = numbers("fixed", fixed, (n,), whole=True)
                fixed = None
            if material is not None and not isinstance(material, str):
                arrays["material"] = np.asarray(material).reshape(n)
                material = None
        elif radius is not None:
            raise ValueError("particles: radius without position")
        entry = dict(file=file, generate=generate, material=material, fixed=fixed, **keys)
        k = self._add("particles", entry)
        if arrays is not None:
            self._arrays["particles"][k] = arrays
        return self

    def barriers(self, vertices=None, *, file=None, stl=None, id=None, **keys):
        """One [[barriers]] source: a barrier CSV `file`, an `stl` file, or `vertices` (M, 3, 3) m
        of M triangles (counter-clockwise seen from the side the normal points to), with the
        entry's keys (group, material, motion, thickness, temperature, ...)."""
        tri = None
        if vertices is not None:
            if file is not None or stl is not None:
                raise ValueError("barriers: give vertices, a file or an stl, not several")
            tri = {"vertices": numbers("vertices", vertices, (-1, 3, 3), reshape=True)}
            if id is not None:
                tri["id"] = numbers("id", id, (len(tri["vertices"]),), whole=True, reshape=True)
        entry = dict(file=file, stl=stl, **keys)
        k = self._add("barriers", entry)
        if tri is not None:
            self._arrays["barriers"][k] = tri
        return self


def input_error(message, key, file="", line=0):
    """An mpdem.InputError (a ValueError) with the attributes the engine's carry."""
    err = _core.InputError(message)
    err.file, err.line, err.key = file, line, key
    return err


def integers(key, values):
    """`values` as an int64 array; a value that is not a whole number (1.5, nan, "a") is refused
    (InputError naming `key`), not truncated."""
    a = np.asarray(values)
    if a.dtype.kind in "iub":
        return a.astype(np.int64)
    try:
        f = np.asarray(a, dtype=float)
        whole = np.isfinite(f) & (f == np.floor(f)) & (np.abs(f) < 2.0**63)
    except (TypeError, ValueError):
        f, whole = a, np.zeros(a.shape, dtype=bool)
    if not np.all(whole):
        bad = f[~whole].reshape(-1)[0] if f.ndim else f
        raise input_error(f"'{key}': expected whole numbers, got {bad!r}", key)
    return f.astype(np.int64)


def numbers(key, value, shape, whole=False, reshape=False):
    """`value` as an array of `shape`: floats (whole: int64, see integers()), one value or row
    broadcast to all (reshape: reshaped instead, e.g. a flat list of 3 N coordinates; a -1 in
    `shape` takes the rows the values make; None: any shape). An InputError naming `key` when the
    values are not numbers or do not fit the shape."""
    if whole:
        a = integers(key, value)
    else:
        try:
            a = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise input_error(f"'{key}': expected numbers, got {type(value).__name__} {value!r:.80}", key) from None
    if shape is None:  # the callee checks the shape
        return a
    try:
        return a.reshape(shape) if reshape else np.broadcast_to(a, shape)
    except ValueError:
        want = "(" + ", ".join("N" if d == -1 else str(d) for d in shape) + ("," if len(shape) == 1 else "") + ")"
        raise input_error(f"'{key}': expected an array of shape {want}, got one of shape {a.shape}", key) from None


def _array_source_error(e, scene_name, table, entry):
    """The InputError `e`, raised in the CSV file of array source `entry` of `table`, as one naming
    that source and its row: "particles entry 2, row 0: 'radius': ..." (row k is line k + 2 of
    the file: the header comes first)."""
    line = int(e.line)
    prefix = f"{e.file}:{line}: " if line > 0 else f"{e.file}: "
    what = str(e)[len(prefix):] if str(e).startswith(prefix) else str(e)
    row = line - 2 if line >= 2 else None
    place = f"{table} entry {entry}" + (f", row {row}" if row is not None else "")
    err = input_error(f"{scene_name}: {place}: {what}", e.key, file=scene_name)
    err.entry, err.row = (table, entry), row
    return err


def _write_particle_csv(path, arrays):
    cols, data = [], []
    for name, names in _PARTICLE_COLUMNS:
        if name not in arrays:
            continue
        a = np.asarray(arrays[name])
        cols.extend(names)
        data.extend([a[:, c] for c in range(a.shape[1])] if a.ndim == 2 else [a])
    with open(path, "w") as f:
        f.write(",".join(cols) + "\n")
        for row in zip(*data):
            f.write(",".join(_csv_field(v.item() if hasattr(v, "item") else v) for v in row) + "\n")


def _write_barrier_csv(path, arrays):
    v = arrays["vertices"]
    cols = (["id"] if "id" in arrays else []) + ["x1", "y1", "z1", "x2", "y2", "z2", "x3", "y3", "z3"]
    with open(path, "w") as f:
        f.write(",".join(cols) + "\n")
        for k in range(len(v)):
            row = ([str(int(arrays["id"][k]))] if "id" in arrays else []) + [repr(float(x)) for x in v[k].reshape(9)]
            f.write(",".join(row) + "\n")


def _scene_of(scene):
    """A Scene for a Scene or a path to a TOML file."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_toml(scene)
    raise TypeError(f"expected an mpdem.Scene or a path to a scene file, got {type(scene).__name__}")
