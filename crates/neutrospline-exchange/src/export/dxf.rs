//! DXF entities: a curve as one exact SPLINE entity, a surface as POLYFACE meshes; what the
//! entity cannot hold (the kind, the membership rule, the degrees, the names) as extended
//! data under `NEUTROSPLINE` ([`crate::dxf_xdata`]).

use neutrospline::{AnyCurve, Bounded, ControlPolygon, KnotVector};

use super::dxf_document::{document, Extent, Tags};
use super::{ColorBy, ExportError, Samples};
use crate::dxf_xdata::{ModelInfo, XValue};
use neutrospline_io::{Model, Shape};

/// What the extended data of the model's entity says, with or without the control points'
/// degrees and names.
fn info(model: &Model, with_points: bool) -> ModelInfo {
    let wide = model.membership().lane_count() == 2;
    let channels = if with_points && wide {
        let values = model.control_channels();
        model
            .membership()
            .channels()
            .iter()
            .enumerate()
            .map(|(c, name)| ((*name).to_owned(), values.iter().map(|v| v[c]).collect()))
            .collect()
    } else {
        Vec::new()
    };
    ModelInfo {
        channels,
        kind: model.kind(),
        dimension: model.shape().dimension(),
        membership: model.membership(),
        name: model.name().map(str::to_owned),
        description: model.description().map(str::to_owned),
        degrees: if with_points && !wide {
            model.shape().control_degrees()
        } else {
            Vec::new()
        },
        point_names: if with_points {
            model.point_names().to_vec()
        } else {
            Vec::new()
        },
    }
}

/// The flags of a SPLINE (group code 70): 4 rational, 8 planar.
const RATIONAL: i64 = 4;
const PLANAR: i64 = 8;

/// One SPLINE entity of `curve`: a Bézier curve as its clamped B-spline (degree n, knots 0 and
/// 1 each n + 1 times), a B-spline or NURBS curve with its own knots (and weights).
fn spline<const D: usize>(t: &mut Tags, owner: u32, curve: &AnyCurve<D>, info: &ModelInfo) {
    let bezier_knots;
    let knots: &KnotVector = match curve {
        AnyCurve::Bezier(c) => {
            bezier_knots = c.to_bspline().knots().clone();
            &bezier_knots
        }
        AnyCurve::BSpline(c) => c.knots(),
        AnyCurve::Nurbs(c) => c.knots(),
    };
    let weights = curve.weights();
    t.start("SPLINE", owner);
    t.tag(100, "AcDbEntity").tag(8, "0").tag(100, "AcDbSpline");
    let mut flags = 0;
    if D == 2 {
        t.point(210, [0.0, 0.0, 1.0]);
        flags |= PLANAR;
    }
    if weights.is_some() {
        flags |= RATIONAL;
    }
    t.int(70, flags).int(71, curve.degree() as i64);
    t.int(72, knots.knots().len() as i64)
        .int(73, curve.len() as i64)
        .int(74, 0);
    t.real(42, 1e-10).real(43, 1e-10);
    for &k in knots.knots() {
        t.real(40, k);
    }
    for &w in weights.unwrap_or(&[]) {
        t.real(41, w);
    }
    for p in curve.control_points() {
        t.point(10, position(&p.position));
    }
    t.xdata(&info.to_values());
}

/// A position with `z = 0` for a plane curve.
fn position<const D: usize>(p: &[f64; D]) -> [f64; 3] {
    let mut out = [0.0; 3];
    out[..D].copy_from_slice(p);
    out
}

fn extent<const D: usize>(curve: &AnyCurve<D>) -> Extent {
    let b = curve.control_bounding_box();
    let mut lo = [0.0; 3];
    let mut hi = [0.0; 3];
    for k in 0..D {
        lo[k] = b.position[k].min;
        hi[k] = b.position[k].max;
    }
    (lo, hi)
}

/// A DXF document with the model's curve as one SPLINE entity.
///
/// # Errors
/// [`ExportError::SurfaceNeedsMesh`] for a surface.
pub(super) fn spline_document(model: &Model) -> Result<String, ExportError> {
    let info = info(model, true);
    Ok(match model.shape() {
        Shape::Curve(c) => neutrospline::on_dimension!(c, c => {
            document(extent(c), |t, owner| spline(t, owner, c, &info))
        }),
        Shape::Surface(_) => {
            return Err(ExportError::SurfaceNeedsMesh {
                kind: model.kind().name().to_owned(),
            })
        }
    })
}

/// The most vertices of one POLYFACE mesh: its face records index them with 16-bit integers.
const MAX_POLYFACE_VERTICES: usize = 32_767;

