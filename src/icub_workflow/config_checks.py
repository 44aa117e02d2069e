"""The config's checks beyond the schema, in one place: run when the workflow reads the config,
before any job (the Snakefile calls them; tests/test_config_checks.py tries them directly).

The schema (workflow/schemas/config.schema.yaml) checks each key alone: its type and range. What
it cannot say is checked here: rules between keys (the phases of training, the window inside the
image, the posture inside Figure 1's ranges, the figures' picks inside the data), the values of a
nested `--config` override (which Snakemake hands over as text), and the scene itself (loaded
once, with MuJoCo). Every refusal names the config key, the value, what is allowed and the fix.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

import yaml

from icub_affordance.learning.variants import NetworkVariant
from icub_affordance.vocabulary import DOF_MAX_DEG, DOF_MIN_DEG, FIGURE1, GRIPS
from icub_workflow.configs import merged

#: Where a user changes a value (named in every fix).
WHERE = "config/config.yaml (or your --configfile / --config)"

#: The cameras the rules render from: the eyes (config vision.eye), Figure 1's overview and the
#: filmstrips' close-up.
CAMERAS = ("left_eye", "right_eye", "overview", "closeup")
#: The filmstrips' frames (workflow/scripts/demo_filmstrip.py, robot_filmstrip.py), pixels.
FILMSTRIP_SIZE = (320, 240)


class ConfigError(ValueError):
    """A config the pipeline refuses, before any job: the message says what to change."""


# ---- --config on the command line ---------------------------------------------------------------


def typed_overrides(overrides: Mapping[str, Any]) -> dict[str, Any]:
    """The nested values of `--config` overrides read as YAML, as a config file would give them.

    Snakemake reads a top-level `--config key=value` as a number or True/False, but a nested one
    (`--config 'network={networks: 12}'`, its documented form for a section) with YAML's
    BaseLoader, which keeps every value as text: `networks` would be the string '12'. Here each
    such text is read again as YAML (`12` -> 12, `0.0375` -> 0.0375, `true` -> True), so a nested
    override means what the same line means in config/config.yaml. Top-level values are kept as
    Snakemake read them.
    """

    def typed(value: Any) -> Any:
        if isinstance(value, Mapping):
            return {key: typed(item) for key, item in value.items()}
        if isinstance(value, list):
            return [typed(item) for item in value]
        if isinstance(value, str):
            try:
                return yaml.safe_load(value) if value.strip() else value
            except yaml.YAMLError:
                return value
        return value

    return {
        key: typed(value) if isinstance(value, Mapping | list) else value
        for key, value in overrides.items()
    }


def check_command_line(overrides: Mapping[str, Any]) -> None:
    """Refuse top-level `--config` values that Snakemake read as text but are meant otherwise."""
    value = overrides.get("robustness")
    if isinstance(value, str):
        raise ConfigError(
            f"config key robustness: {value!r} is text, not a boolean. On the command line write "
            "it capitalised, as Snakemake reads booleans: --config robustness=True (or False)."
        )


# ---- the schema ---------------------------------------------------------------------------------


def _allowed(schema: Mapping[str, Any]) -> str:
    """What a schema node allows, in words."""
    if "enum" in schema:
        return "one of " + ", ".join(map(str, schema["enum"]))
    parts = []
    kind = schema.get("type")
    if kind:
        names = {"integer": "a whole number", "number": "a number", "array": "a list"}
        parts.append(names.get(kind, f"a {kind}"))
    low = schema.get("minimum", schema.get("exclusiveMinimum"))
    high = schema.get("maximum", schema.get("exclusiveMaximum"))
    if low is not None or high is not None:
        below = "<" if "exclusiveMinimum" in schema else "<="
        above = "<" if "exclusiveMaximum" in schema else "<="
        parts.append(
            " ".join(
                [*([f"{low} {below}"] if low is not None else []), "x"]
                + ([f"{above} {high}"] if high is not None else [])
            )
        )
    if "multipleOf" in schema:
        parts.append(f"a multiple of {schema['multipleOf']}")
    if "minItems" in schema or "maxItems" in schema:
        parts.append(
            f"{schema.get('minItems', 0)} to {schema.get('maxItems', 'any number of')} items"
        )
    if schema.get("uniqueItems"):
        parts.append("no repeats")
    if "pattern" in schema:
        parts.append(f"matching {schema['pattern']}")
    if isinstance(schema.get("properties"), Mapping):
        parts.append("the keys " + ", ".join(schema["properties"]))
    text = ", ".join(parts) or "see the schema"
    if schema.get("description"):
        text += f" ({_first_sentence(str(schema['description']))})"
    return text


def _first_sentence(description: str) -> str:
    """The first sentence of a schema description: what the key is, for a refusal; the schema
    holds the rest (some descriptions run to a paragraph)."""
    words = " ".join(description.split())
    end = re.search(r"[.;](?=\s+[A-Z(`])", words)
    return words[: end.start()] if end else words.rstrip(".")


def load_schema(path: str | Path) -> dict[str, Any]:
    """The config's JSON schema (workflow/schemas/config.schema.yaml), with the measures' and the
    signatures' names filled in from where they are declared
    (``icub_affordance.trials.scores.MEASURES``,
    ``icub_affordance.analysis.signature_tests.TESTS``): a measure added there is a valid
    ``readings.measures`` entry and needs an equivalence margin."""
    from icub_affordance.analysis.signature_tests import TESTS
    from icub_affordance.trials.scores import MEASURES

    # LibYAML's loader where PyYAML has it (it reads the schema ten times faster; every
    # Snakemake start reads it)
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    schema = yaml.load(Path(path).read_text(), Loader=loader)
    schema["$defs"]["measure"]["enum"] = list(MEASURES)
    entry = schema["properties"]["signatures"]["properties"]["list"]["items"]["properties"]
    entry["signature"]["enum"] = list(TESTS)
    readings = schema["properties"]["readings"]["properties"]
    readings["equivalence_margin"]["required"] = list(MEASURES)
    return schema


def schema_problem(
    config: Mapping[str, Any], schema: Mapping[str, Any], prefix: str = ""
) -> str | None:
    """The schema's most relevant complaint about `config`, as a refusal that names the key, the
    value, what is allowed and the fix (None: the config is valid)."""
    import jsonschema

    validator = jsonschema.Draft202012Validator(schema)
    error = jsonschema.exceptions.best_match(validator.iter_errors(config))
    if error is None:
        return None
    path = [str(p) for p in error.absolute_path]
    key = prefix + ".".join(path) if path else prefix.rstrip(".") or "(the whole config)"
    schema_file = "workflow/schemas/config.schema.yaml"
    if error.validator == "additionalProperties":
        extra = sorted(set(error.instance) - set(error.schema.get("properties", {})))
        where = f"{key}." if path or prefix else ""
        return (
            f"config key {where}{extra[0] if extra else '?'}: there is no such key here. Allowed: "
            f"{', '.join(error.schema.get('properties', {}))}. Fix: correct its spelling or "
            f"remove it ({schema_file} describes every key)."
        )
    if error.validator == "required":
        return (
            f"config key {key}: {error.message}. Fix: add it (config/config.yaml has every key "
            f"with its default; {schema_file} describes it)."
        )
    return (
        f"config key {key}: {error.instance!r} is refused ({error.message}). Allowed: "
        f"{_allowed(error.schema)}. Fix: set {key} to an allowed value in {WHERE}."
    )


def check_schema(config: Mapping[str, Any], schema: Mapping[str, Any], prefix: str = "") -> None:
    """Refuse a config that the schema refuses (see :func:`schema_problem`)."""
    problem = schema_problem(config, schema, prefix)
    if problem:
        raise ConfigError(problem)


# ---- rules between keys -------------------------------------------------------------------------


def _signature_problems(entries: list[Mapping[str, Any]], key) -> Iterator[str]:
    from icub_affordance.analysis.signature_tests import TESTS

    seen: set[str] = set()
    for i, entry in enumerate(entries):
        name, where = entry["signature"], key(f"signatures.list.{i}")
        test, expected, has_levels = TESTS[name]
        if name in seen:
            yield f"{where}: the signature {name} is listed twice. Fix: keep one entry."
        seen.add(name)
        if entry["test"] != test or entry["expected"] not in expected:
            yield (
                f"{where}: {name} with test {entry['test']!r} expecting {entry['expected']!r}; "
                f"its condition is tested by {test!r}, expecting one of {list(expected)}. Fix: "
                "set test and expected so."
            )
        if has_levels != ("levels" in entry):
            need = "needs `levels` (the steps it is seen)" if has_levels else "has no levels"
            yield f"{where}: {name} {need}. Fix: {'add' if has_levels else 'remove'} them."


def _distractor_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """The distractor's tests are declared on the confirmation's measures, and its two families
    are apart from each other and from the confirmation's (Holm within each alone)."""
    from icub_affordance.analysis.paper_claims import FAMILY

    declared = config["distractor"]
    if list(declared["measures"]) != list(config["confirmation"]["measures"]):
        yield (
            f"{key('distractor.measures')}: {declared['measures']} are not the confirmation's "
            f"measures {config['confirmation']['measures']}. Fix: declare the same list."
        )
    names = [declared["family"], declared["inhibition_family"], FAMILY]
    if len(set(names)) < len(names):
        yield (
            f"{key('distractor.family')}: the declared family, the inhibition's and the "
            "confirmation's need three different names. Fix: rename one."
        )


