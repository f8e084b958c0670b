//! Degree reduction by one, written once on the spline engine (curves of every kind, and
//! surfaces in one direction through the lines of their net): each Bézier piece is replaced by
//! the piece of one degree less that keeps its two end points and is nearest in the L2 sense,
//! `min ∫_0^1 |Σ_j Q_j B_j^{p-1}(s) - Σ_i P_i B_i^p(s)|^2 ds` (the normal equations with the
//! Gram matrices of the Bernstein bases, `∫ B_j^m B_k^n = C(m, j) C(n, k) / ((m + n + 1)
//! C(m + n, j + k))`), the pieces joined with C0 continuity, and then as many knots removed as
//! the tolerance left allows (Tiller), which restores the smoothness the curve had where the
//! reduction kept it.
//!
//! The degree channels are solved under the membership rule's bounds, as fitting solves them
//! (docs/model.md section 8): when the unconstrained piece has a control degree outside the
//! rule, the piece's degree channels are the solution of the same least-squares problem with
//! the rule's constraints on every free control point (`0 <= T <= 1` per channel; `T + F <= 1`
//! for intuitionistic degrees), by the active-set method of the fit (`fit::qp`); rational
//! pieces are reduced in homogeneous form, so the constraint on `w T` is `0 <= w T <= w` with
//! the piece's new weight `w`, solved in `T = (w T) / w`. The two lanes of an interval-valued
//! or bipolar family are reduced stacked in one row, and their channels are solved jointly
//! under the family's rule (`lower <= upper` couples the lanes), then split into the lanes.

use crate::degrees::{DegreeKind, Family};
use crate::fit::banded::{Band, Normal};
use crate::fit::{convex, qp};
use crate::knots::KnotVector;
use crate::spline::Spline;

/// Where the degrees sit in a row of the spline being reduced, and their rule: a row is one
/// or more control points of `point` channels each (a curve: one; a surface's net line: one per
/// point of the line), truth, indeterminacy and falsity from `truth`, the weight at `weight`
/// for a rational spline in homogeneous form. A family of two lanes (`Family::lanes`) has its
/// second lane's three slots from `second` (the lanes stacked in one row, so that one solve
/// sees every channel of the family).
#[derive(Clone, Copy, Debug)]
pub(crate) struct DegreeLayout {
    pub(crate) point: usize,
    pub(crate) truth: usize,
    pub(crate) weight: Option<usize>,
    pub(crate) membership: Family,
    pub(crate) second: Option<usize>,
}

impl DegreeLayout {
    /// The column (from a point's start) and sign of each channel of the family in its
    /// channel order (`Family::channels`): a family of one lane carries its channels in the
    /// truth, indeterminacy and falsity slots; a family of two lanes in the slots of its lanes
    /// (`Family::lanes`, a negated lane with sign -1).
    fn channel_columns(&self) -> Vec<(usize, f64)> {
        let family = self.membership;
        if family.lane_count() == 1 {
            return DegreeKind::ALL
                .into_iter()
                .filter(|kind| family.carries(*kind))
                .map(|kind| (self.truth + kind.index(), 1.0))
                .collect();
        }
        let mut columns = vec![(0, 1.0); family.channel_count()];
        for (lane, start) in family.lanes().iter().zip([Some(self.truth), self.second]) {
            let start = start.unwrap_or_else(|| unreachable!("a two-lane layout has a second"));
            for (slot, channel) in lane.slots.iter().enumerate() {
                if let Some(c) = channel {
                    columns[*c] = (start + slot, if lane.negated { -1.0 } else { 1.0 });
                }
            }
        }
        columns
    }

    /// The columns (from a point's start) of the slots that hold no channel: 0 always.
    fn empty_columns(&self) -> Vec<usize> {
        let family = self.membership;
        if family.lane_count() == 1 {
            return DegreeKind::ALL
                .into_iter()
                .filter(|kind| !family.carries(*kind))
                .map(|kind| self.truth + kind.index())
                .collect();
        }
        family
            .lanes()
            .iter()
            .zip([Some(self.truth), self.second])
            .flat_map(|(lane, start)| {
                let start = start.unwrap_or(self.truth);
                (0..3)
                    .filter(|slot| lane.slots[*slot].is_none())
                    .map(move |slot| start + slot)
            })
            .collect()
    }
}

