"""The book as a reader meets it: every chapter leads with its answer, the words are few enough
to read in twenty minutes, the tables fit the text column, and the front page's scorecard
verdicts follow their tests."""

from __future__ import annotations

import html
import itertools
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from conftest import TOOL_TESTS

from icub_workflow.book import scorecard, text
from icub_workflow.book_build import reading

REPO = Path(__file__).resolve().parents[1]
HTML = "book/_build/html"

#: The issue's budget: at most this many words a reader reads, per chapter and in all.
CHAPTER_WORDS, BOOK_WORDS = 2000, 10000
#: Issue 69: at most 12 pages, and every word, the dropdowns' too, at most 18,000.
MAX_PAGES, ALL_WORDS = 12, 18000


def toc_chapters() -> list[str]:
    toc = yaml.safe_load((REPO / "book" / "_toc.yml").read_text())
    return [toc["root"]] + [entry["file"] for entry in toc["chapters"]]


# -- the reader's count, on pages made here ----------------------------------------------------

PAGE = """<html><body><nav>menu words here</nav><article class="bd-article">
<section><h1>Title of it</h1>
<div class="admonition in-brief"><p class="admonition-title">In brief</p>
<p>The effect is reproduced. The size effect, p = 0.013, is reversed.</p></div>
<p>Five words of plain prose.</p>
<table><tr><td>many numbers 1 2 3 4 5 6</td></tr></table>
<div class="cell docutils container"><div class="cell_input">hidden code words</div></div>
<div class="admonition dropdown"><p>three folded words</p></div>
<details><summary>two more</summary></details>
</section></article></body></html>"""


def test_the_reader_count_skips_tables_code_and_folded_sections():
    page = reading.page_text(PAGE)
    # title 3 + "In brief" 2 + brief 12 + prose 5
    assert page.words == 3 + 2 + 12 + 5
    assert page.folded_words == 3 + 2
    assert page.first_block == reading.IN_BRIEF_CLASS
    assert reading.sentences(page.in_brief) == [
        "The effect is reproduced.",
        "The size effect, p = 0.013, is reversed.",
    ]


def test_a_page_whose_first_block_is_prose_has_no_in_brief():
    page = reading.page_text(PAGE.replace("admonition in-brief", "admonition note"))
    assert page.first_block == "div" and page.in_brief == ""


# -- the scorecard, on outputs made here ----------------------------------------------------------


def claim_rows(congruency_p=0.001, size=-0.026) -> pd.DataFrame:
    """The confirmatory family's summary (data/claims/summary.csv): both claims in the four cue ×
    mode conditions on the paper's measure; the first-step closed-loop tests as given, the others
    in the paper's direction."""
    rows = []
    for cue, mode in itertools.product(("first_step", "all_steps"),
                                       ("closed_loop", "teacher_forced")):  # fmt: skip
        given = (cue, mode) == ("first_step", "closed_loop")
        for effect, estimate, p in (("congruency", 0.04, congruency_p), ("size", size, 0.01)):
            estimate, p = (estimate, p) if given else (0.01, 0.001)
            rows.append({"cue": cue, "mode": mode, "measure": "rmse",
                         "effect": effect, "replications": 10, "estimable": 10,
                         "not_estimable": 0, "estimate": estimate, "ci_low": estimate - 0.01,
                         "ci_high": estimate + 0.01, "p": p, "p_holm": p,
                         "family": "confirmatory", "family_size": 8,
                         "direction": "none" if p >= 0.05 else "paper" if estimate > 0 else
                         "reversed"})  # fmt: skip
    return pd.DataFrame(rows)


