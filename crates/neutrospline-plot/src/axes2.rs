//! 2-D axes at equal scale on x and y (or filling the frame, for data views): for the flat views of curves and the heat maps over a
//! surface's parameter domain.

use crate::drawing::Painter;
use crate::font::text_width;
use crate::layout::{text_centred, Rect, TEXT_BOX};
use crate::point::Pt;
use crate::style::{Anchor, Style, TextStyle};
use crate::theme::{self, Theme};
use crate::ticks::{padded, ticks_inside, widen_degenerate, Ticks};

/// Number of tick intervals for an axis `len` pixels long.
fn tick_target(len: f64, per: f64) -> usize {
    ((len / per).round() as usize).clamp(3, 9)
}

fn widest(labels: &[String], size: f64) -> f64 {
    labels
        .iter()
        .map(|l| text_width(l, size, false))
        .fold(0.0, f64::max)
}

/// Space above the frame: half a tick label.
fn top_margin(theme: &Theme) -> f64 {
    0.6 * theme.tick()
}

/// Space below the frame: ticks, tick labels and the axis label.
fn bottom_margin(theme: &Theme) -> f64 {
    theme.tick_len() + theme.gap() + theme.tick() * TEXT_BOX + theme.gap() + 1.3 * theme.label()
}

/// Fits the left and right margins to the tick labels they must hold: `place` lays out the
/// frame, ticks and scale for given (left, right) margins, and is called again with the
/// margins its labels need, at most three times in all, until they no longer change.
fn fit_margins(
    theme: &Theme,
    place: impl Fn(f64, f64) -> (Rect, Ticks, Ticks, (f64, f64)),
) -> Option<(Rect, Ticks, Ticks, (f64, f64))> {
    let tick = theme.tick();
    let mut left = 4.0 * tick;
    let mut right = 1.5 * tick;
    let mut result = None;
    for _ in 0..3 {
        let (frame, xt, yt, scale) = place(left, right);
        let need_left = theme.tick_len()
            + theme.gap()
            + widest(&yt.labels(), tick)
            + theme.gap()
            + 1.3 * theme.label();
        let need_right = widest(&xt.labels(), tick) / 2.0 + theme.gap();
        let done = (need_left - left).abs() < 0.5 && (need_right - right).abs() < 0.5;
        left = need_left;
        right = need_right.max(theme.gap());
        result = Some((frame, xt, yt, scale));
        if done {
            break;
        }
    }
    result
}

/// How [`Axes2::new`] scales the two axes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scale {
    /// The same pixels per unit on x and y.
    Equal,
    /// Equal, except when that would leave more than half of the frame empty in one direction
    /// (data much wider than tall, or the reverse): then each axis is scaled to fill the frame,
    /// for data whose residuals must stay visible, such as a long survey profile.
    Filling,
}

/// 2-D axes with equal scale on x and y (unless made with [`Scale::Filling`]), filling a plot
/// rectangle.
pub(crate) struct Axes2 {
    pub frame: Rect,
    pub xt: Ticks,
    pub yt: Ticks,
    scale: f64,
    /// Pixels per y unit: `scale` unless the axes were made by [`Scale::Filling`].
    scale_y: f64,
    xlabel: String,
    ylabel: String,
    /// Axes of an image that fills the frame (a heat map): no grid, which the image would
    /// hide anyway, and the y label set upright (a lone `v` turned on its side reads as `>`).
    image: bool,
}

