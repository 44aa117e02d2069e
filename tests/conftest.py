"""Shared fixtures: the robot is cheap to load, so most tests take a fresh one."""

from __future__ import annotations

from pathlib import Path

import pytest

from icub_affordance.body import Robot

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture
def robot() -> Robot:
    r = Robot(REPO / "assets" / "icub_scene.xml")
    yield r
    r.close()
