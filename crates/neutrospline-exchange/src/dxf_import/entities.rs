//! The curves of DXF's curve entities (AutoCAD's DXF reference, "ENTITIES Section"): LINE,
//! ARC, CIRCLE, ELLIPSE, LWPOLYLINE and POLYLINE with its VERTEX entities, as exact pieces in
//! the world coordinates of their block (the object coordinate system applied).

use neutrospline_io::ReadError;

use super::geometry::{bulge_pieces, conic_pieces, ocs, Affine, Piece};
use super::{error, Entity};

/// What a curve entity draws.
pub(super) enum Drawn {
    /// Pieces joined into one curve, in the entity's object coordinates, with the map to the
    /// block's world coordinates.
    Pieces(Vec<Piece>, Affine),
    /// A uniform B-spline (a spline-fit POLYLINE's frame): control points in object
    /// coordinates, knots, degree, and the map to world coordinates.
    Spline {
        points: Vec<[f64; 3]>,
        knots: Vec<f64>,
        degree: usize,
        map: Affine,
    },
    /// Nothing: a zero radius, a line of length zero, a polyline with fewer than 2 vertices
    /// or all its vertices at one point.
    Empty,
    /// A form that is not a curve this importer reads (a polyface or polygon mesh).
    Unsupported,
}

/// The map of an entity's object coordinate system (its extrusion direction 210, 220, 230;
/// (0, 0, 1) when absent) to world coordinates.
fn object_map(file: &str, e: &Entity<'_>) -> Result<Affine, ReadError> {
    let normal = e.point(file, 210, [0.0, 0.0, 1.0])?;
    ocs(normal).map_err(|m| error(file, e.line, format!("{}: {m}", e.kind)))
}

/// The curve of a LINE (start 10/20/30, end 11/21/31, in world coordinates): a degree-1
/// Bézier curve.
pub(super) fn line(file: &str, e: &Entity<'_>) -> Result<Drawn, ReadError> {
    let a = e.required_point(file, 10, "start point")?;
    let b = e.required_point(file, 11, "end point")?;
    if a == b {
        return Ok(Drawn::Empty);
    }
    Ok(Drawn::Pieces(vec![Piece::line(a, b)], Affine::IDENTITY))
}

/// A radius (group code 40): positive, zero (nothing drawn), or an error.
fn radius(file: &str, e: &Entity<'_>, code: u16) -> Result<f64, ReadError> {
    let r = e.required(file, code, "radius")?;
    if r < 0.0 {
        let line = e.first(code).map_or(e.line, |g| g.line);
        return Err(error(
            file,
            line,
            format!(
                "{}: the radius (group code {code}) = {r} is negative",
                e.kind
            ),
        ));
    }
    Ok(r)
}

/// The curve of a CIRCLE (centre 10/20/30 and radius 40 in its object coordinates): the
/// closed NURBS curve of 4 quarter arcs from angle 0, counter-clockwise.
pub(super) fn circle(file: &str, e: &Entity<'_>) -> Result<Drawn, ReadError> {
    let centre = e.required_point(file, 10, "centre")?;
    let r = radius(file, e, 40)?;
    if r == 0.0 {
        return Ok(Drawn::Empty);
    }
    let pieces = conic_pieces(centre, [r, 0.0, 0.0], [0.0, r, 0.0], 0.0, 360.0);
    Ok(Drawn::Pieces(pieces, object_map(file, e)?))
}

/// The curve of an ARC (centre 10/20/30, radius 40, start and end angles 50, 51 in degrees,
/// counter-clockwise from start to end in its object coordinates): rational quadratic pieces
/// of at most 90°. An end angle at or below the start is a turn further (an arc from 350° to
/// 10° sweeps 20°); equal angles draw nothing, angles 360° apart the whole circle.
pub(super) fn arc(file: &str, e: &Entity<'_>) -> Result<Drawn, ReadError> {
    let centre = e.required_point(file, 10, "centre")?;
    let r = radius(file, e, 40)?;
    let start = e.required(file, 50, "start angle")?;
    let end = e.required(file, 51, "end angle")?;
    let mut sweep = (end - start).rem_euclid(360.0);
    if sweep == 0.0 && end != start {
        sweep = 360.0;
    }
    if r == 0.0 || sweep == 0.0 {
        return Ok(Drawn::Empty);
    }
    let pieces = conic_pieces(centre, [r, 0.0, 0.0], [0.0, r, 0.0], start, sweep);
    Ok(Drawn::Pieces(pieces, object_map(file, e)?))
}

