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

/// The normal matrix `M` of a fit and the right-hand sides `b[lane][slot][i]` of the degree
/// slots of both lanes of an interval-valued or bipolar family.
pub(super) type LaneSystem = (Normal, [[Vec<f64>; 3]; 2]);

/// The control degrees of both lanes per unknown (`control[i][lane]` = the lane's truth,
/// indeterminacy and falsity slots), and the values on a bound of the rule.
pub(super) struct BoundedLanes {
    pub(super) control: Vec<[[f64; 3]; 2]>,
    pub(super) at_bound: Vec<AtBound>,
}

/// The control degrees of a family of two lanes (docs/model.md, "Lanes") under its whole rule,
/// from the unconstrained solutions `free[lane][slot][i]` of the slots.
///
/// The slots map linearly onto the family's channels ([`Family::join_slots`]: a slot holds a
/// channel or its negation, an empty slot is 0 and its least squares, of zero data, is 0), and
/// negating a channel's value and data leaves its least squares unchanged, so the fit of the
/// slots is the fit of the channels: the free channels where every control point obeys the
/// rule, else the solution of [`convex::solve_family`] with all of the family's channels at
/// once (`lower <= upper` and `T_U + F_U <= 1` join the lanes), whose rows obey the rule
/// exactly; mapped back to the slots by [`crate::family::Lane::slot_values`]. `system` builds
/// the normal equations; it is called (once) only when a free value breaks the rule. Records
/// the values on a bound: a channel at an end of its box, and the rule's sum at 1.
///
/// # Errors
/// [`FitError::Singular`] when the problem cannot be solved, or the error of `system`.
pub(super) fn bounded_lanes(
    free: [[Vec<f64>; 3]; 2],
    family: Family,
    system: &mut dyn FnMut() -> Result<LaneSystem, FitError>,
) -> Result<BoundedLanes, FitError> {
    let n = free[0][0].len();
    let k = family.channel_count();
    let channels = |slots: &[[Vec<f64>; 3]; 2]| -> Vec<f64> {
        (0..n)
            .flat_map(|i| {
                let lanes = slots.each_ref().map(|lane| lane.each_ref().map(|s| s[i]));
                family.join_slots(&lanes).to_vec()
            })
            .collect()
    };
    let start = channels(&free);
    let x = if start.chunks_exact(k).all(|row| family.check(row).is_ok()) {
        start
    } else {
        let (matrix, rhs) = system()?;
        let b = channels(&rhs);
        convex::solve_family(&matrix, family, &b, &start)
            .ok_or(FitError::Singular)?
            .x
    };
    let names = family.channels();
    let lanes = family.lanes();
    let mut control = Vec::with_capacity(n);
    let mut at_bound = Vec::new();
    for (i, row) in x.chunks_exact(k).enumerate() {
        control.push([lanes[0].slot_values(row), lanes[1].slot_values(row)]);
        for (c, &value) in row.iter().enumerate() {
            let (low, high) = family.channel_range(c);
            if value == low || value == high {
                at_bound.push(AtBound {
                    index: i,
                    channel: names[c].to_owned(),
                    bound: value,
                });
            }
        }
        if let Some((terms, sum)) = family.rule_sum(row) {
            if sum >= 1.0 - RULE_TOLERANCE {
                at_bound.push(AtBound {
                    index: i,
                    channel: terms,
                    bound: 1.0,
                });
            }
        }
    }
    at_bound.sort_by(|a, b| a.index.cmp(&b.index).then(a.channel.cmp(&b.channel)));
    Ok(BoundedLanes { control, at_bound })
}
