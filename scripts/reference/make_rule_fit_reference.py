"""Reference optima of the degree channels' least squares under every membership family's rule.

Writes crates/neutrospline/tests/data/rule_fit_reference.json for the tests of
crates/neutrospline/src/fit/convex.rs: for each family of `Family::EXAMPLES`, seeded problems

    minimise  f(X) = 1/2 sum_c X[:, c]^T M X[:, c] - sum_{i,c} b[i, c] X[i, c]
    subject to X[i, :] in the family's rule for every control point i,

with M = N^T N + smoothing D^T D the normal matrix of a uniform cubic B-spline least-squares
fit (N the basis at the data parameters, D the second differences; open curves with n - 3
spans, or closed ones with n spans and a cyclic band), b = N^T V for data values V drawn at and
beyond the rule's boundary (a random vector scaled onto the power sum 1, pushed out by up to
20 %, plus noise; interval ends swapped half the time). One case per family is ill-conditioned
(one data point per three spans, smoothing 1e-8).

The optimum is computed by a conic solver (cvxpy with Clarabel), an independent method from
the crate's interior-point solver, then polished: with the constraints whose slack at the
solver's point is below 1e-7 taken as equalities, Newton's method on the full Lagrange system
(dense, float64), the active set corrected (negative multipliers released, violated
constraints added) until the multipliers are >= 0 and every constraint holds: the KKT
conditions, so the optimum (the problem is convex). Where the corrections cycle (a degenerate
optimum), the raw solver's answer is kept and its status says "(unpolished)"; its objective
is then good to the solver's gap (about 1e-10 relative). The file records the KKT residuals. `f*`
is evaluated in 40-digit arithmetic (mpmath) from the stored doubles (band of M, b, X*).

M is stored by its band rows: row i lists M[i, i - d] for d = 0..3 (indices mod n for a closed
curve; 0 outside the matrix for an open one).

Run from the workspace root:

    python3 -m venv .venv-ref
    .venv-ref/bin/pip install cvxpy clarabel numpy mpmath scipy
    .venv-ref/bin/python scripts/reference/make_rule_fit_reference.py

Deterministic up to the solver's last digits (fixed seeds).
"""

import json
import pathlib

import cvxpy as cp
import mpmath as mp
import numpy as np

mp.mp.dps = 40

OUT = pathlib.Path("crates/neutrospline/tests/data/rule_fit_reference.json")
TOLERANCE = 1e-10
WIDTH = 3

# name -> (channel count, negative channels from, interval pairs, sum channels, power)
FAMILIES = {
    "neutrosophic": (3, None, [], [], None),
    "intuitionistic": (2, None, [], [0, 1], 1),
    "fuzzy": (1, None, [], [], None),
    "pythagorean": (2, None, [], [0, 1], 2),
    "fermatean": (2, None, [], [0, 1], 3),
    "q-rung:4": (2, None, [], [0, 1], 4),
    "picture": (3, None, [], [0, 1, 2], 1),
    "spherical": (3, None, [], [0, 1, 2], 2),
    "t-spherical:3": (3, None, [], [0, 1, 2], 3),
    "interval-neutrosophic": (6, None, [(0, 1), (2, 3), (4, 5)], [], None),
    "interval-intuitionistic": (4, None, [(0, 1), (2, 3)], [1, 3], 1),
    "interval-type2": (2, None, [(0, 1)], [], None),
    "bipolar-neutrosophic": (6, 3, [], [], None),
}

# (control points, closed, data points per control point, smoothing)
SHAPES = [
    (5, False, 3.0, 1e-3),
    (14, True, 2.0, 1e-2),
    (30, False, 3.0, 0.0),
    (60, False, 1.0 / 3.0, 1e-8),
]


def boxes(k, negative_from):
    low = np.zeros(k)
    high = np.ones(k)
    if negative_from is not None:
        low[negative_from:] = -1.0
        high[negative_from:] = 0.0
    return low, high


def cubic_basis(u):
    v = 1.0 - u
    return [v**3 / 6, (3 * u**3 - 6 * u**2 + 4) / 6, (-3 * u**3 + 3 * u**2 + 3 * u + 1) / 6, u**3 / 6]


def normal_matrix(n, closed, data, smoothing, rng):
    spans = n if closed else n - 3
    rows = []
    for d in range(data):
        t = (d + 0.5 * rng.uniform()) / data * spans
        span = min(int(np.floor(t)), spans - 1)
        row = np.zeros(n)
        for p, value in enumerate(cubic_basis(t - span)):
            row[(span + p) % n] += value
        rows.append(row)
    basis = np.array(rows)
    m = basis.T @ basis
    for r in range(n if closed else n - 2):
        d = np.zeros(n)
        for p, c in enumerate((1.0, -2.0, 1.0)):
            d[(r + p) % n] += c
        m += smoothing * np.outer(d, d)
    # The band rows, and the matrix rebuilt from them (the problem solved is the stored one).
    band = [[float(m[i, (i - d) % n]) if closed or i - d >= 0 else 0.0 for d in range(WIDTH + 1)] for i in range(n)]
    rebuilt = np.zeros((n, n))
    for i in range(n):
        for d in range(WIDTH + 1):
            if closed or i - d >= 0:
                j = (i - d) % n
                rebuilt[i, j] = band[i][d]
                rebuilt[j, i] = band[i][d]
    return basis, band, rebuilt


