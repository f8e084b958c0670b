"""Reference Euclidean projections onto the feasible sets of the membership families.

Writes crates/neutrospline/tests/data/family_projections.json for
crates/neutrospline/tests/integration/family_reference.rs: for each family, seeded random
channel vectors (inside, near the boundary, outside, far outside) and their projection onto
the family's rule computed by a conic solver (cvxpy with Clarabel), an independent method
from the core's closed forms and KKT root finding. The conic solver stops at about 1e-8 (its
answers can break the rule by up to 1e-7), short of the 1e-9 the test asks, so each answer is
then polished: for each set of constraints nearly active at the solver's point, the
constraints are solved as equalities by Newton's method on the full Lagrange system in
60-digit arithmetic (mpmath), and the answer kept is the one where the multipliers are >= 0
and every constraint holds (the KKT conditions: the optimum, the problem being convex). The polished projection must agree with the raw
solver's within 1e-4 (the file records the largest gap); `objective` is the polished squared distance, `solver_objective` the raw.

Run from the workspace root:

    python3 -m venv .venv-ref
    .venv-ref/bin/pip install cvxpy clarabel numpy
    .venv-ref/bin/python scripts/reference/make_family_projection_reference.py

Deterministic up to the solver's last digits (fixed seeds).
"""

import json
import pathlib

import cvxpy as cp
import mpmath as mp
import numpy as np

mp.mp.dps = 60

OUT = pathlib.Path("crates/neutrospline/tests/data/family_projections.json")
POINTS_PER_FAMILY = 30
TOLERANCE = 1e-11

# name -> (channel count, negative channels from, interval pairs, sum channels, power)
FAMILIES = {
    "neutrosophic": (3, None, [], [], None),
    "intuitionistic": (2, None, [], [0, 1], 1),
    "fuzzy": (1, None, [], [], None),
    "pythagorean": (2, None, [], [0, 1], 2),
    "fermatean": (2, None, [], [0, 1], 3),
    "q-rung:1": (2, None, [], [0, 1], 1),
    "q-rung:2": (2, None, [], [0, 1], 2),
    "q-rung:4": (2, None, [], [0, 1], 4),
    "q-rung:7": (2, None, [], [0, 1], 7),
    "q-rung:12": (2, None, [], [0, 1], 12),
    "picture": (3, None, [], [0, 1, 2], 1),
    "spherical": (3, None, [], [0, 1, 2], 2),
    "t-spherical:1": (3, None, [], [0, 1, 2], 1),
    "t-spherical:3": (3, None, [], [0, 1, 2], 3),
    "t-spherical:5": (3, None, [], [0, 1, 2], 5),
    "interval-neutrosophic": (6, None, [(0, 1), (2, 3), (4, 5)], [], None),
    "interval-intuitionistic": (4, None, [(0, 1), (2, 3)], [1, 3], 1),
    "interval-type2": (2, None, [(0, 1)], [], None),
    "bipolar-neutrosophic": (6, 3, [], [], None),
}


def boxes(k, negative_from):
    low = np.zeros(k)
    high = np.ones(k)
    if negative_from is not None:
        low[negative_from:] = -1.0
        high[negative_from:] = 0.0
    return low, high


def feasible(x, spec):
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    if np.any(x < low) or np.any(x > high):
        return False
    if any(x[l] > x[u] for l, u in pairs):
        return False
    if power is not None and sum(x[c] ** power for c in sums) > 1.0:
        return False
    return True


def points(spec, rng):
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    out = []
    for _ in range(10):  # around the box
        out.append(rng.uniform(low - 0.5, high + 0.5))
    for _ in range(8):  # far away
        out.append(rng.uniform(low - 3.0, high + 3.0))
    while len(out) < 24:  # inside
        x = rng.uniform(low, high)
        if feasible(x, spec):
            out.append(x)
    for _ in range(6):  # just outside the boundary of the rule
        x = rng.uniform(low, high)
        if power is not None:
            d = rng.uniform(0.05, 1.0, len(sums))
            d /= sum(d**power) ** (1.0 / power)
            x[sums] = d * (1.0 + rng.uniform(1e-4, 1e-2))
        for l, u in pairs:
            x[l], x[u] = x[u] + rng.uniform(1e-4, 1e-2), x[u]
        out.append(x)
    return out


def project(x, spec):
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    z = cp.Variable(k)
    constraints = [z >= low, z <= high]
    constraints += [z[l] <= z[u] for l, u in pairs]
    if power == 1:
        constraints.append(cp.sum(z[sums]) <= 1)
    elif power is not None:
        constraints.append(cp.pnorm(z[sums], power) <= 1)
    problem = cp.Problem(cp.Minimize(cp.sum_squares(z - x)), constraints)
    problem.solve(
        solver=cp.CLARABEL,
        tol_gap_abs=TOLERANCE,
        tol_gap_rel=TOLERANCE,
        tol_feas=TOLERANCE,
        tol_ktratio=TOLERANCE,
        max_iter=500,
    )
    assert problem.status in (cp.OPTIMAL, cp.OPTIMAL_INACCURATE), problem.status
    return np.asarray(z.value, dtype=float), problem.status


