//! The fit itself: parameters, knots, the basis matrix, the normal equations, the tolerance
//! loop, the bounded degree channels and the report.

use super::banded::{Band, CyclicBand, Factor, Normal};
use super::knots::{
    clamped, interpolation_knots, least_squares_knots, parameters, periodic_base, periodic_knots,
};
use super::report::{AtBound, FitReport};
use super::{
    basis, channel_names, qp, DataWeights, Fit, FitData, FitError, FitKind, FitOptions, FitTarget,
};
use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::degrees::{Degrees, Membership};
use crate::knots::KnotVector;
use crate::point::ControlPoint;
use crate::spline_curve::BSpline;

/// The most knot refinements of a tolerance fit, and the highest degree a Bézier tolerance
/// fit tries.
const MAX_REFINEMENTS: usize = 64;
const MAX_BEZIER_DEGREE: usize = 30;

/// The spline being fitted: degree, knots and how the unknowns map to basis functions.
#[derive(Clone, Debug)]
struct Layout {
    p: usize,
    /// The output's knots (for a periodic spline, the unclamped vector of
    /// [`periodic_knots`]).
    knots: Vec<f64>,
    /// Unknown control points (a periodic spline's distinct ones).
    n: usize,
    periodic: bool,
}

impl Layout {
    fn open(p: usize, knots: Vec<f64>) -> Layout {
        let n = knots.len() - p - 1;
        Layout {
            p,
            knots,
            n,
            periodic: false,
        }
    }

    fn closed(p: usize, base: &[f64]) -> Layout {
        Layout {
            p,
            knots: periodic_knots(base, p),
            n: base.len(),
            periodic: true,
        }
    }

    fn domain(&self) -> (f64, f64) {
        (
            self.knots[self.p],
            self.knots[self.knots.len() - 1 - self.p],
        )
    }

    /// The basis functions (or their derivatives of `order`) at `t` into `values[..=p]`;
    /// returns the unknown of the first (the others follow, cyclically when periodic).
    fn row(&self, t: f64, order: usize, values: &mut [f64]) -> usize {
        let p = self.p;
        let k = basis::span(&self.knots, p, t);
        if order == 0 {
            basis::values(&self.knots, p, k, t, values);
        } else {
            let mut all = vec![0.0; (order + 1) * (p + 1)];
            basis::derivatives(&self.knots, p, k, t, order, &mut all);
            values[..=p].copy_from_slice(&all[order * (p + 1)..]);
        }
        (k - p) % self.n.max(1)
    }

    fn index(&self, first: usize, r: usize) -> usize {
        if self.periodic {
            (first + r) % self.n
        } else {
            first + r
        }
    }

    fn normal(&self) -> Normal {
        if self.periodic {
            Normal::Closed(CyclicBand::zeros(self.n, self.p))
        } else {
            Normal::Open(Band::zeros(self.n, self.p))
        }
    }

    /// The interior breakpoints' spans `[a, b]` of the domain.
    fn spans(&self) -> Vec<(f64, f64)> {
        let (a, b) = self.domain();
        let mut edges: Vec<f64> = self
            .knots
            .iter()
            .copied()
            .filter(|&k| k >= a && k <= b)
            .collect();
        edges.dedup();
        edges.windows(2).map(|w| (w[0], w[1])).collect()
    }
}

/// A row of the basis matrix: its first unknown and `p + 1` values.
struct Rows {
    p: usize,
    first: Vec<usize>,
    values: Vec<f64>,
}

impl Rows {
    fn new(layout: &Layout, params: &[f64]) -> Rows {
        let p = layout.p;
        let mut first = Vec::with_capacity(params.len());
        let mut values = vec![0.0; params.len() * (p + 1)];
        for (k, &t) in params.iter().enumerate() {
            first.push(layout.row(t, 0, &mut values[k * (p + 1)..(k + 1) * (p + 1)]));
        }
        Rows { p, first, values }
    }

    fn row(&self, k: usize) -> (usize, &[f64]) {
        let w = self.p + 1;
        (self.first[k], &self.values[k * w..(k + 1) * w])
    }

    /// `sum_r N_r x_{j_r}` at data point `k`.
    fn dot(&self, layout: &Layout, k: usize, x: &[f64]) -> f64 {
        let (first, values) = self.row(k);
        values
            .iter()
            .enumerate()
            .map(|(r, v)| v * x[layout.index(first, r)])
            .sum()
    }
}

