"""Failing inputs from the peers' bug trackers (nearest point / projection and curve-curve
intersection), one test per thread, named after it. The inputs are transcribed from the
threads; the expected answers are not the threads': each is computed by the independent
reference of reference.py (mpmath at 40 digits) and pinned here to 1e-9, and our command's
answer is judged against it (reference.judge_nearest / judge_intersections).

paper.js writes a cubic as `Curve(point1, handle1, handle2, point2)` with handles relative to
their points: the control points are point1, point1 + handle1, point2 + handle2, point2.
"""

import mpmath as mp

from harness import intersect, query
from reference import Curve, judge_intersections, judge_nearest, nearest_curve


def cubic(*pts):
    return Curve("bezier", len(pts) - 1, [tuple(float(c) for c in p) for p in pts])


def paperjs(p1, h1, h2, p2):
    return cubic(p1, (p1[0] + h1[0], p1[1] + h1[1]), (p2[0] + h2[0], p2[1] + h2[1]), p2)


def check_nearest(cli, curve, expected):
    """expected: [(query, t, distance)] from the reference; ours must agree (judge_nearest)."""
    points = [list(q) for q, _, _ in expected]
    rows = query(cli, curve, points)
    problems = []
    for (q, t, d), r in zip(expected, rows):
        best = nearest_curve(curve, q)[0]
        assert abs(best.distance - d) <= 1e-9 * max(1.0, d), f"reference moved: {q}: {mp.nstr(best.distance, 17)} != {d}"
        assert abs(best.t - t) <= 1e-9, f"reference moved: {q}: t = {mp.nstr(best.t, 17)} != {t}"
        verdict = judge_nearest(curve, q, r["t"], r["distance"], [r["x"], r["y"]])
        if verdict:
            problems.append(f"query {q}: {verdict}")
    assert not problems, "\n".join(problems)


def check_intersections(cli, a, b, expected):
    """expected: [(s, t, kind)] of the reference; ours must give each once and nothing else."""
    rows = intersect(cli, a, b)
    verdict, ref = judge_intersections(a, b, rows)
    got = [(float(c.s), float(c.t), c.kind) for c in ref]
    assert len(got) == len(expected) and all(
        abs(s - es) <= 1e-9 and abs(t - et) <= 1e-9 and k == ek for (s, t, k), (es, et, ek) in zip(got, expected)
    ), f"reference moved: {got} != {expected}"
    assert not verdict, f"{verdict}\nours: {rows}"


# ---- nearest point -------------------------------------------------------------------------


def test_kurbo_issue_446_cubic_nearest_stationary_ends(cli):
    """linebender/kurbo#446: CubicBez::nearest far off on a cubic with (nearly) stationary ends;
    the point is within 3e-12 of the curve at t = 0.5075..."""
    curve = cubic((461.0, 123.0), (460.99999999999994, 123.00000000000004), (111.0, 319.0), (111.0, 319.0))
    check_nearest(cli, curve, [((282.0379003395483, 223.21877580985594), 0.507547429735421, 2.59833836264226e-12)])


def test_flo_curves_issue_25_distance_to_pixel_grid(cli):
    """Logicalshift/flo_curves#25: distance_to / nearest_t unexpected on (259, 322), (272, 329),
    (297, 341), (350, 397) over a pixel grid; a 5 x 4 grid of the picture's points."""
    curve = cubic((259, 322), (272, 329), (297, 341), (350, 397))
    expected = [
        ((250.0, 320.0), 0.0, 9.21954445729289),
        ((250.0, 400.0), 0.544533496519239, 70.7648877674683),
        ((280.0, 340.0), 0.416702116614597, 4.65722793968533),
        ((300.0, 340.0), 0.565499632684386, 7.30653222711677),
        ((330.0, 370.0), 0.840503179586297, 4.73287754407462),
        ((360.0, 400.0), 1.0, 10.4403065089106),
    ]
    check_nearest(cli, curve, expected)


def test_bosl_issue_50_bezier_segment_closest_point(cli):
    """revarbat/BOSL#50: bezier_segment_closest_point() returned u = 0.765625 (distance 2.414)
    for the origin; the nearest point is at t = 0.18387..., distance 1.91359..."""
    curve = cubic((3.98743, 5.29979), (-8.21663, -2.76544), (-5.4184, -5.00586), (8.26971, -0.0435725))
    check_nearest(cli, curve, [((0.0, 0.0), 0.183873743034961, 1.9135911928298)])


def test_bosl2_issue_1545_bezpath_closest_point(cli):
    """BelfrySCAD/BOSL2#1545: the closest point of a two-segment cubic path to its own joint
    (0, 90) was far off. The path as a cubic B-spline with a triple knot at 1/2."""
    curve = Curve(
        "bspline",
        3,
        [(-78.2772, 0.0), (-78.2772, 45.0), (-78.2772, 90.0), (0.0, 90.0), (78.2772, 90.0), (78.2772, 45.0), (78.2772, 0.0)],
        None,
        [0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1],
    )
    # from (0, 0) both ends are 78.2772 away (a tie): the smaller parameter, t = 0
    check_nearest(cli, curve, [((0.0, 90.0), 0.5, 0.0), ((0.0, 0.0), 0.0, 78.2772)])


def test_cubicbezier_issue_1_no_closest_point(cli):
    """kuribas/cubicbezier#1: `closest` found no parameter for (319, 171); the nearest point is
    the end, t = 1, at 30.825..."""
    curve = cubic((52.44, 122.36), (0, 471.95), (506.91, 192.28), (349.59, 174.8))
    check_nearest(cli, curve, [((319.0, 171.0), 1.0, 30.8251212487477)])


