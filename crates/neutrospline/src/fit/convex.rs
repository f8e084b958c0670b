//! The degree channels' least squares under the whole rule of any membership family
//! (docs/model.md, "Membership families"; SPEC section 10).
//!
//! # Problem
//!
//! With the fit's normal matrix `M` (order `n`, banded or cyclic-banded, symmetric positive
//! definite) shared by the `k` channels of the family, and the variables interleaved (value
//! `(i, c)` of control point `i`, channel `c`, at `i k + c`):
//!
//! ```text
//! minimise   f(x) = 1/2 x^T (M (x) I_k) x - b^T x
//! subject to x_i in K   for every control point i,
//! ```
//!
//! where `K` is the family's rule written as constraints `g_j(x_i) <= 0`: the linear ones of
//! [`Family::linear_constraints`] (boxes, `lower <= upper` of interval degrees, the sums
//! `T + F <= 1`, `T + I + F <= 1`, `T_U + F_U <= 1`) and, for a round family, the power rule
//! `sum_{c in S} x_c^p - 1 <= 0` of [`Family::power_rule`] (`p >= 2`, convex on the orthant
//! that the linear constraints keep). The problem is convex with a strictly convex objective:
//! one minimiser `x*`.
//!
//! # Method: a primal-dual interior-point method on the band
//!
//! With slacks `s_j = -g_j(x) > 0` and multipliers `lambda_j > 0` (per point and constraint)
//! the perturbed KKT conditions are
//!
//! ```text
//! r = grad f(x) + sum_j lambda_j grad g_j(x) = 0,     lambda_j s_j = sigma mu.
//! ```
//!
//! Newton's method on them, with `Delta lambda` eliminated, gives one symmetric positive
//! definite system per iteration,
//!
//! ```text
//! (M (x) I_k + blockdiag_i [ sum_j lambda_j hess g_j + sum_j (lambda_j / s_j) grad g_j grad g_j^T ]) dx
//!     = -(grad f(x) + sum_j (c_j / s_j) grad g_j),
//! Delta lambda_j = -lambda_j + c_j / s_j + (lambda_j / s_j) grad g_j . dx,
//! ```
//!
//! whose matrix has the band of `M (x) I_k` (the added blocks are `k x k` on the diagonal), so
//! one banded (or cyclic-banded) Cholesky factorisation per iteration, `O(n k^3 w^2)`. The
//! centring `c_j` follows Mehrotra's predictor-corrector: an affine step (`c_j = 0`) gives the
//! complementarity `mu_aff` it would reach, `sigma = (mu_aff / mu)^3`, and the corrector uses
//! `c_j = sigma mu - Delta s_j^aff Delta lambda_j^aff` with the same factor. One step length
//! `alpha` for primal and dual: 0.995 of the distance to the boundary (`s > 0`, `lambda > 0`;
//! for the power rule, backtracking until every slack keeps 0.5 % of its value).
//!
//! # Termination: a certified bound on the objective gap
//!
//! For feasible `x`, `lambda >= 0` and any feasible `y`, convexity of `f` and of each `g_j`
//! (`grad g_j(x) . (y - x) <= g_j(y) - g_j(x) <= s_j`) gives
//!
//! ```text
//! f(y) >= f(x) + r . (y - x) - sum_j lambda_j s_j,
//! ```
//!
//! so `f(x) - f(x*) <= sum_j lambda_j s_j + sum_{i,c} |r_ic| w_c =: gap`, with `w_c = 1` the
//! width of channel `c`'s box (`|y_ic - x_ic| <= 1`). The iteration stops when
//! `gap <= 1e-13 max(1, |f|)`, when the gap has not decreased for 10 iterations (rounding
//! floor), or after 200 iterations, and keeps the iterate with the smallest gap. Interior-point
//! iterations are nearly independent of the conditioning of `M` (tens of factorisations; the
//! tests measure them on an ill-conditioned smoothing fit).
//!
//! # Finish: exact feasibility
//!
//! The interior iterate is strictly feasible but only close to its active constraints.
//! Constraint `j` of point `i` is identified as active when `s_j <= lambda_j` and
//! `s_j <= 1e-6` (under strict complementarity `s_j ~ mu / lambda_j` tends to 0 while
//! `lambda_j` stays away from 0). Each point is then put exactly on its active constraints:
//! the orthogonal projection onto the affine set of its active linear constraints (box ends
//! and equal interval ends set exactly), the power-sum channels scaled radially onto
//! `sum x_c^p = 1`, and finally [`Family::project`] (a valid point is left unchanged; it only
//! moves by a few units in the last place what rounding left outside), so that
//! [`Family::check`] accepts every point with no tolerance. The gap bound above is evaluated
//! again at the final point (with the same multipliers, valid for any feasible point and
//! `lambda >= 0`) and returned in [`Solution::gap_bound`]: the objective of the returned point
//! is within that certified bound of the optimum.
//!
//! # Polish and active-set corrections
//!
//! Newton's method on the problem with each point's identified constraints as equalities then
//! removes the interior iterate's `O(mu)` distance to the optimum. On an ill-conditioned fit
//! the interior iteration can stall (rounding) with an ambiguous identification, so up to 40
//! corrections follow: at a point left with a residual, a constraint whose nonnegative
//! least-squares multiplier is 0 is released, a constraint a point sits on is added, and the
//! polish is repeated from the last point. The bound need not fall at every correction (a
//! released constraint can send a point onto another one first); they stop after 3 without a
//! smaller bound, and the point with the smallest certified bound is returned. On the reference problems of
//! `scripts/reference/make_rule_fit_reference.py` (condition numbers up to 2e9) the objective
//! is within 5e-11 relative of the reference optimum (worst: intuitionistic, n = 60, 4.3e-11;
//! with at most 4 monotone corrections an earlier version of those problems left 9.4e-10 on
//! the ill-conditioned interval-intuitionistic case).

use super::banded::Normal;
use crate::family::{Family, LinearConstraint, PowerRule, MAX_CHANNELS};

