//! The exact geometry of DXF entities: affine maps (an entity's object coordinate system, an
//! INSERT's placement), circular and elliptical arcs as rational quadratic pieces, and pieces
//! joined into one curve.

use std::f64::consts::FRAC_1_SQRT_2;

use neutrospline::{AnyCurve, BSpline, ControlPoint, Degrees, KnotVector};
use neutrospline_io::Shape;

/// An affine map of space, `p -> linear p + offset` (`linear` by rows).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Affine {
    pub linear: [[f64; 3]; 3],
    pub offset: [f64; 3],
}

impl Affine {
    /// The identity map.
    pub const IDENTITY: Affine = Affine {
        linear: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        offset: [0.0; 3],
    };

    /// The map whose columns are `x`, `y`, `z` (the images of the unit vectors), plus `offset`.
    pub fn from_columns(x: [f64; 3], y: [f64; 3], z: [f64; 3], offset: [f64; 3]) -> Affine {
        Affine {
            linear: [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]],
            offset,
        }
    }

    /// The image of `p`; the identity returns `p` itself (its bits, `-0.0` kept).
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        if *self == Affine::IDENTITY {
            return p;
        }
        let m = &self.linear;
        [0, 1, 2].map(|r| m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + self.offset[r])
    }

    /// The map `outer ∘ self`: first `self`, then `outer`.
    pub fn then(&self, outer: &Affine) -> Affine {
        if *self == Affine::IDENTITY {
            return *outer;
        }
        if *outer == Affine::IDENTITY {
            return *self;
        }
        let (a, b) = (&outer.linear, &self.linear);
        let linear = [0, 1, 2].map(|r| [0, 1, 2].map(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum()));
        Affine {
            linear,
            offset: outer.apply(self.offset),
        }
    }
}