/// Extra equations (end tangents of an interpolation): a row and a target per channel.
struct Extra {
    first: usize,
    values: Vec<f64>,
    targets: Vec<f64>,
}

/// The normal equations of one layout and their factorisation.
struct System<'a> {
    layout: &'a Layout,
    rows: Rows,
    weights: &'a [f64],
    extras: Vec<Extra>,
    /// `lambda R`, when smoothing.
    penalty: Option<Normal>,
    matrix: Normal,
    factor: Factor,
}

impl<'a> System<'a> {
    fn new(
        layout: &'a Layout,
        params: &[f64],
        weights: &'a [f64],
        extras: Vec<Extra>,
        lambda: f64,
    ) -> Result<System<'a>, FitError> {
        let rows = Rows::new(layout, params);
        let mut matrix = layout.normal();
        for k in 0..params.len() {
            let (first, values) = rows.row(k);
            add_outer(&mut matrix, layout, first, values, weights[k]);
        }
        for e in &extras {
            add_outer(&mut matrix, layout, e.first, &e.values, 1.0);
        }
        let penalty = (lambda > 0.0).then(|| second_derivative_gram(layout, lambda));
        if let Some(r) = &penalty {
            matrix.add_matrix(r);
        }
        let factor = matrix.factor().ok_or(FitError::Singular)?;
        Ok(System {
            layout,
            rows,
            weights,
            extras,
            penalty,
            matrix,
            factor,
        })
    }

    /// The right-hand side `N^T W q` (and the extras' rows) for one channel.
    fn rhs(&self, target: &dyn Fn(usize) -> f64, extra: usize) -> Vec<f64> {
        let mut b = vec![0.0; self.layout.n];
        for k in 0..self.weights.len() {
            let (first, values) = self.rows.row(k);
            let wq = self.weights[k] * target(k);
            for (r, v) in values.iter().enumerate() {
                b[self.layout.index(first, r)] += v * wq;
            }
        }
        for e in &self.extras {
            for (r, v) in e.values.iter().enumerate() {
                b[self.layout.index(e.first, r)] += v * e.targets[extra];
            }
        }
        b
    }

    /// The least-squares solution for one channel, with two steps of refinement against the
    /// data residuals (the gradient of the objective computed from `q - N x`, not from the
    /// normal equations), which recovers the accuracy the normal equations lose.
    fn solve(&self, target: &dyn Fn(usize) -> f64, extra: usize) -> Vec<f64> {
        let layout = self.layout;
        let mut x = self.rhs(target, extra);
        self.factor.solve(&mut x);
        for _ in 0..2 {
            let mut g = vec![0.0; layout.n];
            for k in 0..self.weights.len() {
                let residual = self.weights[k] * (target(k) - self.rows.dot(layout, k, &x));
                let (first, values) = self.rows.row(k);
                for (r, v) in values.iter().enumerate() {
                    g[layout.index(first, r)] += v * residual;
                }
            }
            for e in &self.extras {
                let value: f64 = e
                    .values
                    .iter()
                    .enumerate()
                    .map(|(r, v)| v * x[layout.index(e.first, r)])
                    .sum();
                let residual = e.targets[extra] - value;
                for (r, v) in e.values.iter().enumerate() {
                    g[layout.index(e.first, r)] += v * residual;
                }
            }
            if let Some(r) = &self.penalty {
                let mut rx = vec![0.0; layout.n];
                r.mul(&x, &mut rx);
                for (gi, ri) in g.iter_mut().zip(&rx) {
                    *gi -= ri;
                }
            }
            self.factor.solve(&mut g);
            for (xi, di) in x.iter_mut().zip(&g) {
                *xi += di;
            }
        }
        x
    }
}

/// Adds `w v v^T` at the unknowns of a row.
fn add_outer(matrix: &mut Normal, layout: &Layout, first: usize, values: &[f64], w: f64) {
    if w == 0.0 {
        return;
    }
    for (r, vr) in values.iter().enumerate() {
        let i = layout.index(first, r);
        for (s, vs) in values[..=r].iter().enumerate() {
            matrix.add(i, layout.index(first, s), w * vr * vs);
        }
    }
}

