//! Batch evaluation of curves of every kind: a B-spline or NURBS curve as its Bézier pieces.
//!
//! A [`CurveBatch`] holds one prepared Bézier polynomial per non-empty knot span of the
//! domain (for a Bézier curve, one on \[0, 1\]), found once by blossoming (the pieces of
//! [`BSpline::to_bezier_segments`](crate::BSpline::to_bezier_segments)). A parameter `t` in the piece on `[a, b]` is evaluated as
//! that piece at the local parameter `u = (t - a) / (b - a)` by the kernels of
//! [`super::kernel`]. Runs of parameters in one piece go to the kernels together: for
//! non-decreasing parameters (evenly spaced ones included) each run is found by a binary
//! search and written in place; other parameters are grouped by piece (a counting sort of each
//! block), evaluated, and scattered back.
//!
//! A rational piece is evaluated in homogeneous form: channels `w x`, `w y`, `w T`, `w I`,
//! `w F` and `w`, with the piece's weights scaled to a largest weight of 1 (the rational
//! curve does not change, and no product overflows), then one division per parameter (the
//! reciprocal of the weight) and one product per channel. The rational basis functions are non-negative with unit sum, so every value is
//! then projected onto the range of its channel's Euclidean control values: degrees stay
//! within their control range, inside \[0, 1\]. (A piece whose weights, or weights times
//! control values, span so wide a range that the homogeneous products come near the
//! subnormal numbers, beyond a ratio of 1e289, is evaluated point by point in Euclidean form
//! instead: de Boor's rational steps, as the scalar evaluation.)
//!
//! Accuracy: the piece's control values are exact up to a few rounding errors of blossoming
//! (de Boor's own operations), and `u` carries at most one rounding more than de Boor's
//! ratios `(t - u_i) / (u_j - u_i)`; a Bézier piece of degree `n` moves by at most
//! `2n max |c|` per unit of `u`, so the result agrees with de Boor's algorithm within a small
//! multiple of `n u max |c|` (property tests against scalar de Boor evaluation: within 1e-14
//! times the channel's largest absolute control value up to degree 15, 1e-12 up to 400; the
//! worst measured over 3,000 random curves is 3.4e-15 up to degree 15 and 2.2e-14 at degree
//! 300). NURBS curves: within 1e-13 up to degree 15 with weights in \[0.1, 10\] (worst
//! measured 3.5e-15); the homogeneous form adds errors of the order of the ratio of the
//! largest to the smallest weight of a piece times `n u`. At a knot, `u` is exactly 0 or 1
//! and a non-rational piece gives exactly the plain de Boor value there (the scalar
//! evaluation, compensated, is within about a rounding of it).

use core::ops::Range;

use super::kernel::{self, Coeffs, Uniform, Values, MAX_CHANNELS};
use super::lanes::{self, LaneJob, Lanes};
use super::{
    first_outside, partition, plan, run_tasks, Accuracy, BatchOptions, BatchParams, Task, BLOCK,
};
use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::curve::{check_parameter, EvalError, Evaluate};
use crate::layout::stride;
use crate::spline::{bezier_knots, Spline};
use crate::spline_curve::{SplineCurve, Weighting};

