//! The kinds of figure.

use core::fmt;
use core::str::FromStr;

use neutrospline::DegreeKind;

use crate::error::PlotError;

/// Which figure to draw. Names (for [`FromStr`] and [`Display`](fmt::Display)) are the
/// lowercase variant names: `controls`, `truth`, `indeterminacy`, `falsity`, `all`, `plane`,
/// `score`, `derived`, `data`, `band`.
///
/// | view | 2-D model (the paper's figures) | 3-D model | surface |
/// |---|---|---|---|
/// | `controls` | Fig. 1: control polygon and points, each with a callout of its name and three degree bars | the same in a 3-D box, with drop lines to the floor | the control net over the grey surface, each point drawn as three degree bars, corners named |
/// | `truth`, `indeterminacy`, `falsity` | Fig. 2-4: space curve `(x, y, degree)` with its control polygon above the crisp curve (its shadow on the degree = 0 plane) | the 3-D curve coloured by that degree, with a colour bar and its shadow on the floor | the shaded mesh coloured by that degree, with the control net and a colour bar |
/// | `all` | Fig. 5: the three space curves in one box | three panels, one per degree, sharing a colour bar | three meshes, one per degree, sharing a colour bar |
/// | `plane` | crisp curve with three bands along it whose widths are the degrees | the same bands along the curve's projection in the 3-D box | three heat maps of the degrees over the parameter domain (u, v), with knot lines |
/// | `score` | the space curve `(x, y, score)` like Fig. 2-4, the family's score ([`neutrospline::Family::score`]: `(2 + T - I - F) / 3` for the neutrosophic family, `T - F` intuitionistic, `T^2 - F^2` Pythagorean, ...) as the height, sampled from the blended channels; the control polygon lifted to the control points' scores where the score is affine in the channels, else not drawn | the 3-D curve coloured by the score, with a colour bar | the shaded mesh coloured by the score, with the control net and a colour bar |
/// | `derived` | the family's derived degrees ([`neutrospline::Family::derived`]: hesitation, refusal, type-reduced membership and footprint, ...) drawn like `score`, one space curve each, sampled from the blended channels | the 3-D curve coloured by the derived degree (one panel per derived degree) | the mesh coloured by the derived degree (one panel each) |
/// | `band` | the plane view of the fuzzy position (control point spreads, SPEC section 9): the region swept by the curve's alpha-cut at alpha = 0, 0.5 and 1 ([`PlotOptions::with_alphas`](crate::PlotOptions::with_alphas)), lighter for lower alpha, the crisp curve on top and the centroid curve dashed where it differs | the silhouette of the tube of alpha-cut boxes in the 3-D box | none: an error ([`PlotError::BandOnSurface`]) |
/// | `data` | the curve fitted to measured data ([`PlotModel::with_data`](crate::PlotModel::with_data)) as a line on x-y axes, the data points as markers coloured by one degree (viridis, with a colour bar), a residual whisker from each point to its point of the curve | the same in the 3-D box, with the curve's shadow on the floor | the fitted surface's mesh coloured by the same degree, with the data points and their whiskers to the surface at their `(u, v)` (or its nearest point) over it |
///
/// ```
/// use neutrospline_plot::View;
/// let view: View = "truth".parse()?;
/// assert_eq!(view, View::Truth);
/// assert_eq!(view.to_string(), "truth");
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
///
/// The `derived` view needs a family with derived degrees ([`neutrospline::Family::derived_names`]).
/// The `data` view needs a model with data points; without them it is an error
/// ([`PlotError::NoData`]). [`View::MODEL`] lists the views that draw any model (not `band`,
/// which draws curves only, nor `data`, nor `derived`).
///
/// More views may come: the enum is `#[non_exhaustive]`, so a `match` on it outside this crate
/// needs a wildcard arm; [`View::ALL`] lists the views there are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum View {
    /// The control points with their degrees (paper Fig. 1).
    Controls,
    /// The truth curve (paper Fig. 2).
    Truth,
    /// The indeterminacy curve (paper Fig. 3).
    Indeterminacy,
    /// The falsity curve (paper Fig. 4).
    Falsity,
    /// The three degree curves together (paper Fig. 5).
    All,
    /// A flat view: the three degrees as bands along the crisp curve.
    Plane,
    /// The family's score ([`neutrospline::Family::score`]; `(2 + T - I - F) / 3` for the
    /// neutrosophic family, docs/model.md section 7), drawn like a degree: as the height of
    /// the space curve of a 2-D model, as the colour of a 3-D curve or a surface. It is
    /// sampled from the channels blended at each parameter; only where it is affine in the
    /// channels (every linear family) is the score of the curve the curve of the control
    /// points' scores, and the control polygon lifted to them.
    Score,
    /// The degrees the model's family derives from its channels ([`neutrospline::Family::derived`]:
    /// the hesitation `(1 - T^q - F^q)^(1/q)` of the orthopair families, the picture refusal
    /// `1 - T - I - F`, the type-reduced membership and footprint of interval type-2, ...),
    /// drawn like a degree and sampled from the blended channels (docs/model.md, "Membership
    /// families"). A family that derives none (neutrosophic, fuzzy, interval-neutrosophic,
    /// bipolar) is refused ([`PlotModel::check_view`](crate::PlotModel::check_view)).
    Derived,
    /// Measured data points next to the curve fitted to them, with residual whiskers
    /// ([`PlotModel::with_data`](crate::PlotModel::with_data)).
    Data,
    /// The fuzzy position's band: the regions swept by the alpha-cuts of the curve whose
    /// control points carry spreads, with the crisp and the centroid curve (curves only).
    Band,
}

