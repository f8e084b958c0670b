//! The views, one module each, behind one dispatch: [`figure`] maps a [`View`] to the
//! [`Figure`] that draws it. A view module draws its three cases (a 2-D curve, a 3-D curve, a
//! surface) from the shared helpers of the crate, which never import a view module.
//!
//! Adding a view means adding its variant (and name) to [`View`], a module here with a type
//! implementing [`Figure`], and its arm in [`figure`].

mod all;
mod band;
mod controls;
mod data;
mod plane;
mod single;

use neutrospline::DegreeKind;

use crate::ctx::Ctx;
use crate::drawing::Drawing;
use crate::model::Mesh;
use crate::quantity::Quantity;
use crate::view::View;

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

/// The view's drawing: the one dispatch on [`View`].
pub(crate) fn figure(view: View) -> &'static dyn Figure {
    match view {
        View::Controls => &controls::Controls,
        View::Truth => &single::Single(Quantity::Degree(DegreeKind::Truth)),
        View::Indeterminacy => &single::Single(Quantity::Degree(DegreeKind::Indeterminacy)),
        View::Falsity => &single::Single(Quantity::Degree(DegreeKind::Falsity)),
        View::All => &all::All,
        View::Plane => &plane::Plane,
        View::Score => &single::Single(Quantity::Score),
        View::Data => &data::Data,
        View::Band => &band::Band,
    }
}