/// The stopping tolerance on the certified gap, relative to `max(1, |f|)`.
const GAP_TOLERANCE: f64 = 1e-13;
/// The most interior-point iterations.
const MAX_ITERATIONS: usize = 200;
/// Iterations without a smaller gap after which rounding is taken to have won.
const STALL_ITERATIONS: usize = 10;
/// The fraction of the distance to the boundary a step may go.
const TO_BOUNDARY: f64 = 0.995;
/// The most Newton steps of the active-set polish.
const POLISH_STEPS: usize = 12;
/// The largest slack of a constraint identified as active.
const ACTIVE_SLACK: f64 = 1e-6;
/// The most active-set corrections after the polish.
const CORRECTIONS: usize = 40;
/// Corrections without a smaller certified bound after which they stop.
const CORRECTION_STALL: usize = 3;
/// Block Gauss-Seidel sweeps tried when the corrections stall.
const GAUSS_SEIDEL_SWEEPS: usize = 200;

/// A constraint of the rule that holds with equality at a control point of the solution.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Active {
    /// Channel `channel` at the lower end of its box (`0`, or `-1` for a negative bipolar
    /// degree).
    Lower { channel: usize, bound: f64 },
    /// Channel `channel` at the upper end of its box (`1`, or `0` for a negative bipolar
    /// degree).
    Upper { channel: usize, bound: f64 },
    /// An interval degree collapsed: `lower = upper`.
    Order { lower: usize, upper: usize },
    /// A linear sum rule at 1: `sum_{c in channels} x_c = 1` (intuitionistic `T + F`, picture
    /// `T + I + F`, interval-intuitionistic `T_U + F_U`).
    Sum { channels: Vec<usize> },
    /// The round rule at 1: `sum_{c in channels} x_c^power = 1`.
    Power {
        power: u32,
        channels: &'static [usize],
    },
}

impl Active {
    /// The constraint as an equation in the family's channel names: `truth = 0`,
    /// `truth_lower = truth_upper`, `truth + falsity = 1`, `truth^2 + falsity^2 = 1`.
    #[allow(dead_code)]
    pub(crate) fn describe(&self, family: Family) -> String {
        let names = family.channels();
        let name = |c: usize| names.get(c).copied().unwrap_or("?");
        match self {
            Active::Lower { channel, bound } | Active::Upper { channel, bound } => {
                format!("{} = {bound}", name(*channel))
            }
            Active::Order { lower, upper } => format!("{} = {}", name(*lower), name(*upper)),
            Active::Sum { channels } => {
                let terms: Vec<&str> = channels.iter().map(|&c| name(c)).collect();
                format!("{} = 1", terms.join(" + "))
            }
            Active::Power { power, channels } => {
                let terms: Vec<String> = channels
                    .iter()
                    .map(|&c| format!("{}^{power}", name(c)))
                    .collect();
                format!("{} = 1", terms.join(" + "))
            }
        }
    }

    /// What a linear constraint of [`Family::linear_constraints`] says when it is active.
    fn of_linear(constraint: &LinearConstraint) -> Active {
        let coefficients = &constraint.coefficients;
        let positive: Vec<usize> = (0..coefficients.len())
            .filter(|&c| coefficients[c] > 0.0)
            .collect();
        let negative: Vec<usize> = (0..coefficients.len())
            .filter(|&c| coefficients[c] < 0.0)
            .collect();
        match (positive.as_slice(), negative.as_slice()) {
            ([], [channel]) => Active::Lower {
                channel: *channel,
                bound: -constraint.bound / -coefficients[*channel],
            },
            ([channel], []) => Active::Upper {
                channel: *channel,
                bound: constraint.bound / coefficients[*channel],
            },
            ([lower], [upper]) => Active::Order {
                lower: *lower,
                upper: *upper,
            },
            _ => Active::Sum { channels: positive },
        }
    }
}

/// The solution of [`solve_family`].
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Solution {
    /// Interleaved values: channel `c` of control point `i` at `i k + c`; every point passes
    /// [`Family::check`].
    pub(crate) x: Vec<f64>,
    /// The constraints active at each control point.
    pub(crate) active: Vec<Vec<Active>>,
    /// The interior-point iterations (banded factorisations) used.
    pub(crate) iterations: usize,
    /// A certified upper bound of `f(x) - f(x*)` (module documentation).
    pub(crate) gap_bound: f64,
}

/// The rule of one point as constraints `g_j(x) <= 0`: the linear ones, then the power rule.
struct Rule {
    k: usize,
    linear: Vec<LinearConstraint>,
    power: Option<PowerRule>,
}

impl Rule {
    fn new(family: Family) -> Rule {
        Rule {
            k: family.channel_count(),
            linear: family.linear_constraints(),
            power: family.power_rule(),
        }
    }

    /// The number of constraints per point.
    fn count(&self) -> usize {
        self.linear.len() + usize::from(self.power.is_some())
    }

    /// The slack `-g_j(x)` of constraint `j`.
    fn slack(&self, j: usize, x: &[f64]) -> f64 {
        match self.linear.get(j) {
            Some(constraint) => constraint.slack(x),
            None => self.power.map_or(0.0, |rule| {
                1.0 - rule
                    .channels
                    .iter()
                    .map(|&c| power_of(x[c].max(0.0), rule.power))
                    .sum::<f64>()
            }),
        }
    }

    /// The gradient of `g_j` at `x`.
    fn gradient(&self, j: usize, x: &[f64]) -> [f64; MAX_CHANNELS] {
        let mut out = [0.0; MAX_CHANNELS];
        match self.linear.get(j) {
            Some(constraint) => out[..self.k].copy_from_slice(&constraint.coefficients),
            None => {
                if let Some(rule) = self.power {
                    let p = f64::from(rule.power);
                    for &c in rule.channels {
                        out[c] = p * power_of(x[c].max(0.0), rule.power - 1);
                    }
                }
            }
        }
        out
    }

