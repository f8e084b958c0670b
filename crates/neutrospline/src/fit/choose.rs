//! Choosing the knots: by the target (interpolation, a number of control points, given knots,
//! closed curves), and refining them to a tolerance.

use super::knots::{clamped, interpolation_knots, least_squares_knots, periodic_base};
use super::system::{Layout, Rows, System, Values};
use super::{FitData, FitError, FitKind, FitOptions, FitTarget};
use crate::knots::KnotVector;

/// The most knot refinements of a tolerance fit, and the highest degree a Bézier tolerance
/// fit tries.
const MAX_REFINEMENTS: usize = 64;
const MAX_BEZIER_DEGREE: usize = 30;

/// The layout and, for a tolerance fit, whether it was met.
pub(super) struct Chosen {
    pub(super) layout: Layout,
    pub(super) extras_tangents: bool,
    pub(super) tolerance_met: Option<bool>,
}

impl Chosen {
    /// `layout` as chosen, without refinement or extra tangent rows.
    fn of(layout: Layout) -> Chosen {
        Chosen {
            layout,
            extras_tangents: false,
            tolerance_met: None,
        }
    }
}

pub(super) fn too_few(points: usize, why: String) -> FitError {
    FitError::TooFewPoints { points, why }
}

/// Chooses the knots (and, for a tolerance fit, refines them).
pub(super) fn choose<const D: usize>(
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
                Ok(Chosen::of(layout(p)))
            }
        };
    }
    if options.closed {
        let mut layout = closed_layout(p, m, target, params)?;
        return match target {
            FitTarget::Tolerance(e) => {
                refine(data, &mut layout, params, weights, options.smoothing, e)
            }
            _ => Ok(Chosen::of(layout)),
        };
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
            Ok(Chosen::of(Layout::open(
                p,
                least_squares_knots(params, p, n - 1),
            )))
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
pub(super) fn given_knots(
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
    Ok(Chosen::of(Layout::open(p, knots.to_vec())))
}

/// The periodic layout of degree `p` for a closed curve through `m` points at `params` (which
/// are remapped into the layout's base period).
fn closed_layout(
    p: usize,
    m: usize,
    target: FitTarget,
    params: &mut [f64],
) -> Result<Layout, FitError> {
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
    Ok(Layout::closed(p, &base))
}

/// Refuses repeated parameters.
pub(super) fn distinct(params: &[f64], rule: &'static str) -> Result<(), FitError> {
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
pub(super) fn position_fit<const D: usize>(
    data: &FitData<D>,
    layout: &Layout,
    params: &[f64],
    weights: &[f64],
    lambda: f64,
) -> Result<f64, FitError> {
    let rows = Rows::new(layout, params);
    Ok(position_residuals(data, layout, &rows, weights, lambda)?
        .into_iter()
        .fold(0.0, f64::max))
}

/// The position residual of every point after fitting the positions with `layout`.
pub(super) fn position_residuals<const D: usize>(
    data: &FitData<D>,
    layout: &Layout,
    rows: &Rows,
    weights: &[f64],
    lambda: f64,
) -> Result<Vec<f64>, FitError> {
    let q = Values::Points {
        positions: data.positions(),
        lanes: &[],
    };
    let system = System::new(layout, rows, weights, q, Vec::new(), lambda)?;
    let x = system.solve();
    let mut residuals = vec![0.0; data.len()];
    rows.sweep(layout, &x, q, None, |k, r| {
        residuals[k] = r.iter().map(|v| v * v).sum::<f64>().sqrt();
    });
    Ok(residuals)
}

/// Knot refinement to a tolerance (as splipy's `fit` and The NURBS Book's A9.10 do): fit,
/// then split at its middle every span holding a point whose position residual exceeds `e`,
/// as long as the data still determines every control point; stop when every residual is
/// within `e` or no span can be split, or keep the previous layout when the refined one's
/// system is singular in double precision (the tolerance is then reported not met).
pub(super) fn refine<const D: usize>(
    data: &FitData<D>,
    layout: &mut Layout,
    params: &[f64],
    weights: &[f64],
    lambda: f64,
    e: f64,
) -> Result<Chosen, FitError> {
    let mut rows = Rows::new(layout, params);
    // The last layout whose system could be solved: a refinement whose system is singular in
    // double precision (the Schoenberg-Whitney conditions hold, but barely) falls back to it.
    let mut previous: Option<(Layout, Rows)> = None;
    for _ in 0..MAX_REFINEMENTS {
        let residuals = match position_residuals(data, layout, &rows, weights, lambda) {
            Ok(residuals) => residuals,
            Err(FitError::Singular) if previous.is_some() => {
                if let Some((last, _)) = previous.take() {
                    *layout = last;
                }
                return Ok(Chosen {
                    layout: layout.clone(),
                    extras_tangents: false,
                    tolerance_met: Some(false),
                });
            }
            Err(e) => return Err(e),
        };
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
        let candidate_rows = Rows::new(&candidate, params);
        if knots.is_empty()
            || candidate.n > sorted.len()
            || schoenberg_whitney(&candidate, &candidate_rows, params, weights).is_err()
        {
            return Ok(Chosen {
                layout: layout.clone(),
                extras_tangents: false,
                tolerance_met: Some(false),
            });
        }
        previous = Some((layout.clone(), rows));
        *layout = candidate;
        rows = candidate_rows;
    }
    let met = position_fit(data, layout, params, weights, lambda)? <= e;
    Ok(Chosen {
        layout: layout.clone(),
        extras_tangents: false,
        tolerance_met: Some(met),
    })
}

/// The layout with one more knot (one more control point).
pub(super) fn with_knot(layout: &Layout, knot: f64) -> Layout {
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
pub(super) fn schoenberg_whitney(
    layout: &Layout,
    rows: &Rows,
    params: &[f64],
    weights: &[f64],
) -> Result<(), usize> {
    let p = layout.p;
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
            let (first, values) = rows.row(point);
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
