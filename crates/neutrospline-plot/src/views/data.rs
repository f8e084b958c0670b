//! `data`: measured data points next to the curve fitted to them.
//!
//! - 2-D curve: on x-y axes, the fitted curve (its crisp positions) as a line, a residual
//!   whisker from each data point to the curve point it was fitted to, and each data point as
//!   a marker filled with the viridis colour of one degree, with a colour bar of that degree.
//! - 3-D curve: the same in the 3-D box, with the curve's shadow on the floor.
//! - Surface: the fitted surface's shaded mesh in the 3-D box, coloured by the same degree
//!   as the points (one colour bar for both), then the whiskers (to the surface at each
//!   point's `(u, v)`, else to its nearest point) and the points over it, farthest first: no
//!   point is hidden behind the surface, and a whisker shows on which side of it its point
//!   lies.
//!
//! Markers carry no callouts, and shrink past [`CROWD`] points, so that thousands of points
//! stay readable.

use neutrospline::DegreeKind;

use crate::axes2::Scale;
use crate::ctx::{Ctx, DataCtx};
use crate::curve3d::shadowed_box;
use crate::drawing::Drawing;
use crate::layout::{ColorBar, Entry, Legend, LegendPlace, Swatch};
use crate::mesh::{draw_mesh, Paint};
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
        let legend = legend(th, data, Fitted::PlaneCurve);
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
        let legend = legend(th, data, Fitted::SpaceCurve);
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

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, _grid: (usize, usize)) -> Drawing {
        let th = &ctx.theme;
        let Some(data) = &ctx.data else {
            return ctx.figure(Legend::default(), LegendPlace::Corner, |_, _, _| {});
        };
        let look = Look::new(th, data.points.len());
        let legend = legend(th, data, Fitted::Surface);
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            let axes = ctx.draw_box(svg, plot, avoid);
            draw_mesh(svg, th, &axes, mesh, Paint::By(data.color_by.into()));
            let mut order: Vec<(f64, usize)> = data
                .points
                .iter()
                .zip(&data.feet)
                .enumerate()
                .map(|(k, (p, f))| ((axes.screen(p.pos).2 + axes.screen(f.pos).2) / 2.0, k))
                .collect();
            order.sort_by(|a, b| b.0.total_cmp(&a.0));
            svg.begin_group("residuals");
            for &(_, k) in &order {
                let (a, b) = (
                    axes.screen(data.points[k].pos),
                    axes.screen(data.feet[k].pos),
                );
                svg.line((a.0, a.1), (b.0, b.1), &look.whisker);
            }
            svg.end_group();
            svg.begin_group("data-points");
            for &(_, k) in &order {
                let (p, a) = (&data.points[k], axes.screen(data.points[k].pos));
                svg.circle(
                    (a.0, a.1),
                    look.r,
                    &look.marker(p.deg[data.color_by.index()]),
                );
            }
            svg.end_group();
        })
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

/// What the data was fitted with.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Fitted {
    PlaneCurve,
    SpaceCurve,
    Surface,
}

/// The legend: the curve or surface, a data point, a residual (and the shadow, for a space
/// curve), what the whiskers show, and the colour bar of the degree that colours the points
/// (and the surface).
fn legend(th: &Theme, data: &DataCtx, fitted: Fitted) -> Legend {
    let kind: DegreeKind = data.color_by;
    let to = match (fitted, data.at_parameters) {
        (Fitted::Surface, true) => "the surface at each point's (u, v)",
        (Fitted::Surface, false) => "the nearest point of the surface",
        (_, true) => "the curve at each point's parameter",
        (_, false) => "the nearest point of the curve",
    };
    let n = data.points.len();
    let count = if n == 1 {
        "1 data point".to_string()
    } else {
        format!("{n} data points")
    };
    let fitted_entry = if fitted == Fitted::Surface {
        Entry {
            swatch: Swatch::Patch {
                color: theme::colormap(0.5),
            },
            label: "fitted surface".to_string(),
        }
    } else {
        Entry::line(theme::CRISP, th.crisp_w(), None, "fitted curve")
    };
    let mut entries = vec![
        fitted_entry,
        Entry {
            swatch: Swatch::Marker {
                shape: Marker::Circle,
                fill: theme::colormap(0.5),
            },
            label: "data point".to_string(),
        },
        Entry::line(theme::RESIDUAL, 1.25 * th.thin_w(), None, "residual"),
    ];
    if fitted == Fitted::SpaceCurve {
        entries.push(Entry::line(
            theme::SHADOW,
            th.crisp_w(),
            None,
            "shadow on the floor",
        ));
    }
    let mut notes = vec![format!("{count}. Residuals run to {to}.")];
    if fitted == Fitted::Surface {
        notes.push(format!("Points and surface coloured by {}.", kind.name()));
    }
    Legend {
        entries,
        notes,
        colorbar: Some(ColorBar {
            label: if fitted == Fitted::Surface {
                kind.name().to_string()
            } else {
                format!("{} of the data", kind.name())
            },
            length: 0.62,
            range: (0.0, 1.0),
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
