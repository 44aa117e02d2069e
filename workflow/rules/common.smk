# Shared helpers of the rules: the runs of the model, their settings and paths, and the code
# each rule runs.
import itertools
import re
from pathlib import Path

from icub_workflow.code_deps import CodeGraph, page_code
from icub_workflow.configs import ROBOT_KEYS, merged, robot_grid, robot_key
from icub_workflow.config_checks import check_runs
from icub_workflow.scene_files import scene_files


# the project's own code: the science package and the workflow's (src/)
_CODE = CodeGraph([Path(workflow.basedir) / "src"])


def script_code(*scripts, pages=()):
    """The project's modules that `workflow/scripts/{script}.py` imports (and the book `pages`, if
    given), transitively: inputs, so that editing one reruns exactly the rules that run it."""
    folder = Path(workflow.basedir) / "workflow" / "scripts"
    sources = [
        *((folder / f"{script}.py").read_text() for script in scripts),
        *(page_code(page) for page in pages),
    ]
    return [str(p.relative_to(workflow.basedir)) for p in _CODE.closure(sources)]


# The scene and every file it includes: inputs of every rule that loads it.
SCENE_FILES = [str(path) for path in scene_files(config["scene"])]


def settings(value):
    """A config section as a job parameter, keys sorted at every level.

    Snakemake compares a job's parameters with the last run's by their text, so the same settings
    written in another key order would otherwise count as a change and rerun the job.
    """
    if isinstance(value, dict):
        return {key: settings(value[key]) for key in sorted(value)}
    if isinstance(value, list):
        return [settings(item) for item in value]
    return value


# ---- Runs --------------------------------------------------------------------------------------
# A run is the model run once: the config itself (the main run, at the paths under data/), or
# the config with some sections overridden (every other run, under data/runs/{name}/). Runs come
# from config `runs:`, from the cue ablation (the other cue timing), from the sweep and from the
# readings (those not already among the others).

MAIN = "main"


def ablation_run():
    """The cue ablation: the main run with the other categorisation cue timing (MODEL.md 7)."""
    other = {"first_step": "all_steps", "all_steps": "first_step"}[
        config["network"]["categorisation_cue"]
    ]
    return f"cue_{other}", {"network": {"categorisation_cue": other}}


def sweep_runs():
    """Every combination of the `sweep` section's values, a run each (not in the default run)."""
    sweep = config["sweep"]
    runs = {}
    for seed, lr, hidden, cue in itertools.product(
        sweep["seeds"], sweep["learning_rate"], sweep["hidden"], sweep["categorisation_cue"]
    ):
        runs[f"sweep_seed{seed}_lr{lr}_h{hidden}_{cue}"] = {
            "seed": seed,
            "network": {"learning_rate": lr, "hidden": hidden, "categorisation_cue": cue},
        }
    return runs


def reading_runs(known):
    """The readings (config `readings`, MODEL.md sections 5, 7, 8): every combination of cue
    timing and Goal response, each replicated at the config's seed and, with robustness, at each
    of `readings.seeds`. A replication is the run whose config equals the config with that
    reading and seed laid over it: an existing run (in `known`, name -> config) if one has those
    settings, else a new run. Returns the new runs (name -> overrides) and the readings table,
    one row per reading and replication: reading, cue, goal_response, seed, run."""
    readings = config["readings"]
    seeds = [config["seed"], *(readings["seeds"] if config["robustness"] else [])]
    known, new, table = dict(known), {}, []
    for cue, goal in itertools.product(readings["categorisation_cue"], readings["goal_response"]):
        for seed in dict.fromkeys(seeds):
            overrides = {
                "seed": seed,
                "network": {"categorisation_cue": cue},
                "soms": {"goal_response": goal},
            }
            run_config = merged(config, overrides)
            run = next((name for name, c in known.items() if c == run_config), None)
            if run is None:
                run = f"reading_{cue}_{goal}" + ("" if seed == config["seed"] else f"_seed{seed}")
                new[run], known[run] = overrides, run_config
            row = {"reading": f"{cue}+{goal}", "cue": cue, "goal_response": goal}
            table.append(row | {"seed": seed, "run": run})
    return new, table


def robot_variant(cue, target, hidden, iterations, schedule):
    """The network settings of a robot variant: the config's, with phase 1 keeping its share of
    the iterations (rounded so that phase 2 splits evenly between the tasks)."""
    network = config["network"]
    phase1 = round(iterations * network["phase1_iterations"] / network["iterations"])
    phase1 += (iterations - phase1) % 2
    return {
        "categorisation_cue": cue, "target": target, "hidden": hidden, "iterations": iterations,
        "phase1_iterations": phase1, "learning_rate_schedule": schedule,
    }  # fmt: skip


def robot_runs(known):
    """The robot test's variants (config `robot`): every combination of cue timing x target x
    hidden x iterations x learning-rate schedule, plus the config's own networks (the reference row, the main run). A
    variant is the run whose config equals the config with its network settings laid over it: an
    existing run if one has them (the main run for the config's own, the cue ablation for the
    other cue timing's), else a new one, named by what differs from the config's own cue timing
    and schedule. Returns the new runs (name -> overrides) and the variants table: run,
    categorisation_cue, target, hidden, iterations, learning_rate_schedule, default (run without
    robustness)."""
    robot, network = config["robot"], config["network"]
    own = robot_key(network, network)
    chosen = {own} | {robot_key(v, network) for v in robot["default"]}
    known, new, table = dict(known), {}, []
    for variant in dict.fromkeys([own, *robot_grid(robot)]):
        cue, target, hidden, iterations, schedule = variant
        overrides = {"network": robot_variant(*variant)}
        run_config = merged(config, overrides)
        run = next((name for name, c in known.items() if c == run_config), None)
        if run is None:
            run = f"robot_{target}_h{hidden}_it{iterations}"
            run += "" if cue == network["categorisation_cue"] else f"_{cue}"
            run += "" if schedule == network["learning_rate_schedule"] else f"_{schedule}"
            new[run], known[run] = overrides, run_config
        row = {"run": run} | dict(zip(ROBOT_KEYS, variant, strict=True))
        table.append(row | {"default": variant in chosen})
    return new, table


