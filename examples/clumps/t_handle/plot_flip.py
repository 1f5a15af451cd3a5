#!/usr/bin/env python3
"""The T-handle in free space: its body-frame angular velocity against time, |L| and the energy,
and the flip interval against the Jacobi elliptic solution of Euler's equations (Landau &
Lifshitz, Mechanics, section 37); writes flip.png and results.txt."""
import csv
import glob
import math
import sys

CHECK = "--check" in sys.argv  # the test suite's check: the numbers only, no plot


def rot(q):
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def agm_k(k):
    """Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    while abs(a - b) > 1e-15 * a:
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


t, wb, E, L = [], [], [], []
for f in sorted(glob.glob("output/bodies_csv/bodies_*.csv")):
    with open(f) as fh:
        r = next(csv.DictReader(fh))
    R = rot([float(r[k]) for k in ("q0", "q1", "q2", "q3")])  # template frame -> world
    w = [float(r[k]) for k in ("wx", "wy", "wz")]
    # The template's axes are principal: x (largest moment I3), y (I2), z (smallest, I1).
    I = [float(r["I3"]), float(r["I2"]), float(r["I1"])]
    b = [sum(R[i][j] * w[i] for i in range(3)) for j in range(3)]  # R^T w
    lb = [I[j] * b[j] for j in range(3)]
    lw = [sum(R[i][j] * lb[j] for j in range(3)) for i in range(3)]
    t.append(float(r["time"]))
    wb.append(b)
    E.append(0.5 * sum(I[j] * b[j] ** 2 for j in range(3)))
    L.append(lw)

# Sign changes of the intermediate component (the handle turns over), linearly interpolated.
cross = []
for k in range(1, len(t)):
    a, c = wb[k - 1][1], wb[k][1]
    if a * c < 0:
        cross.append(t[k - 1] + (t[k] - t[k - 1]) * a / (a - c))
measured = (cross[-1] - cross[0]) / (len(cross) - 1)

# Elliptic solution: moments I1 < I2 < I3 (template z, y, x), energy and |L|^2 of the start.
I1, I2, I3 = float(r["I1"]), float(r["I2"]), float(r["I3"])
E0 = E[0]
L2 = sum(x * x for x in L[0])
if L2 > 2 * E0 * I2:
    lam = math.sqrt((I3 - I2) * (L2 - 2 * E0 * I1) / (I1 * I2 * I3))
    k2 = (I2 - I1) * (2 * E0 * I3 - L2) / ((I3 - I2) * (L2 - 2 * E0 * I1))
else:
    lam = math.sqrt((I2 - I1) * (2 * E0 * I3 - L2) / (I1 * I2 * I3))
    k2 = (I3 - I2) * (L2 - 2 * E0 * I1) / ((I2 - I1) * (2 * E0 * I3 - L2))
half_period = 2.0 * agm_k(math.sqrt(k2)) / lam  # s, between sign changes of w2
dL = max(math.sqrt(sum((a - b) ** 2 for a, b in zip(l, L[0]))) for l in L) / math.sqrt(L2)
dE = max(abs(e - E0) for e in E) / E0

if CHECK:
    # Issue 47's acceptance: 10 flips or more, L and E within 1e-6, the period within 1 %.
    err = abs(measured - half_period) / half_period
    print(f"{len(cross) - 1} flip intervals: {measured:.6f} s, elliptic {half_period:.6f} s ({err:.2e}); "
          f"|dL|/|L| {dL:.2e}, |dE|/E {dE:.2e}")
    sys.exit(0 if len(cross) - 1 >= 10 and err < 0.01 and dL < 1e-6 and dE < 1e-6 else 1)

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
for j, name in enumerate(("x (I3, largest)", "y (I2, intermediate)", "z (I1, smallest)")):
    a1.plot(t, [b[j] for b in wb], label="w' " + name)
a1.set_ylabel("body-frame w (rad/s)")
a1.legend(fontsize=8)
a1.set_title(f"T-handle: {len(cross) - 1} flip intervals, measured {measured:.5f} s, elliptic {half_period:.5f} s")
a2.plot(t, [e / E0 - 1 for e in E], label="E / E0 - 1")
a2.plot(t, [math.sqrt(sum((a - b) ** 2 for a, b in zip(l, L[0]))) / math.sqrt(L2) for l in L], label="|L - L0| / |L0|")
a2.set_xlabel("t (s)")
a2.legend(fontsize=8)
fig.tight_layout()
fig.savefig("flip.png", dpi=120)

with open("results.txt", "w") as out:
    out.write("T-handle of 5 touching spheres (r = 1 mm, steel), w' = (0.1, 100, 0.1) rad/s, verlet, dt = 3e-5 s (T_rot / 2094)\n")
    out.write(f"principal moments I1, I2, I3 = {I1:.6e}, {I2:.6e}, {I3:.6e} kg m^2\n")
    out.write(f"flip intervals measured: {len(cross) - 1}, mean {measured:.6f} s; elliptic T/2 = {half_period:.6f} s; "
              f"relative difference {abs(measured - half_period) / half_period:.2e}\n")
    out.write(f"largest |L - L0| / |L0| = {dL:.2e}; largest |E - E0| / E0 = {dE:.2e}\n")
print(open("results.txt").read())
