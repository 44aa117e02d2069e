# Beyond the paper: the cue ablation. The main run's 12 networks retrained with the same seeds but
# the other categorisation cue timing (first_step <-> all_steps), tested and analysed the same
# way, so that the book shows which reading of the paper's cue produces the effect (MODEL.md 7).

ABLATION_CUE = {"first_step": "all_steps", "all_steps": "first_step"}[
    config["network"]["categorisation_cue"]
]


def ablation_network(wildcards=None):
    return settings(config["network"] | {"categorisation_cue": ABLATION_CUE})


use rule train as ablation_train with:
    output:
        curve="data/ablation/train/net{net}/curve.csv",
        weights="data/ablation/train/net{net}/weights.npz",
    params:
        network=ablation_network(),
        seed=settings(config["seed"]),
    priority: 0  # after the main networks: less waits on these
    log:
        "data/logs/ablation/train/net{net}.log",
    benchmark:
        "data/benchmarks/ablation/train/net{net}.tsv"


use rule evaluate as ablation_evaluate with:
    input:
        maps=rules.visual_maps.output.maps,
        soms=rules.soms.output[0],
        demos=rules.demos.output.demos,
        weights=expand("data/ablation/train/net{net}/weights.npz", net=NETWORKS),
        code=package_code("spec", "jordan", "som", "train", "evaluate", "io"),
    output:
        trials="data/ablation/eval/trials.csv",
        hidden="data/ablation/eval/hidden.npz",
    params:
        network=ablation_network(),
    log:
        "data/logs/ablation/evaluate.log",
    benchmark:
        "data/benchmarks/ablation/evaluate.tsv"


use rule stats as ablation_stats with:
    input:
        trials=rules.ablation_evaluate.output.trials,
        code=package_code("stats", "io"),
    output:
        json="data/ablation/eval/anova.json",
        table="data/ablation/eval/anova_table.md",
    log:
        "data/logs/ablation/stats.log",
    benchmark:
        "data/benchmarks/ablation/stats.tsv"


use rule figure5 as ablation_figure5 with:
    input:
        trials=rules.ablation_evaluate.output.trials,
        code=package_code("figures", "stats", "io"),
    output:
        figure5="data/figures/ablation_figure5.png",
        timecourse="data/figures/ablation_conflict_timecourse.png",
    log:
        "data/logs/ablation/figure5.log",
    benchmark:
        "data/benchmarks/ablation/figure5.tsv"