/// A curve of any kind (Bézier, B-spline, NURBS) prepared for batch evaluation: its
/// polynomial or rational Bézier pieces, one per non-empty knot span of the domain.
///
/// Built once, then evaluated at any number of parameters in its domain with
/// [`CurveBatch::evaluate`] (or with other curves with [`CurveBatch::evaluate_all`]), through
/// SIMD kernels chosen at run time and threads. See the [`batch`](crate::batch) module
/// documentation for the method and its accuracy; a parameter `t` in the piece on `[a, b]`
/// is evaluated at `u = (t - a) / (b - a)` on that piece, rational pieces in homogeneous form
/// followed by one division. Evenly spaced parameters on a single piece over \[0, 1\] (a
/// Bézier curve) are generated inside the kernels.
///
/// ```
/// use neutrospline::{BSpline, BatchOptions, BatchParams, ControlPoint, CurveBatch, Degrees, KnotVector};
/// let d = Degrees::new(0.2, 0.4, 0.6)?;
/// let pts: Vec<_> = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
///     .into_iter()
///     .map(|p| ControlPoint::new(p, d))
///     .collect();
/// let spline = BSpline::new(pts, KnotVector::clamped_uniform(2, 4)?)?;
/// let batch = CurveBatch::from(&spline);
/// assert_eq!((batch.pieces(), batch.domain()), (2, 0.0..1.0));
/// let count = 3; // t = 0, 0.5, 1
/// let mut out = vec![0.0; 5 * count]; // x, y, truth, indeterminacy, falsity
/// batch.evaluate(BatchParams::Uniform(count), &mut out, &BatchOptions::default())?;
/// assert_eq!(out[..6], [0.0, 2.0, 4.0, 0.0, 2.0, 0.0]); // x, then y
/// assert_eq!(out[6..9], [0.2, 0.2, 0.2]); // truth
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CurveBatch<const D: usize> {
    inner: Pieces,
}

/// The prepared pieces of a curve: everything but its dimension, so that the evaluation
/// code is compiled once, in this crate, for every dimension (the kernels are instantiated
/// per channel count only).
#[derive(Clone, Debug, PartialEq)]
struct Pieces {
    domain: Range<f64>,
    degree: usize,
    rational: bool,
    /// Where each piece starts, increasing (a copy of the pieces' `start`, searched).
    starts: Vec<f64>,
    pieces: Vec<Piece>,
    /// The curve itself (a Bézier curve on Bézier knots), for [`Accuracy::Compensated`].
    source: Spline,
}

/// One Bézier piece on `[start, end]`.
#[derive(Clone, Debug, PartialEq)]
struct Piece {
    start: f64,
    end: f64,
    /// The control values; for a rational piece, homogeneous (`w c` per channel, then `w`).
    coeffs: Coeffs,
    /// Rational pieces: the range of each channel's Euclidean control values, onto which
    /// the quotients are projected.
    lo: [f64; MAX_CHANNELS],
    hi: [f64; MAX_CHANNELS],
    /// A rational piece whose weights span too wide a range for the homogeneous form (see
    /// [`HOMOGENEOUS_MIN`]): the piece as a rational spline on Bézier knots, evaluated point
    /// by point in Euclidean form instead of by the kernels.
    euclidean: Option<Spline>,
}

/// Smallest scaled weight `w_min`, and smallest product `w_min max_i |c_i|` of a channel that
/// is not all zero, of a rational piece evaluated in homogeneous form. Below it the products
/// `w c` approach the subnormal range, where their absolute error (up to `2^-1074` per
/// operation) divided by the weight no longer stays below `n u max |c|`; such a piece (a
/// weight ratio beyond 1e289 within one piece) is evaluated in Euclidean form.
const HOMOGENEOUS_MIN: f64 = 1e-289; // about 2^-960, 2^62 times the smallest normal number

