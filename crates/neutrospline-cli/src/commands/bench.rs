//! `neutrospline bench`: times the library's batch evaluator in-process.
//!
//! The curve is, for `--kind bezier`, the paper's Example 1 for degree 3, else a seeded
//! pseudo-random 2-D curve of the given degree; for `--kind bspline` and `--kind nurbs`, a
//! seeded pseudo-random clamped uniform 2-D spline of the given degree with `--pieces`
//! polynomial pieces (NURBS weights in \[0.5, 2\]). It is evaluated at `points` evenly
//! spaced parameters over its domain into one buffer, best of several runs. Every run of the evaluator alternates with a run of the memory
//! bandwidth reference: the same threads writing the same five output arrays (five f64 per
//! point) in a tight loop with no arithmetic, the most any evaluator could do. The ratio of the
//! two is what fraction of that limit the evaluator reaches, on the same machine at the same
//! moment. With `--compensated` the evaluator is then timed again with
//! `Accuracy::Compensated` (best of as many runs), and both speeds are reported.

use std::io::Write;
use std::time::Instant;

use anyhow::Context;
use neutrospline::{
    batch, example1, Accuracy, BSpline, BatchOptions, BatchParams, Bezier, ControlPoint,
    CurveBatch, Degrees, KnotVector, Nurbs,
};

/// Arguments of `bench`.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchArgs {
    /// Number of evenly spaced parameters t = k / (N - 1)
    #[arg(long, value_name = "N", default_value_t = 1_000_000)]
    pub points: usize,
    /// Curve degree: for a Bézier curve, 3 is the paper's Example 1, any other a seeded
    /// random 2-D curve
    #[arg(long, value_name = "D", default_value_t = 3)]
    pub degree: usize,
    /// Curve kind: a Bézier curve, or a seeded random clamped uniform B-spline or NURBS curve
    #[arg(long, value_enum, default_value_t = BenchKind::Bezier)]
    pub kind: BenchKind,
    /// Polynomial pieces (knot spans) of a B-spline or NURBS curve
    #[arg(long, value_name = "M", default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub pieces: u32,
    /// Threads (0: one per core)
    #[arg(long, value_name = "K", default_value_t = 1)]
    pub threads: usize,
    /// Timed runs; the best is reported
    #[arg(long, value_name = "R", default_value_t = 7, value_parser = clap::value_parser!(u32).range(1..))]
    pub runs: u32,
    /// Seed of the random curve (degrees other than 3)
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// Output format
    #[arg(long, value_enum, default_value_t = BenchFormat::Text)]
    pub format: BenchFormat,
    /// Also time the batch evaluator with compensated accuracy (the library's
    /// `Accuracy::Compensated`: compensated de Casteljau / de Boor per point, as the scalar
    /// evaluation) and report its speed beside the fast kernels'
    #[arg(long)]
    pub compensated: bool,
}

/// Curve kinds of `bench`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum BenchKind {
    /// A Bézier curve (Example 1 at degree 3)
    Bezier,
    /// A clamped uniform B-spline curve
    Bspline,
    /// A clamped uniform NURBS curve
    Nurbs,
}

/// Output formats of `bench`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum BenchFormat {
    /// A few lines for people
    Text,
    /// One JSON object
    Json,
}

/// What one benchmark measured.
#[derive(Debug, Clone, serde::Serialize)]
pub struct BenchResult {
    /// Curve kind.
    pub kind: BenchKind,
    /// Curve degree.
    pub degree: usize,
    /// Polynomial pieces of the curve (1 for a Bézier curve).
    pub pieces: usize,
    /// Parameters per run.
    pub points: usize,
    /// Threads used.
    pub threads: usize,
    /// Million points (position and three degrees) per second, best run.
    pub mpts_per_s: f64,
    /// Seconds of the best run.
    pub best_seconds: f64,
    /// Timed runs.
    pub runs: u32,
    /// `example1`, `random(seed=S)` (Bézier), `random(seed=S, pieces=M)` (splines).
    pub curve: String,
    /// The kernels' instruction set (`avx512`, `avx2+fma` or `portable`).
    pub instruction_set: String,
    /// The memory-bandwidth reference: million points per second of a tight loop writing
    /// the five output arrays with the same threads, best run.
    pub write_reference_mpts_per_s: f64,
    /// `mpts_per_s / write_reference_mpts_per_s`.
    pub fraction_of_write_reference: f64,
    /// With `--compensated`: million points per second of the batch evaluator with
    /// `Accuracy::Compensated`, best run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compensated_mpts_per_s: Option<f64>,
}

