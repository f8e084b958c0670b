//! The degree channels' least squares under the membership rule's bounds (docs/model.md
//! section 8): minimise `1/2 x^T H x - b^T x` where `H = M (x) I_k` (the normal matrix `M` of
//! the fit for each of `k` coupled channels, interleaved: variable `(i, c)` at `i k + c`),
//! subject to per-control-point constraints:
//!
//! - `k = 1` (a neutrosophic degree, or the fuzzy truth): `0 <= x_i <= 1`;
//! - `k = 2` (intuitionistic truth and falsity): `T_i >= 0`, `F_i >= 0`, `T_i + F_i <= 1`.
//!
//! A primal active-set method: from a feasible point, solve the problem with the working set's
//! constraints as equalities (a banded system of the same shape, the fixed variables eliminated
//! through `x_i = Z_i w_i + z_i` per point), step to it or to the first blocking constraint,
//! and drop the constraint whose Lagrange multiplier is most negative, until the KKT conditions
//! hold. Each step is one banded factorisation; the result is exactly feasible.

use super::banded::Normal;

/// Per-point constraints, as `a^T x_i >= c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bound {
    /// `x_c >= 0`.
    Lower(usize),
    /// `x_0 <= 1` (`k = 1`).
    Upper,
    /// `x_0 + x_1 <= 1` (`k = 2`).
    Sum,
}

impl Bound {
    fn normal(self, k: usize) -> [f64; 2] {
        match self {
            Bound::Lower(c) => {
                let mut a = [0.0; 2];
                a[c] = 1.0;
                a
            }
            Bound::Upper => [-1.0, 0.0],
            Bound::Sum => {
                debug_assert_eq!(k, 2);
                [-1.0, -1.0]
            }
        }
    }

    fn rhs(self) -> f64 {
        match self {
            Bound::Lower(_) => 0.0,
            Bound::Upper | Bound::Sum => -1.0,
        }
    }

    /// `a^T x - c`: non-negative when satisfied.
    fn slack(self, x: &[f64]) -> f64 {
        let a = self.normal(x.len());
        a.iter().zip(x).map(|(a, v)| a * v).sum::<f64>() - self.rhs()
    }
}

/// The constraints of one point for `k` channels.
fn bounds(k: usize) -> &'static [Bound] {
    if k == 1 {
        &[Bound::Lower(0), Bound::Upper]
    } else {
        &[Bound::Lower(0), Bound::Lower(1), Bound::Sum]
    }
}

/// The solution and the constraints active at it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Solution {
    /// Interleaved values.
    pub(crate) x: Vec<f64>,
    /// The active constraints of each point.
    pub(crate) active: Vec<Vec<Bound>>,
    /// Whether the KKT conditions were met (false only if the iteration limit was reached; the
    /// point is feasible either way).
    pub(crate) optimal: bool,
}

/// Projects one point onto its feasible set (the interval, or the triangle).
fn project(x: &mut [f64]) {
    if x.len() == 1 {
        x[0] = x[0].clamp(0.0, 1.0);
        return;
    }
    let (t, f) = (x[0].max(0.0), x[1].max(0.0));
    if t + f <= 1.0 {
        x[0] = t;
        x[1] = f;
        return;
    }
    // Onto the edge t + f = 1 (then clamp to its ends).
    let shift = (x[0] + x[1] - 1.0) / 2.0;
    let t = (x[0] - shift).clamp(0.0, 1.0);
    x[0] = t;
    x[1] = 1.0 - t;
}

