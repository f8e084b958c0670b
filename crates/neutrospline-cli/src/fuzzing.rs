//! The bodies of the fuzz targets, shared by `fuzz/` (cargo-fuzz, nightly) and the corpus replay
//! test `tests/integration/fuzz_corpus.rs` (stable, run by CI).
//!
//! Each function takes arbitrary bytes and panics only when a property is broken:
//! - [`csv_model`], [`toml_model`], [`json_model`]: parsing never panics; an error names the
//!   file; a model that parses and builds is evaluated and must satisfy [`check_shape`], and
//!   written in every format it reads back to an equal model (`neutrospline-io`'s writers).
//! - [`evaluate`]: control points, knots, weights and parameters decoded from the bytes are
//!   given to the core directly; whatever the core accepts must satisfy docs/model.md section 4.
//! - [`dxf_model`], [`svg_model`]: importing never panics; an error names the file; every curve
//!   imported satisfies [`check_shape`], writes as TOML, JSON and CSV to files that read back
//!   equal, and exported to DXF imports back to an equal model.
//!
//! The properties checked for a valid shape ([`check_shape`]): every evaluated degree lies in
//! \[0, 1\] and within the range of its control values, positions are finite and inside the
//! control points' bounding box (the convex hull property, weakened), clamped curves interpolate
//! their end control points, and derivatives are either finite or an `Overflow` error, never a
//! silent infinity or NaN.

use std::ops::Range;

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, ControlPolygon, Degrees, Derivative, EvalError,
    Evaluate, EvaluateSurface, Family, KnotVector, Nurbs, Surface,
};

use neutrospline_exchange::{ExportFormat, ExportOptions};
use neutrospline_io::{Format, Kind, KnotRule, KnotSpec, Limits, Model, ReadError, ReadOptions};

use crate::shape::{Extras, Param, Shape, Table};

/// The name the fuzzed file is given in messages.
const FILE: &str = "fuzz-input";

/// Control points beyond this are not evaluated (keeps each run fast).
const MAX_EVAL_POINTS: usize = 4096;

/// Fuzzes the CSV reader under several command-line settings (every kind, every rule).
pub fn csv_model(data: &[u8]) {
    use neutrospline::{CurveKind, SurfaceKind};
    // `ReadOptions` is non-exhaustive: built by assignment.
    let options = |set: &dyn Fn(&mut ReadOptions)| {
        let mut options = ReadOptions::default();
        set(&mut options);
        options
    };
    let settings = [
        ReadOptions::default(),
        options(&|o| o.membership = Some(Family::Intuitionistic)),
        options(&|o| o.membership = Some(Family::Fuzzy)),
        options(&|o| {
            o.kind = Some(Kind::Curve(CurveKind::BSpline));
            o.degree = Some(2);
        }),
        options(&|o| {
            o.kind = Some(Kind::Curve(CurveKind::BSpline));
            o.degree = Some(2);
            o.knots = Some(KnotSpec::Rule(KnotRule::ChordLength));
        }),
        options(&|o| {
            o.kind = Some(Kind::Curve(CurveKind::Nurbs));
            o.degree = Some(2);
        }),
        options(&|o| {
            o.kind = Some(Kind::Surface(SurfaceKind::Bezier));
            o.rows = Some(2);
            o.cols = Some(2);
        }),
        options(&|o| {
            o.kind = Some(Kind::Surface(SurfaceKind::Nurbs));
            o.rows = Some(3);
            o.cols = Some(3);
            o.degree_u = Some(1);
            o.degree_v = Some(2);
        }),
    ];
    for options in &settings {
        model(Format::Csv, data, options);
    }
}

/// Fuzzes the TOML reader.
pub fn toml_model(data: &[u8]) {
    model(Format::Toml, data, &ReadOptions::default());
}

/// Fuzzes the JSON reader.
pub fn json_model(data: &[u8]) {
    model(Format::Json, data, &ReadOptions::default());
}

fn model(format: Format, data: &[u8], options: &ReadOptions) {
    match neutrospline_io::parse(FILE, format, data, options) {
        Ok(model) => {
            check_shape(model.shape());
            check_round_trip(&model, format);
        }
        Err(e) => check_input_error(&e),
    }
}

