# The book (a Jupyter Book 1.x in book/), built from the pipeline's own outputs.
import glob

from icub_workflow.book_build import FULL_SCALE_TABLES, TABLES

BOOK_DATA = {
    "figure1_scene.png": "data/body/figure1_scene.png",
    "figure1_eye.png": "data/body/figure1_eye.png",
    "joint_table.csv": "data/body/joint_table.csv",
    "figure2_maps.png": "data/soms/figure2_maps.png",
    "figure2_architecture.png": "data/figures/figure2_architecture.png",
    "soms.npz": PLAN.path(MAIN, "soms/soms.npz"),
    "figure3.png": "data/vision/figure3.png",
    "visual_maps.npz": "data/vision/visual_maps.npz",
    "filmstrip.png": "data/demos/filmstrip.png",
    "demo_summary.csv": PLAN.path(MAIN, "demos/summary.csv"),
    "demos.npz": PLAN.path(MAIN, "demos/demos.npz"),
    "figure4.png": "data/figures/figure4.png",
    "figure5.png": PLAN.path(MAIN, "figures/figure5.png"),
    "conflict_timecourse.png": PLAN.path(MAIN, "figures/conflict_timecourse.png"),
    "anova.json": PLAN.path(MAIN, "eval/anova.json"),
    "cue_difference.json": "data/eval/cue_difference.json",
    "rulegraph.png": "data/book/rulegraph.png",
    "robot_analysis.json": "data/embodied/analysis.json",
    "robot_success.csv": "data/embodied/success.csv",
    "robot_filmstrip.png": "data/figures/robot_filmstrip.png",
    "ablation_anova.json": PLAN.path(PLAN.ablation, "eval/anova.json"),
    "ablation_figure5.png": PLAN.path(PLAN.ablation, "figures/figure5.png"),
    "divergence.csv": "data/eval/divergence.csv",
    "divergence.json": "data/eval/divergence.json",
    "hidden_explained.csv": "data/eval/hidden_explained.csv",
    "hidden_representations.png": "data/figures/hidden_representations.png",
    "measures.json": PLAN.path(MAIN, "eval/measures.json"),
    "readings_summary.csv": "data/readings/summary.csv",
    "readings_replications.csv": "data/readings/replications.csv",
    "readings_differences.csv": "data/readings/differences.csv",
    "readings_effects.png": "data/readings/effects.png",
    "robot_variants.csv": "data/embodied/variants.csv",
    "robot_effects.json": "data/embodied/effects.json",
    "robot_variants.png": "data/figures/robot_variants.png",
    "robot_tolerance.png": "data/figures/robot_tolerance.png",
    "robot_statistics.json": "data/embodied/statistics.json",
    "robot_confirmation.csv": "data/embodied/confirmation.csv",
    "robot_contact_time.csv": "data/embodied/contact_time.csv",
    "robot_contact_time_cells.csv": "data/embodied/contact_time_cells.csv",
    "robot_contact_time_split.csv": "data/embodied/contact_time_split.csv",
    "robot_grasps.gif": "data/figures/robot_grasps.gif",
    "robot_categorise.gif": "data/figures/robot_categorise.gif",
    "size_summary.csv": "data/size_dose/summary.csv",
    "size_crossed.csv": "data/size_dose/crossed.csv",
    "size_separated.csv": "data/size_dose/separated.csv",
    "size_declared.csv": "data/size_dose/declared.csv",
    "size_power.csv": "data/size_dose/power.csv",
    "size_manipulation.csv": "data/size_dose/manipulation.csv",
    "size_motor.csv": "data/size_dose/motor.csv",
    "size_geometry.csv": "data/size_dose/geometry.csv",
    "size_trajectory_tests.csv": "data/size_dose/trajectory_tests.csv",
    "size_trajectory_separated.csv": "data/size_dose/trajectory_separated.csv",
    "size_dose_response.png": "data/size_dose/dose_response.png",
    "signatures_summary.csv": "data/signatures/summary.csv",
    "signatures_errors.csv": "data/signatures/errors.csv",
    "signatures_extinction_levels.csv": "data/signatures/extinction_levels.csv",
    "signatures.png": "data/signatures/signatures.png",
    "words_summary.csv": "data/words/summary.csv",
    "words_by_form.csv": "data/words/by_form.csv",
    "words_reactivation.csv": "data/words/reactivation.csv",
    "words_error_cells.csv": "data/words/error_cells.csv",
    "words_effects.png": "data/words/effects.png",
    "claims_summary.csv": "data/claims/summary.csv",
    "claims_replications.csv": "data/claims/replications.csv",
    "claims_power.csv": "data/claims/power.csv",
    "claims_learning.csv": "data/claims/learning.csv",
    "claims_forest.png": "data/claims/forest.png",
    "claims_cells.png": "data/claims/cells.png",
    "claims_cells.csv": "data/claims/cells.csv",
    "claims_effect_shares.csv": "data/claims/effect_shares.csv",
    "claims_congruent_size.csv": "data/claims/congruent_size.csv",
    "verdicts.csv": "data/book/verdicts.csv",
    "claims_error_split.csv": "data/claims/error_split.csv",
    "claims_error_cells.csv": "data/claims/error_cells.csv",
    "claims_correct_sensitivity.csv": "data/claims/correct_sensitivity.csv",
    "claims_correct_cells.csv": "data/claims/correct_cells.csv",
    # the full scale's critical path from its job records (benchmarks/critical_path.py --record,
    # tracked: a default build cannot measure it), the reproduce page
    "full_scale_critical_path.json": "benchmarks/full_scale_critical_path.json",
} | {
    f"curves/net{net}.csv": PLAN.path(MAIN, f"train/net{net}/curve.csv") for net in NETWORKS
}
# the Goal map under the other response, if a reading uses it (the readings chapter): its first
# replication's
_GROWS = PLAN.first_reading_run("grows")
if _GROWS is not None and config["soms"]["goal_response"] != "grows":
    BOOK_DATA["readings_grows_soms.npz"] = PLAN.path(PLAN.stage_run(_GROWS, "soms"), "soms/soms.npz")