def score_inputs(congruency_p=0.001, size=-0.026, dose0=-0.02, grips=0.01, held=0.96,
                 ci=(0.93, 0.99)):  # fmt: skip
    learning = pd.DataFrame({"seed": range(101, 111), "networks": 12, "start": 0.22,
                             "end": np.linspace(0.045, 0.049, 10)})  # fmt: skip
    size_rows = pd.DataFrame(
        [{"test": t, "dose": d, "cue": "first_step", "measure": "rmse", "replications": 10,
          "left_out": 0, "estimate": x, "ci_low": x - 0.005, "ci_high": x + 0.005, "p": 0.001,
          "p_holm": 0.001, "family": "size study: declared"}
         for t, d, x in (("size", "0", dose0), ("grip_distance", "0", grips),
                         ("size", "0.6", 0.03), ("dose", "0.6 - 0", 0.01))]
    )  # fmt: skip
    variants = pd.DataFrame(
        [{"run": "main", "grasping_success": 0.0625, "grasping_trials": 48, "networks": 12}]
    )
    confirmation = pd.DataFrame(
        [{"seed_set": "confirmation", "share": held, "ci_low": ci[0], "ci_high": ci[1],
          "networks": 12, "trials": 48}]
    )  # fmt: skip
    signatures = pd.DataFrame(
        [{"signature": "grows_with_rt", "condition": "in view, effect over RT bins",
          "estimate": 0.004, "ci_low": 0.001, "ci_high": 0.007,
          "p_adjusted": 0.01, "verdict": "confirmed", "family": "signatures", "replications": 10,
          "units": 10, "of": 10, "reason": ""},
         {"signature": "advance_cueing", "condition": "not posed",
          "estimate": np.nan, "ci_low": np.nan, "ci_high": np.nan,
          "p_adjusted": np.nan, "verdict": "not assessable", "family": "signatures",
          "replications": 0, "units": 0, "of": 0,
          "reason": "no input names a grip apart from an object"}]
    )  # fmt: skip
    claims = claim_rows(congruency_p, size)
    return claims, learning, size_rows, variants, confirmation, signatures


def verdicts(*args, **kwargs) -> dict[str, str]:
    values, table = scorecard.scorecard(*score_inputs(*args, **kwargs))
    words = {key: value.text for key, value in values.items() if key.endswith("_verdict")}
    assert sorted(table["verdict"]) == sorted(words.values())  # the table shows these values
    return words


CONGRUENCY = "score_claim_rmse_congruency_verdict"
SIZE = "score_claim_rmse_size_verdict"


def test_each_scorecard_verdict_follows_its_test():
    base = verdicts()
    assert base["score_learn_verdict"] == "confirmed"
    assert base[CONGRUENCY] == "confirmed in 4 of 4"
    assert base[SIZE] == "confirmed in 3 of 4, reversed in 1"
    assert base["score_size_size_first_step_verdict"] == "reversed"
    assert base["score_size_grips_first_step_verdict"] == "confirmed"
    # beside the dose-0 rows: the other dose's and the dose contrast's
    assert base["score_size_size_06_first_step_verdict"] == "confirmed"
    assert base["score_size_dose_first_step_verdict"] == "confirmed"
    assert base["score_robot_own_verdict"] == "reversed"
    assert base["score_robot_best_verdict"] == "confirmed"
    # a signature's row shows the verdict its chapter's test gave
    # (icub_affordance.analysis.signature_tests)
    assert base["score_signature_grows_with_rt_verdict"] == "confirmed"
    assert base["score_signature_advance_cueing_verdict"] == "not assessable"
    # flip each statistic: its verdict, and only its, follows
    assert verdicts(congruency_p=0.2)[CONGRUENCY] == ("confirmed in 3 of 4, not shown in 1")
    assert verdicts(size=0.026)[SIZE] == "confirmed in 4 of 4"
    assert verdicts(dose0=0.02)["score_size_size_first_step_verdict"] == "confirmed"
    against = "reversed"
    assert verdicts(grips=-0.02)["score_size_grips_first_step_verdict"] == against
    assert verdicts(ci=(0.84, 0.99))["score_robot_best_verdict"] == "not shown"
    changed = verdicts(congruency_p=0.2)
    assert {k for k in base if base[k] != changed[k]} == {CONGRUENCY}


def test_the_claims_are_read_by_condition_teacher_forced_first():
    summary = claim_rows(congruency_p=0.2)
    values, _ = scorecard.claims_values(
        summary, summary.assign(power_at_least=0.9), sensitivity_rows(), cell_counts()
    )
    said = {k: v.text for k, v in values.items() if isinstance(v, text.Claim)}
    assert said["claims_closed_loop_rmse_congruency"] == (
        "not shown with the cue at the first step and confirmed with it at every step"
    )
    assert said["claims_teacher_forced_rmse_congruency"] == "confirmed under both cue timings"
    assert said["claims_count_rmse_congruency"] == ("confirmed in 3 of 4, not shown in 1")
    assert said["claims_count_rmse_size"] == "confirmed in 3 of 4, reversed in 1"
    # the count of correlated tests is gone: both modes test the same networks
    assert "claims_counts" not in values and "claims_family_size" not in values
    _, table = scorecard.scorecard(*score_inputs(congruency_p=0.2))
    claims = table[table["chapter"] == "index"]
    assert len(claims) == 2  # one row per claim and measure, not per test
    assert claims["this build"].str.startswith("teacher forced: ").all()