impl View {
    /// Every view, in the paper's order, then `plane`, `score`, `derived`, `data` and `band`.
    pub const ALL: [View; 10] = [
        View::Controls,
        View::Truth,
        View::Indeterminacy,
        View::Falsity,
        View::All,
        View::Plane,
        View::Score,
        View::Derived,
        View::Data,
        View::Band,
    ];

    /// The views that draw any model (every view but `derived`, which needs a family with
    /// derived degrees, `data`, which needs data points, and `band`, which draws curves
    /// only), in the order of [`View::ALL`].
    pub const MODEL: [View; 7] = {
        let mut model = [View::Controls; 7];
        let (mut i, mut kept) = (0, 0);
        while i < View::ALL.len() {
            if !matches!(View::ALL[i], View::Derived | View::Data | View::Band) {
                model[kept] = View::ALL[i];
                kept += 1;
            }
            i += 1;
        }
        assert!(
            kept == model.len(),
            "MODEL is ALL without derived, data and band"
        );
        model
    };

    /// The names of [`View::ALL`], in its order.
    pub const NAMES: [&'static str; 10] = {
        let mut names = [""; 10];
        let mut i = 0;
        while i < 10 {
            names[i] = View::ALL[i].name();
            i += 1;
        }
        names
    };

    /// The view's name, as parsed and displayed.
    pub const fn name(self) -> &'static str {
        match self {
            View::Controls => "controls",
            View::Truth => "truth",
            View::Indeterminacy => "indeterminacy",
            View::Falsity => "falsity",
            View::All => "all",
            View::Plane => "plane",
            View::Score => "score",
            View::Derived => "derived",
            View::Data => "data",
            View::Band => "band",
        }
    }

    /// The degree a single-degree view shows (`truth`, `indeterminacy`, `falsity`), else `None`.
    pub const fn degree(self) -> Option<DegreeKind> {
        match self {
            View::Truth => Some(DegreeKind::Truth),
            View::Indeterminacy => Some(DegreeKind::Indeterminacy),
            View::Falsity => Some(DegreeKind::Falsity),
            _ => None,
        }
    }
}

impl From<DegreeKind> for View {
    fn from(kind: DegreeKind) -> View {
        match kind {
            DegreeKind::Truth => View::Truth,
            DegreeKind::Indeterminacy => View::Indeterminacy,
            DegreeKind::Falsity => View::Falsity,
        }
    }
}

impl fmt::Display for View {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for View {
    type Err = PlotError;

    /// Parses a view name (exact, lowercase).
    ///
    /// # Errors
    /// [`PlotError::UnknownView`] for any other text.
    fn from_str(s: &str) -> Result<View, PlotError> {
        View::ALL
            .into_iter()
            .find(|v| v.name() == s)
            .ok_or_else(|| PlotError::UnknownView {
                name: s.to_string(),
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn view_names_round_trip() {
        for v in View::ALL {
            assert_eq!(v.to_string().parse::<View>(), Ok(v));
        }
    }

    #[test]
    fn view_unknown_name_message() {
        let err = "Truth".parse::<View>().unwrap_err();
        assert_eq!(
            err.to_string(),
            "unknown view \"Truth\" (expected one of: controls, truth, indeterminacy, falsity, all, plane, score, derived, data, band)"
        );
        // The message lists every view, in the order of `View::ALL`.
        let names: Vec<&str> = View::ALL.iter().map(|v| v.name()).collect();
        assert!(err
            .to_string()
            .ends_with(&format!("(expected one of: {})", names.join(", "))));
    }

    #[test]
    fn view_degree_kinds() {
        assert_eq!(View::Falsity.degree(), Some(DegreeKind::Falsity));
        assert_eq!(View::All.degree(), None);
        assert_eq!(View::Score.degree(), None);
        assert_eq!(View::from(DegreeKind::Indeterminacy), View::Indeterminacy);
    }
}
