//! Checks the B-spline, NURBS and surface evaluators against independent reference data.
//!
//! The data in `tests/data/spline_*.json` and `tests/data/surface_random.json` is produced by
//! `scripts/reference/make_spline_reference.py` (scipy's `BSpline` for B-splines, the rational
//! formula `R_i = w_i N_i / sum_j w_j N_j` on an mpmath Cox-de Boor basis for NURBS, and
//! mpmath tensor-product sums for surfaces; each cross-checked by a second method). See
//! `scripts/reference/README.md` for how to regenerate it. Tolerances, with `M` the largest
//! |control coordinate| of the case, `p` the degree, `h` the smallest positive
//! `u_{i+p+1} - u_{i+1}` and `r = w_max / w_min` (1 without weights):
//!
//! * position: `1e-12 * M`; truth / indeterminacy / falsity: `1e-12` absolute;
//! * first derivative (and each partial derivative of a surface, with that direction's `p`,
//!   `h`): `1e-12 * 2 p r / h` times `M` for positions, times 1 for degrees; `2 p M r / h`
//!   bounds the derivative's magnitude.
//!
//! Convention: right-hand values at interior knots (also at a knot of multiplicity `p + 1`,
//! where the curve jumps), left-hand at the domain end.

use neutrospline::{
    AnyCurve, BSpline, ControlPoint, Degrees, Derivative, Direction, Evaluate, EvaluateSurface,
    KnotVector, NeutrosophicPoint, Nurbs, Surface,
};
use serde::Deserialize;

use crate::reference_common::{
    channel_name, derivative_channels, point_channels, read_data, Checker,
};

// ------------------------------------------------------------------------ data files

// Inputs (knots, weights, control values, parameters) are strings in the data files and are
// parsed with `str::parse`, which is correctly rounded: serde_json's default float parser is
// not, and can move a parameter by one ulp (for example from just left of a knot onto it).

fn exact<'de, De: serde::Deserializer<'de>>(d: De) -> Result<f64, De::Error> {
    let s = String::deserialize(d)?;
    s.parse()
        .map_err(|e| serde::de::Error::custom(format!("{s:?} is not a number: {e}")))
}

fn exact_vec<'de, De: serde::Deserializer<'de>>(d: De) -> Result<Vec<f64>, De::Error> {
    Vec::<String>::deserialize(d)?
        .into_iter()
        .map(|s| {
            s.parse()
                .map_err(|e| serde::de::Error::custom(format!("{s:?} is not a number: {e}")))
        })
        .collect()
}

fn exact_opt_vec<'de, De: serde::Deserializer<'de>>(d: De) -> Result<Option<Vec<f64>>, De::Error> {
    exact_vec(d).map(Some)
}

#[derive(Debug, Deserialize)]
struct ControlPointJson {
    #[serde(deserialize_with = "exact_vec")]
    position: Vec<f64>,
    #[serde(deserialize_with = "exact")]
    truth: f64,
    #[serde(deserialize_with = "exact")]
    indeterminacy: f64,
    #[serde(deserialize_with = "exact")]
    falsity: f64,
}

#[derive(Debug, Deserialize)]
struct CurveEvaluationJson {
    #[serde(deserialize_with = "exact")]
    t: f64,
    /// Set where the value did not come from the file's main method.
    #[serde(default)]
    #[allow(dead_code)]
    source: Option<String>,
    value: Vec<f64>,
    derivative: Vec<f64>,
}

#[derive(Debug, Deserialize)]
struct CurveCaseJson {
    name: String,
    dimension: usize,
    degree: usize,
    clamped: bool,
    #[serde(deserialize_with = "exact_vec")]
    knots: Vec<f64>,
    control_points: Vec<ControlPointJson>,
    #[serde(default, deserialize_with = "exact_opt_vec")]
    weights: Option<Vec<f64>>,
    evaluations: Vec<CurveEvaluationJson>,
}

#[derive(Debug, Deserialize)]
struct CurveFile {
    cases: Vec<CurveCaseJson>,
}

#[derive(Debug, Deserialize)]
struct SurfaceEvaluationJson {
    #[serde(deserialize_with = "exact")]
    u: f64,
    #[serde(deserialize_with = "exact")]
    v: f64,
    value: Vec<f64>,
    du: Vec<f64>,
    dv: Vec<f64>,
}

