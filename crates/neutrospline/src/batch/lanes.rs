//! Vectors of `f64` lanes for the batch kernels, and the runtime choice of instruction set.
//!
//! The kernels are written once, generic over [`Lanes`]: a vector type and the dozen
//! operations they need. Two implementations exist:
//! - [`Portable`]: four lanes as a plain `[f64; 4]`, element-wise loops that the compiler
//!   turns into SSE2 (or NEON) instructions on any target; no `unsafe`, no dependency;
//! - with the `simd` feature, [`Pulp`]: the vector types of the `pulp` crate, whose
//!   `Arch::dispatch` detects the processor once per call and runs the kernel compiled for
//!   AVX2 + FMA (4 lanes) or, with the `avx512` feature, AVX-512 (8 lanes). The target-feature
//!   functions and the CPU detection live inside `pulp`, so this crate keeps
//!   `#![forbid(unsafe_code)]`.
//!
//! Every operation is IEEE-exact per lane except [`Lanes::mul_add`], which is fused on FMA
//! hardware (one rounding) and a multiply then an add elsewhere (two roundings); the accuracy
//! analysis of the kernels allows either.

use super::kernel::{self, Coeffs, Params};

/// A vector of [`Lanes::LANES`] doubles and the operations the kernels use.
///
/// Every method is `#[inline(always)]` in both implementations so that a kernel inlines into
/// the target-feature function chosen by the dispatcher.
pub(crate) trait Lanes: Copy {
    /// The vector.
    type V: Copy;
    /// Number of `f64` lanes in [`Lanes::V`].
    const LANES: usize;
    fn splat(self, x: f64) -> Self::V;
    fn add(self, a: Self::V, b: Self::V) -> Self::V;
    fn sub(self, a: Self::V, b: Self::V) -> Self::V;
    fn mul(self, a: Self::V, b: Self::V) -> Self::V;
    fn div(self, a: Self::V, b: Self::V) -> Self::V;
    /// `a * b + c`, fused where the instruction set has FMA.
    fn mul_add(self, a: Self::V, b: Self::V, c: Self::V) -> Self::V;
    /// Lane-wise minimum (inputs are never NaN in the kernels).
    fn min(self, a: Self::V, b: Self::V) -> Self::V;
    /// Lane-wise maximum (inputs are never NaN in the kernels).
    fn max(self, a: Self::V, b: Self::V) -> Self::V;
    /// Per lane: `if_le` where `t <= bound`, `otherwise` elsewhere.
    fn select_le(self, t: Self::V, bound: Self::V, if_le: Self::V, otherwise: Self::V) -> Self::V;
    /// The lanes `0, 1, ..., LANES - 1`.
    fn iota(self) -> Self::V;
    /// Loads `src[..LANES]`.
    fn load(self, src: &[f64]) -> Self::V;
    /// Loads `src` (shorter than `LANES`) into the first lanes, the others zero.
    fn load_partial(self, src: &[f64]) -> Self::V;
    /// Stores into `dst[..LANES]`.
    fn store(self, dst: &mut [f64], v: Self::V);
    /// Stores the first `dst.len()` (fewer than `LANES`) lanes.
    fn store_partial(self, dst: &mut [f64], v: Self::V);
    /// `dst` (a multiple of `LANES` long) as a slice of vectors, without copying.
    fn as_vectors_mut(self, dst: &mut [f64]) -> &mut [Self::V];
    /// Runs [`kernel::fixed`] where this lane type has the kernels compiled per degree (by
    /// default it has); `false` when it has not or they do not serve the degree.
    #[inline(always)]
    fn fixed<P: Params, const CH: usize>(
        self,
        coeffs: &Coeffs,
        params: &P,
        out: &mut [&mut [f64]; CH],
    ) -> bool {
        kernel::fixed(self, coeffs, params, out)
    }
}

/// Four lanes as an array; the portable path, vectorised by the compiler for the baseline
/// instruction set of the target.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Portable;

const P: usize = 4;

/// The lane-wise binary operations of a [`Lanes`] implementation, one
/// `#[inline(always)] fn name(self, a: Self::V, b: Self::V) -> Self::V` per entry: for
/// [`Portable`] the expression `e(x, y)` applied to each pair of lanes, for [`Pulp`] the
/// `pulp::Simd` method of that name.
macro_rules! binary {
    (portable: $($name:ident => |$x:ident, $y:ident| $e:expr;)*) => {$(
        #[inline(always)]
        fn $name(self, a: Self::V, b: Self::V) -> Self::V {
            let mut r = [0.0; P];
            for i in 0..P {
                let ($x, $y) = (a[i], b[i]);
                r[i] = $e;
            }
            r
        }
    )*};
    (pulp: $($name:ident => $method:ident;)*) => {$(
        #[inline(always)]
        fn $name(self, a: Self::V, b: Self::V) -> Self::V {
            self.0.$method(a, b)
        }
    )*};
}

