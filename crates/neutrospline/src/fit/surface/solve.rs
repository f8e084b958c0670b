//! The surface fit: parameters, knots, the two-pass or whole solve, the tolerance loop, the
//! bounded degree channels and the report.

use super::super::bounds::{bounded_degrees, bounded_lanes, degrees_of, Bounded, BoundedLanes};
use super::super::choose::{schoenberg_whitney, with_knot};
use super::super::knots::{interpolation_knots, least_squares_knots};
use super::super::report::AtBound;
use super::super::solve::{check_lanes, diagonal, score_weights, shown};
use super::super::system::{Layout, Rows, System, Values};
use super::super::{DataWeights, FitError};
use super::params;
use super::tensor::{Tensor, TensorRows, TensorSystem};
use super::{SurfaceFit, SurfaceFitData, SurfaceFitOptions, SurfaceFitReport, SurfaceShape};
use super::{SurfaceTarget, SurfaceTarget::*};
use crate::degrees::{Degrees, Family};
use crate::knots::KnotVector;
use crate::point::ControlPoint;
use crate::surface::{Direction, Surface, SurfaceError};

/// The most knot refinements of a tolerance fit.
const MAX_REFINEMENTS: usize = 64;

/// The data's parameters: every point's `(u, v)`, and a grid's per-row `u` and per-column `v`.
struct Params {
    all: Vec<[f64; 2]>,
    grid: Option<(Vec<f64>, Vec<f64>)>,
}

/// A solved set of coefficients `x[(i n + j) c + k]` (`c` channels per point) and how.
struct Solved {
    x: Vec<f64>,
    condition: f64,
    two_pass: bool,
    system: Option<TensorSystem>,
}

pub(super) fn run(
    data: &SurfaceFitData,
    options: &SurfaceFitOptions,
) -> Result<SurfaceFit, FitError> {
    let [p, q] = options.degrees;
    let m = data.len();
    check_lanes(data.degrees(), data.second_lane(), options.membership)?;
    let lambda = options.smoothing;
    if !(lambda >= 0.0 && lambda.is_finite()) {
        return Err(FitError::Option(format!(
            "smoothing = {lambda} is not a non-negative finite number"
        )));
    }
    let weights: Vec<f64> = match options.weights {
        DataWeights::None => vec![1.0; m],
        DataWeights::Given => data.weights().map(<[f64]>::to_vec).ok_or_else(|| {
            FitError::Option("data weights were asked for but the data has none".into())
        })?,
        DataWeights::Score => score_weights(data.degrees(), data.second_lane(), options.membership),
    };
    let target = options
        .target
        .unwrap_or(Tolerance(1e-3 * diagonal(data.positions())));
    if let Tolerance(e) = target {
        if !(e > 0.0 && e.is_finite()) {
            return Err(FitError::Option(format!(
                "tolerance = {e} is not a positive finite number"
            )));
        }
    }
    let params = parameters(data, options)?;
    // Channels per point: `x`, `y`, `z`, then `truth`, `indeterminacy`, `falsity` of each lane.
    let lanes: Vec<&[Degrees]> = core::iter::once(data.degrees())
        .chain(data.second_lane())
        .collect();
    let channels = 3 + 3 * lanes.len();
    let q_values: Vec<f64> = (0..m)
        .flat_map(|k| {
            let lanes = &lanes;
            data.positions()[k]
                .into_iter()
                .chain(lanes.iter().flat_map(move |lane| lane[k].to_array()))
        })
        .collect();
    let fit = Fitter {
        data,
        params: &params,
        weights: &weights,
        q: &q_values,
        channels,
        membership: options.membership,
        lambda,
    };
    let (tensor, met) = match target {
        Interpolate => {
            let Some((u, v)) = &params.grid else {
                return Err(FitError::Option(
                    "interpolation needs gridded data (a grid of rows x cols points); fit \
                     scattered data by least squares (control points or a tolerance)"
                        .into(),
                ));
            };
            let SurfaceShape::Grid { rows, cols } = data.shape else {
                unreachable!("grid parameters come from a grid")
            };
            for (count, degree, direction) in [(rows, p, "rows"), (cols, q, "columns")] {
                if count < (degree + 1).max(2) {
                    return Err(too_few(
                        m,
                        format!(
                            "interpolation with degree {degree} needs at least {} {direction} \
                             ({count} here)",
                            (degree + 1).max(2)
                        ),
                    ));
                }
            }
            for (t, direction) in [(u, "rows"), (v, "columns")] {
                if let Some(k) = t.windows(2).position(|w| w[1] <= w[0]) {
                    return Err(FitError::Option(format!(
                        "grid {direction} {k} and {} have one parameter ({}): interpolation \
                         needs distinct ones (the {direction} coincide; remove one, or give \
                         parameters)",
                        k + 1,
                        t[k]
                    )));
                }
            }
            let tensor = Tensor {
                u: Layout::open(p, interpolation_knots(u, p, false)),
                v: Layout::open(q, interpolation_knots(v, q, false)),
            };
            (tensor, None)
        }
        ControlPoints([cu, cv]) => (fit.least_squares_layout(p, q, cu, cv)?, None),
        Tolerance(e) => {
            let (tensor, met) = fit.refine(p, q, e)?;
            (tensor, Some(met))
        }
    };
    fit.finish(options, tensor, target, met)
}

