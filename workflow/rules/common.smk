# Shared helpers of the rules (no rules here): the runs of the model, their settings and paths,
# and the code each rule runs.
import glob
import itertools
import re
from pathlib import Path

from icub_affordance.learning.variants import NetworkVariant
from icub_workflow.code_deps import CodeGraph, page_code
from icub_workflow.config_checks import check_runs
from icub_workflow.parts import part_networks
from icub_workflow.runs import FOLDER_PATTERN, MAIN, plan_runs
from icub_workflow.scene_files import scene_files


# the project's own code: the science package and the workflow's (src/); what each source
# imports is kept beside the compiled modules (Snakefile: _CODE.save), by the source's digest
_CODE = CodeGraph(
    [Path(workflow.basedir) / "src"],
    cache=Path(workflow.basedir) / "src" / "icub_workflow" / "__pycache__" / "code_deps.json",
)


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
# A run is the model made once, for the config with some settings laid over it: the config's own
# run, config `runs`, the cue ablation, the sweep's points, the readings, the robot variants and
# their confirmations. They are planned by icub_workflow.runs.plan_runs, which the tests try
# directly; the rules only ask the plan. A run's files live in its folder under data/
# (PLAN.folder: the config's own at the top, every other under runs/{run}/), which the rules
# serving every run take as the wildcard `folder`.

PLAN = plan_runs(config)
# each run of `runs:`, laid over the config: the schema and the rules between keys
check_runs(config, CONFIG_SCHEMA, taken=[run for run in PLAN.runs if run not in config["runs"]])
NETWORKS = PLAN.networks(MAIN)
# Which rule makes each run's maps, networks, measures and robot test is the plan's to say
# (icub_workflow.runs: RunPlan.rule_for, tested in tests/test_run_plan.py), through where it
# puts the files (RunPlan.path): a measured run's maps, networks and measures lie in its seed's
# folder (rule measured), so `soms`, `train` and `measures` serve any folder of the shape
# FOLDER_PATTERN; the few rules that serve a handful of runs (robot_test, phase1, word_trials)
# name their folders (RunPlan.served_by).
MEASURED_GROUPS = PLAN.measured_groups


def measured_inputs(files):
    """Inputs for `files`, each once: a file, or, for one in a measured group's folder (rule
    measured, RunPlan.container), that folder. The rule passes the files themselves to its
    script as a parameter."""
    return list(dict.fromkeys(PLAN.container(path) for path in files))


def served_by(rule, step):
    """A wildcard constraint: the folders of the runs whose `step` the rule `rule` makes."""
    return folders_pattern(PLAN.served_by(rule, step))


def phase1_files(wildcards):
    """An input: the phase 1 this run's networks continue from (none: they train whole)."""
    owner = PLAN.phase1_run(run_of(wildcards))
    if owner is None:
        return []
    return [PLAN.path(owner, f"train/{part}/phase1.npz") for part in PLAN.parts(owner)]


