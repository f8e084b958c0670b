//! Newton's method at a candidate (crossing or tangency), projections onto `B`, and the
//! tolerances that decide that two curves meet.

use core::ops::Range;

use super::search::{Search, State};
use super::sub::Sub;
use super::{project, width, IntersectError};
use crate::curve::{Derivative, EvalError, Evaluate};
use crate::derivative::CurveDerivative;
use crate::nearest::NearestPoint;
use crate::point::CurvePoint;

impl<'c, A, B> Search<'c, A, B>
where
    A: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
    B: NearestPoint<2> + Derivative<Output = CurveDerivative<2>>,
{
    /// The distance from `point` to `B` on `[lo, hi]`, by Newton's method on
    /// `(B(t) - point) . B'(t) = 0` from `t` (the smallest distance met).
    pub(super) fn gap_to_b(
        &self,
        point: [f64; 2],
        t: f64,
        lo: f64,
        hi: f64,
    ) -> Result<f64, EvalError> {
        Ok(self.project_on_b(point, t, lo, hi)?.0)
    }

    /// [`Search::gap_to_b`], with the parameter on `B` where it is met.
    pub(super) fn project_on_b(
        &self,
        point: [f64; 2],
        t: f64,
        lo: f64,
        hi: f64,
    ) -> Result<(f64, f64), EvalError> {
        project(self.b, &self.db, &self.hb, point, t, lo, hi)
    }

    /// Whether the middle of `x` lies on `y` (within the root tolerance, 1e-12 of the size):
    /// a pair inside a tangential contact, where the curves stay together along a stretch.
    /// Such a pair is polished where it is; halving it would only multiply the pairs of the
    /// contact (the subdivision of `y = x^8` touching `y = 0` down to 1e-7 makes 3 x 10^5).
    /// A crossing inside it is found by the polish (and a second one, if the curves stay
    /// within the tolerance of each other between them, is the same contact).
    pub(super) fn touching(&self, x: &Sub, y: &Sub) -> Result<bool, EvalError> {
        let middle = self.a.evaluate(0.5 * (x.range[0] + x.range[1]))?.position;
        let gap = self.gap_to_b(
            middle,
            0.5 * (y.range[0] + y.range[1]),
            y.range[0],
            y.range[1],
        )?;
        Ok(gap <= 1e-12 * self.scale)
    }

    /// The root tolerance at `(s, t)`: 1e-12 of the size, or what the parameters can resolve
    /// there when that is more (a domain far from 0 and narrow, `[1e4, 1e4 + 1e-3]`, moves
    /// the point by `|A'(s)| ulp(s)` per step of the float `s`).
    pub(super) fn tolerance(&self, s: f64, t: f64, va: [f64; 2], vb: [f64; 2]) -> f64 {
        let resolution =
            2.0 * f64::EPSILON * (s.abs() * va[0].hypot(va[1]) + t.abs() * vb[0].hypot(vb[1]));
        1e-12 * self.scale
            + if resolution.is_finite() {
                resolution
            } else {
                0.0
            }
    }

    /// `|sin theta|` between `A'(s)` and `B'(t)`; 0 where a tangent vanishes.
    pub(super) fn sine(&self, s: f64, t: f64) -> Result<f64, EvalError> {
        let (_, va, vb) = self.state(s, t)?;
        let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
        Ok(if norm > 0.0 && norm.is_finite() {
            ((va[0] * vb[1] - va[1] * vb[0]) / norm).abs()
        } else {
            0.0
        })
    }

    /// Whether `curve` ends where it starts (to 1e-12 of the size).
    pub(super) fn closed<C: Evaluate<Point = CurvePoint<2>>>(
        &self,
        curve: &C,
    ) -> Result<bool, EvalError> {
        let (p, q) = (curve.start()?.position, curve.end()?.position);
        Ok((p[0] - q[0]).hypot(p[1] - q[1]) <= 1e-12 * self.scale)
    }

    /// `A(s) - B(t)`, `A'(s)` and `B'(t)`.
    pub(super) fn state(&self, s: f64, t: f64) -> Result<State, EvalError> {
        let pa = self.a.evaluate(s)?.position;
        let pb = self.b.evaluate(t)?.position;
        let va = self.da.evaluate(s)?.position;
        let vb = self.db.evaluate(t)?.position;
        Ok(([pa[0] - pb[0], pa[1] - pb[1]], va, vb))
    }

    /// [`Search::newton`], with a root next to an end of a domain moved onto the end when the
    /// curves meet there too (curves that meet at their ends, the seam of a closed curve).
    pub(super) fn polish(&self, start: [f64; 2]) -> Result<Option<(f64, f64)>, IntersectError> {
        let Some(root) = self.newton(start)? else {
            return Ok(None);
        };
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let near = |x: f64, r: &Range<f64>| {
            let close = 1e-9 * width(r);
            if (x - r.start).abs() <= close {
                r.start
            } else if (x - r.end).abs() <= close {
                r.end
            } else {
                x
            }
        };
        let snapped = (near(root.0, &ra), near(root.1, &rb));
        if snapped != root {
            let (f, _, _) = self.state(snapped.0, snapped.1)?;
            if f[0].hypot(f[1]) <= 1e-12 * self.scale {
                return Ok(Some(snapped));
            }
        }
        Ok(Some(root))
    }

    /// Newton's method from `start` on `A(s) - B(t) = 0`, then, where the curves are nearly
    /// tangent, on the tangency system; `None` when the curves do not meet there.
    pub(super) fn newton(&self, start: [f64; 2]) -> Result<Option<(f64, f64)>, IntersectError> {
        let (ra, rb) = (self.a.domain(), self.b.domain());
        let clamp = |s: f64, t: f64| (s.clamp(ra.start, ra.end), t.clamp(rb.start, rb.end));
        let (mut s, mut t) = (start[0], start[1]);
        let mut best: Option<(f64, f64, f64)> = None;
        for _ in 0..60 {
            let (f, va, vb) = self.state(s, t)?;
            let gap = f[0].hypot(f[1]);
            if best.is_none_or(|(g, _, _)| gap < g) {
                best = Some((gap, s, t));
            }
            // Solve [va, -vb] (ds, dt) = -f.
            let det = -va[0] * vb[1] + vb[0] * va[1];
            let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
            if det.abs() <= 1e-10 * norm || norm == 0.0 {
                break;
            }
            let ds = (vb[0] * f[1] - f[0] * vb[1]) / det;
            let dt = (va[0] * f[1] - f[0] * va[1]) / det;
            let (ns, nt) = clamp(s - ds, t - dt);
            if ns == s && nt == t {
                break;
            }
            s = ns;
            t = nt;
        }
        let (gap, bs, bt) = best.unwrap_or((f64::INFINITY, s, t));
        let (_, va, vb) = self.state(bs, bt)?;
        let tolerance = self.tolerance(bs, bt, va, vb);
        let cross = (va[0] * vb[1] - va[1] * vb[0]).abs();
        let norm = va[0].hypot(va[1]) * vb[0].hypot(vb[1]);
        if gap <= tolerance && cross > 1e-6 * norm {
            return Ok(Some((bs, bt)));
        }
        // Nearly tangent: A' x B' = 0 and (A - B) . A' = 0.
        let (mut s, mut t) = (bs, bt);
        let (ha, hb) = (self.da.derivative(), self.db.derivative());
        for _ in 0..60 {
            let (f, va, vb) = self.state(s, t)?;
            let aa = ha.evaluate(s)?.position;
            let bb = hb.evaluate(t)?.position;
            let cross = |p: [f64; 2], q: [f64; 2]| p[0] * q[1] - p[1] * q[0];
            let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
            let g = [cross(va, vb), dot(f, va)];
            let j = [
                [cross(aa, vb), cross(va, bb)],
                [dot(va, va) + dot(f, aa), -dot(vb, va)],
            ];
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if det == 0.0 || !det.is_finite() {
                break;
            }
            let ds = (g[0] * j[1][1] - j[0][1] * g[1]) / det;
            let dt = (j[0][0] * g[1] - j[1][0] * g[0]) / det;
            let (ns, nt) = clamp(s - ds, t - dt);
            if ns == s && nt == t {
                break;
            }
            s = ns;
            t = nt;
        }
        let (f, _, _) = self.state(s, t)?;
        if f[0].hypot(f[1]) <= tolerance {
            return Ok(Some((s, t)));
        }
        if gap <= tolerance {
            return Ok(Some((bs, bt)));
        }
        // Both systems are singular where the curves run together (an overlap, a contact of
        // high order, parallel lines): the start's point of A projected onto B.
        let (s, t) = clamp(start[0], start[1]);
        let point = self.a.evaluate(s)?.position;
        let (gap, t) = self.project_on_b(point, t, rb.start, rb.end)?;
        Ok((gap <= tolerance).then_some((s, t)))
    }
}
