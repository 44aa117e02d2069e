"""The config's checks beyond the schema (src/icub_workflow/config_checks.py), tried directly: every
refusal names the key, the value, what is allowed and the fix."""

from __future__ import annotations

import shutil

import pytest
import yaml
from conftest import REPO, load_config

from icub_workflow.config_checks import (
    ConfigError,
    check_command_line,
    check_config,
    check_scene,
    typed_overrides,
)


def refusal(change, prefix: str = "") -> str:
    config = load_config()
    change(config)
    with pytest.raises(ConfigError) as info:
        check_config(config, prefix)
    return str(info.value)


def test_the_default_and_the_test_config_pass():
    from conftest import load_test_config

    check_config(load_config())
    check_config(load_test_config())


@pytest.mark.parametrize(
    ("change", "words"),
    [
        # phase 1 longer than the training, and an odd phase 2
        (
            lambda c: c["network"].update(phase1_iterations=13000),
            ["network.phase1_iterations", "13000", "0..12000", "Fix"],
        ),
        (
            lambda c: c["network"].update(phase1_iterations=5999),
            ["network.phase1_iterations", "5999", "odd", "Fix"],
        ),
        # names whose training shares do not split a phase into whole trials, or show nothing
        (
            lambda c: c["names"].update(
                use=True, training={"phase1": {"both": 1}, "phase2": {"image": 7}}
            ),
            ["names.training.phase2", "6000", "divide", "Fix"],
        ),
        (
            lambda c: c["names"].update(
                use=True, training={"phase1": {"both": 0}, "phase2": {"image": 1}}
            ),
            ["names.training.phase1", "every weight is 0", "Fix"],
        ),
        # the words study's replications not fresh, or counted twice
        (
            lambda c: c["words"].update(seeds=[101, 141]),
            ["words.seeds", "[101]", "confirmation.seeds", "fresh", "Fix"],
        ),
        (
            lambda c: c["words"].update(robustness_seeds=[150, 151]),
            ["words.robustness_seeds", "[150]", "words.seeds too", "Fix"],
        ),
        # the window outside the image, or not a multiple of the grid
        (
            lambda c: c["vision"].update(window=300),
            ["vision.window", "300", "320x240", "at most 240", "Fix"],
        ),
        (lambda c: c["vision"].update(window=105), ["vision.window", "105", "multiple of 10"]),
        # the posture outside Figure 1's ranges
        (
            lambda c: c["initial_posture_deg"].__setitem__(3, 150),
            ["initial_posture_deg[3]", "150", "elbow", "6..106", "Fix"],
        ),
        (
            lambda c: c["initial_posture_deg"].__setitem__(0, -120),
            ["initial_posture_deg[0]", "-120", "shoulder pitch", "-95..90"],
        ),
        # the lift check cannot pass
        (
            lambda c: c["demos"].update(min_lift_m=0.08),
            ["demos.min_lift_m", "0.08", "demos.lift_m", "Fix"],
        ),
        # the figures' picks outside the data
        (
            lambda c: c["figures"].update(filmstrip=[["big_ball", "power", 99]]),
            ["figures.filmstrip[0]", "99", "demos.sequences = 5", "0..4", "Fix"],
        ),
        (
            lambda c: c.update(objects=["big_ball", "small_ball"]),
            ["figures.filmstrip[1]", "small_cube", "objects", "Fix"],
        ),
        (
            lambda c: c["figures"]["embodied"].update(sequence=5),
            ["figures.embodied.sequence", "5", "0..4"],
        ),
        (
            lambda c: c.update(objects=["small_ball", "big_cube", "small_cube"]),
            ["figures.embodied.object", "big_ball", "objects"],
        ),
        # a robot variant of the default build outside the grid; an animation of a variant the
        # default build does not test (not the own networks, robot.default or a confirmation)
        (
            lambda c: c["robot"]["default"].append(
                {"target": "commands", "hidden": 80, "iterations": 12000}
            ),
            ["robot.default[0]", "'hidden': 80", "grid", "Fix"],
        ),
        (
            lambda c: c["robot"]["animation"].update(
                variant={"target": "sensed", "hidden": 40, "iterations": 12000}
            ),
            ["robot.animation.variant", "'hidden': 40", "robot.default", "Fix"]
            + ["robot.confirmation.variants", "fresh networks"],
        ),
        # an entry's cue timing outside the grid's (an entry that leaves it out has the network's)
        (
            lambda c: (
                c["robot"].update(categorisation_cue=["all_steps"]),
                c["robot"]["default"].append(
                    {"target": "commands", "hidden": 40, "iterations": 768000}
                ),
            ),
            ["robot.default[0]", "categorisation_cue first_step", "grid", "Fix"],
        ),
        # a confirmed variant whose cue timing or schedule the grid does not explore
        (
            lambda c: c["robot"].update(categorisation_cue=["first_step"]),
            ["robot.confirmation.variants[0]", "'categorisation_cue': 'all_steps'", "grid"],
        ),
        (
            lambda c: c["robot"].update(learning_rate_schedule=["constant"]),
            ["robot.confirmation.variants[0]", "'learning_rate_schedule': 'anneal'", "grid", "Fix"],
        ),
        (
            lambda c: c["robot"]["tolerance"].update(noise=[0.01, 0.02]),
            ["robot.tolerance.noise", "0.01", "add 0"],
        ),
        (
            lambda c: c["robot"]["animation"].update(object="pear"),
            ["robot.animation.object", "pear", "objects"],
        ),
        # a confirmation of a variant no exploration tried, on the exploration's networks,
        # past net99
        (
            lambda c: c["robot"]["confirmation"]["variants"].append(
                {"categorisation_cue": "first_step", "target": "sensed", "hidden": 80}
                | {"iterations": 48000, "learning_rate_schedule": "anneal"}
            ),
            ["robot.confirmation.variants[1]", "'hidden': 80", "not a variant of the grid", "Fix"],
        ),
        (
            lambda c: c["robot"]["confirmation"].update(first_network=6),
            ["robot.confirmation.first_network", "6", "fresh", "at least 12", "Fix"],
        ),
        (
            lambda c: c["robot"]["confirmation"].update(first_network=70),
            ["robot.confirmation.first_network", "70", "net99", "at most 64", "Fix"],
        ),
        (
            lambda c: c["robot"]["confirmation"].update(robustness_networks=8),
            ["robot.confirmation.robustness_networks", "8", "at least 12", "Fix"],
        ),
        # a margin's declaration for a measure that has no margin
        (
            lambda c: c["readings"]["margin_declared"].update(
                speed={"commit": "abc1234", "results_before": False}
            ),
            ["readings.margin_declared", "['speed']", "equivalence_margin", "Fix"],
        ),
        # the claims' confirmation on a seed another part of the build uses, or twice
        (
            lambda c: c["confirmation"].update(seeds=[101, 2009]),
            ["confirmation.seeds", "[2009]", "seed", "Fix"],
        ),
        (
            lambda c: c["confirmation"].update(robustness_seeds=[110, 111]),
            ["confirmation.robustness_seeds", "repeats", "Fix"],
        ),
        (
            lambda c: c["confirmation"].update(seeds=[1, 101]),
            ["confirmation.seeds", "[1]", "sweep.seeds", "Fix"],
        ),
        # the size study's crossed design on a seed another part of the build uses, or too few
        (
            lambda c: c["size_dose"]["crossed"].update(seeds=[105, *range(121, 140)]),
            ["size_dose.crossed.seeds", "[105]", "confirmation.seeds", "Fix"],
        ),
        (
            lambda c: c["size_dose"]["crossed"].update(seeds=[121, 122, 123]),
            ["size_dose.crossed.seeds", "3 seeds for 20 replications", "Fix"],
        ),
        # the swapped grips need each object's same-shape partner
        (
            lambda c: c.update(objects=[o for o in c["objects"] if o != "small_cube"]),
            ["size_dose.crossed.grip_arrangements", "same-shape partner", "Fix"],
        ),
        # a signature tested by what its condition cannot give, twice, or without its levels
        (
            lambda c: c["signatures"]["list"][0].update(test="equivalence", expected="same"),
            ["signatures.list.0", "grows_with_rt", "'slope'", "Fix"],
        ),
        (
            lambda c: c["signatures"]["list"].append(dict(c["signatures"]["list"][0])),
            ["signatures.list.4", "listed twice", "Fix"],
        ),
        (
            lambda c: c["signatures"]["list"][1].pop("levels"),
            ["signatures.list.1", "extinction", "needs `levels`", "Fix"],
        ),
    ],
)
def test_a_rule_between_keys_is_refused_naming_key_value_allowed_and_fix(change, words):
    message = refusal(change)
    for word in words:
        assert word in message, (word, message)


