//! Geometry along curves (`CurveGeometry`): arc length, curvature, tangent and normal, and the
//! arc-length averages of the degrees, against closed forms (circle arcs of the NURBS circle
//! of `examples/nurbs-circle.toml`, straight lines, constant degrees) and against mpmath
//! quadrature (`scripts/reference/make_arc_length_reference.py`, whose printed constants are
//! copied below verbatim); and property tests over every kind (a curve's length is the sum
//! of its halves' after `split`, and at least its chord).

use core::f64::consts::{FRAC_1_SQRT_2, PI};

use neutrospline::strategies;
use neutrospline::{
    Affine, AnyCurve, Bezier, ControlPoint, ControlPolygon, CurveGeometry, Degrees, Derivative,
    Evaluate, GeometryError, KnotVector, Nurbs, Split, DEFAULT_ACCURACY,
};
use proptest::prelude::*;

// Printed by scripts/reference/make_arc_length_reference.py (mpmath.quad at 50 digits on the
// exact power-basis polynomials; correctly rounded doubles).
const EXAMPLE1_LENGTH: f64 = 8.786730707839524;
const EXAMPLE1_HALF_LENGTH: f64 = 4.066732096133451;
const EXAMPLE1_AVERAGE_TRUTH: f64 = 0.4866571461815867;
const EXAMPLE1_AVERAGE_INDETERMINACY: f64 = 0.30413934315750824;
const EXAMPLE1_AVERAGE_FALSITY: f64 = 0.20920351066090506;
const EXAMPLE1_AVERAGE_SCORE: f64 = 0.6577714307877245;
const SPATIAL_LENGTH: f64 = 5.613689688224749;
const SPATIAL_LENGTH_FROM_0_3_TO_0_8: f64 = 2.4263711172719207;

fn relative_error(value: f64, want: f64) -> f64 {
    (value - want).abs() / want.abs()
}

fn degrees(t: f64, i: f64, f: f64) -> Degrees {
    Degrees::new(t, i, f).unwrap()
}

/// The curve of `examples/nurbs-circle.toml`: the unit circle (radius 1, centre the origin) as
/// a 9-point quadratic NURBS with double knots at the quarters, with the file's degrees.
fn unit_circle() -> Nurbs<2> {
    let w = FRAC_1_SQRT_2;
    let rows = [
        ([1.0, 0.0], 1.0, (0.9, 0.1, 0.0)),
        ([1.0, 1.0], w, (0.8, 0.2, 0.1)),
        ([0.0, 1.0], 1.0, (0.6, 0.3, 0.2)),
        ([-1.0, 1.0], w, (0.3, 0.4, 0.5)),
        ([-1.0, 0.0], 1.0, (0.1, 0.5, 0.8)),
        ([-1.0, -1.0], w, (0.3, 0.4, 0.5)),
        ([0.0, -1.0], 1.0, (0.6, 0.3, 0.2)),
        ([1.0, -1.0], w, (0.8, 0.2, 0.1)),
        ([1.0, 0.0], 1.0, (0.9, 0.1, 0.0)),
    ];
    let points = rows
        .iter()
        .map(|&(p, _, (t, i, f))| ControlPoint::new(p, degrees(t, i, f)))
        .collect();
    let weights = rows.iter().map(|r| r.1).collect();
    let knots = KnotVector::new(
        vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ],
        2,
        9,
    )
    .unwrap();
    Nurbs::new(points, weights, knots).unwrap()
}

/// The unit circle scaled by `radius` about the origin.
fn circle(radius: f64) -> AnyCurve<2> {
    let scale = Affine::new([[radius, 0.0], [0.0, radius]], [0.0, 0.0]);
    AnyCurve::Nurbs(unit_circle()).transform(&scale).unwrap()
}

#[test]
fn the_example_circle_has_radius_one() {
    let curve = unit_circle();
    for k in 0..=64 {
        let p = curve.evaluate(f64::from(k) / 64.0).unwrap().position;
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15, "{p:?}");
    }
}

