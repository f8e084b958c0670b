//! Compensated evaluation: de Casteljau's and de Boor's algorithms with error-free
//! transformations, as accurate as if computed in twice the working precision, then rounded.
//!
//! Both algorithms are one triangle of steps `d_j <- beta d_{j-1} + alpha d_j` (level `r`,
//! `j = p` down to `r`, the value in `d_p`); only the weights differ: `beta = 1 - t`,
//! `alpha = t` for de Casteljau (Graillat, Langlois and Louvet, "Compensated Horner scheme",
//! 2005, and their compensated de Casteljau algorithm), and the ratios of knot differences
//! `alpha = (t - u_lo) / (u_hi - u_lo)`, `beta = (u_hi - t) / (u_hi - u_lo)` for de Boor (Jiang,
//! Li, Cheng and Su, "Accurate evaluation of a polynomial and its derivative in Bernstein
//! form", and Jiang et al., "Compensated de Boor algorithm", 2011). The triangle is written
//! once, [`evaluate`], over every channel of a packed row (positions and the three degrees).
//!
//! Each step computes the rounded value with [`two_product`] and [`two_sum`], which also give
//! its rounding errors exactly, and carries those errors through the same recurrence in a
//! second triangle:
//!
//! ```text
//! [P1, e1] = TwoProduct(beta, d_{j-1})     [P2, e2] = TwoProduct(alpha, d_j)
//! [d_j, s] = TwoSum(P1, P2)
//! err_j    = beta err_{j-1} + alpha err_j + (e1 + e2 + s + db d_{j-1} + da d_j)
//! ```
//!
//! where `db`, `da` are the errors of the weights themselves (`1 - t` by [`two_sum`]; a knot
//! ratio by its exact residual, [`quotient_error`]). The result `d_p + err_p` has an error of
//! at most `u |value| + O(p^2 u^2) sum_i |c_i| N_i(t)`, `u = 2^-53`: about one rounding of the
//! value, at any degree up to the tens of thousands (the plain algorithms' bound is
//! `O(p u) max |c|`).
//!
//! Rational curves (NURBS) are evaluated in homogeneous form: the rows `(w c, w)`, whose
//! products are split exactly by [`two_product`] (the low parts are the initial errors), go
//! through the same triangle as one more channel, and the compensated numerator is divided by
//! the compensated denominator by [`quotient`]. The weights of the span are first scaled by a
//! power of two (exact) so that the largest is in \[1/2, 1\]. A span whose weights are all
//! equal is a polynomial piece and takes the polynomial path (so a NURBS curve with unit
//! weights gives bit for bit a B-spline's values).
//!
//! Every channel is finally projected onto the range of the span's control values, which
//! contains the exact value (the basis is non-negative with unit sum): degrees stay in
//! their control range, inside \[0, 1\], and the ends are exact (at an end every weight is 0
//! or 1 with no error). A channel that overflows in the compensated form (control values
//! near the largest float) is reported as not finite, and the caller then falls back to the
//! plain convex-combination form, which never overflows.

/// `a + b = s + e` exactly, with `s = fl(a + b)` (Knuth's TwoSum: no branch, any order).
#[inline(always)]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a b = p + e` exactly, with `p = fl(a b)` (TwoProduct by one fused multiply-add), unless
/// the product underflows.
#[inline(always)]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// A weight of a step and its error: the exact weight is `value + error` (to first order).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Weight {
    pub(crate) value: f64,
    pub(crate) error: f64,
}

/// The two weights of a step `d_j <- beta d_{j-1} + alpha d_j`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Step {
    pub(crate) beta: Weight,
    pub(crate) alpha: Weight,
}

impl Step {
    /// De Casteljau's step at `t`: `beta = 1 - t` (split exactly), `alpha = t`.
    pub(crate) fn casteljau(t: f64) -> Step {
        let (value, error) = two_sum(1.0, -t);
        Step {
            beta: Weight { value, error },
            alpha: Weight {
                value: t,
                error: 0.0,
            },
        }
    }

    /// De Boor's step at the exact parameter `origin + offset` between the knots `lo < hi`:
    /// `alpha = ((origin - lo) + offset) / (hi - lo)`, `beta = ((hi - origin) - offset) /
    /// (hi - lo)`, each with the error of its differences and of its division. A weight
    /// that rounds outside \[0, 1\] (a parameter at the edge of the span) is projected onto
    /// it, with no error.
    pub(crate) fn de_boor(origin: f64, offset: f64, lo: f64, hi: f64) -> Step {
        let (den, den_err) = two_sum(hi, -lo);
        let ratio = |first: f64, second: f64, third: f64| {
            let (a, e1) = two_sum(first, second);
            let (num, e2) = two_sum(a, third);
            let q = num / den;
            if (0.0..=1.0).contains(&q) {
                Weight {
                    value: q,
                    error: quotient_error(q, num, e1 + e2, den, den_err),
                }
            } else {
                Weight {
                    value: q.clamp(0.0, 1.0),
                    error: 0.0,
                }
            }
        };
        Step {
            alpha: ratio(origin, -lo, offset),
            beta: ratio(hi, -origin, -offset),
        }
    }
}