impl Axes2 {
    /// Axes for data within `x` and `y` (min, max), with `inner` pixels kept free between the
    /// data and the frame (for labels drawn around points), scaled as `scale` says.
    pub(crate) fn new(
        plot: Rect,
        x: (f64, f64),
        y: (f64, f64),
        inner: f64,
        theme: &Theme,
        labels: (&str, &str),
        scale: Scale,
    ) -> Axes2 {
        let fill = scale == Scale::Filling;
        let (x0, x1) = padded(x.0, x.1, 0.03);
        let (y0, y1) = padded(y.0, y.1, 0.03);
        let (top, bottom) = (top_margin(theme), bottom_margin(theme));
        let fit = fit_margins(theme, |left, right| {
            let frame = Rect::new(
                plot.x + left,
                plot.y + top,
                plot.w - left - right,
                plot.h - top - bottom,
            );
            let uw = (frame.w - 2.0 * inner).max(0.3 * frame.w);
            let uh = (frame.h - 2.0 * inner).max(0.3 * frame.h);
            let (sx, sy) = (uw / (x1 - x0), uh / (y1 - y0));
            let scale = sx.min(sy);
            let (sx, sy) = if fill && sx.max(sy) > 2.0 * scale {
                (sx, sy)
            } else {
                (scale, scale)
            };
            let (cx, cy) = (x0 / 2.0 + x1 / 2.0, y0 / 2.0 + y1 / 2.0);
            let hx = frame.w / 2.0 / sx;
            let hy = frame.h / 2.0 / sy;
            let xt = ticks_inside(cx - hx, cx + hx, tick_target(frame.w, 190.0 * theme.s));
            let yt = ticks_inside(cy - hy, cy + hy, tick_target(frame.h, 150.0 * theme.s));
            (frame, xt, yt, (sx, sy))
        });
        Axes2::fitted(fit, plot, (x0, x1), (y0, y1), labels, false)
    }

    /// Axes whose frame is exactly the data rectangle `x` by `y` (no padding), at equal
    /// scale, as large as fits in `plot` with its labels, centred in it: for images such as
    /// heat maps that fill their frame.
    pub(crate) fn exact(
        plot: Rect,
        x: (f64, f64),
        y: (f64, f64),
        theme: &Theme,
        labels: (&str, &str),
    ) -> Axes2 {
        let (x0, x1) = widen_degenerate(x.0, x.1);
        let (y0, y1) = widen_degenerate(y.0, y.1);
        let (top, bottom) = (top_margin(theme), bottom_margin(theme));
        let fit = fit_margins(theme, |left, right| {
            let (aw, ah) = (plot.w - left - right, plot.h - top - bottom);
            let scale = (aw / (x1 - x0)).min(ah / (y1 - y0)).max(1e-300);
            let (fw, fh) = ((x1 - x0) * scale, (y1 - y0) * scale);
            let frame = Rect::new(
                plot.x + left + (aw - fw) / 2.0,
                plot.y + top + (ah - fh) / 2.0,
                fw,
                fh,
            );
            let xt = ticks_inside(x0, x1, tick_target(frame.w, 190.0 * theme.s));
            let yt = ticks_inside(y0, y1, tick_target(frame.h, 150.0 * theme.s));
            (frame, xt, yt, (scale, scale))
        });
        Axes2::fitted(fit, plot, (x0, x1), (y0, y1), labels, true)
    }

    /// Axes with the frame, ticks and scale of `fit`, or failing a fit, the whole `plot` with
    /// plain ticks over `x` by `y`.
    fn fitted(
        fit: Option<(Rect, Ticks, Ticks, (f64, f64))>,
        plot: Rect,
        x: (f64, f64),
        y: (f64, f64),
        labels: (&str, &str),
        image: bool,
    ) -> Axes2 {
        let (frame, xt, yt, (scale, scale_y)) = fit.unwrap_or_else(|| {
            (
                plot,
                ticks_inside(x.0, x.1, 5),
                ticks_inside(y.0, y.1, 5),
                (1.0, 1.0),
            )
        });
        Axes2 {
            frame,
            xt,
            yt,
            scale,
            scale_y,
            xlabel: labels.0.to_string(),
            ylabel: labels.1.to_string(),
            image,
        }
    }

    /// Pixels per data unit (of x, for axes made by [`Scale::Filling`]).
    pub(crate) fn scale(&self) -> f64 {
        self.scale
    }

    /// The frame with its tick and axis labels: what the axes occupy.
    pub(crate) fn outer(&self, theme: &Theme) -> Rect {
        let tick = theme.tick();
        let widest_y = widest(&self.yt.labels(), tick);
        let left = theme.tick_len() + 2.0 * theme.gap() + widest_y + 1.05 * theme.label();
        let bottom = theme.tick_len() + 2.0 * theme.gap() + TEXT_BOX * tick + 1.05 * theme.label();
        let half_x = widest(&self.xt.labels(), tick) / 2.0;
        let f = self.frame;
        Rect::new(
            f.x - left,
            f.y - 0.5 * tick,
            f.w + left + half_x,
            f.h + 0.5 * tick + bottom,
        )
    }