#[test]
fn circle_length_quarters_and_curvature() {
    for radius in [1.0, 2.5, 1e-3, 1e3] {
        let curve = circle(radius);
        let length = curve.arc_length(0.0..1.0, DEFAULT_ACCURACY).unwrap();
        assert!(
            relative_error(length, 2.0 * PI * radius) < 1e-12,
            "{radius}: {length}"
        );
        assert!(relative_error(curve.length().unwrap(), 2.0 * PI * radius) < 1e-12);
        for quarter in 0..4 {
            let start = f64::from(quarter) * 0.25;
            let arc = curve
                .arc_length(start..start + 0.25, DEFAULT_ACCURACY)
                .unwrap();
            assert!(
                relative_error(arc, PI * radius / 2.0) < 1e-12,
                "{radius}: {arc}"
            );
            // Each quarter is symmetric about its middle parameter: an eighth of the circle.
            let eighth = curve
                .arc_length(start..start + 0.125, DEFAULT_ACCURACY)
                .unwrap();
            assert!(
                relative_error(eighth, PI * radius / 4.0) < 1e-12,
                "{eighth}"
            );
        }
        // Three quarters across two breakpoints.
        let three = curve.arc_length(0.1..0.85, DEFAULT_ACCURACY).unwrap();
        let angle = |t: f64| {
            let p = curve.evaluate(t).unwrap().position;
            p[1].atan2(p[0]).rem_euclid(2.0 * PI)
        };
        let want = radius * (angle(0.85) - angle(0.1));
        assert!(relative_error(three, want) < 1e-12, "{three} vs {want}");
        for k in 0..=40 {
            let t = f64::from(k) / 40.0;
            let kappa = curve.curvature(t).unwrap();
            assert!(
                relative_error(kappa, 1.0 / radius) < 1e-12,
                "t = {t}: {kappa}"
            );
            // The unit normal points to the centre, the tangent is perpendicular to it.
            let p = curve.evaluate(t).unwrap().position;
            let normal = curve.unit_normal(t).unwrap();
            let tangent = curve.unit_tangent(t).unwrap();
            assert!(
                (normal[0] + p[0] / radius).abs() < 1e-12,
                "{normal:?} at {p:?}"
            );
            assert!(
                (normal[1] + p[1] / radius).abs() < 1e-12,
                "{normal:?} at {p:?}"
            );
            assert!((tangent[0] * normal[0] + tangent[1] * normal[1]).abs() < 1e-12);
            // Counter-clockwise: the tangent is the normal turned clockwise by 90 degrees.
            assert!(
                (tangent[0] - normal[1]).abs() < 1e-12 && (tangent[1] + normal[0]).abs() < 1e-12
            );
        }
    }
}

#[test]
fn straight_line_length_is_the_chord() {
    let d = degrees(0.5, 0.2, 0.1);
    // Collinear, unevenly spaced control points: the speed varies, the length does not.
    let line = Bezier::new(vec![
        ControlPoint::new([0.0, 0.0], d),
        ControlPoint::new([1.0, 2.0], d),
        ControlPoint::new([3.0, 6.0], d),
        ControlPoint::new([4.0, 8.0], d),
    ])
    .unwrap();
    let chord = 80.0_f64.sqrt();
    let length = line.length().unwrap();
    assert!(
        (length - chord).abs() <= 4.0 * f64::EPSILON * chord,
        "{length} vs {chord}"
    );
    let part = line.arc_length(0.25..0.75, DEFAULT_ACCURACY).unwrap();
    let a = line.evaluate(0.25).unwrap().position;
    let b = line.evaluate(0.75).unwrap().position;
    let want = (b[0] - a[0]).hypot(b[1] - a[1]);
    assert!(
        (part - want).abs() <= 8.0 * f64::EPSILON * chord,
        "{part} vs {want}"
    );
    // Zero to rounding.
    assert!(line.curvature(0.3).unwrap() < 1e-15);
    assert_eq!(
        line.unit_normal(0.3),
        Err(GeometryError::Straight { t: 0.3 })
    );
    let tangent = line.unit_tangent(0.3).unwrap();
    assert!((tangent[0] - 1.0 / 5.0_f64.sqrt()).abs() < 1e-15);
    assert!((tangent[1] - 2.0 / 5.0_f64.sqrt()).abs() < 1e-15);
}