/// A reader's error for bad content: it names the file and fits on one line.
fn check_input_error(error: &ReadError) {
    match error {
        ReadError::Input(e) => {
            assert_eq!(e.file, FILE);
            assert!(!e.message.is_empty());
            // One line on stderr, whatever the file holds.
            assert!(!e.to_string().contains(['\n', '\r']), "{e}");
        }
        e => panic!("not an input error: {e}"),
    }
}

/// The options of the importers: every kind, and the degrees of control points without their
/// own.
fn import_defaults() -> neutrospline_exchange::ImportOptions {
    neutrospline_exchange::ImportOptions::new(
        Degrees::new(0.75, 0.125, 0.25).unwrap_or_else(|e| panic!("{e}")),
    )
}

/// Fuzzes the DXF importer.
pub fn dxf_model(data: &[u8]) {
    imported(
        "DXF",
        neutrospline_exchange::parse_dxf(FILE, data, &import_defaults(), &Limits::default())
            .map(|i| i.models),
    );
}

/// Fuzzes the SVG importer.
pub fn svg_model(data: &[u8]) {
    imported(
        "SVG",
        neutrospline_exchange::parse_svg(FILE, data, &import_defaults(), &Limits::default())
            .map(|i| i.models),
    );
}

/// The checks of the curves an importer read from `read_as` (the first few of them).
fn imported(read_as: &str, result: Result<Vec<Model>, ReadError>) {
    let models = match result {
        Ok(models) => models,
        Err(e) => return check_input_error(&e),
    };
    for model in models.iter().take(8) {
        if model.shape().control_count() > MAX_EVAL_POINTS {
            continue;
        }
        check_shape(model.shape());
        check_round_trip(model, read_as);
        let dxf = neutrospline_exchange::export(model, ExportFormat::Dxf, &ExportOptions::new())
            .unwrap_or_else(|e| panic!("{read_as} read, DXF export: {e}"));
        let back =
            neutrospline_exchange::parse_dxf(FILE, &dxf, &import_defaults(), &Limits::default())
                .map(|i| i.models)
                .unwrap_or_else(|e| panic!("{read_as} read, DXF written, read back: {e}"));
        assert_eq!(
            back,
            std::slice::from_ref(model),
            "{read_as} read, DXF written"
        );
    }
}

/// A model that was read writes in every format to a file that reads back to the same model
/// (CSV: with the options [`Model::csv_read_options`] gives, without the name
/// and description; control point names that a CSV cell cannot hold are refused).
fn check_round_trip(model: &Model, read_as: impl std::fmt::Display) {
    if model.shape().control_count() > MAX_EVAL_POINTS {
        return;
    }
    for format in Format::ALL {
        let text = match neutrospline_io::to_string(model, format) {
            Ok(text) => text,
            Err(e) => {
                assert_eq!(format, Format::Csv, "{e}");
                continue;
            }
        };
        let options = if format == Format::Csv {
            model.csv_read_options()
        } else {
            ReadOptions::default()
        };
        let back = neutrospline_io::parse(FILE, format, text.as_bytes(), &options)
            .unwrap_or_else(|e| panic!("{read_as} read, {format} written, read back: {e}\n{text}"));
        let expected = if format == Format::Csv {
            // A CSV file holds no name or description.
            Model::new(model.shape().clone())
                .with_membership(model.membership())
                .and_then(|m| m.with_point_names(model.point_names().to_vec()))
                .unwrap_or_else(|e| panic!("{e}"))
        } else {
            model.clone()
        };
        assert_eq!(back, expected, "{read_as} read, {format} written:\n{text}");
    }
}

/// Reads numbers and small integers from fuzz bytes.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }

    /// A float: mostly small "nice" values, sometimes any bit pattern (huge, tiny, NaN).
    fn float(&mut self) -> f64 {
        match self.byte() % 4 {
            0 => f64::from(self.byte()) / 255.0,
            1 => f64::from(self.byte() as i8) / 8.0,
            2 => {
                let mut raw = [0u8; 8];
                for b in &mut raw {
                    *b = self.byte();
                }
                f64::from_le_bytes(raw)
            }
            _ => f64::from(self.byte() as i8) * 1e306,
        }
    }

    fn degrees(&mut self) -> Option<Degrees> {
        Degrees::new(self.float(), self.float(), self.float()).ok()
    }
}

