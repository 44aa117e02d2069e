# Shared helpers of the rules.
import sys

# The interpreter running Snakemake, for the rare shell command that calls Python tools.
PYTHON = sys.executable



def package_code(*modules):
    """The package modules that a job imports, declared as inputs so that editing them reruns it.

    Snakemake does not track what a script imports, so each rule declares it here.
    """
    return [f"src/icub_affordance/{name}.py" for name in ("__init__", *modules)]