# the distractor's declared tests (signatures.md), when the build makes them (distractor.run)
if config["distractor"]["run"]:
    BOOK_DATA["distractor_summary.csv"] = "data/distractor/summary.csv"

# With `--config robustness=True` the book also shows the sweep and its cost (reproduce.md);
# without, that page says that this build did not run them.
if PLAN.robustness:
    BOOK_DATA |= {
        "sweep_points.csv": "data/sweep/points.csv",
        "sweep_summary.csv": "data/sweep/summary.csv",
        "sweep_effects.png": "data/sweep/effects.png",
    }


# The book displays, the pipeline computes: the rule `findings` writes every number, verdict,
# sentence and table the pages show (data/book/findings.json, data/book/tables/), from every
# data file the book stages (BOOK_DATA); the pages only glue and display them. It reads no figure.
FINDINGS_READS = [name for name in BOOK_DATA if not name.endswith((".png", ".gif"))]
FINDINGS_TABLES = [*TABLES, *(FULL_SCALE_TABLES if PLAN.robustness else ())]
# the distractor's tables (signatures.md), when the build makes its tests (distractor.run)
FINDINGS_TABLES += ["distractor", "distractor_cells"] if config["distractor"]["run"] else []
FINDINGS_CONFIG = [
    "seed", "object_sizes_m", "vision", "demos", "soms", "network", "robustness", "sweep", "readings",
    "robot", "size_dose", "signatures", "confirmation", "names", "words",
]
BOOK_FINDINGS = {"findings.json": "data/book/findings.json"} | {
    f"tables/{table}.csv": f"data/book/tables/{table}.csv" for table in FINDINGS_TABLES
}


rule verdicts:
    """Every test a sentence of the book may rest on, by name, with its verdict code: what the
    book's `finding` directive checks each sentence's assumed verdicts against
    (icub_workflow.book_build.verdict_table, pinned)."""
    input:
        claims=rules.claims.output.summary,
        correct_sensitivity=rules.claims_correct.output.sensitivity,
        congruent_size=rules.claims_cells.output.added,
        # the chapters' own tests: this run and its other cue timing, the readings, the size
        # study, the signatures, the names and the robot's declared tests
        runs=[BOOK_DATA["anova.json"], BOOK_DATA["ablation_anova.json"]],
        readings=BOOK_DATA["readings_summary.csv"],
        size_study=BOOK_DATA["size_declared.csv"],
        size_metrics=BOOK_DATA["size_trajectory_tests.csv"],
        signatures=BOOK_DATA["signatures_summary.csv"],
        signature_errors=BOOK_DATA["signatures_errors.csv"],
        words=BOOK_DATA["words_summary.csv"],
        contact_time=BOOK_DATA["robot_contact_time.csv"],
        confirmation=BOOK_DATA["robot_confirmation.csv"],
        # the distractor's declared tests, when the build makes them (config distractor.run)
        **({"distractor": BOOK_DATA["distractor_summary.csv"]} if config["distractor"]["run"]
           else {}),
        code=script_code("verdicts"),
    params:
        # the cue timing of each run in `runs`: the config's own, then the other
        cues=[config["network"]["categorisation_cue"], PLAN.config(PLAN.ablation)["network"][
            "categorisation_cue"]],
    output:
        "data/book/verdicts.csv",
    log:
        "data/logs/verdicts.log",
    benchmark:
        "data/benchmarks/verdicts.tsv"
    script:
        "../scripts/verdicts.py"


