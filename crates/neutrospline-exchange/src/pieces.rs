//! The curve of joined pieces, shared by the importers: pieces of one degree whose control
//! points are joined (consecutive pieces share their end point, kept once).

use neutrospline::{AnyCurve, BSpline, Bezier, ControlPoint, KnotVector, Nurbs};

/// The curve of `pieces` joined pieces of `degree` with the joined control `points` (and
/// their `weights` when `rational`): one polynomial piece is a Bézier curve; otherwise a
/// B-spline (NURBS when rational) with the knots 0, 1, ..., m, each interior one repeated
/// `degree` times and the ends `degree + 1` times, so that piece k spans \[k, k + 1\].
///
/// # Errors
/// The core's message for points or weights it refuses (a coordinate that is not finite).
pub(crate) fn joined<const D: usize>(
    points: Vec<ControlPoint<D>>,
    weights: Vec<f64>,
    pieces: usize,
    degree: usize,
    rational: bool,
) -> Result<AnyCurve<D>, String> {
    let built = if pieces == 1 && !rational {
        Bezier::new(points).map(AnyCurve::Bezier)
    } else {
        let mut knots = vec![0.0; degree + 1];
        for k in 1..pieces {
            knots.extend(std::iter::repeat_n(k as f64, degree));
        }
        knots.extend(std::iter::repeat_n(pieces as f64, degree + 1));
        let knots = KnotVector::new(knots, degree, points.len()).map_err(|e| e.to_string())?;
        if rational {
            Nurbs::new(points, weights, knots).map(AnyCurve::Nurbs)
        } else {
            BSpline::new(points, knots).map(AnyCurve::BSpline)
        }
    };
    built.map_err(|e| e.to_string())
}
