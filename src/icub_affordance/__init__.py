"""icub-affordance: reproducing Macura et al. (2009), "A Cognitive Robotic Model of Grasping".

Laid out like the paper: ``body`` (the simulated iCub, its grasps, demonstrations and vision),
``learning`` (the Kohonen maps and the Jordan network, and their training), ``trials`` (tests of
a trained network, in silico and on the robot) and ``analysis`` (the statistics, the paper's
claims and the tests added to them). Shared by all of them at the top: the vocabulary of objects,
grips and tasks (``vocabulary``), what a test shows (``outcome``), tests over replications
(``replicated``), file writing (``files``) and the figures (``figures``).
"""

import os

# MuJoCo renders offscreen on the CPU through EGL here (osmesa and glfw do not work); the choice
# must be made before mujoco is first imported, so the package makes it on import.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
