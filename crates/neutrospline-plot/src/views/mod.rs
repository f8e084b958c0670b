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
mod figure;
mod plane;
mod single;

use neutrospline::DegreeKind;

use crate::quantity::Quantity;
use crate::view::View;

pub(crate) use figure::Figure;

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
