"""What the bond examples share: the mpdem program (for `mpdem agglomerate` and `mpdem mesh`), a
bonded agglomerate read back from its two CSV files, the fragments that the intact bonds hold
together (a union-find over the bonds), and pictures of spheres without ParaView."""

import os
import shutil
import subprocess
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import EllipseCollection

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
    (n, 3) m, radii (n,) m, bond file path, the command's report without the files' folder)."""
    report = run_tool("agglomerate", "-o", prefix, *options, "--overwrite")
    report = "\n".join(line for line in report.splitlines() if not line.startswith("->"))
    report = report.replace(str(Path(prefix).parent) + os.sep, "")
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


def draw_view(ax, x, r, colour, title, top=False):
    """Spheres seen along +y (x right, z up; the far ones first) or from above (x right, y up)."""
    depth, plane = (x[:, 2], [0, 1]) if top else (-x[:, 1], [0, 2])
    order = np.argsort(depth)
    ax.add_collection(EllipseCollection(2e3 * r[order], 2e3 * r[order], np.zeros(len(r)), units="xy",
                                        offsets=1e3 * x[order][:, plane], offset_transform=ax.transData,
                                        facecolors=np.asarray(colour)[order], edgecolors="k", linewidths=0.2))
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]" if top else "z [mm]")
    ax.set_title(title, fontsize=9)


def fragment_colours(labels):
    """The 9 largest fragments in colours, smaller pieces light grey, single spheres dark grey."""
    cycle = plt.get_cmap("tab10").colors
    sizes = np.bincount(labels)
    return [cycle[k] if k < 9 and sizes[k] > 1 else ((0.8, 0.8, 0.8) if sizes[k] > 1 else (0.4, 0.4, 0.4))
            for k in labels]
