//! The tables the command makes of a shape (`neutrospline-io`'s [`Shape`]: the core's curves
//! of any kind, planar or spatial, and its surfaces): the columns, the parameter checks of
//! `--at` and the row-by-row evaluation that `eval` writes ([`Table`]).

use std::fmt;
use std::ops::Range;

use std::cell::Cell;

use neutrospline::{
    DerivativeValue, DynCurve, DynDerivative, EvalError, EvaluateSurface, Family, GeometryError,
    KnotVector, Surface, DEFAULT_ACCURACY,
};
pub use neutrospline_io::{DegreeView, Shape};

use crate::output::number;

/// A parameter of a shape: `t` on a curve, `(u, v)` on a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Param {
    /// A curve parameter.
    T(f64),
    /// A surface parameter pair.
    Uv(f64, f64),
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Param::T(t) => write!(f, "t = {}", number(t)),
            Param::Uv(u, v) => write!(f, "u = {}, v = {}", number(u), number(v)),
        }
    }
}

/// Which extra columns a table has.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extras {
    /// The highest derivative order whose columns are added, 0 for none (curves: d/dt,
    /// d2/dt2, ...; surfaces: the partials d/du, d/dv, then d2/du2, d2/dudv, d2/dv2, ...).
    pub derivative: usize,
    /// The unit normal (surfaces).
    pub normal: bool,
    /// The score, accuracy and certainty of the degrees (docs/model.md section 7).
    pub scores: bool,
    /// Curves: the arc length from the start of the domain and the curvature.
    pub geometry: bool,
    /// The relative accuracy of the arc length (`geometry` only).
    pub accuracy: f64,
    /// The membership family of the degrees: which degree columns, derived degrees and
    /// scores the table has ([`DegreeView`]).
    pub family: Family,
}

impl Default for Extras {
    fn default() -> Self {
        Extras {
            derivative: 0,
            normal: false,
            scores: false,
            geometry: false,
            accuracy: DEFAULT_ACCURACY,
            family: Family::Neutrosophic,
        }
    }
}

/// Column names of the geometry along a curve.
const GEOMETRY: [&str; 2] = ["arc_length", "curvature"];

/// A row of a table: `None` is a value that does not exist (a normal where the surface is
/// degenerate), written as an empty CSV cell or JSON `null`.
pub type Row = Vec<Option<f64>>;

/// Column names of the position, by dimension.
const AXES: [&str; 3] = ["x", "y", "z"];

/// The domain `[a, b]` of a curve or one direction of a surface, as text: `[0, 1]`, or with its
/// knot indices, `[knot 2, knot 7] = [2, 5]`.
fn domain_text(domain: &Range<f64>, knots: Option<&KnotVector>, prefix: &str) -> String {
    let values = format!("[{}, {}]", number(domain.start), number(domain.end));
    match knots {
        Some(k) => {
            let p = k.degree();
            let end = k.knots().len() - 1 - p;
            format!("[{prefix}{p}, {prefix}{end}] = {values}")
        }
        None => values,
    }
}

fn contains(domain: &Range<f64>, t: f64) -> bool {
    domain.start <= t && t <= domain.end
}

/// What the command computes from a shape: table columns, `--at` checks and rows.
pub trait Table {
    /// The domain of a curve as text, with its knot indices for splines.
    fn curve_domain_text(&self) -> Option<String>;

    /// Checks that `param` has the right form (`T` for curves, `U:V` for surfaces) and lies in
    /// the domain; the message names the domain.
    ///
    /// # Errors
    /// A message for `--at`.
    fn check_param(&self, param: Param, text: &str) -> Result<(), String>;

    /// Column names of a table of samples.
    ///
    /// Curves: `t`, then `x, y[, z], truth, indeterminacy, falsity`, and with `derivative`
    /// the same names prefixed by `d` (`dx, ..., dfalsity`), then for order 2 by `d2`
    /// (`d2x, ...`), for order 3 by `d3`. Surfaces: `u, v, x, y, z, truth, indeterminacy,
    /// falsity`; with `derivative` each channel's `d<name>_du` then `d<name>_dv`, then for
    /// order 2 `d<name>_duu`, `d<name>_duv`, `d<name>_dvv`, for order 3 `_duuu`, `_duuv`,
    /// `_duvv`, `_dvvv`; with `normal` `nx, ny, nz`. Curves with `geometry` end with
    /// `arc_length, curvature`.
    fn columns(&self, extras: Extras) -> Vec<String>;

