"""How the book is built and measured, apart from what it says (``icub_workflow.book``).

- ``run``: the run's provenance and the staging of outputs into ``book/_data``.
- ``notebooks``: the pages executed ahead of Sphinx, two at a time.
- ``reading``: the built pages' article text, words and "In brief" boxes, as a reader meets them.
"""

#: The tables the rule ``findings`` writes, data/book/tables/{name}.csv (declared from here; the
#: findings are ``icub_workflow.book``'s); at full scale also the sweep's.
TABLES = (
    "scorecard",
    "claims",
    "readings_summary",
    "readings_differences",
    "robot_variants",
    "robot_effects",
    "robot_pairs",
    "robot_confirmation",
    "robot_cells",
    "size_tests",
    "size_metrics",
    "signatures",
    "words",
)
FULL_SCALE_TABLES = ("sweep",)
