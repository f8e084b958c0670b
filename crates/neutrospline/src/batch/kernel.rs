//! The batch kernels: one Bézier polynomial with `CH` channels evaluated at a run of
//! parameters, [`Lanes::LANES`] parameters at a time (one per lane), channel-major output.
//!
//! Three formulations, chosen by degree:
//!
//! - **Taylor about the nearer end** (degree `1 ..= TAYLOR_MAX_DEGREE`): per channel the
//!   coefficients `a_k = C(n, k) Δ^k c_0` of `p(t) = sum_k a_k t^k`, and `b_k` likewise from
//!   the reversed control values, `p = sum_k b_k s^k` with `s = 1 - t`, computed once per
//!   curve; lanes with `t <= 1/2` run Horner's rule in `t` on `a`, the others in `s` (exact
//!   there) on `b`: `n` multiply-adds per channel, no weights. With `|Δ^k c| <= 2^k max |c|`
//!   and `t, s <= 1/2` on their side, `sum_k |a_k| t^k <= 2^n max |c|`, so the error is at
//!   most about `(2n + 1) 2^n u max |c|` (56 u for a cubic, below 1e-14); `a_0 = c_0` and
//!   `b_0 = c_n`, so the ends come out exactly. The same projection as below follows.
//! - **Bernstein weights** (degree `1 ..= DIRECT_MAX_DEGREE`): per lane,
//!   `w_i = C(n, i) t^i s^(n-i)` with `s = 1 - t` (the powers by repeated multiplication, the
//!   binomial coefficients exact integers rounded once; up to degree 15 they are folded into
//!   the control values once per curve, `C(n, i) c_{c,i}`, unless a product overflows), then
//!   one dot product per channel, `v_c = sum_i w_i c_{c,i}`. O(n) per parameter and channel
//!   instead of de Casteljau's O(n^2), with no binomial coefficient near overflow
//!   (`C(1000, 500) < 2^995`; a power `t^i` that underflows belongs to a weight below
//!   `2^-1022 C(n, i)`, negligible) and no cancellation: every weight is a product of
//!   non-negative factors, the powers with a relative error of at most `(n + 3) u`
//!   (`u = 2^-53`) and the binomial coefficients exact up to degree 67 and within
//!   `(n - 66) u` above, so `|computed - exact| <= 3n u max_i |c_{c,i}|` per channel
//!   (`(2n + 4) u` up to degree 67). Up to degree [`FIXED_MAX_DEGREE`] a kernel compiled per
//!   degree keeps everything in registers; above, [`LongWeights`] keeps the weights in a
//!   scratch buffer. De Casteljau's error is of the same order, so the two agree to a few `n u max |c|` (tested to 1e-14 up to degree
//!   15, 1e-12 up to 400; the worst measured is about `1.5 n u`). At `t = 0` and `t = 1` the
//!   weights are exactly `(1, 0, ..., 0)` and `(0, ..., 0, 1)` (and `C(n, 0) = C(n, n) = 1`),
//!   so the end control values come out exactly.
//!   Each channel is then projected onto `[min_i c_{c,i}, max_i c_{c,i}]`. The weights are
//!   non-negative with unit sum, so that interval contains the exact value: the projection
//!   only removes rounding excursions (it can only move a value closer to the exact one) and
//!   it is what keeps every degree within its control range, inside \[0, 1\].
//! - **de Casteljau** (above degree 1000): the recurrence of [`crate::bernstein`], lane-parallel,
//!   with the same operation order and the same projection of every convex combination, so
//!   its results are bit-identical to the scalar evaluation.

use super::lanes::Lanes;

mod taylor;
mod weights;

use taylor::{taylor, taylor_row};
use weights::{run, Casteljau, LongWeights};

/// Highest degree evaluated with Bernstein weights; de Casteljau above it.
pub(crate) const DIRECT_MAX_DEGREE: usize = super::DIRECT_MAX_DEGREE;

/// Lowest degree with a kernel compiled for it (below, the Taylor kernel serves).
const FIXED_MIN_DEGREE: usize = 4;

/// Highest degree with a kernel compiled for it (unrolled, binomials folded in).
const FIXED_MAX_DEGREE: usize = 15;

/// Highest degree evaluated with the Taylor kernel (its error bound, `(n + 1) 2^n u` from
/// the coefficients plus `n 2^n u` from Horner's rule, is below `1e-14` up to here).
const TAYLOR_MAX_DEGREE: usize = 3;