    /// A sampler producing one row per parameter, in the order of [`Table::columns`].
    fn sampler(&self, extras: Extras) -> Sampler<'_>;
}

/// A sampler of a model's lanes (`Model::lanes`: one shape, or two of the same geometry for
/// the interval-valued and bipolar families, docs/model.md "Lanes"): every lane is evaluated
/// at the same parameter, the position (and its rates) comes from the first, and the degree
/// columns are [`DegreeView::values`] of all lanes' degrees (the rates [`DegreeView::rates`]
/// of all lanes' degree rates).
///
/// # Panics
/// If `lanes` is empty, or its shapes are not all curves or all surfaces (the lanes of a
/// model have one geometry).
pub fn lanes_sampler<'a>(lanes: &[&'a Shape], extras: Extras) -> Sampler<'a> {
    match lanes[0] {
        Shape::Curve(_) => Sampler::Curve(CurveSampler::new(
            &lanes
                .iter()
                .map(|shape| shape.curve().expect("the lanes of a curve are curves"))
                .collect::<Vec<_>>(),
            extras,
        )),
        Shape::Surface(_) => Sampler::Surface(
            lanes
                .iter()
                .map(|shape| match shape {
                    Shape::Surface(s) => s,
                    Shape::Curve(_) => panic!("the lanes of a surface are surfaces"),
                })
                .collect(),
            extras,
        ),
    }
}

impl Table for Shape {
    fn curve_domain_text(&self) -> Option<String> {
        self.curve_domain()
            .map(|d| domain_text(&d, self.curve_knots(), "knot "))
    }

    fn check_param(&self, param: Param, text: &str) -> Result<(), String> {
        match (self, param) {
            (Shape::Surface(_), Param::T(_)) => Err(format!(
                "`{text}` is not a pair U:V (a surface is evaluated at --at U:V,U:V,...)"
            )),
            (Shape::Curve(_), Param::Uv(..)) => Err(format!(
                "`{text}` is a pair U:V but the file holds a curve (give --at T1,T2,...)"
            )),
            (Shape::Surface(s), Param::Uv(u, v)) => {
                let [domain_u, domain_v] = s.domain();
                for (name, value, domain, knots) in [
                    ("u", u, domain_u, s.knots_u()),
                    ("v", v, domain_v, s.knots_v()),
                ] {
                    if !contains(&domain, value) {
                        let knots =
                            (s.kind() != neutrospline::SurfaceKind::Bezier).then_some(knots);
                        return Err(format!(
                            "{name} = {} (in `{text}`) is outside the surface's {name} domain {}",
                            number(value),
                            domain_text(&domain, knots, &format!("knot_{name} "))
                        ));
                    }
                }
                Ok(())
            }
            (_, Param::T(t)) => {
                let domain = self.curve_domain().unwrap_or(0.0..1.0);
                if contains(&domain, t) {
                    Ok(())
                } else {
                    Err(format!(
                        "t = {} is outside the curve's domain {}",
                        number(t),
                        self.curve_domain_text().unwrap_or_default()
                    ))
                }
            }
        }
    }

    fn columns(&self, extras: Extras) -> Vec<String> {
        let view = DegreeView::new(extras.family);
        let axes = &AXES[..self.dimension()];
        let names: Vec<&str> = axes.iter().copied().chain(view.channel_names()).collect();
        let mut columns: Vec<String> = if self.is_surface() {
            vec!["u".to_owned(), "v".to_owned()]
        } else {
            vec!["t".to_owned()]
        };
        columns.extend(axes.iter().chain(&view.names()).map(|n| (*n).to_owned()));
        if extras.scores {
            columns.extend(view.score_names().iter().map(|n| (*n).to_owned()));
        }
        for order in 1..=extras.derivative {
            if self.is_surface() {
                for partial in partial_names(order) {
                    columns.extend(names.iter().map(|n| format!("d{n}_{partial}")));
                }
            } else {
                let prefix = if order == 1 {
                    "d".to_owned()
                } else {
                    format!("d{order}")
                };
                columns.extend(names.iter().map(|n| format!("{prefix}{n}")));
            }
        }
        if extras.normal && self.is_surface() {
            columns.extend(["nx", "ny", "nz"].map(str::to_owned));
        }
        if extras.geometry && !self.is_surface() {
            columns.extend(GEOMETRY.map(str::to_owned));
        }
        columns
    }

