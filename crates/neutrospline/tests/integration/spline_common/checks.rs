//! The generic checks: each takes a curve of either spline kind (`TestSpline`).

use super::*;
use neutrospline::ControlPolygon;

// ------------------------------------------------------------------------ generic checks

/// docs/model.md section 4: every point is a valid neutrosophic point whose degrees lie within the range of
/// the (active) control degrees. Exact: no tolerance.
pub fn check_degree_bounds<const D: usize, C: TestSpline<D>>(
    c: &C,
    t: f64,
) -> Result<(), TestCaseError> {
    let p = c.evaluate(t).unwrap();
    let points = c.points();
    let local = &points[active(c.knot_vector(), t)];
    for k in DegreeKind::ALL {
        let v = p.degree(k);
        for set in [&points[..], local] {
            let lo = set
                .iter()
                .map(|q| q.degree(k))
                .fold(f64::INFINITY, f64::min);
            let hi = set
                .iter()
                .map(|q| q.degree(k))
                .fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(
                lo <= v && v <= hi,
                "{k} = {v} outside [{lo}, {hi}] at t = {t}"
            );
        }
        prop_assert!((0.0..=1.0).contains(&v));
    }
    let [tr, i, f] = p.degrees.to_array();
    prop_assert!(Degrees::new(tr, i, f).is_ok());
    Ok(())
}

/// Partition of unity and local support: with truth_j = 1 and every other truth 0, the truth
/// of the curve is the basis function R_j(t) (rational for NURBS): in \[0, 1\], exactly 0
/// outside `[u_j, u_{j+p+1}]`, and the R_j sum to 1. A constant curve evaluates to its
/// control point exactly.
pub fn check_partition_of_unity<const D: usize, C: TestSpline<D>>(
    c: &C,
    t: f64,
) -> Result<(), TestCaseError> {
    let points = c.points();
    let n = points.len();
    let p = degree(c);
    let u = c.knot_vector().knots().to_vec();
    let mut sum = 0.0;
    for j in 0..n {
        let unit: Vec<ControlPoint<D>> = points
            .iter()
            .enumerate()
            .map(|(i, q)| {
                let d = q.degrees;
                let truth = if i == j { 1.0 } else { 0.0 };
                ControlPoint::new(
                    q.position,
                    Degrees::new(truth, d.indeterminacy(), d.falsity()).unwrap(),
                )
            })
            .collect();
        let r = c.rebuild(unit).evaluate(t).unwrap().degrees.truth();
        prop_assert!((0.0..=1.0).contains(&r), "R_{j}({t}) = {r}");
        if t < u[j] || t > u[j + p + 1] {
            prop_assert_eq!(r, 0.0, "R_{}({}) outside its support", j, t);
        }
        sum += r;
    }
    let tol = 4.0 * (p as f64 + 1.0) * (n as f64) * EPS;
    prop_assert!((sum - 1.0).abs() <= tol, "sum R_j({t}) = {sum}");
    // Constant control points: the exact point, by projection of every convex step.
    let constant = c.rebuild(vec![points[0]; n]);
    prop_assert_eq!(constant.evaluate(t).unwrap(), points[0]);
    Ok(())
}

/// Clamped knots: the curve starts and ends exactly at its end control points.
pub fn check_endpoints<const D: usize, C: TestSpline<D>>(c: &C) -> Result<(), TestCaseError> {
    let points = c.points();
    let (a, b) = (c.domain().start, c.domain().end);
    prop_assert_eq!(c.start().unwrap(), c.evaluate(a).unwrap());
    prop_assert_eq!(c.end().unwrap(), c.evaluate(b).unwrap());
    if c.knot_vector().is_clamped() {
        prop_assert_eq!(c.start().unwrap(), points[0]);
        prop_assert_eq!(c.end().unwrap(), points[points.len() - 1]);
    }
    Ok(())
}

/// The curve, degrees included, lies in the convex hull of its active control points.
pub fn check_convex_hull<const D: usize, C: TestSpline<D>>(
    c: &C,
    t: f64,
    directions: &[Vec<f64>],
) -> Result<(), TestCaseError> {
    let point = channels(&c.evaluate(t).unwrap());
    let points = c.points();
    let local: Vec<Vec<f64>> = points[active(c.knot_vector(), t)]
        .iter()
        .map(channels)
        .collect();
    let tol = 16.0 * (degree(c) as f64 + 1.0) * EPS * scale(&points);
    let dims = D + 3;
    let axes = (0..dims).flat_map(|a| {
        [1.0, -1.0].map(|sign| (0..dims).map(|b| if a == b { sign } else { 0.0 }).collect())
    });
    for u in axes.chain(directions.iter().cloned()) {
        let dot = |v: &[f64]| v.iter().zip(&u).map(|(a, b)| a * b).sum::<f64>();
        let support = local
            .iter()
            .map(|q| dot(q))
            .fold(f64::NEG_INFINITY, f64::max);
        prop_assert!(
            dot(&point) <= support + tol,
            "outside hull along {u:?} at t = {t}"
        );
    }
    Ok(())
}