def _problems(config: Mapping[str, Any], prefix: str) -> Iterator[str]:
    """Every rule between keys that `config` breaks, one message each."""

    def key(name: str) -> str:
        return f"config key {prefix}{name}"

    yield from _signature_problems(config["signatures"]["list"], key)
    yield from _claims_problems(config, key)
    yield from _distractor_problems(config, key)

    network = config["network"]
    iterations, phase1 = network["iterations"], network["phase1_iterations"]
    if phase1 > iterations:
        yield (
            f"{key('network.phase1_iterations')}: {phase1} is more than network.iterations "
            f"({iterations}); phase 1 (grasping only) is part of the training. Allowed: "
            f"0..{iterations}. Fix: lower phase1_iterations or raise iterations."
        )
    elif (iterations - phase1) % 2:
        yield (
            f"{key('network.phase1_iterations')}: {phase1} leaves {iterations - phase1} "
            f"iterations for phase 2 (network.iterations = {iterations}), an odd number; phase 2 "
            "is half grasping, half categorisation. Allowed: iterations - phase1_iterations even. "
            "Fix: change either by one."
        )
    yield from _names_problems(config, key)

    vision = config["vision"]
    window, grid = vision["window"], vision["grid"]
    width, height = vision["width"], vision["height"]
    if window > min(width, height):
        yield (
            f"{key('vision.window')}: {window} pixels does not fit in the {width}x{height} eye "
            f"image (vision.width x vision.height). Allowed: at most {min(width, height)}. Fix: "
            "lower vision.window or enlarge the image."
        )
    if window % grid:
        yield (
            f"{key('vision.window')}: {window} is not a multiple of vision.grid ({grid}); each "
            f"map cell averages a whole block of pixels. Allowed: a multiple of {grid}, e.g. "
            f"{max(grid, window - window % grid)}. Fix: change vision.window or vision.grid."
        )

    posture = config["initial_posture_deg"]
    for k, angle in enumerate(posture):
        if not DOF_MIN_DEG[k] <= angle <= DOF_MAX_DEG[k]:
            yield (
                f"{key(f'initial_posture_deg[{k}]')}: {angle:g} degrees for {FIGURE1[k][1]} is "
                f"outside Figure 1's range for that joint. Allowed: {DOF_MIN_DEG[k]:g}.."
                f"{DOF_MAX_DEG[k]:g}. Fix: change item {k} (counting from 0) of "
                "initial_posture_deg."
            )

    demos = config["demos"]
    if demos["min_lift_m"] > demos["lift_m"]:
        yield (
            f"{key('demos.min_lift_m')}: {demos['min_lift_m']} m is more than demos.lift_m "
            f"({demos['lift_m']} m); the object cannot rise further than the hand lifts it. "
            f"Allowed: at most {demos['lift_m']}. Fix: lower min_lift_m or raise lift_m."
        )

    objects, sequences = list(config["objects"]), demos["sequences"]
    for i, pick in enumerate(config["figures"]["filmstrip"]):
        obj, grip, seq = pick
        here = key(f"figures.filmstrip[{i}]")
        if obj not in objects:
            yield (
                f"{here}: {pick} shows {obj!r}, which this run does not demonstrate (config "
                f"objects: {objects}). Allowed: one of {objects}. Fix: pick one of them or add "
                f"{obj!r} to objects."
            )
        if grip not in GRIPS:
            yield f"{here}: {pick}: grip {grip!r}. Allowed: one of {list(GRIPS)}."
        if not 0 <= seq < sequences:
            yield (
                f"{here}: {pick}: sequence {seq} does not exist; there are demos.sequences = "
                f"{sequences} per object and grip. Allowed: 0..{sequences - 1}. Fix: pick a "
                "sequence in that range."
            )
    robot, network = config["robot"], config["network"]
    grid = NetworkVariant.grid(robot)
    own = NetworkVariant.of(network, network)
    listed = [own]
    for i, entry in enumerate(robot["default"]):
        listed.append(NetworkVariant.of(entry, network))
        if listed[-1] not in grid:
            keys = NetworkVariant.keys()
            yield (
                f"{key(f'robot.default[{i}]')}: {entry} ({_variant_words(listed[-1])}) is not a "
                f"variant of the grid {' x '.join(f'robot.{k}' for k in keys)} (a key the entry "
                "leaves out is the network's). Allowed: a combination of "
                f"{', '.join(str(robot[k]) for k in keys)}. Fix: add its values to the grid or "
                "change the entry."
            )
    confirmed = [NetworkVariant.of(v, network) for v in robot["confirmation"]["variants"]]
    animated = robot["animation"]["variant"]
    if NetworkVariant.of(animated, network) not in [*listed, *confirmed]:
        yield (
            f"{key('robot.animation.variant')}: {animated} is not tested in the default build. "
            f"Allowed: the config's own networks ({_variant_words(own)}), an entry of "
            "robot.default, or a variant of robot.confirmation.variants (its fresh networks "
            "are filmed). Fix: pick one of them or add it to robot.default."
        )
    yield from _confirmation_problems(config, [own, *grid], key)
    undated = sorted(
        set(config["readings"]["equivalence_margin"]) - set(config["readings"]["margin_declared"])
    )
    if undated:
        yield (
            f"{key('readings.margin_declared')}: no entry for {undated}. Allowed: one entry per "
            "margin of readings.equivalence_margin, naming the commit that first wrote it and "
            "whether results of its measure had been read then. Fix: add them."
        )
    unknown = sorted(
        set(config["readings"]["margin_declared"]) - set(config["readings"]["equivalence_margin"])
    )
    if unknown:
        yield (
            f"{key('readings.margin_declared')}: an entry for {unknown}, which has no margin in "
            "readings.equivalence_margin (a declaration of nothing). Allowed: the measures of "
            f"readings.equivalence_margin ({sorted(config['readings']['equivalence_margin'])}). "
            "Fix: remove the entry or correct its name."
        )
    if 0 not in robot["tolerance"]["noise"]:
        yield (
            f"{key('robot.tolerance.noise')}: {robot['tolerance']['noise']} does not list 0, the "
            "unshifted plan that the book compares the offsets with. Fix: add 0 to the list."
        )
    if robot["animation"]["object"] not in objects:
        yield (
            f"{key('robot.animation.object')}: {robot['animation']['object']!r} is not tested in "
            f"this run (config objects: {objects}). Allowed: one of {objects}. Fix: pick one."
        )
    embodied = config["figures"]["embodied"]
    if embodied["object"] not in objects:
        yield (
            f"{key('figures.embodied.object')}: {embodied['object']!r} is not tested in this "
            f"run (config objects: {objects}). Allowed: one of {objects}. Fix: pick one of them."
        )
    if not 0 <= embodied["sequence"] < sequences:
        yield (
            f"{key('figures.embodied.sequence')}: {embodied['sequence']} does not exist; there "
            f"are demos.sequences = {sequences} per object and grip. Allowed: "
            f"0..{sequences - 1}. Fix: pick a sequence in that range."
        )