    /// Opens a group clipped to the frame (id `plot-clip`); close it with
    /// [`Painter::end_group`].
    pub(crate) fn begin_clip(&self, svg: &mut Painter) {
        let f = self.frame;
        svg.begin_clip("plot-clip", f.x, f.y, f.w, f.h);
    }

    /// Pixel positions of points (their x and y).
    pub(crate) fn pixels(&self, pts: &[Pt]) -> Vec<(f64, f64)> {
        pts.iter().map(|p| self.map(p.pos[0], p.pos[1])).collect()
    }

    /// Pixel position of data point `(x, y)`.
    pub(crate) fn map(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.frame.x + (x - self.xt.lo) * self.scale,
            self.frame.bottom() - (y - self.yt.lo) * self.scale_y,
        )
    }

    /// The frame: a dark rectangle around the plot.
    pub(crate) fn draw_frame(&self, svg: &mut Painter, theme: &Theme) {
        let f = self.frame;
        svg.rect(
            f.x,
            f.y,
            f.w,
            f.h,
            &Style::stroke(theme::AXIS, theme.axis_w()).square(),
        );
    }

    /// Background, grid, frame, ticks and axis labels.
    pub(crate) fn draw(&self, svg: &mut Painter, theme: &Theme) {
        let f = self.frame;
        svg.begin_group("axes");
        let grid = Style::stroke(theme::GRID, theme.grid_w()).square();
        let tick_style = Style::stroke(theme::AXIS, theme.axis_w()).square();
        let ts = TextStyle::new(theme.tick(), theme::INK).with_class("tick-label");
        for (v, label) in self.xt.values.iter().zip(self.xt.labels()) {
            let (px, _) = self.map(*v, self.yt.lo);
            if !self.image {
                svg.line((px, f.y), (px, f.bottom()), &grid);
            }
            svg.line(
                (px, f.bottom()),
                (px, f.bottom() + theme.tick_len()),
                &tick_style,
            );
            text_centred(
                svg,
                (
                    px,
                    f.bottom() + theme.tick_len() + theme.gap() + TEXT_BOX * theme.tick() / 2.0,
                ),
                &label,
                &ts,
            );
        }
        let mut widest_y: f64 = 0.0;
        for (v, label) in self.yt.values.iter().zip(self.yt.labels()) {
            let (_, py) = self.map(self.xt.lo, *v);
            if !self.image {
                svg.line((f.x, py), (f.right(), py), &grid);
            }
            svg.line((f.x - theme.tick_len(), py), (f.x, py), &tick_style);
            widest_y = widest_y.max(text_width(&label, theme.tick(), false));
            svg.text(
                f.x - theme.tick_len() - theme.gap(),
                py + 0.36 * theme.tick(),
                &label,
                &ts.clone().anchor(Anchor::End),
            );
        }
        self.draw_frame(svg, theme);
        let ls = TextStyle::new(theme.label(), theme::INK).with_class("axis-label");
        text_centred(
            svg,
            (
                f.x + f.w / 2.0,
                f.bottom()
                    + theme.tick_len()
                    + 2.0 * theme.gap()
                    + TEXT_BOX * theme.tick()
                    + 0.55 * theme.label(),
            ),
            &self.xlabel,
            &ls,
        );
        if self.image {
            let w = text_width(&self.ylabel, theme.label(), false);
            text_centred(
                svg,
                (
                    f.x - theme.tick_len() - 3.0 * theme.gap() - widest_y - w / 2.0,
                    f.y + f.h / 2.0,
                ),
                &self.ylabel,
                &ls,
            );
        } else {
            text_centred(
                svg,
                (
                    f.x - theme.tick_len() - 2.0 * theme.gap() - widest_y - 0.5 * theme.label(),
                    f.y + f.h / 2.0,
                ),
                &self.ylabel,
                &ls.clone().rotate(-90.0),
            );
        }
        svg.end_group();
    }
}