/// Knot insertion leaves the curve unchanged; errors where the multiplicity would pass p + 1.
pub fn check_insertion<const D: usize, C: TestSpline<D>>(
    c: &C,
    u: f64,
    ts: &[f64],
) -> Result<(), TestCaseError> {
    let knots = c.knot_vector();
    let p = knots.degree();
    let m = knots.multiplicity(u);
    match c.insert(u) {
        Ok(ins) => {
            prop_assert!(m < p + 1, "inserted a knot of multiplicity {m} = p + 1");
            let k = ins.knot_vector();
            prop_assert_eq!(k.multiplicity(u), m + 1);
            prop_assert_eq!(k.knots().len(), knots.knots().len() + 1);
            prop_assert_eq!(ins.points().len(), c.points().len() + 1);
            prop_assert_eq!(k.domain(), knots.domain());
            // The knots stay a valid vector.
            prop_assert!(KnotVector::new(k.knots().to_vec(), p, ins.points().len()).is_ok());
            let mm = scale(&c.points());
            for &t in ts.iter().chain([u].iter()) {
                let (a, b) = (ins.evaluate(t).unwrap(), c.evaluate(t).unwrap());
                assert_close(&format!("insert {u} at t = {t}"), &a, &b, p, mm, 32.0)?;
            }
            // The weights of the new control points are positive.
            prop_assert!(ins.weight_list().iter().all(|&w| w > 0.0));
        }
        Err(KnotError::MultiplicityTooHigh {
            value,
            multiplicity,
            max,
        }) => {
            prop_assert_eq!(m, p + 1);
            prop_assert_eq!((value, multiplicity, max), (u, p + 2, p + 1));
        }
        Err(e) => prop_assert!(false, "insert_knot({u}): unexpected {e}"),
    }
    Ok(())
}

/// Split and subsegment keep the curve's parameters and reproduce it (subsegments in both
/// directions); a split at an end of the domain and an empty subsegment are refused.
pub fn check_split<const D: usize, C: TestSpline<D>>(
    c: &C,
    t: f64,
    ts: &[f64],
) -> Result<(), TestCaseError> {
    let domain = c.domain();
    let p = degree(c);
    let mm = scale(&c.points());
    // Up to p insertions, each a few roundings (more with unequal weights).
    let factor = 64.0 * (p as f64 + 1.0) * weight_ratio(&c.weight_list());
    let empty = matches!(c.subsegment(t, t), Err(EvalError::EmptyPiece { .. }));
    prop_assert!(empty, "subsegment({t}, {t}) is not refused");
    if t == domain.start || t == domain.end {
        let refused = matches!(c.split(t), Err(EvalError::EmptyPiece { .. }));
        prop_assert!(refused, "split at the end {t} is not refused");
        return Ok(());
    }
    let (left, right) = c.split(t).unwrap();
    prop_assert_eq!(left.domain(), domain.start..t);
    prop_assert_eq!(right.domain(), t..domain.end);
    // Where the curve jumps (a knot of multiplicity p + 1 inside the domain) it takes the value
    // from the right, and a piece ending there the limit from the left.
    let jumps = |x: f64| x > domain.start && x < domain.end && c.knot_vector().multiplicity(x) > p;
    for &s in ts {
        let want = c.evaluate(s).unwrap();
        let piece = if s < t { &left } else { &right };
        let got = piece.evaluate(s).unwrap();
        assert_close(
            &format!("split at {t}, t = {s}"),
            &got,
            &want,
            p,
            mm,
            factor,
        )?;
    }
    if !jumps(t) {
        // Both pieces meet at the curve's point.
        let at = c.evaluate(t).unwrap();
        assert_close("left end", &left.end().unwrap(), &at, p, mm, factor)?;
        assert_close("right start", &right.start().unwrap(), &at, p, mm, factor)?;
    }
    // The piece between another parameter and t, forwards and backwards.
    let s = ts.iter().copied().find(|&s| s != t).unwrap_or(domain.start);
    let (lo, hi) = (s.min(t), s.max(t));
    let forward = c.subsegment(lo, hi).unwrap();
    let backward = c.subsegment(hi, lo).unwrap();
    prop_assert_eq!(forward.domain(), lo..hi);
    prop_assert_eq!(backward.domain(), lo..hi);
    let derivative = c.derivative();
    for k in 0..=8 {
        let x = neutrospline::uniform_parameter(k, 9, lo..hi);
        if x == hi && jumps(hi) {
            continue;
        }
        let want = c.evaluate(x).unwrap();
        assert_close(
            "subsegment",
            &forward.evaluate(x).unwrap(),
            &want,
            p,
            mm,
            factor,
        )?;
        // The reversed piece at lo + hi - x: its knots are reflected with a rounding each, so
        // allow the curve's speed times a few ulps of the parameter too. (At a jump it takes
        // the other side's value, and so within the parameter's rounding of one.)
        let near = 8.0 * EPS * lo.abs().max(hi.abs()).max(hi - lo);
        if c.knot_vector()
            .knots()
            .iter()
            .any(|&u| jumps(u) && (u - x).abs() <= near)
        {
            continue;
        }
        let mirrored = (lo + hi - x).clamp(lo, hi);
        let got = backward.evaluate(mirrored).unwrap();
        let speed = derivative_channels(&derivative.evaluate(x).unwrap())
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        let slack = 8.0 * EPS * lo.abs().max(hi.abs()).max(hi - lo) * speed;
        for (ch, (g, w)) in channels(&got).iter().zip(channels(&want)).enumerate() {
            let scale_of = if ch < D { mm } else { 1.0 };
            let tol = factor * (p as f64 + 1.0) * EPS * scale_of + slack;
            prop_assert!(
                (g - w).abs() <= tol,
                "reversed piece at {mirrored}: channel {ch}: {g:e} vs {w:e} (tolerance {tol:e})"
            );
        }
    }
    Ok(())
}

