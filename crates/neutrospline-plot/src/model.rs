//! What a figure shows: a curve, its control points and their names.

use std::fmt;
use std::ops::Range;
use std::sync::Arc;

use neutrospline::{
    alpha_cut, centroid_curve, uniform_parameter, AnyCurve, Bezier, ControlPoint, ControlPolygon,
    CurveKind, CurvePoint, DynCurve, EvaluateSurface, NearestPoint, NeutrosophicPoint, Spread,
    Surface, SurfaceKind,
};

use crate::error::PlotError;
use crate::nearest::nearest;
use crate::overlay::DataOverlay;
use crate::point::Pt;
use crate::quantity::Quantity;

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
    fn domain(&self) -> Range<f64>;
    /// The curve at parameter `t` (of the point `index` of the data overlay, for errors).
    fn at(&self, t: f64, index: usize) -> Result<Pt, PlotError>;
    /// The parameter of the curve's global nearest point to `target` (the core's
    /// [`NearestPoint`], as `neutrospline query` finds it; z ignored for a plane curve), for
    /// the data point `index`.
    fn nearest(&self, target: [f64; 3], index: usize) -> Result<f64, PlotError>;
}

struct CurveSampler<C, const D: usize>(C);

impl<C, const D: usize> Sampler for CurveSampler<C, D>
where
    C: NearestPoint<D> + Send + Sync,
{
    fn sample(&self, n: usize) -> Result<Vec<Pt>, PlotError> {
        let ts = parameters(self.0.domain(), n);
        let mut out = vec![self.0.start()?; ts.len()];
        self.0.evaluate_many(&ts, &mut out)?;
        to_pts(&out, "curve sample")
    }

    fn domain(&self) -> Range<f64> {
        self.0.domain()
    }

    fn at(&self, t: f64, index: usize) -> Result<Pt, PlotError> {
        to_pt(&self.0.evaluate(t)?, "curve point of data point", index)
    }

    fn nearest(&self, target: [f64; 3], index: usize) -> Result<f64, PlotError> {
        let point: [f64; D] = core::array::from_fn(|a| target[a]);
        self.0
            .nearest(point)
            .map(|near| near.parameter)
            .map_err(|source| PlotError::Nearest { index, source })
    }
}

/// A fuzzy curve that can be sampled at render time: its alpha-cut curves and its centroid
/// curve, at the parameters of [`Sampler::sample`].
pub(crate) trait BandSampler: Send + Sync {
    /// The lower and upper curves of the alpha-cut, `n` samples each.
    fn cut(&self, alpha: f64, n: usize) -> Result<(Vec<Pt>, Vec<Pt>), PlotError>;
    /// The centroid curve, `n` samples.
    fn centroid(&self, n: usize) -> Result<Vec<Pt>, PlotError>;
}

/// A curve with one spread per control point.
struct FuzzyCurve<const D: usize> {
    curve: AnyCurve<D>,
    spreads: Vec<Spread<D>>,
}

impl<const D: usize> FuzzyCurve<D> {
    fn sample(curve: &AnyCurve<D>, n: usize) -> Result<Vec<Pt>, PlotError> {
        CurveSampler::<_, D>(curve.clone()).sample(n)
    }
}

impl<const D: usize> BandSampler for FuzzyCurve<D> {
    fn cut(&self, alpha: f64, n: usize) -> Result<(Vec<Pt>, Vec<Pt>), PlotError> {
        let (lower, upper) = alpha_cut(&self.curve, &self.spreads, alpha)
            .map_err(|e| PlotError::Fuzzy(e.to_string()))?;
        Ok((Self::sample(&lower, n)?, Self::sample(&upper, n)?))
    }

    fn centroid(&self, n: usize) -> Result<Vec<Pt>, PlotError> {
        let centroid = centroid_curve(&self.curve, &self.spreads)
            .map_err(|e| PlotError::Fuzzy(e.to_string()))?;
        Self::sample(&centroid, n)
    }
}

