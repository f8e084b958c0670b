//! What a figure shows: a curve, its control points and their names.

use std::fmt;
use std::ops::Range;
use std::sync::Arc;

use neutrospline::{
    uniform_parameter, AnyCurve, Bezier, ControlPoint, ControlPolygon, CurveKind, CurvePoint,
    DegreeKind, Evaluate, EvaluateSurface, NeutrosophicPoint, Surface, SurfaceKind,
};

use crate::error::PlotError;

/// A point as the renderer uses it: position padded to 3-D (z = 0 for planar models) and
/// the degrees `[truth, indeterminacy, falsity]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pt {
    pub pos: [f64; 3],
    pub deg: [f64; 3],
}

const CHANNELS: [&str; 6] = ["x", "y", "z", "truth", "indeterminacy", "falsity"];

fn to_pt<const D: usize>(
    p: &NeutrosophicPoint<D>,
    what: &'static str,
    index: usize,
) -> Result<Pt, PlotError> {
    let mut pos = [0.0; 3];
    for (axis, (&v, slot)) in p.position.iter().zip(pos.iter_mut()).enumerate() {
        if !v.is_finite() {
            return Err(PlotError::NotFinite {
                what,
                index,
                channel: CHANNELS[axis],
                value: v,
            });
        }
        *slot = v;
    }
    let deg = p.degrees.to_array();
    for (k, &v) in deg.iter().enumerate() {
        if !v.is_finite() {
            return Err(PlotError::NotFinite {
                what,
                index,
                channel: CHANNELS[3 + k],
                value: v,
            });
        }
    }
    Ok(Pt { pos, deg })
}

fn to_pts<const D: usize>(
    points: &[NeutrosophicPoint<D>],
    what: &'static str,
) -> Result<Vec<Pt>, PlotError> {
    points
        .iter()
        .enumerate()
        .map(|(i, p)| to_pt(p, what, i))
        .collect()
}

fn check_dimension(d: usize) -> Result<(), PlotError> {
    if d == 2 || d == 3 {
        Ok(())
    } else {
        Err(PlotError::UnsupportedDimension { dimension: d })
    }
}

/// A curve that can be sampled at render time.
trait Sampler: Send + Sync {
    fn sample(&self, n: usize) -> Result<Vec<Pt>, PlotError>;
}

struct CurveSampler<C, const D: usize>(C);

impl<C, const D: usize> Sampler for CurveSampler<C, D>
where
    C: Evaluate<Point = CurvePoint<D>> + Send + Sync,
{
    fn sample(&self, n: usize) -> Result<Vec<Pt>, PlotError> {
        let ts = parameters(self.0.domain(), n);
        let mut out = vec![self.0.start()?; ts.len()];
        self.0.evaluate_many(&ts, &mut out)?;
        to_pts(&out, "curve sample")
    }
}

#[derive(Clone)]
enum Geometry {
    Samples(Vec<Pt>),
    Curve(Arc<dyn Sampler>),
    Surface(Arc<Surface>),
}

/// `n` (at least 2) evenly spaced parameters over `domain`, both ends exact (the core's
/// [`uniform_parameter`]).
fn parameters(domain: Range<f64>, n: usize) -> Vec<f64> {
    let n = n.max(2);
    (0..n)
        .map(|k| uniform_parameter(k, n, domain.clone()))
        .collect()
}

/// A surface sampled on an `n x n` grid of parameters: points and unit normals, row `a`
/// (along u) by column `b` (along v), stored at `a * n + b`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Mesh {
    pub n: usize,
    pub u: Vec<f64>,
    pub v: Vec<f64>,
    pub points: Vec<Pt>,
    /// `None` where the surface has no normal (a collapsed edge, a degenerate patch).
    pub normals: Vec<Option<[f64; 3]>>,
    /// The distinct interior knots in u and in v (the patch boundaries of a spline surface).
    pub knots: [Vec<f64>; 2],
}

impl Mesh {
    pub(crate) fn at(&self, a: usize, b: usize) -> &Pt {
        &self.points[a * self.n + b]
    }