/// The triangles cut into groups whose vertices a POLYFACE mesh can index, each with its
/// vertices (indices into the samples) and its faces (1-based indices into those).
fn polyface_groups(triangles: &[[u32; 3]], points: usize) -> Vec<(Vec<u32>, Vec<[i64; 3]>)> {
    let mut groups = Vec::new();
    let mut local = vec![0i64; points];
    let mut vertices: Vec<u32> = Vec::new();
    let mut faces: Vec<[i64; 3]> = Vec::new();
    for triangle in triangles {
        let new = triangle.iter().filter(|&&k| local[k as usize] == 0).count();
        if vertices.len() + new > MAX_POLYFACE_VERTICES {
            for &k in &vertices {
                local[k as usize] = 0;
            }
            groups.push((std::mem::take(&mut vertices), std::mem::take(&mut faces)));
        }
        let face = triangle.map(|k| {
            if local[k as usize] == 0 {
                vertices.push(k);
                local[k as usize] = vertices.len() as i64;
            }
            local[k as usize]
        });
        faces.push(face);
    }
    if !faces.is_empty() {
        groups.push((vertices, faces));
    }
    groups
}

/// A DXF document with the sampled surface as POLYFACE meshes (more than one when it has more
/// than 32,767 points): each vertex keeps its degrees as extended data, each triangle is
/// painted (true colour) with the mean of its vertices' values of `by`.
pub(super) fn mesh_document(model: &Model, samples: &Samples, by: ColorBy) -> String {
    let info = info(model, false).to_values();
    let triangles = samples.triangles.as_deref().unwrap_or(&[]);
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in &samples.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    document((lo, hi), |t, owner| {
        for (vertices, faces) in polyface_groups(triangles, samples.positions.len()) {
            let mesh = t.start("POLYLINE", owner);
            t.tag(100, "AcDbEntity")
                .tag(8, "0")
                .tag(100, "AcDbPolyFaceMesh");
            t.int(66, 1).point(10, [0.0; 3]).int(70, 64);
            t.int(71, vertices.len() as i64).int(72, faces.len() as i64);
            t.xdata(&info);
            for &k in &vertices {
                t.start("VERTEX", mesh);
                t.tag(100, "AcDbEntity").tag(8, "0");
                t.tag(100, "AcDbVertex").tag(100, "AcDbPolyFaceMeshVertex");
                t.point(10, samples.positions[k as usize]).int(70, 192);
                // `degrees` 1 T I F, or each channel of a family of two lanes by its name.
                let mut values = Vec::new();
                match &samples.channels {
                    None => {
                        values.extend([XValue::Text("degrees".to_owned()), XValue::Long(1)]);
                        values.extend(samples.degrees[k as usize].to_array().map(XValue::Real));
                    }
                    Some((family, channels)) => {
                        for (name, v) in family.channels().iter().zip(channels[k as usize].iter()) {
                            values.extend([
                                XValue::Text((*name).to_owned()),
                                XValue::Long(1),
                                XValue::Real(*v),
                            ]);
                        }
                    }
                }
                t.xdata(&values);
            }
            for face in faces {
                let mean = face
                    .iter()
                    .map(|&k| by.value(&samples.degrees[vertices[k as usize - 1] as usize]))
                    .sum::<f64>()
                    / 3.0;
                let [r, g, b] = neutrospline::color::viridis(mean);
                t.start("VERTEX", mesh);
                t.tag(100, "AcDbEntity").tag(8, "0");
                t.int(
                    420,
                    (i64::from(r) << 16) | (i64::from(g) << 8) | i64::from(b),
                );
                t.tag(100, "AcDbFaceRecord")
                    .point(10, [0.0; 3])
                    .int(70, 128);
                t.int(71, face[0]).int(72, face[1]).int(73, face[2]);
            }
            t.start("SEQEND", mesh);
            t.tag(100, "AcDbEntity").tag(8, "0");
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polyface_groups_stay_within_16_bits() {
        // A strip of triangles over 40,000 points: two groups, the second repeating the
        // vertices it shares with the first.
        let triangles: Vec<[u32; 3]> = (0..39_998).map(|k| [k, k + 1, k + 2]).collect();
        let groups = polyface_groups(&triangles, 40_000);
        assert_eq!(groups.len(), 2);
        assert_eq!(groups[0].0.len(), MAX_POLYFACE_VERTICES);
        assert_eq!(groups[0].1.len() + groups[1].1.len(), triangles.len());
        assert_eq!(groups[1].1[0], [1, 2, 3]);
        assert_eq!(groups[1].0[..2], [32_765, 32_766]);
        let small = polyface_groups(&[[0, 1, 2], [0, 2, 3]], 4);
        assert_eq!(small, [(vec![0, 1, 2, 3], vec![[1, 2, 3], [1, 3, 4]])]);
    }
}