impl Piece {
    /// The piece on `[start, end]` with point-major control rows `rows` (`stride` values each)
    /// and, for a rational piece, one positive weight per row.
    fn new(start: f64, end: f64, stride: usize, rows: &[f64], weights: Option<&[f64]>) -> Self {
        let mut lo = [0.0; MAX_CHANNELS];
        let mut hi = [0.0; MAX_CHANNELS];
        let mut euclidean = None;
        let coeffs = match weights {
            None => Coeffs::from_packed(stride, rows),
            Some(weights) => {
                let largest = weights.iter().copied().fold(0.0, f64::max);
                let mut homogeneous = Vec::with_capacity(rows.len() + weights.len());
                for (row, &weight) in rows.chunks_exact(stride).zip(weights) {
                    // In (0, 1]: |w c| <= |c|.
                    let w = weight / largest;
                    homogeneous.extend(row.iter().map(|v| w * v));
                    homogeneous.push(w);
                }
                let smallest = weights.iter().copied().fold(f64::INFINITY, f64::min) / largest;
                let mut homogeneous_ok = smallest >= HOMOGENEOUS_MIN;
                for c in 0..stride {
                    let channel = rows.iter().skip(c).step_by(stride).copied();
                    lo[c] = channel.clone().fold(f64::INFINITY, f64::min);
                    hi[c] = channel.fold(f64::NEG_INFINITY, f64::max);
                    let size = lo[c].abs().max(hi[c].abs());
                    homogeneous_ok &= size == 0.0 || smallest * size >= HOMOGENEOUS_MIN;
                }
                if !homogeneous_ok {
                    let p = rows.len() / stride - 1;
                    euclidean = Some(Spline {
                        knots: bezier_knots(p),
                        stride,
                        data: rows.to_vec(),
                        weights: Some(weights.to_vec()),
                    });
                }
                Coeffs::from_packed(stride + 1, &homogeneous)
            }
        };
        Piece {
            start,
            end,
            coeffs,
            lo,
            hi,
            euclidean,
        }
    }

    /// The local parameter of `t` in `[start, end]`: in \[0, 1\], exactly 0 at `start`
    /// and 1 at `end` (rounding is monotonic, so `t - start <= end - start`).
    #[inline(always)]
    fn local(&self, t: f64) -> f64 {
        (t - self.start) / (self.end - self.start)
    }
}

impl<const D: usize> CurveBatch<D> {
    /// Prepares `curve` (also `CurveBatch::from(&curve)` for each kind).
    pub fn new(curve: &AnyCurve<D>) -> Self {
        match curve {
            AnyCurve::Bezier(c) => Self::from(c),
            AnyCurve::BSpline(c) => Self::from(c),
            AnyCurve::Nurbs(c) => Self::from(c),
        }
    }

    /// Every curve of the library is 2-D or 3-D (their constructors check it), so `D + 3`
    /// channels are 5 or 6.
    fn from_pieces(domain: Range<f64>, source: Spline, pieces: Vec<Piece>) -> Self {
        CurveBatch {
            inner: Pieces {
                domain,
                degree: source.degree(),
                rational: source.weights.is_some(),
                starts: pieces.iter().map(|p| p.start).collect(),
                pieces,
                source,
            },
        }
    }

    fn from_spline(spline: &Spline, domain: Range<f64>) -> Self {
        let pieces = spline
            .bezier_segments()
            .into_iter()
            .map(|s| {
                Piece::new(
                    s.start,
                    s.end,
                    spline.stride,
                    s.packed.data(),
                    s.weights.as_deref(),
                )
            })
            .collect();
        Self::from_pieces(domain, spline.clone(), pieces)
    }

    /// The parameter domain `start..end` (\[0, 1\] for a Bézier curve).
    pub fn domain(&self) -> Range<f64> {
        self.inner.domain.clone()
    }

    /// The prepared control values of piece `j` (for tests of the kernels).
    #[cfg(test)]
    pub(crate) fn piece_coeffs(&self, j: usize) -> &Coeffs {
        &self.inner.pieces[j].coeffs
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        self.inner.degree
    }

    /// `true` for a NURBS curve.
    pub fn is_rational(&self) -> bool {
        self.inner.rational
    }

    /// The number of Bézier pieces (non-empty knot spans of the domain; 1 for a Bézier curve).
    pub fn pieces(&self) -> usize {
        self.inner.pieces.len()
    }