/// `lambda R`, `R_ij = int N_i'' N_j''` over the domain, by Gauss-Legendre quadrature with `p`
/// nodes per span (exact: the integrand has degree `2 (p - 2)`).
fn second_derivative_gram(layout: &Layout, lambda: f64) -> Normal {
    let p = layout.p;
    let mut r = layout.normal();
    let (nodes, weights) = gauss_legendre(p.max(1));
    let mut ders = vec![0.0; 3 * (p + 1)];
    for (a, b) in layout.spans() {
        let half = 0.5 * (b - a);
        for (x, w) in nodes.iter().zip(&weights) {
            let t = a + half * (x + 1.0);
            let k = basis::span(&layout.knots, p, t);
            basis::derivatives(&layout.knots, p, k, t, 2, &mut ders);
            let second = &ders[2 * (p + 1)..];
            let first = (k - p) % layout.n;
            add_outer(&mut r, layout, first, second, lambda * w * half);
        }
    }
    r
}

/// Gauss-Legendre nodes and weights on `[-1, 1]` (Newton's method on the Legendre
/// polynomial from the Chebyshev-like initial guesses).
fn gauss_legendre(count: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = Vec::with_capacity(count);
    let mut weights = Vec::with_capacity(count);
    for i in 0..count {
        let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (count as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=count {
                let pj = ((2 * j - 1) as f64 * x * p1 - (j - 1) as f64 * p0) / j as f64;
                p0 = p1;
                p1 = pj;
            }
            let pn = if count == 1 { x } else { p1 };
            let pm = if count == 1 { 1.0 } else { p0 };
            derivative = count as f64 * (x * pn - pm) / (x * x - 1.0);
            let dx = pn / derivative;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        nodes.push(x);
        weights.push(2.0 / ((1.0 - x * x) * derivative * derivative));
    }
    (nodes, weights)
}

/// The data's parameters on the curve: given, or by the parametrization.
fn data_parameters<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
) -> Result<Vec<f64>, FitError> {
    if let Some(given) = data.parameters() {
        if options.closed {
            if let Some((index, &value)) = given
                .iter()
                .enumerate()
                .find(|(_, t)| !(0.0..1.0).contains(*t))
            {
                return Err(FitError::Option(format!(
                    "point {index}: parameter {value} is outside [0, 1) (a closed curve's \
                     parameters have period 1)"
                )));
            }
        }
        return Ok(given.to_vec());
    }
    parameters(data.positions(), options.parametrization, options.closed).map_err(|index| {
        let previous = (index + data.len() - 1) % data.len();
        FitError::RepeatedParameter {
            index,
            previous,
            value: 0.0,
            rule: "a point repeats the previous one, so chord-length and centripetal \
                   parameters repeat too (remove it, give parameters, or use uniform ones)",
        }
    })
}

/// Runs the fit.
pub(super) fn run<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
) -> Result<Fit<D>, FitError> {
    let p = options.degree;
    let m = data.len();
    for (index, d) in data.degrees().iter().enumerate() {
        d.check_membership(options.membership)
            .map_err(|source| FitError::Degrees { index, source })?;
    }
    if !(options.smoothing >= 0.0 && options.smoothing.is_finite()) {
        return Err(FitError::Option(format!(
            "smoothing = {} is not a non-negative finite number",
            options.smoothing
        )));
    }
    if options.smoothing > 0.0 && p < 2 {
        return Err(FitError::Option(format!(
            "smoothing penalises the second derivative, which a degree-{p} curve does not have \
             (use degree 2 or more)"
        )));
    }
    let weights: Vec<f64> = match options.weights {
        DataWeights::None => vec![1.0; m],
        DataWeights::Given => data.weights().map(<[f64]>::to_vec).ok_or_else(|| {
            FitError::Option("data weights were asked for but the data has none".into())
        })?,
        DataWeights::Score => data
            .degrees()
            .iter()
            .map(|d| (2.0 + d.truth() - d.indeterminacy() - d.falsity()) / 3.0)
            .collect(),
    };
    let target = match (&options.knots, options.target) {
        (_, Some(target)) => target,
        (Some(knots), None) => FitTarget::ControlPoints(knots.len().saturating_sub(p + 1)),
        (None, None) => FitTarget::Tolerance(1e-3 * diagonal(data)),
    };
    if let FitTarget::Tolerance(e) = target {
        if !(e > 0.0 && e.is_finite()) {
            return Err(FitError::Option(format!(
                "tolerance = {e} is not a positive finite number"
            )));
        }
    }
    if options.knots.is_some() && (options.closed || options.kind == FitKind::Bezier) {
        return Err(FitError::Option(
            "knots can be given for an open B-spline only (not with --closed or --kind bezier)"
                .into(),
        ));
    }
    if options.tangents.is_some()
        && (target != FitTarget::Interpolate || options.closed || options.kind == FitKind::Bezier)
    {
        return Err(FitError::Option(
            "end tangents apply to the interpolation of an open B-spline (--interpolate)".into(),
        ));
    }
    let mut params = data_parameters(data, options)?;
    let chosen = choose(data, options, target, &mut params, &weights)?;
    finish(data, options, chosen, params, &weights, target)
}

