//! Path data (SVG 1.1, section 8.3) and point lists, parsed by svgtypes: subpaths as lists of
//! segments, arcs converted into exact rational quadratic pieces.

use super::transform::{apply, Matrix};

/// A segment of a subpath: its control points and weights (all 1 unless an arc piece).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Segment {
    pub(super) points: Vec<[f64; 2]>,
    pub(super) weights: Option<Vec<f64>>,
}

impl Segment {
    pub(super) fn polynomial(points: Vec<[f64; 2]>) -> Segment {
        Segment {
            points,
            weights: None,
        }
    }

    pub(super) fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

/// The rational quadratic pieces of the elliptical arc from `p0` to `p1` (SVG 1.1, appendix
/// F.6.5 for the centre and angles, F.6.6 for radii out of range).
pub(super) fn arc(
    p0: [f64; 2],
    radii: [f64; 2],
    rotation: f64,
    large: bool,
    sweep: bool,
    p1: [f64; 2],
) -> Vec<Segment> {
    if p0 == p1 {
        return Vec::new();
    }
    let (mut rx, mut ry) = (radii[0].abs(), radii[1].abs());
    if rx == 0.0 || ry == 0.0 {
        return vec![Segment::polynomial(vec![p0, p1])];
    }
    let (sin, cos) = rotation.to_radians().sin_cos();
    let (dx, dy) = ((p0[0] - p1[0]) / 2.0, (p0[1] - p1[1]) / 2.0);
    let x1 = cos * dx + sin * dy;
    let y1 = -sin * dx + cos * dy;
    let lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
    if lambda > 1.0 {
        let s = lambda.sqrt();
        rx *= s;
        ry *= s;
    }
    let numerator = (rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1).max(0.0);
    let denominator = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    let mut factor = (numerator / denominator).sqrt();
    if large == sweep {
        factor = -factor;
    }
    let (cx1, cy1) = (factor * rx * y1 / ry, -factor * ry * x1 / rx);
    let center = [
        cos * cx1 - sin * cy1 + (p0[0] + p1[0]) / 2.0,
        sin * cx1 + cos * cy1 + (p0[1] + p1[1]) / 2.0,
    ];
    let angle = |ux: f64, uy: f64| uy.atan2(ux);
    let theta = angle((x1 - cx1) / rx, (y1 - cy1) / ry);
    let mut delta = angle((-x1 - cx1) / rx, (-y1 - cy1) / ry) - theta;
    let tau = std::f64::consts::TAU;
    if sweep && delta < 0.0 {
        delta += tau;
    } else if !sweep && delta > 0.0 {
        delta -= tau;
    }
    // The unit circle to the ellipse: scale, rotate, translate.
    let ellipse: Matrix = [
        cos * rx,
        sin * rx,
        -sin * ry,
        cos * ry,
        center[0],
        center[1],
    ];
    let pieces = (delta.abs() / std::f64::consts::FRAC_PI_2).ceil().max(1.0) as usize;
    let step = delta / pieces as f64;
    let mut out = Vec::with_capacity(pieces);
    for k in 0..pieces {
        let a = theta + step * k as f64;
        let b = a + step;
        let h = step / 2.0;
        let m = a + h;
        let start = if k == 0 {
            p0
        } else {
            apply(&ellipse, [a.cos(), a.sin()])
        };
        let end = if k + 1 == pieces {
            p1
        } else {
            apply(&ellipse, [b.cos(), b.sin()])
        };
        let middle = apply(&ellipse, [m.cos() / h.cos(), m.sin() / h.cos()]);
        out.push(Segment {
            points: vec![start, middle, end],
            weights: Some(vec![1.0, h.cos(), 1.0]),
        });
    }
    out
}

/// Path data read up to its end or its first error: the subpaths that draw something, and
/// the error, when there is one, with the number of segments before it.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct PathData {
    pub(super) subpaths: Vec<Vec<Segment>>,
    pub(super) error: Option<String>,
}