def _names_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """A run with names whose training shares do not split a phase into whole trials."""
    names, network = config["names"], config["network"]
    if not names["use"]:
        return
    phase1 = network["phase1_iterations"]
    lengths = {"phase1": phase1, "phase2": network["iterations"] - phase1}
    for phase, weights in names["training"].items():
        total = sum(weights.values())
        if total == 0:
            yield (
                f"{key(f'names.training.{phase}')}: every weight is 0, so no trial of the phase "
                "shows anything. Fix: give image, name or both a weight of 1 or more."
            )
        elif lengths[phase] % total:
            yield (
                f"{key(f'names.training.{phase}')}: the weights {dict(weights)} sum to {total}, "
                f"which does not divide the phase's {lengths[phase]} iterations into whole "
                "shares. Fix: weights whose sum divides the phase's iterations (e.g. 1 each)."
            )


def _variant_words(variant: NetworkVariant) -> str:
    """A variant's settings, for a refusal: "categorisation_cue first_step, target ..."."""
    return ", ".join(f"{k} {v}" for k, v in variant.row().items())


def _confirmation_problems(
    config: Mapping[str, Any], explored: list[NetworkVariant], key
) -> Iterator[str]:
    """Config robot.confirmation: variants the exploration tries (``explored``: the config's
    own networks and the grid, every one tested at full scale; the default build need not test
    them on networks 0.. again), on network indices the exploration never used, whose names fit
    the two-digit `net{NN}` folders."""
    robot, network = config["robot"], config["network"]
    confirmation, keys = robot["confirmation"], NetworkVariant.keys()
    for i, variant in enumerate(confirmation["variants"]):
        if NetworkVariant.of(variant, network) not in explored:
            yield (
                f"{key(f'robot.confirmation.variants[{i}]')}: {variant} is not a variant of "
                f"the grid {' x '.join(f'robot.{k}' for k in keys)} (a key it leaves out is the "
                "network's), so no exploration tried it and there is nothing to confirm. "
                "Allowed: the config's own networks or a combination of "
                f"{', '.join(str(robot[k]) for k in keys)}. Fix: add its values to the grid or "
                "confirm a variant of it."
            )
    first, explored = confirmation["first_network"], network["networks"]
    if first < explored:
        yield (
            f"{key('robot.confirmation.first_network')}: {first} reuses network indices that "
            f"the exploration chose the variants on (0..{explored - 1}, network.networks = "
            f"{explored}); a confirmation needs fresh ones. Allowed: at least {explored}. Fix: "
            f"set first_network to {explored} or more."
        )
    most = max(confirmation["networks"], confirmation["robustness_networks"])
    if first + most > 100:
        yield (
            f"{key('robot.confirmation.first_network')}: {first} + {most} networks runs past "
            "index 99 (the networks' folders are net00..net99). Allowed: first_network + "
            f"networks at most 100. Fix: lower first_network to at most {100 - most}."
        )
    if confirmation["robustness_networks"] < confirmation["networks"]:
        yield (
            f"{key('robot.confirmation.robustness_networks')}: "
            f"{confirmation['robustness_networks']} is fewer than robot.confirmation.networks "
            f"({confirmation['networks']}); robustness confirms on more networks, not fewer. "
            f"Allowed: at least {confirmation['networks']}. Fix: raise it."
        )