    /// Evaluates at every parameter of `params` into `out`, channel-major: channel `c` at
    /// parameter `k` is `out[c * params.len() + k]`, channels x, y, \[z,\] truth,
    /// indeterminacy, falsity.
    /// [`BatchParams::Uniform`] parameters are evenly spaced over the domain (see
    /// [`uniform_parameter`](crate::uniform_parameter)); [`BatchParams::Values`] must lie in
    /// the domain.
    ///
    /// # Errors
    /// The first parameter (lowest index) not finite or outside the domain; `out` is then
    /// partly written.
    ///
    /// # Panics
    /// If `out.len() != (D + 3) * params.len()`.
    pub fn evaluate(
        &self,
        params: BatchParams<'_>,
        out: &mut [f64],
        options: &BatchOptions,
    ) -> Result<(), EvalError> {
        evaluate_pieces(&[&self.inner], stride(D), params, out, options)
    }

    /// Evaluates every curve at the same parameters (evenly spaced over each curve's own
    /// domain for [`BatchParams::Uniform`]): curve `j`, channel `c`, parameter `k` at
    /// `out[(j * (D + 3) + c) * params.len() + k]`. The curves may be of different kinds,
    /// degrees and domains.
    ///
    /// # Errors
    /// The first parameter (lowest index; for equal indices, the first curve) not finite or
    /// outside a curve's domain; `out` is then partly written.
    ///
    /// # Panics
    /// If `out.len() != curves.len() * (D + 3) * params.len()`.
    pub fn evaluate_all(
        curves: &[Self],
        params: BatchParams<'_>,
        out: &mut [f64],
        options: &BatchOptions,
    ) -> Result<(), EvalError> {
        let inner: Vec<&Pieces> = curves.iter().map(|c| &c.inner).collect();
        evaluate_pieces(&inner, stride(D), params, out, options)
    }
}

impl Pieces {
    /// A single non-rational piece on exactly \[0, 1\] (a Bézier curve): its local parameter
    /// is the parameter itself, so evenly spaced parameters go to the kernels as they are.
    fn is_unit_polynomial(&self) -> bool {
        !self.rational
            && self.pieces.len() == 1
            && self.pieces[0].start == 0.0
            && self.pieces[0].end == 1.0
    }

    /// The piece holding `t` (in the domain): the last one that starts at or before `t`, as
    /// [`crate::KnotVector::span`] chooses the span.
    #[inline]
    fn piece_of(&self, t: f64) -> usize {
        self.starts.partition_point(|&s| s <= t).saturating_sub(1)
    }
}

impl<const D: usize> From<&Bezier<D>> for CurveBatch<D> {
    fn from(curve: &Bezier<D>) -> Self {
        let piece = Piece::new(0.0, 1.0, stride(D), curve.packed().data(), None);
        let source = Spline::from_bezier(curve.packed(), None);
        Self::from_pieces(0.0..1.0, source, vec![piece])
    }
}

impl<const D: usize, W: Weighting> From<&SplineCurve<D, W>> for CurveBatch<D> {
    fn from(curve: &SplineCurve<D, W>) -> Self {
        Self::from_spline(curve.spline(), curve.domain())
    }
}

impl<const D: usize> From<&AnyCurve<D>> for CurveBatch<D> {
    fn from(curve: &AnyCurve<D>) -> Self {
        Self::new(curve)
    }
}

/// Evaluates prepared curves of `channels` (5 or 6) output channels each. Not generic: the
/// kernels are compiled here, once for each channel count (not per dimension and crate).
#[inline(never)]
fn evaluate_pieces(
    curves: &[&Pieces],
    channels: usize,
    params: BatchParams<'_>,
    out: &mut [f64],
    options: &BatchOptions,
) -> Result<(), EvalError> {
    match channels {
        5 => evaluate_channels::<5>(curves, params, out, options),
        6 => evaluate_channels::<6>(curves, params, out, options),
        _ => unreachable!("curves are 2-D or 3-D: 5 or 6 channels"),
    }
}

