//! `score` and `derived` of a membership family (docs/model.md, "Membership families"; SPEC
//! section 10): the family's own score ([`Family::score`]: `T - F` intuitionistic, `T^2 -
//! F^2` Pythagorean, `(M_L + M_U) / 2` interval type-2, ...) or its derived degrees
//! ([`Family::derived`]: the hesitation `(1 - T^q - F^q)^(1/q)`, the picture refusal `1 - T -
//! I - F`, the type-reduced membership and the footprint of interval type-2, ...), drawn like
//! a degree.
//!
//! Each measure is *sampled*: at every curve sample (and mesh point) the channels are read
//! off the blended lanes ([`Family::join_slots`] of the lanes' degree slots, docs/model.md
//! "Lanes"), and the measure is computed from them. A measure that is not affine in the
//! channels (`T^2 - F^2`, the hesitation `sqrt(1 - T^2 - F^2)`) is not the blend of the
//! control points' measures, so its lifted control polygon would lie; it is drawn only for
//! the linear families ([`Family::is_linear`]), whose scores and derived degrees are affine in
//! the channels (every basis is non-negative with unit sum, so the measure of the curve is
//! the curve of the control points' measures).
//!
//! - 2-D curve: the space curve `(x, y, measure)` of each measure in one box (signed scores
//!   on a vertical axis over \[-1, 1\], the crisp curve at 0), above (or through) the crisp
//!   curve; the lifted control polygon where affine.
//! - 3-D curve: the curve coloured by the measure, with a colour bar over its range (one
//!   panel per measure for two derived degrees).
//! - Surface: the mesh coloured by the measure (one panel per measure), with the control net.

use neutrospline::Family;

use crate::ctx::Ctx;
use crate::curve3d::{coloured_legend, coloured_panel};
use crate::drawing::Drawing;
use crate::layout::{Entry, Legend, LegendPlace, Rect};
use crate::lifted::{self, Look};
use crate::mesh::{mesh_panel, quantity_legend};
use crate::model::Mesh;
use crate::panels;
use crate::point::Pt;
use crate::quantity::Quantity;
use crate::theme::Marker;

use super::figure::Figure;

/// How one box of a measure view is drawn: into an area, of one quantity, clear of the
/// legend's rectangle (when it shares the area).
type Panel<'a> = dyn Fn(&mut crate::drawing::Painter, Rect, Quantity, Option<Rect>) + 'a;

/// What a measure view draws: the family's score, or its derived degrees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// [`Family::score`].
    Score,
    /// [`Family::derived`], one quantity per [`Family::derived_names`].
    Derived,
}

/// The `score` or `derived` view of a model of `family`.
pub(crate) struct Measure {
    pub family: Family,
    pub kind: Kind,
}

/// The family's score formula, as the legend writes it (no spaces, so that the legend never
/// breaks it; minus signs as U+2212): `T^2−F^2` for Pythagorean, `(M_L+M_U)/2` for interval
/// type-2, ... (the table of [`Family::score`]).
pub(crate) fn score_formula(family: Family) -> String {
    let formula = match family {
        Family::Neutrosophic => "(2+T-I-F)/3".to_string(),
        Family::Fuzzy => "T".to_string(),
        Family::IntervalNeutrosophic => "(4+T_L+T_U-I_L-I_U-F_L-F_U)/6".to_string(),
        Family::IntervalIntuitionistic => "(T_L-F_L+T_U-F_U)/2".to_string(),
        Family::IntervalType2 => "(M_L+M_U)/2".to_string(),
        // T+ .. F+ the positive degrees, T- .. F- the negative ones (in [-1, 0]).
        Family::BipolarNeutrosophic => {
            return "(3+T\u{207a}\u{2212}I\u{207a}\u{2212}F\u{207a}+T\u{207b}\u{2212}I\u{207b}\u{2212}F\u{207b})/6"
                .to_string()
        }
        other => match other.power() {
            Some(1) | None => "T-F".to_string(),
            Some(p) => format!("T^{p}-F^{p}"),
        },
    };
    formula.replace('-', "\u{2212}")
}

