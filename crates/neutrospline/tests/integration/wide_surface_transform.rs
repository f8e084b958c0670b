//! Degree reduction and knot removal of surfaces of the families of two lanes
//! (interval-neutrosophic, interval-intuitionistic, interval-type2, bipolar-neutrosophic;
//! docs/model.md, "Lanes"): an elevated surface reduces back to its control values, a knot
//! inserted comes off again, a knot stays when one line of one lane cannot lose it, and a
//! reduction that breaks `lower <= upper` when each lane is solved alone keeps it when the
//! lanes are solved together (the joint minimum worked out by hand).

use neutrospline::{
    ControlPoint, Degrees, Direction, Family, KnotError, KnotVector, Surface, SurfaceKind,
};

const WIDE: [Family; 4] = [
    Family::IntervalNeutrosophic,
    Family::IntervalIntuitionistic,
    Family::IntervalType2,
    Family::BipolarNeutrosophic,
];

/// Channel values of control point `k` that obey `family`'s rule strictly (lower < upper,
/// T_U + F_U < 1, negatives in [-1, 0]), varied with `k`.
fn channels(family: Family, k: usize) -> Vec<f64> {
    let x = |c: usize| ((k * 7 + c * 3) % 11) as f64 / 25.0; // in [0, 0.4]
    match family {
        Family::IntervalNeutrosophic => {
            (0..3).flat_map(|d| [x(d), x(d) + x(d + 5) + 0.1]).collect()
        }
        Family::IntervalIntuitionistic => vec![x(0), x(0) + 0.05, x(1), x(1) + x(2) + 0.01],
        Family::IntervalType2 => vec![x(0), x(0) + x(1) + 0.2],
        Family::BipolarNeutrosophic => vec![x(0), x(1), x(2), -x(3), -x(4) - 0.5, -x(5)],
        other => unreachable!("{other} has one lane"),
    }
}

/// The two lane surfaces of a `rows x cols` net with positions `position(k)`, channel values
/// `values(k)` (split into the lanes by the family), of `kind` over `knots` (weights
/// `weight(k)` for NURBS).
fn lanes(
    family: Family,
    kind: SurfaceKind,
    (rows, cols): (usize, usize),
    knots: Option<(KnotVector, KnotVector)>,
    position: impl Fn(usize) -> [f64; 3],
    values: impl Fn(usize) -> Vec<f64>,
) -> [Surface; 2] {
    let mut nets = [Vec::new(), Vec::new()];
    for k in 0..rows * cols {
        let (split, count) = family.split(&values(k)).unwrap();
        assert_eq!(count, 2);
        for (net, degrees) in nets.iter_mut().zip(split) {
            net.push(ControlPoint::new(position(k), degrees));
        }
    }
    nets.map(|net| match kind {
        SurfaceKind::Bezier => Surface::bezier(rows, cols, net).unwrap(),
        SurfaceKind::BSpline => {
            let (ku, kv) = knots.clone().unwrap();
            Surface::bspline(rows, cols, net, ku, kv).unwrap()
        }
        SurfaceKind::Nurbs => {
            let (ku, kv) = knots.clone().unwrap();
            let w = (0..rows * cols)
                .map(|k| 0.5 + (k % 5) as f64 * 0.4)
                .collect();
            Surface::nurbs(rows, cols, net, w, ku, kv).unwrap()
        }
    })
}

/// The channels of every control point of two lanes (joined by the family), checked
/// against the family's rule exactly.
fn control_channels(family: Family, lanes: &[Surface; 2]) -> Vec<Vec<f64>> {
    let (a, b) = (lanes[0].control_points(), lanes[1].control_points());
    a.iter()
        .zip(&b)
        .enumerate()
        .map(|(k, (p, q))| {
            let values = family.join(&[p.degrees, q.degrees]).to_vec();
            family
                .check(&values)
                .unwrap_or_else(|e| panic!("{family} control point {k} {values:?}: {e}"));
            values
        })
        .collect()
}

fn positions(s: &Surface) -> Vec<[f64; 3]> {
    s.control_points().iter().map(|p| p.position).collect()
}

fn close(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-12, "{what}: {a:?} vs {b:?}");
    }
}

/// The same control values, positions, weights and knots to 1e-12.
fn same_lanes(family: Family, got: &[Surface; 2], want: &[Surface; 2], what: &str) {
    assert_eq!(
        (got[0].rows(), got[0].cols()),
        (want[0].rows(), want[0].cols()),
        "{what}"
    );
    for (g, w) in got.iter().zip(want) {
        close(
            g.knots_u().knots(),
            w.knots_u().knots(),
            &format!("{what} knots_u"),
        );
        close(
            g.knots_v().knots(),
            w.knots_v().knots(),
            &format!("{what} knots_v"),
        );
        close(
            g.weights().unwrap_or(&[]),
            w.weights().unwrap_or(&[]),
            &format!("{what} weights"),
        );
        for (p, q) in positions(g).iter().zip(positions(w)) {
            close(p, &q, &format!("{what} positions"));
        }
    }
    for (k, (x, y)) in control_channels(family, got)
        .iter()
        .zip(control_channels(family, want))
        .enumerate()
    {
        close(x, &y, &format!("{what} channels of point {k}"));
    }
}

