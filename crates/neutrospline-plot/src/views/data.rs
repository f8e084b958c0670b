//! `data`: measured data points next to the curve fitted to them.
//!
//! - 2-D curve: on x-y axes, the fitted curve (its crisp positions) as a line, a residual
//!   whisker from each data point to the curve point it was fitted to, and each data point as
//!   a marker filled with the viridis colour of one degree, with a colour bar of that degree.
//! - 3-D curve: the same in the 3-D box, with the curve's shadow on the floor.
//! - Surface: none: [`render_svg`](crate::render_svg) refuses the data view of a surface
//!   ([`PlotError::DataOnSurface`](crate::PlotError::DataOnSurface)) before drawing, so
//!   [`Figure::surface`] draws only the frame.
//!
//! Markers carry no callouts, and shrink past [`CROWD`] points, so that thousands of points
//! stay readable.

use neutrospline::DegreeKind;

use crate::axes2::Scale;
use crate::ctx::{Ctx, DataCtx};
use crate::curve3d::shadowed_box;
use crate::drawing::Drawing;
use crate::layout::{ColorBar, Entry, Legend, LegendPlace, Swatch};
use crate::model::Mesh;
use crate::scene::{Shape, CHUNK, DATA, OVER};
use crate::style::{Color, Style};
use crate::theme::{self, Marker, Theme};

use super::figure::Figure;

/// The `data` view.
pub(crate) struct Data;

/// Beyond this many points the markers shrink (with the square root of the count) and their
/// outlines thin.
const CROWD: usize = 200;

impl Figure for Data {
    fn title(&self, label: &str, _surface: bool) -> String {
        format!("{label} fitted to data")
    }

    fn draws_data(&self) -> bool {
        true
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let Some(data) = &ctx.data else {
            return ctx.figure(Legend::default(), LegendPlace::Column, |_, _, _| {});
        };
        let look = Look::new(th, data.points.len());
        let legend = legend(th, data, false);
        ctx.figure(legend, LegendPlace::Column, |svg, plot, _| {
            let axes = ctx.axes2(plot, 2.0 * look.r, Scale::Filling);
            axes.draw(svg, th);
            let curve = axes.pixels(&ctx.curve);
            let points = axes.pixels(&data.points);
            let feet = axes.pixels(&data.feet);
            axes.begin_clip(svg);
            svg.begin_group("residuals");
            for (a, b) in points.iter().zip(&feet) {
                svg.line(*a, *b, &look.whisker);
            }
            svg.end_group();
            svg.begin_group("data-points");
            for (p, d) in points.iter().zip(&data.points) {
                svg.circle(*p, look.r, &look.marker(d.deg[data.color_by.index()]));
            }
            svg.end_group();
            svg.polyline(&curve, &halo_style(th));
            svg.polyline(&curve, &curve_style(th));
            svg.end_group();
        })
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let Some(data) = &ctx.data else {
            return ctx.figure(Legend::default(), LegendPlace::Corner, |_, _, _| {});
        };
        let look = Look::new(th, data.points.len());
        let legend = legend(th, data, true);
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            let (axes, mut scene) = shadowed_box(svg, ctx, plot, avoid);
            for (p, foot) in data.points.iter().zip(&data.feet) {
                let (a, b) = (axes.screen(p.pos), axes.screen(foot.pos));
                scene.push(
                    DATA,
                    (a.2 + b.2) / 2.0,
                    Shape::Polyline(vec![(a.0, a.1), (b.0, b.1)], look.whisker.clone()),
                );
            }
            // The curve and the points are sorted by depth together, so that each hides
            // what lies behind it; the curve's halo lies a layer below, so that no piece of
            // it cuts into the line where two pieces meet.
            let curve: Vec<(f64, f64, f64)> =
                ctx.curve.iter().map(|p| axes.screen(p.pos)).collect();
            let (halo, line) = (halo_style(th), curve_style(th));
            for part in curve.windows(2).collect::<Vec<_>>().chunks(CHUNK) {
                let mut pts: Vec<(f64, f64)> = part.iter().map(|w| (w[0].0, w[0].1)).collect();
                let last = part[part.len() - 1][1];
                pts.push((last.0, last.1));
                let depth =
                    part.iter().map(|w| w[0].2 + w[1].2).sum::<f64>() / (2 * part.len()) as f64;
                scene.push(DATA, depth, Shape::Polyline(pts.clone(), halo.clone()));
                scene.push(OVER, depth, Shape::Polyline(pts, line.clone()));
            }
            if let [p] = curve[..] {
                scene.push(OVER, p.2, Shape::Polyline(vec![(p.0, p.1)], line.clone()));
            }
            for p in &data.points {
                let a = axes.screen(p.pos);
                scene.push(
                    OVER,
                    a.2,
                    Shape::Marker(
                        Marker::Circle,
                        (a.0, a.1),
                        look.r,
                        look.marker(p.deg[data.color_by.index()]),
                    ),
                );
            }
            scene.draw(svg);
        })
    }

    fn surface(&self, ctx: &Ctx, _mesh: &Mesh, _grid: (usize, usize)) -> Drawing {
        // Unreachable through `render_svg`, which refuses a surface first.
        ctx.figure(Legend::default(), LegendPlace::Corner, |_, _, _| {})
    }
}

