//! Symmetric positive definite systems with a band (and, for closed curves, a cyclic band):
//! the normal equations of spline fitting. Cholesky factorisation `A = L L^T` of the band, with
//! `w` sub-diagonals: `O(n w^2)` to factor, `O(n w)` per right-hand side.

/// A symmetric matrix stored by its lower band: entry `(i, j)`, `0 <= i - j <= w`, at
/// `band[i * (w + 1) + (i - j)]`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Band {
    n: usize,
    w: usize,
    band: Vec<f64>,
}

impl Band {
    /// The zero matrix of order `n` with `w` sub-diagonals.
    pub(crate) fn zeros(n: usize, w: usize) -> Band {
        Band {
            n,
            w,
            band: vec![0.0; n * (w + 1)],
        }
    }

    pub(crate) fn order(&self) -> usize {
        self.n
    }

    pub(crate) fn width(&self) -> usize {
        self.w
    }

    /// Entry `(i, j)` (either triangle; 0 outside the band).
    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        if i - j > self.w {
            0.0
        } else {
            self.band[i * (self.w + 1) + (i - j)]
        }
    }

    /// Adds `v` to entry `(i, j)` and its mirror; `|i - j| <= w`.
    pub(crate) fn add(&mut self, i: usize, j: usize, v: f64) {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        debug_assert!(i - j <= self.w);
        self.band[i * (self.w + 1) + (i - j)] += v;
    }

    /// Sets row and column `i` to those of the identity.
    pub(crate) fn unit_row(&mut self, i: usize) {
        for j in i.saturating_sub(self.w)..=(i + self.w).min(self.n - 1) {
            let (a, b) = if i >= j { (i, j) } else { (j, i) };
            self.band[a * (self.w + 1) + (a - b)] = if i == j { 1.0 } else { 0.0 };
        }
    }

    /// `y = A x`.
    pub(crate) fn mul(&self, x: &[f64], y: &mut [f64]) {
        for (i, yi) in y.iter_mut().enumerate() {
            let lo = i.saturating_sub(self.w);
            let hi = (i + self.w).min(self.n - 1);
            *yi = (lo..=hi).map(|j| self.get(i, j) * x[j]).sum();
        }
    }

    /// The 1-norm (largest column sum of absolute values).
    pub(crate) fn norm1(&self) -> f64 {
        (0..self.n)
            .map(|j| {
                let lo = j.saturating_sub(self.w);
                let hi = (j + self.w).min(self.n - 1);
                (lo..=hi).map(|i| self.get(i, j).abs()).sum::<f64>()
            })
            .fold(0.0, f64::max)
    }

    /// The Cholesky factor, or `None` when the matrix is not (numerically) positive definite.
    pub(crate) fn cholesky(&self) -> Option<BandCholesky> {
        let (n, w) = (self.n, self.w);
        let mut l = self.band.clone();
        let at = |i: usize, j: usize| i * (w + 1) + (i - j);
        for j in 0..n {
            // Diagonal: a_jj - sum_k l_jk^2.
            let mut d = l[at(j, j)];
            for k in j.saturating_sub(w)..j {
                d -= l[at(j, k)] * l[at(j, k)];
            }
            if !(d > 0.0 && d.is_finite()) {
                return None;
            }
            let d = d.sqrt();
            l[at(j, j)] = d;
            for i in j + 1..=(j + w).min(n - 1) {
                let mut s = l[at(i, j)];
                for k in i.saturating_sub(w)..j {
                    s -= l[at(i, k)] * l[at(j, k)];
                }
                l[at(i, j)] = s / d;
            }
        }
        Some(BandCholesky { n, w, l })
    }
}

/// `L` of `A = L L^T`, stored like [`Band`].
#[derive(Clone, Debug)]
pub(crate) struct BandCholesky {
    n: usize,
    w: usize,
    l: Vec<f64>,
}

impl BandCholesky {
    /// Solves `A x = b` in place.
    pub(crate) fn solve(&self, b: &mut [f64]) {
        let (n, w) = (self.n, self.w);
        let at = |i: usize, j: usize| i * (w + 1) + (i - j);
        for i in 0..n {
            let mut s = b[i];
            for k in i.saturating_sub(w)..i {
                s -= self.l[at(i, k)] * b[k];
            }
            b[i] = s / self.l[at(i, i)];
        }
        for i in (0..n).rev() {
            let mut s = b[i];
            for k in i + 1..=(i + w).min(n - 1) {
                s -= self.l[at(k, i)] * b[k];
            }
            b[i] = s / self.l[at(i, i)];
        }
    }
}