/// The unit circle of [`unit_circle`] with its knots moved to `origin + 0.1 u` (an affine map
/// of the parameter, which keeps the curve and its length).
fn circle_with_knots_at(origin: f64) -> Nurbs<2> {
    let unit = unit_circle();
    let knots: Vec<f64> = unit
        .knots()
        .knots()
        .iter()
        .map(|u| origin + 0.1 * u)
        .collect();
    let points = (0..9).map(|i| unit.control_point(i)).collect();
    let weights = unit.weights().unwrap().to_vec();
    Nurbs::new(points, weights, KnotVector::new(knots, 2, 9).unwrap()).unwrap()
}

#[test]
fn length_on_knots_far_from_zero_is_as_exact_as_on_the_unit_interval() {
    // Knots near 1.7e9 (a time stamp in seconds) 0.025 apart: one float there is 2.4e-7, a
    // part 1e-5 of a span. The quadrature's nodes are carried as an origin and an offset.
    for origin in [0.0, -9.5, 1e6, 1.7e9] {
        let circle = circle_with_knots_at(origin);
        let length = circle.length().unwrap();
        assert!(
            relative_error(length, 2.0 * PI) <= 1e-14,
            "origin {origin}: {length}"
        );
        let averages = circle.arc_averages(DEFAULT_ACCURACY).unwrap();
        assert!(relative_error(averages.length, 2.0 * PI) <= 1e-14);
    }
}

/// Found by `nurbs_length_is_additive_and_at_least_the_chord` in CI: three straight rational
/// pieces (degree 1, double knots) on knots near -9.49 a span of 0.005 apart, with weight
/// ratios up to 54. The rule's nodes rounded to the floats near -9.49 made the length
/// 1.9e-12 of itself short of the chords (asked for 1e-12).
#[test]
fn straight_rational_pieces_on_short_spans_have_the_chords_length_regression() {
    let rows = [
        [887.6167597620141, -818.8758933753064],
        [-163.87863098548888, -467.40288332740323],
        [-86.77862484238905, -961.7747639930916],
        [974.2311271667082, 955.9607299815106],
        [742.4710803200949, -942.9846469428896],
        [478.9013885170063, -452.0483683798562],
    ];
    let weights = vec![0.13685787323246615, 7.454788748274259, 1.0, 1.0, 10.0, 1.0];
    let knots = vec![
        -9.48932809074735,
        -9.48932809074735,
        -9.484328090747349,
        -9.484328090747349,
        -9.47932809074735,
        -9.47932809074735,
        -9.474328090747349,
        -9.46622553855121,
    ];
    let d = degrees(0.5, 0.2, 0.1);
    let points = rows.iter().map(|&p| ControlPoint::new(p, d)).collect();
    let curve = Nurbs::new(points, weights, KnotVector::new(knots, 1, 6).unwrap()).unwrap();
    let chords: f64 = [(0, 1), (2, 3), (4, 5)]
        .iter()
        .map(|&(a, b)| distance(&rows[a], &rows[b]))
        .sum();
    for accuracy in [DEFAULT_ACCURACY, 1e-14] {
        let domain = curve.domain();
        let length = curve.arc_length(domain, accuracy).unwrap();
        assert!(
            relative_error(length, chords) <= 4.0 * f64::EPSILON,
            "accuracy {accuracy}: {length} vs {chords}"
        );
    }
}

