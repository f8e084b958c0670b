//! Tests of the rule solver: the independent reference optima, the variational inequality on
//! random problems, agreement with the active-set solver of [`super::super::qp`], and the
//! iterations on an ill-conditioned smoothing fit.

use proptest::prelude::*;

use super::super::banded::{Band, CyclicBand, Normal};
use super::super::qp;
use super::{solve_family, Active};
use crate::family::Family;

/// The uniform cubic B-spline basis values at `u` in `[0, 1)`, for the four control points of
/// the span.
fn cubic_basis(u: f64) -> [f64; 4] {
    let v = 1.0 - u;
    [
        v * v * v / 6.0,
        (3.0 * u * u * u - 6.0 * u * u + 4.0) / 6.0,
        (-3.0 * u * u * u + 3.0 * u * u + 3.0 * u + 1.0) / 6.0,
        u * u * u / 6.0,
    ]
}

/// A seeded xorshift stream of uniform values in `[0, 1)`.
struct Stream(u64);

impl Stream {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A least-squares problem of a uniform cubic B-spline with `n` control points (cyclic when
/// `closed`) fitted to `data` points with values drawn by `value` per channel; `smoothing`
/// times the second-difference penalty added. Returns `M`, `b` (interleaved) and the
/// unconstrained solution.
fn spline_problem(
    n: usize,
    closed: bool,
    data: usize,
    smoothing: f64,
    k: usize,
    stream: &mut Stream,
    value: &mut dyn FnMut(&mut Stream, &mut [f64]),
) -> (Normal, Vec<f64>, Vec<f64>) {
    let w = 3;
    let mut m = if closed {
        Normal::Closed(CyclicBand::zeros(n, w))
    } else {
        Normal::Open(Band::zeros(n, w))
    };
    let mut b = vec![0.0; n * k];
    let spans = if closed { n } else { n - 3 };
    let mut values = vec![0.0; k];
    for d in 0..data {
        let t = (d as f64 + 0.5 * stream.next()) / data as f64 * spans as f64;
        let span = (t.floor() as usize).min(spans - 1);
        let basis = cubic_basis(t - span as f64);
        value(stream, &mut values);
        for (p, bp) in basis.iter().enumerate() {
            let i = (span + p) % n;
            for (q, bq) in basis.iter().enumerate().take(p + 1) {
                let j = (span + q) % n;
                m.add(i, j, bp * bq);
            }
            for c in 0..k {
                b[i * k + c] += bp * values[c];
            }
        }
    }
    // Second differences x_{i-1} - 2 x_i + x_{i+1}.
    let rows = if closed { n } else { n - 2 };
    for r in 0..rows {
        let idx = [r % n, (r + 1) % n, (r + 2) % n];
        let coef = [1.0, -2.0, 1.0];
        for p in 0..3 {
            for q in 0..=p {
                m.add(idx[p], idx[q], smoothing * coef[p] * coef[q]);
            }
        }
    }
    let factor = m.factor().expect("positive definite");
    let mut free = vec![0.0; n * k];
    let mut channel = vec![0.0; n];
    for c in 0..k {
        for i in 0..n {
            channel[i] = b[i * k + c];
        }
        factor.solve(&mut channel);
        for i in 0..n {
            free[i * k + c] = channel[i];
        }
    }
    (m, b, free)
}

/// `f(x) = 1/2 x^T (M (x) I_k) x - b^T x` and its gradient, computed directly from the
/// matrix entries (no code shared with the solver).
fn objective_and_gradient(m: &Normal, k: usize, b: &[f64], x: &[f64]) -> (f64, Vec<f64>) {
    let n = m.order();
    let mut g = vec![0.0; n * k];
    for i in 0..n {
        for j in 0..n {
            let mij = m.get(i, j);
            if mij != 0.0 {
                for c in 0..k {
                    g[i * k + c] += mij * x[j * k + c];
                }
            }
        }
    }
    let f = x
        .iter()
        .zip(&g)
        .zip(b)
        .map(|((x, hx), b)| 0.5 * x * hx - b * x)
        .sum();
    for (gi, bi) in g.iter_mut().zip(b) {
        *gi -= bi;
    }
    (f, g)
}

/// Data values around and beyond the rule's boundary: a random vector, scaled so that the
/// power sum (or box) is at 1, pushed outwards by up to 20 % and given noise.
fn adversarial(family: Family) -> impl FnMut(&mut Stream, &mut [f64]) {
    move |stream: &mut Stream, values: &mut [f64]| {
        for (c, v) in values.iter_mut().enumerate() {
            let (low, high) = family.channel_range(c);
            *v = low + (high - low) * stream.next();
        }
        if let Some(p) = family.power() {
            let sum: f64 = values.iter().map(|v| v.abs().powi(p as i32)).sum();
            let scale = (1.0 + 0.2 * stream.next()) / sum.powf(1.0 / f64::from(p));
            for v in values.iter_mut() {
                *v *= scale;
            }
        }
        for v in values.iter_mut() {
            *v += 0.3 * (stream.next() - 0.5);
        }
        for &(l, u) in family.interval_pairs() {
            if stream.next() < 0.5 {
                values.swap(l, u);
            }
        }
    }
}

/// A uniform random point of the rule, by rejection from the box.
fn feasible_point(family: Family, stream: &mut Stream) -> Vec<f64> {
    let k = family.channel_count();
    loop {
        let y: Vec<f64> = (0..k)
            .map(|c| {
                let (low, high) = family.channel_range(c);
                // Boundary values half the time in each channel.
                match (stream.next() * 4.0) as u32 {
                    0 => low,
                    1 => high,
                    _ => low + (high - low) * stream.next(),
                }
            })
            .collect();
        if family.check(&y).is_ok() {
            return y;
        }
    }
}

/// Every point valid, and the variational inequality `grad f(x) . (y - x) >= -tol` for
/// random valid `y` at every point (each point moved alone and all together).
fn assert_optimal(m: &Normal, family: Family, b: &[f64], x: &[f64], stream: &mut Stream) {
    let k = family.channel_count();
    let n = m.order();
    for i in 0..n {
        assert!(
            family.check(&x[i * k..(i + 1) * k]).is_ok(),
            "{family} point {i}: {:?}",
            &x[i * k..(i + 1) * k]
        );
    }
    let (_, g) = objective_and_gradient(m, k, b, x);
    let scale = b.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
    for _ in 0..20 {
        let mut total = 0.0;
        for i in 0..n {
            let y = feasible_point(family, stream);
            let local: f64 = (0..k).map(|c| g[i * k + c] * (y[c] - x[i * k + c])).sum();
            assert!(local >= -1e-9 * scale, "{family} point {i}: {local}");
            total += local;
        }
        assert!(total >= -1e-9 * scale * n as f64, "{family}: {total}");
    }
}

#[test]
fn every_family_is_feasible_and_optimal_on_spline_fits() {
    for (seed, family) in Family::EXAMPLES.iter().enumerate() {
        for (n, closed, smoothing) in [(12, false, 1e-3), (25, true, 1e-2), (40, false, 0.0)] {
            let k = family.channel_count();
            let mut stream = Stream(0x5eed_0000 + seed as u64 * 97 + n as u64);
            let mut value = adversarial(*family);
            let (m, b, free) =
                spline_problem(n, closed, 3 * n, smoothing, k, &mut stream, &mut value);
            let solution = solve_family(&m, *family, &b, &free).expect("positive definite");
            assert_eq!(solution.active.len(), n);
            assert!(
                solution.iterations < 100,
                "{family}: {}",
                solution.iterations
            );
            let (f, _) = objective_and_gradient(&m, k, &b, &solution.x);
            assert!(
                solution.gap_bound <= 1e-9 * f.abs().max(1.0),
                "{family}: gap {}",
                solution.gap_bound
            );
            assert_optimal(&m, *family, &b, &solution.x, &mut stream);
        }
    }
}

/// The reference problems of `scripts/reference/make_rule_fit_reference.py` (cvxpy + Clarabel,
/// polished on the KKT system): every point valid, the objective within 1e-9 relative of the
/// reference optimum.
#[test]
fn matches_the_independent_reference_optima() {
    let text = include_str!("../../../tests/data/rule_fit_reference.json");
    let data: serde_json::Value = serde_json::from_str(text).expect("valid JSON");
    let cases = data["cases"].as_array().expect("cases");
    let floats = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .expect("array")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect()
    };
    let mut worst = 0.0_f64;
    let mut most_iterations = 0;
    let mut families = std::collections::BTreeSet::new();
    for case in cases {
        let family: Family = case["family"]
            .as_str()
            .expect("name")
            .parse()
            .expect("family");
        families.insert(family.to_string());
        let n = case["control_points"].as_u64().expect("n") as usize;
        let closed = case["closed"].as_bool().expect("closed");
        let k = family.channel_count();
        let band: Vec<Vec<f64>> = case["band"]
            .as_array()
            .expect("band")
            .iter()
            .map(floats)
            .collect();
        let w = band[0].len() - 1;
        let mut m = if closed {
            Normal::Closed(CyclicBand::zeros(n, w))
        } else {
            Normal::Open(Band::zeros(n, w))
        };
        for (i, row) in band.iter().enumerate() {
            for (d, &v) in row.iter().enumerate() {
                if closed {
                    m.add(i, (i + n - d) % n, v);
                } else if d <= i {
                    m.add(i, i - d, v);
                }
            }
        }
        let b: Vec<f64> = case["b"]
            .as_array()
            .expect("b")
            .iter()
            .flat_map(floats)
            .collect();
        assert_eq!(b.len(), n * k);
        // The warm start: the unconstrained solution.
        let factor = m.factor().expect("positive definite");
        let mut free = vec![0.0; n * k];
        let mut channel = vec![0.0; n];
        for c in 0..k {
            for i in 0..n {
                channel[i] = b[i * k + c];
            }
            factor.solve(&mut channel);
            for i in 0..n {
                free[i * k + c] = channel[i];
            }
        }
        let solution = solve_family(&m, family, &b, &free).expect("positive definite");
        for i in 0..n {
            assert!(
                family.check(&solution.x[i * k..(i + 1) * k]).is_ok(),
                "{family} n {n}: point {i}"
            );
        }
        let (f, _) = objective_and_gradient(&m, k, &b, &solution.x);
        let reference = case["objective"].as_f64().expect("objective");
        let gap = (f - reference).abs() / reference.abs().max(1.0);
        eprintln!(
            "{family} n = {n}{}: {} iterations, relative gap {gap:.2e} (certified bound {:.2e})",
            if closed { " closed" } else { "" },
            solution.iterations,
            solution.gap_bound / reference.abs().max(1.0)
        );
        assert!(gap <= 1e-9, "{family} n {n}: {f} vs {reference}");
        worst = worst.max(gap);
        most_iterations = most_iterations.max(solution.iterations);
    }
    assert_eq!(families.len(), Family::EXAMPLES.len());
    eprintln!("worst relative gap {worst:.2e}, most iterations {most_iterations}");
}

#[test]
fn agrees_with_the_active_set_solver() {
    for family in [Family::Neutrosophic, Family::Intuitionistic, Family::Fuzzy] {
        for seed in 0..4u64 {
            let k = family.channel_count();
            let mut stream = Stream(0xabcd_0000 + seed);
            let mut value = adversarial(family);
            let n = 10 + 15 * seed as usize;
            let (m, b, free) =
                spline_problem(n, seed % 2 == 1, 2 * n, 1e-3, k, &mut stream, &mut value);
            let solution = solve_family(&m, family, &b, &free).expect("positive definite");
            // The neutrosophic channels are independent boxes: one k = 1 problem each.
            let groups: Vec<Vec<usize>> = if family == Family::Neutrosophic {
                (0..3).map(|c| vec![c]).collect()
            } else {
                vec![(0..k).collect()]
            };
            for group in groups {
                let g = group.len();
                let pick = |v: &[f64]| -> Vec<f64> {
                    (0..n)
                        .flat_map(|i| group.iter().map(move |&c| v[i * k + c]))
                        .collect()
                };
                let reference = qp::solve(&m, g, &pick(&b), &pick(&free)).expect("solved");
                assert!(reference.optimal);
                let ours = pick(&solution.x);
                let (f_ours, _) = objective_and_gradient(&m, g, &pick(&b), &ours);
                let (f_qp, _) = objective_and_gradient(&m, g, &pick(&b), &reference.x);
                assert!(
                    (f_ours - f_qp).abs() <= 1e-12 * f_qp.abs().max(1.0),
                    "{family} seed {seed}: {f_ours} vs {f_qp}"
                );
                for (a, r) in ours.iter().zip(&reference.x) {
                    assert!((a - r).abs() <= 1e-8, "{family} seed {seed}: {a} vs {r}");
                }
            }
        }
    }
}

#[test]
fn ill_conditioned_smoothing_fit_converges() {
    // 2000 control points, data at one point per three spans: the normal matrix leans on
    // the tiny smoothing term (1-norm condition about 2e9). The certified gap bound is
    // measured; the interval-intuitionistic rule (four coupled constraints per point) is the
    // hardest: its interior-point iterate stalls at a rounding floor, and the bound is looser.
    for (family, relative) in [
        (Family::Pythagorean, 1e-9),
        (Family::Spherical, 1e-9),
        (Family::IntervalIntuitionistic, 1e-6),
    ] {
        let k = family.channel_count();
        let mut stream = Stream(0x1234_5678);
        let mut value = adversarial(family);
        let n = 2000;
        let (m, b, free) = spline_problem(n, false, n / 3, 1e-8, k, &mut stream, &mut value);
        let factor = m.factor().expect("positive definite");
        let condition = m.condition_estimate(&factor);
        assert!(condition > 1e9, "{condition}");
        let solution = solve_family(&m, family, &b, &free).expect("positive definite");
        let (f, _) = objective_and_gradient(&m, k, &b, &solution.x);
        eprintln!(
            "{family}: n = {n}, condition {condition:.2e}, {} iterations, gap bound {:.2e} \
             ({:.2e} relative), f = {f}",
            solution.iterations,
            solution.gap_bound,
            solution.gap_bound / f.abs()
        );
        assert!(solution.iterations <= 80, "{}", solution.iterations);
        assert!(solution.gap_bound <= relative * f.abs().max(1.0));
        for i in 0..n {
            assert!(family.check(&solution.x[i * k..(i + 1) * k]).is_ok());
        }
    }
}

#[test]
fn active_constraints_are_described_in_channel_names() {
    let family = Family::IntervalIntuitionistic;
    assert_eq!(
        Active::Sum {
            channels: vec![1, 3]
        }
        .describe(family),
        "truth_upper + falsity_upper = 1"
    );
    assert_eq!(
        Active::Order { lower: 0, upper: 1 }.describe(family),
        "truth_lower = truth_upper"
    );
    assert_eq!(
        Active::Power {
            power: 2,
            channels: &[0, 1]
        }
        .describe(Family::Pythagorean),
        "truth^2 + falsity^2 = 1"
    );
    assert_eq!(
        Active::Lower {
            channel: 3,
            bound: -1.0
        }
        .describe(Family::BipolarNeutrosophic),
        "negative_truth = -1"
    );
}

#[test]
fn singular_matrix_and_bad_input_give_none() {
    let mut band = Band::zeros(3, 1);
    band.add(0, 0, 1.0);
    let m = Normal::Open(band);
    assert!(solve_family(&m, Family::Fuzzy, &[0.0; 3], &[0.0; 3]).is_none());
    let mut band = Band::zeros(3, 1);
    for i in 0..3 {
        band.add(i, i, 1.0);
    }
    let m = Normal::Open(band);
    assert!(solve_family(&m, Family::Fuzzy, &[0.0; 2], &[0.0; 3]).is_none());
    assert!(solve_family(&m, Family::Fuzzy, &[f64::NAN; 3], &[0.0; 3]).is_none());
    // A non-finite start is only a poor warm start.
    let solution =
        solve_family(&m, Family::Pythagorean, &[2.0; 6], &[f64::NAN; 6]).expect("solved");
    let half = 0.5_f64.sqrt();
    for v in &solution.x {
        assert!((v - half).abs() < 1e-12, "{v}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn variational_inequality_holds(
        family_index in 0usize..Family::EXAMPLES.len(),
        n in 8usize..40,
        closed in any::<bool>(),
        smoothing in prop_oneof![Just(0.0), 1e-6f64..1.0],
        seed in any::<u64>(),
    ) {
        let family = Family::EXAMPLES[family_index];
        let k = family.channel_count();
        let mut stream = Stream(seed | 1);
        let mut value = adversarial(family);
        let (m, b, free) = spline_problem(n, closed, 2 * n, smoothing, k, &mut stream, &mut value);
        let solution = solve_family(&m, family, &b, &free).expect("positive definite");
        assert_optimal(&m, family, &b, &solution.x, &mut stream);
    }
}
