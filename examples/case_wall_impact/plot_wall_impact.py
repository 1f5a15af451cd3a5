"""Case study 3: granular flow impacting a vertical wall (run by run.sh).

Reads output/barrier_groups.csv (force of the particles on the group "wall", N), output/log.csv
and the particle CSV snapshots; writes wall_force.png and wall_impact_snapshots.png and prints
the numbers quoted in README.md:
  * hydrodynamic estimate F = rho_b h w v^2 from the flow depth h, width w, front speed v and
    bulk density rho_b measured in the snapshot just before the impact,
  * the same estimate, time-resolved, at a fixed section 40-100 mm upstream of the wall,
  * the final (static) wall force against the earth-pressure estimate K rho_b g H^2 w / 2.
"""
import glob
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "output")
G = 9.81           # m/s^2
RHO_S = 2500.0     # kg/m^3, bead density (scene.toml)
WIDTH = 0.08       # m, slide width w (run.sh)
X_WALL = 0.2       # m, wall position (run.sh)
SECTION = (0.10, 0.16)   # m, control section on the run-out for the time-resolved estimate
MU_S = 0.5         # particle friction coefficient (scene.toml)


def bulk(d, sel, x0, x1):
    """Flow depth h (95 % quantile of bead tops, m), mean x-velocity (m/s) and bulk density
    (kg/m^3, bead volume / (w (x1 - x0) h)) of the beads selected in the slab x0 <= x < x1."""
    if np.sum(sel) < 5:
        return 0.0, 0.0, 0.0
    top = d["z"][sel] + d["radius"][sel]
    h = np.percentile(top, 95)
    v = d["vx"][sel].mean()
    vol = (4.0 / 3.0 * np.pi * d["radius"][sel] ** 3).sum()
    return h, v, RHO_S * vol / (WIDTH * (x1 - x0) * h)