    pub(crate) fn normal(&self, a: usize, b: usize) -> Option<[f64; 3]> {
        self.normals[a * self.n + b]
    }

    /// The degree `kind` of the cell between samples `(a, b)` and `(a + 1, b + 1)`: the mean
    /// of its four corners.
    pub(crate) fn cell_degree(&self, a: usize, b: usize, kind: DegreeKind) -> f64 {
        [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)]
            .iter()
            .map(|&(i, j)| self.at(i, j).deg[kind.index()])
            .sum::<f64>()
            / 4.0
    }
}

fn sample_surface(surface: &Surface, n: usize) -> Result<Mesh, PlotError> {
    let [domain_u, domain_v] = surface.domain();
    let us = parameters(domain_u, n);
    let vs = parameters(domain_v, n);
    let n = us.len();
    let mut points = Vec::with_capacity(n * n);
    let mut normals = Vec::with_capacity(n * n);
    for &u in &us {
        for &v in &vs {
            let p = surface.evaluate(u, v)?;
            points.push(to_pt(&p, "surface sample", points.len())?);
            let normal = surface
                .normal(u, v)?
                .filter(|m| m.iter().all(|x| x.is_finite()));
            normals.push(normal);
        }
    }
    let knots = [
        surface.knots_u().interior_breakpoints(),
        surface.knots_v().interior_breakpoints(),
    ];
    Ok(Mesh {
        n,
        u: us,
        v: vs,
        points,
        normals,
        knots,
    })
}

/// What a figure shows: a neutrosophic curve (sampled when drawn, or given as samples) or a
/// tensor-product surface, its control points and, optionally, their names.
///
/// The model is independent of the curve kind: anything that implements
/// [`neutrospline::Evaluate`] can feed it through [`PlotModel::from_curve`], and
/// [`PlotModel::from_samples`] takes points computed elsewhere. Positions are 2-D (the paper's
/// model: the degrees become the third axis of the 3-D views) or 3-D. Surfaces of every kind
/// come in through [`PlotModel::from_surface`]; they are 3-D, and their control points form a
/// grid (the control net).
///
/// ```
/// use neutrospline_plot::PlotModel;
/// let curve = neutrospline::example1();
/// let model = PlotModel::from(&curve).with_names(neutrospline::EXAMPLE1_NAMES)?;
/// assert_eq!(model.dimension(), 2);
/// assert_eq!(model.names(), ["C0", "C1", "C2", "C3"]);
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
#[derive(Clone)]
pub struct PlotModel {
    dimension: usize,
    curve: Geometry,
    controls: Vec<Pt>,
    /// Rows and columns of a surface's control net.
    grid: Option<(usize, usize)>,
    names: Vec<String>,
    label: String,
}

impl fmt::Debug for PlotModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let curve = match &self.curve {
            Geometry::Samples(s) => format!("{} samples", s.len()),
            Geometry::Curve(_) => "curve".to_string(),
            Geometry::Surface(_) => "surface".to_string(),
        };
        f.debug_struct("PlotModel")
            .field("dimension", &self.dimension)
            .field("curve", &curve)
            .field("controls", &self.controls.len())
            .field("grid", &self.grid)
            .field("names", &self.names)
            .field("label", &self.label)
            .finish()
    }
}

// The labels of the models by kind, used in default titles ([`PlotModel::label`]);
// `CURVE_LABEL` is that of models made by `from_curve` and `from_samples`.
const BEZIER_LABEL: &str = "Neutrosophic Bézier curve";
const BSPLINE_LABEL: &str = "Neutrosophic B-spline curve";
const NURBS_LABEL: &str = "Neutrosophic NURBS curve";
const CURVE_LABEL: &str = "Neutrosophic curve";
const BEZIER_SURFACE_LABEL: &str = "Neutrosophic Bézier surface";
const BSPLINE_SURFACE_LABEL: &str = "Neutrosophic B-spline surface";
const NURBS_SURFACE_LABEL: &str = "Neutrosophic NURBS surface";

