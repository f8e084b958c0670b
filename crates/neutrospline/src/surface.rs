//! Tensor-product neutrosophic surfaces: Bézier, B-spline and NURBS (Topal and Tas 2018).

use core::fmt;
use core::ops::Range;

use crate::any_curve::AnyCurve;
use crate::bezier::Bezier;
use crate::curve::{check_parameter, CurveError, EvalError};
use crate::knots::{KnotError, KnotVector};
use crate::layout::{derivative_from_row, pack_points, point_from_row, stride};
use crate::point::{BoundingBox, ControlPoint, CurvePoint, DerivativeValue};
use crate::spline::{bezier_knots, blossom, Spline};
use crate::spline_curve::{check_weights, BSpline, Nurbs};

/// Evaluation of a parametric surface: a neutrosophic surface (whose points are
/// [`CurvePoint`]s), in the style of the curve trait [`Evaluate`](crate::Evaluate).
///
/// ```
/// use neutrospline::{ControlPoint, Degrees, EvaluateSurface, Surface};
/// let d = Degrees::new(0.5, 0.25, 0.0)?;
/// let grid = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
///     .map(|p| ControlPoint::new(p, d));
/// let s = Surface::bezier(2, 2, grid.to_vec())?;
/// assert_eq!(s.domain(), [0.0..1.0, 0.0..1.0]);
/// assert_eq!(s.evaluate(1.0, 1.0)?.position, [1.0, 1.0, 1.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait EvaluateSurface {
    /// What the surface yields at a parameter pair.
    type Point: Copy;

    /// The parameter domains `[u, v]` (each closed at both ends).
    fn domain(&self) -> [Range<f64>; 2];

    /// The point at `(u, v)`.
    ///
    /// # Errors
    /// A parameter not finite or outside its domain.
    fn evaluate(&self, u: f64, v: f64) -> Result<Self::Point, EvalError>;

    /// Evaluates at every `[u, v]` pair of `params` into `out` (same length).
    ///
    /// # Errors
    /// The first pair that fails; `out` is then partly written.
    ///
    /// # Panics
    /// If `out.len() != params.len()`.
    fn evaluate_many(&self, params: &[[f64; 2]], out: &mut [Self::Point]) -> Result<(), EvalError> {
        assert_eq!(
            params.len(),
            out.len(),
            "evaluate_many: params and out differ in length"
        );
        for (&[u, v], slot) in params.iter().zip(out.iter_mut()) {
            *slot = self.evaluate(u, v)?;
        }
        Ok(())
    }
}

/// The kinds of tensor-product surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceKind {
    /// Bézier in both directions: degrees `rows - 1` and `cols - 1`.
    Bezier,
    /// B-spline in both directions.
    BSpline,
    /// NURBS: B-spline with a positive weight per control point.
    Nurbs,
}

impl SurfaceKind {
    /// The name used in files: `bezier-surface`, `bspline-surface`, `nurbs-surface`.
    pub const fn name(self) -> &'static str {
        match self {
            SurfaceKind::Bezier => "bezier-surface",
            SurfaceKind::BSpline => "bspline-surface",
            SurfaceKind::Nurbs => "nurbs-surface",
        }
    }
}

impl fmt::Display for SurfaceKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Which parameter direction of a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// The `u` direction, along which the row index varies.
    U,
    /// The `v` direction, along which the column index varies.
    V,
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Direction::U => "u",
            Direction::V => "v",
        })
    }
}

/// Why a surface cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SurfaceError {
    /// A problem with the control points or weights.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// The knots of one direction are invalid.
    #[error("knots_{direction}: {source}")]
    Knots {
        /// The direction.
        direction: Direction,
        /// What is wrong.
        source: KnotError,
    },
}

/// The partial derivatives of a surface at a parameter pair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceDerivatives {
    /// d/du of position and degrees.
    pub du: DerivativeValue<3>,
    /// d/dv of position and degrees.
    pub dv: DerivativeValue<3>,
}

