"""Try bad inputs on a scratch copy of a finished run, as a new user would: each must be refused
before any job (a dry run already fails), naming the key or file, and no file of the run may
change. Prints a Markdown table: case, exit code, the refusal, data unchanged.

    python tools/try_bad_inputs.py            # this checkout's code, on a copy of its data/
    python tools/try_bad_inputs.py --code DIR --data DIR/data   # another checkout's code

The scratch copy links the code (Snakefile, workflow/, src/, ...) and copies data/ and Snakemake's
records (.snakemake/metadata), so a refusal that came too late would show as changed data.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[1]

GOOD_POSTURE = [-50, 30, 0, 70, 0, 0, 0, 0, 10, 0, 0, 0, 0, 0, 0, 0]


def posture(k: int, value: float) -> dict:
    angles = list(GOOD_POSTURE)
    angles[k] = value
    return {"initial_posture_deg": angles}


# (case, the change, should it be accepted?). A change is a config file's keys (laid over the
# default config with --configfile, as a user's own config is) or, as a list, --config entries.
CASES: list[tuple[str, dict | list[str], bool]] = [
    ("phase 1 longer than training", {"network": {"phase1_iterations": 13000}}, False),
    ("phase 2 of odd length", {"network": {"phase1_iterations": 5999}}, False),
    ("phase 1 beyond any bound", {"network": {"phase1_iterations": 99999999}}, False),
    ("window larger than the image", {"vision": {"window": 300}}, False),
    ("window not a multiple of the grid", {"vision": {"window": 105}}, False),
    ("posture outside Figure 1 (elbow 150)", posture(3, 150), False),
    ("posture item beyond any joint (400)", posture(0, 400), False),
    ("posture of 15 angles", {"initial_posture_deg": GOOD_POSTURE[:15]}, False),
    ("filmstrip sequence 99", {"figures": {"filmstrip": [["big_ball", "power", 99]]}}, False),
    ("filmstrip sequence 5 of 5", {"figures": {"filmstrip": [["big_ball", "power", 5]]}}, False),
    ("filmstrip object not shown", {"objects": ["big_ball", "small_ball", "big_cube"]}, False),
    ("robot filmstrip sequence 7", {"figures": {"embodied": {"sequence": 7}}}, False),
    ("lift check that cannot pass", {"demos": {"min_lift_m": 0.08}}, False),
    ("touch threshold 50 N", {"demos": {"touch_threshold": 50}}, False),
    ("negative seed", ["seed=-5"], False),
    ("seed as text", ["seed=abc"], False),
    ("sweep seed beyond 2^32", {"sweep": {"seeds": [5000000000]}}, False),
    ("robustness in lower case", ["robustness=true"], False),
    ("unknown key", ["learningrate=0.1"], False),
    ("unknown object", {"objects": ["big_ball", "pear"]}, False),
    ("odd number of networks", {"network": {"networks": 7}}, False),
    ("learning rate as text", {"network": {"learning_rate": "fast"}}, False),
    ("no hidden units", {"network": {"hidden": 0}}, False),
    ("unknown cue timing", {"network": {"categorisation_cue": "sometimes"}}, False),
    ("unknown eye", {"vision": {"eye": "nose_eye"}}, False),
    ("Figure 1 of 5000 pixels", {"body_figure": {"width": 5000}}, False),
    ("one demo sequence (none left to test)", {"demos": {"sequences": 1}}, False),
    ("empty filmstrip", {"figures": {"filmstrip": []}}, False),
    ("run with a bad phase 1", {"runs": {"x": {"network": {"phase1_iterations": 20000}}}}, False),
    ("run named like the main run", {"runs": {"main": {"seed": 1}}}, False),
    ("run changing a section it may not", {"runs": {"x": {"vision": {"window": 50}}}}, False),
    ("missing scene file", ["scene=assets/nope.xml"], False),
    ("scene not well-formed XML", ["scene=bad/broken.xml"], False),
    ("scene that is not the iCub", ["scene=bad/empty.xml"], False),
    ("scene without the close-up camera", ["scene=bad/icub_scene.xml"], False),
    ("scene that MuJoCo cannot compile", ["scene=bad/invalid.xml"], False),
    ("nested --config of a bad value", ["network={phase1_iterations: 13000}"], False),
    # valid inputs that must be accepted
    ("nested --config of a section (valid)", ["network={networks: 12}"], True),
    ("nested --config of a run (valid)", ["runs={x: {network: {learning_rate: 0.0375}}}"], True),
]


def bad_scenes(folder: Path, assets: Path) -> None:
    """The scenes the scene cases point at, beside a copy of the real one."""
    folder.mkdir()
    (folder / "broken.xml").write_text("<mujoco><worldbody><body></mujoco>")
    (folder / "empty.xml").write_text("<mujoco><worldbody/></mujoco>")
    (folder / "invalid.xml").write_text(
        '<mujoco><worldbody><geom type="nonsense"/></worldbody></mujoco>'
    )
    for name in ("icub_scene.xml", "icub_right_arm.xml"):
        shutil.copy(assets / name, folder / name)
    scene = folder / "icub_scene.xml"
    scene.write_text(scene.read_text().replace('name="closeup"', 'name="elsewhere"'))


def digest(folder: Path) -> str:
    h = hashlib.sha256()
    for path in sorted(folder.rglob("*")):
        if path.is_file() and not {"logs", "benchmarks"} & set(path.relative_to(folder).parts):
            h.update(str(path.relative_to(folder)).encode() + path.read_bytes())
    return h.hexdigest()


def scratch(code: Path, data: Path, where: Path) -> Path:
    where.mkdir(parents=True)
    for name in ("Snakefile", "workflow", "config", "assets", "src", "benchmarks", ".test"):
        (where / name).symlink_to(code / name)
    shutil.copytree(data, where / "data", symlinks=True)
    metadata = data.parent / ".snakemake" / "metadata"
    if metadata.is_dir():
        shutil.copytree(metadata, where / ".snakemake" / "metadata")
    shutil.copytree(code / "book", where / "book", symlinks=True)
    bad_scenes(where / "bad", code / "assets")
    return where


def first_error(text: str) -> str:
    """The refusal: Snakemake's error kind and the message under it, on one line."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    for i, line in enumerate(lines):
        if "Error" in line and " in file " in line:
            message = []
            for follow in lines[i + 1 :]:
                if follow.startswith(("File ", "Traceback")):
                    break
                message.append(follow)
            return line.split(" in file ")[0] + ": " + " ".join(message)
    noise = ("Config file", "Assuming", "Building DAG", "Migrating", "Migration")
    useful = [line for line in lines if not line.startswith(noise)]
    return " ".join(useful[-3:])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--code", type=Path, default=REPO)
    parser.add_argument("--data", type=Path, default=REPO / "data")
    args = parser.parse_args()
    code = args.code.resolve()
    env = os.environ | {
        "PYTHONPATH": os.pathsep.join(str(code / p) for p in ("src",)),
        "MUJOCO_GL": "egl",
    }
    with tempfile.TemporaryDirectory() as tmp:
        work = scratch(code, args.data.resolve(), Path(tmp) / "w")
        before = digest(work / "data")
        print("| # | case | change | expected | exit | the answer | data unchanged |")
        print("|---|---|---|---|---|---|---|")
        for i, (case, change, good) in enumerate(CASES, 1):
            cmd = [sys.executable, "-m", "snakemake", "-n", "-c2"]
            if isinstance(change, list):
                cmd += ["--config", *change]
                shown = "--config " + " ".join(change)
            else:
                overlay = Path(tmp) / f"case{i}.yaml"
                overlay.write_text(yaml.safe_dump(change, default_flow_style=True))
                cmd += ["--configfile", str(overlay)]
                shown = yaml.safe_dump(change, default_flow_style=True, width=1000).strip()
            result = subprocess.run(cmd, cwd=work, capture_output=True, text=True, env=env)
            answer = first_error(result.stdout + result.stderr) if result.returncode else "accepted"
            unchanged = digest(work / "data") == before
            expected = "accepted" if good else "refused"
            shown, answer = shown.replace("|", "\\|"), answer.replace("|", "\\|")[:400]
            print(
                f"| {i} | {case} | `{shown}` | {expected} | {result.returncode} | {answer} "
                f"| {'yes' if unchanged else 'NO'} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