def check_config(config: Mapping[str, Any], prefix: str = "") -> None:
    """Refuse a config (already valid against the schema) that breaks a rule between its keys.

    `prefix` is put before every key named (`runs.half_lr.` for a run's config).
    """
    problems = list(_problems(config, prefix))
    if not prefix:
        problems += _backed_problems(config, lambda name: f"config key {name}")
        problems += _words_problems(config, lambda name: f"config key {name}")
    if len(problems) == 1:
        raise ConfigError(problems[0])
    if problems:
        raise ConfigError(f"{len(problems)} problems:\n  - " + "\n  - ".join(problems))


def _words_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """The words study's replications must be fresh, seeds no other study of the build runs
    (a test over them would otherwise rest on models other choices were made on), and its
    runs, which turn names on, must be able to train with the config's names."""
    words = config["words"]
    others = {
        "seed": [config["seed"]],
        "confirmation.seeds": config["confirmation"]["seeds"],
        "confirmation.robustness_seeds": config["confirmation"]["robustness_seeds"],
        "size_dose.crossed.seeds": config["size_dose"]["crossed"]["seeds"],
        "sweep.seeds": config["sweep"]["seeds"],
    }
    for name in ("seeds", "robustness_seeds"):
        for other, seeds in others.items():
            shared = sorted(set(words[name]) & set(seeds))
            if shared:
                yield (
                    f"{key(f'words.{name}')}: {shared} also seeds {other}; the words study's "
                    "replications must be fresh. Fix: choose seeds no other study runs."
                )
    both = sorted(set(words["seeds"]) & set(words["robustness_seeds"]))
    if both:
        yield (
            f"{key('words.robustness_seeds')}: {both} is in words.seeds too. Fix: drop it from "
            "one of them."
        )
    if not config["names"]["use"]:  # the study turns names on: its shares must split phases
        yield from _names_problems(merged(config, {"names": {"use": True}}), key)


