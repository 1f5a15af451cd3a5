"""mpdem: multiphysics soft-sphere DEM. docs/python.md is the reference.

    import mpdem
    scene = mpdem.Scene.from_toml("scene.toml")
    sim = mpdem.Simulation(scene, threads=2)
    sim.run(duration=0.1, callback=lambda s: print(s.time), every=1000)
    x = sim.particles.position        # (N, 3) m, in id order
"""

from ._core import InputError, RunError, __version__
from .scene import Scene
from .bodies import Bodies
from .simulation import Bonds, Particles, Simulation

__all__ = ["Bodies", "Bonds", "InputError", "RunError", "Particles", "Scene", "Simulation", "__version__"]
