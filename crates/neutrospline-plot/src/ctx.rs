//! What every view draws from: the model's points as the renderer uses them, the options,
//! the theme and the texts, and the axes fitted to the points.

use neutrospline::DegreeKind;

use crate::axes2::{Axes2, Scale};
use crate::axes3::{box_lengths3, Axes3};
use crate::callout::{draw_names, Keep, Obstacle};
use crate::camera::Camera;
use crate::drawing::{Drawing, Painter};
use crate::layout::{Frame, Legend, LegendPlace, Rect};
use crate::model::Mesh;
use crate::options::PlotOptions;
use crate::point::Pt;
use crate::theme::Theme;
use crate::ticks::{padded, ticks_loose, Ticks};

/// The data points of the `data` view and the curve points their whiskers go to.
pub(crate) struct DataCtx {
    pub points: Vec<Pt>,
    /// One per point: the curve at its parameter, or the curve's point nearest to it.
    pub feet: Vec<Pt>,
    /// The degree that colours the points.
    pub color_by: DegreeKind,
    /// Whether the feet are the curve at the points' parameters (else the nearest points).
    pub at_parameters: bool,
}

/// The band view's curves: per alpha level (ascending), the lower and upper curves of the
/// alpha-cut; and the centroid curve. Samples at the parameters of `Ctx::curve`.
pub(crate) struct BandCtx {
    pub levels: Vec<(f64, Vec<Pt>, Vec<Pt>)>,
    pub centroid: Vec<Pt>,
}

/// The second lane of an interval-valued or bipolar model (docs/model.md, "Lanes"): its
/// samples, control points and mesh, at the parameters of `Ctx::curve`, `Ctx::controls` and
/// the first lane's mesh (the positions are the same; the degree slots hold the upper
/// degrees, or the negative degrees negated).
pub(crate) struct WideCtx<'a> {
    pub curve: Vec<Pt>,
    pub controls: &'a [Pt],
    pub mesh: Option<Mesh>,
}

/// Everything a view needs.
pub(crate) struct Ctx<'a> {
    pub theme: Theme,
    pub options: &'a PlotOptions,
    /// The curve samples (for a surface: the mesh points, so that extents cover them).
    pub curve: Vec<Pt>,
    pub controls: &'a [Pt],
    pub names: &'a [String],
    /// How many control points, from the first, get a name or callout.
    pub labelled: usize,
    pub title: String,
    pub caption: String,
    /// The data overlay, for the view that draws it (`None` for every other view).
    pub data: Option<DataCtx>,
    /// The band view's curves (`None` for every other view).
    pub band: Option<BandCtx>,
    /// The second lane of a wide family (`None` for the families of one lane).
    pub wide: Option<WideCtx<'a>>,
}

