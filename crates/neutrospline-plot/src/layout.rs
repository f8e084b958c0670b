//! Figure layout: rectangles, text measuring and wrapping, title, caption and legend.

use neutrospline::DegreeKind;

use crate::drawing::Painter;
use crate::font::text_width;
use crate::style::{Anchor, Color, Style, TextStyle};
use crate::theme::{self, Marker, Theme};
use crate::ticks::ticks_inside;

/// An axis-aligned rectangle in pixels (y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rect {
    pub x: f64,
    pub y: f64,
    pub w: f64,
    pub h: f64,
}

impl Rect {
    pub(crate) fn new(x: f64, y: f64, w: f64, h: f64) -> Rect {
        Rect {
            x,
            y,
            w: w.max(1.0),
            h: h.max(1.0),
        }
    }

    pub(crate) fn right(&self) -> f64 {
        self.x + self.w
    }

    pub(crate) fn bottom(&self) -> f64 {
        self.y + self.h
    }

    pub(crate) fn centre(&self) -> (f64, f64) {
        (self.x + self.w / 2.0, self.y + self.h / 2.0)
    }

    pub(crate) fn contains(&self, p: (f64, f64)) -> bool {
        p.0 >= self.x && p.0 <= self.right() && p.1 >= self.y && p.1 <= self.bottom()
    }

    /// Area of the intersection with `other`.
    pub(crate) fn overlap(&self, other: &Rect) -> f64 {
        let w = self.right().min(other.right()) - self.x.max(other.x);
        let h = self.bottom().min(other.bottom()) - self.y.max(other.y);
        if w > 0.0 && h > 0.0 {
            w * h
        } else {
            0.0
        }
    }

    /// Area of this rectangle outside `outer`.
    pub(crate) fn outside(&self, outer: &Rect) -> f64 {
        self.w * self.h - self.overlap(outer)
    }

    /// Whether the segment `a`-`b` meets the rectangle.
    pub(crate) fn hits_segment(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        // Liang-Barsky clipping.
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let d = (b.0 - a.0, b.1 - a.1);
        for (p, q) in [
            (-d.0, a.0 - self.x),
            (d.0, self.right() - a.0),
            (-d.1, a.1 - self.y),
            (d.1, self.bottom() - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
                if t0 > t1 {
                    return false;
                }
            }
        }
        true
    }
}

/// Height of a text box for layout: cap height plus a little, in units of the font size.
pub(crate) const TEXT_BOX: f64 = 0.92;
/// Baseline below the centre of a text box, in units of the font size.
pub(crate) const BASELINE_FROM_CENTRE: f64 = 0.36;

/// Splits `text` into lines no wider than `max_w` (a single word wider than that stays whole).
pub(crate) fn wrap(text: &str, size: f64, max_w: f64, bold: bool) -> Vec<String> {
    let mut lines = Vec::new();
    for paragraph in text.split('\n') {
        let mut line = String::new();
        for word in paragraph.split_whitespace() {
            let candidate = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if !line.is_empty() && text_width(&candidate, size, bold) > max_w {
                lines.push(std::mem::take(&mut line));
                line = word.to_string();
            } else {
                line = candidate;
            }
        }
        if !line.is_empty() {
            lines.push(line);
        }
    }
    lines
}

/// Draws text centred on `c` (horizontally and on the cap height).
pub(crate) fn text_centred(svg: &mut Painter, c: (f64, f64), text: &str, style: &TextStyle) {
    let style = style.clone().anchor(Anchor::Middle);
    if style.rotate == 0.0 {
        svg.text(c.0, c.1 + BASELINE_FROM_CENTRE * style.size, text, &style);
    } else {
        // Rotated by -90 degrees: the baseline lies to the right of the centre.
        svg.text(c.0 + BASELINE_FROM_CENTRE * style.size, c.1, text, &style);
    }
}

/// How far from `anchor` along the unit direction `d` the centre of a `w` x `h` box must sit
/// so that the box just touches the anchor (the support function of the box).
pub(crate) fn support(d: (f64, f64), w: f64, h: f64) -> f64 {
    d.0.abs() * w / 2.0 + d.1.abs() * h / 2.0
}

