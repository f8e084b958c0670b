//! The curves derived from a curve (split, elevated, with knots inserted), their degrees
//! under the membership rule and their spreads.

use neutrospline::alpha_cut;
use neutrospline::{
    AnyCurve, BSpline as BSplineCurve, Bezier as BezierCurve, ControlPoint, ControlPolygon,
    CurveError, Degrees, Family, KnotVector, Nurbs as NurbsCurve, Spread,
};
use neutrospline_io::Shape;
use pyo3::prelude::*;

use super::{model_into_py, Curve};
use crate::errors::invalid;
use crate::model;

/// Control points with degrees re-derived under `membership` (the intuitionistic
/// indeterminacy `1 - truth - falsity` recomputed after blending, which rounds).
pub(super) fn under_rule<const D: usize>(
    curve: AnyCurve<D>,
    membership: Family,
) -> PyResult<AnyCurve<D>> {
    if membership != Family::Intuitionistic {
        return Ok(curve);
    }
    let points: Vec<ControlPoint<D>> = curve
        .control_points()
        .into_iter()
        .map(|p| {
            let [t, _, f] = p.degrees.to_array();
            let d = Degrees::with_membership(membership, t, None, Some(f)).map_err(invalid)?;
            Ok(ControlPoint::new(p.position, d))
        })
        .collect::<PyResult<_>>()?;
    let rebuilt: Result<AnyCurve<D>, CurveError> = match &curve {
        AnyCurve::Bezier(_) => BezierCurve::new(points).map(Into::into),
        AnyCurve::BSpline(c) => BSplineCurve::new(points, c.knots().clone()).map(Into::into),
        AnyCurve::Nurbs(c) => NurbsCurve::new(
            points,
            c.weights().map(<[f64]>::to_vec).unwrap_or_default(),
            c.knots().clone(),
        )
        .map(Into::into),
    };
    rebuilt.map_err(invalid)
}

/// The spreads of the control points of `crisp` whose alpha = 0 cut curves are `lower` and
/// `upper` (the same kind and knots): `left = crisp - lower`, `right = upper - crisp` per axis
/// (non-negative up to rounding, which is clamped).
pub(super) fn spreads_between<const D: usize>(
    crisp: &AnyCurve<D>,
    lower: &AnyCurve<D>,
    upper: &AnyCurve<D>,
) -> Vec<Spread<3>> {
    let (c, lo, hi) = (
        crisp.control_points(),
        lower.control_points(),
        upper.control_points(),
    );
    c.iter()
        .zip(lo.iter().zip(&hi))
        .map(|(p, (l, h))| {
            let left = core::array::from_fn(|a| (p.position[a] - l.position[a]).max(0.0));
            let right = core::array::from_fn(|a| (h.position[a] - p.position[a]).max(0.0));
            Spread::<D>::new(left, right).resize::<3>()
        })
        .collect()
}

/// A Bézier curve as the B-spline it is (clamped knots `0^(n+1) 1^(n+1)`).
pub(super) fn bezier_as_bspline<const D: usize>(
    curve: &BezierCurve<D>,
) -> PyResult<BSplineCurve<D>> {
    let points = curve.control_points();
    let n = points.len();
    let knots = KnotVector::clamped_uniform(n - 1, n).map_err(invalid)?;
    BSplineCurve::new(points, knots).map_err(invalid)
}

impl Curve {
    /// New curve objects from the curves `op` derives from this one's `lanes` (same
    /// metadata): `lanes[0]` is the curve, `lanes[1]` the second lane of a family of two
    /// lanes, to which `op` applies alike, so the derived lanes keep one geometry
    /// (docs/model.md, "Lanes"). `split`, `elevate` and `insert_knot` map the control points
    /// by convex combinations, so applied to the alpha = 0 cut curves they give the derived
    /// curves' cut curves (docs/model.md section 9): a fuzzy model's spreads are carried
    /// along.
    pub(super) fn derive<const D: usize>(
        &self,
        py: Python<'_>,
        lanes: &[&AnyCurve<D>],
        op: impl Fn(&AnyCurve<D>) -> PyResult<Vec<AnyCurve<D>>>,
    ) -> PyResult<Vec<Py<PyAny>>>
    where
        Shape: From<AnyCurve<D>>,
    {
        let (model, _) = self.model()?;
        let source = lanes[0];
        let crisp = op(source)?;
        let mut second = match lanes.get(1) {
            Some(lane) => op(lane)?.into_iter().map(Some).collect(),
            None => vec![None; crisp.len()],
        };
        if second.len() != crisp.len() {
            return Err(invalid("the lanes of the model gave different pieces"));
        }
        let spreads: Vec<Option<Vec<Spread<3>>>> = match model.spreads() {
            None => vec![None; crisp.len()],
            Some(spreads) => {
                let local: Vec<Spread<D>> = spreads.iter().map(Spread::resize).collect();
                let (lower, upper) = alpha_cut(source, &local, 0.0).map_err(invalid)?;
                let (lower, upper) = (op(&lower)?, op(&upper)?);
                crisp
                    .iter()
                    .zip(lower.iter().zip(&upper))
                    .map(|(c, (lo, hi))| Some(spreads_between(c, lo, hi)))
                    .collect()
            }
        };
        crisp
            .into_iter()
            .zip(spreads)
            .zip(second.drain(..))
            .map(|((curve, spreads), second)| {
                let curve = under_rule(curve, model.membership())?;
                let model = model::derived(model, curve, second.map(Shape::from), spreads)?;
                model_into_py(py, model)
            })
            .collect()
    }
}
