//! The scalar Bernstein toolkit: polynomials in one variable on [0, 1] given by their
//! Bernstein coefficients `c_0 .. c_n` (`p(x) = sum_k c_k B_{n,k}(x)`), as the nearest-point
//! and intersection searches use them: binomials, de Casteljau halving, value and slope,
//! sign changes (Descartes' rule of signs for the Bernstein basis: the number of roots in
//! (0, 1) is at most the number of sign changes of the coefficients, and has its parity),
//! deflation of the roots at the ends, and a safeguarded root of a bracketed polynomial.

use crate::bernstein::Packed;

pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, r| acc * (n - r) as f64 / (r + 1) as f64)
}

/// One level of de Casteljau at 1/2: the coefficients of the left and right halves
/// ([`Packed::split`] on one channel).
pub(crate) fn halves(c: &[f64], left: &mut Vec<f64>, right: &mut Vec<f64>) {
    let (l, r) = Packed::new(1, c.to_vec()).split(0.5);
    left.clear();
    left.extend_from_slice(l.data());
    right.clear();
    right.extend_from_slice(r.data());
}

/// The value and derivative at `x` in [0, 1] of the Bernstein polynomial with coefficients `c`.
pub(crate) fn value_and_slope(c: &[f64], x: f64) -> (f64, f64) {
    let n = c.len() - 1;
    if n == 0 {
        return (c[0], 0.0);
    }
    let mut stack = [0.0; 32];
    let mut heap;
    let work: &mut [f64] = if c.len() <= stack.len() {
        stack[..c.len()].copy_from_slice(c);
        &mut stack[..c.len()]
    } else {
        heap = c.to_vec();
        &mut heap
    };
    for level in 1..n {
        for i in 0..=n - level {
            work[i] = (1.0 - x) * work[i] + x * work[i + 1];
        }
    }
    let (a, b) = (work[0], work[1]);
    ((1.0 - x) * a + x * b, n as f64 * (b - a))
}

/// Sign changes of a coefficient sequence (zeros skipped), and whether the first non-zero
/// coefficient is negative.
pub(crate) fn sign_changes(c: &[f64]) -> (usize, bool) {
    let mut changes = 0;
    let mut last = 0.0_f64;
    let mut first_negative = false;
    for &x in c {
        if x == 0.0 {
            continue;
        }
        if last == 0.0 {
            first_negative = x < 0.0;
        } else if (x < 0.0) != (last < 0.0) {
            changes += 1;
        }
        last = x;
    }
    (changes, first_negative)
}

/// Divides out the roots at 0 and 1 of a Bernstein polynomial (exact zero end coefficients),
/// which keeps the sign inside (0, 1): with `c_m = 0`,
/// `sum_k c_k B_{m,k} = (1 - x) sum_{k<m} c_k m / (m - k) B_{m-1,k}`, and with `c_0 = 0`,
/// `x sum_{k>0} c_k m / k B_{m-1,k-1}`. A zero polynomial is left as one zero.
pub(crate) fn deflate(c: &mut Vec<f64>) {
    while c.len() > 1 {
        let m = c.len() - 1;
        if c[m] == 0.0 {
            c.pop();
            for (k, x) in c.iter_mut().enumerate() {
                *x *= m as f64 / (m - k) as f64;
            }
        } else if c[0] == 0.0 {
            c.remove(0);
            for (k, x) in c.iter_mut().enumerate() {
                *x *= m as f64 / (k + 1) as f64;
            }
        } else {
            break;
        }
    }
}

/// A root of the Bernstein polynomial `c` in (0, 1), where `c(0) < 0 < c(1)` (after
/// [`deflate`]).
///
/// Newton's method inside a bracket `[lo, hi]` with `c(lo) < 0 < c(hi)`, kept at every step.
/// A Newton step is taken only where the slope is positive (the polynomial rises through the
/// root it brackets) and the step stays inside the bracket; otherwise the bracket is bisected.
/// A slope of the wrong sign is no evidence of convergence: near a stationary end (a double
/// control point makes `c(0)` rounding noise and `c` fall at first) the Newton step is tiny
/// and points away from the root. The search ends when a rising Newton step is a few ulps of
/// 1, or the bracket is that narrow.
pub(crate) fn bracketed_root(c: &[f64]) -> f64 {
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    let (first, last) = (c[0], c[c.len() - 1]);
    let guess = -first / (last - first);
    let mut x = if guess > 0.0 && guess < 1.0 {
        guess
    } else {
        0.5
    };
    // 64 bisections narrow [0, 1] below an ulp; Newton steps only shorten the search.
    for _ in 0..200 {
        let (value, slope) = value_and_slope(c, x);
        if value == 0.0 {
            return x;
        }
        if value < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if hi - lo <= 4.0 * f64::EPSILON {
            return 0.5 * (lo + hi);
        }
        let rising = slope > 0.0;
        let newton = x - value / slope;
        if rising && (newton - x).abs() <= 4.0 * f64::EPSILON {
            return newton.clamp(lo, hi);
        }
        x = if rising && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    0.5 * (lo + hi)
}
