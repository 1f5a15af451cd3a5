"""Periodic chute (examples/chute_bagnold): steady state, velocity profile and Bagnold fit.
Run by run.sh after the run; reads

    output/particles_csv/particles_*.csv    snapshots (time, id, x, y, z, vx, ..., fixed, ...)
    output/log.csv                          global log (kinetic energy per row)
    output/cg_chute.csv                     coarse-grained profile (chute_fields.py)

and writes chute_profile.png (v_x(z) with the fits and the 1.5 law, the shear rate, the volume
fraction), chute_steady.png (mean velocity
and kinetic energy against time), chute_fields.png (velocity, stress and friction coefficient from
the coarse-grained profile, chute_fields.py) and prints results.txt (run.sh tees it).

Reduced units: d = 1 mm (mean diameter), tau = sqrt(d/g), velocities in sqrt(g d). Heights z are
measured from the base plane z_b = mean top of the base spheres (mean centre height + d/2).

Fits, all over the slabs more than 2 d above the base and more than 2 d below the free surface
(h_s, where the volume fraction falls to half its bulk value), v in sqrt(g d), z and h in d:
- the requested form v(z) = A [h^a - (h - z)^a] (v = 0 at the base plane; h free, kept above the
  highest fitted slab; for each (a, h) the best A is linear, (a, h) by a grid search refined
  twice); the same with a = 1.5 fixed gives the Bagnold curve to compare with;
- h pinned to the measured surface, base slip free: v = v_0 + A [h_s^a - (h_s - z)^a];
- free slip, v = v_s - B (h - z)^a (h and v_s free: the base level does not enter);
- the shear rate: dv/dz between neighbouring slabs against h_s - z, ln(dv/dz) = ln B + (a - 1) ln(h_s - z).
The +- of every exponent is the standard error from fitting four consecutive time blocks of the
averaging window separately. Diagnostics: the same fits with thicker excluded layers, and in
consecutive 0.2 s windows (does the profile's shape still change?).
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

import chute_fields

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
TREND_DT = 0.2                             # s, windows of the profile-shape diagnostic


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
    zmax = 70.0
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


def _grid_req(z, v, a_grid, h_grid):
    """RMS residual of v = A [h^a - (h - z)^a] (A in closed form) on an (a, h) grid: best point."""
    best = None
    H = h_grid[:, None]
    for a in a_grid:
        f = H ** a - (H - z[None, :]) ** a
        A = (f @ v) / np.einsum("ij,ij->i", f, f)
        r = v[None, :] - A[:, None] * f
        res = np.sqrt(np.mean(r * r, axis=1))
        j = int(np.argmin(res))
        if best is None or res[j] < best[3]:
            best = (float(a), float(A[j]), float(h_grid[j]), float(res[j]))
    return best


def fit(z, v, a_fixed=None):
    """Least squares of v = A [h^a - (h - z)^a]: grid over (a, h), refined; A in closed form.
    h is kept above the highest fitted slab (h >= z_max), a in [0.5, 6]."""
    a_lo, a_hi = (a_fixed, a_fixed) if a_fixed is not None else (0.5, 6.0)
    h_lo, h_hi = z.max() + 1e-3, z.max() + 40.0
    best = None
    for _ in range(3):
        a_grid = np.linspace(a_lo, a_hi, 1 if a_fixed is not None else 221)
        h_grid = np.linspace(h_lo, h_hi, 201)
        b = _grid_req(z, v, a_grid, h_grid)
        if best is None or b[3] < best[3]:
            best = b
        a, _, h, _ = best
        da = (a_hi - a_lo) / 20.0
        dh = (h_hi - h_lo) / 20.0
        a_lo, a_hi = (a_fixed, a_fixed) if a_fixed is not None else (max(0.5, a - da), a + da)
        h_lo, h_hi = max(z.max() + 1e-3, h - dh), h + dh
    return best


def fit_free_slip(z, v):
    """v = v_s - B (h - z)^a: for each (a, h), v_s and B by linear least squares (closed form)."""
    best = None
    a_lo, a_hi, h_lo, h_hi = 0.5, 6.0, z.max() + 1e-3, z.max() + 40.0
    vm = v.mean()
    dv = v - vm
    for _ in range(3):
        H = np.linspace(h_lo, h_hi, 201)[:, None]
        for a in np.linspace(a_lo, a_hi, 221):
            x = (H - z[None, :]) ** a
            xm = x.mean(axis=1, keepdims=True)
            dx = x - xm
            sxx = np.einsum("ij,ij->i", dx, dx)
            sxv = dx @ dv
            B = -sxv / sxx
            vs = vm + B * xm[:, 0]
            r = dv[None, :] + B[:, None] * dx
            res = np.sqrt(np.mean(r * r, axis=1))
            j = int(np.argmin(res))
            if best is None or res[j] < best[4]:
                best = (float(a), float(vs[j]), float(B[j]), float(H[j, 0]), float(res[j]))
        a, _, _, h, _ = best
        da, dh = (a_hi - a_lo) / 20.0, (h_hi - h_lo) / 20.0
        a_lo, a_hi = max(0.5, a - da), a + da
        h_lo, h_hi = max(z.max() + 1e-3, h - dh), h + dh
    return best

def fit_pinned(z, v, hs):
    """h pinned to the measured free surface h_s, base slip v_0 free: v = v_0 + A [h_s^a - (h_s - z)^a].
    For each a, v_0 and A by linear least squares; a by a grid search refined twice."""
    best = None
    lo, hi = 0.3, 4.0
    for _ in range(4):
        for a in np.linspace(lo, hi, 371):
            M = np.column_stack([np.ones_like(z), hs ** a - (hs - z) ** a])
            c, *_ = np.linalg.lstsq(M, v, rcond=None)
            r = v - M @ c
            res = float(np.sqrt(np.mean(r * r)))
            if best is None or res < best[3]:
                best = (a, c[0], c[1], res)
        da = (hi - lo) / 20.0
        lo, hi = max(0.3, best[0] - da), best[0] + da
    return best


def shear_profile(zc, v):
    """Shear rate dv/dz between neighbouring slab centres, at the slab interfaces."""
    return zc[:-1] + 0.5 * SLAB, np.diff(v) / SLAB


def fit_shear(zi, g, hs):
    """ln(dv/dz) = ln B + (a - 1) ln(h_s - z), least squares: returns a, B, rms residual of ln."""
    x = np.log(hs - zi)
    p = np.polyfit(x, np.log(g), 1)
    r = np.log(g) - np.polyval(p, x)
    return float(p[0] + 1.0), float(math.exp(p[1])), float(np.sqrt(np.mean(r * r)))


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
    zi, g = shear_profile(zc, v)

    def variants(zc_, v_, eb, es=EXCLUDE, with_15=False):
        """All fits over z in (eb, h_s - es) of one profile."""
        sel_ = (zc_ > eb) & (zc_ < h_s - es) & np.isfinite(v_)
        zf_, vf_ = zc_[sel_], v_[sel_]
        out = dict(sel=sel_, req=fit(zf_, vf_), pin=fit_pinned(zf_, vf_, h_s), slip=fit_free_slip(zf_, vf_))
        zi_, g_ = shear_profile(zc_, v_)
        m_ = (zi_ > eb) & (zi_ < h_s - es) & (g_ > 0)
        out["shear"] = fit_shear(zi_[m_], g_[m_], h_s)
        out["shear_n"] = int(np.sum(m_))
        out["req_bound"] = out["req"][2] < zf_.max() + 0.05
        if with_15:
            out["b15"] = fit(zf_, vf_, a_fixed=1.5)
        return out

    # four consecutive time blocks of the window: the +- of every exponent
    nb = 4
    block_prof = []
    for b in range(nb):
        part = win[b * len(win) // nb:(b + 1) * len(win) // nb]
        zb_, vb_, nb_, _ = profile(part, z_base)
        vb_ = np.where(nb_ > 0.5, vb_, np.nan)
        block_prof.append((zb_, vb_))

    def with_blocks(eb, es=EXCLUDE, with_15=False):
        full = variants(zc, np.where(filled, v, np.nan), eb, es, with_15)
        bl = [variants(zb_, vb_, eb, es) for zb_, vb_ in block_prof]
        err = {}
        for key, ia in (("req", 0), ("pin", 0), ("slip", 0), ("shear", 0)):
            vals = [b[key][ia] for b in bl]
            err[key] = (float(np.std(vals, ddof=1) / math.sqrt(nb)), vals)
        full["err"] = err
        full["req_bound_blocks"] = sum(b["req_bound"] for b in bl)
        return full

    main_fit = with_blocks(EXCLUDE, with_15=True)
    sens = {(eb, EXCLUDE): with_blocks(eb) for eb in (4.0, 6.0, 8.0)}
    sens.update({(EXCLUDE, es): with_blocks(EXCLUDE, es) for es in (4.0, 6.0)})
    sel = main_fit["sel"]
    zf, vf = zc[sel], v[sel]
    a_fit, A_fit, h_fit, res = main_fit["req"]
    _, A15, h15, res15 = main_fit["b15"]
    fs = main_fit["slip"]
    a_err = main_fit["err"]["req"][0]
    blocks = main_fit["err"]["req"][1]
    a_pin, v0_pin, A_pin, res_pin = main_fit["pin"]
    a_sh, B_sh, res_sh = main_fit["shear"]
    # headline: the requested form if its h is an interior optimum, else h pinned to h_s (slip free)
    headline = "pin" if main_fit["req_bound"] else "req"
    a_head = main_fit[headline][0]
    a_head_err = main_fit["err"][headline][0]
    v_surf = float(np.max(v[filled & (zc < h_s)]))
    in_band = abs(a_head - 1.5) <= 0.15

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
    p("  %6s %10s %10s %8s %6s %18s" % ("z/d", "v_x/sqrt(gd)", "fit", "phi", "fitted", "dv/dz above [sqrt(g/d)]"))
    gg = np.r_[g, np.nan]
    for zz, vv, pp, ok, nn, gk in zip(zc, v, phi, sel, nslab, gg):
        if nn < 0.5:
            continue
        fv = A_fit * (h_fit ** a_fit - max(h_fit - zz, 0.0) ** a_fit)
        p("  %6.1f %10.4f %10.4f %8.3f %6s %12.4f" % (zz, vv, fv, pp, "yes" if ok else "no", gk))
    p("  bulk volume fraction %.3f, free surface h_s = %.2f d (phi = half the bulk value)" % (bulk, h_s))
    p("")
    names = {"req": "v = A [h^a - (h - z)^a] (requested form; h free, h >= highest fitted slab)",
             "pin": "v = v_0 + A [h_s^a - (h_s - z)^a] (h pinned to the measured surface h_s, base slip v_0 free)",
             "slip": "v = v_s - B (h - z)^a (free slip: h and v_s free)",
             "shear": "dv/dz = B (h_s - z)^(a-1) (slab-to-slab shear rate, log-log least squares)"}
    p("fits over z = %.1f .. %.1f d (%d slabs; excluded: within %.0f d of the base and of the free surface h_s);"
      " +- = standard error from %d consecutive time blocks of the window" % (zf[0], zf[-1], len(zf), EXCLUDE, nb))
    p("  %s:" % names["req"])
    p("    a = %.3f +- %.3f (blocks: %s), A = %.5g sqrt(g d) / d^a, h = %.2f d%s, residual %.4g sqrt(g d) = %.2f %% of"
      " the surface velocity %.3f" % (a_fit, a_err, ", ".join("%.3f" % x for x in blocks), A_fit, h_fit,
                                       " (ON ITS LOWER BOUND)" if main_fit["req_bound"] else " (interior optimum)",
                                       res, 100 * res / v_surf, v_surf))
    p("  %s:" % names["pin"])
    p("    a = %.3f +- %.3f (blocks: %s), A = %.5g, v_0 = %.4f sqrt(g d), residual %.4g"
      % (a_pin, main_fit["err"]["pin"][0], ", ".join("%.3f" % x for x in main_fit["err"]["pin"][1]), A_pin, v0_pin, res_pin))
    p("  %s:" % names["slip"])
    p("    a = %.3f +- %.3f (blocks: %s), v_s = %.4f, B = %.5g, h = %.2f d, residual %.4g"
      % (fs[0], main_fit["err"]["slip"][0], ", ".join("%.3f" % x for x in main_fit["err"]["slip"][1]), fs[1], fs[2], fs[3], fs[4]))
    p("  %s, %d interfaces:" % (names["shear"], main_fit["shear_n"]))
    p("    a = %.3f +- %.3f (blocks: %s), B = %.5g sqrt(g/d), rms of ln(dv/dz) %.3f"
      % (a_sh, main_fit["err"]["shear"][0], ", ".join("%.3f" % x for x in main_fit["err"]["shear"][1]), B_sh, res_sh))
    p("  Bagnold a = 1.5 fixed (requested form): A = %.5g, h = %.2f d%s, residual %.4g sqrt(g d) (Silbert's A_theta = 3/2 A = %.4g)"
      % (A15, h15, " (on its lower bound)" if h15 < zf.max() + 0.05 else "", res15, 1.5 * A15))
    p("headline (%s): a = %.3f +- %.3f; expected a = 1.5 +- 0.15: %s"
      % ("requested form" if headline == "req" else "h pinned to h_s, the requested form's h being on its bound",
         a_head, a_head_err, "yes" if in_band else "NO"))
    p("")
    p("sensitivity to the excluded layers (diagnostic; the result above uses %.0f d at both ends), a +- block error:" % EXCLUDE)
    p("  %-18s %16s %16s %16s %16s" % ("excluded base/top", "requested", "h pinned", "free slip", "shear rate"))
    for (eb, es), f in [((EXCLUDE, EXCLUDE), main_fit)] + sorted(sens.items()):
        p("  %-18s %16s %16s %16s %16s" % (
            "%.0f d / %.0f d" % (eb, es),
            "%.3f +- %.3f%s" % (f["req"][0], f["err"]["req"][0], "*" if f["req_bound"] else " "),
            "%.3f +- %.3f" % (f["pin"][0], f["err"]["pin"][0]),
            "%.3f +- %.3f" % (f["slip"][0], f["err"]["slip"][0]),
            "%.3f +- %.3f" % (f["shear"][0], f["err"]["shear"][0])))
    p("  (* = h on its lower bound)")
    p("")
    p("profile shape against time (diagnostic): the fits over 2 d .. h_s - 2 d in consecutive %.1f s windows" % TREND_DT)
    p("  %-14s %7s %10s %10s %10s %10s" % ("t (s)", "h_s/d", "mean v_x", "requested", "h pinned", "shear rate"))
    t_lo = 0.4
    while t_lo + TREND_DT <= t[-1] + 1e-9:
        part = [sn for sn in snaps if t_lo - 1e-9 <= sn[0] < t_lo + TREND_DT - 1e-9]
        zq, vq, nq, phq = profile(part, z_base)
        okq = nq > 0.5
        kq = int(np.argmax((zq > 3.0) & (phq < 0.5 * bulk)))
        hq = float(zq[kq - 1] + (phq[kq - 1] - 0.5 * bulk) / (phq[kq - 1] - phq[kq]) * (zq[kq] - zq[kq - 1]))
        sq = (zq > EXCLUDE) & (zq < hq - EXCLUDE) & okq
        ziq, gq = shear_profile(zq, vq)
        mq = (ziq > EXCLUDE) & (ziq < hq - EXCLUDE) & (gq > 0)
        vm_q = np.mean([np.mean(a[a[:, c["fixed"]] == 0, c["vx"]]) for _, a, c in part]) / VU
        p("  %5.2f - %5.2f %7.2f %10.3f %10.3f %10.3f %10.3f" % (
            t_lo, t_lo + TREND_DT, hq, vm_q, fit(zq[sq], vq[sq])[0], fit_pinned(zq[sq], vq[sq], hq)[0],
            fit_shear(ziq[mq], gq[mq], hq)[0]))
        t_lo += TREND_DT

    p("")
    accel = float(np.polyfit(tw, vmean[start:], 1)[0]) * VU  # m/s^2, mean downhill acceleration
    chute_fields.report(OUT, os.path.join(HERE, "chute_fields.png"), tw[0], z_base, D, G, THETA, accel, zc,
                        np.where(filled, v, np.nan), h_s, EXCLUDE, p)

    # --- plots
    fig, ax = plt.subplots(1, 3, figsize=(14, 5.5), gridspec_kw={"width_ratios": [3, 2, 1]})
    zz = np.linspace(0.0, h_fit, 300)
    ax[0].plot(v[filled & sel], zc[filled & sel], "o", color="C0", label="simulation (fitted slabs)")
    ax[0].plot(v[filled & ~sel], zc[filled & ~sel], "o", mfc="none", color="C0", label="simulation (excluded)")
    ax[0].plot(A_fit * (h_fit ** a_fit - (h_fit - zz) ** a_fit), zz, "-", color="C3",
               label="A[h$^a$-(h-z)$^a$]: a = %.3f, h = %.1f d%s" % (a_fit, h_fit, " (bound)" if main_fit["req_bound"] else ""))
    zp = np.linspace(0.0, h_s, 300)
    ax[0].plot(v0_pin + A_pin * (h_s ** a_pin - (h_s - zp) ** a_pin), zp, "-.", color="C2",
               label="v$_0$+A[h$_s^a$-(h$_s$-z)$^a$]: a = %.3f" % a_pin)
    zz15 = np.linspace(0.0, h15, 300)
    ax[0].plot(A15 * (h15 ** 1.5 - (h15 - zz15) ** 1.5), zz15, "--", color="k", label="Bagnold a = 1.5")
    ax[0].axhline(h_s, color="gray", lw=0.8, ls=":")
    ax[0].axhspan(0, EXCLUDE, color="gray", alpha=0.15)
    ax[0].axhspan(h_s - EXCLUDE, h_s, color="gray", alpha=0.15)
    ax[0].set_xlabel("$v_x / \\sqrt{g d}$")
    ax[0].set_ylabel("z / d (above the base)")
    ax[0].set_title("periodic chute, theta = %.0f deg, h$_s$ = %.1f d" % (THETA, h_s))
    ax[0].legend(loc="upper left", fontsize=8)
    okg = (g > 0) & (zi < h_s)
    fitg = (zi > EXCLUDE) & (zi < h_s - EXCLUDE) & okg
    ax[1].loglog(h_s - zi[fitg], g[fitg], "o", color="C0", label="dv/dz (fitted)")
    ax[1].loglog(h_s - zi[okg & ~fitg], g[okg & ~fitg], "o", mfc="none", color="C0", label="dv/dz (excluded)")
    xx = np.linspace(EXCLUDE, h_s, 50)
    ax[1].loglog(xx, B_sh * xx ** (a_sh - 1), "-", color="C3", label="B (h$_s$-z)$^{a-1}$: a = %.3f" % a_sh)
    i_mid = np.argmin(np.abs(xx - 0.5 * h_s))
    ax[1].loglog(xx, B_sh * xx[i_mid] ** (a_sh - 1) * (xx / xx[i_mid]) ** 0.5, "--", color="k", label="slope 1/2 (a = 1.5)")
    ax[1].set_xlabel("(h$_s$ - z) / d")
    ax[1].set_ylabel("dv/dz / $\\sqrt{g/d}$")
    ax[1].legend(fontsize=8)
    ax[1].set_title("shear rate")
    ax[2].plot(phi[filled], zc[filled], "s-", ms=3)
    ax[2].axhline(h_s, color="gray", lw=0.8, ls=":")
    ax[2].set_xlabel("volume fraction")
    ax[2].set_ylabel("z / d")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "chute_profile.png"), dpi=110)

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
