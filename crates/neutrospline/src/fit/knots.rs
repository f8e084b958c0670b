//! Data parameters and knot vectors for fitting (The NURBS Book, section 9.2 and 9.4;
//! docs/model.md section 8).

/// How the data parameters are chosen when the data does not give them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Parametrization {
    /// Evenly spaced: `t_k = k / m`.
    Uniform,
    /// Proportional to the distance between consecutive points (the default).
    #[default]
    ChordLength,
    /// Proportional to the square root of that distance (the centripetal model).
    Centripetal,
}

impl Parametrization {
    /// The name used on the command line: `uniform`, `chord-length`, `centripetal`.
    pub const fn name(self) -> &'static str {
        match self {
            Parametrization::Uniform => "uniform",
            Parametrization::ChordLength => "chord-length",
            Parametrization::Centripetal => "centripetal",
        }
    }
}

/// Cumulative parameters of the points, normalised so that the last is `1`: increments
/// `|Q_k - Q_{k-1}|^e` (and, for a closed curve, the closing chord from the last point back
/// to the first counts too, so that the points get `t_k < 1` and the first is also `t = 1`).
/// `Err(k)` names a point whose increment is zero (it repeats point `k - 1`; for a closed curve
/// `k = 0` when the last point repeats the first) under chord-length or centripetal
/// parameters, or all points coincide.
pub(crate) fn parameters<const D: usize>(
    positions: &[[f64; D]],
    parametrization: Parametrization,
    closed: bool,
) -> Result<Vec<f64>, usize> {
    let m = positions.len();
    let distance = |a: &[f64; D], b: &[f64; D]| -> f64 {
        let d2: f64 = (0..D).map(|i| (a[i] - b[i]).powi(2)).sum();
        match parametrization {
            Parametrization::Uniform => 1.0,
            Parametrization::ChordLength => d2.sqrt(),
            Parametrization::Centripetal => d2.sqrt().sqrt(),
        }
    };
    let mut steps: Vec<f64> = positions
        .windows(2)
        .map(|w| distance(&w[0], &w[1]))
        .collect();
    if closed {
        steps.push(distance(&positions[m - 1], &positions[0]));
    }
    if let Some(k) = steps.iter().position(|&s| s == 0.0) {
        return Err((k + 1) % m);
    }
    let total: f64 = steps.iter().sum();
    if !(total > 0.0 && total.is_finite()) {
        return Err(0);
    }
    let mut params = Vec::with_capacity(m);
    let mut acc = 0.0;
    params.push(0.0);
    for s in &steps[..m - 1] {
        acc += s;
        params.push((acc / total).min(1.0));
    }
    if !closed {
        params[m - 1] = 1.0;
    }
    Ok(params)
}

/// Clamped knots for interpolation by averaging (eq. 9.8): `p + 1` copies of `t_0` and of
/// `t_m`, interior knots `u_{j+p} = (t_j + ... + t_{j+p-1}) / p`, `j = 1 ..= m - p`. With
/// `tangents`, two more control points and interior knots `(t_j + ... + t_{j+p-1}) / p` for
/// `j = 0 ..= m - p + 1` (eq. 9.22 generalised).
pub(crate) fn interpolation_knots(params: &[f64], p: usize, tangents: bool) -> Vec<f64> {
    let m = params.len() - 1;
    let (a, b) = (params[0], params[m]);
    let average = |j: usize| params[j..j + p].iter().sum::<f64>() / p as f64;
    let interior: Vec<f64> = if tangents {
        (0..=m + 1 - p).map(average).collect()
    } else if p == 0 {
        // Degree 0: a step at the middle between consecutive parameters.
        (1..=m).map(|j| 0.5 * (params[j - 1] + params[j])).collect()
    } else {
        (1..=m - p).map(average).collect()
    };
    clamped(a, b, p, interior)
}

/// Clamped knots for least squares with `n + 1` control points (eq. 9.68-9.69): with
/// `d = (m + 1) / (n - p + 1)`, the interior knots `u_{p+j} = (1 - a) t_{i-1} + a t_i`,
/// `i = floor(j d)`, `a = j d - i`, `j = 1 ..= n - p`.
pub(crate) fn least_squares_knots(params: &[f64], p: usize, n: usize) -> Vec<f64> {
    let m = params.len() - 1;
    let d = (m + 1) as f64 / (n - p + 1) as f64;
    let interior = (1..=n - p)
        .map(|j| {
            let jd = j as f64 * d;
            let i = (jd.floor() as usize).clamp(1, m);
            let a = jd - i as f64;
            (1.0 - a) * params[i - 1] + a * params[i]
        })
        .collect();
    clamped(params[0], params[m], p, interior)
}