    fn sampler(&self, extras: Extras) -> Sampler<'_> {
        lanes_sampler(&[self], extras)
    }
}

/// The partials of a surface of total order `order`, as column suffixes: `du, dv` for 1,
/// `duu, duv, dvv` for 2, ..., in the order of [`Surface::mixed_partials`] (u first).
fn partial_names(order: usize) -> Vec<String> {
    (0..=order)
        .map(|j| format!("d{}{}", "u".repeat(order - j), "v".repeat(j)))
        .collect()
}

/// Evaluates a shape (and its derivatives) row by row.
pub enum Sampler<'a> {
    /// For a curve.
    Curve(CurveSampler<'a>),
    /// For a surface: its lanes.
    Surface(Vec<&'a Surface>, Extras),
}

impl Sampler<'_> {
    /// The row at `param`: the parameter, the position, the degrees and, if asked, their
    /// derivatives and the normal.
    ///
    /// # Errors
    /// The core's [`EvalError`] (parameter outside the domain, overflow), or a parameter of the
    /// wrong form (a pair for a curve, a single value for a surface; [`Table::check_param`]
    /// rules those out beforehand).
    pub fn row(&self, param: Param) -> anyhow::Result<Row> {
        Ok(match (self, param) {
            (Sampler::Curve(s), Param::T(t)) => s.row(t)?,
            (Sampler::Surface(lanes, extras), Param::Uv(u, v)) => {
                surface_row(lanes, *extras, u, v)?
            }
            (Sampler::Surface(..), Param::T(_)) => {
                anyhow::bail!("a surface needs a parameter pair (u, v)")
            }
            (_, Param::Uv(..)) => anyhow::bail!("a curve takes one parameter t"),
        })
    }
}

/// A lane of a curve with its derivatives computed once.
struct LaneCurve<'a> {
    curve: &'a DynCurve,
    /// The derivatives of orders 1, 2, ... asked for.
    derivatives: Vec<DynDerivative>,
}

/// A curve (all its lanes) with its derivatives computed once.
pub struct CurveSampler<'a> {
    /// The lanes; the first gives the position and the geometry.
    lanes: Vec<LaneCurve<'a>>,
    scores: bool,
    view: DegreeView,
    /// The accuracy of the arc length, when the geometry columns are asked for.
    geometry: Option<f64>,
    /// The last parameter and its arc length: a row at a larger parameter adds the length
    /// from there (each part to the relative accuracy, so their sum is too).
    last_length: Cell<Option<(f64, f64)>>,
}

impl<'a> CurveSampler<'a> {
    fn new(lanes: &[&'a DynCurve], extras: Extras) -> Self {
        let lane = |curve: &'a DynCurve| LaneCurve {
            curve,
            derivatives: (1..=extras.derivative)
                .scan(None, |previous: &mut Option<DynDerivative>, _| {
                    let next = match previous {
                        Some(d) => d.derivative(),
                        None => curve.derivative(),
                    };
                    *previous = Some(next.clone());
                    Some(next)
                })
                .collect(),
        };
        CurveSampler {
            lanes: lanes.iter().map(|c| lane(c)).collect(),
            scores: extras.scores,
            view: DegreeView::new(extras.family),
            geometry: extras.geometry.then_some(extras.accuracy),
            last_length: Cell::new(None),
        }
    }

