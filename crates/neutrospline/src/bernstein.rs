//! Polynomials in Bernstein form over \[0, 1\] with several channels, packed point-major.
//!
//! This is the single numerical engine behind every Bézier operation: positions and the three
//! degrees are stored side by side as channels of one packed array
//! (`data[i * stride + c]` is channel `c` of control value `i`), so each algorithm is written
//! once and the degrees can never drift from the geometry. The layout is private.

/// Convex combination `(1 - t) a + t b`, with `s = 1 - t` supplied by the caller.
///
/// The form `s a + t b` never overflows for finite `a`, `b` (each term is bounded by the
/// larger magnitude), unlike `a + t (b - a)`. The exact value lies between `a` and `b`, so the
/// result is projected back onto `[min(a, b), max(a, b)]`: this removes rounding excursions
/// outside that interval and can only bring the result closer to the exact value. It is what
/// makes the degrees of every evaluated point provably stay in \[0, 1\].
#[inline(always)]
pub(crate) fn lerp(a: f64, b: f64, s: f64, t: f64) -> f64 {
    let v = s * a + t * b;
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    if v < lo {
        lo
    } else if v > hi {
        hi
    } else {
        v
    }
}

/// Control values of a multi-channel polynomial in Bernstein form.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Packed {
    stride: usize,
    data: Vec<f64>,
}

/// Largest packed length evaluated with a scratch buffer on the stack.
const STACK_SCRATCH: usize = 192;

impl Packed {
    /// `data.len()` must be a non-zero multiple of `stride`.
    pub(crate) fn new(stride: usize, data: Vec<f64>) -> Self {
        debug_assert!(stride > 0 && !data.is_empty() && data.len().is_multiple_of(stride));
        Packed { stride, data }
    }

    /// Number of control values (degree + 1).
    pub(crate) fn count(&self) -> usize {
        self.data.len() / self.stride
    }

    pub(crate) fn degree(&self) -> usize {
        self.count() - 1
    }

    /// Channels per control value.
    pub(crate) fn stride(&self) -> usize {
        self.stride
    }

    pub(crate) fn data(&self) -> &[f64] {
        &self.data
    }

    /// The channels of control value `i`.
    pub(crate) fn row(&self, i: usize) -> &[f64] {
        &self.data[i * self.stride..(i + 1) * self.stride]
    }

    /// Channel `c` of every control value.
    pub(crate) fn channel(&self, c: usize) -> Vec<f64> {
        self.data
            .iter()
            .skip(c)
            .step_by(self.stride)
            .copied()
            .collect()
    }

    /// Evaluates every channel at `t` by de Casteljau's algorithm into `out[..stride]`.
    ///
    /// `t` must be in \[0, 1\]. Uses a stack scratch buffer when small, else allocates once.
    pub(crate) fn evaluate(&self, t: f64, out: &mut [f64]) {
        if self.data.len() <= STACK_SCRATCH {
            let mut scratch = [0.0; STACK_SCRATCH];
            self.evaluate_with(t, &mut scratch[..self.data.len()], out);
        } else {
            let mut scratch = vec![0.0; self.data.len()];
            self.evaluate_with(t, &mut scratch, out);
        }
    }

    /// De Casteljau's algorithm with caller-provided scratch (`scratch.len() == data.len()`).
    ///
    /// Level `r` replaces `b_i` by `(1 - t) b_i + t b_{i+1}` for `i < n - r + 1`; after `n`
    /// levels `b_0` is the value. O(n^2) operations per channel, every one a convex
    /// combination, hence backward stable at any degree.
    pub(crate) fn evaluate_with(&self, t: f64, scratch: &mut [f64], out: &mut [f64]) {
        let stride = self.stride;
        scratch.copy_from_slice(&self.data);
        let s = 1.0 - t;
        let n = self.degree();
        for level in 1..=n {
            let len = (n + 1 - level) * stride;
            for k in 0..len {
                scratch[k] = lerp(scratch[k], scratch[k + stride], s, t);
            }
        }
        out[..stride].copy_from_slice(&scratch[..stride]);
    }

    /// Splits at `t` into the control values on \[0, t\] and on \[t, 1\] (de Casteljau).
    pub(crate) fn split(&self, t: f64) -> (Packed, Packed) {
        let stride = self.stride;
        let n = self.degree();
        let mut work = self.data.clone();
        let mut left = Vec::with_capacity(self.data.len());
        let mut right = vec![0.0; self.data.len()];
        let s = 1.0 - t;
        left.extend_from_slice(&work[..stride]);
        right[n * stride..].copy_from_slice(&work[n * stride..]);
        for level in 1..=n {
            let len = (n + 1 - level) * stride;
            for k in 0..len {
                work[k] = lerp(work[k], work[k + stride], s, t);
            }
            left.extend_from_slice(&work[..stride]);
            let last = (n - level) * stride;
            right[last..last + stride].copy_from_slice(&work[last..last + stride]);
        }
        (Packed::new(stride, left), Packed::new(stride, right))
    }