impl PlotModel {
    /// A model of any curve kind: `curve` is sampled evenly in its parameter domain when the
    /// figure is drawn ([`PlotOptions::with_samples`](crate::PlotOptions::with_samples)), and
    /// `controls` are drawn as its control points, in order.
    ///
    /// # Errors
    /// [`PlotError::UnsupportedDimension`] unless `D` is 2 or 3,
    /// [`PlotError::NoControlPoints`], or [`PlotError::NotFinite`] for a control value.
    pub fn from_curve<const D: usize, C>(
        curve: C,
        controls: &[ControlPoint<D>],
    ) -> Result<PlotModel, PlotError>
    where
        C: Evaluate<Point = CurvePoint<D>> + Send + Sync + 'static,
    {
        check_dimension(D)?;
        if controls.is_empty() {
            return Err(PlotError::NoControlPoints);
        }
        Ok(PlotModel {
            dimension: D,
            curve: Geometry::Curve(Arc::new(CurveSampler::<C, D>(curve))),
            controls: to_pts(controls, "control point")?,
            grid: None,
            names: Vec::new(),
            label: CURVE_LABEL.to_string(),
        })
    }

    /// A model of a Bézier curve and its control points, labelled "Neutrosophic Bézier curve".
    ///
    /// # Errors
    /// [`PlotError::UnsupportedDimension`] unless `D` is 2 or 3 (the `From` impls for
    /// `&Bezier<2>` and `&Bezier<3>` cannot fail), or [`PlotError::NotFinite`] for a degree
    /// built unchecked as NaN.
    pub fn from_bezier<const D: usize>(curve: &Bezier<D>) -> Result<PlotModel, PlotError> {
        let model = PlotModel::from_curve(curve.clone(), &curve.control_points())?;
        Ok(model.with_label(BEZIER_LABEL))
    }

    /// A model of a curve of any kind and its control points, labelled by kind
    /// ("Neutrosophic Bézier curve", "Neutrosophic B-spline curve", "Neutrosophic NURBS
    /// curve"). The curve is sampled evenly in its parameter domain.
    ///
    /// ```
    /// use neutrospline::AnyCurve;
    /// use neutrospline_plot::PlotModel;
    /// let model = PlotModel::from_any(&AnyCurve::from(neutrospline::example1()))?;
    /// assert_eq!(model.label(), "Neutrosophic Bézier curve");
    /// # Ok::<(), neutrospline_plot::PlotError>(())
    /// ```
    ///
    /// # Errors
    /// As [`PlotModel::from_bezier`].
    pub fn from_any<const D: usize>(curve: &AnyCurve<D>) -> Result<PlotModel, PlotError> {
        let label = match curve.kind() {
            CurveKind::Bezier => BEZIER_LABEL,
            CurveKind::BSpline => BSPLINE_LABEL,
            CurveKind::Nurbs => NURBS_LABEL,
        };
        let model = PlotModel::from_curve(curve.clone(), &curve.control_points())?;
        Ok(model.with_label(label))
    }

    /// A model from curve points computed elsewhere (drawn as given, in order) and control
    /// points.
    ///
    /// # Errors
    /// [`PlotError::UnsupportedDimension`], [`PlotError::NoCurvePoints`],
    /// [`PlotError::NoControlPoints`] or [`PlotError::NotFinite`].
    pub fn from_samples<const D: usize>(
        curve: &[CurvePoint<D>],
        controls: &[ControlPoint<D>],
    ) -> Result<PlotModel, PlotError> {
        check_dimension(D)?;
        if curve.is_empty() {
            return Err(PlotError::NoCurvePoints);
        }
        if controls.is_empty() {
            return Err(PlotError::NoControlPoints);
        }
        Ok(PlotModel {
            dimension: D,
            curve: Geometry::Samples(to_pts(curve, "curve sample")?),
            controls: to_pts(controls, "control point")?,
            grid: None,
            names: Vec::new(),
            label: CURVE_LABEL.to_string(),
        })
    }

