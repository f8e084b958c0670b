"""Type reduction in Python (docs/model.md, "Type reduction"): `centroid_interval` against a
brute force over every embedded set at the vertices of the membership box, closed forms, and
its refusals."""

import itertools
import random

import numpy as np
import pytest

import neutrospline as ns


def brute_force(x, lower, upper):
    """The smallest and largest centroid over all 2^N vertex choices w_k in {L_k, U_k}."""
    centroids = []
    for choice in itertools.product((0, 1), repeat=len(x)):
        w = [upper[k] if c else lower[k] for k, c in enumerate(choice)]
        mass = sum(w)
        if mass > 0:
            centroids.append(sum(xk * wk for xk, wk in zip(x, w)) / mass)
    return min(centroids), max(centroids)


def test_the_interval_equals_the_brute_force_over_vertices():
    rng = random.Random(20261204)
    for _ in range(300):
        n = rng.randint(1, 10)
        # Unsorted points with ties, memberships with zeros and ones.
        x = [rng.choice([rng.uniform(-5, 5), float(rng.randint(-2, 2))]) for _ in range(n)]
        pairs = [
            sorted(rng.choice([0.0, 1.0, rng.random()]) for _ in range(2)) for _ in range(n)
        ]
        lower = [p[0] for p in pairs]
        upper = [p[1] for p in pairs]
        if max(upper) == 0:
            upper[0] = 0.5
        c_l, c_r, midpoint = ns.centroid_interval(x, lower, upper)
        want_l, want_r = brute_force(x, lower, upper)
        assert c_l == pytest.approx(want_l, abs=1e-12)
        assert c_r == pytest.approx(want_r, abs=1e-12)
        assert midpoint == pytest.approx((want_l + want_r) / 2, abs=1e-12)


def test_closed_forms():
    # L = U: the type-1 centroid, the same at both ends.
    x, w = [3.0, -1.0, 0.5], [0.2, 0.9, 0.4]
    type1 = (3.0 * 0.2 - 0.9 + 0.5 * 0.4) / 1.5
    c_l, c_r, midpoint = ns.centroid_interval(x, w, w)
    assert c_l == pytest.approx(type1, abs=1e-15)
    assert c_r == pytest.approx(type1, abs=1e-15)
    # Constant [0.5, 1] on -2..2: c_l = (-2 - 1 + 0.5 (0 + 1 + 2)) / (2 + 1.5) = -3/7, and
    # the interval is symmetric, its midpoint 0.
    c_l, c_r, midpoint = ns.centroid_interval(
        np.array([2.0, 1.0, 0.0, -1.0, -2.0]), np.full(5, 0.5), np.ones(5)
    )
    assert c_l == pytest.approx(-3 / 7, abs=1e-15)
    assert c_r == pytest.approx(3 / 7, abs=1e-15)
    assert midpoint == 0.0


def test_refusals_say_why():
    with pytest.raises(ns.ModelError, match=r"every upper membership is 0"):
        ns.centroid_interval([0.0, 1.0], [0.0, 0.0], [0.0, 0.0])
    with pytest.raises(
        ns.ModelError,
        match=r"^at point 1 the lower membership 0\.7 exceeds the upper membership 0\.6 "
        r"\(lower <= upper\)$",
    ):
        ns.centroid_interval([0.0, 1.0], [0.0, 0.7], [0.5, 0.6])
    with pytest.raises(ns.ModelError, match=r"differ in number \(1, 2 and 1\)"):
        ns.centroid_interval([0.0], [0.0, 0.1], [0.5])
    with pytest.raises(ns.ModelError, match=r"^lower membership 0 is -0\.1; memberships"):
        ns.centroid_interval([0.0], [-0.1], [0.5])
