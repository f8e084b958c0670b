//! SPLINE entities: each becomes a model,
//! exactly (degree, knots, control points and weights as written, numbers parsed with Rust's
//! correctly rounded `f64` parser), with the degrees, kind, membership rule and names of its
//! `NEUTROSPLINE` extended data ([`crate::dxf_xdata`]) when it has them and the given default
//! degrees when it has none.
//!
//! A SPLINE entity (AutoCAD's DXF reference, "SPLINE") has the flags (70: 4
//! rational), the degree (71), the numbers of knots (72), control points (73) and fit points
//! (74), the knots (40, in order), the weights (41, one per control point when the curve is
//! rational) and the control points (10, 20, 30: x, y, z, in world coordinates, in order),
//! mapped by the INSERTs it is drawn through (an affine map: the weights stay). A spline given
//! by fit points only is not read (the caller records it as unsupported): its curve is
//! defined by the CAD program's interpolation, not by the file.
//!
//! Without extended data, a spline whose control points all have `z = 0` is a plane curve, and
//! its kind is `nurbs` when it has weights, `bspline` otherwise.

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, CurveKind, Degrees, KnotVector, Nurbs,
};

use super::geometry::Affine;
use super::groups::Group;
use super::{error, real};
use crate::dxf_xdata::{self, ModelInfo, XTag};
use neutrospline_io::{Kind, Limits, Model, ReadError};