#[test]
fn cubic_beziers_against_mpmath() {
    let curve = neutrospline::example1();
    let length = curve.length().unwrap();
    assert!(relative_error(length, EXAMPLE1_LENGTH) < 1e-12, "{length}");
    let half = curve.arc_length(0.0..0.5, DEFAULT_ACCURACY).unwrap();
    assert!(relative_error(half, EXAMPLE1_HALF_LENGTH) < 1e-12, "{half}");
    let averages = curve.arc_averages(DEFAULT_ACCURACY).unwrap();
    assert!(relative_error(averages.length, EXAMPLE1_LENGTH) < 1e-12);
    for (value, want) in [
        (averages.truth, EXAMPLE1_AVERAGE_TRUTH),
        (averages.indeterminacy, EXAMPLE1_AVERAGE_INDETERMINACY),
        (averages.falsity, EXAMPLE1_AVERAGE_FALSITY),
        (averages.score, EXAMPLE1_AVERAGE_SCORE),
    ] {
        assert!((value - want).abs() < 1e-12, "{value} vs {want}");
    }

    let d = degrees(0.5, 0.2, 0.1);
    let spatial = Bezier::new(vec![
        ControlPoint::new([0.0, 0.0, 0.0], d),
        ControlPoint::new([1.0, 2.0, 0.5], d),
        ControlPoint::new([3.0, -1.0, 2.0], d),
        ControlPoint::new([4.0, 1.0, -1.0], d),
    ])
    .unwrap();
    let length = spatial.length().unwrap();
    assert!(relative_error(length, SPATIAL_LENGTH) < 1e-12, "{length}");
    let part = spatial.arc_length(0.3..0.8, DEFAULT_ACCURACY).unwrap();
    assert!(
        relative_error(part, SPATIAL_LENGTH_FROM_0_3_TO_0_8) < 1e-12,
        "{part}"
    );
    // A looser accuracy still lands within it.
    let rough = spatial.arc_length(0.0..1.0, 1e-6).unwrap();
    assert!(relative_error(rough, SPATIAL_LENGTH) < 1e-6, "{rough}");
}

#[test]
fn averages_of_constant_degrees_are_the_constant() {
    let d = degrees(0.7, 0.25, 0.15);
    let circle = unit_circle();
    let points = circle
        .control_points()
        .into_iter()
        .map(|p| ControlPoint::new(p.position, d))
        .collect();
    let constant = Nurbs::new(
        points,
        circle.weights().unwrap().to_vec(),
        circle.knots().clone(),
    )
    .unwrap();
    let averages = constant.arc_averages(DEFAULT_ACCURACY).unwrap();
    assert!((averages.truth - 0.7).abs() < 1e-14, "{averages:?}");
    assert!(
        (averages.indeterminacy - 0.25).abs() < 1e-14,
        "{averages:?}"
    );
    assert!((averages.falsity - 0.15).abs() < 1e-14, "{averages:?}");
    assert!((averages.score - d.score()).abs() < 1e-14, "{averages:?}");
    assert!(relative_error(averages.length, 2.0 * PI) < 1e-12);
}

