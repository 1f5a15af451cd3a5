"""Case study 2: plate forces of a rock falling on granular layers (run by run.sh).

Reads output/<variant>/barrier_groups.csv (force of the particles on each barrier group, N) and
the particle CSV snapshots, writes plate_forces.png, plate_forces_zoom.png, peak_forces.png and
prints the table quoted in README.md.
"""
import glob
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
VARIANTS = [("bare", "bare plate", "k"),
            ("thin", "thin layer", "tab:blue"),
            ("thick", "thick layer", "tab:green"),
            ("thick_frictionless", "thick layer, no grain friction", "tab:red")]
G = 9.81  # m/s^2


def read(variant):
    d = np.genfromtxt(os.path.join(HERE, "output", variant, "barrier_groups.csv"), delimiter=",", names=True)
    t = d["time"]                                   # s
    fz = -d["platefz"]                              # N, downward push of the particles on the plate
    ft = np.hypot(d["platefx"], d["platefy"])       # N, tangential (horizontal) force magnitude
    fx = d["platefx"]                               # N, along the rock's horizontal motion
    return t, fz, ft, fx


def snapshots(variant):
    for f in sorted(glob.glob(os.path.join(HERE, "output", variant, "particles_csv", "*.csv"))):
        yield np.atleast_1d(np.genfromtxt(f, delimiter=",", names=True))


def snapshot_before(variant, t_before):
    best = None
    for d in snapshots(variant):
        if d["time"][0] <= t_before:
            best = d
    return best


def main():
    rows = []
    series = {}
    for key, label, colour in VARIANTS:
        t, fz, ft, fx = read(key)
        series[key] = (t, fz, ft, fx)
        snap = snapshot_before(key, 0.13)
        grains = snap["radius"] < 0.01
        mass = (4.0 / 3.0 * np.pi * snap["radius"] ** 3 * 2500.0)
        weight = mass[grains].sum() * G               # N, layer weight
        if grains.any():
            top = np.percentile(snap["z"][grains] + snap["radius"][grains], 95)   # m
            vmean = np.sqrt(snap["vx"] ** 2 + snap["vy"] ** 2 + snap["vz"] ** 2)[grains].mean()
        else:
            top, vmean = 0.0, 0.0
        static = np.median(fz[(t > 0.13) & (t < 0.14)])  # N, plate load just before the impact
        i = np.argmax(fz)
        # lowest point of the rock above the plate (m): did it reach the plate through the layer?
        gap = min(np.atleast_1d(d["z"])[np.atleast_1d(d["radius"]) > 0.01][0] - 0.025
                  for d in snapshots(key) if d["time"][0] > 0.15)
        if top > 0:
            label = f"{label} ({top * 1e3:.0f} mm)"
        rows.append((key, label, colour, top, vmean, weight, static, fz[i], t[i], fz[i] - static, ft.max(), gap))
    bare_peak = rows[0][7]
    print("variant                         layer(mm) grain|v|(m/s) W_layer(N) F_before(N) peak Fz(N) t_peak(s) "
          "peak-F_before(N) reduction peak Ft(N) rock gap(mm)")
    print("(rock gap: lowest rock bottom above the plate in the 10 ms snapshots after t = 0.15 s)")
    for (key, label, colour, top, vmean, w, st, pk, tp, dyn, ftm, imp) in rows:
        print(f"{label:31s} {top*1e3:8.1f} {vmean:12.3g} {w:10.3f} {st:11.3f} {pk:10.1f} {tp:9.4f} "
              f"{dyn:16.1f} {100*(1-pk/bare_peak):8.1f}% {ftm:9.1f} {'-' if key == 'bare' else f'{imp*1e3:.1f}':>11s}")
    # bare-plate check: free fall from 0.13 m, restitution 0.5 -> impulse m (1 + e) v; elastic Hertz peak
    t, fz = series["bare"][0], series["bare"][1]
    impulse = np.sum(fz) * (t[1] - t[0])            # N s, the bare plate sees only the rock's bounce
    m_rock, r_rock, e_star = 4.0 / 3.0 * np.pi * 0.025 ** 3 * 2500.0, 0.025, 1e8 / (2 * (1 - 0.3 ** 2))
    v_in = np.sqrt(2 * G * 0.13)
    d_max = (15 * m_rock * v_in ** 2 / (16 * e_star * np.sqrt(r_rock))) ** 0.4
    print(f"bare plate: impact speed {v_in:.3f} m/s at t = {np.sqrt(2 * 0.13 / G):.4f} s; expected impulse "
          f"m (1 + e) v = {m_rock * 1.5 * v_in:.3f} N s, simulated {impulse:.3f} N s; undamped Hertz peak 4/3 E* sqrt(R) d^1.5 = "
          f"{4 / 3 * e_star * np.sqrt(r_rock) * d_max ** 1.5:.1f} N (the damped peak is lower)")

    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for (key, label, colour, *_rest) in rows:
        t, fz, ft, fx = series[key]
        ax[0].plot(t, fz, color=colour, label=label, lw=1)
        ax[1].plot(t, fx, color=colour, label=label, lw=1)
    ax[0].set_ylabel("vertical force on plate $-F_z$ (N)")
    ax[1].set_ylabel("tangential force on plate $F_x$ (N)")
    ax[1].set_xlabel("time t (s)")
    ax[0].set_title("Rock (R = 25 mm) falling 0.13 m onto the plate")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "plate_forces.png"), dpi=110)

    # zoom on the impacts, log scale for the vertical force (bare-plate peak is much larger)
    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for (key, label, colour, *_rest) in rows:
        t, fz, ft, fx = series[key]
        sel = (t > 0.14) & (t < 0.2)
        ax[0].plot(t[sel], fz[sel], color=colour, label=label, lw=1)
        ax[1].plot(t[sel], ft[sel], color=colour, label=label, lw=1)
    ax[0].set_ylabel("vertical force on plate $-F_z$ (N)")
    ax[1].set_ylabel(r"tangential force $\sqrt{F_x^2+F_y^2}$ (N)")
    ax[1].set_xlabel("time t (s)")
    ax[0].set_title("Impact phase (plate loads sampled every 0.1 ms)")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "plate_forces_zoom.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    labels = [r[1].replace(", ", ",\n").replace(" (", "\n(") for r in rows]
    ax.bar(range(len(rows)), [r[7] for r in rows], color=[r[2] for r in rows], label="peak $-F_z$")
    ax.bar(range(len(rows)), [r[6] for r in rows], color="0.6", width=0.4, label="layer load before impact")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels(labels, fontsize=8)
    for k, r in enumerate(rows):
        ax.text(k, r[7] * 1.08, f"{r[7]:.0f} N" + ("" if k == 0 else f"\n-{100 * (1 - r[7] / bare_peak):.0f} %"),
                ha="center", va="bottom", fontsize=8)
    ax.set_ylim(1, bare_peak * 4)
    ax.set_yscale("log")
    ax.set_ylabel("vertical plate force (N)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y", which="both")
    ax.set_title("Peak vertical force on the plate")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "peak_forces.png"), dpi=110)


if __name__ == "__main__":
    main()