/// The formula of derived degree `name` of `family` (the table of [`Family::derived`]), as
/// [`score_formula`] writes it.
pub(crate) fn derived_formula(family: Family, name: &str) -> String {
    let formula = match (family, name) {
        (Family::IntervalIntuitionistic, "hesitation_lower") => "1-T_U-F_U".to_string(),
        (Family::IntervalIntuitionistic, _) => "1-T_L-F_L".to_string(),
        (Family::IntervalType2, "type_reduced") => "(M_L+M_U)/2".to_string(),
        (Family::IntervalType2, _) => "M_U-M_L".to_string(),
        (Family::Picture, _) => "1-T-I-F".to_string(),
        (other, _) => {
            let three = family.channel_count() == 3;
            match other.power() {
                Some(1) | None if three => "1-T-I-F".to_string(),
                Some(1) | None => "1-T-F".to_string(),
                Some(p) if three => format!("(1-T^{p}-I^{p}-F^{p})^(1/{p})"),
                Some(p) => format!("(1-T^{p}-F^{p})^(1/{p})"),
            }
        }
    };
    formula.replace('-', "\u{2212}")
}

/// Whether the family's score is signed (in \[-1, 1\]): the orthopair, picture, spherical
/// and interval-intuitionistic scores (the table of [`Family::score`]).
pub(crate) fn score_is_signed(family: Family) -> bool {
    !matches!(
        family,
        Family::Neutrosophic
            | Family::Fuzzy
            | Family::IntervalNeutrosophic
            | Family::IntervalType2
            | Family::BipolarNeutrosophic
    )
}

/// The measures of `kind` of a point of a `family` model whose lanes hold the degree slots
/// `lanes` (one lane, or two for the interval-valued and bipolar families): the channels
/// are joined from the slots ([`Family::join_slots`]), then the score or the derived degrees
/// are computed from them, into slots 0, 1, ... of the result.
pub(crate) fn measures(family: Family, kind: Kind, lanes: &[[f64; 3]]) -> [f64; 3] {
    let channels = family.join_slots(lanes);
    let mut out = [0.0; 3];
    match kind {
        Kind::Score => out[0] = family.score(&channels),
        Kind::Derived => {
            for (slot, v) in out.iter_mut().zip(family.derived(&channels).iter()) {
                *slot = *v;
            }
        }
    }
    out
}

/// Points whose degree slots hold the measures of `kind` of the points `first` (and, for a
/// wide family, the second lane's points `second`, at the same parameters), at their
/// positions.
pub(crate) fn measured(family: Family, kind: Kind, first: &[Pt], second: Option<&[Pt]>) -> Vec<Pt> {
    first
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let deg = match second.and_then(|s| s.get(k)) {
                Some(q) => measures(family, kind, &[p.deg, q.deg]),
                None => measures(family, kind, &[p.deg]),
            };
            Pt { pos: p.pos, deg }
        })
        .collect()
}

impl Measure {
    /// The quantities drawn: the score, or one per derived degree.
    fn quantities(&self) -> Vec<Quantity> {
        match self.kind {
            Kind::Score => vec![Quantity::Measured {
                slot: 0,
                name: "score",
                signed: score_is_signed(self.family),
            }],
            Kind::Derived => self
                .family
                .derived_names()
                .iter()
                .take(3)
                .enumerate()
                .map(|(slot, &name)| Quantity::Measured {
                    slot,
                    name,
                    signed: false,
                })
                .collect(),
        }
    }

    /// The formula of quantity `q` (`T^2−F^2`, `M_U−M_L`, ...).
    fn formula(&self, q: Quantity) -> String {
        match self.kind {
            Kind::Score => score_formula(self.family),
            Kind::Derived => derived_formula(self.family, q.name()),
        }
    }

    /// Whether the measures are affine in the channels, so that the control polygon may be
    /// lifted to the control points' measures: the linear families' are.
    fn affine(&self) -> bool {
        self.family.is_linear()
    }

    /// The axis and colour-bar label of the quantities: `score T^2−F^2` (the formula when
    /// short), `score`, `hesitation`, `derived degree` for two.
    fn axis(&self, kinds: &[Quantity]) -> String {
        match (self.kind, kinds) {
            (Kind::Score, [q]) => {
                let formula = self.formula(*q);
                if formula.chars().count() <= 12 {
                    format!("score {formula}")
                } else {
                    "score".to_string()
                }
            }
            (_, [q]) => q.name().to_string(),
            _ => "derived degree".to_string(),
        }
    }