/// Runs the benchmark and writes its result to `out`.
///
/// # Errors
/// A write error.
pub fn run(args: &BenchArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let result = measure(args)?;
    match args.format {
        BenchFormat::Json => {
            serde_json::to_writer(&mut *out, &result)?;
            writeln!(out)?;
        }
        BenchFormat::Text => write_text(&result, out)?,
    }
    Ok(())
}

fn write_text(r: &BenchResult, out: &mut dyn Write) -> anyhow::Result<()> {
    writeln!(
        out,
        "batch evaluation: {} {} (degree {}), {} points, {} thread{}, {}",
        match r.kind {
            BenchKind::Bezier => "Bézier",
            BenchKind::Bspline => "B-spline",
            BenchKind::Nurbs => "NURBS",
        },
        r.curve,
        r.degree,
        r.points,
        r.threads,
        if r.threads == 1 { "" } else { "s" },
        r.instruction_set
    )?;
    writeln!(
        out,
        "  {:.1} Mpts/s (best of {} runs: {:.3} ms)",
        r.mpts_per_s,
        r.runs,
        r.best_seconds * 1e3
    )?;
    writeln!(
        out,
        "  memory-bandwidth reference (5 f64 per point, same threads): {:.1} Mpts/s; \
evaluator at {:.0}% of it",
        r.write_reference_mpts_per_s,
        100.0 * r.fraction_of_write_reference
    )?;
    if let Some(compensated) = r.compensated_mpts_per_s {
        writeln!(
            out,
            "  compensated ({}): {:.3} Mpts/s, {:.1}x the time of the fast kernels ({})",
            Accuracy::Compensated.name(),
            compensated,
            r.mpts_per_s / compensated,
            Accuracy::Fast.name()
        )?;
    }
    Ok(())
}

/// Times the evaluator and the write reference, alternating, best of `args.runs` each.
///
/// # Errors
/// Never in practice (the parameters are valid by construction).
pub fn measure(args: &BenchArgs) -> anyhow::Result<BenchResult> {
    let pieces = args.pieces as usize;
    let spline_name = format!("random(seed={}, pieces={pieces})", args.seed);
    let (batch, name) = match args.kind {
        BenchKind::Bezier if args.degree == 3 => {
            (CurveBatch::from(&example1()), "example1".to_string())
        }
        BenchKind::Bezier => (
            CurveBatch::from(&random_curve(args.degree, args.seed)),
            format!("random(seed={})", args.seed),
        ),
        BenchKind::Bspline => (
            CurveBatch::from(&random_bspline(args.degree, pieces, args.seed)),
            spline_name,
        ),
        BenchKind::Nurbs => (
            CurveBatch::from(&random_nurbs(args.degree, pieces, args.seed)),
            spline_name,
        ),
    };
    let options = BatchOptions::default().with_threads(args.threads);
    let threads = options.effective_threads();
    let points = args.points;
    let mut buffer = vec![0.0; 5 * points];
    let evaluate =
        |buffer: &mut [f64]| batch.evaluate(BatchParams::Uniform(points), buffer, &options);
    // One untimed run of each: pages mapped, code and caches warm.
    evaluate(&mut buffer).context("evaluating the benchmark curve")?;
    write_reference(&mut buffer, points, threads);
    let (mut best, mut best_reference) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..args.runs {
        let start = Instant::now();
        evaluate(&mut buffer).context("evaluating the benchmark curve")?;
        best = best.min(start.elapsed().as_secs_f64());
        std::hint::black_box(&mut buffer);
        let start = Instant::now();
        write_reference(&mut buffer, points, threads);
        best_reference = best_reference.min(start.elapsed().as_secs_f64());
        std::hint::black_box(&mut buffer);
    }
    let rate = |seconds: f64| {
        if seconds > 0.0 {
            points as f64 / seconds / 1e6
        } else {
            f64::INFINITY
        }
    };
    let (mpts, reference) = (rate(best), rate(best_reference));
    let compensated = if args.compensated {
        let options = options.clone().with_accuracy(Accuracy::Compensated);
        let evaluate =
            |buffer: &mut [f64]| batch.evaluate(BatchParams::Uniform(points), buffer, &options);
        evaluate(&mut buffer).context("evaluating the benchmark curve")?;
        let mut best = f64::INFINITY;
        for _ in 0..args.runs {
            let start = Instant::now();
            evaluate(&mut buffer).context("evaluating the benchmark curve")?;
            best = best.min(start.elapsed().as_secs_f64());
            std::hint::black_box(&mut buffer);
        }
        Some(rate(best))
    } else {
        None
    };
    let (degree, pieces) = (batch.degree(), batch.pieces());
    Ok(BenchResult {
        kind: args.kind,
        degree,
        pieces,
        points,
        threads,
        mpts_per_s: mpts,
        best_seconds: best,
        runs: args.runs,
        curve: name,
        instruction_set: batch::instruction_set().to_string(),
        write_reference_mpts_per_s: reference,
        fraction_of_write_reference: mpts / reference,
        compensated_mpts_per_s: compensated,
    })
}