#[test]
fn errors_are_typed() {
    let curve = neutrospline::example1();
    for accuracy in [0.0, -1e-12, f64::NAN, f64::INFINITY] {
        let error = curve.arc_length(0.0..1.0, accuracy).unwrap_err();
        assert!(
            matches!(error, GeometryError::AccuracyNotPositive { .. }),
            "{error}"
        );
    }
    assert_eq!(
        curve.arc_length(0.75..0.25, DEFAULT_ACCURACY),
        Err(GeometryError::ReversedRange {
            start: 0.75,
            end: 0.25
        })
    );
    assert!(matches!(
        curve.arc_length(0.0..1.5, DEFAULT_ACCURACY),
        Err(GeometryError::Eval(_))
    ));
    assert_eq!(curve.arc_length(0.5..0.5, DEFAULT_ACCURACY), Ok(0.0));
    let d = degrees(0.5, 0.2, 0.1);
    let point = Bezier::new(vec![
        ControlPoint::new([1.0, 1.0], d),
        ControlPoint::new([1.0, 1.0], d),
    ])
    .unwrap();
    assert_eq!(point.length(), Ok(0.0));
    assert_eq!(
        point.curvature(0.5),
        Err(GeometryError::Stationary { t: 0.5 })
    );
    assert_eq!(
        point.unit_tangent(0.5),
        Err(GeometryError::Stationary { t: 0.5 })
    );
    assert_eq!(
        point.arc_averages(DEFAULT_ACCURACY),
        Err(GeometryError::ZeroLength)
    );
    // A cusp: (0,0), (1,1), (0,1), (1,0) has C'(1/2) = 0.
    let cusp = Bezier::new(vec![
        ControlPoint::new([0.0, 0.0], d),
        ControlPoint::new([1.0, 1.0], d),
        ControlPoint::new([0.0, 1.0], d),
        ControlPoint::new([1.0, 0.0], d),
    ])
    .unwrap();
    assert_eq!(
        cusp.curvature(0.5),
        Err(GeometryError::Stationary { t: 0.5 })
    );
    // Its length is still found: the two halves are mirror images.
    let whole = cusp.length().unwrap();
    let left = cusp.arc_length(0.0..0.5, DEFAULT_ACCURACY).unwrap();
    assert!(
        relative_error(whole, 2.0 * left) < 1e-12,
        "{whole} vs {left}"
    );
}

/// The distance between two points.
fn distance<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0_f64, |acc, (x, y)| acc.hypot(x - y))
}

/// The interior knots where a spline jumps (multiplicity `p + 1`): there its length does not
/// count the gap, so the chord bound is taken piece by piece.
fn jumps(knots: &KnotVector) -> Vec<f64> {
    let domain = knots.domain();
    let mut found: Vec<f64> = knots
        .knots()
        .iter()
        .copied()
        .filter(|&u| u > domain.start && u < domain.end && knots.multiplicity(u) > knots.degree())
        .collect();
    found.dedup();
    found
}

/// Length checks for one curve that jumps at `jumps` (empty for a continuous curve): the
/// length is the sum of its halves' after `split` and of its two `arc_length` ranges, and it is
/// at least the sum of the chords of its continuous pieces.
fn length_checks<const D: usize, C>(curve: &C, jumps: &[f64], s: f64) -> Result<(), TestCaseError>
where
    C: CurveGeometry<D> + Split + Clone,
{
    let domain = curve.domain();
    let t = domain.start + s * (domain.end - domain.start);
    let whole = curve.length().unwrap();
    let (left, right) = curve.split(t).unwrap();
    let sum = left.length().unwrap() + right.length().unwrap();
    prop_assert!(
        (whole - sum).abs() <= 1e-10 * whole,
        "whole {whole}, halves {sum}"
    );
    let by_range = curve.arc_length(domain.start..t, DEFAULT_ACCURACY).unwrap()
        + curve.arc_length(t..domain.end, DEFAULT_ACCURACY).unwrap();
    prop_assert!(
        (whole - by_range).abs() <= 1e-10 * whole,
        "{whole} vs {by_range}"
    );
    // Each continuous piece starts at the value from the right and ends at the limit from the
    // left, which is where the left part of a split there ends.
    let mut bounds = vec![domain.start];
    bounds.extend_from_slice(jumps);
    bounds.push(domain.end);
    let mut chords = 0.0;
    for piece in bounds.windows(2) {
        let start = curve.evaluate(piece[0]).unwrap().position;
        let end = if piece[1] < domain.end {
            curve.split(piece[1]).unwrap().0.end().unwrap().position
        } else {
            curve.end().unwrap().position
        };
        chords += distance(&start, &end);
    }
    prop_assert!(
        whole >= chords * (1.0 - 1e-12),
        "length {whole} < chords {chords} of the pieces between {bounds:?}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bezier_length_is_additive_and_at_least_the_chord(
        curve in strategies::bezier::<2>(1..=6),
        spatial in strategies::bezier::<3>(1..=6),
        s in 0.05..0.95f64,
    ) {
        length_checks(&curve, &[], s)?;
        length_checks(&spatial, &[], s)?;
    }

    #[test]
    fn bspline_length_is_additive_and_at_least_the_chord(
        curve in strategies::bspline::<2>(1..=4),
        spatial in strategies::bspline::<3>(1..=4),
        s in 0.05..0.95f64,
    ) {
        length_checks(&curve, &jumps(curve.knots()), s)?;
        length_checks(&spatial, &jumps(spatial.knots()), s)?;
    }

    #[test]
    fn nurbs_length_is_additive_and_at_least_the_chord(
        curve in strategies::nurbs::<2>(1..=4),
        spatial in strategies::nurbs::<3>(1..=4),
        s in 0.05..0.95f64,
    ) {
        length_checks(&curve, &jumps(curve.knots()), s)?;
        let spatial_jumps = jumps(spatial.knots());
        length_checks(&AnyCurve::from(spatial), &spatial_jumps, s)?;
    }
}

