# The paper's claims confirmed on fresh replications (config `confirmation`; the front page):
# the readings' replications at the config's Goal response are the confirmation's runs (one per
# declared cue timing and seed), each scored on the declared measures (rule measured);
# rule `claims` tests each declared claim over them, Holm over the family, with the design's
# power from the declared pilot. The forest plot is a plot rule.


CLAIM_MEASURES = [PLAN.path(row["run"], "eval/measures.json") for row in PLAN.claim_rows]
CLAIM_TRIALS = [PLAN.path(row["run"], "eval/measures.csv") for row in PLAN.claim_rows]
CLAIM_CURVES = [path for row in PLAN.own_reading_rows for path in curve_files(row["run"])]


rule claims:
    """Every declared test of the paper's claims over the confirmation's replications
    (data/claims/summary.csv, contract), each replication's estimates, the design's power and
    the replications' training RMSE."""
    input:
        measured=measured_inputs([*CLAIM_MEASURES, *CLAIM_CURVES]),
        pilot=config["confirmation"]["pilot"],
        code=script_code("claims"),
    output:
        replications="data/claims/replications.csv",
        summary="data/claims/summary.csv",
        power="data/claims/power.csv",
        learning="data/claims/learning.csv",
    params:
        # the files in the folders named above (measured_inputs)
        analyses=CLAIM_MEASURES,
        curves=CLAIM_CURVES,
        rows=PLAN.claim_rows,
        declaration=settings(config["confirmation"]),
        seeds=[row["seed"] for row in PLAN.own_reading_rows],
        networks=config["network"]["networks"],
        phase1_iterations=config["network"]["phase1_iterations"],
    log:
        "data/logs/claims/summary.log",
    benchmark:
        "data/benchmarks/claims/summary.tsv"
    script:
        "../scripts/claims.py"


rule claims_errors:
    """Each condition's all-trial RMSE effects taken apart over the confirmation's replications:
    the part its wrong-grip trials carry (their rate times what a wrong grip costs beyond a
    correct trial) and the part of its correct trials, which add up to the effect, with each
    congruency x size cell's rates, RMSEs and grips' distance (icub_affordance.analysis.error_split)."""
    input:
        trials=measured_inputs(CLAIM_TRIALS),
        code=script_code("claims_errors"),
    output:
        cells="data/claims/error_cells.csv",
        split="data/claims/error_split.csv",
    params:
        trials=CLAIM_TRIALS,  # the files in the folders named above (measured_inputs)
        cues=[row["cue"] for row in PLAN.claim_rows],
    log:
        "data/logs/claims/errors.log",
    benchmark:
        "data/benchmarks/claims/errors.tsv"
    script:
        "../scripts/claims_errors.py"


rule claims_correct:
    """The correct-trial RMSE's effects over every confirmation replication, an exploration
    (family "exploration: correct-trial sensitivity"): a replication with no correct trial in a
    cell is kept, not dropped for the outcome under test. Per replication, mapping and cell the
    networks that carry it (correct_cells.csv); per cue x mode a mixed model of the network x
    object means with a random intercept and effect slopes per replication and a random
    intercept per network, t on replications - 1 df, Holm
    (correct_sensitivity.csv; icub_affordance.analysis.correct_sensitivity)."""
    input:
        trials=measured_inputs(CLAIM_TRIALS),
        code=script_code("claims_correct"),
    output:
        cells="data/claims/correct_cells.csv",
        sensitivity="data/claims/correct_sensitivity.csv",
    params:
        trials=CLAIM_TRIALS,  # the files in the folders named above (measured_inputs)
        cues=[row["cue"] for row in PLAN.claim_rows],
        seeds=[row["seed"] for row in PLAN.claim_rows],
        least=config["confirmation"]["min_replications"],  # the one minimum
    log:
        "data/logs/claims/correct.log",
    benchmark:
        "data/benchmarks/claims/correct.tsv"
    script:
        "../scripts/claims_correct.py"


rule claims_cells:
    """Where the paper's two effects live: per cue timing x test mode, the four cells of object
    size x grip asked over the confirmation's replications (mean, 95% t interval): all-trial
    RMSE, wrong-grip rate, and the wrong trials' way towards the other grip and their RMSE beyond
    a correct trial's (icub_affordance.analysis.cells); each declared RMSE estimate as a share of
    its condition's mean RMSE. Description: the declared tests are `claims`'. And one test
    added after the results (family "exploration, added after results"): size among congruent
    trials alone, per cue x mode (congruent_size.csv)."""
    input:
        trials=measured_inputs(CLAIM_TRIALS),
        declared=rules.claims.output.summary,
        code=script_code("claims_cells"),
    output:
        cells="data/claims/cells.csv",
        replications="data/claims/cell_replications.csv",
        shares="data/claims/effect_shares.csv",
        added="data/claims/congruent_size.csv",
    params:
        trials=CLAIM_TRIALS,  # the files in the folders named above (measured_inputs)
        cues=[row["cue"] for row in PLAN.claim_rows],
        seeds=[row["seed"] for row in PLAN.claim_rows],
        least=config["confirmation"]["min_replications"],
        alpha=config["confirmation"]["alpha"],
    log:
        "data/logs/claims/cells.log",
    benchmark:
        "data/benchmarks/claims/cells.tsv"
    script:
        "../scripts/claims_cells.py"


rule claims_cells_figure:
    """The cells drawn: each condition's four cells with the declared estimates above them, and
    the closed-loop wrong grips by object size (plot only; the book's front page)."""
    input:
        cells=rules.claims_cells.output.cells,
        summary=rules.claims.output.summary,
        code=script_code("claims_cells_figure"),
    output:
        "data/claims/cells.png",
    params:
        cues=config["confirmation"]["cues"],
    log:
        "data/logs/claims/cells_figure.log",
    benchmark:
        "data/benchmarks/claims/cells_figure.tsv"
    script:
        "../scripts/claims_cells_figure.py"


rule claims_figure:
    """The answer at a glance: every declared test's estimate with its 95% interval, the paper's
    direction marked, the verdict as its colour (plot only)."""
    input:
        summary=rules.claims.output.summary,
        code=script_code("claims_figure"),
    output:
        "data/claims/forest.png",
    log:
        "data/logs/claims/figure.log",
    benchmark:
        "data/benchmarks/claims/figure.tsv"
    script:
        "../scripts/claims_figure.py"