/// The bounding-box diagonal of the data's positions.
fn diagonal<const D: usize>(data: &FitData<D>) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in data.positions() {
        for a in 0..D {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    let d2: f64 = (0..D).map(|a| (hi[a] - lo[a]).powi(2)).sum();
    let d = d2.sqrt();
    if d > 0.0 {
        d
    } else {
        1.0
    }
}

/// The layout and, for a tolerance fit, whether it was met.
struct Chosen {
    layout: Layout,
    extras_tangents: bool,
    tolerance_met: Option<bool>,
}

fn too_few(points: usize, why: String) -> FitError {
    FitError::TooFewPoints { points, why }
}

/// Chooses the knots (and, for a tolerance fit, refines them).
fn choose<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
    target: FitTarget,
    params: &mut [f64],
    weights: &[f64],
) -> Result<Chosen, FitError> {
    let p = options.degree;
    let m = data.len();
    let tangents = options.tangents.is_some();
    if options.kind == FitKind::Bezier {
        let layout = |degree: usize| {
            Layout::open(
                degree,
                clamped(params[0], params[m - 1], degree, Vec::new()),
            )
        };
        return match target {
            FitTarget::Interpolate if m != p + 1 => Err(FitError::Option(format!(
                "a Bézier segment of degree {p} interpolates exactly {} points, not {m} (give \
                 --degree {} or fit by least squares)",
                p + 1,
                m.saturating_sub(1)
            ))),
            FitTarget::ControlPoints(n) if n != p + 1 => Err(FitError::Option(format!(
                "a Bézier segment of degree {p} has {} control points, not {n}",
                p + 1
            ))),
            FitTarget::Tolerance(e) => {
                let mut degree = p;
                loop {
                    if m < degree + 1 {
                        return Err(too_few(
                            m,
                            format!(
                                "a degree-{degree} Bézier segment needs at least {}",
                                degree + 1
                            ),
                        ));
                    }
                    let l = layout(degree);
                    let met = position_fit(data, &l, params, weights, options.smoothing)? <= e;
                    if met || degree >= MAX_BEZIER_DEGREE.min(m - 1) {
                        return Ok(Chosen {
                            layout: l,
                            extras_tangents: false,
                            tolerance_met: Some(met),
                        });
                    }
                    degree += 1;
                }
            }
            _ => {
                if m < p + 1 {
                    return Err(too_few(
                        m,
                        format!("a degree-{p} Bézier segment needs at least {}", p + 1),
                    ));
                }
                Ok(Chosen {
                    layout: layout(p),
                    extras_tangents: false,
                    tolerance_met: None,
                })
            }
        };
    }
    if options.closed {
        return choose_closed(data, options, target, params, weights);
    }
    if let Some(knots) = &options.knots {
        return given_knots(options, target, params, knots);
    }
    let need = p + 1;
    match target {
        FitTarget::Interpolate => {
            if m < need.max(2) {
                return Err(too_few(
                    m,
                    format!(
                        "interpolation with degree {p} needs at least {}",
                        need.max(2)
                    ),
                ));
            }
            if tangents && p < 2 {
                return Err(FitError::Option(
                    "end tangents need degree 2 or more".into(),
                ));
            }
            distinct(
                params,
                "interpolation passes through every point at its own parameter",
            )?;
            Ok(Chosen {
                layout: Layout::open(p, interpolation_knots(params, p, tangents)),
                extras_tangents: tangents,
                tolerance_met: None,
            })
        }
        FitTarget::ControlPoints(n) => {
            if n < need {
                return Err(FitError::Option(format!(
                    "{n} control points are too few for degree {p} (at least degree + 1 = {need})"
                )));
            }
            if m < n {
                return Err(too_few(
                    m,
                    format!("{n} control points need at least {n} points"),
                ));
            }
            Ok(Chosen {
                layout: Layout::open(p, least_squares_knots(params, p, n - 1)),
                extras_tangents: false,
                tolerance_met: None,
            })
        }
        FitTarget::Tolerance(e) => {
            if m < need {
                return Err(too_few(m, format!("degree {p} needs at least {need}")));
            }
            let mut layout = Layout::open(p, clamped(params[0], params[m - 1], p, Vec::new()));
            refine(data, &mut layout, params, weights, options.smoothing, e)
        }
    }
}