/// The curve of an ELLIPSE (centre 10/20/30, the end of the major axis 11/21/31 relative to
/// the centre, the ratio of minor to major axis 40, the start and end parameters 41, 42 in
/// radians, the normal 210/220/230; all in world coordinates): the points
/// `centre + cos(u) M + sin(u) r (N × M)` for u from start to end (N the unit normal),
/// counter-clockwise about N, as rational quadratic pieces of at most 90° of u (the affine
/// image of circular arcs, exact). An end at or below the start is a turn further; a sweep
/// within 1e-12 of 2π (0 to 6.283185307179586 as written) is the whole ellipse.
pub(super) fn ellipse(file: &str, e: &Entity<'_>) -> Result<Drawn, ReadError> {
    let centre = e.required_point(file, 10, "centre")?;
    let major = e.required_point(file, 11, "major axis end point")?;
    let ratio = e.required(file, 40, "ratio of the minor to the major axis")?;
    let start = e.real_or(file, 41, 0.0, "start parameter")?;
    let end = e.real_or(file, 42, std::f64::consts::TAU, "end parameter")?;
    let normal = e.point(file, 210, [0.0, 0.0, 1.0])?;
    let n = ocs(normal)
        .map_err(|m| error(file, e.line, format!("ELLIPSE: {m}")))?
        .linear
        .map(|row| row[2]);
    let tau = std::f64::consts::TAU;
    let mut sweep = (end - start).rem_euclid(tau);
    if (sweep - tau).abs() < 1e-12 || sweep.abs() < 1e-12 && end != start {
        sweep = tau;
    }
    if major == [0.0; 3] || ratio == 0.0 || sweep == 0.0 {
        return Ok(Drawn::Empty);
    }
    let minor = [
        ratio * (n[1] * major[2] - n[2] * major[1]),
        ratio * (n[2] * major[0] - n[0] * major[2]),
        ratio * (n[0] * major[1] - n[1] * major[0]),
    ];
    let (start, sweep) = if sweep == tau {
        (0.0, 360.0)
    } else {
        (start.to_degrees(), sweep.to_degrees())
    };
    let pieces = conic_pieces(centre, major, minor, start, sweep);
    Ok(Drawn::Pieces(pieces, Affine::IDENTITY))
}

/// Whether every one of `points` is the first (a polyline that draws a point, not a curve).
fn coincident<T: PartialEq>(points: impl IntoIterator<Item = T>) -> bool {
    let mut points = points.into_iter();
    let first = points.next();
    points.all(|p| Some(p) == first)
}

/// The pieces of a 2-D polyline through `vertices` (x, y, bulge) at height `z`, closed back to
/// the first vertex when `closed` ([`bulge_pieces`]).
fn polyline_pieces(vertices: &[([f64; 2], f64)], closed: bool, z: f64) -> Vec<Piece> {
    let n = vertices.len();
    let segments = if closed { n } else { n - 1 };
    (0..segments)
        .flat_map(|i| {
            let (p0, b) = vertices[i];
            let (p1, _) = vertices[(i + 1) % n];
            bulge_pieces(p0, p1, b, z)
        })
        .collect()
}

/// The curve of an LWPOLYLINE (vertices 10/20 with bulges 42 in its object coordinates at
/// the elevation 38; flag 70 bit 1 closed): one curve of its segments, a segment of bulge b
/// != 0 the exact circular arc of included angle 4 atan b ([`bulge_pieces`]). Fewer than two
/// vertices, or all at one point, draw nothing.
pub(super) fn lwpolyline(file: &str, e: &Entity<'_>) -> Result<Drawn, ReadError> {
    let mut vertices: Vec<([f64; 2], f64)> = Vec::new();
    let mut pending_x: Option<f64> = None;
    for g in e.body() {
        match g.code {
            10 => {
                if pending_x.is_some() {
                    return Err(error(
                        file,
                        g.line,
                        "LWPOLYLINE: a vertex has an x (group code 10) but no y (group code 20)"
                            .to_owned(),
                    ));
                }
                pending_x = Some(super::real(file, *g, "vertex x")?);
            }
            20 => {
                let Some(x) = pending_x.take() else {
                    return Err(error(file, g.line, "LWPOLYLINE: a y (group code 20) that is not after the x (group code 10) of a vertex".to_owned()));
                };
                vertices.push(([x, super::real(file, *g, "vertex y")?], 0.0));
            }
            42 => match vertices.last_mut() {
                Some(v) => v.1 = super::real(file, *g, "bulge")?,
                None => {
                    return Err(error(
                        file,
                        g.line,
                        "LWPOLYLINE: a bulge (group code 42) before the first vertex".to_owned(),
                    ))
                }
            },
            _ => {}
        }
    }
    if pending_x.is_some() {
        return Err(error(
            file,
            e.line,
            "LWPOLYLINE: the last vertex has an x (group code 10) but no y (group code 20)"
                .to_owned(),
        ));
    }
    let closed = e.int_or(file, 70, 0)? & 1 != 0;
    let z = e.real_or(file, 38, 0.0, "elevation")?;
    if vertices.len() < 2 || coincident(vertices.iter().map(|v| v.0)) {
        return Ok(Drawn::Empty);
    }
    Ok(Drawn::Pieces(
        polyline_pieces(&vertices, closed, z),
        object_map(file, e)?,
    ))
}