    /// The same polynomial restricted to \[t0, t1\] (or reversed when `t0 > t1`), reparametrised
    /// to \[0, 1\].
    pub(crate) fn subsegment(&self, t0: f64, t1: f64) -> Packed {
        if t0 > t1 {
            return self.subsegment(t1, t0).reversed();
        }
        if t1 <= 0.0 || t0 >= 1.0 || t0 == t1 {
            // A single parameter: every control value is the point itself.
            let mut point = vec![0.0; self.stride];
            self.evaluate(t0, &mut point);
            return Packed::new(self.stride, point.repeat(self.count()));
        }
        // Keep [t0, 1], then the part of it up to t1, which is at (t1 - t0) / (1 - t0) there.
        let upper = if t0 > 0.0 {
            self.split(t0).1
        } else {
            self.clone()
        };
        if t1 >= 1.0 {
            return upper;
        }
        let u = ((t1 - t0) / (1.0 - t0)).clamp(0.0, 1.0);
        upper.split(u).0
    }

    /// Control values in reverse order: the polynomial at `1 - t`.
    pub(crate) fn reversed(&self) -> Packed {
        let mut data = Vec::with_capacity(self.data.len());
        for row in self.data.chunks_exact(self.stride).rev() {
            data.extend_from_slice(row);
        }
        Packed::new(self.stride, data)
    }

    /// Degree elevation by one: `Q_i = (i / (n + 1)) P_{i-1} + (1 - i / (n + 1)) P_i`.
    pub(crate) fn elevate(&self) -> Packed {
        let stride = self.stride;
        let n = self.degree();
        let m = (n + 1) as f64;
        let mut data = Vec::with_capacity(self.data.len() + stride);
        data.extend_from_slice(self.row(0));
        for i in 1..=n {
            let t = i as f64 / m; // weight of P_{i-1}
            let s = (n + 1 - i) as f64 / m; // weight of P_i
            let (prev, cur) = (self.row(i - 1), self.row(i));
            for c in 0..stride {
                data.push(lerp(cur[c], prev[c], s, t));
            }
        }
        data.extend_from_slice(self.row(n));
        Packed::new(stride, data)
    }

    /// Bounds of channel `c` over \[0, 1\]: contain every value, and each is within `tolerance`
    /// of the true extremum (see [`lower_bound`]).
    pub(crate) fn channel_range(
        &self,
        c: usize,
        weights: Option<&[f64]>,
        tolerance: f64,
    ) -> (f64, f64) {
        let coeffs = self.channel(c);
        let low = lower_bound(&coeffs, weights, tolerance);
        let negated: Vec<f64> = coeffs.iter().map(|v| -v).collect();
        let high = -lower_bound(&negated, weights, tolerance);
        (low, high)
    }

    /// Minimum and maximum of channel `c` over the control values.
    pub(crate) fn control_range(&self, c: usize) -> (f64, f64) {
        self.data
            .iter()
            .skip(c)
            .step_by(self.stride)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            })
    }
}

/// A lower bound `L` of a one-channel Bernstein polynomial over \[0, 1\] with
/// `min - tolerance * scale <= L <= min`, where `scale` is the largest absolute coefficient.
/// With `weights` (all positive) the function is the rational `sum B_i w_i c_i / sum B_i w_i`.
///
/// Branch and bound on the convex hull property: a piece's minimum is at least its smallest
/// coefficient, and its end coefficients are attained values. Pieces whose smallest
/// coefficient cannot improve on the best attained value by more than the tolerance are
/// dropped; the others are halved by (rational) de Casteljau. The control polygon converges
/// quadratically, so about `log2(1 / sqrt(tolerance))` halvings suffice near each minimum.
pub(crate) fn lower_bound(coeffs: &[f64], weights: Option<&[f64]>, tolerance: f64) -> f64 {
    const MAX_DEPTH: u32 = 60;
    let scale = coeffs.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let slack = tolerance * scale;
    let n = coeffs.len() - 1;
    let mut best = coeffs[0].min(coeffs[n]);
    let mut bound = best;
    let unit = vec![1.0; coeffs.len()];
    let start_weights = weights.map_or(unit, <[f64]>::to_vec);
    let mut stack: Vec<(Vec<f64>, Vec<f64>, u32)> = vec![(coeffs.to_vec(), start_weights, 0)];
    while let Some((piece, w, depth)) = stack.pop() {
        best = best.min(piece[0]).min(piece[n]);
        let lowest = piece.iter().copied().fold(f64::INFINITY, f64::min);
        if lowest >= best - slack || depth >= MAX_DEPTH {
            bound = bound.min(lowest);
            continue;
        }
        let (left, right) = split_half(piece, w, weights.is_some());
        stack.push((right.0, right.1, depth + 1));
        stack.push((left.0, left.1, depth + 1));
    }
    bound.min(best)
}

