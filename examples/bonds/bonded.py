"""What the bond examples share: the mpdem program (for `mpdem agglomerate` and `mpdem mesh`), a
bonded agglomerate read back from its two CSV files, and the fragments that the intact bonds hold
together (a union-find over the bonds)."""

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np

import mpdem


def mpdem_program():
    """The mpdem executable: $MPDEM_BINARY, else the one built beside the Python module
    (build/mpdem for PYTHONPATH=build/python), else `mpdem` on PATH."""
    if os.environ.get("MPDEM_BINARY"):
        return os.environ["MPDEM_BINARY"]
    built = Path(mpdem.__file__).resolve().parents[2] / "mpdem"
    if built.is_file():
        return str(built)
    found = shutil.which("mpdem")
    if found is None:
        raise SystemExit("the mpdem program was not found: set MPDEM_BINARY or put it on PATH")
    return found


def run_tool(*args):
    """Runs `mpdem ARGS...` and returns its standard output (raises on a non-zero exit)."""
    done = subprocess.run([mpdem_program(), *map(str, args)], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"mpdem {' '.join(map(str, args))} failed:\n{done.stderr}")
    return done.stdout


def agglomerate(prefix, *options):
    """`mpdem agglomerate -o PREFIX OPTIONS... --overwrite` read back: (ids (n,) int64, centres
    (n, 3) m, radii (n,) m, bond file path, the command's report)."""
    report = run_tool("agglomerate", "-o", prefix, *options, "--overwrite")
    data = np.loadtxt(f"{prefix}_particles.csv", delimiter=",", comments="#", skiprows=2, ndmin=2)
    return data[:, 0].astype(np.int64), data[:, 1:4], data[:, 4], Path(f"{prefix}_bonds.csv").resolve(), report


def fragments(ids, id_i, id_j, intact):
    """Fragments held together by the intact bonds: the label of each particle of `ids` (n,)
    (0 for the largest fragment, 1 for the next, ...; ties by the smallest id) and the fragment
    sizes in particles, largest first."""
    index = {int(k): n for n, k in enumerate(ids)}
    parent = np.arange(len(ids))

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b, on in zip(id_i, id_j, intact):
        if on:
            ra, rb = root(index[int(a)]), root(index[int(b)])
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([root(a) for a in range(len(ids))])
    uniq, inverse, counts = np.unique(roots, return_inverse=True, return_counts=True)
    order = np.lexsort((uniq, -counts))  # largest first, then by the root (the smallest index)
    rank = np.empty(len(uniq), dtype=np.int64)
    rank[order] = np.arange(len(uniq))
    return rank[inverse], counts[order]