/// Parameter vectors per step of the Taylor kernel.
const TAYLOR_STEP: usize = 4;

/// Largest number of channels (3-D positions, three degrees and, for rational curves, the
/// weight).
pub(crate) const MAX_CHANNELS: usize = 7;

/// A Bézier polynomial prepared for the kernels.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Coeffs {
    /// Polynomial degree `n`.
    pub(crate) degree: usize,
    /// Number of channels.
    pub(crate) channels: usize,
    /// Channel-major control values: channel `c`, index `i` at `c * (n + 1) + i`. (This and
    /// `binomials` are dropped when `scaled` or `taylor` serves the degree: only the data the
    /// degree's kernel reads is kept, which matters for a spline's many pieces.)
    pub(crate) values: Vec<f64>,
    /// `C(n, i)` for `i = 0 ..= n` (empty above [`DIRECT_MAX_DEGREE`]).
    pub(crate) binomials: Vec<f64>,
    /// `C(n, i) c_{c,i}`, channel-major, for the fixed-degree kernels (degree
    /// `1 ..= FIXED_MAX_DEGREE`); empty otherwise, or if a product overflows.
    pub(crate) scaled: Vec<f64>,
    /// Taylor coefficients about the nearer end (degree `1 ..= TAYLOR_MAX_DEGREE`; empty
    /// otherwise, or if one is not finite): channel-major, `n + 1` per channel, first about
    /// `t = 0` (all channels), then about `t = 1` in `s = 1 - t`. See [`taylor_row`].
    pub(crate) taylor: Vec<f64>,
    /// Smallest control value of each channel.
    pub(crate) lo: [f64; MAX_CHANNELS],
    /// Largest control value of each channel.
    pub(crate) hi: [f64; MAX_CHANNELS],
}

impl Coeffs {
    /// From point-major packed control values (`data[i * channels + c]`).
    pub(crate) fn from_packed(channels: usize, data: &[f64]) -> Self {
        debug_assert!(
            channels <= MAX_CHANNELS && !data.is_empty() && data.len().is_multiple_of(channels)
        );
        let count = data.len() / channels;
        let degree = count - 1;
        let mut values = Vec::with_capacity(data.len());
        let mut lo = [0.0; MAX_CHANNELS];
        let mut hi = [0.0; MAX_CHANNELS];
        for c in 0..channels {
            let channel = data.iter().skip(c).step_by(channels).copied();
            values.extend(channel);
            let column = &values[c * count..];
            lo[c] = column.iter().copied().fold(f64::INFINITY, f64::min);
            hi[c] = column.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        }
        let mut binomials = if degree <= DIRECT_MAX_DEGREE {
            binomial_row(degree)
        } else {
            Vec::new()
        };
        let mut scaled = Vec::new();
        if (1..=FIXED_MAX_DEGREE).contains(&degree) {
            scaled = values
                .iter()
                .enumerate()
                .map(|(k, v)| v * binomials[k % count])
                .collect();
            if scaled.iter().any(|v| !v.is_finite()) {
                scaled.clear();
            }
        }
        let mut taylor = Vec::new();
        if (1..=TAYLOR_MAX_DEGREE).contains(&degree) {
            let rows = values.chunks_exact(count);
            taylor.extend(rows.clone().flat_map(|row| taylor_row(row.iter().copied())));
            taylor.extend(rows.flat_map(|row| taylor_row(row.iter().rev().copied())));
            if taylor.iter().any(|v| !v.is_finite()) {
                taylor.clear();
            }
        }
        if !taylor.is_empty() {
            scaled = Vec::new();
        }
        if !taylor.is_empty() || !scaled.is_empty() {
            values = Vec::new();
            binomials = Vec::new();
        }
        Coeffs {
            degree,
            channels,
            values,
            binomials,
            scaled,
            taylor,
            lo,
            hi,
        }
    }
}

/// `C(n, i)`, `i = 0 ..= n`, by Pascal's rule: in exact integers up to row 67 (the last
/// that fits in `u64`), each rounded once to `f64`, then in `f64`. Sums of positive terms, so
/// row `n > 67` has a relative error of at most `(n - 66) u`; finite up to `n = 1029`.
fn binomial_row(n: usize) -> Vec<f64> {
    const EXACT_ROWS: usize = 67;
    let mut exact = vec![0u64; n.min(EXACT_ROWS) + 1];
    exact[0] = 1;
    for k in 1..exact.len() {
        for i in (1..=k).rev() {
            exact[i] += exact[i - 1];
        }
    }
    let mut row: Vec<f64> = exact.into_iter().map(|c| c as f64).collect();
    for k in EXACT_ROWS + 1..=n {
        row.push(0.0);
        for i in (1..=k).rev() {
            row[i] += row[i - 1];
        }
    }
    row
}

