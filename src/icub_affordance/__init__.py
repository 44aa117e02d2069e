"""icub-affordance: reproducing Macura et al. (2009), "A Cognitive Robotic Model of Grasping".

Laid out like the paper, in layers that import only downwards: ``learning`` (the Kohonen maps
and the Jordan network, and their training), ``body`` (the simulated iCub, its grasps,
demonstrations and vision), ``trials`` (tests of a trained network, in silico and on the
robot) and ``analysis`` (the statistics of the trials, the hidden states and the contacts, the
paper's claims and the tests added to them). At the top, below them all: the vocabulary of
objects, grips and tasks (``vocabulary``), what a test shows (``outcome``) and file writing
(``files``); above them all: the figures (``figures``) and the robot's films (``animation``).
"""

import os

# MuJoCo renders offscreen on the CPU through EGL here (osmesa and glfw do not work); the choice
# must be made before mujoco is first imported, so the package makes it on import.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