#[derive(Debug, Deserialize)]
struct SurfaceCaseJson {
    name: String,
    kind: String,
    rows: usize,
    cols: usize,
    degree_u: usize,
    degree_v: usize,
    #[serde(deserialize_with = "exact_vec")]
    knots_u: Vec<f64>,
    #[serde(deserialize_with = "exact_vec")]
    knots_v: Vec<f64>,
    control_points: Vec<ControlPointJson>,
    #[serde(default, deserialize_with = "exact_opt_vec")]
    weights: Option<Vec<f64>>,
    evaluations: Vec<SurfaceEvaluationJson>,
}

#[derive(Debug, Deserialize)]
struct SurfaceFile {
    cases: Vec<SurfaceCaseJson>,
}

fn load_curves(name: &str) -> Vec<CurveCaseJson> {
    let file: CurveFile = serde_json::from_str(&read_data(name, "make_spline_reference.py"))
        .unwrap_or_else(|e| panic!("cannot parse tests/data/{name}: {e}"));
    assert!(!file.cases.is_empty(), "{name} holds no cases");
    file.cases
}

fn control_points<const D: usize>(name: &str, cps: &[ControlPointJson]) -> Vec<ControlPoint<D>> {
    cps.iter()
        .enumerate()
        .map(|(i, cp)| {
            let position: [f64; D] = cp.position.as_slice().try_into().unwrap_or_else(|_| {
                panic!(
                    "{name}: control point {i} has {} coordinates, expected {D}",
                    cp.position.len()
                )
            });
            let degrees = Degrees::new(cp.truth, cp.indeterminacy, cp.falsity)
                .unwrap_or_else(|e| panic!("{name}: control point {i}: {e}"));
            NeutrosophicPoint::new(position, degrees)
        })
        .collect()
}

// ------------------------------------------------------------------------ tolerances

/// Largest |coordinate| over the control points.
fn position_scale(cps: &[ControlPointJson]) -> f64 {
    cps.iter()
        .flat_map(|cp| cp.position.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()))
}

/// `2 p r / h`: with `M`, a bound on the first derivative (see the module docs).
fn derivative_scale(knots: &[f64], p: usize, weights: Option<&[f64]>) -> f64 {
    let n = knots.len() - p - 1;
    let h = (0..n.saturating_sub(1))
        .map(|i| knots[i + p + 1] - knots[i + 1])
        .filter(|&s| s > 0.0)
        .fold(f64::INFINITY, f64::min);
    let h = if h.is_finite() { h } else { 1.0 };
    let ratio = weights.map_or(1.0, |w| {
        let hi = w.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let lo = w.iter().copied().fold(f64::INFINITY, f64::min);
        hi / lo
    });
    2.0 * p as f64 * ratio / h
}

const REL: f64 = 1e-12;

// ------------------------------------------------------------------------ comparison

// ------------------------------------------------------------------------ curves

fn curve_band(case: &CurveCaseJson) -> String {
    let kind = if case.weights.is_some() {
        "nurbs"
    } else {
        "bspline"
    };
    let discontinuous = {
        let (p, k) = (case.degree, &case.knots);
        let n = k.len() - p - 1;
        k.iter()
            .filter(|&&x| k[p] < x && x < k[n])
            .any(|&x| k.iter().filter(|&&y| y == x).count() > p)
    };
    let degrees = match case.degree {
        0..=3 => "p  0..3",
        4..=7 => "p  4..7",
        _ => "p  9..15",
    };
    if case.name.contains("circle") {
        format!("{kind} circle")
    } else if discontinuous {
        format!("{kind} discontinuous")
    } else {
        format!("{kind} {degrees}")
    }
}