fn evaluate_channels<const CH: usize>(
    curves: &[&Pieces],
    params: BatchParams<'_>,
    out: &mut [f64],
    options: &BatchOptions,
) -> Result<(), EvalError> {
    let count = params.len();
    let degrees = curves.iter().map(|c| c.degree);
    let Some(threads) = plan(out.len(), CH, count, degrees, options) else {
        return Ok(());
    };
    let refs: Vec<(usize, &Pieces)> = curves.iter().copied().enumerate().collect();
    let tasks = partition::<_, CH>(&refs, count, out, threads);
    let failure = match options.accuracy() {
        Accuracy::Fast => run_tasks(tasks, threads, |task| run_task(task, params)),
        Accuracy::Compensated => run_tasks(tasks, threads, |task| compensated_task(task, params)),
    };
    match failure {
        None => Ok(()),
        Some((k, j)) => {
            let domain = &curves[j].domain;
            Err(check_parameter(params.get(k, domain.clone()), domain)
                .expect_err("an invalid parameter was reported"))
        }
    }
}

/// The evenly spaced parameters `block` of `count` over `domain` into `ts`: exactly
/// [`uniform_parameter`](crate::uniform_parameter), in a loop the compiler vectorises (the
/// ends set apart: the formula may round the last beside `b`).
#[inline(always)]
fn uniform_block(count: usize, block: Range<usize>, domain: &Range<f64>, ts: &mut Vec<f64>) {
    let (a, b) = (domain.start, domain.end);
    let denominator = count.saturating_sub(1).max(1) as f64;
    let width = b - a;
    let (start, end) = (block.start, block.end);
    ts.clear();
    // (Through i64: one conversion instruction; the indices are far below 2^53.)
    ts.extend(block.map(|k| (a + width * (k as i64 as f64 / denominator)).max(a).min(b)));
    if let (true, Some(first)) = (start == 0, ts.first_mut()) {
        *first = a;
    }
    if let (true, Some(last)) = (end == count && count > 1, ts.last_mut()) {
        *last = b;
    }
}

/// Buffers reused from block to block by one task.
struct Workspace<V> {
    /// Local parameters (in piece order when the block is sorted by piece).
    local: Vec<f64>,
    /// The weight channel of rational pieces.
    weight: Vec<f64>,
    /// Parameters not in order: the piece of each, the block's permutation by piece, the
    /// count per piece, and the kernel's output in piece order (channel-major).
    piece: Vec<u32>,
    order: Vec<u32>,
    counts: Vec<u32>,
    values: Vec<f64>,
    /// The runs of one piece: the piece and where the run ends (it starts where the
    /// previous one ends).
    runs: Vec<(usize, usize)>,
    /// The kernels' scratch buffer.
    kernel: Vec<V>,
}

/// Evaluates one task, curve by curve, each through the kernels for its number of kernel
/// channels `H` (the outputs, plus the weight of a rational curve: 5, 6 or 7), one
/// dispatched function per `H` so that no compiled function holds more than one set of
/// kernels; returns the first invalid parameter's index and curve (lowest index, then lowest
/// curve).
fn run_task<const CH: usize>(
    task: Task<'_, (usize, &Pieces), CH>,
    params: BatchParams<'_>,
) -> Option<(usize, usize)> {
    let Task {
        start,
        end,
        mut items,
    } = task;
    let mut first_bad: Option<(usize, usize)> = None;
    for ((index, curve), outs) in items.iter_mut() {
        let run = Run {
            curve,
            outs: &mut outs[..],
            start,
            end,
            params,
        };
        let unit = curve.is_unit_polynomial() && matches!(params, BatchParams::Uniform(_));
        let bad = match CH + usize::from(curve.rational) {
            _ if unit => lanes::dispatch(UnitJob::<CH>(run)),
            5 => lanes::dispatch(PieceJob::<5>(run)),
            6 => lanes::dispatch(PieceJob::<6>(run)),
            7 => lanes::dispatch(PieceJob::<7>(run)),
            _ => unreachable!("curves are 2-D or 3-D: 5 or 6 channels"),
        };
        if let Some(k) = bad {
            let found = (k, *index);
            first_bad = Some(first_bad.map_or(found, |f| f.min(found)));
        }
    }
    first_bad
}