/// A tensor-product neutrosophic surface in 3-D over a `rows x cols` grid of control points.
///
/// ```text
/// S(u, v) = sum_i sum_j R_{ij}(u, v) P_ij,   R_ij = w_ij N_i(u) N_j(v) / sum_kl w_kl N_k(u) N_l(v)
/// ```
///
/// and likewise for the three degrees (with `w_ij = 1` for Bézier and B-spline surfaces;
/// Bézier surfaces use the Bernstein basis, i.e. single-span clamped knots on \[0, 1\]). The
/// row index `i` runs along `u`, the column index `j` along `v`; control points are stored
/// row by row. Evaluation runs the curve algorithm along `v` in each row, then along `u`:
/// every step is a convex combination, so the degrees stay in the control range.
///
/// ```
/// use neutrospline::{ControlPoint, Degrees, EvaluateSurface, Surface};
/// let d = |t| Degrees::new(t, 0.0, 1.0 - t).unwrap();
/// let grid = vec![
///     ControlPoint::new([0.0, 0.0, 0.0], d(0.0)),
///     ControlPoint::new([0.0, 1.0, 0.0], d(0.5)),
///     ControlPoint::new([1.0, 0.0, 0.0], d(0.5)),
///     ControlPoint::new([1.0, 1.0, 1.0], d(1.0)),
/// ];
/// let s = Surface::bezier(2, 2, grid)?;
/// let p = s.evaluate(0.5, 0.5)?;
/// assert_eq!(p.position, [0.5, 0.5, 0.25]);
/// assert_eq!(p.degrees.truth(), 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    pub(crate) kind: SurfaceKind,
    pub(crate) rows: usize,
    pub(crate) cols: usize,
    pub(crate) knots_u: KnotVector,
    pub(crate) knots_v: KnotVector,
    pub(crate) data: Vec<f64>,
    pub(crate) weights: Option<Vec<f64>>,
    /// Rows `(w P, w)` of the homogeneous form (weight 1 without weights), for derivatives.
    pub(crate) homogeneous: Vec<f64>,
}

pub(crate) const S: usize = stride(3);

impl Surface {
    /// A Bézier surface of degrees `rows - 1` (in u) and `cols - 1` (in v).
    ///
    /// # Errors
    /// [`CurveError::GridSize`] when `control_points.len() != rows * cols` (or a dimension
    /// is 0), a non-finite position.
    pub fn bezier(
        rows: usize,
        cols: usize,
        control_points: Vec<ControlPoint<3>>,
    ) -> Result<Self, SurfaceError> {
        check_grid(rows, cols, control_points.len())?;
        // The B-spline surface over the Bézier knots (one patch), marked as a Bézier surface.
        let knots_u = bezier_knots(rows - 1);
        let knots_v = bezier_knots(cols - 1);
        let mut surface = Surface::bspline(rows, cols, control_points, knots_u, knots_v)?;
        surface.kind = SurfaceKind::Bezier;
        Ok(surface)
    }

    /// A B-spline surface over the given knots (degrees are the knots').
    ///
    /// # Errors
    /// Grid size, non-finite positions, knots invalid for `rows` (u) or `cols` (v).
    pub fn bspline(
        rows: usize,
        cols: usize,
        control_points: Vec<ControlPoint<3>>,
        knots_u: KnotVector,
        knots_v: KnotVector,
    ) -> Result<Self, SurfaceError> {
        Surface::build(
            SurfaceKind::BSpline,
            rows,
            cols,
            control_points,
            None,
            knots_u,
            knots_v,
        )
    }

    /// A NURBS surface: one positive weight per control point, row by row.
    ///
    /// # Errors
    /// As [`Surface::bspline`]; weight count or a weight that is not positive and finite.
    pub fn nurbs(
        rows: usize,
        cols: usize,
        control_points: Vec<ControlPoint<3>>,
        weights: Vec<f64>,
        knots_u: KnotVector,
        knots_v: KnotVector,
    ) -> Result<Self, SurfaceError> {
        Surface::build(
            SurfaceKind::Nurbs,
            rows,
            cols,
            control_points,
            Some(weights),
            knots_u,
            knots_v,
        )
    }

    fn build(
        kind: SurfaceKind,
        rows: usize,
        cols: usize,
        control_points: Vec<ControlPoint<3>>,
        weights: Option<Vec<f64>>,
        knots_u: KnotVector,
        knots_v: KnotVector,
    ) -> Result<Self, SurfaceError> {
        check_grid(rows, cols, control_points.len())?;
        let data = pack_points(&control_points)?;
        if let Some(w) = &weights {
            check_weights(w, control_points.len())?;
        }
        for (direction, knots, count) in [
            (Direction::U, &knots_u, rows),
            (Direction::V, &knots_v, cols),
        ] {
            if knots.control_count() != count {
                return Err(SurfaceError::Knots {
                    direction,
                    source: KnotError::WrongLength {
                        got: knots.knots().len(),
                        expected: count + knots.degree() + 1,
                    },
                });
            }
        }
        Ok(Surface::from_parts(
            kind, rows, cols, knots_u, knots_v, data, weights,
        ))
    }

