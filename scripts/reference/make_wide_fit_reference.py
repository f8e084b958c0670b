"""Reference optima of whole fits of the interval-valued and bipolar families' data.

Writes crates/neutrospline/tests/data/wide_fit_reference.json for
crates/neutrospline/tests/integration/wide_fit.rs. For each of the four families of two lanes
(docs/model.md, "Lanes") and two seeds, data that obey the family's rule but are built to make
an unconstrained fit break it: piecewise-constant channel values on the rule's boundary
(lower = upper, a channel at 0 or 1 or -1, T_U + F_U = 1) with jumps between pieces, so that
least squares rings past the boxes and makes lower and upper curves cross. The points have
their own parameters t_k (uniform in [0, 1]) and the fit a fixed clamped cubic knot vector, so
the basis is known here without the crate: N is scipy's B-spline design matrix.

The degree channels' least squares under the rule at every control point,

    minimise  1/2 sum_k sum_c (sum_i N_ki X_ic - V_kc)^2
    subject to X[i, :] in the family's rule for every control point i,

is solved by a conic solver (cvxpy with Clarabel, tolerances 1e-12), an independent method
from the crate's interior-point solver; the optimum's objective is stored. A fit by the crate
must reach it within 1e-9 relative (its objective cannot be below the optimum by more than the
solver's tolerance either). Clarabel stops with status OPTIMAL only when its own primal-dual gap
is below 1e-12 (absolute and relative) and its point is feasible to 1e-12; the script checks the
point against the rule again (to 1e-9) and that the unconstrained fit does break the rule (else
the case would test nothing).

Run from the workspace root:

    python3 -m venv .venv-ref
    .venv-ref/bin/pip install cvxpy clarabel numpy scipy
    .venv-ref/bin/python scripts/reference/make_wide_fit_reference.py
"""

import json
import pathlib

import cvxpy as cp
import numpy as np
from scipy.interpolate import BSpline

OUT = pathlib.Path("crates/neutrospline/tests/data/wide_fit_reference.json")
DEGREE = 3
CONTROL_POINTS = 10
POINTS = 48

# name -> (channel names, interval pairs (lower, upper), sum channels (<= 1), negative from)
FAMILIES = {
    "interval-neutrosophic": (
        ["truth_lower", "truth_upper", "indeterminacy_lower", "indeterminacy_upper",
         "falsity_lower", "falsity_upper"],
        [(0, 1), (2, 3), (4, 5)], [], None),
    "interval-intuitionistic": (
        ["truth_lower", "truth_upper", "falsity_lower", "falsity_upper"],
        [(0, 1), (2, 3)], [1, 3], None),
    "interval-type2": (["truth_lower", "truth_upper"], [(0, 1)], [], None),
    "bipolar-neutrosophic": (
        ["truth", "indeterminacy", "falsity", "negative_truth", "negative_indeterminacy",
         "negative_falsity"],
        [], [], 3),
}


def boxes(k, negative_from):
    low, high = np.zeros(k), np.ones(k)
    if negative_from is not None:
        low[negative_from:], high[negative_from:] = -1.0, 0.0
    return low, high


def piece(spec, rng):
    """One valid channel vector on the rule's boundary."""
    names, pairs, sums, negative_from = spec
    k = len(names)
    low, high = boxes(k, negative_from)
    v = np.array([rng.choice([low[c], high[c], rng.uniform(low[c], high[c])]) for c in range(k)])
    for lower, upper in pairs:
        a, b = sorted((v[lower], v[upper]))
        if rng.uniform() < 0.5:
            a = b  # a collapsed interval: lower = upper
        v[lower], v[upper] = a, b
    if sums:
        # T_U + F_U = 1 exactly (a binary fraction keeps the sum exact), lowers below.
        t = rng.integers(0, 9) / 8.0
        v[sums[0]], v[sums[1]] = t, 1.0 - t
        for lower, upper in pairs:
            v[lower] = min(v[lower], v[upper])
    return v


def data(spec, rng):
    values = []
    while len(values) < POINTS:
        v = piece(spec, rng)
        values.extend([v] * int(rng.integers(3, 9)))
    return np.array(values[:POINTS])


def check_rule(spec, x, tol):
    names, pairs, sums, negative_from = spec
    low, high = boxes(len(names), negative_from)
    assert np.all(x >= low - tol) and np.all(x <= high + tol)
    for lower, upper in pairs:
        assert np.all(x[:, lower] <= x[:, upper] + tol)
    if sums:
        assert np.all(x[:, sums].sum(axis=1) <= 1 + tol)


def main():
    interior = np.linspace(0, 1, CONTROL_POINTS - DEGREE + 1)[1:-1]
    knots = np.concatenate([[0.0] * (DEGREE + 1), interior, [1.0] * (DEGREE + 1)])
    params = np.linspace(0.0, 1.0, POINTS)
    basis = BSpline.design_matrix(params, knots, DEGREE).toarray()
    cases = []
    for family, spec in FAMILIES.items():
        names, pairs, sums, negative_from = spec
        for seed in (1, 2):
            rng = np.random.default_rng(1000 + 17 * seed + len(family))
            values = data(spec, rng)
            check_rule(spec, values, 0.0)
            k = len(names)
            low, high = boxes(k, negative_from)
            free = np.linalg.lstsq(basis, values, rcond=None)[0]
            x = cp.Variable((CONTROL_POINTS, k))
            cons = [x >= np.tile(low, (CONTROL_POINTS, 1)), x <= np.tile(high, (CONTROL_POINTS, 1))]
            cons += [x[:, lower] <= x[:, upper] for lower, upper in pairs]
            if sums:
                cons.append(x[:, sums[0]] + x[:, sums[1]] <= 1)
            objective = 0.5 * cp.sum_squares(basis @ x - values)
            problem = cp.Problem(cp.Minimize(objective), cons)
            problem.solve(solver=cp.CLARABEL, tol_gap_abs=1e-12, tol_gap_rel=1e-12,
                          tol_feas=1e-12, tol_ktratio=1e-10, max_iter=500)
            assert problem.status == cp.OPTIMAL, problem.status
            check_rule(spec, x.value, 1e-9)
            optimum = float(problem.value)
            # The free fit breaks the rule (else the case tests nothing).
            broken = (np.any(free < low - 1e-9) or np.any(free > high + 1e-9)
                      or any(np.any(free[:, l] > free[:, u] + 1e-9) for l, u in pairs))
            assert broken, (family, seed)
            cases.append({
                "family": family,
                "seed": seed,
                "degree": DEGREE,
                "knots": knots.tolist(),
                "parameters": params.tolist(),
                "positions": [[float(t), float(np.sin(3 * t))] for t in params],
                "channels": names,
                "values": values.tolist(),
                "objective": optimum,
                "free_objective": float(0.5 * np.sum((basis @ free - values) ** 2)),
            })
            print(f"{family} seed {seed}: optimum {optimum:.15g}, free "
                  f"{cases[-1]['free_objective']:.6g}")
    OUT.write_text(json.dumps({"cases": cases}, indent=1) + "\n")


if __name__ == "__main__":
    main()
