"""A network variant: the settings that tell the robot test's networks apart, in one place.

The robot test (config ``robot``) compares networks that differ in a few of the trainer's settings
(the cue timing, what the outputs learn, the hidden units, the iterations, the learning-rate
schedule). Everything that names, lists, checks or tabulates a variant asks this type: its
fields are the grid's dimensions (and the columns of the robot tables), their metadata say how a
run is named after them, and :meth:`NetworkVariant.network` builds the trainer's settings. A new
dimension is a new field here (and its key in the config schema's ``robot`` section).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from dataclasses import astuple, dataclass, field, fields
from typing import Any


def _dimension(name: str, always: bool, order: int, label: Callable[[Any], str]) -> Any:
    """A field of the grid: its part of a run's name (``name`` formats the value), whether that
    part is written when the value is the config's own (``always``), where it goes, and its
    words in a label (``label``)."""
    return field(metadata={"name": name, "always": always, "order": order, "label": label})


#: The learning-rate schedules in words.
SCHEDULE_WORDS = {"constant": "constant rate", "anneal": "annealed rate"}


@dataclass(frozen=True)
class NetworkVariant:
    """One point of the robot test's grid, keyed as in config ``network``."""

    categorisation_cue: str = _dimension(
        "{}", always=False, order=3, label=lambda v: f"cue {str(v).replace('_', ' ')}"
    )
    target: str = _dimension("{}", always=True, order=0, label=str)
    hidden: int = _dimension("h{}", always=True, order=1, label=lambda v: f"{int(v)} hidden")
    iterations: int = _dimension(
        "it{}", always=True, order=2, label=lambda v: f"{int(v):,} iterations"
    )
    learning_rate_schedule: str = _dimension(
        "{}", always=False, order=4, label=lambda v: SCHEDULE_WORDS[v]
    )

    @classmethod
    def keys(cls) -> tuple[str, ...]:
        """The grid's dimensions, in the order of the tables' columns and the grid's product."""
        return tuple(f.name for f in fields(cls))

    @classmethod
    def of(cls, entry: Mapping[str, Any], network: Mapping[str, Any]) -> NetworkVariant:
        """A variant as written in the config (an entry of robot.default, robot.confirmation or
        robot.animation): a key the entry leaves out is the config's own (config ``network``)."""
        return cls(**{key: entry.get(key, network[key]) for key in cls.keys()})

    @classmethod
    def grid(cls, robot: Mapping[str, Any]) -> list[NetworkVariant]:
        """Every combination of the lists of config ``robot``, in the order of :meth:`keys`."""
        return [cls(*values) for values in itertools.product(*(robot[k] for k in cls.keys()))]

    def values(self) -> tuple:
        return astuple(self)

    def row(self) -> dict[str, Any]:
        """The variant's columns of a table."""
        return dict(zip(self.keys(), self.values(), strict=True))

    @classmethod
    def from_row(cls, row: Mapping[str, Any]) -> NetworkVariant:
        """The variant of a table's row (its columns :meth:`keys`)."""
        return cls(**{key: row[key] for key in cls.keys()})

    def label(self, leave_out: tuple[str, ...] = ()) -> str:
        """The variant in words, every setting named but those in ``leave_out``."""
        return ", ".join(
            f.metadata["label"](getattr(self, f.name))
            for f in fields(self)
            if f.name not in leave_out
        )

    def network(self, network: Mapping[str, Any]) -> dict[str, Any]:
        """The trainer's settings of this variant laid over ``network``: phase 1 keeps the
        config's share of the iterations, rounded so that phase 2 splits evenly between tasks."""
        phase1 = round(self.iterations * network["phase1_iterations"] / network["iterations"])
        phase1 += (self.iterations - phase1) % 2
        return self.row() | {"phase1_iterations": phase1}

    def run_name(self, network: Mapping[str, Any]) -> str:
        """The run's name: what it sets, each part once, leaving out what equals the config's."""
        parts = sorted(fields(self), key=lambda f: f.metadata["order"])
        words = [
            f.metadata["name"].format(getattr(self, f.name))
            for f in parts
            if f.metadata["always"] or getattr(self, f.name) != network[f.name]
        ]
        return "_".join(["robot", *words])
