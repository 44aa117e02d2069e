"""The workflow's machinery, beside the science package ``icub_affordance`` (which never imports
it): the config's checks, the plan of the runs, the code each rule runs, the DAG's drawing, the
benchmarks' tables and the book's pages and words. Importable without Snakemake, so the tests
try it directly; the Snakefile, the rules and their scripts import it as an installed package.
"""
