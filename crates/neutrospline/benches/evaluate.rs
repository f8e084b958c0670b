//! Criterion benches of the core operations over degree and size.
//!
//! Run with the fast paths enabled (otherwise the batch benches measure the portable kernel):
//!
//! ```text
//! cargo bench -p neutrospline --features simd,parallel
//! ```
//!
//! `write_reference` is the memory-bandwidth yardstick of the batch benches: a tight loop
//! writing the same five output arrays (five f64 per point) with no arithmetic.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use neutrospline::{
    batch, example1, AnyCurve, BSpline, BatchOptions, BatchParams, Bezier, ControlPoint,
    ControlPolygon, CurveBatch, CurvePoint, Degrees, Derivative, Evaluate, KnotVector, Nurbs,
    Split,
};

/// `count` seeded pseudo-random control points.
fn points(count: usize) -> Vec<ControlPoint<2>> {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            let degrees = Degrees::new(next(), next(), next()).expect("in [0, 1]");
            ControlPoint::new([10.0 * next(), 10.0 * next()], degrees)
        })
        .collect()
}

/// Example 1 for degree 3, else a seeded pseudo-random curve of degree `n`.
fn curve(n: usize) -> Bezier<2> {
    if n == 3 {
        return example1();
    }
    Bezier::new(points(n + 1)).expect("finite control points")
}

/// A clamped uniform cubic B-spline with 64 pieces, and the NURBS curve with the same points
/// and weights cycling through 0.5, 1, 2.
fn splines() -> [(&'static str, AnyCurve<2>); 2] {
    let count = 3 + 64;
    let knots = KnotVector::clamped_uniform(3, count).expect("count > degree");
    let bspline = BSpline::new(points(count), knots.clone()).expect("valid");
    let weights = (0..count).map(|i| [0.5, 1.0, 2.0][i % 3]).collect();
    let nurbs = Nurbs::new(points(count), weights, knots).expect("valid");
    [("bspline", bspline.into()), ("nurbs", nurbs.into())]
}

const DEGREES: [usize; 3] = [3, 7, 15];

fn single(c: &mut Criterion) {
    let mut group = c.benchmark_group("evaluate_single");
    for n in DEGREES {
        let bezier = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &bezier, |b, bezier| {
            b.iter(|| bezier.evaluate(black_box(0.37)))
        });
    }
    group.finish();
}

fn batch_bezier(c: &mut Criterion) {
    let name = format!("batch_uniform_{}_1thread", batch::instruction_set());
    let mut group = c.benchmark_group(name);
    let options = BatchOptions::default().with_threads(1);
    for n in DEGREES {
        let prepared = CurveBatch::from(&curve(n));
        for points in [1_000usize, 100_000] {
            let mut out = vec![0.0; 5 * points];
            group.throughput(Throughput::Elements(points as u64));
            group.bench_function(BenchmarkId::new(format!("degree{n}"), points), |b| {
                b.iter(|| {
                    prepared
                        .evaluate(BatchParams::Uniform(points), &mut out, &options)
                        .expect("valid parameters")
                })
            });
        }
    }
    // The scalar path over the same work, for comparison.
    let bezier = curve(3);
    let points = 100_000;
    let ts: Vec<f64> = (0..points)
        .map(|k| k as f64 / (points - 1) as f64)
        .collect();
    let mut out = vec![bezier.control_point(0); points];
    group.throughput(Throughput::Elements(points as u64));
    group.bench_function(BenchmarkId::new("scalar_degree3", points), |b| {
        b.iter(|| bezier.evaluate_many(&ts, &mut out).expect("valid"))
    });
    group.finish();
}

/// Splines (degree 3, 64 pieces): the batch evaluator against the scalar de Boor path.
fn batch_spline(c: &mut Criterion) {
    let name = format!("batch_spline_{}_1thread", batch::instruction_set());
    let mut group = c.benchmark_group(name);
    let options = BatchOptions::default().with_threads(1);
    let points = 100_000;
    let mut out = vec![0.0; 5 * points];
    let mut scalar_out =
        vec![CurvePoint::new([0.0; 2], Degrees::new_unchecked(0.0, 0.0, 0.0)); points];
    let ts: Vec<f64> = (0..points)
        .map(|k| k as f64 / (points - 1) as f64)
        .collect();
    group.throughput(Throughput::Elements(points as u64));
    for (kind, spline) in splines() {
        let prepared = CurveBatch::new(&spline);
        group.bench_function(BenchmarkId::new(kind, points), |b| {
            b.iter(|| {
                prepared
                    .evaluate(BatchParams::Uniform(points), &mut out, &options)
                    .expect("valid parameters")
            })
        });
        group.bench_function(BenchmarkId::new(format!("scalar_{kind}"), points), |b| {
            b.iter(|| spline.evaluate_many(&ts, &mut scalar_out).expect("valid"))
        });
    }
    group.finish();
}

fn write_reference(c: &mut Criterion) {
    let mut group = c.benchmark_group("write_reference");
    for points in [100_000usize, 1_000_000] {
        let mut out = vec![0.0; 5 * points];
        group.throughput(Throughput::Elements(points as u64));
        group.bench_function(BenchmarkId::from_parameter(points), |b| {
            b.iter(|| {
                let mut channels = out.chunks_exact_mut(points);
                let mut next = || channels.next().expect("five channels");
                let (x, y, t, i, f) = (next(), next(), next(), next(), next());
                for k in 0..points {
                    let v = k as f64;
                    x[k] = v;
                    y[k] = v;
                    t[k] = v;
                    i[k] = v;
                    f[k] = v;
                }
                black_box(&mut out);
            })
        });
    }
    group.finish();
}

fn split_and_derivative(c: &mut Criterion) {
    let mut group = c.benchmark_group("split");
    for n in DEGREES {
        let bezier = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &bezier, |b, bezier| {
            b.iter(|| bezier.split(black_box(0.37)))
        });
    }
    group.finish();
    let mut group = c.benchmark_group("derivative");
    for n in DEGREES {
        let bezier = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &bezier, |b, bezier| {
            b.iter(|| bezier.derivative().evaluate(black_box(0.37)))
        });
    }
    group.finish();
}

/// The degree channels' solve of a fit under a round rule: 500 control points, Pythagorean
/// data on and beyond `truth^2 + falsity^2 = 1` (the interior-point solver of the rule fit).
fn rule_fit(c: &mut Criterion) {
    let mut group = c.benchmark_group("rule_fit_solve");
    let problem = neutrospline::fit::RuleFitBench::new(neutrospline::Family::Pythagorean, 500);
    group.bench_function("pythagorean_500", |b| {
        b.iter(|| black_box(&problem).solve())
    });
    group.finish();
}

criterion_group!(
    benches,
    single,
    batch_bezier,
    batch_spline,
    write_reference,
    split_and_derivative,
    rule_fit
);
criterion_main!(benches);
