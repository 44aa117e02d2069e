"""The mixed model (MODEL.md section 8), recomputed independently on a small synthetic data set
with a known effect: balanced, so REML's variance components are the ANOVA estimators and the
fixed effects a generalised least-squares fit that NumPy can do by hand."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats as sps

from icub_affordance.stats import MIXED_TERMS, coded, mixed_model, network_object_means

OBJECTS = {  # object: (size, category)
    "big_ball": ("large", "natural"),
    "small_ball": ("small", "natural"),
    "big_cube": ("large", "artefact"),
    "small_cube": ("small", "artefact"),
}
NATURAL = {"large": "power", "small": "precision"}
MAPPING = {
    "A": {"natural": "power", "artefact": "precision"},
    "B": {"natural": "precision", "artefact": "power"},
}
TRUTH = {"congruency": 0.03, "size": 0.0}


def synthetic(seed: int = 3, networks: int = 12, sequences: int = 5) -> pd.DataFrame:
    """Categorisation trials of ``networks`` networks: RMSE = 0.1 + network intercept +
    0.03 if incongruent + trial noise (no size effect)."""
    rng = np.random.default_rng(seed)
    rows = []
    for net in range(networks):
        mapping = "A" if net < networks // 2 else "B"
        intercept = rng.normal(0, 0.02)
        for obj, (size, category) in OBJECTS.items():
            congruent = MAPPING[mapping][category] == NATURAL[size]
            cell = rng.normal(0, 0.01)  # the network x object deviation
            for seq in range(sequences):
                rmse = 0.1 + intercept + (0 if congruent else TRUTH["congruency"]) + cell
                rows.append(
                    {
                        "network": net,
                        "mapping": mapping,
                        "object": obj,
                        "size": size,
                        "congruency": "congruent" if congruent else "incongruent",
                        "sequence": seq,
                        "rmse": rmse + rng.normal(0, 0.002),
                    }
                )
    return pd.DataFrame(rows)


def by_hand(df: pd.DataFrame) -> dict[str, tuple[float, float]]:
    """Estimate and standard error of every term, by NumPy: the variance components from the
    balanced design's mean squares, then generalised least squares."""
    data = coded(network_object_means(df)).sort_values(["network", "object"])
    y = data["rmse"].to_numpy()
    c, s, m = (data[f].to_numpy() for f in ("congruency", "size", "mapping"))
    columns = {
        "Intercept": np.ones_like(y),
        "congruency": c,
        "size": s,
        "mapping": m,
        "congruency:size": c * s,
        "congruency:mapping": c * m,
        "size:mapping": s * m,
        "congruency:size:mapping": c * s * m,
    }
    X = np.column_stack(list(columns.values()))
    nets = data["network"].to_numpy()
    groups = np.unique(nets)
    per = len(y) // len(groups)
    # within networks: residuals of a fit with one intercept per network and the within terms
    dummies = (nets[:, None] == groups[None, :]).astype(float)
    within = np.column_stack([dummies, c, s, c * s, c * m, s * m, c * s * m])
    resid = y - within @ np.linalg.lstsq(within, y, rcond=None)[0]
    sigma2_e = resid @ resid / (len(y) - np.linalg.matrix_rank(within))
    # between networks: the network means regressed on the mapping
    means = np.array([y[nets == g].mean() for g in groups])
    maps = np.array([m[nets == g][0] for g in groups])
    B = np.column_stack([np.ones_like(maps), maps])
    r = means - B @ np.linalg.lstsq(B, means, rcond=None)[0]
    sigma2_u = max(r @ r / (len(groups) - 2) - sigma2_e / per, 0.0)
    V = sigma2_e * np.eye(len(y)) + sigma2_u * (nets[:, None] == nets[None, :])
    Vi = np.linalg.inv(V)
    cov = np.linalg.inv(X.T @ Vi @ X)
    beta = cov @ X.T @ Vi @ y
    return {
        name: (float(beta[k]), float(np.sqrt(cov[k, k])))
        for k, name in enumerate(columns)
        if name != "Intercept"
    }


def test_mixed_model_matches_a_computation_by_hand():
    df = synthetic()
    fit, hand = mixed_model(df), by_hand(df)
    assert set(fit) == set(MIXED_TERMS)
    z = sps.norm.ppf(0.975)
    for term in MIXED_TERMS:
        estimate, se = hand[term]
        assert fit[term]["estimate"] == pytest.approx(estimate, abs=1e-9)
        assert fit[term]["ci_low"] == pytest.approx(estimate - z * se, rel=2e-3)
        assert fit[term]["ci_high"] == pytest.approx(estimate + z * se, rel=2e-3)
        assert fit[term]["p"] == pytest.approx(
            2 * sps.norm.sf(abs(estimate / se)), rel=5e-2, abs=1e-12
        )


def test_mixed_model_finds_the_known_effect():
    fit = mixed_model(synthetic())
    cong, size = fit["congruency"], fit["size"]
    assert cong["ci_low"] < TRUTH["congruency"] < cong["ci_high"] and cong["p"] < 0.001
    assert size["ci_low"] < TRUTH["size"] < size["ci_high"]


def test_mixed_model_uses_network_means_not_trials():
    """Five identical copies of every trial (closed loop) give the same fit as one."""
    df = synthetic(sequences=1)
    copies = pd.concat([df.assign(sequence=k) for k in range(5)])
    a, b = mixed_model(df), mixed_model(copies)
    for term in MIXED_TERMS:
        assert a[term]["ci_low"] == pytest.approx(b[term]["ci_low"], rel=1e-6)


def test_mixed_model_of_a_constant_measure_is_zero_without_p():
    """Every trial committing at the same step: no difference, no variance, no p."""
    fit = mixed_model(synthetic().assign(rmse=1.0))
    for term in MIXED_TERMS:
        assert fit[term]["estimate"] == fit[term]["ci_low"] == fit[term]["ci_high"] == 0.0
        assert np.isnan(fit[term]["p"])
