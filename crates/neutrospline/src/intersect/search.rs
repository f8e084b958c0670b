//! The subdivision search: pairs of sub-pieces halved until small, candidates polished, roots
//! grouped into contacts.

use core::ops::Range;

use super::sub::Sub;
use super::{
    nearest_failure, width, Contact, IntersectError, Intersection, CROWD, MAX_DEPTH, NEAR, SAME,
    SMALL, TANGENT_SINE,
};
use crate::curve::{Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::nearest::NearestPoint;

pub(super) struct Search<'c, A, B> {
    pub(super) a: &'c A,
    pub(super) b: &'c B,
    pub(super) same: bool,
    pub(super) da: CurveDerivative<2>,
    pub(super) db: CurveDerivative<2>,
    /// `A''` and `B''`, for projecting onto the curves.
    pub(super) ha: CurveDerivative<2>,
    pub(super) hb: CurveDerivative<2>,
    pub(super) scale: f64,
}

/// `A(s) - B(t)`, `A'(s)` and `B'(t)` at a parameter pair.
pub(super) type State = ([f64; 2], [f64; 2], [f64; 2]);

/// A stretch two curves share: its parameters on `A` and on `B`.
pub(super) type Stretch = (Range<f64>, Range<f64>);

/// The parameters on `A` and on `B` of a sub-piece of `A` that lies on `B`.
pub(super) type Spans = ([f64; 2], [f64; 2]);

/// How two roots are one contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Joined {
    /// They are the same point (to 1e-6 of each domain).
    Same,
    /// The curves stay within the root tolerance of each other between them.
    Along,
}

/// A polished candidate: parameters, and `|sin theta|` of the tangents there (1 where a
/// tangent vanishes is not known: 0, tangent).
#[derive(Clone, Copy, Debug)]
pub(super) struct Root {
    pub(super) s: f64,
    pub(super) t: f64,
    pub(super) sine: f64,
}