/// Evaluates the curve (as itself and as an `AnyCurve`) at every reference parameter with
/// every evaluator, checks they agree bitwise, and compares with the reference.
fn check_curve_case<const D: usize>(checker: &mut Checker, case: &CurveCaseJson) {
    let name = &case.name;
    let points = control_points::<D>(name, &case.control_points);
    let knots = KnotVector::new(case.knots.clone(), case.degree, points.len())
        .unwrap_or_else(|e| panic!("{name}: KnotVector::new: {e}"));
    checker.check(knots.is_clamped() == case.clamped, || {
        format!("{name}: is_clamped() = {}", knots.is_clamped())
    });
    let curve: AnyCurve<D> = match &case.weights {
        None => BSpline::new(points, knots)
            .unwrap_or_else(|e| panic!("{name}: BSpline::new: {e}"))
            .into(),
        Some(w) => Nurbs::new(points, w.clone(), knots)
            .unwrap_or_else(|e| panic!("{name}: Nurbs::new: {e}"))
            .into(),
    };
    assert_eq!(curve.degree(), case.degree, "{name}: degree()");
    let band = curve_band(case);
    let value_tol = |c: usize| {
        if c < D {
            REL * position_scale(&case.control_points)
        } else {
            REL
        }
    };
    let d_scale = derivative_scale(&case.knots, case.degree, case.weights.as_deref());
    let derivative_tol = |c: usize| {
        if c < D {
            REL * d_scale * position_scale(&case.control_points)
        } else {
            REL * d_scale
        }
    };

    let ts: Vec<f64> = case.evaluations.iter().map(|e| e.t).collect();
    let m = ts.len();
    let mut many = vec![curve.start().unwrap(); m];
    curve
        .evaluate_many(&ts, &mut many)
        .unwrap_or_else(|e| panic!("{name}: evaluate_many: {e}"));

    for (k, e) in case.evaluations.iter().enumerate() {
        let t = e.t;
        let at = format!("{name}: t = {t:e}");
        assert_eq!(e.value.len(), D + 3, "{at}: reference value length");
        assert_eq!(
            e.derivative.len(),
            D + 3,
            "{at}: reference derivative length"
        );
        let own = match &curve {
            AnyCurve::BSpline(c) => c.evaluate(t),
            AnyCurve::Nurbs(c) => c.evaluate(t),
            AnyCurve::Bezier(c) => c.evaluate(t),
        }
        .unwrap_or_else(|err| panic!("{at}: evaluate: {err}"));
        let own_d = match &curve {
            AnyCurve::BSpline(c) => c.derivative().evaluate(t),
            AnyCurve::Nurbs(c) => c.derivative().evaluate(t),
            AnyCurve::Bezier(c) => c.derivative().evaluate(t),
        }
        .unwrap_or_else(|err| panic!("{at}: derivative: {err}"));
        let any = curve.evaluate(t).unwrap();
        let any_d = curve.derivative().evaluate(t).unwrap();
        let (got, got_d) = (point_channels(&own), derivative_channels(&own_d));
        let (got_any, got_any_d) = (point_channels(&any), derivative_channels(&any_d));
        let got_many = point_channels(&many[k]);
        for c in 0..D + 3 {
            let ch = channel_name(c, D);
            checker.same_bits(&at, "AnyCurve::evaluate != evaluate", got_any[c], got[c]);
            checker.same_bits(
                &at,
                "AnyCurve::derivative != derivative",
                got_any_d[c],
                got_d[c],
            );
            checker.same_bits(&at, "evaluate_many != evaluate", got_many[c], got[c]);
            checker.close(&band, &at, "value", ch, got[c], e.value[c], value_tol(c));
            checker.close(
                &band,
                &at,
                "derivative",
                ch,
                got_d[c],
                e.derivative[c],
                derivative_tol(c),
            );
        }
        // The library's own validity check accepts every evaluated point.
        let [tr, i, f] = own.degrees.to_array();
        checker.check(Degrees::new(tr, i, f).is_ok(), || {
            format!("{at}: invalid degrees {own:?}")
        });
        if case.name.contains("circle") {
            // A circle is a circle: exactly, up to the rounding of x^2 + y^2.
            let r = own.position[0].hypot(own.position[1]);
            checker.check((r - 1.0).abs() <= 2.0 * f64::EPSILON, || {
                format!("{at}: |C(t)| = {r:e}, off the unit circle by {:e}", r - 1.0)
            });
        }
    }
    // The domain ends: start() / end() are the evaluations there.
    let (a, b) = (curve.domain().start, curve.domain().end);
    assert_eq!(
        curve.start().unwrap(),
        curve.evaluate(a).unwrap(),
        "{name}: start()"
    );
    assert_eq!(
        curve.end().unwrap(),
        curve.evaluate(b).unwrap(),
        "{name}: end()"
    );
}

fn check_curve_file(file: &str, test: &str) {
    let cases = load_curves(file);
    let mut checker = Checker::default();
    for case in &cases {
        match case.dimension {
            2 => check_curve_case::<2>(&mut checker, case),
            3 => check_curve_case::<3>(&mut checker, case),
            d => panic!("{}: unsupported dimension {d}", case.name),
        }
    }
    checker.finish(test);
}

#[test]
fn bspline_curves_match_scipy() {
    let cases = load_curves("spline_bspline.json");
    assert!(cases.iter().all(|c| c.weights.is_none()));
    // The data covers what it claims to: every degree 0..=7, 2-D and 3-D, both knot styles,
    // discontinuities.
    for p in 0..=7 {
        for d in [2, 3] {
            assert!(cases
                .iter()
                .any(|c| c.degree == p && c.dimension == d && c.clamped));
            // (every degree-0 knot vector counts as clamped)
            assert!(
                p == 0
                    || cases
                        .iter()
                        .any(|c| c.degree == p && c.dimension == d && !c.clamped)
            );
        }
    }
    assert!(cases.iter().any(|c| c.degree == 15));
    assert!(
        cases
            .iter()
            .filter(|c| curve_band(c).contains("discontinuous"))
            .count()
            >= 6
    );
    check_curve_file("spline_bspline.json", "bspline_curves_match_scipy");
}

