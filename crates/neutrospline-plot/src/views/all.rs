//! `all` (paper Fig. 5): the three degrees together.
//!
//! - 2-D curve: the three space curves `(x, y, degree)` in one box, each in its colour with
//!   its own marker shape, above the crisp curve.
//! - 3-D curve: three panels, one per degree (the curve coloured by it), sharing the colour
//!   bar, arranged by [`panels`].
//! - Surface: three meshes, one per degree, arranged alike.

use neutrospline::DegreeKind;

use crate::ctx::Ctx;
use crate::curve3d::{coloured_legend, coloured_panel};
use crate::drawing::{Drawing, Painter};
use crate::layout::{Entry, Legend, Rect, Swatch};
use crate::lifted::{self, Look};
use crate::mesh::{mesh_panel, quantity_legend};
use crate::model::Mesh;
use crate::panels;
use crate::quantity::Quantity;
use crate::theme;

use super::figure::Figure;

/// The `all` view.
pub(crate) struct All;

impl Figure for All {
    fn title(&self, label: &str, _surface: bool) -> String {
        format!("{label}: all three degrees")
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let mut entries: Vec<Entry> = DegreeKind::ALL
            .iter()
            .map(|&kind| {
                let c = theme::degree_color(kind);
                Entry {
                    swatch: Swatch::Line {
                        color: c,
                        width: th.curve_w(),
                        dash: None,
                        marker: Some((theme::degree_marker(kind), c)),
                    },
                    label: format!("{} curve", kind.name()),
                }
            })
            .collect();
        entries.push(Entry::line(
            theme::CONSTRUCTION,
            th.polygon_w(),
            Some(th.dash()),
            "control polygons",
        ));
        let look = Look {
            axis: "degree",
            curtain: false,
            polygon_w: th.thin_w(),
            marker: Quantity::marker,
            lift_controls: true,
        };
        let kinds = DegreeKind::ALL.map(Quantity::from);
        lifted::figure(ctx, &kinds, entries, Vec::new(), &look)
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let legend = coloured_legend(&ctx.theme, "degree", "degree", Vec::new());
        boxes(ctx, legend, &|svg, area, kind| {
            coloured_panel(svg, ctx, area, kind.into(), None);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        let legend = quantity_legend(&ctx.theme, "degree", "degree", Vec::new());
        boxes(ctx, legend, &|svg, area, kind| {
            mesh_panel(svg, ctx, mesh, grid, area, kind.into(), None);
        })
    }
}

/// Three 3-D boxes, one per degree, drawn by `panel`, with the shared `legend` (without its
/// notes, which the panels make plain).
fn boxes(ctx: &Ctx, mut legend: Legend, panel: &dyn Fn(&mut Painter, Rect, DegreeKind)) -> Drawing {
    legend.notes.clear();
    panels::figure(ctx, &legend, &|area| ctx.fit_box(area), panel)
}
