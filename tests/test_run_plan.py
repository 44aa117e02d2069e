"""The run plan (icub_workflow.runs.plan_runs), tried directly on configs: which runs a config
asks for, what they are called, which are one run, whose demonstrations and maps each reuses and
where their files live. And the robot variant type it builds them from."""

from __future__ import annotations

import dataclasses

import pytest
from conftest import load_config, load_test_config

from icub_affordance.learning.variants import NetworkVariant
from icub_workflow.configs import merged
from icub_workflow.runs import MAIN, plan_runs


@pytest.fixture(scope="module")
def config() -> dict:
    return load_config() | {"robustness": False}


@pytest.fixture(scope="module")
def plan(config):
    return plan_runs(config)


def test_the_configs_own_run_is_first_at_the_top_of_data(plan, config):
    assert next(iter(plan.runs)) == MAIN
    assert plan.config(MAIN) == config
    assert plan.path(MAIN, "eval/trials.csv") == "data/eval/trials.csv"
    assert plan.folder(plan.ablation) == f"runs/{plan.ablation}/"
    # every run has its own folder, and the folder gives the run back
    folders = plan.folders()
    assert len(set(folders)) == len(folders) == len(plan.runs)
    assert all(plan.run_in(plan.folder(run)) == run for run in plan.runs)
    with pytest.raises(KeyError):
        plan.folder("no_such_run")
    with pytest.raises(KeyError, match="no run of this config lives in data/runs/typo/"):
        plan.run_in("runs/typo/")


def test_every_runs_folder_has_the_shape_the_rules_match():
    """The rules match a run's folder by its shape (FOLDER_PATTERN), not by a list of every
    run's: each run's folder has it, whole, at either scale, and paths outside runs/ do not."""
    import re

    from icub_workflow.runs import FOLDER_PATTERN

    shape = re.compile(FOLDER_PATTERN)
    for robustness in (False, True):
        plan = plan_runs(load_config() | {"robustness": robustness})
        assert all(shape.fullmatch(plan.folder(run)) for run in plan.runs)
    for other in ("measured/seed101/", "runs/a/b/", "words/", "runs//"):
        assert not shape.fullmatch(other), other


def test_the_ablation_is_the_other_cue_timing(plan, config):
    own = config["network"]["categorisation_cue"]
    other = plan.config(plan.ablation)["network"]["categorisation_cue"]
    assert {own, other} == {"first_step", "all_steps"}
    assert plan.ablation == f"cue_{other}"
    assert plan.config(plan.ablation) == merged(config, {"network": {"categorisation_cue": other}})
    assert plan.whole == [MAIN, *config["runs"], plan.ablation]


def test_each_reading_is_a_run_of_its_settings_at_each_confirmation_seed(plan, config):
    """A reading's runs have its cue timing and Goal response at its seed; the readings at the
    config's Goal response under the declared cues are the confirmation's replications, none of
    them the config's own run (seed 2009 is not among the fresh seeds)."""
    rows = plan.readings
    cues, goals = config["readings"]["categorisation_cue"], config["readings"]["goal_response"]
    seeds = config["confirmation"]["seeds"]
    assert len(rows) == len(cues) * len(goals) * len(seeds)
    for row in rows:
        run = plan.config(row["run"])
        assert run["network"]["categorisation_cue"] == row["cue"]
        assert run["soms"]["goal_response"] == row["goal_response"]
        assert run["seed"] == row["seed"] and row["seed"] in seeds
        assert row["run"] not in (MAIN, plan.ablation)
    # the readings of one seed share its demonstrations
    for seed in seeds:
        demos = {plan.stage_run(r["run"], "demos") for r in rows if r["seed"] == seed}
        assert len(demos) == 1