/// A 5 x 4 B-spline or NURBS net of degrees (2, 3) with an interior knot in u (0.4) and one
/// in v (0.6).
fn spline_lanes(family: Family, kind: SurfaceKind) -> [Surface; 2] {
    let ku = KnotVector::new(vec![0.0, 0.0, 0.0, 0.4, 0.7, 1.0, 1.0, 1.0], 2, 5).unwrap();
    let kv = KnotVector::new(vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], 3, 4).unwrap();
    let position = |k: usize| {
        let (i, j) = ((k / 4) as f64, (k % 4) as f64);
        [i, j, (i * 0.7 + j * 1.3).sin()]
    };
    lanes(family, kind, (5, 4), Some((ku, kv)), position, |k| {
        channels(family, k)
    })
}

/// Every wide family, B-spline, NURBS and Bézier, each direction: the lanes elevated once
/// (exact, lane by lane) and reduced once come back to the original control channels,
/// positions, weights and knots (interior knots included) to 1e-12, with a deviation found
/// below 1e-12.
#[test]
fn an_elevated_wide_surface_reduces_back_to_itself() {
    for family in WIDE {
        let mut cases: Vec<(&str, [Surface; 2])> = vec![
            ("bspline", spline_lanes(family, SurfaceKind::BSpline)),
            ("nurbs", spline_lanes(family, SurfaceKind::Nurbs)),
        ];
        cases.push((
            "bezier",
            lanes(
                family,
                SurfaceKind::Bezier,
                (3, 4),
                None,
                |k| [(k / 4) as f64, (k % 4) as f64, (k % 3) as f64 * 0.5],
                |k| channels(family, k + 3),
            ),
        ));
        for (kind, original) in &cases {
            for direction in [Direction::U, Direction::V] {
                let up = original.clone().map(|lane| lane.elevate(direction));
                let back = Surface::reduced_lanes([&up[0], &up[1]], direction, 1, 1e-9, family)
                    .unwrap_or_else(|e| panic!("{family} {kind} {direction}: {e}"));
                let what = format!("{family} {kind} {direction}");
                assert!(back.error < 1e-12, "{what}: deviation {:e}", back.error);
                assert_eq!(back.curve[0].kind(), original[0].kind(), "{what}");
                same_lanes(family, &back.curve, original, &what);
            }
        }
    }
}

/// Every wide family, B-spline and NURBS: the knot 0.55 inserted twice in v and the knot 0.2
/// once in u (lane by lane) come off again, twice and once, giving back the original net to
/// 1e-12; an original knot of these nets (u = 0.4, the data not made for it) stays within
/// 1e-9; a value that is not a knot is refused with the knots listed.
#[test]
fn a_knot_inserted_into_a_wide_surface_comes_off_again() {
    for family in WIDE {
        for kind in [SurfaceKind::BSpline, SurfaceKind::Nurbs] {
            let original = spline_lanes(family, kind);
            let what = format!("{family} {kind:?}");
            for (direction, u, times) in [(Direction::V, 0.55, 2), (Direction::U, 0.2, 1)] {
                let more = original
                    .clone()
                    .map(|lane| lane.insert_knot(direction, u, times).unwrap());
                let back =
                    Surface::remove_knot_lanes([&more[0], &more[1]], direction, u, 5, 1e-9, family)
                        .unwrap();
                assert_eq!(back.removed, times, "{what} {direction}");
                assert!(back.error < 1e-12, "{what}: deviation {:e}", back.error);
                same_lanes(
                    family,
                    &back.curve,
                    &original,
                    &format!("{what} {direction}"),
                );
            }
            let kept = Surface::remove_knot_lanes(
                [&original[0], &original[1]],
                Direction::U,
                0.4,
                1,
                1e-9,
                family,
            )
            .unwrap();
            assert_eq!(kept.removed, 0, "{what}");
            assert_eq!(kept.curve, original, "{what}");
            let refused = Surface::remove_knot_lanes(
                [&original[0], &original[1]],
                Direction::V,
                0.5,
                1,
                1e-9,
                family,
            );
            assert_eq!(
                refused,
                Err(KnotError::NotAnInteriorKnot {
                    value: 0.5,
                    knots: "none".to_owned()
                })
            );
        }
    }
}