fn too_few(points: usize, why: String) -> FitError {
    FitError::TooFewPoints { points, why }
}

/// The `(u, v)` of the data: given, or averaged over a grid, or projected.
fn parameters(data: &SurfaceFitData, options: &SurfaceFitOptions) -> Result<Params, FitError> {
    match (data.shape, data.parameters()) {
        (SurfaceShape::Grid { rows, cols }, given) => {
            let (u, v) = match given {
                Some(given) => (
                    (0..rows).map(|k| given[k * cols][0]).collect(),
                    (0..cols).map(|l| given[l][1]).collect(),
                ),
                None => params::grid(data.positions(), rows, cols, options.parametrization)?,
            };
            let all = (0..rows)
                .flat_map(|k| (0..cols).map(move |l| (k, l)))
                .map(|(k, l)| [u[k], v[l]])
                .collect();
            Ok(Params {
                all,
                grid: Some((u, v)),
            })
        }
        (SurfaceShape::Scattered, Some(given)) => Ok(Params {
            all: given.to_vec(),
            grid: None,
        }),
        (SurfaceShape::Scattered, None) => Ok(Params {
            all: params::project(data.positions(), options.projection),
            grid: None,
        }),
    }
}

/// The sorted distinct values of one parameter of the data (`a = 0` for `u`).
fn distinct_sorted(params: &[[f64; 2]], a: usize) -> Vec<f64> {
    let mut t: Vec<f64> = params.iter().map(|uv| uv[a]).collect();
    t.sort_by(f64::total_cmp);
    t.dedup();
    t
}

struct Fitter<'a> {
    data: &'a SurfaceFitData,
    params: &'a Params,
    weights: &'a [f64],
    q: &'a [f64],
    /// Channels per point of `q`: 6, or 9 with a second lane.
    channels: usize,
    membership: Family,
    lambda: f64,
}

