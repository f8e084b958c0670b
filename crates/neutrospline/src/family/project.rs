//! The Euclidean projection onto a family's feasible set: the nearest valid channel vector,
//! exactly (the bound fitting gives every control point; docs/model.md, "Family
//! families").
//!
//! - boxes: clamping;
//! - `{x >= 0, sum x <= 1}` (intuitionistic, picture): clamping at 0, or the projection onto
//!   the simplex `sum x = 1` by sorting (Held, Wolfe and Crowder; Duchi et al. 2008);
//! - `{x >= 0, sum x^p <= 1}`, `p >= 2` (the round families): `y = max(x, 0)`; if `y` is
//!   outside, the KKT conditions `z_c + lambda p z_c^(p-1) = y_c`, `sum z_c^p = 1` are solved for
//!   the multiplier `lambda > 0` by safeguarded Newton in a bracket, each `z_c(lambda)` by
//!   Newton from above (monotone: `z + lambda p z^(p-1)` is convex and increasing on `z >= 0`);
//! - `{lo <= L <= U <= hi}` (interval degrees, each pair alone): clamping when `L <= U`, else
//!   the clamped midpoint for both;
//! - interval-intuitionistic (pairs coupled by `T_U + F_U <= 1`): every set of active
//!   constraints is tried (5 constraints, 4 unknowns: 31 small linear systems) and the nearest
//!   feasible candidate kept, which is the projection because the projection is the projection
//!   onto the affine hull of its own active constraints.
//!
//! A last step moves the result by a few units in the last place where rounding left it
//! outside, so that [`Family::check`] accepts it with no tolerance.

use super::rule::{pow_int, power_sum, LinearConstraint};
use super::{Family, Shape, MAX_CHANNELS};

impl Family {
    /// Replaces `values` by the nearest valid channel vector (Euclidean distance): the
    /// projection onto the family's convex feasible set. The result passes
    /// [`Family::check`] exactly; a valid input is returned unchanged. Non-finite entries
    /// are first replaced by the nearest end of their box (NaN by the lower end).
    ///
    /// ```
    /// use neutrospline::Family;
    /// let mut v = [0.9, 0.9];
    /// Family::Pythagorean.project(&mut v); // onto the unit circle: (0.9, 0.9) / |(0.9, 0.9)|
    /// assert!((v[0] - 0.5f64.sqrt()).abs() < 1e-15 && v[0] == v[1]);
    /// assert!(Family::Pythagorean.check(&v).is_ok());
    /// let mut w = [0.7, 0.3];
    /// Family::IntervalType2.project(&mut w); // lower above upper: both at the midpoint
    /// assert_eq!(w, [0.5, 0.5]);
    /// ```
    ///
    /// # Panics
    /// If `values.len()` differs from [`Family::channel_count`].
    pub fn project(&self, values: &mut [f64]) {
        let shape = self.shape();
        assert_eq!(values.len(), shape.channels.len(), "channels of {self}");
        for (c, v) in values.iter_mut().enumerate() {
            let (low, high) = self.channel_range(c);
            if v.is_nan() {
                *v = low;
            } else if v.is_infinite() {
                *v = v.clamp(low, high);
            }
        }
        match (shape.pairs.is_empty(), self.power()) {
            (true, None) => {}
            (true, Some(1)) => project_capped_simplex(values),
            (true, Some(p)) => project_power_ball(values, p),
            (false, None) => {
                for &(l, u) in shape.pairs {
                    let (low, high) = self.channel_range(l);
                    if values[l] > values[u] {
                        let mid = (0.5 * (values[l] + values[u])).clamp(low, high);
                        values[l] = mid;
                        values[u] = mid;
                    }
                }
            }
            (false, Some(_)) => project_polytope(values, &self.linear_constraints()),
        }
        self.snap(&shape, values);
    }

