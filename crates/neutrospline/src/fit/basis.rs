//! B-spline basis functions and their derivatives at a parameter (The NURBS Book, A2.2 and
//! A2.3), over a knot vector given as a slice: the rows of the fitting matrix.

use super::width::{with_width, Width};

/// The span `k` with `u_k <= t < u_{k+1}` among `u_p ..= u_{len - p - 2}` (the last non-empty
/// span for `t` at the end), for `t` in `[u_p, u_{len-p-1}]`.
pub(crate) fn span(knots: &[f64], p: usize, t: f64) -> usize {
    let last = knots.len() - 2 - p;
    let upper = knots[p..=last].partition_point(|&k| k <= t) + p;
    let mut k = upper.saturating_sub(1).max(p);
    while k > p && knots[k] == knots[k + 1] {
        k -= 1;
    }
    k
}

/// The `p + 1` non-zero basis functions at a run of parameters (Cox-de Boor, The NURBS Book
/// A2.2): non-negative with unit sum.
///
/// On span `k` the recursion divides by the knot differences `u_{k+r+1} - u_{k+1-j+r}`
/// (`1 <= j <= p`, `0 <= r < j`), which do not depend on `t` and are positive (each contains
/// the span); their reciprocals are kept with the span, and the span of the previous
/// parameter is tried first, so that sorted data costs a few multiplications per point.
pub(crate) struct Basis<'a> {
    knots: &'a [f64],
    p: usize,
    /// The span of the kept reciprocals (`usize::MAX` before the first).
    span: usize,
    /// `1 / (u_{k+r+1} - u_{k+1-j+r})` at `j (j - 1) / 2 + r`.
    inverse: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
}

