//! The layout of the three-panel `all` figures (one panel per degree) with a shared legend.
//!
//! Three arrangements compete: a 2 x 2 grid with the legend in the fourth cell, a row of
//! three with the legend in a column on the right, and a column of three with the legend on
//! the right. Each panel must stay inside its cell and the legend inside its own place, so
//! nothing can overlap; the colour bar is shortened until the legend fits. The arrangement
//! whose smallest panel is drawn at the largest scale wins (ties go to the grid). Each panel
//! title sits right above its drawing.

use neutrospline::DegreeKind;

use crate::ctx::Ctx;
use crate::drawing::{Drawing, Painter};
use crate::layout::{text_centred, Frame, Legend, LegendPlace, Rect};
use crate::style::{Color, TextStyle};
use crate::theme::{self, Theme};

/// Shortest colour bar, relative to the default length, before an arrangement is rejected.
const MIN_BAR: f64 = 0.22;

/// Where the three panels and the legend of an `all` figure go.
struct Panels {
    /// Title, caption and the placed legend.
    pub frame: Frame,
    /// One cell per panel (truth, indeterminacy, falsity; or a wide family's two lanes),
    /// panel title included.
    pub cells: Vec<Rect>,
    /// The top of each panel's drawing (pixels), once fitted: its title goes right above.
    tops: Vec<f64>,
}

impl Panels {
    /// Height of a panel title row.
    fn head(theme: &Theme) -> f64 {
        1.3 * theme.subtitle()
    }

    /// The drawing area of panel `j`: its cell below the panel title.
    fn area(&self, j: usize, theme: &Theme) -> Rect {
        area_of(&self.cells[j], theme)
    }

    /// The centre of panel `j`'s title: right above its drawing, inside its cell.
    fn title_centre(&self, j: usize, theme: &Theme) -> (f64, f64) {
        let c = &self.cells[j];
        let highest = c.y + 0.5 * theme.subtitle();
        (
            c.x + c.w / 2.0,
            (self.tops[j] - 0.8 * theme.subtitle()).max(highest),
        )
    }
}