/// The memory-bandwidth reference: `threads` threads each writing its share of the five
/// channel arrays of `buffer` (channel-major, `points` per channel), five f64 per point.
fn write_reference(buffer: &mut [f64], points: usize, threads: usize) {
    if points == 0 {
        return;
    }
    let share = points.div_ceil(threads.max(1)).next_multiple_of(8);
    // Per thread, its piece of each of the five channels.
    let mut pieces: Vec<Vec<&mut [f64]>> = Vec::new();
    for channel in buffer.chunks_exact_mut(points) {
        for (j, piece) in channel.chunks_mut(share).enumerate() {
            if pieces.len() <= j {
                pieces.push(Vec::with_capacity(5));
            }
            pieces[j].push(piece);
        }
    }
    let fill = |start: usize, channels: Vec<&mut [f64]>| {
        let [x, y, t, i, f] = <[&mut [f64]; 5]>::try_from(channels).expect("five channels");
        for k in 0..x.len() {
            let v = (start + k) as f64;
            x[k] = v;
            y[k] = v;
            t[k] = v;
            i[k] = v;
            f[k] = v;
        }
    };
    if pieces.len() == 1 {
        fill(0, pieces.pop().expect("one piece"));
        return;
    }
    std::thread::scope(|scope| {
        for (j, channels) in pieces.into_iter().enumerate() {
            scope.spawn(move || fill(j * share, channels));
        }
    });
}

