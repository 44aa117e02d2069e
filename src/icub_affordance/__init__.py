"""icub-affordance: reproducing Macura et al. (2009), "A Cognitive Robotic Model of Grasping"."""

import os

# MuJoCo renders offscreen on the CPU through EGL here (osmesa and glfw do not work); the choice
# must be made before mujoco is first imported, so the package makes it on import.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
