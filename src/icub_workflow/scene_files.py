"""The files a MuJoCo scene is made of: what a rule that loads the scene reads.

Kept out of the package (the rules ask it when the workflow is parsed, and MuJoCo need not load
then), and tested with the scene in tests/test_mjcf.py.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from pathlib import Path


def scene_files(scene_path: str | os.PathLike) -> list[Path]:
    """The scene file and every file it includes (``<include file=...>``), recursively.

    In the order MuJoCo reads them, the scene first. An include is looked up as MuJoCo does:
    relative to the scene's directory, then to the including file's. The paths stay relative if
    ``scene_path`` is: they are what a Snakemake rule that loads the scene lists as inputs.
    """
    scene = Path(scene_path)
    files: list[Path] = []

    def visit(path: Path, included_by: Path | None) -> None:
        if path in files:
            raise ValueError(f"{included_by} includes {path} a second time (MuJoCo refuses)")
        if not path.is_file():
            where = f", included by {included_by}" if included_by else ""
            raise FileNotFoundError(f"MuJoCo scene file not found: {path}{where}")
        files.append(path)
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as err:
            raise ValueError(f"{path} is not well-formed XML: {err}") from err
        for element in root.iter("include"):
            name = element.get("file")
            if not name:
                raise ValueError(f"{path}: an <include> without a file attribute")
            candidates = [Path(os.path.normpath(d / name)) for d in (scene.parent, path.parent)]
            visit(next((c for c in candidates if c.is_file()), candidates[-1]), path)

    visit(Path(os.path.normpath(scene)), None)
    return files
