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

use std::path::Path;

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, ControlPolygon, Degrees, Elevate, KnotVector, Nurbs,
};

use neutrospline_io::read_whole;
use neutrospline_io::{InputError, Limits, Model, ReadError};

/// An affine map of the plane, SVG's `matrix(a b c d e f)`: (x, y) -> (a x + c y + e,
/// b x + d y + f).
type Matrix = [f64; 6];

const IDENTITY: Matrix = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

/// `outer` after `inner` (the matrix of a child inside its parent is parent x child).
fn compose(outer: &Matrix, inner: &Matrix) -> Matrix {
    let [a, b, c, d, e, f] = *outer;
    let [g, h, i, j, k, l] = *inner;
    [
        a * g + c * h,
        b * g + d * h,
        a * i + c * j,
        b * i + d * j,
        a * k + c * l + e,
        b * k + d * l + f,
    ]
}

fn apply(m: &Matrix, p: [f64; 2]) -> [f64; 2] {
    [
        m[0] * p[0] + m[2] * p[1] + m[4],
        m[1] * p[0] + m[3] * p[1] + m[5],
    ]
}

/// Elements whose content is not drawn where it stands.
const NOT_DRAWN: [&str; 6] = ["defs", "clipPath", "mask", "marker", "pattern", "symbol"];

/// A drawn element with curves: its name, attributes and the line of its `<`.
struct Element {
    name: String,
    attributes: Vec<(String, String)>,
    line: usize,
    matrix: Matrix,
}