/// Uniform numbers in \[0, 1) from a xorshift generator seeded with `seed`.
fn generator(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` 2-D control points with coordinates in \[0, 10\] and degrees in \[0, 1\]: per
/// point x, y, truth, indeterminacy, falsity, in this order, from `next`.
fn random_points(count: usize, next: &mut impl FnMut() -> f64) -> Vec<ControlPoint<2>> {
    (0..count)
        .map(|_| {
            let (x, y) = (10.0 * next(), 10.0 * next());
            let degrees = Degrees::new_unchecked(next(), next(), next());
            ControlPoint::new([x, y], degrees)
        })
        .collect()
}

/// A 2-D curve of degree `n` with coordinates in \[0, 10\] and degrees in \[0, 1\] from a
/// xorshift generator seeded with `seed`.
pub fn random_curve(n: usize, seed: u64) -> Bezier<2> {
    Bezier::new(random_points(n + 1, &mut generator(seed))).expect("finite coordinates")
}

/// A clamped uniform 2-D B-spline of degree `p` with `pieces` pieces (`p + pieces` control
/// points from the generator of [`random_curve`]) on \[0, 1\].
pub fn random_bspline(p: usize, pieces: usize, seed: u64) -> BSpline<2> {
    let count = p + pieces;
    let points = random_points(count, &mut generator(seed));
    let knots = KnotVector::clamped_uniform(p, count).expect("count > degree");
    BSpline::new(points, knots).expect("valid random B-spline")
}

/// [`random_bspline`] with weights `2^(2r - 1)` in \[0.5, 2\], `r` drawn after the points.
pub fn random_nurbs(p: usize, pieces: usize, seed: u64) -> Nurbs<2> {
    let count = p + pieces;
    let mut next = generator(seed);
    let points = random_points(count, &mut next);
    let weights = (0..count).map(|_| (2.0 * next() - 1.0).exp2()).collect();
    let knots = KnotVector::clamped_uniform(p, count).expect("count > degree");
    Nurbs::new(points, weights, knots).expect("valid random NURBS")
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::ControlPolygon;

    fn args(points: usize, degree: usize, format: BenchFormat) -> BenchArgs {
        BenchArgs {
            points,
            degree,
            kind: BenchKind::Bezier,
            pieces: 64,
            threads: 1,
            runs: 1,
            seed: 1,
            format,
            compensated: false,
        }
    }

    #[test]
    fn bench_json_has_the_fields() {
        let mut out = Vec::new();
        run(&args(1000, 3, BenchFormat::Json), &mut out).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["degree"], 3);
        assert_eq!(v["points"], 1000);
        assert_eq!(v["threads"], 1);
        assert_eq!(v["curve"], "example1");
        assert!(v["mpts_per_s"].as_f64().unwrap() > 0.0);
        assert!(v["write_reference_mpts_per_s"].as_f64().unwrap() > 0.0);
        assert!(v.get("compensated_mpts_per_s").is_none());
    }

    #[test]
    fn bench_compensated_reports_both_speeds() {
        let mut a = args(1000, 7, BenchFormat::Json);
        a.compensated = true;
        let mut out = Vec::new();
        run(&a, &mut out).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert!(v["mpts_per_s"].as_f64().unwrap() > 0.0);
        assert!(v["compensated_mpts_per_s"].as_f64().unwrap() > 0.0);
        a.format = BenchFormat::Text;
        let mut out = Vec::new();
        run(&a, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("  compensated (compensated): "), "{text}");
        assert!(
            text.contains("x the time of the fast kernels (fast)"),
            "{text}"
        );
    }

    #[test]
    fn bench_random_curve_and_text() {
        let c = random_curve(15, 7);
        assert_eq!(c.degree(), 15);
        assert_eq!(c, random_curve(15, 7));
        let mut out = Vec::new();
        run(&args(100, 15, BenchFormat::Text), &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("batch evaluation: Bézier random(seed=1) (degree 15), 100 points"));
    }

    #[test]
    fn bench_spline_kinds() {
        for kind in [BenchKind::Bspline, BenchKind::Nurbs] {
            let mut a = args(1000, 5, BenchFormat::Json);
            (a.kind, a.pieces) = (kind, 12);
            let mut out = Vec::new();
            run(&a, &mut out).unwrap();
            let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
            assert_eq!(
                v["kind"],
                if kind == BenchKind::Bspline {
                    "bspline"
                } else {
                    "nurbs"
                }
            );
            assert_eq!(
                (v["degree"].as_u64(), v["pieces"].as_u64()),
                (Some(5), Some(12))
            );
            assert_eq!(v["curve"], "random(seed=1, pieces=12)");
        }
        let b = random_bspline(3, 10, 4);
        assert_eq!((b.degree(), b.len(), b.knots().domain()), (3, 13, 0.0..1.0));
        let n = random_nurbs(3, 10, 4);
        assert_eq!(n.control_points(), b.control_points());
        assert!(n.weights().unwrap().iter().all(|w| (0.5..=2.0).contains(w)));
    }

    #[test]
    fn bench_write_reference_fills_every_channel() {
        for threads in [1, 2, 3] {
            let points = 37;
            let mut buffer = vec![-1.0; 5 * points];
            write_reference(&mut buffer, points, threads);
            for c in 0..5 {
                for k in 0..points {
                    assert_eq!(buffer[c * points + k], k as f64);
                }
            }
        }
    }
}