def sensitivity_rows(first_p_holm: float = 0.001) -> pd.DataFrame:
    """The correct-trial estimates over every replication (data/claims/correct_sensitivity.csv):
    the first-step closed-loop congruency test at ``first_p_holm``, the others below 0.05."""
    rows = []
    for cue, mode, effect in itertools.product(
        ("first_step", "all_steps"), ("closed_loop", "teacher_forced"), ("congruency", "size")
    ):
        first = (cue, mode, effect) == ("first_step", "closed_loop", "congruency")
        p = first_p_holm if first else 0.001
        rows.append({"cue": cue, "mode": mode, "effect": effect, "replications_used": 10,
                     "estimate": 0.004, "ci_low": 0.001, "ci_high": 0.007, "p": p,
                     "p_holm": p})  # fmt: skip
    return pd.DataFrame(rows)


def cell_counts() -> pd.DataFrame:
    """Networks carrying each cell (data/claims/correct_cells.csv): mapping B's fewest is 1."""
    return pd.DataFrame(
        [{"cue": cue, "mode": mode, "mapping": mapping, "networks": 6 if mapping == "A" else n}
         for cue in ("first_step", "all_steps") for mode in ("closed_loop", "teacher_forced")
         for mapping in ("A", "B") for n in (1, 6)]
    )  # fmt: skip


def test_where_every_replication_disagrees_with_the_confirmation_the_scorecard_says_so():
    correct = claim_rows().assign(measure="rmse_correct")
    inputs = list(score_inputs())
    for p_holm, differs in ((0.001, False), (0.3, True)):
        inputs[0] = correct
        _, table = scorecard.scorecard(*inputs, sensitivity=sensitivity_rows(p_holm))
        row = table[table["claim or question"].str.startswith("Congruent")].iloc[0]
        # led by every replication's verdicts, the declared ones beside them
        every = "over every replication (exploration), teacher forced: confirmed under both"
        assert row["this build"].startswith(every), row["this build"]
        assert ("closed loop: not shown with the cue at the first step" in row["this build"]) \
            == differs, row["this build"]  # fmt: skip
        assert ". Declared (confirmatory), teacher forced: " in row["this build"]
        assert row["verdict"].startswith("every replication: confirmed in ")
        assert "; declared: confirmed in 4 of 4" in row["verdict"]
    # a declared test on fewer replications says what they were selected on
    inputs[0] = correct.assign(estimable=np.where(correct["mode"] == "closed_loop", 5, 10))
    _, table = scorecard.scorecard(*inputs, sensitivity=sensitivity_rows())
    row = table[table["claim or question"].str.startswith("Congruent")].iloc[0]
    assert row["this build"].endswith("on the replications with a correct trial in every cell: "
                                      "5 of 10 (closed loop, cue at the first step), 5 of 10 "
                                      "(closed loop, cue at every step)")  # fmt: skip
    assert row["measured at"] == "10 replications × 12 networks per condition"
    _, claims = scorecard.claims_values(
        correct, correct.assign(power_at_least=0.9), sensitivity_rows(0.3), cell_counts()
    )
    first = claims.iloc[0]
    assert first["fewest networks per cell (A / B)"] == "6 / 1"
    assert first["over every replication (exploration)"].endswith("Holm p 0.3: not shown")


def test_the_fewest_networks_are_counted_in_the_replications_a_test_used():
    """Issue 70: a replication with no correct trial in a cell gives no estimate and is left out
    of the test; the networks beside the test are those of the replications it rests on."""
    correct = claim_rows().assign(measure="rmse_correct")
    cells = pd.DataFrame(
        [{"cue": c, "mode": m, "seed": seed, "mapping": mapping, "networks": n}
         for c in ("first_step", "all_steps") for m in ("closed_loop", "teacher_forced")
         for seed, mapping, n in ((1, "A", 0), (1, "B", 6), (2, "A", 4), (2, "B", 5))]
    )  # fmt: skip
    keys = ["cue", "mode", "measure", "effect"]
    replications = pd.concat(
        [correct[keys].assign(seed=seed, estimate=estimate) for seed, estimate in
         ((1, np.nan), (2, 0.01))]
    )  # fmt: skip
    args = (correct, correct.assign(power_at_least=0.9), sensitivity_rows(), cells)
    _, used = scorecard.claims_values(*args, replications)
    _, every = scorecard.claims_values(*args)
    assert set(used["fewest networks per cell (A / B)"]) == {"4 / 5"}
    assert set(every["fewest networks per cell (A / B)"]) == {"0 / 5"}
    _, none = scorecard.claims_values(*args, replications.assign(estimate=np.nan))
    assert set(none["fewest networks per cell (A / B)"]) == {"–"}