/// The parameter domain of a model given as samples: the samples are taken at evenly spaced
/// parameters over \[0, 1\], joined by straight lines.
const SAMPLES_DOMAIN: Range<f64> = 0.0..1.0;

/// The polyline through `samples` at parameter `t` of [`SAMPLES_DOMAIN`].
fn polyline_at(samples: &[Pt], t: f64) -> Pt {
    let n = samples.len();
    if n < 2 {
        return samples[0];
    }
    let s = t.clamp(0.0, 1.0) * (n - 1) as f64;
    let k = (s.floor() as usize).min(n - 2);
    let f = s - k as f64;
    let (a, b) = (samples[k], samples[k + 1]);
    let lerp = |x: f64, y: f64| if f == 0.0 { x } else { x + (y - x) * f };
    Pt {
        pos: [0, 1, 2].map(|i| lerp(a.pos[i], b.pos[i])),
        deg: [0, 1, 2].map(|i| lerp(a.deg[i], b.deg[i])),
    }
}

/// The data points and, one each, the curve points their whiskers go to.
pub(crate) type Residuals = (Vec<Pt>, Vec<Pt>);

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

    /// The quantity `q` (a degree or the score) of the cell between samples `(a, b)` and
    /// `(a + 1, b + 1)`: the mean of its four corners.
    pub(crate) fn cell_value(&self, a: usize, b: usize, q: Quantity) -> f64 {
        [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)]
            .iter()
            .map(|&(i, j)| q.at(self.at(i, j)))
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
    /// The control points that get a name or callout: all, or a periodic curve's distinct
    /// ones (its last `degree` repeat its first).
    labelled: Option<usize>,
    label: String,
    data: Option<DataOverlay>,
    /// The fuzzy position of a curve (control point spreads, SPEC section 9), for the band
    /// view; `None` draws the curve as crisp.
    band: Option<Arc<dyn BandSampler>>,
    /// The membership family of the degrees: which views draw them truthfully
    /// ([`PlotModel::check_view`]).
    family: neutrospline::Family,
    /// The second lane of an interval-valued or bipolar family (docs/model.md, "Lanes"): the
    /// same geometry with the upper (or the negated negative) degrees in its three slots;
    /// `None` for the families of one lane.
    second: Option<Arc<PlotModel>>,
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
            .finish()?;
        match &self.data {
            Some(d) => write!(f, " with {} data points", d.positions.len()),
            None => Ok(()),
        }
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
        C: NearestPoint<D> + Send + Sync + 'static,
    {
        check_dimension(D)?;
        if controls.is_empty() {
            return Err(PlotError::NoControlPoints);
        }
        let curve = Geometry::Curve(Arc::new(CurveSampler::<C, D>(curve)));
        PlotModel::curve_model(curve, controls)
    }

    /// The model of a `D`-dimensional curve, `curve`, with its control points, unnamed,
    /// labelled `CURVE_LABEL`.
    fn curve_model<const D: usize>(
        curve: Geometry,
        controls: &[ControlPoint<D>],
    ) -> Result<PlotModel, PlotError> {
        Ok(PlotModel {
            dimension: D,
            curve,
            controls: to_pts(controls, "control point")?,
            grid: None,
            names: Vec::new(),
            labelled: None,
            label: CURVE_LABEL.to_string(),
            data: None,
            band: None,
            family: neutrospline::Family::Neutrosophic,
            second: None,
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
        let mut model = PlotModel::from_curve(curve.clone(), &curve.control_points())?;
        model.labelled = curve.periodic_count();
        Ok(model.with_label(label))
    }

    /// [`PlotModel::from_any`] for a curve of either dimension.
    ///
    /// # Errors
    /// As [`PlotModel::from_any`].
    pub fn from_dyn(curve: &DynCurve) -> Result<PlotModel, PlotError> {
        neutrospline::on_dimension!(curve, c => PlotModel::from_any(c))
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
        let curve = Geometry::Samples(to_pts(curve, "curve sample")?);
        PlotModel::curve_model(curve, controls)
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
            labelled: None,
            label: label.to_string(),
            data: None,
            band: None,
            family: neutrospline::Family::Neutrosophic,
            second: None,
        })
    }

    /// The figure model of a model file's shape ([`neutrospline_io::Model`]), with its control
    /// points' names when the file gives any (`P{i}` for the unnamed ones): what
    /// `neutrospline plot`, the Python package and the studio draw.
    ///
    /// ```
    /// use neutrospline_io::{parse, Format, ReadOptions};
    /// use neutrospline_plot::PlotModel;
    /// let text = "kind = \"bezier\"\n[[control_points]]\nname = \"A\"\nx = 0\ny = 0\ntruth = 1\n\
    ///             indeterminacy = 0\nfalsity = 0\n[[control_points]]\nx = 1\ny = 1\ntruth = 0\n\
    ///             indeterminacy = 0\nfalsity = 1\n";
    /// let model = parse("line.toml", Format::Toml, text.as_bytes(), &ReadOptions::default())?;
    /// let figure = PlotModel::from_model(&model)?;
    /// assert_eq!(figure.names(), ["A", "P1"]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`PlotModel::from_any`] and [`PlotModel::from_surface`].
    pub fn from_model(model: &neutrospline_io::Model) -> Result<PlotModel, PlotError> {
        use neutrospline_io::Shape;
        let zero = vec![Spread::ZERO; model.shape().control_count()];
        let spreads = model.spreads().unwrap_or(&zero);
        let figure = match model.shape() {
            Shape::Curve(c) => neutrospline::on_dimension!(c, c => {
                PlotModel::from_any(c)?.with_band(FuzzyCurve {
                    curve: c.clone(),
                    spreads: spreads.iter().map(Spread::resize).collect(),
                })
            }),
            Shape::Surface(s) => PlotModel::from_surface(s)?,
        };
        let mut figure = figure;
        let family = model.membership();
        figure.family = family;
        // A wide family's second lane: the same geometry, its own three slots.
        if let Some(second) = model.lanes().get(1) {
            let lane = match second {
                Shape::Curve(c) => neutrospline::on_dimension!(c, c => PlotModel::from_any(c)?),
                Shape::Surface(s) => PlotModel::from_surface(s)?,
            };
            figure.second = Some(Arc::new(lane));
        }
        // The title names the family beyond the original three: "Pythagorean fuzzy Bézier
        // curve", "q-rung (q = 4) orthopair fuzzy B-spline curve", "Interval-valued
        // neutrosophic Bézier curve", ...
        use neutrospline::Family;
        let adjective = match family {
            Family::Neutrosophic | Family::Intuitionistic | Family::Fuzzy => None,
            Family::QRung(q) => Some(format!("q-rung (q = {q}) orthopair fuzzy")),
            Family::TSpherical(n) => Some(format!("T-spherical (n = {n}) fuzzy")),
            Family::IntervalNeutrosophic => Some("Interval-valued neutrosophic".to_string()),
            Family::IntervalIntuitionistic => {
                Some("Interval-valued intuitionistic fuzzy".to_string())
            }
            Family::IntervalType2 => Some("Interval type-2 fuzzy".to_string()),
            Family::BipolarNeutrosophic => Some("Bipolar neutrosophic".to_string()),
            other => {
                let name = other.name();
                let mut chars = name.chars();
                let capital: String = chars
                    .next()
                    .map(|c| c.to_ascii_uppercase())
                    .into_iter()
                    .chain(chars)
                    .collect();
                Some(format!("{capital} fuzzy"))
            }
        };
        if let Some(adjective) = adjective {
            if let Some(rest) = figure.label.strip_prefix("Neutrosophic") {
                figure.label = format!("{adjective}{rest}");
            }
        }
        let names = model.point_names();
        if names.iter().all(Option::is_none) {
            return Ok(figure);
        }
        let names = names
            .iter()
            .enumerate()
            .map(|(i, n)| n.clone().unwrap_or_else(|| format!("P{i}")));
        figure.with_names(names)
    }

    /// The membership family of the degrees (neutrosophic unless the model came from a model
    /// file of another family, [`PlotModel::from_model`]).
    pub fn family(&self) -> neutrospline::Family {
        self.family
    }

    /// The second lane of an interval-valued or bipolar model: the same geometry with the
    /// upper degrees (or the negative degrees, negated) in its slots.
    pub(crate) fn second_lane(&self) -> Option<&PlotModel> {
        self.second.as_deref()
    }

    /// Refuses a view that would misdraw the degrees of this model's family, or that has
    /// nothing to draw for it. The `score` view draws the family's own score
    /// ([`neutrospline::Family::score`]) and the `derived` view its derived degrees
    /// ([`neutrospline::Family::derived`]), refused for a family that derives none
    /// (neutrosophic, fuzzy, interval-neutrosophic, bipolar-neutrosophic). The other views
    /// draw truth, indeterminacy and falsity: a family outside the original three that does
    /// not carry indeterminacy (the orthopair families: pythagorean, q-rung, ...) has no
    /// indeterminacy to draw.
    ///
    /// The interval-valued and bipolar families carry two values per degree (docs/model.md,
    /// "Lanes"). Their `truth`, `indeterminacy` and `falsity` views draw both (a 2-D curve:
    /// the lower and upper curves with the band between them, or the positive degree above
    /// the crisp plane and the negative one below it; a 3-D curve or a surface: two panels,
    /// one per lane), and the `all` view of a 2-D curve draws every degree's pair. The views
    /// that draw one value per degree are refused: `controls` (three bars per point), `plane`
    /// (three lanes whose widths are the degrees), `data` (data points coloured by one
    /// degree), and `all` of a 3-D curve or surface (one panel per degree).
    ///
    /// The messages name views as `` the view `truth` ``, for the command line's `--view` and
    /// the studio's view boxes alike.
    ///
    /// ```
    /// use neutrospline_io::{parse, Format, ReadOptions};
    /// use neutrospline_plot::{PlotModel, View};
    /// let text = "kind = \"bezier\"\nmembership = \"interval-type2\"\n\
    ///             [[control_points]]\nx = 0\ny = 0\ntruth_lower = 0.2\ntruth_upper = 0.5\n\
    ///             [[control_points]]\nx = 1\ny = 1\ntruth_lower = 0.6\ntruth_upper = 0.7\n";
    /// let model = parse("fou.toml", Format::Toml, text.as_bytes(), &ReadOptions::default())?;
    /// let figure = PlotModel::from_model(&model)?;
    /// assert!(figure.check_view(View::Truth).is_ok());
    /// assert!(figure.check_view(View::Score).is_ok());
    /// assert_eq!(
    ///     figure.check_view(View::Falsity).unwrap_err().to_string(),
    ///     "the view `falsity` does not draw interval-type2 models: interval type-2 degrees are \
    ///      a lower and an upper membership, held as truth_lower and truth_upper; draw the view \
    ///      `truth` (or `all`) for the footprint of uncertainty between them"
    /// );
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`PlotError::FamilyView`] naming the view, the family and why.
    pub fn check_view(&self, view: crate::View) -> Result<(), PlotError> {
        use crate::View;
        use neutrospline::{DegreeKind, Family};
        let family = self.family;
        let reason = if view == View::Score {
            return Ok(());
        } else if view == View::Derived {
            if !family.derived_names().is_empty() {
                return Ok(());
            }
            let views: Vec<String> = View::ALL
                .into_iter()
                .filter(|&v| !matches!(v, View::Derived | View::Data | View::Band))
                .filter(|&v| self.check_view(v).is_ok())
                .map(|v| format!("`{v}`"))
                .collect();
            format!(
                "the derived view draws the degrees a family derives from its channels \
                 (hesitation, refusal, footprint, ...), and {family} degrees derive none; the \
                 views of this model are {}",
                views.join(", ")
            )
        } else if family == Family::Neutrosophic
            || matches!(family, Family::Intuitionistic | Family::Fuzzy)
        {
            return Ok(());
        } else if self.second.is_some() {
            match self.wide_refusal(view) {
                Some(reason) => reason,
                None => return Ok(()),
            }
        } else if matches!(
            view,
            View::Indeterminacy | View::All | View::Plane | View::Controls
        ) && !family.carries(DegreeKind::Indeterminacy)
        {
            format!(
                "{family} degrees are {} (no indeterminacy); draw the view `truth` or `falsity`",
                family.channels().join(" and ")
            )
        } else {
            return Ok(());
        };
        Err(PlotError::FamilyView {
            view: view.name().to_owned(),
            family: family.to_string(),
            reason,
        })
    }

    /// Why `view` would misdraw this wide (two-lane) model, if it would.
    fn wide_refusal(&self, view: crate::View) -> Option<String> {
        use crate::View;
        use neutrospline::Family;
        let family = self.family;
        let pairs = match family {
            Family::BipolarNeutrosophic => "a positive and a negative value",
            _ => "a lower and an upper value",
        };
        let channels = family.channels().join(", ");
        let degree_views = match family {
            Family::IntervalType2 => "the view `truth` (or `all`)",
            Family::IntervalIntuitionistic => "the view `truth`, `falsity` or `all`",
            _ => "the view `truth`, `indeterminacy`, `falsity` or `all`",
        };
        let one_degree = match family {
            Family::IntervalType2 => "the view `truth`",
            Family::IntervalIntuitionistic => "the view `truth` or `falsity`",
            _ => "the view `truth`, `indeterminacy` or `falsity`",
        };
        match view {
            View::Controls => Some(format!(
                "the controls view draws one truth, indeterminacy and falsity bar per control \
                 point, and {family} points carry {pairs} per degree ({channels}); draw \
                 {degree_views}"
            )),
            View::Plane => Some(format!(
                "the plane view widens three lanes by one truth, indeterminacy and falsity, and \
                 {family} degrees carry {pairs} each ({channels}); draw {degree_views}"
            )),
            View::Data => Some(format!(
                "the data view colours data points by one degree, and {family} degrees carry \
                 {pairs} each ({channels})"
            )),
            View::All if self.dimension == 3 || self.is_surface() => Some(format!(
                "the all view of a 3-D curve or a surface draws one panel per degree, and \
                 {family} degrees carry {pairs} each; draw {one_degree} for two panels, one \
                 per lane"
            )),
            View::Indeterminacy | View::Falsity if family == Family::IntervalType2 => Some(
                "interval type-2 degrees are a lower and an upper membership, held as \
                 truth_lower and truth_upper; draw the view `truth` (or `all`) for the \
                 footprint of uncertainty between them"
                    .to_string(),
            ),
            View::Indeterminacy if family == Family::IntervalIntuitionistic => Some(format!(
                "interval-intuitionistic degrees are {channels} (no indeterminacy); draw the \
                 view `truth` or `falsity`"
            )),
            _ => None,
        }
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

    /// Attaches measured data points, drawn by the [`data`](crate::View::Data) view next to
    /// this curve or surface (the one fitted to them): the curve as a line (a surface as its
    /// mesh), each point as a marker coloured by its [`color_by`](DataOverlay::color_by)
    /// degree, and a residual whisker from each point to the curve at its parameter (the
    /// surface at its `(u, v)`) or, without parameters, to the nearest point. Other views ignore the data. For a 2-D model the points' z is
    /// ignored (set to 0). A model given as samples ([`PlotModel::from_samples`]) has the
    /// parameter domain \[0, 1\]: its samples at evenly spaced parameters, joined by
    /// straight lines.
    ///
    /// ```
    /// use neutrospline_plot::{DataOverlay, PlotError, PlotModel};
    /// let model = PlotModel::from(&neutrospline::example1());
    /// let data = DataOverlay::new(vec![[4.0, 4.5, 0.0]], vec![[0.6, 0.2, 0.1]]);
    /// assert!(model.clone().with_data(data.clone())?.data().is_some());
    /// let err = model.with_data(data.with_parameters(vec![1.5])).unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "data point 0: parameter t = 1.5 is outside the curve's domain [0, 1]"
    /// );
    /// # Ok::<(), PlotError>(())
    /// ```
    ///
    /// # Errors
    /// [`PlotError::EmptyData`] without points, [`PlotError::DataCount`] when the degrees or
    /// parameters are not one per point, [`PlotError::ParameterKind`] for curve parameters
    /// given to a surface or surface parameters to a curve, [`PlotError::NotFinite`] for a
    /// coordinate, degree or parameter that is NaN or infinite, [`PlotError::DataDegreeRange`]
    /// for a degree outside \[0, 1\], [`PlotError::ParameterOutsideDomain`] for a parameter
    /// outside the curve's domain and [`PlotError::SurfaceParameterOutsideDomain`] for a
    /// `(u, v)` outside the surface's.
    pub fn with_data(mut self, data: DataOverlay) -> Result<PlotModel, PlotError> {
        self.data = Some(match &self.curve {
            Geometry::Surface(s) => data.checked_on_surface(s.domain())?,
            Geometry::Samples(_) => data.checked(self.dimension, SAMPLES_DOMAIN)?,
            Geometry::Curve(c) => data.checked(self.dimension, c.domain())?,
        });
        Ok(self)
    }

    /// The data points drawn by the `data` view ([`PlotModel::with_data`]), if any.
    pub fn data(&self) -> Option<&DataOverlay> {
        self.data.as_ref()
    }

    /// The data points and, for each, the curve point it was fitted to: the curve at its
    /// parameter, else the curve's global nearest point to it (the core's `NearestPoint`; for a
    /// model given as samples, the nearest point of the polyline).
    /// For a surface: the surface at each point's `(u, v)`, else its global nearest point
    /// (the core's `SurfaceProjector`). `None` without data.
    pub(crate) fn residuals(&self) -> Result<Option<Residuals>, PlotError> {
        let Some(data) = &self.data else {
            return Ok(None);
        };
        let points: Vec<Pt> = data
            .positions
            .iter()
            .zip(&data.degrees)
            .map(|(&pos, &deg)| Pt { pos, deg })
            .collect();
        let feet = match (&self.curve, &data.parameters) {
            (Geometry::Surface(s), _) => {
                surface_feet(s, &points, data.surface_parameters.as_deref())?
            }
            (Geometry::Curve(c), Some(ts)) => ts
                .iter()
                .enumerate()
                .map(|(k, &t)| c.at(t, k))
                .collect::<Result<Vec<Pt>, PlotError>>()?,
            (Geometry::Samples(s), Some(ts)) => ts.iter().map(|&t| polyline_at(s, t)).collect(),
            (Geometry::Curve(c), None) => points
                .iter()
                .enumerate()
                .map(|(k, p)| c.at(c.nearest(p.pos, k)?, k))
                .collect::<Result<Vec<Pt>, PlotError>>()?,
            (Geometry::Samples(s), None) => {
                let n = s.len();
                let ts = parameters(SAMPLES_DOMAIN, n);
                let pos: Vec<[f64; 3]> = s.iter().map(|p| p.pos).collect();
                let at = |t: f64| Ok::<_, PlotError>(polyline_at(s, t).pos);
                points
                    .iter()
                    .map(|p| nearest(&at, &ts[..n], &pos, p.pos).map(|(t, _)| polyline_at(s, t)))
                    .collect::<Result<Vec<Pt>, PlotError>>()?
            }
        };
        Ok(Some((points, feet)))
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

    /// With the fuzzy position of the curve, for the band view.
    fn with_band(mut self, band: impl BandSampler + 'static) -> PlotModel {
        self.band = Some(Arc::new(band));
        self
    }

    /// The alpha-cut of the curve at `alpha` (lower and upper samples) and its centroid
    /// curve, at the parameters of [`PlotModel::curve_points`]; a crisp curve (no spreads)
    /// gives its own samples.
    #[allow(clippy::type_complexity)]
    pub(crate) fn band_points(
        &self,
        alphas: &[f64],
        samples: usize,
    ) -> Result<(Vec<(f64, Vec<Pt>, Vec<Pt>)>, Vec<Pt>), PlotError> {
        match &self.band {
            Some(band) => Ok((
                alphas
                    .iter()
                    .map(|&a| band.cut(a, samples).map(|(lo, hi)| (a, lo, hi)))
                    .collect::<Result<_, _>>()?,
                band.centroid(samples)?,
            )),
            None => {
                let crisp = self.curve_points(samples)?;
                Ok((
                    alphas
                        .iter()
                        .map(|&a| (a, crisp.clone(), crisp.clone()))
                        .collect(),
                    crisp,
                ))
            }
        }
    }

    pub(crate) fn controls(&self) -> &[Pt] {
        &self.controls
    }

    /// How many control points, from the first, are named or called out (a periodic curve's
    /// copies of its first points are not).
    pub(crate) fn labelled(&self) -> usize {
        self.labelled.unwrap_or(self.controls.len())
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
            labelled: None,
            label: BEZIER_LABEL.to_string(),
            data: None,
            band: None,
            family: neutrospline::Family::Neutrosophic,
            second: None,
        }
    }
}

