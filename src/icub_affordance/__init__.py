"""icub-affordance: reproducing Macura et al. (2009), "A Cognitive Robotic Model of Grasping"."""

__version__ = "0.1.0"