type Piece = (Vec<f64>, Vec<f64>);

/// Halves a one-channel (rational when `rational`) Bézier piece by de Casteljau at 1/2.
fn split_half(mut c: Vec<f64>, mut w: Vec<f64>, rational: bool) -> (Piece, Piece) {
    let n = c.len() - 1;
    let mut left = (Vec::with_capacity(n + 1), Vec::with_capacity(n + 1));
    let mut right = (vec![0.0; n + 1], vec![0.0; n + 1]);
    left.0.push(c[0]);
    left.1.push(w[0]);
    right.0[n] = c[n];
    right.1[n] = w[n];
    for level in 1..=n {
        for i in 0..=n - level {
            let (s, t) = if rational {
                let total = w[i] + w[i + 1];
                (w[i] / total, w[i + 1] / total)
            } else {
                (0.5, 0.5)
            };
            c[i] = lerp(c[i], c[i + 1], s, t);
            w[i] = 0.5 * (w[i] + w[i + 1]);
        }
        left.0.push(c[0]);
        left.1.push(w[0]);
        right.0[n - level] = c[n - level];
        right.1[n - level] = w[n - level];
    }
    (left, right)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic() -> Packed {
        // One channel: 1, -2, 3, 0.5.
        Packed::new(1, vec![1.0, -2.0, 3.0, 0.5])
    }

    fn eval1(p: &Packed, t: f64) -> f64 {
        let mut out = [0.0];
        p.evaluate(t, &mut out);
        out[0]
    }

    /// Power form of the cubic above: sum_i c_i C(3,i) t^i (1-t)^(3-i).
    fn cubic_closed(t: f64) -> f64 {
        let s = 1.0 - t;
        s * s * s - 2.0 * 3.0 * t * s * s + 3.0 * 3.0 * t * t * s + 0.5 * t * t * t
    }

    #[test]
    fn packed_evaluate_matches_closed_form() {
        let p = cubic();
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            assert!((eval1(&p, t) - cubic_closed(t)).abs() < 1e-15);
        }
    }

    #[test]
    fn lerp_stays_between_endpoints() {
        for &(a, b) in &[(1.0, 1.0), (0.0, 1.0), (0.3, 0.7), (1e308, -1e308)] {
            for k in 0..=100 {
                let t = k as f64 / 100.0;
                let v = lerp(a, b, 1.0 - t, t);
                assert!(v >= a.min(b) && v <= a.max(b) && v.is_finite());
            }
        }
    }

    #[test]
    fn packed_split_and_subsegment() {
        let p = cubic();
        let (l, r) = p.split(0.3);
        for k in 0..=10 {
            let u = k as f64 / 10.0;
            assert!((eval1(&l, u) - cubic_closed(0.3 * u)).abs() < 1e-14);
            assert!((eval1(&r, u) - cubic_closed(0.3 + 0.7 * u)).abs() < 1e-14);
        }
        let s = p.subsegment(0.2, 0.6);
        let rev = p.subsegment(0.6, 0.2);
        for k in 0..=10 {
            let u = k as f64 / 10.0;
            assert!((eval1(&s, u) - cubic_closed(0.2 + 0.4 * u)).abs() < 1e-14);
            assert!((eval1(&rev, u) - cubic_closed(0.6 - 0.4 * u)).abs() < 1e-14);
        }
        let point = p.subsegment(0.5, 0.5);
        assert!(point.data().iter().all(|&v| v == eval1(&p, 0.5)));
    }

    #[test]
    fn packed_elevate() {
        let p = cubic();
        let e = p.elevate();
        assert_eq!(e.degree(), 4);
        // Q_i = i/4 P_{i-1} + (1 - i/4) P_i.
        assert_eq!(e.data(), &[1.0, -1.25, 0.5, 2.375, 0.5]);
    }

    #[test]
    fn lower_bound_of_cubic() {
        // f'(t) = 3 (-3 s^2 + 10 t s - 2.5 t^2) = 3 (-3 + 16 t - 15.5 t^2) vanishes at
        // t = (16 -+ sqrt(70)) / 31: a local minimum then a local maximum, both inside (0, 1),
        // below f(1) = 0.5 and above f(0) = 1 respectively.
        let p = cubic();
        let min_exact = cubic_closed((16.0 - 70f64.sqrt()) / 31.0);
        let max_exact = cubic_closed((16.0 + 70f64.sqrt()) / 31.0);
        assert!(min_exact < 0.5 && max_exact > 1.0);
        let (lo, hi) = p.channel_range(0, None, 1e-12);
        assert!(
            lo <= min_exact && lo >= min_exact - 3e-12,
            "{lo} vs {min_exact}"
        );
        assert!(
            hi >= max_exact && hi <= max_exact + 3e-12,
            "{hi} vs {max_exact}"
        );
    }
}
