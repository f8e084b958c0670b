//! The tensor-product normal equations of a surface fit, solved whole: unknowns `(i, j)` at
//! `i n + j` (`n` control points along `v`), so that `B^T W B + lambda R` is a band with
//! `p n + q` sub-diagonals, factored by the curve fit's banded Cholesky.

use super::super::banded::{Band, Factor, Normal};
use super::super::system::{derivative_gram, Layout, Rows};
use super::super::FitError;

/// The two directions' layouts of a surface.
pub(super) struct Tensor {
    pub(super) u: Layout,
    pub(super) v: Layout,
}

impl Tensor {
    /// The number of unknowns `m n`.
    pub(super) fn len(&self) -> usize {
        self.u.n * self.v.n
    }

    /// The zero normal matrix.
    fn normal(&self) -> Band {
        Band::zeros(self.len(), self.u.p * self.v.n + self.v.p)
    }
}

/// The tensor basis at the data: point `k` has the `u` row and the `v` row of its
/// parameters.
pub(super) struct TensorRows {
    pub(super) u: Rows,
    pub(super) v: Rows,
}

impl TensorRows {
    pub(super) fn new(tensor: &Tensor, params: &[[f64; 2]]) -> TensorRows {
        let us: Vec<f64> = params.iter().map(|uv| uv[0]).collect();
        let vs: Vec<f64> = params.iter().map(|uv| uv[1]).collect();
        TensorRows {
            u: Rows::new(&tensor.u, &us),
            v: Rows::new(&tensor.v, &vs),
        }
    }

    /// Point `k`'s unknowns and basis values, `(p + 1)(q + 1)` of each, in increasing order.
    fn row(&self, tensor: &Tensor, k: usize, index: &mut Vec<usize>, values: &mut Vec<f64>) {
        let (fu, nu) = self.u.row(k);
        let (fv, nv) = self.v.row(k);
        index.clear();
        values.clear();
        for (a, x) in nu.iter().enumerate() {
            for (b, y) in nv.iter().enumerate() {
                index.push((fu + a) * tensor.v.n + fv + b);
                values.push(x * y);
            }
        }
    }

    /// The first control point `(i, j)` (row-major index) whose support holds no point of
    /// positive weight, if any.
    pub(super) fn empty_support(&self, tensor: &Tensor, weights: &[f64]) -> Option<usize> {
        let mut hit = vec![false; tensor.len()];
        let (mut index, mut values) = (Vec::new(), Vec::new());
        for (k, w) in weights.iter().enumerate() {
            if *w <= 0.0 {
                continue;
            }
            self.row(tensor, k, &mut index, &mut values);
            for (i, v) in index.iter().zip(&values) {
                if *v > 0.0 {
                    hit[*i] = true;
                }
            }
        }
        hit.iter().position(|h| !h)
    }

    /// Calls `each(k, residual)` with `residual[c] = q_kc - (B x)_kc` for every point (`c`
    /// channels, `x[i c + j]`), and with `gradient` adds `B^T W (q - B x)` into it.
    pub(super) fn sweep(
        &self,
        tensor: &Tensor,
        x: &[f64],
        q: &[f64],
        c: usize,
        mut gradient: Option<(&[f64], &mut [f64])>,
        mut each: impl FnMut(usize, &[f64]),
    ) {
        let (mut index, mut values) = (Vec::new(), Vec::new());
        let mut residual = vec![0.0; c];
        for k in 0..q.len() / c {
            self.row(tensor, k, &mut index, &mut values);
            residual.copy_from_slice(&q[k * c..(k + 1) * c]);
            for (i, v) in index.iter().zip(&values) {
                for (r, xv) in residual.iter_mut().zip(&x[i * c..(i + 1) * c]) {
                    *r -= v * xv;
                }
            }
            each(k, &residual);
            if let Some((weights, g)) = &mut gradient {
                let w = weights[k];
                for (i, v) in index.iter().zip(&values) {
                    for (gv, r) in g[i * c..(i + 1) * c].iter_mut().zip(&residual) {
                        *gv += w * v * r;
                    }
                }
            }
        }
    }
}