/// A run of parameters, read one vector at a time.
pub(crate) trait Params: Sync {
    /// The parameters at positions `offset .. offset + LANES` of the run. Lanes past the end
    /// of the run hold arbitrary finite values (their results are discarded).
    fn vector<L: Lanes>(&self, lanes: L, offset: usize) -> L::V;

    /// Where the parameters at positions `offset .. offset + len` lie with respect to 1/2,
    /// decided exactly as the lane test `t <= 0.5` would (`len` a multiple of `LANES`; lanes
    /// past the end of the run included).
    fn side<L: Lanes>(&self, offset: usize, len: usize) -> Side;
}

/// Where a vector of parameters lies with respect to 1/2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Side {
    /// Every lane `t <= 1/2`.
    Low,
    /// Every lane `t > 1/2`.
    High,
    /// Some of each.
    Mixed,
}

/// `t_k = k / denominator` for `k = first, first + 1, ...`: the evenly spaced parameters,
/// computed exactly as the scalar `k as f64 / (count - 1) as f64` (an exactly rounded division
/// of two exact integers, in every lane).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Uniform {
    pub(crate) first: usize,
    pub(crate) denominator: f64,
}

impl Params for Uniform {
    #[inline(always)]
    fn vector<L: Lanes>(&self, l: L, offset: usize) -> L::V {
        // Integers below 2^53 are exact as f64, and so is their sum with the lane index.
        // (Through i64: one conversion instruction, where u64 to f64 takes several.)
        let k = l.add(l.splat((self.first + offset) as i64 as f64), l.iota());
        l.div(k, l.splat(self.denominator))
    }

    #[inline(always)]
    fn side<L: Lanes>(&self, offset: usize, len: usize) -> Side {
        // `k / d` rounded is `<= 1/2` exactly when `2 k <= d`: if `2 k > d`, the exact
        // quotient exceeds 1/2 by at least `1 / (2 d)`, more than half an ulp of 1/2 (2^-54)
        // for any `d < 2^53`. Integers below 2^53 and their doubles are exact in f64.
        let first = (self.first + offset) as f64;
        let last = first + (len - 1) as f64;
        if 2.0 * last <= self.denominator {
            Side::Low
        } else if 2.0 * first > self.denominator {
            Side::High
        } else {
            Side::Mixed
        }
    }
}

/// Given parameters.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Values<'a>(pub(crate) &'a [f64]);

impl Params for Values<'_> {
    #[inline(always)]
    fn vector<L: Lanes>(&self, l: L, offset: usize) -> L::V {
        // (A step of several vectors may start a vector past the end: zeros there.)
        let rest = self.0.get(offset..).unwrap_or_default();
        if rest.len() >= L::LANES {
            l.load(rest)
        } else {
            l.load_partial(rest)
        }
    }

    #[inline(always)]
    fn side<L: Lanes>(&self, offset: usize, len: usize) -> Side {
        let rest = self.0.get(offset..).unwrap_or_default();
        let lanes = &rest[..rest.len().min(len)];
        let low = lanes.iter().filter(|&&t| t <= 0.5).count();
        // Lanes past the end are zero: low.
        if low == lanes.len() {
            Side::Low
        } else if low == 0 && lanes.len() == len {
            Side::High
        } else {
            Side::Mixed
        }
    }
}

/// Evaluates `coeffs` at the parameters of `params` into `out[c]` (channel `c`; every slice
/// as long as the run). `scratch` is reused across calls (de Casteljau only).
#[inline(always)]
pub(crate) fn evaluate<L: Lanes, P: Params, const CH: usize>(
    l: L,
    coeffs: &Coeffs,
    params: &P,
    out: &mut [&mut [f64]; CH],
    scratch: &mut Vec<L::V>,
) {
    debug_assert_eq!(coeffs.channels, CH);
    match coeffs.degree {
        0 => constant(coeffs, out),
        1 if !coeffs.taylor.is_empty() => taylor::<L, P, CH, 2>(l, coeffs, params, out),
        2 if !coeffs.taylor.is_empty() => taylor::<L, P, CH, 3>(l, coeffs, params, out),
        3 if !coeffs.taylor.is_empty() => taylor::<L, P, CH, 4>(l, coeffs, params, out),
        n => {
            if !l.fixed(coeffs, params, out) {
                if n <= DIRECT_MAX_DEGREE {
                    let mut kernel = LongWeights::new(l, coeffs, scratch);
                    drive::<L, P, _, CH, 1>(l, &mut kernel, params, out);
                } else {
                    let mut kernel = Casteljau::new(l, coeffs, scratch);
                    drive::<L, P, _, CH, 1>(l, &mut kernel, params, out);
                }
            }
        }
    }
}