/// Least squares on the caller's knots.
fn given_knots(
    options: &FitOptions,
    target: FitTarget,
    params: &[f64],
    knots: &[f64],
) -> Result<Chosen, FitError> {
    let p = options.degree;
    let count = knots.len().saturating_sub(p + 1);
    let vector = KnotVector::new(knots.to_vec(), p, count)
        .map_err(|e| FitError::Option(format!("knots: {e}")))?;
    match options.target {
        None => {}
        Some(FitTarget::ControlPoints(n)) if n == count => {}
        Some(other) => {
            return Err(FitError::Option(format!(
                "the knots given make a least-squares fit with {count} control points, not {other}"
            )))
        }
    }
    let _ = target;
    let domain = vector.domain();
    if let Some((index, &t)) = params
        .iter()
        .enumerate()
        .find(|(_, t)| !(domain.start <= **t && **t <= domain.end))
    {
        return Err(FitError::Option(format!(
            "point {index}: parameter {t} is outside the knots' domain [{}, {}]",
            domain.start, domain.end
        )));
    }
    Ok(Chosen {
        layout: Layout::open(p, knots.to_vec()),
        extras_tangents: false,
        tolerance_met: None,
    })
}

/// Closed curves: periodic layouts.
fn choose_closed<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
    target: FitTarget,
    params: &mut [f64],
    weights: &[f64],
) -> Result<Chosen, FitError> {
    let p = options.degree;
    let m = data.len();
    let need = 2 * p + 2;
    let remap = |params: &mut [f64], base: &[f64]| {
        for t in params.iter_mut() {
            if *t < base[0] {
                *t += 1.0;
            }
        }
    };
    let n = match target {
        FitTarget::Interpolate => m,
        FitTarget::ControlPoints(n) => n,
        FitTarget::Tolerance(_) => need,
    };
    if n < need {
        return Err(FitError::Option(format!(
            "a closed curve of degree {p} needs at least 2 degree + 2 = {need} control points \
             ({n} here)"
        )));
    }
    if m < n {
        return Err(too_few(
            m,
            format!("{n} control points need at least {n} points"),
        ));
    }
    if target == FitTarget::Interpolate {
        distinct(
            params,
            "interpolation passes through every point at its own parameter",
        )?;
    }
    let base = periodic_base(params, p, n);
    remap(params, &base);
    let mut layout = Layout::closed(p, &base);
    match target {
        FitTarget::Tolerance(e) => refine(data, &mut layout, params, weights, options.smoothing, e),
        _ => Ok(Chosen {
            layout,
            extras_tangents: false,
            tolerance_met: None,
        }),
    }
}

/// Refuses repeated parameters.
fn distinct(params: &[f64], rule: &'static str) -> Result<(), FitError> {
    match params.windows(2).position(|w| w[1] <= w[0]) {
        Some(i) => Err(FitError::RepeatedParameter {
            index: i + 1,
            previous: i,
            value: params[i + 1],
            rule,
        }),
        None => Ok(()),
    }
}

/// Fits the positions with `layout` and returns the largest position residual.
fn position_fit<const D: usize>(
    data: &FitData<D>,
    layout: &Layout,
    params: &[f64],
    weights: &[f64],
    lambda: f64,
) -> Result<f64, FitError> {
    Ok(position_residuals(data, layout, params, weights, lambda)?
        .into_iter()
        .fold(0.0, f64::max))
}

/// The position residual of every point after fitting the positions with `layout`.
fn position_residuals<const D: usize>(
    data: &FitData<D>,
    layout: &Layout,
    params: &[f64],
    weights: &[f64],
    lambda: f64,
) -> Result<Vec<f64>, FitError> {
    let system = System::new(layout, params, weights, Vec::new(), lambda)?;
    let positions = data.positions();
    let coords: Vec<Vec<f64>> = (0..D)
        .map(|a| system.solve(&|k| positions[k][a], 0))
        .collect();
    Ok((0..data.len())
        .map(|k| {
            let d2: f64 = (0..D)
                .map(|a| (system.rows.dot(layout, k, &coords[a]) - positions[k][a]).powi(2))
                .sum();
            d2.sqrt()
        })
        .collect())
}