/// The degree channels of the free control points `inner` of a reduced piece (the solution
/// of `a x = b` for every channel) solved again under the rule of `layout` where they break
/// it. `None` when the constrained problem cannot be solved (a singular system).
fn bound_degrees(
    a: &[Vec<f64>],
    b: &[Vec<f64>],
    inner: &mut [Vec<f64>],
    layout: &DegreeLayout,
) -> Option<()> {
    let n = inner.len();
    let stride = inner.first().map_or(0, Vec::len);
    let columns = layout.channel_columns();
    let empty = layout.empty_columns();
    for base in (0..stride).step_by(layout.point) {
        let weights: Vec<f64> = (0..n)
            .map(|j| layout.weight.map_or(1.0, |w| inner[j][base + w]))
            .collect();
        if weights.iter().any(|w| !(*w > 0.0 && w.is_finite())) {
            // Left to the caller, which refuses a non-positive weight.
            continue;
        }
        // Channel groups solved together (indices into `columns`): each neutrosophic degree
        // alone, the intuitionistic truth and falsity by the active-set method, the channels
        // of any other family (the two lanes of a wide family together) under its whole rule.
        let all: Vec<usize> = (0..columns.len()).collect();
        let groups: Vec<Vec<usize>> = match layout.membership {
            Family::Neutrosophic => vec![vec![0], vec![1], vec![2]],
            _ => vec![all],
        };
        // The Euclidean channel value (sign applied) of channel `c` at point `j`.
        let euclidean = |inner: &[Vec<f64>], j: usize, c: usize| {
            let (column, sign) = columns[c];
            sign * inner[j][base + column] / weights[j]
        };
        let breaks = |inner: &[Vec<f64>], group: &[usize]| {
            (0..n).any(|j| {
                let values: Vec<f64> = group.iter().map(|&c| euclidean(inner, j, c)).collect();
                match layout.membership {
                    Family::Neutrosophic => !(0.0..=1.0).contains(&values[0]),
                    family => family.check(&values).is_err(),
                }
            })
        };
        for group in &groups {
            if !breaks(inner, group) {
                continue;
            }
            let k = group.len();
            // In T = (w T) / w: the matrix D A D and right-hand side D b, D = diag(w).
            let mut band = Band::zeros(n, n.saturating_sub(1));
            for r in 0..n {
                for c in 0..=r {
                    band.add(r, c, weights[r] * a[r][c] * weights[c]);
                }
            }
            let mut rhs = vec![0.0; n * k];
            let mut start = vec![0.0; n * k];
            for j in 0..n {
                for (slot, &c) in group.iter().enumerate() {
                    let (column, sign) = columns[c];
                    rhs[j * k + slot] = sign * weights[j] * b[j][base + column];
                    start[j * k + slot] = euclidean(inner, j, c);
                }
            }
            let matrix = Normal::Open(band);
            let solution = match layout.membership {
                Family::Neutrosophic | Family::Fuzzy | Family::Intuitionistic => {
                    qp::solve(&matrix, k, &rhs, &start)?.x
                }
                family => convex::solve_family(&matrix, family, &rhs, &start)?.x,
            };
            for j in 0..n {
                for (slot, &c) in group.iter().enumerate() {
                    let (column, sign) = columns[c];
                    inner[j][base + column] = sign * weights[j] * solution[j * k + slot];
                }
            }
        }
        // The channels the rule derives, and the slots that hold none.
        let (t, i, f) = (
            base + layout.truth,
            base + layout.truth + 1,
            base + layout.truth + 2,
        );
        for (j, row) in inner.iter_mut().enumerate() {
            let w = weights[j];
            if layout.membership == Family::Intuitionistic {
                row[i] = w * (1.0 - row[t] / w - row[f] / w).max(0.0);
            } else {
                for &column in &empty {
                    row[base + column] = 0.0;
                }
            }
        }
    }
    Some(())
}

fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// `∫_0^1 B_j^m(s) B_k^n(s) ds`.
fn gram(m: usize, j: usize, n: usize, k: usize) -> f64 {
    binomial(m, j) * binomial(n, k) / ((m + n + 1) as f64 * binomial(m + n, j + k))
}

/// Solves `a x = b` (`a` square, rows of `b` the right-hand sides per channel) by Gaussian
/// elimination with partial pivoting; `None` when singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            let f = a[row][col] / a[col][col];
            if f != 0.0 {
                for c in col..n {
                    a[row][c] -= f * a[col][c];
                }
                let (top, rest) = b.split_at_mut(row);
                for (x, y) in rest[0].iter_mut().zip(&top[col]) {
                    *x -= f * y;
                }
            }
        }
    }
    let mut x = vec![vec![0.0; b.first().map_or(0, Vec::len)]; n];
    for row in (0..n).rev() {
        let mut v = b[row].clone();
        for c in row + 1..n {
            for (vi, xi) in v.iter_mut().zip(&x[c]) {
                *vi -= a[row][c] * xi;
            }
        }
        for vi in &mut v {
            *vi /= a[row][row];
        }
        x[row] = v;
    }
    Some(x)
}

