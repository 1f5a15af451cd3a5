#!/usr/bin/env python3
"""Silo discharge (examples/silo_beverloo): bulk density of the settled fill, the steady mass flow
rate W of every orifice from the sink's log columns, Beverloo fits, plot and table. Run by run.sh:

    plot_silo.py --width L --hole circle|square --head H_TOP --fill output/fill [--png FILE] output/runs.txt

runs.txt has one line per orifice: NAME D0 T_OPEN OUTPUT_DIR. Writes silo_beverloo.png (next to
this file) and prints the table that run.sh saves as results.txt.

Definitions (README.md):
- d = mean bead diameter (2 x mean radius of the fill);
- fill height H = mean over 7 x 7 columns of the silo of the highest bead top (z + r) in the
  column; rho_b = fill mass / (L^2 H);
- W = slope of a least-squares line through the sink's `out.removed_mass` (kg) against time over
  the window [T_OPEN + T_TRANS, end]; the mean of `out.mass_rate` over the same rows is printed as
  a check; the +- is the standard error of the mean of the slopes over NSUB equal sub-windows
  (std / sqrt(NSUB)); the drift is the second half's slope against the first half's;
- head: mass in the silo M(t) = fill mass + inlet's inserted mass - sink's removed mass (the beads
  falling between the floor and the sink, < 1 % of it, counted in), as a height M / (rho_b L^2);
  `fed` = fraction of the window's log rows in which the inlet reported a shortfall (its box was
  full: the head was kept at the top of the box);
- D0 = diameter of the circular orifice (Beverloo's orifices), or the side of a square one (= its
  hydraulic diameter 4 A / P; C and k are then also given for the circle of the same area);
- free-exponent fit  W = C' (D0 - k d)^a: weighted least squares in ln W (weights 1 / (err/W)^2);
  for every k of a fine grid the best a, ln C' are linear, the k of the smallest chi^2 is kept;
  standard errors from the Jacobian, scaled by sqrt(chi^2/dof) when that exceeds 1;
- Beverloo fit (a = 5/2): W^(2/5) = (C rho_b sqrt(g))^(2/5) (D0 - k d), a straight line in D0
  (weighted the same way; standard errors of C and k from the line's covariance, scaled likewise);
- the exponent is checked (2.5 +- 0.2) by the free fit over the orifices in Beverloo's range,
  D0 > 6 d (BEVERLOO_MIN: below it the flow is intermittent, and one (D0 - k d)^a with one k does
  not hold down to a few bead diameters, Mankoc et al. 2007); the fits over all orifices and from
  9 d on are printed beside it (a and k are strongly correlated: the range moves both).
"""
import argparse
import csv
import glob
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
G = 9.81          # m/s^2
RHO_P = 2500.0    # kg/m^3, bead density (silo.toml.in)
T_TRANS = 0.15    # s after the lid opens: flow established at the orifice and beads fallen into the sink
NSUB = 6          # sub-windows for the +- of W
SINK = "out"
BEVERLOO_MIN = 6.0  # D0 / d above which Beverloo's correlation is taken to hold
FAR_MIN = 8.5       # D0 / d: the fit "from 9 d on", printed beside it
FEED = "feed"


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if line.strip() and not line.startswith("#")))
    return [{k.strip(): v.strip() for k, v in r.items()} for r in rows]


def last_snapshot(folder):
    files = sorted(glob.glob(os.path.join(folder, "particles_csv", "particles_*.csv")))
    return read_csv(files[-1])


