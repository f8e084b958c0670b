//! The spline being fitted (its layout), the basis matrix at the data and the normal
//! equations of one layout, with the smoothing penalty.

use super::banded::{Band, CyclicBand, Factor, Normal};
use super::basis;
use super::knots::periodic_knots;
use super::width::{with_width, Width};
use super::FitError;
use crate::degrees::Degrees;

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
        let k = if order == 0 {
            basis::Basis::new(&self.knots, p).values(t, values)
        } else {
            let k = basis::span(&self.knots, p, t);
            let mut all = vec![0.0; (order + 1) * (p + 1)];
            basis::derivatives(&self.knots, p, k, t, order, &mut all);
            values[..=p].copy_from_slice(&all[order * (p + 1)..]);
            k
        };
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

/// The data values a pass reads: the positions, and after them the degrees (truth,
/// indeterminacy, falsity) of each lane when every channel is fitted (`D + 3 L` channels per
/// point for `L` lanes: none for the positions alone, two for the interval-valued and bipolar
/// families, docs/model.md "Lanes"); or a table of any number of channels per point (a pass of
/// the two-pass surface solver, whose "points" are whole rows of a grid).
#[derive(Clone, Copy)]
pub(super) enum Values<'a, const D: usize> {
    Points {
        positions: &'a [[f64; D]],
        /// The degrees of each lane, one per point.
        lanes: &'a [&'a [Degrees]],
    },
    Table {
        /// Point `k`'s channels at `values[k * channels..(k + 1) * channels]`.
        values: &'a [f64],
        channels: usize,
    },
}

impl<const D: usize> Values<'_, D> {
    pub(super) fn channels(&self) -> usize {
        match self {
            Values::Points { lanes, .. } => D + 3 * lanes.len(),
            Values::Table { channels, .. } => *channels,
        }
    }

    /// Point `k`'s channels into `out`.
    #[inline(always)]
    fn load(&self, k: usize, out: &mut [f64]) {
        match self {
            Values::Points { positions, lanes } => {
                out[..D].copy_from_slice(&positions[k]);
                for (slots, lane) in out[D..].chunks_exact_mut(3).zip(lanes.iter()) {
                    slots.copy_from_slice(&lane[k].to_array());
                }
            }
            Values::Table { values, channels } => {
                out.copy_from_slice(&values[k * channels..(k + 1) * channels]);
            }
        }
    }
}

/// The basis matrix at the data: row `k` has `p + 1` values from unknown `first[k]` on
/// (cyclically when periodic).
pub(super) struct Rows {
    pub(super) p: usize,
    pub(super) first: Vec<usize>,
    pub(super) values: Vec<f64>,
}

impl Rows {
    pub(super) fn new(layout: &Layout, params: &[f64]) -> Rows {
        let p = layout.p;
        let mut basis = basis::Basis::new(&layout.knots, p);
        let mut first = Vec::with_capacity(params.len());
        let mut values = vec![0.0; params.len() * (p + 1)];
        let n = layout.n.max(1);
        with_width!(row width = p + 1 => {
            for (t, row) in params.iter().zip(values.chunks_exact_mut(p + 1)) {
                first.push((basis.values_in(width, *t, row) - p) % n);
            }
        });
        Rows { p, first, values }
    }

    pub(super) fn row(&self, k: usize) -> (usize, &[f64]) {
        let w = self.p + 1;
        (self.first[k], &self.values[k * w..(k + 1) * w])
    }

