"""The declared tests whose declaring commit the project records, and the result files each reads.

A declaration means something only if it came before the data it tests: so, from issue 70 on, a
declaration is committed before its input files exist, and tests/test_declarations.py checks it
on the tracked manifest (``results.sha256``) as of the declaring commit, which must list none of
the inputs. A declaration made when they already existed says so here (``exception``, with the
reason), so the check names it instead of passing it silently, and every later one is checked.

Not listed: the readings' equivalence margins (config ``readings.margin_declared``), which
record their commit and whether their measure's results had been read by then
(``results_before``) in the config; their measures share result files with the readings'
other measures, so a file's presence says nothing about when a margin was set.
"""

from __future__ import annotations

from dataclasses import dataclass
from fnmatch import fnmatch


@dataclass(frozen=True)
class Declaration:
    """A declared test: its config key, the commit that declared it, the result files it reads
    (``fnmatch`` patterns over the manifest's paths) and, where those existed at that commit,
    why (empty: they must not have)."""

    test: str
    commit: str
    inputs: tuple[str, ...]
    exception: str = ""

    def inputs_in(self, manifest: str) -> list[str]:
        """The paths of a manifest's text (``<sha256>  <path>`` lines) that are inputs."""
        paths = [line.split(maxsplit=1)[1] for line in manifest.splitlines() if line.strip()]
        return [p for p in paths if any(fnmatch(p, pattern) for pattern in self.inputs)]


DECLARED = (
    Declaration(
        test="robot.confirmation.contact_time",
        commit="bec68e0",
        # the fresh networks' robot trials, joined (rule robot_confirmation) and per run
        inputs=("data/embodied/confirmation_trials.csv", "data/runs/*_confirm/embodied/*"),
        exception=(
            "declared three minutes before its result (94c1bbe) while the fresh networks' "
            "trials it tests already existed; issue 70: from now on a declaration is "
            "committed before the data it tests exist"
        ),
    ),
    Declaration(
        test="distractor",
        commit="13c505d",
        # the distractor's trials and tests (rule distractor), made on the confirmation's
        # networks only after the declaration (issue 73); first recorded in b88831d
        inputs=("data/distractor/*",),
    ),
)