/// The median distance in pixels from a point to its nearest neighbour (infinite for fewer
/// than two points): how crowded the control points are on screen.
pub(crate) fn median_spacing(at: &[(f64, f64)]) -> f64 {
    if at.len() < 2 {
        return f64::INFINITY;
    }
    let mut nearest: Vec<f64> = at
        .iter()
        .enumerate()
        .map(|(i, p)| {
            at.iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .map(|(_, q)| ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt())
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    nearest.sort_by(f64::total_cmp);
    nearest[nearest.len() / 2]
}

/// Draws a marker of the given shape.
pub(crate) fn marker(svg: &mut Painter, shape: Marker, c: (f64, f64), r: f64, style: &Style) {
    match shape {
        Marker::Circle => svg.circle(c, r, style),
        Marker::Square => {
            let a = r * 0.9;
            svg.rect(c.0 - a, c.1 - a, 2.0 * a, 2.0 * a, style)
        }
        Marker::Diamond => {
            let a = r * 1.25;
            svg.polygon(
                &[
                    (c.0, c.1 - a),
                    (c.0 + a, c.1),
                    (c.0, c.1 + a),
                    (c.0 - a, c.1),
                ],
                style,
            )
        }
    }
}

/// The look of a legend entry's sample.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Swatch {
    /// A line, optionally dashed, optionally with a marker at its middle.
    Line {
        color: Color,
        width: f64,
        dash: Option<(f64, f64)>,
        marker: Option<(Marker, Color)>,
    },
    /// A lane of the plane view: grey track, coloured band of half its width.
    Band { color: Color },
    /// A marker alone (a data point), of `shape` filled with `fill`.
    Marker { shape: Marker, fill: Color },
    /// A filled patch with an outline (a surface).
    Patch { color: Color },
    /// A dashed line across a patch (lines drawn over a heat map).
    LineOnPatch {
        patch: Color,
        line: Color,
        width: f64,
        dash: (f64, f64),
    },
}

/// A legend entry.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entry {
    pub swatch: Swatch,
    pub label: String,
}

impl Entry {
    /// A line sample, optionally dashed.
    pub(crate) fn line(color: Color, width: f64, dash: Option<(f64, f64)>, label: &str) -> Entry {
        Entry {
            swatch: Swatch::Line {
                color,
                width,
                dash,
                marker: None,
            },
            label: label.to_string(),
        }
    }

    /// A control polygon's sample: a dashed line with a marker of `shape` filled with `fill`.
    pub(crate) fn polygon(
        theme: &Theme,
        color: Color,
        shape: Marker,
        fill: Color,
        label: &str,
    ) -> Entry {
        Entry {
            swatch: Swatch::Line {
                color,
                width: theme.polygon_w(),
                dash: Some(theme.dash()),
                marker: Some((shape, fill)),
            },
            label: label.to_string(),
        }
    }

    /// A band sample per degree (truth, indeterminacy, falsity in their colours), labelled
    /// by `label`.
    pub(crate) fn bands(label: impl Fn(DegreeKind) -> String) -> Vec<Entry> {
        DegreeKind::ALL
            .iter()
            .map(|&kind| Entry {
                swatch: Swatch::Band {
                    color: theme::degree_color(kind),
                },
                label: label(kind),
            })
            .collect()
    }
}

/// A vertical colour bar for values in `range` (degrees: \[0, 1\]; a signed score:
/// \[-1, 1\]), the colour map spread over it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ColorBar {
    pub label: String,
    /// Length relative to the default (13 legend font sizes).
    pub length: f64,
    /// The values at the bottom and the top of the bar.
    pub range: (f64, f64),
}

/// The legend column: entries, notes, and an optional colour bar.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Legend {
    pub entries: Vec<Entry>,
    pub notes: Vec<String>,
    pub colorbar: Option<ColorBar>,
}

struct LegendMetrics {
    pad: f64,
    swatch_w: f64,
    row_h: f64,
    note_row: f64,
    bar_w: f64,
    bar_h: f64,
}

impl Legend {
    fn metrics(theme: &Theme) -> LegendMetrics {
        let fs = theme.legend();
        LegendMetrics {
            pad: 0.75 * fs,
            swatch_w: 2.4 * fs,
            row_h: 1.55 * fs,
            note_row: 1.3 * theme.note(),
            bar_w: 1.1 * fs,
            bar_h: 13.0 * fs,
        }
    }

