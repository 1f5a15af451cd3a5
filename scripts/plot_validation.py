#!/usr/bin/python3
"""Draws the plots of `mpdem validate`: one PNG per CSV written by a validation case.

    /usr/bin/python3 scripts/plot_validation.py OUTPUT_DIR STEM [STEM ...]

reads OUTPUT_DIR/STEM.csv and writes OUTPUT_DIR/STEM.png. CSV format (src/validate/plot_csv.hpp):
'#' lines give title, xlabel, ylabel, xscale, yscale; the header names the x column, then
"<series> simulated" columns, each optionally followed by "<series> <kind>" (kind: analytic, or
the reference used); '# hline: y label' adds a dashed line. Simulated values are drawn as
markers, the analytic/reference curve as a line of the same colour, so the two stay
distinguishable where they coincide.
"""
import csv
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

MAX_MARKERS = 60  # per series: enough to see the shape, few enough to see the line beneath


def read(path):
    meta, lines = {"hline": []}, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                key, _, value = line[1:].partition(":")
                if key.strip() == "hline":
                    y, _, label = value.strip().partition(" ")
                    meta["hline"].append((float(y), label))
                else:
                    meta[key.strip()] = value.strip()
            elif line.strip():
                lines.append(line)
    rows = list(csv.reader(lines))
    header, data = rows[0], rows[1:]
    cols = [[float(r[k]) if k < len(r) and r[k] != "" else math.nan for r in data] for k in range(len(header))]
    return meta, header, cols


def plot(out_dir, stem):
    meta, header, cols = read(os.path.join(out_dir, stem + ".csv"))
    x = cols[0]
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    k = 1
    while k < len(header):
        name = header[k]
        if not name.endswith(" simulated"):
            k += 1
            continue
        label = name[: -len(" simulated")]
        y = cols[k]
        pts = [(a, b) for a, b in zip(x, y) if not math.isnan(b)]
        every = max(1, len(pts) // MAX_MARKERS)
        ref = None
        if k + 1 < len(header) and header[k + 1].startswith(label + " ") and not header[k + 1].endswith(" simulated"):
            ref = (header[k + 1][len(label) + 1:], cols[k + 1])
        color = None
        if ref is not None:
            line, = ax.plot(x, ref[1], "-", lw=1.3, label=f"{label} ({ref[0]})", zorder=2)
            color = line.get_color()
            k += 1
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=4, mfc="none", mew=1.0, color=color,
                markevery=every, label=f"{label} (mpdem)", zorder=3)
        k += 1
    for y, label in meta["hline"]:
        ax.axhline(y, color="grey", ls="--", lw=1.0, label=label)
    ax.set_xscale(meta.get("xscale", "linear"))
    ax.set_yscale(meta.get("yscale", "linear"))
    ax.set_xlabel(meta.get("xlabel", header[0]))
    ax.set_ylabel(meta.get("ylabel", ""))
    ax.set_title(meta.get("title", stem), fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, stem + ".png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    for stem in sys.argv[2:]:
        plot(sys.argv[1], stem)


if __name__ == "__main__":
    main()
