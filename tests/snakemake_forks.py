"""Snakemake started by fork from a process that has imported it once (the tests' Snakemake runs).

A Snakemake start spends most of its CPU importing Snakemake and its plugins (pandas among them)
before it reads the Snakefile; the tests start it about a hundred times. This server imports it
once, then forks a fresh child for each run: the child is `python -m snakemake ARGS` in its own
directory and environment, with its own output files, and nothing of one run reaches the next
(the project's own modules are imported by each child, from the Snakefile, as before).

Protocol, one JSON line each way per run: {"args", "argv0", "cwd", "env", "out", "err"} in;
the child's {"pid"} and then its {"returncode"} out."""

from __future__ import annotations

import json
import os
import sys


def _child(request: dict) -> None:
    os.setpgid(0, 0)  # its own process group: a run that hangs is killed with its jobs
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    for fd, name in ((1, "out"), (2, "err")):
        file = os.open(request[name], os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(file, fd)
        os.close(file)
    stdin = os.open(os.devnull, os.O_RDONLY)
    os.dup2(stdin, 0)
    os.close(stdin)
    sys.argv = [request["argv0"], *request["args"]]
    code = 1
    try:
        from snakemake.cli import main
        from snakemake.workflow import Workflow

        Workflow._rundir = os.getcwd()  # read once, at import: the run's own directory
        main(request["args"])
    except SystemExit as exit:
        code = exit.code if isinstance(exit.code, int) else (0 if exit.code is None else 1)
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except Exception:
                pass
    os._exit(code)


def serve() -> None:
    import snakemake.cli

    snakemake.cli.get_argument_parser()  # collects every plugin, as each start would
    protocol = sys.stdout
    for line in sys.stdin:
        request = json.loads(line)
        protocol.flush()
        pid = os.fork()
        if pid == 0:
            _child(request)
        protocol.write(json.dumps({"pid": pid}) + "\n")
        protocol.flush()
        _, status = os.waitpid(pid, 0)
        protocol.write(json.dumps({"returncode": os.waitstatus_to_exitcode(status)}) + "\n")
        protocol.flush()


if __name__ == "__main__":
    serve()
