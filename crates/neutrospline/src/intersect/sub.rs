//! Sub-pieces of the curves' Bézier pieces: boxes, halving, the tests that prune a pair.

use crate::bernstein::Packed;
use crate::nearest::Piece;

/// A sub-piece: homogeneous control data, and its parameters on the curve.
#[derive(Clone, Debug)]
pub(super) struct Sub {
    pub(super) points: Vec<[f64; 2]>,
    pub(super) weights: Option<Vec<f64>>,
    pub(super) range: [f64; 2],
    pub(super) low: [f64; 2],
    pub(super) high: [f64; 2],
    pub(super) depth: usize,
    /// The index of the piece it came from (self-intersections: adjacency).
    pub(super) piece: usize,
}

impl Sub {
    pub(super) fn new(piece: &Piece<2>, index: usize) -> Sub {
        Sub::with(
            piece.points.clone(),
            piece.weights.clone(),
            [piece.start, piece.end],
            0,
            index,
        )
    }

    pub(super) fn with(
        points: Vec<[f64; 2]>,
        weights: Option<Vec<f64>>,
        range: [f64; 2],
        depth: usize,
        piece: usize,
    ) -> Sub {
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for p in &points {
            for a in 0..2 {
                low[a] = low[a].min(p[a]);
                high[a] = high[a].max(p[a]);
            }
        }
        Sub {
            points,
            weights,
            range,
            low,
            high,
            depth,
            piece,
        }
    }

    pub(super) fn size(&self) -> f64 {
        (self.high[0] - self.low[0]).hypot(self.high[1] - self.low[1])
    }

    pub(super) fn overlaps(&self, other: &Sub, slack: f64) -> bool {
        (0..2).all(|a| self.low[a] <= other.high[a] + slack && other.low[a] <= self.high[a] + slack)
    }

    /// Whether the control points of `self` and `other` lie in disjoint bands across the
    /// chord of `self` (more than `slack` apart along its normal): then the pieces cannot
    /// meet (each lies in the convex hull of its control points, positive weights included).
    /// Boxes along the axes cannot part two nearly coincident pieces at 45 degrees until they
    /// are as small as their distance; these bands can (an osculating pair of curves, 1e-9
    /// apart at 1e-3 of the size from their contact, is parted at once, not after 10^5 pieces).
    pub(super) fn apart_across(&self, other: &Sub, slack: f64) -> bool {
        let (first, last) = (self.points[0], self.points[self.points.len() - 1]);
        let chord = [last[0] - first[0], last[1] - first[1]];
        let length = chord[0].hypot(chord[1]);
        if !(length > 0.0 && length.is_finite()) {
            return false;
        }
        let normal = [-chord[1] / length, chord[0] / length];
        let band = |points: &[[f64; 2]]| {
            points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    let along = (p[0] - first[0]) * normal[0] + (p[1] - first[1]) * normal[1];
                    (lo.min(along), hi.max(along))
                })
        };
        let (a, b) = (band(&self.points), band(&other.points));
        a.1 + slack < b.0 || b.1 + slack < a.0
    }

    /// The halves at the middle (de Casteljau on the homogeneous points `(w x, w y, w)`,
    /// [`Packed::split`]).
    pub(super) fn halves(&self) -> (Sub, Sub) {
        let weight = |i: usize| self.weights.as_ref().map_or(1.0, |w| w[i]);
        let rows = self
            .points
            .iter()
            .enumerate()
            .flat_map(|(i, p)| {
                let w = weight(i);
                [p[0] * w, p[1] * w, w]
            })
            .collect();
        let (left, right) = Packed::new(3, rows).split(0.5);
        let mid = 0.5 * (self.range[0] + self.range[1]);
        let unpack = |half: &Packed| -> (Vec<[f64; 2]>, Option<Vec<f64>>) {
            let rows = half.data().chunks_exact(3);
            let points = rows.clone().map(|r| [r[0] / r[2], r[1] / r[2]]).collect();
            let weights = self.weights.as_ref().map(|_| rows.map(|r| r[2]).collect());
            (points, weights)
        };
        let (lp, lw) = unpack(&left);
        let (rp, rw) = unpack(&right);
        (
            Sub::with(lp, lw, [self.range[0], mid], self.depth + 1, self.piece),
            Sub::with(rp, rw, [mid, self.range[1]], self.depth + 1, self.piece),
        )
    }

    /// Whether the piece moves monotonically in some direction: every difference
    /// `P_j - P_i` (`i < j`) of its control points lies in one open half-plane (then it cannot
    /// cross itself). `others` are control points that follow it (an adjacent piece).
    pub(super) fn monotone_with(&self, others: &[[f64; 2]]) -> bool {
        let all: Vec<[f64; 2]> = self.points.iter().chain(others).copied().collect();
        let mut angles = Vec::new();
        for i in 0..all.len() {
            for j in i + 1..all.len() {
                let d = [all[j][0] - all[i][0], all[j][1] - all[i][1]];
                if d != [0.0, 0.0] {
                    angles.push(d[1].atan2(d[0]));
                }
            }
        }
        if angles.is_empty() {
            return true;
        }
        angles.sort_by(f64::total_cmp);
        let mut gap = angles[0] + 2.0 * core::f64::consts::PI - angles[angles.len() - 1];
        for w in angles.windows(2) {
            gap = gap.max(w[1] - w[0]);
        }
        // A half-plane leaves a gap of more than pi (with a margin for rounding).
        gap > core::f64::consts::PI + 1e-9
    }
}
