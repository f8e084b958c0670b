//! Path data (SVG 1.1, section 8.3) and point lists: subpaths as lists of segments, arcs
//! converted into rational quadratic pieces.

use super::numbers::Numbers;
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

/// The subpaths of path data, each a list of segments (subpaths that draw nothing are left
/// out).
pub(super) fn path_data(d: &str) -> Result<Vec<Vec<Segment>>, String> {
    let mut numbers = Numbers::new(d);
    let mut subpaths: Vec<Vec<Segment>> = Vec::new();
    let mut current: Vec<Segment> = Vec::new();
    let mut point = [0.0, 0.0];
    let mut start = [0.0, 0.0];
    // The last control point of a cubic (for S) or a quadratic (for T) segment.
    let mut last_cubic: Option<[f64; 2]> = None;
    let mut last_quadratic: Option<[f64; 2]> = None;
    let mut command: Option<u8> = None;
    let mut first = true;
    let finish = |current: &mut Vec<Segment>, subpaths: &mut Vec<Vec<Segment>>| {
        if !current.is_empty() {
            subpaths.push(std::mem::take(current));
        }
    };
    while !numbers.at_end() {
        let c = numbers.text[numbers.k];
        let position = numbers.position();
        let letter = if c.is_ascii_alphabetic() {
            numbers.k += 1;
            c
        } else {
            // Implicit repetition; after M the pairs are L (m: l).
            match command {
                Some(b'M') => b'L',
                Some(b'm') => b'l',
                Some(b'Z' | b'z') | None => {
                    return Err(format!(
                        "expected a command at character {position}, found `{}`",
                        char::from(c)
                    ))
                }
                Some(other) => other,
            }
        };
        if first && !matches!(letter, b'M' | b'm') {
            return Err(format!(
                "the path data starts with `{}`, not with a moveto (M or m)",
                char::from(letter)
            ));
        }
        first = false;
        let relative = letter.is_ascii_lowercase();
        let base = if relative { point } else { [0.0, 0.0] };
        let at = |p: [f64; 2]| [base[0] + p[0], base[1] + p[1]];
        let mut cubic = None;
        let mut quadratic = None;
        match letter.to_ascii_uppercase() {
            b'M' => {
                finish(&mut current, &mut subpaths);
                point = at(numbers.pair()?);
                start = point;
            }
            b'L' => {
                let p = at(numbers.pair()?);
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            b'H' => {
                let x = numbers.number()? + base[0];
                let p = [x, point[1]];
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            b'V' => {
                let y = numbers.number()? + base[1];
                let p = [point[0], y];
                current.push(Segment::polynomial(vec![point, p]));
                point = p;
            }
            b'C' | b'S' => {
                let c1 = if letter.eq_ignore_ascii_case(&b'C') {
                    at(numbers.pair()?)
                } else {
                    // The reflection of the previous cubic's second control point, or the
                    // current point.
                    last_cubic.map_or(point, |q| [2.0 * point[0] - q[0], 2.0 * point[1] - q[1]])
                };
                let c2 = at(numbers.pair()?);
                let p = at(numbers.pair()?);
                current.push(Segment::polynomial(vec![point, c1, c2, p]));
                cubic = Some(c2);
                point = p;
            }
            b'Q' | b'T' => {
                let c1 = if letter.eq_ignore_ascii_case(&b'Q') {
                    at(numbers.pair()?)
                } else {
                    last_quadratic.map_or(point, |q| [2.0 * point[0] - q[0], 2.0 * point[1] - q[1]])
                };
                let p = at(numbers.pair()?);
                current.push(Segment::polynomial(vec![point, c1, p]));
                quadratic = Some(c1);
                point = p;
            }
            b'A' => {
                let radii = [numbers.number()?, numbers.number()?];
                let rotation = numbers.number()?;
                let large = numbers.flag()?;
                let sweep = numbers.flag()?;
                let p = at(numbers.pair()?);
                current.extend(arc(point, radii, rotation, large, sweep, p));
                point = p;
            }
            b'Z' => {
                if point != start {
                    current.push(Segment::polynomial(vec![point, start]));
                }
                finish(&mut current, &mut subpaths);
                point = start;
            }
            _ => {
                return Err(format!(
                    "unknown command `{}` at character {position} (known: M, L, H, V, C, S, Q, T, A, Z and their lower-case relative forms)",
                    char::from(letter)
                ))
            }
        }
        last_cubic = cubic;
        last_quadratic = quadratic;
        command = Some(letter);
    }
    finish(&mut current, &mut subpaths);
    Ok(subpaths)
}

/// The points of a `points` attribute.
pub(super) fn point_list(text: &str) -> Result<Vec<[f64; 2]>, String> {
    let mut numbers = Numbers::new(text);
    let mut out = Vec::new();
    while !numbers.at_end() {
        out.push(numbers.pair()?);
    }
    Ok(out)
}
