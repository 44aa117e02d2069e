"""Execute the book's pages side by side, before Sphinx reads them.

Every executed page starts its own Jupyter kernel (about a second) and then reads the
pipeline's outputs. Sphinx runs them one after another, and it cannot read pages in parallel
here: ``sphinx_external_toc``, which every Jupyter Book loads, loads
``sphinx_multitoc_numbering``, and that extension does not declare itself safe for it. So we
execute the pages ourselves, ``workers`` at a time, and leave the outputs in the Jupyter cache
that MyST-NB reads in ``execute_notebooks: cache`` mode (``book/_config.yml``). MyST-NB then
finds every page's outputs there, matched by the hash of its code, and executes nothing.

The cache is emptied first on every build. It is keyed on the pages' code, not on the data they
read, so outputs left from an earlier run would otherwise be shown as this run's.
"""

from __future__ import annotations

import shutil
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

#: Where Jupyter Book 1.x keeps the cache when ``execute.cache`` is not set in ``_config.yml``.
CACHE_DIR = Path("_build") / ".jupyter_cache"


def is_notebook(page: Path) -> bool:
    """MyST-NB executes a Markdown page when its front matter names a kernel."""
    text = page.read_text("utf8")
    if not text.startswith("---"):
        return False
    front_matter = text.split("---", 2)[1]
    return "kernelspec:" in front_matter


def execute_pages(
    book: Path, pages: list[Path], workers: int = 2, timeout: int = 300
) -> dict[str, float]:
    """Execute ``pages`` (MyST Markdown notebooks in ``book``) into a fresh Jupyter cache.

    Each page runs in its own directory, as MyST-NB runs it (``execution_in_temp: false``).
    Returns the seconds each page took. Raises ``RuntimeError`` naming every page that failed,
    with its traceback, after the others have run.
    """
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn
    from jupyter_cache.executors.utils import single_nb_execution
    from myst_nb.core.read import read_myst_markdown_notebook

    book = Path(book).resolve()
    cache_path = book / CACHE_DIR
    shutil.rmtree(cache_path, ignore_errors=True)
    cache = get_cache(str(cache_path))

    def run(page: Path):
        page = page.resolve()
        notebook = read_myst_markdown_notebook(
            page.read_text("utf8"), add_source_map=True, path=str(page)
        )
        result = single_nb_execution(
            notebook, cwd=str(page.parent), timeout=timeout, allow_errors=False, meta_override=True
        )
        return page, notebook, result

    seconds, failures = {}, []
    with ThreadPoolExecutor(max(1, workers)) as pool:
        for page, notebook, result in pool.map(run, pages):
            if result.err is not None:
                failures.append(f"{page.name}:\n{result.exc_string}")
                continue
            bundle = CacheBundleIn(notebook, str(page), data={"execution_seconds": result.time})
            cache.cache_notebook_bundle(bundle, check_validity=False, overwrite=True)
            seconds[page.name] = result.time
    if failures:
        raise RuntimeError(
            f"{len(failures)} book page(s) failed to execute:\n\n" + "\n\n".join(failures)
        )
    return seconds
