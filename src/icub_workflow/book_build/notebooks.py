"""Execute the book's pages before Sphinx reads them: two at a time, in two kernels.

MyST-NB would execute the pages one after another, each in a new Jupyter kernel. Measured on
this book: the pages' own code takes about 7 s in all, starting twelve kernels about 15 s. And
Sphinx cannot read pages in parallel here: ``sphinx_external_toc``, which every Jupyter Book
loads, loads ``sphinx_multitoc_numbering``, which does not declare itself safe for it.

So the rule ``book`` executes the pages itself, and MyST-NB, in ``execute_notebooks: cache``
mode (``book/_config.yml``), finds every page's outputs in the Jupyter cache, matched by the hash
of the page's code, and executes nothing. ``workers`` kernels run side by side, each taking the
next page when done. Before each page its kernel is reset (``%reset -f``: every name the last
page defined is gone, and its figures are closed) and moved to the page's directory, so a page
sees what it would see in a kernel of its own, except that modules already imported load at once.

The cache is emptied first on every build. It is keyed on the pages' code, not on the data they
read, so outputs left from an earlier run would otherwise be shown as this run's.
"""

from __future__ import annotations

import queue
import shutil
import threading
import time
from pathlib import Path

#: Where Jupyter Book 1.x keeps the cache when ``execute.cache`` is not set in ``_config.yml``.
CACHE_DIR = Path("_build") / ".jupyter_cache"

#: Run in a worker's kernel before each page.
RESET = """\
get_ipython().run_line_magic("reset", "-f")
import os as _os, sys as _sys
_os.chdir({cwd!r})
if "matplotlib.pyplot" in _sys.modules:
    _sys.modules["matplotlib.pyplot"].close("all")
del _os, _sys
"""


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

    Returns the seconds each page's code took. Raises ``RuntimeError`` naming every page that
    failed, with its error, after the others have run.
    """
    import nbformat
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn
    from myst_nb.core.read import read_myst_markdown_notebook
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    book = Path(book).resolve()
    cache_path = book / CACHE_DIR
    shutil.rmtree(cache_path, ignore_errors=True)
    cache = get_cache(str(cache_path))
    todo: queue.Queue[Path] = queue.Queue()
    for page in pages:
        todo.put(Path(page).resolve())
    done: list[tuple[Path, object, float | str]] = []  # (page, notebook, seconds or error)
    crashes: list[str] = []
    lock = threading.Lock()

    def worker() -> None:
        try:
            run_pages()
        except Exception as error:  # a kernel that died: report it with the failures below
            with lock:
                crashes.append(f"{type(error).__name__}: {error}")

    def run_pages() -> None:
        client = NotebookClient(
            nbformat.v4.new_notebook(),
            timeout=timeout,
            allow_errors=False,
            kernel_name="python3",
            record_timing=False,  # timings in cell metadata would change the cache key
            # a cell's outputs can reach the client after its reply; nbclient waits 4 s for them
            # by default and then drops the rest silently, which lost the last glued values of
            # a page with hundreds of them on a loaded machine: wait longer, and fail if still
            # missing rather than build a page without them
            iopub_timeout=120,
            raise_on_iopub_timeout=True,
        )
        with client.setup_kernel(cwd=str(book)):
            while True:
                try:
                    page = todo.get_nowait()
                except queue.Empty:
                    return
                notebook = read_myst_markdown_notebook(
                    page.read_text("utf8"), add_source_map=True, path=str(page)
                )
                # the reset runs as a notebook of its own: nbclient stores each executed cell
                # into the client's notebook at its index
                reset = nbformat.v4.new_code_cell(RESET.format(cwd=str(page.parent)))
                client.nb = nbformat.v4.new_notebook(cells=[reset])
                client.execute_cell(reset, 0, store_history=False)
                client.nb = notebook
                client.reset_execution_trackers()
                start = time.perf_counter()
                try:
                    for index, cell in enumerate(notebook.cells):
                        client.execute_cell(cell, index)
                    outcome: float | str = time.perf_counter() - start
                except CellExecutionError as error:
                    outcome = str(error)
                with lock:
                    done.append((page, notebook, outcome))

    threads = [threading.Thread(target=worker) for _ in range(max(1, min(workers, len(pages))))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()

    seconds, failures = {}, []
    for page, notebook, outcome in sorted(done, key=lambda d: d[0]):
        if isinstance(outcome, str):
            failures.append(f"{page.name}:\n{outcome}")
            continue
        bundle = CacheBundleIn(notebook, str(page), data={"execution_seconds": outcome})
        cache.cache_notebook_bundle(bundle, check_validity=False, overwrite=True)
        seconds[page.name] = outcome
    failures += [f"a kernel stopped: {crash}" for crash in crashes]
    missing = sorted({Path(p).resolve().name for p in pages} - {d[0].name for d in done})
    if missing:
        failures.append(f"never executed: {', '.join(missing)}")
    if failures:
        raise RuntimeError(
            f"{len(failures)} book page(s) failed to execute:\n\n" + "\n\n".join(failures)
        )
    return seconds