    /// The runs of consecutive rows that share their first unknown (one per span for sorted
    /// data): sums over a run are gathered in a small block and added to the system once.
    fn runs(&self) -> impl Iterator<Item = (usize, core::ops::Range<usize>)> + '_ {
        let mut start = 0;
        self.first.chunk_by(|a, b| a == b).map(move |run| {
            let rows = start..start + run.len();
            start = rows.end;
            (run[0], rows)
        })
    }

    /// Adds the lower triangle of `N^T W N` into `matrix` and `N^T W q` of the data values `q`
    /// into `b` (`b[i c + j]`, `c` channels).
    fn normal_equations<const D: usize>(
        &self,
        layout: &Layout,
        weights: &[f64],
        q: Values<'_, D>,
        matrix: &mut Normal,
        b: &mut [f64],
    ) {
        with_width!(row row = self.p + 1 => with_width!(channels channels = q.channels() => {
            self.normal_equations_in((channels, row), layout, weights, q, matrix, b)
        }));
    }

    fn normal_equations_in<const D: usize>(
        &self,
        (channels, row): (impl Width, impl Width),
        layout: &Layout,
        weights: &[f64],
        q: Values<'_, D>,
        matrix: &mut Normal,
        b: &mut [f64],
    ) {
        let (c, w) = (channels.get(), row.get());
        let mut block = vec![0.0; w * w];
        let mut sums = vec![0.0; w * c];
        let mut qk = vec![0.0; c];
        for (first, rows) in self.runs() {
            block.fill(0.0);
            sums.fill(0.0);
            for k in rows {
                let weight = weights[k];
                if weight == 0.0 {
                    continue;
                }
                let values = &self.values[k * w..(k + 1) * w];
                q.load(k, &mut qk);
                for (r, v) in values.iter().enumerate() {
                    let a = weight * v;
                    for (entry, vs) in block[r * w..r * w + r + 1].iter_mut().zip(values) {
                        *entry += a * vs;
                    }
                    for (sum, qv) in sums[r * c..(r + 1) * c].iter_mut().zip(&qk) {
                        *sum += a * qv;
                    }
                }
            }
            for r in 0..w {
                let i = layout.index(first, r);
                for s in 0..=r {
                    matrix.add(i, layout.index(first, s), block[r * w + s]);
                }
                for (bv, sum) in b[i * c..(i + 1) * c].iter_mut().zip(&sums[r * c..]) {
                    *bv += sum;
                }
            }
        }
    }

    /// One pass over the data with the coefficients `x` (`x[i c + j]`) of the `c` channels of
    /// `q`: calls `each(k, residual)` with `residual[j] = q_kj - (N x)_kj` for every row, and,
    /// with `gradient`, adds `N^T W (q - N x)` into it.
    pub(super) fn sweep<const D: usize>(
        &self,
        layout: &Layout,
        x: &[f64],
        q: Values<'_, D>,
        gradient: Option<(&[f64], &mut [f64])>,
        each: impl FnMut(usize, &[f64]),
    ) {
        with_width!(row row = self.p + 1 => with_width!(channels channels = q.channels() => {
            self.sweep_in((channels, row), layout, x, q, gradient, each)
        }));
    }

    fn sweep_in<const D: usize>(
        &self,
        (channels, row): (impl Width, impl Width),
        layout: &Layout,
        x: &[f64],
        q: Values<'_, D>,
        mut gradient: Option<(&[f64], &mut [f64])>,
        mut each: impl FnMut(usize, &[f64]),
    ) {
        let (c, w) = (channels.get(), row.get());
        let mut local = vec![0.0; w * c];
        let mut sums = vec![0.0; w * c];
        let mut residual = vec![0.0; c];
        for (first, rows) in self.runs() {
            for r in 0..w {
                let i = layout.index(first, r);
                local[r * c..(r + 1) * c].copy_from_slice(&x[i * c..(i + 1) * c]);
            }
            sums.fill(0.0);
            for k in rows {
                let values = &self.values[k * w..(k + 1) * w];
                q.load(k, &mut residual);
                for (v, xr) in values.iter().zip(local.chunks_exact(c)) {
                    for (res, xv) in residual.iter_mut().zip(xr) {
                        *res -= v * xv;
                    }
                }
                each(k, &residual);
                if let Some((weights, _)) = &gradient {
                    let weight = weights[k];
                    for (v, sr) in values.iter().zip(sums.chunks_exact_mut(c)) {
                        let a = weight * v;
                        for (sum, res) in sr.iter_mut().zip(&residual) {
                            *sum += a * res;
                        }
                    }
                }
            }
            if let Some((_, g)) = &mut gradient {
                for r in 0..w {
                    let i = layout.index(first, r);
                    for (gv, sum) in g[i * c..(i + 1) * c].iter_mut().zip(&sums[r * c..]) {
                        *gv += sum;
                    }
                }
            }
        }
    }
}

/// Extra equations (end tangents of an interpolation): a row and a target per channel.
pub(super) struct Extra {
    pub(super) first: usize,
    pub(super) values: Vec<f64>,
    pub(super) targets: Vec<f64>,
}

/// The normal equations of one layout for `c` channels of data values, factored.
pub(super) struct System<'a, const D: usize> {
    pub(super) layout: &'a Layout,
    pub(super) rows: &'a Rows,
    pub(super) weights: &'a [f64],
    /// The data values.
    pub(super) q: Values<'a, D>,
    pub(super) c: usize,
    pub(super) extras: Vec<Extra>,
    /// `lambda R`, when smoothing.
    pub(super) penalty: Option<Normal>,
    pub(super) matrix: Normal,
    pub(super) factor: Factor,
    /// An estimate of the matrix's 1-norm condition number.
    pub(super) condition: f64,
    /// The right-hand sides `N^T W q` (and the extras' rows), `b[i c + j]`.
    pub(super) rhs: Vec<f64>,
}

