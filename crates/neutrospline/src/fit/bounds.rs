//! The degree channels under the bounds of the membership rule (docs/model.md section 8),
//! shared by curve and surface fits: the unconstrained least-squares values where they keep
//! to the bounds, else the active-set solution of [`qp`] on the fit's normal matrix.

use super::banded::Normal;
use super::report::AtBound;
use super::{channel_names, convex, qp, FitError};
use crate::degrees::{DegreeKind, Degrees, Family};
use crate::family::RULE_TOLERANCE;

/// The normal matrix `M` of a fit and the right-hand sides `b[c][i]` of the degree channels
/// (truth, indeterminacy, falsity) at each unknown `i`.
pub(super) type DegreeSystem = (Normal, [Vec<f64>; 3]);

/// The control degrees `[truth, indeterminacy, falsity]` per unknown, and the values on a
/// bound (sorted by unknown, then channel).
pub(super) struct Bounded {
    pub(super) control: Vec<[f64; 3]>,
    pub(super) at_bound: Vec<AtBound>,
}

/// The control degrees under `membership`'s bounds, from the unconstrained solutions
/// `free[c][i]`. `system` builds the normal equations; it is called (once) only when a free
/// value leaves the bounds.
///
/// # Errors
/// [`FitError::Singular`] when the bounded problem cannot be solved, or the error of `system`.
pub(super) fn bounded_degrees(
    free: [Vec<f64>; 3],
    membership: Family,
    system: &mut dyn FnMut() -> Result<DegreeSystem, FitError>,
) -> Result<Bounded, FitError> {
    let n = free[0].len();
    let mut built: Option<DegreeSystem> = None;
    let mut at_bound = Vec::new();
    let mut bounded = |columns: &[usize]| -> Result<Vec<Vec<f64>>, FitError> {
        let k = columns.len();
        let feasible = (0..n).all(|i| {
            columns.iter().all(|&c| (0.0..=1.0).contains(&free[c][i]))
                && (k == 1 || free[columns[0]][i] + free[columns[1]][i] <= 1.0)
        });
        if feasible {
            return Ok(columns.iter().map(|&c| free[c].clone()).collect());
        }
        if built.is_none() {
            built = Some(system()?);
        }
        let (matrix, rhs) = built
            .as_ref()
            .unwrap_or_else(|| unreachable!("built above"));
        let mut start = vec![0.0; n * k];
        let mut b = vec![0.0; n * k];
        for (j, &c) in columns.iter().enumerate() {
            for i in 0..n {
                start[i * k + j] = free[c][i];
                b[i * k + j] = rhs[c][i];
            }
        }
        let solution = qp::solve(matrix, k, &b, &start).ok_or(FitError::Singular)?;
        for (i, active) in solution.active.iter().enumerate() {
            for c in active {
                let (channel, bound) = match c {
                    qp::Bound::Lower(j) => (channel_names(0)[columns[*j]], 0.0),
                    qp::Bound::Upper => (channel_names(0)[columns[0]], 1.0),
                    qp::Bound::Sum => ("truth + falsity", 1.0),
                };
                at_bound.push(AtBound {
                    index: i,
                    channel: channel.to_owned(),
                    bound,
                });
            }
        }
        Ok((0..k)
            .map(|j| (0..n).map(|i| solution.x[i * k + j]).collect())
            .collect())
    };
    let mut control = vec![[0.0; 3]; n];
    match membership {
        Family::Neutrosophic => {
            for c in 0..3 {
                let values = bounded(&[c])?.remove(0);
                for (i, v) in values.into_iter().enumerate() {
                    control[i][c] = v.clamp(0.0, 1.0);
                }
            }
        }
        Family::Intuitionistic => {
            let tf = bounded(&[0, 2])?;
            for i in 0..n {
                let t = tf[0][i].clamp(0.0, 1.0);
                let f = tf[1][i].clamp(0.0, 1.0 - t);
                control[i] = [t, 1.0 - t - f, f];
            }
        }
        Family::Fuzzy => {
            let t = bounded(&[0])?.remove(0);
            for i in 0..n {
                control[i] = [t[i].clamp(0.0, 1.0), 0.0, 0.0];
            }
        }
        family => {
            control = under_rule(&free, family, &mut built, system, &mut at_bound)?;
        }
    }
    // Values exactly on a bound that the unconstrained solution reached by itself.
    for (i, row) in control.iter().enumerate() {
        for c in 0..3 {
            let name = channel_names(0)[c];
            if !membership.carries(DegreeKind::ALL[c]) {
                continue;
            }
            for bound in [0.0, 1.0] {
                if row[c] == bound && !at_bound.iter().any(|a| a.index == i && a.channel == name) {
                    at_bound.push(AtBound {
                        index: i,
                        channel: name.to_owned(),
                        bound,
                    });
                }
            }
        }
    }
    at_bound.sort_by(|a, b| a.index.cmp(&b.index).then(a.channel.cmp(&b.channel)));
    Ok(Bounded { control, at_bound })
}

