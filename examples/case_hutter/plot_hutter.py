"""Case study 1 (Hutter apparatus): front / centre-of-mass kinematics, deposit profile and the
Coulomb-block comparison. Run by run.sh after the two runs:

    output/tilt/particles_csv/   tilt test (50 deg): effective basal friction angle delta
    output/flow/particles_csv/   the chute flow

Writes hutter_front_com.png, hutter_com_velocity.png, hutter_deposit.png, tilt_test.png and prints
the numbers quoted in README.md.
"""
import glob
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
G = 9.81                       # m/s^2
# chute geometry: must match run.sh (mpdem mesh chute)
ANGLE = math.radians(40.0)     # incline angle a
RADIUS = 0.2                   # m, transition radius
LENGTH = 0.6                   # m, incline length along the slope
RUNOUT = 1.4                   # m
TILT = math.radians(50.0)      # tilt-test angle (gravity tilted in tilt_test.toml)
X_ARC = -RADIUS * math.sin(ANGLE)                       # m, incline/arc joint
Z_ARC = RADIUS * (1.0 - math.cos(ANGLE))
X_TOP = X_ARC - LENGTH * math.cos(ANGLE)                # m, upper end of the incline
Z_TOP = Z_ARC + LENGTH * math.sin(ANGLE)
S_ARC_END = LENGTH + RADIUS * ANGLE                     # m, curvilinear abscissa of the run-out start


def snapshots(folder):
    for f in sorted(glob.glob(os.path.join(HERE, "output", folder, "particles_csv", "*.csv"))):
        yield np.genfromtxt(f, delimiter=",", names=True)


def profile_coords(x, z):
    """Curvilinear abscissa s along the chute (m, 0 at the top of the incline), height above the
    surface along its local normal (m) and the local downstream tangent (tx, tz)."""
    s = np.empty_like(x)
    h = np.empty_like(x)
    tx = np.empty_like(x)
    tz = np.empty_like(x)
    inc = x <= X_ARC
    s[inc] = (x[inc] - X_TOP) * math.cos(ANGLE) - (z[inc] - Z_TOP) * math.sin(ANGLE)
    h[inc] = (x[inc] - X_TOP) * math.sin(ANGLE) + (z[inc] - Z_TOP) * math.cos(ANGLE)
    tx[inc], tz[inc] = math.cos(ANGLE), -math.sin(ANGLE)
    arc = (x > X_ARC) & (x < 0.0)
    phi = np.arctan2(-x[arc], RADIUS - z[arc])          # 0 at the run-out, ANGLE at the incline
    s[arc] = LENGTH + RADIUS * (ANGLE - phi)
    h[arc] = RADIUS - np.hypot(x[arc], z[arc] - RADIUS)
    tx[arc], tz[arc] = np.cos(phi), -np.sin(phi)
    run = x >= 0.0
    s[run] = S_ARC_END + x[run]
    h[run] = z[run]
    tx[run], tz[run] = 1.0, 0.0
    return s, h, tx, tz


def tilt_test():
    t, v = [], []
    for d in snapshots("tilt"):
        m = d["radius"] ** 3                              # mass ~ r^3 (one density)
        t.append(d["time"][0])
        v.append((m * d["vx"]).sum() / m.sum())           # m/s, down-slope CoM velocity
    t, v = np.array(t), np.array(v)
    sel = t >= 0.05                                       # after the block has landed on the floor
    a, v0 = np.polyfit(t[sel], v[sel], 1)
    delta = math.atan(math.tan(TILT) - a / (G * math.cos(TILT)))
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(t, v, "o", ms=3, label="simulation (block of 957 beads)")
    ax.plot(t[sel], a * t[sel] + v0, "-", label=f"linear fit, a = {a:.3f} m/s$^2$")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("down-slope CoM velocity (m/s)")
    ax.set_title(f"Tilt test at 50 deg: effective basal friction angle {math.degrees(delta):.1f} deg")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "tilt_test.png"), dpi=110)
    return a, delta


