"""The robot's visual input (paper section 2.2, Figure 3): an edge map of the foveated object.

Eye image -> Sobel edges of the R, G and B channels -> the strongest of the three -> a fixed-size
window at the fixation point -> binary edges -> a 10x10 map. The window is the same size for
every object, so the map carries the object's size as well as its outline.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import cv2
import numpy as np

from icub_affordance.body.robot import Robot


@dataclass(frozen=True)
class VisionConfig:
    width: int = 320  # eye image, pixels
    height: int = 240
    window: int = 100  # side of the foveated window, pixels (a multiple of `grid`)
    grid: int = 10  # the map is grid x grid
    edge_threshold: float = 60.0  # Sobel magnitude (0-255 image units) that counts as an edge
    eye: str = "left_eye"

    def __post_init__(self) -> None:
        if self.window % self.grid or self.window > min(self.width, self.height):
            raise ValueError(
                f"vision window {self.window} must be a multiple of grid {self.grid} "
                f"and fit in the {self.width}x{self.height} eye image"
            )


@dataclass(frozen=True)
class VisualStages:
    """What Figure 3 shows for one object."""

    eye: np.ndarray  # (H, W, 3) uint8, the full eye image
    sobel: np.ndarray  # (window, window) float, the combined edge magnitude
    edges: np.ndarray  # (window, window) uint8 0/1
    visual_map: np.ndarray  # (grid, grid) uint8 0/1


def render_eye(robot: Robot, config: VisionConfig) -> np.ndarray:
    """The eye's RGB image without cast shadows: the map should hold the object's own outline."""
    return robot.render(config.eye, config.width, config.height, shadows=False)


def sobel_rgb(image: np.ndarray) -> np.ndarray:
    """Edge magnitude per colour channel (three Sobel filters), combined by taking the strongest."""
    image = image.astype(np.float32)
    magnitudes = []
    for channel in range(3):
        gx = cv2.Sobel(image[..., channel], cv2.CV_32F, 1, 0, ksize=3)
        gy = cv2.Sobel(image[..., channel], cv2.CV_32F, 0, 1, ksize=3)
        magnitudes.append(np.hypot(gx, gy) / 4.0)  # /4: a unit step reads as its height
    return np.max(magnitudes, axis=0)


def foveate(image: np.ndarray, window: int) -> np.ndarray:
    """The window centred on the image centre, where the fixated object is (the eyes foveate)."""
    h, w = image.shape[:2]
    top, left = (h - window) // 2, (w - window) // 2
    return image[top : top + window, left : left + window]


def to_map(edges: np.ndarray, grid: int) -> np.ndarray:
    """A cell is 1 if any edge pixel falls in it."""
    n = edges.shape[0] // grid
    return edges.reshape(grid, n, grid, n).max(axis=(1, 3)).astype(np.uint8)


def visual_stages(robot: Robot, obj: str, config: VisionConfig) -> VisualStages:
    robot.place_object(obj)
    eye = render_eye(robot, config)
    sobel = foveate(sobel_rgb(eye), config.window)
    edges = (sobel >= config.edge_threshold).astype(np.uint8)
    return VisualStages(eye, sobel, edges, to_map(edges, config.grid))


def visual_maps(
    robot: Robot, objects: tuple[str, ...], config: VisionConfig
) -> dict[str, VisualStages]:
    """Figure 3's stages for every object, each seen on the spot from the same posture."""
    return {obj: visual_stages(robot, obj, config) for obj in objects}


def check_seen(maps: dict[str, np.ndarray], edge_threshold: float) -> None:
    """Refuse visual maps that would make the rest meaningless: an object the eye does not see
    (no edge cell: the networks would learn from a blank Object map) or two objects it cannot
    tell apart (equal maps: size and shape could not matter). Names the objects and the fix."""
    blind = [obj for obj, m in maps.items() if not np.any(m)]
    if blind:
        raise ValueError(
            f"the eye sees no edge of {blind}: their visual maps have 0 edge cells at config "
            f"vision.edge_threshold = {edge_threshold:g} (Sobel magnitude, 0-255 image units), "
            "so the networks would learn from a blank Object map. Lower vision.edge_threshold "
            "(config/config.yaml has 60), or check the scene and vision.eye."
        )
    same = [(a, b) for a, b in combinations(maps, 2) if np.array_equal(maps[a], maps[b])]
    if same:
        raise ValueError(
            f"the visual maps of {same} are identical at config vision.edge_threshold = "
            f"{edge_threshold:g} (window {next(iter(maps.values())).shape}): the robot cannot "
            "tell these objects apart, and their size or shape could not affect the results. "
            "Change vision.edge_threshold, vision.window or vision.grid (config/config.yaml: "
            "60, 100, 10)."
        )
