//! The spline being fitted (its layout), the basis matrix at the data and the normal
//! equations of one layout, with the smoothing penalty.

use super::banded::{Band, CyclicBand, Factor, Normal};
use super::basis;
use super::knots::periodic_knots;
use super::FitError;

/// The spline being fitted: degree, knots and how the unknowns map to basis functions.
#[derive(Clone, Debug)]
pub(super) struct Layout {
    pub(super) p: usize,
    /// The output's knots (for a periodic spline, the unclamped vector of
    /// [`periodic_knots`]).
    pub(super) knots: Vec<f64>,
    /// Unknown control points (a periodic spline's distinct ones).
    pub(super) n: usize,
    pub(super) periodic: bool,
}

impl Layout {
    pub(super) fn open(p: usize, knots: Vec<f64>) -> Layout {
        let n = knots.len() - p - 1;
        Layout {
            p,
            knots,
            n,
            periodic: false,
        }
    }

    pub(super) fn closed(p: usize, base: &[f64]) -> Layout {
        Layout {
            p,
            knots: periodic_knots(base, p),
            n: base.len(),
            periodic: true,
        }
    }

    pub(super) fn domain(&self) -> (f64, f64) {
        (
            self.knots[self.p],
            self.knots[self.knots.len() - 1 - self.p],
        )
    }

    /// The basis functions (or their derivatives of `order`) at `t` into `values[..=p]`;
    /// returns the unknown of the first (the others follow, cyclically when periodic).
    pub(super) fn row(&self, t: f64, order: usize, values: &mut [f64]) -> usize {
        let p = self.p;
        let k = basis::span(&self.knots, p, t);
        if order == 0 {
            basis::values(&self.knots, p, k, t, values);
        } else {
            let mut all = vec![0.0; (order + 1) * (p + 1)];
            basis::derivatives(&self.knots, p, k, t, order, &mut all);
            values[..=p].copy_from_slice(&all[order * (p + 1)..]);
        }
        (k - p) % self.n.max(1)
    }

    pub(super) fn index(&self, first: usize, r: usize) -> usize {
        if self.periodic {
            (first + r) % self.n
        } else {
            first + r
        }
    }

    pub(super) fn normal(&self) -> Normal {
        if self.periodic {
            Normal::Closed(CyclicBand::zeros(self.n, self.p))
        } else {
            Normal::Open(Band::zeros(self.n, self.p))
        }
    }

    /// The interior breakpoints' spans `[a, b]` of the domain.
    pub(super) fn spans(&self) -> Vec<(f64, f64)> {
        let (a, b) = self.domain();
        let mut edges: Vec<f64> = self
            .knots
            .iter()
            .copied()
            .filter(|&k| k >= a && k <= b)
            .collect();
        edges.dedup();
        edges.windows(2).map(|w| (w[0], w[1])).collect()
    }
}

/// A row of the basis matrix: its first unknown and `p + 1` values.
pub(super) struct Rows {
    pub(super) p: usize,
    pub(super) first: Vec<usize>,
    pub(super) values: Vec<f64>,
}

impl Rows {
    pub(super) fn new(layout: &Layout, params: &[f64]) -> Rows {
        let p = layout.p;
        let mut first = Vec::with_capacity(params.len());
        let mut values = vec![0.0; params.len() * (p + 1)];
        for (k, &t) in params.iter().enumerate() {
            first.push(layout.row(t, 0, &mut values[k * (p + 1)..(k + 1) * (p + 1)]));
        }
        Rows { p, first, values }
    }

    pub(super) fn row(&self, k: usize) -> (usize, &[f64]) {
        let w = self.p + 1;
        (self.first[k], &self.values[k * w..(k + 1) * w])
    }

    /// `sum_r N_r x_{j_r}` at data point `k`.
    pub(super) fn dot(&self, layout: &Layout, k: usize, x: &[f64]) -> f64 {
        let (first, values) = self.row(k);
        values
            .iter()
            .enumerate()
            .map(|(r, v)| v * x[layout.index(first, r)])
            .sum()
    }
}

/// Extra equations (end tangents of an interpolation): a row and a target per channel.
pub(super) struct Extra {
    pub(super) first: usize,
    pub(super) values: Vec<f64>,
    pub(super) targets: Vec<f64>,
}

/// The normal equations of one layout and their factorisation.
pub(super) struct System<'a> {
    pub(super) layout: &'a Layout,
    pub(super) rows: Rows,
    pub(super) weights: &'a [f64],
    pub(super) extras: Vec<Extra>,
    /// `lambda R`, when smoothing.
    pub(super) penalty: Option<Normal>,
    pub(super) matrix: Normal,
    pub(super) factor: Factor,
}

