//! The [`Figure`] trait: how one view is drawn. Each view module implements it; the dispatch
//! in the parent module (`views::figure`) picks the implementation for a [`View`](crate::View).

use crate::ctx::Ctx;
use crate::drawing::Drawing;
use crate::model::Mesh;

/// How one view is drawn: its default title and its figure of each kind of model.
pub(crate) trait Figure {
    /// The title when the options set none, from the model's label.
    fn title(&self, label: &str, surface: bool) -> String;

    /// The figure of a 2-D curve (positions x, y: the degrees can become heights).
    fn curve_2d(&self, ctx: &Ctx) -> Drawing;

    /// The figure of a 3-D curve (positions x, y, z).
    fn curve_3d(&self, ctx: &Ctx) -> Drawing;

    /// The figure of a surface sampled as `mesh`, with a `rows x cols` control net.
    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing;

    /// Whether the view draws the model's data overlay: [`render_svg`](crate::render_svg)
    /// then requires a curve with data, and gives the view the data (`Ctx::data`) instead of
    /// the control points.
    fn draws_data(&self) -> bool {
        false
    }
}