fn area_of(cell: &Rect, theme: &Theme) -> Rect {
    let head = Panels::head(theme);
    Rect::new(cell.x, cell.y + head, cell.w, cell.h - head)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Arrangement {
    Grid,
    Row,
    Column,
}

/// Sets the colour bar so that the legend is at most `avail` tall; returns whether it fits
/// with a bar of at least [`MIN_BAR`].
fn fit_bar(legend: &mut Legend, theme: &Theme, avail: f64) -> bool {
    let Some(bar) = legend.colorbar.as_mut() else {
        return legend.size(theme).1 <= avail;
    };
    let wanted = bar.length;
    bar.length = 0.0;
    let h0 = legend.size(theme).1;
    if let Some(bar) = legend.colorbar.as_mut() {
        bar.length = 1.0;
    }
    let per = legend.size(theme).1 - h0;
    let length = if per > 0.0 {
        ((avail - h0) / per).min(wanted)
    } else {
        wanted
    };
    if let Some(bar) = legend.colorbar.as_mut() {
        bar.length = length.max(MIN_BAR);
    }
    length >= MIN_BAR
}

/// Lays out one arrangement: the frame, the cells, and whether the legend fits.
fn arrange(
    arrangement: Arrangement,
    count: usize,
    theme: &Theme,
    legend: &Legend,
    frame: &dyn Fn(Legend, LegendPlace) -> Frame,
) -> (Panels, bool) {
    let gap = theme.gap();
    match arrangement {
        Arrangement::Grid => {
            let plot = frame(legend.clone(), LegendPlace::Manual).plot;
            let (cw, ch) = (plot.w / 2.0, plot.h / 2.0);
            let cell = |j: usize| {
                Rect::new(
                    plot.x + cw * (j % 2) as f64,
                    plot.y + ch * (j / 2) as f64,
                    cw,
                    ch,
                )
            };
            let mut legend = legend.clone();
            let mut fits = fit_bar(&mut legend, theme, ch - 2.0 * gap);
            let (lw, lh) = legend.size(theme);
            fits &= lw <= cw - 2.0 * gap;
            let mut f = frame(legend, LegendPlace::Manual);
            let last = cell(3);
            // Centred in the fourth cell, but never off the canvas.
            let x = (last.x + (cw - lw) / 2.0).clamp(0.0, (f.width - lw).max(0.0));
            let y = (last.y + (ch - lh) / 2.0).clamp(0.0, (f.height - lh).max(0.0));
            f.place_legend(x, y);
            (
                Panels {
                    frame: f,
                    cells: (0..count).map(cell).collect(),
                    tops: vec![0.0; count],
                },
                fits,
            )
        }
        Arrangement::Row | Arrangement::Column => {
            let probe = frame(legend.clone(), LegendPlace::Column).plot;
            let mut legend = legend.clone();
            let fits = fit_bar(&mut legend, theme, probe.h);
            let f = frame(legend, LegendPlace::Column);
            let plot = f.plot;
            let n = count as f64;
            let cells = (0..count)
                .map(|j| {
                    let j = j as f64;
                    if arrangement == Arrangement::Row {
                        Rect::new(plot.x + plot.w / n * j, plot.y, plot.w / n, plot.h)
                    } else {
                        Rect::new(plot.x, plot.y + plot.h / n * j, plot.w, plot.h / n)
                    }
                })
                .collect();
            (
                Panels {
                    frame: f,
                    cells,
                    tops: vec![0.0; count],
                },
                fits,
            )
        }
    }
}

/// Chooses the arrangement whose smallest panel is largest: `fit` gives the scale at which a
/// panel fills a drawing area and the top of what it then draws (pixels); `frame` builds the
/// figure's frame for a legend.
fn choose(
    count: usize,
    theme: &Theme,
    legend: &Legend,
    frame: &dyn Fn(Legend, LegendPlace) -> Frame,
    fit: &dyn Fn(Rect) -> (f64, f64),
) -> Panels {
    let mut best: Option<(bool, f64, Panels)> = None;
    // The grid (the legend in the fourth cell) suits three panels only.
    let arrangements: &[Arrangement] = if count == 3 {
        &[Arrangement::Grid, Arrangement::Row, Arrangement::Column]
    } else {
        &[Arrangement::Row, Arrangement::Column]
    };
    for &arrangement in arrangements {
        let (mut panels, fits) = arrange(arrangement, count, theme, legend, frame);
        let fitted: Vec<(f64, f64)> = panels
            .cells
            .iter()
            .map(|c| fit(area_of(c, theme)))
            .collect();
        let score = fitted.iter().map(|f| f.0).fold(f64::INFINITY, f64::min);
        panels.tops = fitted.iter().map(|f| f.1).collect();
        let better = match &best {
            None => true,
            // A fitting legend first, then the larger panels (by more than 2 %).
            Some((bf, bs, _)) => (fits && !bf) || (fits == *bf && score > bs * 1.02),
        };
        if better {
            best = Some((fits, score, panels));
        }
    }
    match best {
        Some((_, _, panels)) => panels,
        None => arrange(arrangements[0], count, theme, legend, frame).0,
    }
}

/// A figure of three panels, one per degree (truth, indeterminacy, falsity), each under its
/// title, arranged by [`choose`] with the shared `legend`: `fit` gives the scale at which a
/// panel fills an area and the top of its drawing, `panel` draws the panel of a degree into
/// an area.
pub(crate) fn figure(
    ctx: &Ctx,
    legend: &Legend,
    fit: &dyn Fn(Rect) -> (f64, f64),
    panel: &dyn Fn(&mut Painter, Rect, DegreeKind),
) -> Drawing {
    let titles = DegreeKind::ALL.map(|kind| (kind.name().to_string(), theme::degree_color(kind)));
    figure_of(ctx, legend, fit, &titles, &|svg, area, j| {
        panel(svg, area, DegreeKind::ALL[j]);
    })
}

/// A figure of one panel per entry of `titles` (2 or 3; each panel's title text and colour),
/// arranged by [`choose`] with the shared `legend`: `fit` as in [`figure`], `panel` draws
/// panel `j` into an area.
pub(crate) fn figure_of(
    ctx: &Ctx,
    legend: &Legend,
    fit: &dyn Fn(Rect) -> (f64, f64),
    titles: &[(String, Color)],
    panel: &dyn Fn(&mut Painter, Rect, usize),
) -> Drawing {
    let th = &ctx.theme;
    let layout = choose(
        titles.len(),
        th,
        legend,
        &|legend, place| ctx.frame(legend, place),
        fit,
    );
    let mut svg = ctx.svg();
    for (j, (title, color)) in titles.iter().enumerate() {
        panel_title(&mut svg, th, layout.title_centre(j, th), title, *color);
        panel(&mut svg, layout.area(j, th), j);
    }
    layout.frame.draw(&mut svg, th);
    svg.finish()
}

/// The title of one panel: the degree's name (or a lane's) in its colour.
fn panel_title(svg: &mut Painter, th: &Theme, at: (f64, f64), title: &str, color: Color) {
    text_centred(
        svg,
        at,
        title,
        &TextStyle::new(th.subtitle(), color)
            .bold()
            .with_class("panel-title"),
    );
}