/// Fuzzes the core directly: a curve or surface of any kind from arbitrary control points,
/// knots, weights and parameters.
pub fn evaluate(data: &[u8]) {
    let mut b = Bytes(data);
    let selector = b.byte();
    let count = usize::from(b.byte() % 12) + 1;
    let degree = usize::from(b.byte() % 6);
    match selector % 5 {
        0..=2 => {
            let mut points: Vec<ControlPoint<2>> = Vec::with_capacity(count);
            for _ in 0..count {
                let position = [b.float(), b.float()];
                let Some(degrees) = b.degrees() else { return };
                points.push(ControlPoint::new(position, degrees));
            }
            let knots = || -> Option<KnotVector> {
                let mut kb = Bytes(data.get(data.len() / 2..).unwrap_or_default());
                if kb.byte() % 2 == 0 {
                    KnotVector::clamped_uniform(degree, count).ok()
                } else {
                    let values = (0..count + degree + 1).map(|_| kb.float()).collect();
                    KnotVector::new(values, degree, count).ok()
                }
            };
            let curve = match selector % 5 {
                0 => Bezier::new(points).ok().map(AnyCurve::Bezier),
                1 => knots().and_then(|k| BSpline::new(points, k).ok().map(AnyCurve::BSpline)),
                _ => {
                    let weights = (0..count).map(|_| b.float()).collect();
                    knots().and_then(|k| Nurbs::new(points, weights, k).ok().map(AnyCurve::Nurbs))
                }
            };
            if let Some(curve) = curve {
                // Arbitrary parameters: an error or a valid point, never a panic.
                for _ in 0..4 {
                    let t = b.float();
                    if let Ok(p) = curve.evaluate(t) {
                        assert!(p.position.iter().all(|c| c.is_finite()), "t = {t}: {p:?}");
                    }
                    if let Ok(d) = curve.derivative().evaluate(t) {
                        assert!(finite_rates(&d), "t = {t}: {d:?}");
                    }
                }
                check_shape(&Shape::from(curve));
            }
        }
        _ => {
            let rows = count.min(4);
            let cols = usize::from(b.byte() % 4) + 1;
            let mut points: Vec<ControlPoint<3>> = Vec::with_capacity(rows * cols);
            for _ in 0..rows * cols {
                let position = [b.float(), b.float(), b.float()];
                let Some(degrees) = b.degrees() else { return };
                points.push(ControlPoint::new(position, degrees));
            }
            let surface = if selector % 5 == 3 {
                Surface::bezier(rows, cols, points).ok()
            } else {
                let du = degree.min(rows.saturating_sub(1));
                let dv = usize::from(b.byte() % 4).min(cols.saturating_sub(1));
                let weights = (0..rows * cols).map(|_| b.float()).collect();
                match (
                    KnotVector::clamped_uniform(du, rows),
                    KnotVector::clamped_uniform(dv, cols),
                ) {
                    (Ok(ku), Ok(kv)) => Surface::nurbs(rows, cols, points, weights, ku, kv).ok(),
                    _ => None,
                }
            };
            if let Some(surface) = surface {
                check_shape(&Shape::Surface(surface));
            }
        }
    }
}

fn finite_rates<const D: usize>(d: &neutrospline::DerivativeValue<D>) -> bool {
    d.position
        .iter()
        .chain([&d.truth, &d.indeterminacy, &d.falsity])
        .all(|v| v.is_finite())
}

/// `count` parameters spread over `[a, b]`, ends included.
fn spread(count: u32, Range { start: a, end: b }: Range<f64>) -> impl Iterator<Item = f64> {
    (0..=count).map(move |k| {
        if k == 0 {
            a
        } else if k == count {
            b
        } else {
            (a + (b - a) * (f64::from(k) / f64::from(count))).clamp(a, b)
        }
    })
}

/// Within `tolerance` of `[lo, hi]`.
fn within(value: f64, lo: f64, hi: f64, tolerance: f64) -> bool {
    value >= lo - tolerance && value <= hi + tolerance
}