impl<'a> System<'a> {
    pub(super) fn new(
        layout: &'a Layout,
        params: &[f64],
        weights: &'a [f64],
        extras: Vec<Extra>,
        lambda: f64,
    ) -> Result<System<'a>, FitError> {
        let rows = Rows::new(layout, params);
        let mut matrix = layout.normal();
        for k in 0..params.len() {
            let (first, values) = rows.row(k);
            add_outer(&mut matrix, layout, first, values, weights[k]);
        }
        for e in &extras {
            add_outer(&mut matrix, layout, e.first, &e.values, 1.0);
        }
        let penalty = (lambda > 0.0).then(|| second_derivative_gram(layout, lambda));
        if let Some(r) = &penalty {
            matrix.add_matrix(r);
        }
        let factor = matrix.factor().ok_or(FitError::Singular)?;
        Ok(System {
            layout,
            rows,
            weights,
            extras,
            penalty,
            matrix,
            factor,
        })
    }

    /// The right-hand side `N^T W q` (and the extras' rows) for one channel.
    pub(super) fn rhs(&self, target: &dyn Fn(usize) -> f64, extra: usize) -> Vec<f64> {
        let mut b = vec![0.0; self.layout.n];
        for k in 0..self.weights.len() {
            let (first, values) = self.rows.row(k);
            let wq = self.weights[k] * target(k);
            for (r, v) in values.iter().enumerate() {
                b[self.layout.index(first, r)] += v * wq;
            }
        }
        for e in &self.extras {
            for (r, v) in e.values.iter().enumerate() {
                b[self.layout.index(e.first, r)] += v * e.targets[extra];
            }
        }
        b
    }

    /// The least-squares solution for one channel, with two steps of refinement against the
    /// data residuals (the gradient of the objective computed from `q - N x`, not from the
    /// normal equations), which recovers the accuracy the normal equations lose.
    pub(super) fn solve(&self, target: &dyn Fn(usize) -> f64, extra: usize) -> Vec<f64> {
        let layout = self.layout;
        let mut x = self.rhs(target, extra);
        self.factor.solve(&mut x);
        for _ in 0..2 {
            let mut g = vec![0.0; layout.n];
            for k in 0..self.weights.len() {
                let residual = self.weights[k] * (target(k) - self.rows.dot(layout, k, &x));
                let (first, values) = self.rows.row(k);
                for (r, v) in values.iter().enumerate() {
                    g[layout.index(first, r)] += v * residual;
                }
            }
            for e in &self.extras {
                let value: f64 = e
                    .values
                    .iter()
                    .enumerate()
                    .map(|(r, v)| v * x[layout.index(e.first, r)])
                    .sum();
                let residual = e.targets[extra] - value;
                for (r, v) in e.values.iter().enumerate() {
                    g[layout.index(e.first, r)] += v * residual;
                }
            }
            if let Some(r) = &self.penalty {
                let mut rx = vec![0.0; layout.n];
                r.mul(&x, &mut rx);
                for (gi, ri) in g.iter_mut().zip(&rx) {
                    *gi -= ri;
                }
            }
            self.factor.solve(&mut g);
            for (xi, di) in x.iter_mut().zip(&g) {
                *xi += di;
            }
        }
        x
    }
}

/// Adds `w v v^T` at the unknowns of a row.
pub(super) fn add_outer(
    matrix: &mut Normal,
    layout: &Layout,
    first: usize,
    values: &[f64],
    w: f64,
) {
    if w == 0.0 {
        return;
    }
    for (r, vr) in values.iter().enumerate() {
        let i = layout.index(first, r);
        for (s, vs) in values[..=r].iter().enumerate() {
            matrix.add(i, layout.index(first, s), w * vr * vs);
        }
    }
}

/// `lambda R`, `R_ij = int N_i'' N_j''` over the domain, by Gauss-Legendre quadrature with `p`
/// nodes per span (exact: the integrand has degree `2 (p - 2)`).
pub(super) fn second_derivative_gram(layout: &Layout, lambda: f64) -> Normal {
    let p = layout.p;
    let mut r = layout.normal();
    let (nodes, weights) = gauss_legendre(p.max(1));
    let mut ders = vec![0.0; 3 * (p + 1)];
    for (a, b) in layout.spans() {
        let half = 0.5 * (b - a);
        for (x, w) in nodes.iter().zip(&weights) {
            let t = a + half * (x + 1.0);
            let k = basis::span(&layout.knots, p, t);
            basis::derivatives(&layout.knots, p, k, t, 2, &mut ders);
            let second = &ders[2 * (p + 1)..];
            let first = (k - p) % layout.n;
            add_outer(&mut r, layout, first, second, lambda * w * half);
        }
    }
    r
}

/// Gauss-Legendre nodes and weights on `[-1, 1]` (Newton's method on the Legendre
/// polynomial from the Chebyshev-like initial guesses).
pub(super) fn gauss_legendre(count: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = Vec::with_capacity(count);
    let mut weights = Vec::with_capacity(count);
    for i in 0..count {
        let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (count as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=count {
                let pj = ((2 * j - 1) as f64 * x * p1 - (j - 1) as f64 * p0) / j as f64;
                p0 = p1;
                p1 = pj;
            }
            let pn = if count == 1 { x } else { p1 };
            let pm = if count == 1 { 1.0 } else { p0 };
            derivative = count as f64 * (x * pn - pm) / (x * x - 1.0);
            let dx = pn / derivative;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        nodes.push(x);
        weights.push(2.0 / ((1.0 - x * x) * derivative * derivative));
    }
    (nodes, weights)
}