# ---- intersections -------------------------------------------------------------------------


def test_paperjs_issue_565_tangential_intersections(cli):
    """paperjs/paper.js#565: getIntersections() failed on curves meeting at a shallow angle;
    with the thread's decimals they cross twice."""
    a = paperjs((421.75945, 416.40481), (-181.49299, -224.94946), (44.52004, -194.13319), (397.47615, 331.34712))
    b = paperjs((360.09446, 350.97254), (-58.58867, -218.45806), (-109.55091, -220.99561), (527.83582, 416.79948))
    check_intersections(cli, a, b, [(0.467245307084118, 0.341356022850741, "crossing"), (0.716046156109958, 0.541748058275672, "crossing")])


def test_paperjs_issue_568_intersection_found_twice(cli):
    """paperjs/paper.js#568: three intersections reported where there are two."""
    a = paperjs((509.05465863179415, 440.1211663847789), (233.6728838738054, -245.8216403145343), (-270.755685120821, 53.14275110140443), (514.079892472364, 481.95262297522277))
    b = paperjs((542.1666181180626, 451.06309361290187), (179.91238399408758, 148.68241581134498), (193.42650789767504, -47.97609066590667), (423.66228222381324, 386.3876062911004))
    check_intersections(cli, a, b, [(0.0702418877707078, 0.752706681792416, "crossing"), (0.480774143306967, 0.84850471622749, "crossing")])


def test_paperjs_issue_571_shared_end_point(cli):
    """paperjs/paper.js#571: curves sharing an end point, A(1) = B(0) exactly, and crossing once
    more; the shared end is a contact."""
    a = paperjs((171.0, 359.0), (205.3908899553486, -14.994581100305595), (5.767644819815757, 28.49094950835297), (420.1235851920127, 275.8351912321666))
    b = paperjs((420.1235851920127, 275.8351912321666), (-10.77224553077383, -53.21262197949682), (-259.2129470250785, -258.56165821345775), (465.0, 467.0))
    check_intersections(cli, a, b, [(0.411588134823875, 0.773210427548527, "crossing"), (1.0, 0.0, "end")])


def test_bezier_issue_10_false_negative_at_tangency(cli):
    """dhermes/bezier#10: curves 38 and 39 reported without intersection; they touch at
    s = 1/3, t = 1/2."""
    a = Curve("bezier", 2, [(0.5, 0.125), (1.25, -0.25), (2.0, 0.5)])
    b = Curve("bezier", 2, [(0.5, -0.125), (1.0, 0.125), (1.5, -0.125)])
    check_intersections(cli, a, b, [(1 / 3, 0.5, "tangent")])


def test_bezierjs_issue_201_degenerate_control_point(cli):
    """Pomax/bezierjs#201: no intersection found when a control point coincides with the start."""
    a = cubic((50, 25), (50, 25), (122, 185), (111, 185))
    b = cubic((9, 111), (8, 99), (136, 78), (142, 58))
    check_intersections(cli, a, b, [(0.421794888589634, 0.520025889006662, "crossing")])


def test_bezierjs_issue_205_vertical_line(cli):
    """Pomax/bezierjs#205: a quadratic and a vertical segment, no intersection found."""
    a = Curve("bezier", 2, [(623.0342104670767, 427.30684253642517), (359.8595533490565, 519.6488274901164), (96.68489623103626, 427.3068425364252)])
    b = Curve("bezier", 1, [(608.0342104670767, 443.30684253642517), (608.0342104670767, 422.30684253642517)])
    check_intersections(cli, a, b, [(0.0284981847497445, 0.51842059768164, "crossing")])


def test_bezier_hx_issue_2_four_intersections(cli):
    """profelis/bezier.hx#2: two quadratics meeting in four points, none found."""
    a = Curve("bezier", 2, [(400.0, 50.0), (5.0, 70.0), (350.0, 100.0)])
    b = Curve("bezier", 2, [(250.0, 110.0), (260.0, -20.0), (270.0, 120.0)])
    check_intersections(
        cli,
        a,
        b,
        [
            (0.216193760005074, 0.689716928809445, "crossing"),
            (0.234765114546332, 0.266020358714129, "crossing"),
            (0.824522071858873, 0.0853340999251088, "crossing"),
            (0.859654188724857, 0.886856540479245, "crossing"),
        ],
    )


def test_lyon_pr_422_clipped_to_a_point_no_intersection(cli):
    """nical/lyon#422: Bézier clipping reduced a curve to a point at a loop's end; the curves do
    not meet."""
    a = cubic((-1.0, 0.0), (0.0, 0.0), (-1.0, -0.1), (-1.0, -0.1))
    b = cubic((0.0, 0.0), (5.0, -5.0), (-5.0, -5.0), (0.0, 0.0))
    check_intersections(cli, a, b, [])


def test_lyon_pr_427_end_near_interior_no_intersection(cli):
    """nical/lyon#427: an end point of one curve near the other's interior gave a false
    intersection far from both; the curves do not meet."""
    a = cubic((76868.875, 47679.28), (65326.86, 856.21094), (-85621.64, -80823.375), (-56517.53, 28062.227))
    b = cubic((-67977.72, 77673.53), (-59829.57, -41917.87), (57.4375, 52822.97), (51075.86, 85772.84))
    check_intersections(cli, a, b, [])
