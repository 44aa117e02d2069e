"""Every config key is described once, in the schema (workflow/schemas/config.schema.yaml):
config/config.yaml carries values and short signposts only, so a description cannot drift."""

from __future__ import annotations

from typing import Any

import yaml
from conftest import CONFIG, REPO

SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"


def undescribed(config: Any, schema: dict[str, Any]) -> list[str]:
    """The keys of `config` (dotted paths, list entries as [i]) whose schema has no description,
    walking config and schema together: a ``$ref`` to ``$defs`` lends its target's keys (the
    key's own win), a key absent from ``properties`` takes ``additionalProperties`` when that is a
    schema, and the entries of a list take ``items``."""
    defs = schema.get("$defs", {})

    def resolve(node: dict[str, Any]) -> dict[str, Any]:
        while "$ref" in node:
            name = node["$ref"].removeprefix("#/$defs/")
            node = {**defs[name], **{k: v for k, v in node.items() if k != "$ref"}}
        return node

    missing: list[str] = []

    def walk(value: Any, node: dict[str, Any], path: str) -> None:
        node = resolve(node)
        if isinstance(value, dict):
            for key, sub in value.items():
                child = node.get("properties", {}).get(key)
                if child is None and isinstance(node.get("additionalProperties"), dict):
                    child = node["additionalProperties"]
                where = f"{path}.{key}" if path else str(key)
                if child is None:
                    missing.append(f"{where} (no schema)")
                    continue
                if not resolve(child).get("description", "").strip():
                    missing.append(where)
                walk(sub, child, where)
        elif isinstance(value, list) and isinstance(node.get("items"), dict):
            for i, entry in enumerate(value):
                walk(entry, node["items"], f"{path}[{i}]")

    walk(config, schema, "")
    return missing


def test_every_config_key_is_described_in_the_schema():
    config = yaml.safe_load(CONFIG.read_text())
    schema = yaml.safe_load(SCHEMA.read_text())
    assert not undescribed(config, schema), undescribed(config, schema)


def test_a_key_without_a_description_is_found():
    config = yaml.safe_load(CONFIG.read_text())
    schema = yaml.safe_load(SCHEMA.read_text())
    del schema["properties"]["vision"]["properties"]["grid"]["description"]
    del schema["$defs"]["cue"]["description"]
    schema["properties"]["network"]["properties"]["categorisation_cue"].pop("description")
    entry = schema["properties"]["signatures"]["properties"]["list"]["items"]["properties"]
    del entry["finding"]["description"]
    missing = undescribed(config, schema)
    assert "vision.grid" in missing
    assert "network.categorisation_cue" in missing
    assert "signatures.list[0].finding" in missing
    assert "confirmation.seeds" not in missing


def test_no_description_is_cut_short():
    """A comma in an unquoted description of a flow mapping ({..., description: a, b}) cuts it
    there and makes the rest a key with no value, which the schema's checks ignore."""
    schema = yaml.safe_load(SCHEMA.read_text())
    empty = []

    def visit(node: Any, path: str) -> None:
        if isinstance(node, dict):
            for key, value in node.items():
                if value is None:
                    empty.append(f"{path}: {key!r}")
                visit(value, f"{path}.{key}")
        elif isinstance(node, list):
            for i, value in enumerate(node):
                visit(value, f"{path}[{i}]")

    visit(schema, "schema")
    assert not empty, empty
