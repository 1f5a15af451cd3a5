"""Coarse-grained fields of the periodic chute (examples/chute_bagnold), used by plot_chute.py.

Reads output/cg_chute.csv, the `[[coarse_grain]]` profile of scene.toml (Gaussian kernel,
w = d/2, x and y integrated over the periodic cell, each output the mean of 50 snapshots over the
0.1 s before it; columns in docs/output.md "Coarse-grained fields"), averages the outputs whose
windows lie in the steady window of plot_chute.py, and

- compares the velocity with the slab-binned profile of the particle snapshots;
- checks the momentum balance of a uniform flow along z: the normal stress sigma_zz carries the
  weight above, g cos(theta) int_z^inf rho dz', and the shear stress -sigma_xz the downhill pull
  of the material above, int_z^inf rho (g sin(theta) - a_x) dz', with a_x the measured mean
  acceleration of the window (the flow is quasi-steady);
- gives the friction coefficient mu = -sigma_xz / sigma_zz, tan(theta) for a steady flow.

The stress is MercuryCG's (kinetic + contact, compression positive, row = force component); the
fixed base spheres are particles, so the base's contacts carry their part of the stress.
Writes chute_fields.png and prints its section of results.txt.
"""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def load(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    times = np.unique(d["time"])
    nz = int(np.sum(d["time"] == times[0]))
    return {name: d[name].reshape(len(times), nz) for name in d.dtype.names}, times


def report(out_dir, fig_path, t0, z_base, d, g, theta_deg, accel, zc, v_slab, h_s, exclude, p=print):
    """t0: start of the steady window (s); z_base: base plane (m); d: diameter (m); accel: mean
    downhill acceleration over the window (m/s^2); zc, v_slab: the slab profile (in d and
    sqrt(g d)); h_s: free surface (d above the base); exclude: d left out at base and surface."""
    path = os.path.join(out_dir, "cg_chute.csv")
    if not os.path.exists(path):
        p("coarse-grained fields: %s missing (scene.toml's [[coarse_grain]] \"chute\")" % path)
        return
    f, times = load(path)
    every = times[1] - times[0] if len(times) > 1 else times[0]
    use = times - every >= t0 - 1e-9                     # windows inside the steady window
    if not np.any(use):
        use = times == times[-1]
    mean = {k: np.mean(a[use], axis=0) for k, a in f.items()}
    th = math.radians(theta_deg)
    vu = math.sqrt(g * d)
    z = (mean["z"] - z_base) / d                         # d above the base plane
    rho = mean["density"]
    vx = np.where(rho > 0, mean["momentum_x"] / np.where(rho > 0, rho, 1.0), np.nan) / vu  # <p>/<rho>
    dz = (mean["z"][1] - mean["z"][0])
    # integral from z to the top (trapezoid; rho vanishes at the top of the profile)
    above = np.r_[np.cumsum(0.5 * (rho[1:] + rho[:-1])[::-1] * dz)[::-1], 0.0]
    w_n = g * math.cos(th) * above                      # Pa
    w_t = (g * math.sin(th) - accel) * above             # Pa
    s_zz, s_xz = mean["stress_zz"], -mean["stress_xz"]
    k_zz, k_xz = mean["kinetic_stress_zz"], -mean["kinetic_stress_xz"]
    bulk = (z > exclude) & (z < h_s - exclude)
    mu = s_xz / np.where(s_zz > 0, s_zz, np.nan)
    v_at = np.interp(zc, z, vx)
    ok = np.isfinite(v_slab) & (zc > 0) & (zc < h_s)

    p("coarse-grained fields (output/cg_chute.csv: Gaussian kernel, w = d/2, %d outputs averaged, windows"
      " %.2f .. %.2f s)" % (int(np.sum(use)), times[use][0] - every, times[use][-1]))
    p("  velocity: rms difference from the slab profile over 0 < z < h_s %.4f sqrt(g d) (surface velocity %.3f)"
      % (float(np.sqrt(np.mean((v_at[ok] - v_slab[ok]) ** 2))), float(np.nanmax(v_slab[ok]))))
    p("  momentum balance over %.0f d < z < h_s - %.0f d (%d points), mean acceleration a_x = %.4g m/s^2"
      " (%.2f %% of g sin theta):" % (exclude, exclude, int(np.sum(bulk)), accel, 100 * accel / (g * math.sin(th))))
    p("    sigma_zz / (g cos theta int rho dz) - 1: max %.2f %%, mean %+.2f %%"
      % (100 * np.max(np.abs(s_zz[bulk] / w_n[bulk] - 1)), 100 * np.mean(s_zz[bulk] / w_n[bulk] - 1)))
    p("    -sigma_xz / ((g sin theta - a_x) int rho dz) - 1: max %.2f %%, mean %+.2f %%"
      % (100 * np.max(np.abs(s_xz[bulk] / w_t[bulk] - 1)), 100 * np.mean(s_xz[bulk] / w_t[bulk] - 1)))
    p("    mu = -sigma_xz / sigma_zz: mean %.4f (min %.4f, max %.4f); tan theta = %.4f"
      % (float(np.mean(mu[bulk])), float(np.min(mu[bulk])), float(np.max(mu[bulk])), math.tan(th)))
    p("    kinetic share of sigma_zz: %.2f %% at mid-depth, %.2f %% at h_s - %.0f d"
      % (100 * float(np.interp(0.5 * h_s, z, k_zz / np.where(s_zz > 0, s_zz, np.nan))),
         100 * float(np.interp(h_s - exclude, z, k_zz / np.where(s_zz > 0, s_zz, np.nan))), exclude))
    p("  bulk solid fraction %.3f, coordination number %.2f (means over the same points)"
      % (float(np.mean(mean["solid_fraction"][bulk])), float(np.mean(mean["coordination"][bulk]))))

    fig, ax = plt.subplots(1, 3, figsize=(13, 5.5), sharey=True)
    inside = rho > 1e-3 * np.max(rho)
    ax[0].plot(vx[inside], z[inside], "-", color="C0", label="coarse-grained, w = d/2")
    ax[0].plot(v_slab[ok], zc[ok], "o", ms=3, mfc="none", color="C1", label="slabs of 1 d (particle CSV)")
    ax[0].set_xlabel("$v_x / \\sqrt{g d}$")
    ax[0].set_ylabel("z / d (above the base)")
    ax[0].set_title("velocity")
    ax[0].legend(fontsize=8)
    ax[1].plot(s_zz, z, "-", color="C0", label="$\\sigma_{zz}$")
    ax[1].plot(w_n, z, "--", color="k", lw=1, label="$g\\cos\\theta\\int_z^\\infty\\rho\\,dz'$")
    ax[1].plot(s_xz, z, "-", color="C3", label="$-\\sigma_{xz}$")
    ax[1].plot(w_t, z, ":", color="k", lw=1, label="$(g\\sin\\theta - a_x)\\int_z^\\infty\\rho\\,dz'$")
    ax[1].plot(k_zz, z, "-", color="C2", lw=1, label="kinetic part of $\\sigma_{zz}$")
    ax[1].set_xlabel("stress [Pa]")
    ax[1].set_title("stress (kinetic + contact)")
    ax[1].legend(fontsize=8)
    sel = inside & (s_zz > 0.02 * np.max(s_zz))
    ax[2].plot(mu[sel], z[sel], "-", color="C0", label="$-\\sigma_{xz}/\\sigma_{zz}$")
    ax[2].axvline(math.tan(th), color="k", ls="--", lw=1, label="tan %.0f deg" % theta_deg)
    ax[2].set_xlabel("friction coefficient $\\mu$ [-]")
    ax[2].set_xlim(0.3, 0.6)
    ax[2].set_title("stress ratio")
    ax[2].legend(fontsize=8)
    for a in ax:
        a.axhline(h_s, color="gray", lw=0.8, ls=":")
        a.axhline(0.0, color="gray", lw=0.8)
    fig.suptitle("periodic chute, coarse-grained profile (cg_chute.csv), %.2f .. %.2f s"
                 % (times[use][0] - every, times[use][-1]))
    fig.tight_layout()
    fig.savefig(fig_path, dpi=110)