/// The acceptance rule of the joint removal: an inserted knot whose second lane is then
/// changed at one control point of one line (the channel raised by 0.05, so no spline without
/// the knot holds that line) stays on every line of both lanes, though the first lane alone
/// loses it (one-lane `Surface::remove_knot`).
#[test]
fn a_knot_stays_when_one_line_of_one_lane_needs_it() {
    let family = Family::IntervalType2;
    let original = spline_lanes(family, SurfaceKind::BSpline);
    let more = original
        .clone()
        .map(|lane| lane.insert_knot(Direction::V, 0.55, 1).unwrap());
    // The control point of row 2 nearest the new knot in v (column 2 of 5).
    let mut points = more[1].control_points();
    let k = 2 * more[1].cols() + 2;
    let upper = points[k].degrees.truth() + 0.05;
    points[k].degrees = Degrees::new(upper, 0.0, 0.0).unwrap();
    let changed = Surface::bspline(
        more[1].rows(),
        more[1].cols(),
        points,
        more[1].knots_u().clone(),
        more[1].knots_v().clone(),
    )
    .unwrap();
    let alone = more[0].remove_knot(Direction::V, 0.55, 1, 1e-9).unwrap();
    assert_eq!(alone.removed, 1);
    let joint =
        Surface::remove_knot_lanes([&more[0], &changed], Direction::V, 0.55, 1, 1e-9, family)
            .unwrap();
    assert_eq!(joint.removed, 0);
    assert_eq!(joint.curve, [more[0].clone(), changed]);
}

/// The adversarial reduction: an interval-type2 Bézier net of 2 x 4 points, cubic in v, whose
/// positions are an elevated quadratic. Row 0 has lower memberships 0, 0.5, 0.5, 0 and upper
/// 0.4, 0.5, 0.5, 0; row 1 has lower = upper = 0.2, 0.3, 0.3, 0.2. Reducing to degree 2 in v
/// keeps the ends of every row and puts the middle point at the L2 nearest
/// `(-P0 + 3 P1 + 3 P2 - P3) / 4` (the normal equation of the one free point with the Gram
/// values of the Bernstein bases): row 0 lower 3/4 and upper 0.65 — each lane alone (one-lane
/// `Surface::reduce_degree`) breaks lower <= upper. Solved jointly, row 0's objective is
/// `a ((x_L - 0.75)^2 + (x_U - 0.65)^2)` with `x_L <= x_U`, minimal at the mean 0.7 for both;
/// row 1 is unconstrained there, 0.35 for both. Every control point passes the rule.
#[test]
fn a_wide_surface_reduction_solves_the_lanes_jointly_on_every_line() {
    let family = Family::IntervalType2;
    let y = [0.0, 2.0 / 3.0, 4.0 / 3.0, 2.0];
    let z = [0.0, 4.0 / 3.0, 4.0 / 3.0, 0.0];
    let rows = [
        ([0.0, 0.5, 0.5, 0.0], [0.4, 0.5, 0.5, 0.0]),
        ([0.2, 0.3, 0.3, 0.2], [0.2, 0.3, 0.3, 0.2]),
    ];
    let original = lanes(
        family,
        SurfaceKind::Bezier,
        (2, 4),
        None,
        |k| [(k / 4) as f64, y[k % 4], z[k % 4]],
        |k| vec![rows[k / 4].0[k % 4], rows[k / 4].1[k % 4]],
    );
    let alone: Vec<f64> = original
        .iter()
        .map(|lane| {
            let r = lane
                .reduce_degree(Direction::V, 1.0, Family::Neutrosophic)
                .unwrap();
            r.curve.control_point(0, 1).degrees.truth()
        })
        .collect();
    close(&alone, &[0.75, 0.65], "each lane alone");
    let r =
        Surface::reduced_lanes([&original[0], &original[1]], Direction::V, 1, 0.2, family).unwrap();
    assert_eq!(r.curve[0].degree_v(), 2);
    assert_eq!(r.curve[0].kind(), SurfaceKind::Bezier);
    let channels = control_channels(family, &r.curve);
    let expect = [
        [0.0, 0.4],
        [0.7, 0.7],
        [0.0, 0.0],
        [0.2, 0.2],
        [0.35, 0.35],
        [0.2, 0.2],
    ];
    for (k, (c, e)) in channels.iter().zip(expect).enumerate() {
        close(c, &e, &format!("control point {k}"));
        assert!(c[0] <= c[1], "lower <= upper exactly at {k}: {c:?}");
    }
    for (k, p) in positions(&r.curve[0]).iter().enumerate() {
        let (i, j) = ((k / 3) as f64, k % 3);
        close(
            p,
            &[i, [0.0, 1.0, 2.0][j], [0.0, 2.0, 0.0][j]],
            "the quadratic",
        );
    }
    // Each lane is a valid surface of the engine, and the deviation is the lanes' larger.
    assert!(r.error > 0.0 && r.error < 0.2, "{}", r.error);
}
