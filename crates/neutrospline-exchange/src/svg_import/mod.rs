//! Reading curves from SVG files: each subpath of a `<path>` element's path data, and each
//! `<polyline>` and `<polygon>`, becomes a plane curve in the file's user units (x to the
//! right, y down, as SVG draws them), with the `transform` attributes of the element and its
//! ancestors applied, and the given degrees at every control point.
//!
//! Path data (SVG 1.1, section 8.3): the commands M, L, H, V, C, S, Q, T, A and Z, absolute
//! (upper case) and relative (lower case), with the implicit repetition of a command's
//! arguments. A subpath's segments become one curve:
//!
//! - lines, quadratic and cubic Bézier segments keep their control points; when a subpath
//!   mixes degrees, every segment is raised to the highest by degree elevation (exact: the same
//!   curve, [`neutrospline::Elevate`]);
//! - an elliptical arc is converted exactly (SVG 1.1, appendix F.6: its centre, radii and
//!   angles) into rational quadratic pieces of at most 90 degrees each: the piece from angle a
//!   to b of the unit circle has the control points (cos a, sin a), (cos m, sin m) / cos(h) and
//!   (cos b, sin b) with m = (a + b) / 2 and h = (b - a) / 2, weights 1, cos(h), 1, mapped by
//!   the ellipse's scaling, rotation and translation (an affine map, under which a rational
//!   curve keeps its weights). An arc with a zero radius is the straight line the SVG rules
//!   make it; radii too small to reach the end point are scaled up as the rules say;
//! - one segment is a Bézier curve (a NURBS curve for one arc piece); several segments are a
//!   B-spline (NURBS when an arc is among them) with the segments' control points joined and
//!   the knots 0, 1, ..., m each repeated degree times (degree + 1 at the ends), segment k over
//!   \[k, k + 1\].
//!
//! Elements inside `<defs>`, `<clipPath>`, `<mask>`, `<marker>`, `<pattern>` and `<symbol>`
//! are not drawn where they stand and are not read.

mod markup;
mod numbers;
mod path_data;
mod transform;

use std::path::Path;

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, ControlPolygon, Degrees, Elevate, KnotVector, Nurbs,
};

use crate::report::{Import, ImportOptions, ImportReport};
use neutrospline_io::read_whole;
use neutrospline_io::{InputError, Limits, Model, ReadError};

use markup::elements;
use path_data::{path_data, point_list, Segment};
use transform::{apply, Matrix};

/// A segment raised to `degree` by degree elevation in the core (the same curve).
///
/// # Errors
/// The core's message for a segment it refuses (a coordinate that overflowed to infinity).
fn elevated(
    segment: &Segment,
    degree: usize,
    defaults: Degrees,
) -> Result<(Vec<[f64; 2]>, Vec<f64>), String> {
    let points: Vec<ControlPoint<2>> = segment
        .points
        .iter()
        .map(|&p| ControlPoint::new(p, defaults))
        .collect();
    let count = points.len();
    let mut curve = match &segment.weights {
        Some(w) => {
            let clamped = [vec![0.0; count], vec![1.0; count]].concat();
            let knots = KnotVector::new(clamped, count - 1, count).map_err(|e| e.to_string())?;
            AnyCurve::Nurbs(Nurbs::new(points, w.clone(), knots).map_err(|e| e.to_string())?)
        }
        None => AnyCurve::Bezier(Bezier::new(points).map_err(|e| e.to_string())?),
    };
    while curve.degree() < degree {
        curve = curve.elevate();
    }
    let weights = curve
        .weights()
        .map_or_else(|| vec![1.0; degree + 1], <[f64]>::to_vec);
    let positions = curve.control_points().iter().map(|p| p.position).collect();
    Ok((positions, weights))
}

/// The curve of one subpath's segments ([module docs](self)), mapped by `matrix`.
fn curve(segments: &[Segment], matrix: &Matrix, defaults: Degrees) -> Result<AnyCurve<2>, String> {
    let degree = segments.iter().map(Segment::degree).max().unwrap_or(1);
    let rational = segments.iter().any(|s| s.weights.is_some());
    let mut positions: Vec<[f64; 2]> = Vec::new();
    let mut weights: Vec<f64> = Vec::new();
    for (k, segment) in segments.iter().enumerate() {
        let (p, w) = elevated(segment, degree, defaults)?;
        // Consecutive segments share an end point: keep it once.
        let skip = usize::from(k > 0);
        positions.extend(&p[skip..]);
        weights.extend(&w[skip..]);
    }
    let points: Vec<ControlPoint<2>> = positions
        .iter()
        .map(|&p| ControlPoint::new(apply(matrix, p), defaults))
        .collect();
    let built = if segments.len() == 1 && !rational {
        Bezier::new(points).map(AnyCurve::Bezier)
    } else {
        let m = segments.len();
        let mut knots = vec![0.0; degree + 1];
        for k in 1..m {
            knots.extend(std::iter::repeat_n(k as f64, degree));
        }
        knots.extend(std::iter::repeat_n(m as f64, degree + 1));
        let knots = KnotVector::new(knots, degree, points.len()).map_err(|e| e.to_string())?;
        if rational {
            Nurbs::new(points, weights, knots).map(AnyCurve::Nurbs)
        } else {
            BSpline::new(points, knots).map(AnyCurve::BSpline)
        }
    };
    built.map_err(|e| e.to_string())
}