/// The thin-plate penalty `lambda R`,
/// `R = G2_u (x) G0_v + 2 G1_u (x) G1_v + G0_u (x) G2_v` with `Gr_ij = int N_i^(r) N_j^(r)`:
/// `P^T R P = int int S_uu^2 + 2 S_uv^2 + S_vv^2` for each channel.
fn thin_plate(tensor: &Tensor, lambda: f64) -> Band {
    let gu = [0, 1, 2].map(|r| derivative_gram(&tensor.u, r, 1.0));
    let gv = [0, 1, 2].map(|r| derivative_gram(&tensor.v, r, 1.0));
    let terms = [(2, 0, 1.0), (1, 1, 2.0), (0, 2, 1.0)];
    let (m, n) = (tensor.u.n, tensor.v.n);
    let (p, q) = (tensor.u.p, tensor.v.p);
    let mut r = tensor.normal();
    for i in 0..m {
        for i2 in i.saturating_sub(p)..=i {
            for j in 0..n {
                let top = if i2 == i { j } else { (j + q).min(n - 1) };
                for j2 in j.saturating_sub(q)..=top {
                    let value: f64 = terms
                        .iter()
                        .map(|&(a, b, s)| s * gu[a].get(i, i2) * gv[b].get(j, j2))
                        .sum();
                    if value != 0.0 {
                        r.add(i * n + j, i2 * n + j2, lambda * value);
                    }
                }
            }
        }
    }
    r
}

/// The normal equations of a surface fit for `c` channels, factored.
pub(super) struct TensorSystem {
    pub(super) matrix: Normal,
    factor: Factor,
    penalty: Option<Normal>,
    pub(super) condition: f64,
    /// `B^T W q`, `rhs[i c + j]`.
    pub(super) rhs: Vec<f64>,
    c: usize,
}

impl TensorSystem {
    /// `(B^T W B + lambda R) x = B^T W q` for the data values `q[k c + j]`.
    ///
    /// # Errors
    /// [`FitError::Singular`] when the matrix is not numerically positive definite.
    pub(super) fn new(
        tensor: &Tensor,
        rows: &TensorRows,
        weights: &[f64],
        q: &[f64],
        c: usize,
        lambda: f64,
    ) -> Result<TensorSystem, FitError> {
        let mut band = tensor.normal();
        let mut rhs = vec![0.0; tensor.len() * c];
        let (mut index, mut values) = (Vec::new(), Vec::new());
        for (k, &w) in weights.iter().enumerate() {
            if w == 0.0 {
                continue;
            }
            rows.row(tensor, k, &mut index, &mut values);
            let qk = &q[k * c..(k + 1) * c];
            for (r, (&i, &vi)) in index.iter().zip(&values).enumerate() {
                let a = w * vi;
                for (&j, &vj) in index[..=r].iter().zip(&values[..=r]) {
                    band.add(i, j, a * vj);
                }
                for (b, qv) in rhs[i * c..(i + 1) * c].iter_mut().zip(qk) {
                    *b += a * qv;
                }
            }
        }
        let mut matrix = Normal::Open(band);
        let penalty = (lambda > 0.0).then(|| Normal::Open(thin_plate(tensor, lambda)));
        if let Some(r) = &penalty {
            matrix.add_matrix(r);
        }
        let factor = matrix.factor().ok_or(FitError::Singular)?;
        let condition = matrix.condition_estimate(&factor);
        Ok(TensorSystem {
            matrix,
            factor,
            penalty,
            condition,
            rhs,
            c,
        })
    }

    fn solve_in_place(&self, b: &mut [f64]) {
        let (c, n) = (self.c, b.len() / self.c);
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

    /// The least-squares solution `x[i c + j]`, with a step of refinement against the data
    /// residuals (two when ill-conditioned), as the curve solver does.
    pub(super) fn solve(
        &self,
        tensor: &Tensor,
        rows: &TensorRows,
        weights: &[f64],
        q: &[f64],
    ) -> Vec<f64> {
        let c = self.c;
        let mut x = self.rhs.clone();
        self.solve_in_place(&mut x);
        let steps = if self.condition > 1e6 { 2 } else { 1 };
        for _ in 0..steps {
            let mut g = vec![0.0; x.len()];
            rows.sweep(tensor, &x, q, c, Some((weights, &mut g)), |_, _| {});
            if let Some(r) = &self.penalty {
                let n = tensor.len();
                let (mut column, mut product) = (vec![0.0; n], vec![0.0; n]);
                for j in 0..c {
                    for i in 0..n {
                        column[i] = x[i * c + j];
                    }
                    r.mul(&column, &mut product);
                    for i in 0..n {
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