def data_values(spec, count, rng):
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    out = []
    for _ in range(count):
        v = rng.uniform(low, high)
        if power is not None:
            s = sum(abs(v[c]) ** power for c in sums)
            v[sums] = v[sums] * (1.0 + 0.2 * rng.uniform()) / s ** (1.0 / power)
        v += 0.3 * (rng.uniform(size=k) - 0.5)
        for l, u in pairs:
            if rng.uniform() < 0.5:
                v[l], v[u] = v[u], v[l]
        out.append(v)
    return np.array(out)


def constraints_of(spec):
    """Per point, every constraint as (value, gradient, hessian diagonal) of g(x) <= 0."""
    k, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    out = []

    def unit(c, a):
        g = np.zeros(k)
        g[c] = a
        return g

    for c in range(k):
        out.append((lambda z, c=c: low[c] - z[c], lambda z, c=c: unit(c, -1.0), lambda z: np.zeros(k)))
        out.append((lambda z, c=c: z[c] - high[c], lambda z, c=c: unit(c, 1.0), lambda z: np.zeros(k)))
    for l, u in pairs:
        g = unit(l, 1.0) + unit(u, -1.0)
        out.append((lambda z, l=l, u=u: z[l] - z[u], lambda z, g=g: g, lambda z: np.zeros(k)))
    if power == 1:
        g = np.zeros(k)
        g[sums] = 1.0
        out.append((lambda z: sum(z[c] for c in sums) - 1.0, lambda z, g=g: g, lambda z: np.zeros(k)))
    elif power is not None:
        p = power

        def grad(z):
            g = np.zeros(k)
            for c in sums:
                g[c] = p * max(z[c], 0.0) ** (p - 1)
            return g

        def hess(z):
            h = np.zeros(k)
            for c in sums:
                h[c] = p * (p - 1) * max(z[c], 0.0) ** (p - 2)
            return h

        out.append((lambda z: sum(max(z[c], 0.0) ** p for c in sums) - 1.0, grad, hess))
    return out


def solve_conic(spec, m, b):
    n, k = b.shape
    k_, negative_from, pairs, sums, power = spec
    low, high = boxes(k, negative_from)
    x = cp.Variable((n, k))
    chol = np.linalg.cholesky(m)
    objective = 0.5 * cp.sum_squares(chol.T @ x) - cp.sum(cp.multiply(b, x))
    cons = [x >= np.tile(low, (n, 1)), x <= np.tile(high, (n, 1))]
    cons += [x[:, l] <= x[:, u] for l, u in pairs]
    if power == 1:
        cons.append(cp.sum(x[:, sums], axis=1) <= 1)
    elif power == 2:
        cons.append(cp.norm(x[:, sums], 2, axis=1) <= 1)
    elif power is not None:
        cons += [cp.pnorm(x[i, sums], power) <= 1 for i in range(n)]
    problem = cp.Problem(cp.Minimize(objective), cons)
    problem.solve(
        solver=cp.CLARABEL,
        tol_gap_abs=TOLERANCE,
        tol_gap_rel=TOLERANCE,
        tol_feas=TOLERANCE,
        tol_ktratio=TOLERANCE,
        max_iter=500,
    )
    assert problem.status in (cp.OPTIMAL, cp.OPTIMAL_INACCURATE), problem.status
    return np.asarray(x.value, dtype=float), problem.status


def polish(spec, m, b, x0):
    """Newton on the KKT system of the active set, with active-set corrections."""
    n, k = b.shape
    cons = constraints_of(spec)
    x = x0.copy()
    active = {(i, j) for i in range(n) for j, c in enumerate(cons) if c[0](x[i]) > -1e-7}
    for _ in range(25):
        act = sorted(active)
        mu = np.zeros(len(act))
        y = x.copy()
        for _ in range(50):
            grad_f = (m @ y) - b
            size = n * k + len(act)
            kkt = np.zeros((size, size))
            rhs = np.zeros(size)
            for c in range(k):
                kkt[c : n * k : k, c : n * k : k] = m
            rhs[: n * k] = grad_f.reshape(-1)
            for a, (i, j) in enumerate(act):
                g = cons[j][1](y[i])
                h = cons[j][2](y[i])
                kkt[i * k : (i + 1) * k, n * k + a] = g
                kkt[n * k + a, i * k : (i + 1) * k] = g
                kkt[np.arange(i * k, (i + 1) * k), np.arange(i * k, (i + 1) * k)] += mu[a] * h
                rhs[i * k : (i + 1) * k] += mu[a] * g
                rhs[n * k + a] = cons[j][0](y[i])
            if np.max(np.abs(rhs), initial=0.0) < 1e-15 * max(1.0, np.max(np.abs(b))):
                break
            try:
                step = np.linalg.lstsq(kkt, -rhs, rcond=None)[0]
            except np.linalg.LinAlgError:
                break
            y = y + step[: n * k].reshape(n, k)
            mu = mu + step[n * k :]
        negative = {act[a] for a in range(len(act)) if mu[a] < -1e-10}
        violated = {(i, j) for i in range(n) for j, c in enumerate(cons) if c[0](y[i]) > 1e-12 and (i, j) not in active}
        if not negative and not violated:
            return y, act, mu
        active = (active - negative) | violated
    return None