    /// A surface of checked parts (its homogeneous rows computed here).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts(
        kind: SurfaceKind,
        rows: usize,
        cols: usize,
        knots_u: KnotVector,
        knots_v: KnotVector,
        data: Vec<f64>,
        weights: Option<Vec<f64>>,
    ) -> Surface {
        let homogeneous = homogeneous_rows(&data, weights.as_deref());
        Surface {
            kind,
            rows,
            cols,
            knots_u,
            knots_v,
            data,
            weights,
            homogeneous,
        }
    }

    /// The kind of surface.
    pub fn kind(&self) -> SurfaceKind {
        self.kind
    }

    /// Number of control points along u.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of control points along v.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Polynomial degree in u.
    pub fn degree_u(&self) -> usize {
        self.knots_u.degree()
    }

    /// Polynomial degree in v.
    pub fn degree_v(&self) -> usize {
        self.knots_v.degree()
    }

    /// Knots in u.
    pub fn knots_u(&self) -> &KnotVector {
        &self.knots_u
    }

    /// Knots in v.
    pub fn knots_v(&self) -> &KnotVector {
        &self.knots_v
    }

    /// Knots along `direction`: [`Surface::knots_u`] or [`Surface::knots_v`].
    pub fn knots(&self, direction: Direction) -> &KnotVector {
        match direction {
            Direction::U => &self.knots_u,
            Direction::V => &self.knots_v,
        }
    }

    /// Control point in row `i` (u index) and column `j` (v index).
    ///
    /// # Panics
    /// If `i >= rows()` or `j >= cols()`.
    pub fn control_point(&self, i: usize, j: usize) -> ControlPoint<3> {
        assert!(
            i < self.rows && j < self.cols,
            "control point index out of the grid"
        );
        let k = i * self.cols + j;
        point_from_row(&self.data[k * S..(k + 1) * S])
    }

    /// All control points, row by row.
    pub fn control_points(&self) -> Vec<ControlPoint<3>> {
        self.data.chunks_exact(S).map(point_from_row).collect()
    }

    /// The weights, row by row (NURBS surfaces).
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    fn check(&self, u: f64, v: f64) -> Result<(), EvalError> {
        check_parameter(u, &self.knots_u.domain())?;
        check_parameter(v, &self.knots_v.domain())
    }

    /// Evaluates the row curves (along v at `v`) for the rows that matter at `u`, then the
    /// column (along u at `u`), in Euclidean-rational form; writes the row into `out`.
    fn evaluate_into(&self, u: f64, v: f64, out: &mut [f64]) {
        let (cols, stride) = (self.cols, S);
        let weights = self.weights.as_deref();
        let ku = self.knots_u.span(u);
        let kv = self.knots_v.span(v);
        let pu = self.knots_u.degree();
        let mut column = vec![0.0; self.rows * stride];
        let mut column_w = vec![1.0; self.rows];
        for i in ku - pu..=ku {
            let row = &self.data[i * cols * stride..(i + 1) * cols * stride];
            let row_w = weights.map(|w| &w[i * cols..(i + 1) * cols]);
            column_w[i] = blossom(
                &self.knots_v,
                stride,
                row,
                row_w,
                kv,
                |_| (v, 0.0),
                &mut column[i * stride..(i + 1) * stride],
            );
        }
        let column_weights = weights.map(|_| column_w.as_slice());
        blossom(
            &self.knots_u,
            stride,
            &column,
            column_weights,
            ku,
            |_| (u, 0.0),
            out,
        );
    }

    /// The partial derivatives `dS/du` and `dS/dv` of position and degrees, by the quotient
    /// rule on the homogeneous form `H = sum N_i N_j w_ij (P_ij, 1)`: `S_u = (H_u - H_u^w S) / H^w`.
    ///
    /// # Errors
    /// A parameter not finite or outside its domain; [`EvalError::Overflow`].
    pub fn partial_derivatives(&self, u: f64, v: f64) -> Result<SurfaceDerivatives, EvalError> {
        self.check(u, v)?;
        let hs = S + 1;
        let h = &self.homogeneous;
        // Along u: evaluate every column in v first... by symmetry, build the curve of the
        // other direction at the fixed parameter and differentiate it.
        let du = self.directional(h, hs, Direction::U, u, v);
        let dv = self.directional(h, hs, Direction::V, u, v);
        let (du, dv) = (
            du.ok_or(EvalError::Overflow { t: u })?,
            dv.ok_or(EvalError::Overflow { t: v })?,
        );
        Ok(SurfaceDerivatives { du, dv })
    }

    /// Derivative in `direction` at `(u, v)` from the homogeneous rows `h` (stride `hs`).
    fn directional(
        &self,
        h: &[f64],
        hs: usize,
        direction: Direction,
        u: f64,
        v: f64,
    ) -> Option<DerivativeValue<3>> {
        // The homogeneous iso-curve in `direction` through the fixed other parameter.
        let (along, fixed, fixed_knots, count_along, count_fixed) = match direction {
            Direction::U => (&self.knots_u, v, &self.knots_v, self.rows, self.cols),
            Direction::V => (&self.knots_v, u, &self.knots_u, self.cols, self.rows),
        };
        let index = |a: usize, f: usize| match direction {
            Direction::U => a * self.cols + f,
            Direction::V => f * self.cols + a,
        };
        let t = match direction {
            Direction::U => u,
            Direction::V => v,
        };
        let k = fixed_knots.span(fixed);
        // Only the control lines of the span containing `t` (and so of its derivative)
        // matter; the iso-curve's other rows stay zero and are never read.
        let k_along = along.span(t);
        let first_along = k_along - along.degree();
        let first_fixed = k - fixed_knots.degree();
        let mut iso = vec![0.0; count_along * hs];
        let mut line = vec![0.0; count_fixed * hs];
        for a in first_along..=k_along {
            for f in first_fixed..=k {
                let src = index(a, f);
                line[f * hs..(f + 1) * hs].copy_from_slice(&h[src * hs..(src + 1) * hs]);
            }
            blossom(
                fixed_knots,
                hs,
                &line,
                None,
                k,
                |_| (fixed, 0.0),
                &mut iso[a * hs..(a + 1) * hs],
            );
        }
        let curve = Spline {
            knots: along.clone(),
            stride: hs,
            data: iso,
            weights: None,
        };
        let mut value = [0.0; S + 1];
        let mut rate = [0.0; S + 1];
        curve.evaluate_plain(t, &mut value);
        curve.derivative().evaluate_plain(t, &mut rate);
        let (w, dw) = (value[S], rate[S]);
        let mut row = [0.0; S];
        for c in 0..S {
            row[c] = (rate[c] - dw * (value[c] / w)) / w;
        }
        row.iter()
            .all(|x| x.is_finite())
            .then(|| derivative_from_row(&row))
    }

    /// The mixed partial derivatives of total order `order` of position and degrees at
    /// `(u, v)`: `order + 1` values, `d^order S / du^(order - j) dv^j` for `j = 0 ..= order`
    /// (for order 2: `S_uu`, `S_uv`, `S_vv`).
    ///
    /// With the homogeneous form `H(u, v) = sum_ij N_i(u) N_j(v) w_ij (P_ij, 1)`, a
    /// tensor-product spline whose last channel is the weight function `w`, the partials
    /// `H^(a, b)` come from differentiating the control rows `b` times along v and the
    /// resulting column `a` times along u (each a spline derivative). `S = H / w` then follows
    /// from Leibniz's rule in two variables (The NURBS Book, eq. 4.20):
    ///
    /// ```text
    /// S^(k,l) = ( H^(k,l) - sum_{(i,j) != (0,0), i <= k, j <= l}
    ///             binom(k, i) binom(l, j) w^(i,j) S^(k-i, l-j) ) / w
    /// ```
    ///
    /// For Bézier and B-spline surfaces `w = 1` and every derivative of it vanishes, so
    /// `S^(k,l) = H^(k,l)`. Order 0 gives the point itself (as a [`DerivativeValue`]); the
    /// first-order values equal [`Surface::partial_derivatives`] up to rounding. At an interior
    /// knot the value from the right (above) is returned, as for curves.
    ///
    /// ```
    /// use neutrospline::{ControlPoint, Degrees, Surface};
    /// let d = Degrees::new(0.5, 0.25, 0.0)?;
    /// // z = u v on the bilinear patch: S_uu = 0, S_uv = (0, 0, 1), S_vv = 0.
    /// let grid = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
    ///     .map(|p| ControlPoint::new(p, d));
    /// let s = Surface::bezier(2, 2, grid.to_vec())?;
    /// let second = s.mixed_partials(0.3, 0.6, 2)?;
    /// assert_eq!(second.len(), 3);
    /// assert_eq!(second[1].position, [0.0, 0.0, 1.0]);
    /// assert_eq!(second[0].position, [0.0, 0.0, 0.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// A parameter not finite or outside its domain; [`EvalError::Overflow`] when a value is
    /// not representable.
    pub fn mixed_partials(
        &self,
        u: f64,
        v: f64,
        order: usize,
    ) -> Result<Vec<DerivativeValue<3>>, EvalError> {
        self.check(u, v)?;
        let hs = S + 1;
        let n = order + 1;
        // homogeneous[a * n + b] = H^(a, b)(u, v), a, b = 0 ..= order.
        let mut homogeneous = vec![[0.0; S + 1]; n * n];
        let ku = self.knots_u.span(u);
        let pu = self.knots_u.degree();
        // column[b] holds, for the rows that matter at u, the rows' b-th v-derivative at v.
        let mut columns = vec![vec![0.0; self.rows * hs]; n];
        for i in ku - pu..=ku {
            let row = Spline {
                knots: self.knots_v.clone(),
                stride: hs,
                data: self.homogeneous[i * self.cols * hs..(i + 1) * self.cols * hs].to_vec(),
                weights: None,
            };
            for (b, spline) in row.derivatives(order).iter().enumerate() {
                spline.evaluate_plain(v, &mut columns[b][i * hs..(i + 1) * hs]);
            }
        }
        for (b, column) in columns.into_iter().enumerate() {
            let column = Spline {
                knots: self.knots_u.clone(),
                stride: hs,
                data: column,
                weights: None,
            };
            for (a, spline) in column.derivatives(order).iter().enumerate() {
                spline.evaluate_plain(u, &mut homogeneous[a * n + b]);
            }
        }
        // Leibniz's rule in two variables, S^(k,l) for k + l <= order.
        let binomial =
            |m: usize, i: usize| (0..i).fold(1.0, |acc, r| acc * (m - r) as f64 / (r + 1) as f64);
        let w = homogeneous[0][S];
        let mut values = vec![[0.0; S]; n * n];
        for total in 0..=order {
            for k in (0..=total).rev() {
                let l = total - k;
                let mut row = [0.0; S];
                for c in 0..S {
                    let mut numerator = homogeneous[k * n + l][c];
                    for i in 0..=k {
                        for j in 0..=l {
                            if i + j > 0 {
                                numerator -= binomial(k, i)
                                    * binomial(l, j)
                                    * homogeneous[i * n + j][S]
                                    * values[(k - i) * n + (l - j)][c];
                            }
                        }
                    }
                    row[c] = numerator / w;
                }
                values[k * n + l] = row;
            }
        }
        let result: Vec<[f64; S]> = (0..=order).map(|j| values[(order - j) * n + j]).collect();
        if result.iter().flatten().any(|x| !x.is_finite()) {
            return Err(EvalError::Overflow { t: u });
        }
        Ok(result.iter().map(|r| derivative_from_row(r)).collect())
    }

    /// The unit normal `S_u x S_v / |S_u x S_v|`, or `None` where the surface is degenerate
    /// (the cross product vanishes, for example at a collapsed edge).
    ///
    /// # Errors
    /// As [`Surface::partial_derivatives`].
    pub fn normal(&self, u: f64, v: f64) -> Result<Option<[f64; 3]>, EvalError> {
        let d = self.partial_derivatives(u, v)?;
        let (a, b) = (d.du.position, d.dv.position);
        let n = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let scale = a.iter().chain(&b).fold(0.0_f64, |m, x| m.max(x.abs()));
        if len <= 1e-14 * scale * scale || !len.is_finite() {
            return Ok(None);
        }
        Ok(Some(n.map(|x| x / len)))
    }

    /// The iso-parameter curve at fixed `u` (running along v) or fixed `v` (along u), as a
    /// curve of the surface's kind: its control points are the evaluated other-direction
    /// curves, with their combined weights for NURBS.
    ///
    /// # Errors
    /// The parameter not finite or outside its domain.
    pub fn iso_curve(&self, fixed: Direction, value: f64) -> Result<AnyCurve<3>, EvalError> {
        let (fixed_knots, count_fixed, along_knots, count_along) = match fixed {
            Direction::U => (&self.knots_u, self.rows, &self.knots_v, self.cols),
            Direction::V => (&self.knots_v, self.cols, &self.knots_u, self.rows),
        };
        check_parameter(value, &fixed_knots.domain())?;
        let index = |a: usize, f: usize| match fixed {
            Direction::U => f * self.cols + a,
            Direction::V => a * self.cols + f,
        };
        let k = fixed_knots.span(value);
        let mut line = vec![0.0; count_fixed * S];
        let mut line_w = vec![1.0; count_fixed];
        let mut points = Vec::with_capacity(count_along);
        let mut weights = Vec::with_capacity(count_along);
        let mut out = [0.0; S];
        for a in 0..count_along {
            for f in 0..count_fixed {
                let src = index(a, f);
                line[f * S..(f + 1) * S].copy_from_slice(&self.data[src * S..(src + 1) * S]);
                line_w[f] = self.weights.as_ref().map_or(1.0, |w| w[src]);
            }
            let lw = self.weights.as_ref().map(|_| line_w.as_slice());
            weights.push(blossom(
                fixed_knots,
                S,
                &line,
                lw,
                k,
                |_| (value, 0.0),
                &mut out,
            ));
            points.push(point_from_row::<3>(&out));
        }
        let built = match self.kind {
            SurfaceKind::Bezier => Bezier::new(points).map(AnyCurve::Bezier),
            SurfaceKind::BSpline => {
                BSpline::new(points, along_knots.clone()).map(AnyCurve::BSpline)
            }
            SurfaceKind::Nurbs => {
                Nurbs::new(points, weights, along_knots.clone()).map(AnyCurve::Nurbs)
            }
        };
        // The points come from evaluating valid data and the knots are the surface's own.
        Ok(built.unwrap_or_else(|e| unreachable!("iso-curve data is valid: {e}")))
    }

    /// Bounds of the control values (they contain the surface, by the convex hull property).
    pub fn control_bounding_box(&self) -> BoundingBox<3> {
        BoundingBox::from_channel_ranges(|c| {
            self.data
                .iter()
                .skip(c)
                .step_by(S)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                    (lo.min(v), hi.max(v))
                })
        })
    }
}