    /// The diagonal of the Hessian of `g_j` at `x` (zero for the linear constraints).
    fn curvature(&self, j: usize, x: &[f64]) -> [f64; MAX_CHANNELS] {
        let mut out = [0.0; MAX_CHANNELS];
        if j == self.linear.len() {
            if let Some(rule) = self.power {
                let p = f64::from(rule.power);
                for &c in rule.channels {
                    out[c] = p * (p - 1.0) * power_of(x[c].max(0.0), rule.power - 2);
                }
            }
        }
        out
    }

    /// Constraint `j` as an [`Active`] description.
    fn describe(&self, j: usize) -> Active {
        match (self.linear.get(j), self.power) {
            (Some(constraint), _) => Active::of_linear(constraint),
            (None, Some(rule)) => Active::Power {
                power: rule.power,
                channels: rule.channels,
            },
            (None, None) => Active::Sum {
                channels: Vec::new(),
            },
        }
    }

    /// A point strictly inside the rule: every slack positive.
    fn center(&self, family: Family) -> [f64; MAX_CHANNELS] {
        let mut out = [0.0; MAX_CHANNELS];
        let fraction = if family.power().is_some() {
            0.25 / self.k as f64
        } else {
            0.5
        };
        let pairs = family.interval_pairs();
        for (c, value) in out.iter_mut().enumerate().take(self.k) {
            let (low, high) = family.channel_range(c);
            let share = if pairs.iter().any(|&(l, _)| l == c) {
                0.5 * fraction
            } else {
                fraction
            };
            *value = low + share * (high - low);
        }
        out
    }
}

/// `x^p` for `x >= 0` (`p` saturated at `i32::MAX`: `x^p` is then 0, or 1 at `x = 1`).
fn power_of(x: f64, p: u32) -> f64 {
    x.powi(i32::try_from(p).unwrap_or(i32::MAX))
}

/// `g = (M (x) I_k) x - b`.
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

/// `f(x) = 1/2 x^T (M (x) I_k) x - b^T x` from the gradient `g = (M (x) I_k) x - b`:
/// `f = 1/2 x . (g - b)`.
fn objective_from_gradient(x: &[f64], g: &[f64], b: &[f64]) -> f64 {
    0.5 * x
        .iter()
        .zip(g.iter().zip(b))
        .map(|(x, (g, b))| x * (g - b))
        .sum::<f64>()
}

/// The state of the iteration: the point, the slacks and the multipliers (`count` of each
/// per point).
struct Iterate {
    x: Vec<f64>,
    slack: Vec<f64>,
    lambda: Vec<f64>,
}

/// The quantities of the termination test at an iterate.
struct Measures {
    objective: f64,
    /// `sum lambda_j s_j`.
    complementarity: f64,
    /// The measure of progress: complementarity + infeasibility + `sum |r|`; at a feasible
    /// point with `s_j = -g_j(x)` it is the certified gap bound.
    gap: f64,
    /// `grad f(x)`.
    gradient: Vec<f64>,
    /// `g_j(x) + s_j`, `count` per point.
    primal: Vec<f64>,
}

fn measure(m: &Normal, rule: &Rule, b: &[f64], state: &Iterate) -> Measures {
    let (n, k, count) = (m.order(), rule.k, rule.count());
    let mut grad = vec![0.0; n * k];
    gradient(m, k, &state.x, b, &mut grad);
    let objective = objective_from_gradient(&state.x, &grad, b);
    let mut primal = vec![0.0; n * count];
    let (mut complementarity, mut infeasibility, mut residual) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let point = &state.x[i * k..(i + 1) * k];
        let mut r = [0.0; MAX_CHANNELS];
        r[..k].copy_from_slice(&grad[i * k..(i + 1) * k]);
        for j in 0..count {
            let idx = i * count + j;
            let lambda = state.lambda[idx];
            let p = state.slack[idx] - rule.slack(j, point);
            primal[idx] = p;
            complementarity += lambda * state.slack[idx];
            infeasibility += (1.0 + lambda) * p.abs();
            let a = rule.gradient(j, point);
            for c in 0..k {
                r[c] += lambda * a[c];
            }
        }
        residual += r[..k].iter().map(|v| v.abs()).sum::<f64>();
    }
    Measures {
        objective,
        complementarity,
        gap: complementarity + infeasibility + residual,
        gradient: grad,
        primal,
    }
}