/// Evaluates one task point by point with the compensated algorithms of the scalar
/// evaluation, on each curve itself; returns the first invalid parameter's index and curve
/// (lowest index, then lowest curve).
fn compensated_task<const CH: usize>(
    task: Task<'_, (usize, &Pieces), CH>,
    params: BatchParams<'_>,
) -> Option<(usize, usize)> {
    let Task {
        start,
        end,
        mut items,
    } = task;
    let mut first_bad: Option<(usize, usize)> = None;
    let mut row = [0.0; MAX_CHANNELS];
    for ((index, curve), outs) in items.iter_mut() {
        let domain = &curve.domain;
        for k in start..end {
            let t = params.get(k, domain.clone());
            if !(domain.start <= t && t <= domain.end) {
                let found = (k, *index);
                first_bad = Some(first_bad.map_or(found, |f| f.min(found)));
                break;
            }
            curve.source.evaluate(t, &mut row);
            for (out, &v) in outs.iter_mut().zip(&row) {
                out[k - start] = v;
            }
        }
    }
    first_bad
}

/// One curve's share of a task: parameters `start..end` into `outs` (one slice per output
/// channel).
struct Run<'r, 'a, 'p> {
    curve: &'r Pieces,
    outs: &'r mut [&'a mut [f64]],
    start: usize,
    end: usize,
    params: BatchParams<'p>,
}

impl Run<'_, '_, '_> {
    /// The run's blocks of at most [`BLOCK`] parameters, `(first, end)` each, in order.
    fn blocks(&self) -> impl Iterator<Item = (usize, usize)> {
        let end = self.end;
        (self.start..end)
            .step_by(BLOCK)
            .map(move |block| (block, (block + BLOCK).min(end)))
    }
}

/// A single non-rational piece on \[0, 1\] (a Bézier curve) at evenly spaced parameters,
/// generated in the kernels' lanes (no parameter array to write and read back: at degree 3
/// the evaluation runs at the speed of writing the output).
struct UnitJob<'r, 'a, 'p, const CH: usize>(Run<'r, 'a, 'p>);

impl<const CH: usize> LaneJob for UnitJob<'_, '_, '_, CH> {
    type Output = Option<usize>;

    #[inline(always)]
    fn run<L: Lanes>(self, l: L) -> Option<usize> {
        let run = self.0;
        let denominator = run.params.len().saturating_sub(1).max(1) as f64;
        let mut scratch = Vec::new();
        for (block, stop) in run.blocks() {
            let uniform = Uniform {
                first: block,
                denominator,
            };
            let mut channels = run.outs.iter_mut();
            let mut slots: [&mut [f64]; CH] = core::array::from_fn(|_| match channels.next() {
                Some(channel) => &mut channel[block - run.start..stop - run.start],
                None => unreachable!("a run has CH output channels"),
            });
            let coeffs = &run.curve.pieces[0].coeffs;
            kernel::evaluate(l, coeffs, &uniform, &mut slots, &mut scratch);
        }
        None
    }
}

/// A curve of any kind evaluated piece by piece with `H` kernel channels (the outputs, plus
/// the weight for a rational curve), block by block; stops at the first invalid parameter.
struct PieceJob<'r, 'a, 'p, const H: usize>(Run<'r, 'a, 'p>);