def constraints_of(spec):
    """Every constraint as g(z) <= 0: (value, gradient, hessian diagonal) functions."""
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    out = []

    def unit(c, a):
        g = [mp.mpf(0)] * k
        g[c] = mp.mpf(a)
        return g

    for c in range(k):
        out.append((lambda z, c=c: mp.mpf(low[c]) - z[c], lambda z, c=c: unit(c, -1), lambda z: [0] * k))
        out.append((lambda z, c=c: z[c] - mp.mpf(high[c]), lambda z, c=c: unit(c, 1), lambda z: [0] * k))
    for l, u in pairs:
        out.append(
            (
                lambda z, l=l, u=u: z[l] - z[u],
                lambda z, l=l, u=u: [mp.mpf(1) if c == l else mp.mpf(-1) if c == u else mp.mpf(0) for c in range(k)],
                lambda z: [0] * k,
            )
        )
    if power is not None:
        p = power
        out.append(
            (
                lambda z: sum(z[c] ** p for c in sums) - 1,
                lambda z: [p * z[c] ** (p - 1) if c in sums else mp.mpf(0) for c in range(k)],
                lambda z: [p * (p - 1) * z[c] ** (p - 2) if c in sums and p > 1 else mp.mpf(0) for c in range(k)],
            )
        )
    return out


def polish(x, z0, spec):
    """The exact projection near the solver's z0: Newton on the KKT system of an active set."""
    k = len(x)
    cons = constraints_of(spec)
    xm = [mp.mpf(float(v)) for v in x]
    zf = [mp.mpf(float(v)) for v in z0]

    def independent(rows, j):
        grads = [[float(v) for v in cons[i][1](zf)] for i in rows + [j]]
        return np.linalg.matrix_rank(np.array(grads), tol=1e-9) == len(rows) + 1

    near = [j for j, c in enumerate(cons) if c[0](zf) > -1e-5]
    found = []
    for mask in range(1 << len(near)):
        active = [j for b, j in enumerate(near) if mask >> b & 1]
        if not all(independent(active[:a], active[a]) for a in range(len(active))):
            continue
        z = list(zf)
        mu = [mp.mpf(0)] * len(active)
        converged = False
        for _ in range(60):
            grads = [cons[j][1](z) for j in active]
            hess = [cons[j][2](z) for j in active]
            n = k + len(active)
            J = mp.zeros(n, n)
            F = mp.zeros(n, 1)
            for c in range(k):
                F[c] = z[c] - xm[c] + sum(m * g[c] for m, g in zip(mu, grads))
                J[c, c] = 1 + sum(m * h[c] for m, h in zip(mu, hess))
                for a, g in enumerate(grads):
                    J[c, k + a] = g[c]
                    J[k + a, c] = g[c]
            for a, j in enumerate(active):
                F[k + a] = cons[j][0](z)
            if mp.norm(F) < mp.mpf(10) ** -50:
                converged = True
                break
            try:
                step = mp.lu_solve(J, -F)
            except ZeroDivisionError:
                break
            z = [z[c] + step[c] for c in range(k)]
            mu = [mu[a] + step[k + a] for a in range(len(active))]
        if not converged or any(m < 0 for m in mu):
            continue
        if any(g(z) > mp.mpf(10) ** -50 for g, _, _ in cons):
            continue
        found.append((sum((a - b) ** 2 for a, b in zip(z, xm)), z))
    if found:
        return min(found, key=lambda f: f[0])[1]
    raise RuntimeError(f"no KKT point near the solver's answer for {x}")


def main():
    cases = []
    worst_violation = 0.0
    worst_gap = 0.0
    for index, (name, spec) in enumerate(FAMILIES.items()):
        rng = np.random.default_rng(2700 + index)
        for x in points(spec, rng):
            raw, status = project(x, spec)
            exact = polish(x, raw, spec)
            z = np.array([float(v) for v in exact])
            worst_gap = max(worst_gap, float(np.max(np.abs(z - raw))))
            assert worst_gap < 1e-4, (x, z, raw)
            objective = float(sum((e - mp.mpf(float(v))) ** 2 for e, v in zip(exact, x)))
            k, negative_from, pairs, sums, power = spec
            low, high = boxes(k, negative_from)
            violation = max(
                [0.0]
                + list(low - raw)
                + list(raw - high)
                + [raw[l] - raw[u] for l, u in pairs]
                + ([sum(max(raw[c], 0.0) ** power for c in sums) - 1.0] if power else [])
            )
            worst_violation = max(worst_violation, violation)
            cases.append(
                {
                    "family": name,
                    "point": [float(v) for v in x],
                    "projection": [float(v) for v in z],
                    "objective": objective,
                    "solver_objective": float(np.sum((raw - x) ** 2)),
                    "inside": bool(feasible(x, spec)),
                    "status": status,
                }
            )
    OUT.write_text(
        json.dumps(
            {
                "about": "Euclidean projections onto the membership families' rules, "
                "by cvxpy + Clarabel (scripts/reference/make_family_projection_reference.py); "
                "objective = squared distance from point to projection",
                "cvxpy": cp.__version__,
                "worst_solver_violation": worst_violation,
                "worst_solver_gap": worst_gap,
                "cases": cases,
            },
            indent=1,
        )
        + "\n"
    )
    print(f"{len(cases)} cases; raw solver: worst violation {worst_violation:.3g}, worst distance to the polished projection {worst_gap:.3g}")


if __name__ == "__main__":
    main()
