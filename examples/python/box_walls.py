"""Triangles of an open-topped box (floor and four walls) for the examples, normals inward."""

import numpy as np


def quad(a, b, c, d):
    """Two triangles of the quadrilateral a-b-c-d (counter-clockwise seen from the normal side)."""
    return [[a, b, c], [a, c, d]]


def open_box(lo, hi):
    """(10, 3, 3) m: floor z = lo[2] and walls x = lo/hi[0], y = lo/hi[1] up to hi[2]."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    tri = []
    tri += quad((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0))  # floor, normal +z
    tri += quad((x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1))  # x = x0, normal +x
    tri += quad((x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0))  # x = x1, normal -x
    tri += quad((x0, y0, z0), (x0, y0, z1), (x1, y0, z1), (x1, y0, z0))  # y = y0, normal +y
    tri += quad((x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1))  # y = y1, normal -y
    return np.array(tri, dtype=float)