/// The error of `q = fl(n / d)` as an approximation of `(n + en) / (d + ed)`:
/// `(r + en - q ed) / d` with the exact residual `r = n - q d` (one fused multiply-add).
#[inline(always)]
pub(crate) fn quotient_error(q: f64, n: f64, en: f64, d: f64, ed: f64) -> f64 {
    let r = (-q).mul_add(d, n);
    (r + en - q * ed) / d
}

/// `(n + en) / (d + ed)` to about one rounding: the rounded quotient plus its error.
#[inline(always)]
pub(crate) fn quotient(n: f64, en: f64, d: f64, ed: f64) -> f64 {
    let q = n / d;
    q + quotient_error(q, n, en, d, ed)
}

/// Largest packed length (values or errors) kept on the stack.
const STACK_SCRATCH: usize = 192;

/// The compensated triangle over `p + 1` rows of `stride` channels in `values` (with their
/// initial errors in `errors`): level `r = 1 ..= p`, `j = p` down to `r`,
/// `d_j <- beta d_{j-1} + alpha d_j` with the weights `step(r, j)`. Afterwards row `p` holds
/// the rounded values and their errors.
fn triangle(
    stride: usize,
    p: usize,
    values: &mut [f64],
    errors: &mut [f64],
    mut step: impl FnMut(usize, usize) -> Step,
) {
    for r in 1..=p {
        for j in (r..=p).rev() {
            let Step { beta, alpha } = step(r, j);
            let (left, right) = ((j - 1) * stride, j * stride);
            for c in 0..stride {
                let (a, b) = (values[left + c], values[right + c]);
                let (p1, e1) = two_product(beta.value, a);
                let (p2, e2) = two_product(alpha.value, b);
                let (v, s) = two_sum(p1, p2);
                let local = e1 + e2 + s + beta.error * a + alpha.error * b;
                let carried = beta
                    .value
                    .mul_add(errors[left + c], alpha.value * errors[right + c]);
                errors[right + c] = carried + local;
                values[right + c] = v;
            }
        }
    }
}

/// Evaluates the polynomial or rational piece with the `p + 1` control rows `rows` (`stride`
/// channels each) and optional positive `weights`, by the compensated triangle with the
/// weights `step(r, j)` of level `r` and row `j`, into `out[..stride]`. Returns `false` when a
/// value is not finite (overflow in the products; the caller then uses the plain form).
pub(crate) fn evaluate(
    stride: usize,
    rows: &[f64],
    weights: Option<&[f64]>,
    step: impl FnMut(usize, usize) -> Step,
    out: &mut [f64],
) -> bool {
    let count = rows.len() / stride;
    let p = count - 1;
    // A rational piece whose weights are all equal is the polynomial piece.
    let weights = weights.filter(|w| w.iter().any(|&x| x != w[0]));
    let width = stride + usize::from(weights.is_some());
    let len = count * width;
    let mut stack = [0.0; 2 * STACK_SCRATCH];
    let mut heap;
    let scratch: &mut [f64] = if len <= STACK_SCRATCH {
        &mut stack[..2 * len]
    } else {
        heap = vec![0.0; 2 * len];
        &mut heap
    };
    let (values, errors) = scratch.split_at_mut(len);
    match weights {
        None => {
            values.copy_from_slice(rows);
            errors.fill(0.0);
        }
        Some(ws) => {
            // A power of two near the largest weight: the scaling is exact.
            let largest = ws.iter().copied().fold(0.0, f64::max);
            let scale = 2f64.powi(-(largest.log2().ceil() as i32));
            for (i, (row, &w)) in rows.chunks_exact(stride).zip(ws).enumerate() {
                let w = w * scale;
                for (c, &v) in row.iter().enumerate() {
                    let (hi, lo) = two_product(w, v);
                    values[i * width + c] = hi;
                    errors[i * width + c] = lo;
                }
                values[i * width + stride] = w;
                errors[i * width + stride] = 0.0;
            }
        }
    }
    triangle(width, p, values, errors, step);
    let last = p * width;
    let mut finite = true;
    for c in 0..stride {
        let v = match weights {
            None => values[last + c] + errors[last + c],
            Some(_) => quotient(
                values[last + c],
                errors[last + c],
                values[last + stride],
                errors[last + stride],
            ),
        };
        let (lo, hi) = rows
            .iter()
            .skip(c)
            .step_by(stride)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            });
        finite &= v.is_finite();
        out[c] = v.clamp(lo, hi);
    }
    finite
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod accuracy;