@pytest.mark.parametrize(
    ("change", "words"),
    [
        # the case: the confirmation declares every-step tests no reading replicates
        (
            lambda c: c["readings"].update(categorisation_cue=["first_step"]),
            ["confirmation.cues", "['all_steps'] has no replication", "Fix"],
        ),
        (
            lambda c: c["readings"].update(goal_response=["grows"]),
            ["readings.goal_response", "soms.goal_response: fixed", "Fix"],
        ),
        (
            lambda c: c["readings"].update(measures=["rmse"]),
            ["confirmation.measures", "['rmse_correct']", "Fix"],
        ),
        (
            lambda c: (
                c["network"].update(categorisation_cue="all_steps")
                or c["confirmation"].update(cues=["first_step"])
            ),
            ["confirmation.cues", "network.categorisation_cue: all_steps", "Fix"],
        ),
        (
            lambda c: c["confirmation"].update(min_replications=11),
            ["confirmation.min_replications", "11", "Allowed: at most 10", "Fix"],
        ),
        (
            lambda c: c["size_dose"]["crossed"].update(replications=4),
            [
                "size_dose.crossed.replications",
                "4",
                "confirmation.min_replications (5)",
                "Allowed: at least 5",
                "Fix",
            ],
        ),
        (
            lambda c: c["size_dose"]["crossed"].update(robustness_replications=3),
            ["size_dose.crossed.robustness_replications", "3", "Allowed: at least 5", "Fix"],
        ),
        (
            lambda c: c["words"].update(min_replications=11),
            ["words.min_replications", "11", "Allowed: at most 10", "Fix"],
        ),
        (
            lambda c: c["confirmation"].update(pilot="config/no_such_pilot.csv"),
            ["confirmation.pilot", "config/no_such_pilot.csv", "not a file", "Fix"],
        ),
        (
            lambda c: c["readings"].update(goal_response=["fixed"]),
            ["readings.equivalence_margin", "Goal response", "Fix"],
        ),
        (
            lambda c: c["robot"]["confirmation"]["contact_time"].update(min_networks=13),
            ["robot.confirmation.contact_time.min_networks", "13", "at most 12", "Fix"],
        ),
    ],
)
def test_a_declaration_no_run_backs_is_refused_naming_key_and_fix(change, words):
    """A declared test, margin or minimum whose runs the build does not make would pass every
    check and then rest on nothing: refused, naming the key and the fix; the shipped configs
    pass."""
    message = refusal(change)
    for word in words:
        assert word in message, (word, message)