impl<'a> Basis<'a> {
    pub(crate) fn new(knots: &'a [f64], p: usize) -> Basis<'a> {
        Basis {
            knots,
            p,
            span: usize::MAX,
            inverse: vec![0.0; p * (p + 1) / 2],
            left: vec![0.0; p + 1],
            right: vec![0.0; p + 1],
        }
    }

    /// `N_{k-p,p}(t) ..= N_{k,p}(t)` into `out[..=p]`; returns the span `k`.
    pub(crate) fn values(&mut self, t: f64, out: &mut [f64]) -> usize {
        with_width!(row row = self.p + 1 => self.values_in(row, t, out))
    }

    /// [`Basis::values`] with the row's width `p + 1` given as a [`Width`].
    #[inline(always)]
    pub(crate) fn values_in(&mut self, row: impl Width, t: f64, out: &mut [f64]) -> usize {
        let knots = self.knots;
        let p = row.get() - 1;
        let out = &mut out[..=p];
        let (left, right) = (&mut self.left[..=p], &mut self.right[..=p]);
        let mut k = self.span;
        if k == usize::MAX || !(knots[k] <= t && t < knots[k + 1]) {
            k = span(knots, p, t);
            if k != self.span {
                self.span = k;
                for j in 1..=p {
                    for r in 0..j {
                        self.inverse[j * (j - 1) / 2 + r] =
                            1.0 / (knots[k + r + 1] - knots[k + 1 - j + r]);
                    }
                }
            }
        }
        for j in 1..=p {
            left[j] = t - knots[k + 1 - j];
            right[j] = knots[k + j] - t;
        }
        out[0] = 1.0;
        for j in 1..=p {
            let inverse = &self.inverse[j * (j - 1) / 2..];
            let mut saved = 0.0;
            for r in 0..j {
                let temp = out[r] * inverse[r];
                out[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            out[j] = saved;
        }
        k
    }
}

/// The derivatives of orders `0 ..= order` of the `p + 1` basis functions on span `k` at `t`:
/// `out[d * (p + 1) + j]` is `N^(d)_{k-p+j,p}(t)` (A2.3; zero for `d > p`).
pub(crate) fn derivatives(
    knots: &[f64],
    p: usize,
    k: usize,
    t: f64,
    order: usize,
    out: &mut [f64],
) {
    let n1 = p + 1;
    out[..(order + 1) * n1].iter_mut().for_each(|v| *v = 0.0);
    // ndu: basis functions (upper triangle) and knot differences (lower).
    let mut ndu = vec![0.0; n1 * n1];
    let mut left = vec![0.0; n1];
    let mut right = vec![0.0; n1];
    ndu[0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[k + 1 - j];
        right[j] = knots[k + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j * n1 + r] = right[r + 1] + left[j - r];
            let temp = ndu[r * n1 + j - 1] / ndu[j * n1 + r];
            ndu[r * n1 + j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j * n1 + j] = saved;
    }
    for j in 0..=p {
        out[j] = ndu[j * n1 + p];
    }
    let mut a = vec![0.0; 2 * n1];
    for r in 0..=p {
        let (mut s1, mut s2) = (0, n1);
        a.iter_mut().for_each(|v| *v = 0.0);
        a[0] = 1.0;
        for d in 1..=order.min(p) {
            let mut value = 0.0;
            let rk = r as isize - d as isize;
            let pk = p - d;
            if r >= d {
                a[s2] = a[s1] / ndu[(pk + 1) * n1 + rk as usize];
                value = a[s2] * ndu[rk as usize * n1 + pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if (r as isize - 1) <= pk as isize {
                d - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2 + j] = (a[s1 + j] - a[s1 + j - 1]) / ndu[(pk + 1) * n1 + idx];
                value += a[s2 + j] * ndu[idx * n1 + pk];
            }
            if r <= pk {
                a[s2 + d] = -a[s1 + d - 1] / ndu[(pk + 1) * n1 + r];
                value += a[s2 + d] * ndu[r * n1 + pk];
            }
            out[d * n1 + r] = value;
            core::mem::swap(&mut s1, &mut s2);
        }
    }
    // Multiply by p! / (p - d)!.
    let mut factor = p as f64;
    for d in 1..=order.min(p) {
        for j in 0..=p {
            out[d * n1 + j] *= factor;
        }
        factor *= (p - d) as f64;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cox-de Boor recursion, the textbook way (reference).
    fn cox(knots: &[f64], i: usize, p: usize, t: f64) -> f64 {
        if p == 0 {
            let last = knots
                .iter()
                .rposition(|&k| k < knots[knots.len() - 1])
                .unwrap_or(0);
            return if (knots[i] <= t && t < knots[i + 1])
                || (t == knots[knots.len() - 1] && i == last)
            {
                1.0
            } else {
                0.0
            };
        }
        let mut v = 0.0;
        let d1 = knots[i + p] - knots[i];
        if d1 > 0.0 {
            v += (t - knots[i]) / d1 * cox(knots, i, p - 1, t);
        }
        let d2 = knots[i + p + 1] - knots[i + 1];
        if d2 > 0.0 {
            v += (knots[i + p + 1] - t) / d2 * cox(knots, i + 1, p - 1, t);
        }
        v
    }

    #[test]
    fn basis_values_and_derivatives_match_the_recursion() {
        let knots = [0.0, 0.0, 0.0, 0.0, 0.2, 0.5, 0.5, 0.8, 1.0, 1.0, 1.0, 1.0];
        let p = 3;
        let mut basis = Basis::new(&knots, p);
        // Forwards, then backwards: the kept span is reused or replaced.
        for step in (0..=20).chain((0..=20).rev()) {
            let t = step as f64 / 20.0;
            let mut n = [0.0; 4];
            let k = basis.values(t, &mut n);
            assert_eq!(k, span(&knots, p, t));
            assert!((n.iter().sum::<f64>() - 1.0).abs() < 1e-15);
            for j in 0..=p {
                let want = cox(&knots, k - p + j, p, t);
                assert!((n[j] - want).abs() < 1e-14, "t {t} j {j}: {} {want}", n[j]);
            }
            let mut ders = [0.0; 12];
            derivatives(&knots, p, k, t, 2, &mut ders);
            assert!(
                (ders[..4]
                    .iter()
                    .zip(&n)
                    .map(|(a, b)| (a - b).abs())
                    .sum::<f64>())
                    < 1e-14
            );
            // First and second derivatives against central differences (inside the span).
            if t > knots[k] + 1e-3 && t < knots[k + 1] - 1e-3 {
                let h = 1e-5;
                for j in 0..=p {
                    let f = |x: f64| cox(&knots, k - p + j, p, x);
                    let d1 = (f(t + h) - f(t - h)) / (2.0 * h);
                    let d2 = (f(t + h) - 2.0 * f(t) + f(t - h)) / (h * h);
                    assert!((ders[4 + j] - d1).abs() < 1e-6, "d1 t {t} j {j}");
                    assert!((ders[8 + j] - d2).abs() < 1e-3, "d2 t {t} j {j}");
                }
            }
            // Derivatives of the partition of unity vanish.
            assert!(ders[4..8].iter().sum::<f64>().abs() < 1e-12);
            assert!(ders[8..12].iter().sum::<f64>().abs() < 1e-10);
        }
    }
}