/// The kernels compiled per degree (`FIXED_MIN_DEGREE ..= FIXED_MAX_DEGREE`), with the binomial
/// coefficients folded into the control values (`scaled`): the weights are then plain products
/// of powers, two multiplications fewer per weight. Returns `false` when none serves the
/// degree (or `scaled` is empty: a product overflowed), and the caller runs the general kernel.
/// The lane types call it from [`Lanes::fixed`] (the portable fallback of x86-64 builds with
/// SIMD does not: these kernels are most of the crate's compile time).
#[inline(always)]
pub(crate) fn fixed<L: Lanes, P: Params, const CH: usize>(
    l: L,
    coeffs: &Coeffs,
    params: &P,
    out: &mut [&mut [f64]; CH],
) -> bool {
    if coeffs.scaled.is_empty() {
        return false;
    }
    macro_rules! fixed {
        ($($w:literal)*) => {
            match coeffs.degree {
                $($w => {
                    const { assert!(FIXED_MIN_DEGREE <= $w && $w <= FIXED_MAX_DEGREE) };
                    run::<L, P, CH, { $w + 1 }>(l, coeffs, params, out)
                })*
                _ => return false,
            }
        };
    }
    fixed!(4 5 6 7 8 9 10 11 12 13 14 15);
    true
}

/// Degree 0: every point is the control point.
fn constant<const CH: usize>(coeffs: &Coeffs, out: &mut [&mut [f64]; CH]) {
    for (c, channel) in out.iter_mut().enumerate() {
        channel.fill(coeffs.values[c]);
    }
}

/// Runs `kernel` over the whole output, `U` vectors of parameters per step, then the rest one
/// vector at a time (the last one stored partially). (Running the rest as one more step into
/// vectors on the stack measured 3-7 % slower at degree 7: the coefficients stay live longer.)
// Inlining: as for `run`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn drive<L: Lanes, P: Params, K: Kernel<L, CH>, const CH: usize, const U: usize>(
    l: L,
    kernel: &mut K,
    params: &P,
    out: &mut [&mut [f64]; CH],
) {
    let len = out[0].len();
    let step = U * L::LANES;
    let full = len - len % step;
    let vectors = full / L::LANES;
    // The outputs as slices of vectors: one index for every channel, bounds checks proven
    // away by the equal lengths.
    let heads = out.each_mut().map(|s| l.as_vectors_mut(&mut s[..full]));
    for head in &heads {
        assert_eq!(head.len(), vectors);
    }
    let mut sink = Vectors { heads, j: 0 };
    while sink.j < vectors {
        let at = Step {
            params,
            offset: sink.j * L::LANES,
        };
        kernel.step::<P, _, U>(l, at, &mut sink);
        sink.j += U;
    }
    // The last, partial step: one vector at a time, stored partially at the end.
    let mut k = full;
    while k < len {
        let mut sink = Tail { out: &mut *out, k };
        kernel.step::<P, _, 1>(l, Step { params, offset: k }, &mut sink);
        k += L::LANES;
    }
}

/// Where a kernel puts its results: vector `u` of the current step, channel `c`.
///
/// A kernel hands over each channel as soon as it is done (rather than returning them all),
/// so that the compiler need not keep `CH * U` vectors alive at once, which spills.
trait Sink<L: Lanes> {
    fn put(&mut self, l: L, c: usize, u: usize, v: L::V);
}

/// The outputs as slices of vectors; the step starts at vector `j`.
struct Vectors<'a, V, const CH: usize> {
    heads: [&'a mut [V]; CH],
    j: usize,
}

impl<L: Lanes, const CH: usize> Sink<L> for Vectors<'_, L::V, CH> {
    #[inline(always)]
    fn put(&mut self, _: L, c: usize, u: usize, v: L::V) {
        self.heads[c][self.j + u] = v;
    }
}

