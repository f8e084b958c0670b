//! [`Samples`]: the points of a shape that the polyline and mesh formats write, taken with the
//! core's sampling ([`neutrospline::sample`]).

use neutrospline::sample::{
    adaptive_parameters, adaptive_surface_parameters, chord_tolerance, surface_tolerance,
    uniform_parameters, SurfaceGrid,
};
use neutrospline::{AnyCurve, Degrees, Evaluate, EvaluateSurface, Family, FamilyValues, Surface};

use super::{ColorBy, ExportError};
use neutrospline_io::{Model, Shape};

/// Sampled points of a curve (a polyline through them, in order) or a surface (a triangle
/// mesh with normals).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Samples {
    /// 2 for a plane curve (whose `z` is 0 here), 3 otherwise.
    pub dimension: usize,
    /// The positions, `z = 0` for a plane curve.
    pub positions: Vec<[f64; 3]>,
    /// The degrees of each point (of the first lane for a family of two lanes).
    pub degrees: Vec<Degrees>,
    /// A family of two lanes (`Family::lanes`): its channel values at each point, the lanes
    /// evaluated at the same parameters and joined; `None` for a family of one lane.
    pub channels: Option<(Family, Vec<FamilyValues>)>,
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
    second: Option<&Shape>,
) -> Result<(Samples, Vec<Degrees>), ExportError> {
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
    let mut other = Vec::new();
    for t in ts {
        let p = curve.evaluate(t)?;
        let mut position = [0.0; 3];
        position[..D].copy_from_slice(&p.position);
        positions.push(position);
        degrees.push(p.degrees);
        if let Some(Shape::Curve(c)) = second {
            other.push(neutrospline::on_dimension!(c, c => c.evaluate(t)?.degrees));
        }
    }
    Ok((
        Samples {
            dimension: D,
            positions,
            degrees,
            channels: None,
            normals: None,
            triangles: None,
        },
        other,
    ))
}

fn surface(
    surface: &Surface,
    samples: Option<usize>,
    second: Option<&Shape>,
) -> Result<(Samples, Vec<Degrees>), ExportError> {
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
    let other = match second {
        Some(Shape::Surface(s)) => SurfaceGrid::new(s, u.clone(), v.clone())?
            .points()
            .iter()
            .map(|p| p.degrees)
            .collect(),
        _ => Vec::new(),
    };
    let grid = SurfaceGrid::new(surface, u, v)?;
    // Indices fit: there are at most u32::MAX points.
    let triangles = grid
        .triangles()
        .into_iter()
        .map(|t| t.map(|k| k as u32))
        .collect();
    Ok((
        Samples {
            dimension: 3,
            positions: grid.points().iter().map(|p| p.position).collect(),
            degrees: grid.points().iter().map(|p| p.degrees).collect(),
            channels: None,
            normals: Some(grid.normals().to_vec()),
            triangles: Some(triangles),
        },
        other,
    ))
}

impl Samples {
    /// Samples `shape`: `samples` evenly spaced points of a curve (an N x N grid of a
    /// surface), or without it the adaptive parameters of [`neutrospline::sample`].
    #[cfg(test)]
    pub fn of(shape: &Shape, samples: Option<usize>) -> Result<Samples, ExportError> {
        Ok(Self::lanes(shape, None, samples)?.0)
    }

    fn lanes(
        shape: &Shape,
        second: Option<&Shape>,
        samples: Option<usize>,
    ) -> Result<(Samples, Vec<Degrees>), ExportError> {
        match shape {
            Shape::Curve(c) => neutrospline::on_dimension!(c, c => curve(c, samples, second)),
            Shape::Surface(s) => surface(s, samples, second),
        }
    }

    /// Samples the model's shape as [`Samples::of`]; a family of two lanes has its second
    /// lane evaluated at the same parameters, and the channel values of every point joined
    /// ([`Samples::channels`]).
    pub fn of_model(model: &Model, samples: Option<usize>) -> Result<Samples, ExportError> {
        let lanes = model.lanes();
        let (mut out, other) = Self::lanes(lanes[0], lanes.get(1).copied(), samples)?;
        if lanes.len() == 2 {
            let family = model.membership();
            let channels = out
                .degrees
                .iter()
                .zip(&other)
                .map(|(a, b)| family.join(&[*a, *b]))
                .collect();
            out.channels = Some((family, channels));
        }
        Ok(out)
    }

    /// The names and values (one row per point) of what the file keeps of each point's
    /// membership: `truth`, `indeterminacy`, `falsity` for a family of one lane, the family's
    /// channels (`truth_lower`, ..., `negative_truth`, ...) for a family of two lanes.
    pub fn value_columns(&self) -> (Vec<&'static str>, Vec<Vec<f64>>) {
        match &self.channels {
            None => (
                vec!["truth", "indeterminacy", "falsity"],
                self.degrees.iter().map(|d| d.to_array().to_vec()).collect(),
            ),
            Some((family, values)) => (
                family.channels().to_vec(),
                values.iter().map(|v| v.to_vec()).collect(),
            ),
        }
    }

    /// The colour of each point, viridis of `by`.
    ///
    /// For an interval-valued family the value is taken from the midpoints of its intervals
    /// (`(T_L + T_U) / 2`, ...), for the bipolar family from its positive degrees.
    pub fn colors(&self, by: ColorBy) -> Vec<[u8; 3]> {
        self.degrees
            .iter()
            .enumerate()
            .map(|(k, d)| {
                let shown = match &self.channels {
                    Some((family, values)) if *family != Family::BipolarNeutrosophic => {
                        let (lanes, _) = family.split(&values[k]).unwrap_or(([*d, *d], 2));
                        let [a, b] = [lanes[0].to_array(), lanes[1].to_array()];
                        Degrees::new_unchecked(
                            (a[0] + b[0]) / 2.0,
                            (a[1] + b[1]) / 2.0,
                            (a[2] + b[2]) / 2.0,
                        )
                    }
                    _ => *d,
                };
                neutrospline::color::viridis(by.value(&shown))
            })
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
