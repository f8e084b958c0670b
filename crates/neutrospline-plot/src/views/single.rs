//! `truth`, `indeterminacy`, `falsity` (paper Fig. 2-4) and `score`: one quantity, a degree
//! or the score of the degrees (docs/model.md section 7), drawn alike.
//!
//! - 2-D curve: the space curve `(x, y, q)` with its control polygon lifted to the control
//!   points' values in a 3-D box, a translucent curtain down to the crisp curve on the q = 0
//!   floor, drop lines. The score is affine in the degrees and every basis is non-negative
//!   with unit sum, so the lifted score curve is the curve of the lifted control polygon.
//! - 3-D curve: the curve coloured by the quantity (viridis) with a colour bar, its control
//!   polygon and points coloured alike, drop lines and the shadow on the floor.
//! - Surface: the shaded mesh coloured by the quantity, with the control net and a colour
//!   bar.

use crate::ctx::Ctx;
use crate::curve3d::{coloured_legend, coloured_panel};
use crate::drawing::Drawing;
use crate::layout::{Entry, LegendPlace};
use crate::lifted::{self, Look};
use crate::mesh::{mesh_panel, quantity_legend};
use crate::model::Mesh;
use crate::quantity::Quantity;
use crate::theme::Marker;

use super::figure::Figure;

/// The view of one quantity.
pub(crate) struct Single(pub Quantity);

impl Figure for Single {
    fn title(&self, label: &str, _surface: bool) -> String {
        format!("{label}: {}", self.0.name())
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let q = self.0;
        let c = q.color();
        let entries = vec![
            Entry::line(c, th.curve_w(), None, &format!("{} curve", q.name())),
            Entry::polygon(th, c, Marker::Circle, c, "control polygon"),
        ];
        let look = Look {
            axis: q.name(),
            curtain: true,
            polygon_w: th.polygon_w(),
            marker: |_| Marker::Circle,
            lift_controls: true,
        };
        lifted::figure(ctx, &[q], entries, q.notes(), &look)
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let q = self.0;
        let legend = coloured_legend(&ctx.theme, q.name(), q.noun(), q.notes());
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            coloured_panel(svg, ctx, plot, q, avoid);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        let q = self.0;
        let legend = quantity_legend(&ctx.theme, q.name(), q.noun(), q.notes());
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            mesh_panel(svg, ctx, mesh, grid, plot, q, avoid);
        })
    }
}
