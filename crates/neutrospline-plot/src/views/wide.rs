//! The degree views of the interval-valued and bipolar families (docs/model.md, "Lanes"):
//! each degree carries two values, held by the model's two lanes (same geometry; the second
//! lane holds the upper degrees, or the negative degrees negated).
//!
//! - `truth`, `indeterminacy`, `falsity` of a 2-D curve: the two lifted curves of the degree.
//!   Interval-valued: the lower curve (dashed) and the upper curve (solid) with a translucent
//!   ruled strip between them, legend `truth_lower` / `truth_upper` (for interval type-2, the
//!   lower and upper membership, held in the truth slots, and the strip is the footprint of
//!   uncertainty). Bipolar: the positive degree above the crisp plane and the negative degree
//!   below it (z = the negative degree, in \[-1, 0\]), each with its curtain to the plane.
//! - `all` of a 2-D curve: every degree the family carries, each pair in its colour.
//! - `truth`, `indeterminacy`, `falsity` of a 3-D curve or a surface: two panels side by side
//!   (or stacked), the first lane and the second, each coloured by its value of the degree
//!   on the shared colour bar \[0, 1\]; a bipolar negative degree's panel is coloured by its
//!   magnitude. (A 3-D curve or surface has no axis left for the degree, so the pair cannot
//!   share one box.) Their `all` view is refused ([`PlotModel::check_view`]).
//!
//! [`PlotModel::check_view`]: crate::PlotModel::check_view

use neutrospline::{DegreeKind, Family};

use crate::ctx::Ctx;
use crate::curve3d::{coloured_legend, coloured_panel};
use crate::drawing::Drawing;
use crate::layout::{Entry, Swatch};
use crate::lifted::{self, WideLook};
use crate::mesh::{mesh_panel, quantity_legend};
use crate::model::Mesh;
use crate::panels;
use crate::quantity::Quantity;
use crate::style::Color;
use crate::theme::{self, Marker};

use super::figure::Figure;

/// A degree view (`Some(kind)`) or the `all` view (`None`) of a wide family.
pub(crate) struct Wide {
    pub family: Family,
    pub kind: Option<DegreeKind>,
}

/// The degrees a wide family carries: those whose slot its first lane fills.
pub(crate) fn carried(family: Family) -> Vec<DegreeKind> {
    let lane = family.lanes()[0];
    DegreeKind::ALL
        .into_iter()
        .filter(|k| lane.slots[k.index()].is_some())
        .collect()
}

/// What the two lanes of degree `kind` are called: the channel names (`truth_lower`,
/// `truth_upper`; `truth`, `negative_truth`), or for interval type-2 the lower and upper
/// membership.
pub(crate) fn lane_names(family: Family, kind: DegreeKind) -> [String; 2] {
    if family == Family::IntervalType2 {
        return ["lower membership".into(), "upper membership".into()];
    }
    let channels = family.channels();
    family.lanes()[..2]
        .iter()
        .map(|lane| {
            lane.slots[kind.index()].map_or_else(|| kind.name().to_string(), |c| channels[c].into())
        })
        .collect::<Vec<_>>()
        .try_into()
        .unwrap_or_else(|_| [kind.name().into(), kind.name().into()])
}

impl Wide {
    fn bipolar(&self) -> bool {
        self.family == Family::BipolarNeutrosophic
    }

    /// The degree of a single-degree view; for `all`, the first the family carries.
    fn degree(&self) -> DegreeKind {
        self.kind.unwrap_or(DegreeKind::Truth)
    }

    /// The name of the degree's axis: `membership` for interval type-2 (in the `all` view
    /// too, whose one degree is the membership), else the degree, or `degree` for `all`.
    fn axis(&self) -> String {
        match self.kind {
            _ if self.family == Family::IntervalType2 => "membership".to_string(),
            None => "degree".to_string(),
            Some(kind) => kind.name().to_string(),
        }
    }

    /// Two panels (3-D curve, surface) of the degree, one per lane, drawn by `panel` from the
    /// lane's context and index.
    fn panels(
        &self,
        ctx: &Ctx,
        legend: crate::layout::Legend,
        panel: &dyn Fn(&mut crate::drawing::Painter, &Ctx, crate::layout::Rect, usize),
    ) -> Drawing {
        let kind = self.degree();
        let c = theme::degree_color(kind);
        let [first, second] = lane_names(self.family, kind);
        let second = if self.bipolar() {
            format!("|{second}|")
        } else {
            second
        };
        let titles: [(String, Color); 2] = [(first, c), (second, c)];
        let lane = ctx.second_lane();
        let lanes: [&Ctx; 2] = [ctx, lane.as_ref().unwrap_or(ctx)];
        panels::figure_of(
            ctx,
            &legend,
            &|area| ctx.fit_box(area),
            &titles,
            &|svg, area, j| {
                panel(svg, lanes[j], area, j);
            },
        )
    }