def main():
    bg = np.genfromtxt(os.path.join(OUT, "barrier_groups.csv"), delimiter=",", names=True)
    t = bg["time"]
    fn = bg["wallfx"]          # N, normal force of the particles on the wall (+x, into the wall)
    fz = bg["wallfz"]          # N, vertical (tangential) force on the wall
    i_imp = np.argmax(fn > 1e-3)
    t_imp = t[i_imp]
    i_pk = np.argmax(fn)
    dt_log = t[1] - t[0]                            # s, barrier log interval
    n_avg = max(1, int(round(0.01 / dt_log)))       # 10 ms moving average (granular impacts are spiky)
    padded = np.pad(fn, (n_avg // 2, n_avg - 1 - n_avg // 2), mode="edge")
    fn_avg = np.convolve(padded, np.ones(n_avg) / n_avg, mode="valid")
    i_pk_avg = np.argmax(fn_avg)
    snaps = [np.genfromtxt(f, delimiter=",", names=True)
             for f in sorted(glob.glob(os.path.join(OUT, "particles_csv", "*.csv")))]
    times = np.array([d["time"][0] for d in snaps])

    # just before the impact: the front slab (last 50 mm of the flow)
    before = snaps[np.where(times < t_imp)[0][-1]]
    x_front = np.percentile(before["x"], 99.5)
    sel = before["x"] > x_front - 0.05
    h0, v0, rho0 = bulk(before, sel, x_front - 0.05, x_front)
    f_hyd0 = rho0 * h0 * WIDTH * v0 ** 2
    # body: the 50 mm slab 50-100 mm behind the front (deeper than the thin front wedge)
    sel_b = (before["x"] > x_front - 0.10) & (before["x"] <= x_front - 0.05)
    hb, vb, rhob = bulk(before, sel_b, x_front - 0.10, x_front - 0.05)
    f_hydb = rhob * hb * WIDTH * vb ** 2

    # time-resolved estimate at the control section
    hs, vs, rs = [], [], []
    for d in snaps:
        sel_s = (d["x"] >= SECTION[0]) & (d["x"] < SECTION[1])
        h, v, r = bulk(d, sel_s, *SECTION)
        hs.append(h), vs.append(v), rs.append(r)
    hs, vs, rs = map(np.array, (hs, vs, rs))
    f_sec = rs * hs * WIDTH * np.maximum(vs, 0.0) ** 2

    # final state: deposit height at the wall and its bulk density
    last = snaps[-1]
    near = last["x"] > X_WALL - 0.02
    H = np.percentile(last["z"][near] + last["radius"][near], 95)
    slab = (last["x"] > X_WALL - 0.03) & (last["z"] < H / 2)   # fully inside the deposit (centres)
    rho_dep = RHO_S * (4.0 / 3.0 * np.pi * last["radius"][slab] ** 3).sum() / (WIDTH * 0.03 * H / 2)
    f_end = fn[t > t[-1] - 0.05].mean()
    phi = math.atan(MU_S)
    k_a = (1 - math.sin(phi)) / (1 + math.sin(phi))
    k_0 = 1 - math.sin(phi)
    k_p = 1 / k_a                                   # Rankine passive
    f_unit = rho_dep * G * H ** 2 * WIDTH / 2       # N, earth pressure with K = 1 (hydrostatic)
    log = np.genfromtxt(os.path.join(OUT, "log.csv"), delimiter=",", names=True)

    print(f"impact (wall force > 1 mN) at t = {t_imp:.4f} s; snapshot used: t = {before['time'][0]:.3f} s, "
          f"front at x = {x_front:.3f} m")
    print(f"front slab (last 50 mm): h = {h0*1e3:.1f} mm, v = {v0:.3f} m/s, rho_b = {rho0:.0f} kg/m^3 -> "
          f"rho_b h w v^2 = {f_hyd0:.3f} N")
    print(f"body slab (50-100 mm behind the front): h = {hb*1e3:.1f} mm, v = {vb:.3f} m/s, rho_b = {rhob:.0f} kg/m^3 "
          f"-> rho_b h w v^2 = {f_hydb:.3f} N")
    print(f"section {SECTION[0]}-{SECTION[1]} m: max rho_b h w v^2 = {f_sec.max():.3f} N at t = {times[np.argmax(f_sec)]:.3f} s")
    print(f"peak wall normal force {fn[i_pk]:.3f} N at t = {t[i_pk]:.4f} s "
          f"(peak / front estimate = {fn[i_pk]/f_hyd0:.2f}, peak / section max = {fn[i_pk]/f_sec.max():.2f})")
    print(f"peak of the 10 ms moving average {fn_avg[i_pk_avg]:.3f} N at t = {t[i_pk_avg]:.4f} s "
          f"(/ front estimate = {fn_avg[i_pk_avg]/f_hyd0:.2f}, / body estimate = {fn_avg[i_pk_avg]/f_hydb:.2f}, "
          f"/ section max = {fn_avg[i_pk_avg]/f_sec.max():.2f})")
    print(f"final: deposit height at the wall H = {H*1e3:.1f} mm, bulk density {rho_dep:.0f} kg/m^3, "
          f"wall force (mean of last 0.05 s) {f_end:.3f} N, kinetic energy at the end {log['kinetic'][-1]:.3e} J")
    print(f"earth pressure rho_b g H^2 w / 2 = {f_unit:.3f} N x K: K_eff = {f_end/f_unit:.2f}; "
          f"phi = atan({MU_S}) = {math.degrees(phi):.1f} deg: Rankine K_a = {k_a:.2f} ({k_a*f_unit:.3f} N), "
          f"Jaky K_0 = {k_0:.2f} ({k_0*f_unit:.3f} N), hydrostatic K = 1 ({f_unit:.3f} N), "
          f"Rankine passive K_p = {k_p:.2f} ({k_p*f_unit:.3f} N)")
    print(f"deposit weight {(4/3*np.pi*last['radius']**3*RHO_S).sum()*G:.3f} N; "
          f"final vertical force on the wall {fz[t > t[-1]-0.05].mean():.3f} N")

    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax[0].plot(t, fn, color="0.6", lw=0.8, label="wall normal force $F_x$ (simulation, 1 ms samples)")
    ax[0].plot(t, fn_avg, color="k", lw=1.5, label="same, 10 ms moving average")
    ax[0].plot(times, f_sec, "o-", ms=3, color="tab:blue",
               label=r"$\rho_b h w v^2$ at section x = 0.10-0.16 m (40-100 mm upstream)")
    ax[0].axhline(f_hyd0, color="tab:red", ls="--",
                  label=rf"$\rho_b h w v^2$ of the front just before impact = {f_hyd0:.2f} N")
    ax[0].axhline(f_hydb, color="tab:orange", ls="--",
                  label=rf"$\rho_b h w v^2$ of the body behind the front = {f_hydb:.2f} N")
    ax[0].axhspan(k_a * f_unit, k_p * f_unit, color="tab:green", alpha=0.15,
                  label=rf"static: $K \rho_b g H^2 w/2$, $K_a$ = {k_a:.2f} to $K_p$ = {k_p:.2f} (H = {H*1e3:.0f} mm)")
    ax[0].axhline(k_0 * f_unit, color="tab:green", ls=":",
                  label=rf"static, at rest: $K_0 \rho_b g H^2 w/2$ = {k_0*f_unit:.2f} N ($K_0$ = {k_0:.2f})")
    ax[0].set_ylabel("force normal to the wall (N)")
    ax[0].set_title("Granular flow impacting a vertical wall (2000 beads, 40 deg slide)")
    ax[0].legend(fontsize=7)
    ax[0].grid(alpha=0.3)
    ax[1].plot(t, fz, color="tab:purple", lw=1, label="vertical (tangential) force on the wall $F_z$")
    ax[1].set_ylabel("tangential force (N)")
    ax[1].set_xlabel("time t (s)")
    ax[1].legend(fontsize=8)
    ax[1].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "wall_force.png"), dpi=110)

    # side views: just before the impact, at the peak, at the end
    picks = [before, snaps[np.argmin(np.abs(times - t[i_pk]))], last]
    fig, ax = plt.subplots(3, 1, figsize=(7.5, 9), sharex=True, constrained_layout=True)
    xs = np.linspace(-0.0643, 0.0, 20)
    for a, d in zip(ax, picks):
        a.plot([-0.3324, -0.0643], [0.2484, 0.0234], "k-", lw=1)
        a.plot(xs, 0.1 - np.sqrt(0.01 - xs ** 2), "k-", lw=1)
        a.plot([0.0, X_WALL, X_WALL], [0.0, 0.0, 0.15], "k-", lw=1.5)
        sc = a.scatter(d["x"], d["z"], s=1, c=d["vx"], cmap="viridis", vmin=-0.5, vmax=2.0)
        a.set_aspect("equal")
        a.set_xlim(-0.34, 0.22)
        a.set_ylim(-0.01, 0.26)
        a.set_ylabel("z (m)")
        a.grid(alpha=0.3)
        a.set_title(f"t = {d['time'][0]:.2f} s", fontsize=9)
    ax[-1].set_xlabel("x (m)")
    fig.colorbar(sc, ax=ax, label="$v_x$ (m/s)", shrink=0.6)
    fig.savefig(os.path.join(HERE, "wall_impact_snapshots.png"), dpi=100)


if __name__ == "__main__":
    main()
