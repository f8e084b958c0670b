//! `neutrospline bench-fit`: times fitting in-process on synthetic noisy data (the data of
//! `bench/compare_fit.py`, which times scipy on the same points in the same run).

use std::io::Write;
use std::time::Instant;

use anyhow::Context;
use neutrospline::fit::{fit, FitData, FitOptions, FitTarget};
use neutrospline::{ControlPolygon, Degrees};

/// Arguments of `bench-fit`.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchFitArgs {
    /// Number of data points
    #[arg(long, value_name = "N", default_value_t = 1000, value_parser = clap::value_parser!(u64).range(8..=100_000_000))]
    pub points: u64,
    /// Control points of the least-squares fit (ignored with --tolerance)
    #[arg(long, value_name = "K", default_value_t = 20)]
    pub control_points: usize,
    /// Fit to this tolerance (absolute) instead of a number of control points
    #[arg(long, value_name = "E")]
    pub tolerance: Option<f64>,
    /// Degree of the fitted curve
    #[arg(long, value_name = "P", default_value_t = 3)]
    pub degree: usize,
    /// Amplitude of the noise added to y
    #[arg(long, value_name = "A", default_value_t = 0.01)]
    pub noise: f64,
    /// Timed runs; the best is reported
    #[arg(long, value_name = "R", default_value_t = 7, value_parser = clap::value_parser!(u32).range(1..))]
    pub runs: u32,
}

/// The benchmark's data, point `k` of `n`: `s = k / (n - 1)`, `x = 10 s`,
/// `y = sin(6 s) + a * frac(sin(12.9898 k) * 43758.5453)` (a deterministic noise in
/// `(-a, a)`), truth `0.5 + 0.3 sin(5 s)`, indeterminacy `0.3 + 0.1 cos(3 s)`, falsity
/// `0.2 + 0.1 s`. `bench/compare_fit.py` computes the same values.
pub fn data(n: usize, noise: f64) -> anyhow::Result<FitData<2>> {
    let mut positions = Vec::with_capacity(n);
    let mut degrees = Vec::with_capacity(n);
    for k in 0..n {
        let s = k as f64 / (n - 1) as f64;
        let wobble = ((k as f64 * 12.9898).sin() * 43758.5453).fract();
        positions.push([10.0 * s, (6.0 * s).sin() + noise * wobble]);
        degrees.push(Degrees::new(
            0.5 + 0.3 * (5.0 * s).sin(),
            0.3 + 0.1 * (3.0 * s).cos(),
            0.2 + 0.1 * s,
        )?);
    }
    Ok(FitData::new(positions, degrees)?)
}

/// Times the fit and writes one JSON object: the best and the median seconds, the control
/// points, the largest position residual, and the fitted knots and control values (x, y,
/// truth, indeterminacy, falsity per control point) for a comparison of the results.
///
/// # Errors
/// A write error, or a fit that fails.
pub fn run(args: &BenchFitArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let n = usize::try_from(args.points).context("too many points")?;
    let data = data(n, args.noise)?;
    let target = match args.tolerance {
        Some(e) => FitTarget::Tolerance(e),
        None => FitTarget::ControlPoints(args.control_points),
    };
    let options = FitOptions::default()
        .with_degree(args.degree)
        .with_target(target);
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..=args.runs {
        let start = Instant::now();
        let fitted = fit(&data, &options)?;
        times.push(start.elapsed().as_secs_f64());
        last = Some(fitted);
    }
    // The first run warms up (pages, caches) and is not counted.
    times.remove(0);
    times.sort_by(f64::total_cmp);
    let fitted = last.context("at least one run")?;
    let knots = fitted.curve.knots().map(|k| k.knots().to_vec());
    let coefficients: Vec<[f64; 5]> = fitted
        .curve
        .control_points()
        .iter()
        .map(|c| {
            let [x, y] = c.position;
            let [t, i, f] = c.degrees.to_array();
            [x, y, t, i, f]
        })
        .collect();
    let result = serde_json::json!({
        "points": n,
        "degree": args.degree,
        "target": target.to_string(),
        "control_points": fitted.report.control_points,
        "best_seconds": times[0],
        "median_seconds": times[times.len() / 2],
        "runs": args.runs,
        "max_position_error": fitted.report.worst_distance,
        "tolerance_met": fitted.report.tolerance_met,
        "condition_estimate": fitted.report.condition_estimate,
        "at_bound": fitted.report.at_bound.len(),
        "knots": knots,
        "coefficients": coefficients,
    });
    serde_json::to_writer(&mut *out, &result)?;
    writeln!(out)?;
    Ok(())
}
