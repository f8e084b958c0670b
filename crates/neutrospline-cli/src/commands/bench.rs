//! `neutrospline bench`: times the library's batch evaluator in-process.
//!
//! The curve is the paper's Example 1 for degree 3, else a seeded pseudo-random 2-D curve of
//! the given degree; it is evaluated at `points` evenly spaced parameters into one buffer,
//! best of several runs. Every run of the evaluator alternates with a run of the memory
//! bandwidth reference: the same threads writing the same five output arrays (five f64 per
//! point) in a tight loop with no arithmetic, the most any evaluator could do. The ratio of the
//! two is what fraction of that limit the evaluator reaches, on the same machine at the same
//! moment.

use std::io::Write;
use std::time::Instant;

use anyhow::Context;
use neutrospline::{
    batch_instruction_set, example1, BatchOptions, BatchParams, Bezier, BezierBatch, ControlPoint,
    Degrees,
};

/// Arguments of `bench`.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchArgs {
    /// Number of evenly spaced parameters t = k / (N - 1)
    #[arg(long, value_name = "N", default_value_t = 1_000_000)]
    pub points: usize,
    /// Curve degree: 3 is the paper's Example 1, any other a seeded random 2-D curve
    #[arg(long, value_name = "D", default_value_t = 3)]
    pub degree: usize,
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
    /// Curve degree.
    pub degree: usize,
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
    /// `example1` or `random(seed=S)`.
    pub curve: String,
    /// The kernels' instruction set (`avx512`, `avx2+fma` or `portable`).
    pub instruction_set: String,
    /// The memory-bandwidth reference: million points per second of a tight loop writing
    /// the five output arrays with the same threads, best run.
    pub write_reference_mpts_per_s: f64,
    /// `mpts_per_s / write_reference_mpts_per_s`.
    pub fraction_of_write_reference: f64,
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
        "batch evaluation: {} (degree {}), {} points, {} thread{}, {}",
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
    Ok(())
}

/// Times the evaluator and the write reference, alternating, best of `args.runs` each.
///
/// # Errors
/// Never in practice (the parameters are valid by construction).
pub fn measure(args: &BenchArgs) -> anyhow::Result<BenchResult> {
    let (curve, name) = if args.degree == 3 {
        (example1(), "example1".to_string())
    } else {
        (
            random_curve(args.degree, args.seed),
            format!("random(seed={})", args.seed),
        )
    };
    let options = BatchOptions::default().with_threads(args.threads);
    let threads = options.effective_threads();
    let batch = BezierBatch::new(&curve);
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
    Ok(BenchResult {
        degree: curve.degree(),
        points,
        threads,
        mpts_per_s: mpts,
        best_seconds: best,
        runs: args.runs,
        curve: name,
        instruction_set: batch_instruction_set().to_string(),
        write_reference_mpts_per_s: reference,
        fraction_of_write_reference: mpts / reference,
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

/// A 2-D curve of degree `n` with coordinates in \[0, 10\] and degrees in \[0, 1\] from a
/// xorshift generator seeded with `seed`.
pub fn random_curve(n: usize, seed: u64) -> Bezier<2> {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let points = (0..=n)
        .map(|_| {
            let (x, y) = (10.0 * next(), 10.0 * next());
            let degrees = Degrees::new_unchecked(next(), next(), next());
            ControlPoint::new([x, y], degrees)
        })
        .collect();
    Bezier::new(points).expect("finite coordinates")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(points: usize, degree: usize, format: BenchFormat) -> BenchArgs {
        BenchArgs {
            points,
            degree,
            threads: 1,
            runs: 1,
            seed: 1,
            format,
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
    }

    #[test]
    fn bench_random_curve_and_text() {
        let c = random_curve(15, 7);
        assert_eq!(c.degree(), 15);
        assert_eq!(c, random_curve(15, 7));
        let mut out = Vec::new();
        run(&args(100, 15, BenchFormat::Text), &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.starts_with("batch evaluation: random(seed=1) (degree 15), 100 points"));
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
