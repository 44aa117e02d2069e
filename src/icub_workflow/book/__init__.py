"""The book's machinery, kept out of the science package ``icub_affordance``.

- ``findings``: what every page shows (numbers, verdicts, sentences, tables), from the
  pipeline's outputs; run once per build by the rule ``findings``.
- ``text``: the words: numbers formatted for reading and the generated sentences.
- ``run``: the run's provenance and the staging of outputs into ``book/_data``.
- ``notebooks``: the pages executed ahead of Sphinx, two at a time.
"""