/// `x_i = Z_i w_i + z_i` for the working set of a point; a column of `Z_i` that is zero marks
/// a dummy variable of the reduced system.
fn parametrise(k: usize, active: &[Bound]) -> ([[f64; 2]; 2], [f64; 2]) {
    let mut z = [[0.0; 2]; 2]; // z[row][col]
    let mut offset = [0.0; 2];
    if k == 1 {
        match active.first() {
            None => z[0][0] = 1.0,
            Some(Bound::Lower(_)) => offset[0] = 0.0,
            Some(_) => offset[0] = 1.0,
        }
        return (z, offset);
    }
    let has = |b: Bound| active.contains(&b);
    match (has(Bound::Lower(0)), has(Bound::Lower(1)), has(Bound::Sum)) {
        (false, false, false) => {
            z[0][0] = 1.0;
            z[1][1] = 1.0;
        }
        (true, false, false) => z[1][1] = 1.0,
        (false, true, false) => z[0][0] = 1.0,
        (false, false, true) => {
            z[0][0] = 1.0;
            z[1][0] = -1.0;
            offset[1] = 1.0;
        }
        (true, _, true) => offset[1] = 1.0,
        (_, true, true) => offset[0] = 1.0,
        (true, true, false) => {}
    }
    (z, offset)
}

/// Solves the bound-constrained problem for the `k` interleaved channels with right-hand
/// sides `b` (interleaved, `n k` values), starting from the unconstrained solution
/// `start` (interleaved).
pub(crate) fn solve(m: &Normal, k: usize, b: &[f64], start: &[f64]) -> Option<Solution> {
    let n = m.order();
    let mut x = start.to_vec();
    for point in x.chunks_exact_mut(k) {
        project(point);
    }
    let mut active: Vec<Vec<Bound>> = x
        .chunks_exact(k)
        .map(|p| {
            let mut set: Vec<Bound> = bounds(k)
                .iter()
                .copied()
                .filter(|c| c.slack(p) == 0.0)
                .collect();
            set.truncate(k);
            set
        })
        .collect();
    let limit = 20 * n * k + 50;
    for _ in 0..limit {
        let target = reduced_solution(m, k, b, &active)?;
        // The step from x to target; blocked by the first inactive constraint it violates.
        let mut step = 1.0_f64;
        let mut blocking: Option<(usize, Bound)> = None;
        for i in 0..n {
            let (from, to) = (&x[i * k..(i + 1) * k], &target[i * k..(i + 1) * k]);
            for &c in bounds(k) {
                if active[i].contains(&c) {
                    continue;
                }
                let (s0, s1) = (c.slack(from), c.slack(to));
                if s1 < 0.0 {
                    let alpha = (s0 / (s0 - s1)).clamp(0.0, 1.0);
                    if alpha < step {
                        step = alpha;
                        blocking = Some((i, c));
                    }
                }
            }
        }
        if let Some((i, c)) = blocking {
            for (v, t) in x.iter_mut().zip(&target) {
                *v += step * (t - *v);
            }
            // Put the blocking point exactly on its constraint.
            active[i].push(c);
            let point = &mut x[i * k..(i + 1) * k];
            let (z, offset) = parametrise(k, &active[i]);
            if z == [[0.0; 2]; 2] {
                point.copy_from_slice(&offset[..k]);
            } else {
                project_onto(point, &active[i]);
            }
            continue;
        }
        x = target;
        // Multipliers: g_i = sum_j lambda_j a_j over the point's active constraints.
        let mut g = vec![0.0; n * k];
        gradient(m, k, &x, b, &mut g);
        let scale = b.iter().fold(1e-300_f64, |s, v| s.max(v.abs()));
        let mut worst: Option<(usize, usize, f64)> = None;
        for i in 0..n {
            let gi = &g[i * k..(i + 1) * k];
            let lambdas = multipliers(k, &active[i], gi);
            for (j, &l) in lambdas.iter().enumerate() {
                if l < -1e-12 * scale && worst.is_none_or(|w| l < w.2) {
                    worst = Some((i, j, l));
                }
            }
        }
        match worst {
            None => {
                return Some(Solution {
                    x,
                    active,
                    optimal: true,
                })
            }
            Some((i, j, _)) => {
                active[i].remove(j);
            }
        }
    }
    Some(Solution {
        x,
        active,
        optimal: false,
    })
}