def _backed_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """Every declared test needs the runs that make it (issue 57), else it would pass every
    check and plan, and then rest on nothing: the confirmation's cue timings, Goal response and
    measures must be readings the build runs; the signatures and the learning curves read the
    config's own cue timing among the confirmation's; a declared minimum must be reachable by
    the replications or networks declared; an equivalence margin needs both Goal responses.
    The config's own keys only: a run of `runs:` declares no test."""
    readings, declared = config["readings"], config["confirmation"]
    cues, goals = readings["categorisation_cue"], readings["goal_response"]
    missing = [cue for cue in declared["cues"] if cue not in cues]
    if missing:
        yield (
            f"{key('confirmation.cues')}: {missing} has no replication to test: the "
            f"confirmation's replications are the readings' runs, and readings."
            f"categorisation_cue is {cues}. Fix: add {missing} to readings.categorisation_cue, "
            "or take it out of confirmation.cues."
        )
    goal = config["soms"]["goal_response"]
    if goal not in goals:
        yield (
            f"{key('readings.goal_response')}: {goals} lacks the config's Goal response "
            f"(soms.goal_response: {goal}), at which the confirmation and the signatures test "
            f"the readings' runs. Fix: add {goal} to readings.goal_response."
        )
    unmeasured = [m for m in declared["measures"] if m not in readings["measures"]]
    if unmeasured:
        yield (
            f"{key('confirmation.measures')}: {unmeasured} is not scored on the readings' runs "
            f"(readings.measures: {readings['measures']}). Fix: add it to readings.measures, or "
            "take it out of confirmation.measures."
        )
    own = config["network"]["categorisation_cue"]
    if own not in declared["cues"]:
        yield (
            f"{key('confirmation.cues')}: {declared['cues']} lacks the config's own cue timing "
            f"(network.categorisation_cue: {own}), whose replications the signatures and the "
            f"learning curves test. Fix: add {own} to confirmation.cues."
        )
    yield from _minimum_problems(config, key)
    if len(goals) < 2 and readings["equivalence_margin"]:
        yield (
            f"{key('readings.equivalence_margin')}: its margins test whether the Goal response "
            f"makes a difference, but readings.goal_response runs one ({goals}). Fix: list both "
            "Goal responses, fixed and grows."
        )
    robot = config["robot"]["confirmation"]
    fewest = min(robot["networks"], robot["robustness_networks"])
    if robot["variants"] and robot["contact_time"]["min_networks"] > fewest:
        yield (
            f"{key('robot.confirmation.contact_time.min_networks')}: "
            f"{robot['contact_time']['min_networks']} is more than the confirmation's "
            f"{fewest} networks, so the declared contact-time test could never be assessed. "
            f"Allowed: at most {fewest}. Fix: lower it or confirm on more networks."
        )


