//! What a figure shows: a curve, its control points and their names.

use std::fmt;
use std::sync::Arc;

use neutrospline::{
    AnyCurve, Bezier, ControlPoint, CurveKind, CurvePoint, Evaluate, NeutrosophicPoint,
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

impl<C: Evaluate<D> + Send + Sync, const D: usize> Sampler for CurveSampler<C, D> {
    fn sample(&self, n: usize) -> Result<Vec<Pt>, PlotError> {
        let (start, end) = self.0.domain();
        let n = n.max(2);
        let last = (n - 1) as f64;
        // The end parameter is exact; the others are affine in k, never past `end`.
        let ts: Vec<f64> = (0..n)
            .map(|k| {
                if k + 1 == n {
                    end
                } else {
                    (start + (end - start) * (k as f64 / last)).min(end)
                }
            })
            .collect();
        let mut out = vec![self.0.start(); n];
        self.0.evaluate_many(&ts, &mut out)?;
        to_pts(&out, "curve sample")
    }
}

#[derive(Clone)]
enum CurveData {
    Samples(Vec<Pt>),
    Curve(Arc<dyn Sampler>),
}

/// What a figure shows: a neutrosophic curve (sampled when drawn, or given as samples), its
/// control points and, optionally, their names.
///
/// The model is independent of the curve kind: anything that implements
/// [`neutrospline::Evaluate`] can feed it through [`PlotModel::from_curve`], and
/// [`PlotModel::from_samples`] takes points computed elsewhere. Positions are 2-D (the paper's
/// model: the degrees become the third axis of the 3-D views) or 3-D.
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
    curve: CurveData,
    controls: Vec<Pt>,
    names: Vec<String>,
    label: String,
}

impl fmt::Debug for PlotModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let curve = match &self.curve {
            CurveData::Samples(s) => format!("{} samples", s.len()),
            CurveData::Curve(_) => "curve".to_string(),
        };
        f.debug_struct("PlotModel")
            .field("dimension", &self.dimension)
            .field("curve", &curve)
            .field("controls", &self.controls.len())
            .field("names", &self.names)
            .field("label", &self.label)
            .finish()
    }
}

/// The label of models made from a [`Bezier`].
pub const BEZIER_LABEL: &str = "Neutrosophic Bézier curve";
/// The label of models made from a B-spline ([`AnyCurve::BSpline`]).
pub const BSPLINE_LABEL: &str = "Neutrosophic B-spline curve";
/// The label of models made from a NURBS curve ([`AnyCurve::Nurbs`]).
pub const NURBS_LABEL: &str = "Neutrosophic NURBS curve";
/// The label of models made by [`PlotModel::from_curve`] and [`PlotModel::from_samples`].
pub const CURVE_LABEL: &str = "Neutrosophic curve";

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
        C: Evaluate<D> + Send + Sync + 'static,
    {
        check_dimension(D)?;
        if controls.is_empty() {
            return Err(PlotError::NoControlPoints);
        }
        Ok(PlotModel {
            dimension: D,
            curve: CurveData::Curve(Arc::new(CurveSampler(curve))),
            controls: to_pts(controls, "control point")?,
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
            curve: CurveData::Samples(to_pts(curve, "curve sample")?),
            controls: to_pts(controls, "control point")?,
            names: Vec::new(),
            label: CURVE_LABEL.to_string(),
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

    /// The control point names (empty when none were given).
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The label used in default titles.
    pub fn label(&self) -> &str {
        &self.label
    }

    pub(crate) fn controls(&self) -> &[Pt] {
        &self.controls
    }

    /// The curve points: the given samples, or `samples` evaluations.
    pub(crate) fn curve_points(&self, samples: usize) -> Result<Vec<Pt>, PlotError> {
        match &self.curve {
            CurveData::Samples(s) => Ok(s.clone()),
            CurveData::Curve(c) => c.sample(samples),
        }
    }
}

impl From<&Bezier<2>> for PlotModel {
    fn from(curve: &Bezier<2>) -> PlotModel {
        let controls: Vec<Pt> = curve
            .control_points()
            .iter()
            .map(|p| Pt {
                pos: [p.position[0], p.position[1], 0.0],
                deg: p.degrees.to_array(),
            })
            .collect();
        PlotModel {
            dimension: 2,
            curve: CurveData::Curve(Arc::new(CurveSampler(curve.clone()))),
            controls,
            names: Vec::new(),
            label: BEZIER_LABEL.to_string(),
        }
    }
}

impl From<&Bezier<3>> for PlotModel {
    fn from(curve: &Bezier<3>) -> PlotModel {
        let controls: Vec<Pt> = curve
            .control_points()
            .iter()
            .map(|p| Pt {
                pos: p.position,
                deg: p.degrees.to_array(),
            })
            .collect();
        PlotModel {
            dimension: 3,
            curve: CurveData::Curve(Arc::new(CurveSampler(curve.clone()))),
            controls,
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