    /// The legend notes: each quantity's formula (with the family), and for a non-affine
    /// measure, why the control polygon is not lifted.
    fn notes(&self, kinds: &[Quantity]) -> Vec<String> {
        let family = self.family;
        let mut notes: Vec<String> = kinds
            .iter()
            .map(|&q| format!("{} = {} ({family})", q.name(), self.formula(q)))
            .collect();
        notes.push("Sampled from the blended channels.".to_string());
        if !self.affine() {
            notes.push(format!(
                "Control polygon not lifted: the {} is not affine in the channels.",
                if self.kind == Kind::Score {
                    "score"
                } else {
                    "degree"
                }
            ));
        }
        notes
    }

    /// The measured context: `ctx`'s curve samples and control points (both lanes of a wide
    /// family) replaced by their measures, at the same positions; and the mesh likewise.
    fn measured_ctx<'a>(&self, ctx: &'a Ctx<'a>, controls: &'a [Pt]) -> Ctx<'a> {
        let wide = ctx.wide.as_ref();
        Ctx {
            theme: ctx.theme,
            options: ctx.options,
            curve: measured(
                self.family,
                self.kind,
                &ctx.curve,
                wide.map(|w| &w.curve[..]),
            ),
            controls,
            names: ctx.names,
            labelled: ctx.labelled,
            title: ctx.title.clone(),
            caption: ctx.caption.clone(),
            data: None,
            band: None,
            wide: None,
        }
    }

    fn measured_controls(&self, ctx: &Ctx) -> Vec<Pt> {
        let wide = ctx.wide.as_ref();
        measured(
            self.family,
            self.kind,
            ctx.controls,
            wide.map(|w| w.controls),
        )
    }

    fn measured_mesh(&self, ctx: &Ctx, mesh: &Mesh) -> Mesh {
        let second = ctx.wide.as_ref().and_then(|w| w.mesh.as_ref());
        Mesh {
            points: measured(
                self.family,
                self.kind,
                &mesh.points,
                second.map(|m| &m.points[..]),
            ),
            ..mesh.clone()
        }
    }

    /// A colour-bar legend (from `make`) over the range of the quantities, with the notes.
    fn bar_legend(
        &self,
        ctx: &Ctx,
        kinds: &[Quantity],
        make: fn(&crate::theme::Theme, &str, &str, Vec<String>) -> Legend,
    ) -> Legend {
        let noun = kinds.first().map_or("degree", |q| q.noun());
        let mut legend = make(&ctx.theme, &self.axis(kinds), noun, self.notes(kinds));
        if let (Some(bar), Some(q)) = (legend.colorbar.as_mut(), kinds.first()) {
            bar.range = q.range();
        }
        legend
    }

    /// One panel per quantity (one box for one), each drawn by `panel`.
    fn boxes(&self, ctx: &Ctx, kinds: &[Quantity], legend: Legend, panel: &Panel<'_>) -> Drawing {
        if let [q] = kinds {
            return ctx.figure(legend, LegendPlace::Corner, |svg, plot, avoid| {
                panel(svg, plot, *q, avoid);
            });
        }
        let titles: Vec<(String, crate::style::Color)> = kinds
            .iter()
            .map(|q| (q.name().to_string(), q.color()))
            .collect();
        panels::figure_of(
            ctx,
            &legend,
            &|area| ctx.fit_box(area),
            &titles,
            &|svg, area, j| panel(svg, area, kinds[j], None),
        )
    }
}