def test_the_confirmation_and_the_signatures_read_the_plans_rows_of_the_declared_readings(
    plan, config
):
    """The plan says which replications back the declared tests (no rule filters the readings
    itself): the confirmation's are the readings at the config's Goal response under each
    declared cue, one per seed; the signatures' and the learning curves' those of the config's
    own cue among them; the readings chapter's other Goal map is the first seed's."""
    goal, cues = config["soms"]["goal_response"], config["confirmation"]["cues"]
    own_cue = config["network"]["categorisation_cue"]
    seeds = config["confirmation"]["seeds"]
    claims = plan.claim_rows
    assert sorted((row["cue"], row["seed"]) for row in claims) == sorted(
        (cue, seed) for cue in cues for seed in seeds
    )
    for row in claims:
        run = plan.config(row["run"])
        assert (run["network"]["categorisation_cue"], run["soms"]["goal_response"]) == (
            row["cue"],
            goal,
        )
    own = plan.own_reading_rows
    assert [row["seed"] for row in own] == seeds
    assert {plan.config(row["run"])["network"]["categorisation_cue"] for row in own} == {own_cue}
    other_goal = next(g for g in config["readings"]["goal_response"] if g != goal)
    first = plan.first_reading_run(other_goal)
    assert plan.config(first)["seed"] == seeds[0]
    assert plan.config(first)["soms"]["goal_response"] == other_goal
    assert plan.first_reading_run("no_such_response") is None


def test_runs_share_demonstrations_and_maps_exactly_when_their_settings_are_equal(plan, config):
    for run in plan.runs:
        for stage in ("demos", "soms"):
            source = plan.stage_run(run, stage)
            # the source comes first and has the same settings; nothing earlier has them
            assert list(plan.runs).index(source) <= list(plan.runs).index(run)
    # a robot variant changes only the network: the config's demonstrations and maps
    variant = next(row["run"] for row in plan.robot_variants if row["run"] != MAIN)
    assert plan.stage_run(variant, "demos") == plan.stage_run(variant, "soms") == MAIN
    # a reading with the other Goal response: its seed's demonstrations, its own maps
    grows = next(r for r in plan.readings if r["goal_response"] != "fixed")
    fixed = next(r for r in plan.readings if r["goal_response"] == "fixed"
                 and r["seed"] == grows["seed"] and r["cue"] == grows["cue"])  # fmt: skip
    assert plan.stage_run(grows["run"], "demos") == plan.stage_run(fixed["run"], "demos")
    assert plan.makes(grows["run"], "soms") and not plan.makes(grows["run"], "demos")
    # sweep points of one seed share theirs; of another seed, make their own
    points = list(plan.sweep)
    by_seed: dict[int, list[str]] = {}
    for point in points:
        by_seed.setdefault(plan.sweep[point]["seed"], []).append(point)
    for seed, same in by_seed.items():
        first = plan.stage_run(same[0], "demos")
        assert all(plan.stage_run(p, "demos") == first for p in same)
        assert (first == MAIN) == (seed == config["seed"])


def test_robot_variants_are_named_by_what_differs_from_the_config(plan, config):
    network = config["network"]
    rows = plan.robot_variants
    grid = NetworkVariant.grid(config["robot"])
    assert len(rows) == len({NetworkVariant.from_row(r) for r in rows}) == len(grid)
    assert rows[0]["run"] == MAIN and rows[0]["default"]
    for row in rows[1:]:
        variant = NetworkVariant.from_row(row)
        settings = plan.config(row["run"])["network"]
        assert {k: settings[k] for k in variant.keys()} == variant.row()
        if row["run"] not in (MAIN, plan.ablation):
            assert row["run"] == variant.run_name(network)
            assert plan.trained_for_robot(row["run"])
    tested = [r["run"] for r in rows if r["default"]]
    assert plan.robot_runs == tested and len(tested) == 1 + len(config["robot"]["default"])
    assert len(plan_runs(config | {"robustness": True}).robot_runs) == len(rows)


def test_confirmations_train_fresh_networks_of_the_chosen_variant(plan, config):
    confirmation = config["robot"]["confirmation"]
    assert len(plan.confirmation) == len(confirmation["variants"])
    for row in plan.confirmation:
        run = row["confirmation"]
        assert run == f"{row['exploration']}_confirm"
        first = confirmation["first_network"]
        assert plan.networks(run) == [
            f"{i:02d}" for i in range(first, first + confirmation["networks"])
        ]
        assert not set(plan.networks(run)) & set(plan.networks(row["exploration"]))
        assert plan.stage_run(run, "demos") == plan.stage_run(run, "soms") == MAIN
        explored = plan.config(row["exploration"])["network"]
        fresh = plan.config(run)["network"]
        assert {k: v for k, v in fresh.items() if k not in ("networks", "first_network")} == {
            k: v for k, v in explored.items() if k != "networks"
        }
    robust = plan_runs(config | {"robustness": True})
    run = robust.confirmation[0]["confirmation"]
    assert len(robust.networks(run)) == confirmation["robustness_networks"]