    /// A model of a tensor-product surface of any kind and its control net, labelled by kind
    /// ("Neutrosophic Bézier surface", "Neutrosophic B-spline surface", "Neutrosophic NURBS
    /// surface"). The surface is sampled on an `N x N` grid, evenly spaced in its parameter
    /// domain, when the figure is drawn (`N` from
    /// [`PlotOptions::surface_samples`](crate::PlotOptions::surface_samples)); its normals
    /// shade the mesh. The control points are taken row by row (as
    /// [`Surface::control_points`]), so names given to [`PlotModel::with_names`] follow that
    /// order.
    ///
    /// ```
    /// use neutrospline::{ControlPoint, Degrees, Surface};
    /// use neutrospline_plot::{render_svg, PlotModel, PlotOptions, View};
    /// let d = Degrees::new(0.7, 0.2, 0.1)?;
    /// let grid = (0..4)
    ///     .map(|k| ControlPoint::new([f64::from(k / 2), f64::from(k % 2), 0.0], d))
    ///     .collect();
    /// let model = PlotModel::from_surface(&Surface::bezier(2, 2, grid)?)?;
    /// assert_eq!(model.label(), "Neutrosophic Bézier surface");
    /// assert_eq!(model.grid(), Some((2, 2)));
    /// let options = PlotOptions::default().with_size(400, 300).with_samples(8);
    /// assert!(render_svg(&model, View::Truth, &options)?.contains("class=\"mesh\""));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`PlotError::NotFinite`] for a control value that is not finite (degrees built
    /// unchecked).
    pub fn from_surface(surface: &Surface) -> Result<PlotModel, PlotError> {
        let label = match surface.kind() {
            SurfaceKind::Bezier => BEZIER_SURFACE_LABEL,
            SurfaceKind::BSpline => BSPLINE_SURFACE_LABEL,
            SurfaceKind::Nurbs => NURBS_SURFACE_LABEL,
        };
        Ok(PlotModel {
            dimension: 3,
            curve: Geometry::Surface(Arc::new(surface.clone())),
            controls: to_pts(&surface.control_points(), "control point")?,
            grid: Some((surface.rows(), surface.cols())),
            names: Vec::new(),
            label: label.to_string(),
        })
    }

    /// Names the control points, in order (one name each, shown next to each point).
    ///
    /// # Errors
    /// [`PlotError::NamesMismatch`] when the count differs from the control points'.
    pub fn with_names<I, S>(mut self, names: I) -> Result<PlotModel, PlotError>
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        let names: Vec<String> = names.into_iter().map(Into::into).collect();
        if names.len() != self.controls.len() {
            return Err(PlotError::NamesMismatch {
                names: names.len(),
                points: self.controls.len(),
            });
        }
        self.names = names;
        Ok(self)
    }

    /// Sets the label used in default titles (for example "Neutrosophic B-spline").
    pub fn with_label(mut self, label: impl Into<String>) -> PlotModel {
        self.label = label.into();
        self
    }

    /// 2 or 3.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// Number of control points.
    pub fn control_count(&self) -> usize {
        self.controls.len()
    }

    /// Whether the model is a surface ([`PlotModel::from_surface`]).
    pub fn is_surface(&self) -> bool {
        matches!(self.curve, Geometry::Surface(_))
    }

    /// Rows and columns of a surface's control net (`None` for curves).
    pub fn grid(&self) -> Option<(usize, usize)> {
        self.grid
    }

    /// The control point names (empty when none were given).
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The label used in default titles: the one set by [`PlotModel::with_label`], else the
    /// kind of model: "Neutrosophic Bézier curve", "Neutrosophic B-spline curve",
    /// "Neutrosophic NURBS curve", "Neutrosophic Bézier surface", "Neutrosophic B-spline
    /// surface", "Neutrosophic NURBS surface", or "Neutrosophic curve" for
    /// [`PlotModel::from_curve`] and [`PlotModel::from_samples`].
    pub fn label(&self) -> &str {
        &self.label
    }

    pub(crate) fn controls(&self) -> &[Pt] {
        &self.controls
    }

    /// The curve points: the given samples, or `samples` evaluations (none for a surface).
    pub(crate) fn curve_points(&self, samples: usize) -> Result<Vec<Pt>, PlotError> {
        match &self.curve {
            Geometry::Samples(s) => Ok(s.clone()),
            Geometry::Curve(c) => c.sample(samples),
            Geometry::Surface(_) => Ok(Vec::new()),
        }
    }

    /// The surface sampled on an `n x n` grid, if the model is a surface.
    pub(crate) fn mesh(&self, n: usize) -> Result<Option<Mesh>, PlotError> {
        match &self.curve {
            Geometry::Surface(s) => sample_surface(s, n).map(Some),
            _ => Ok(None),
        }
    }
}