impl Fitter<'_> {
    /// The parameters each direction's knots follow: a grid's rows and columns, or the
    /// distinct values of scattered data (so that the knots follow the data's density).
    fn knot_parameters(&self) -> [Vec<f64>; 2] {
        match &self.params.grid {
            Some((u, v)) => [u.clone(), v.clone()],
            None => [0, 1].map(|a| distinct_sorted(&self.params.all, a)),
        }
    }

    /// Least-squares knots for `[cu, cv]` control points (The NURBS Book eq. 9.68-9.69 in
    /// each direction).
    fn least_squares_layout(
        &self,
        p: usize,
        q: usize,
        cu: usize,
        cv: usize,
    ) -> Result<Tensor, FitError> {
        let [tu, tv] = self.knot_parameters();
        for (count, degree, distinct, direction) in [(cu, p, &tu, "u"), (cv, q, &tv, "v")] {
            if count < degree + 1 {
                return Err(FitError::Option(format!(
                    "{count} control points along {direction} are too few for degree {degree} \
                     (at least {})",
                    degree + 1
                )));
            }
            if distinct.len() < count && self.lambda == 0.0 {
                return Err(too_few(
                    self.data.len(),
                    format!(
                        "{count} control points along {direction} need at least {count} \
                         distinct {direction} values ({} here) without smoothing",
                        distinct.len()
                    ),
                ));
            }
            if distinct.len() < 2 {
                return Err(too_few(
                    self.data.len(),
                    format!("all points have one {direction}: a surface needs a range of both"),
                ));
            }
        }
        if self.params.grid.is_none() && self.lambda == 0.0 && self.data.len() < cu * cv {
            return Err(too_few(
                self.data.len(),
                format!(
                    "{cu} x {cv} control points need at least {} points without smoothing",
                    cu * cv
                ),
            ));
        }
        Ok(Tensor {
            u: Layout::open(p, least_squares_knots(&tu, p, cu - 1)),
            v: Layout::open(q, least_squares_knots(&tv, q, cv - 1)),
        })
    }

    /// Whether the layout can be fitted: without smoothing, every control point needs data
    /// in its support; `Err` names the first that has none.
    fn check_supports(&self, tensor: &Tensor, rows: &TensorRows) -> Result<bool, FitError> {
        match rows.empty_support(tensor, self.weights) {
            None => Ok(true),
            Some(_) if self.lambda > 0.0 => Ok(false),
            Some(index) => {
                let (i, j) = (index / tensor.v.n, index % tensor.v.n);
                let (ku, kv) = (&tensor.u.knots, &tensor.v.knots);
                Err(FitError::EmptyCell {
                    row: i,
                    col: j,
                    u: [ku[i], ku[i + tensor.u.p + 1]],
                    v: [kv[j], kv[j + tensor.v.p + 1]],
                })
            }
        }
    }

    /// Solves every channel: two passes of the curve solver for unweighted, unsmoothed
    /// gridded data, else the whole tensor system.
    fn solve(&self, tensor: &Tensor, rows: &TensorRows) -> Result<Solved, FitError> {
        let uniform = self.weights.iter().all(|&w| w == 1.0);
        if let (Some((u, v)), true, true) = (&self.params.grid, uniform, self.lambda == 0.0) {
            let (x, condition) = two_pass(tensor, u, v, self.q, self.channels)?;
            return Ok(Solved {
                x,
                condition,
                two_pass: true,
                system: None,
            });
        }
        let system = TensorSystem::new(
            tensor,
            rows,
            self.weights,
            self.q,
            self.channels,
            self.lambda,
        )?;
        let x = system.solve(tensor, rows, self.weights, self.q);
        Ok(Solved {
            x,
            condition: system.condition,
            two_pass: false,
            system: Some(system),
        })
    }

    /// The position residual of every point for coefficients `x`.
    fn residuals(&self, tensor: &Tensor, rows: &TensorRows, x: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.data.len()];
        rows.sweep(tensor, x, self.q, self.channels, None, |k, r| {
            out[k] = r[..3].iter().map(|v| v * v).sum::<f64>().sqrt();
        });
        out
    }

    /// Knot refinement to a tolerance, from one span in each direction: fit, then split at
    /// its middle every `u` span and every `v` span that holds a point whose position
    /// residual exceeds `e` (or, when that would overfill the data, the worst point's spans),
    /// while the data still determines the control points; stop when every residual is within
    /// `e` (`true`) or no span can be split (`false`).
    fn refine(&self, p: usize, q: usize, e: f64) -> Result<(Tensor, bool), FitError> {
        let mut tensor = self.least_squares_layout(p, q, p + 1, q + 1)?;
        let [tu, tv] = self.knot_parameters();
        let mut previous: Option<Tensor> = None;
        for _ in 0..MAX_REFINEMENTS {
            let rows = TensorRows::new(&tensor, &self.params.all);
            self.check_supports(&tensor, &rows)?;
            let solved = match (self.solve(&tensor, &rows), previous.take()) {
                (Ok(solved), _) => solved,
                // A refinement the system cannot resolve: the last one is the answer.
                (Err(FitError::Singular), Some(last)) => return Ok((last, false)),
                (Err(e), _) => return Err(e),
            };
            let residuals = self.residuals(&tensor, &rows, &solved.x);
            let mut bad: Vec<([f64; 2], f64)> = self
                .params
                .all
                .iter()
                .zip(&residuals)
                .filter(|(_, r)| **r > e)
                .map(|(uv, r)| (*uv, *r))
                .collect();
            if bad.is_empty() {
                return Ok((tensor, true));
            }
            // Every span with a point beyond the tolerance; failing that, the worst point's.
            let all = self.split(&tensor, &tu, &tv, &bad);
            let candidate = match all {
                Some(candidate) => candidate,
                None => {
                    bad.sort_by(|a, b| b.1.total_cmp(&a.1));
                    bad.truncate(1);
                    match self.split(&tensor, &tu, &tv, &bad) {
                        Some(candidate) => candidate,
                        None => return Ok((tensor, false)),
                    }
                }
            };
            previous = Some(core::mem::replace(&mut tensor, candidate));
        }
        let rows = TensorRows::new(&tensor, &self.params.all);
        let solved = self.solve(&tensor, &rows)?;
        let worst = self
            .residuals(&tensor, &rows, &solved.x)
            .into_iter()
            .fold(0.0, f64::max);
        Ok((tensor, worst <= e))
    }

    /// `tensor` with a knot at the middle of every `u` span and every `v` span that holds
    /// one of the `bad` points (where both halves keep two distinct parameter values of the
    /// data, so that the control net stays well determined), if the result grew and the data
    /// still determines it.
    fn split(
        &self,
        tensor: &Tensor,
        tu: &[f64],
        tv: &[f64],
        bad: &[([f64; 2], f64)],
    ) -> Option<Tensor> {
        let split = |layout: &Layout, t: &[f64], a: usize| {
            let mut out = layout.clone();
            for (lo, hi) in layout.spans() {
                let mid = 0.5 * (lo + hi);
                let count = |x: f64, y: f64, end: bool| {
                    t.iter()
                        .filter(|&&s| s >= x && (s < y || end && s == y))
                        .count()
                };
                if mid > lo
                    && mid < hi
                    && bad.iter().any(|(uv, _)| uv[a] >= lo && uv[a] <= hi)
                    && count(lo, mid, false) >= 2
                    && count(mid, hi, true) >= 2
                {
                    out = with_knot(&out, mid);
                }
            }
            out
        };
        let candidate = Tensor {
            u: split(&tensor.u, tu, 0),
            v: split(&tensor.v, tv, 1),
        };
        let grown = candidate.u.n > tensor.u.n || candidate.v.n > tensor.v.n;
        let fits = match &self.params.grid {
            // Each direction a curve fit: the Schoenberg-Whitney conditions along it.
            Some((u, v)) => [(&candidate.u, u), (&candidate.v, v)].iter().all(|(l, t)| {
                let ones = vec![1.0; t.len()];
                l.n <= t.len() && schoenberg_whitney(l, &Rows::new(l, t), t, &ones).is_ok()
            }),
            None => candidate.len() <= self.data.len(),
        };
        if !(grown && fits) {
            return None;
        }
        let rows = TensorRows::new(&candidate, &self.params.all);
        let supported = self.lambda > 0.0 || rows.empty_support(&candidate, self.weights).is_none();
        supported.then_some(candidate)
    }

    /// Fits every channel on `tensor`, bounds the degrees and builds the surface and report.
    fn finish(
        &self,
        options: &SurfaceFitOptions,
        tensor: Tensor,
        target: SurfaceTarget,
        met: Option<bool>,
    ) -> Result<SurfaceFit, FitError> {
        let rows = TensorRows::new(&tensor, &self.params.all);
        let supported = self.check_supports(&tensor, &rows)?;
        let solved = self.solve(&tensor, &rows)?;
        let n = tensor.len();
        let cc = self.channels;
        let column = |x: &[f64], c: usize| -> Vec<f64> { (0..n).map(|i| x[i * cc + c]).collect() };
        let mut existing = solved.system;
        let mut system = || match existing.take() {
            Some(system) => Ok(system),
            None => TensorSystem::new(&tensor, &rows, self.weights, self.q, cc, self.lambda),
        };
        // The degree slots under the rule; `control[i][lane]`.
        let (control, at_bound): (Vec<Vec<[f64; 3]>>, _) = if cc == 6 {
            let free = [3, 4, 5].map(|c| column(&solved.x, c));
            let Bounded { control, at_bound } =
                bounded_degrees(free, options.membership, &mut || {
                    let system = system()?;
                    let rhs = [3, 4, 5].map(|c| column(&system.rhs, c));
                    Ok((system.matrix, rhs))
                })?;
            (control.into_iter().map(|row| vec![row]).collect(), at_bound)
        } else {
            let slots = |x: &[f64]| [0, 1].map(|l| [0, 1, 2].map(|c| column(x, 3 + 3 * l + c)));
            let BoundedLanes { control, at_bound } =
                bounded_lanes(slots(&solved.x), options.membership, &mut || {
                    let system = system()?;
                    Ok((system.matrix, slots(&system.rhs)))
                })?;
            (
                control.into_iter().map(|row| row.to_vec()).collect(),
                at_bound,
            )
        };
        let mut coefficients = solved.x;
        for (i, row) in control.iter().enumerate() {
            for (l, slots) in row.iter().enumerate() {
                coefficients[i * cc + 3 + 3 * l..i * cc + 3 + 3 * (l + 1)].copy_from_slice(slots);
            }
        }
        let lane_family = if control.first().is_some_and(|row| row.len() == 2) {
            Family::Neutrosophic
        } else {
            options.membership
        };
        let (p, q) = (tensor.u.p, tensor.v.p);
        let knots = |layout: &Layout, degree: usize, direction: Direction| {
            KnotVector::new(layout.knots.clone(), degree, layout.n)
                .map_err(|source| SurfaceError::Knots { direction, source })
        };
        let lane_surface = |l: usize| -> Result<Surface, FitError> {
            let points: Vec<ControlPoint<3>> = (0..n)
                .map(|i| {
                    let position = [0, 1, 2].map(|a| coefficients[i * cc + a]);
                    ControlPoint::new(position, degrees_of(control[i][l], lane_family))
                })
                .collect();
            Ok(Surface::bspline(
                tensor.u.n,
                tensor.v.n,
                points,
                knots(&tensor.u, p, Direction::U)?,
                knots(&tensor.v, q, Direction::V)?,
            )?)
        };
        let surface = lane_surface(0)?;
        let second_lane = if cc == 9 {
            Some(lane_surface(1)?)
        } else {
            None
        };
        let report = self.report(
            &tensor,
            &rows,
            &coefficients,
            &Summary {
                condition: solved.condition,
                two_pass: solved.two_pass,
                supported,
            },
            at_bound,
            target,
            met,
        );
        Ok(SurfaceFit {
            surface,
            parameters: self.params.all.clone(),
            report,
            second_lane,
        })
    }

    #[allow(clippy::too_many_arguments)]
    fn report(
        &self,
        tensor: &Tensor,
        rows: &TensorRows,
        coefficients: &[f64],
        summary: &Summary,
        at_bound: Vec<AtBound>,
        target: SurfaceTarget,
        met: Option<bool>,
    ) -> SurfaceFitReport {
        let mut max = vec![0.0_f64; self.channels];
        let mut sum = vec![0.0_f64; self.channels];
        let (mut worst_index, mut worst_distance) = (0, -1.0);
        rows.sweep(tensor, coefficients, self.q, self.channels, None, |k, r| {
            for (j, v) in r.iter().enumerate() {
                max[j] = max[j].max(v.abs());
                sum[j] += v * v;
            }
            let d = r[..3].iter().map(|v| v * v).sum::<f64>().sqrt();
            if d > worst_distance {
                worst_distance = d;
                worst_index = k;
            }
        });
        let count = self.data.len() as f64;
        SurfaceFitReport {
            control_points: [tensor.u.n, tensor.v.n],
            degrees: [tensor.u.p, tensor.v.p],
            max_error: shown::<3>(max, self.membership),
            rms_error: shown::<3>(
                sum.iter().map(|s| (s / count).sqrt()).collect(),
                self.membership,
            ),
            worst_index,
            worst_parameters: self.params.all[worst_index],
            worst_distance,
            data_in_every_support: summary.supported,
            two_pass: summary.two_pass,
            condition_estimate: summary.condition,
            at_bound,
            tolerance: match target {
                Tolerance(e) => Some(e),
                _ => None,
            },
            tolerance_met: met,
        }
    }
}

