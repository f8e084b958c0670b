//! The Bernstein-weight kernels (degrees 4 to 1000: compiled per degree up to 15, weights in a
//! scratch buffer above) and lane-parallel de Casteljau (above 1000).

use super::{drive, Coeffs, Kernel, Lanes, Params, Range, Sink, Step};

/// The Bernstein-weight kernel for degree `W - 1`, the binomial coefficients folded into the
/// control values (`coeffs.scaled`).
// Inlined into the dispatcher's target-feature function in optimised builds; a function of
// its own in unoptimised ones, whose frames are not merged: inlining every kernel there made
// one frame large enough to overflow a test thread's stack.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn run<L: Lanes, P: Params, const CH: usize, const W: usize>(
    l: L,
    coeffs: &Coeffs,
    params: &P,
    out: &mut [&mut [f64]; CH],
) {
    let mut prepared = Prepared::<L, CH, W>::new(l, coeffs);
    // Up to degree 7 one vector of parameters per step: the out-of-order core overlaps
    // consecutive steps. Above, the dot products are long chains of multiply-adds, and two
    // vectors per step (two independent chains per channel, sharing each coefficient load)
    // measured 1.5x faster at degree 15; at low degree the extra registers only spill.
    if W <= 8 {
        drive::<L, P, _, CH, 1>(l, &mut prepared, params, out);
    } else {
        drive::<L, P, _, CH, 2>(l, &mut prepared, params, out);
    }
}

/// The broadcast coefficients of a Bernstein-weight kernel, built once per run: kept in
/// locals, they are not reloaded after every store to the output (which the compiler cannot
/// prove does not alias them).
struct Prepared<L: Lanes, const CH: usize, const W: usize> {
    /// `C(n, i) c_{c,i}`, channel-major, `W = n + 1` per channel. On the heap: arrays of `CH * W` vectors overflowed
    /// test threads' stacks in unoptimised builds (when `W` went up to 65).
    values: Vec<L::V>,
    range: Range<L, CH>,
}

impl<L: Lanes, const CH: usize, const W: usize> Prepared<L, CH, W> {
    #[inline(always)]
    fn new(l: L, coeffs: &Coeffs) -> Self {
        debug_assert_eq!((coeffs.degree + 1, coeffs.scaled.len()), (W, CH * W));
        Prepared {
            values: {
                // (A loop, not a closure: see `Range::new`.)
                let mut values = Vec::with_capacity(coeffs.scaled.len());
                for &v in &coeffs.scaled {
                    values.push(l.splat(v));
                }
                values
            },
            range: Range::new(l, coeffs),
        }
    }
}

impl<L: Lanes, const CH: usize, const W: usize> Kernel<L, CH> for Prepared<L, CH, W> {
    /// Per parameter the products `t^i s^(n-i)`, a dot product per channel with the scaled
    /// control values `C(n, i) c_{c,i}`,
    /// then the projection onto the channel's control range (which contains the exact value:
    /// convex combination).
    #[inline(always)]
    fn step<P: Params, S: Sink<L>, const U: usize>(&mut self, l: L, at: Step<P>, sink: &mut S) {
        let p = self;
        let (n, count) = (W - 1, W);
        let one = l.splat(1.0);
        let zero = l.splat(0.0);
        let ts = at.vectors::<L, U>(l);
        // t^i and s^j for i, j = 0 ..= n, per parameter vector, computed before the
        // dot products so that their only loop-carried dependencies are the accumulators.
        let mut tp = [[one; W]; U];
        let mut sp = [[one; W]; U];
        for u in 0..U {
            let s = l.sub(one, ts[u]);
            let (mut power_t, mut power_s) = (one, one);
            for j in 0..count {
                tp[u][j] = power_t;
                sp[u][j] = power_s;
                power_t = l.mul(power_t, ts[u]);
                power_s = l.mul(power_s, s);
            }
        }
        // (Two partial sums per channel, to halve the chain of dependent multiply-adds,
        // measured no faster at degree 3 and 15 and 10% slower at degree 7.)
        let mut acc = [[zero; CH]; U];
        for i in 0..count {
            let mut w = [zero; U];
            for u in 0..U {
                w[u] = l.mul(tp[u][i], sp[u][n - i]);
            }
            for c in 0..CH {
                for u in 0..U {
                    acc[u][c] = if i == 0 {
                        l.mul(w[u], p.values[c * count + i])
                    } else {
                        l.mul_add(w[u], p.values[c * count + i], acc[u][c])
                    };
                }
            }
        }
        for c in 0..CH {
            for u in 0..U {
                sink.put(l, c, u, p.range.project(l, c, acc[u][c]));
            }
        }
    }
}