/// Solves the least squares of the `k = family.channel_count()` interleaved channels with
/// right-hand sides `b` (`n k` values) under the family's whole rule at every control point,
/// warm-started from `start` (`n k` values, e.g. the unconstrained solution; projected onto
/// the rule first). The method, its termination and the exact feasibility of the result are
/// described in the module documentation.
///
/// Returns `None` when `M` is singular (not numerically positive definite), and also when
/// `b` or `start` does not have `n k` entries or `b` is not finite (no problem to solve).
pub(crate) fn solve_family(
    m: &Normal,
    family: Family,
    b: &[f64],
    start: &[f64],
) -> Option<Solution> {
    let rule = Rule::new(family);
    let (n, k, count) = (m.order(), rule.k, rule.count());
    if n == 0 || b.len() != n * k || start.len() != n * k || !b.iter().all(|v| v.is_finite()) {
        return None;
    }
    m.factor()?;
    // A strictly interior start: the projected warm start moved a tenth of the way to the
    // centre of the rule.
    let center = rule.center(family);
    let mut x = start.to_vec();
    for point in x.chunks_exact_mut(k) {
        family.project(point);
        for (v, c) in point.iter_mut().zip(&center) {
            *v = 0.9 * *v + 0.1 * c;
        }
    }
    let mut grad = vec![0.0; n * k];
    gradient(m, k, &x, b, &mut grad);
    let scale = 0.1 * grad.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
    let mut slack = vec![0.0; n * count];
    let mut lambda = vec![0.0; n * count];
    for i in 0..n {
        let point = &x[i * k..(i + 1) * k];
        for j in 0..count {
            let s = rule.slack(j, point).max(1e-3);
            slack[i * count + j] = s;
            lambda[i * count + j] = scale / s;
        }
    }
    let mut state = Iterate { x, slack, lambda };
    let mut measures = measure(m, &rule, b, &state);
    let mut best = (measures.gap, state.x.clone(), state.lambda.clone());
    let mut since_best = 0;
    let mut iterations = 0;
    while iterations < MAX_ITERATIONS
        && measures.gap > GAP_TOLERANCE * measures.objective.abs().max(1.0)
        && since_best < STALL_ITERATIONS
    {
        iterations += 1;
        if !newton_step(m, &rule, &mut state, &measures) {
            break;
        }
        measures = measure(m, &rule, b, &state);
        if measures.gap < best.0 {
            best = (measures.gap, state.x.clone(), state.lambda.clone());
            since_best = 0;
        } else {
            since_best += 1;
        }
    }
    let (_, mut x, lambda) = best;
    let mut active = finish(family, &rule, &mut x, &lambda);
    let interior_bound = certified_gap(m, &rule, b, &x, &lambda);
    let (polished, polished_bound) = polish(m, family, &rule, b, x, &active);
    // Active-set corrections: at a point left with a residual, a constraint whose
    // least-squares multiplier is 0 is released; a constraint a point sits on is added; then
    // polished again. An ill-conditioned fit can need tens of them, and the bound need not
    // fall at each one: the point with the smallest bound is kept.
    let mut best = (polished.clone(), polished_bound, active.clone());
    let mut x = polished;
    let mut since_best = 0;
    for _ in 0..CORRECTIONS {
        let objective = {
            let mut grad = vec![0.0; n * k];
            gradient(m, k, &best.0, b, &mut grad);
            objective_from_gradient(&best.0, &grad, b)
        };
        if best.1.min(interior_bound) <= GAP_TOLERANCE * objective.abs().max(1.0) {
            break;
        }
        let revised = revise_active(m, &rule, b, &x, &active);
        if revised == active {
            break;
        }
        let (candidate, bound) = polish(m, family, &rule, b, x, &revised);
        if bound < best.1 {
            best = (candidate.clone(), bound, revised.clone());
            since_best = 0;
        } else {
            since_best += 1;
            if since_best >= CORRECTION_STALL {
                break;
            }
        }
        x = candidate;
        active = revised;
    }
    let (mut x, mut polished_bound, mut active) = best;
    // When the corrections stall short of the tolerance, block Gauss-Seidel sweeps (each
    // point's channels set to the exact minimiser over the rule with the others fixed: a
    // projection, since the point's block of the Hessian is `M_ii I_k`) descend from the best
    // point and settle its active set; the polish from their active set is kept if its
    // certified bound is smaller.
    let objective = {
        let mut grad = vec![0.0; n * k];
        gradient(m, k, &x, b, &mut grad);
        objective_from_gradient(&x, &grad, b)
    };
    if polished_bound.min(interior_bound) > GAP_TOLERANCE * objective.abs().max(1.0) {
        let mut y = x.clone();
        gauss_seidel(m, family, b, &mut y, GAUSS_SEIDEL_SWEEPS);
        let settled: Vec<Vec<usize>> = y
            .chunks_exact(k)
            .map(|point| {
                (0..count)
                    .filter(|&j| rule.slack(j, point) <= 1e-12)
                    .collect()
            })
            .collect();
        let (candidate, bound) = polish(m, family, &rule, b, y, &settled);
        if bound < polished_bound {
            (x, polished_bound, active) = (candidate, bound, settled);
        }
    }
    Some(Solution {
        x,
        active: active
            .iter()
            .map(|set| set.iter().map(|&j| rule.describe(j)).collect())
            .collect(),
        iterations,
        gap_bound: interior_bound.min(polished_bound),
    })
}

/// Block Gauss-Seidel on the problem: for each control point in turn, its channels set to the
/// exact minimiser of `f` over the rule with the other points fixed, the projection
/// ([`Family::project`]) of `(b_i - sum_{j != i} M_ij x_j) / M_ii` onto the rule. Every sweep
/// keeps `x` feasible and does not raise `f`.
fn gauss_seidel(m: &Normal, family: Family, b: &[f64], x: &mut [f64], sweeps: usize) {
    let (n, k) = (m.order(), family.channel_count());
    for _ in 0..sweeps {
        for i in 0..n {
            let diagonal = m.get(i, i);
            let mut target = [0.0; MAX_CHANNELS];
            target[..k].copy_from_slice(&b[i * k..(i + 1) * k]);
            for j in m.neighbours(i).into_iter().filter(|&j| j != i) {
                let v = m.get(i, j);
                for c in 0..k {
                    target[c] -= v * x[j * k + c];
                }
            }
            for value in &mut target[..k] {
                *value /= diagonal;
            }
            family.project(&mut target[..k]);
            x[i * k..(i + 1) * k].copy_from_slice(&target[..k]);
        }
    }
}

/// The certified bound `sum_j lambda_j s_j + sum_{i,c} |r_ic|` of the module documentation at
/// a feasible `x`, for multipliers `lambda >= 0` (`count` per point; negative ones taken as 0).
fn certified_gap(m: &Normal, rule: &Rule, b: &[f64], x: &[f64], lambda: &[f64]) -> f64 {
    let (n, k, count) = (m.order(), rule.k, rule.count());
    let mut grad = vec![0.0; n * k];
    gradient(m, k, x, b, &mut grad);
    let mut bound = 0.0;
    for i in 0..n {
        let point = &x[i * k..(i + 1) * k];
        let mut r = [0.0; MAX_CHANNELS];
        r[..k].copy_from_slice(&grad[i * k..(i + 1) * k]);
        for j in 0..count {
            let multiplier = lambda[i * count + j].max(0.0);
            bound += multiplier * rule.slack(j, point).max(0.0);
            let a = rule.gradient(j, point);
            for c in 0..k {
                r[c] += multiplier * a[c];
            }
        }
        bound += r[..k].iter().map(|v| v.abs()).sum::<f64>();
    }
    bound
}