def main():
    a_tilt, delta = tilt_test()
    a_coulomb = G * (math.sin(ANGLE) - math.tan(delta) * math.cos(ANGLE))
    print(f"tilt test: CoM acceleration {a_tilt:.3f} m/s^2 at 50 deg -> delta = {math.degrees(delta):.2f} deg "
          f"(tan delta = {math.tan(delta):.3f})")
    print(f"Coulomb block on the 40 deg incline: a = g (sin a - tan d cos a) = {a_coulomb:.3f} m/s^2")

    T, S_CM, V_CM, FRONT, DENSE, TAIL, ON_INCLINE = [], [], [], [], [], [], []
    edges = np.arange(-0.05, S_ARC_END + RUNOUT + 0.1, 0.01)   # m, 10 mm bins along s
    last = None
    for d in snapshots("flow"):
        s, h, tx, tz = profile_coords(d["x"], d["z"])
        m = d["radius"] ** 3
        T.append(d["time"][0])
        S_CM.append((m * s).sum() / m.sum())
        V_CM.append((m * (d["vx"] * tx + d["vz"] * tz)).sum() / m.sum())
        FRONT.append(np.percentile(s, 99.5))    # leading beads: 99.5 % of the beads are behind
        # front of the dense mass: last 10 mm bin holding >= 20 beads (a close-packed monolayer
        # over the 0.1 m width holds ~60); ahead of it only a sparse fringe of single beads rolls
        counts, _ = np.histogram(s, edges)
        DENSE.append(edges[1:][counts >= 20].max())
        TAIL.append(np.percentile(s, 0.5))
        ON_INCLINE.append(np.percentile(s, 99.9) < LENGTH)
        last = d
    T, S_CM, V_CM, FRONT, DENSE, TAIL = map(np.array, (T, S_CM, V_CM, FRONT, DENSE, TAIL))
    ON_INCLINE = np.array(ON_INCLINE)

    # CoM acceleration while the whole mass is on the incline, after the first 0.05 s (the loose
    # release packing collapses onto the incline first)
    win = ON_INCLINE & (T >= 0.05)
    a_cm, v0 = np.polyfit(T[win], V_CM[win], 1)
    print(f"flow: whole mass on the incline for t <= {T[ON_INCLINE].max():.3f} s; fit window "
          f"{T[win].min():.3f}-{T[win].max():.3f} s: CoM acceleration {a_cm:.3f} m/s^2 "
          f"({100 * (a_cm / a_coulomb - 1):+.1f} % vs Coulomb block)")
    i_stop = np.argmax(np.abs(V_CM) < 0.01) if np.any((np.abs(V_CM) < 0.01) & (T > 0.3)) else -1
    print(f"front reaches the run-out (s = {S_ARC_END:.3f} m) at t = {T[np.argmax(FRONT > S_ARC_END)]:.3f} s; "
          f"final leading beads s = {FRONT[-1]:.3f} m (x = {FRONT[-1] - S_ARC_END:.3f} m), "
          f"final front of the dense mass s = {DENSE[-1]:.3f} m (x = {DENSE[-1] - S_ARC_END:.3f} m), tail s = {TAIL[-1]:.3f} m, "
          f"CoM s = {S_CM[-1]:.3f} m; max CoM speed {V_CM.max():.3f} m/s; "
          f"final CoM speed {V_CM[-1]:.4f} m/s")
    del i_stop

    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(T, FRONT, ":", color="tab:red", label="leading beads (99.5 % quantile of s)")
    ax.plot(T, DENSE, "-", color="tab:red", label="front of the dense mass (>= 20 beads per 10 mm)")
    ax.plot(T, S_CM, "-", color="k", label="centre of mass")
    ax.plot(T, TAIL, "-", color="tab:blue", label="tail (0.5 % quantile of s)")
    tt = T[win]
    ax.plot(tt, S_CM[win][0] + V_CM[win][0] * (tt - tt[0]) + 0.5 * a_coulomb * (tt - tt[0]) ** 2, "--",
            color="tab:green", label=f"Coulomb block, a = {a_coulomb:.2f} m/s$^2$ (delta = {math.degrees(delta):.1f} deg)")
    ax.axhline(LENGTH, color="0.5", lw=0.8, ls=":")
    ax.axhline(S_ARC_END, color="0.5", lw=0.8, ls=":")
    ax.text(T[-1], LENGTH, "end of incline", ha="right", va="bottom", fontsize=8, color="0.4")
    ax.text(T[-1], S_ARC_END, "start of run-out", ha="right", va="bottom", fontsize=8, color="0.4")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("distance along the chute s (m)")
    ax.set_title("Hutter chute (40 deg, 5000 beads): front and centre of mass")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hutter_front_com.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(T, V_CM, "o-", ms=3, color="k", label="CoM velocity along the chute")
    ax.plot(tt, a_cm * tt + v0, "-", color="tab:orange", label=f"fit on the incline: {a_cm:.2f} m/s$^2$")
    ax.plot(tt, V_CM[win][0] + a_coulomb * (tt - tt[0]), "--", color="tab:green",
            label=f"Coulomb block: {a_coulomb:.2f} m/s$^2$")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("CoM velocity along the chute (m/s)")
    ax.set_title("Centre-of-mass velocity (tangent to the local chute surface)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hutter_com_velocity.png"), dpi=110)

    # final deposit: side view and thickness along the chute
    s, h, _, _ = profile_coords(last["x"], last["z"])
    speed = np.sqrt(last["vx"] ** 2 + last["vy"] ** 2 + last["vz"] ** 2)
    rest = speed < 0.01
    removed_file = os.path.join(HERE, "output", "flow", "removed.csv")
    n_removed = 0
    if os.path.exists(removed_file):
        n_removed = len(np.atleast_1d(np.genfromtxt(removed_file, delimiter=",", names=True)))
    print(f"end (t = {last['time'][0]:.2f} s): {len(speed)} beads in the domain, {n_removed} left it; "
          f"{100 * rest.mean():.1f} % at rest (|v| < 1 cm/s); median speed {np.median(speed):.2e} m/s; "
          f"beads at rest span x = {last['x'][rest].min():.3f} .. {last['x'][rest].max():.3f} m")
    top = h + last["radius"]
    bins = np.arange(0.0, S_ARC_END + RUNOUT + 1e-9, 0.01)
    idx = np.digitize(s, bins) - 1
    thick = np.array([np.percentile(top[idx == k], 95) if np.sum(idx == k) >= 3 else 0.0
                      for k in range(len(bins) - 1)])
    centres = 0.5 * (bins[1:] + bins[:-1])
    print(f"deposit: max thickness {thick.max() * 1e3:.1f} mm at s = {centres[np.argmax(thick)]:.3f} m "
          f"(x = {centres[np.argmax(thick)] - S_ARC_END:+.3f} m); beads on the incline "
          f"{np.sum(s < LENGTH)}, on the arc {np.sum((s >= LENGTH) & (s < S_ARC_END))}, "
          f"on the run-out {np.sum(s >= S_ARC_END)}")
    fig, ax = plt.subplots(2, 1, figsize=(9, 7))
    prof_x = np.concatenate(([X_TOP], X_ARC + 0 * np.arange(1),
                             -RADIUS * np.sin(np.linspace(ANGLE, 0, 30)), [RUNOUT]))
    prof_z = np.concatenate(([Z_TOP], [Z_ARC],
                             RADIUS * (1 - np.cos(np.linspace(ANGLE, 0, 30))), [0.0]))
    ax[0].plot(prof_x, prof_z, "k-", lw=1.5, label="chute surface")
    ax[0].scatter(last["x"], last["z"], s=0.5, c="tab:brown", label=f"beads at t = {last['time'][0]:.2f} s")
    ax[0].set_xlim(-0.25, RUNOUT + 0.02)
    ax[0].set_ylim(-0.005, 0.06)
    ax[0].set_xlabel("x (m)")
    ax[0].set_ylabel("z (m)")
    ax[0].set_title("Final deposit, side view of the transition and run-out (vertical scale exaggerated)")
    ax[0].legend(fontsize=8, markerscale=10)
    ax[0].grid(alpha=0.3)
    ax[1].plot(centres - S_ARC_END, thick * 1e3, "-", color="tab:brown")
    ax[1].axvline(0.0, color="0.5", ls=":", lw=0.8)
    ax[1].axvline(LENGTH - S_ARC_END, color="0.5", ls=":", lw=0.8)
    ax[1].text(0.0, ax[1].get_ylim()[1] * 0.9, " run-out", fontsize=8, color="0.4")
    ax[1].text(LENGTH - S_ARC_END, ax[1].get_ylim()[1] * 0.9, " arc", fontsize=8, color="0.4")
    ax[1].set_xlabel("distance along the chute from the start of the run-out, s - s$_{runout}$ (m)")
    ax[1].set_ylabel("deposit thickness normal\nto the surface (mm)")
    ax[1].set_title("Final deposit thickness (95 % quantile of bead tops in 10 mm bins)")
    ax[1].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hutter_deposit.png"), dpi=110)


if __name__ == "__main__":
    main()