    /// The curve of the first lane (the geometry of all).
    fn curve(&self) -> &'a DynCurve {
        self.lanes[0].curve
    }

    /// The arc length from the start of the domain to `t`.
    fn arc_length(&self, t: f64, accuracy: f64) -> Result<f64, GeometryError> {
        let curve = self.curve();
        let start = curve.domain().start;
        let length = match self.last_length.get() {
            Some((previous, length)) if previous <= t => {
                length + curve.arc_length(previous..t, accuracy)?
            }
            _ => curve.arc_length(start..t, accuracy)?,
        };
        self.last_length.set(Some((t, length)));
        Ok(length)
    }

    fn row(&self, t: f64) -> anyhow::Result<Row> {
        let p = self
            .curve()
            .evaluate_point(t)
            .map_err(explain("position"))?;
        let mut degrees = vec![p.degrees];
        for lane in &self.lanes[1..] {
            let q = lane.curve.evaluate_point(t).map_err(explain("position"))?;
            degrees.push(q.degrees);
        }
        let mut row = vec![t];
        row.extend(&p.position);
        row.extend(self.view.values(&degrees));
        if self.scores {
            row.extend(self.view.scores(&degrees));
        }
        for order in 0..self.lanes[0].derivatives.len() {
            let mut rates = Vec::with_capacity(self.lanes.len());
            for (k, lane) in self.lanes.iter().enumerate() {
                let values = lane.derivatives[order]
                    .evaluate_row(t)
                    .map_err(explain("derivative"))?;
                let (position, slots) = values.split_at(values.len() - 3);
                if k == 0 {
                    row.extend(position);
                }
                rates.push([slots[0], slots[1], slots[2]]);
            }
            row.extend(self.view.rates(&rates));
        }
        let mut row: Row = row.into_iter().map(Some).collect();
        if let Some(accuracy) = self.geometry {
            row.push(Some(self.arc_length(t, accuracy)?));
            // No curvature where the curve stands still (|C'| = 0): an empty cell.
            row.push(match self.curve().curvature(t) {
                Ok(kappa) => Some(kappa),
                Err(GeometryError::Stationary { .. }) => None,
                Err(e) => return Err(e.into()),
            });
        }
        Ok(row)
    }
}

/// The degree rates `[dT, dI, dF]` of a lane's derivative.
fn slot_rates<const D: usize>(d: &DerivativeValue<D>) -> [f64; 3] {
    [d.truth, d.indeterminacy, d.falsity]
}

/// Appends the position rates of the first lane's derivative and the channel rates of all
/// lanes' derivatives (one [`DerivativeValue`] per lane).
fn push_rates(row: &mut Vec<f64>, view: DegreeView, lanes: &[DerivativeValue<3>]) {
    row.extend(lanes[0].position);
    let rates: Vec<[f64; 3]> = lanes.iter().map(slot_rates).collect();
    row.extend(view.rates(&rates));
}

/// The core's error, with an overflow said in terms of what overflowed (the core's message
/// names a parameter `t` even on a surface).
fn explain(what: &'static str) -> impl Fn(EvalError) -> anyhow::Error {
    move |e| match e {
        EvalError::Overflow { .. } => {
            anyhow::anyhow!("the {what} overflows a 64-bit float (control values too large)")
        }
        e => e.into(),
    }
}