/// A symmetric matrix whose entries `(i, j)` are non-zero only where the cyclic distance
/// `min(|i - j|, n - |i - j|)` is at most `w`: the normal equations of a closed (periodic)
/// spline. Solved through the Schur complement of its banded interior: the `2w` variables
/// next to the seam are eliminated last, as a dense system.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CyclicBand {
    n: usize,
    w: usize,
    /// Entries by `(i, cyclic offset d)`, `0 <= d <= w`: `(i, i - d mod n)`.
    band: Vec<f64>,
}

impl CyclicBand {
    /// The zero matrix; needs `n > 2 w` (then every pair is at one cyclic distance).
    pub(crate) fn zeros(n: usize, w: usize) -> CyclicBand {
        debug_assert!(n > 2 * w);
        CyclicBand {
            n,
            w,
            band: vec![0.0; n * (w + 1)],
        }
    }

    fn slot(&self, i: usize, j: usize) -> Option<usize> {
        let n = self.n;
        let down = (i + n - j) % n; // i - j mod n
        let up = (j + n - i) % n;
        if down <= self.w {
            Some(i * (self.w + 1) + down)
        } else if up <= self.w {
            Some(j * (self.w + 1) + up)
        } else {
            None
        }
    }

    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        self.slot(i, j).map_or(0.0, |s| self.band[s])
    }

    /// Adds `v` to `(i, j)` and its mirror (cyclic distance at most `w`).
    pub(crate) fn add(&mut self, i: usize, j: usize, v: f64) {
        if let Some(s) = self.slot(i, j) {
            self.band[s] += v;
        } else {
            debug_assert!(false, "({i}, {j}) outside the cyclic band");
        }
    }

    /// Sets row and column `i` to those of the identity.
    pub(crate) fn unit_row(&mut self, i: usize) {
        let n = self.n;
        for d in 0..=self.w {
            for j in [(i + d) % n, (i + n - d) % n] {
                if let Some(s) = self.slot(i, j) {
                    self.band[s] = if i == j { 1.0 } else { 0.0 };
                }
            }
        }
    }

    pub(crate) fn mul(&self, x: &[f64], y: &mut [f64]) {
        let n = self.n;
        for (i, yi) in y.iter_mut().enumerate() {
            let mut s = self.get(i, i) * x[i];
            for d in 1..=self.w {
                let (a, b) = ((i + d) % n, (i + n - d) % n);
                s += self.get(i, a) * x[a];
                if b != a {
                    s += self.get(i, b) * x[b];
                }
            }
            *yi = s;
        }
    }

    /// The 1-norm. (With `n > 2 w`, the entries at cyclic offsets `+d` and `-d` are distinct.)
    pub(crate) fn norm1(&self) -> f64 {
        let n = self.n;
        (0..n)
            .map(|j| {
                self.get(j, j).abs()
                    + (1..=self.w)
                        .map(|d| {
                            self.get((j + d) % n, j).abs() + self.get((j + n - d) % n, j).abs()
                        })
                        .sum::<f64>()
            })
            .fold(0.0, f64::max)
    }

    /// The factorisation: interior `I = [w, n - w)` (banded, order `n - 2w`) and the border
    /// `B = [0, w) u [n - w, n)`; `S = A_BB - A_BI A_II^-1 A_IB`, dense, by Cholesky.
    pub(crate) fn factor(&self) -> Option<CyclicCholesky> {
        let (n, w) = (self.n, self.w);
        let m = n - 2 * w;
        let border: Vec<usize> = (0..w).chain(n - w..n).collect();
        let mut interior = Band::zeros(m, w);
        for i in 0..m {
            for d in 0..=w.min(i) {
                interior.add(i, i - d, self.get(w + i, w + i - d));
            }
        }
        let chol = interior.cholesky()?;
        // Z = A_II^-1 A_IB, column by column.
        let k = border.len();
        let mut z = vec![0.0; m * k];
        for (c, &b) in border.iter().enumerate() {
            let col = &mut z[c * m..(c + 1) * m];
            for (r, slot) in col.iter_mut().enumerate() {
                *slot = self.get(w + r, b);
            }
            chol.solve(col);
        }
        let mut s = vec![0.0; k * k];
        for (r, &br) in border.iter().enumerate() {
            for (c, &bc) in border.iter().enumerate() {
                let mut v = self.get(br, bc);
                let col = &z[c * m..(c + 1) * m];
                for (q, &zq) in col.iter().enumerate() {
                    v -= self.get(br, w + q) * zq;
                }
                s[r * k + c] = v;
            }
        }
        let dense = DenseCholesky::new(k, s)?;
        let coupling = border
            .iter()
            .flat_map(|&b| (0..m).map(move |q| (b, q)))
            .map(|(b, q)| self.get(b, w + q))
            .collect();
        Some(CyclicCholesky {
            n,
            w,
            interior: chol,
            z,
            border,
            dense,
            coupling,
        })
    }
}

