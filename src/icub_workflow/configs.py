"""Configs laid over configs: the test config over the default, a run's overrides over the main
run's config. Key by key, as Snakemake lays `--configfile` files over the Snakefile's config."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any


def merged(base: Mapping[str, Any], overrides: Mapping[str, Any]) -> dict[str, Any]:
    """`base` with `overrides` laid over it, dictionaries merged key by key (neither is changed)."""
    out = _copied(dict(base))
    for key, value in overrides.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merged(out[key], value)
        else:
            out[key] = _copied(value)
    return out


def _copied(value: Any) -> Any:
    """A deep copy of a config's tree of mappings and lists (its leaves are numbers, strings and
    booleans, which need none): what ``copy.deepcopy`` gives, several times faster, since the run
    plan lays hundreds of runs over the config at every Snakemake start."""
    kind = type(value)
    if kind is dict or (kind not in _LEAVES and isinstance(value, Mapping)):
        return {key: _copied(item) for key, item in value.items()}
    if kind is list or kind is tuple:
        return kind(_copied(item) for item in value)
    return value


#: The leaves a config holds: no test against the Mapping ABC for them (a slow isinstance).
_LEAVES = frozenset({str, int, float, bool, type(None)})
