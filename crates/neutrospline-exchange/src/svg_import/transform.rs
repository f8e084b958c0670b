//! Affine maps of the plane: SVG's `transform` attribute (SVG 1.1, section 7.6).

use std::str::FromStr;

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

/// The matrix of a `transform` attribute or CSS property: a list of matrix, translate, scale,
/// rotate, skewX and skewY, applied right to left (parsed by svgtypes). The CSS form's units
/// (`rotate(45deg)`, `translate(10px, 0)`) are read as SVG's (degrees, user units); other
/// units are refused.
pub(super) fn transform(text: &str) -> Result<Matrix, String> {
    let plain = text.replace("deg", "").replace("px", "");
    let t = svgtypes::Transform::from_str(&plain).map_err(|e| e.to_string())?;
    let m = [t.a, t.b, t.c, t.d, t.e, t.f];
    if m.iter().all(|v| v.is_finite()) {
        Ok(m)
    } else {
        Err("the transform is not finite".to_owned())
    }
}
