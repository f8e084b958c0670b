//! `truth`, `indeterminacy`, `falsity` (paper Fig. 2-4): one degree.
//!
//! - 2-D curve: the space curve `(x, y, degree)` with its control polygon in a 3-D box, a
//!   translucent curtain down to the crisp curve on the degree = 0 floor, drop lines.
//! - 3-D curve: the curve coloured by the degree (viridis) with a colour bar, its control
//!   polygon and points coloured alike, drop lines and the shadow on the floor.
//! - Surface: the shaded mesh coloured by the degree, with the control net and a colour bar.

use neutrospline::DegreeKind;

use crate::ctx::Ctx;
use crate::curve3d::{coloured_legend, coloured_panel};
use crate::layout::{Entry, LegendPlace};
use crate::lifted::{self, Look};
use crate::mesh::{degree_legend, mesh_panel};
use crate::model::Mesh;
use crate::theme::{self, Marker};

use super::Figure;

/// The view of one degree.
pub(crate) struct Degree(pub DegreeKind);

impl Figure for Degree {
    fn title(&self, label: &str, _surface: bool) -> String {
        format!("{label}: {}", self.0.name())
    }

    fn curve_2d(&self, ctx: &Ctx) -> String {
        let th = &ctx.theme;
        let kind = self.0;
        let c = theme::degree_color(kind);
        let entries = vec![
            Entry::line(c, th.curve_w(), None, &format!("{} curve", kind.name())),
            Entry::polygon(th, c, Marker::Circle, c, "control polygon"),
        ];
        let look = Look {
            axis: kind.name(),
            curtain: true,
            polygon_w: th.polygon_w(),
            marker: |_| Marker::Circle,
        };
        lifted::figure(ctx, &[kind], entries, &look)
    }

    fn curve_3d(&self, ctx: &Ctx) -> String {
        let th = &ctx.theme;
        let legend = coloured_legend(th, self.0.name());
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            coloured_panel(svg, ctx, plot, self.0, avoid);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> String {
        let th = &ctx.theme;
        let legend = degree_legend(th, self.0.name());
        ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
            mesh_panel(svg, ctx, mesh, grid, plot, self.0, avoid);
        })
    }
}
