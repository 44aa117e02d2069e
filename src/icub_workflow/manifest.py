"""The results manifest: the SHA-256 of every file of a build that holds a result.

"Same configuration, same bytes" is a claim about files, so it is checked on files. The manifest is
written in the format of GNU ``sha256sum`` (``<digest>  <path>``, paths relative to the project's
root), so a reader can check a build without this project's code: ``sha256sum -c results.sha256``.
A tracked copy, ``results.sha256`` at the project's root, holds the default configuration's build;
``snakemake -c2 verify`` compares the files in ``data/`` with it and names each that differs.

A result is a table, an array or a summary: ``.csv``, ``.json``, ``.npz`` and ``.md`` files. Not
logs or benchmarks (times), not figures and films (pixels from a renderer and a font library, made
from tables that are in the manifest), not the HTML (it carries its build date).
"""

from __future__ import annotations

import hashlib
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

# The arithmetic the manifest's bytes assume, set by the Snakefile for every job. numpy picks SIMD
# kernels at import by what the CPU offers: with AVX-512 its exp, log1p and tanh differ in the
# last bit from the AVX2 ones; OpenBLAS likewise picks its matrix kernels (another order of sums).
# Both are held at the AVX2 (Haswell) level that x86-64 machines of the last decade share, and
# every library runs one thread. The trainer's numba code needs nothing: it is compiled without
# fast-math (no reordered sums, no fused multiply-adds) and computes its own exponential.
ONE_THREAD = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
AVX2_LEVEL = {
    "NPY_DISABLE_CPU_FEATURES": "X86_V4 AVX512_ICL AVX512_SPR",
    "OPENBLAS_CORETYPE": "Haswell",
}


def cpu_flags(cpuinfo: str | os.PathLike[str] = "/proc/cpuinfo") -> set[str]:
    """The CPU's feature flags as Linux lists them (none where it does not: another system)."""
    try:
        text = Path(cpuinfo).read_text()
    except OSError:
        return set()
    line = next((line for line in text.splitlines() if line.startswith("flags")), "")
    return set(line.partition(":")[2].split())


def arithmetic_environment(flags: set[str]) -> dict[str, str]:
    """The environment for the jobs of a machine with these CPU flags: one thread each and, where
    the CPU has AVX2 and FMA, the AVX2 level. (OpenBLAS runs the kernels it is told to without
    asking the CPU: told Haswell on a CPU without AVX2, it would stop at an illegal
    instruction. Such a machine keeps its own kernels, and may differ in the last bits.)"""
    return ONE_THREAD | (AVX2_LEVEL if {"avx2", "fma"} <= flags else {})


def arithmetic_problems(environment: Mapping[str, str]) -> list[str]:
    """What of `environment` (:func:`arithmetic_environment`'s) this process does not compute
    with: each variable it lacks, each numpy SIMD level it was to leave and still uses, and
    OpenBLAS's kernels if they are not the ones named. Imports numpy, so only a process whose
    environment was set before its first numpy import passes; none means it computes as the
    build's jobs do."""
    import ctypes

    import numpy as np
    from numpy._core import _multiarray_umath as umath

    problems = [
        f"{key}={os.environ.get(key)!r}, not {value!r}"
        for key, value in environment.items()
        if os.environ.get(key) != value
    ]
    dropped = environment.get("NPY_DISABLE_CPU_FEATURES", "").split()
    problems += [
        f"numpy uses {level}, which NPY_DISABLE_CPU_FEATURES leaves out: numpy was imported "
        "before the variable was set"
        for level in dropped
        if umath.__cpu_features__.get(level)
    ]
    if "OPENBLAS_CORETYPE" in environment:
        wanted = environment["OPENBLAS_CORETYPE"]
        bundled = Path(np.__file__).parent.with_name("numpy.libs")
        libraries = sorted(bundled.glob("libscipy_openblas*"))
        if not libraries:
            problems.append("numpy's OpenBLAS (numpy.libs/libscipy_openblas*) was not found")
        else:
            corename = ctypes.CDLL(str(libraries[0])).scipy_openblas_get_corename64_
            corename.restype = ctypes.c_char_p
            used = corename().decode()
            if used.lower() != wanted.lower():
                problems.append(f"OpenBLAS runs {used} kernels, not {wanted}")
    return problems


RESULT_SUFFIXES = (".csv", ".json", ".npz", ".md")
NOT_RESULTS = ("data/logs/", "data/benchmarks/")
_LINE = re.compile(r"^([0-9a-f]{64})  (\S.*)$")