impl Lanes for Portable {
    type V = [f64; P];
    const LANES: usize = P;
    #[inline(always)]
    fn splat(self, x: f64) -> Self::V {
        [x; P]
    }
    binary! { portable:
        add => |x, y| x + y;
        sub => |x, y| x - y;
        mul => |x, y| x * y;
        div => |x, y| x / y;
        min => |x, y| if x < y { x } else { y };
        max => |x, y| if x > y { x } else { y };
    }
    #[inline(always)]
    fn mul_add(self, a: Self::V, b: Self::V, c: Self::V) -> Self::V {
        // Not `f64::mul_add`: without FMA hardware that is a slow library call.
        self.add(self.mul(a, b), c)
    }
    #[inline(always)]
    fn select_le(self, t: Self::V, bound: Self::V, if_le: Self::V, otherwise: Self::V) -> Self::V {
        let mut r = otherwise;
        for i in 0..P {
            if t[i] <= bound[i] {
                r[i] = if_le[i];
            }
        }
        r
    }
    #[inline(always)]
    fn iota(self) -> Self::V {
        [0.0, 1.0, 2.0, 3.0]
    }
    #[inline(always)]
    fn load(self, src: &[f64]) -> Self::V {
        let mut v = [0.0; P];
        v.copy_from_slice(&src[..P]);
        v
    }
    #[inline(always)]
    fn load_partial(self, src: &[f64]) -> Self::V {
        let mut v = [0.0; P];
        v[..src.len()].copy_from_slice(src);
        v
    }
    #[inline(always)]
    fn store(self, dst: &mut [f64], v: Self::V) {
        dst[..P].copy_from_slice(&v);
    }
    #[inline(always)]
    fn store_partial(self, dst: &mut [f64], v: Self::V) {
        let len = dst.len();
        dst.copy_from_slice(&v[..len]);
    }
    #[inline(always)]
    fn as_vectors_mut(self, dst: &mut [f64]) -> &mut [Self::V] {
        dst.as_chunks_mut::<P>().0
    }
    /// On x86-64 with the `simd` feature this path only serves processors without AVX2 (before
    /// 2013), and goes without the per-degree kernels (Bernstein weights in a scratch buffer
    /// instead, about half the speed from degree 4 to 15); elsewhere it is the main path and
    /// has them (the trait's default).
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    #[inline(always)]
    fn fixed<Q: Params, const CH: usize>(
        self,
        _: &Coeffs,
        _: &Q,
        _: &mut [&mut [f64]; CH],
    ) -> bool {
        false
    }
}

/// The vectors of a `pulp` instruction set (AVX2 + FMA, AVX-512, or pulp's scalar fallback).
#[cfg(feature = "simd")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pulp<S>(pub(crate) S);

#[cfg(feature = "simd")]
impl<S: pulp::Simd> Lanes for Pulp<S> {
    type V = S::f64s;
    const LANES: usize = S::F64_LANES;
    #[inline(always)]
    fn splat(self, x: f64) -> Self::V {
        self.0.splat_f64s(x)
    }
    binary! { pulp:
        add => add_f64s;
        sub => sub_f64s;
        mul => mul_f64s;
        div => div_f64s;
        min => min_f64s;
        max => max_f64s;
    }
    #[inline(always)]
    fn mul_add(self, a: Self::V, b: Self::V, c: Self::V) -> Self::V {
        // The `_e` form: fused when the instruction set has FMA, else multiply then add.
        self.0.mul_add_e_f64s(a, b, c)
    }
    #[inline(always)]
    fn select_le(self, t: Self::V, bound: Self::V, if_le: Self::V, otherwise: Self::V) -> Self::V {
        let mask = self.0.less_than_or_equal_f64s(t, bound);
        self.0.select_f64s(mask, if_le, otherwise)
    }
    #[inline(always)]
    fn iota(self) -> Self::V {
        const IOTA: [f64; 16] = [
            0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0,
        ];
        self.load(&IOTA)
    }
    #[inline(always)]
    fn load(self, src: &[f64]) -> Self::V {
        S::as_simd_f64s(&src[..S::F64_LANES]).0[0]
    }
    #[inline(always)]
    fn load_partial(self, src: &[f64]) -> Self::V {
        self.0.partial_load_f64s(src)
    }
    #[inline(always)]
    fn store(self, dst: &mut [f64], v: Self::V) {
        S::as_mut_simd_f64s(&mut dst[..S::F64_LANES]).0[0] = v;
    }
    #[inline(always)]
    fn store_partial(self, dst: &mut [f64], v: Self::V) {
        self.0.partial_store_f64s(dst, v);
    }
    #[inline(always)]
    fn as_vectors_mut(self, dst: &mut [f64]) -> &mut [Self::V] {
        S::as_mut_simd_f64s(dst).0
    }
}

