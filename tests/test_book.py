"""The book: built by the pipeline, showing Figures 1-5 and the ANOVA, numbers from the outputs."""

from __future__ import annotations

import json
import re
import shutil

import pandas as pd
import pytest
import yaml
from conftest import load_test_config, run_snakemake

HTML = "book/_build/html"


@pytest.fixture(scope="module")
def html(built):
    return {page.stem: page.read_text() for page in (built / HTML).glob("*.html")}


@pytest.mark.parametrize(
    ("page", "image"),
    [
        ("model", "figure1_scene.png"),
        ("model", "figure2_maps.png"),
        ("model", "figure2_architecture.png"),
        ("reproduce", "rulegraph.png"),
        ("model", "figure3.png"),
        ("results", "figure4.png"),
        ("results", "figure5.png"),
        ("results", "conflict_timecourse.png"),
        ("model", "filmstrip.png"),
    ],
)
def test_figures_are_the_pipelines_outputs(built, html, page, image):
    assert f"_images/{image}" in html[page]
    shown = (built / HTML / "_images" / image).read_bytes()
    source = next((built / "data").rglob(image)).read_bytes()
    assert shown == source  # the very file the pipeline wrote


def test_figure2_diagram_is_a_plot_rules_output(html):
    """Figure 2's diagram and the DAG are drawn by plot rules: the pages only show them."""
    assert "Figure 2 (drawn by rule" in html["model"]
    for page in ("model", "reproduce"):
        assert not re.search(r'src="_images/[0-9a-f]{64}\.png"', html[page]), page  # no drawing


def test_anova_numbers_in_the_book_equal_anova_json(built, html):
    anova = json.loads((built / "data" / "eval" / "anova.json").read_text())
    for mode in ("closed_loop", "teacher_forced"):
        for analysis in ("two_way", "repeated_measures"):
            for effect, r in anova[mode][analysis].items():
                assert f"{r['F']:.2f}" in html["results"], (mode, analysis, effect)
                if analysis == "repeated_measures":
                    assert f"{r['p']:.2g}" in html["results"], (mode, analysis, effect)
        # the two-way rows (trials as observations, each movement counted five times) show no p
        table = re.search(rf'<table id="T_anova_{mode}".*?</table>', html["results"], re.S)
        rows = re.findall(r"<tr>(.*?)</tr>", table.group(0), re.S)
        two_way = [re.findall(r"<td[^>]*>(.*?)</td>", row, re.S) for row in rows
                   if "two-way" in row]  # fmt: skip
        assert len(two_way) == len(anova[mode]["two_way"]), mode
        assert all(cells[3].strip() == "–" for cells in two_way), two_way
    # inference is the per-network contrasts', in the results
    for mode in ("closed_loop", "teacher_forced"):
        for term, r in anova["contrasts"][mode].items():
            assert f"{r['estimate']:+.4f}" in html["results"], (mode, term)


def test_front_page_shows_provenance(built, html):
    run = json.loads((built / "book" / "_data" / "run.json").read_text())
    assert run["commit"] in html["index"]
    # the packages and the configuration are on the reproduce page, folded
    assert run["versions"]["mujoco"] in html["reproduce"]
    assert f"seed: {run['config']['seed']}" in html["reproduce"]


def test_without_robustness_the_robustness_page_says_so_and_gives_the_command(built, html):
    """The sweep's section of the reproduce page (the robustness page before issue 69)."""
    page = html["reproduce"]
    start, end = page.index('id="replications-at-other'), page.index('id="this-run-s-packages')
    page = page[start:end]
    words = " ".join(re.sub(r"<[^>]+>", "", page).split())  # the text a reader sees
    assert "This build did not run it (robustness is false, the default)" in words
    assert "snakemake -c2 --config robustness=True" in words
    assert "sweep_effects.png" not in page and "<table" not in page  # no numbers invented