/// Checks the properties of docs/model.md section 4 on a valid shape, and that the command's own row
/// sampler (with derivatives and normals) either succeeds with finite values or reports an
/// error: never a panic, never a silent infinity or NaN.
///
/// # Panics
/// When a property is broken (that is the point).
pub fn check_shape(shape: &Shape) {
    match shape {
        Shape::Curve(c) => neutrospline::on_dimension!(c, c => check_curve(c)),
        Shape::Surface(s) => check_surface(s),
    }
    let extras = Extras {
        derivative: 3,
        normal: shape.is_surface(),
        scores: true,
        geometry: !shape.is_surface(),
        ..Extras::default()
    };
    let sampler = shape.sampler(extras);
    let params: Vec<Param> = match shape {
        Shape::Surface(s) => spread(3, s.domain()[0].clone())
            .flat_map(|u| spread(3, s.domain()[1].clone()).map(move |v| Param::Uv(u, v)))
            .collect(),
        _ => spread(8, shape.curve_domain().unwrap_or(0.0..1.0))
            .map(Param::T)
            .collect(),
    };
    for param in params {
        if let Ok(row) = sampler.row(param) {
            assert!(
                row.iter().flatten().all(|v| v.is_finite()),
                "{param}: {row:?}"
            );
        }
    }
}

fn bounds<const D: usize>(points: &[ControlPoint<D>]) -> ([f64; D], [f64; D], [[f64; 2]; 3]) {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    let mut degrees = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
    for p in points {
        for k in 0..D {
            lo[k] = lo[k].min(p.position[k]);
            hi[k] = hi[k].max(p.position[k]);
        }
        for (range, v) in degrees.iter_mut().zip(p.degrees.to_array()) {
            range[0] = range[0].min(v);
            range[1] = range[1].max(v);
        }
    }
    (lo, hi, degrees)
}

fn check_point<const D: usize>(
    at: &str,
    p: &neutrospline::CurvePoint<D>,
    (lo, hi, degrees): &([f64; D], [f64; D], [[f64; 2]; 3]),
) {
    for (k, &c) in p.position.iter().enumerate() {
        assert!(c.is_finite(), "{at}: position {c}");
        let tolerance = 1e-9 * (1.0 + lo[k].abs().max(hi[k].abs()));
        assert!(
            within(c, lo[k], hi[k], tolerance),
            "{at}: coordinate {k} = {c} outside the control points' range [{}, {}]",
            lo[k],
            hi[k]
        );
    }
    for (range, v) in degrees.iter().zip(p.degrees.to_array()) {
        assert!((0.0..=1.0).contains(&v), "{at}: degree {v} outside [0, 1]");
        assert!(
            within(v, range[0], range[1], 1e-12),
            "{at}: degree {v} outside the control values' range {range:?}"
        );
    }
}

fn check_curve<const D: usize>(curve: &AnyCurve<D>) {
    if curve.len() > MAX_EVAL_POINTS {
        return;
    }
    let points = curve.control_points();
    let b = bounds(&points);
    let domain = curve.domain();
    let derivative = curve.derivative();
    for t in spread(16, domain.clone()) {
        match curve.evaluate(t) {
            Ok(p) => check_point(&format!("t = {t}"), &p, &b),
            Err(e) => panic!("t = {t} inside the domain {domain:?}: {e}"),
        }
        match derivative.evaluate(t) {
            Ok(d) => assert!(finite_rates(&d), "t = {t}: {d:?}"),
            Err(EvalError::Overflow { .. }) => {}
            Err(e) => panic!("derivative at t = {t}: {e}"),
        }
    }
    let clamped = curve.knots().is_none_or(KnotVector::is_clamped);
    if clamped {
        let ends = [
            (domain.start, points[0]),
            (domain.end, points[points.len() - 1]),
        ];
        for (t, control) in ends {
            let p = curve.evaluate(t).expect("end of the domain");
            for k in 0..D {
                let scale = 1.0 + b.0[k].abs().max(b.1[k].abs());
                assert!(
                    (p.position[k] - control.position[k]).abs() <= 1e-9 * scale,
                    "t = {t}: {p:?} does not interpolate {control:?}"
                );
            }
            for (v, c) in p
                .degrees
                .to_array()
                .into_iter()
                .zip(control.degrees.to_array())
            {
                assert!((v - c).abs() <= 1e-12, "t = {t}: {p:?} vs {control:?}");
            }
        }
    }
}

fn check_surface(surface: &Surface) {
    if surface.rows() * surface.cols() > MAX_EVAL_POINTS {
        return;
    }
    let b = bounds(&surface.control_points());
    let [domain_u, domain_v] = surface.domain();
    for u in spread(4, domain_u) {
        for v in spread(4, domain_v.clone()) {
            match surface.evaluate(u, v) {
                Ok(p) => check_point(&format!("u = {u}, v = {v}"), &p, &b),
                Err(e) => panic!("u = {u}, v = {v} inside the domain: {e}"),
            }
        }
    }
}