/// The active sets revised at a feasible `x`: at a point whose stationarity residual with
/// the least-squares multipliers `lambda >= 0` is not negligible, the active constraints with
/// `lambda_j = 0` are released; constraints with slack at most `1e-12` are added.
fn revise_active(
    m: &Normal,
    rule: &Rule,
    b: &[f64],
    x: &[f64],
    active: &[Vec<usize>],
) -> Vec<Vec<usize>> {
    let (n, k, count) = (m.order(), rule.k, rule.count());
    let mut grad = vec![0.0; n * k];
    gradient(m, k, x, b, &mut grad);
    let scale = b.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
    let mut lambda = vec![0.0; count];
    (0..n)
        .map(|i| {
            let point = &x[i * k..(i + 1) * k];
            let g = &grad[i * k..(i + 1) * k];
            point_multipliers(rule, point, g, &active[i], &mut lambda);
            let mut r = [0.0; MAX_CHANNELS];
            r[..k].copy_from_slice(g);
            for &j in &active[i] {
                let a = rule.gradient(j, point);
                for c in 0..k {
                    r[c] += lambda[j] * a[c];
                }
            }
            let stuck = r[..k].iter().map(|v| v.abs()).sum::<f64>() > 1e-13 * scale;
            (0..count)
                .filter(|&j| {
                    if active[i].contains(&j) {
                        !(stuck && lambda[j] == 0.0)
                    } else {
                        rule.slack(j, point) <= 1e-12
                    }
                })
                .collect()
        })
        .collect()
}

/// One predictor-corrector step on the perturbed KKT conditions with slack variables,
/// `g_j(x) + s_j = 0`; `false` when the Newton matrix cannot be factored or no step is
/// possible.
///
/// With the primal residual `p_j = g_j(x) + s_j`, Newton's equations reduce to
/// `(H + sum lambda_j hess g_j + sum (lambda_j / s_j) grad g_j grad g_j^T) dx =
/// -(grad f + sum ((lambda_j p_j + c_j) / s_j) grad g_j)`, `dlambda_j = (lambda_j / s_j)
/// (grad g_j . dx + p_j) - lambda_j + c_j / s_j`, `ds_j = -p_j - grad g_j . dx`.
fn newton_step(m: &Normal, rule: &Rule, state: &mut Iterate, measures: &Measures) -> bool {
    let (n, k, count) = (m.order(), rule.k, rule.count());
    let total = (n * count).max(1) as f64;
    let mu = measures.complementarity / total;
    // The matrix M (x) I_k + per-point blocks.
    let mut h = m.expanded(k);
    for i in 0..n {
        for j in m.neighbours(i) {
            if j > i {
                continue;
            }
            let mij = m.get(i, j);
            for c in 0..k {
                h.add(i * k + c, j * k + c, mij);
            }
        }
        let point = &state.x[i * k..(i + 1) * k];
        let mut block = [[0.0; MAX_CHANNELS]; MAX_CHANNELS];
        for j in 0..count {
            let lambda = state.lambda[i * count + j];
            let s = state.slack[i * count + j];
            let a = rule.gradient(j, point);
            let curvature = rule.curvature(j, point);
            for c in 0..k {
                block[c][c] += lambda * curvature[c];
                for d in 0..=c {
                    block[c][d] += lambda / s * a[c] * a[d];
                }
            }
        }
        for c in 0..k {
            for d in 0..=c {
                if block[c][d] != 0.0 {
                    h.add(i * k + c, i * k + d, block[c][d]);
                }
            }
        }
    }
    // Near the end the blocks' `lambda / s` terms reach 1e12 and more: when rounding breaks
    // the Cholesky factorisation, a growing multiple of the identity (relative to the largest
    // diagonal entry) is added, which only shortens the Newton step slightly.
    let largest = (0..n * k).fold(0.0_f64, |a, r| a.max(h.get(r, r)));
    let mut factor = h.factor();
    let mut shift = 1e-15 * largest;
    while factor.is_none() && shift <= 1e-6 * largest {
        for r in 0..n * k {
            h.add(r, r, shift);
        }
        factor = h.factor();
        shift *= 10.0;
    }
    let Some(factor) = factor else {
        return false;
    };
    let direction = |centring: &[f64]| -> Direction {
        let mut dx: Vec<f64> = measures.gradient.iter().map(|g| -g).collect();
        for i in 0..n {
            let point = &state.x[i * k..(i + 1) * k];
            for j in 0..count {
                let idx = i * count + j;
                let s = state.slack[idx];
                let a = rule.gradient(j, point);
                let weight = (state.lambda[idx] * measures.primal[idx] + centring[idx]) / s;
                for c in 0..k {
                    dx[i * k + c] -= weight * a[c];
                }
            }
        }
        factor.solve(&mut dx);
        let mut dlambda = vec![0.0; n * count];
        let mut ds = vec![0.0; n * count];
        for i in 0..n {
            let point = &state.x[i * k..(i + 1) * k];
            for j in 0..count {
                let idx = i * count + j;
                let (s, lambda) = (state.slack[idx], state.lambda[idx]);
                let a = rule.gradient(j, point);
                let directional: f64 = (0..k).map(|c| a[c] * dx[i * k + c]).sum();
                ds[idx] = -measures.primal[idx] - directional;
                dlambda[idx] =
                    lambda / s * (directional + measures.primal[idx]) - lambda + centring[idx] / s;
            }
        }
        Direction { dx, dlambda, ds }
    };
    // Predictor: no centring.
    let affine = direction(&vec![0.0; n * count]);
    let alpha_affine = linear_step(&state.slack, &state.lambda, &affine);
    let mu_affine = state
        .slack
        .iter()
        .zip(&affine.ds)
        .zip(state.lambda.iter().zip(&affine.dlambda))
        .map(|((s, ds), (l, dl))| (s + alpha_affine * ds) * (l + alpha_affine * dl))
        .sum::<f64>()
        / total;
    let sigma = if mu > 0.0 {
        (mu_affine / mu).clamp(0.0, 1.0).powi(3)
    } else {
        0.0
    };
    // Corrector: centring sigma mu with Mehrotra's second-order term.
    let centring: Vec<f64> = affine
        .ds
        .iter()
        .zip(&affine.dlambda)
        .map(|(ds, dl)| sigma * mu - ds * dl)
        .collect();
    let step = direction(&centring);
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    if !finite(&step.dx) || !finite(&step.dlambda) || !finite(&step.ds) {
        return false;
    }
    let alpha = linear_step(&state.slack, &state.lambda, &step);
    if alpha <= 0.0 {
        return false;
    }
    for (v, d) in state.x.iter_mut().zip(&step.dx) {
        *v += alpha * d;
    }
    for (s, d) in state.slack.iter_mut().zip(&step.ds) {
        *s = (*s + alpha * d).max(f64::MIN_POSITIVE);
    }
    for (l, d) in state.lambda.iter_mut().zip(&step.dlambda) {
        *l = (*l + alpha * d).max(f64::MIN_POSITIVE);
    }
    true
}