/// Elevation (once and twice) leaves the curve unchanged and raises every interior knot's
/// multiplicity by one; the result is clamped on the same domain.
pub fn check_elevation<const D: usize, C: TestSpline<D>>(
    c: &C,
    ts: &[f64],
) -> Result<(), TestCaseError> {
    let p = degree(c);
    let knots = c.knot_vector();
    let once = c.elevated();
    let twice = once.elevated();
    let mm = scale(&c.points());
    for (e, q) in [(&once, p + 1), (&twice, p + 2)] {
        let k = e.knot_vector();
        prop_assert_eq!(k.degree(), q);
        prop_assert_eq!(k.domain(), knots.domain());
        prop_assert!(k.is_clamped());
        prop_assert!(KnotVector::new(k.knots().to_vec(), q, e.points().len()).is_ok());
        for b in knots.interior_breakpoints() {
            prop_assert_eq!(
                k.multiplicity(b),
                knots.multiplicity(b) + q - p,
                "knot {}",
                b
            );
        }
        prop_assert_eq!(k.interior_breakpoints(), knots.interior_breakpoints());
        prop_assert!(e.weight_list().iter().all(|&w| w > 0.0));
        for &t in ts {
            let (a, b) = (e.evaluate(t).unwrap(), c.evaluate(t).unwrap());
            // Each new control point is computed locally from blossoms: the error is a few
            // (q + 1) u M whatever the degree, the number of spans or the weights.
            assert_close(&format!("elevate to {q} at t = {t}"), &a, &b, q, mm, 16.0)?;
        }
    }
    Ok(())
}

/// The Bézier pieces cover the domain in order and reproduce the curve.
pub fn check_pieces<const D: usize, C: TestSpline<D>>(
    c: &C,
    ts: &[f64],
) -> Result<(), TestCaseError> {
    let pieces = c.pieces();
    let knots = c.knot_vector();
    let want = spans(knots);
    let got: Vec<(f64, f64)> = pieces.iter().map(|(a, b, _)| (*a, *b)).collect();
    prop_assert_eq!(&got, &want);
    let p = knots.degree();
    let mm = scale(&c.points());
    for (_, _, piece) in &pieces {
        prop_assert_eq!(piece.degree(), p);
        prop_assert_eq!(piece.domain(), 0.0..1.0);
    }
    for &t in ts {
        // The piece used at t: right-hand at interior knots, the last piece at the end.
        let index = pieces
            .iter()
            .position(|(a, b, _)| *a <= t && t < *b)
            .unwrap_or(pieces.len() - 1);
        let (a, b, piece) = &pieces[index];
        let s = ((t - a) / (b - a)).clamp(0.0, 1.0);
        let got = piece.evaluate(s).unwrap();
        assert_close(
            &format!("piece {index} at t = {t}"),
            &got,
            &c.evaluate(t).unwrap(),
            p,
            mm,
            32.0 * weight_ratio(&c.weight_list()),
        )?;
    }
    Ok(())
}

