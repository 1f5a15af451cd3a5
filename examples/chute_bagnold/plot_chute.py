"""Periodic chute (examples/chute_bagnold): steady state, velocity profile and Bagnold fit.
Run by run.sh after the run; reads

    output/particles_csv/particles_*.csv    snapshots (time, id, x, y, z, vx, ..., fixed, ...)
    output/log.csv                          global log (kinetic energy per row)

and writes chute_profile.png (v_x(z), the fit and the 1.5 law), chute_steady.png (mean velocity
and kinetic energy against time) and prints results.txt (run.sh tees it).

Reduced units: d = 1 mm (mean diameter), tau = sqrt(d/g), velocities in sqrt(g d). Heights z are
measured from the base plane z_b = mean top of the base spheres (mean centre height + d/2).

Fit: v(z) = A [h^a - (h - z)^a] (v in sqrt(g d), z and h in d) over the slabs more than 2 d above
the base and more than 2 d below the free surface (h_s, where the volume fraction falls to half
its bulk value): for each (a, h) the best A is linear (closed form), (a, h) by a grid search
refined twice. The same with a = 1.5 fixed gives the Bagnold curve to compare with. A check
variant v(z) = v_s - B (h - z)^a (free slip: the base level does not enter) is printed too. The
scatter of a comes from fitting four consecutive blocks of the averaging window separately.
"""
import csv
import glob
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "output")
D = 1.0e-3                                 # m, mean diameter
G = 9.81                                   # m/s^2
THETA = 24.0                               # deg (scene.toml gravity)
TAU = math.sqrt(D / G)                     # s
VU = math.sqrt(G * D)                      # m/s
LX, LY = 0.0105, 0.010911920087683926      # m, the periods (scene.toml [domain])
SLAB = 1.0                                 # d, slab thickness
EXCLUDE = 2.0                              # d, left out of the fit at the base and at the surface
STEADY_TOL = 0.02                          # relative drift of the mean velocity over the window