def fill_state(folder, width):
    rows = last_snapshot(folder)
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    z = np.array([float(r["z"]) for r in rows])
    r = np.array([float(r["radius"]) for r in rows])
    t = float(rows[0]["time"])
    mass = float(np.sum(4.0 / 3.0 * math.pi * r**3 * RHO_P))
    nc = 7
    ix = np.clip(((x + width / 2) / width * nc).astype(int), 0, nc - 1)
    iy = np.clip(((y + width / 2) / width * nc).astype(int), 0, nc - 1)
    top = np.zeros((nc, nc))
    np.maximum.at(top, (ix, iy), z + r)
    h = float(np.mean(top))
    d = 2.0 * float(np.mean(r))
    # interior solid fraction (centres in a box 2 d from the walls and floor, 3 d below the surface)
    m = (np.abs(x) < width / 2 - 2 * d) & (np.abs(y) < width / 2 - 2 * d) & (z > 2 * d) & (z < h - 3 * d)
    vol = (width - 4 * d) ** 2 * (h - 5 * d)
    phi_in = float(np.sum(4.0 / 3.0 * math.pi * r[m] ** 3) / vol)
    log = read_csv(os.path.join(folder, "log.csv"))
    ke = float(log[-1]["kinetic"])
    return dict(t=t, n=len(rows), mass=mass, h=h, top_min=float(top.min()), top_max=float(top.max()),
                d=d, rmin=float(r.min()), rmax=float(r.max()), phi_in=phi_in, ke=ke,
                rho_b=mass / (width * width * h))


def slope(t, m):
    a = np.polyfit(t, m, 1)
    return float(a[0])


def discharge(name, d0, t_open, folder, fill, width):
    log = read_csv(os.path.join(folder, "log.csv"))
    t = np.array([float(r["time"]) for r in log])
    m = np.array([float(r[SINK + ".removed_mass"]) for r in log])
    rate = np.array([float(r[SINK + ".mass_rate"]) for r in log])
    n = np.array([int(r["particles"]) for r in log])
    fed = FEED + ".inserted_mass" in log[0]
    m_in = np.array([float(r[FEED + ".inserted_mass"]) for r in log]) if fed else np.zeros_like(t)
    short = np.array([float(r[FEED + ".shortfall"]) for r in log]) if fed else np.zeros_like(t)
    before = m[t < t_open]
    first = t[m > 0][0] if np.any(m > 0) else float("nan")
    w0 = t_open + T_TRANS
    sel = t >= w0
    tw, mw = t[sel], m[sel]
    w = slope(tw, mw)
    q = np.array_split(np.arange(len(tw)), NSUB)
    ws = [slope(tw[i], mw[i]) for i in q]
    err = float(np.std(ws, ddof=1) / math.sqrt(NSUB))
    h2 = np.array_split(np.arange(len(tw)), 2)
    drift = (slope(tw[h2[1]], mw[h2[1]]) - slope(tw[h2[0]], mw[h2[0]])) / w
    head = (fill["mass"] + m_in[sel] - mw) / (fill["rho_b"] * width * width)
    return dict(name=name, d0=d0, t_open=t_open, t=t, m=m, W=w, err=err, ws=ws, drift=drift,
                rate=float(np.mean(rate[sel])),
                before=float(before.max()) if len(before) else 0.0, first=first, w0=float(tw[0]),
                w1=float(tw[-1]), removed=float(mw[-1]) - float(mw[0]), h_mean=float(np.mean(head)),
                h_min=float(np.min(head)), fed=float(np.mean(short[sel] > 0)), n_end=int(n[-1]),
                inserted=float(m_in[sel][-1] - m_in[sel][0]), n_removed=int(log[-1][SINK + ".removed"]))


def fit_free(d0, w, d, err, kmin=-4.0):
    """W = Cp (D0 - k d)^a, weighted least squares in ln W; returns a, k, Cp and standard errors."""
    lw = np.log(w)
    sw = err / w                      # relative errors = errors of ln W
    wt = 1.0 / sw
    best = None
    for k in np.arange(kmin, min(d0) / d - 0.2, 0.0005):
        x = np.log(d0 - k * d)
        A = np.vstack([np.ones_like(x), x]).T
        coef, *_ = np.linalg.lstsq(A * wt[:, None], lw * wt, rcond=None)
        chi2 = float(np.sum(((A @ coef - lw) * wt) ** 2))
        if best is None or chi2 < best[0]:
            best = (chi2, k, coef[1], coef[0])
    chi2, k, a, lc = best
    u = d0 - k * d
    J = np.vstack([-np.ones_like(u), -np.log(u), a * d / u]).T * wt[:, None]   # d residual / d (ln Cp, a, k)
    dof = max(len(w) - 3, 1)
    scale = max(1.0, chi2 / dof)
    se = np.sqrt(np.diag(scale * np.linalg.inv(J.T @ J)))
    rms = math.sqrt(float(np.mean((np.log(w) - lc - a * np.log(u)) ** 2)))
    return dict(a=a, k=k, cp=math.exp(lc), se_a=float(se[1]), se_k=float(se[2]), se_lc=float(se[0]),
                chi2=chi2, dof=dof, rms=rms, at_bound=abs(k - kmin) < 1e-9)