/// The factorisation of a [`CyclicBand`].
#[derive(Clone, Debug)]
pub(crate) struct CyclicCholesky {
    n: usize,
    w: usize,
    interior: BandCholesky,
    /// `A_II^-1 A_IB`, column-major (`m` rows, one column per border variable).
    z: Vec<f64>,
    border: Vec<usize>,
    dense: DenseCholesky,
    /// `A_BI`, row-major (`k` rows, `m` columns).
    coupling: Vec<f64>,
}

impl CyclicCholesky {
    /// Solves `A x = b` in place: `y = A_II^-1 b_I`, `S x_B = b_B - A_BI y`,
    /// `x_I = y - Z x_B`.
    pub(crate) fn solve(&self, b: &mut [f64]) {
        let (n, w) = (self.n, self.w);
        let m = n - 2 * w;
        let k = self.border.len();
        let mut y = b[w..n - w].to_vec();
        self.interior.solve(&mut y);
        let mut xb: Vec<f64> = self
            .border
            .iter()
            .enumerate()
            .map(|(r, &br)| {
                let row = &self.coupling[r * m..(r + 1) * m];
                b[br] - row.iter().zip(&y).map(|(a, v)| a * v).sum::<f64>()
            })
            .collect();
        self.dense.solve(&mut xb);
        for (q, yq) in y.iter_mut().enumerate() {
            for c in 0..k {
                *yq -= self.z[c * m + q] * xb[c];
            }
        }
        b[w..n - w].copy_from_slice(&y);
        for (c, &bc) in self.border.iter().enumerate() {
            b[bc] = xb[c];
        }
    }
}

/// A small dense SPD matrix factored by Cholesky.
#[derive(Clone, Debug)]
pub(crate) struct DenseCholesky {
    k: usize,
    l: Vec<f64>,
}

impl DenseCholesky {
    pub(crate) fn new(k: usize, mut a: Vec<f64>) -> Option<DenseCholesky> {
        for j in 0..k {
            let mut d = a[j * k + j];
            for q in 0..j {
                d -= a[j * k + q] * a[j * k + q];
            }
            if !(d > 0.0 && d.is_finite()) {
                return None;
            }
            let d = d.sqrt();
            a[j * k + j] = d;
            for i in j + 1..k {
                let mut s = a[i * k + j];
                for q in 0..j {
                    s -= a[i * k + q] * a[j * k + q];
                }
                a[i * k + j] = s / d;
            }
        }
        Some(DenseCholesky { k, l: a })
    }

    pub(crate) fn solve(&self, b: &mut [f64]) {
        let k = self.k;
        for i in 0..k {
            let mut s = b[i];
            for q in 0..i {
                s -= self.l[i * k + q] * b[q];
            }
            b[i] = s / self.l[i * k + i];
        }
        for i in (0..k).rev() {
            let mut s = b[i];
            for q in i + 1..k {
                s -= self.l[q * k + i] * b[q];
            }
            b[i] = s / self.l[i * k + i];
        }
    }
}

/// A normal-equations matrix of either shape.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Normal {
    Open(Band),
    Closed(CyclicBand),
}

/// The factorisation of a [`Normal`] matrix.
#[derive(Clone, Debug)]
pub(crate) enum Factor {
    Open(BandCholesky),
    Closed(CyclicCholesky),
}

