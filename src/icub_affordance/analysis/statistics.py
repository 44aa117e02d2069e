"""The statistics toolkit: the tests and adjustments any analysis uses (a t-term from an estimate
and its standard error, a regression of per-network values on the mapping, the equivalence test,
Holm's adjustment, the exact McNemar test, a mean's t-interval, partial eta squared and an ANOVA
effect's row), knowing nothing of the trials' columns.

Apart from the analysis of the trials (``trial_effects``) and the sweep's tables (``sweep``), so
that a module which only needs a test (the size study, the replications) does not depend on the
trial analysis, and editing the trial analysis does not rerun what only tests.
"""

from __future__ import annotations

import numpy as np


def partial_eta_squared(f: float, df1: float, df2: float) -> float:
    return float(f * df1 / (f * df1 + df2))


def effect_row(f, df1, df2, p) -> dict[str, float]:
    f, df1, df2 = float(f), float(df1), float(df2)
    return {
        "F": f,
        "df1": df1,
        "df2": df2,
        "p": float(p),
        "eta_p2": partial_eta_squared(f, df1, df2),
    }


def t_term(estimate: float, se: float, df: float, level: float = 0.95) -> dict[str, float]:
    """An estimate with its standard error and degrees of freedom: t, the t-interval and the
    two-sided p. A zero standard error (every network the same) gives p = 0 for a non-zero
    estimate and an undefined p for a zero one."""
    from scipy import stats as sps

    estimate, se, df = float(estimate), float(se), float(df)
    if not (df > 0 and np.isfinite(se)):
        nan = float("nan")
        return {"estimate": estimate, "se": nan, "t": nan, "df": df, "ci_low": nan,
                "ci_high": nan, "p": nan}  # fmt: skip
    if se == 0:
        p = float("nan") if estimate == 0 else 0.0
        t = float("nan") if estimate == 0 else float(np.sign(estimate) * np.inf)
        return {"estimate": estimate, "se": 0.0, "t": t, "df": df, "ci_low": estimate,
                "ci_high": estimate, "p": p}  # fmt: skip
    half = float(sps.t.ppf(0.5 + level / 2, df)) * se
    t = estimate / se
    return {
        "estimate": estimate,
        "se": se,
        "t": t,
        "df": df,
        "ci_low": estimate - half,
        "ci_high": estimate + half,
        "p": float(2 * sps.t.sf(abs(t), df)),
    }


def group_regression(values: np.ndarray, mapping: np.ndarray) -> dict[str, dict[str, float]]:
    """Per-network values regressed on the mapping (coded -0.5 / +0.5): ``mean``, the average of
    the two mappings' means, and ``mapping``, their difference B - A, each with its t-test on the
    residual degrees of freedom (networks - 2). With one mapping only, the mean and networks - 1."""
    values, mapping = np.asarray(values, dtype=float), np.asarray(mapping, dtype=float)
    n = len(values)
    both = len(set(mapping.tolist())) == 2
    X = np.column_stack([np.ones(n), mapping]) if both else np.ones((n, 1))
    df = n - X.shape[1]
    beta, *_ = np.linalg.lstsq(X, values, rcond=None)
    tol = 1e-14 * max(1.0, float(np.abs(values).max()))
    beta = np.where(np.abs(beta) < tol, 0.0, beta)  # rounding is no effect
    resid = values - X @ beta
    s2 = float(resid @ resid / df) if df > 0 else float("nan")
    cov = s2 * np.linalg.inv(X.T @ X)
    # a residual of rounding size is no variance: every network gave the same value
    if df > 0 and np.allclose(resid, 0, atol=tol):
        cov = np.zeros_like(cov)
    out = {"mean": t_term(beta[0], np.sqrt(cov[0, 0]), df)}
    nan = float("nan")
    out["mapping"] = (
        t_term(beta[1], np.sqrt(cov[1, 1]), df)
        if both
        else {
            "estimate": nan,
            "se": nan,
            "t": nan,
            "df": nan,
            "ci_low": nan,
            "ci_high": nan,
            "p": nan,
        }  # fmt: skip
    )
    return out


def mcnemar_exact(only_a: int, only_b: int) -> float:
    """The exact McNemar test of paired binary outcomes from its discordant pairs (``only_a``
    pairs with the outcome under A alone, ``only_b`` under B alone): the two-sided binomial test
    of ``only_a`` of the discordant pairs at 1/2; 1 without discordant pairs."""
    from scipy.stats import binomtest

    n = only_a + only_b
    return float(binomtest(only_a, n, 0.5).pvalue) if n else 1.0


def equivalence(term: dict[str, float], margin: float) -> dict[str, float]:
    """Two one-sided t-tests (TOST) of ``|estimate| < margin`` from a term's estimate, standard
    error and df: ``p`` is the larger one-sided p; below alpha, the difference is within the
    margin (a "no difference" claim). ``margin`` must be declared before the result is read. A
    zero standard error has no test: NaN p."""
    from scipy import stats as sps

    est, se, df = term["estimate"], term["se"], term["df"]
    if not (margin > 0):
        raise ValueError(f"an equivalence margin must be positive, got {margin}")
    if not (np.isfinite(se) and se > 0 and df > 0):  # se 0: no spread, no test (not p = 0)
        return {"margin": margin, "p_lower": float("nan"), "p_upper": float("nan"),
                "p": float("nan")}  # fmt: skip
    p_lower = float(sps.t.sf((est + margin) / se, df))  # H0: estimate <= -margin
    p_upper = float(sps.t.cdf((est - margin) / se, df))  # H0: estimate >= +margin
    return {"margin": margin, "p_lower": p_lower, "p_upper": p_upper, "p": max(p_lower, p_upper)}


def holm(pvalues) -> np.ndarray:
    """Holm's step-down adjustment over one family of tests; undefined (NaN) p stay NaN and are
    not counted in the family. The arithmetic of statsmodels' ``multipletests(method="holm")``,
    to the bit (tests/test_contrasts.py compares them), without its ``gc.collect()`` at every
    call, which costs a quarter of a second in a process that has loaded torch and pandas."""
    p = np.asarray(pvalues, dtype=float)
    out = np.full_like(p, np.nan)
    ok = np.isfinite(p)
    if ok.any():
        family = p[ok]
        order = np.argsort(family)
        ranked = np.take(family, order) * np.arange(len(family), 0, -1)
        adjusted = np.minimum(np.maximum.accumulate(ranked), 1.0)
        unsorted = np.empty_like(adjusted)
        unsorted[order] = adjusted
        out[ok] = unsorted
    return out


def mean_ci(values: np.ndarray, level: float = 0.95) -> tuple[float, float, float]:
    """Mean and its t-interval."""
    from scipy import stats as sps

    values = np.asarray(values, dtype=float)
    mean = float(values.mean())
    if len(values) < 2:
        return mean, float("nan"), float("nan")
    half = float(
        sps.t.ppf(0.5 + level / 2, len(values) - 1) * values.std(ddof=1) / np.sqrt(len(values))
    )
    return mean, mean - half, mean + half