/// A computation generic over the lane type, run with the best one for this processor.
pub(crate) trait LaneJob {
    type Output;
    fn run<L: Lanes>(self, lanes: L) -> Self::Output;
}

/// Which lane implementation [`dispatch`] picks on this processor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(not(feature = "simd"), allow(dead_code))]
pub(crate) enum Isa {
    Portable,
    Avx2Fma,
    Avx512,
    /// pulp's one-lane fallback (not used for f64 work: [`Portable`] is wider).
    Other,
}

/// The instruction set [`dispatch`] uses on this processor.
pub(crate) fn isa() -> Isa {
    #[cfg(feature = "simd")]
    {
        isa_of(pulp::Arch::new())
    }
    #[cfg(not(feature = "simd"))]
    {
        Isa::Portable
    }
}

#[cfg(feature = "simd")]
fn isa_of(arch: pulp::Arch) -> Isa {
    struct Probe;
    impl pulp::WithSimd for Probe {
        type Output = Isa;
        #[inline(always)]
        fn with_simd<S: pulp::Simd>(self, _simd: S) -> Isa {
            match (S::IS_SCALAR, S::F64_LANES) {
                (true, _) => Isa::Portable,
                (false, 4) => Isa::Avx2Fma,
                (false, 8) => Isa::Avx512,
                _ => Isa::Other,
            }
        }
    }
    arch.dispatch(Probe)
}

/// Runs `job` with the widest lanes this processor supports (see the module docs).
#[inline]
pub(crate) fn dispatch<J: LaneJob>(job: J) -> J::Output {
    #[cfg(feature = "simd")]
    {
        struct Adapter<J>(J);
        impl<J: LaneJob> pulp::WithSimd for Adapter<J> {
            type Output = J::Output;
            #[inline(always)]
            fn with_simd<S: pulp::Simd>(self, simd: S) -> J::Output {
                if S::IS_SCALAR || S::F64_LANES < 2 {
                    // pulp's scalar fallback has one lane; the portable arrays are wider.
                    self.0.run(Portable)
                } else {
                    self.0.run(Pulp(simd))
                }
            }
        }
        pulp::Arch::new().dispatch(Adapter(job))
    }
    #[cfg(not(feature = "simd"))]
    {
        job.run(Portable)
    }
}

/// Runs `job` on the portable lanes whatever the processor (tests compare the two paths).
#[cfg(test)]
pub(crate) fn dispatch_portable<J: LaneJob>(job: J) -> J::Output {
    job.run(Portable)
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Ops;
    impl LaneJob for Ops {
        type Output = Vec<f64>;
        fn run<L: Lanes>(self, l: L) -> Vec<f64> {
            let a = l.iota();
            let b = l.splat(2.0);
            let mut out = vec![0.0; 9 * L::LANES];
            let results = [
                l.add(a, b),
                l.sub(a, b),
                l.mul(a, b),
                l.div(a, b),
                l.mul_add(a, b, b),
                l.min(a, b),
                l.max(a, b),
                l.load(&[5.0; 16]),
                l.select_le(a, b, a, l.splat(-1.0)),
            ];
            for (chunk, v) in out.chunks_exact_mut(L::LANES).zip(results) {
                l.store(chunk, v);
            }
            let mut part = [9.0; 3];
            l.store_partial(&mut part[..1.min(L::LANES - 1)], l.load_partial(&[7.0]));
            out.push(part[0]);
            out
        }
    }

    #[test]
    fn lanes_operations_agree_between_paths() {
        let fast = dispatch(Ops);
        let portable = dispatch_portable(Ops);
        let lanes = (fast.len() - 1) / 9;
        // Compare lane by lane, the first four lanes of each result.
        for r in 0..9 {
            for i in 0..4.min(lanes) {
                assert_eq!(fast[r * lanes + i], portable[r * 4 + i], "op {r} lane {i}");
            }
        }
        assert_eq!(portable[..4], [2.0, 3.0, 4.0, 5.0]);
        assert_eq!(portable[4 * 5..4 * 6], [0.0, 1.0, 2.0, 2.0]);
        assert_eq!(portable[4 * 6..4 * 7], [2.0, 2.0, 2.0, 3.0]);
        assert_eq!(portable[4 * 8..4 * 9], [0.0, 1.0, 2.0, -1.0]);
        assert_eq!(*portable.last().unwrap(), 7.0);
        assert_eq!(*fast.last().unwrap(), 7.0);
    }

    #[test]
    fn lanes_isa_is_reported() {
        let isa = isa();
        assert_ne!(isa, Isa::Other);
        #[cfg(all(feature = "simd", target_arch = "x86_64"))]
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            assert_ne!(isa, Isa::Portable);
        }
    }
}
