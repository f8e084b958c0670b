//! Figures of a model, drawn the way `neutrospline plot` draws them: one code path for the
//! command and the studio, so that the studio's "export SVG" writes the command's bytes.

use neutrospline_io::Model;
use neutrospline_plot::{Drawing, PlotOptions};

/// The options `neutrospline plot FILE --azimuth A --elevation E` draws with: the default
/// size and samples, the default title, and the model's description as the caption.
pub fn figure_options(model: &Model, azimuth: f64, elevation: f64) -> PlotOptions {
    let options = PlotOptions::new()
        .with_size(PlotOptions::DEFAULT_WIDTH, PlotOptions::DEFAULT_HEIGHT)
        .with_camera(azimuth, elevation);
    match model.description() {
        Some(caption) => options.with_caption(caption),
        None => options,
    }
}

/// Where the control points of a plane curve are drawn in a `plane` view: the pixel of each,
/// and the map from model coordinates to pixels (`px = ox + sx x`, `py = oy + sy y`).
#[derive(Debug, Clone, PartialEq)]
pub struct Handles {
    /// The centre of each control point's marker, in SVG pixels, in order.
    pub pixels: Vec<[f64; 2]>,
    /// `[sx, sy, ox, oy]`, or `None` when the points do not determine it (3-D models).
    pub frame: Option<[f64; 4]>,
}

/// The handles of a `plane` view `drawing` of a 2-D curve with control positions `points`:
/// the pixels of its control-point markers (circles of class `control-point`), and the scale
/// and offset on each axis from the two points farthest apart along it (the plane view draws
/// x and y at one scale, which stands in for an axis on which all points coincide).
pub fn handles(drawing: &Drawing, points: &[[f64; 2]]) -> Handles {
    let pixels = drawing.circle_centres("control-point");
    let frame = (pixels.len() == points.len() && !points.is_empty())
        .then(|| {
            let axis = |a: usize| -> Option<f64> {
                let (lo, hi) = (0..points.len()).fold((0, 0), |(lo, hi), i| {
                    (
                        if points[i][a] < points[lo][a] { i } else { lo },
                        if points[i][a] > points[hi][a] { i } else { hi },
                    )
                });
                let d = points[hi][a] - points[lo][a];
                (d > 0.0).then(|| (pixels[hi][a] - pixels[lo][a]) / d)
            };
            let (sx, sy) = match (axis(0), axis(1)) {
                (Some(sx), Some(sy)) => (sx, sy),
                (Some(sx), None) => (sx, -sx),
                (None, Some(sy)) => (-sy, sy),
                (None, None) => return None,
            };
            let (ox, oy) = (
                pixels[0][0] - sx * points[0][0],
                pixels[0][1] - sy * points[0][1],
            );
            [sx, sy, ox, oy]
                .iter()
                .all(|v| v.is_finite())
                .then_some([sx, sy, ox, oy])
        })
        .flatten();
    Handles { pixels, frame }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::ControlPolygon;
    use neutrospline_plot::{render_drawing, PlotModel, View};

    #[test]
    fn handles_map_model_to_pixels() {
        let curve = neutrospline::example1();
        let model = PlotModel::from(&curve);
        let drawing = render_drawing(&model, View::Plane, &PlotOptions::default()).unwrap();
        let points: Vec<[f64; 2]> = curve.control_points().iter().map(|p| p.position).collect();
        let h = handles(&drawing, &points);
        assert_eq!(h.pixels.len(), 4);
        let [sx, sy, ox, oy] = h.frame.unwrap();
        // Equal scale on both axes, y down.
        assert!((sx + sy).abs() < 1e-3 * sx, "{sx} {sy}");
        for (p, px) in points.iter().zip(&h.pixels) {
            assert!((ox + sx * p[0] - px[0]).abs() < 1e-6, "{p:?} {px:?}");
            assert!((oy + sy * p[1] - px[1]).abs() < 1e-6, "{p:?} {px:?}");
        }
    }
}
