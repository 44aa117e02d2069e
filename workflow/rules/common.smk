# Shared helpers of the rules.
import sys

# The interpreter running Snakemake, for the rare shell command that calls Python tools.
PYTHON = sys.executable



def package_code(*modules):
    """The package modules that a job imports, declared as inputs so that editing them reruns it.

    Snakemake does not track what a script imports, so each rule declares it here.
    """
    return [f"src/icub_affordance/{name}.py" for name in ("__init__", *modules)]


def settings(value):
    """A config section as a job parameter, keys sorted at every level.

    Snakemake compares a job's parameters with the last run's by their text, so the same settings
    written in another key order would otherwise count as a change and rerun the job.
    """
    if isinstance(value, dict):
        return {key: settings(value[key]) for key in sorted(value)}
    if isinstance(value, list):
        return [settings(item) for item in value]
    return value
