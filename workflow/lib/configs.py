"""Configs laid over configs: the test config over the default, a run's overrides over the main
run's config. Key by key, as Snakemake lays `--configfile` files over the Snakefile's config."""

from __future__ import annotations

import copy
from collections.abc import Iterable, Mapping
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


def check_runs(
    config: Mapping[str, Any], schema: Mapping[str, Any], taken: Iterable[str] = ()
) -> None:
    """Refuse a run of config `runs` whose overrides, laid over the config, break the schema
    (an unknown section or key, a bad value), or whose name is `taken`, naming the run and key."""
    import jsonschema

    validator = jsonschema.Draft202012Validator(schema)
    taken = set(taken)
    for name, overrides in config["runs"].items():
        if name in taken:
            raise ValueError(
                f"config runs: the name {name!r} is taken (the main run, the cue ablation or a "
                "sweep point). Give the run another name."
            )
        error = jsonschema.exceptions.best_match(validator.iter_errors(merged(config, overrides)))
        if error is not None:
            key = ".".join(str(part) for part in error.absolute_path)
            raise ValueError(
                f"config runs.{name}: {key or 'the run'}: {error.message}. Fix or remove this "
                "key in the run's entry under `runs:` (workflow/schemas/config.schema.yaml says "
                "what is allowed)."
            )