    fn is_empty(&self) -> bool {
        self.entries.is_empty() && self.notes.is_empty() && self.colorbar.is_none()
    }

    /// Wraps the notes to the width of the entries (or a sensible minimum).
    fn wrapped_notes(&self, theme: &Theme) -> Vec<String> {
        let m = Self::metrics(theme);
        let entries_w = self
            .entries
            .iter()
            .map(|e| m.swatch_w + theme.gap() + text_width(&e.label, theme.legend(), false))
            .fold(10.0 * theme.legend(), f64::max);
        self.notes
            .iter()
            .flat_map(|n| wrap(n, theme.note(), entries_w, false))
            .collect()
    }

    /// Width and height of the legend box.
    pub(crate) fn size(&self, theme: &Theme) -> (f64, f64) {
        if self.is_empty() {
            return (0.0, 0.0);
        }
        let m = Self::metrics(theme);
        let mut w: f64 = 0.0;
        let mut h = m.pad;
        for e in &self.entries {
            w = w.max(m.swatch_w + theme.gap() + text_width(&e.label, theme.legend(), false));
            h += m.row_h;
        }
        let notes = self.wrapped_notes(theme);
        if !notes.is_empty() {
            h += 0.3 * m.row_h;
        }
        for n in &notes {
            w = w.max(text_width(n, theme.note(), false));
            h += m.note_row;
        }
        if let Some(bar) = &self.colorbar {
            let label_w = text_width(&bar.label, theme.legend(), true);
            let tick_w = if bar.range.0 < 0.0 {
                text_width("\u{2212}1.0", theme.tick(), false)
            } else {
                text_width("0.0", theme.tick(), false)
            };
            w = w
                .max(label_w)
                .max(m.bar_w + theme.tick_len() + theme.gap() + tick_w);
            h += if self.entries.is_empty() && notes.is_empty() {
                0.0
            } else {
                0.6 * m.row_h
            };
            h += 1.6 * theme.legend() + m.bar_h * bar.length + 0.6 * theme.tick();
        }
        (w + 2.0 * m.pad, h + m.pad)
    }

    /// The entries laid out in rows no wider than `max_w` (legend boxes under a narrow
    /// plot): per row, each entry's index and its left edge from the box's inner left edge.
    fn rows(&self, theme: &Theme, max_w: f64) -> Vec<Vec<(usize, f64)>> {
        // A grid: as many columns of the widest entry as fit, filled row by row.
        let m = Self::metrics(theme);
        let spacing = 1.2 * theme.legend();
        let widest = self
            .entries
            .iter()
            .map(|e| m.swatch_w + theme.gap() + text_width(&e.label, theme.legend(), false))
            .fold(0.0, f64::max);
        let columns = (((max_w + spacing) / (widest + spacing)).floor() as usize).max(1);
        let pitch = if columns > 1 {
            (max_w - widest) / (columns - 1) as f64
        } else {
            0.0
        };
        (0..self.entries.len())
            .collect::<Vec<_>>()
            .chunks(columns)
            .map(|row| {
                row.iter()
                    .enumerate()
                    .map(|(k, &i)| (i, k as f64 * pitch.min(widest + 2.0 * spacing)))
                    .collect()
            })
            .collect()
    }

    /// Whether the legend can be laid out in rows: entries and notes, no colour bar.
    pub(crate) fn fits_rows(&self) -> bool {
        self.colorbar.is_none() && !self.is_empty()
    }

    /// The height of the legend in rows `width` wide (entries in rows, notes wrapped to
    /// the width), box included.
    pub(crate) fn rows_height(&self, theme: &Theme, width: f64) -> f64 {
        let m = Self::metrics(theme);
        let inner = width - 2.0 * m.pad;
        let notes: Vec<String> = self
            .notes
            .iter()
            .flat_map(|n| wrap(n, theme.note(), inner, false))
            .collect();
        let mut h = m.pad + self.rows(theme, inner).len() as f64 * m.row_h;
        if !notes.is_empty() {
            h += 0.3 * m.row_h + notes.len() as f64 * m.note_row;
        }
        h + m.pad
    }

