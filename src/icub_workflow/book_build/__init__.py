"""How the book is built and measured, apart from what it says (``icub_workflow.book``).

- ``run``: the run's provenance and the staging of outputs into ``book/_data``.
- ``notebooks``: the pages executed ahead of Sphinx, two at a time.
- ``reading``: the built pages' article text, words and "In brief" boxes, as a reader meets them.
"""