impl<'a, const D: usize> System<'a, D> {
    pub(super) fn new(
        layout: &'a Layout,
        rows: &'a Rows,
        weights: &'a [f64],
        q: Values<'a, D>,
        extras: Vec<Extra>,
        lambda: f64,
    ) -> Result<System<'a, D>, FitError> {
        let c = q.channels();
        let mut matrix = layout.normal();
        let mut rhs = vec![0.0; layout.n * c];
        rows.normal_equations(layout, weights, q, &mut matrix, &mut rhs);
        for e in &extras {
            add_outer(&mut matrix, layout, e.first, &e.values, 1.0);
            for (r, v) in e.values.iter().enumerate() {
                let i = layout.index(e.first, r);
                for (bv, target) in rhs[i * c..(i + 1) * c].iter_mut().zip(&e.targets) {
                    *bv += v * target;
                }
            }
        }
        let penalty = (lambda > 0.0).then(|| second_derivative_gram(layout, lambda));
        if let Some(r) = &penalty {
            matrix.add_matrix(r);
        }
        let factor = matrix.factor().ok_or(FitError::Singular)?;
        let condition = matrix.condition_estimate(&factor);
        Ok(System {
            layout,
            rows,
            weights,
            q,
            c,
            extras,
            penalty,
            matrix,
            factor,
            condition,
            rhs,
        })
    }

    /// Solves `M x = b` for the `c` channels (`b[i c + j]`), in place.
    fn solve_in_place(&self, b: &mut [f64]) {
        let (n, c) = (self.layout.n, self.c);
        let mut column = vec![0.0; n];
        for j in 0..c {
            for i in 0..n {
                column[i] = b[i * c + j];
            }
            self.factor.solve(&mut column);
            for i in 0..n {
                b[i * c + j] = column[i];
            }
        }
    }

    /// The least-squares solution, with one step of refinement against the data residuals
    /// (the gradient of the objective computed from `q - N x`, not from the normal
    /// equations), which recovers the accuracy the normal equations lose, and a second when
    /// the matrix is ill-conditioned. Returns the coefficients `x[i c + j]`.
    pub(super) fn solve(&self) -> Vec<f64> {
        let (layout, c) = (self.layout, self.c);
        let mut x = self.rhs.clone();
        self.solve_in_place(&mut x);
        let steps = if self.condition > 1e6 { 2 } else { 1 };
        for _ in 0..steps {
            let mut g = vec![0.0; layout.n * c];
            self.rows
                .sweep(layout, &x, self.q, Some((self.weights, &mut g)), |_, _| {});
            for e in &self.extras {
                for j in 0..c {
                    let value: f64 = e
                        .values
                        .iter()
                        .enumerate()
                        .map(|(r, v)| v * x[layout.index(e.first, r) * c + j])
                        .sum();
                    let residual = e.targets[j] - value;
                    for (r, v) in e.values.iter().enumerate() {
                        g[layout.index(e.first, r) * c + j] += v * residual;
                    }
                }
            }
            if let Some(r) = &self.penalty {
                let (mut column, mut product) = (vec![0.0; layout.n], vec![0.0; layout.n]);
                for j in 0..c {
                    for i in 0..layout.n {
                        column[i] = x[i * c + j];
                    }
                    r.mul(&column, &mut product);
                    for i in 0..layout.n {
                        g[i * c + j] -= product[i];
                    }
                }
            }
            self.solve_in_place(&mut g);
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

/// `lambda R`, `R_ij = int N_i'' N_j''` over the domain (the curve's smoothing penalty).
pub(super) fn second_derivative_gram(layout: &Layout, lambda: f64) -> Normal {
    derivative_gram(layout, 2, lambda)
}

/// `scale G`, `G_ij = int N_i^(r) N_j^(r)` over the domain for the derivative order `r <= 2`,
/// by Gauss-Legendre quadrature with `p + 1` nodes per span for `r = 0` and `p` otherwise
/// (exact: the integrand has degree `2 (p - r)`).
pub(super) fn derivative_gram(layout: &Layout, order: usize, scale: f64) -> Normal {
    let p = layout.p;
    let mut r = layout.normal();
    let (nodes, weights) = gauss_legendre(p.max(1) + usize::from(order == 0));
    let mut ders = vec![0.0; 3 * (p + 1)];
    for (a, b) in layout.spans() {
        let half = 0.5 * (b - a);
        for (x, w) in nodes.iter().zip(&weights) {
            let t = a + half * (x + 1.0);
            let k = basis::span(&layout.knots, p, t);
            basis::derivatives(&layout.knots, p, k, t, 2, &mut ders);
            let values = &ders[order * (p + 1)..(order + 1) * (p + 1)];
            let first = (k - p) % layout.n;
            add_outer(&mut r, layout, first, values, scale * w * half);
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