    /// Moves values that rounding left outside the rule by a few units in the last place.
    fn snap(&self, shape: &Shape, values: &mut [f64]) {
        for (c, v) in values.iter_mut().enumerate() {
            let (low, high) = self.channel_range(c);
            *v = v.clamp(low, high) + 0.0;
        }
        match self.power() {
            Some(1) => {
                for _ in 0..8 {
                    let sum = power_sum(values, shape.sum, 1);
                    if sum <= 1.0 {
                        break;
                    }
                    let largest = shape.sum.iter().copied().fold(shape.sum[0], |a, c| {
                        if values[c] > values[a] {
                            c
                        } else {
                            a
                        }
                    });
                    values[largest] = (values[largest] - (sum - 1.0)).max(0.0);
                }
            }
            Some(p) => {
                for _ in 0..64 {
                    if power_sum(values, shape.sum, p) <= 1.0 {
                        break;
                    }
                    for &c in shape.sum {
                        values[c] *= 1.0 - f64::EPSILON;
                    }
                }
            }
            None => {}
        }
        for &(l, u) in shape.pairs {
            values[l] = values[l].min(values[u]);
        }
    }
}

/// Onto `{x >= 0, sum x <= 1}`.
fn project_capped_simplex(x: &mut [f64]) {
    for v in x.iter_mut() {
        *v = v.max(0.0);
    }
    if x.iter().sum::<f64>() <= 1.0 {
        return;
    }
    // Onto the simplex sum x = 1: x - theta clamped at 0, theta from the sorted values.
    let mut sorted = [0.0; MAX_CHANNELS];
    let sorted = &mut sorted[..x.len()];
    sorted.copy_from_slice(x);
    sorted.sort_by(|a, b| b.total_cmp(a));
    let (mut cumulative, mut theta) = (0.0, 0.0);
    for (j, &s) in sorted.iter().enumerate() {
        cumulative += s;
        let candidate = (cumulative - 1.0) / (j + 1) as f64;
        if s - candidate > 0.0 {
            theta = candidate;
        }
    }
    for v in x.iter_mut() {
        *v = (*v - theta).max(0.0);
    }
}

/// The root `z` in `[0, y]` of `z + c z^(p-1) = y` (`y >= 0`, `c >= 0`, `p >= 2`) and
/// `dz/dc`. Newton from an upper bound of the root decreases monotonically to it, because the
/// function is convex and increasing on `z >= 0`.
fn orthant_root(y: f64, c: f64, p: u32) -> (f64, f64) {
    if y == 0.0 {
        return (0.0, 0.0);
    }
    let q = f64::from(p - 1);
    let slope = |z: f64| 1.0 + c * q * pow_int(z, p - 2);
    // Both y and (y / c)^(1/(p-1)) bound the root from above (the latter widened by 1e-12
    // against the rounding of powf).
    let mut z = if c > 0.0 {
        y.min((y / c).powf(1.0 / q) * (1.0 + 1e-12))
    } else {
        y
    };
    for _ in 0..200 {
        let h = z + c * pow_int(z, p - 1) - y;
        let next = (z - h / slope(z)).max(0.0);
        if next >= z {
            break;
        }
        z = next;
    }
    (z, -pow_int(z, p - 1) / slope(z))
}