rule rulegraph:
    """The DAG's rules and their dependencies for this run's config (the sweep's rules with
    robustness=True), canonical: the same bytes on every run, for the book's reproduction page."""
    input:
        "Snakefile",
        sorted(glob.glob("workflow/rules/*.smk")),
        code=script_code("rulegraph"),
    output:
        "data/book/rulegraph.dot",
    params:
        # the graph drawn is this config's (not `runs`: a run adds no rule, and a new run
        # reruns nothing of the main run's)
        config=settings({key: value for key, value in config.items() if key != "runs"}),
    log:
        "data/logs/rulegraph.log",
    benchmark:
        "data/benchmarks/rulegraph.tsv"
    script:
        "../scripts/rulegraph.py"



rule rulegraph_figure:
    """The DAG drawn for the book's reproduction page: the rules top to bottom, each arrow a
    direct need (plot only)."""
    input:
        dot=rules.rulegraph.output[0],
        code=script_code("rulegraph_figure"),
    output:
        "data/book/rulegraph.png",
    log:
        "data/logs/rulegraph_figure.log",
    benchmark:
        "data/benchmarks/rulegraph_figure.tsv"
    script:
        "../scripts/rulegraph_figure.py"


rule other_scale:
    """How much the build at the other scale (robustness flipped) would train and test, for the
    reproduce page: its run plan made here, not at every start of Snakemake (issue 56)."""
    input:
        code=script_code("other_scale"),
    output:
        "data/book/other_scale.json",
    params:
        # the settings the plan's counts depend on (not `runs`: a user's run is counted nowhere)
        config=settings({key: config[key] for key in FINDINGS_CONFIG}),
    log:
        "data/logs/other_scale.log",
    benchmark:
        "data/benchmarks/other_scale.tsv"
    script:
        "../scripts/other_scale.py"


rule findings:
    """Every number, verdict, sentence and table the book shows, from the run's outputs."""
    input:
        # a file in a measured group's folder: the folder (common.smk: measured_inputs)
        data=measured_inputs(BOOK_DATA[name] for name in FINDINGS_READS),
        # what the other scale would train and test (the reproduce page)
        other_scale=rules.other_scale.output[0],
        # the sweep's jobs' benchmark files (none without robustness): its cost
        sweep_jobs=lambda wildcards: list(sweep_job_records()),
        code=script_code("findings"),
    output:
        json=BOOK_FINDINGS["findings.json"],
        tables=[BOOK_FINDINGS[f"tables/{table}.csv"] for table in FINDINGS_TABLES],
    params:
        # the settings the pages quote or the findings depend on (not, say, the figures')
        config=settings({key: config[key] for key in FINDINGS_CONFIG}),
        # the cue timing the ablation trained with (common.smk: PLAN.ablation)
        ablation_cue=PLAN.config(PLAN.ablation)["network"]["categorisation_cue"],
        # what this build trains and tests (the reproduce page; the other scale's: other_scale)
        scale=PLAN.scale(),
        names=FINDINGS_READS,
        data=[BOOK_DATA[name] for name in FINDINGS_READS],  # the files, by name
        sweep_jobs=sweep_job_records,
    resources:
        mem_mb=1000,
    log:
        "data/logs/findings.log",
    benchmark:
        "data/benchmarks/findings.tsv"
    script:
        "../scripts/findings.py"


rule book:
    """Stage the outputs the book shows and the findings, record the run's provenance, build the
    book strictly."""
    input:
        # a file in a measured group's folder: the folder (common.smk: measured_inputs)
        data=measured_inputs(BOOK_DATA.values()),
        findings=list(BOOK_FINDINGS.values()),
        # the build's results manifest and the tracked one (the first page's provenance)
        manifest="data/results.sha256",
        # every other job's record of its wall time and memory (the reproduce page's table); not
        # the user's runs of `runs:`, so that a new one reruns nothing of the main run's
        benchmarks=lambda wildcards: job_records(
            [
                path
                for path in DEFAULT_OUTPUTS
                if path not in rules.book.output
                and not path.startswith(tuple(PLAN.path(run, "") for run in config["runs"]))
            ]
        ),
        tracked_manifest="results.sha256",
        pages=expand("book/{page}.md", page=glob_wildcards("book/{page,[^/]+}.md").page),
        book_config=[
            "book/_config.yml",
            "book/_toc.yml",
            "book/references.bib",
            *sorted(glob.glob("book/_static/*")),
        ],
        code=script_code("book", pages=sorted(glob.glob("book/*.md"))),
    output:
        "book/_build/html/index.html",
    params:
        # the run's provenance; not `runs`, which the book does not show (a new run reruns
        # nothing of the main run's)
        config=settings({key: value for key, value in config.items() if key != "runs"}),
        names=list(BOOK_DATA) + list(BOOK_FINDINGS),
        data=list(BOOK_DATA.values()),  # the files, by name
    threads: 2  # pages execute side by side (src/icub_workflow/book_build/notebooks.py)
    resources:
        mem_mb=2000,
        runtime=15,
    log:
        "data/logs/book.log",
    benchmark:
        "data/benchmarks/book.tsv"
    script:
        "../scripts/book.py"