/// The curve of a POLYLINE and its VERTEX entities (flags 70: 1 closed, 2 curve-fit, 4
/// spline-fit, 8 3-D polyline, 16 polygon mesh, 64 polyface mesh):
///
/// - a 2-D polyline: its vertices (10/20, bulges 42, in its object coordinates at the
///   elevation of the POLYLINE's 30) as for LWPOLYLINE; a curve-fit polyline's vertices
///   include the fit vertices (vertex flag 1) and their bulges, which are the arcs it draws;
/// - a 3-D polyline (flag 8): line segments through its vertices (10/20/30, world
///   coordinates);
/// - a spline-fit polyline (flag 4): the DXF reference's frame control points (vertex flag
///   16) are the control points of the B-spline it stands for, of degree 2 when its curve
///   type (75) is 5 (quadratic) and 3 otherwise (6, cubic, and the header's `$SPLINETYPE`
///   default), with uniform knots clamped at both ends (an open frame) or the frame wrapped
///   round periodically (a closed one, flag 1); the vertices the CAD program computed on that
///   spline (vertex flag 8, an approximation) are not read. A spline-fit polyline without
///   frame vertices is read through its vertices as written;
/// - a polygon or polyface mesh (flags 16, 64) is a surface: [`Drawn::Unsupported`];
/// - vertices (or frame vertices) all at one point draw nothing: [`Drawn::Empty`].
pub(super) fn polyline(
    file: &str,
    e: &Entity<'_>,
    spline_degree: usize,
) -> Result<Drawn, ReadError> {
    let flags = e.int_or(file, 70, 0)?;
    if flags & (16 | 64) != 0 {
        return Ok(Drawn::Unsupported);
    }
    let closed = flags & 1 != 0;
    let spatial = flags & 8 != 0;
    let vertices: Vec<&Entity<'_>> = e.children.iter().filter(|v| v.kind == "VERTEX").collect();
    let mut read = Vec::with_capacity(vertices.len());
    for v in &vertices {
        let p = v.required_point(file, 10, "location")?;
        let b = v.real_or(file, 42, 0.0, "bulge")?;
        let vflags = v.int_or(file, 70, 0)?;
        read.push((p, b, vflags));
    }
    let frame: Vec<[f64; 3]> = read.iter().filter(|v| v.2 & 16 != 0).map(|v| v.0).collect();
    let map = if spatial {
        Affine::IDENTITY
    } else {
        object_map(file, e)?
    };
    if flags & 4 != 0 && !frame.is_empty() {
        if coincident(frame.iter().copied()) {
            return Ok(Drawn::Empty);
        }
        let degree = match e.int_or(file, 75, 0)? {
            5 => 2,
            6 => 3,
            _ => spline_degree,
        };
        let z = e.point(file, 10, [0.0; 3])?[2];
        let mut points: Vec<[f64; 3]> = frame
            .iter()
            .map(|p| if spatial { *p } else { [p[0], p[1], z] })
            .collect();
        if points.len() <= degree && !closed {
            // Too few frame points for the degree: the frame itself.
            let pieces = points
                .windows(2)
                .map(|w| Piece::line(w[0], w[1]))
                .collect::<Vec<_>>();
            return Ok(if pieces.is_empty() {
                Drawn::Empty
            } else {
                Drawn::Pieces(pieces, map)
            });
        }
        let knots: Vec<f64> = if closed {
            // Periodic: the first `degree` control points repeated at the end, uniform knots;
            // the curve is the part over [degree, count].
            let first: Vec<[f64; 3]> = points.iter().take(degree).copied().collect();
            points.extend(first);
            (0..points.len() + degree + 1).map(|k| k as f64).collect()
        } else {
            let spans = points.len() - degree;
            let mut knots = vec![0.0; degree + 1];
            knots.extend((1..spans).map(|k| k as f64));
            knots.extend(std::iter::repeat_n(spans as f64, degree + 1));
            knots
        };
        return Ok(Drawn::Spline {
            points,
            knots,
            degree,
            map,
        });
    }
    let fitted: Vec<_> = if flags & 4 != 0 {
        read.iter().filter(|v| v.2 & 16 == 0).collect()
    } else {
        read.iter().collect()
    };
    if fitted.len() < 2 || coincident(fitted.iter().map(|v| v.0)) {
        return Ok(Drawn::Empty);
    }
    if spatial {
        let n = fitted.len();
        let segments = if closed { n } else { n - 1 };
        let pieces = (0..segments)
            .map(|i| Piece::line(fitted[i].0, fitted[(i + 1) % n].0))
            .collect();
        return Ok(Drawn::Pieces(pieces, map));
    }
    let z = e.point(file, 10, [0.0; 3])?[2];
    let plane: Vec<([f64; 2], f64)> = fitted.iter().map(|v| ([v.0[0], v.0[1]], v.1)).collect();
    Ok(Drawn::Pieces(polyline_pieces(&plane, closed, z), map))
}