def test_a_run_of_runs_declares_nothing_so_its_cue_timing_is_free():
    """A run laid over the config is checked by the rules between keys, not as a declaration:
    another cue timing than the confirmation's passes for it, not for the config's own."""
    from icub_workflow.config_checks import check_runs, load_schema

    schema = load_schema(REPO / "workflow" / "schemas" / "config.schema.yaml")
    config = load_config()
    config["confirmation"]["cues"] = ["first_step"]
    config["runs"] = {"other_cue": {"network": {"categorisation_cue": "all_steps"}}}
    check_runs(config, schema)
    config["network"]["categorisation_cue"] = "all_steps"
    with pytest.raises(ConfigError, match="lacks the config's own cue timing"):
        check_config(config)


def test_a_confirmed_variant_of_the_grid_need_not_be_tested_in_the_default_build():
    """The exploration is the grid's, tested at full scale: a confirmed variant that the default
    build does not test on networks 0.. (robot.default empty) passes, and so does an animation
    of it (its fresh networks are filmed); the same variant outside the grid is refused, once:
    the animation of a confirmed variant is not a second fault."""
    config = load_config()
    config["robot"]["default"] = []
    entry = {"categorisation_cue": "first_step", "target": "sensed", "hidden": 20}
    entry |= {"iterations": 48000, "learning_rate_schedule": "anneal"}
    config["robot"]["confirmation"]["variants"] = [entry]
    config["robot"]["animation"]["variant"] = entry
    check_config(config)
    config["robot"]["hidden"] = [10, 40]
    with pytest.raises(ConfigError) as info:
        check_config(config)
    assert "robot.confirmation.variants[0]" in str(info.value)
    assert "robot.animation.variant" not in str(info.value)


