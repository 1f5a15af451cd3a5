"""Assertions of the silo example's short check (check.sh; tests/CMakeLists.txt
Examples.ClumpSiloShort). Python's standard library only.

Usage: check_silo.py T_OPEN WIDTH TETRA_RUN_DIR SPHERE_RUN_DIR

Asserted, with the reasons for the tolerances:
- the lid holds: no mass below the orifice plane before T_OPEN (exactly);
- the flow starts at once: the first body below the plane within FIRST_WITHIN s after T_OPEN (a
  body's centre falls the 3 mm of its reach in 25 ms from rest);
- both shapes flow without an arch lasting 0.1 s and discharge at least MIN_DISCHARGED of the fill;
- the rates are comparable: W(tetra) / W(sphere) in RATIO_RANGE. Measured 0.85 and 0.95 in this
  short set-up (lid removed at 0.2 and 0.15 s); in the full example (README.md) 0.71-0.96 per fill,
  0.84 +- 0.16 and 0.91 +- 0.04 on average: the clumps discharge somewhat slower, but one short
  window scatters as much as the difference, so the check asserts the range only, not the sign;
- the clumps pack looser: bulk density of the settled fill below the spheres' by MIN_LOOSER or more
  (measured 7 % here, 4 % in the full example, every run).
"""

import sys

from silo_rate import measure

FIRST_WITHIN = 0.05  # s
MIN_DISCHARGED = 0.15
RATIO_RANGE = (0.65, 1.2)
MIN_LOOSER = 0.02


def main():
    t_open, width = float(sys.argv[1]), float(sys.argv[2])
    runs = {"tetra": measure(sys.argv[3], t_open, width=width), "sphere": measure(sys.argv[4], t_open, width=width)}
    failures = []
    for name, m in runs.items():
        print(f"{name}: W = {m['rate']:.4f} +- {m['err']:.4f} kg/s over t = {m['window'][0]:.3f}-{m['window'][1]:.3f} s, "
              f"bulk density {m['bulk']:.0f} kg/m^3, first below the orifice at t = {m['first']:.3f} s, mass below "
              f"before the opening {m['before']} kg, discharged {m['reached']:.1%}, jam {m['jam']}")
        if m["before"] != 0.0:
            failures.append(f"{name}: {m['before']} kg below the orifice before the lid is removed")
        if m["first"] is None or not t_open < m["first"] <= t_open + FIRST_WITHIN:
            failures.append(f"{name}: first body below the orifice at {m['first']} s, expected within "
                            f"({t_open}, {t_open + FIRST_WITHIN}] s")
        if m["jam"] is not None:
            failures.append(f"{name}: the flow stopped at t = {m['jam']} s")
        if m["reached"] < MIN_DISCHARGED:
            failures.append(f"{name}: only {m['reached']:.1%} discharged (expected >= {MIN_DISCHARGED:.0%})")
    ratio = runs["tetra"]["rate"] / runs["sphere"]["rate"]
    looser = 1.0 - runs["tetra"]["bulk"] / runs["sphere"]["bulk"]
    print(f"W(tetra) / W(sphere) = {ratio:.3f} (expected in {RATIO_RANGE}); tetra fill looser by {looser:.1%} "
          f"(expected >= {MIN_LOOSER:.0%})")
    if not RATIO_RANGE[0] <= ratio <= RATIO_RANGE[1]:
        failures.append(f"W(tetra) / W(sphere) = {ratio:.3f} outside {RATIO_RANGE}")
    if looser < MIN_LOOSER:
        failures.append(f"the clumps' fill is looser by {looser:.1%} only")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("silo check passed")


if __name__ == "__main__":
    main()
