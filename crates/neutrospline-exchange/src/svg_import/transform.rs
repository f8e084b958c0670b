//! Affine maps of the plane: SVG's `transform` attribute (SVG 1.1, section 7.6).

use super::numbers::Numbers;

/// An affine map of the plane, SVG's `matrix(a b c d e f)`: (x, y) -> (a x + c y + e,
/// b x + d y + f).
pub(super) type Matrix = [f64; 6];

pub(super) const IDENTITY: Matrix = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

/// `outer` after `inner` (the matrix of a child inside its parent is parent x child).
pub(super) fn compose(outer: &Matrix, inner: &Matrix) -> Matrix {
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

pub(super) fn apply(m: &Matrix, p: [f64; 2]) -> [f64; 2] {
    [
        m[0] * p[0] + m[2] * p[1] + m[4],
        m[1] * p[0] + m[3] * p[1] + m[5],
    ]
}

/// The matrix of a `transform` attribute: a list of matrix, translate, scale, rotate, skewX
/// and skewY, applied right to left.
pub(super) fn transform(text: &str) -> Result<Matrix, String> {
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