/// The Bernstein-weight kernel above [`FIXED_MAX_DEGREE`] (and wherever the binomials cannot
/// be folded into the control values): the weights `w_i = (C(n, i) t^i) s^(n-i)` in `scratch`,
/// one vector of parameters at a time, then the channels' dot products side by side, `CH`
/// independent chains of multiply-adds. (It replaced a [`Prepared`]-style kernel with
/// 65-vector arrays for degrees 16 to 64: 1.2x to 2.1x faster there.)
pub(super) struct LongWeights<'a, L: Lanes, const CH: usize> {
    coeffs: &'a Coeffs,
    range: Range<L, CH>,
    /// The weights, then the powers of `s`: `n + 1` vectors each.
    scratch: &'a mut Vec<L::V>,
}

impl<'a, L: Lanes, const CH: usize> LongWeights<'a, L, CH> {
    #[inline(always)]
    pub(super) fn new(l: L, coeffs: &'a Coeffs, scratch: &'a mut Vec<L::V>) -> Self {
        scratch.clear();
        scratch.resize(2 * (coeffs.degree + 1), l.splat(1.0));
        LongWeights {
            coeffs,
            range: Range::new(l, coeffs),
            scratch,
        }
    }
}

impl<L: Lanes, const CH: usize> Kernel<L, CH> for LongWeights<'_, L, CH> {
    #[inline(always)]
    fn step<P: Params, S: Sink<L>, const U: usize>(&mut self, l: L, at: Step<P>, sink: &mut S) {
        let coeffs = self.coeffs;
        let count = coeffs.degree + 1;
        let one = l.splat(1.0);
        let (weights, powers_s) = self.scratch.split_at_mut(count);
        // The control values, or (up to degree FIXED_MAX_DEGREE) the control values times the
        // binomial coefficients, which then count as 1.
        let folded = !coeffs.scaled.is_empty();
        let values = if folded {
            &coeffs.scaled
        } else {
            &coeffs.values
        };
        for (u, t) in at.vectors::<L, U>(l).into_iter().enumerate() {
            let s = l.sub(one, t);
            // C(n, i) t^i and s^j, then w_i = (C(n, i) t^i) s^(n-i).
            let (mut power_t, mut power_s) = (one, one);
            for (i, (w, p)) in weights.iter_mut().zip(powers_s.iter_mut()).enumerate() {
                let binomial = if folded { 1.0 } else { coeffs.binomials[i] };
                *w = l.mul(l.splat(binomial), power_t);
                *p = power_s;
                power_t = l.mul(power_t, t);
                power_s = l.mul(power_s, s);
            }
            for (w, &p) in weights.iter_mut().zip(powers_s.iter().rev()) {
                *w = l.mul(*w, p);
            }
            let mut acc = [one; CH];
            for (c, a) in acc.iter_mut().enumerate() {
                *a = l.mul(weights[0], l.splat(values[c * count]));
            }
            for (i, &w) in weights.iter().enumerate().skip(1) {
                for (c, a) in acc.iter_mut().enumerate() {
                    *a = l.mul_add(w, l.splat(values[c * count + i]), *a);
                }
            }
            for (c, a) in acc.into_iter().enumerate() {
                sink.put(l, c, u, self.range.project(l, c, a));
            }
        }
    }
}

/// Lane-parallel de Casteljau, channel by channel, in the operation order of
/// [`crate::bernstein::lerp`]: `s a + t b` projected onto `[min(a, b), max(a, b)]`.
pub(super) struct Casteljau<'a, L: Lanes> {
    coeffs: &'a Coeffs,
    /// One level of the recurrence: `n + 1` vectors.
    scratch: &'a mut Vec<L::V>,
}

impl<'a, L: Lanes> Casteljau<'a, L> {
    #[inline(always)]
    pub(super) fn new(l: L, coeffs: &'a Coeffs, scratch: &'a mut Vec<L::V>) -> Self {
        scratch.clear();
        scratch.resize(coeffs.degree + 1, l.splat(0.0));
        Casteljau { coeffs, scratch }
    }
}

impl<L: Lanes, const CH: usize> Kernel<L, CH> for Casteljau<'_, L> {
    #[inline(always)]
    fn step<P: Params, S: Sink<L>, const U: usize>(&mut self, l: L, at: Step<P>, sink: &mut S) {
        let n = self.coeffs.degree;
        let count = n + 1;
        let one = l.splat(1.0);
        let scratch = &mut *self.scratch;
        for (u, t) in at.vectors::<L, U>(l).into_iter().enumerate() {
            let s = l.sub(one, t);
            for c in 0..CH {
                let row = &self.coeffs.values[c * count..(c + 1) * count];
                for (slot, &v) in scratch.iter_mut().zip(row) {
                    *slot = l.splat(v);
                }
                for level in 1..=n {
                    for i in 0..=n - level {
                        let (a, b) = (scratch[i], scratch[i + 1]);
                        let v = l.add(l.mul(s, a), l.mul(t, b));
                        scratch[i] = l.min(l.max(v, l.min(a, b)), l.max(a, b));
                    }
                }
                sink.put(l, c, u, scratch[0]);
            }
        }
    }
}
