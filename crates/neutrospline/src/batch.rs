//! Batch evaluation: many parameters, and many curves, into flat caller-owned buffers.
//!
//! A [`CurveBatch`] is a curve of any kind prepared for batch evaluation: its Bézier pieces
//! (one for a Bézier curve, one per non-empty knot span of a B-spline or NURBS curve) with
//! their control values stored channel by channel. [`CurveBatch::evaluate`] and
//! [`CurveBatch::evaluate_all`] write positions and the three degrees channel-major, one
//! contiguous array per channel, allocating nothing per point. The parameters are
//! [`BatchParams::Uniform`] (evenly spaced over the domain, generated on the fly) or
//! [`BatchParams::Values`]. Each parameter is evaluated on its piece at the local parameter
//! `(t - a) / (b - a)`, rational pieces in homogeneous form followed by one division.
//!
//! This module also holds the tuning constants and the instruction-set query
//! ([`DIRECT_MAX_DEGREE`], [`PARALLEL_THRESHOLD`], [`instruction_set`]), which most users
//! never need; the crate root re-exports the rest.
//!
//! ## Method and accuracy
//! The kernels run several parameters at once, one per SIMD lane. Up to degree 3 they run
//! Horner's rule on the Taylor expansion about the nearer end of \[0, 1\] (in `t` below 1/2,
//! in `1 - t` above, so the variable never exceeds 1/2 and the error stays below
//! `(2n + 1) 2^n 2^-53` times the largest control value). From degree 4 to
//! [`DIRECT_MAX_DEGREE`] (1000) they compute the Bernstein weights
//! `C(n, i) t^i (1 - t)^(n - i)` of each parameter and take one dot product per channel (O(n)
//! per channel instead of de Casteljau's O(n^2)); above (where `C(n, n/2)` nears the end of
//! the `f64` range), they run de Casteljau's algorithm lane-parallel. Accuracy is not traded for speed: the result
//! agrees with [`Evaluate::evaluate`](crate::Evaluate::evaluate) within a few `n * 2^-53` times the channel's largest
//! absolute control value (tested: 1e-14 up to degree 15, 1e-12 up to degree 400, parameters
//! near 0 and 1 included), the end parameters give the end control points exactly, and every
//! channel is projected onto the range of its control values, which provably contains the
//! exact value (the weights are non-negative and sum to 1), so degrees stay inside \[0, 1\].
//! Above degree 1000 the results are bit-identical to the plain de Casteljau recurrence.
//!
//! With [`BatchOptions::with_accuracy`]`(`[`Accuracy::Compensated`]`)` every point is instead
//! evaluated by the compensated de Casteljau or de Boor algorithm of
//! [`Evaluate::evaluate`](crate::Evaluate::evaluate), on the curve itself (not its Bézier
//! pieces), bit for bit the scalar result: about one rounding of the exact value at any
//! degree, at a higher cost (`neutrospline bench --compensated` reports both speeds).
//!
//! ## Instruction sets and threads
//! With the `simd` feature the widest instruction set of the processor is chosen at run time
//! (AVX2 + FMA; AVX-512 with the `avx512` feature), through the safe dispatch of the `pulp`
//! crate; otherwise, and on other processors, a portable four-lane path that the compiler
//! vectorises for the target's baseline. With the `parallel` feature, work above
//! [`BatchOptions::parallel_threshold`] is split between threads (rayon).

mod kernel;
mod lanes;
mod piecewise;

pub use piecewise::CurveBatch;

use core::ops::Range;

/// Highest degree evaluated through Bernstein weights; above it the batch kernels run
/// de Casteljau's algorithm and give results bit-identical to its plain (not compensated)
/// recurrence.
pub const DIRECT_MAX_DEGREE: usize = 1000;

/// Default of [`BatchOptions::parallel_threshold`]: `2^18` units of work, i.e. 65,536
/// parameters of a cubic. Below it, splitting costs more than it saves.
pub const PARALLEL_THRESHOLD: usize = 1 << 18;

/// Parameters evaluated per block: each block is checked, then evaluated for every curve of
/// a task while its parameters are in cache.
const BLOCK: usize = 4096;