/// The text with `&amp;`, `&lt;`, `&gt;`, `&quot;`, `&apos;` and character references
/// replaced; an unknown entity is kept as written.
fn unescape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find('&') {
        out.push_str(&rest[..at]);
        rest = &rest[at..];
        let end = rest.find(';').unwrap_or(0);
        let entity = &rest[1..end.max(1)];
        let c = match entity {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            _ => entity
                .strip_prefix("#x")
                .map(|h| u32::from_str_radix(h, 16).ok())
                .or_else(|| entity.strip_prefix('#').map(|d| d.parse::<u32>().ok()))
                .flatten()
                .and_then(char::from_u32),
        };
        match (end, c) {
            (end, Some(c)) if end > 0 => {
                out.push(c);
                rest = &rest[end + 1..];
            }
            _ => {
                out.push('&');
                rest = &rest[1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// Where each line starts, to turn byte offsets into line numbers.
struct Lines(Vec<usize>);

impl Lines {
    fn new(text: &str) -> Lines {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(k, _)| k + 1));
        Lines(starts)
    }

    /// The 1-based line of byte `offset`.
    fn of(&self, offset: usize) -> usize {
        self.0.partition_point(|&s| s <= offset)
    }
}

/// The drawn `<path>`, `<polyline>` and `<polygon>` elements, in document order, each with the
/// matrix of its own and its ancestors' `transform`s.
fn elements(file: &str, text: &str) -> Result<Vec<Element>, ReadError> {
    let lines = Lines::new(text);
    let at = |offset: usize, message: String| -> ReadError {
        InputError::new(file, Some(lines.of(offset)), None, message).into()
    };
    // Open elements: name, matrix, whether drawn.
    let mut stack: Vec<(String, Matrix, bool)> = Vec::new();
    let mut out = Vec::new();
    let mut k = 0;
    while let Some(found) = text[k..].find('<') {
        let start = k + found;
        let rest = &text[start..];
        let skip_to = |end: &str, what: &str| -> Result<usize, ReadError> {
            rest.find(end)
                .map(|e| start + e + end.len())
                .ok_or_else(|| at(start, format!("{what} is not closed (no `{end}`)")))
        };
        if rest.starts_with("<!--") {
            k = skip_to("-->", "a comment `<!--`")?;
            continue;
        }
        if rest.starts_with("<![CDATA[") {
            k = skip_to("]]>", "a CDATA section")?;
            continue;
        }
        if rest.starts_with("<?") {
            k = skip_to("?>", "a processing instruction `<?`")?;
            continue;
        }
        if rest.starts_with("<!") {
            // A document type declaration, possibly with an internal subset in brackets.
            let mut depth = 0usize;
            let end = rest.char_indices().find(|&(_, c)| {
                match c {
                    '[' => depth += 1,
                    ']' => depth = depth.saturating_sub(1),
                    '>' if depth == 0 => return true,
                    _ => {}
                }
                false
            });
            k = start
                + end
                    .ok_or_else(|| at(start, "a declaration `<!` is not closed".to_owned()))?
                    .0
                + 1;
            continue;
        }
        // A tag: find its end outside quoted attribute values.
        let mut quote = None;
        let end = rest
            .char_indices()
            .skip(1)
            .find(|&(_, c)| {
                match (quote, c) {
                    (None, '"' | '\'') => quote = Some(c),
                    (Some(q), c) if c == q => quote = None,
                    (None, '>') => return true,
                    _ => {}
                }
                false
            })
            .ok_or_else(|| at(start, "a tag `<` is not closed (no `>`)".to_owned()))?
            .0;
        k = start + end + 1;
        let tag = &rest[1..end];
        if let Some(name) = tag.strip_prefix('/') {
            let name = name.trim();
            match stack.pop() {
                Some((open, _, _)) if open == name => {}
                Some((open, _, _)) => {
                    return Err(at(start, format!("`</{name}>` closes `<{open}>`")));
                }
                None => return Err(at(start, format!("`</{name}>` closes no element"))),
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.strip_suffix('/').unwrap_or(tag);
        let name_end = tag.find(|c: char| c.is_whitespace()).unwrap_or(tag.len());
        let name = &tag[..name_end];
        let attributes =
            attributes(&tag[name_end..]).map_err(|m| at(start, format!("<{name}>: {m}")))?;
        let (parent_matrix, parent_drawn) =
            stack.last().map_or((IDENTITY, true), |(_, m, d)| (*m, *d));
        let own = match attributes.iter().find(|(n, _)| n == "transform") {
            Some((_, value)) => {
                transform(value).map_err(|m| at(start, format!("<{name}> transform: {m}")))?
            }
            None => IDENTITY,
        };
        let matrix = compose(&parent_matrix, &own);
        let drawn = parent_drawn && !NOT_DRAWN.contains(&name);
        if drawn && matches!(name, "path" | "polyline" | "polygon") {
            out.push(Element {
                name: name.to_owned(),
                attributes: attributes.clone(),
                line: lines.of(start),
                matrix,
            });
        }
        if !self_closing {
            stack.push((name.to_owned(), matrix, drawn));
        }
    }
    Ok(out)
}

/// The attributes of a tag: `name="value"` or `name='value'`, values unescaped.
fn attributes(text: &str) -> Result<Vec<(String, String)>, String> {
    let mut out = Vec::new();
    let mut rest = text.trim_start();
    while !rest.is_empty() {
        let eq = rest
            .find('=')
            .ok_or_else(|| format!("attribute `{}` has no value", rest.trim()))?;
        let name = rest[..eq].trim();
        let after = rest[eq + 1..].trim_start();
        let quote = after
            .chars()
            .next()
            .filter(|c| *c == '"' || *c == '\'')
            .ok_or_else(|| format!("the value of attribute `{name}` is not in quotes"))?;
        let close = after[1..]
            .find(quote)
            .ok_or_else(|| format!("the value of attribute `{name}` is not closed"))?;
        out.push((name.to_owned(), unescape(&after[1..1 + close])));
        rest = after[close + 2..].trim_start();
    }
    Ok(out)
}

/// Numbers of SVG's grammar, in path data, point lists and transforms.
struct Numbers<'a> {
    text: &'a [u8],
    k: usize,
}

impl<'a> Numbers<'a> {
    fn new(text: &'a str) -> Numbers<'a> {
        Numbers {
            text: text.as_bytes(),
            k: 0,
        }
    }

    /// Skips white space and at most one comma.
    fn separator(&mut self) {
        while self.k < self.text.len() && self.text[self.k].is_ascii_whitespace() {
            self.k += 1;
        }
        if self.k < self.text.len() && self.text[self.k] == b',' {
            self.k += 1;
            while self.k < self.text.len() && self.text[self.k].is_ascii_whitespace() {
                self.k += 1;
            }
        }
    }

    fn at_end(&mut self) -> bool {
        self.separator();
        self.k >= self.text.len()
    }

    /// The character position (1-based) of the next token, for messages.
    fn position(&self) -> usize {
        self.k + 1
    }

    /// The next number: sign, digits, fraction, exponent.
    fn number(&mut self) -> Result<f64, String> {
        self.separator();
        let start = self.k;
        let t = self.text;
        let mut k = self.k;
        if k < t.len() && matches!(t[k], b'+' | b'-') {
            k += 1;
        }
        let digits = |k: &mut usize| {
            let s = *k;
            while *k < t.len() && t[*k].is_ascii_digit() {
                *k += 1;
            }
            *k > s
        };
        let whole = digits(&mut k);
        let mut fraction = false;
        if k < t.len() && t[k] == b'.' {
            k += 1;
            fraction = digits(&mut k);
        }
        if !whole && !fraction {
            let found = String::from_utf8_lossy(&t[start..(start + 1).min(t.len())]).into_owned();
            return Err(if found.is_empty() {
                format!(
                    "a number is missing at character {} (the data ends)",
                    start + 1
                )
            } else {
                format!(
                    "expected a number at character {}, found `{found}`",
                    start + 1
                )
            });
        }
        if k < t.len() && matches!(t[k], b'e' | b'E') {
            let mut e = k + 1;
            if e < t.len() && matches!(t[e], b'+' | b'-') {
                e += 1;
            }
            if digits(&mut e) {
                k = e;
            }
        }
        self.k = k;
        let text = std::str::from_utf8(&t[start..k]).unwrap_or("");
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(format!(
                "`{text}` at character {} is not a finite number",
                start + 1
            )),
        }
    }

    /// An arc flag: `0` or `1` (no separator needed after it).
    fn flag(&mut self) -> Result<bool, String> {
        self.separator();
        match self.text.get(self.k) {
            Some(b'0') => {
                self.k += 1;
                Ok(false)
            }
            Some(b'1') => {
                self.k += 1;
                Ok(true)
            }
            _ => Err(format!(
                "an arc flag at character {} is not 0 or 1",
                self.k + 1
            )),
        }
    }

    fn pair(&mut self) -> Result<[f64; 2], String> {
        Ok([self.number()?, self.number()?])
    }
}

/// The matrix of a `transform` attribute: a list of matrix, translate, scale, rotate, skewX
/// and skewY, applied right to left.
fn transform(text: &str) -> Result<Matrix, String> {
    let mut matrix = IDENTITY;
    let mut rest = text.trim();
    while !rest.is_empty() {
        let open = rest
            .find('(')
            .ok_or_else(|| format!("`{rest}` is not a transform"))?;
        let close = open
            + rest[open..]
                .find(')')
                .ok_or_else(|| format!("`{rest}` is not closed"))?;
        let name = rest[..open].trim().trim_start_matches(',').trim();
        let mut numbers = Numbers::new(&rest[open + 1..close]);
        let mut args = Vec::new();
        while !numbers.at_end() {
            args.push(numbers.number()?);
        }
        let degrees = |a: f64| a.to_radians();
        let m: Matrix = match (name, args.as_slice()) {
            ("matrix", &[a, b, c, d, e, f]) => [a, b, c, d, e, f],
            ("translate", &[x]) => [1.0, 0.0, 0.0, 1.0, x, 0.0],
            ("translate", &[x, y]) => [1.0, 0.0, 0.0, 1.0, x, y],
            ("scale", &[s]) => [s, 0.0, 0.0, s, 0.0, 0.0],
            ("scale", &[x, y]) => [x, 0.0, 0.0, y, 0.0, 0.0],
            ("rotate", &[a]) => {
                let (s, c) = degrees(a).sin_cos();
                [c, s, -s, c, 0.0, 0.0]
            }
            ("rotate", &[a, x, y]) => {
                let (s, c) = degrees(a).sin_cos();
                let r = [c, s, -s, c, 0.0, 0.0];
                compose(&compose(&[1.0, 0.0, 0.0, 1.0, x, y], &r), &[1.0, 0.0, 0.0, 1.0, -x, -y])
            }
            ("skewX", &[a]) => [1.0, 0.0, degrees(a).tan(), 1.0, 0.0, 0.0],
            ("skewY", &[a]) => [1.0, degrees(a).tan(), 0.0, 1.0, 0.0, 0.0],
            ("matrix" | "translate" | "scale" | "rotate" | "skewX" | "skewY", _) => {
                return Err(format!("{name} with {} numbers (matrix takes 6, translate and scale 1 or 2, rotate 1 or 3, skewX and skewY 1)", args.len()));
            }
            _ => {
                return Err(format!(
                    "`{name}` is not a transform (known: matrix, translate, scale, rotate, skewX, skewY)"
                ))
            }
        };
        matrix = compose(&matrix, &m);
        rest = rest[close + 1..]
            .trim_start()
            .trim_start_matches(',')
            .trim_start();
    }
    Ok(matrix)
}

/// A segment of a subpath: its control points and weights (all 1 unless an arc piece).
#[derive(Debug, Clone, PartialEq)]
struct Segment {
    points: Vec<[f64; 2]>,
    weights: Option<Vec<f64>>,
}

impl Segment {
    fn polynomial(points: Vec<[f64; 2]>) -> Segment {
        Segment {
            points,
            weights: None,
        }
    }

    fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

/// The rational quadratic pieces of the elliptical arc from `p0` to `p1` (SVG 1.1, appendix
/// F.6.5 for the centre and angles, F.6.6 for radii out of range).
fn arc(
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
fn path_data(d: &str) -> Result<Vec<Vec<Segment>>, String> {
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
fn point_list(text: &str) -> Result<Vec<[f64; 2]>, String> {
    let mut numbers = Numbers::new(text);
    let mut out = Vec::new();
    while !numbers.at_end() {
        out.push(numbers.pair()?);
    }
    Ok(out)
}

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
    defaults: Degrees,
    limits: &Limits,
) -> Result<Vec<Model>, ReadError> {
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
    Ok(models)
}

/// The curves of the SVG file at `path` ([`parse_svg`]), read whole up to
/// [`Limits::max_file_size`] bytes.
///
/// # Errors
/// [`ReadError::Io`] and [`ReadError::IsDirectory`] when the file cannot be read, as
/// [`parse_svg`] otherwise.
pub fn load_svg(
    path: impl AsRef<Path>,
    defaults: Degrees,
    limits: &Limits,
) -> Result<Vec<Model>, ReadError> {
    let (shown, bytes) = read_whole(path.as_ref(), limits.max_file_size)?;
    parse_svg(&shown, &bytes, defaults, limits)
}

#[cfg(test)]
mod tests {
    use neutrospline::{CurveKind, Evaluate};
    use proptest::prelude::*;

    use super::*;
    use neutrospline_io::{Kind, Shape};

    fn defaults() -> Degrees {
        Degrees::new(0.6, 0.3, 0.1).unwrap()
    }

    fn curves(svg: &str) -> Vec<AnyCurve<2>> {
        parse_svg("f.svg", svg.as_bytes(), defaults(), &Limits::default())
            .unwrap()
            .into_iter()
            .map(|m| match m.into_shape() {
                Shape::Curve(neutrospline::DynCurve::Planar(c)) => c,
                other => panic!("a plane curve, not {:?}", other.kind()),
            })
            .collect()
    }

    fn one(d: &str) -> AnyCurve<2> {
        let all = curves(&format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"{d}\"/></svg>"
        ));
        assert_eq!(all.len(), 1, "{d}");
        all.into_iter().next().unwrap()
    }

    fn positions(c: &AnyCurve<2>) -> Vec<[f64; 2]> {
        c.control_points().iter().map(|p| p.position).collect()
    }

    fn message(svg: &str) -> String {
        parse_svg("f.svg", svg.as_bytes(), defaults(), &Limits::default())
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn svg_lines_make_a_degree_one_spline() {
        let c = one("M0 0 H10 V10 H0 Z");
        assert_eq!(c.kind(), CurveKind::BSpline);
        assert_eq!(
            positions(&c),
            [
                [0.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [0.0, 10.0],
                [0.0, 0.0]
            ]
        );
        assert_eq!(
            c.knots().unwrap().knots(),
            [0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0]
        );
        assert!(c.control_points().iter().all(|p| p.degrees == defaults()));
        let p = c.evaluate(2.5).unwrap();
        assert_eq!(p.position, [5.0, 10.0]);
    }

    #[test]
    fn svg_cubic_with_reflection_and_mixed_degrees() {
        let c = one("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0");
        assert_eq!(
            positions(&c),
            [
                [0.0, 0.0],
                [0.0, 10.0],
                [10.0, 10.0],
                [10.0, 0.0],
                [10.0, -10.0],
                [20.0, -10.0],
                [20.0, 0.0]
            ]
        );
        assert_eq!(
            c.knots().unwrap().knots(),
            [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0]
        );
        // A single cubic is a Bezier curve; a line before it is raised to degree 3 exactly.
        assert_eq!(one("M0 0 C 0 10 10 10 10 0").kind(), CurveKind::Bezier);
        let c = one("M0 0 L 3 0 C 4 0 5 1 5 2");
        assert_eq!(
            positions(&c)[..5],
            [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0], [4.0, 0.0]]
        );
        assert_eq!(c.evaluate(1.0).unwrap().position, [3.0, 0.0]);
        // Relative commands, the implicit lineto after m, and T's reflection.
        let c = one("m 1 1 2 0 q 1 1 2 0 t 2 0");
        assert_eq!(
            positions(&c),
            [
                [1.0, 1.0],
                [2.0, 1.0],
                [3.0, 1.0],
                [4.0, 2.0],
                [5.0, 1.0],
                [6.0, 0.0],
                [7.0, 1.0]
            ]
        );
        // Two subpaths are two curves; numbers run together as SVG allows.
        let all = curves("<svg><path d='M0,0L1-1.5.5-2M3 3l1e1 0'/></svg>");
        assert_eq!(positions(&all[0]), [[0.0, 0.0], [1.0, -1.5], [0.5, -2.0]]);
        assert_eq!(positions(&all[1]), [[3.0, 3.0], [13.0, 3.0]]);
    }

    #[test]
    fn svg_arcs_are_exact_rational_quadratics() {
        // A quarter of the unit circle (sweep 1: from +x towards +y): one rational piece.
        let c = one("M 1 0 A 1 1 0 0 1 0 1");
        assert_eq!(c.kind(), CurveKind::Nurbs);
        let p = positions(&c);
        assert_eq!((p[0], p[2]), ([1.0, 0.0], [0.0, 1.0]));
        assert!(
            (p[1][0] - 1.0).abs() < 1e-15 && (p[1][1] - 1.0).abs() < 1e-15,
            "{p:?}"
        );
        let w = c.weights().unwrap();
        assert_eq!((w[0], w[2]), (1.0, 1.0));
        assert!((w[1] - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
        // A whole circle of two half arcs: four pieces, every point at distance 2 from (5, 5).
        let c = one("M 7 5 A 2 2 0 1 1 3 5 A 2 2 0 1 1 7 5");
        assert_eq!(c.len(), 9);
        for k in 0..=400 {
            let t = 4.0 * f64::from(k) / 400.0;
            let q = c.evaluate(t).unwrap().position;
            let r = ((q[0] - 5.0).powi(2) + (q[1] - 5.0).powi(2)).sqrt();
            assert!((r - 2.0).abs() < 1e-14, "t = {t}: r = {r}");
        }
        // A quarter of an ellipse with radii 3 and 1 turned 30 degrees about the centre
        // (5, 5), after a line: every point satisfies the ellipse's equation.
        let (sin, cos) = 30f64.to_radians().sin_cos();
        let start = [5.0 + 3.0 * cos, 5.0 + 3.0 * sin];
        let end = [5.0 - sin, 5.0 + cos];
        let c = one(&format!(
            "M 5 5 L {} {} A 3 1 30 0 1 {} {}",
            start[0], start[1], end[0], end[1]
        ));
        assert_eq!((c.kind(), c.degree(), c.len()), (CurveKind::Nurbs, 2, 5));
        for k in 0..=200 {
            let t = 1.0 + f64::from(k) / 200.0;
            let q = c.evaluate(t).unwrap().position;
            let (x, y) = (q[0] - 5.0, q[1] - 5.0);
            let (u, v) = (cos * x + sin * y, -sin * x + cos * y);
            let e = (u / 3.0).powi(2) + v * v - 1.0;
            assert!(e.abs() < 1e-14, "t = {t}: {e}");
        }
        // Radii too small are scaled up: a half circle of diameter 4.
        let c = one("M 0 0 A 1 1 0 0 1 4 0");
        for k in 0..=100 {
            let t = c.domain().end * f64::from(k) / 100.0;
            let q = c.evaluate(t).unwrap().position;
            let r = ((q[0] - 2.0).powi(2) + q[1].powi(2)).sqrt();
            assert!((r - 2.0).abs() < 1e-14, "r = {r}");
        }
        // A zero radius is a line.
        assert_eq!(
            positions(&one("M 0 0 A 0 1 0 0 1 4 0")),
            [[0.0, 0.0], [4.0, 0.0]]
        );
    }

    #[test]
    fn svg_transforms_hidden_elements_and_markup() {
        let svg = r#"<?xml version="1.0"?>
<!DOCTYPE svg [ <!ENTITY x "y"> ]>
<svg xmlns="http://www.w3.org/2000/svg">
  <!-- <path d="M 9 9 L 8 8"/> -->
  <defs><path id="hidden" d="M 0 0 L 1 1"/></defs>
  <clipPath id="c"><polygon points="0,0 1,0 1,1"/></clipPath>
  <g transform="translate(10 20) scale(2)">
    <path id="a &amp; b" d="M1 1 L2 1"/>
    <polyline transform="rotate(90)" points="1 0, 2 0"/>
  </g>
  <text><![CDATA[ <path d="M 5 5 L 6 6"/> ]]></text>
  <polygon points="0 0 4 0 4 3"/>
</svg>"#;
        let models = parse_svg("t.svg", svg.as_bytes(), defaults(), &Limits::default()).unwrap();
        assert_eq!(models.len(), 3);
        assert_eq!(models[0].name(), Some("a & b"));
        let Some(neutrospline::DynCurve::Planar(a)) = models[0].shape().curve() else {
            panic!()
        };
        assert_eq!(positions(a), [[12.0, 22.0], [14.0, 22.0]]);
        let Some(neutrospline::DynCurve::Planar(b)) = models[1].shape().curve() else {
            panic!()
        };
        let p = positions(b);
        assert!((p[0][0] - 10.0).abs() < 1e-15 && p[0][1] == 22.0, "{p:?}");
        assert!((p[1][0] - 10.0).abs() < 1e-15 && p[1][1] == 24.0, "{p:?}");
        let Some(neutrospline::DynCurve::Planar(c)) = models[2].shape().curve() else {
            panic!()
        };
        assert_eq!(
            positions(c),
            [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 0.0]]
        );
        assert_eq!(models[2].kind(), Kind::Curve(CurveKind::BSpline));
    }

    #[test]
    fn svg_errors_are_located() {
        let huge = message("<svg><path d='M 1e308 0 l 1e308 0'/></svg>");
        assert_eq!(
            huge,
            "f.svg:1: <path> (element 1): control point 1: x = inf is not a finite number (positions must be finite)"
        );
        let path = |d: &str| format!("<svg>\n<path d=\"{d}\"/>\n</svg>");
        assert_eq!(
            message(&path("M0 0 X 1")),
            "f.svg:2: <path> (element 1): d: unknown command `X` at character 6 (known: M, L, H, V, C, S, Q, T, A, Z and their lower-case relative forms)"
        );
        assert_eq!(
            message(&path("M 0 0 L 1")),
            "f.svg:2: <path> (element 1): d: a number is missing at character 10 (the data ends)"
        );
        assert_eq!(
            message(&path("M0 0 A 1 1 0 2 1 3 3")),
            "f.svg:2: <path> (element 1): d: an arc flag at character 14 is not 0 or 1"
        );
        assert_eq!(message(&path("L 1 1")), "f.svg:2: <path> (element 1): d: the path data starts with `L`, not with a moveto (M or m)");
        assert_eq!(
            message(&path("M 0 0 L 1 #")),
            "f.svg:2: <path> (element 1): d: expected a number at character 11, found `#`"
        );
        assert_eq!(
            message("<svg>\n<path/>\n</svg>"),
            "f.svg:2: <path> (element 1): it has no path data (attribute d)"
        );
        assert_eq!(
            message("<svg>\n\n<path d='M0 0 L1 1'"),
            "f.svg:3: a tag `<` is not closed (no `>`)"
        );
        assert_eq!(message("<svg><g transform='spin(3)'><path d='M0 0 L1 1'/></g></svg>"), "f.svg:1: <g> transform: `spin` is not a transform (known: matrix, translate, scale, rotate, skewX, skewY)");
        assert_eq!(message("<svg><rect width='3' height='4'/></svg>"), "f.svg: the file has no curve to import (no drawn <path>, <polyline> or <polygon> that draws a segment)");
        assert_eq!(message("<svg></g></svg>"), "f.svg:1: `</g>` closes `<svg>`");
        assert_eq!(
            message("<svg><path transform=')scale(2' d='M0 0 L1 1'/></svg>"),
            "f.svg:1: <path> transform: `)scale(2` is not closed"
        );
    }

    proptest! {
        /// Any path data, transform or markup gives curves or a message, never a panic.
        #[test]
        fn svg_never_panics(
            d in "[MmLlHhVvCcSsQqTtAaZzX0-9.eE+, #-]{0,40}",
            transform in "[a-zXY() 0-9.,-]{0,20}",
            markup in "[<>/='\"a-z !?\\[\\]&#;-]{0,30}",
        ) {
            let svg = format!("<svg><g transform='{transform}'><path d='{d}'/></g>{markup}</svg>");
            let _ = parse_svg("p.svg", svg.as_bytes(), defaults(), &Limits::default());
            let svg = format!("<svg><path d='{d}'/>{markup}<polyline points='{d}'/></svg>");
            let _ = parse_svg("p.svg", svg.as_bytes(), defaults(), &Limits::default());
        }
    }
}