def is_result(path: str) -> bool:
    """Whether an output path of the pipeline holds a result (see the module's docstring)."""
    path = Path(path).as_posix()
    return path.endswith(RESULT_SUFFIXES) and not path.startswith(NOT_RESULTS)


def result_files(outputs: Iterable[str]) -> list[str]:
    """The results among a build's outputs: sorted, each once (a folder stands for its files)."""
    found: set[str] = set()
    for output in outputs:
        path = Path(output)
        if path.is_dir():
            found.update(p.as_posix() for p in path.rglob("*") if p.is_file())
        else:
            found.add(path.as_posix())
    return sorted(p for p in found if is_result(p))


def sha256(path: str | os.PathLike[str]) -> str:
    with open(path, "rb") as handle:
        return hashlib.file_digest(handle, "sha256").hexdigest()


def digests(paths: Iterable[str], root: str | os.PathLike[str] = ".") -> dict[str, str]:
    """Each file's SHA-256, by its path relative to `root`."""
    return {path: sha256(Path(root) / path) for path in paths}


def format_manifest(entries: Mapping[str, str]) -> str:
    """The manifest's text: one ``<digest>  <path>`` line per file, by path."""
    return "".join(f"{entries[path]}  {path}\n" for path in sorted(entries))


def parse_manifest(text: str, source: str = "the manifest") -> dict[str, str]:
    """The entries of a manifest's text; a line that is not ``<sha256>  <path>`` is refused."""
    entries: dict[str, str] = {}
    for number, line in enumerate(text.splitlines(), start=1):
        match = _LINE.match(line)
        if match is None:
            raise ValueError(
                f"{source}, line {number}: {line[:80]!r} is not '<sha256 in hex>  <path>'; "
                "restore the file from git (git checkout -- results.sha256)"
            )
        digest, path = match.groups()
        if path in entries:
            raise ValueError(f"{source}, line {number}: {path} is listed twice")
        entries[path] = digest
    return entries


def read_manifest(path: str | os.PathLike[str]) -> dict[str, str]:
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(
            f"{path}: no results manifest; it is tracked in git (git checkout -- {path.name})"
        )
    return parse_manifest(path.read_text(), str(path))


@dataclass(frozen=True)
class Comparison:
    """How a build's result files stand against a manifest.

    `changed`: listed, made, and not the bytes listed. `missing`: listed and not in ``data/`` (not
    built yet, or deleted). `unlisted`: a result this configuration makes that the manifest lacks
    (a new output); `dropped`: listed, and no longer a result of this configuration.
    """

    checked: int
    changed: list[str]
    missing: list[str]
    unlisted: list[str]
    dropped: list[str]

    @property
    def same(self) -> bool:
        return not (self.changed or self.missing or self.unlisted or self.dropped)

    def report(self, manifest: str) -> str:
        if self.same:
            return f"all {self.checked} result files are as {manifest} lists them"
        kinds = {
            "changed": self.changed,
            "missing": self.missing,
            "not in the manifest": self.unlisted,
            "no longer made": self.dropped,
        }
        count = sum(map(len, kinds.values()))
        lines = [f"{count} of {self.checked} result files differ from {manifest}:"]
        lines += [f"  {kind}: {path}" for kind, paths in kinds.items() for path in paths]
        if self.missing:
            lines.append("A missing file is made by the build: run `snakemake -c2` first.")
        if self.changed or self.unlisted or self.dropped:
            lines.append(
                "If a change to the code or the config moved these results on purpose, "
                f"record them: cp data/results.sha256 {manifest} (after `snakemake -c2`), and "
                "commit it with the change."
            )
        return "\n".join(lines)


def compare(
    expected: Mapping[str, str], results: Iterable[str], root: str | os.PathLike[str] = "."
) -> Comparison:
    """Hash every file of `results` (this configuration's result paths) under `root`, and compare
    with `expected`."""
    results = set(results)
    changed, missing = [], []
    for path in sorted(results & set(expected)):
        file = Path(root) / path
        if not file.is_file():
            missing.append(path)
        elif sha256(file) != expected[path]:
            changed.append(path)
    return Comparison(
        checked=len(results | set(expected)),
        changed=changed,
        missing=missing,
        unlisted=sorted(results - set(expected)),
        dropped=sorted(set(expected) - results),
    )