/// The control degrees `[truth, indeterminacy, falsity]` as [`Degrees`] of `membership`
/// (valid by construction: [`bounded_degrees`] keeps them within the rule).
pub(super) fn degrees_of([t, i, f]: [f64; 3], membership: Family) -> Degrees {
    let given = |kind: DegreeKind, v: f64| membership.carries(kind).then_some(v);
    let degrees = if membership == Family::Intuitionistic {
        Degrees::intuitionistic(t, f)
    } else {
        Degrees::with_membership(
            membership,
            t,
            given(DegreeKind::Indeterminacy, i),
            given(DegreeKind::Falsity, f),
        )
    };
    degrees.unwrap_or_else(|_| Degrees::new_unchecked(t, i, f))
}

/// The control degrees under the rule of a family outside the three of the bounded
/// active-set method ([`qp`]): the free values where every control point obeys the rule, else
/// the solution of [`convex::solve_family`] on the fit's normal matrix, whose rows obey the
/// rule exactly. Records the values on a bound: a channel at 0 or 1, or the rule's sum at 1.
fn under_rule(
    free: &[Vec<f64>; 3],
    family: Family,
    built: &mut Option<DegreeSystem>,
    system: &mut dyn FnMut() -> Result<DegreeSystem, FitError>,
    at_bound: &mut Vec<AtBound>,
) -> Result<Vec<[f64; 3]>, FitError> {
    let n = free[0].len();
    let slots: Vec<usize> = DegreeKind::ALL
        .into_iter()
        .filter(|kind| family.carries(*kind))
        .map(DegreeKind::index)
        .collect();
    let k = slots.len();
    let row = |i: usize| -> Vec<f64> { slots.iter().map(|&c| free[c][i]).collect() };
    let rows: Vec<Vec<f64>> = if (0..n).all(|i| family.check(&row(i)).is_ok()) {
        (0..n).map(row).collect()
    } else {
        if built.is_none() {
            *built = Some(system()?);
        }
        let (matrix, rhs) = built
            .as_ref()
            .unwrap_or_else(|| unreachable!("built above"));
        let mut start = vec![0.0; n * k];
        let mut b = vec![0.0; n * k];
        for i in 0..n {
            for (j, &c) in slots.iter().enumerate() {
                start[i * k + j] = free[c][i];
                b[i * k + j] = rhs[c][i];
            }
        }
        let solution =
            convex::solve_family(matrix, family, &b, &start).ok_or(FitError::Singular)?;
        solution.x.chunks_exact(k).map(<[f64]>::to_vec).collect()
    };
    let mut control = vec![[0.0; 3]; n];
    for (i, values) in rows.iter().enumerate() {
        for (j, &c) in slots.iter().enumerate() {
            control[i][c] = values[j];
        }
        if let Some((terms, sum)) = family.rule_sum(values) {
            if sum >= 1.0 - RULE_TOLERANCE {
                at_bound.push(AtBound {
                    index: i,
                    channel: terms,
                    bound: 1.0,
                });
            }
        }
    }
    Ok(control)
}
