"""Bodies: the rigid clumps' arrays (docs/python.md, "Bodies")."""

import numpy as np

from . import _core
from .scene import integers, numbers

__all__ = ["Bodies"]


class Bodies:
    """The clumps' rigid bodies (docs/python.md, "Bodies"): one row per body, in ascending body id
    order (a numbering of its own, the body CSV's `id`). Attributes are copies; velocity and
    angular_velocity can be assigned (all bodies, id order) or set(name, values, ids) between
    steps: the members then move with their bodies. A scene without clumps has none (len 0).
    The member spheres are particles (sim.particles) whose `body` is their body's id.
    """

    def __init__(self, core):
        self._core = core

    def __len__(self):
        return self._core.body_count

    @property
    def template(self):
        """(B,) str, the name of each body's clump template"""
        return np.array(self._core.body_get("template"), dtype=str)

    def set(self, name, values, ids=None):
        """Sets `name` (velocity m/s, angular_velocity rad/s, world frame) for the bodies `ids`
        (rows in that order; one row: the same for all), or for every body in id order when ids is
        None; the members' velocities follow (v + w x d) and the rates are evaluated at the new
        state before the next step."""
        ids = None if ids is None else np.atleast_1d(integers("ids", ids))
        n = len(self) if ids is None else len(ids)
        self._core.body_set(name, np.ascontiguousarray(numbers(name, values, (n, 3))), ids)

    def as_dict(self):
        """Every array, id-ordered copies."""
        return {name: getattr(self, name) for name in _core.body_arrays}


def _array_property(name, doc):
    def get(self):
        return self._core.body_get(name)

    def put(self, values):
        self.set(name, values)

    return property(get, put if name in _core.settable_body_arrays else None, doc=doc)


# The engine's body arrays (src/python/body_arrays.cpp): name, shape, unit, settable.
for _name in _core.body_arrays:
    if _name != "template":
        setattr(Bodies, _name, _array_property(_name, _core.body_array_docs[_name]))
