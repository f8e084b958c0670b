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
mod measure;
mod plane;
mod single;
mod wide;

use neutrospline::DegreeKind;

use crate::drawing::Painter;
use crate::layout::Entry;
use crate::quantity::Quantity;
use crate::style::{Color, Style};
use crate::theme::{self, marker_style, Marker, Theme};
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
        // Drawn per family by `family_figure`; a model of no family given (neutrosophic)
        // has none, which `PlotModel::check_view` refuses before drawing.
        View::Derived => &measure::Measure {
            family: neutrospline::Family::Neutrosophic,
            kind: measure::Kind::Derived,
        },
        View::Data => &data::Data,
        View::Band => &band::Band,
    }
}

/// The view's drawing of a family's own measures: the `score` view of every family but the
/// neutrosophic one (whose score `(2 + T - I - F) / 3` the [`single`] view draws, lifted from
/// the control points), and the `derived` view; `None` for the other views.
pub(crate) fn family_figure(view: View, family: neutrospline::Family) -> Option<Box<dyn Figure>> {
    let kind = match view {
        View::Score if family != neutrospline::Family::Neutrosophic => measure::Kind::Score,
        View::Derived => measure::Kind::Derived,
        _ => return None,
    };
    Some(Box::new(measure::Measure { family, kind }))
}

/// The view's drawing for a wide (two-lane) family, for the views that draw both lanes:
/// `truth`, `indeterminacy`, `falsity` and `all` ([`wide`]); `None` for the others (the `band`
/// view draws the position, which the lanes share; the rest are refused by
/// [`PlotModel::check_view`](crate::PlotModel::check_view)).
pub(crate) fn wide_figure(view: View, family: neutrospline::Family) -> Option<Box<dyn Figure>> {
    let kind = match view {
        View::Truth => Some(DegreeKind::Truth),
        View::Indeterminacy => Some(DegreeKind::Indeterminacy),
        View::Falsity => Some(DegreeKind::Falsity),
        View::All => None,
        _ => return None,
    };
    Some(Box::new(wide::Wide { family, kind }))
}

/// The control polygon of a 2-D figure (pixel points `ctrl`), dashed in the construction
/// colour.
fn draw_control_polygon(svg: &mut Painter, th: &Theme, ctrl: &[(f64, f64)]) {
    svg.polyline(
        ctrl,
        &Style::stroke(theme::CONSTRUCTION, th.polygon_w())
            .with_dash(th.dash().0, th.dash().1)
            .with_class("control-polygon"),
    );
}

/// Over a 2-D figure's other layers: the crisp curve (pixel points `curve`), then the control
/// points `ctrl` as white markers.
fn draw_crisp_and_controls(
    svg: &mut Painter,
    th: &Theme,
    curve: &[(f64, f64)],
    ctrl: &[(f64, f64)],
) {
    svg.polyline(
        curve,
        &Style::stroke(theme::CRISP, th.thin_w()).with_class("curve crisp"),
    );
    for p in ctrl {
        svg.circle(
            *p,
            th.marker_r(),
            &marker_style(th, Color::WHITE).with_class("control-point"),
        );
    }
}

/// The legend entry of the control polygon and points drawn by [`draw_control_polygon`] and
/// [`draw_crisp_and_controls`].
fn control_polygon_entry(th: &Theme) -> Entry {
    Entry::polygon(
        th,
        theme::CONSTRUCTION,
        Marker::Circle,
        Color::WHITE,
        "control polygon",
    )
}