    /// Draws the legend in rows in a box `width` wide with its top-left corner at `(x, y)`.
    pub(crate) fn draw_rows(&self, svg: &mut Painter, theme: &Theme, x: f64, y: f64, width: f64) {
        let m = Self::metrics(theme);
        let h = self.rows_height(theme, width);
        svg.begin_group("legend");
        svg.rect(
            x,
            y,
            width,
            h,
            &Style::stroke(theme::PANE_EDGE, theme.grid_w())
                .with_fill(Color::WHITE)
                .square(),
        );
        let inner = width - 2.0 * m.pad;
        let mut cy = y + m.pad + m.row_h / 2.0;
        for row in self.rows(theme, inner) {
            for (i, dx) in row {
                draw_entry(svg, theme, &self.entries[i], x + m.pad + dx, cy);
            }
            cy += m.row_h;
        }
        let mut top = cy - m.row_h / 2.0 + 0.3 * m.row_h;
        for n in self
            .notes
            .iter()
            .flat_map(|n| wrap(n, theme.note(), inner, false))
        {
            svg.text(
                x + m.pad,
                top + 0.5 * m.note_row + BASELINE_FROM_CENTRE * theme.note(),
                &n,
                &TextStyle::new(theme.note(), theme::INK_SOFT),
            );
            top += m.note_row;
        }
        svg.end_group();
    }

    /// Draws the legend with its top-left corner at `(x, y)`.
    pub(crate) fn draw(&self, svg: &mut Painter, theme: &Theme, x: f64, y: f64) {
        if self.is_empty() {
            return;
        }
        let m = Self::metrics(theme);
        let (w, h) = self.size(theme);
        svg.begin_group("legend");
        svg.rect(
            x,
            y,
            w,
            h,
            &Style::stroke(theme::PANE_EDGE, theme.grid_w())
                .with_fill(Color::WHITE)
                .square(),
        );
        let fs = theme.legend();
        let mut cy = y + m.pad + m.row_h / 2.0;
        for e in &self.entries {
            draw_entry(svg, theme, e, x + m.pad, cy);
            cy += m.row_h;
        }
        let notes = self.wrapped_notes(theme);
        let mut top = cy - m.row_h / 2.0;
        if !notes.is_empty() {
            top += 0.3 * m.row_h;
        }
        for n in &notes {
            svg.text(
                x + m.pad,
                top + 0.5 * m.note_row + BASELINE_FROM_CENTRE * theme.note(),
                n,
                &TextStyle::new(theme.note(), theme::INK_SOFT),
            );
            top += m.note_row;
        }
        if let Some(bar) = &self.colorbar {
            if !(self.entries.is_empty() && notes.is_empty()) {
                top += 0.6 * m.row_h;
            }
            svg.text(
                x + m.pad,
                top + 0.5 * fs + BASELINE_FROM_CENTRE * fs,
                &bar.label,
                &TextStyle::new(fs, theme::INK)
                    .bold()
                    .with_class("colorbar-label"),
            );
            top += 1.6 * fs;
            let bx = x + m.pad;
            let bar_h = m.bar_h * bar.length;
            svg.vertical_gradient("colorbar", theme::colormap_stops());
            svg.gradient_rect("colorbar", bx, top, m.bar_w, bar_h);
            svg.rect(
                bx,
                top,
                m.bar_w,
                bar_h,
                &Style::stroke(theme::AXIS, theme.grid_w()).square(),
            );
            let target = ((bar_h / (1.7 * theme.tick())) as usize).clamp(1, 5);
            let (lo, hi) = bar.range;
            let ticks = ticks_inside(lo, hi, target);
            for (v, label) in ticks.values.iter().zip(ticks.labels()) {
                let ty = top + bar_h * (1.0 - (v - lo) / (hi - lo));
                let tx = bx + m.bar_w;
                svg.line(
                    (tx, ty),
                    (tx + theme.tick_len(), ty),
                    &Style::stroke(theme::AXIS, theme.grid_w()).square(),
                );
                svg.text(
                    tx + theme.tick_len() + theme.gap(),
                    ty + BASELINE_FROM_CENTRE * theme.tick(),
                    &label,
                    &TextStyle::new(theme.tick(), theme::INK),
                );
            }
        }
        svg.end_group();
    }
}