@pytest.mark.parametrize("robustness", [False, True])
def test_every_reading_is_replicated_at_the_confirmations_seeds(config, robustness):
    """The readings' replications are the confirmation's: every reading at each of its seeds
    (the full scale's too), none at the config's own seed, each run its seed's."""
    plan = plan_runs(config | {"robustness": robustness})
    declared = config["confirmation"]
    seeds = [*declared["seeds"], *(declared["robustness_seeds"] if robustness else [])]
    readings = {(r["reading"]) for r in plan.readings}
    assert len(plan.readings) == len(readings) * len(seeds) and len(seeds) >= 10
    assert {r["seed"] for r in plan.readings} == set(seeds)
    assert config["seed"] not in seeds
    for row in plan.readings:
        assert plan.config(row["run"])["seed"] == row["seed"]


def test_a_configured_run_is_planned_and_its_name_kept(config):
    plan = plan_runs(config | {"runs": {"lr_half": {"network": {"learning_rate": 0.0375}}}})
    assert list(plan.runs)[1] == "lr_half" and "lr_half" in plan.whole
    assert plan.config("lr_half")["network"]["learning_rate"] == 0.0375
    assert plan.stage_run("lr_half", "soms") == MAIN


def test_the_test_config_plans_few_runs():
    plan = plan_runs(load_test_config() | {"robustness": False})
    # two replications of 4 readings, of 4 size runs and of the words study, and the rest
    assert len(plan.runs) < 27
    assert all(plan.networks(run) for run in plan.runs)


def test_only_the_configs_own_run_has_a_job_per_network(plan):
    assert [run for run in plan.runs if plan.jobs_per_network(run)] == [MAIN]


def test_the_readings_and_size_study_runs_are_measured_in_one_job_per_seed(plan, config):
    """Every reading and dose run that is not also a run the book tests in full (the config's
    own, the cue ablation) is in exactly one group, the group of its seed."""
    groups = plan.measured_groups
    grouped = [run for runs in groups.values() for run in runs]
    assert len(grouped) == len(set(grouped))
    expected = {row["run"] for row in [*plan.readings, *plan.size_dose]} - set(plan.whole)
    assert set(grouped) == expected
    for name, runs in groups.items():
        assert {f"seed{plan.config(run)['seed']}" for run in runs} == {name}
        assert {plan.group(run) for run in runs} == {name}
    # the readings at the confirmation's seeds; the size study at its own seeds
    crossed = config["size_dose"]["crossed"]
    seeds = {*config["confirmation"]["seeds"], *crossed["seeds"][: crossed["replications"]]}
    assert set(groups) == {f"seed{seed}" for seed in seeds}


def test_a_measured_runs_files_live_in_its_groups_folder(plan):
    """Rule measured makes its group's folder whole: a measured run's SOMs, networks and
    measures live in it (a rule that reads one names the folder, RunPlan.container); its other
    files (demonstrations, size-free maps) in its own folder; any other run's where they were."""
    for group, runs in plan.measured_groups.items():
        for run in runs:
            for relative in ("soms/soms.npz", "train/all/weights.npz", "eval/measures.json"):
                path = plan.path(run, relative)
                assert path == f"data/measured/{group}/{run}/{relative}"
                assert plan.container(path) == f"data/measured/{group}"
            demos = plan.path(run, "demos/demos.npz")
            assert demos == f"data/runs/{run}/demos/demos.npz" and plan.container(demos) == demos
    assert plan.group(MAIN) is None
    assert plan.path(MAIN, "train/net00/weights.npz") == "data/train/net00/weights.npz"
    assert plan.path(plan.ablation, "eval/measures.json").startswith("data/runs/")