/// Knot refinement to a tolerance (as splipy's `fit` and The NURBS Book's A9.10 do): fit,
/// then split at its middle every span holding a point whose position residual exceeds `e`,
/// as long as the data still determines every control point; stop when every residual is
/// within `e` or no span can be split.
fn refine<const D: usize>(
    data: &FitData<D>,
    layout: &mut Layout,
    params: &[f64],
    weights: &[f64],
    lambda: f64,
    e: f64,
) -> Result<Chosen, FitError> {
    for _ in 0..MAX_REFINEMENTS {
        let residuals = position_residuals(data, layout, params, weights, lambda)?;
        let bad: Vec<f64> = params
            .iter()
            .zip(&residuals)
            .filter(|(_, r)| **r > e)
            .map(|(t, _)| *t)
            .collect();
        if bad.is_empty() {
            return Ok(Chosen {
                layout: layout.clone(),
                extras_tangents: false,
                tolerance_met: Some(true),
            });
        }
        // Split the spans that hold a point beyond the tolerance, where both halves keep
        // data of their own; then check the Schoenberg-Whitney conditions once.
        let mut sorted: Vec<f64> = params
            .iter()
            .zip(weights)
            .filter(|(_, w)| **w > 0.0)
            .map(|(t, _)| *t)
            .collect();
        sorted.sort_by(f64::total_cmp);
        let count = |lo: f64, hi: f64, closed_hi: bool| {
            let start = sorted.partition_point(|&t| t < lo);
            let end = if closed_hi {
                sorted.partition_point(|&t| t <= hi)
            } else {
                sorted.partition_point(|&t| t < hi)
            };
            end - start
        };
        let mut knots = Vec::new();
        for (a, b) in layout.spans() {
            let mid = 0.5 * (a + b);
            if mid > a
                && mid < b
                && bad.iter().any(|&t| t >= a && t <= b)
                && count(a, mid, false) > 0
                && count(mid, b, true) > 0
            {
                knots.push(mid);
            }
        }
        let mut candidate = layout.clone();
        for &k in &knots {
            candidate = with_knot(&candidate, k);
        }
        if knots.is_empty()
            || candidate.n > sorted.len()
            || schoenberg_whitney(&candidate, params, weights).is_err()
        {
            return Ok(Chosen {
                layout: layout.clone(),
                extras_tangents: false,
                tolerance_met: Some(false),
            });
        }
        *layout = candidate;
    }
    let met = position_fit(data, layout, params, weights, lambda)? <= e;
    Ok(Chosen {
        layout: layout.clone(),
        extras_tangents: false,
        tolerance_met: Some(met),
    })
}

/// The layout with one more knot (one more control point).
fn with_knot(layout: &Layout, knot: f64) -> Layout {
    if layout.periodic {
        let p = layout.p;
        let mut base: Vec<f64> = layout.knots[p..p + layout.n].to_vec();
        let at = base.partition_point(|&k| k < knot);
        base.insert(at, knot);
        Layout::closed(p, &base)
    } else {
        let mut knots = layout.knots.clone();
        let at = knots.partition_point(|&k| k <= knot);
        knots.insert(at, knot);
        Layout::open(layout.p, knots)
    }
}

/// Whether every unknown has a data point of its own (positive weight, its basis function
/// positive there), in order: the Schoenberg-Whitney conditions. `Err` names the first
/// unknown without.
fn schoenberg_whitney(layout: &Layout, params: &[f64], weights: &[f64]) -> Result<(), usize> {
    let p = layout.p;
    let mut values = vec![0.0; p + 1];
    let mut next = 0;
    let mut order: Vec<usize> = (0..params.len()).collect();
    order.sort_by(|&a, &b| params[a].total_cmp(&params[b]));
    let mut k = 0;
    while next < layout.n {
        loop {
            let Some(&point) = order.get(k) else {
                return Err(next);
            };
            k += 1;
            if weights[point] <= 0.0 {
                continue;
            }
            let first = layout.row(params[point], 0, &mut values);
            let hit = (0..=p).any(|r| layout.index(first, r) == next && values[r] > 0.0);
            if hit {
                break;
            }
            // For a periodic layout, later unknowns may wrap: keep looking.
        }
        next += 1;
    }
    Ok(())
}