def confirmation_runs(variants):
    """The confirmation (config robot.confirmation): each variant chosen on the exploration (its
    row of `variants`, the robot test's table) trained again on fresh network indices,
    first_network.. (robustness_networks of them with robustness, else networks), its other
    settings the variant's, so it shares the main run's demonstrations and maps (stage_run).
    Returns the new runs (name -> overrides) and the confirmation table: the variant's keys, its
    exploration run and its confirmation run."""
    confirmation, network = config["robot"]["confirmation"], config["network"]
    count = confirmation["robustness_networks" if config["robustness"] else "networks"]
    fresh = {"networks": count, "first_network": confirmation["first_network"]}
    new, table = {}, []
    for variant in confirmation["variants"]:
        key = robot_key(variant, network)
        explored = next(r for r in variants if tuple(r[k] for k in ROBOT_KEYS) == key)
        run = f"{explored['run']}_confirm"
        new[run] = {"network": robot_variant(*key) | fresh}
        row = dict(zip(ROBOT_KEYS, key, strict=True))
        table.append(row | {"exploration": explored["run"], "confirmation": run})
    return new, table


ABLATION, _ablation_overrides = ablation_run()
SWEEP_RUNS = sweep_runs()
_EARLIER = {**config["runs"], ABLATION: _ablation_overrides, **SWEEP_RUNS}
READING_RUNS, READINGS = reading_runs(
    {MAIN: config} | {name: merged(config, o) for name, o in _EARLIER.items()}
)
ROBOT_RUNS, ROBOT_VARIANTS = robot_runs(
    {MAIN: config} | {name: merged(config, o) for name, o in {**_EARLIER, **READING_RUNS}.items()}
)
# the variants the robot test runs: those of the default run, or every one with robustness
ROBOT_TESTED = [row for row in ROBOT_VARIANTS if row["default"] or config["robustness"]]
CONFIRMATION_RUNS, CONFIRMATION = confirmation_runs(ROBOT_VARIANTS)
# in this order, which decides whose demonstrations and SOMs a run shares (stage_run)
RUNS = {**_EARLIER, **READING_RUNS, **ROBOT_RUNS, **CONFIRMATION_RUNS}
CONFIGURED_RUNS = [*config["runs"], ABLATION]  # in the default target
RUN_CONFIG = {MAIN: config} | {name: merged(config, o) for name, o in RUNS.items()}


# each run of `runs:`, laid over the config: the schema and the rules between keys
check_runs(
    config,
    CONFIG_SCHEMA,
    taken=[MAIN, ABLATION, *SWEEP_RUNS, *READING_RUNS, *ROBOT_RUNS, *CONFIRMATION_RUNS],
)


def run_dir(run):
    return "data" if run == MAIN else f"data/runs/{run}"


def run_of(wildcards):
    return wildcards.get("run", MAIN)


wildcard_constraints:
    run="|".join(map(re.escape, RUNS)),  # names may hold dots (lr0.075)
    net=r"\d\d",


# The settings each shared stage depends on: a run uses the stage of the first run (in the order
# of RUN_CONFIG: main, config `runs`, the ablation, the sweep) whose settings for it are equal, so
# a run that changes only the network reuses the main run's demonstrations and maps, and two
# sweep points with one seed share theirs.
STAGE_SETTINGS = {
    "demos": ("seed", "scene", "objects", "object_sizes_m", "initial_posture_deg", "demos"),
    "soms": ("seed", "scene", "objects", "object_sizes_m", "initial_posture_deg", "vision", "soms"),
}


def stage_run(run, stage):
    """The run whose `stage` outputs this run reads."""
    key = [RUN_CONFIG[run][k] for k in STAGE_SETTINGS[stage]]
    return next(r for r in RUN_CONFIG if [RUN_CONFIG[r][k] for k in STAGE_SETTINGS[stage]] == key)


def run_networks(run):
    """A run's network indices (each network's seed is network_seed(seed, index)): 0.. for
    every run but a confirmation, whose fresh ones start at robot.confirmation.first_network."""
    network = RUN_CONFIG[run]["network"]
    first = network.get("first_network", 0)
    return [f"{i:02d}" for i in range(first, first + network["networks"])]


def run_section(section):
    """A job parameter: this run's config section (keys sorted)."""
    return lambda wildcards: settings(RUN_CONFIG[run_of(wildcards)][section])


def model_inputs(wildcards):
    """What the networks of a run learn from: the visual maps, its SOMs and its demonstrations."""
    run = run_of(wildcards)
    return {
        "maps": "data/vision/visual_maps.npz",
        "soms": f"{run_dir(stage_run(run, 'soms'))}/soms/soms.npz",
        "demos": f"{run_dir(stage_run(run, 'demos'))}/demos/demos.npz",
    }


def run_file(path):
    """An input: this run's file at `path` under its folder (`{net}` kept as a wildcard)."""
    return lambda wildcards: f"{run_dir(run_of(wildcards))}/{path}"


def run_network_files(path):
    """An input: `path` (with `{net}`) for every network of this run."""

    def files(wildcards):
        run = run_of(wildcards)
        return [f"{run_dir(run)}/{path}".format(net=net) for net in run_networks(run)]

    return files
