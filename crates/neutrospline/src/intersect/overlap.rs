//! Overlaps: the stretch two curves share, and the check when the pairs crowd.

use super::search::{Root, Search, Spans, Stretch};
use super::sub::Sub;
use super::{project, width, IntersectError, ON, SAME};
use crate::curve::{Derivative, EvalError};
use crate::derivative::CurveDerivative;
use crate::nearest::{distance_to_piece, NearestPoint, Piece};

impl<'c, A, B> Search<'c, A, B>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    /// The stretch the curves share around the tangential contact `root`, if they share one:
    /// `A` is followed from `root` in both directions to the end of its piece (at 64 evenly
    /// spaced points and at distances halving down to 2^-40 of the way), each point projected
    /// onto `B`; the curves share the stretch when every point lies on `B` (within 1e-12 of
    /// the size) until the end of `A`'s piece, or until `B`'s projection reaches the end of a
    /// piece of `B` (for one curve: until it turns back onto itself, `s = t`). Two polynomial
    /// (or rational) pieces that agree along an interval agree along the whole of both, so a
    /// shared stretch can only stop where a piece stops; a contact of high order (`y = x^4` on
    /// `y = 0`) stops in the middle of the pieces, where the curves separate.
    pub(super) fn shared_stretch(
        &self,
        root: Root,
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<Option<Stretch>, EvalError> {
        let rb = self.b.domain();
        let wb = width(&rb).max(1e-300);
        let on = ON * self.scale;
        let boundary_near = |t: f64, reach: f64| {
            pieces_b
                .iter()
                .any(|p| (t - p.range[0]).abs() <= reach || (t - p.range[1]).abs() <= reach)
        };
        let mut ends = [(root.s, root.t); 2];
        for (k, forward) in [false, true].into_iter().enumerate() {
            let Some(piece) = pieces_a
                .iter()
                .find(|p| p.range[0] <= root.s && root.s <= p.range[1])
            else {
                return Ok(None);
            };
            let limit = if forward {
                piece.range[1]
            } else {
                piece.range[0]
            };
            let mut fractions: Vec<f64> = (1..=64)
                .map(|i| f64::from(i) / 64.0)
                .chain((1..=40).map(|i| 0.5_f64.powi(i)))
                .collect();
            fractions.sort_by(f64::total_cmp);
            let (mut last, mut before) = ((root.s, root.t), root.t);
            let mut reached = root.s == limit;
            for f in fractions {
                if reached {
                    break;
                }
                let s = root.s + (limit - root.s) * f;
                let point = self.a.evaluate(s)?.position;
                let (gap, t) = self.project_on_b(point, last.1, rb.start, rb.end)?;
                let step = (last.1 - before).abs() + 1e-9 * wb;
                if gap > on {
                    // The curves part between `last` and `s`: where, by bisection.
                    let mut parted = s;
                    for _ in 0..60 {
                        let middle = 0.5 * (last.0 + parted);
                        if middle == last.0 || middle == parted {
                            break;
                        }
                        let point = self.a.evaluate(middle)?.position;
                        let (gap, t) = self.project_on_b(point, last.1, rb.start, rb.end)?;
                        if gap > on {
                            parted = middle;
                        } else {
                            last = (middle, t);
                        }
                    }
                    // A shared stretch ends here only at the end of a piece of B (or, for one
                    // curve, where it turns back onto itself).
                    reached = boundary_near(last.1, 2.0 * step)
                        || (self.same && (last.0 - last.1).abs() <= 2.0 * step);
                    break;
                }
                before = last.1;
                last = (s, t);
                reached = f == 1.0;
            }
            if !reached {
                return Ok(None);
            }
            ends[k] = last;
        }
        // Ends within 1e-9 of a piece's end are on it.
        let snap = |x: f64, pieces: &[Sub], w: f64| {
            pieces
                .iter()
                .flat_map(|p| p.range)
                .find(|&e| (x - e).abs() <= 1e-9 * w)
                .unwrap_or(x)
        };
        let wa = width(&self.a.domain()).max(1e-300);
        let mut snapped = [(0.0, 0.0); 2];
        for (k, (s, t)) in ends.into_iter().enumerate() {
            let (s, t) = (snap(s, pieces_a, wa), snap(t, pieces_b, wb));
            // At the end of a piece of B, the end on A is where A passes B's end point.
            let at_a = pieces_a.iter().any(|p| p.range.contains(&s));
            let s = if !at_a && pieces_b.iter().any(|p| p.range.contains(&t)) {
                let ra = self.a.domain();
                let point = self.b.evaluate(t)?.position;
                let (gap, on_a) = project(self.a, &self.da, &self.ha, point, s, ra.start, ra.end)?;
                if gap <= on {
                    snap(on_a, pieces_a, wa)
                } else {
                    s
                }
            } else {
                s
            };
            snapped[k] = (s, t);
        }
        let ends = snapped;
        let (s0, s1) = (ends[0].0.min(ends[1].0), ends[0].0.max(ends[1].0));
        let (t0, t1) = (ends[0].1.min(ends[1].1), ends[0].1.max(ends[1].1));
        if s1 - s0 <= SAME * 1e3 * width(&self.a.domain()) {
            // A point, not a stretch (the contact is at the end of both pieces).
            return Ok(None);
        }
        Ok(Some((s0..s1, t0..t1)))
    }

    /// Pairs crowd: look for sub-pieces of `A` that lie on `B`: nine points of each within
    /// 1e-12 of the size of the sub-pieces of `B` it is paired with (at most 512 sub-pieces of
    /// `A`, evenly spread in `s`, are tested; each test is nine nearest-point searches). The
    /// curves share a stretch when at least a quarter of the tested sub-pieces lie on `B` and
    /// the stretch they span ends, at both of its ends, where a piece of either curve ends
    /// (or, for one curve, where it turns back onto itself, `s = t`): two polynomial (or
    /// rational) pieces that agree along an interval agree along the whole of both pieces, so
    /// a shared stretch can only stop where a piece stops. A contact of high order (`y = x^4`
    /// touching `y = 0`) crowds the pairs too, but in the middle of the pieces: it is no
    /// overlap, and its roots are one contact.
    pub(super) fn check_overlap(
        &self,
        pairs: &[(Sub, Sub)],
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<(), IntersectError> {
        // The pairs grouped by their sub-piece of A, in order of s.
        let mut sorted: Vec<&(Sub, Sub)> = pairs
            .iter()
            .filter(|(x, y)| !(self.same && x.range == y.range))
            .collect();
        sorted.sort_by(|p, q| {
            p.0.range[0]
                .total_cmp(&q.0.range[0])
                .then(p.0.range[1].total_cmp(&q.0.range[1]))
        });
        let mut groups: Vec<&[&(Sub, Sub)]> = Vec::new();
        let mut start = 0;
        for k in 1..=sorted.len() {
            if k == sorted.len() || sorted[k].0.range != sorted[start].0.range {
                groups.push(&sorted[start..k]);
                start = k;
            }
        }
        if groups.is_empty() {
            return Ok(());
        }
        let stride = groups.len().div_ceil(512);
        let tested: Vec<&[&(Sub, Sub)]> = groups.iter().step_by(stride).copied().collect();
        // (s range, t range) of each tested sub-piece of A that lies on B.
        let mut on: Vec<Spans> = Vec::new();
        for group in &tested {
            let x = &group[0].0;
            let pieces: Vec<Piece<2>> = group
                .iter()
                .map(|(_, y)| Piece {
                    start: y.range[0],
                    end: y.range[1],
                    points: y.points.clone(),
                    weights: y.weights.clone(),
                    jump_at_end: false,
                })
                .collect();
            let mut all = true;
            for k in 0..=8 {
                let s = x.range[0] + (x.range[1] - x.range[0]) * k as f64 / 8.0;
                let p = self.a.evaluate(s)?.position;
                let gap = pieces
                    .iter()
                    .map(|piece| distance_to_piece(piece.clone(), &p))
                    .fold(f64::INFINITY, f64::min);
                if gap > ON * self.scale {
                    all = false;
                    break;
                }
            }
            if all {
                let t = group
                    .iter()
                    .fold([f64::INFINITY, f64::NEG_INFINITY], |m, (_, y)| {
                        [m[0].min(y.range[0]), m[1].max(y.range[1])]
                    });
                on.push((x.range, t));
            }
        }
        if on.is_empty() || on.len() * 4 < tested.len() {
            return Ok(());
        }
        let a = on.iter().fold(f64::INFINITY, |m, p| m.min(p.0[0]))
            ..on.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.0[1]));
        let b = on.iter().fold(f64::INFINITY, |m, p| m.min(p.1[0]))
            ..on.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.1[1]));
        // The stretch's ends, as (s, t): B runs along A or against it (`on` is in order of s).
        let along = on[0].1[0] <= on[on.len() - 1].1[0];
        let ends = if along {
            [(a.start, b.start), (a.end, b.end)]
        } else {
            [(a.start, b.end), (a.end, b.start)]
        };
        // How far the tested stretch may stop short of its true end: the widths of the
        // sub-pieces and the spacing of the tested ones.
        let reach = |range: fn(&Spans) -> [f64; 2]| {
            let mut starts: Vec<f64> = on.iter().map(|p| range(p)[0]).collect();
            starts.sort_by(f64::total_cmp);
            let gaps = starts.windows(2).fold(0.0_f64, |m, w| m.max(w[1] - w[0]));
            on.iter()
                .fold(gaps, |m, p| m.max(range(p)[1] - range(p)[0]))
        };
        let (reach_s, reach_t) = (reach(|p| p.0), reach(|p| p.1));
        let boundary = |x: f64, pieces: &[Sub], reach: f64| {
            pieces.iter().any(|p| {
                (x - p.range[0]).abs() <= 2.0 * reach || (x - p.range[1]).abs() <= 2.0 * reach
            })
        };
        let stops = |(s, t): (f64, f64)| {
            boundary(s, pieces_a, reach_s)
                || boundary(t, pieces_b, reach_t)
                || (self.same && (s - t).abs() <= 2.0 * (reach_s + reach_t))
        };
        if ends.into_iter().all(stops) {
            Err(IntersectError::Overlap { a, b })
        } else {
            Ok(())
        }
    }
}