/// What one SPLINE entity says, before it becomes a model.
pub(super) struct SplineGroups<'a> {
    line: usize,
    flags: Option<Group<'a>>,
    degree: Option<Group<'a>>,
    knot_count: Option<Group<'a>>,
    point_count: Option<Group<'a>>,
    fit_count: Option<Group<'a>>,
    knots: Vec<Group<'a>>,
    weights: Vec<Group<'a>>,
    /// x, then y and z when given.
    points: Vec<[Option<Group<'a>>; 3]>,
    fit_points: usize,
    xdata: Option<(usize, Vec<XTag<'a>>)>,
}

/// The groups of one SPLINE entity (`entity`, after its `0 SPLINE` on `line`).
pub(super) fn collect<'a>(
    file: &str,
    line: usize,
    entity: &[Group<'a>],
) -> Result<SplineGroups<'a>, ReadError> {
    let mut s = SplineGroups {
        line,
        flags: None,
        degree: None,
        knot_count: None,
        point_count: None,
        fit_count: None,
        knots: Vec::new(),
        weights: Vec::new(),
        points: Vec::new(),
        fit_points: 0,
        xdata: None,
    };
    let mut k = 0;
    while k < entity.len() {
        let g = entity[k];
        match g.code {
            70 => s.flags = Some(g),
            71 => s.degree = Some(g),
            72 => s.knot_count = Some(g),
            73 => s.point_count = Some(g),
            74 => s.fit_count = Some(g),
            40 => s.knots.push(g),
            41 => s.weights.push(g),
            10 => s.points.push([Some(g), None, None]),
            20 | 30 => {
                let axis = usize::from(g.code / 10 - 1);
                match s.points.last_mut() {
                    Some(p) if p[axis].is_none() => p[axis] = Some(g),
                    _ => {
                        return Err(error(
                            file,
                            g.line,
                            format!("group code {} = `{}` is not after the x (group code 10) of a control point", g.code, g.value),
                        ))
                    }
                }
            }
            11 => s.fit_points += 1,
            1001 => {
                // Extended data: ours is read, another application's skipped.
                let end = entity[k + 1..]
                    .iter()
                    .position(|x| x.code == 1001)
                    .map_or(entity.len(), |e| k + 1 + e);
                if g.value.trim() == dxf_xdata::APP {
                    let tags = entity[k + 1..end]
                        .iter()
                        .map(|x| (x.code, x.value, x.line))
                        .collect();
                    s.xdata = Some((g.line, tags));
                }
                k = end;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    Ok(s)
}

/// A required integer group.
fn count(
    file: &str,
    line: usize,
    g: Option<Group<'_>>,
    what: &str,
    code: u16,
) -> Result<usize, ReadError> {
    let g = g.ok_or_else(|| {
        error(
            file,
            line,
            format!("the SPLINE has no {what} (group code {code})"),
        )
    })?;
    g.value.trim().parse::<usize>().map_err(|_| {
        error(
            file,
            g.line,
            format!(
                "{what} (group code {code}) = `{}` is not a whole number",
                g.value.trim()
            ),
        )
    })
}

/// The model of one SPLINE entity, its control points mapped by `map` (the placement of the
/// INSERTs it is drawn through; a rational curve keeps its weights under an affine map), or
/// `None` for a spline given by fit points only (its curve is the CAD program's
/// interpolation, which this program does not repeat).
pub(super) fn model(
    file: &str,
    s: &SplineGroups<'_>,
    map: &Affine,
    defaults: Degrees,
    limits: &Limits,
) -> Result<Option<Model>, ReadError> {
    let at = |line: usize, message: String| error(file, line, message);
    let degree = count(file, s.line, s.degree, "degree", 71)?;
    let knot_count = count(file, s.line, s.knot_count, "number of knots", 72)?;
    let point_count = count(file, s.line, s.point_count, "number of control points", 73)?;
    let fit_count = match s.fit_count {
        Some(g) => count(file, s.line, Some(g), "number of fit points", 74)?,
        None => s.fit_points,
    };
    if point_count == 0 && s.points.is_empty() {
        if fit_count > 0 {
            return Ok(None);
        }
        return Err(at(s.line, "the SPLINE has no control points".to_owned()));
    }
    if s.points.len() as u64 > limits.max_control_points {
        return Err(at(s.line, limits.too_many_control_points()));
    }
    if s.knots.len() != knot_count {
        return Err(at(
            s.knot_count.map_or(s.line, |g| g.line),
            format!("the number of knots (group code 72) is {knot_count}, but the SPLINE has {} knots (group code 40)", s.knots.len()),
        ));
    }
    if s.points.len() != point_count {
        return Err(at(
            s.point_count.map_or(s.line, |g| g.line),
            format!("the number of control points (group code 73) is {point_count}, but the SPLINE has {} (group code 10)", s.points.len()),
        ));
    }
    let knots = s
        .knots
        .iter()
        .map(|&g| real(file, g, "knot"))
        .collect::<Result<Vec<_>, _>>()?;
    let weights = s
        .weights
        .iter()
        .map(|&g| real(file, g, "weight"))
        .collect::<Result<Vec<_>, _>>()?;
    if !weights.is_empty() && weights.len() != point_count {
        return Err(at(
            s.weights[0].line,
            format!("{} weights (group code 41) for {point_count} control points (give one weight per control point, or none)", weights.len()),
        ));
    }
    let mut positions = Vec::with_capacity(point_count);
    for p in &s.points {
        let mut xyz = [0.0; 3];
        for (axis, g) in p.iter().enumerate() {
            match g {
                Some(g) => xyz[axis] = real(file, *g, ["x", "y", "z"][axis])?,
                None if axis == 1 => {
                    let x = p[0].map_or(s.line, |g| g.line);
                    return Err(at(
                        x,
                        "the control point has an x (group code 10) but no y (group code 20)"
                            .to_owned(),
                    ));
                }
                None => {}
            }
        }
        positions.push(map.apply(xyz));
    }
    if let Some(g) = s.flags {
        let flags = g.value.trim().parse::<i64>().map_err(|_| {
            at(
                g.line,
                format!(
                    "flags (group code 70) = `{}` is not an integer",
                    g.value.trim()
                ),
            )
        })?;
        if flags & 4 != 0 && weights.is_empty() {
            return Err(at(g.line, format!("flags (group code 70) = {flags} say the SPLINE is rational (4), but it has no weights (group code 41)")));
        }
    }
    let info = match &s.xdata {
        Some((line, tags)) => Some(
            dxf_xdata::read(tags, *line)
                .map_err(|(l, m)| at(l, format!("NEUTROSPLINE extended data: {m}")))?,
        ),
        None => None,
    };
    let xdata_line = s.xdata.as_ref().map_or(s.line, |x| x.0);
    let planar = positions.iter().all(|p| p[2] == 0.0);
    let dimension = match &info {
        Some(info) if info.dimension == 2 && !planar => {
            return Err(at(
                xdata_line,
                "the extended data says the curve is 2-D, but a control point has z other than 0"
                    .to_owned(),
            ));
        }
        Some(info) => info.dimension,
        None if planar => 2,
        None => 3,
    };
    let kind = match &info {
        Some(ModelInfo {
            kind: Kind::Curve(kind),
            ..
        }) => *kind,
        Some(ModelInfo { kind, .. }) => {
            return Err(at(
                xdata_line,
                format!(
                    "the extended data says `{}`, but a SPLINE entity is a curve",
                    kind.name()
                ),
            ));
        }
        None if !weights.is_empty() => CurveKind::Nurbs,
        None => CurveKind::BSpline,
    };
    if kind == CurveKind::Nurbs && weights.is_empty() {
        return Err(at(
            s.line,
            "a NURBS curve without weights (group code 41, one per control point)".to_owned(),
        ));
    }
    if kind != CurveKind::Nurbs && weights.iter().any(|&w| w != 1.0) {
        return Err(at(
            s.weights[0].line,
            format!(
                "the extended data says `{}`, but the SPLINE has weights other than 1",
                Kind::Curve(kind).name()
            ),
        ));
    }
    // A family of two lanes: the channels of every control point split into the lanes.
    let mut second_lane: Option<Vec<Degrees>> = None;
    let degrees = match &info {
        Some(info) if info.membership.lane_count() == 2 => {
            let family = info.membership;
            let mut columns = Vec::new();
            for channel in family.channels() {
                let values = info
                    .channels
                    .iter()
                    .find(|(name, _)| name == channel)
                    .map(|(_, v)| v)
                    .ok_or_else(|| {
                        at(
                            xdata_line,
                            format!(
                                "the extended data of a {family} curve has no `{channel}` \
                                 (its channels: {})",
                                family.channels().join(", ")
                            ),
                        )
                    })?;
                if values.len() != point_count {
                    return Err(at(
                        xdata_line,
                        format!(
                            "the extended data has `{channel}` for {} control points, the \
                             SPLINE has {point_count}",
                            values.len()
                        ),
                    ));
                }
                columns.push(values);
            }
            let mut lanes = (Vec::new(), Vec::new());
            for k in 0..point_count {
                let values: Vec<f64> = columns.iter().map(|c| c[k]).collect();
                let (split, _) = family.split(&values).map_err(|e| {
                    at(
                        xdata_line,
                        format!("NEUTROSPLINE extended data: control point {k}: {e}"),
                    )
                })?;
                lanes.0.push(split[0]);
                lanes.1.push(split[1]);
            }
            second_lane = Some(lanes.1);
            lanes.0
        }
        Some(info) if !info.degrees.is_empty() => {
            if info.degrees.len() != point_count {
                return Err(at(xdata_line, format!("the extended data has degrees for {} control points, the SPLINE has {point_count}", info.degrees.len())));
            }
            info.degrees.clone()
        }
        _ => vec![defaults; point_count],
    };
    let build = |degrees: &[Degrees]| -> Result<neutrospline_io::Shape, ReadError> {
        let (knots, weights) = (knots.clone(), weights.clone());
        Ok(match dimension {
            2 => curve::<2>(file, s, kind, degree, knots, weights, &positions, degrees)?.into(),
            _ => curve::<3>(file, s, kind, degree, knots, weights, &positions, degrees)?.into(),
        })
    };
    let shape = build(&degrees)?;
    let second = second_lane.as_deref().map(build).transpose()?;
    let mut model = Model::new(shape);
    if let Some(info) = info {
        if let Some(name) = info.name {
            model = model.with_name(name);
        }
        if let Some(description) = info.description {
            model = model.with_description(description);
        }
        model = match second {
            Some(second) => model.with_lanes(info.membership, second),
            None => model.with_membership(info.membership),
        }
        .map_err(|e| at(xdata_line, format!("NEUTROSPLINE extended data: {e}")))?;
        if !info.point_names.is_empty() {
            model = model
                .with_point_names(info.point_names)
                .map_err(|e| at(xdata_line, format!("NEUTROSPLINE extended data: {e}")))?;
        }
    }
    Ok(Some(model))
}

/// The curve of one SPLINE entity, in `D` dimensions.
#[allow(clippy::too_many_arguments)]
fn curve<const D: usize>(
    file: &str,
    s: &SplineGroups<'_>,
    kind: CurveKind,
    degree: usize,
    knots: Vec<f64>,
    weights: Vec<f64>,
    positions: &[[f64; 3]],
    degrees: &[Degrees],
) -> Result<AnyCurve<D>, ReadError> {
    let points: Vec<ControlPoint<D>> = positions
        .iter()
        .zip(degrees)
        .map(|(p, d)| {
            let mut position = [0.0; D];
            position.copy_from_slice(&p[..D]);
            ControlPoint::new(position, *d)
        })
        .collect();
    let count = points.len();
    let knot_line = s.knot_count.map_or(s.line, |g| g.line);
    if kind == CurveKind::Bezier {
        let clamped: Vec<f64> = [vec![0.0; count], vec![1.0; count]].concat();
        if degree + 1 != count || knots != clamped {
            return Err(error(
                file,
                knot_line,
                format!(
                    "the extended data says `bezier`, but the SPLINE is not a Bezier curve \
                     (degree {degree} with {count} control points and knots 0 and 1 each \
                     degree + 1 times)"
                ),
            ));
        }
        return Bezier::new(points)
            .map(AnyCurve::Bezier)
            .map_err(|e| error(file, s.line, e.to_string()));
    }
    let knots =
        KnotVector::new(knots, degree, count).map_err(|e| error(file, knot_line, e.to_string()))?;
    let built = match kind {
        CurveKind::Nurbs => Nurbs::new(points, weights, knots).map(AnyCurve::Nurbs),
        _ => BSpline::new(points, knots).map(AnyCurve::BSpline),
    };
    built.map_err(|e| error(file, s.line, e.to_string()))
}
