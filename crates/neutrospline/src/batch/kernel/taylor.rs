//! The Taylor kernel (degrees 1 to 3): Horner's rule about the nearer end of \[0, 1\].

use super::{
    binomial_row, Kernel, Lanes, Params, Range, Side, Sink, Step, TAYLOR_MAX_DEGREE, TAYLOR_STEP,
};
use super::{drive, Coeffs};

/// The Taylor coefficients about `t = 0` of the Bézier polynomial with control values `row`
/// (`c_0, ..., c_n`): `p(t) = sum_k a_k t^k` with `a_k = C(n, k) Δ^k c_0`, the forward
/// differences taken by repeated subtraction. Fed the reversed row, the coefficients about
/// `t = 1` in powers of `s = 1 - t`. `a_0 = c_0` exactly.
pub(super) fn taylor_row(row: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut differences: Vec<f64> = row.collect();
    let n = differences.len() - 1;
    let binomials = binomial_row(n);
    let mut coefficients = Vec::with_capacity(n + 1);
    coefficients.push(differences[0]);
    for k in 1..=n {
        for i in 0..=n - k {
            differences[i] = differences[i + 1] - differences[i];
        }
        coefficients.push(binomials[k] * differences[0]);
    }
    coefficients
}

/// Runs the Taylor kernel for degree `N1 - 1`.
// Inlining: as for `run`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn taylor<L: Lanes, P: Params, const CH: usize, const N1: usize>(
    l: L,
    coeffs: &Coeffs,
    params: &P,
    out: &mut [&mut [f64]; CH],
) {
    const { assert!(N1 - 1 <= TAYLOR_MAX_DEGREE) };
    let mut kernel = Taylor::<L, CH, N1>::new(l, coeffs);
    drive::<L, P, _, CH, TAYLOR_STEP>(l, &mut kernel, params, out);
}

/// The Taylor kernel for degree `N1 - 1` (see the module docs): Horner's rule in `t` about
/// `t = 0` for the lanes with `t <= 1/2`, in `s = 1 - t` about `t = 1` for the others.
struct Taylor<L: Lanes, const CH: usize, const N1: usize> {
    /// Coefficients about `t = 0`, per channel.
    low: [[L::V; N1]; CH],
    /// Coefficients about `t = 1` (in powers of `s`), per channel.
    high: [[L::V; N1]; CH],
    range: Range<L, CH>,
}

impl<L: Lanes, const CH: usize, const N1: usize> Taylor<L, CH, N1> {
    #[inline(always)]
    fn new(l: L, coeffs: &Coeffs) -> Self {
        debug_assert_eq!(coeffs.taylor.len(), 2 * CH * N1);
        // (Loops, not closures: see `Range::new`.)
        let zero = l.splat(0.0);
        let mut taylor = Taylor {
            low: [[zero; N1]; CH],
            high: [[zero; N1]; CH],
            range: Range::new(l, coeffs),
        };
        for c in 0..CH {
            for k in 0..N1 {
                taylor.low[c][k] = l.splat(coeffs.taylor[c * N1 + k]);
                taylor.high[c][k] = l.splat(coeffs.taylor[(CH + c) * N1 + k]);
            }
        }
        taylor
    }
}

/// Channel `c` of `sum_k a[k] x^k` by Horner's rule (a multiply-add per coefficient) at the
/// `U` vectors `x`, interleaved so that each coefficient is loaded once per step: with the
/// coefficients operands in memory, loads are what limits this kernel.
#[inline(always)]
fn horner<L: Lanes, const CH: usize, const N1: usize, const U: usize>(
    l: L,
    a: &[[L::V; N1]; CH],
    c: usize,
    x: &[L::V; U],
) -> [L::V; U] {
    let mut v = [a[c][N1 - 1]; U];
    for k in (0..N1 - 1).rev() {
        for u in 0..U {
            v[u] = l.mul_add(v[u], x[u], a[c][k]);
        }
    }
    v
}

impl<L: Lanes, const CH: usize, const N1: usize> Kernel<L, CH> for Taylor<L, CH, N1> {
    #[inline(always)]
    fn step<P: Params, S: Sink<L>, const U: usize>(&mut self, l: L, at: Step<P>, sink: &mut S) {
        let ts = at.vectors::<L, U>(l);
        // (`1 - t` is exact for `t` in [1/2, 1], Sterbenz.)
        let side = at.side::<L, U>();
        if side != Side::Mixed {
            let (a, x) = if side == Side::Low {
                (&self.low, ts)
            } else {
                (&self.high, complement(l, ts))
            };
            let x = &x;
            for c in 0..CH {
                let v = horner(l, a, c, x);
                for u in 0..U {
                    sink.put(l, c, u, self.range.project(l, c, v[u]));
                }
            }
        } else {
            let half = l.splat(0.5);
            let ss = complement(l, ts);
            for c in 0..CH {
                let below = horner(l, &self.low, c, &ts);
                let above = horner(l, &self.high, c, &ss);
                for u in 0..U {
                    let v = l.select_le(ts[u], half, below[u], above[u]);
                    sink.put(l, c, u, self.range.project(l, c, v));
                }
            }
        }
    }
}

/// `1 - t` per lane. (A function, not a closure, so that it is inlined with the caller's
/// target features: see `Range::new`.)
#[inline(always)]
fn complement<L: Lanes, const U: usize>(l: L, ts: [L::V; U]) -> [L::V; U] {
    let one = l.splat(1.0);
    let mut ss = ts;
    for s in &mut ss {
        *s = l.sub(one, *s);
    }
    ss
}