def _minimum_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """Every study that tests over replications has at least its minimum of them (the one rule,
    icub_affordance.analysis.replicated): else its every test would be not assessable. The
    confirmation, the readings and the signatures run at confirmation.seeds and the size study
    at size_dose.crossed.replications, all under confirmation.min_replications; the words study
    at words.seeds under words.min_replications. And the confirmation's pilot, a tracked file,
    must exist (its power is computed from it)."""
    declared, crossed, words = (
        config["confirmation"],
        config["size_dose"]["crossed"],
        config["words"],
    )
    least, seeds = declared["min_replications"], declared["seeds"]
    if least > len(seeds):
        yield (
            f"{key('confirmation.min_replications')}: {least} is more than the {len(seeds)} "
            "replications of confirmation.seeds (the confirmation's, the readings' and the "
            "signatures'), so every test over them would be not assessable. Allowed: at most "
            f"{len(seeds)}. Fix: lower it or add seeds."
        )
    for name in ("replications", "robustness_replications"):
        if crossed[name] < least:
            yield (
                f"{key(f'size_dose.crossed.{name}')}: {crossed[name]} is fewer than "
                f"confirmation.min_replications ({least}), the minimum of every test over "
                "replications, so every test of the size study would be not assessable. Allowed: "
                f"at least {least}. Fix: raise it (and add size_dose.crossed.seeds) or lower "
                "confirmation.min_replications."
            )
    if words["min_replications"] > len(words["seeds"]):
        yield (
            f"{key('words.min_replications')}: {words['min_replications']} is more than the "
            f"{len(words['seeds'])} replications of words.seeds, so every declared test of the "
            f"words study would be not assessable. Allowed: at most {len(words['seeds'])}. Fix: "
            "lower it or add seeds."
        )
    pilot = declared["pilot"]
    if not Path(pilot).is_file():
        yield (
            f"{key('confirmation.pilot')}: {pilot!r} is not a file (paths are read from the "
            f"workflow's directory, {Path.cwd()}), and the confirmation's power is computed from "
            "it. Allowed: the tracked pilot table. Fix: point it back at "
            "config/confirmation_pilot.csv (restore it with `git checkout -- config/`), or make "
            "it with tools/confirmation_pilot.py."
        )