@pytest.mark.parametrize("robustness", [False, True])
def test_each_runs_step_is_made_by_exactly_one_rule(config, robustness):
    """The plan routes every run's maps, networks, measures and robot test to one rule, and the
    runs a rule serves are exactly those routed to it: one rule trains every run but the
    measured ones (a job per part: each of the config's own networks, another run's `all`);
    one rule tests every tested run on the robot, likewise in parts (the config's own networks
    a job each, another run's, at any indices, in one job `all`); the measured runs with their
    seed's others; every rule a step names exists."""
    plan = plan_runs(config | {"robustness": robustness})
    rules = {
        "soms": {"soms", "measured"},
        "measures": {"measures", "measured"},
        "train": {"train", "measured"},
        "robot_test": {"robot_test"},
    }
    for step, names in rules.items():
        runs = plan.robot_tested_runs if step == "robot_test" else list(plan.runs)
        routed = {run: plan.rule_for(run, step) for run in runs}
        assert set(routed.values()) <= names, (step, set(routed.values()))
        served = [run for rule in names for run in plan.served_by(rule, step)]
        assert sorted(served) == sorted(runs)  # each run once
    measured = {run for group in plan.measured_groups.values() for run in group}
    assert {r for r in plan.runs if plan.rule_for(r, "train") == "measured"} == measured
    assert plan.served_by("train", "train") == [r for r in plan.runs if r not in measured]
    assert plan.served_by("robot_test", "robot_test") == plan.robot_tested_runs
    assert plan.parts(MAIN) == [f"net{net}" for net in plan.networks(MAIN)]
    assert all(plan.parts(r) == ["all"] for r in plan.runs if r not in measured | {MAIN})
    own = plan.parts(MAIN, "robot_test")
    assert own == plan.parts(MAIN) and MAIN in plan.robot_tested_runs
    fresh = plan.confirmation_runs
    assert all(plan.parts(r, "robot_test") == ["all"] for r in plan.robot_tested_runs[1:])
    assert fresh and all(plan.networks(r) != plan.networks(MAIN) for r in fresh)
    with pytest.raises(ValueError, match="no rule"):
        plan.rule_for(MAIN, "evaluate")


def test_a_run_with_other_network_indices_is_trained_and_tested_in_one_job(config):
    """A run of `runs:` with 6 networks is trained like any other (one job, its part `all`); a
    robot run with such networks is tested on the robot by the same rule, its part `all`: a
    part holds whichever indices its run has, so no set of indices lacks a rule."""
    plan = plan_runs(config | {"runs": {"six": {"network": {"networks": 6}}}})
    assert plan.rule_for("six", "train") == "train" and plan.parts("six") == ["all"]
    assert {MAIN, "six"} <= set(plan.served_by("train", "train"))
    robot = dataclasses.replace(plan.runs["six"], origin="robot")
    odd = dataclasses.replace(plan, runs=plan.runs | {"six": robot})
    assert odd.rule_for("six", "robot_test") == "robot_test"
    assert odd.parts("six", "robot_test") == ["all"]
    # a confirmation at the config's own indices is trained and tested like any other run
    same = plan_runs(config | {"robot": config["robot"] | {
        "confirmation": config["robot"]["confirmation"] | {"first_network": 0}}})  # fmt: skip
    assert all(
        same.rule_for(run, "robot_test") == "robot_test"
        and same.parts(run, "robot_test") == ["all"]
        for run in same.confirmation_runs
    )
    with pytest.raises(ValueError, match="no parts"):
        plan.parts(MAIN, "evaluate")


#: The variants earlier default builds tested beside the config's own networks: 40 hidden,
#: 768,000 iterations, under both cue timings and (every step) with the annealed rate.
EARLIER_DEFAULT = [
    {"categorisation_cue": "all_steps", "target": "commands", "hidden": 40, "iterations": 768000},
    {"categorisation_cue": "first_step", "target": "commands", "hidden": 40, "iterations": 768000},
    {"categorisation_cue": "all_steps", "target": "commands", "hidden": 40, "iterations": 768000}
    | {"learning_rate_schedule": "anneal"},
]


