#!/usr/bin/python3
"""Independent read-back of mpdem's particle snapshots on several ranks, used by
tests/parallel/mpi_pvtu_output.cpp (docs/output.md, "Particle snapshots on several ranks").

    check_pvtu.py RANKS/particles.pvd ONE/particles.pvd

For every snapshot the two .pvd list (the same count, the same times): reads the snapshot of the
run on several ranks - a .pvtu (parsed with xml.etree; meshio 5 has no .pvtu reader): each of its
<Piece Source=...> read with meshio (xml.etree for an empty piece, which meshio 5 cannot read); or
a .vtu (one rank) - and the one-rank .vtu with meshio, and compares them by id: the same ids, no
id in two pieces, ids ascending within a piece, the pieces' arrays the ones the .pvtu declares,
every point array and the points equal to 1e-10 of the array's largest magnitude (integer arrays
exactly), the same TimeValue. Prints one line per snapshot; exits 1 naming the first mismatch.

Run with /usr/bin/python3 (the interpreter that has meshio and numpy).
"""
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

RELATIVE = 1e-10  # the rank-count round-off of docs/parallel.md is below this for the test's run


def fail(message):
    print(f"check_pvtu: {message}")
    sys.exit(1)


def pvd_entries(path):
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.attrib.get("type") != "Collection":
        fail(f"{path}: not a VTK Collection")
    folder = os.path.dirname(path)
    return [(float(d.attrib["timestep"]), os.path.join(folder, d.attrib["file"])) for d in root.iter("DataSet")]


def declared(element):
    """(name, type, components) of each DataArray / PDataArray child, in order."""
    return [(a.attrib["Name"], a.attrib["type"], int(a.attrib.get("NumberOfComponents", "1"))) for a in element]


def read_piece(path):
    """{name: 2-d array} of the points ("Points") and point arrays, the time, the declared arrays."""
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    arrays = declared(piece.find("PointData")) + declared(piece.find("Points"))
    n = int(piece.attrib["NumberOfPoints"])
    time = float(root.find("UnstructuredGrid/FieldData/DataArray").text)
    if n == 0:
        data = {name: np.zeros((0, comps)) for name, _, comps in arrays}
        return data, time, arrays
    mesh = meshio.read(path)
    data = {name: np.asarray(a).reshape(n, -1) for name, a in mesh.point_data.items()}
    data["Points"] = np.asarray(mesh.points).reshape(n, -1)
    if float(np.asarray(mesh.field_data["TimeValue"]).ravel()[0]) != time:
        fail(f"{path}: meshio's TimeValue differs from the file's")
    return data, time, arrays


def read_snapshot(path):
    """The union of the pieces (a .pvtu) or the one file (a .vtu): ({name: array} by row, time, pieces)."""
    if not path.endswith(".pvtu"):
        data, time, _ = read_piece(path)
        return data, time, 1
    root = ET.parse(path).getroot()
    grid = root.find("PUnstructuredGrid")
    if root.attrib.get("type") != "PUnstructuredGrid" or grid is None:
        fail(f"{path}: not a PUnstructuredGrid")
    promised = declared(grid.find("PPointData")) + declared(grid.find("PPoints"))
    sources = [p.attrib["Source"] for p in grid.findall("Piece")]
    if not sources:
        fail(f"{path}: no pieces")
    parts, times = [], set()
    for source in sources:
        piece = os.path.join(os.path.dirname(path), source)
        data, time, arrays = read_piece(piece)
        if arrays != promised:
            fail(f"{piece}: arrays {arrays} differ from the .pvtu's {promised}")
        ids = data["id"].ravel()
        if np.any(np.diff(ids) <= 0):
            fail(f"{piece}: ids not ascending")
        parts.append(data)
        times.add(time)
    if len(times) != 1:
        fail(f"{path}: pieces of different times {sorted(times)}")
    union = {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}
    return union, times.pop(), len(sources)


def compare(path, one_path):
    many, t_many, pieces = read_snapshot(path)
    one, t_one, _ = read_snapshot(one_path)
    if t_many != t_one:
        fail(f"{path}: TimeValue {t_many!r}, one rank {t_one!r}")
    ids_many, ids_one = many["id"].ravel(), one["id"].ravel()
    if len(np.unique(ids_many)) != len(ids_many):
        fail(f"{path}: an id in two pieces")
    if sorted(ids_many) != sorted(ids_one):
        fail(f"{path}: ids differ from the one-rank snapshot's ({len(ids_many)} vs {len(ids_one)})")
    if sorted(many) != sorted(one):
        fail(f"{path}: arrays {sorted(many)} vs {sorted(one)}")
    order_many, order_one = np.argsort(ids_many), np.argsort(ids_one)
    worst = 0.0
    for name in sorted(one):
        a, b = many[name][order_many], one[name][order_one]
        if a.shape != b.shape:
            fail(f"{path}: {name} has shape {a.shape}, one rank {b.shape}")
        if np.issubdtype(b.dtype, np.integer):
            if not np.array_equal(a, b):
                fail(f"{path}: {name} differs")
            continue
        scale = float(np.max(np.abs(b))) if b.size else 0.0
        deviation = float(np.max(np.abs(a - b))) if b.size else 0.0
        if deviation > RELATIVE * scale:
            fail(f"{path}: {name} deviates by {deviation:.3e} (largest magnitude {scale:.3e})")
        if scale > 0.0:
            worst = max(worst, deviation / scale)
    print(f"{os.path.basename(path)}: {pieces} piece(s), {len(ids_many)} particles, t = {t_many!r}, "
          f"largest relative deviation {worst:.2e}")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: check_pvtu.py RANKS/particles.pvd ONE/particles.pvd")
    many, one = pvd_entries(sys.argv[1]), pvd_entries(sys.argv[2])
    if not many or [t for t, _ in many] != [t for t, _ in one]:
        fail(f"the .pvd list different times: {[t for t, _ in many]} vs {[t for t, _ in one]}")
    for (_, path), (_, one_path) in zip(many, one):
        compare(path, one_path)
    print(f"check_pvtu: {len(many)} snapshots match")


if __name__ == "__main__":
    main()