def _claims_problems(config: Mapping[str, Any], key) -> Iterator[str]:
    """The claims' replications must be fresh: no seed of theirs may be the config's own or a
    sweep point's (the readings and the size study run at these seeds, sharing their
    demonstrations), and the seeds of the default build and of the full scale must differ."""
    declared = config["confirmation"]
    ours = [*declared["seeds"], *declared["robustness_seeds"]]
    if len(set(ours)) != len(ours):
        yield (
            f"{key('confirmation.robustness_seeds')}: {declared['robustness_seeds']} repeats a "
            f"seed of confirmation.seeds ({declared['seeds']}). Fix: list seeds not in both."
        )
    others = {
        "seed": [config["seed"]],
        "sweep.seeds": config["sweep"]["seeds"],
    }
    for name, seeds in others.items():
        shared = sorted(set(ours) & set(seeds))
        if shared:
            yield (
                f"{key('confirmation.seeds')}: {shared} also seed {name}; a confirmation runs on "
                f"replications no other part of the build uses. Fix: choose other seeds."
            )
    yield from _crossed_problems(config, ours, key)


def _crossed_problems(config: Mapping[str, Any], confirmation: list[int], key) -> Iterator[str]:
    """The size study's crossed design (config size_dose.crossed) is declared on fresh seeds:
    none of the confirmation's, the config's own or a sweep point's; and enough of them for its
    replications."""
    crossed = config["size_dose"]["crossed"]
    swapping = "swapped" in crossed["grip_arrangements"] or config["grip_distance"] == "swapped"
    if swapping:
        from icub_affordance.learning.grip_distance import (
            shape_partners,  # scipy: only when a swap is asked for
        )

        try:
            shape_partners(list(config["objects"]))
        except (ValueError, KeyError) as error:
            yield (
                f"{key('size_dose.crossed.grip_arrangements')}: the swapped grips move each "
                f"object's grips to its same-shape partner's distance, but {error}. Allowed: "
                "objects that pair up by shape (a large and a small ball, a large and a small "
                "cube). Fix: restore the four objects, or run the study with grip_distance "
                "natural only."
            )
    needed = max(crossed["replications"], crossed["robustness_replications"])
    if len(crossed["seeds"]) < needed:
        yield (
            f"{key('size_dose.crossed.seeds')}: {len(crossed['seeds'])} seeds for {needed} "
            f"replications (each replication takes the next seed of the list). Allowed: at least "
            f"{needed} seeds. Fix: add seeds or lower size_dose.crossed.replications / "
            "robustness_replications."
        )
    others = {
        "confirmation.seeds / robustness_seeds": confirmation,
        "seed": [config["seed"]],
        "sweep.seeds": config["sweep"]["seeds"],
    }
    for name, seeds in others.items():
        shared = sorted(set(crossed["seeds"]) & set(seeds))
        if shared:
            yield (
                f"{key('size_dose.crossed.seeds')}: {shared} also seed {name}; the crossed "
                "design's declared tests run on replications no other part of the build uses. "
                "Fix: choose other seeds."
            )


