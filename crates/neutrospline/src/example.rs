//! The paper's Example 1 (docs/model.md section 5), built into the library.

use crate::bezier::Bezier;
use crate::degrees::Degrees;
use crate::point::ControlPoint;

/// Names of Example 1's control points, in order.
pub const EXAMPLE1_NAMES: [&str; 4] = ["C0", "C1", "C2", "C3"];

/// Example 1's control data as `(x, y, truth, indeterminacy, falsity)` rows (the paper's
/// Table 1).
///
/// Erratum: the paper's Table 3 gives C3 an indeterminacy of 0.1, while Table 1, which defines
/// the example, gives 0.4. The project follows Table 1.
pub const EXAMPLE1_TABLE: [[f64; 5]; 4] = [
    [1.0, 3.0, 0.3, 0.6, 0.1],
    [3.0, 6.0, 0.8, 0.1, 0.1],
    [6.0, 2.0, 0.7, 0.1, 0.2],
    [9.0, 5.0, 0.2, 0.4, 0.4],
];

/// The paper's Example 1: the cubic neutrosophic Bézier curve of [`EXAMPLE1_TABLE`].
///
/// ```
/// use neutrospline::Evaluate;
/// let curve = neutrospline::example1();
/// assert_eq!(curve.degree(), 3);
/// assert_eq!(curve.evaluate(0.5)?.position, [4.625, 4.0]);
/// # Ok::<(), neutrospline::EvalError>(())
/// ```
pub fn example1() -> Bezier<2> {
    let points = EXAMPLE1_TABLE
        .iter()
        .map(|&[x, y, t, i, f]| ControlPoint::new([x, y], Degrees::new_unchecked(t, i, f)))
        .collect();
    // The table is constant and valid: four finite points with degrees in [0, 1].
    match Bezier::new(points) {
        Ok(curve) => curve,
        Err(_) => unreachable!("Example 1's table is valid"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ControlPolygon;

    #[test]
    fn example1_table_is_valid() {
        for row in EXAMPLE1_TABLE {
            assert!(Degrees::new(row[2], row[3], row[4]).is_ok());
        }
        assert_eq!(example1().control_point(3).degrees.indeterminacy(), 0.4);
    }
}
