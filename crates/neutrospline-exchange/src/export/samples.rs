//! [`Samples`]: the points of a shape that the polyline and mesh formats write, taken with the
//! core's sampling ([`neutrospline::sample`]).

use neutrospline::sample::{
    adaptive_parameters, adaptive_surface_parameters, chord_tolerance, surface_tolerance,
    uniform_parameters, SurfaceGrid,
};
use neutrospline::{AnyCurve, Degrees, Evaluate, EvaluateSurface, Surface};

use super::{ColorBy, ExportError};
use neutrospline_io::Shape;

/// Sampled points of a curve (a polyline through them, in order) or a surface (a triangle
/// mesh with normals).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Samples {
    /// 2 for a plane curve (whose `z` is 0 here), 3 otherwise.
    pub dimension: usize,
    /// The positions, `z = 0` for a plane curve.
    pub positions: Vec<[f64; 3]>,
    /// The degrees of each point.
    pub degrees: Vec<Degrees>,
    /// Surfaces: the unit normal of each point.
    pub normals: Option<Vec<[f64; 3]>>,
    /// Surfaces: the triangles, counter-clockwise seen from the normals' side.
    pub triangles: Option<Vec<[u32; 3]>>,
}

/// The most points a sampled shape may have: 32-bit indices address them.
const MAX_POINTS: usize = u32::MAX as usize;

fn curve<const D: usize>(
    curve: &AnyCurve<D>,
    samples: Option<usize>,
) -> Result<Samples, ExportError> {
    let ts = match samples {
        Some(n) => uniform_parameters(curve.domain(), n),
        None => adaptive_parameters(curve, chord_tolerance(curve)),
    };
    if ts.len() > MAX_POINTS {
        return Err(ExportError::TooManySamples {
            count: ts.len(),
            max: MAX_POINTS,
        });
    }
    let mut positions = Vec::with_capacity(ts.len());
    let mut degrees = Vec::with_capacity(ts.len());
    for t in ts {
        let p = curve.evaluate(t)?;
        let mut position = [0.0; 3];
        position[..D].copy_from_slice(&p.position);
        positions.push(position);
        degrees.push(p.degrees);
    }
    Ok(Samples {
        dimension: D,
        positions,
        degrees,
        normals: None,
        triangles: None,
    })
}

fn surface(surface: &Surface, samples: Option<usize>) -> Result<Samples, ExportError> {
    let [u, v] = match samples {
        Some(n) => {
            let [du, dv] = surface.domain();
            [uniform_parameters(du, n), uniform_parameters(dv, n)]
        }
        None => adaptive_surface_parameters(surface, surface_tolerance(surface))?,
    };
    let count = u.len().saturating_mul(v.len());
    if count > MAX_POINTS {
        return Err(ExportError::TooManySamples {
            count,
            max: MAX_POINTS,
        });
    }
    let grid = SurfaceGrid::new(surface, u, v)?;
    // Indices fit: there are at most u32::MAX points.
    let triangles = grid
        .triangles()
        .into_iter()
        .map(|t| t.map(|k| k as u32))
        .collect();
    Ok(Samples {
        dimension: 3,
        positions: grid.points().iter().map(|p| p.position).collect(),
        degrees: grid.points().iter().map(|p| p.degrees).collect(),
        normals: Some(grid.normals().to_vec()),
        triangles: Some(triangles),
    })
}

impl Samples {
    /// Samples `shape`: `samples` evenly spaced points of a curve (an N x N grid of a
    /// surface), or without it the adaptive parameters of [`neutrospline::sample`].
    pub fn of(shape: &Shape, samples: Option<usize>) -> Result<Samples, ExportError> {
        match shape {
            Shape::Curve(c) => neutrospline::on_dimension!(c, c => curve(c, samples)),
            Shape::Surface(s) => surface(s, samples),
        }
    }

    /// The colour of each point, viridis of `by`.
    pub fn colors(&self, by: ColorBy) -> Vec<[u8; 3]> {
        self.degrees
            .iter()
            .map(|d| neutrospline::color::viridis(by.value(d)))
            .collect()
    }

    /// The segments of a curve's polyline, `[k, k + 1]`; none for a surface.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        if self.triangles.is_some() {
            return Vec::new();
        }
        // A curve has at most u32::MAX points.
        (1..self.positions.len() as u32)
            .map(|k| [k - 1, k])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::example1;

    #[test]
    fn curve_samples_are_eval_rows() {
        let shape = Shape::from(AnyCurve::from(example1()));
        let s = Samples::of(&shape, Some(3)).unwrap();
        assert_eq!(
            s.positions,
            [[1.0, 3.0, 0.0], [4.625, 4.0, 0.0], [9.0, 5.0, 0.0]]
        );
        assert_eq!(s.degrees[1].truth(), 0.625);
        assert_eq!(s.edges(), [[0, 1], [1, 2]]);
        assert_eq!(
            s.colors(ColorBy::Truth)[0],
            neutrospline::color::viridis(0.3)
        );
        let adaptive = Samples::of(&shape, None).unwrap();
        assert!(adaptive.positions.len() > 8);
    }
}