impl Ctx<'_> {
    /// The context of the second lane of a wide model (its samples and control points in
    /// place of the first lane's; no data, band or further lane), for the views that draw
    /// each lane in its own panel.
    pub(crate) fn second_lane(&self) -> Option<Ctx<'_>> {
        let wide = self.wide.as_ref()?;
        Some(Ctx {
            theme: self.theme,
            options: self.options,
            curve: wide.curve.clone(),
            controls: wide.controls,
            names: self.names,
            labelled: self.labelled,
            title: self.title.clone(),
            caption: self.caption.clone(),
            data: None,
            band: None,
            wide: None,
        })
    }

    /// The camera of the 3-D views.
    pub(crate) fn cam(&self) -> Camera {
        Camera::new(self.options.azimuth(), self.options.elevation())
    }

    /// The curve samples, then the control points, then the data points and their feet on
    /// the curve (for the view that draws them).
    fn all_points(&self) -> impl Iterator<Item = &Pt> {
        let data = self
            .data
            .iter()
            .flat_map(|d| d.points.iter().chain(d.feet.iter()));
        let band = self.band.iter().flat_map(|b| {
            b.levels
                .iter()
                .flat_map(|(_, lo, hi)| lo.iter().chain(hi.iter()))
                .chain(b.centroid.iter())
        });
        self.curve
            .iter()
            .chain(self.controls.iter())
            .chain(data)
            .chain(band)
    }

    /// (min, max) of coordinate `axis` over curve and control points.
    pub(crate) fn extent(&self, axis: usize) -> (f64, f64) {
        self.all_points()
            .map(|p| p.pos[axis])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    }

    /// The figure's frame (title, caption, plot area) with `legend` at `place`.
    pub(crate) fn frame(&self, legend: Legend, place: LegendPlace) -> Frame {
        Frame::new(
            self.options.width(),
            self.options.height(),
            &self.theme,
            &self.title,
            &self.caption,
            legend,
            place,
        )
    }

    /// Draws the names of points at pixel positions `at`, clear of `obstacles`, inside
    /// `bounds` and off `avoid`.
    pub(crate) fn names(
        &self,
        svg: &mut Painter,
        at: &[(f64, f64)],
        obstacles: Vec<Obstacle>,
        bounds: Rect,
        avoid: Option<Rect>,
    ) {
        if self.names.is_empty() {
            return;
        }
        let keep = Keep::new(obstacles, bounds, avoid);
        let shown = self.labelled.min(at.len()).min(self.names.len());
        draw_names(svg, &self.theme, &at[..shown], &self.names[..shown], &keep);
    }

    /// A figure of one drawing with `legend` at `place`: `draw` draws into the plot area, given
    /// with the legend's rectangle to keep clear of, and the frame (title, caption, legend) is
    /// drawn last.
    pub(crate) fn figure(
        &self,
        legend: Legend,
        place: LegendPlace,
        draw: impl FnOnce(&mut Painter, Rect, Option<Rect>),
    ) -> Drawing {
        let frame = self.frame(legend, place);
        let mut svg = self.svg();
        draw(&mut svg, frame.plot, frame.legend_rect(&self.theme));
        frame.draw(&mut svg, &self.theme);
        svg.finish()
    }

    /// An empty SVG document of the figure's size and title.
    pub(crate) fn svg(&self) -> Painter {
        Painter::new(self.options.width(), self.options.height(), &self.title)
    }

    /// 2-D axes x, y for the model in `plot`, with `inner` pixels kept free around the data,
    /// scaled as `scale` says.
    pub(crate) fn axes2(&self, plot: Rect, inner: f64, scale: Scale) -> Axes2 {
        let (x, y) = (self.extent(0), self.extent(1));
        Axes2::new(plot, x, y, inner, &self.theme, ("x", "y"), scale)
    }

    /// The 3-D box x, y, z of the model (about `target` ticks per axis) fitted into `area`,
    /// clear of `avoid`.
    pub(crate) fn axes3(&self, area: Rect, target: usize, avoid: Option<Rect>) -> Axes3 {
        let t: [Ticks; 3] = [0, 1, 2].map(|a| {
            let (lo, hi) = self.extent(a);
            let (lo, hi) = padded(lo, hi, 0.03);
            ticks_loose(lo, hi, target)
        });
        let len = box_lengths3([&t[0], &t[1], &t[2]]);
        Axes3::new(
            area,
            t,
            len,
            ["x", "y", "z"],
            self.cam(),
            &self.theme,
            avoid,
        )
    }

    /// The 3-D box fitted into `area` clear of `avoid` (as [`Ctx::axes3`], about five ticks
    /// per axis), drawn into `svg`.
    pub(crate) fn draw_box(&self, svg: &mut Painter, area: Rect, avoid: Option<Rect>) -> Axes3 {
        let axes = self.axes3(area, 5, avoid);
        axes.draw(svg, &self.theme);
        axes
    }

    /// How a panel of the 3-D box fits `area`: its scale and the top of its drawing (for
    /// the three-panel figures).
    pub(crate) fn fit_box(&self, area: Rect) -> (f64, f64) {
        let axes = self.axes3(area, 5, None);
        (axes.scale(), axes.bounds().y)
    }
}
