//! The fit itself: parameters, knots, the basis matrix, the normal equations, the tolerance
//! loop, the bounded degree channels and the report.

use super::bounds::{bounded_degrees, bounded_lanes, degrees_of, Bounded, BoundedLanes};
use super::choose::{choose, schoenberg_whitney, Chosen};
use super::knots::parameters;
use super::report::FitReport;
use super::system::{Extra, Layout, Rows, System, Values};
use super::{channel_names, DataWeights, Fit, FitData, FitError, FitKind, FitOptions, FitTarget};
use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::degrees::{DegreeKind, Degrees, Family};
use crate::knots::KnotVector;
use crate::point::ControlPoint;
use crate::spline_curve::BSpline;

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
        FitError::RepeatedPoint {
            index,
            previous: (index + data.len() - 1) % data.len(),
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
    check_lanes(data.degrees(), data.second_lane(), options.membership)?;
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
        DataWeights::Score => score_weights(data.degrees(), data.second_lane(), options.membership),
    };
    let target = match (&options.knots, options.target) {
        (_, Some(target)) => target,
        (Some(knots), None) => FitTarget::ControlPoints(knots.len().saturating_sub(p + 1)),
        (None, None) => FitTarget::Tolerance(1e-3 * diagonal(data.positions())),
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

/// Checks the data's degrees against `family`: each point's degrees under a family of one
/// lane; each point's channels, joined from its two lanes ([`Family::join`]), under a family
/// of two (docs/model.md, "Lanes"), which needs the second lane and a family of one refuses.
///
/// # Errors
/// [`FitError::Degrees`] for a point that breaks the rule; [`FitError::Option`] for a second
/// lane missing or given where the family has one lane.
pub(super) fn check_lanes(
    degrees: &[Degrees],
    second_lane: Option<&[Degrees]>,
    family: Family,
) -> Result<(), FitError> {
    match (family.lane_count(), second_lane) {
        (1, None) => {
            for (index, d) in degrees.iter().enumerate() {
                d.check_membership(family)
                    .map_err(|source| FitError::Degrees { index, source })?;
            }
            Ok(())
        }
        (1, Some(_)) => Err(FitError::Option(format!(
            "the data has a second lane of degrees, but membership {family} rides in one lane \
             (only the interval-valued and bipolar families have two)"
        ))),
        (_, None) => Err(FitError::Option(format!(
            "membership {family} has {} channels ({}) in two lanes: the data needs the second \
             lane's degrees (`{}`) as well as the first (`{}`)",
            family.channel_count(),
            family.channels().join(", "),
            family.lanes()[1].name,
            family.lanes()[0].name
        ))),
        (_, Some(second)) => {
            for (index, (first, second)) in degrees.iter().zip(second).enumerate() {
                family
                    .check(&family.join(&[*first, *second]))
                    .map_err(|source| FitError::Degrees {
                        index,
                        source: source.into(),
                    })?;
            }
            Ok(())
        }
    }
}

/// The weight of each point by its score ([`DataWeights::Score`]): the neutrosophic score
/// `(2 + T - I - F) / 3` of its degrees under a family of one lane; under a family of two, the
/// family's own score of its channels ([`Family::score`], SPEC section 10), which is in
/// \[0, 1\] for the interval-neutrosophic, interval type-2 and bipolar families, and for the
/// interval-intuitionistic one, whose score is in \[-1, 1\], mapped onto \[0, 1\] by
/// `(1 + s) / 2`.
pub(super) fn score_weights(
    degrees: &[Degrees],
    second_lane: Option<&[Degrees]>,
    family: Family,
) -> Vec<f64> {
    match second_lane {
        None => degrees.iter().map(Degrees::score).collect(),
        Some(second) => degrees
            .iter()
            .zip(second)
            .map(|(first, second)| {
                let score = family.score(&family.join(&[*first, *second]));
                if family == Family::IntervalIntuitionistic {
                    0.5 * (1.0 + score)
                } else {
                    score
                }
            })
            .collect(),
    }
}

/// The bounding-box diagonal of the data's positions.
pub(super) fn diagonal<const D: usize>(positions: &[[f64; D]]) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in positions {
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
    let rows = Rows::new(layout, &params);
    let sw = schoenberg_whitney(layout, &rows, &params, weights);
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
    // The degrees of each lane: one, or two for the interval-valued and bipolar families.
    let lanes: Vec<&[Degrees]> = core::iter::once(data.degrees())
        .chain(data.second_lane())
        .collect();
    let extras = if chosen.extras_tangents {
        tangent_rows(data, options, layout, &params)
    } else {
        Vec::new()
    };
    // Every channel at once: positions, then truth, indeterminacy, falsity of each lane.
    let cc = D + 3 * lanes.len();
    let q = Values::Points {
        positions: data.positions(),
        lanes: &lanes,
    };
    let system = System::new(layout, &rows, weights, q, extras, options.smoothing)?;
    let all = system.solve();
    let rhs = &system.rhs;
    let n = layout.n;
    let column = |x: &[f64], j: usize| -> Vec<f64> { (0..n).map(|i| x[i * cc + j]).collect() };
    // The degree slots: unconstrained, then under the rule where they break it;
    // `control[i][lane]`.
    let (control, at_bound): (Vec<Vec<[f64; 3]>>, _) = if lanes.len() == 1 {
        let free = [0, 1, 2].map(|c| column(&all, D + c));
        let Bounded { control, at_bound } = bounded_degrees(free, options.membership, &mut || {
            let b = [0, 1, 2].map(|c| column(rhs, D + c));
            Ok((system.matrix.clone(), b))
        })?;
        (control.into_iter().map(|row| vec![row]).collect(), at_bound)
    } else {
        let slots = |x: &[f64]| [0, 1].map(|l| [0, 1, 2].map(|c| column(x, D + 3 * l + c)));
        let BoundedLanes { control, at_bound } =
            bounded_lanes(slots(&all), options.membership, &mut || {
                Ok((system.matrix.clone(), slots(rhs)))
            })?;
        (
            control.into_iter().map(|row| row.to_vec()).collect(),
            at_bound,
        )
    };
    // The final coefficients: the positions as solved, the degrees as bounded.
    let mut coefficients = all.clone();
    for (i, row) in control.iter().enumerate() {
        for (l, slots) in row.iter().enumerate() {
            coefficients[i * cc + D + 3 * l..i * cc + D + 3 * (l + 1)].copy_from_slice(slots);
        }
    }
    // A lane's curve: the positions, and the lane's slots as its degrees (a wide family's
    // lane is a neutrosophic triple, docs/model.md "Lanes").
    let lane_family = if lanes.len() == 1 {
        options.membership
    } else {
        Family::Neutrosophic
    };
    let lane_curve = |l: usize| -> Result<AnyCurve<D>, FitError> {
        let points: Vec<ControlPoint<D>> = (0..n)
            .map(|i| {
                let position = core::array::from_fn(|a| coefficients[i * cc + a]);
                ControlPoint::new(position, degrees_of(control[i][l], lane_family))
            })
            .collect();
        build_curve(layout, points, options.kind)
    };
    let curve = lane_curve(0)?;
    let second_lane = if lanes.len() == 2 {
        Some(lane_curve(1)?)
    } else {
        None
    };
    // Residuals of every channel at every point.
    let mut max = vec![0.0_f64; cc];
    let mut sum = vec![0.0_f64; cc];
    let (mut worst_index, mut worst_distance) = (0, -1.0);
    rows.sweep(layout, &coefficients, q, None, |k, residual| {
        let mut d2 = 0.0;
        for (j, r) in residual.iter().enumerate() {
            if j < D {
                d2 += r * r;
            }
            max[j] = max[j].max(r.abs());
            sum[j] += r * r;
        }
        let d = d2.sqrt();
        if d > worst_distance {
            worst_distance = d;
            worst_index = k;
        }
    });
    let report = FitReport {
        control_points: n,
        degree: p,
        max_error: shown::<D>(max, options.membership),
        rms_error: shown::<D>(
            sum.iter().map(|s| (s / m as f64).sqrt()).collect(),
            options.membership,
        ),
        worst_index,
        worst_parameter: params[worst_index],
        worst_distance,
        schoenberg_whitney: sw.is_ok(),
        condition_estimate: system.condition,
        at_bound,
        tolerance: match target {
            FitTarget::Tolerance(e) => Some(e),
            _ => None,
        },
        tolerance_met: match target {
            FitTarget::Tolerance(_) => chosen.tolerance_met,
            _ => None,
        },
    };
    Ok(Fit {
        curve,
        parameters: params,
        report,
        second_lane,
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
    let lanes: Vec<&[Degrees]> = core::iter::once(data.degrees())
        .chain(data.second_lane())
        .collect();
    let quotient = |lane: &[Degrees], a: usize, b: usize, c: usize| {
        (lane[b].to_array()[c] - lane[a].to_array()[c]) / (params[b] - params[a])
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
        for lane in &lanes {
            targets.extend((0..3).map(|c| quotient(lane, a, b, c)));
        }
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

/// The channels a report lists with their values, from the values of the fit's columns
/// (positions, then the three degree slots of each lane): the positions and the degrees the
/// family carries (all three for the original families, whose intuitionistic indeterminacy is
/// the hesitation and whose fuzzy ones are 0); for a family of two lanes, its channels by name,
/// each from the slot that holds it ([`Family::lanes`]; a negated slot's residual has the
/// channel's size).
pub(super) fn shown<const D: usize>(values: Vec<f64>, family: Family) -> Vec<(&'static str, f64)> {
    let names = channel_names(D);
    let positions = names.iter().copied().zip(values.iter().copied()).take(D);
    if family.lane_count() == 2 {
        let channels = family.channels().iter().enumerate().map(|(c, &name)| {
            let (l, s) = family
                .lanes()
                .iter()
                .enumerate()
                .find_map(|(l, lane)| {
                    lane.slots
                        .iter()
                        .position(|slot| *slot == Some(c))
                        .map(|s| (l, s))
                })
                .unwrap_or_else(|| unreachable!("every channel rides in a lane slot"));
            (name, values[D + 3 * l + s])
        });
        return positions.chain(channels).collect();
    }
    let original = matches!(
        family,
        Family::Neutrosophic | Family::Intuitionistic | Family::Fuzzy
    );
    names
        .iter()
        .copied()
        .zip(values)
        .filter(|(name, _)| {
            original
                || DegreeKind::ALL
                    .iter()
                    .all(|k| k.name() != *name || family.carries(*k))
        })
        .collect()
}
