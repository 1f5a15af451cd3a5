"""Assertions of the heap example's short check (check.sh; tests/CMakeLists.txt
Examples.ClumpHeapShort). Python's standard library only.

Usage: check_heap.py R_DISK TETRA_RUN_DIR SPHERE_RUN_DIR

The short heap (disk of radius 20 mm, 150 bodies) is small, a few grains high, so each measure
scatters: with seeds 1 and 2 the sector-fit angles came out 34.4 +- 3.9 and 27.8 +- 2.9 deg
(clumps) and 9.8 +- 3.3 and 11.8 +- 4.8 deg (spheres), the apex angles 31.2, 33.1 and 21.0,
24.1 deg, the bodies left on the disk 63, 70 and 47, 53. The full example (README.md) measures
36.1 +- 1.1 against 21.7 +- 0.6 deg. Asserted, each with a margin of about twice the scatter:
- each heap still stands on the disk (at least MIN_BODIES bodies);
- the angles lie in TETRA_RANGE and SPHERE_RANGE;
- the clumps stand steeper than the spheres (the shape's interlocking and rolling resistance, the
  trend of the literature): by MIN_FIT_DIFFERENCE in the sector fits, by MIN_APEX_DIFFERENCE in
  the apex angle, and the disk keeps MIN_KEPT_RATIO times more clump bodies than spheres (a cone on
  the disk holds a volume proportional to the tangent of its angle; bodies of equal volume).
"""

import sys

from heap_angle import measure

MIN_BODIES = 30
TETRA_RANGE = (20.0, 50.0)  # deg
SPHERE_RANGE = (0.0, 25.0)  # deg
MIN_FIT_DIFFERENCE = 5.0  # deg
MIN_APEX_DIFFERENCE = 4.0  # deg
MIN_KEPT_RATIO = 1.15


def main():
    r_disk = float(sys.argv[1])
    tetra, sphere = measure(sys.argv[2], r_disk), measure(sys.argv[3], r_disk)
    failures = []
    for name, m, (lo, hi) in (("tetra", tetra, TETRA_RANGE), ("sphere", sphere, SPHERE_RANGE)):
        print(f"{name}: angle of repose {m['angle']:.1f} +- {m['err']:.1f} deg (sectors "
              + " ".join(f"{a:.1f}" for a in m["sectors"]) + f"), apex angle {m['apex_angle']:.1f} deg, "
              f"{m['bodies_on_disk']} bodies on the disk at t = {m['time']:.2f} s")
        if m["bodies_on_disk"] < MIN_BODIES:
            failures.append(f"{name}: only {m['bodies_on_disk']} bodies on the disk (expected >= {MIN_BODIES})")
        if not lo <= m["angle"] <= hi:
            failures.append(f"{name}: angle {m['angle']:.1f} deg outside [{lo}, {hi}] deg")
    fit = tetra["angle"] - sphere["angle"]
    apex = tetra["apex_angle"] - sphere["apex_angle"]
    kept = tetra["bodies_on_disk"] / sphere["bodies_on_disk"]
    print(f"tetra - sphere: fits {fit:.1f} deg (expected >= {MIN_FIT_DIFFERENCE}), apex {apex:.1f} deg (expected >= "
          f"{MIN_APEX_DIFFERENCE}); bodies kept tetra / sphere {kept:.2f} (expected >= {MIN_KEPT_RATIO})")
    if fit < MIN_FIT_DIFFERENCE:
        failures.append(f"the clumps' fitted angle exceeds the spheres' by {fit:.1f} deg only")
    if apex < MIN_APEX_DIFFERENCE:
        failures.append(f"the clumps' apex angle exceeds the spheres' by {apex:.1f} deg only")
    if kept < MIN_KEPT_RATIO:
        failures.append(f"the disk keeps {kept:.2f} times more clumps than spheres only")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("heap check passed")


if __name__ == "__main__":
    main()