impl EvaluateSurface for Surface {
    type Point = CurvePoint<3>;

    fn domain(&self) -> [Range<f64>; 2] {
        [self.knots_u.domain(), self.knots_v.domain()]
    }

    /// The point at `(u, v)`: the curve algorithm along `v` in each row, then along `u`.
    ///
    /// # Errors
    /// A parameter not finite or outside its domain.
    fn evaluate(&self, u: f64, v: f64) -> Result<CurvePoint<3>, EvalError> {
        self.check(u, v)?;
        let mut out = [0.0; S];
        self.evaluate_into(u, v, &mut out);
        Ok(point_from_row(&out))
    }
}

/// Rows `(w P, w)` of the homogeneous form (weight 1 for non-rational surfaces).
pub(crate) fn homogeneous_rows(data: &[f64], weights: Option<&[f64]>) -> Vec<f64> {
    let mut h = Vec::with_capacity(data.len() / S * (S + 1));
    for (k, row) in data.chunks_exact(S).enumerate() {
        let w = weights.map_or(1.0, |w| w[k]);
        h.extend(row.iter().map(|x| x * w));
        h.push(w);
    }
    h
}

fn check_grid(rows: usize, cols: usize, points: usize) -> Result<(), CurveError> {
    if rows == 0 || cols == 0 || rows * cols != points {
        return Err(CurveError::GridSize { points, rows, cols });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::Evaluate;
    use crate::degrees::Degrees;

    fn grid(rows: usize, cols: usize) -> Vec<ControlPoint<3>> {
        let mut pts = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let (x, y) = (i as f64, j as f64);
                let z = (x * 0.7 + y * y * 0.3).sin();
                let t = (i + j) as f64 / (rows + cols) as f64;
                pts.push(ControlPoint::new(
                    [x, y, z],
                    Degrees::new(t, 1.0 - t, t * 0.5).unwrap(),
                ));
            }
        }
        pts
    }

    /// Direct tensor-product Bernstein sum.
    fn bernstein_surface(
        pts: &[ControlPoint<3>],
        rows: usize,
        cols: usize,
        u: f64,
        v: f64,
    ) -> [f64; 4] {
        let b = |n: usize, i: usize, t: f64| {
            let c = (0..i).fold(1.0, |acc, k| acc * (n - k) as f64 / (k + 1) as f64);
            c * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
        };
        let mut out = [0.0; 4];
        for i in 0..rows {
            for j in 0..cols {
                let w = b(rows - 1, i, u) * b(cols - 1, j, v);
                let p = pts[i * cols + j];
                for a in 0..3 {
                    out[a] += w * p.position[a];
                }
                out[3] += w * p.degrees.truth();
            }
        }
        out
    }

    #[test]
    fn surface_bezier_matches_tensor_bernstein() {
        let pts = grid(4, 3);
        let s = Surface::bezier(4, 3, pts.clone()).unwrap();
        for &(u, v) in &[(0.0, 0.0), (0.3, 0.8), (1.0, 0.5), (0.77, 0.21)] {
            let p = s.evaluate(u, v).unwrap();
            let want = bernstein_surface(&pts, 4, 3, u, v);
            for a in 0..3 {
                assert!((p.position[a] - want[a]).abs() < 1e-14);
            }
            assert!((p.degrees.truth() - want[3]).abs() < 1e-15);
        }
    }

    #[test]
    fn surface_partials_match_finite_differences_and_iso_curves() {
        let pts = grid(5, 4);
        let ku = KnotVector::clamped_uniform(2, 5).unwrap();
        let kv = KnotVector::clamped_uniform(3, 4).unwrap();
        let weights: Vec<f64> = (0..20).map(|k| 0.5 + (k % 7) as f64 * 0.25).collect();
        let bs = Surface::bspline(5, 4, pts.clone(), ku.clone(), kv.clone()).unwrap();
        let nu = Surface::nurbs(5, 4, pts, weights, ku, kv).unwrap();
        for s in [&bs, &nu] {
            let (u, v, h) = (0.37, 0.61, 1e-6);
            let d = s.partial_derivatives(u, v).unwrap();
            let fu = |du: f64| s.evaluate(u + du, v).unwrap();
            let fv = |dv: f64| s.evaluate(u, v + dv).unwrap();
            for a in 0..3 {
                let nu_ = (fu(h).position[a] - fu(-h).position[a]) / (2.0 * h);
                let nv = (fv(h).position[a] - fv(-h).position[a]) / (2.0 * h);
                assert!(
                    (nu_ - d.du.position[a]).abs() < 1e-6,
                    "{nu_} {}",
                    d.du.position[a]
                );
                assert!(
                    (nv - d.dv.position[a]).abs() < 1e-6,
                    "{nv} {}",
                    d.dv.position[a]
                );
            }
            let dt = (fu(h).degrees.truth() - fu(-h).degrees.truth()) / (2.0 * h);
            assert!((dt - d.du.truth).abs() < 1e-6);
            let n = s.normal(u, v).unwrap().unwrap();
            let dot = n[0] * d.du.position[0] + n[1] * d.du.position[1] + n[2] * d.du.position[2];
            assert!(dot.abs() < 1e-12);
            // Iso curves are curves of the library passing through the surface.
            let iso_u = s.iso_curve(Direction::U, u).unwrap();
            let iso_v = s.iso_curve(Direction::V, v).unwrap();
            let p = s.evaluate(u, v).unwrap();
            for q in [iso_u.evaluate(v).unwrap(), iso_v.evaluate(u).unwrap()] {
                for a in 0..3 {
                    assert!((p.position[a] - q.position[a]).abs() < 1e-13);
                }
                assert!((p.degrees.falsity() - q.degrees.falsity()).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn surface_errors() {
        assert_eq!(
            Surface::bezier(2, 3, grid(2, 2)).unwrap_err().to_string(),
            "4 control points do not fill a grid of 2 rows x 3 columns (6 points)"
        );
        let e = Surface::bspline(
            3,
            3,
            grid(3, 3),
            KnotVector::clamped_uniform(2, 3).unwrap(),
            KnotVector::clamped_uniform(1, 4).unwrap(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "knots_v: knot vector has 6 knots, expected 5 (number of control points + degree + 1)"
        );
    }
}
