"""Stage the outputs, record provenance, and build the Jupyter Book strictly (warnings fail)."""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

from icub_affordance.files import atomic_path, redirect_log, write_text
from icub_workflow.benchmark_tables import (
    benchmark_table,
    executor,
    job_times,
    read_benchmarks,
    timeline,
)
from icub_workflow.book_build import pinned
from icub_workflow.book_build.notebooks import execute_pages, is_notebook
from icub_workflow.book_build.run import provenance, results_provenance, stage

with redirect_log(snakemake.log[0]):
    book = Path("book")
    data_dir = book / "_data"
    files = [*snakemake.params.data, *snakemake.input.findings]
    stage(dict(zip(snakemake.params.names, files, strict=True)), data_dir)
    run = provenance(dict(snakemake.params.config), Path.cwd())
    run["results"] = results_provenance(snakemake.input.manifest, snakemake.input.tracked_manifest)
    write_text(data_dir / "run.json", json.dumps(run, indent=2) + "\n")
    # a sentence whose test's verdict moved fails the book (strict) or is marked (config
    # findings_check; auto: strict for the tracked results, whose sentences the book's are)
    mode = dict(snakemake.params.config)["findings_check"]
    tracked = run["results"]["digest"] == run["results"]["tracked_digest"]
    check = {"mode": mode, "strict": mode == "strict" or (mode == "auto" and tracked)}
    write_text(data_dir / pinned.CHECK.name, json.dumps(check) + "\n")
    # how long each rule took, from the benchmark file of every job of the build (declared:
    # common.smk, job_records), the reproduce page's table
    records = Path("data/benchmarks"), list(snakemake.input.benchmarks)
    with atomic_path(data_dir / "benchmarks.csv") as tmp:
        benchmark_table(read_benchmarks(*records)).to_csv(tmp)
    # and when they ran: for a build from scratch, its wall time up to this job
    line = timeline(job_times(*records)) | executor(dict(os.environ))
    write_text(data_dir / "timeline.json", json.dumps(line, indent=2) + "\n")
    # a clean build every time: no pages left from an earlier table of contents, and the same
    # HTML as a first build (Sphinx links its CSS differently when the last build's is there)
    shutil.rmtree(book / "_build", ignore_errors=True)
    # the pages' code runs here, `threads` pages at a time; Sphinx then reads their outputs
    # from the Jupyter cache (execute_notebooks: cache) instead of running them one by one
    seconds = execute_pages(
        book, [page for page in sorted(book.glob("*.md")) if is_notebook(page)], snakemake.threads
    )
    print(f"executed {len(seconds)} pages, {sum(seconds.values()):.1f} s of kernel time")
    # the book's Sphinx extension (book/_config.yml), imported here so that its code is this
    # rule's input: a change to how findings are checked rebuilds the book
    assert pinned.__name__ in (book / "_config.yml").read_text()
    jupyter_book = str(Path(sys.executable).parent / "jupyter-book")
    # --all: every page, every time (the build above is clean anyway). Sphinx would rebuild
    # only the pages whose source changed, but what changes is the data in book/_data.
    result = subprocess.run(
        [jupyter_book, "build", "--all", "-W", "-n", "--keep-going", str(book)],
        capture_output=True,
        text=True,
    )
    print(result.stdout[-20000:])
    print(result.stderr[-20000:])
    if result.returncode != 0:
        raise RuntimeError(f"the book did not build cleanly (see {snakemake.log[0]})")
