"""The DAG of data/book/rulegraph.dot, drawn for the book's reproduction page (plot only)."""

from pathlib import Path

from icub_affordance.files import redirect_log
from icub_workflow.rulegraph_figure import draw_rulegraph

with redirect_log(snakemake.log[0]):
    draw_rulegraph(Path(snakemake.input.dot).read_text(), snakemake.output[0])