/// A legend entry: its swatch from `x` and its label after it, centred on `cy`.
fn draw_entry(svg: &mut Painter, theme: &Theme, entry: &Entry, x: f64, cy: f64) {
    let fs = theme.legend();
    let swatch_w = Legend::metrics(theme).swatch_w;
    draw_swatch(svg, theme, &entry.swatch, x, cy, swatch_w);
    svg.text(
        x + swatch_w + theme.gap(),
        cy + BASELINE_FROM_CENTRE * fs,
        &entry.label,
        &TextStyle::new(fs, theme::INK).with_class("legend-label"),
    );
}

fn draw_swatch(svg: &mut Painter, theme: &Theme, swatch: &Swatch, x: f64, cy: f64, w: f64) {
    match swatch {
        Swatch::Line {
            color,
            width,
            dash,
            marker: mk,
        } => {
            let mut style = Style::stroke(*color, *width);
            if let Some((on, off)) = dash {
                style = style.with_dash(*on, *off);
            }
            svg.line((x, cy), (x + w, cy), &style);
            if let Some((shape, fill)) = mk {
                marker(
                    svg,
                    *shape,
                    (x + w / 2.0, cy),
                    theme.marker_r(),
                    &Style::stroke(theme::CRISP, theme.s * 1.5).with_fill(*fill),
                );
            }
        }
        Swatch::Patch { color } => {
            let h = 0.8 * theme.legend();
            svg.rect(
                x,
                cy - h / 2.0,
                w,
                h,
                &Style::stroke(theme::AXIS, theme.grid_w())
                    .with_fill(*color)
                    .square(),
            );
        }
        Swatch::LineOnPatch {
            patch,
            line,
            width,
            dash,
        } => {
            let h = 0.8 * theme.legend();
            svg.rect(x, cy - h / 2.0, w, h, &Style::fill(*patch).square());
            svg.line(
                (x, cy),
                (x + w, cy),
                &Style::stroke(*line, *width).with_dash(dash.0, dash.1),
            );
        }
        Swatch::Marker { shape, fill } => {
            marker(
                svg,
                *shape,
                (x + w / 2.0, cy),
                0.7 * theme.marker_r(),
                &Style::stroke(theme::CRISP, theme.s * 1.5).with_fill(*fill),
            );
        }
        Swatch::Band { color } => {
            let h = 0.7 * theme.legend();
            svg.rect(x, cy - h / 2.0, w, h, &Style::fill(theme::TRACK).square());
            svg.rect(x, cy - h / 4.0, w, h / 2.0, &Style::fill(*color).square());
        }
    }
}

/// Where the legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LegendPlace {
    /// A column right of the plot.
    Column,
    /// The top-right corner of the plot area, which the drawing must avoid
    /// ([`Frame::legend_rect`]).
    Corner,
    /// Placed by the view with [`Frame::place_legend`].
    Manual,
}

/// The parts of a figure around its plot: title at the top, caption at the bottom, legend on
/// the right; `plot` is what is left.
pub(crate) struct Frame {
    pub width: f64,
    pub height: f64,
    pub plot: Rect,
    title: Vec<String>,
    caption: Vec<String>,
    legend: Legend,
    legend_pos: (f64, f64),
    /// The width of the legend when it is laid out in rows under the plot (a column would
    /// take more than [`Frame::MAX_COLUMN_SHARE`] of the figure's width).
    rows_width: Option<f64>,
}

impl Frame {
    /// The largest share of the figure's width a legend column or corner box may take;
    /// past it the legend goes under the plot, in rows.
    pub(crate) const MAX_COLUMN_SHARE: f64 = 0.3;