/// A Newton direction: the point step, the multiplier steps and the linearised slack steps.
struct Direction {
    dx: Vec<f64>,
    dlambda: Vec<f64>,
    ds: Vec<f64>,
}

/// The largest step `alpha <= 1` keeping `TO_BOUNDARY` of the way to `s + alpha ds = 0` and
/// `lambda + alpha dlambda = 0` (slacks linearised).
fn linear_step(slacks: &[f64], lambda: &[f64], direction: &Direction) -> f64 {
    let mut alpha = 1.0_f64;
    for (s, ds) in slacks.iter().zip(&direction.ds) {
        if *ds < 0.0 {
            alpha = alpha.min(TO_BOUNDARY * s / -ds);
        }
    }
    for (l, dl) in lambda.iter().zip(&direction.dlambda) {
        if *dl < 0.0 {
            alpha = alpha.min(TO_BOUNDARY * l / -dl);
        }
    }
    alpha
}

/// Identifies the active constraints of every point (module documentation), puts the point
/// exactly on them and inside the rule; returns the active constraints (indices into the
/// rule) per point.
fn finish(family: Family, rule: &Rule, x: &mut [f64], lambda: &[f64]) -> Vec<Vec<usize>> {
    let (k, count) = (rule.k, rule.count());
    let n = x.len() / k.max(1);
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let point = &mut x[i * k..(i + 1) * k];
        let multipliers = &lambda[i * count..(i + 1) * count];
        let active: Vec<usize> = (0..count)
            .filter(|&j| {
                let s = rule.slack(j, point);
                s <= multipliers[j] && s <= ACTIVE_SLACK
            })
            .collect();
        snap(family, rule, point, &active);
        out.push(active);
    }
    out
}

/// Puts `point` on the constraints `active` (indices into the rule): onto the affine set of
/// the linear ones (box ends and equal interval ends set exactly), the power-sum channels
/// scaled radially onto `sum x_c^p = 1`, then [`Family::project`] for what rounding left
/// outside.
fn snap(family: Family, rule: &Rule, point: &mut [f64], active: &[usize]) {
    let linear: Vec<usize> = active
        .iter()
        .copied()
        .filter(|&j| j < rule.linear.len())
        .collect();
    onto_affine(point, &rule.linear, &linear);
    for &j in &linear {
        match Active::of_linear(&rule.linear[j]) {
            Active::Lower { channel, bound } | Active::Upper { channel, bound } => {
                point[channel] = bound;
            }
            Active::Order { lower, upper } => {
                let mid = 0.5 * (point[lower] + point[upper]);
                point[lower] = mid;
                point[upper] = mid;
            }
            Active::Sum { .. } | Active::Power { .. } => {}
        }
    }
    if let Some(power_rule) = rule.power {
        if active.contains(&rule.linear.len()) {
            let sum: f64 = power_rule
                .channels
                .iter()
                .map(|&c| power_of(point[c].max(0.0), power_rule.power))
                .sum();
            if sum > 0.0 && sum.is_finite() {
                let factor = sum.powf(-1.0 / f64::from(power_rule.power));
                for &c in power_rule.channels {
                    point[c] = point[c].max(0.0) * factor;
                }
            }
        }
    }
    family.project(point);
}

/// An orthonormal basis of the span of `rows` (modified Gram-Schmidt, dependent rows left
/// out) followed by an orthonormal basis of its complement in `R^k`; returns the basis and the
/// rank.
fn split_basis(
    rows: &[[f64; MAX_CHANNELS]],
    k: usize,
) -> ([[f64; MAX_CHANNELS]; MAX_CHANNELS], usize) {
    let mut basis = [[0.0; MAX_CHANNELS]; MAX_CHANNELS];
    let mut len = 0;
    let units = (0..k).map(|c| {
        let mut e = [0.0; MAX_CHANNELS];
        e[c] = 1.0;
        e
    });
    let mut rank = 0;
    for (index, mut v) in rows.iter().copied().chain(units).enumerate() {
        if len == k {
            break;
        }
        for q in &basis[..len] {
            let dot: f64 = (0..k).map(|c| v[c] * q[c]).sum();
            for c in 0..k {
                v[c] -= dot * q[c];
            }
        }
        let norm = (0..k).map(|c| v[c] * v[c]).sum::<f64>().sqrt();
        if norm > 1e-9 {
            for value in v.iter_mut() {
                *value /= norm;
            }
            basis[len] = v;
            len += 1;
            if index < rows.len() {
                rank = len;
            }
        }
    }
    (basis, rank)
}

