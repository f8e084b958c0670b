//! The data's `(u, v)` on a fitted surface: averaged curve parameters for a grid (The NURBS
//! Book 9.2.5, algorithm A9.3), a projection for scattered points.

use super::super::{FitError, Parametrization};
use super::Projection;

/// Checks that given grid parameters are a grid's: `u` the same along each row, `v` the same
/// along each column (to 1e-12 of their range).
pub(super) fn check_grid_parameters(
    parameters: &[[f64; 2]],
    rows: usize,
    cols: usize,
) -> Result<(), FitError> {
    let range = |a: usize| {
        let (lo, hi) = parameters
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), uv| {
                (lo.min(uv[a]), hi.max(uv[a]))
            });
        (hi - lo).max(1.0) * 1e-12
    };
    let (eu, ev) = (range(0), range(1));
    for k in 0..rows {
        for l in 0..cols {
            let [u, v] = parameters[k * cols + l];
            let (u0, v0) = (parameters[k * cols][0], parameters[l][1]);
            if (u - u0).abs() > eu || (v - v0).abs() > ev {
                return Err(FitError::Option(format!(
                    "point {} (row {k}, column {l}): (u, v) = ({u}, {v}) is not on the grid of \
                     the given parameters (u must be the same along a row, here {u0}, and v \
                     along a column, here {v0})",
                    k * cols + l
                )));
            }
        }
    }
    Ok(())
}

/// The parameters of one direction of a grid: for each of `lines` lines of `count` points
/// (`at(line, k)` the point `k` of a line), the cumulative `|Q_k - Q_k-1|^e` normalised to
/// `[0, 1]`, averaged over the lines; a line whose points all coincide (a pole) is left
/// out. `Err(k)` when every line is degenerate or `count < 2`.
pub(super) fn averaged(
    lines: usize,
    count: usize,
    at: impl Fn(usize, usize) -> [f64; 3],
    parametrization: Parametrization,
) -> Result<Vec<f64>, usize> {
    if count < 2 {
        return Ok(vec![0.0; count]);
    }
    let mut sum = vec![0.0; count];
    let mut used = 0;
    let mut steps = vec![0.0; count - 1];
    for line in 0..lines {
        for (k, step) in steps.iter_mut().enumerate() {
            let (a, b) = (at(line, k), at(line, k + 1));
            let d = (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
            *step = match parametrization {
                Parametrization::Uniform => 1.0,
                Parametrization::ChordLength => d,
                Parametrization::Centripetal => d.sqrt(),
            };
        }
        let total: f64 = steps.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            continue;
        }
        used += 1;
        let mut acc = 0.0;
        for (k, step) in steps.iter().enumerate() {
            acc += step;
            sum[k + 1] += (acc / total).min(1.0);
        }
    }
    if used == 0 {
        return Err(0);
    }
    let mut params: Vec<f64> = sum.iter().map(|s| s / used as f64).collect();
    params[0] = 0.0;
    params[count - 1] = 1.0;
    Ok(params)
}

/// The `(u, v)` of a `rows x cols` grid: `u` averaged over the columns, `v` over the rows.
pub(super) fn grid(
    positions: &[[f64; 3]],
    rows: usize,
    cols: usize,
    parametrization: Parametrization,
) -> Result<(Vec<f64>, Vec<f64>), FitError> {
    let degenerate = |direction: &str| {
        FitError::Option(format!(
            "every {direction} of the grid has all its points at one position: chord-length and \
             centripetal parameters need distinct points (give parameters, or use uniform ones)"
        ))
    };
    let u = averaged(cols, rows, |l, k| positions[k * cols + l], parametrization)
        .map_err(|_| degenerate("column"))?;
    let v = averaged(rows, cols, |k, l| positions[k * cols + l], parametrization)
        .map_err(|_| degenerate("row"))?;
    Ok((u, v))
}