def fit_beverloo(d0, w, d, rho_b, err):
    """a = 5/2: W^(2/5) linear in D0, weighted (W^(2/5) has relative errors 2/5 of W's)."""
    y = w ** 0.4
    sy = 0.4 * y * err / w
    A = np.vstack([d0, np.ones_like(d0)]).T / sy[:, None]
    (s, b), *_ = np.linalg.lstsq(A, y / sy, rcond=None)
    chi2 = float(np.sum(((s * d0 + b - y) / sy) ** 2))
    dof = max(len(w) - 2, 1)
    cov = max(1.0, chi2 / dof) * np.linalg.inv(A.T @ A)
    k = -b / s / d
    c = s ** 2.5 / (rho_b * math.sqrt(G))
    # error propagation: k = -b/(s d), C ~ s^2.5
    gk = np.array([b / (s * s * d), -1.0 / (s * d)])
    se_k = float(math.sqrt(gk @ cov @ gk))
    se_c = float(2.5 * c / s * math.sqrt(cov[0, 0]))
    res = y - (s * d0 + b)
    return dict(s=float(s), b=float(b), k=float(k), C=float(c), se_k=se_k, se_C=se_c, chi2=chi2, dof=dof,
                rel=float(np.max(np.abs(res / y))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("runs")
    ap.add_argument("--width", type=float, required=True)
    ap.add_argument("--hole", choices=("circle", "square"), default="circle")
    ap.add_argument("--head", type=float, default=None, help="m, top of the feeding inlet's box")
    ap.add_argument("--fill", required=True)
    ap.add_argument("--png", default=os.path.join(HERE, "silo_beverloo.png"))
    a = ap.parse_args()
    L = a.width
    fill = fill_state(a.fill, L)
    d = fill["d"]
    runs = []
    with open(a.runs) as f:
        for line in f:
            if line.strip():
                name, d0, t_open, folder = line.split()
                runs.append(discharge(name, float(d0), float(t_open), folder, fill, L))
    runs.sort(key=lambda r: r["d0"])
    d0 = np.array([r["d0"] for r in runs])
    w = np.array([r["W"] for r in runs])
    err = np.array([r["err"] for r in runs])

    size_word = "diameter" if a.hole == "circle" else "side"  # what D0 measures
    what = ("circular orifice of diameter D0" if a.hole == "circle"
            else "square orifice of side D0 (D0 = side = hydraulic diameter)")
    print(f"silo: square, width L = {L} m, flat floor, {what} in its centre")
    print(f"beads: radius {fill['rmin']*1e3:.3f}-{fill['rmax']*1e3:.3f} mm, mean diameter d = {d*1e3:.4f} mm, "
          f"density {RHO_P:g} kg/m^3, E = 2e6 Pa, e = 0.5, mu = 0.5")
    print(f"settled fill (t = {fill['t']:.3f} s, kinetic energy {fill['ke']:.3g} J): {fill['n']} beads, mass {fill['mass']:.4f} kg, "
          f"fill height H = {fill['h']*1e3:.1f} mm (column tops {fill['top_min']*1e3:.1f}-{fill['top_max']*1e3:.1f} mm) "
          f"= {fill['h']/L:.2f} L = {fill['h']/d:.1f} d")
    print(f"bulk density rho_b = mass / (L^2 H) = {fill['rho_b']:.1f} kg/m^3 (solid fraction {fill['rho_b']/RHO_P:.3f}; "
          f"interior solid fraction {fill['phi_in']:.3f})")
    if a.head:
        print(f"discharges fed at the top: the inlet's box reaches z = {a.head*1e3:.0f} mm; head = mass in the silo / (rho_b L^2)")
    print(f"W: slope of {SINK}.removed_mass over [t_open + {T_TRANS} s, end]; +- = std / sqrt({NSUB}) of {NSUB} "
          "sub-window slopes; drift = (2nd half - 1st half) / W")
    print()
    print(f"{'D0 (m)':>8} {'D0/d':>6} {'L/D0':>5} {'W (kg/s)':>10} {'+-':>7} {'+-%':>5} {'mean rate':>10} "
          f"{'drift':>6} {'window (s)':>12} {'removed':>8} {'head/D0':>12} {'fed':>4} {'before open':>11}")
    for r in runs:
        print(f"{r['d0']:8.4f} {r['d0']/d:6.2f} {L/r['d0']:5.2f} {r['W']:10.4f} {r['err']:7.4f} "
              f"{100*r['err']/r['W']:5.2f} {r['rate']:10.4f} {100*r['drift']:+5.1f}% "
              f"{r['w0']:5.3f}-{r['w1']:5.3f} {r['removed']:7.3f}kg {r['h_mean']/r['d0']:5.2f} (>{r['h_min']/r['d0']:4.2f}) "
              f"{r['fed']:4.2f} {r['before']:11.3g}")
    print("  sub-window slopes (kg/s):")
    for r in runs:
        print(f"    D0 = {r['d0']*1e3:5.1f} mm: " + " ".join(f"{x:.4f}" for x in r["ws"]))
    print()
    ff = fit_free(d0, w, d, err)
    print(f"free-exponent fit W = C' (D0 - k d)^a (weighted): a = {ff['a']:.3f} +- {ff['se_a']:.3f}, "
          f"k = {ff['k']:.3f} +- {ff['se_k']:.3f}, C' = {ff['cp']:.4g} kg s^-1 m^-a, "
          f"C = C' / (rho_b sqrt(g)) = {ff['cp']/(fill['rho_b']*math.sqrt(G)):.4g} m^(a-5/2); "
          f"chi^2 = {ff['chi2']:.2f} for {ff['dof']} dof; rms residual {100*ff['rms']:.2f} % in W"
          + ("  (k ON ITS BOUND)" if ff["at_bound"] else ""))
    inside = d0 / d > BEVERLOO_MIN
    fr = fit_free(d0[inside], w[inside], d, err[inside]) if inside.sum() >= 4 else None
    if fr:
        print(f"  over Beverloo's range D0 > {BEVERLOO_MIN:g} d ({int(inside.sum())} orifices): a = {fr['a']:.3f} +- "
              f"{fr['se_a']:.3f}, k = {fr['k']:.3f} +- {fr['se_k']:.3f}; chi^2 = {fr['chi2']:.2f} for {fr['dof']} dof; "
              f"expected a = 2.5 +- 0.2: {'yes' if abs(fr['a'] - 2.5) <= 0.2 else 'NO'}")
    far = d0 / d > FAR_MIN
    if far.sum() >= 4:
        f9 = fit_free(d0[far], w[far], d, err[far])
        print(f"  from 9 d on ({int(far.sum())} orifices): a = {f9['a']:.3f} +- {f9['se_a']:.3f}, k = {f9['k']:.3f}")
    fu = fit_free(d0, w, d, np.full_like(w, 0.01) * w)
    print(f"  unweighted (all rates equally weighted): a = {fu['a']:.3f}, k = {fu['k']:.3f}")
    prof = []
    for k in (0.0, 1.0, 1.5, 2.0):
        x = np.log(d0 - k * d)
        a_k = np.polyfit(x, np.log(w), 1, w=w / err)[0]
        prof.append(f"k = {k:g}: a = {a_k:.2f}")
    print("  best a at fixed k: " + ", ".join(prof))
    loo = []
    for i in range(len(w)):
        if len(w) < 5:
            break
        m = np.arange(len(w)) != i
        fi = fit_free(d0[m], w[m], d, err[m])
        loo.append(f"{d0[i]/d:.1f} d: a = {fi['a']:.2f} +- {fi['se_a']:.2f}, k = {fi['k']:.2f}")
    if loo:
        print("  leaving one orifice out: " + "; ".join(loo))
    bf = fit_beverloo(d0, w, d, fill["rho_b"], err)
    f_area = (2 / math.sqrt(math.pi))
    ca = bf["C"] / f_area ** 2.5
    print(f"Beverloo fit (a = 5/2, weighted): C = {bf['C']:.4f} +- {bf['se_C']:.4f}, k = {bf['k']:.3f} +- {bf['se_k']:.3f} "
          f"(D0 = {size_word}); chi^2 = {bf['chi2']:.2f} for {bf['dof']} dof; largest residual of W^(2/5) {100*bf['rel']:.2f} %")
    if a.hole == "square":
        print(f"  as a circle of the same area (D_A = 2 D0 / sqrt(pi)): C = {ca:.4f} +- {bf['se_C']/f_area**2.5:.4f}, "
              f"k = {bf['k']*f_area:.3f} +- {bf['se_k']*f_area:.3f}  (Beverloo et al. 1961: C = 0.58, k ~ 1.5 for circular orifices)")
    else:
        print("  (Beverloo et al. 1961: C = 0.58, k ~ 1.5 for circular orifices)")

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    xs = np.linspace(0, d0.max() * 1.05, 100)
    ax[0].errorbar(d0 * 1e3, w ** 0.4, yerr=0.4 * w ** 0.4 * err / w, fmt="o", label="simulation")
    ax[0].plot(xs * 1e3, np.clip(bf["s"] * xs + bf["b"], 0, None), "-",
               label=f"Beverloo, a = 5/2: C = {bf['C']:.3f}, k = {bf['k']:.2f}")
    ax[0].set_xlabel(f"orifice {size_word} D0 (mm)")
    ax[0].set_ylabel("W^(2/5) (kg/s)^(2/5)")
    ax[0].set_xlim(0, None)
    ax[0].set_ylim(0, None)
    ax[0].legend(fontsize=8)
    ax[0].set_title(f"{a.hole} orifice, W^(2/5) against D0 (L = {L*1e3:.0f} mm): straight for a = 5/2", fontsize=10)
    u = d0 - ff["k"] * d
    us = np.linspace(u.min() * 0.9, u.max() * 1.1, 50)
    ax[1].errorbar(u * 1e3, w, yerr=err, fmt="o", label="simulation")
    ax[1].loglog(us * 1e3, ff["cp"] * us ** ff["a"], "-",
                 label=f"fit: a = {ff['a']:.2f} +- {ff['se_a']:.2f}, k = {ff['k']:.2f}")
    if fr:
        ax[1].loglog(us * 1e3, fr["cp"] * (us + (ff["k"] - fr["k"]) * d) ** fr["a"], "--",
                     label=f"D0 > {BEVERLOO_MIN:g} d only: a = {fr['a']:.2f} +- {fr['se_a']:.2f}, k = {fr['k']:.2f}")
    ax[1].loglog(us * 1e3, ff["cp"] * u[-1] ** ff["a"] * (us / u[-1]) ** 2.5, ":", color="gray", label="slope 5/2")
    ax[1].set_xscale("log")
    ax[1].set_yscale("log")
    ax[1].set_xlabel("D0 - k d (mm)")
    ax[1].set_ylabel("W (kg/s)")
    ax[1].legend(fontsize=8)
    ax[1].set_title("free exponent W = C' (D0 - k d)^a")
    for r in runs:
        ax[2].plot(r["t"] - r["t_open"], r["m"], label=f"D0 = {r['d0']*1e3:.1f} mm")
        tt = np.array([r["w0"], r["w1"]])
        m0 = r["m"][np.searchsorted(r["t"], r["w0"])]
        ax[2].plot(tt - r["t_open"], m0 + r["W"] * (tt - r["w0"]), "k--", lw=0.8)
    ax[2].axvline(T_TRANS, color="gray", lw=0.8)
    ax[2].set_xlabel("time after the lid opens (s)")
    ax[2].set_ylabel("mass in the sink (kg)")
    ax[2].legend(fontsize=8)
    ax[2].set_title("sink mass; dashed: fitted W over the window")
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