impl<'c, A, B> Search<'c, A, B>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    pub(super) fn new(a: &'c A, b: &'c B, same: bool) -> Self {
        let (da, db) = (a.derivative(), b.derivative());
        Search {
            a,
            b,
            same,
            ha: da.derivative(),
            hb: db.derivative(),
            da,
            db,
            scale: 1.0,
        }
    }

    pub(super) fn run(mut self) -> Result<Vec<Intersection>, IntersectError> {
        let pa: Vec<Sub> = self
            .a
            .bezier_pieces()
            .iter()
            .enumerate()
            .map(|(i, p)| Sub::new(p, i))
            .collect();
        let pb: Vec<Sub> = if self.same {
            pa.clone()
        } else {
            self.b
                .bezier_pieces()
                .iter()
                .enumerate()
                .map(|(i, p)| Sub::new(p, i))
                .collect()
        };
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for s in pa.iter().chain(&pb) {
            for c in 0..2 {
                low[c] = low[c].min(s.low[c]);
                high[c] = high[c].max(s.high[c]);
            }
        }
        let size = (high[0] - low[0]).hypot(high[1] - low[1]);
        self.scale = if size > 0.0 && size.is_finite() {
            size
        } else {
            1.0
        };
        let slack = 1e-12 * self.scale;
        let mut pairs: Vec<(Sub, Sub)> = Vec::new();
        for (i, x) in pa.iter().enumerate() {
            for (j, y) in pb.iter().enumerate() {
                if self.same && j < i {
                    continue;
                }
                pairs.push((x.clone(), y.clone()));
            }
        }
        let mut terminal: Vec<(Sub, Sub)> = Vec::new();
        let mut crowd = CROWD;
        let mut small = SMALL * self.scale;
        while !pairs.is_empty() {
            if pairs.len() > crowd {
                self.check_overlap(&pairs, &pa, &pb)?;
                if pairs.len() > 16 * CROWD {
                    // Still crowding, and no overlap: a contact of high order, where the curves
                    // stay within the boxes' slack of each other along a stretch. The pairs
                    // alive are polished where they are; halving them further would only
                    // multiply them. Their roots are one contact (`collect`).
                    small = pairs
                        .iter()
                        .fold(small, |m, (x, y)| m.max(x.size()).max(y.size()));
                    crowd = usize::MAX;
                } else {
                    crowd = 4 * pairs.len();
                }
            }
            let mut next = Vec::new();
            for (x, y) in pairs {
                let identical = self.same && x.range == y.range;
                let adjacent = self.same && x.range[1] == y.range[0];
                if identical {
                    if x.monotone_with(&[]) {
                        continue;
                    }
                    let (l, r) = x.halves();
                    next.push((l.clone(), l.clone()));
                    next.push((r.clone(), r.clone()));
                    next.push((l, r));
                    continue;
                }
                if adjacent && x.monotone_with(&y.points[1..]) {
                    continue;
                }
                if !x.overlaps(&y, slack) || x.apart_across(&y, slack) || y.apart_across(&x, slack)
                {
                    continue;
                }
                let (xs, ys) = (x.size(), y.size());
                if (xs <= small && ys <= small)
                    || x.depth.max(y.depth) >= MAX_DEPTH
                    || (xs.max(ys) <= NEAR * self.scale && self.touching(&x, &y)?)
                {
                    terminal.push((x, y));
                    continue;
                }
                if xs >= ys {
                    let (l, r) = x.halves();
                    next.push((l, y.clone()));
                    next.push((r, y));
                } else {
                    let (l, r) = y.halves();
                    next.push((x.clone(), l));
                    next.push((x, r));
                }
            }
            pairs = next;
        }
        let mut roots = self.polish_terminal(terminal)?;
        if !self.same {
            roots.extend(self.end_roots()?);
        }
        self.collect(roots, &pa, &pb)
    }

    /// The ends of each curve that lie on the other (within 1e-12 of the size), found by the
    /// global nearest point: curves joined end to end, or an end resting on the other curve.
    /// Where the curves meet there tangentially (a smooth join), subdivision and Newton's
    /// method cannot settle on the end (the systems are singular at the domain's edge); the
    /// nearest point can.
    pub(super) fn end_roots(&self) -> Result<Vec<Root>, IntersectError> {
        let tolerance = 1e-12 * self.scale;
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let mut roots = Vec::new();
        let on_b = self.b.projector();
        for s in [ra.start, ra.end] {
            let near = on_b
                .nearest(self.a.evaluate(s)?.position)
                .map_err(nearest_failure(s))?;
            if near.distance <= tolerance {
                roots.push((s, near.parameter));
            }
        }
        let on_a = self.a.projector();
        for t in [rb.start, rb.end] {
            let near = on_a
                .nearest(self.b.evaluate(t)?.position)
                .map_err(nearest_failure(t))?;
            if near.distance <= tolerance {
                roots.push((near.parameter, t));
            }
        }
        roots
            .into_iter()
            .map(|(s, t)| {
                Ok(Root {
                    s,
                    t,
                    sine: self.sine(s, t)?,
                })
            })
            .collect()
    }

    /// Polishes the pairs that subdivision left (both sub-pieces below 1e-7 of the size):
    /// pairs whose ranges touch in both parameters form a cluster, and a cluster is polished
    /// from each of its pairs when it has at most four (a crossing on the boundary of
    /// sub-pieces), else from its first and last pairs and from the pair whose middles are
    /// nearest each other. Large clusters come from shallow crossings and from tangential
    /// contacts, where the curves stay within the boxes' slack along a stretch (`y = x^4`
    /// and `y = 0`: 2 x 10^4 pairs); Newton's method from any of their pairs reaches the same
    /// point, so polishing each would only repeat it.
    pub(super) fn polish_terminal(
        &self,
        mut terminal: Vec<(Sub, Sub)>,
    ) -> Result<Vec<Root>, IntersectError> {
        terminal.sort_by(|p, q| {
            p.0.range[0]
                .total_cmp(&q.0.range[0])
                .then(p.1.range[0].total_cmp(&q.1.range[0]))
        });
        // (s end, t low, t high, members)
        let mut clusters: Vec<(f64, f64, f64, Vec<usize>)> = Vec::new();
        for (k, (x, y)) in terminal.iter().enumerate() {
            let home = clusters
                .iter_mut()
                .rev()
                .find(|c| x.range[0] <= c.0 && y.range[0] <= c.2 && y.range[1] >= c.1);
            match home {
                Some(c) => {
                    c.0 = c.0.max(x.range[1]);
                    c.1 = c.1.min(y.range[0]);
                    c.2 = c.2.max(y.range[1]);
                    c.3.push(k);
                }
                None => clusters.push((x.range[1], y.range[0], y.range[1], vec![k])),
            }
        }
        let middle = |k: usize| {
            let (x, y) = &terminal[k];
            [
                0.5 * (x.range[0] + x.range[1]),
                0.5 * (y.range[0] + y.range[1]),
            ]
        };
        let mut roots: Vec<Root> = Vec::new();
        for (_, _, _, members) in &clusters {
            // A cluster that holds a root found from an earlier one (Newton's method converges
            // to a contact from the pairs all around it) adds nothing.
            let holds = |r: &Root| {
                members.iter().any(|&k| {
                    let (x, y) = &terminal[k];
                    x.range[0] <= r.s && r.s <= x.range[1] && y.range[0] <= r.t && r.t <= y.range[1]
                })
            };
            if roots.iter().any(holds) {
                continue;
            }
            let starts: Vec<usize> = if members.len() <= 4 {
                members.clone()
            } else {
                let mut nearest = (f64::INFINITY, members[0]);
                for &k in members {
                    let [s, t] = middle(k);
                    let (f, _, _) = self.state(s, t)?;
                    let gap = f[0].hypot(f[1]);
                    if gap < nearest.0 {
                        nearest = (gap, k);
                    }
                }
                vec![members[0], nearest.1, members[members.len() - 1]]
            };
            for k in starts {
                if let Some((s, t)) = self.polish(middle(k))? {
                    roots.push(Root {
                        s,
                        t,
                        sine: self.sine(s, t)?,
                    });
                }
            }
        }
        Ok(roots)
    }

    /// Groups the roots into contacts, orders them by `s` and evaluates them.
    ///
    /// Two roots are one contact when they are the same point (within 1e-9 of each domain,
    /// times 1e3), or when they lie within 1e-3 of each domain of each other, at least one is
    /// nearly tangent (`|sin theta| <= 1e-3`) and the curves stay within the root tolerance
    /// (1e-12 of the size) of each other half-way between them: the roots that Newton's method
    /// finds from every sub-piece along a tangential contact, where the curves separate only
    /// at second or higher order. Distinct crossings near a tangency are apart by more than
    /// that (the curves separate between them). A group of several roots is a tangential
    /// contact, reported at its most tangent root (an end of a curve, when one is in it).
    ///
    /// A tangential contact may be a stretch the curves share: [`Search::shared_stretch`]
    /// decides, and the stretch is refused as [`IntersectError::Overlap`].
    pub(super) fn collect(
        &self,
        mut roots: Vec<Root>,
        pieces_a: &[Sub],
        pieces_b: &[Sub],
    ) -> Result<Vec<Intersection>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let wa = width(&ra);
        // A closed curve (its end is its start) meets at its end where it meets at its start:
        // the root is reported at the start, once.
        let (closed_a, closed_b) = (self.closed(self.a)?, self.closed(self.b)?);
        for r in &mut roots {
            if closed_a && r.s == ra.end {
                r.s = ra.start;
            }
            if closed_b && r.t == rb.end {
                r.t = rb.start;
            }
        }
        if self.same {
            // Self-intersections: t_a < t_b, the trivial s = t dropped.
            roots = roots
                .into_iter()
                .map(|r| {
                    if r.s <= r.t {
                        r
                    } else {
                        Root {
                            s: r.t,
                            t: r.s,
                            sine: r.sine,
                        }
                    }
                })
                .filter(|r| r.t - r.s > SAME * wa.max(1e-300) * 1e3)
                .collect();
            // A root near the diagonal that rounding cannot tell from it is no loop: at a cusp
            // `C(1/2 - h)` and `C(1/2 + h)` agree to rounding for h up to about 1e-5, where
            // the tangents are nearly opposite. Newton's step on `A(s) - A(t)` moves the
            // parameters by `|J^-1| rounding`, `J = [A'(s), -A'(t)]`, `|J^-1| <= |J|_F / |det J|`;
            // a root whose `t - s` is within that uncertainty is dropped.
            let mut kept = Vec::with_capacity(roots.len());
            for r in roots {
                if r.t - r.s > NEAR * wa || self.apart_beyond_rounding(&r)? {
                    kept.push(r);
                }
            }
            roots = kept;
        }
        roots.sort_by(|p, q| p.s.total_cmp(&q.s).then(p.t.total_cmp(&q.t)));
        // Each group: its roots, and whether two of them are distinct points joined because the
        // curves stay together between them (a tangential contact).
        let mut groups: Vec<(Vec<Root>, bool)> = Vec::new();
        for r in roots {
            let mut home = None;
            for (k, (g, _)) in groups.iter().enumerate().rev() {
                let last = g[g.len() - 1];
                if r.s - last.s > NEAR * wa.max(1e-300) {
                    continue;
                }
                if let Some(joined) = self.one_contact(&last, &r)? {
                    home = Some((k, joined));
                    break;
                }
            }
            match home {
                Some((k, joined)) => {
                    groups[k].0.push(r);
                    groups[k].1 |= joined == Joined::Along;
                }
                None => groups.push((vec![r], false)),
            }
        }
        let at_end = |r: &Root| {
            (!closed_a && (r.s == ra.start || r.s == ra.end))
                || (!closed_b && (r.t == rb.start || r.t == rb.end))
        };
        let mut found = Vec::with_capacity(groups.len());
        for (g, along) in &groups {
            let chosen = g
                .iter()
                .find(|r| at_end(r))
                .or_else(|| g.iter().min_by(|p, q| p.sine.total_cmp(&q.sine)))
                .copied()
                .expect("a group holds a root");
            let tangent = *along || chosen.sine <= TANGENT_SINE;
            if tangent {
                if let Some((a, b)) = self.shared_stretch(chosen, pieces_a, pieces_b)? {
                    return Err(IntersectError::Overlap { a, b });
                }
            }
            let contact = if at_end(&chosen) {
                Contact::End
            } else if tangent {
                Contact::Tangent
            } else {
                Contact::Crossing
            };
            found.push(Intersection {
                parameter_a: chosen.s,
                parameter_b: chosen.t,
                point_a: self.a.evaluate(chosen.s)?,
                point_b: self.b.evaluate(chosen.t)?,
                contact,
            });
        }
        found.sort_by(|p, q| {
            p.parameter_a
                .total_cmp(&q.parameter_a)
                .then(p.parameter_b.total_cmp(&q.parameter_b))
        });
        Ok(found)
    }

    /// Whether a self-intersection root `r` (`r.s < r.t`) is farther from the diagonal than
    /// the rounding of its parameters: `t - s > 16 eps scale |J|_F / |det J|` with
    /// `J = [A'(s), -A'(t)]` (see [`Search::collect`]).
    fn apart_beyond_rounding(&self, r: &Root) -> Result<bool, EvalError> {
        let p = self.da.evaluate(r.s)?.position;
        let q = self.da.evaluate(r.t)?.position;
        let det = (p[0] * q[1] - p[1] * q[0]).abs();
        let frobenius = (p[0] * p[0] + p[1] * p[1] + q[0] * q[0] + q[1] * q[1]).sqrt();
        let unsure = 16.0 * f64::EPSILON * self.scale * frobenius;
        Ok(r.t - r.s > 0.0 && (r.t - r.s) * det > unsure)
    }

    /// Whether roots `p` and `q` (`p.s <= q.s`) are one contact (see [`Search::collect`]),
    /// and how.
    pub(super) fn one_contact(&self, p: &Root, q: &Root) -> Result<Option<Joined>, EvalError> {
        let (wa, wb) = (
            width(&self.a.domain()).max(1e-300),
            width(&self.b.domain()).max(1e-300),
        );
        let (ds, dt) = ((q.s - p.s).abs(), (q.t - p.t).abs());
        if ds <= SAME * wa * 1e3 && dt <= SAME * wb * 1e3 {
            return Ok(Some(Joined::Same));
        }
        if ds > NEAR * wa || dt > NEAR * wb || p.sine.min(q.sine) > NEAR {
            return Ok(None);
        }
        let middle = self.a.evaluate(0.5 * (p.s + q.s))?.position;
        let (lo, hi) = (p.t.min(q.t), p.t.max(q.t));
        Ok(
            (self.gap_to_b(middle, 0.5 * (lo + hi), lo, hi)? <= 1e-12 * self.scale)
                .then_some(Joined::Along),
        )
    }
}