impl<const H: usize> LaneJob for PieceJob<'_, '_, '_, H> {
    type Output = Option<usize>;

    #[inline(always)]
    fn run<L: Lanes>(self, l: L) -> Option<usize> {
        let run = self.0;
        let blocks = run.blocks();
        let Run {
            curve,
            outs,
            start,
            params,
            ..
        } = run;
        let mut ws = Workspace {
            local: Vec::new(),
            weight: Vec::new(),
            piece: Vec::new(),
            order: Vec::new(),
            counts: Vec::new(),
            values: Vec::new(),
            runs: Vec::new(),
            kernel: Vec::new(),
        };
        let mut generated = Vec::new();
        for (block, stop) in blocks {
            let ts: &[f64] = match params {
                BatchParams::Uniform(count) => {
                    uniform_block(count, block..stop, &curve.domain, &mut generated);
                    &generated
                }
                BatchParams::Values(ts) => {
                    let ts = &ts[block..stop];
                    if let Some(bad) = first_outside(ts, &curve.domain) {
                        return Some(block + bad);
                    }
                    ts
                }
            };
            let channels = outs.len();
            let mut slots: [&mut [f64]; MAX_CHANNELS] = Default::default();
            for (slot, channel) in slots.iter_mut().zip(outs.iter_mut()) {
                *slot = &mut channel[block - start..stop - start];
            }
            // (A Bézier curve's single piece takes the parameters in any order: no scan.)
            let in_order = matches!(params, BatchParams::Uniform(_))
                || curve.is_unit_polynomial()
                || ts.windows(2).fold(true, |ok, w| ok & (w[0] <= w[1])); // branch-free
            let outs = &mut slots[..channels];
            self::block::<L, H>(l, curve, ts, in_order, outs, &mut ws);
        }
        None
    }
}

/// `H` channels evaluated by the kernels: the `outs.len()` output
/// channels, then the weight if the curve is rational.
///
/// The parameters are first cut into runs of one piece with their local parameters; then
/// the kernels run once per run, from a single call site (they are inlined there, so one copy
/// of them per channel count and instruction set).
#[inline(always)]
fn block<L: Lanes, const H: usize>(
    l: L,
    curve: &Pieces,
    ts: &[f64],
    in_order: bool,
    outs: &mut [&mut [f64]],
    ws: &mut Workspace<L::V>,
) {
    let n = ts.len();
    let rational = H > outs.len();
    ws.local.resize(n, 0.0);
    ws.weight.resize(n, 0.0);
    ws.runs.clear();
    // A single non-rational piece on [0, 1] (a Bézier curve) at given parameters: the local
    // parameters are the parameters (`(t - 0) / (1 - 0) = t` exactly), read where they are.
    let unit = curve.is_unit_polynomial();
    if unit {
        ws.runs.push((0, n));
    } else if in_order {
        // (Evenly spaced parameters always are.) Each piece's run is contiguous, found by
        // binary search, and evaluated in place.
        let mut k = 0;
        while k < n {
            let j = curve.piece_of(ts[k]);
            let end = match curve.starts.get(j + 1) {
                Some(&next) => k + ts[k..].partition_point(|&t| t < next),
                None => n,
            };
            let piece = &curve.pieces[j];
            for (u, &t) in ws.local[k..end].iter_mut().zip(&ts[k..end]) {
                *u = piece.local(t);
            }
            ws.runs.push((j, end));
            k = end;
        }
    } else {
        group_by_piece(curve, ts, ws);
        ws.values.resize(H * n, 0.0);
    }
    let mut k = 0;
    for &(j, end) in &ws.runs {
        let piece = &curve.pieces[j];
        {
            let mut target: [&mut [f64]; H] = if in_order || unit {
                let mut slots = outs
                    .iter_mut()
                    .map(|s| &mut s[k..end])
                    .chain(core::iter::once(&mut ws.weight[k..end]));
                core::array::from_fn(|_| slots.next().expect("H output channels"))
            } else {
                let mut slots = ws.values.chunks_exact_mut(n).map(|s| &mut s[k..end]);
                core::array::from_fn(|_| slots.next().expect("H channels of values"))
            };
            let run = if unit { ts } else { &ws.local[k..end] };
            match &piece.euclidean {
                None => {
                    kernel::evaluate(l, &piece.coeffs, &Values(run), &mut target, &mut ws.kernel)
                }
                Some(spline) => euclidean_run(spline, run, &mut target),
            }
        }
        if (in_order || unit) && rational {
            let weights = &mut ws.weight[k..end];
            reciprocals(weights);
            for (c, out) in outs.iter_mut().enumerate() {
                let (lo, hi) = (piece.lo[c], piece.hi[c]);
                for (v, &r) in out[k..end].iter_mut().zip(&*weights) {
                    *v = (*v * r).max(lo).min(hi);
                }
            }
        }
        k = end;
    }
    if in_order || unit {
        return;
    }
    // Scatter the values, in piece order, back to the parameters' places.
    let (values, weights) = ws.values.split_at_mut(outs.len() * n);
    if rational {
        reciprocals(weights);
    }
    for (c, (out, column)) in outs.iter_mut().zip(values.chunks_exact(n)).enumerate() {
        if rational {
            for ((&i, &v), &r) in ws.order.iter().zip(column).zip(&*weights) {
                let piece = &curve.pieces[ws.piece[i as usize] as usize];
                out[i as usize] = (v * r).max(piece.lo[c]).min(piece.hi[c]);
            }
        } else {
            for (&i, &v) in ws.order.iter().zip(column) {
                out[i as usize] = v;
            }
        }
    }
}