/// The curves of an SVG file held in memory, in document order, every control point with the
/// degrees `defaults`. `file` names it in messages.
///
/// Each subpath of a drawn `<path>`'s path data (the commands M, L, H, V, C, S, Q, T, A, Z,
/// absolute and relative), and each `<polyline>` and `<polygon>`, is one plane curve in the
/// file's user units (y down, as SVG draws), with the `transform`s of the element and its
/// ancestors applied (an affine map of the control points, exact for every kind). Lines,
/// quadratic and cubic segments keep their control points, raised by exact degree elevation to
/// the subpath's highest degree; an elliptical arc becomes rational quadratic pieces of at most
/// 90 degrees (the piece from angle a to b of the unit circle has the control points
/// (cos a, sin a), (cos m, sin m) / cos h, (cos b, sin b) with m = (a + b) / 2,
/// h = (b - a) / 2 and the weights 1, cos h, 1, mapped onto the ellipse). One segment is a
/// Bézier curve (NURBS for one arc piece); several are a B-spline (NURBS with an arc) whose
/// segment k spans the knots \[k, k + 1\], each interior knot repeated degree times. The
/// element's `id` is the model's name. Elements inside `<defs>`, `<clipPath>`, `<mask>`,
/// `<marker>`, `<pattern>` and `<symbol>` are not read.
///
/// # Errors
/// [`ReadError::Input`] naming the file and line: markup that is not closed, a `transform`
/// or path data that does not parse (naming the character), an element without its `d` or
/// `points`, no curve in the file, more control points in a curve than `limits` allow.
pub fn parse_svg(
    file: &str,
    bytes: &[u8],
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let defaults = options.defaults;
    let mut report = ImportReport::default();
    let text = std::str::from_utf8(bytes).map_err(|e| {
        InputError::new(
            file,
            None,
            None,
            format!("the file is not UTF-8 text (byte {})", e.valid_up_to()),
        )
    })?;
    let mut models = Vec::new();
    for (index, element) in elements(file, text)?.iter().enumerate() {
        let located = |message: String| -> ReadError {
            InputError::new(
                file,
                Some(element.line),
                None,
                format!("<{}> (element {}): {message}", element.name, index + 1),
            )
            .into()
        };
        let attribute = |name: &str| {
            element
                .attributes
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| v.as_str())
        };
        let subpaths = if element.name == "path" {
            let d = attribute("d")
                .ok_or_else(|| located("it has no path data (attribute d)".to_owned()))?;
            path_data(d).map_err(|m| located(format!("d: {m}")))?
        } else {
            let text = attribute("points")
                .ok_or_else(|| located("it has no attribute points".to_owned()))?;
            let mut points = point_list(text).map_err(|m| located(format!("points: {m}")))?;
            if element.name == "polygon" && points.len() > 1 && points.first() != points.last() {
                points.push(points[0]);
            }
            let segments: Vec<Segment> = points
                .windows(2)
                .map(|w| Segment::polynomial(w.to_vec()))
                .collect();
            if segments.is_empty() {
                Vec::new()
            } else {
                vec![segments]
            }
        };
        for segments in subpaths {
            let curve = curve(&segments, &element.matrix, defaults).map_err(located)?;
            if curve.len() as u64 > limits.max_control_points {
                return Err(located(limits.too_many_control_points()));
            }
            let mut model = Model::new(curve);
            if let Some(id) = attribute("id") {
                model = model.with_name(id);
            }
            models.push(model);
            report.imported(&format!("<{}>", element.name));
        }
    }
    if models.is_empty() {
        return Err(InputError::new(
            file,
            None,
            None,
            "the file has no curve to import (no drawn <path>, <polyline> or <polygon> that draws a segment)".to_owned(),
        )
        .into());
    }
    Ok(Import { models, report })
}

/// The curves of the SVG file at `path` ([`parse_svg`]), read whole up to
/// [`Limits::max_file_size`] bytes.
///
/// # Errors
/// [`ReadError::Io`] and [`ReadError::IsDirectory`] when the file cannot be read, as
/// [`parse_svg`] otherwise.
pub fn load_svg(
    path: impl AsRef<Path>,
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let (shown, bytes) = read_whole(path.as_ref(), limits.max_file_size, "a .svg file")?;
    parse_svg(&shown, &bytes, options, limits)
}

#[cfg(test)]
mod tests;