/// How a fit was solved, for the report.
struct Summary {
    condition: f64,
    two_pass: bool,
    supported: bool,
}

/// `P = N^+ Q M^+T` for a `rows x cols` grid `q` of `c` channels (point `k cols + l`): the
/// curve solver along `u` with each grid row's `cols c` values as the channels of one point,
/// then along `v` with each column of the result as one point. Returns the coefficients and
/// the product of the two systems' condition estimates (the Kronecker product's).
fn two_pass(
    tensor: &Tensor,
    u: &[f64],
    v: &[f64],
    q: &[f64],
    c: usize,
) -> Result<(Vec<f64>, f64), FitError> {
    let (rows, cols) = (u.len(), v.len());
    let (nu, nv) = (tensor.u.n, tensor.v.n);
    let rows_u = Rows::new(&tensor.u, u);
    let ones = vec![1.0; rows.max(cols)];
    let along_u = System::<3>::new(
        &tensor.u,
        &rows_u,
        &ones[..rows],
        Values::Table {
            values: q,
            channels: cols * c,
        },
        Vec::new(),
        0.0,
    )?;
    let r = along_u.solve();
    // The intermediate net, transposed: point l (a grid column) holds nu c values.
    let mut t = vec![0.0; cols * nu * c];
    for i in 0..nu {
        for l in 0..cols {
            t[(l * nu + i) * c..(l * nu + i + 1) * c]
                .copy_from_slice(&r[(i * cols + l) * c..(i * cols + l + 1) * c]);
        }
    }
    let rows_v = Rows::new(&tensor.v, v);
    let along_v = System::<3>::new(
        &tensor.v,
        &rows_v,
        &ones[..cols],
        Values::Table {
            values: &t,
            channels: nu * c,
        },
        Vec::new(),
        0.0,
    )?;
    let s = along_v.solve();
    let mut x = vec![0.0; nu * nv * c];
    for i in 0..nu {
        for j in 0..nv {
            x[(i * nv + j) * c..(i * nv + j + 1) * c]
                .copy_from_slice(&s[(j * nu + i) * c..(j * nu + i + 1) * c]);
        }
    }
    Ok((x, along_u.condition * along_v.condition))
}