def kkt_residuals(spec, m, b, x, act, mu):
    n, k = b.shape
    cons = constraints_of(spec)
    r = (m @ x) - b
    for a, (i, j) in enumerate(act):
        r[i] += mu[a] * cons[j][1](x[i])
    stationarity = float(np.max(np.abs(r)))
    violation = max(0.0, max(c[0](x[i]) for i in range(n) for c in cons))
    complementarity = max([0.0] + [abs(mu[a] * cons[j][0](x[i])) for a, (i, j) in enumerate(act)])
    return stationarity, violation, complementarity


def objective(band, closed, b, x):
    n, k = b.shape
    total = mp.mpf(0)
    for i in range(n):
        for d in range(WIDTH + 1):
            if not closed and i - d < 0:
                continue
            j = (i - d) % n
            weight = mp.mpf(band[i][d]) * (1 if d == 0 else 2)
            for c in range(k):
                total += weight * mp.mpf(float(x[i, c])) * mp.mpf(float(x[j, c])) / 2
    for i in range(n):
        for c in range(k):
            total -= mp.mpf(float(b[i, c])) * mp.mpf(float(x[i, c]))
    return total


def main():
    cases = []
    worst = {"stationarity": 0.0, "violation": 0.0, "complementarity": 0.0, "solver_gap": 0.0}
    for index, (name, spec) in enumerate(FAMILIES.items()):
        for shape_index, (n, closed, per_point, smoothing) in enumerate(SHAPES):
            rng = np.random.default_rng(9100 + 10 * index + shape_index)
            data = max(int(round(per_point * n)), 4)
            basis, band, m = normal_matrix(n, closed, data, smoothing, rng)
            values = data_values(spec, data, rng)
            b = basis.T @ values
            raw, status = solve_conic(spec, m, b)
            polished = polish(spec, m, b, raw)
            if polished is None:
                # The active-set corrections cycled (a degenerate optimum): the raw solver's
                # answer, projected onto the boxes, with its KKT residuals recorded.
                low, high = boxes(spec[0], spec[1])
                x = np.clip(raw, low, high)
                cons = constraints_of(spec)
                act = [(i, j) for i in range(n) for j, c in enumerate(cons) if c[0](x[i]) > -1e-7]
                mu = np.zeros(len(act))
                status = status + " (unpolished)"
            else:
                x, act, mu = polished
            stationarity, violation, complementarity = kkt_residuals(spec, m, b, x, act, mu)
            f_star = objective(band, closed, b, x)
            f_raw = objective(band, closed, b, raw)
            gap = float(abs(f_raw - f_star) / max(1, abs(f_star)))
            worst["stationarity"] = max(worst["stationarity"], stationarity)
            worst["violation"] = max(worst["violation"], violation)
            worst["complementarity"] = max(worst["complementarity"], complementarity)
            worst["solver_gap"] = max(worst["solver_gap"], gap)
            cases.append(
                {
                    "family": name,
                    "control_points": n,
                    "closed": closed,
                    "data_points": data,
                    "smoothing": smoothing,
                    "band": band,
                    "b": [[float(v) for v in row] for row in b],
                    "x": [[float(v) for v in row] for row in x],
                    "objective": float(f_star),
                    "condition": float(np.linalg.cond(m)),
                    "active": len(act),
                    "kkt_stationarity": stationarity,
                    "kkt_violation": violation,
                    "solver_relative_gap": gap,
                    "status": status,
                }
            )
            print(f"{name} n={n} closed={closed}: cond {np.linalg.cond(m):.2e}, {len(act)} active, stationarity {stationarity:.1e}, violation {violation:.1e}, raw solver gap {gap:.1e}")
    OUT.write_text(
        json.dumps(
            {
                "about": "Optima of 1/2 sum_c X_c^T M X_c - b.X under each membership family's rule per "
                "control point, by cvxpy + Clarabel polished by Newton on the KKT system "
                "(scripts/reference/make_rule_fit_reference.py); band[i][d] = M[i, i-d] (mod n when closed)",
                "cvxpy": cp.__version__,
                "worst": worst,
                "cases": cases,
            },
            separators=(",", ":"),
        )
        + "\n"
    )
    print(f"{len(cases)} cases; worst {worst}")


if __name__ == "__main__":
    main()