impl Figure for Measure {
    fn title(&self, label: &str, _surface: bool) -> String {
        let names: Vec<&str> = self.quantities().iter().map(|q| q.name()).collect();
        match (self.kind, &names[..]) {
            (Kind::Score, _) => format!("{label}: score"),
            (Kind::Derived, [name]) => format!("{label}: {name}"),
            (Kind::Derived, _) => format!("{label}: derived degrees"),
        }
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let kinds = self.quantities();
        let controls = self.measured_controls(ctx);
        let mctx = self.measured_ctx(ctx, &controls);
        let family = self.family;
        let mut entries: Vec<Entry> = kinds
            .iter()
            .map(|&q| {
                let label = match self.kind {
                    Kind::Score => format!("score {} ({family})", self.formula(q)),
                    Kind::Derived => format!("{} curve", q.name()),
                };
                Entry::line(q.color(), th.curve_w(), None, &label)
            })
            .collect();
        match (&kinds[..], self.affine()) {
            (_, false) => {}
            ([q], true) => {
                let c = q.color();
                entries.push(Entry::polygon(th, c, Marker::Circle, c, "control polygon"));
            }
            (_, true) => entries.push(Entry::line(
                crate::theme::CONSTRUCTION,
                th.polygon_w(),
                Some(th.dash()),
                "control polygons",
            )),
        }
        let mut notes = self.notes(&kinds);
        if self.kind == Kind::Score {
            // The curve's entry names the formula already.
            notes.remove(0);
        }
        let axis = self.axis(&kinds);
        let look = Look {
            axis: &axis,
            curtain: kinds.len() == 1,
            polygon_w: th.polygon_w(),
            marker: Quantity::marker,
            lift_controls: self.affine(),
        };
        lifted::figure(&mctx, &kinds, entries, notes, &look)
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let kinds = self.quantities();
        let controls = self.measured_controls(ctx);
        let mctx = self.measured_ctx(ctx, &controls);
        let legend = self.bar_legend(ctx, &kinds, coloured_legend);
        self.boxes(&mctx, &kinds, legend, &|svg, area, q, avoid| {
            coloured_panel(svg, &mctx, area, q, avoid);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        let kinds = self.quantities();
        let controls = self.measured_controls(ctx);
        let mctx = self.measured_ctx(ctx, &controls);
        let mesh = self.measured_mesh(ctx, mesh);
        let legend = self.bar_legend(ctx, &kinds, quantity_legend);
        self.boxes(&mctx, &kinds, legend, &|svg, area, q, avoid| {
            mesh_panel(svg, &mctx, &mesh, grid, area, q, avoid);
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The measures of blended lane slots, against the families' formulas by hand.
    #[test]
    fn measure_values_from_the_slots() {
        // Pythagorean: T and F in the truth and falsity slots.
        let s = measures(Family::Pythagorean, Kind::Score, &[[0.7, 0.0, 0.625]]);
        assert_eq!(s[0], 0.7 * 0.7 - 0.625 * 0.625);
        let h = measures(Family::Pythagorean, Kind::Derived, &[[0.6, 0.0, 0.0]]);
        assert!((h[0] - 0.8).abs() < 1e-15);
        // Intuitionistic: the indeterminacy slot holds the hesitation, not a channel.
        let s = measures(Family::Intuitionistic, Kind::Score, &[[0.5, 0.3, 0.2]]);
        assert_eq!(s[0], 0.5 - 0.2);
        // Bipolar: lane 1 holds the negative degrees negated.
        let s = measures(
            Family::BipolarNeutrosophic,
            Kind::Score,
            &[[0.9, 0.1, 0.0], [0.0, 0.1, 0.6]],
        );
        assert!((s[0] - (3.0 + 0.9 - 0.1 - 0.0 - 0.0 + 0.1 + 0.6) / 6.0).abs() < 1e-15);
        // Interval type-2: type-reduced and footprint in slots 0 and 1.
        let d = measures(
            Family::IntervalType2,
            Kind::Derived,
            &[[0.25, 0.0, 0.0], [0.75, 0.0, 0.0]],
        );
        assert_eq!(d, [0.5, 0.5, 0.0]);
    }

    #[test]
    fn measure_formulas_and_ranges() {
        assert_eq!(score_formula(Family::Pythagorean), "T^2\u{2212}F^2");
        assert_eq!(score_formula(Family::q_rung(4).unwrap()), "T^4\u{2212}F^4");
        assert_eq!(score_formula(Family::Fuzzy), "T");
        assert_eq!(score_formula(Family::Intuitionistic), "T\u{2212}F");
        assert_eq!(
            derived_formula(Family::Spherical, "hesitation"),
            "(1\u{2212}T^2\u{2212}I^2\u{2212}F^2)^(1/2)"
        );
        assert_eq!(
            derived_formula(Family::Intuitionistic, "hesitation"),
            "1\u{2212}T\u{2212}F"
        );
        assert!(score_is_signed(Family::Pythagorean));
        assert!(score_is_signed(Family::IntervalIntuitionistic));
        assert!(!score_is_signed(Family::IntervalType2));
        // Each signed score reaches -1 and 1 within its rule; the unsigned ones stay in [0, 1].
        assert_eq!(Family::Pythagorean.score(&[0.0, 1.0]), -1.0);
        assert_eq!(Family::IntervalType2.score(&[0.0, 0.0]), 0.0);
    }
}
