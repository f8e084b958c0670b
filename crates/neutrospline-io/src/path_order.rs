//! Whether measured points look like an ordered path: a curve fit goes through its data in the
//! order of the rows, so scattered points (a cloud over an area, or a path with its rows
//! shuffled) give a curve that zigzags between them without a word unless someone says so.

/// How far a table of points is from an ordered path, when it is far enough to warn.
#[derive(Debug, Clone, PartialEq)]
pub struct PathDisorder {
    /// The median distance between consecutive rows.
    pub median_step: f64,
    /// The median distance from a point to its nearest other point.
    pub median_nearest: f64,
    /// The steps longer than [`JUMP`] times the median step.
    pub jumps: usize,
    /// The index of the point that ends the longest step.
    pub longest: usize,
    /// The longest step over the median step.
    pub longest_ratio: f64,
}

/// A step longer than this many median steps is a jump.
pub const JUMP: f64 = 10.0;

/// Consecutive rows this many times farther apart (in the median) than nearest neighbours are
/// not in path order.
pub const SPREAD: f64 = 3.0;

/// The most points whose nearest neighbour is measured (evenly spread over the table), so
/// that the check costs at most this many passes over the points.
const SAMPLED: usize = 400;

/// `None` when `points` look like an ordered path, else how they do not: the median step
/// between consecutive rows is more than [`SPREAD`] times the median distance from a point to
/// its nearest neighbour (consecutive rows are not neighbours), or some step is longer than
/// [`JUMP`] median steps. Fewer than 4 points, or points that all coincide, are never judged.
pub fn path_disorder(points: &[[f64; 3]]) -> Option<PathDisorder> {
    let n = points.len();
    if n < 4 {
        return None;
    }
    let distance = |a: &[f64; 3], b: &[f64; 3]| {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    };
    let steps: Vec<f64> = points.windows(2).map(|w| distance(&w[0], &w[1])).collect();
    let median_step = median(steps.clone());
    if median_step <= 0.0 || !median_step.is_finite() {
        return None;
    }
    let stride = n.div_ceil(SAMPLED).max(1);
    let nearest: Vec<f64> = (0..n)
        .step_by(stride)
        .map(|i| {
            points
                .iter()
                .enumerate()
                .filter(|&(j, p)| j != i && distance(p, &points[i]) > 0.0)
                .map(|(_, p)| distance(p, &points[i]))
                .fold(f64::INFINITY, f64::min)
        })
        .filter(|d| d.is_finite())
        .collect();
    let median_nearest = median(nearest);
    let (longest, longest_step) =
        steps.iter().enumerate().fold(
            (0, 0.0),
            |best, (k, &s)| if s > best.1 { (k + 1, s) } else { best },
        );
    let jumps = steps.iter().filter(|&&s| s > JUMP * median_step).count();
    let scattered = median_nearest > 0.0 && median_step > SPREAD * median_nearest;
    (scattered || jumps > 0).then_some(PathDisorder {
        median_step,
        median_nearest,
        jumps,
        longest,
        longest_ratio: longest_step / median_step,
    })
}

/// The median of `values` (the lower one of the middle two); 0 for none.
fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    values[(values.len() - 1) / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A helix sampled in order is a path; the same points in a scrambled order are not, and
    /// neither is a path with one row moved far from its place.
    #[test]
    fn ordered_helix_passes_scrambled_fails() {
        let helix: Vec<[f64; 3]> = (0..60)
            .map(|k| {
                let t = f64::from(k) * 0.2;
                [t.cos(), t.sin(), 0.1 * t]
            })
            .collect();
        assert_eq!(path_disorder(&helix), None);
        // k -> 37 k mod 60 visits every point, far apart each step.
        let scrambled: Vec<[f64; 3]> = (0..60).map(|k| helix[(37 * k) % 60]).collect();
        let disorder = path_disorder(&scrambled).unwrap();
        assert!(disorder.median_step > SPREAD * disorder.median_nearest);
        let mut moved = helix.clone();
        let row = moved.remove(5);
        moved.insert(50, row);
        let disorder = path_disorder(&moved).unwrap();
        assert_eq!(disorder.jumps, 2);
        assert!([50, 51].contains(&disorder.longest), "{disorder:?}");
    }

    #[test]
    fn small_or_degenerate_tables_are_not_judged() {
        assert_eq!(path_disorder(&[[0.0; 3]; 3]), None);
        assert_eq!(path_disorder(&[[1.0, 2.0, 3.0]; 10]), None);
    }
}