/// Central differences inside a span agree with the derivative.
pub fn check_derivative<const D: usize, C: TestSpline<D>>(
    c: &C,
    span: prop::sample::Index,
    fraction: f64,
) -> Result<(), TestCaseError> {
    let spans = spans(c.knot_vector());
    let (a, b) = spans[span.index(spans.len())];
    let len = b - a;
    let t = a + fraction * len;
    let h = 1e-6 * len;
    let d = derivative_channels(&c.derivative_value(t));
    let (lo, hi) = (c.evaluate(t - h).unwrap(), c.evaluate(t + h).unwrap());
    let p = degree(c) as f64;
    let r = weight_ratio(&c.weight_list());
    // 2 p M r / len bounds the derivative on this span (every knot difference in its de Boor
    // triangle is at least len); central differences are accurate to ~1e-7 of that here.
    let bound = 2.0 * p * r / len;
    let mm = scale(&c.points());
    for (ch, (x0, x1)) in channels(&lo).iter().zip(channels(&hi)).enumerate() {
        let fd = (x1 - x0) / (2.0 * h);
        let tol = 1e-6 * bound * if ch < D { mm } else { 1.0 } + 1e-9;
        prop_assert!(
            (fd - d[ch]).abs() <= tol,
            "channel {ch} at t = {t}: fd {fd:e} vs {:e} (tol {tol:e})",
            d[ch]
        );
    }
    Ok(())
}

/// The tight box contains every evaluated point (within rounding) and sits in the control box.
pub fn check_bounding_box<const D: usize, C: TestSpline<D>>(
    c: &C,
    ts: &[f64],
) -> Result<(), TestCaseError> {
    let b = c.bounding_box();
    let cb = c.control_bounding_box();
    let mm = scale(&c.points());
    let slack = 64.0 * (degree(c) as f64 + 1.0) * EPS * weight_ratio(&c.weight_list());
    for &t in ts {
        let p = c.evaluate(t).unwrap();
        for a in 0..D {
            let (r, v) = (b.position[a], p.position[a]);
            prop_assert!(
                r.min - slack * mm <= v && v <= r.max + slack * mm,
                "axis {a} = {v} not in {r:?} at t = {t}"
            );
        }
        for k in DegreeKind::ALL {
            let (r, v) = (b.degree(k), p.degree(k));
            prop_assert!(
                r.min - slack <= v && v <= r.max + slack,
                "{k} = {v} not in {r:?} at t = {t}"
            );
        }
    }
    for a in 0..D {
        let (r, cr) = (b.position[a], cb.position[a]);
        prop_assert!(cr.min <= r.min + slack * mm && r.max <= cr.max + slack * mm);
    }
    for k in DegreeKind::ALL {
        prop_assert!(cb.degree(k).min <= b.degree(k).min && b.degree(k).max <= cb.degree(k).max);
    }
    Ok(())
}