impl Normal {
    pub(crate) fn add(&mut self, i: usize, j: usize, v: f64) {
        match self {
            Normal::Open(a) => a.add(i, j, v),
            Normal::Closed(a) => a.add(i, j, v),
        }
    }

    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        match self {
            Normal::Open(a) => a.get(i, j),
            Normal::Closed(a) => a.get(i, j),
        }
    }

    /// Adds a matrix of the same shape.
    pub(crate) fn add_matrix(&mut self, other: &Normal) {
        let (mine, theirs) = match (self, other) {
            (Normal::Open(a), Normal::Open(b)) => (&mut a.band, &b.band),
            (Normal::Closed(a), Normal::Closed(b)) => (&mut a.band, &b.band),
            _ => unreachable!("matrices of one layout have one shape"),
        };
        debug_assert_eq!(mine.len(), theirs.len());
        for (x, y) in mine.iter_mut().zip(theirs) {
            *x += y;
        }
    }

    pub(crate) fn order(&self) -> usize {
        match self {
            Normal::Open(a) => a.order(),
            Normal::Closed(a) => a.n,
        }
    }

    pub(crate) fn unit_row(&mut self, i: usize) {
        match self {
            Normal::Open(a) => a.unit_row(i),
            Normal::Closed(a) => a.unit_row(i),
        }
    }

    pub(crate) fn mul(&self, x: &[f64], y: &mut [f64]) {
        match self {
            Normal::Open(a) => a.mul(x, y),
            Normal::Closed(a) => a.mul(x, y),
        }
    }

    pub(crate) fn factor(&self) -> Option<Factor> {
        match self {
            Normal::Open(a) => a.cholesky().map(Factor::Open),
            Normal::Closed(a) => a.factor().map(Factor::Closed),
        }
    }

    /// The band's half-width `w`.
    pub(crate) fn width(&self) -> usize {
        match self {
            Normal::Open(a) => a.width(),
            Normal::Closed(a) => a.w,
        }
    }

    /// The zero matrix of the same shape for `k` interleaved channels per variable: order
    /// `n k`, half-width `k (w + 1) - 1`.
    pub(crate) fn expanded(&self, k: usize) -> Normal {
        let (n, w) = (self.order(), self.width());
        match self {
            Normal::Open(_) => Normal::Open(Band::zeros(n * k, k * (w + 1) - 1)),
            Normal::Closed(_) => Normal::Closed(CyclicBand::zeros(n * k, k * (w + 1) - 1)),
        }
    }

    /// The columns `j` whose entries `(i, j)` may be non-zero.
    pub(crate) fn neighbours(&self, i: usize) -> Vec<usize> {
        let (n, w) = (self.order(), self.width());
        match self {
            Normal::Open(_) => (i.saturating_sub(w)..=(i + w).min(n - 1)).collect(),
            Normal::Closed(_) => {
                let mut js: Vec<usize> = (0..=w)
                    .flat_map(|d| [(i + d) % n, (i + n - d) % n])
                    .collect();
                js.sort_unstable();
                js.dedup();
                js
            }
        }
    }

    /// An estimate of the 1-norm condition number `||A||_1 ||A^-1||_1` (Hager's method, as
    /// LAPACK's `dlacon`, for the norm of the inverse: a few solves).
    pub(crate) fn condition_estimate(&self, factor: &Factor) -> f64 {
        let n = self.order();
        let norm = match self {
            Normal::Open(a) => a.norm1(),
            Normal::Closed(a) => a.norm1(),
        };
        let mut x = vec![1.0 / n as f64; n];
        let mut estimate = 0.0;
        for _ in 0..5 {
            let mut y = x.clone();
            factor.solve(&mut y);
            let new: f64 = y.iter().map(|v| v.abs()).sum();
            if new <= estimate {
                break;
            }
            estimate = new;
            let mut z: Vec<f64> = y
                .iter()
                .map(|v| if *v >= 0.0 { 1.0 } else { -1.0 })
                .collect();
            factor.solve(&mut z); // A symmetric: A^-T = A^-1
            let (j, zmax) =
                z.iter()
                    .enumerate()
                    .fold((0, f64::NEG_INFINITY), |(bj, bv), (j, v)| {
                        if v.abs() > bv {
                            (j, v.abs())
                        } else {
                            (bj, bv)
                        }
                    });
            let zx: f64 = z.iter().zip(&x).map(|(a, b)| a * b).sum();
            if zmax <= zx {
                break;
            }
            x.iter_mut().for_each(|v| *v = 0.0);
            x[j] = 1.0;
        }
        norm * estimate
    }
}