/// The degree-(p-1) Bézier rows nearest (L2) to the degree-p rows `p_rows`, ends kept, the
/// degrees within the rule of `layout` ([`bound_degrees`]; rows without degrees: `None`).
fn reduce_piece(p_rows: &[Vec<f64>], layout: Option<&DegreeLayout>) -> Option<Vec<Vec<f64>>> {
    let p = p_rows.len() - 1;
    let m = p - 1;
    let stride = p_rows[0].len();
    let (first, last) = (p_rows[0].clone(), p_rows[p].clone());
    if m == 1 {
        return Some(vec![first, last]);
    }
    let unknowns = m - 1;
    let a: Vec<Vec<f64>> = (1..m)
        .map(|j| (1..m).map(|k| gram(m, j, m, k)).collect())
        .collect();
    let b: Vec<Vec<f64>> = (1..m)
        .map(|j| {
            (0..stride)
                .map(|c| {
                    let target: f64 = (0..=p).map(|i| gram(m, j, p, i) * p_rows[i][c]).sum();
                    target - gram(m, j, m, 0) * first[c] - gram(m, j, m, m) * last[c]
                })
                .collect()
        })
        .collect();
    debug_assert_eq!(a.len(), unknowns);
    let mut inner = solve(a.clone(), b.clone())?;
    if let Some(layout) = layout {
        bound_degrees(&a, &b, &mut inner, layout)?;
    }
    let mut out = Vec::with_capacity(m + 1);
    out.push(first);
    out.extend(inner);
    out.push(last);
    Some(out)
}

impl Spline {
    /// The spline of degree `p - 1` made of the reduced Bézier pieces, joined C0 (interior
    /// breakpoints of multiplicity `p - 1`), on the same domain; `None` for degree below 2 or
    /// a singular system. Non-rational splines only (a rational one goes through its
    /// homogeneous form).
    pub(crate) fn reduced_pieces(&self, layout: &DegreeLayout) -> Option<Spline> {
        debug_assert!(self.weights.is_none());
        let p = self.degree();
        if p < 2 {
            return None;
        }
        let m = p - 1;
        let stride = self.stride;
        let segments = self.bezier_segments();
        let mut rows: Vec<Vec<f64>> = Vec::new();
        let domain = self.knots.domain();
        let mut knots: Vec<f64> = vec![domain.start; m + 1];
        for (k, seg) in segments.iter().enumerate() {
            let data = seg.packed.data();
            let p_rows: Vec<Vec<f64>> = data.chunks_exact(stride).map(<[f64]>::to_vec).collect();
            let q = reduce_piece(&p_rows, Some(layout))?;
            if k == 0 {
                rows.extend(q);
            } else {
                // The joint: the previous piece's end and this one's start are the same point
                // of the curve; keep their mean.
                if let Some(prev) = rows.last_mut() {
                    for (a, b) in prev.iter_mut().zip(&q[0]) {
                        *a = 0.5 * (*a + b);
                    }
                }
                rows.extend(q.into_iter().skip(1));
                knots.extend(std::iter::repeat_n(seg.start, m));
            }
        }
        knots.extend(std::iter::repeat_n(domain.end, m + 1));
        Some(Spline {
            knots: KnotVector::from_parts_unchecked(m, knots),
            stride,
            data: rows.concat(),
            weights: None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Gram values against their integrals in closed form: ∫ B_0^1 B_0^1 = ∫ (1-s)^2 =
    /// 1/3, ∫ B_1^2 B_0^1 = ∫ 2 s (1 - s)^2 = 1/6.
    #[test]
    fn gram_values() {
        assert!((gram(1, 0, 1, 0) - 1.0 / 3.0).abs() < 1e-16);
        assert!((gram(2, 1, 1, 0) - 1.0 / 6.0).abs() < 1e-16);
    }

    /// An elevated cubic reduces back to the cubic exactly.
    #[test]
    fn an_elevated_piece_comes_back() {
        let cubic = vec![
            vec![0.0, 1.0],
            vec![1.0, 3.0],
            vec![3.0, -2.0],
            vec![4.0, 0.5],
        ];
        // Elevate to degree 4: Q_i = i/4 P_{i-1} + (1 - i/4) P_i.
        let mut quartic = vec![cubic[0].clone()];
        for i in 1..4 {
            let a = i as f64 / 4.0;
            quartic.push(
                (0..2)
                    .map(|c| a * cubic[i - 1][c] + (1.0 - a) * cubic[i][c])
                    .collect(),
            );
        }
        quartic.push(cubic[3].clone());
        let back = reduce_piece(&quartic, None).unwrap();
        for (r, s) in back.iter().zip(&cubic) {
            for (x, y) in r.iter().zip(s) {
                assert!((x - y).abs() < 1e-13, "{back:?}");
            }
        }
    }
}