impl<const D: usize> From<&Bezier<D>> for PlotModel {
    /// Infallible: a Bézier curve is 2-D or 3-D with finite control values (its constructor
    /// checks both).
    fn from(curve: &Bezier<D>) -> PlotModel {
        let controls: Vec<Pt> = curve
            .control_points()
            .iter()
            .map(|p| {
                let mut pos = [0.0; 3];
                pos[..D].copy_from_slice(&p.position);
                Pt {
                    pos,
                    deg: p.degrees.to_array(),
                }
            })
            .collect();
        PlotModel {
            dimension: D,
            curve: Geometry::Curve(Arc::new(CurveSampler::<_, D>(curve.clone()))),
            controls,
            grid: None,
            names: Vec::new(),
            label: BEZIER_LABEL.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{BSpline, Degrees};

    #[test]
    fn model_from_any_bspline() {
        let pts: Vec<ControlPoint<2>> = (0..6)
            .map(|i| {
                let x = f64::from(i);
                NeutrosophicPoint::new([x, (x * 1.3).sin()], Degrees::new(0.5, 0.1, 0.2).unwrap())
            })
            .collect();
        let curve = AnyCurve::from(BSpline::clamped_uniform(pts, 3).unwrap());
        let model = PlotModel::from_any(&curve).unwrap();
        assert_eq!(model.label(), BSPLINE_LABEL);
        assert_eq!(model.control_count(), 6);
        let samples = model.curve_points(11).unwrap();
        assert_eq!(samples[0].pos, [0.0, 0.0, 0.0]);
        assert!((samples[10].pos[0] - 5.0).abs() < 1e-12);
    }

    #[test]
    fn model_from_bezier_samples_endpoints() {
        let curve = neutrospline::example1();
        let model = PlotModel::from(&curve);
        let pts = model.curve_points(5).unwrap();
        assert_eq!(pts.len(), 5);
        assert_eq!(pts[0].pos, [1.0, 3.0, 0.0]);
        assert_eq!(pts[4].pos, [9.0, 5.0, 0.0]);
        assert_eq!(pts[2].pos, [4.625, 4.0, 0.0]);
        assert_eq!(model.label(), BEZIER_LABEL);
    }

    #[test]
    fn model_names_must_match() {
        let model = PlotModel::from(&neutrospline::example1());
        let err = model.with_names(["a", "b"]).unwrap_err();
        assert_eq!(err.to_string(), "2 names given for 4 control points");
    }

    #[test]
    fn model_rejects_bad_input() {
        let d = Degrees::new(0.1, 0.2, 0.3).unwrap();
        let p = NeutrosophicPoint::new([0.0, f64::NAN], d);
        let good = NeutrosophicPoint::new([0.0, 0.0], d);
        let err = PlotModel::from_samples(&[good], &[p]).unwrap_err();
        assert_eq!(
            err.to_string(),
            "control point 0: y = NaN is not a finite number"
        );
        let one = NeutrosophicPoint::new([0.0; 1], d);
        assert_eq!(
            PlotModel::from_samples(&[one], &[one]).unwrap_err(),
            PlotError::UnsupportedDimension { dimension: 1 }
        );
        assert_eq!(
            PlotModel::from_samples::<2>(&[], &[good]).unwrap_err(),
            PlotError::NoCurvePoints
        );
        let nan_degree =
            NeutrosophicPoint::new([0.0, 0.0], Degrees::new_unchecked(f64::NAN, 0.0, 0.0));
        assert_eq!(
            PlotModel::from_samples(&[good], &[nan_degree])
                .unwrap_err()
                .to_string(),
            "control point 0: truth = NaN is not a finite number"
        );
    }
}