def with_default(config: dict, entries: list[dict]) -> dict:
    """The config with ``entries`` as robot.default."""
    return config | {"robot": config["robot"] | {"default": entries}}


def test_the_default_build_tests_the_own_networks_and_the_confirmations_alone(plan, config):
    """Issue 47: the default build pays for no exploration on the robot: it tests the config's
    own networks (a job each) and each confirmed variant on its fresh networks, nothing else;
    the full scale tests every variant of the grid on networks 0.. as well, the confirmed
    variant's exploration among them."""
    assert config["robot"]["default"] == []
    assert plan.robot_runs == [MAIN]
    assert plan.robot_tested_runs == [MAIN, *plan.confirmation_runs]
    assert plan.confirmation_runs == ["robot_commands_h40_it768000_all_steps_anneal_confirm"]
    assert [row["run"] for row in plan.robot_tested] == [MAIN]
    assert plan.served_by("robot_test", "robot_test") == [MAIN, *plan.confirmation_runs]
    assert plan.phase1_owners == []  # no variant trains on networks 0.., so no shared phase 1
    full = plan_runs(config | {"robustness": True})
    grid = {NetworkVariant.of(v.row(), config["network"]) for v in NetworkVariant.grid(
        config["robot"])}  # fmt: skip
    assert {NetworkVariant.from_row(r) for r in full.robot_tested} == grid
    assert full.robot_tested_runs == [*full.robot_runs, *full.confirmation_runs]
    explored = [row["exploration"] for row in full.confirmation]
    assert set(explored) <= set(full.robot_runs) and len(full.robot_runs) == len(grid)


def test_the_exploration_row_is_tested_only_where_the_build_tests_its_run(plan, config):
    """The confirmation table's exploration run: None in the default build (not tested there),
    the grid's run at full scale, and in the default build once robot.default lists it."""
    (row,) = plan.confirmation_tested
    explored = plan.confirmation[0]["exploration"]
    assert row == plan.confirmation[0] | {"exploration": None}
    (full,) = plan_runs(config | {"robustness": True}).confirmation_tested
    assert full == plan.confirmation[0] and full["exploration"] == explored
    (listed,) = plan_runs(with_default(config, EARLIER_DEFAULT[2:])).confirmation_tested
    assert listed["exploration"] == explored


def test_a_confirmed_animation_films_the_confirmations_fresh_networks(plan, config):
    """The animated variant is the confirmed one, not tested on networks 0.. in the default
    build: the films show its confirmation run's first network of each mapping (fresh indices
    12.., the first half mapping A: 12 and 18; 12 and 30 of the full scale's 36). Listed in
    robot.default, or the config's own networks, it is filmed on networks 0 and 6; a variant
    the default build does not test is refused."""
    entry = config["robot"]["animation"]["variant"]
    run = plan.confirmation_runs[0]
    assert plan.animated(entry) == (run, ["12", "18"])
    assert plan_runs(config | {"robustness": True}).animated(entry) == (run, ["12", "30"])
    listed = plan_runs(with_default(config, EARLIER_DEFAULT[2:]))
    assert listed.animated(entry) == (plan.confirmation[0]["exploration"], ["00", "06"])
    assert plan.animated(config["network"]) == (MAIN, ["00", "06"])
    with pytest.raises(ValueError, match="not tested in the default build"):
        plan.animated({"target": "sensed", "hidden": 20, "iterations": 48000})