/// The parameters of a batch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BatchParams<'a> {
    /// `count` evenly spaced parameters over the curve's domain `[a, b]`: `t_k =`
    /// [`uniform_parameter`]`(k, count, a..b)`, so `t_0 = a` and `t_{count-1} = b` exactly
    /// (on \[0, 1\] exactly `k as f64 / (count - 1) as f64`); a single parameter is `t = a`.
    Uniform(usize),
    /// The given parameters, each finite and in the curve's domain.
    Values(&'a [f64]),
}

impl BatchParams<'_> {
    /// The number of parameters.
    pub fn len(&self) -> usize {
        match self {
            BatchParams::Uniform(count) => *count,
            BatchParams::Values(ts) => ts.len(),
        }
    }

    /// `true` when there is no parameter.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Parameter `k` for a curve with the given domain.
    ///
    /// # Panics
    /// If `k >= len()`.
    pub fn get(&self, k: usize, domain: Range<f64>) -> f64 {
        match *self {
            BatchParams::Uniform(count) => {
                assert!(k < count, "parameter index {k} out of range ({count})");
                uniform_parameter(k, count, domain)
            }
            BatchParams::Values(ts) => ts[k],
        }
    }
}

/// Parameter `k` of `count` evenly spaced over `[a, b]` (the domain `a..b`):
/// `a + (b - a) (k / (count - 1))`, with both ends exact and never outside `[a, b]` (a single
/// parameter is `a`). On \[0, 1\] it is exactly `k as f64 / (count - 1) as f64`. Every front
/// end samples curves with it, and so does [`BatchParams::Uniform`].
///
/// ```
/// use neutrospline::uniform_parameter;
/// assert_eq!(uniform_parameter(0, 5, 2.0..3.0), 2.0);
/// assert_eq!(uniform_parameter(2, 5, 2.0..3.0), 2.5);
/// assert_eq!(uniform_parameter(4, 5, 0.1..0.7), 0.7);
/// assert_eq!(uniform_parameter(3, 10, 0.0..1.0), 3.0 / 9.0);
/// ```
pub fn uniform_parameter(k: usize, count: usize, Range { start: a, end: b }: Range<f64>) -> f64 {
    if k == 0 || count <= 1 {
        a
    } else if k + 1 >= count {
        b
    } else {
        // (max then min rather than clamp: no panic on a reversed interval.)
        (a + (b - a) * (k as f64 / (count - 1) as f64))
            .max(a)
            .min(b)
    }
}

/// How a batch evaluation computes each point: the fast SIMD kernels, or the compensated
/// algorithms of the scalar evaluation.
///
/// ```
/// use neutrospline::{Accuracy, BatchOptions};
/// assert_eq!(BatchOptions::default().accuracy(), Accuracy::Fast);
/// let exact = BatchOptions::default().with_accuracy(Accuracy::Compensated);
/// assert_eq!(exact.accuracy(), Accuracy::Compensated);
/// assert_eq!(Accuracy::from_name("compensated"), Some(Accuracy::Compensated));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Accuracy {
    /// The SIMD kernels (the default): within a few `n u max |c|` of the exact value
    /// (`u = 2^-53`, `n` the degree, `c` a channel's control values); see the module
    /// documentation.
    #[default]
    Fast,
    /// Compensated de Casteljau or de Boor per point, exactly as
    /// [`Evaluate::evaluate`](crate::Evaluate::evaluate) (bit for bit): about one rounding of
    /// the exact value at any degree, a few times slower than the kernels at low degree and
    /// O(n^2) instead of O(n) per point at high degree.
    Compensated,
}

impl Accuracy {
    /// Every setting, in the order of [`Accuracy::NAMES`].
    pub const ALL: [Accuracy; 2] = [Accuracy::Fast, Accuracy::Compensated];
    /// The settings' names (`fast`, `compensated`), as every front end spells them.
    pub const NAMES: [&'static str; 2] = ["fast", "compensated"];

    /// The setting's name.
    pub fn name(self) -> &'static str {
        match self {
            Accuracy::Fast => Self::NAMES[0],
            Accuracy::Compensated => Self::NAMES[1],
        }
    }

    /// The setting with this name, if any.
    pub fn from_name(name: &str) -> Option<Accuracy> {
        Self::ALL.into_iter().find(|a| a.name() == name)
    }
}

/// Threads, threshold and accuracy of a batch evaluation.
///
/// ```
/// use neutrospline::BatchOptions;
/// let one_thread = BatchOptions::default().with_threads(1);
/// assert_eq!(one_thread.threads(), 1);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BatchOptions {
    threads: usize,
    parallel_threshold: usize,
    accuracy: Accuracy,
}