/// The `(u, v)` of scattered points by `projection`, each scaled to `[0, 1]`.
pub(super) fn project(positions: &[[f64; 3]], projection: Projection) -> Vec<[f64; 2]> {
    let (e1, e2, centre) = match projection {
        Projection::Xy => ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3]),
        Projection::Plane => principal_axes(positions),
    };
    let dot = |a: &[f64; 3], p: &[f64; 3]| (0..3).map(|i| a[i] * (p[i] - centre[i])).sum::<f64>();
    let raw: Vec<[f64; 2]> = positions
        .iter()
        .map(|p| [dot(&e1, p), dot(&e2, p)])
        .collect();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for uv in &raw {
        for a in 0..2 {
            lo[a] = lo[a].min(uv[a]);
            hi[a] = hi[a].max(uv[a]);
        }
    }
    let scale = [0, 1].map(|a| {
        if hi[a] > lo[a] {
            1.0 / (hi[a] - lo[a])
        } else {
            0.0
        }
    });
    raw.iter()
        .map(|uv| [0, 1].map(|a| ((uv[a] - lo[a]) * scale[a]).clamp(0.0, 1.0)))
        .collect()
}

/// The two principal axes of the points (eigenvectors of the covariance with the largest
/// eigenvalues, by cyclic Jacobi rotations; each with its largest component positive) and
/// the centroid.
fn principal_axes(positions: &[[f64; 3]]) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let n = positions.len() as f64;
    let mut c = [0.0; 3];
    for p in positions {
        for i in 0..3 {
            c[i] += p[i] / n;
        }
    }
    let mut a = [[0.0; 3]; 3];
    for p in positions {
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += (p[i] - c[i]) * (p[j] - c[j]);
            }
        }
    }
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let scale = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= 1e-15 * scale || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let sign = if theta >= 0.0 { 1.0 } else { -1.0 };
            let t = sign / (theta.abs() + (theta * theta + 1.0).sqrt());
            let (cs, sn) = (1.0 / (t * t + 1.0).sqrt(), t / (t * t + 1.0).sqrt());
            for k in 0..3 {
                let (akp, akq) = (a[k][p], a[k][q]);
                a[k][p] = cs * akp - sn * akq;
                a[k][q] = sn * akp + cs * akq;
            }
            for k in 0..3 {
                let (apk, aqk) = (a[p][k], a[q][k]);
                a[p][k] = cs * apk - sn * aqk;
                a[q][k] = sn * apk + cs * aqk;
            }
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = cs * vp - sn * vq;
                row[q] = sn * vp + cs * vq;
            }
        }
    }
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| a[j][j].total_cmp(&a[i][i]));
    let axis = |k: usize| {
        let mut e = [v[0][k], v[1][k], v[2][k]];
        let big = (0..3)
            .max_by(|&i, &j| e[i].abs().total_cmp(&e[j].abs()))
            .unwrap_or(0);
        if e[big] < 0.0 {
            e.iter_mut().for_each(|x| *x = -*x);
        }
        e
    };
    (axis(order[0]), axis(order[1]), c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averaged_parameters_follow_the_nurbs_book() {
        // Two columns of three points: chords 1, 3 and 2, 2: u = (0, (1/4 + 1/2)/2, 1).
        let cols = [
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [4.0, 0.0, 0.0]],
            [[0.0, 1.0, 0.0], [2.0, 1.0, 0.0], [4.0, 1.0, 0.0]],
        ];
        let u = averaged(2, 3, |l, k| cols[l][k], Parametrization::ChordLength).unwrap();
        assert_eq!(u, vec![0.0, 0.375, 1.0]);
        // A pole (a column of one point) is left out.
        let pole = [[[0.0; 3]; 3], cols[0]];
        let u = averaged(2, 3, |l, k| pole[l][k], Parametrization::ChordLength).unwrap();
        assert_eq!(u, vec![0.0, 0.25, 1.0]);
        assert!(averaged(1, 3, |_, _| [1.0; 3], Parametrization::ChordLength).is_err());
    }

    #[test]
    fn plane_projection_recovers_a_tilted_plane() {
        // Points on the plane z = x (normal (1, 0, -1)/sqrt 2): the axes span it.
        let pts: Vec<[f64; 3]> = (0..20)
            .map(|k| {
                let (a, b) = ((k % 5) as f64, (k / 5) as f64 * 0.5);
                [a, b, a]
            })
            .collect();
        let (e1, e2, _) = principal_axes(&pts);
        let normal = [1.0, 0.0, -1.0];
        for e in [e1, e2] {
            let d: f64 = (0..3).map(|i| e[i] * normal[i]).sum();
            assert!(d.abs() < 1e-12, "{e:?}");
        }
        let uv = project(&pts, Projection::Plane);
        assert!(uv
            .iter()
            .all(|p| (0.0..=1.0).contains(&p[0]) && (0.0..=1.0).contains(&p[1])));
    }
}