/// `p + 1` copies of `a`, the interior knots (made non-decreasing and kept inside `[a, b]`),
/// `p + 1` copies of `b`.
pub(crate) fn clamped(a: f64, b: f64, p: usize, interior: Vec<f64>) -> Vec<f64> {
    let mut knots: Vec<f64> = core::iter::repeat_n(a, p + 1).collect();
    let mut previous = a;
    for k in interior {
        previous = k.clamp(previous, b);
        knots.push(previous);
    }
    knots.extend(core::iter::repeat_n(b, p + 1));
    knots
}

/// The periodic base knots `tau_0 < ... < tau_{n-1}` in `[tau_0, tau_0 + 1)` for `n` control
/// points of a closed curve through data with parameters `params` (in `[0, 1)`): for
/// interpolation (`n = m`), the parameters themselves for odd degrees and the midpoints
/// between consecutive ones for even degrees (where knots at the data would make the
/// collocation matrix singular); otherwise the parameters interpolated at the fractional
/// indices `j m / n`.
pub(crate) fn periodic_base(params: &[f64], p: usize, n: usize) -> Vec<f64> {
    let m = params.len();
    let at = |x: f64| -> f64 {
        // Parameter at fractional index x in [0, m], with t_m = 1.
        let i = x.floor() as usize;
        let a = x - i as f64;
        let t = |k: usize| if k >= m { 1.0 } else { params[k] };
        (1.0 - a) * t(i) + a * t(i + 1)
    };
    if n == m {
        if p % 2 == 1 {
            params.to_vec()
        } else {
            (0..m).map(|k| at(k as f64 + 0.5)).collect()
        }
    } else {
        (0..n).map(|j| at(j as f64 * m as f64 / n as f64)).collect()
    }
}

/// The knot vector of the unclamped B-spline with `n + p` control points (the `n` free ones,
/// then the first `p` again) that a periodic spline with base knots `base` (period 1) is:
/// [`crate::KnotVector::periodic`] of the breakpoints `base, base_0 + 1`; its domain is
/// `[tau_0, tau_0 + 1]`.
pub(crate) fn periodic_knots(base: &[f64], p: usize) -> Vec<f64> {
    let mut breakpoints = base.to_vec();
    breakpoints.push(base[0] + 1.0);
    crate::knots::periodic_extension(p, &breakpoints)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_by_chord_length_and_errors() {
        let pts = [[0.0, 0.0], [3.0, 4.0], [3.0, 5.0]];
        assert_eq!(
            parameters(&pts, Parametrization::ChordLength, false).unwrap(),
            vec![0.0, 5.0 / 6.0, 1.0]
        );
        assert_eq!(
            parameters(&pts, Parametrization::Uniform, false).unwrap(),
            vec![0.0, 0.5, 1.0]
        );
        let c = parameters(&pts, Parametrization::Centripetal, false).unwrap();
        assert!((c[1] - 5f64.sqrt() / (5f64.sqrt() + 1.0)).abs() < 1e-15);
        // Closed: the chord back to the start (length 5.830...) counts.
        let closed = parameters(&pts, Parametrization::ChordLength, true).unwrap();
        let back = 34f64.sqrt();
        assert!((closed[2] - 6.0 / (6.0 + back)).abs() < 1e-15);
        let repeated = [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0]];
        assert_eq!(
            parameters(&repeated, Parametrization::ChordLength, false),
            Err(2)
        );
        assert!(parameters(&repeated, Parametrization::Uniform, false).is_ok());
    }

    #[test]
    fn averaged_and_least_squares_knots() {
        // NURBS Book example 9.1-like: parameters 0, 5/17, 9/17, 14/17, 1, cubic.
        let t = [0.0, 5.0 / 17.0, 9.0 / 17.0, 14.0 / 17.0, 1.0];
        let k = interpolation_knots(&t, 3, false);
        assert_eq!(k.len(), 9);
        assert!((k[4] - 28.0 / 51.0).abs() < 1e-15);
        let tangents = interpolation_knots(&t, 3, true);
        assert_eq!(tangents.len(), 5 + 2 + 3 + 1);
        let lsq = least_squares_knots(&[0.0, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0], 2, 3);
        // d = 7 / 2, j = 1: i = 3, a = 0.5: (t_2 + t_3) / 2 = 0.3.
        assert_eq!(lsq.len(), 7);
        assert!((lsq[3] - 0.3).abs() < 1e-15);
    }

    #[test]
    fn periodic_knot_vectors() {
        let base = [0.0, 0.25, 0.5, 0.75];
        let k = periodic_knots(&base, 2);
        assert_eq!(k, vec![-0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5]);
        let mid = periodic_base(&[0.0, 0.5], 2, 2);
        assert_eq!(mid, vec![0.25, 0.75]);
    }
}