/// The feet of data `points` on surface `s`: the surface at `uv[k]` when given, else the
/// surface's point nearest to point `k`.
fn surface_feet(s: &Surface, points: &[Pt], uv: Option<&[[f64; 2]]>) -> Result<Vec<Pt>, PlotError> {
    let foot = |p: neutrospline::CurvePoint<3>| Pt {
        pos: p.position,
        deg: p.degrees.to_array(),
    };
    match uv {
        Some(uv) => uv
            .iter()
            .map(|&[u, v]| Ok(foot(s.evaluate(u, v)?)))
            .collect(),
        None => {
            let projector = neutrospline::SurfaceProjector::new(s);
            points
                .iter()
                .enumerate()
                .map(|(index, p)| {
                    projector
                        .nearest(p.pos)
                        .map(|n| foot(n.point))
                        .map_err(|source| PlotError::Nearest { index, source })
                })
                .collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{BSpline, Degrees, Evaluate};

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
    fn model_residual_feet_are_the_curve_at_the_parameters() {
        let curve = neutrospline::example1();
        let ts = [0.0, 0.125, 0.4, 0.77, 1.0];
        let positions = ts.iter().map(|&t| [t * 10.0, 1.0 - t, 7.0]).collect();
        let data =
            DataOverlay::new(positions, vec![[0.3, 0.2, 0.1]; 5]).with_parameters(ts.to_vec());
        let model = PlotModel::from(&curve).with_data(data).unwrap();
        let (points, feet) = model.residuals().unwrap().unwrap();
        assert_eq!(points[1].pos, [1.25, 0.875, 0.0], "z of 2-D data is 0");
        for (k, &t) in ts.iter().enumerate() {
            let p = curve.evaluate(t).unwrap();
            for i in 0..2 {
                assert!((feet[k].pos[i] - p.position[i]).abs() < 1e-9, "{k}");
            }
            assert_eq!(feet[k].pos[2], 0.0);
            assert!((feet[k].deg[0] - p.degrees.truth()).abs() < 1e-9);
        }
    }

    /// The whiskers end at the core's global nearest point (`neutrospline query`'s): on the
    /// straight cubic of issue 22 (first two control points 1e-13 apart, last two equal),
    /// where a search from samples and the old root finder both went astray, each data point
    /// on the line gets its foot on the line, at the nearest point's parameter exactly.
    #[test]
    fn model_residual_feet_are_the_global_nearest_points() {
        use neutrospline::{ControlPoint, NearestPoint};
        let d = Degrees::new(0.5, 0.25, 0.125).unwrap();
        let curve = Bezier::new(
            [
                [461.0, 123.0],
                [461.0 - 6e-14, 123.0 + 4e-14],
                [111.0, 319.0],
                [111.0, 319.0],
            ]
            .map(|p| ControlPoint::new(p, d))
            .to_vec(),
        )
        .unwrap();
        let data: Vec<[f64; 3]> = (1..10)
            .map(|k| {
                let s = f64::from(k) / 10.0;
                [461.0 - 350.0 * s, 123.0 + 196.0 * s, 0.0]
            })
            .collect();
        let overlay = DataOverlay::new(data.clone(), vec![[0.5, 0.25, 0.125]; data.len()]);
        let model = PlotModel::from_bezier(&curve)
            .unwrap()
            .with_data(overlay)
            .unwrap();
        let (_, feet) = model.residuals().unwrap().unwrap();
        for (q, foot) in data.iter().zip(&feet) {
            let near = curve.nearest([q[0], q[1]]).unwrap();
            assert_eq!([foot.pos[0], foot.pos[1]], near.point.position);
            assert!(near.distance < 1e-11, "{q:?}: {near:?}");
        }
    }

    #[test]
    fn model_residual_feet_without_parameters_are_the_nearest_points() {
        // Example 1 is a planar cubic: at the nearest point, the residual is perpendicular to
        // the tangent, and no sample of the curve is nearer.
        let curve = neutrospline::example1();
        let targets = [
            [3.0, 6.0, 0.0],
            [6.0, 2.0, 0.0],
            [9.5, 5.5, 0.0],
            [0.0, 0.0, 0.0],
        ];
        let data = DataOverlay::new(targets.to_vec(), vec![[0.5; 3]; 4]);
        let model = PlotModel::from(&curve).with_data(data).unwrap();
        let (_, feet) = model.residuals().unwrap().unwrap();
        let dense = model.curve_points(20_000).unwrap();
        for (q, foot) in targets.iter().zip(&feet) {
            let d = |p: &[f64; 3]| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
            let best = dense
                .iter()
                .map(|p| d(&p.pos))
                .fold(f64::INFINITY, f64::min);
            assert!(d(&foot.pos) <= best + 1e-12, "{q:?}");
            assert!(best - d(&foot.pos) < 1e-4, "{q:?}");
        }
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

    /// A wide model's two lanes share the positions; lane 0 holds the lower degrees and lane
    /// 1 the upper, each the Bernstein blend of its control values (tests/wide/interval.toml:
    /// truth_lower 0.2, 0.6, 0.4, 0.7; truth_upper 0.5, 0.9, 0.55, 0.8; falsity_upper 0.2,
    /// 0.15, 0.45, 0.7), computed here by hand at t = 1/2: (a + 3b + 3c + d) / 8.
    #[test]
    fn model_wide_lanes_are_the_lower_and_upper_blends() {
        let text = include_str!("../tests/wide/interval.toml");
        let file = neutrospline_io::parse(
            "interval.toml",
            neutrospline_io::Format::Toml,
            text.as_bytes(),
            &neutrospline_io::ReadOptions::default(),
        )
        .unwrap();
        let model = PlotModel::from_model(&file).unwrap();
        assert_eq!(model.family(), neutrospline::Family::IntervalNeutrosophic);
        assert_eq!(model.label(), "Interval-valued neutrosophic Bézier curve");
        let upper = model.second_lane().unwrap();
        let (lo, hi) = (
            model.curve_points(3).unwrap(),
            upper.curve_points(3).unwrap(),
        );
        assert_eq!(lo[1].pos, hi[1].pos, "one geometry");
        let half = |a: f64, b: f64, c: f64, d: f64| (a + 3.0 * b + 3.0 * c + d) / 8.0;
        assert!((lo[1].deg[0] - half(0.2, 0.6, 0.4, 0.7)).abs() < 1e-15);
        assert!((hi[1].deg[0] - half(0.5, 0.9, 0.55, 0.8)).abs() < 1e-15);
        assert!((hi[1].deg[2] - half(0.2, 0.15, 0.45, 0.7)).abs() < 1e-15);
        assert_eq!(upper.controls()[2].deg, [0.55, 0.8, 0.45]);
        // A model of one lane has none.
        assert!(PlotModel::from(&neutrospline::example1())
            .second_lane()
            .is_none());
    }
}
