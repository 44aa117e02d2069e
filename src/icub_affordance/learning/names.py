"""Object names, the paper's proposed next step (section 4; book/notes.md, "Names"): an input
that identifies an object without showing it.

A name is **localist**: each object owns a block of ``units_per_name`` units, on for its name
and off for every other (after the localist codes of Yoon et al.'s naming-and-action model,
which the paper cites). Every two names are then equally far apart and equally active, so
nothing in the pattern sets a big ball's name nearer to the big cube's than to the small
ball's: a name carries its object's identity and nothing of its size or shape. A distributed
code would have to be drawn at random, and its chance overlaps could line up with size. The
block's width sets how strongly a name drives the Object map against the visual map's edge
cells (4-43 for the four objects).

A name enters where the visual map goes (``routes``): beside it into the network's hidden layer
(its units appended after the Goal map's input), and into the Object map (appended to the visual
map), and so through the Goal map. A trial shows its object's image, its name, or both
(vocabulary.FORMS); training shows each form on declared shares of each phase's trials.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from icub_affordance.vocabulary import FORMS, NAME_ROUTES

PATTERNS: tuple[str, ...] = ("localist",)


@dataclass(frozen=True)
class NamesConfig:
    """A run's names (config key ``names``, where the values are described), when ``use``."""

    pattern: str  # one of PATTERNS
    units_per_name: int
    routes: tuple[str, ...]  # a subset of NAME_ROUTES
    phase1: tuple[int, ...]  # the forms' weights in phase 1 (FORMS order): shares of its trials
    phase2: tuple[int, ...]  # the same in phase 2

    def __post_init__(self) -> None:
        if self.pattern not in PATTERNS:
            raise ValueError(f"names.pattern must be one of {PATTERNS}, not {self.pattern!r}")
        if self.units_per_name < 1:
            raise ValueError("names.units_per_name must be 1 or more")
        if not self.routes or set(self.routes) - set(NAME_ROUTES):
            raise ValueError(f"names.routes must be a non-empty subset of {NAME_ROUTES}")
        for phase in (self.phase1, self.phase2):
            if len(phase) != len(FORMS) or min(phase) < 0 or sum(phase) == 0:
                raise ValueError(
                    f"names.training: each phase gives a weight of 0 or more to each of {FORMS}, "
                    "not all 0"
                )

    @classmethod
    def of(cls, names: Mapping) -> NamesConfig | None:
        """The config block ``names`` as settings, or None when names are not used (the
        paper's model: nothing of this module acts)."""
        if not names["use"]:
            return None
        training = names["training"]
        return cls(
            pattern=names["pattern"],
            units_per_name=int(names["units_per_name"]),
            routes=tuple(names["routes"]),
            phase1=tuple(int(training["phase1"].get(form, 0)) for form in FORMS),
            phase2=tuple(int(training["phase2"].get(form, 0)) for form in FORMS),
        )

    @property
    def trained_forms(self) -> tuple[str, ...]:
        """The forms some training trial shows (the Object map learns from these)."""
        return tuple(f for f, a, b in zip(FORMS, self.phase1, self.phase2, strict=True) if a + b)


def name_patterns(n_objects: int, units_per_name: int) -> np.ndarray:
    """Each object's name (objects, objects * units_per_name): localist blocks of ones."""
    return np.kron(np.eye(n_objects), np.ones((1, units_per_name)))


def shown(visual: np.ndarray, names: np.ndarray, form: str) -> tuple[np.ndarray, np.ndarray]:
    """What a trial of ``form`` shows: the visual maps (objects, ...) blanked (all 0, an empty
    retina) unless the image is shown, and the names (objects, units) all 0 unless the name is."""
    if form not in FORMS:
        raise ValueError(f"a trial shows one of {FORMS}, not {form!r}")
    image, name = form in ("image", "both"), form in ("name", "both")
    return visual * image, names * name


def form_counts(weights: tuple[int, ...], iterations: int) -> np.ndarray:
    """How many of a phase's ``iterations`` show each form: the weights' shares, exactly."""
    total = sum(weights)
    counts = np.array([iterations * w // total for w in weights])
    if counts.sum() != iterations:
        raise ValueError(
            f"names.training: the weights {dict(zip(FORMS, weights, strict=True))} do not divide "
            f"a phase's {iterations} iterations into whole shares; choose weights whose sum "
            "divides the phase's iterations"
        )
    return counts


def form_schedule(
    config: NamesConfig, phase1_iterations: int, iterations: int, rng: np.random.Generator
) -> np.ndarray:
    """The form (an index into FORMS) each iteration shows: each phase's shares, in random order
    within the phase."""
    phases = ((config.phase1, phase1_iterations), (config.phase2, iterations - phase1_iterations))
    return np.concatenate(
        [
            rng.permutation(np.repeat(np.arange(len(FORMS)), form_counts(weights, n)))
            for weights, n in phases
        ]
    ).astype(np.int64)