@pytest.mark.heavy
def test_robot_variants_that_differ_only_after_phase_1_share_it(plan, config):
    """Earlier defaults' three variants (40 hidden, 768,000 iterations: two cue timings, two
    schedules), listed in robot.default, share one phase 1; the config's own run and a
    confirmation (fresh networks) train whole. With robustness, each tested group of cue
    timings x schedules shares."""
    listed = plan_runs(with_default(config, EARLIER_DEFAULT))
    first = "robot_commands_h40_it768000"
    for run in (first, f"{first}_all_steps", f"{first}_all_steps_anneal"):
        assert listed.phase1_run(run) == first
    assert listed.phase1_run(MAIN) is None
    assert all(listed.phase1_run(run) is None for run in listed.confirmation_runs)
    assert all(plan.phase1_run(run) is None for run in plan.runs)  # the default tests none
    full = plan_runs(config | {"robustness": True})
    owners = {}
    for run in full.runs:
        if (owner := full.phase1_run(run)) is not None:
            owners.setdefault(owner, []).append(run)
            differ = {
                k
                for k in full.config(run)["network"]
                if full.config(run)["network"][k] != full.config(owner)["network"][k]
            }
            assert differ <= {"learning_rate_schedule", "categorisation_cue"}
    assert owners and all(
        2 <= len(runs) <= 4 and runs[0] == owner for owner, runs in owners.items()
    )


def test_the_scale_counts_what_each_build_trains(plan, config):
    """The reproduce page's scale: the default build and the full one, counted from the plan
    and checked against the config's lists."""
    study, readings = config["size_dose"], config["readings"]
    crossed = study["crossed"]
    # per cue timing and replication: each dose under each grip arrangement, and the removal
    # control
    conditions = len(study["doses"]) * len(crossed["grip_arrangements"]) + study["removal"]
    per_replication = len(study["categorisation_cue"]) * conditions
    assert plan.scale() == {
        "reading_seeds": len(config["confirmation"]["seeds"]),
        "readings": len(readings["categorisation_cue"]) * len(readings["goal_response"]),
        "size_runs": per_replication * crossed["replications"],
        "size_replications": crossed["replications"],
        "variants": len(config["robot"]["default"]),
        "fresh": config["robot"]["confirmation"]["networks"],
        "sweep": 0,
    }
    full = plan_runs(config | {"robustness": True}).scale()
    declared = config["confirmation"]
    assert full["reading_seeds"] == len(declared["seeds"]) + len(declared["robustness_seeds"])
    assert full["size_runs"] == per_replication * crossed["robustness_replications"]
    assert full["size_replications"] == crossed["robustness_replications"]
    assert full["fresh"] == config["robot"]["confirmation"]["robustness_networks"]
    assert full["variants"] + 1 == len(NetworkVariant.grid(config["robot"]))
    assert full["sweep"] == len(config["sweep"]["seeds"]) * len(
        config["sweep"]["categorisation_cue"]
    )


# ---- the variant type ----------------------------------------------------------------------------


def test_a_variant_entry_takes_the_configs_value_for_what_it_leaves_out(config):
    network = config["network"]
    entry = {"target": "commands", "hidden": 40, "iterations": 768000}
    variant = NetworkVariant.of(entry, network)
    assert variant.categorisation_cue == network["categorisation_cue"]
    assert variant.learning_rate_schedule == network["learning_rate_schedule"]
    assert NetworkVariant.of(network, network).run_name(network).startswith("robot_")


def test_a_variants_name_leaves_out_what_equals_the_config():
    network = {"categorisation_cue": "first_step", "learning_rate_schedule": "constant"}
    plain = NetworkVariant("first_step", "sensed", 10, 3000, "constant")
    assert plain.run_name(network) == "robot_sensed_h10_it3000"
    other = NetworkVariant("all_steps", "commands", 40, 768000, "anneal")
    assert other.run_name(network) == "robot_commands_h40_it768000_all_steps_anneal"
    assert other.label() == "cue all steps, commands, 40 hidden, 768,000 iterations, annealed rate"
    assert other.label(leave_out=("categorisation_cue",)).startswith("commands, 40 hidden")


def test_phase_one_keeps_its_share_and_leaves_an_even_phase_two():
    network = {"iterations": 3000, "phase1_iterations": 1000}
    for iterations in (12000, 48000, 192000, 768000, 12004):
        settings = NetworkVariant("first_step", "sensed", 10, iterations, "constant").network(
            network
        )
        phase1 = settings["phase1_iterations"]
        assert (iterations - phase1) % 2 == 0
        assert abs(phase1 - iterations / 3) <= 1
        assert settings["iterations"] == iterations