/// The subpaths of path data (SVG 1.1, section 8.3, parsed by svgtypes), each a list of
/// segments; subpaths that draw nothing are left out. As the SVG specification's error
/// handling says (SVG 1.1, appendix F.2; SVG 2, "Error handling" of path data), data that
/// breaks off is drawn up to the last complete command before the error: those segments are
/// kept and the error is returned beside them.
pub(super) fn path_data(d: &str) -> PathData {
    let mut subpaths: Vec<Vec<Segment>> = Vec::new();
    let mut current: Vec<Segment> = Vec::new();
    let mut point = [0.0, 0.0];
    let mut start = [0.0, 0.0];
    // The last control point of a cubic (for S) or a quadratic (for T) segment.
    let mut last_cubic: Option<[f64; 2]> = None;
    let mut last_quadratic: Option<[f64; 2]> = None;
    let mut error = None;
    for segment in svgtypes::PathParser::from(d) {
        let segment = match segment {
            Ok(segment) => segment,
            Err(e) => {
                error = Some(e.to_string());
                break;
            }
        };
        let relative = !segment.is_abs();
        let base = if relative { point } else { [0.0, 0.0] };
        let at = |x: f64, y: f64| [base[0] + x, base[1] + y];
        let mut cubic = None;
        let mut quadratic = None;
        use svgtypes::PathSegment as S;
        match segment {
            S::MoveTo { x, y, .. } => {
                if !current.is_empty() {
                    subpaths.push(std::mem::take(&mut current));
                }
                point = at(x, y);
                start = point;
            }
            S::LineTo { x, y, .. } => {
                let p = at(x, y);
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            S::HorizontalLineTo { x, .. } => {
                let p = [x + base[0], point[1]];
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            S::VerticalLineTo { y, .. } => {
                let p = [point[0], y + base[1]];
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            S::CurveTo {
                x1,
                y1,
                x2,
                y2,
                x,
                y,
                ..
            } => {
                let (c1, c2, p) = (at(x1, y1), at(x2, y2), at(x, y));
                current.push(Segment::polynomial(vec![point, c1, c2, p]));
                cubic = Some(c2);
                point = p;
            }
            S::SmoothCurveTo { x2, y2, x, y, .. } => {
                // The reflection of the previous cubic's second control point, or the current
                // point.
                let c1 =
                    last_cubic.map_or(point, |q| [2.0 * point[0] - q[0], 2.0 * point[1] - q[1]]);
                let (c2, p) = (at(x2, y2), at(x, y));
                current.push(Segment::polynomial(vec![point, c1, c2, p]));
                cubic = Some(c2);
                point = p;
            }
            S::Quadratic { x1, y1, x, y, .. } => {
                let (c1, p) = (at(x1, y1), at(x, y));
                current.push(Segment::polynomial(vec![point, c1, p]));
                quadratic = Some(c1);
                point = p;
            }
            S::SmoothQuadratic { x, y, .. } => {
                let c1 = last_quadratic
                    .map_or(point, |q| [2.0 * point[0] - q[0], 2.0 * point[1] - q[1]]);
                let p = at(x, y);
                current.push(Segment::polynomial(vec![point, c1, p]));
                quadratic = Some(c1);
                point = p;
            }
            S::EllipticalArc {
                rx,
                ry,
                x_axis_rotation,
                large_arc,
                sweep,
                x,
                y,
                ..
            } => {
                let p = at(x, y);
                current.extend(arc(point, [rx, ry], x_axis_rotation, large_arc, sweep, p));
                point = p;
            }
            S::ClosePath { .. } => {
                if point != start {
                    current.push(Segment::polynomial(vec![point, start]));
                }
                if !current.is_empty() {
                    subpaths.push(std::mem::take(&mut current));
                }
                point = start;
            }
        }
        last_cubic = cubic;
        last_quadratic = quadratic;
    }
    if !current.is_empty() {
        subpaths.push(current);
    }
    PathData { subpaths, error }
}

/// The points of a `points` attribute (svgtypes' number list), and the error that ends it
/// early: a number that does not parse, or an odd number of coordinates (the last one has no
/// partner and is left out, as SVG 1.1, section 9.7.1, says).
pub(super) fn point_list(text: &str) -> (Vec<[f64; 2]>, Option<String>) {
    let mut numbers = Vec::new();
    let mut error = None;
    for number in svgtypes::NumberListParser::from(text) {
        match number {
            Ok(x) => numbers.push(x),
            Err(e) => {
                error = Some(e.to_string());
                break;
            }
        }
    }
    if numbers.len() % 2 == 1 && error.is_none() {
        error = Some(format!(
            "an odd number of coordinates ({}): the last one is left out",
            numbers.len()
        ));
    }
    let points = numbers.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
    (points, error)
}

/// The rational quadratic piece of the ellipse with centre `c` and radii `r` from angle `a`
/// to angle `b` (radians, `|b - a| <= pi / 2`; y down, so increasing angles turn from +x
/// towards +y), between the end points `from = c + r (cos a, sin a)` and `to = c + r (cos b,
/// sin b)`, given exactly by the caller so that pieces and sides meet in the same numbers: the
/// control points `from`, `c + r (cos m, sin m) / cos h`, `to` with `m = (a + b) / 2`,
/// `h = (b - a) / 2`, and the weights `1, cos h, 1`.
fn ellipse_piece(
    c: [f64; 2],
    r: [f64; 2],
    a: f64,
    b: f64,
    from: [f64; 2],
    to: [f64; 2],
) -> Segment {
    let (m, h) = ((a + b) / 2.0, (b - a) / 2.0);
    let middle = [
        c[0] + r[0] * m.cos() / h.cos(),
        c[1] + r[1] * m.sin() / h.cos(),
    ];
    Segment {
        points: vec![from, middle, to],
        weights: Some(vec![1.0, h.cos(), 1.0]),
    }
}

/// The closed ellipse with centre `c` and radii `r` (SVG 2, section 10.4: it starts at
/// `(cx + rx, cy)` and turns towards +y): four exact quarter pieces.
pub(super) fn ellipse(c: [f64; 2], r: [f64; 2]) -> Vec<Segment> {
    let q = std::f64::consts::FRAC_PI_2;
    let quarter = [
        [c[0] + r[0], c[1]],
        [c[0], c[1] + r[1]],
        [c[0] - r[0], c[1]],
        [c[0], c[1] - r[1]],
    ];
    (0..4)
        .map(|k| {
            let angle = q * k as f64;
            ellipse_piece(c, r, angle, angle + q, quarter[k], quarter[(k + 1) % 4])
        })
        .collect()
}

/// The outline of a rectangle at `(x, y)` of size `w x h` with corner radii `r` (already
/// resolved and clamped to half the sides, SVG 2 section 10.2): from `(x + rx, y)` clockwise
/// on screen, sides as lines and corners as exact quarter-ellipse pieces; no corner pieces
/// when a radius is 0.
pub(super) fn rectangle(x: f64, y: f64, w: f64, h: f64, r: [f64; 2]) -> Vec<Segment> {
    let [rx, ry] = r;
    let (right, bottom) = (x + w, y + h);
    if rx <= 0.0 || ry <= 0.0 {
        let corners = [[x, y], [right, y], [right, bottom], [x, bottom], [x, y]];
        return corners
            .windows(2)
            .map(|p| Segment::polynomial(p.to_vec()))
            .collect();
    }
    let q = std::f64::consts::FRAC_PI_2;
    let (x0, x1, y0, y1) = (x + rx, right - rx, y + ry, bottom - ry);
    let mut out = Vec::new();
    let line = |a: [f64; 2], b: [f64; 2], out: &mut Vec<Segment>| {
        if a != b {
            out.push(Segment::polynomial(vec![a, b]));
        }
    };
    line([x0, y], [x1, y], &mut out);
    out.push(ellipse_piece([x1, y0], r, -q, 0.0, [x1, y], [right, y0]));
    line([right, y0], [right, y1], &mut out);
    out.push(ellipse_piece(
        [x1, y1],
        r,
        0.0,
        q,
        [right, y1],
        [x1, bottom],
    ));
    line([x1, bottom], [x0, bottom], &mut out);
    out.push(ellipse_piece(
        [x0, y1],
        r,
        q,
        2.0 * q,
        [x0, bottom],
        [x, y1],
    ));
    line([x, y1], [x, y0], &mut out);
    out.push(ellipse_piece(
        [x0, y0],
        r,
        2.0 * q,
        3.0 * q,
        [x, y0],
        [x0, y],
    ));
    out
}