/// The fitted curve: a dark line of the crisp curve's width, drawn over the data.
fn curve_style(th: &Theme) -> Style {
    Style::stroke(theme::CRISP, th.crisp_w()).with_class("curve fitted")
}

/// A white halo under the fitted curve, that sets it off from the points it crosses.
fn halo_style(th: &Theme) -> Style {
    let mut halo = Style::stroke(Color::WHITE, th.crisp_w() + 3.0 * th.s).with_class("curve halo");
    halo.stroke_opacity = 0.8;
    halo
}

/// The sizes of the data's marks for `n` points.
struct Look {
    /// Marker radius.
    r: f64,
    /// Marker outline width (none for crowded points, whose outlines would hide their fill).
    outline: Option<f64>,
    /// The whiskers' style.
    whisker: Style,
}

impl Look {
    fn new(th: &Theme, n: usize) -> Look {
        let crowd = if n > CROWD {
            (CROWD as f64 / n as f64).sqrt().max(0.35)
        } else {
            1.0
        };
        let mut whisker = Style::stroke(theme::RESIDUAL, 1.25 * th.thin_w() * crowd.max(0.5))
            .with_class("residual");
        if crowd < 1.0 {
            whisker.stroke_opacity = 0.6;
        }
        Look {
            r: 0.6 * th.marker_r() * crowd,
            outline: (crowd >= 0.5).then_some(th.s * (0.6 + 0.9 * crowd)),
            whisker,
        }
    }

    /// A data point's marker, filled with the colour of `value`.
    fn marker(&self, value: f64) -> Style {
        let fill = theme::colormap(value);
        match self.outline {
            Some(w) => Style::stroke(theme::CRISP, w).with_fill(fill),
            None => Style::fill(fill),
        }
        .with_class("data-point")
    }
}

/// The legend: the curve, a data point, a residual (and the shadow, in 3-D), what the
/// whiskers show, and the colour bar of the degree that colours the points.
fn legend(th: &Theme, data: &DataCtx, shadow: bool) -> Legend {
    let kind: DegreeKind = data.color_by;
    let to = if data.at_parameters {
        "the curve at each point's parameter"
    } else {
        "the nearest point of the curve"
    };
    let n = data.points.len();
    let count = if n == 1 {
        "1 data point".to_string()
    } else {
        format!("{n} data points")
    };
    let mut entries = vec![
        Entry::line(theme::CRISP, th.crisp_w(), None, "fitted curve"),
        Entry {
            swatch: Swatch::Marker {
                shape: Marker::Circle,
                fill: theme::colormap(0.5),
            },
            label: "data point".to_string(),
        },
        Entry::line(theme::RESIDUAL, 1.25 * th.thin_w(), None, "residual"),
    ];
    if shadow {
        entries.push(Entry::line(
            theme::SHADOW,
            th.crisp_w(),
            None,
            "shadow on the floor",
        ));
    }
    Legend {
        entries,
        notes: vec![format!("{count}. Residuals run to {to}.")],
        colorbar: Some(ColorBar {
            label: format!("{} of the data", kind.name()),
            length: 0.62,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_markers_shrink_past_the_crowd() {
        let th = Theme::new(1600, 1200);
        assert_eq!(Look::new(&th, 10).r, Look::new(&th, CROWD).r);
        assert!(Look::new(&th, 800).r < 0.6 * Look::new(&th, CROWD).r);
        assert_eq!(Look::new(&th, 100_000).r, 0.35 * Look::new(&th, 1).r);
        assert_eq!(Look::new(&th, 100_000).outline, None);
    }
}