# ---- the scene ----------------------------------------------------------------------------------


def check_scene(config: Mapping[str, Any]) -> None:
    """Load the scene once, as every rule that uses it will (with the config's object sizes), and
    check that it has what the rules use: Figure 1's 16 actuators, the touch sensors, the four
    objects, the cameras, and an offscreen buffer as large as the largest image rendered."""
    scene = config["scene"]
    fix = (
        f"Fix: point `scene` in {WHERE} back at assets/icub_scene.xml (restore it with "
        "`git checkout -- assets/`), or repair the file."
    )
    try:
        from icub_affordance.body.robot import Robot

        robot = Robot(scene, dict(config["object_sizes_m"]))
    except Exception as err:  # whatever MuJoCo or the model indexing raise: the scene is unusable
        raise ConfigError(
            f"config key scene: {scene!r} cannot be used: {str(err).rstrip('.')}. Allowed: an "
            "MJCF scene that MuJoCo loads, with the iCub arm of Figure 1, its touch sensors and "
            f"the four objects. {fix}"
        ) from err
    try:
        model = robot.model
        cameras = {model.camera(i).name for i in range(model.ncam)}
        missing = [c for c in CAMERAS if c not in cameras]
        if missing:
            raise ConfigError(
                f"config key scene: {scene!r} lacks the camera(s) {missing} that the rules "
                f"render from. Allowed: a scene with the cameras {list(CAMERAS)}. {fix}"
            )
        need_w = max(config["vision"]["width"], config["body_figure"]["width"], FILMSTRIP_SIZE[0])
        need_h = max(config["vision"]["height"], config["body_figure"]["height"], FILMSTRIP_SIZE[1])
        have_w, have_h = int(model.vis.global_.offwidth), int(model.vis.global_.offheight)
        if need_w > have_w or need_h > have_h:
            raise ConfigError(
                f"config keys vision.width/height, body_figure.width/height: images up to "
                f"{need_w}x{need_h} pixels are rendered, but the scene {scene!r} allows at most "
                f"{have_w}x{have_h} (its <visual><global offwidth offheight>). Fix: render "
                "smaller images, or raise offwidth/offheight in the scene."
            )
    finally:
        robot.close()


def check_runs(
    config: Mapping[str, Any], schema: Mapping[str, Any], taken: Iterable[str] = ()
) -> None:
    """Refuse a run of config `runs` whose name is `taken`, whose entry changes what a run may
    not, or whose overrides, laid over the config, break the schema or a rule between keys
    (src/icub_workflow/config_checks.py), naming the run and the key."""
    taken = set(taken)
    for name, overrides in config["runs"].items():
        prefix = f"runs.{name}."
        if name in taken:
            raise ConfigError(
                f"config key runs.{name}: the name {name!r} is taken (the main run, the cue "
                "ablation, a sweep point or a reading). Allowed: any other name. Fix: rename the "
                "run."
            )
        # the entry itself: only the sections a run may change, and at least one
        entry = schema["properties"]["runs"]["additionalProperties"]
        check_schema(overrides, entry | {"$defs": schema.get("$defs", {})}, prefix)
        # the run's whole config (its own `runs` aside: the entries are checked one by one)
        run = merged(config, overrides) | {"runs": {}}
        check_schema(run, schema, prefix)
        check_config(run, prefix)