def test_the_declared_words_study_is_fresh_and_has_ten_replications():
    """The words study's seeds (declared before any result with names) are at least ten, and no
    other run of either scale's plan is made at any of them."""
    from icub_workflow.runs import plan_runs

    config = load_config()
    words = config["words"]
    assert len(words["seeds"]) >= 10
    for robustness in (False, True):
        plan = plan_runs(config | {"robustness": robustness})
        used = {run.config["seed"] for run in plan.runs.values() if run.origin != "words"}
        assert not used & set(words["seeds"] + words["robustness_seeds"])


def test_the_default_confirmation_is_fresh_and_large_enough():
    """Issue 24: the default build confirms on at least 12 fresh networks, robustness on at
    least 36, and the variant confirmed is the one the exploration picked (the annealed all-steps
    servo-target variant, 40 hidden, 768,000 iterations)."""
    config = load_config()
    confirmation = config["robot"]["confirmation"]
    assert confirmation["networks"] >= 12 and confirmation["robustness_networks"] >= 36
    assert confirmation["first_network"] >= config["network"]["networks"]
    assert confirmation["variants"] == [
        {"categorisation_cue": "all_steps", "target": "commands", "hidden": 40}
        | {"iterations": 768000, "learning_rate_schedule": "anneal"}
    ]


def test_every_problem_is_listed_at_once_and_a_run_is_named():
    def change(c):
        c["network"].update(phase1_iterations=20000)
        c["vision"].update(window=250)

    message = refusal(change, prefix="runs.half_lr.")
    assert "2 problems" in message
    assert "runs.half_lr.network.phase1_iterations" in message
    assert "runs.half_lr.vision.window" in message


@pytest.mark.parametrize(
    ("given", "meant"),
    [
        ({"network": {"networks": "12"}}, {"network": {"networks": 12}}),
        ({"network": {"learning_rate": "0.0375"}}, {"network": {"learning_rate": 0.0375}}),
        (
            {"network": {"categorisation_cue": "all_steps"}},
            {"network": {"categorisation_cue": "all_steps"}},
        ),  # noqa: E501
        (
            {"runs": {"x": {"network": {"hidden": "5"}}}},
            {"runs": {"x": {"network": {"hidden": 5}}}},
        ),  # noqa: E501
        ({"initial_posture_deg": ["-50", "30"]}, {"initial_posture_deg": [-50, 30]}),
        ({"sweep": {"seeds": ["1", "2"]}}, {"sweep": {"seeds": [1, 2]}}),
        # top-level values are Snakemake's own reading, kept as they are
        ({"seed": 7, "robustness": True}, {"seed": 7, "robustness": True}),
        ({"scene": "assets/x.xml"}, {"scene": "assets/x.xml"}),
    ],
)
def test_nested_command_line_values_are_read_as_in_a_config_file(given, meant):
    assert typed_overrides(given) == meant


def test_robustness_as_text_is_refused_with_the_spelling_that_works():
    with pytest.raises(ConfigError, match="robustness=True"):
        check_command_line({"robustness": "true"})
    check_command_line({"robustness": True})


def test_the_scene_is_loaded_and_checked(tmp_path):
    config = load_config()
    config["scene"] = str(REPO / "assets" / "icub_scene.xml")
    check_scene(config)

    config["scene"] = str(tmp_path / "nope.xml")
    with pytest.raises(ConfigError, match=r"config key scene: .*nope\.xml.*Fix"):
        check_scene(config)

    broken = tmp_path / "broken.xml"
    broken.write_text("<mujoco><worldbody><body></mujoco>")
    config["scene"] = str(broken)
    with pytest.raises(ConfigError, match=r"config key scene: .*broken\.xml.*cannot be used"):
        check_scene(config)

    # well-formed XML, but not the iCub scene
    empty = tmp_path / "empty.xml"
    empty.write_text("<mujoco><worldbody/></mujoco>")
    config["scene"] = str(empty)
    with pytest.raises(ConfigError, match=r"config key scene: .*empty\.xml.*Figure 1"):
        check_scene(config)

    # the scene without a camera the rules render from
    for name in ("icub_scene.xml", "icub_right_arm.xml"):
        shutil.copy(REPO / "assets" / name, tmp_path / name)
    scene = tmp_path / "icub_scene.xml"
    scene.write_text(scene.read_text().replace('name="closeup"', 'name="elsewhere"'))
    config["scene"] = str(scene)
    with pytest.raises(ConfigError, match=r"lacks the camera\(s\) \['closeup'\]"):
        check_scene(config)