impl Factor {
    pub(crate) fn solve(&self, b: &mut [f64]) {
        match self {
            Factor::Open(f) => f.solve(b),
            Factor::Closed(f) => f.solve(b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dense reference solve by Gaussian elimination with partial pivoting.
    fn dense_solve(a: &[Vec<f64>], b: &[f64]) -> Vec<f64> {
        let n = b.len();
        let mut m: Vec<Vec<f64>> = a.to_vec();
        let mut x = b.to_vec();
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))
                .unwrap();
            m.swap(c, p);
            x.swap(c, p);
            for r in c + 1..n {
                let f = m[r][c] / m[c][c];
                for k in c..n {
                    m[r][k] -= f * m[c][k];
                }
                x[r] -= f * x[c];
            }
        }
        for r in (0..n).rev() {
            let s: f64 = (r + 1..n).map(|k| m[r][k] * x[k]).sum();
            x[r] = (x[r] - s) / m[r][r];
        }
        x
    }

    fn pseudo(k: usize) -> f64 {
        ((k as f64 * 0.7548776662466927).fract() - 0.5) * 2.0
    }

    #[test]
    fn band_cholesky_matches_dense_solve() {
        let (n, w) = (23, 3);
        let mut a = Band::zeros(n, w);
        for i in 0..n {
            a.add(i, i, 8.0 + pseudo(i));
            for d in 1..=w.min(i) {
                a.add(i, i - d, pseudo(i * 7 + d) / d as f64);
            }
        }
        let dense: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| a.get(i, j)).collect())
            .collect();
        let b: Vec<f64> = (0..n).map(|i| pseudo(i + 100)).collect();
        let want = dense_solve(&dense, &b);
        let mut got = b.clone();
        a.cholesky().unwrap().solve(&mut got);
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-14, "{g} {w}");
        }
        let mut y = vec![0.0; n];
        a.mul(&got, &mut y);
        for (yi, bi) in y.iter().zip(&b) {
            assert!((yi - bi).abs() < 1e-13);
        }
    }

    #[test]
    fn cyclic_band_matches_dense_solve() {
        let (n, w) = (17, 3);
        let mut a = CyclicBand::zeros(n, w);
        for i in 0..n {
            a.add(i, i, 9.0 + pseudo(i));
            for d in 1..=w {
                a.add(i, (i + d) % n, pseudo(i * 5 + d) / d as f64);
            }
        }
        let dense: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| a.get(i, j)).collect())
            .collect();
        for i in 0..n {
            for j in 0..n {
                assert_eq!(dense[i][j], dense[j][i]);
            }
        }
        assert!(dense[0][n - 1] != 0.0 && dense[0][n / 2] == 0.0);
        let b: Vec<f64> = (0..n).map(|i| pseudo(i + 50)).collect();
        let want = dense_solve(&dense, &b);
        let normal = Normal::Closed(a);
        let factor = normal.factor().unwrap();
        let mut got = b.clone();
        factor.solve(&mut got);
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-13, "{g} {w}");
        }
        // Condition estimate: a lower bound of the true 1-norm condition, within a small factor.
        let cond = normal.condition_estimate(&factor);
        assert!(cond >= 1.0 && cond.is_finite());
    }

    #[test]
    fn band_unit_rows_and_failures() {
        let mut a = Band::zeros(4, 1);
        for i in 0..4 {
            a.add(i, i, 2.0);
        }
        a.add(1, 0, -1.0);
        a.add(2, 1, -1.0);
        a.add(3, 2, -1.0);
        a.unit_row(2);
        assert_eq!((a.get(2, 1), a.get(2, 2), a.get(3, 2)), (0.0, 1.0, 0.0));
        let mut singular = Band::zeros(2, 1);
        singular.add(0, 0, 1.0);
        singular.add(1, 1, 1.0);
        singular.add(1, 0, 1.0);
        assert!(singular.cholesky().is_none());
    }
}