/// Sets a point exactly on its active constraints (after a step that reached them up to
/// rounding).
fn project_onto(point: &mut [f64], active: &[Bound]) {
    for c in active {
        match c {
            Bound::Lower(ch) => point[*ch] = 0.0,
            Bound::Upper => point[0] = 1.0,
            Bound::Sum => point[1] = 1.0 - point[0],
        }
    }
}

/// `g = H x - b`.
fn gradient(m: &Normal, k: usize, x: &[f64], b: &[f64], g: &mut [f64]) {
    let n = m.order();
    let mut channel = vec![0.0; n];
    let mut product = vec![0.0; n];
    for c in 0..k {
        for i in 0..n {
            channel[i] = x[i * k + c];
        }
        m.mul(&channel, &mut product);
        for i in 0..n {
            g[i * k + c] = product[i] - b[i * k + c];
        }
    }
}

/// The multipliers of a point's active constraints: `g = sum_j lambda_j a_j`.
fn multipliers(k: usize, active: &[Bound], g: &[f64]) -> Vec<f64> {
    match active.len() {
        0 => Vec::new(),
        1 => {
            let a = active[0].normal(k);
            let aa: f64 = a[..k].iter().map(|v| v * v).sum();
            let ga: f64 = a[..k].iter().zip(g).map(|(a, g)| a * g).sum();
            vec![ga / aa]
        }
        _ => {
            let (a, c) = (active[0].normal(k), active[1].normal(k));
            let det = a[0] * c[1] - a[1] * c[0];
            vec![
                (g[0] * c[1] - g[1] * c[0]) / det,
                (a[0] * g[1] - a[1] * g[0]) / det,
            ]
        }
    }
}

/// The minimiser with the working set's constraints as equalities, as full interleaved values.
fn reduced_solution(m: &Normal, k: usize, b: &[f64], active: &[Vec<Bound>]) -> Option<Vec<f64>> {
    let n = m.order();
    let maps: Vec<([[f64; 2]; 2], [f64; 2])> = active.iter().map(|a| parametrise(k, a)).collect();
    let mut h = m.expanded(k);
    let dummy = |i: usize, a: usize| (0..k).all(|r| maps[i].0[r][a] == 0.0);
    // Entries: M_ij (Z_i^T Z_j)_ab.
    for i in 0..n {
        for j in m.neighbours(i) {
            let mij = m.get(i, j);
            for a in 0..k {
                for bcol in 0..k {
                    let zz: f64 = (0..k).map(|r| maps[i].0[r][a] * maps[j].0[r][bcol]).sum();
                    if zz != 0.0 && (i * k + a) >= (j * k + bcol) {
                        h.add(i * k + a, j * k + bcol, mij * zz);
                    }
                }
            }
        }
    }
    for i in 0..n {
        for a in 0..k {
            if dummy(i, a) {
                h.unit_row(i * k + a);
            }
        }
    }
    // Right-hand side: Z^T (b - H z).
    let offsets: Vec<f64> = maps
        .iter()
        .flat_map(|(_, z)| z[..k].iter().copied())
        .collect();
    let mut hz = vec![0.0; n * k];
    gradient(m, k, &offsets, &vec![0.0; n * k], &mut hz);
    let mut rhs = vec![0.0; n * k];
    for i in 0..n {
        for a in 0..k {
            rhs[i * k + a] = if dummy(i, a) {
                0.0
            } else {
                (0..k)
                    .map(|r| maps[i].0[r][a] * (b[i * k + r] - hz[i * k + r]))
                    .sum()
            };
        }
    }
    h.factor()?.solve(&mut rhs);
    let mut x = vec![0.0; n * k];
    for i in 0..n {
        for r in 0..k {
            x[i * k + r] = maps[i].1[r]
                + (0..k)
                    .map(|a| maps[i].0[r][a] * rhs[i * k + a])
                    .sum::<f64>();
        }
    }
    Some(x)
}
