# A job that does nothing, for benchmarks/where_time_goes.py (issue 71): its benchmark record is
# what every job pays before its own work (the interpreter, Snakemake's script preamble). Not
# part of any target: run by name, `snakemake -c1 benchmark_noop`.


rule benchmark_noop:
    """A job's fixed cost: a script that does nothing, timed like every job."""
    log:
        "data/logs/benchmark_noop.log",
    benchmark:
        "data/benchmarks/benchmark_noop.tsv"
    script:
        "../scripts/benchmark_noop.py"