    fn panel_notes(&self) -> Vec<String> {
        if self.bipolar() {
            vec!["Negative degree coloured by its magnitude.".to_string()]
        } else {
            Vec::new()
        }
    }
}

impl Figure for Wide {
    fn title(&self, label: &str, _surface: bool) -> String {
        match (self.kind, self.family) {
            (_, Family::IntervalType2) => format!("{label}: lower and upper membership"),
            (None, Family::BipolarNeutrosophic) => {
                format!("{label}: positive and negative degrees")
            }
            (None, _) => format!("{label}: lower and upper degrees"),
            (Some(kind), family) => {
                let [a, b] = lane_names(family, kind);
                format!("{label}: {a} and {b}")
            }
        }
    }

    fn curve_2d(&self, ctx: &Ctx) -> Drawing {
        let th = &ctx.theme;
        let kinds: Vec<DegreeKind> = match self.kind {
            Some(kind) => vec![kind],
            None => carried(self.family),
        };
        let long_dash = Some((1.8 * th.dash().0, 1.2 * th.dash().1));
        // The `all` view's keys to the two lanes.
        let (solid, dashed) = match self.family {
            Family::BipolarNeutrosophic => ("positive, above 0", "negative_*, below 0"),
            Family::IntervalType2 => ("upper membership", "lower membership"),
            _ => ("upper (*_upper)", "lower (*_lower)"),
        };
        let mut entries = Vec::new();
        if let Some(kind) = self.kind {
            let c = theme::degree_color(kind);
            let [first, second] = lane_names(self.family, kind);
            let (solid_name, dashed_name) = if self.bipolar() {
                (format!("{first} (above 0)"), format!("{second} (below 0)"))
            } else {
                (second, first)
            };
            entries.push(Entry::line(c, th.curve_w(), None, &solid_name));
            entries.push(Entry::line(c, th.curve_w(), long_dash, &dashed_name));
            if !self.bipolar() {
                let band = if self.family == Family::IntervalType2 {
                    "footprint of uncertainty".to_string()
                } else {
                    format!("{} interval", kind.name())
                };
                entries.push(Entry {
                    swatch: Swatch::Patch {
                        color: c.mix(Color::WHITE, 0.7),
                    },
                    label: band,
                });
            }
            entries.push(Entry::polygon(th, c, Marker::Circle, c, "control polygons"));
        } else {
            for &kind in &kinds {
                let c = theme::degree_color(kind);
                let label = if self.family == Family::IntervalType2 {
                    "membership"
                } else {
                    kind.name()
                };
                entries.push(Entry {
                    swatch: Swatch::Line {
                        color: c,
                        width: th.curve_w(),
                        dash: None,
                        marker: Some((theme::degree_marker(kind), c)),
                    },
                    label: label.to_string(),
                });
            }
            entries.push(Entry::line(theme::INK_SOFT, th.curve_w(), None, solid));
            entries.push(Entry::line(
                theme::INK_SOFT,
                th.curve_w(),
                long_dash,
                dashed,
            ));
            entries.push(Entry::line(
                theme::CONSTRUCTION,
                th.polygon_w(),
                Some(th.dash()),
                "control polygons",
            ));
        }
        let look = WideLook {
            axis: self.axis(),
            bipolar: self.bipolar(),
            single: self.kind.is_some(),
            marker: if self.kind.is_some() {
                |_| Marker::Circle
            } else {
                Quantity::marker
            },
        };
        let quantities: Vec<Quantity> = kinds.into_iter().map(Quantity::from).collect();
        let (curve, controls) = match &ctx.wide {
            Some(wide) => (&wide.curve[..], wide.controls),
            None => (&ctx.curve[..], ctx.controls),
        };
        lifted::wide_figure(ctx, (curve, controls), &quantities, entries, &look)
    }

    fn curve_3d(&self, ctx: &Ctx) -> Drawing {
        let q = Quantity::from(self.degree());
        let mut legend = coloured_legend(&ctx.theme, &self.axis(), q.noun(), self.panel_notes());
        legend.notes.truncate(2);
        self.panels(ctx, legend, &|svg, lane, area, _| {
            coloured_panel(svg, lane, area, q, None);
        })
    }

    fn surface(&self, ctx: &Ctx, mesh: &Mesh, grid: (usize, usize)) -> Drawing {
        let q = Quantity::from(self.degree());
        let legend = quantity_legend(&ctx.theme, &self.axis(), q.noun(), self.panel_notes());
        let second = ctx
            .wide
            .as_ref()
            .and_then(|w| w.mesh.as_ref())
            .unwrap_or(mesh);
        self.panels(ctx, legend, &|svg, lane, area, j| {
            let m = if j == 0 { mesh } else { second };
            mesh_panel(svg, lane, m, grid, area, q, None);
        })
    }
}
