//! The point of a curve nearest to a given point: the nearest of dense samples of the curve,
//! refined by a golden-section search between that sample's neighbours.

/// Most golden-section steps: each shrinks the bracket to 0.618 of itself, so 60 steps take
/// the bracket of two sample intervals below 1e-12 of it (the search stops earlier when the
/// bracket no longer shrinks in floating point).
const STEPS: usize = 60;

fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)
}

/// The parameter and the point of the curve `at` nearest to `target`, from the curve's
/// samples `pts` at the increasing parameters `ts` (as many, at least one): the nearest
/// sample, then a golden-section search of the squared distance between its neighbouring
/// samples. Returns the refined point, or the sample when that is nearer (the distance need
/// not be unimodal on the bracket). Like any minimisation by function values, the parameter
/// is found to about the square root of the float precision (1e-8 of the bracket, far below
/// a pixel).
pub(crate) fn nearest<E>(
    at: &dyn Fn(f64) -> Result<[f64; 3], E>,
    ts: &[f64],
    pts: &[[f64; 3]],
    target: [f64; 3],
) -> Result<(f64, [f64; 3]), E> {
    let Some(k) = (0..pts.len()).min_by(|&i, &j| {
        dist2(pts[i], target)
            .total_cmp(&dist2(pts[j], target))
            .then(i.cmp(&j))
    }) else {
        return Ok((f64::NAN, [f64::NAN; 3]));
    };
    let (mut a, mut b) = (ts[k.saturating_sub(1)], ts[(k + 1).min(ts.len() - 1)]);
    if b <= a {
        return Ok((ts[k], pts[k]));
    }
    let f = |t: f64| at(t).map(|p| dist2(p, target));
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    for _ in 0..STEPS {
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            if !(c > a && c < d) {
                break;
            }
            fc = f(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            if !(d > c && d < b) {
                break;
            }
            fd = f(d)?;
        }
    }
    let (t, value) = if fc <= fd { (c, fc) } else { (d, fd) };
    if value <= dist2(pts[k], target) {
        Ok((t, at(t)?))
    } else {
        Ok((ts[k], pts[k]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    fn sampled(
        at: &dyn Fn(f64) -> Result<[f64; 3], Infallible>,
        domain: (f64, f64),
        n: usize,
    ) -> (Vec<f64>, Vec<[f64; 3]>) {
        let ts: Vec<f64> = (0..n)
            .map(|k| domain.0 + (domain.1 - domain.0) * k as f64 / (n - 1) as f64)
            .collect();
        let pts = ts.iter().map(|&t| at(t).unwrap()).collect();
        (ts, pts)
    }

    #[test]
    fn nearest_on_a_straight_line_is_the_foot_of_the_perpendicular() {
        // The line p(t) = (1, 2, 0) + t (3, 4, 0), t in [0, 2]; the foot of q is at
        // t = (q - p0) . d / |d|^2.
        let line = |t: f64| Ok([1.0 + 3.0 * t, 2.0 + 4.0 * t, 0.0]);
        let (ts, pts) = sampled(&line, (0.0, 2.0), 17);
        for q in [
            [4.0, 1.0, 0.0],
            [0.0, 9.0, 0.0],
            [2.5, 4.5, 3.0],
            [5.0, 5.0, -1.0],
        ] {
            let exact = ((q[0] - 1.0) * 3.0 + (q[1] - 2.0) * 4.0) / 25.0;
            let (t, p) = nearest(&line, &ts, &pts, q).unwrap();
            assert!((t - exact).abs() < 1e-7, "{q:?}: t = {t}, exact {exact}");
            let foot = line(exact).unwrap();
            assert!(dist2(p, foot).sqrt() < 5e-7, "{q:?}: {p:?} vs {foot:?}");
            // The point returned is the curve at the parameter returned.
            assert_eq!(p, line(t).unwrap());
        }
        // Beyond the ends the nearest point is the end.
        let (t, p) = nearest(&line, &ts, &pts, [-5.0, -5.0, 0.0]).unwrap();
        assert_eq!((t, p), (0.0, [1.0, 2.0, 0.0]));
        let (t, p) = nearest(&line, &ts, &pts, [20.0, 20.0, 0.0]).unwrap();
        assert_eq!((t, p), (2.0, [7.0, 10.0, 0.0]));
    }

    #[test]
    fn nearest_on_a_circle_is_along_the_radius() {
        // The circle of radius 2 about (1, -1): the nearest point to q lies on the ray from
        // the centre through q, at angle atan2.
        let circle = |t: f64| Ok([1.0 + 2.0 * t.cos(), -1.0 + 2.0 * t.sin(), 0.0]);
        let (ts, pts) = sampled(&circle, (0.0, std::f64::consts::TAU), 64);
        for (x, y) in [
            (3.5, 0.2),
            (0.0, 0.0),
            (-4.0, -3.0),
            (1.2, -1.1),
            (1.0, 5.0),
        ] {
            let angle = (y + 1.0f64)
                .atan2(x - 1.0)
                .rem_euclid(std::f64::consts::TAU);
            let (t, p) = nearest(&circle, &ts, &pts, [x, y, 0.0]).unwrap();
            assert!(
                (t - angle).abs() < 1e-7,
                "({x}, {y}): t = {t}, exact {angle}"
            );
            let foot = circle(angle).unwrap();
            assert!(
                dist2(p, foot).sqrt() < 5e-7,
                "({x}, {y}): {p:?} vs {foot:?}"
            );
        }
    }

    #[test]
    fn nearest_of_a_single_sample_is_that_sample() {
        let point = |_t: f64| Ok::<_, Infallible>([3.0, 4.0, 0.0]);
        assert_eq!(
            nearest(&point, &[0.5], &[[3.0, 4.0, 0.0]], [0.0, 0.0, 0.0]).unwrap(),
            (0.5, [3.0, 4.0, 0.0])
        );
    }
}