# The filmstrip and the films show the first network of each mapping: for any object one of them
# categorises it with its natural grip (congruent) and the other with the other grip.
FILM_NETWORKS = [NETWORKS[0], NETWORKS[len(NETWORKS) // 2]]


def folders_pattern(runs):
    """A wildcard constraint that matches exactly these runs' folders ((?!) matches nothing)."""
    # in a group: an empty pattern (the config's own folder alone) would count as no constraint
    folders = "|".join(re.escape(PLAN.folder(run)) for run in runs) if runs else "(?!)"
    return f"(?:{folders})"


def run_of(wildcards):
    """The run a job serves, from its wildcard `folder`."""
    return PLAN.run_in(wildcards["folder"])


def run_section(section):
    """A job parameter: this run's config section (keys sorted)."""
    return lambda wildcards: settings(PLAN.config(run_of(wildcards))[section])


def maps_file(run):
    """The visual maps a run's SOMs and networks see: the eye's (rule visual_maps), or, for a
    run with size_free_input, those maps made size-free (rule size_free_maps)."""
    if PLAN.config(run)["size_free_input"]:
        return PLAN.path(PLAN.stage_run(run, "maps"), "vision/size_free_maps.npz")
    return "data/vision/visual_maps.npz"


def model_inputs(wildcards):
    """What the networks of a run learn from: the visual maps, its SOMs and its demonstrations."""
    run = run_of(wildcards)
    return {
        "maps": maps_file(run),
        "soms": PLAN.path(PLAN.stage_run(run, "soms"), "soms/soms.npz"),
        "demos": PLAN.path(PLAN.stage_run(run, "demos"), "demos/demos.npz"),
    }


def run_file(path):
    """An input: this run's file at `path` in its folder."""
    return lambda wildcards: PLAN.path(run_of(wildcards), path)


def part_files(run, step, name, nets=None):
    """A run's files `name` of a step (`train` or `robot_test`), part by part
    (icub_workflow.parts: one file per network of the config's own run; one file `all` for any
    other run): those holding the networks `nets` (all, if None). Read with
    icub_workflow.parts' loaders."""
    parts = PLAN.parts(run, step)
    if nets is not None and parts != ["all"]:
        parts = [f"net{net}" for net in nets]
    folder = {"train": "train", "robot_test": "embodied"}[step]
    return [PLAN.path(run, f"{folder}/{part}/{name}") for part in parts]


def weights_files(run, nets=None):
    """A run's trained weights, those holding the networks `nets` (all, if None). Read with
    icub_workflow.parts.load_weights."""
    return part_files(run, "train", "weights.npz", nets)


def curve_files(run):
    """A run's learning curves, part by part (read with icub_workflow.parts.load_curves)."""
    return part_files(run, "train", "curve.csv")


def run_weights(wildcards):
    """An input: this run's trained weights, every part."""
    return weights_files(run_of(wildcards))


def robot_test_weights(wildcards):
    """The weights a robot test's part drives with: its network's (`net03`), or every network's
    of the run (`all`)."""
    nets = part_networks(wildcards.part)
    return weights_files(run_of(wildcards), None if nets is None else [f"{n:02d}" for n in nets])


#: Each file `outputs` named: the rule and wildcards of the job that makes it.
_MADE_BY = {}


def outputs(rule, run, **wildcards):
    """The files `rule` makes for `run` (`wildcards`: a value or a list of values each), in
    `expand`'s order (output by output), each noted with its job's rule and wildcards
    (_MADE_BY, for job_records)."""
    values = {k: v if isinstance(v, list) else [v] for k, v in wildcards.items()}
    jobs = [
        {"folder": PLAN.folder(run), **dict(zip(values, combination))}
        for combination in itertools.product(*values.values())
    ]
    files = []
    for pattern in getattr(rules, rule).output:
        for job in jobs:
            (path,) = expand(pattern, **job)
            _MADE_BY[path] = (rule, job)
            files.append(path)
    return files


def robot_test_files(run, name, nets=None):
    """A tested variant's robot-test files (`name`: trials.csv or states.npz), those holding the
    networks `nets` (all, if None). Read with icub_workflow.parts.load_robot_trials and
    load_robot_states."""
    return part_files(run, "robot_test", name, nets)


def step_files(run, step):
    """The files a step of a run makes (RunPlan.steps): its rule's outputs in the run's folder,
    part by part for the networks and the robot test."""
    if step in _RULED_STEPS and PLAN.rule_for(run, step) == "measured":
        return measured_files(run, step)
    if step == "train":
        return outputs("train", run, part=PLAN.parts(run))
    if step == "robot_test":
        return outputs("robot_test", run, part=PLAN.parts(run, "robot_test"))
    return outputs(step, run)


_RULED_STEPS = ("soms", "train", "measures", "robot_test")


def measured_files(run, step):
    """The files of a measured run's step (soms, train, measures) in its group's folder, each
    noted as made by its group's job (_MADE_BY, for job_records)."""
    relative = {
        "soms": ["soms/soms.npz"],
        "train": [f"train/{part}/{name}" for part in PLAN.parts(run) for name in
                  ("curve.csv", "weights.npz")],
        "measures": ["eval/measures.csv", "eval/measures.json"],
    }[step]  # fmt: skip
    files = [PLAN.path(run, path) for path in relative]
    for path in files:
        _MADE_BY[path] = ("measured", {"group": PLAN.group(run)})
    return files


def measured_table(wildcards):
    """Each run of the job's group as its script reads it: its settings and its files."""
    return [
        {
            "run": run,
            "network": settings(PLAN.config(run)["network"]),
            "grip_distance": PLAN.config(run)["grip_distance"],
            "seed": PLAN.config(run)["seed"],
            **model_inputs({"folder": PLAN.folder(run)}),
            "makes_soms": PLAN.makes(run, "soms"),  # else it reads an earlier run's (same seed)
            "som_settings": settings(PLAN.config(run)["soms"]),
            "names": settings(PLAN.config(run)["names"]),
            "curves": curve_files(run),  # its part `all`: one file each
            "weights": weights_files(run),
            "trials": PLAN.path(run, "eval/measures.csv"),
            "json": PLAN.path(run, "eval/measures.json"),
        }
        for run in MEASURED_GROUPS[wildcards.group]
    ]


def measured_models(wildcards):
    """An input: the maps, SOMs and demonstrations the group's runs learn from, but the SOMs
    the job makes itself."""
    table = measured_table(wildcards)
    made = {row["soms"] for row in table if row["makes_soms"]}
    return sorted({row[key] for row in table for key in ("maps", "soms", "demos")} - made)


def run_files(run, tests=True):
    """Every file a run makes (RunPlan.steps: its demonstrations and SOMs unless it reads an
    earlier run's, its networks, and with `tests` its in-silico tests).

    All of them are inputs of the run's target, not only its last files: Snakemake does not
    remake a missing file that no job still to run needs, so a deleted (or corrupt, and deleted
    as the error says) intermediate file would otherwise stay missing after a green run.
    """
    return [f for step in PLAN.steps(run, tests) for f in step_files(run, step)]


def run_outputs(run):
    """Every file the default target makes of a run, for each part it plays
    (RunPlan.built_steps)."""
    return [f for step in PLAN.built_steps(run) for f in step_files(run, step)]


def job_records(files):
    """The engine's own record of each job that makes one of `files`, once per job: its
    `benchmark:` file (the job's wall time in column `s`). The job is found as Snakemake finds
    it, by the one rule whose output matches the file (wildcard constraints included), so this
    holds whichever rule serves a run; call it from an input function, once every rule is read.
    A file a rule names whole is looked up; only the others are matched, and only against the
    outputs that can end in their name (_outputs_index)."""
    exact, by_name, any_name = _outputs_index()
    records = []
    for path in files:
        if path in exact:
            makers, wildcards = [exact[path]], {}
        elif path in _MADE_BY:  # a run's file: its job is known from the plan (outputs)
            maker, wildcards = _MADE_BY[path]
            makers = [workflow.get_rule(maker)]
        else:
            candidates = [*by_name.get(path.rsplit("/", 1)[-1], ()), *any_name]
            matches = [(r, found) for r, output in candidates if (found := output.match(path))]
            makers = list(dict.fromkeys(r for r, _ in matches))
            # the wildcards from the output's own match (Rule.get_wildcards matches again, slowly)
            wildcards = matches[0][1].groupdict() if len(makers) == 1 else {}
        if len(makers) != 1 or not makers[0].benchmark:
            makers = [r for r in workflow.rules if any(o.match(path) for o in r.output)]
            raise ValueError(
                f"{path}: made by the rules {[r.name for r in makers]}; its job's record needs "
                "one rule, with a `benchmark:` file"
            )
        records.append(str(makers[0].expand_benchmark(wildcards)))
    return list(dict.fromkeys(records))


_OUTPUTS_INDEX = []


def _outputs_index():
    """The outputs of the rules, read once when first asked (all rules read): the files a rule
    names whole ({path: rule}; a replication's measures name hundreds), the patterns whose
    file name has no wildcard, filed by it ({name: [(rule, output), ...]}), and the others
    ([(rule, output), ...]). A file is looked up, or matched against its name's patterns and
    the few others, not against every output of every rule (issue 56)."""
    if not _OUTPUTS_INDEX:
        exact, by_name, any_name = {}, {}, []
        for r in workflow.rules:
            for output in r.output:
                pattern = str(output)
                tail = pattern[pattern.rfind("}") + 1 :]  # all of it, without a wildcard
                if "{" not in pattern:
                    exact[pattern] = r
                elif "/" in tail:
                    by_name.setdefault(tail.rsplit("/", 1)[-1], []).append((r, output))
                else:
                    any_name.append((r, output))
        _OUTPUTS_INDEX.append((exact, by_name, any_name))
    return _OUTPUTS_INDEX[0]


def sweep_job_records(wildcards=None):
    """The sweep's cost (reproduce.md), with robustness: the engine's record of each job that
    made a file of a sweep point (common.smk: job_records, run_files), with the seed of the
    replication it served, {benchmark file: seed}. Without robustness, none."""
    if not PLAN.robustness:
        return {}
    return {
        record: PLAN.sweep[run]["seed"]
        for run in PLAN.sweep
        for record in job_records(run_files(run))
    }


def signature_replications():
    """Each replication of the config's own reading (its cue timing and Goal response) that
    this build makes (RunPlan.own_reading_rows): its run's seed, model inputs, settings and
    weights."""
    return [
        {
            "seed": PLAN.config(row["run"])["seed"],
            **model_inputs({"folder": PLAN.folder(row["run"])}),
            "grip_distance": PLAN.config(row["run"])["grip_distance"],
            "network": settings(PLAN.config(row["run"])["network"]),
            "weights": weights_files(row["run"]),
        }
        for row in PLAN.own_reading_rows
    ]