/// Fits every channel with the chosen layout and builds the curve and the report.
fn finish<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
    chosen: Chosen,
    params: Vec<f64>,
    weights: &[f64],
    target: FitTarget,
) -> Result<Fit<D>, FitError> {
    let layout = &chosen.layout;
    let p = layout.p;
    let m = data.len();
    let sw = schoenberg_whitney(layout, &params, weights);
    if let Err(unknown) = sw {
        if options.smoothing == 0.0 && !chosen.extras_tangents {
            return Err(FitError::SchoenbergWhitney {
                detail: format!(
                    "no point with positive weight falls in control point {unknown}'s basis \
                     function, in order"
                ),
            });
        }
    }
    let degrees = data.degrees();
    let channel = |k: usize, c: usize| degrees[k].to_array()[c];
    let extras = if chosen.extras_tangents {
        tangent_rows(data, options, layout, &params)
    } else {
        Vec::new()
    };
    let system = System::new(layout, &params, weights, extras, options.smoothing)?;
    let positions = data.positions();
    let coords: Vec<Vec<f64>> = (0..D)
        .map(|a| system.solve(&|k| positions[k][a], a))
        .collect();
    // The degree channels: unconstrained, then under the rule's bounds where they leave them.
    let n = layout.n;
    let solve_free = |c: usize| system.solve(&|k| channel(k, c), D + c);
    let mut at_bound = Vec::new();
    let mut bounded = |k: usize, columns: &[usize]| -> Result<Vec<Vec<f64>>, FitError> {
        let free: Vec<Vec<f64>> = columns.iter().map(|&c| solve_free(c)).collect();
        let mut start = vec![0.0; n * k];
        let mut b = vec![0.0; n * k];
        for (j, &c) in columns.iter().enumerate() {
            let rhs = system.rhs(&|q| channel(q, c), D + c);
            for i in 0..n {
                start[i * k + j] = free[j][i];
                b[i * k + j] = rhs[i];
            }
        }
        let feasible = start
            .chunks_exact(k)
            .all(|x| x.iter().all(|v| (0.0..=1.0).contains(v)) && (k == 1 || x[0] + x[1] <= 1.0));
        if feasible {
            return Ok(free);
        }
        let solution = qp::solve(&system.matrix, k, &b, &start).ok_or(FitError::Singular)?;
        for (i, active) in solution.active.iter().enumerate() {
            for c in active {
                let (name, bound) = match (c, k) {
                    (qp::Bound::Lower(j), _) => (channel_names(0)[columns[*j]], 0.0),
                    (qp::Bound::Upper, _) => (channel_names(0)[columns[0]], 1.0),
                    (qp::Bound::Sum, _) => ("truth + falsity", 1.0),
                };
                at_bound.push(AtBound {
                    index: i,
                    channel: name,
                    bound,
                });
            }
        }
        Ok((0..k)
            .map(|j| (0..n).map(|i| solution.x[i * k + j]).collect())
            .collect())
    };
    // Control degrees per point: [truth, indeterminacy, falsity].
    let mut control = vec![[0.0; 3]; n];
    match options.membership {
        Membership::Neutrosophic => {
            for c in 0..3 {
                let values = bounded(1, &[c])?.remove(0);
                for (i, v) in values.into_iter().enumerate() {
                    control[i][c] = v.clamp(0.0, 1.0);
                }
            }
        }
        Membership::Intuitionistic => {
            let tf = bounded(2, &[0, 2])?;
            for i in 0..n {
                let t = tf[0][i].clamp(0.0, 1.0);
                let f = tf[1][i].clamp(0.0, 1.0 - t);
                control[i] = [t, 1.0 - t - f, f];
            }
        }
        Membership::Fuzzy => {
            let t = bounded(1, &[0])?.remove(0);
            for i in 0..n {
                control[i] = [t[i].clamp(0.0, 1.0), 0.0, 0.0];
            }
        }
    }
    // Values exactly on a bound that the unconstrained solution reached by itself.
    for (i, row) in control.iter().enumerate() {
        for c in 0..3 {
            let name = channel_names(0)[c];
            if options.membership == Membership::Intuitionistic && c == 1 {
                continue;
            }
            if options.membership == Membership::Fuzzy && c > 0 {
                continue;
            }
            for bound in [0.0, 1.0] {
                if row[c] == bound && !at_bound.iter().any(|a| a.index == i && a.channel == name) {
                    at_bound.push(AtBound {
                        index: i,
                        channel: name,
                        bound,
                    });
                }
            }
        }
    }
    at_bound.sort_by(|a, b| a.index.cmp(&b.index).then(a.channel.cmp(b.channel)));
    let points: Vec<ControlPoint<D>> = (0..n)
        .map(|i| {
            let mut position = [0.0; D];
            for a in 0..D {
                position[a] = coords[a][i];
            }
            let [t, ind, f] = control[i];
            let degrees = match options.membership {
                Membership::Neutrosophic => Degrees::new(t, ind, f),
                Membership::Intuitionistic => Degrees::intuitionistic(t, f),
                Membership::Fuzzy => Degrees::fuzzy(t),
            }
            .unwrap_or_else(|_| Degrees::new_unchecked(t, ind, f));
            ControlPoint::new(position, degrees)
        })
        .collect();
    let curve = build_curve(layout, points, options.kind)?;
    // Residuals of every channel at every point.
    let names = channel_names(D);
    let mut max = vec![0.0_f64; D + 3];
    let mut sum = vec![0.0_f64; D + 3];
    let (mut worst_index, mut worst_distance) = (0, -1.0);
    let controls: Vec<Vec<f64>> = (0..3)
        .map(|c| control.iter().map(|row| row[c]).collect())
        .collect();
    for k in 0..m {
        let mut d2 = 0.0;
        for a in 0..D {
            let r = system.rows.dot(layout, k, &coords[a]) - positions[k][a];
            d2 += r * r;
            max[a] = max[a].max(r.abs());
            sum[a] += r * r;
        }
        for c in 0..3 {
            let r = system.rows.dot(layout, k, &controls[c]) - channel(k, c);
            max[D + c] = max[D + c].max(r.abs());
            sum[D + c] += r * r;
        }
        let d = d2.sqrt();
        if d > worst_distance {
            worst_distance = d;
            worst_index = k;
        }
    }
    let report = FitReport {
        control_points: n,
        degree: p,
        max_error: names.iter().copied().zip(max).collect(),
        rms_error: names
            .iter()
            .copied()
            .zip(sum.iter().map(|s| (s / m as f64).sqrt()))
            .collect(),
        worst_index,
        worst_parameter: params[worst_index],
        worst_distance,
        schoenberg_whitney: sw.is_ok(),
        condition_estimate: system.matrix.condition_estimate(&system.factor),
        at_bound,
        tolerance_met: match target {
            FitTarget::Tolerance(_) => chosen.tolerance_met,
            _ => None,
        },
    };
    Ok(Fit {
        curve,
        parameters: params,
        report,
    })
}