/// Affine maps of the positions commute with evaluation; the degrees are untouched (bitwise).
pub fn check_affine<const D: usize, C: TestSpline<D>>(
    c: &C,
    t: f64,
    linear: [[f64; D]; D],
    shift: [f64; D],
) -> Result<(), TestCaseError> {
    let map = Affine::new(linear, shift);
    let mapped = c.mapped(&map);
    let got = mapped.evaluate(t).unwrap();
    let p = c.evaluate(t).unwrap();
    prop_assert_eq!(got.degrees, p.degrees);
    let want = map.apply(p.position);
    let mm = scale(&c.points());
    let norm = linear
        .iter()
        .flat_map(|r| r.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let shift_max = shift.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let tol = 64.0 * (degree(c) as f64 + 1.0) * EPS * (D as f64 * norm * mm + shift_max + mm);
    for a in 0..D {
        prop_assert!(
            (got.position[a] - want[a]).abs() <= tol,
            "axis {a}: {} vs {} (tol {tol:e})",
            got.position[a],
            want[a]
        );
    }
    Ok(())
}

/// `AnyCurve` forwards every method to the kind's own, bitwise.
pub fn check_any_curve<const D: usize, C: TestSpline<D>>(
    c: &C,
    ts: &[f64],
    kind: CurveKind,
) -> Result<(), TestCaseError> {
    let any: AnyCurve<D> = c.clone().into();
    prop_assert_eq!(any.kind(), kind);
    prop_assert_eq!(any.degree(), degree(c));
    prop_assert_eq!(any.domain(), c.domain());
    prop_assert_eq!(any.len(), c.points().len());
    prop_assert!(!any.is_empty());
    prop_assert_eq!(any.control_points(), c.points());
    prop_assert_eq!(any.knots(), Some(c.knot_vector()));
    match kind {
        CurveKind::Nurbs => prop_assert_eq!(any.weights(), Some(&c.weight_list()[..])),
        _ => prop_assert_eq!(any.weights(), None),
    }
    prop_assert_eq!(any.bounding_box(), c.bounding_box());
    prop_assert_eq!(any.control_bounding_box(), c.control_bounding_box());
    prop_assert_eq!(Bounded::bounding_box(&any), c.bounding_box());
    prop_assert_eq!(any.start(), c.start());
    prop_assert_eq!(any.end(), c.end());
    let elevated: AnyCurve<D> = c.elevated().into();
    prop_assert_eq!(any.elevate(), elevated);
    let map = Affine::new(
        core::array::from_fn(|r| core::array::from_fn(|k| if r == k { 2.0 } else { 0.5 })),
        [1.0; D],
    );
    let mapped: AnyCurve<D> = c.mapped(&map).into();
    prop_assert_eq!(any.transform(&map).unwrap(), mapped);
    let mut many = vec![c.start().unwrap(); ts.len()];
    let mut many_any = many.clone();
    c.evaluate_many(ts, &mut many).unwrap();
    Evaluate::evaluate_many(&any, ts, &mut many_any).unwrap();
    prop_assert_eq!(&many, &many_any);
    let (derivative, derivative_any) = (c.derivative(), any.derivative());
    prop_assert_eq!(&derivative, &derivative_any);
    for (k, &t) in ts.iter().enumerate() {
        let p = c.evaluate(t).unwrap();
        prop_assert_eq!(any.evaluate(t).unwrap(), p);
        prop_assert_eq!(many[k], p);
        prop_assert_eq!(derivative_any.evaluate(t).unwrap(), c.derivative_value(t));
    }
    // Out of the domain: the same error.
    let (a, b) = (c.domain().start, c.domain().end);
    let outside = b + (b - a).max(1.0);
    prop_assert_eq!(any.evaluate(outside), c.evaluate(outside));
    prop_assert!(c.evaluate(outside).is_err());
    prop_assert!(c.evaluate(f64::NAN).is_err());
    Ok(())
}

pub fn directions(dims: usize) -> impl Strategy<Value = Vec<Vec<f64>>> {
    prop::collection::vec(prop::collection::vec(-1.0..=1.0f64, dims), 6)
}

pub fn knots_of_bspline<const D: usize>(c: &BSpline<D>) -> KnotVector {
    c.knots().clone()
}

pub fn knots_of_nurbs<const D: usize>(c: &Nurbs<D>) -> KnotVector {
    c.knots().clone()
}

/// The tight box of a curve is no larger than its sampled extent allows.
pub fn check_bounding_box_is_tight<const D: usize, C: TestSpline<D>>(
    c: &C,
) -> Result<(), TestCaseError> {
    let b = c.bounding_box();
    let mm = scale(&c.points());
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    let mut slack: f64 = 0.0;
    // Dense samples of each piece, ends included: at a knot of multiplicity p + 1 the box
    // holds the left-hand limit too (the closure of the curve). The extent between samples
    // can exceed them by at most |C''| h^2 / 8, with |C''| <= 4 p^2 M r^3 / len^2 on the
    // piece (h = len / 400).
    let p = degree(c) as f64;
    let r = weight_ratio(&c.weight_list());
    for (_, _, piece) in c.pieces() {
        slack = slack.max(4.0 * p * p * r * r * r / (8.0 * 400.0 * 400.0));
        for k in 0..=400 {
            let q = piece.evaluate(k as f64 / 400.0).unwrap();
            for ax in 0..D {
                lo[ax] = lo[ax].min(q.position[ax]);
                hi[ax] = hi[ax].max(q.position[ax]);
            }
        }
    }
    let tol = slack * mm + 1e-9 * mm;
    for ax in 0..D {
        prop_assert!(
            b.position[ax].min >= lo[ax] - tol,
            "axis {ax}: box min {} < sampled {} - {tol:e}",
            b.position[ax].min,
            lo[ax]
        );
        prop_assert!(
            b.position[ax].max <= hi[ax] + tol,
            "axis {ax}: box max {} > sampled {} + {tol:e}",
            b.position[ax].max,
            hi[ax]
        );
    }
    Ok(())
}