/// The multipliers `lambda >= 0` of the active constraints `active` at a point: the least
/// squares solution of `grad f_i + sum_j lambda_j grad g_j = 0` by projected coordinate
/// descent (at most `MAX_CHANNELS` unknowns; exact when the gradients are orthogonal, as for
/// boxes), written into `out` (`count` entries, zero for the inactive constraints).
fn point_multipliers(rule: &Rule, point: &[f64], grad: &[f64], active: &[usize], out: &mut [f64]) {
    let k = rule.k;
    out.iter_mut().for_each(|v| *v = 0.0);
    let rows: Vec<[f64; MAX_CHANNELS]> = active.iter().map(|&j| rule.gradient(j, point)).collect();
    let mut residual = [0.0; MAX_CHANNELS];
    residual[..k].copy_from_slice(grad);
    let mut values = vec![0.0; active.len()];
    for _ in 0..200 {
        let mut change = 0.0_f64;
        for (q, row) in rows.iter().enumerate() {
            let norm: f64 = (0..k).map(|c| row[c] * row[c]).sum();
            if norm == 0.0 {
                continue;
            }
            let dot: f64 = (0..k).map(|c| row[c] * residual[c]).sum();
            let next = (values[q] - dot / norm).max(0.0);
            let delta = next - values[q];
            if delta != 0.0 {
                for c in 0..k {
                    residual[c] += delta * row[c];
                }
                values[q] = next;
                change = change.max(delta.abs());
            }
        }
        if change <= 1e-17 * values.iter().fold(1.0_f64, |a, v| a.max(*v)) {
            break;
        }
    }
    for (&j, v) in active.iter().zip(&values) {
        out[j] = *v;
    }
}

/// Newton's method on the problem with each point's active constraints as equalities
/// (reduced to the null space `Z_i` of their gradients: the matrix `Z^T (M (x) I_k +
/// blockdiag lambda_power hess g) Z` has the band of `M (x) I_k`), each step followed by
/// [`snap`] and kept only when the objective decreases; at most 6 steps. Returns the point
/// and the certified gap bound with the least-squares multipliers. With the right active set
/// this removes the interior-point iterate's `O(mu)` distance to the optimum.
fn polish(
    m: &Normal,
    family: Family,
    rule: &Rule,
    b: &[f64],
    mut x: Vec<f64>,
    active: &[Vec<usize>],
) -> (Vec<f64>, f64) {
    let (n, k, count) = (m.order(), rule.k, rule.count());
    let mut grad = vec![0.0; n * k];
    let mut lambda = vec![0.0; n * count];
    let mut objective = {
        gradient(m, k, &x, b, &mut grad);
        objective_from_gradient(&x, &grad, b)
    };
    for _ in 0..POLISH_STEPS {
        let mut bases = Vec::with_capacity(n);
        for i in 0..n {
            let point = &x[i * k..(i + 1) * k];
            let rows: Vec<[f64; MAX_CHANNELS]> =
                active[i].iter().map(|&j| rule.gradient(j, point)).collect();
            let (basis, rank) = split_basis(&rows, k);
            bases.push((basis, rank));
            point_multipliers(
                rule,
                point,
                &grad[i * k..(i + 1) * k],
                &active[i],
                &mut lambda[i * count..(i + 1) * count],
            );
        }
        // Reduced variable a of point i is the coefficient of basis vector rank_i + a.
        let free = |i: usize| k - bases[i].1;
        let column = |i: usize, a: usize| &bases[i].0[bases[i].1 + a];
        let mut h = m.expanded(k);
        let mut rhs = vec![0.0; n * k];
        for i in 0..n {
            for j in m.neighbours(i) {
                if j > i {
                    continue;
                }
                let mij = m.get(i, j);
                for a in 0..free(i) {
                    for bb in 0..free(j) {
                        if i == j && bb > a {
                            continue;
                        }
                        let (u, v) = (column(i, a), column(j, bb));
                        let dot: f64 = (0..k).map(|c| u[c] * v[c]).sum();
                        if dot != 0.0 {
                            h.add(i * k + a, j * k + bb, mij * dot);
                        }
                    }
                }
            }
            let point = &x[i * k..(i + 1) * k];
            let power_index = rule.linear.len();
            let curvature = if active[i].contains(&power_index) {
                let weight = lambda[i * count + power_index];
                let mut diag = rule.curvature(power_index, point);
                diag.iter_mut().for_each(|v| *v *= weight);
                diag
            } else {
                [0.0; MAX_CHANNELS]
            };
            for a in 0..free(i) {
                let u = column(i, a);
                for bb in 0..=a {
                    let v = column(i, bb);
                    let value: f64 = (0..k).map(|c| u[c] * curvature[c] * v[c]).sum();
                    if value != 0.0 {
                        h.add(i * k + a, i * k + bb, value);
                    }
                }
                rhs[i * k + a] = -(0..k).map(|c| u[c] * grad[i * k + c]).sum::<f64>();
            }
            for a in free(i)..k {
                h.unit_row(i * k + a);
            }
        }
        let Some(factor) = h.factor() else {
            break;
        };
        factor.solve(&mut rhs);
        // The full step, else halved steps (a point whose active set is not the optimum's
        // can send the full step far along a flat direction).
        let mut accepted = None;
        let mut fraction = 1.0;
        for _ in 0..30 {
            let mut trial = x.clone();
            let mut largest = 0.0_f64;
            for i in 0..n {
                for a in 0..free(i) {
                    let u = column(i, a);
                    for c in 0..k {
                        let delta = fraction * rhs[i * k + a] * u[c];
                        trial[i * k + c] += delta;
                        largest = largest.max(delta.abs());
                    }
                }
                snap(family, rule, &mut trial[i * k..(i + 1) * k], &active[i]);
            }
            let mut trial_grad = vec![0.0; n * k];
            gradient(m, k, &trial, b, &mut trial_grad);
            let trial_objective = objective_from_gradient(&trial, &trial_grad, b);
            if trial_objective <= objective {
                accepted = Some((trial, trial_grad, trial_objective, largest));
                break;
            }
            fraction *= 0.5;
        }
        let Some((trial, trial_grad, trial_objective, largest)) = accepted else {
            break;
        };
        x = trial;
        grad = trial_grad;
        objective = trial_objective;
        if largest <= 1e-15 {
            break;
        }
    }
    for i in 0..n {
        point_multipliers(
            rule,
            &x[i * k..(i + 1) * k],
            &grad[i * k..(i + 1) * k],
            &active[i],
            &mut lambda[i * count..(i + 1) * count],
        );
    }
    let bound = certified_gap(m, rule, b, &x, &lambda);
    (x, bound)
}