impl Default for BatchOptions {
    /// All threads of the current rayon pool, above [`PARALLEL_THRESHOLD`], the fast kernels.
    fn default() -> Self {
        BatchOptions {
            threads: 0,
            parallel_threshold: PARALLEL_THRESHOLD,
            accuracy: Accuracy::Fast,
        }
    }
}

impl BatchOptions {
    /// The same as [`BatchOptions::default`].
    pub fn new() -> Self {
        Self::default()
    }

    /// At most `threads` threads; 0 means as many as the current rayon pool has. Without the
    /// `parallel` feature evaluation always uses the calling thread only. More threads than
    /// the pool has are served by a pool built for the call.
    pub fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self
    }

    /// Split between threads only when `points * (degree + 1)` (summed over the curves) is at
    /// least `work`.
    pub fn with_parallel_threshold(mut self, work: usize) -> Self {
        self.parallel_threshold = work;
        self
    }

    /// Evaluates with the fast kernels ([`Accuracy::Fast`], the default) or compensated
    /// ([`Accuracy::Compensated`]).
    pub fn with_accuracy(mut self, accuracy: Accuracy) -> Self {
        self.accuracy = accuracy;
        self
    }

    /// The accuracy setting.
    pub fn accuracy(&self) -> Accuracy {
        self.accuracy
    }

    /// The requested thread count (0: the current pool's).
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// The work threshold for splitting between threads.
    pub fn parallel_threshold(&self) -> usize {
        self.parallel_threshold
    }

    /// The number of threads a large batch uses: 1 without the `parallel` feature.
    pub fn effective_threads(&self) -> usize {
        #[cfg(feature = "parallel")]
        {
            if self.threads == 0 {
                rayon::current_num_threads()
            } else {
                self.threads
            }
        }
        #[cfg(not(feature = "parallel"))]
        {
            1
        }
    }
}

/// The instruction set the batch kernels use on this processor: `"avx512"`, `"avx2+fma"` or
/// `"portable"` (see the module documentation and the `simd` / `avx512` features).
pub fn instruction_set() -> &'static str {
    match lanes::isa() {
        lanes::Isa::Avx512 => "avx512",
        lanes::Isa::Avx2Fma => "avx2+fma",
        lanes::Isa::Portable | lanes::Isa::Other => "portable",
    }
}