def read_snapshot(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    col = {name: k for k, name in enumerate(head)}
    a = np.array([[float(v) for v in r] for r in rows[1:] if r], dtype=float)
    return a, col


def load_snapshots():
    files = sorted(glob.glob(os.path.join(OUT, "particles_csv", "particles_*.csv")))
    if not files:
        sys.exit("no snapshots in %s: run run.sh first" % OUT)
    snaps = []
    for f in files:
        a, col = read_snapshot(f)
        snaps.append((a[0, col["time"]], a, col))
    return snaps


def drift(t, v):
    """Relative change of a linear fit of v(t) over the window: slope * span / mean."""
    p = np.polyfit(t, v, 1)
    return p[0] * (t[-1] - t[0]) / np.mean(v)


def profile(snaps, z_base):
    """Slab means of v_x (free particles) and volume fraction (centres binned), reduced units."""
    zmax = 45.0
    nb = int(zmax / SLAB)
    sv = np.zeros(nb)
    sn = np.zeros(nb)
    svol = np.zeros(nb)
    for _, a, col in snaps:
        free = a[:, col["fixed"]] == 0
        z = (a[free, col["z"]] - z_base) / D
        k = np.floor(z / SLAB).astype(int)
        ok = (k >= 0) & (k < nb)
        np.add.at(sv, k[ok], a[free, col["vx"]][ok] / VU)
        np.add.at(sn, k[ok], 1.0)
        np.add.at(svol, k[ok], 4.0 / 3.0 * math.pi * a[free, col["radius"]][ok] ** 3)
    zc = (np.arange(nb) + 0.5) * SLAB
    with np.errstate(invalid="ignore", divide="ignore"):
        v = sv / sn
    phi = svol / (len(snaps) * LX * LY * SLAB * D)
    return zc, v, sn / len(snaps), phi


def best_A(z, v, a, h):
    f = h ** a - (h - z) ** a
    A = np.dot(v, f) / np.dot(f, f)
    r = v - A * f
    return A, float(np.sqrt(np.mean(r * r)))


def fit(z, v, a_fixed=None):
    """Least squares of v = A [h^a - (h - z)^a]: grid over (a, h), refined; A in closed form."""
    a_lo, a_hi = (a_fixed, a_fixed) if a_fixed is not None else (0.5, 6.0)
    h_lo, h_hi = z.max() + 1e-3, z.max() + 40.0
    best = None
    for _ in range(3):
        a_grid = np.linspace(a_lo, a_hi, 1 if a_fixed is not None else 221)
        h_grid = np.linspace(h_lo, h_hi, 201)
        for a in a_grid:
            for h in h_grid:
                A, res = best_A(z, v, a, h)
                if best is None or res < best[3]:
                    best = (a, A, h, res)
        a, _, h, _ = best
        da = (a_hi - a_lo) / 20.0
        dh = (h_hi - h_lo) / 20.0
        a_lo, a_hi = (a_fixed, a_fixed) if a_fixed is not None else (max(0.5, a - da), a + da)
        h_lo, h_hi = max(z.max() + 1e-3, h - dh), h + dh
    return best


def fit_free_slip(z, v):
    """v = v_s - B (h - z)^a: for each (a, h), v_s and B by linear least squares."""
    best = None
    a_lo, a_hi, h_lo, h_hi = 0.5, 6.0, z.max() + 1e-3, z.max() + 40.0
    for _ in range(3):
        for a in np.linspace(a_lo, a_hi, 221):
            for h in np.linspace(h_lo, h_hi, 201):
                M = np.column_stack([np.ones_like(z), -(h - z) ** a])
                c, *_ = np.linalg.lstsq(M, v, rcond=None)
                r = v - M @ c
                res = float(np.sqrt(np.mean(r * r)))
                if best is None or res < best[4]:
                    best = (a, c[0], c[1], h, res)
        a, _, _, h, _ = best
        da, dh = (a_hi - a_lo) / 20.0, (h_hi - h_lo) / 20.0
        a_lo, a_hi = max(0.5, a - da), a + da
        h_lo, h_hi = max(z.max() + 1e-3, h - dh), h + dh
    return best


def main():
    snaps = load_snapshots()
    t = np.array([s[0] for s in snaps])
    a0, col0 = snaps[0][1], snaps[0][2]
    base = a0[:, col0["fixed"]] == 1
    z_base = float(np.mean(a0[base, col0["z"]] + a0[base, col0["radius"]]))
    n_free0 = int(np.sum(~base))
    n_base = int(np.sum(base))

    # --- steady state: mean v_x of the free particles against time
    vmean = np.array([np.mean(a[a[:, c["fixed"]] == 0, c["vx"]]) for _, a, c in snaps]) / VU
    nfree = np.array([int(np.sum(a[:, c["fixed"]] == 0)) for _, a, c in snaps])
    # base particles: bitwise the same positions in every snapshot (ids as in the first)
    base_moved = 0
    ref = {int(r[col0["id"]]): (r[col0["x"]], r[col0["y"]], r[col0["z"]]) for r in a0[base]}
    for _, a, c in snaps:
        for r in a[a[:, c["fixed"]] == 1]:
            if ref.get(int(r[c["id"]])) != (r[c["x"]], r[c["y"]], r[c["z"]]):
                base_moved += 1
    # averaging window: the earliest start (on the snapshot grid, at most the last 60 % kept out)
    # from which the mean velocity drifts by less than STEADY_TOL (linear fit over the window)
    start = len(t) // 2
    for k in range(len(t) // 4, len(t) - 10):
        if abs(drift(t[k:], vmean[k:])) < STEADY_TOL:
            start = k
            break
    win = snaps[start:]
    tw = t[start:]
    d_win = drift(tw, vmean[start:])
    # late-window half-against-half comparison
    half = len(tw) // 2
    v1, v2 = np.mean(vmean[start:start + half]), np.mean(vmean[start + half:])

    log = np.genfromtxt(os.path.join(OUT, "log.csv"), delimiter=",", names=True)

    # --- profile over the window
    zc, v, nslab, phi = profile(win, z_base)
    filled = nslab > 0.5
    bulk = float(np.median(phi[(zc > 3.0) & filled][: max(1, int(np.sum((zc > 3.0) & filled)) // 2)]))
    # free surface: first slab above the bulk where phi falls below half the bulk value, linearly
    # interpolated between slab centres
    k = int(np.argmax((zc > 3.0) & (phi < 0.5 * bulk)))
    h_s = float(zc[k - 1] + (phi[k - 1] - 0.5 * bulk) / (phi[k - 1] - phi[k]) * (zc[k] - zc[k - 1]))
    sel = (zc > EXCLUDE) & (zc < h_s - EXCLUDE) & filled
    zf, vf = zc[sel], v[sel]
    a_fit, A_fit, h_fit, res = fit(zf, vf)
    _, A15, h15, res15 = fit(zf, vf, a_fixed=1.5)
    fs = fit_free_slip(zf, vf)
    # diagnostic: the same fit over the upper bulk only (z >= 8 d), above the basal shear layer
    up = sel & (zc >= 8.0)
    a_up, A_up, h_up, res_up = fit(zc[up], v[up])
    # block scatter of a: four consecutive blocks of the window
    blocks = []
    nb = 4
    for b in range(nb):
        part = win[b * len(win) // nb:(b + 1) * len(win) // nb]
        zb_, vb_, nb_, _ = profile(part, z_base)
        ok = sel & (nb_ > 0.5)
        blocks.append(fit(zb_[ok], vb_[ok])[0])
    a_err = float(np.std(blocks, ddof=1) / math.sqrt(nb))
    v_surf = float(np.max(v[filled & (zc < h_s)]))
    in_band = abs(a_fit - 1.5) <= 0.15

    # --- results
    p = print
    p("Periodic chute flow, Bagnold profile (examples/chute_bagnold)")
    p("theta = %.1f deg, periods L_x = %.2f d, L_y = %.2f d, %d base (fixed) + %d free spheres"
      % (THETA, LX / D, LY / D, n_base, n_free0))
    p("reduced units: d = 1 mm, tau = sqrt(d/g) = %.4g s, sqrt(g d) = %.4g m/s; z from the base plane"
      " z_b = %.4g mm (mean top of the base spheres)" % (TAU, VU, z_base * 1e3))
    p("")
    p("steady state: run to t = %.3f s (%.0f tau), %d snapshots every %.3g s"
      % (t[-1], t[-1] / TAU, len(t), t[1] - t[0]))
    p("  mean v_x of the free spheres [sqrt(g d)] at t/tau = " + ", ".join(
        "%.0f: %.3f" % (t[i] / TAU, vmean[i]) for i in range(0, len(t), max(1, len(t) // 10))))
    p("  averaging window t = %.3f .. %.3f s (%.0f .. %.0f tau, %d snapshots): linear drift of the mean"
      " velocity over it %+.2f %% (criterion |drift| < %.0f %%), first half %.4f, second half %.4f sqrt(g d)"
      % (tw[0], tw[-1], tw[0] / TAU, tw[-1] / TAU, len(tw), 100 * d_win, 100 * STEADY_TOL, v1, v2))
    kin = log["kinetic"]
    lt = log["time"]
    p("  kinetic energy (log.csv) at the window start %.4g J, at the end %.4g J" %
      (np.interp(tw[0], lt, kin), kin[-1]))
    p("  free spheres at the end: %d of %d (lost: %d); base spheres whose position changed: %d"
      % (nfree[-1], n_free0, n_free0 - nfree[-1], base_moved))
    p("")
    p("profile over the window (slabs of %.0f d; z = slab centre; phi = volume fraction, centres binned):" % SLAB)
    p("  %6s %10s %10s %8s %6s" % ("z/d", "v_x/sqrt(gd)", "fit", "phi", "fitted"))
    for zz, vv, pp, ok, nn in zip(zc, v, phi, sel, nslab):
        if nn < 0.5:
            continue
        fv = A_fit * (h_fit ** a_fit - max(h_fit - zz, 0.0) ** a_fit)
        p("  %6.1f %10.4f %10.4f %8.3f %6s" % (zz, vv, fv, pp, "yes" if ok else "no"))
    p("  bulk volume fraction %.3f, free surface h_s = %.2f d (phi = half the bulk value)" % (bulk, h_s))
    p("")
    p("fit v(z) = A [h^a - (h - z)^a] over %d slabs, z = %.1f .. %.1f d (excluded: within %.0f d of the"
      " base and of the free surface h_s)" % (len(zf), zf[0], zf[-1], EXCLUDE))
    p("  a = %.3f +- %.3f (scatter of 4 time blocks: %s)" % (a_fit, a_err, ", ".join("%.3f" % x for x in blocks)))
    p("  A = %.5g sqrt(g d) / d^a" % A_fit)
    p("  h = %.2f d" % h_fit)
    p("  residual (RMS over the fitted slabs) = %.4g sqrt(g d) = %.2f %% of the surface velocity %.3f"
      % (res, 100 * res / v_surf, v_surf))
    p("  expected a = 1.5 +- 0.15: %s" % ("yes" if in_band else "NO"))
    p("Bagnold a = 1.5 fixed: A = %.5g, h = %.2f d, residual %.4g sqrt(g d) (Silbert's A_theta = 3/2 A = %.4g)"
      % (A15, h15, res15, 1.5 * A15))
    p("check, free slip v = v_s - B (h - z)^a: a = %.3f, v_s = %.4f, B = %.5g, h = %.2f d, residual %.4g"
      % fs)
    p("diagnostic, the first fit over the upper bulk z = %.1f .. %.1f d only: a = %.3f, A = %.5g, h = %.2f d,"
      " residual %.4g" % (zc[up][0], zc[up][-1], a_up, A_up, h_up, res_up))

    # --- plots
    fig, ax = plt.subplots(1, 2, figsize=(10, 5), gridspec_kw={"width_ratios": [3, 1]}, sharey=True)
    zz = np.linspace(0.0, h_fit, 300)
    ax[0].plot(v[filled & sel], zc[filled & sel], "o", color="C0", label="simulation (fitted slabs)")
    ax[0].plot(v[filled & ~sel], zc[filled & ~sel], "o", mfc="none", color="C0", label="simulation (excluded)")
    ax[0].plot(A_fit * (h_fit ** a_fit - (h_fit - zz) ** a_fit), zz, "-", color="C3",
               label="fit A[h$^a$-(h-z)$^a$], a = %.3f" % a_fit)
    zz15 = np.linspace(0.0, h15, 300)
    ax[0].plot(A15 * (h15 ** 1.5 - (h15 - zz15) ** 1.5), zz15, "--", color="k", label="Bagnold a = 1.5")
    ax[0].axhline(h_s, color="gray", lw=0.8, ls=":")
    ax[0].axhspan(0, EXCLUDE, color="gray", alpha=0.15)
    ax[0].axhspan(h_s - EXCLUDE, h_s, color="gray", alpha=0.15)
    ax[0].set_xlabel("$v_x / \\sqrt{g d}$")
    ax[0].set_ylabel("z / d (above the base)")
    ax[0].set_title("periodic chute, theta = %.0f deg: velocity profile" % THETA)
    ax[0].legend(loc="upper left", fontsize=9)
    ax[1].plot(phi[filled], zc[filled], "s-", ms=3)
    ax[1].axhline(h_s, color="gray", lw=0.8, ls=":")
    ax[1].set_xlabel("volume fraction")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "chute_profile.png"), dpi=120)

    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax[0].plot(t / TAU, vmean, ".-")
    ax[0].axvspan(tw[0] / TAU, tw[-1] / TAU, color="C2", alpha=0.15, label="averaging window")
    ax[0].set_ylabel("mean $v_x / \\sqrt{g d}$")
    ax[0].legend()
    ax[1].plot(lt / TAU, kin * 1e6)
    ax[1].set_ylabel("kinetic energy [uJ]")
    ax[1].set_xlabel("t / tau")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "chute_steady.png"), dpi=120)


if __name__ == "__main__":
    main()
