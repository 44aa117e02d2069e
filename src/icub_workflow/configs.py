"""Configs laid over configs: the test config over the default, a run's overrides over the main
run's config. Key by key, as Snakemake lays `--configfile` files over the Snakefile's config."""

from __future__ import annotations

import copy
from collections.abc import Mapping
from typing import Any


def merged(base: Mapping[str, Any], overrides: Mapping[str, Any]) -> dict[str, Any]:
    """`base` with `overrides` laid over it, dictionaries merged key by key (neither is changed)."""
    out = copy.deepcopy(dict(base))
    for key, value in overrides.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merged(out[key], value)
        else:
            out[key] = copy.deepcopy(value)
    return out


#: What tells the robot test's variants apart (config `robot`), in the order of their run names.
ROBOT_KEYS = ("categorisation_cue", "target", "hidden", "iterations", "learning_rate_schedule")


def robot_key(variant: Mapping[str, Any], network: Mapping[str, Any]) -> tuple:
    """A robot variant (an entry of robot.default or robot.animation.variant) as the grid's
    tuple; an entry that names no cue timing or learning-rate schedule has the config's own
    (network.categorisation_cue, network.learning_rate_schedule)."""
    cue = variant.get("categorisation_cue", network["categorisation_cue"])
    schedule = variant.get("learning_rate_schedule", network["learning_rate_schedule"])
    return (cue, variant["target"], variant["hidden"], variant["iterations"], schedule)


def robot_grid(robot: Mapping[str, Any]) -> list[tuple]:
    """Every variant of the grid robot.categorisation_cue x target x hidden x iterations x
    learning_rate_schedule."""
    import itertools

    return list(itertools.product(*(robot[key] for key in ROBOT_KEYS)))