/// Onto `{x >= 0, sum x^p <= 1}`, `p >= 2`.
fn project_power_ball(x: &mut [f64], p: u32) {
    for v in x.iter_mut() {
        *v = v.max(0.0);
    }
    let all = [0, 1, 2, 3, 4, 5];
    let channels = &all[..x.len()];
    if power_sum(x, channels, p) <= 1.0 {
        return;
    }
    let mut y = [0.0; MAX_CHANNELS];
    let y = &mut y[..x.len()];
    y.copy_from_slice(x);
    let pf = f64::from(p);
    // phi(lambda) = sum z_c(lambda)^p - 1 decreases from phi(0) > 0; the multiplier lambda
    // enters through c = lambda p.
    let phi = |lambda: f64, z: &mut [f64]| -> (f64, f64) {
        let mut slope = 0.0;
        for (zc, &yc) in z.iter_mut().zip(y.iter()) {
            let (root, dz_dc) = orthant_root(yc, lambda * pf, p);
            *zc = root;
            slope += pf * pow_int(root, p - 1) * dz_dc * pf;
        }
        (power_sum(z, channels, p) - 1.0, slope)
    };
    let mut z = [0.0; MAX_CHANNELS];
    let z = &mut z[..x.len()];
    // Upper end: z_c <= (y_c / (lambda p))^(1/(p-1)) makes phi <= 0 from this lambda on.
    let exponent = pf / (pf - 1.0);
    let mut hi = y
        .iter()
        .map(|v| v.powf(exponent))
        .sum::<f64>()
        .powf(1.0 / exponent)
        / pf;
    for _ in 0..64 {
        if phi(hi, z).0 <= 0.0 {
            break;
        }
        hi *= 2.0;
    }
    let mut lo = 0.0;
    let mut lambda = hi;
    for _ in 0..200 {
        let (value, slope) = phi(lambda, z);
        if value == 0.0 {
            break;
        }
        if value > 0.0 {
            lo = lambda;
        } else {
            hi = lambda;
        }
        let newton = lambda - value / slope;
        let next = if newton > lo && newton < hi && slope < 0.0 {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if next == lambda || next <= lo || next >= hi {
            break;
        }
        lambda = next;
    }
    phi(lambda, z);
    x.copy_from_slice(z);
}

/// Onto the polytope `{a_j . x <= b_j}` of at most [`MAX_CHANNELS`] unknowns, by trying every
/// set of at most `n` active constraints (small rules only: 2^m systems).
fn project_polytope(x: &mut [f64], constraints: &[LinearConstraint]) {
    let n = x.len();
    let m = constraints.len();
    let feasible = |z: &[f64]| constraints.iter().all(|c| c.slack(z) >= -1e-12);
    if feasible(x) {
        return;
    }
    let y: Vec<f64> = x.to_vec();
    let mut best: Option<(f64, Vec<f64>)> = None;
    for mask in 1u32..(1 << m) {
        let active: Vec<&LinearConstraint> = (0..m)
            .filter(|j| mask >> j & 1 == 1)
            .map(|j| &constraints[j])
            .collect();
        if active.len() > n {
            continue;
        }
        // z = y - A^T mu with (A A^T) mu = A y - b.
        let k = active.len();
        let mut gram = vec![0.0; k * (k + 1)];
        for (r, a) in active.iter().enumerate() {
            for (s, b) in active.iter().enumerate() {
                gram[r * (k + 1) + s] = a
                    .coefficients
                    .iter()
                    .zip(b.coefficients.iter())
                    .map(|(u, v)| u * v)
                    .sum();
            }
            gram[r * (k + 1) + k] = -a.slack(&y);
        }
        let Some(mu) = solve(&mut gram, k) else {
            continue;
        };
        let mut z = y.clone();
        for (a, m) in active.iter().zip(&mu) {
            for (zc, ac) in z.iter_mut().zip(a.coefficients.iter()) {
                *zc -= ac * m;
            }
        }
        if feasible(&z) {
            let distance: f64 = z.iter().zip(&y).map(|(a, b)| (a - b) * (a - b)).sum();
            if best.as_ref().is_none_or(|(d, _)| distance < *d) {
                best = Some((distance, z));
            }
        }
    }
    if let Some((_, z)) = best {
        x.copy_from_slice(&z);
    }
}

/// Solves the `k x k` system stored row-major with its right-hand side as column `k`, by
/// Gaussian elimination with partial pivoting; `None` when (nearly) singular.
fn solve(a: &mut [f64], k: usize) -> Option<Vec<f64>> {
    let w = k + 1;
    for col in 0..k {
        let pivot =
            (col..k).max_by(|&r, &s| a[r * w + col].abs().total_cmp(&a[s * w + col].abs()))?;
        if a[pivot * w + col].abs() < 1e-12 {
            return None;
        }
        for j in 0..w {
            a.swap(col * w + j, pivot * w + j);
        }
        for r in col + 1..k {
            let f = a[r * w + col] / a[col * w + col];
            for j in col..w {
                a[r * w + j] -= f * a[col * w + j];
            }
        }
    }
    let mut out = vec![0.0; k];
    for r in (0..k).rev() {
        let s: f64 = (r + 1..k).map(|j| a[r * w + j] * out[j]).sum();
        out[r] = (a[r * w + k] - s) / a[r * w + r];
    }
    Some(out)
}