def test_every_scorecard_row_about_the_model_rests_on_ten_replications_or_says_so():
    _, table = scorecard.scorecard(*score_inputs())
    model = table[~table["chapter"].isin(["robot_test"])]
    for scale in model["measured at"]:
        if scale == "not posed":  # a signature the model cannot express: nothing was measured
            continue
        found = [int(n) for n in re.findall(r"(\d+) (?:of \d+ )?replications", scale)]
        assert found and max(found) >= 10, scale
    claims = table[table["claim or question"].str.startswith(("Congruent", "Large"))]
    assert claims["this build"].str.contains("confirmatory").all()


def test_each_scorecard_verdict_rests_on_the_numbers_beside_it():
    values, _ = scorecard.scorecard(*score_inputs())
    for value in values.values():
        if isinstance(value, text.Claim):
            for entry in value.rests_on:
                page, name = entry.split(".", 1)
                assert page == "index" and isinstance(values[name], float), entry


# -- the built book (the test configuration's run) -----------------------------------------------


@pytest.fixture(scope="module")
def pages(built):
    return reading.chapters(built / HTML)


def test_every_chapter_of_the_table_of_contents_is_built(pages):
    assert set(toc_chapters()) <= set(pages), set(toc_chapters()) - set(pages)


def test_every_chapter_leads_with_an_in_brief_of_at_most_three_sentences(pages):
    for name in toc_chapters():
        page = pages[name]
        assert page.first_block == reading.IN_BRIEF_CLASS, name
        assert 1 <= len(reading.sentences(page.in_brief)) <= 3, (name, page.in_brief)


def test_the_front_pages_in_brief_is_read_in_a_minute(pages):
    """Issue 69: the paper's claims, what was found, how sure and why, in at most 150 words."""
    assert len(pages["index"].in_brief.split()) <= 150, pages["index"].in_brief


def test_the_book_is_short_enough_to_read_in_twenty_minutes(pages):
    counts = {name: pages[name].words for name in toc_chapters()}
    assert {n: c for n, c in counts.items() if c > CHAPTER_WORDS} == {}
    assert sum(counts.values()) <= BOOK_WORDS, counts
    folded = {name: pages[name].folded_words for name in toc_chapters()}
    assert sum(counts.values()) + sum(folded.values()) <= ALL_WORDS, folded


def test_the_book_has_at_most_twelve_pages():
    """The front page and its chapters: the model's four parts are one chapter, the paper's
    numbers sit with this run's results, the sweep with the build it repeats."""
    assert len(toc_chapters()) <= MAX_PAGES, toc_chapters()


def test_the_scorecard_on_the_front_page_is_the_findings(built):
    found = json.loads((built / "data" / "book" / "findings.json").read_text())
    table = pd.read_csv(built / "data" / "book" / "tables" / "scorecard.csv")
    verdicts = [v for k, v in found["index"].items() if k.startswith("score_") and k.endswith(
        "_verdict")]  # fmt: skip
    assert sorted(table["verdict"]) == sorted(verdicts)
    assert all(k in found["claims"]["index"] for k in found["index"] if k.endswith("_verdict"))
    html = (built / HTML / "index.html").read_text()
    for claim in table["claim or question"]:
        assert claim.replace("'", "&#x27;") in html or claim in html, claim


# -- looked at: tables and figures within the text column, in headless Chromium ----------------

#: Run in each page after load: every table and image in the article, and whether it is wider
#: than the article's text column (its own width, or a scrolled-away part of it).
MEASURE = """<script>
window.addEventListener("load", () => {
  const article = document.querySelector("article");
  const column = article.getBoundingClientRect();
  const wide = [];
  // an output's own scroll box (a div inside .cell_output) is where a wide table is cut
  for (const el of article.querySelectorAll("table, img, figure, .cell_output, .cell_output div")) {
    const box = el.getBoundingClientRect();
    const cut = el.scrollWidth > el.clientWidth + 1 && el.tagName !== "IMG";
    if (box.right > column.right + 1 || cut) {
      wide.push(`${el.tagName.toLowerCase()} ${Math.round(Math.max(box.width, el.scrollWidth))}px`
        + ` in a ${Math.round(column.width)}px column: ${el.textContent.trim().slice(0, 60)}`);
    }
  }
  const out = document.createElement("pre");
  out.id = "width-report";
  out.textContent = JSON.stringify(wide);
  document.body.appendChild(out);
});
</script>"""


