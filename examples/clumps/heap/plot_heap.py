"""Plot and tabulate the heap example (examples/clumps/heap): the angle of repose of tetrahedral
clumps and of spheres of the same volume (heap_angle.py), side views of the heaps with the fitted
surfaces, and the kinetic energy of each run (log.csv).

Usage: /usr/bin/python3 plot_heap.py R_DISK TIMES_FILE RUN_DIR:LABEL ...   (writes heap.png, prints results)
"""

import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from heap_angle import FIT_HI, FIT_LO, N_SECTORS, measure


def log_columns(run_dir, names):
    with open(f"{run_dir}/log.csv") as f:
        rows = list(csv.DictReader(f))
    return [np.array([float(r[n]) for r in rows]) for n in names]


def main():
    r_disk = float(sys.argv[1])
    times = dict(line.split(":", 1) for line in open(sys.argv[2]).read().split("\n") if ":" in line)
    runs = [a.split(":") for a in sys.argv[3:]]
    fig, axes = plt.subplots(1, len(runs) + 1, figsize=(5 * (len(runs) + 1), 4.2))
    lines = [f"heap on a rough disk of radius {r_disk * 1e3:.0f} mm (fixed spheres), cylinder lifted; "
             f"angle: {N_SECTORS} sectors, line fit of the top profile over {FIT_LO:.1f}-{FIT_HI:.1f} R_disk",
             "",
             "| grains | bodies on the disk | angle of repose (deg) | sector angles (deg) | apex angle (deg) | "
             "speed on the disk at the end, mean / max (m/s) | wall time (s) |",
             "|---|---|---|---|---|---|---|"]
    angles = {}
    for ax, (run_dir, label) in zip(axes, runs):
        m = measure(run_dir, r_disk)
        angles[label] = m
        pts = np.array(m["points"])
        ax.scatter(pts[:, 0] * 1e3, pts[:, 2] * 1e3, s=2, c="0.6", label="particle tops (all azimuths)")
        x = np.array([FIT_LO, FIT_HI]) * r_disk
        for k, (s, c) in enumerate(m["fits"]):
            ax.plot(x * 1e3, (s * x + c) * 1e3, "r-", lw=0.8, label="sector fits" if k == 0 else None)
        ax.axvline(r_disk * 1e3, color="k", ls=":", lw=1)
        ax.set_xlim(0, r_disk * 1.1e3)
        ax.set_ylim(-2, r_disk * 1.05e3)
        ax.set_aspect("equal")
        ax.set_xlabel("distance from the axis [mm]")
        ax.set_ylabel("height [mm]")
        ax.set_title(f"{label}: {m['angle']:.1f} ± {m['err']:.1f}°")
        ax.legend(loc="upper right", fontsize=7)
        t, ke, kr = log_columns(run_dir, ["time", "kinetic", "rotational"])
        axes[-1].semilogy(t, ke + kr, label=label)
        lines.append(f"| {label} | {m['bodies_on_disk']} | {m['angle']:.1f} ± {m['err']:.1f} | "
                     + " ".join(f"{a:.1f}" for a in m["sectors"])
                     + f" | {m['apex_angle']:.1f} | {m['mean_speed']:.1e} / {m['max_speed']:.1e} | "
                     f"{times.get(label, '?').strip()} |")
    axes[-1].set_xlabel("time [s]")
    axes[-1].set_ylabel("kinetic + rotational energy [J]")
    axes[-1].set_title("settling, lift, slump, rest")
    axes[-1].legend()
    fig.tight_layout()
    fig.savefig("heap.png", dpi=110)
    labels = list(angles)
    if len(labels) == 2:
        a, b = angles[labels[0]], angles[labels[1]]
        lines += ["", f"difference {labels[0]} - {labels[1]}: {a['angle'] - b['angle']:.1f} ± "
                  f"{math.hypot(a['err'], b['err']):.1f} deg"]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