/// One thread's share: a run of parameters `[start, end)` for some curves (`T`: a reference
/// to a prepared curve), each with its `CH` output channels.
struct Task<'a, T, const CH: usize> {
    start: usize,
    end: usize,
    items: Vec<(T, [&'a mut [f64]; CH])>,
}

/// Checks that `out` holds `channels` values per curve and parameter and chooses the number of
/// threads: several when the work, `count * (degree + 1)` summed over the curves (of the
/// given `degrees`), reaches [`BatchOptions::parallel_threshold`]. `None` when there is
/// nothing to evaluate.
///
/// # Panics
/// If `out_len` is not `curves * channels * count`.
fn plan(
    out_len: usize,
    channels: usize,
    count: usize,
    degrees: impl ExactSizeIterator<Item = usize>,
    options: &BatchOptions,
) -> Option<usize> {
    let curves = degrees.len();
    assert_eq!(
        out_len,
        curves * channels * count,
        "batch evaluation: out must hold curves * (D + 3) * params.len() values"
    );
    if count == 0 || curves == 0 {
        return None;
    }
    let work: usize = degrees.map(|n| count.saturating_mul(n + 1)).sum();
    Some(if work >= options.parallel_threshold {
        options.effective_threads().max(1)
    } else {
        1
    })
}

/// Splits the work in `threads` tasks: by curves when there are at least as many curves as
/// threads, else by runs of parameters (multiples of 8 long, so runs start on whole vectors).
fn partition<'a, T: Copy, const CH: usize>(
    curves: &[T],
    count: usize,
    out: &'a mut [f64],
    threads: usize,
) -> Vec<Task<'a, T, CH>> {
    let mut channels = out.chunks_exact_mut(count);
    let mut curve_outputs: Vec<(T, [&'a mut [f64]; CH])> = curves
        .iter()
        .map(|&c| {
            let outs: [&'a mut [f64]; CH] =
                core::array::from_fn(|_| channels.next().expect("out has a block per curve"));
            (c, outs)
        })
        .collect();
    if threads <= 1 {
        return vec![Task {
            start: 0,
            end: count,
            items: curve_outputs,
        }];
    }
    if curves.len() >= threads {
        // Contiguous groups of curves, as many curves in each.
        let per = curves.len().div_ceil(threads);
        let mut items = curve_outputs.into_iter().peekable();
        let mut tasks = Vec::with_capacity(threads);
        while items.peek().is_some() {
            tasks.push(Task {
                start: 0,
                end: count,
                items: items.by_ref().take(per).collect(),
            });
        }
        return tasks;
    }
    let run = count.div_ceil(threads).next_multiple_of(8);
    let mut tasks = Vec::with_capacity(threads);
    let mut start = 0;
    while start < count {
        let end = (start + run).min(count);
        let items = curve_outputs
            .iter_mut()
            .map(|(c, outs)| {
                let piece: [&'a mut [f64]; CH] = core::array::from_fn(|ch| {
                    let whole = core::mem::take(&mut outs[ch]);
                    let (head, tail) = whole.split_at_mut(end - start);
                    outs[ch] = tail;
                    head
                });
                (*c, piece)
            })
            .collect();
        tasks.push(Task { start, end, items });
        start = end;
    }
    tasks
}

/// Runs the tasks, each on its own thread when there are several; returns the smallest
/// failure (for the evaluators: the index of an invalid parameter), if any.
fn run_tasks<'a, T: Send, R: Ord + Send, const CH: usize>(
    tasks: Vec<Task<'a, T, CH>>,
    threads: usize,
    run: impl Fn(Task<'a, T, CH>) -> Option<R> + Sync + Send,
) -> Option<R> {
    #[cfg(feature = "parallel")]
    if tasks.len() > 1 {
        use rayon::prelude::*;
        let go = || tasks.into_par_iter().with_max_len(1).filter_map(&run).min();
        if threads > rayon::current_num_threads() {
            if let Ok(pool) = rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
                return pool.install(go);
            }
        }
        return go();
    }
    let _ = threads;
    tasks.into_iter().filter_map(run).min()
}

/// Index of the first parameter not in `[start, end]` (NaN included).
#[inline(always)]
fn first_outside(ts: &[f64], Range { start, end }: &Range<f64>) -> Option<usize> {
    let (start, end) = (*start, *end);
    // Branch-free test first (vectorised); the search only when something is wrong.
    let inside = |t: &f64| start <= *t && *t <= end;
    let all_valid = ts.iter().fold(true, |ok, t| ok & inside(t));
    if all_valid {
        None
    } else {
        ts.iter().position(|t| !inside(t))
    }
}

#[cfg(test)]
mod tests {
    use super::kernel::Values;
    use super::lanes::{LaneJob, Lanes};
    use super::*;
    use crate::bezier::Bezier;
    use crate::curve::Evaluate;
    use crate::example::example1;
    use crate::layout::stride;
    use crate::point::ControlPoint;
    use crate::Degrees;