def test_the_schema_bounds_every_number():
    """No number in the schema is left without both bounds (a range, an enum or a rule here)."""
    schema = yaml.safe_load((REPO / "workflow/schemas/config.schema.yaml").read_text())
    unbounded = []

    def visit(node, path):
        if isinstance(node, dict):
            if node.get("type") in ("number", "integer"):
                low = "minimum" in node or "exclusiveMinimum" in node
                high = "maximum" in node or "exclusiveMaximum" in node
                if not (low and high):
                    unbounded.append(path)
            for key, value in node.items():
                visit(value, f"{path}.{key}")
        elif isinstance(node, list):
            for i, value in enumerate(node):
                visit(value, f"{path}[{i}]")

    visit(schema, "schema")
    assert not unbounded, unbounded


SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"


@pytest.mark.parametrize(
    ("change", "words"),
    [
        (lambda c: c["network"].update(hidden=0), ["network.hidden", "0", "1 <= x <= 1000", "Fix"]),
        (lambda c: c["network"].update(networks=7), ["network.networks", "7", "multiple of 2"]),
        (lambda c: c.update(seed="abc"), ["config key seed", "'abc'", "whole number", "Fix"]),
        (lambda c: c["vision"].update(eye="nose_eye"), ["vision.eye", "nose_eye", "left_eye"]),
        (lambda c: c.update(learningrate=0.1), ["learningrate", "no such key", "network", "Fix"]),
        (lambda c: c["network"].pop("hidden"), ["config key network", "hidden", "required", "Fix"]),
        (
            lambda c: c["initial_posture_deg"].__setitem__(0, 400),
            ["initial_posture_deg.0", "400", "-180 <= x <= 180"],
        ),
        (lambda c: c["demos"].update(touch_threshold=50), ["demos.touch_threshold", "50", "10"]),
        (
            lambda c: c["sweep"].update(seeds=[5_000_000_000]),
            ["sweep.seeds.0", "5000000000", "4294967295"],
        ),
        (
            lambda c: c["robot"]["confirmation"].update(networks=7),
            ["robot.confirmation.networks", "7", "multiple of 2", "Fix"],
        ),
        (
            lambda c: c["robot"]["confirmation"]["variants"][0].pop("hidden"),
            ["robot.confirmation.variants.0", "hidden", "required"],
        ),
        (
            lambda c: c["runs"].update(x={"vision": {"window": 50}}),
            ["runs.x.vision", "no such key", "seed, network, soms"],
        ),
    ],
)
def test_a_schema_refusal_names_key_value_allowed_and_fix(change, words):
    from icub_workflow.config_checks import check_schema, load_schema

    config = load_config()
    check_schema(config, load_schema(SCHEMA))
    change(config)
    with pytest.raises(ConfigError) as info:
        check_schema(config, load_schema(SCHEMA))
    for word in words:
        assert word in str(info.value), (word, str(info.value))


def test_the_measures_names_come_from_their_registry(monkeypatch):
    """A measure is named once, in icub_affordance.trials.scores.MEASURES: the schema takes its
    valid `readings.measures` entries and the margins it requires from there."""
    from icub_affordance.trials import scores as measures
    from icub_workflow.config_checks import check_schema, load_schema

    config = load_config()
    config["readings"]["measures"] = [*config["readings"]["measures"], "new_measure"]
    with pytest.raises(ConfigError, match="new_measure"):
        check_schema(config, load_schema(SCHEMA))
    monkeypatch.setattr(measures, "MEASURES", (*measures.MEASURES, "new_measure"))
    with pytest.raises(ConfigError, match="new_measure"):  # now known, but it has no margin
        check_schema(config, load_schema(SCHEMA))
    config["readings"]["equivalence_margin"]["new_measure"] = 0.1
    schema = load_schema(SCHEMA)
    schema["properties"]["readings"]["properties"]["equivalence_margin"]["properties"][
        "new_measure"
    ] = {"type": "number"}
    check_schema(config, schema)