def looked_at(page: Path, script: str, report_id: str, chromium: str) -> list:
    """What ``script``, run in ``page`` after load in headless Chromium at 1280 px, reports in
    its ``<pre id=report_id>`` (JSON); the page is the copy's, changed in place."""
    page.write_text(page.read_text().replace("</body>", script + "</body>"))
    dom = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--window-size=1280,2000",
         "--virtual-time-budget=5000", "--dump-dom", page.as_uri()],
        capture_output=True, text=True, timeout=120,
    ).stdout  # fmt: skip
    report = re.search(rf'<pre id="{report_id}"[^>]*>(.*?)</pre>', dom, re.S)
    assert report, f"{page.stem}: the measuring script did not run"
    return json.loads(html.unescape(report.group(1)))


@pytest.mark.dryrun
@pytest.mark.tool("chromium")
def test_no_table_or_figure_is_wider_than_the_text_column(built, tmp_path):
    """Looked at in headless Chromium at 1280 px: no table or figure overflows the text column,
    nor is cut by its own scroll box. `.ci/run` installs Chromium and asks for this test."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        assert os.environ.get(TOOL_TESTS["chromium"]) != "1", "asked for, but no chromium"
        pytest.skip("Debian's chromium is not installed (apt-get install chromium)")
    site = tmp_path / "html"
    shutil.copytree(built / HTML, site)
    too_wide = {}
    for name in toc_chapters():
        found = looked_at(site / f"{name}.html", MEASURE, "width-report", chromium)
        if found:
            too_wide[name] = found
    assert too_wide == {}


#: The issue's floor: no figure's text smaller than this, in points, at the width its page shows it.
SMALLEST_PT = 8

#: Images the book shows that `figures.save` does not draw, so they carry no font record: the
#: workflow's graph (Graphviz), the rendered robot and its eye's view, the robot's animations.
NOT_SAVED = {"rulegraph.png", "figure1_scene.png", "figure1_eye.png", "robot_grasps.gif",
             "robot_categorise.gif"}  # fmt: skip

#: Run in each page after load: every image in the article, its source, natural and shown width.
IMAGES = """<script>
window.addEventListener("load", () => {
  const shown = [...document.querySelectorAll("article img")].map((img) => ({
    src: img.getAttribute("src"), natural: img.naturalWidth,
    css: img.getBoundingClientRect().width}));
  const out = document.createElement("pre");
  out.id = "image-report";
  out.textContent = JSON.stringify(shown);
  document.body.appendChild(out);
});
</script>"""


def png_text(page: Path, src: str) -> dict[str, str]:
    """The text metadata of the image `src` of `page` (a file beside it, or a data: URI)."""
    import base64
    import io
    from urllib.parse import unquote

    from PIL import Image

    if src.startswith("data:"):
        data = io.BytesIO(base64.b64decode(src.split(",", 1)[1]))
        return dict(getattr(Image.open(data), "text", {}))
    with Image.open(page.parent / unquote(src.split("?")[0])) as image:
        return dict(getattr(image, "text", {}))


def figure_text_sizes(site: Path, chromium: str) -> list[dict]:
    """Each image of each chapter of the built book in `site`, as headless Chromium shows it at
    1280 px: its page, name, and its smallest text in points as seen (None: no font record).
    The record's points at its dpi, scaled by shown over natural width: pt · dpi/96 · css/px."""
    from icub_affordance.figures import DPI_KEY, SMALLEST_FONT_KEY

    sizes = []
    for name in toc_chapters():
        page = site / f"{name}.html"
        for img in looked_at(page, IMAGES, "image-report", chromium):
            meta = png_text(page, img["src"])
            image = "inline image" if img["src"].startswith("data:") else Path(img["src"]).name
            effective = None
            if SMALLEST_FONT_KEY in meta and img["natural"]:
                scale = img["css"] / img["natural"]
                effective = float(meta[SMALLEST_FONT_KEY]) * float(meta[DPI_KEY]) / 96 * scale
            sizes.append({"page": name, "image": image, "pt": effective})
    return sizes