/// A rational piece evaluated point by point in Euclidean form (de Boor's rational steps on
/// the piece): the values into the first channels of `target`, 1 into the weight channel.
fn euclidean_run<const H: usize>(spline: &Spline, us: &[f64], target: &mut [&mut [f64]; H]) {
    let mut row = [0.0; MAX_CHANNELS];
    for (k, &u) in us.iter().enumerate() {
        spline.evaluate_plain(u, &mut row);
        for (c, channel) in target.iter_mut().enumerate() {
            channel[k] = if c + 1 < H { row[c] } else { 1.0 };
        }
    }
}

/// Replaces the evaluated weights by their reciprocals, so that each channel then takes a
/// product instead of a division (1.5 ulp instead of 0.5; five divisions per point measured
/// half the speed at degree 3). Finite: the kernels project each weight onto its piece's
/// range, so it is at least [`HOMOGENEOUS_MIN`] (or exactly 1 from a piece evaluated in
/// Euclidean form).
#[inline(always)]
fn reciprocals(weights: &mut [f64]) {
    for w in weights {
        *w = 1.0 / *w;
    }
}

/// Parameters out of order: the piece of each (`ws.piece`), the block's permutation by piece
/// (`ws.order`: a counting sort, or a comparison sort when there are many more pieces than
/// parameters), the local parameters in that order (`ws.local`) and the runs of one piece
/// (`ws.runs`).
fn group_by_piece<V>(curve: &Pieces, ts: &[f64], ws: &mut Workspace<V>) {
    let n = ts.len();
    let pieces = curve.pieces.len();
    ws.piece.clear();
    ws.piece
        .extend(ts.iter().map(|&t| curve.piece_of(t) as u32));
    ws.order.clear();
    if pieces <= 4 * n {
        ws.counts.clear();
        ws.counts.resize(pieces + 1, 0);
        for &j in &ws.piece {
            ws.counts[j as usize + 1] += 1;
        }
        for j in 1..=pieces {
            ws.counts[j] += ws.counts[j - 1];
        }
        ws.order.resize(n, 0);
        for (i, &j) in ws.piece.iter().enumerate() {
            let slot = &mut ws.counts[j as usize];
            ws.order[*slot as usize] = i as u32;
            *slot += 1;
        }
    } else {
        ws.order.extend(0..n as u32);
        let piece = &ws.piece;
        ws.order.sort_unstable_by_key(|&i| piece[i as usize]);
    }
    for (u, &i) in ws.local.iter_mut().zip(&ws.order) {
        let i = i as usize;
        *u = curve.pieces[ws.piece[i] as usize].local(ts[i]);
    }
    let mut k = 0;
    while k < n {
        let j = ws.piece[ws.order[k] as usize];
        let end = k + ws.order[k..]
            .iter()
            .position(|&i| ws.piece[i as usize] != j)
            .unwrap_or(n - k);
        ws.runs.push((j as usize, end));
        k = end;
    }
}