def test_the_grid_is_every_combination_in_the_keys_order(config):
    robot = config["robot"]
    grid = NetworkVariant.grid(robot)
    sizes = [len(robot[k]) for k in NetworkVariant.keys()]
    assert len(grid) == len(set(grid)) == __import__("math").prod(sizes)
    assert grid[0].values() == tuple(robot[k][0] for k in NetworkVariant.keys())
    assert grid[1].values()[-1] == robot[NetworkVariant.keys()[-1]][1]


def test_a_new_dimension_is_one_field(config):
    """A sixth dimension, added as a field of a type like NetworkVariant: the grid, the names,
    the rows, the labels and the trainer's settings follow without other code."""
    extra = dataclasses.field(
        default=0.5,
        metadata={"name": "s{}", "always": False, "order": 5, "label": lambda v: f"scale {v}"},
    )
    Six = dataclasses.make_dataclass(
        "Six", [("init_scale", float, extra)], bases=(NetworkVariant,), frozen=True
    )
    network = config["network"]
    robot = config["robot"] | {"init_scale": [network["init_scale"], 0.1]}
    grid = Six.grid(robot)
    assert len(grid) == 2 * len(NetworkVariant.grid(config["robot"]))
    assert Six.keys()[-1] == "init_scale"
    changed = next(v for v in grid if v.init_scale == 0.1)
    assert changed.run_name(network).endswith("_s0.1")
    assert changed.network(network)["init_scale"] == 0.1
    assert changed.label().endswith("scale 0.1")
    assert (
        Six.of({"target": "sensed", "hidden": 10, "iterations": 4}, network).init_scale
        == (network["init_scale"])
    )


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("cue_all_steps", "cue ablation"),
        ("robot_commands_h40_it768000", "robot variant"),
        ("reading_all_steps_grows_seed101", "reading"),
        ("size_dose0.6_swapped_first_step_seed121", "size study's run"),
    ],
)
def test_a_user_run_named_like_a_run_the_plan_makes_is_refused(config, name, words):
    """Issue 49, item 7: the user's settings would silently replace the plan's own run."""
    from icub_workflow.config_checks import ConfigError

    with pytest.raises(ConfigError) as refused:
        plan_runs(config | {"runs": {name: {"seed": 3}}})
    message = str(refused.value)
    for word in (f"runs.{name}", words, "Fix: rename"):
        assert word in message, (word, message)
    assert "half_lr" in plan_runs(config | {"runs": {"half_lr": {"seed": 3}}}).runs


# ---- the jobs of the default target, from the plan alone (no Snakemake) ----------------------
# tests/test_stats.py holds a dry run's job stats to RunPlan.job_counts for each configuration.


def test_the_default_build_trains_the_own_networks_a_job_each_and_each_other_run_in_one(
    plan, config
):
    counts = plan.job_counts()
    n = config["network"]["networks"]
    confirmed = len(config["robot"]["confirmation"]["variants"])
    # the config's own networks a job each; the cue ablation's in one job, each confirmation's
    # fresh ones in one job (their part `all`), each words replication's in one job
    words = config["words"]
    n_words = len(words["seeds"]) * len(words["cues"])
    assert counts["train"] == n + 1 + confirmed + n_words
    # on the robot likewise: the config's own a job each, each confirmation's in one
    assert counts["robot_test"] == n + confirmed
    # tested in silico: the config's own run and the cue ablation
    assert counts["evaluate"] == counts["stats"] == counts["figure5"] == 2
    # a replication of the whole model per seed: the confirmation's (every reading) and the
    # size study's, each trained and measured in one job; demonstrations per seed, the config's
    # own seed's too; the SOMs of the config's own run alone by rule soms
    crossed = config["size_dose"]["crossed"]
    seeds = [*config["confirmation"]["seeds"], *crossed["seeds"][: crossed["replications"]]]
    assert counts["measured"] == len(set(seeds))  # rule measured: a job per seed's group
    assert not [r for r in counts if r.startswith("measured_")]
    # the words study's: a replication's cue timings share them
    assert counts["demos"] == len({config["seed"], *seeds, *words["seeds"]})
    assert counts["soms"] == 1 + len(words["seeds"])
    assert counts["measures"] == 1  # the config's own: the book reads it
    assert counts["size_free_maps"] == int(config["size_dose"]["removal"])
    assert "phase1" not in counts  # no two long trainings share a phase 1 in this build