/// The cross product `a × b`.
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v / |v|`, or `None` for a zero or non-finite vector.
fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let length = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    (length > 0.0 && length.is_finite()).then(|| v.map(|x| x / length))
}

/// The object coordinate system of the extrusion direction `normal` by the DXF reference's
/// Arbitrary Axis Algorithm: with N = normal / |normal|, the x axis is Ax = (Wy × N) / |·|
/// when |Nx| < 1/64 and |Ny| < 1/64, Ax = (Wz × N) / |·| otherwise; the y axis is
/// Ay = (N × Ax) / |·|; a point (x, y, z) of the OCS is x Ax + y Ay + z N in the world. N =
/// (0, 0, 1) gives the identity and N = (0, 0, -1) the mirror x -> -x, z -> -z.
///
/// # Errors
/// A message for a zero or non-finite direction.
pub(super) fn ocs(normal: [f64; 3]) -> Result<Affine, String> {
    if normal == [0.0, 0.0, 1.0] {
        return Ok(Affine::IDENTITY);
    }
    let n = unit(normal).ok_or_else(|| {
        format!(
            "the extrusion direction (group codes 210, 220, 230) = ({}, {}, {}) has no length",
            normal[0], normal[1], normal[2]
        )
    })?;
    let limit = 1.0 / 64.0;
    let world = if n[0].abs() < limit && n[1].abs() < limit {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let ax = unit(cross(world, n)).unwrap_or([1.0, 0.0, 0.0]);
    let ay = unit(cross(n, ax)).unwrap_or([0.0, 1.0, 0.0]);
    Ok(Affine::from_columns(ax, ay, n, [0.0; 3]))
}

/// (sin d, cos d) of an angle `d` in degrees, exact at the multiples of 45° and symmetric
/// under quarter turns: d is reduced to d = 90 q + r with |r| <= 45 and the values of r
/// rotated by q quarter turns, so that sin 90° = 1 and cos 90° = 0 exactly and
/// sin 45° = cos 45° = 1/√2 to the same bit.
pub(super) fn sin_cos_degrees(d: f64) -> (f64, f64) {
    let turned = d.rem_euclid(360.0);
    let quarter = (turned / 90.0).round();
    let r = turned - 90.0 * quarter;
    let (s, c) = if r == 0.0 {
        (0.0, 1.0)
    } else if r.abs() == 45.0 {
        (FRAC_1_SQRT_2.copysign(r), FRAC_1_SQRT_2)
    } else {
        r.to_radians().sin_cos()
    };
    match (quarter as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// A piece of a curve: a line (2 control points) or a conic (3 control points, with weights
/// when rational).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Piece {
    pub points: Vec<[f64; 3]>,
    pub weights: Option<Vec<f64>>,
}

impl Piece {
    /// The straight line from `a` to `b`.
    pub fn line(a: [f64; 3], b: [f64; 3]) -> Piece {
        Piece {
            points: vec![a, b],
            weights: None,
        }
    }

    fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

/// The number of pieces of at most 90° for a sweep of `sweep` degrees (at least one).
fn piece_count(sweep: f64) -> usize {
    ((sweep.abs() / 90.0).ceil() as usize).max(1)
}

/// The rational quadratic pieces of the curve `centre + cos(a) u + sin(a) v` for `a` from
/// `start` over `sweep` degrees (negative: clockwise), each of at most 90°: the piece from `a`
/// to `b` has the control points `P(a)`, `centre + (cos m u + sin m v) / cos h` and `P(b)`
/// with `m = (a + b) / 2`, `h = (b - a) / 2`, and the weights 1, cos h, 1. This is exact for a
/// circle (u, v orthogonal of length r) and for an ellipse (its conjugate axes), the affine
/// image of the unit circle.
pub(super) fn conic_pieces(
    centre: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
    start: f64,
    sweep: f64,
) -> Vec<Piece> {
    let n = piece_count(sweep);
    let at = |c: f64, s: f64| [0, 1, 2].map(|k| centre[k] + c * u[k] + s * v[k]);
    let angle = |i: usize| start + sweep * i as f64 / n as f64;
    let (_, cos_h) = sin_cos_degrees(sweep / (2 * n) as f64);
    (0..n)
        .map(|i| {
            let (a, b) = (angle(i), angle(i + 1));
            let (sa, ca) = sin_cos_degrees(a);
            let (sm, cm) = sin_cos_degrees((a + b) / 2.0);
            let (sb, cb) = sin_cos_degrees(b);
            Piece {
                points: vec![at(ca, sa), at(cm / cos_h, sm / cos_h), at(cb, sb)],
                weights: Some(vec![1.0, cos_h, 1.0]),
            }
        })
        .collect()
}

/// The pieces of a polyline segment from `p0` to `p1` (at height `z`) with bulge `b`: a line
/// when b = 0; otherwise the circular arc of included angle θ = 4 atan b (counter-clockwise
/// when b > 0). An arc of at most 90° (|b| <= tan 22.5°) is one rational quadratic piece
/// straight from the bulge: with the chord c = p1 - p0 and its right normal n = (c_y, -c_x),
/// the middle control point is (p0 + p1) / 2 + n b / (1 - b²) and its weight
/// cos(θ / 2) = (1 - b²) / (1 + b²). A larger arc is cut into k equal arcs of bulge
/// tan(θ / 4k) at the points centre + r (cos, sin)(a0 + iθ/k), with the centre
/// (p0 + p1) / 2 - n (1 - b²) / (4b) and the radius |c| (1 + b²) / (4|b|); its ends stay p0
/// and p1 as written.
pub(super) fn bulge_pieces(p0: [f64; 2], p1: [f64; 2], b: f64, z: f64) -> Vec<Piece> {
    let lift = |p: [f64; 2]| [p[0], p[1], z];
    let c = [p1[0] - p0[0], p1[1] - p0[1]];
    if b == 0.0 || c == [0.0, 0.0] {
        return vec![Piece::line(lift(p0), lift(p1))];
    }
    let one = |q0: [f64; 2], q1: [f64; 2], b: f64| {
        let c = [q1[0] - q0[0], q1[1] - q0[1]];
        let n = [c[1], -c[0]];
        let lift_by = b / (1.0 - b * b);
        let middle = [
            (q0[0] + q1[0]) / 2.0 + n[0] * lift_by,
            (q0[1] + q1[1]) / 2.0 + n[1] * lift_by,
        ];
        Piece {
            points: vec![lift(q0), lift(middle), lift(q1)],
            weights: Some(vec![1.0, (1.0 - b * b) / (1.0 + b * b), 1.0]),
        }
    };
    let theta = 4.0 * b.atan().to_degrees();
    let k = piece_count(theta);
    if k == 1 {
        return vec![one(p0, p1, b)];
    }
    let n = [c[1], -c[0]];
    let back = (1.0 - b * b) / (4.0 * b);
    let centre = [
        (p0[0] + p1[0]) / 2.0 - n[0] * back,
        (p0[1] + p1[1]) / 2.0 - n[1] * back,
    ];
    let radius = (c[0] * c[0] + c[1] * c[1]).sqrt() * (1.0 + b * b) / (4.0 * b.abs());
    let a0 = (p0[1] - centre[1]).atan2(p0[0] - centre[0]).to_degrees();
    let sub = (theta / (4 * k) as f64).to_radians().tan();
    let point = |i: usize| {
        if i == 0 {
            p0
        } else if i == k {
            p1
        } else {
            let (s, c) = sin_cos_degrees(a0 + theta * i as f64 / k as f64);
            [centre[0] + radius * c, centre[1] + radius * s]
        }
    };
    (0..k).map(|i| one(point(i), point(i + 1), sub)).collect()
}

/// A curve's control points and weights from its pieces, mapped by `map`: every piece raised
/// to the highest degree (a line to degree 2 by its midpoint, the same curve), consecutive
/// pieces sharing their end point. One polynomial piece is a Bézier curve; several pieces, or
/// a rational one, are a B-spline (NURBS when a piece is rational) whose piece k spans the
/// knots \[k, k + 1\], each interior knot repeated degree times. A curve whose points all have
/// z = 0 is a plane curve.
///
/// # Errors
/// The core's message for a curve it refuses (a coordinate that overflowed).
pub(super) fn curve_of(pieces: &[Piece], map: &Affine, defaults: Degrees) -> Result<Shape, String> {
    let degree = pieces.iter().map(Piece::degree).max().unwrap_or(1);
    let rational = pieces.iter().any(|p| p.weights.is_some());
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut weights: Vec<f64> = Vec::new();
    for (k, piece) in pieces.iter().enumerate() {
        let (points, w) = if piece.degree() < degree {
            let [a, b] = [piece.points[0], piece.points[1]];
            let middle = [0, 1, 2].map(|i| (a[i] + b[i]) / 2.0);
            (vec![a, middle, b], vec![1.0; 3])
        } else {
            let w = piece
                .weights
                .clone()
                .unwrap_or_else(|| vec![1.0; degree + 1]);
            (piece.points.clone(), w)
        };
        let skip = usize::from(k > 0);
        positions.extend(points[skip..].iter().map(|&p| map.apply(p)));
        weights.extend(&w[skip..]);
    }
    if positions.iter().all(|p| p[2] == 0.0) {
        build::<2>(
            &positions,
            weights,
            pieces.len(),
            degree,
            rational,
            defaults,
        )
        .map(Shape::from)
    } else {
        build::<3>(
            &positions,
            weights,
            pieces.len(),
            degree,
            rational,
            defaults,
        )
        .map(Shape::from)
    }
}

fn build<const D: usize>(
    positions: &[[f64; 3]],
    weights: Vec<f64>,
    pieces: usize,
    degree: usize,
    rational: bool,
    defaults: Degrees,
) -> Result<AnyCurve<D>, String> {
    let points: Vec<ControlPoint<D>> = positions
        .iter()
        .map(|p| {
            let mut position = [0.0; D];
            position.copy_from_slice(&p[..D]);
            ControlPoint::new(position, defaults)
        })
        .collect();
    crate::pieces::joined(points, weights, pieces, degree, rational)
}

/// The B-spline of `points` (mapped by `map`) with `knots` and `degree`: a plane curve when
/// every mapped point has z = 0.
///
/// # Errors
/// The core's message for knots it refuses.
pub(super) fn spline_of(
    points: &[[f64; 3]],
    knots: Vec<f64>,
    degree: usize,
    map: &Affine,
    defaults: Degrees,
) -> Result<Shape, String> {
    let positions: Vec<[f64; 3]> = points.iter().map(|&p| map.apply(p)).collect();
    fn make<const D: usize>(
        positions: &[[f64; 3]],
        knots: Vec<f64>,
        degree: usize,
        defaults: Degrees,
    ) -> Result<AnyCurve<D>, String> {
        let points: Vec<ControlPoint<D>> = positions
            .iter()
            .map(|p| {
                let mut position = [0.0; D];
                position.copy_from_slice(&p[..D]);
                ControlPoint::new(position, defaults)
            })
            .collect();
        let knots = KnotVector::new(knots, degree, points.len()).map_err(|e| e.to_string())?;
        BSpline::new(points, knots)
            .map(AnyCurve::BSpline)
            .map_err(|e| e.to_string())
    }
    if positions.iter().all(|p| p[2] == 0.0) {
        make::<2>(&positions, knots, degree, defaults).map(Shape::from)
    } else {
        make::<3>(&positions, knots, degree, defaults).map(Shape::from)
    }
}