/// Moves `point` to the nearest point of the affine set where the linear constraints
/// `selected` hold with equality: `x - A^T (A A^T)^-1 (A x - beta)`, with the dependent rows
/// of `A` left out.
fn onto_affine(point: &mut [f64], constraints: &[LinearConstraint], selected: &[usize]) {
    let k = point.len();
    // Rows kept, with an orthonormal basis of their span (modified Gram-Schmidt).
    let mut rows: Vec<&LinearConstraint> = Vec::new();
    let mut basis: Vec<[f64; MAX_CHANNELS]> = Vec::new();
    for &j in selected {
        let Some(constraint) = constraints.get(j) else {
            continue;
        };
        let mut v = [0.0; MAX_CHANNELS];
        v[..k].copy_from_slice(&constraint.coefficients);
        for q in &basis {
            let dot: f64 = (0..k).map(|c| v[c] * q[c]).sum();
            for c in 0..k {
                v[c] -= dot * q[c];
            }
        }
        let norm = (0..k).map(|c| v[c] * v[c]).sum::<f64>().sqrt();
        if norm > 1e-9 {
            for value in v.iter_mut() {
                *value /= norm;
            }
            basis.push(v);
            rows.push(constraint);
        }
    }
    let r = rows.len();
    if r == 0 {
        return;
    }
    // Gram system (A A^T) y = A x - beta, solved by Gaussian elimination with pivoting.
    let mut gram = [[0.0; MAX_CHANNELS + 1]; MAX_CHANNELS];
    for (p, a) in rows.iter().enumerate() {
        for (q, c) in rows.iter().enumerate() {
            gram[p][q] = (0..k).map(|t| a.coefficients[t] * c.coefficients[t]).sum();
        }
        gram[p][r] = -a.slack(point);
    }
    for col in 0..r {
        let pivot = (col..r).fold(col, |best, row| {
            if gram[row][col].abs() > gram[best][col].abs() {
                row
            } else {
                best
            }
        });
        gram.swap(col, pivot);
        let d = gram[col][col];
        if d.abs() < 1e-300 {
            return;
        }
        for row in col + 1..r {
            let f = gram[row][col] / d;
            for t in col..=r {
                gram[row][t] -= f * gram[col][t];
            }
        }
    }
    let mut y = [0.0; MAX_CHANNELS];
    for row in (0..r).rev() {
        let s: f64 = (row + 1..r).map(|t| gram[row][t] * y[t]).sum();
        y[row] = (gram[row][r] - s) / gram[row][row];
    }
    for (a, yp) in rows.iter().zip(&y) {
        for c in 0..k {
            point[c] -= a.coefficients[c] * yp;
        }
    }
}

#[cfg(test)]
mod tests;

/// A seeded rule-fit problem for the benches (not part of the API): the normal matrix of a
/// uniform cubic B-spline least-squares fit with `3 n` data points and smoothing `1e-4`, and
/// data values on and beyond the family's boundary.
#[doc(hidden)]
#[derive(Clone, Debug)]
pub struct RuleFitBench {
    m: Normal,
    family: Family,
    b: Vec<f64>,
    start: Vec<f64>,
}

impl RuleFitBench {
    /// The problem with `control_points >= 4` control points (fewer are raised to 4).
    pub fn new(family: Family, control_points: usize) -> RuleFitBench {
        use super::banded::Band;
        let n = control_points.max(4);
        let k = family.channel_count();
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut band = Band::zeros(n, 3);
        let mut b = vec![0.0; n * k];
        let spans = n - 3;
        let data = 3 * n;
        let mut values = [0.0; MAX_CHANNELS];
        for d in 0..data {
            let t = (d as f64 + 0.5 * next()) / data as f64 * spans as f64;
            let span = (t as usize).min(spans - 1);
            let u = t - span as f64;
            let v = 1.0 - u;
            let basis = [
                v * v * v / 6.0,
                (3.0 * u * u * u - 6.0 * u * u + 4.0) / 6.0,
                (-3.0 * u * u * u + 3.0 * u * u + 3.0 * u + 1.0) / 6.0,
                u * u * u / 6.0,
            ];
            for (c, value) in values.iter_mut().enumerate().take(k) {
                let (low, high) = family.channel_range(c);
                *value = low + (high - low) * next();
            }
            if let Some(p) = family.power() {
                let sum: f64 = values[..k].iter().map(|x| power_of(x.abs(), p)).sum();
                let scale = (1.0 + 0.2 * next()) / sum.powf(1.0 / f64::from(p));
                values[..k].iter_mut().for_each(|x| *x *= scale);
            }
            for (p, bp) in basis.iter().enumerate() {
                for (q, bq) in basis.iter().enumerate().take(p + 1) {
                    band.add(span + p, span + q, bp * bq);
                }
                for c in 0..k {
                    b[(span + p) * k + c] += bp * values[c];
                }
            }
        }
        for r in 0..n - 2 {
            let coefficients = [1.0, -2.0, 1.0];
            for p in 0..3 {
                for q in 0..=p {
                    band.add(r + p, r + q, 1e-4 * coefficients[p] * coefficients[q]);
                }
            }
        }
        let m = Normal::Open(band);
        let mut start = vec![0.0; n * k];
        if let Some(factor) = m.factor() {
            let mut channel = vec![0.0; n];
            for c in 0..k {
                for i in 0..n {
                    channel[i] = b[i * k + c];
                }
                factor.solve(&mut channel);
                for i in 0..n {
                    start[i * k + c] = channel[i];
                }
            }
        }
        RuleFitBench {
            m,
            family,
            b,
            start,
        }
    }

    /// Solves the problem; returns the interior-point iterations (`None`: singular).
    pub fn solve(&self) -> Option<usize> {
        solve_family(&self.m, self.family, &self.b, &self.start).map(|s| s.iterations)
    }
}