/// Points evenly spaced by arc length on the unit circle (a rational curve whose parameter
/// is far from arc length) sit at evenly spaced angles: an independent check by `atan2` of
/// the evaluated points, to 1e-12 radians.
#[test]
fn arc_length_samples_of_the_circle_are_evenly_spaced_angles() {
    let circle = unit_circle();
    let n = 49;
    let ts = circle.arc_length_parameters(n, 1e-14).unwrap();
    assert_eq!(ts.len(), n);
    let start = {
        let p = circle.evaluate(ts[0]).unwrap().position;
        p[1].atan2(p[0])
    };
    for (k, &t) in ts.iter().enumerate() {
        let p = circle.evaluate(t).unwrap().position;
        let mut angle = p[1].atan2(p[0]) - start;
        if angle < -1e-9 {
            angle += 2.0 * PI;
        }
        if k == n - 1 && angle < 1e-9 {
            angle = 2.0 * PI;
        }
        let want = 2.0 * PI * k as f64 / (n - 1) as f64;
        assert!(
            (angle - want).abs() < 1e-12,
            "k = {k}: angle {angle}, want {want}"
        );
    }
}

/// Through a cusp (a cubic whose speed vanishes at t = 1/2) the parameters still increase and
/// each arc length from the start is k L / (n - 1) to 1e-12 of L; a length outside [0, L] is
/// refused.
#[test]
fn arc_length_samples_cross_a_cusp() {
    let d = degrees(0.5, 0.2, 0.1);
    let cusp = Bezier::new(vec![
        ControlPoint::new([0.0, 0.0], d),
        ControlPoint::new([1.0, 1.0], d),
        ControlPoint::new([0.0, 1.0], d),
        ControlPoint::new([1.0, 0.0], d),
    ])
    .unwrap();
    let speed = cusp.derivative().evaluate(0.5).unwrap().position;
    assert!(
        speed[0].hypot(speed[1]) < 1e-15,
        "the cubic has its cusp at 1/2"
    );
    let total = cusp.length().unwrap();
    let ts = cusp.arc_length_parameters(21, 1e-13).unwrap();
    assert!(ts.windows(2).all(|w| w[0] < w[1]), "{ts:?}");
    for (k, &t) in ts.iter().enumerate() {
        let s = cusp.arc_length(0.0..t, 1e-13).unwrap();
        assert!(
            (s - total * k as f64 / 20.0).abs() <= 1e-12 * total,
            "k = {k}"
        );
    }
    assert_eq!(
        cusp.parameter_at_length(2.0 * total, 1e-12)
            .unwrap_err()
            .to_string(),
        format!(
            "arc length {} is outside [0, {total}] (the curve's length)",
            2.0 * total
        )
    );
}
