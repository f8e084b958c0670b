//! Sizes and colours shared by every view, so all figures look alike.

use neutrospline::DegreeKind;

use crate::options::PlotOptions;
use crate::style::{Color, Style};

/// Text colour.
pub(crate) const INK: Color = Color(0x1a, 0x1a, 0x1a);
/// Secondary text (captions, notes).
pub(crate) const INK_SOFT: Color = Color(0x4d, 0x4d, 0x4d);
/// Axis lines and tick marks.
pub(crate) const AXIS: Color = Color(0x33, 0x33, 0x33);
/// Grid lines.
pub(crate) const GRID: Color = Color(0xd4, 0xd7, 0xdb);
/// Fill of the back panes of a 3-D box.
pub(crate) const PANE: Color = Color(0xf2, 0xf3, 0xf5);
/// Outline of the back panes.
pub(crate) const PANE_EDGE: Color = Color(0xa8, 0xad, 0xb3);
/// The crisp curve (the model's positions).
pub(crate) const CRISP: Color = Color(0x22, 0x22, 0x22);
/// The crisp control polygon and other neutral construction lines.
pub(crate) const CONSTRUCTION: Color = Color(0x6e, 0x6e, 0x6e);
/// Shadows and drop lines.
pub(crate) const SHADOW: Color = Color(0x9a, 0x9a, 0x9a);
/// A surface drawn without a degree (the `controls` view of a surface).
pub(crate) const SURFACE: Color = Color(0xcf, 0xd5, 0xdc);
/// Knot lines over a heat map.
pub(crate) const KNOT: Color = Color(0xff, 0xff, 0xff);
/// Residual whiskers from data points to the curve (Paul Tol's vibrant red: apart from the
/// viridis fills of the points and from the grey curve).
pub(crate) const RESIDUAL: Color = Color(0xcc, 0x33, 0x11);
/// The lifted score curve (Paul Tol's bright green: apart from the three degree colours).
pub(crate) const SCORE: Color = Color(0x22, 0x88, 0x33);
/// The second derived degree of a family (the footprint of interval type-2, the upper
/// hesitation of interval intuitionistic), next to the first in [`SCORE`]'s green.
pub(crate) const DERIVED_SECOND: Color = Color(0x88, 0x33, 0x99);
/// The centroid curve of the band view (orange: apart from the blue bands and the grey curve).
pub(crate) const CENTROID: Color = Color(0xdd, 0x77, 0x00);
/// Background of the degree lanes of the plane view.
pub(crate) const TRACK: Color = Color(0xe6, 0xe8, 0xeb);

/// The colour of a degree (Paul Tol's high-contrast scheme: distinct for colour-blind readers
/// and in greyscale).
pub(crate) fn degree_color(kind: DegreeKind) -> Color {
    match kind {
        DegreeKind::Truth => Color(0x00, 0x44, 0x88),
        DegreeKind::Indeterminacy => Color(0xc8, 0x8a, 0x12),
        DegreeKind::Falsity => Color(0xbb, 0x55, 0x66),
    }
}

/// The marker shape of a degree (so the three stay apart without colour).
pub(crate) fn degree_marker(kind: DegreeKind) -> Marker {
    match kind {
        DegreeKind::Truth => Marker::Circle,
        DegreeKind::Indeterminacy => Marker::Square,
        DegreeKind::Falsity => Marker::Diamond,
    }
}

/// One-letter symbol of a degree.
pub(crate) fn degree_letter(kind: DegreeKind) -> &'static str {
    match kind {
        DegreeKind::Truth => "T",
        DegreeKind::Indeterminacy => "I",
        DegreeKind::Falsity => "F",
    }
}

/// Marker shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Marker {
    Circle,
    Square,
    Diamond,
}

/// The stops of the core's colour map ([`neutrospline::color::VIRIDIS`]), as colours.
const VIRIDIS: [Color; 11] = {
    let mut out = [Color(0, 0, 0); 11];
    let mut i = 0;
    while i < out.len() {
        let [r, g, b] = neutrospline::color::VIRIDIS[i];
        out[i] = Color(r, g, b);
        i += 1;
    }
    out
};

/// The colour of degree value `v` in \[0, 1\]: the core's [`neutrospline::color::viridis`],
/// the same colours as the exported meshes (out-of-range values are clamped for display, NaN
/// shows as 0).
pub(crate) fn colormap(v: f64) -> Color {
    let [r, g, b] = neutrospline::color::viridis(v);
    Color(r, g, b)
}