    pub(crate) fn new(
        width: u32,
        height: u32,
        theme: &Theme,
        title: &str,
        caption: &str,
        legend: Legend,
        place: LegendPlace,
    ) -> Frame {
        let (w, h) = (f64::from(width), f64::from(height));
        let m = theme.margin();
        let inner_w = w - 2.0 * m;
        let title_lines = wrap(title, theme.title(), inner_w, true);
        let caption_lines = wrap(caption, theme.caption(), inner_w, false);
        let mut top = m;
        if !title_lines.is_empty() {
            top += title_lines.len() as f64 * 1.25 * theme.title() + 0.4 * theme.title();
        }
        let mut bottom = h - m;
        if !caption_lines.is_empty() {
            bottom -= caption_lines.len() as f64 * 1.35 * theme.caption() + 0.5 * theme.caption();
        }
        let (lw, _) = legend.size(theme);
        if place != LegendPlace::Manual && lw > Frame::MAX_COLUMN_SHARE * w && legend.fits_rows() {
            let lh = legend.rows_height(theme, inner_w);
            let legend_top = bottom - lh;
            return Frame {
                width: w,
                height: h,
                plot: Rect::new(m, top, inner_w, legend_top - m - top),
                title: title_lines,
                caption: caption_lines,
                legend_pos: (m, legend_top),
                rows_width: Some(inner_w),
                legend,
            };
        }
        let right = if lw > 0.0 && place == LegendPlace::Column {
            w - m - lw - m
        } else {
            w - m
        };
        let plot = Rect::new(m, top, right - m, bottom - top);
        Frame {
            width: w,
            height: h,
            plot,
            title: title_lines,
            caption: caption_lines,
            legend_pos: (w - m - lw, top),
            rows_width: None,
            legend,
        }
    }

    /// The rectangle the legend occupies.
    pub(crate) fn legend_rect(&self, theme: &Theme) -> Option<Rect> {
        let (w, h) = match self.rows_width {
            Some(w) => (w, self.legend.rows_height(theme, w)),
            None => self.legend.size(theme),
        };
        (w > 0.0).then(|| Rect::new(self.legend_pos.0, self.legend_pos.1, w, h))
    }

    /// Moves the legend's top-left corner.
    pub(crate) fn place_legend(&mut self, x: f64, y: f64) {
        self.legend_pos = (x, y);
    }

    /// Draws the title, caption and legend.
    pub(crate) fn draw(&self, svg: &mut Painter, theme: &Theme) {
        let m = theme.margin();
        if !self.title.is_empty() {
            svg.begin_group("title");
            let mut y = m + theme.title() * 0.85;
            for line in &self.title {
                svg.text(
                    self.width / 2.0,
                    y,
                    line,
                    &TextStyle::new(theme.title(), theme::INK)
                        .bold()
                        .anchor(Anchor::Middle),
                );
                y += 1.25 * theme.title();
            }
            svg.end_group();
        }
        if !self.caption.is_empty() {
            svg.begin_group("caption");
            let lh = 1.35 * theme.caption();
            let mut y = self.height - m - (self.caption.len() as f64 - 1.0) * lh - 0.25 * lh;
            for line in &self.caption {
                svg.text(
                    m,
                    y,
                    line,
                    &TextStyle::new(theme.caption(), theme::INK_SOFT),
                );
                y += lh;
            }
            svg.end_group();
        }
        let (x, y) = self.legend_pos;
        match self.rows_width {
            Some(width) => self.legend.draw_rows(svg, theme, x, y, width),
            None => self.legend.draw(svg, theme, x, y),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_splits_on_width() {
        let lines = wrap(
            "aaa bbb ccc",
            10.0,
            text_width("aaa bbb", 10.0, false) + 0.1,
            false,
        );
        assert_eq!(lines, vec!["aaa bbb", "ccc"]);
        assert!(wrap("", 10.0, 100.0, false).is_empty());
        assert_eq!(wrap("verylongword", 10.0, 1.0, false), vec!["verylongword"]);
    }

    #[test]
    fn rect_segment_hits() {
        let r = Rect::new(0.0, 0.0, 10.0, 10.0);
        assert!(r.hits_segment((-5.0, 5.0), (15.0, 5.0)));
        assert!(r.hits_segment((2.0, 2.0), (3.0, 3.0)));
        assert!(!r.hits_segment((-5.0, -5.0), (-1.0, 20.0)));
        assert!(!r.hits_segment((11.0, 0.0), (20.0, 10.0)));
    }

    #[test]
    fn support_of_box() {
        assert_eq!(support((1.0, 0.0), 10.0, 4.0), 5.0);
        assert_eq!(support((0.0, -1.0), 10.0, 4.0), 2.0);
    }
}
