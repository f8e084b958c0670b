//! Degree reduction by one, written once on the spline engine (curves of every kind, and
//! surfaces in one direction through the lines of their net): each Bézier piece is replaced by
//! the piece of one degree less that keeps its two end points and is nearest in the L2 sense,
//! `min ∫_0^1 |Σ_j Q_j B_j^{p-1}(s) - Σ_i P_i B_i^p(s)|^2 ds` (the normal equations with the
//! Gram matrices of the Bernstein bases, `∫ B_j^m B_k^n = C(m, j) C(n, k) / ((m + n + 1)
//! C(m + n, j + k))`), the pieces joined with C0 continuity, and then as many knots removed as
//! the tolerance left allows (Tiller), which restores the smoothness the curve had where the
//! reduction kept it.

use crate::knots::KnotVector;
use crate::spline::Spline;

fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// `∫_0^1 B_j^m(s) B_k^n(s) ds`.
fn gram(m: usize, j: usize, n: usize, k: usize) -> f64 {
    binomial(m, j) * binomial(n, k) / ((m + n + 1) as f64 * binomial(m + n, j + k))
}

/// Solves `a x = b` (`a` square, rows of `b` the right-hand sides per channel) by Gaussian
/// elimination with partial pivoting; `None` when singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            let f = a[row][col] / a[col][col];
            if f != 0.0 {
                for c in col..n {
                    a[row][c] -= f * a[col][c];
                }
                let (top, rest) = b.split_at_mut(row);
                for (x, y) in rest[0].iter_mut().zip(&top[col]) {
                    *x -= f * y;
                }
            }
        }
    }
    let mut x = vec![vec![0.0; b.first().map_or(0, Vec::len)]; n];
    for row in (0..n).rev() {
        let mut v = b[row].clone();
        for c in row + 1..n {
            for (vi, xi) in v.iter_mut().zip(&x[c]) {
                *vi -= a[row][c] * xi;
            }
        }
        for vi in &mut v {
            *vi /= a[row][row];
        }
        x[row] = v;
    }
    Some(x)
}

/// The degree-(p-1) Bézier rows nearest (L2) to the degree-p rows `p_rows`, ends kept.
fn reduce_piece(p_rows: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let p = p_rows.len() - 1;
    let m = p - 1;
    let stride = p_rows[0].len();
    let (first, last) = (p_rows[0].clone(), p_rows[p].clone());
    if m == 1 {
        return Some(vec![first, last]);
    }
    let unknowns = m - 1;
    let a: Vec<Vec<f64>> = (1..m)
        .map(|j| (1..m).map(|k| gram(m, j, m, k)).collect())
        .collect();
    let b: Vec<Vec<f64>> = (1..m)
        .map(|j| {
            (0..stride)
                .map(|c| {
                    let target: f64 = (0..=p).map(|i| gram(m, j, p, i) * p_rows[i][c]).sum();
                    target - gram(m, j, m, 0) * first[c] - gram(m, j, m, m) * last[c]
                })
                .collect()
        })
        .collect();
    debug_assert_eq!(a.len(), unknowns);
    let inner = solve(a, b)?;
    let mut out = Vec::with_capacity(m + 1);
    out.push(first);
    out.extend(inner);
    out.push(last);
    Some(out)
}

impl Spline {
    /// The spline of degree `p - 1` made of the reduced Bézier pieces, joined C0 (interior
    /// breakpoints of multiplicity `p - 1`), on the same domain; `None` for degree below 2 or
    /// a singular system. Non-rational splines only (a rational one goes through its
    /// homogeneous form).
    pub(crate) fn reduced_pieces(&self) -> Option<Spline> {
        debug_assert!(self.weights.is_none());
        let p = self.degree();
        if p < 2 {
            return None;
        }
        let m = p - 1;
        let stride = self.stride;
        let segments = self.bezier_segments();
        let mut rows: Vec<Vec<f64>> = Vec::new();
        let domain = self.knots.domain();
        let mut knots: Vec<f64> = vec![domain.start; m + 1];
        for (k, seg) in segments.iter().enumerate() {
            let data = seg.packed.data();
            let p_rows: Vec<Vec<f64>> = data.chunks_exact(stride).map(<[f64]>::to_vec).collect();
            let q = reduce_piece(&p_rows)?;
            if k == 0 {
                rows.extend(q);
            } else {
                // The joint: the previous piece's end and this one's start are the same point
                // of the curve; keep their mean.
                if let Some(prev) = rows.last_mut() {
                    for (a, b) in prev.iter_mut().zip(&q[0]) {
                        *a = 0.5 * (*a + b);
                    }
                }
                rows.extend(q.into_iter().skip(1));
                knots.extend(std::iter::repeat_n(seg.start, m));
            }
        }
        knots.extend(std::iter::repeat_n(domain.end, m + 1));
        Some(Spline {
            knots: KnotVector::from_parts_unchecked(m, knots),
            stride,
            data: rows.concat(),
            weights: None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Gram values against their integrals in closed form: ∫ B_0^1 B_0^1 = ∫ (1-s)^2 =
    /// 1/3, ∫ B_1^2 B_0^1 = ∫ 2 s (1 - s)^2 = 1/6.
    #[test]
    fn gram_values() {
        assert!((gram(1, 0, 1, 0) - 1.0 / 3.0).abs() < 1e-16);
        assert!((gram(2, 1, 1, 0) - 1.0 / 6.0).abs() < 1e-16);
    }

    /// An elevated cubic reduces back to the cubic exactly.
    #[test]
    fn an_elevated_piece_comes_back() {
        let cubic = vec![
            vec![0.0, 1.0],
            vec![1.0, 3.0],
            vec![3.0, -2.0],
            vec![4.0, 0.5],
        ];
        // Elevate to degree 4: Q_i = i/4 P_{i-1} + (1 - i/4) P_i.
        let mut quartic = vec![cubic[0].clone()];
        for i in 1..4 {
            let a = i as f64 / 4.0;
            quartic.push(
                (0..2)
                    .map(|c| a * cubic[i - 1][c] + (1.0 - a) * cubic[i][c])
                    .collect(),
            );
        }
        quartic.push(cubic[3].clone());
        let back = reduce_piece(&quartic).unwrap();
        for (r, s) in back.iter().zip(&cubic) {
            for (x, y) in r.iter().zip(s) {
                assert!((x - y).abs() < 1e-13, "{back:?}");
            }
        }
    }
}