def test_without_robustness_the_test_build_tests_its_own_networks_and_the_confirmation():
    config = load_test_config() | {"robustness": False}
    counts = plan_runs(config).job_counts()
    n = config["network"]["networks"]
    assert counts["robot_test"] == n + 1  # the confirmation's networks: its part `all`
    assert "phase1" not in counts
    assert not [rule for rule in counts if rule.startswith("sweep")]


def test_with_robustness_the_plan_adds_the_sweep_and_the_robot_grid_in_one_job_each():
    import itertools

    from icub_affordance.analysis.paper_claims import seeds as claim_seeds

    config = load_test_config() | {"robustness": True}
    counts = plan_runs(config).job_counts()
    n, net, readings = config["network"]["networks"], config["network"], config["readings"]
    sweep = config["sweep"]
    keys = ("seeds", "learning_rate", "hidden", "categorisation_cue")
    points = list(itertools.product(*(sweep[key] for key in keys)))
    # a sweep point at a reading's settings and seed is that reading's replication: trained once
    shared = sum(
        1
        for seed, lr, hidden, cue in points
        if seed in [*claim_seeds(config["confirmation"], True), config["seed"]]
        and cue in readings["categorisation_cue"]
        and config["soms"]["goal_response"] in readings["goal_response"]
        and (lr, hidden) == (net["learning_rate"], net["hidden"])
    )
    robot = config["robot"]
    variants = len(robot["target"]) * len(robot["hidden"]) * len(robot["iterations"])
    own = (net["target"], net["hidden"], net["iterations"]) in itertools.product(
        robot["target"], robot["hidden"], robot["iterations"]
    )
    # the config's own networks a job each, every other variant's in one, the confirmation's
    assert counts["robot_test"] == n + variants - own + 1
    # and trained: the cue ablation, the sweep points (but those that are a reading's
    # replication, trained with its seed's measured runs), the robot variants and the words
    # study's replications
    words = config["words"]
    n_words = len(words["cues"]) * len(words["seeds"] + words["robustness_seeds"])
    assert counts["train"] == n + 1 + len(points) - shared + variants - own + 1 + n_words
    # the main run, the cue ablation and the sweep points are tested in silico; a point's ANOVAs
    # are the sweep summary's, and no page shows its Figure 5: the main run's and the ablation's
    assert counts["evaluate"] - 2 == len(points)
    assert counts["stats"] == counts["figure5"] == 2


@pytest.mark.parametrize("robustness", [False, True])
def test_the_words_study_is_the_whole_model_with_names_at_each_seed_and_cue(config, robustness):
    """A run per declared seed and cue timing, names on and nothing else changed, its own
    demonstrations and maps shared by its two cue timings only, trained in one job, then tested
    in every form (rule word_trials); the paper's tests (evaluate) it does not run."""
    config = config | {"robustness": robustness}
    plan = plan_runs(config)
    words = config["words"]
    seeds = words["seeds"] + (words["robustness_seeds"] if robustness else [])
    assert [(r["cue"], r["seed"]) for r in plan.words] == [
        (cue, seed) for cue in words["cues"] for seed in seeds
    ]
    for row in plan.words:
        run = plan.runs[row["run"]]
        assert run.origin == "words" and run.config["names"]["use"] is True
        assert run.config["seed"] == row["seed"]
        assert run.config["network"]["categorisation_cue"] == row["cue"]
        assert merged(config, run.overrides) == run.config
        assert set(run.overrides) == {"seed", "names", "network"}
        for stage in ("demos", "soms"):
            owner = plan.stage_run(row["run"], stage)
            assert plan.runs[owner].origin == "words" and plan.config(owner)["seed"] == row["seed"]
        assert plan.built_steps(row["run"])[-2:] == ["train", "word_trials"]
        assert plan.parts(row["run"]) == ["all"]
    counts = plan.job_counts()
    assert counts["word_trials"] == len(plan.words) == len(words["cues"]) * len(seeds)