/// One vector at position `k` of the outputs, possibly past their end (partial store).
struct Tail<'a, 'b, const CH: usize> {
    out: &'a mut [&'b mut [f64]; CH],
    k: usize,
}

impl<L: Lanes, const CH: usize> Sink<L> for Tail<'_, '_, CH> {
    #[inline(always)]
    fn put(&mut self, l: L, c: usize, u: usize, v: L::V) {
        debug_assert_eq!(u, 0);
        let dst = &mut self.out[c][self.k..];
        if dst.len() >= L::LANES {
            l.store(dst, v);
        } else {
            l.store_partial(dst, v);
        }
    }
}

/// A kernel: every channel at `U` consecutive vectors of parameters.
///
/// No closures here: a closure is a function of its own that the compiler may leave out of
/// line, compiled without the dispatcher's target features.
trait Kernel<L: Lanes, const CH: usize> {
    /// The channels at the `U` vectors of parameters of `at`, vector by vector, into `sink`.
    fn step<P: Params, S: Sink<L>, const U: usize>(&mut self, l: L, at: Step<P>, sink: &mut S);
}

/// The parameters of one step of a kernel: the `U` vectors at positions
/// `offset .. offset + U * LANES` of the run.
struct Step<'p, P> {
    params: &'p P,
    offset: usize,
}

// (Not derived: that would require `P: Copy`, and only the reference is copied.)
impl<P> Clone for Step<'_, P> {
    #[inline(always)]
    fn clone(&self) -> Self {
        *self
    }
}

impl<P> Copy for Step<'_, P> {}

impl<P: Params> Step<'_, P> {
    /// The `U` vectors of parameters.
    #[inline(always)]
    fn vectors<L: Lanes, const U: usize>(self, l: L) -> [L::V; U] {
        let mut ts = [l.splat(0.0); U];
        for (u, t) in ts.iter_mut().enumerate() {
            *t = self.params.vector(l, self.offset + u * L::LANES);
        }
        ts
    }

    /// Where the `U` vectors lie with respect to 1/2 ([`Params::side`]).
    #[inline(always)]
    fn side<L: Lanes, const U: usize>(self) -> Side {
        self.params.side::<L>(self.offset, U * L::LANES)
    }
}

/// The control range of every channel, broadcast: `[min_i c_{c,i}, max_i c_{c,i}]`.
struct Range<L: Lanes, const CH: usize> {
    lo: [L::V; CH],
    hi: [L::V; CH],
}

impl<L: Lanes, const CH: usize> Range<L, CH> {
    #[inline(always)]
    fn new(l: L, coeffs: &Coeffs) -> Self {
        // Loops, not `array::from_fn` closures: a closure is compiled without the
        // dispatcher's target features, so the vector operations inside it become calls
        // (measured: most of the time of a spline with thousands of short pieces).
        let mut range = Range {
            lo: [l.splat(0.0); CH],
            hi: [l.splat(0.0); CH],
        };
        for c in 0..CH {
            range.lo[c] = l.splat(coeffs.lo[c]);
            range.hi[c] = l.splat(coeffs.hi[c]);
        }
        range
    }

    /// `v` projected onto channel `c`'s range.
    #[inline(always)]
    fn project(&self, l: L, c: usize, v: L::V) -> L::V {
        l.min(l.max(v, self.lo[c]), self.hi[c])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kernel_binomials_exact() {
        assert_eq!(binomial_row(4), [1.0, 4.0, 6.0, 4.0, 1.0]);
        let row = binomial_row(64);
        assert_eq!(row[32], 1_832_624_140_942_590_534u64 as f64);
        assert_eq!(binomial_row(0), [1.0]);
        // Above row 67 in `f64`: within `(n - 66) u` of the exact value (Python's
        // `float(math.comb(n, k))`, the nearest `f64`).
        let u = f64::EPSILON / 2.0;
        for (n, k, exact) in [
            (68, 34, 2.845_304_147_524_057_5e19),
            (100, 50, 1.008913445455642e29),
            (1000, 3, 166167000.0),
            (1000, 500, 2.7028824094543655e299),
        ] {
            let row = binomial_row(n);
            assert_eq!(row.len(), n + 1);
            assert_eq!((row[0], row[n], row[1]), (1.0, 1.0, n as f64));
            let error = (row[k] - exact).abs() / exact;
            assert!(error <= (n - 66) as f64 * u, "C({n}, {k}): {error:e}");
            assert_eq!(row[k], row[n - k]);
        }
    }
}