/// The end-tangent equations of an interpolation: `C'(t_0) = D_0`, `C'(t_m) = D_1`; the
/// degree channels' targets are the one-sided difference quotients of the data.
fn tangent_rows<const D: usize>(
    data: &FitData<D>,
    options: &FitOptions,
    layout: &Layout,
    params: &[f64],
) -> Vec<Extra> {
    let m = data.len();
    let Some([start, end]) = &options.tangents else {
        return Vec::new();
    };
    let degrees = data.degrees();
    let quotient = |a: usize, b: usize, c: usize| {
        (degrees[b].to_array()[c] - degrees[a].to_array()[c]) / (params[b] - params[a])
    };
    let mut extras = Vec::new();
    for (t, given, (a, b)) in [
        (params[0], start, (0, 1)),
        (params[m - 1], end, (m - 2, m - 1)),
    ] {
        let mut values = vec![0.0; layout.p + 1];
        let first = layout.row(t, 1, &mut values);
        let mut targets: Vec<f64> = given.iter().copied().take(D).collect();
        targets.resize(D, 0.0);
        targets.extend((0..3).map(|c| quotient(a, b, c)));
        extras.push(Extra {
            first,
            values,
            targets,
        });
    }
    extras
}

/// The fitted curve of the layout's kind.
fn build_curve<const D: usize>(
    layout: &Layout,
    mut points: Vec<ControlPoint<D>>,
    kind: FitKind,
) -> Result<AnyCurve<D>, FitError> {
    let p = layout.p;
    if kind == FitKind::Bezier {
        return Ok(AnyCurve::Bezier(Bezier::new(points)?));
    }
    if layout.periodic {
        let wrap: Vec<ControlPoint<D>> = points[..p].to_vec();
        points.extend(wrap);
    }
    let count = points.len();
    let knots =
        KnotVector::new(layout.knots.clone(), p, count).map_err(crate::curve::CurveError::from)?;
    Ok(AnyCurve::BSpline(BSpline::new(points, knots)?))
}
