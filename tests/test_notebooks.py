"""The book's pages executed ahead of Sphinx: MyST-NB must find each page's outputs in the cache."""

from __future__ import annotations

from pathlib import Path

import pytest

from icub_workflow.book_build.notebooks import CACHE_DIR, execute_pages, is_notebook

FRONT = "---\nkernelspec:\n  name: python3\n  display_name: Python 3\n---\n\n"


def page(book: Path, name: str, code: str) -> Path:
    path = book / name
    path.write_text(f"{FRONT}# {name}\n\n```{{code-cell}} ipython3\n{code}\n```\n")
    return path


def cached_outputs(book: Path, path: Path):
    """What MyST-NB does in cache mode: read the page, match it in the cache, merge outputs."""
    from jupyter_cache import get_cache
    from myst_nb.core.read import read_myst_markdown_notebook

    notebook = read_myst_markdown_notebook(path.read_text(), add_source_map=True, path=str(path))
    _, merged = get_cache(str(book / CACHE_DIR)).merge_match_into_notebook(notebook)
    return [cell.outputs for cell in merged.cells if cell.cell_type == "code"]


@pytest.mark.heavy
def test_every_page_is_found_in_the_cache_with_its_outputs(tmp_path):
    (tmp_path / "data.txt").write_text("from the pipeline")
    a = page(tmp_path, "a.md", "print(open('data.txt').read())")  # runs in the page's directory
    b = page(tmp_path, "b.md", "6 * 7")
    seconds = execute_pages(tmp_path, [a, b], workers=2)
    assert set(seconds) == {"a.md", "b.md"}
    assert cached_outputs(tmp_path, a)[0][0]["text"] == "from the pipeline\n"
    assert cached_outputs(tmp_path, b)[0][0]["data"]["text/plain"] == "42"


@pytest.mark.heavy
def test_a_new_build_never_shows_the_last_builds_outputs(tmp_path):
    """The cache is keyed on the code, not the data it reads: it must be emptied every build."""
    data = tmp_path / "data.txt"
    a = page(tmp_path, "a.md", "print(open('data.txt').read())")
    data.write_text("first run")
    execute_pages(tmp_path, [a], workers=1)
    data.write_text("second run")
    execute_pages(tmp_path, [a], workers=1)
    assert cached_outputs(tmp_path, a)[0][0]["text"] == "second run\n"


@pytest.mark.heavy
def test_a_page_never_sees_what_an_earlier_page_in_its_kernel_defined(tmp_path):
    """One kernel runs several pages: each must start from an empty namespace, as in its own."""
    first = page(tmp_path, "a_first.md", "import json\nsecret = 42")
    second = page(tmp_path, "b_second.md", "print(secret)")
    third = page(tmp_path, "c_third.md", "json.dumps(1)")
    with pytest.raises(RuntimeError, match=r"2 book page\(s\) failed") as error:
        execute_pages(tmp_path, [first, second, third], workers=1)
    assert "name 'secret' is not defined" in str(error.value)
    assert "name 'json' is not defined" in str(error.value)
    assert "a_first.md" not in str(error.value)


@pytest.mark.heavy
def test_a_failing_page_is_named_with_its_error(tmp_path):
    good = page(tmp_path, "good.md", "1")
    bad = page(tmp_path, "bad.md", "raise ValueError('anova.json lacks closed_loop')")
    with pytest.raises(RuntimeError, match=r"1 book page\(s\) failed") as error:
        execute_pages(tmp_path, [good, bad], workers=2)
    assert "bad.md" in str(error.value) and "anova.json lacks closed_loop" in str(error.value)
    assert "good.md" not in str(error.value)


def test_only_pages_that_name_a_kernel_are_executed(tmp_path):
    assert is_notebook(page(tmp_path, "a.md", "1"))
    plain = tmp_path / "plain.md"
    plain.write_text("# References\n\n```{bibliography}\n```\n")
    assert not is_notebook(plain)
    book = Path(__file__).resolve().parents[1] / "book"
    assert is_notebook(book / "results.md")
