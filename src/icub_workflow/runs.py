"""The runs of the model a config asks for, planned once and before any rule: a pure function.

A run is the model made once: demonstrations, maps, networks and their tests, for one config.
The config's own run (its networks are the paper's model) is one run among the others: the runs
of config ``runs``, the cue ablation (the other cue timing), the sweep's points, the readings'
replications, the robot test's variants and their confirmations. Each is the config with a few
settings laid over it. :func:`plan_runs` names them, finds which of them are one and the same run
(a reading at the config's own settings *is* the config's run), and records which earlier run's
demonstrations and maps each one reuses. The rules ask the plan; only :meth:`RunPlan.path`
knows where a run's files live.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from icub_affordance.analysis.paper_claims import seeds as claim_seeds
from icub_affordance.learning.variants import NetworkVariant
from icub_affordance.vocabulary import AFTER_PHASE1
from icub_workflow.config_checks import ConfigError
from icub_workflow.configs import merged
from icub_workflow.parts import part_names

#: The config's own run: its name in the tables (column ``run``).
MAIN = "main"

#: The shape of every run's folder (``RunPlan.folder``): empty, or ``runs/{run}/``.
FOLDER_PATTERN = r"(?:runs/[^/]+/)?"

#: A measured run's files that its seed's one job makes (rule ``measured``: the steps soms,
#: train and measures), by their path in the run's folder: they live in the job's folder.
MEASURED_FILES = ("soms/", "train/", "eval/measures.")

#: What asked for a run (``Run.origin``), in words for a refusal.
ORIGIN_WORDS = {"main": "config's own run", "configured": "run of config `runs`",
                "ablation": "cue ablation", "sweep": "sweep point", "reading": "reading",
                "robot": "robot variant", "confirmation": "robot variant's confirmation",
                "size_dose": "size study's run", "words": "words study's run"}  # fmt: skip

#: The settings each shared stage depends on: a run reuses the stage of the first run (in the
#: plan's order) whose settings for it are equal, so a run that changes only the network reuses
#: the config's demonstrations and maps, and two sweep points with one seed share theirs.
_SCENE = ("scene", "objects", "object_sizes_m", "initial_posture_deg")
STAGE_SETTINGS = {
    "maps": (*_SCENE, "vision", "size_free_input"),
    "demos": ("seed", *_SCENE, "demos"),
    "soms": ("seed", *_SCENE, "vision", "size_free_input", "soms", "names"),
}


@dataclass(frozen=True)
class Run:
    """One run: its name, the settings laid over the config, the config that results, and what
    asked for it first (main, configured, ablation, sweep, reading, robot, confirmation)."""

    name: str
    overrides: Mapping[str, Any]
    config: Mapping[str, Any]
    origin: str

    def networks(self) -> list[str]:
        """The run's network indices, as two digits (each network's seed comes from its index):
        0.. for every run but a confirmation, whose fresh ones start at its first_network."""
        network = self.config["network"]
        first = network.get("first_network", 0)
        return [f"{i:02d}" for i in range(first, first + network["networks"])]


@dataclass(frozen=True)
class RunPlan:
    """Every run a config asks for, in the order that decides whose stages a run shares, and the
    tables that say which run answers which question."""

    runs: dict[str, Run]
    #: the runs the default target makes in full beside the config's own: config ``runs`` and
    #: the cue ablation
    configured: list[str]
    ablation: str
    sweep: dict[str, dict[str, Any]]  # point -> its seed and swept network settings
    #: one row per reading and replication: reading, cue, goal_response, seed, run
    readings: list[dict[str, Any]]
    #: one row per robot variant: run, the variant's keys, default (tested without robustness)
    robot_variants: list[dict[str, Any]]
    #: one row per confirmed variant: its keys, its exploration run and its confirmation run
    confirmation: list[dict[str, Any]]
    #: one row per dose (or "removed"), cue timing and replication: dose, cue, seed, run
    size_dose: list[dict[str, Any]]
    robustness: bool
    #: one row per words replication (config ``words``: names on): cue, seed, run
    words: list[dict[str, Any]]

    # ---- where a run's files live (the one place that knows) ----------------------------------

    def folder(self, run: str) -> str:
        """A run's folder under ``data/``: the config's own at the top, every other run under
        ``runs/{run}/`` (ends with a slash, or is empty)."""
        return "" if self.runs[run].origin == "main" else f"runs/{run}/"

    def path(self, run: str, relative: str) -> str:
        """A run's file: ``relative`` in its folder under ``data/``; a measured run's files of
        the steps its seed's job makes (``MEASURED_FILES``) in that job's folder instead
        (``group_folder``: ``measured/seed<n>/{run}/``)."""
        group = self.group(run)
        if group is not None and relative.startswith(MEASURED_FILES):
            return f"data/{self.group_folder(group)}{run}/{relative}"
        return f"data/{self.folder(run)}{relative}"

    def group(self, run: str) -> str | None:
        """The seed's group (``measured_groups``) whose one job trains and measures this run,
        or None (the run's steps have their own rules)."""
        run_config = self.runs[run]
        if run_config.origin not in ("reading", "size_dose"):
            return None
        return f"seed{run_config.config['seed']}"

    @staticmethod
    def group_folder(group: str) -> str:
        """The folder under ``data/`` that a measured group's job makes whole (rule
        ``measured``'s one output, a directory): each of its runs' files in ``{run}/``."""
        return f"measured/{group}/"

    def container(self, path: str) -> str:
        """What a rule names to read ``path``: the file, or, for a file that a measured
        group's job makes, that job's folder (an input cannot name a file inside a folder
        that another rule makes whole)."""
        prefix = "data/measured/"
        if path.startswith(prefix):
            return prefix + path[len(prefix) :].split("/", 1)[0]
        return path

    def run_in(self, folder: str) -> str:
        """The run whose folder is ``folder`` (the inverse of :meth:`folder`); a folder no run
        of this config has is refused, naming it."""
        try:
            return self._by_folder()[folder]
        except KeyError:
            raise KeyError(
                f"no run of this config lives in data/{folder}: a run's files are in data/ (the "
                "config's own) or data/runs/{run}/ for a run the plan makes (RunPlan.runs); "
                "check the path asked for, or the config that plans the run"
            ) from None

    def folders(self, runs: list[str] | None = None) -> list[str]:
        return [self.folder(run) for run in (self.runs if runs is None else runs)]

    def _by_folder(self) -> dict[str, str]:
        return {self.folder(run): run for run in self.runs}

    # ---- what a run makes and reuses -----------------------------------------------------------

    @property
    def own(self) -> Run:
        return self.runs[MAIN]

    def config(self, run: str) -> Mapping[str, Any]:
        return self.runs[run].config

    def networks(self, run: str) -> list[str]:
        return self.runs[run].networks()

    def stage_run(self, run: str, stage: str) -> str:
        """The run whose ``stage`` (demos, soms) outputs this run reads: the first with equal
        settings for it (itself, if none before it has them)."""
        return self._stage_owners[stage][run]

    @cached_property
    def _stage_owners(self) -> dict[str, dict[str, str]]:
        """For each stage, each run's ``stage_run``, found once (every Snakemake start asks a
        thousand times): the first run whose settings for the stage equal the run's."""
        owners: dict[str, dict[str, str]] = {}
        for stage, keys in STAGE_SETTINGS.items():
            firsts: list[tuple[list[Any], str]] = []  # each distinct setting and its first run
            owners[stage] = {}
            for run in self.runs:
                setting = [self.config(run)[k] for k in keys]
                owner = next((first for seen, first in firsts if seen == setting), None)
                if owner is None:
                    firsts.append((setting, run))
                    owner = run
                owners[stage][run] = owner
        return owners

    def makes(self, run: str, stage: str) -> bool:
        """Does this run make its own ``stage`` (rather than read an earlier run's)?"""
        return self.stage_run(run, stage) == run

    def parts(self, run: str, step: str = "train") -> list[str]:
        """A run's networks as files of a step (``train`` or ``robot_test``;
        icub_workflow.parts): one part per network for the config's own run (a job each), else
        the one part ``all`` (one job: rule train or robot_test, or a measured run's seed's)."""
        if step not in ("train", "robot_test"):
            raise ValueError(f"no parts for the step {step!r}")
        return part_names(self.networks(run), self.jobs_per_network(run))

    def jobs_per_network(self, run: str) -> bool:
        """Is each network a job of its own (trained, and tested on the robot)? For the config's
        own run, whose networks every later stage waits on: in parallel at the start. Any other
        run trains its networks in one job (a network is short beside a job's start-up)."""
        return self.runs[run].origin == "main"

    # ---- which rule makes a run's step (the rules ask; none decides) ---------------------------
    # One rule per step serves every run, through the wildcards `folder` (the run) and, for the
    # networks, `part` (``parts``); only a measured run's steps go to its seed's one job, whose
    # folder holds their files (``path``), so no other rule's output matches them. The plan
    # says which rule serves each run's step; a rule that serves a few runs takes the folders
    # it names (``served_by``), the others any folder of the shape ``FOLDER_PATTERN``.

    def rule_for(self, run: str, step: str) -> str:
        """The rule that makes ``step`` (soms, train, measures, robot_test) for ``run``.

        - A reading's or the size study's run (``measured_groups``) is trained and scored on the
          measures with its seed's others in one job, its own maps too: ``measured``.
        - Every other run's step: the step's own rule, one job per part (``parts``): for
          ``train`` and ``robot_test``, a job per network of the config's own run, one job
          (part ``all``) for any other run's networks, whatever their indices.
        """
        if step not in ("soms", "train", "measures", "robot_test"):
            raise ValueError(f"no rule is named for the step {step!r}")
        measured = self.group(run) is not None
        return "measured" if measured and step != "robot_test" else step

    def served_by(self, rule: str, step: str) -> list[str]:
        """The runs whose ``step`` the rule ``rule`` makes (see ``rule_for``); for the robot
        test, among the runs tested on the robot."""
        runs = self.robot_tested_runs if step == "robot_test" else list(self.runs)
        return [run for run in runs if self.rule_for(run, step) == rule]

    @property
    def robot_tested_runs(self) -> list[str]:
        """Every run whose networks drive the robot: the tested variants and the confirmations."""
        return list(dict.fromkeys([*self.robot_runs, *self.confirmation_runs]))

    @property
    def phase1_owners(self) -> list[str]:
        """The runs that train a phase 1 for themselves and others (rule phase1)."""
        return list(dict.fromkeys(r for r in map(self.phase1_run, self.runs) if r is not None))

    @property
    def whole(self) -> list[str]:
        """The runs the default target makes in full, their in-silico tests included: the
        config's own, config ``runs`` and the cue ablation."""
        return [MAIN, *self.configured]

    @property
    def robot_runs(self) -> list[str]:
        """The robot variants tested in this build on the config's network indices: the
        config's own networks and those of robot.default (none in the shipped config), or every
        variant of the grid with robustness (the exploration). The confirmations' fresh
        networks are tested beside them (``robot_tested_runs``)."""
        return [row["run"] for row in self.robot_tested]

    @property
    def robot_tested(self) -> list[dict[str, Any]]:
        return [row for row in self.robot_variants if row["default"] or self.robustness]

    @property
    def confirmation_runs(self) -> list[str]:
        return [row["confirmation"] for row in self.confirmation]

    @property
    def confirmation_tested(self) -> list[dict[str, Any]]:
        """The confirmation rows as this build tests them: a variant's exploration run (its
        networks 0..) where this build tests it on the robot too (with robustness, or as an
        entry of robot.default), else None. The default build confirms on the fresh networks
        alone: the exploration was measured before (at full scale), and paying for it again in
        every build would buy a share that cannot move the verdict, which is the fresh
        networks'."""
        tested = set(self.robot_runs)
        return [
            row | {"exploration": row["exploration"] if row["exploration"] in tested else None}
            for row in self.confirmation
        ]

    def animated(self, entry: Mapping[str, Any]) -> tuple[str, list[str]]:
        """The run the book's films show for config robot.animation.variant ``entry``, and its
        first network of each mapping (the first half of a run's networks learn mapping A).
        The variant's own run where the default build tests it (the config's own networks or
        an entry of robot.default), else its confirmation's run: the fresh networks, so that
        the films are made at either scale without the exploration (a config check refuses a
        variant that is neither)."""
        run = self.variant_run(entry)
        if not next(row["default"] for row in self.robot_variants if row["run"] == run):
            fresh = {row["exploration"]: row["confirmation"] for row in self.confirmation}
            if run not in fresh:
                raise ValueError(
                    f"the animated variant {dict(entry)} is not tested in the default build: "
                    "not the config's own networks, an entry of robot.default or a confirmed "
                    "variant"
                )
            run = fresh[run]
        nets = self.networks(run)
        return run, [nets[0], nets[len(nets) // 2]]

    def phase1_run(self, run: str) -> str | None:
        """The run whose phase 1 this run's networks continue from (rule phase1), or None
        (it trains whole). Robot variants of this build, trained in one job, whose settings
        differ only in what acts after phase 1 (the cue timing, the learning-rate schedule:
        vocabulary.AFTER_PHASE1) share it: the first of them (in the plan's order) trains it once,
        and each continues from it to the same bits as when trained whole. Only for these long
        trainings: a short one costs less than its file."""
        if not self._may_share_phase1(run):
            return None
        key = _phase1_settings(self.config(run))
        sharing = [
            r
            for r in self.runs
            if self._may_share_phase1(r) and _phase1_settings(self.config(r)) == key
        ]
        return sharing[0] if len(sharing) > 1 else None

    def _may_share_phase1(self, run: str) -> bool:
        return (
            run in self.robot_runs  # tested in this build (all of the grid with robustness)
            and not self.jobs_per_network(run)
            and self.networks(run) == self.networks(MAIN)
        )

    @property
    def measured_groups(self) -> dict[str, list[str]]:
        """The runs that are trained and then only scored on the declared measures (the readings'
        and the size study's own runs), grouped by seed (``seed<n>``): one process trains and
        measures a group, so a dozen short runs pay one start-up."""
        groups: dict[str, list[str]] = {}
        for name in self.runs:
            group = self.group(name)
            if group is not None:
                groups.setdefault(group, []).append(name)
        return groups

    # ---- what the default target makes (the rules and the tests read it here) ------------------

    def built(self, users: bool = True) -> list[str]:
        """The runs the default target makes: the config's own, config ``runs`` (unless not
        ``users``) and the cue ablation (whole), the robot variants and confirmations tested in
        this build, the readings' and the size study's runs, and with robustness the sweep's
        points; each once."""
        user_runs = set(self.configured) - {self.ablation}
        runs = [
            *(run for run in self.whole if users or run not in user_runs),
            *self.robot_tested_runs,
            *(row["run"] for row in self.readings),
            *(row["run"] for row in self.size_dose),
            *(self.sweep if self.robustness else []),
            *(row["run"] for row in self.words),
        ]
        return list(dict.fromkeys(runs))

    @property
    def claim_rows(self) -> list[dict[str, Any]]:
        """The confirmation's replications: the readings' rows at the config's Goal response
        under each declared cue timing (config ``confirmation.cues``), one per seed."""
        own = self.own.config
        goal, cues = own["soms"]["goal_response"], own["confirmation"]["cues"]
        return [r for r in self.readings if r["goal_response"] == goal and r["cue"] in cues]

    @property
    def own_reading_rows(self) -> list[dict[str, Any]]:
        """The replications of the config's own reading (its cue timing and Goal response),
        among the confirmation's: the signatures' networks and the learning curves' row."""
        cue = self.own.config["network"]["categorisation_cue"]
        return [row for row in self.claim_rows if row["cue"] == cue]

    def first_reading_run(self, goal_response: str) -> str | None:
        """The run of the first replication (the readings' first seed) of a reading under this
        Goal response, or None (no reading uses it)."""
        first_seed = self.readings[0]["seed"] if self.readings else None
        return next(
            (
                row["run"]
                for row in self.readings
                if row["goal_response"] == goal_response and row["seed"] == first_seed
            ),
            None,
        )

    def measured(self, run: str) -> bool:
        """A run of the readings or the size study: its trials scored on the declared measures."""
        return run in {row["run"] for row in [*self.readings, *self.size_dose]}

    def steps(self, run: str, tests: bool = True) -> list[str]:
        """The steps whose files a run makes (each names its rule's outputs): its maps made
        size-free, demonstrations and SOMs (unless it reads an earlier run's, ``stage_run``),
        its networks, and (``tests``) the in-silico tests, ANOVAs and Figure 5. A robot variant
        is tested on the robot only: its in-silico closed loop would feed a servo target back
        as the posture reached (icub_affordance.trials.in_silico). A sweep point's ANOVAs and
        Figure 5 no page reads: its trials alone, which the sweep's summary analyses."""
        steps = []
        if self.makes(run, "maps") and self.config(run)["size_free_input"]:
            steps.append("size_free_maps")
        steps += [stage for stage in ("demos", "soms") if self.makes(run, stage)]
        steps.append("train")
        if tests and not self.trained_for_robot(run):
            steps += ["evaluate"] if run in self.sweep else ["evaluate", "stats", "figure5"]
        return steps

    def built_steps(self, run: str) -> list[str]:
        """The steps the default target makes of a run, for each part it plays: its model and
        tests (a measured run that is neither whole nor a sweep point is scored on the measures
        only, not tested in silico), its measures (the config's own too: the book reads them),
        and its robot test."""
        sweep_point = self.robustness and run in self.sweep
        words = self.runs[run].origin == "words"
        tested = run in self.whole or sweep_point or not (self.measured(run) or words)
        steps = self.steps(run, tests=tested)
        if self.measured(run) or run == MAIN:
            steps.append("measures")
        if words:
            steps.append("word_trials")  # tested in every form: image, name, both
        if run in self.robot_tested_runs:
            steps.append("robot_test")
        return steps

    def job_counts(self) -> dict[str, int]:
        """How many jobs each rule that serves runs has in the default target, from the plan
        alone: a job per step of each built run, per part for the networks and the robot test
        (``parts``), and one per seed for the measured runs (``measured_groups``: rule
        ``measured``, a job per group). The tests hold a dry run's job stats to these numbers."""
        counts: dict[str, int] = {}
        groups: set[str] = set()
        for run in self.built():
            for step in self.built_steps(run):
                rule = step
                if step in ("soms", "train", "measures", "robot_test"):
                    rule = self.rule_for(run, step)
                if rule == "measured":
                    groups.add(str(self.group(run)))
                    counts["measured"] = len(groups)
                    continue
                jobs = len(self.parts(run, step)) if step in ("train", "robot_test") else 1
                counts[rule] = counts.get(rule, 0) + jobs
        owners = {self.phase1_run(run) for run in self.built()} - {None}
        if owners:
            counts["phase1"] = sum(len(self.parts(owner)) for owner in owners)
        return counts

    def scale(self) -> dict[str, int]:
        """How much this plan's build trains and tests (the book's reproduce page says it)."""
        return {
            "reading_seeds": len({row["seed"] for row in self.readings}),
            "readings": len({row["reading"] for row in self.readings}),
            "size_runs": len(self.size_dose),
            "size_replications": len({row["seed"] for row in self.size_dose}),
            "variants": len(self.robot_runs) - 1,  # besides the config's own networks
            "fresh": sum(self.config(run)["network"]["networks"] for run in self.confirmation_runs),
            "sweep": len(self.sweep) if self.robustness else 0,
        }

    def trained_for_robot(self, run: str) -> bool:
        """A robot variant or confirmation of its own: trained, then tested on the robot only
        (its in-silico closed loop would feed a servo target back as the posture reached)."""
        return self.runs[run].origin in ("robot", "confirmation")

    def variant_run(self, entry: Mapping[str, Any]) -> str:
        """The run of a variant as written in the config (e.g. robot.animation.variant)."""
        variant = NetworkVariant.of(entry, self.own.config["network"])
        keys = NetworkVariant.keys()
        return next(
            row["run"]
            for row in self.robot_variants
            if tuple(row[k] for k in keys) == variant.values()
        )


def _phase1_settings(config: Mapping[str, Any]) -> dict[str, Any]:
    """A run's config without what acts only after phase 1 (or on no result:
    vocabulary.AFTER_PHASE1, the cue timing, the rate's schedule, the learning curve's rows)."""
    network = {k: v for k, v in config["network"].items() if k not in AFTER_PHASE1}
    return dict(config) | {"network": network}


def plan_runs(config: Mapping[str, Any]) -> RunPlan:
    """Every run of ``config``, named and ordered; see the module's docstring."""
    planner = _Planner(config)
    planner.add(MAIN, {}, "main")
    for name, overrides in config["runs"].items():
        planner.add(name, overrides, "configured")
    ablation = planner.add(*_ablation(config), "ablation")
    # the size study before the sweep: its replications' demonstrations live in its own folders
    # (a sweep point, a target of its own, may reuse them, not the other way round)
    size_dose = _size_dose(config, planner)
    sweep = {}
    for name, overrides in _sweep(config):
        planner.add(name, overrides, "sweep")
        network = overrides["network"]
        sweep[name] = {"seed": overrides["seed"]} | {
            key: network[key] for key in ("learning_rate", "hidden", "categorisation_cue")
        }
    readings = _readings(config, planner)
    variants = _robot_variants(config, planner)
    confirmation = _confirmation(config, planner, variants)
    words = _words(config, planner)
    return RunPlan(
        runs=planner.runs,
        configured=[*config["runs"], ablation],
        ablation=ablation,
        sweep=sweep,
        readings=readings,
        robot_variants=variants,
        confirmation=confirmation,
        size_dose=size_dose,
        robustness=bool(config["robustness"]),
        words=words,
    )


class _Planner:
    """The runs so far, in order; a run asked for again (the same config) is found, not added."""

    def __init__(self, config: Mapping[str, Any]) -> None:
        self.config = config
        self.runs: dict[str, Run] = {}

    def add(
        self,
        name: str,
        overrides: Mapping[str, Any],
        origin: str,
        run_config: Mapping[str, Any] | None = None,
    ) -> str:
        """A new run (``run_config``: its config, if already laid); a name the plan already gave
        (a run of config ``runs`` named like a run the plan makes itself) is refused: its
        settings would silently replace the plan's run."""
        if name in self.runs:
            made = next(o for o in (self.runs[name].origin, origin) if o != "configured")
            raise ConfigError(
                f"config key runs.{name}: the name {name!r} is the plan's own name for the "
                f"{ORIGIN_WORDS.get(made, made)}, and the run of config `runs` would silently "
                "replace its settings. Allowed: a name the plan does not use. Fix: rename the run."
            )
        if run_config is None:
            run_config = merged(self.config, overrides)
        self.runs[name] = Run(name, overrides, run_config, origin)
        return name

    def find_or_add(self, name: str, overrides: Mapping[str, Any], origin: str) -> str:
        """The run whose config equals the config with ``overrides`` laid over it, if one exists
        (whatever its name), else a new run called ``name``."""
        run_config = merged(self.config, overrides)
        same = next((r.name for r in self.runs.values() if r.config == run_config), None)
        return same or self.add(name, overrides, origin, run_config)


def _ablation(config: Mapping[str, Any]) -> tuple[str, dict[str, Any]]:
    """The cue ablation: the config's run with the other categorisation cue timing."""
    own = config["network"]["categorisation_cue"]
    other = {"first_step": "all_steps", "all_steps": "first_step"}[own]
    return f"cue_{other}", {"network": {"categorisation_cue": other}}


def _sweep(config: Mapping[str, Any]) -> list[tuple[str, dict[str, Any]]]:
    """Every combination of the ``sweep`` section's values (a target of its own)."""
    sweep = config["sweep"]
    return [
        (
            f"sweep_seed{seed}_lr{lr}_h{hidden}_{cue}",
            {
                "seed": seed,
                "network": {"learning_rate": lr, "hidden": hidden, "categorisation_cue": cue},
            },
        )
        for seed, lr, hidden, cue in itertools.product(
            sweep["seeds"], sweep["learning_rate"], sweep["hidden"], sweep["categorisation_cue"]
        )
    ]


def _readings(config: Mapping[str, Any], planner: _Planner) -> list[dict[str, Any]]:
    """Every combination of cue timing and Goal response (config ``readings``), replicated at
    each of the confirmation's seeds (config ``confirmation``; with robustness its further
    seeds too): the readings' replications are the confirmation's, whose family is the
    readings at the config's Goal response."""
    readings = config["readings"]
    seeds = claim_seeds(config["confirmation"], bool(config["robustness"]))
    table = []
    for cue, goal in itertools.product(readings["categorisation_cue"], readings["goal_response"]):
        for seed in dict.fromkeys(seeds):
            overrides = {
                "seed": seed,
                "network": {"categorisation_cue": cue},
                "soms": {"goal_response": goal},
            }
            name = f"reading_{cue}_{goal}" + ("" if seed == config["seed"] else f"_seed{seed}")
            run = planner.find_or_add(name, overrides, "reading")
            row = {"reading": f"{cue}+{goal}", "cue": cue, "goal_response": goal}
            table.append(row | {"seed": seed, "run": run})
    return table


def _robot_variants(config: Mapping[str, Any], planner: _Planner) -> list[dict[str, Any]]:
    """The config's own networks and every variant of the grid (config ``robot``), each the run
    with its network settings; ``default`` marks those tested without robustness."""
    robot, network = config["robot"], config["network"]
    own = NetworkVariant.of(network, network)
    chosen = {own} | {NetworkVariant.of(entry, network) for entry in robot["default"]}
    table = []
    for variant in dict.fromkeys([own, *NetworkVariant.grid(robot)]):
        overrides = {"network": variant.network(network)}
        run = planner.find_or_add(variant.run_name(network), overrides, "robot")
        table.append({"run": run} | variant.row() | {"default": variant in chosen})
    return table


def _confirmation(
    config: Mapping[str, Any], planner: _Planner, variants: list[dict[str, Any]]
) -> list[dict[str, Any]]:
    """Each variant of robot.confirmation trained again on fresh network indices (its other
    settings the variant's, so it shares the config's demonstrations and maps)."""
    confirmation, network = config["robot"]["confirmation"], config["network"]
    count = confirmation["robustness_networks" if config["robustness"] else "networks"]
    fresh = {"networks": count, "first_network": confirmation["first_network"]}
    keys = NetworkVariant.keys()
    table = []
    for entry in confirmation["variants"]:
        variant = NetworkVariant.of(entry, network)
        explored = next(r for r in variants if tuple(r[k] for k in keys) == variant.values())
        overrides = {"network": variant.network(network) | fresh}
        run = planner.add(f"{explored['run']}_confirm", overrides, "confirmation")
        table.append(variant.row() | {"exploration": explored["run"], "confirmation": run})
    return table


def _size_dose(config: Mapping[str, Any], planner: _Planner) -> list[dict[str, Any]]:
    """The size study (config ``size_dose``): every dose under every cue timing with each grip
    arrangement of ``size_dose.crossed`` (``natural``: the demonstrations as made; ``swapped``:
    each object's grips at its same-shape partner's distance, config ``grip_distance``),
    replicated at the first seeds of ``size_dose.crossed.seeds`` (seeds no other part of the
    build uses, so the declared tests are read on fresh data); and, with ``removal``, the
    control with no size in the input (natural grips). A dose is the Object and Goal maps'
    width per sqrt(edge cell), the Goal map growing, the clusters kept whole."""
    study = config["size_dose"]
    crossed = study["crossed"]
    count = crossed["robustness_replications" if config["robustness"] else "replications"]
    seeds = list(crossed["seeds"][:count])
    conditions: list[tuple[Any, str]] = [
        (dose, arrangement)
        for dose in study["doses"]
        for arrangement in crossed["grip_arrangements"]
    ] + ([("removed", "natural")] if study["removal"] else [])
    table = []
    for cue, (dose, arrangement), seed in itertools.product(
        study["categorisation_cue"], conditions, seeds
    ):
        if dose == "removed":
            overrides: dict[str, Any] = {"size_free_input": True}
            name = f"size_removed_{cue}"
        else:
            grows = {"object_width_per_edge": dose, "goal_response": "grows", "keep_whole": True}
            overrides = {"soms": grows}
            name = f"size_dose{dose}_{cue}"
            if arrangement != "natural":
                overrides["grip_distance"] = arrangement
                name = f"size_dose{dose}_{arrangement}_{cue}"
        overrides |= {"seed": seed, "network": {"categorisation_cue": cue}}
        name += "" if seed == config["seed"] else f"_seed{seed}"
        run = planner.find_or_add(name, overrides, "size_dose")
        table.append({"dose": dose, "arrangement": arrangement, "cue": cue, "seed": seed,
                      "run": run})  # fmt: skip
    return table


def _words(config: Mapping[str, Any], planner: _Planner) -> list[dict[str, Any]]:
    """The words study (config ``words``): the whole model with names on (config ``names``),
    at each of its seeds (with robustness its further seeds too) and under each of its cue
    timings; seeds no other study runs (config_checks), so each is a run of its own."""
    words = config["words"]
    table = []
    for cue, seed in itertools.product(
        words["cues"], dict.fromkeys(claim_seeds(words, bool(config["robustness"])))
    ):
        overrides = {"seed": seed, "names": {"use": True}, "network": {"categorisation_cue": cue}}
        run = planner.add(f"words_{cue}_seed{seed}", overrides, "words")
        table.append({"cue": cue, "seed": seed, "run": run})
    return table
