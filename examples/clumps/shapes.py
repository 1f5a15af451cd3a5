"""The two grain shapes of the heap and silo examples (examples/clumps/heap, examples/clumps/silo)
and the time step, gravity, contacts and material the two share.

A tetrahedral clump of four spheres of radius R whose centres sit on the vertices of a regular
tetrahedron R from its centre (they overlap: centre distance 1.633 R), and the sphere of the same
volume. Units: m.
"""

import math

R = 0.0015  # m, member radius
# Volume of the union of the four members for R = 1.5 mm, as `mpdem check` prints it (integrated,
# relative error estimate 3e-9): 3.72 times one member's volume.
V_TETRA = 5.26049e-08  # m^3
R_EQ = (3.0 * V_TETRA / (4.0 * math.pi)) ** (1.0 / 3.0)  # m, 2.3246 mm
REACH = 2.0 * R  # m, largest distance of a member's surface from the body's centre


def tetra_members_toml():
    """The [[clump]] members array: rows [x, y, z, radius] (m)."""
    a = R / math.sqrt(3.0)
    rows = [[s1 * a, s2 * a, s1 * s2 * a, R] for s1, s2 in ((1, 1), (1, -1), (-1, 1), (-1, -1))]
    return "[" + ", ".join("[" + ", ".join(f"{v:.17g}" for v in m) + "]" for m in rows) + "]"


def bodies_toml(shape, generate, material="grain"):
    """The [[clump]] and [[particles]] entries of `shape` ("tetra" or "sphere"); `generate` is the
    inline table's keys without radius and placement."""
    if shape == "tetra":
        return (f'[[clump]]\nname = "tetra"\nmembers = {tetra_members_toml()}   # x, y, z, radius (m)\n\n'
                f'[[particles]]\nclump = "tetra"\nmaterial = "{material}"\n'
                f'generate = {{ {generate}, placement = "members" }}\n')
    return f'[[particles]]\nmaterial = "{material}"\ngenerate = {{ {generate}, radius = {R_EQ!r} }}\n'


def physics_toml(duration, dt):
    """[time], [gravity], the contact tables and the material "grain" (the same for both shapes:
    Hertz-Mindlin, e = 0.5, mu = 0.5, no rolling resistance)."""
    return f"""[time]
duration = {duration!r}       # s
integrator = "verlet"
dt = {dt!r}             # s

[gravity]
vector = [0.0, 0.0, -9.81]

[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5

[contact.particle_barrier]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5

[[material]]
name = "grain"
density = 2500.0          # kg/m^3
young = 5e6               # Pa, softened (glass ~6e10) for a larger time step
poisson = 0.3
"""
