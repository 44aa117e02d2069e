"""The rules as a maintainer reads them: each documented in docs/pipeline.md, each stating only
the resources it needs beyond the profiles' defaults."""

from __future__ import annotations

import re

import pytest
import yaml
from conftest import REPO, run_snakemake

RULE_FILES = [REPO / "Snakefile", *sorted((REPO / "workflow" / "rules").glob("*.smk"))]
PROFILES = sorted((REPO / "workflow" / "profiles").glob("*/config.yaml"))


def _rules(*config: str) -> set[str]:
    """The rules Snakemake defines for the default config, with `config` laid over it."""
    args = ["--config", *config] if config else []
    result = run_snakemake(REPO, "--list-rules", *args, config=REPO / "config" / "config.yaml")
    assert result.returncode == 0, result.stderr[-3000:]
    # a rule's line starts at the margin; its docstring's wrapped lines are indented
    return {line.split()[0] for line in result.stdout.splitlines() if line[:1].strip()}


@pytest.mark.dryrun  # runs Snakemake (twice: the default config and the full scale)
def test_docs_pipeline_names_every_rule_the_snakefile_defines():
    # a name written with a wildcard (`name_{w}`) stands for every name it matches
    names = re.findall(r"`(\w+(?:\{\w+\}\w*)?)`", (REPO / "docs" / "pipeline.md").read_text())
    documented = [re.compile(re.sub(r"\\\{\w+\\\}", r"\\w+", re.escape(n))) for n in names]
    rules = _rules() | _rules("robustness=True")
    missing = sorted(r for r in rules if not any(p.fullmatch(r) for p in documented))
    assert not missing, f"docs/pipeline.md does not name the rule(s) {missing}"


def test_every_profile_sets_the_same_default_resources():
    defaults = [yaml.safe_load(p.read_text())["default-resources"] for p in PROFILES]
    common = [{k: d[k] for k in ("mem_mb", "runtime")} for d in defaults]
    assert len(PROFILES) >= 3 and all(c == common[0] for c in common), common


def test_a_rule_states_a_resource_only_where_it_needs_more_than_the_default():
    default = yaml.safe_load(PROFILES[0].read_text())["default-resources"]
    for path in RULE_FILES:
        text = path.read_text()
        assert not re.search(r"^\s+threads: 1$", text, re.M), (
            f"{path.name}: threads: 1 is the default"
        )
        for key in ("mem_mb", "runtime"):
            for value in re.findall(rf"^\s+{key}=(\d+),?$", text, re.M):
                assert int(value) > default[key], (
                    f"{path.name}: {key}={value} is not above the default"
                )
