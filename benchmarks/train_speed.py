"""Speed of training: the project's trainer vs a plain per-step torch autograd loop, and a run's
networks trained one by one vs together.

Both run the same arithmetic on the same schedule (online back-propagation, one update per time
step). The plain loop is timed on a sample of iterations and scaled to the full run. The
project's trainer is a compiled loop (icub_affordance.learning.kernel): its first call in a process
compiles it or loads it from numba's cache, shown on its own line; `single_s` is the best of
three networks after that (each a full 12,000-iteration training, `train_network`), what every
further network of a job costs. `batch12_s` is the best of three trainings of a run's 12
networks of the paper's size together (`train_networks`: eight, then four, in a vector's lanes,
each network's bits as trained alone), the config's settings and mappings.
`wide_s` is one long, wide network of the robot test (40 hidden units, 768,000 iterations,
the config's other settings) trained by the project's trainer: its CPU seconds; `wide12_s` the
CPU seconds of 12 of them trained together.
Prints a small table; the last line is JSON: {"single_s": ..., "batch12_s": ..., "plain_s": ...,
"ratio": ..., "wide_s": ..., "wide12_s": ...}.

    python benchmarks/train_speed.py            # synthetic materials with the real shapes
    python benchmarks/train_speed.py --no-wide  # leave out the wide networks (about 2 minutes)
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np
import torch
import yaml

from icub_affordance.learning.materials import synthetic_materials
from icub_affordance.learning.network import Weights
from icub_affordance.learning.torch_reference import JordanNet, train_sequence_torch
from icub_affordance.learning.training import (
    TrainConfig,
    context,
    mapping_of,
    network_seed,
    schedule,
    target_grip,
    train_network,
    train_networks,
)

REPO = Path(__file__).resolve().parents[1]


def main(plain_sample: int = 1500, wide: bool = True) -> None:
    torch.set_num_threads(1)
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    m = synthetic_materials()
    network = yaml.safe_load((Path(__file__).parents[1] / "config" / "config.yaml").read_text())[
        "network"
    ]
    config = TrainConfig(**{k: v for k, v in network.items() if k != "networks"})  # its curve_rows

    start = time.perf_counter()
    train_network(m, config, "A", seed=1)
    first = time.perf_counter() - start
    times = []
    for seed in (1, 2, 3):
        start = time.perf_counter()
        train_network(m, config, "A", seed=seed)
        times.append(time.perf_counter() - start)
    fast = min(times)
    mappings = [mapping_of(i, 12) for i in range(12)]
    seeds = [network_seed(1, i) for i in range(12)]
    train_networks(m, config, mappings, seeds)  # compile or cache load
    batch_times = []
    for _ in range(3):
        start = time.perf_counter()
        train_networks(m, config, mappings, seeds)
        batch_times.append(time.perf_counter() - start)
    batch = min(batch_times)

    rng = np.random.default_rng(1)
    weights = Weights.init(config.hidden, config.init_scale, rng)
    tasks, objects, sequences = schedule(config, 4, 4, rng)
    net = JordanNet(weights)
    sgd = torch.optim.SGD(net.parameters(), lr=config.learning_rate)
    start = time.perf_counter()
    for task, obj, seq in list(zip(tasks, objects, sequences, strict=True))[:plain_sample]:
        grip = m.grips.index(target_grip(m.objects[obj], task, "A"))
        train_sequence_torch(net, sgd, context(m, obj, task, "first_step"), m.demos[obj, grip, seq])
    plain = (time.perf_counter() - start) * config.iterations / plain_sample

    print(f"{'trainer':<28}{'one network, 12000 iterations (s)':>36}")
    print(f"{'compiled loop, first call':<28}{first:>36.2f}   (compile or cache load, and train)")
    print(f"{'compiled loop':<28}{fast:>36.3f}   (best of {times_text(times)})")
    print(f"{'plain torch autograd loop':<28}{plain:>36.2f}   (timed on {plain_sample} iterations)")
    print(f"{'ratio':<28}{plain / fast:>36.1f}x")
    print(f"{'12 networks together':<28}{batch:>36.3f}   (best of {times_text(batch_times)}; "
          f"{batch / fast:.2f} x single)")  # fmt: skip
    result = {
        "single_s": round(fast, 3),
        "batch12_s": round(batch, 3),
        "plain_s": round(plain, 3),
        "ratio": round(plain / fast, 1),
    }
    if wide:
        long = TrainConfig(
            **{k: v for k, v in network.items() if k != "networks"}
            | {"hidden": 40, "iterations": 768_000, "phase1_iterations": 384_000}
        )
        start = time.process_time()
        train_network(m, long, "A", seed=1)
        result["wide_s"] = round(time.process_time() - start, 2)
        wide_s = result["wide_s"]
        print(f"{'compiled loop, wide':<28}{wide_s:>36.2f}   (40 hidden, 768,000 its, CPU s)")
        start = time.process_time()
        train_networks(m, long, mappings, seeds)
        result["wide12_s"] = round(time.process_time() - start, 2)
        wide12 = result["wide12_s"]
        print(f"{'12 wide together':<28}{wide12:>36.2f}   (CPU s; {wide12 / wide_s:.2f} x wide)")
    print(json.dumps(result))


def times_text(times: list[float]) -> str:
    return ", ".join(f"{t:.3f}" for t in times)


if __name__ == "__main__":
    import sys

    main(wide="--no-wide" not in sys.argv[1:])