@pytest.mark.dryrun
@pytest.mark.tool("chromium")
def test_every_figure_s_text_is_at_least_8_pt_at_the_page_s_width(built, tmp_path):
    """Looked at in headless Chromium at 1280 px: each figure drawn by `figures.save` shows its
    smallest text (tick labels included) at 8 pt or more; an image without the record is one
    named in `NOT_SAVED`, so that a new figure cannot slip by unmeasured."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        assert os.environ.get(TOOL_TESTS["chromium"]) != "1", "asked for, but no chromium"
        pytest.skip("Debian's chromium is not installed (apt-get install chromium)")
    site = tmp_path / "html"
    shutil.copytree(built / HTML, site)
    sizes = figure_text_sizes(site, chromium)
    assert sizes, "no image measured"
    unrecorded = {f"{s['page']}: {s['image']}" for s in sizes if s["pt"] is None
                  and s["image"] not in NOT_SAVED}  # fmt: skip
    assert unrecorded == set(), "images not drawn by figures.save"
    small = [f"{s['page']}: {s['image']} at {s['pt']:.1f} pt" for s in sizes
             if s["pt"] is not None and s["pt"] < SMALLEST_PT]  # fmt: skip
    assert small == []


def test_the_declared_contact_time_row_follows_its_test_and_names_its_cells():
    cells = pd.DataFrame(
        [{"run": "fresh", "congruency": c, "size": s, "trials": 12,
          "touched": 9 if (c, s) == ("incongruent", "small") else 12}
         for c in ("congruent", "incongruent") for s in ("large", "small")]
    )  # fmt: skip
    for p_holm, word in ((0.03, "confirmed"), (0.3, "not shown")):
        contact = pd.DataFrame([{"run": "fresh", "networks": 12, "networks_tested": 9,
                                 "estimate": 0.11, "ci_low": 0.01, "ci_high": 0.21,
                                 "p_holm": p_holm,
                                 "direction": "paper" if p_holm < 0.05 else "none"}])  # fmt: skip
        values, table = scorecard.scorecard(*score_inputs(), contact=contact, contact_cells=cells)
        row = table[table["claim or question"].str.contains("fingers touch")].iloc[0]
        assert row["verdict"] == values["score_robot_contact_verdict"].text == word
        assert "9 of 12 networks" in row["this build"]
        assert "incongruent small 9 of 12" in row["this build"]


def test_the_scorecard_puts_each_dose_beside_the_dose_0_rows_then_the_contrast():
    _values, table = scorecard.scorecard(*score_inputs())
    size = table.loc[table["chapter"] == "size", "claim or question"].tolist()
    assert len(size) == 4
    assert "(dose 0)" in size[0] and "(dose 0.6)" in size[1] and "dose contrast" in size[3]


def article_words(page: Path) -> str:
    """A built page's article, tables and folded sections included, as plain text."""
    article = re.search(r"<article.*?</article>", page.read_text(), re.S)
    text = re.sub(
        r"<(script|style)\b.*?</\1>", " ", article.group(0) if article else "", flags=re.S
    )
    return re.sub(r"\s+", " ", html.unescape(re.sub(r"<[^>]+>", " ", text))).replace("’", "'")


def retired_in(text: str) -> list[str]:
    """The retired verdict words (book.words.RETIRED) a text still uses, each once."""
    from icub_workflow.book.words import RETIRED

    return [word for word in RETIRED if re.search(rf"\b{re.escape(word)}\b", text)]


def test_the_book_and_the_readme_speak_only_the_five_verdict_words(built):
    """Issue 69: the verdict words the book once used (reproduced, shown, opposite, falls short,
    not known, not testable, ...) are gone from every page, tables and dropdowns included, and
    from the README; the five that replace them are defined once, on the front page."""
    from icub_workflow.book.words import VERDICTS

    pages = {name: article_words(built / HTML / f"{name}.html") for name in toc_chapters()}
    assert {name: retired_in(text) for name, text in pages.items() if retired_in(text)} == {}
    assert retired_in((REPO / "README.md").read_text()) == []
    definitions = re.search(r"Five words(.*?)How to read the scorecard", pages["index"])
    assert definitions, "the front page defines the five words in one section"
    assert all(word.capitalize() in definitions.group(1) for word in VERDICTS)