    /// Channel-major values from the plain (not compensated) de Casteljau recurrence, which
    /// the kernels reproduce bit for bit above degree 1000.
    fn reference<const D: usize>(curve: &Bezier<D>, ts: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; stride(D) * ts.len()];
        let mut row = [0.0; 6];
        for (k, &t) in ts.iter().enumerate() {
            curve.packed().evaluate(t, &mut row);
            for (c, v) in row[..stride(D)].iter().enumerate() {
                out[c * ts.len() + k] = *v;
            }
        }
        out
    }

    fn curve_of_degree(n: usize) -> Bezier<2> {
        let pts = (0..=n)
            .map(|i| {
                let x = i as f64;
                let d = Degrees::new((x * 0.37).fract(), (x * 0.71).fract(), (x * 0.13).fract())
                    .unwrap();
                ControlPoint::new([(x * 1.3).sin() * 10.0, (x * 0.7).cos() * 3.0 - 1.0], d)
            })
            .collect();
        Bezier::new(pts).unwrap()
    }

    #[test]
    fn batch_uniform_matches_scalar_example1() {
        let curve = example1();
        let count = 1001;
        let ts: Vec<f64> = (0..count).map(|k| k as f64 / (count - 1) as f64).collect();
        let mut out = vec![0.0; 5 * count];
        CurveBatch::from(&curve)
            .evaluate(
                BatchParams::Uniform(count),
                &mut out,
                &BatchOptions::default(),
            )
            .unwrap();
        let expected = reference(&curve, &ts);
        for (a, b) in out.iter().zip(&expected) {
            assert!((a - b).abs() <= 1e-14 * 9.0, "{a} vs {b}");
        }
        // End points exactly.
        assert_eq!(out[0], 1.0);
        assert_eq!(out[count - 1], 9.0);
        assert_eq!(out[4 * count - 1], 0.4);
    }

    #[test]
    fn batch_every_kernel_matches_scalar() {
        // Degrees through the Taylor and fixed kernels, the scratch-buffer weight kernel and
        // de Casteljau; odd counts exercise the partial last vector.
        for n in [0, 1, 2, 3, 5, 7, 15, 16, 40, 64, 65, 90, 1000, 1001] {
            let curve = curve_of_degree(n);
            let batch = CurveBatch::from(&curve);
            let counts: &[usize] = if n > 100 { &[3, 9] } else { &[1, 3, 9, 37] };
            for &count in counts {
                let ts: Vec<f64> = (0..count)
                    .map(|k| ((k * 7919) % 101) as f64 / 100.0)
                    .collect();
                let mut out = vec![0.0; 5 * count];
                batch
                    .evaluate(BatchParams::Values(&ts), &mut out, &BatchOptions::default())
                    .unwrap();
                let expected = reference(&curve, &ts);
                for (a, b) in out.iter().zip(&expected) {
                    if n > DIRECT_MAX_DEGREE {
                        assert_eq!(a, b, "degree {n}");
                    } else {
                        // 1e-13, and 1e-12 times the largest control value (10) up high.
                        let tolerance = if n > 100 { 1e-11 } else { 1e-13 };
                        assert!((a - b).abs() <= tolerance, "degree {n}: {a} vs {b}");
                    }
                }
            }
        }
    }

    #[test]
    fn batch_portable_path_agrees() {
        struct Both<'a>(&'a kernel::Coeffs, &'a [f64]);
        impl LaneJob for Both<'_> {
            type Output = Vec<f64>;
            fn run<L: Lanes>(self, l: L) -> Vec<f64> {
                let count = self.1.len();
                let mut out = vec![0.0; 5 * count];
                let mut chunks = out.chunks_exact_mut(count);
                let mut block: [&mut [f64]; 5] = core::array::from_fn(|_| chunks.next().unwrap());
                kernel::evaluate(l, self.0, &Values(self.1), &mut block, &mut Vec::new());
                out
            }
        }
        for n in [3, 7, 15, 30, 70] {
            let batch = CurveBatch::from(&curve_of_degree(n));
            let ts: Vec<f64> = (0..29).map(|k| k as f64 / 28.0).collect();
            let coeffs = batch.piece_coeffs(0);
            let fast = lanes::dispatch(Both(coeffs, &ts));
            let portable = lanes::dispatch_portable(Both(coeffs, &ts));
            for (a, b) in fast.iter().zip(&portable) {
                assert!((a - b).abs() <= 1e-13, "degree {n}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn batch_rejects_bad_parameters_with_lowest_index() {
        let batch = CurveBatch::from(&example1());
        let mut ts = vec![0.5; 10_000];
        ts[9000] = f64::NAN;
        ts[7000] = 1.5;
        let mut out = vec![0.0; 5 * ts.len()];
        for threads in [1, 2, 3] {
            let options = BatchOptions::default()
                .with_threads(threads)
                .with_parallel_threshold(0);
            let err = batch
                .evaluate(BatchParams::Values(&ts), &mut out, &options)
                .unwrap_err();
            assert_eq!(
                err.to_string(),
                "parameter t = 1.5 is outside the domain [0, 1]"
            );
        }
        let err = batch
            .evaluate(
                BatchParams::Values(&[f64::NAN]),
                &mut [0.0; 5],
                &BatchOptions::default(),
            )
            .unwrap_err();
        assert_eq!(err.to_string(), "parameter t = NaN is not a finite number");
    }

    #[test]
    fn batch_threads_and_curves_partition() {
        let curves: Vec<CurveBatch<2>> = (0..7)
            .map(|n| CurveBatch::from(&curve_of_degree(n)))
            .collect();
        let count = 1000;
        let mut one = vec![0.0; curves.len() * 5 * count];
        CurveBatch::evaluate_all(
            &curves,
            BatchParams::Uniform(count),
            &mut one,
            &BatchOptions::default().with_threads(1),
        )
        .unwrap();
        for threads in [2, 3, 4, 16] {
            for subset in [1, 2, 7] {
                let mut many = vec![0.0; subset * 5 * count];
                CurveBatch::evaluate_all(
                    &curves[..subset],
                    BatchParams::Uniform(count),
                    &mut many,
                    &BatchOptions::default()
                        .with_threads(threads)
                        .with_parallel_threshold(0),
                )
                .unwrap();
                assert_eq!(
                    many[..],
                    one[..subset * 5 * count],
                    "{threads} threads, {subset} curves"
                );
            }
        }
    }

    #[test]
    fn batch_uniform_edge_counts() {
        let batch = CurveBatch::from(&example1());
        let mut none: [f64; 0] = [];
        batch
            .evaluate(BatchParams::Uniform(0), &mut none, &BatchOptions::default())
            .unwrap();
        let mut single = [0.0; 5];
        batch
            .evaluate(
                BatchParams::Uniform(1),
                &mut single,
                &BatchOptions::default(),
            )
            .unwrap();
        assert_eq!(single, [1.0, 3.0, 0.3, 0.6, 0.1]);
        assert_eq!(BatchParams::Uniform(1).get(0, 0.0..1.0), 0.0);
        assert_eq!(BatchParams::Uniform(3).get(1, 0.0..1.0), 0.5);
        assert_eq!(BatchParams::Uniform(3).get(1, 2.0..4.0), 3.0);
        assert!(BatchParams::Values(&[]).is_empty());
    }

    #[test]
    fn batch_3d_layout() {
        let c = example1().degree_curve(crate::DegreeKind::Truth);
        let ts = [0.0, 0.3, 1.0];
        let mut out = vec![0.0; 6 * 3];
        CurveBatch::from(&c)
            .evaluate(BatchParams::Values(&ts), &mut out, &BatchOptions::default())
            .unwrap();
        let expected = reference(&c, &ts);
        for (a, b) in out.iter().zip(&expected) {
            assert!((a - b).abs() <= 1e-14 * 9.0);
        }
    }

    /// `Accuracy::Compensated` gives the scalar (compensated) evaluation bit for bit, for
    /// several curves at once, split between threads, and reports the first bad parameter.
    #[test]
    fn batch_compensated_is_the_scalar_evaluation() {
        use crate::curve::ControlPolygon;
        let bezier = example1();
        let spline = crate::BSpline::clamped_uniform(
            (0..12).map(|i| bezier.control_point(i % 4)).collect(),
            5,
        )
        .unwrap();
        let weights = (0..12).map(|i| 0.5 + 0.1 * i as f64).collect();
        let nurbs =
            crate::Nurbs::new(spline.control_points(), weights, spline.knots().clone()).unwrap();
        let curves = [
            CurveBatch::from(&bezier),
            CurveBatch::from(&spline),
            CurveBatch::from(&nurbs),
        ];
        let scalar = [
            crate::AnyCurve::from(bezier.clone()),
            crate::AnyCurve::from(spline.clone()),
            crate::AnyCurve::from(nurbs),
        ];
        let count = 257;
        let options = BatchOptions::default()
            .with_accuracy(Accuracy::Compensated)
            .with_threads(2)
            .with_parallel_threshold(0);
        let mut out = vec![0.0; 3 * 5 * count];
        CurveBatch::evaluate_all(&curves, BatchParams::Uniform(count), &mut out, &options).unwrap();
        for (j, curve) in scalar.iter().enumerate() {
            for k in 0..count {
                let t = uniform_parameter(k, count, curve.domain());
                let p = curve.evaluate(t).unwrap();
                let channels = p.position.into_iter().chain(p.degrees.to_array());
                for (c, v) in channels.enumerate() {
                    assert_eq!(
                        out[(j * 5 + c) * count + k],
                        v,
                        "curve {j} channel {c} at {t}"
                    );
                }
            }
        }
        let ts = [0.0, 0.5, 1.5, f64::NAN];
        let mut out = vec![0.0; 5 * ts.len()];
        let error = curves[1]
            .evaluate(BatchParams::Values(&ts), &mut out, &options)
            .unwrap_err();
        assert_eq!(
            error,
            crate::curve::check_parameter(1.5, &(0.0..1.0)).unwrap_err()
        );
    }
}