/// The colour map's stops, for gradients.
pub(crate) fn colormap_stops() -> &'static [Color] {
    &VIRIDIS
}

/// A degree for display: clamped to \[0, 1\], NaN as 0.
pub(crate) fn unit(v: f64) -> f64 {
    if v.is_finite() {
        v.clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// The style of a control point's marker: `fill` in a dark outline.
pub(crate) fn marker_style(theme: &Theme, fill: Color) -> Style {
    Style::stroke(CRISP, theme.s * 1.8).with_fill(fill)
}

/// Sizes of one figure: every length is a size at 1600 x 1200 times the figure's scale `s`,
/// and every text size one times the text scale `t`: `s` too, except on paper, where text
/// does not shrink below [`PlotOptions::PRINT_TICK_POINTS`] for the tick labels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Theme {
    pub s: f64,
    pub t: f64,
}

/// The tick labels' size at scale 1: the reference of the print text scale.
const TICK: f64 = 36.0;

impl Theme {
    pub(crate) fn new(width: u32, height: u32) -> Theme {
        let s = (f64::from(width) / 1600.0).min(f64::from(height) / 1200.0);
        Theme { s, t: s }
    }

    /// The theme of a figure with these options: on paper (a print size, whose canvas unit is
    /// the point) the text scale is at least the one that sets the tick labels at
    /// [`PlotOptions::PRINT_TICK_POINTS`].
    pub(crate) fn of(options: &PlotOptions) -> Theme {
        let theme = Theme::new(options.width(), options.height());
        match options.print_size() {
            Some(_) => Theme {
                t: theme.s.max(PlotOptions::PRINT_TICK_POINTS / TICK),
                ..theme
            },
            None => theme,
        }
    }

    pub(crate) fn title(&self) -> f64 {
        54.0 * self.t
    }
    pub(crate) fn subtitle(&self) -> f64 {
        40.0 * self.t
    }
    pub(crate) fn tick(&self) -> f64 {
        TICK * self.t
    }
    pub(crate) fn label(&self) -> f64 {
        42.0 * self.t
    }
    pub(crate) fn legend(&self) -> f64 {
        35.0 * self.t
    }
    pub(crate) fn note(&self) -> f64 {
        31.0 * self.t
    }
    pub(crate) fn caption(&self) -> f64 {
        31.0 * self.t
    }
    pub(crate) fn name(&self) -> f64 {
        34.0 * self.t
    }
    pub(crate) fn callout(&self) -> f64 {
        29.0 * self.t
    }
    pub(crate) fn margin(&self) -> f64 {
        32.0 * self.s
    }
    pub(crate) fn gap(&self) -> f64 {
        10.0 * self.s
    }
    pub(crate) fn tick_len(&self) -> f64 {
        11.0 * self.s
    }
    pub(crate) fn curve_w(&self) -> f64 {
        6.0 * self.s
    }
    pub(crate) fn crisp_w(&self) -> f64 {
        4.5 * self.s
    }
    pub(crate) fn polygon_w(&self) -> f64 {
        3.0 * self.s
    }
    pub(crate) fn thin_w(&self) -> f64 {
        2.0 * self.s
    }
    pub(crate) fn axis_w(&self) -> f64 {
        2.2 * self.s
    }
    pub(crate) fn grid_w(&self) -> f64 {
        1.6 * self.s
    }
    pub(crate) fn marker_r(&self) -> f64 {
        10.0 * self.s
    }
    pub(crate) fn dash(&self) -> (f64, f64) {
        (14.0 * self.s, 9.0 * self.s)
    }
    pub(crate) fn dot(&self) -> (f64, f64) {
        (2.0 * self.s, 7.0 * self.s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colormap_ends_and_nan() {
        assert_eq!(colormap(0.0), VIRIDIS[0]);
        assert_eq!(colormap(1.0), VIRIDIS[10]);
        assert_eq!(colormap(f64::NAN), VIRIDIS[0]);
        assert_eq!(colormap(0.5), VIRIDIS[5]);
    }

    #[test]
    fn theme_scales_with_smaller_ratio() {
        assert_eq!(Theme::new(1600, 1200).s, 1.0);
        assert_eq!(Theme::new(800, 1200).s, 0.5);
        assert_eq!(Theme::new(3200, 1200).s, 1.0);
    }
}