def without_build_time(page):
    """The page without its build's date and the build's job records (the reproduce page's
    span and job time, which a rebuild of the book extends by the book's own job)."""
    text = re.sub(r"built \d{4}-\d\d-\d\d \d\d:\d\d UTC", "built (time)", page.read_text())
    return re.sub(
        r"The whole build this book comes from .*? records\.", "(the build)", text, flags=re.S
    )


@pytest.mark.reruns
def test_a_rebuild_gives_the_same_pages_and_follows_a_changed_output(built, tmp_path):
    """No random table ids or layouts: a rebuild from the same outputs moves only the build time
    and the job records. Then, in the same place (only the data changed, not the page), a
    changed output changes the page after a rebuild."""
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    result = run_snakemake(copy, "-c2", "book/_build/html/index.html", "--forcerun", "book")
    assert result.returncode == 0, result.stderr[-3000:]
    for page in sorted((built / HTML).glob("*.html")):
        if page.name not in ("reproduce.html", "search.html"):
            assert without_build_time(copy / HTML / page.name) == without_build_time(page), (
                page.name
            )
    # the DAG drawing on the reproduce page, the pipeline's rulegraph.png
    drawn = [(root / HTML / "_images" / "rulegraph.png").read_bytes() for root in (built, copy)]
    assert drawn[0] == drawn[1]
    # a changed output, rebuilt where the book was just built
    anova_path = copy / "data" / "eval" / "anova.json"
    anova = json.loads(anova_path.read_text())
    anova["closed_loop"]["repeated_measures"]["congruency"]["F"] = 12345.678
    anova_path.write_text(json.dumps(anova))
    result = run_snakemake(copy, "-c2", "book/_build/html/index.html")
    assert result.returncode == 0, result.stderr[-3000:]
    assert "12345.68" in (copy / HTML / "results.html").read_text()
    assert "12345.68" not in (built / HTML / "results.html").read_text()


def seen(page: str) -> str:
    """A page's text as a reader sees it (tags dropped, spaces joined)."""
    return " ".join(re.sub(r"<[^>]+>", " ", page).split())


@pytest.mark.reruns
def test_the_robot_chapter_compares_variants_only_where_the_build_tests_them(built, html, tmp_path):
    """Issue 47: the default build tests the config's own networks alone beside the
    confirmation, so the robot chapter compares no variants, says that the full scale does,
    shows the fresh networks' row alone and films the confirmation's fresh networks. Listing the
    confirmed variant in robot.default (as the full scale tests the whole grid) brings the
    comparison, the figure of success against training, the exploration's row and films of its
    networks 0.. into the chapter."""
    page = seen(html["robot_test"])
    assert "This build therefore compares no variants" in page and "at full scale only" in page
    assert "robot_variants.png" not in html["robot_test"] and not re.search(r"\bnan\b", page)
    assert "best variant" not in page
    nets = load_test_config()["robot"]["confirmation"]
    first, count = nets["first_network"], nets["networks"]
    assert f"networks {first} and {first + count // 2}" in page
    table = pd.read_csv(built / "data/embodied/confirmation.csv")
    assert table["seed_set"].tolist() == ["confirmation"]
    copy = tmp_path / "copy"
    shutil.copytree(built, copy, symlinks=True)
    config = load_test_config()
    config["robot"]["default"] = [{"target": "commands", "hidden": 10, "iterations": 1200}]
    path = tmp_path / "listed.yaml"
    path.write_text(yaml.safe_dump(config))
    result = run_snakemake(copy, "-c2", config=path)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    listed = (copy / HTML / "robot_test.html").read_text()
    words = seen(listed)
    assert "compares no variants" not in words and "the variant that grasps most often" in words
    assert "_images/robot_variants.png" in listed and not re.search(r"\bnan\b", words)
    assert "networks 0 and 2" in words  # the films: the variant's own networks now
    table = pd.read_csv(copy / "data/embodied/confirmation.csv")
    assert table["seed_set"].tolist() == ["exploration", "confirmation"]
    assert f"there it held the object in {table['held'][0]} of {table['trials'][0]}" in words