#[test]
fn nurbs_curves_match_the_rational_formula() {
    let cases = load_curves("spline_nurbs.json");
    assert!(cases.iter().all(|c| c.weights.is_some()));
    assert!(cases.iter().any(|c| c.name == "nurbs_quarter_circle"));
    assert!(cases.iter().any(|c| c.name == "nurbs_full_circle"));
    check_curve_file(
        "spline_nurbs.json",
        "nurbs_curves_match_the_rational_formula",
    );
}

// ------------------------------------------------------------------------ surfaces

fn build_surface(case: &SurfaceCaseJson) -> Surface {
    let name = &case.name;
    let points = control_points::<3>(name, &case.control_points);
    let knots = |k: &[f64], p: usize, count: usize| {
        KnotVector::new(k.to_vec(), p, count).unwrap_or_else(|e| panic!("{name}: knots: {e}"))
    };
    let built = match case.kind.as_str() {
        "bezier" => Surface::bezier(case.rows, case.cols, points),
        "bspline" => Surface::bspline(
            case.rows,
            case.cols,
            points,
            knots(&case.knots_u, case.degree_u, case.rows),
            knots(&case.knots_v, case.degree_v, case.cols),
        ),
        "nurbs" => Surface::nurbs(
            case.rows,
            case.cols,
            points,
            case.weights.clone().expect("nurbs case without weights"),
            knots(&case.knots_u, case.degree_u, case.rows),
            knots(&case.knots_v, case.degree_v, case.cols),
        ),
        other => panic!("{name}: unknown kind {other}"),
    };
    let s = built.unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(
        (s.degree_u(), s.degree_v()),
        (case.degree_u, case.degree_v),
        "{name}"
    );
    s
}

#[test]
fn surfaces_match_tensor_products() {
    let file: SurfaceFile = serde_json::from_str(&read_data(
        "surface_random.json",
        "make_spline_reference.py",
    ))
    .expect("cannot parse tests/data/surface_random.json");
    assert!(!file.cases.is_empty());
    let mut checker = Checker::default();
    for case in &file.cases {
        let s = build_surface(case);
        let band = format!("{} surface", case.kind);
        let m = position_scale(&case.control_points);
        let w = case.weights.as_deref();
        let su = derivative_scale(&case.knots_u, case.degree_u, w);
        let sv = derivative_scale(&case.knots_v, case.degree_v, w);
        let tol = |c: usize, scale: f64| REL * scale * if c < 3 { m } else { 1.0 };
        for e in &case.evaluations {
            let (u, v) = (e.u, e.v);
            let at = format!("{}: (u, v) = ({u:e}, {v:e})", case.name);
            let p = s.evaluate(u, v).unwrap_or_else(|err| panic!("{at}: {err}"));
            let d = s
                .partial_derivatives(u, v)
                .unwrap_or_else(|err| panic!("{at}: {err}"));
            let (got, du, dv) = (
                point_channels(&p),
                derivative_channels(&d.du),
                derivative_channels(&d.dv),
            );
            // Iso-curves through the point reproduce it.
            let iso_u = s.iso_curve(Direction::U, u).unwrap().evaluate(v).unwrap();
            let iso_v = s.iso_curve(Direction::V, v).unwrap().evaluate(u).unwrap();
            for c in 0..6 {
                let ch = channel_name(c, 3);
                checker.close(&band, &at, "value", ch, got[c], e.value[c], tol(c, 1.0));
                checker.close(&band, &at, "du", ch, du[c], e.du[c], tol(c, su));
                checker.close(&band, &at, "dv", ch, dv[c], e.dv[c], tol(c, sv));
                let iso = (point_channels(&iso_u)[c], point_channels(&iso_v)[c]);
                checker.close(
                    &band,
                    &at,
                    "iso-curve u",
                    ch,
                    iso.0,
                    e.value[c],
                    tol(c, 1.0),
                );
                checker.close(
                    &band,
                    &at,
                    "iso-curve v",
                    ch,
                    iso.1,
                    e.value[c],
                    tol(c, 1.0),
                );
            }
            let [tr, i, f] = p.degrees.to_array();
            checker.check(Degrees::new(tr, i, f).is_ok(), || {
                format!("{at}: invalid degrees")
            });
        }
    }
    checker.finish("surfaces_match_tensor_products");
}