fn surface_row(lanes: &[&Surface], extras: Extras, u: f64, v: f64) -> anyhow::Result<Row> {
    let surface = lanes[0];
    let p = surface.evaluate(u, v).map_err(explain("position"))?;
    let mut degrees = vec![p.degrees];
    for lane in &lanes[1..] {
        degrees.push(lane.evaluate(u, v).map_err(explain("position"))?.degrees);
    }
    let view = DegreeView::new(extras.family);
    let mut values = Vec::with_capacity(2 + 3 * 6);
    values.extend([u, v]);
    values.extend(p.position);
    values.extend(view.values(&degrees));
    if extras.scores {
        values.extend(view.scores(&degrees));
    }
    if extras.derivative >= 1 {
        let mut du = Vec::with_capacity(lanes.len());
        let mut dv = Vec::with_capacity(lanes.len());
        for lane in lanes {
            let d = lane
                .partial_derivatives(u, v)
                .map_err(explain("derivative"))?;
            du.push(d.du);
            dv.push(d.dv);
        }
        push_rates(&mut values, view, &du);
        push_rates(&mut values, view, &dv);
    }
    for order in 2..=extras.derivative {
        let partials = lanes
            .iter()
            .map(|lane| lane.mixed_partials(u, v, order))
            .collect::<Result<Vec<_>, _>>()
            .map_err(explain("derivative"))?;
        for k in 0..partials[0].len() {
            let of_lanes: Vec<DerivativeValue<3>> = partials.iter().map(|p| p[k]).collect();
            push_rates(&mut values, view, &of_lanes);
        }
    }
    let mut row: Row = values.into_iter().map(Some).collect();
    if extras.normal {
        match surface.normal(u, v).map_err(explain("derivative"))? {
            Some(n) => row.extend(n.map(Some)),
            None => row.extend([None; 3]),
        }
    }
    Ok(row)
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{ControlPoint, Degrees, KnotVector};

    fn planar_bspline() -> Shape {
        let d = Degrees::new(0.5, 0.25, 0.0).unwrap();
        let points = (0..5)
            .map(|i| ControlPoint::new([f64::from(i), 0.0], d))
            .collect();
        let knots = KnotVector::new((0..8).map(f64::from).collect(), 2, 5).unwrap();
        Shape::from(neutrospline::AnyCurve::BSpline(
            neutrospline::BSpline::new(points, knots).unwrap(),
        ))
    }

    #[test]
    fn shape_columns() {
        let c = planar_bspline();
        assert_eq!(
            c.columns(Extras::default()).join(","),
            "t,x,y,truth,indeterminacy,falsity"
        );
        assert_eq!(
            c.columns(Extras {
                derivative: 1,
                normal: true,
                scores: false,
                ..Extras::default()
            })
            .join(","),
            "t,x,y,truth,indeterminacy,falsity,dx,dy,dtruth,dindeterminacy,dfalsity"
        );
        assert_eq!(
            c.columns(Extras {
                scores: true,
                ..Extras::default()
            })
            .join(","),
            "t,x,y,truth,indeterminacy,falsity,score,accuracy,certainty"
        );
        // (T, I, F) = (0.5, 0.25, 0) everywhere: score 0.75, accuracy 0.5, certainty 0.5.
        let row = c
            .sampler(Extras {
                scores: true,
                ..Extras::default()
            })
            .row(Param::T(3.0))
            .unwrap();
        for (value, want) in row[6..].iter().zip([0.75, 0.5, 0.5]) {
            assert!((value.unwrap() - want).abs() < 1e-15, "{row:?}");
        }
        let d = Degrees::new(0.5, 0.25, 0.0).unwrap();
        let s = Shape::Surface(
            Surface::bezier(
                2,
                2,
                vec![
                    ControlPoint::new([0.0, 0.0, 0.0], d),
                    ControlPoint::new([0.0, 1.0, 0.0], d),
                    ControlPoint::new([1.0, 0.0, 0.0], d),
                    ControlPoint::new([1.0, 1.0, 0.0], d),
                ],
            )
            .unwrap(),
        );
        assert_eq!(
            s.columns(Extras {
                derivative: 1,
                normal: true,
                scores: false,
                ..Extras::default()
            })
            .join(","),
            "u,v,x,y,z,truth,indeterminacy,falsity,\
             dx_du,dy_du,dz_du,dtruth_du,dindeterminacy_du,dfalsity_du,\
             dx_dv,dy_dv,dz_dv,dtruth_dv,dindeterminacy_dv,dfalsity_dv,nx,ny,nz"
        );
        let row = s
            .sampler(Extras {
                derivative: 0,
                normal: true,
                scores: false,
                ..Extras::default()
            })
            .row(Param::Uv(0.5, 0.5))
            .unwrap();
        assert_eq!(&row[8..], &[Some(0.0), Some(0.0), Some(1.0)]);
    }

    #[test]
    fn shape_check_param_names_the_domain() {
        let c = planar_bspline();
        assert_eq!(c.check_param(Param::T(2.0), "2"), Ok(()));
        assert_eq!(c.check_param(Param::T(5.0), "5"), Ok(()));
        assert_eq!(
            c.check_param(Param::T(1.5), "1.5").unwrap_err(),
            "t = 1.5 is outside the curve's domain [knot 2, knot 5] = [2, 5]"
        );
        assert_eq!(
            c.check_param(Param::Uv(0.5, 0.5), "0.5:0.5").unwrap_err(),
            "`0.5:0.5` is a pair U:V but the file holds a curve (give --at T1,T2,...)"
        );
    }
}
