//! # neutrospline-plot
//!
//! Figures of neutrosophic curves and surfaces as SVG and PNG: the paper's figures 1-5
//! (control points; truth, indeterminacy and falsity curves; all three together), a flat
//! `plane` view, a `score` view (the score of the degrees drawn like a degree), the same seven
//! views for tensor-product surfaces, and a `data` view of a curve next to the measured points
//! it was fitted to.
//!
//! ## The public items
//! - [`PlotModel`]: what to draw: a curve (any kind implementing [`neutrospline::Evaluate`],
//!   sampled when drawn, or precomputed samples) or a surface ([`PlotModel::from_surface`]:
//!   Bézier, B-spline or NURBS), its control points and optionally their names; its
//!   [`label`](PlotModel::label) (the kind of model) goes into the default titles; and
//!   optionally, for a curve, the data points it was fitted to
//!   ([`PlotModel::with_data`]).
//! - [`DataOverlay`]: measured data points (positions, their three degrees, optionally their
//!   curve parameters, and the degree that colours them), drawn by the `data` view.
//! - [`PlotOptions`]: size, title, caption, camera and sampling, with the defaults and limits
//!   as associated constants ([`PlotOptions::DEFAULT_WIDTH`], [`PlotOptions::MAX_SAMPLES`],
//!   [`PlotOptions::MIN_SIDE`], ...).
//! - [`View`]: which figure to draw (`controls`, `truth`, `indeterminacy`, `falsity`, `all`,
//!   `plane`, `score`, `data`); parsed from and displayed as those names. It is
//!   `#[non_exhaustive]`: views may be added, so a `match` on it needs a wildcard arm.
//! - [`render_svg`] draws one view of a model with options; [`render_png`] draws and
//!   rasterizes it, [`svg_to_png`] rasterizes an SVG document.
//! - [`render_drawing`] draws the view as a [`Drawing`], its primitives in order, which
//!   [`Drawing::to_svg`] writes as the SVG above and [`Drawing::to_display_list`] as compact
//!   JSON for painting on an HTML canvas (the studio's frames while a point is dragged).
//! - [`PlotError`]: every error of the above; [`FONT_FAMILY`]: the bundled font's family name.
//!
//! ```
//! use neutrospline_plot::{render_png, render_svg, PlotModel, PlotOptions, View};
//!
//! let curve = neutrospline::example1();
//! let model = PlotModel::from(&curve).with_names(neutrospline::EXAMPLE1_NAMES)?;
//! let options = PlotOptions::default()
//!     .with_caption("Example 1 of the paper, Table 1 data.");
//! let svg = render_svg(&model, View::All, &options)?;
//! assert!(svg.contains("indeterminacy"));
//! let png = render_png(&model, View::Controls, &options.with_size(320, 240))?;
//! assert!(png.starts_with(b"\x89PNG"));
//! # Ok::<(), neutrospline_plot::PlotError>(())
//! ```
//!
//! ## The views
//! For 2-D models (positions x, y: the paper's model) the degree becomes the height of a 3-D
//! view, as in the paper:
//! - `controls` (Fig. 1): the control polygon and points on x-y axes, each point with a
//!   callout showing its name and three bars (truth, indeterminacy, falsity; a full bar is 1)
//!   with the values; the crisp curve in light grey for context.
//! - `truth`, `indeterminacy`, `falsity` (Fig. 2-4): axes x, y and the degree; the space curve
//!   `(x(t), y(t), degree(t))` with its control polygon and points `(x_i, y_i, degree_i)`, a
//!   translucent curtain down to the crisp curve drawn on the degree = 0 plane (its shadow),
//!   the crisp control polygon and drop lines from each control point.
//! - `all` (Fig. 5): the three space curves in one box, each in its colour with its own marker
//!   shape, above the crisp shadow.
//! - `plane`: a flat view: the crisp curve with three lanes along it, one per degree (truth,
//!   indeterminacy, falsity from the left of the direction of travel), each filled to a width
//!   proportional to the degree (a full grey lane is 1).
//! - `score`: like `truth`, with the score `(2 + T - I - F) / 3` of the degrees
//!   ([`neutrospline::Degrees::score`], in \[0, 1\]) as the height: the space curve
//!   `(x(t), y(t), score(t))` with its control polygon lifted to the control points' scores,
//!   above the crisp curve on the score = 0 plane. The score is affine in the degrees and every
//!   basis is non-negative with unit sum, so the score of the curve is exactly the curve of
//!   the control points' scores.
//!
//! For 3-D models (positions x, y, z) the three spatial axes are taken, so:
//! - `truth`, `indeterminacy`, `falsity`, `score`: the 3-D curve coloured by that degree or
//!   the score (viridis, 0 to 1) with a colour bar, control polygon, points coloured alike,
//!   drop lines and the curve's shadow on the floor of the box;
//! - `all`: three such panels, one per degree, sharing the colour bar: in a 2 x 2 grid with
//!   the legend in the fourth cell, or in a row or a column with the legend beside them,
//!   whichever draws the panels largest for the figure's size (every panel and the legend keep
//!   to their own cells, so nothing overlaps at any size);
//! - `controls`: the 3-D control polygon with the same callouts as in 2-D, drop lines and
//!   shadow;
//! - `plane`: the same lanes as in 2-D, drawn along the curve's projection in the 3-D view
//!   (the lanes are flat on the screen; the box keeps the 3-D context).
//!
//! For surfaces (positions x, y, z; a `rows x cols` control net), sampled on an `N x N`
//! grid ([`PlotOptions::with_samples`], default [`PlotOptions::DEFAULT_SURFACE_SAMPLES`] = 40
//! per direction, at most [`PlotOptions::MAX_SURFACE_SAMPLES`]):
//! - `truth`, `indeterminacy`, `falsity`, `score`: the surface as a mesh of `(N - 1)^2` quads
//!   coloured by that degree or the score (viridis, 0 to 1, with a colour bar), shaded by
//!   its normals (Lambert lighting from the upper left that darkens a face by at most a
//!   third, so the colour stays readable), drawn far to near (painter's algorithm) with about
//!   eight iso-parameter lines each way and a dark boundary; the control net as a dashed grey
//!   wire with its points coloured alike, in full where it lies in front of the surface and
//!   faint where the surface hides it;
//! - `all`: three such panels, arranged like the curves';
//! - `controls`: the net over the surface in neutral grey; each control point drawn as a
//!   small box of three bars (its truth, indeterminacy and falsity; a full bar is 1),
//!   shrunk where points crowd, for a regular subset of at most 64 points on large nets; the
//!   four corners named (`P00`, ... or the model's names);
//! - `plane`: the parameter domain seen from above: one heat map per degree over (u, v), `u`
//!   across and `v` up, with the interior knot lines of a spline surface dashed in white,
//!   arranged like `all`.
//!
//! The interval-valued and bipolar families (`interval-neutrosophic`,
//! `interval-intuitionistic`, `interval-type2`, `bipolar-neutrosophic`) carry two values per
//! degree, held by the model's two lanes (docs/model.md, "Lanes"; [`PlotModel::from_model`]):
//! - `truth`, `indeterminacy`, `falsity` of a 2-D curve: the lower curve (dashed) and the
//!   upper curve (solid) of the degree with a translucent ruled strip between them (legend
//!   `truth_lower`, `truth_upper`; for interval type-2 the lower and upper membership, held in
//!   the truth slots, and the strip is the footprint of uncertainty); for the bipolar family
//!   the positive degree (solid) above the crisp plane and the negative degree (dashed) below
//!   it, on a vertical axis over \[-1, 1\];
//! - `all` of a 2-D curve: every degree the family carries, each pair in its colour;
//! - `truth`, `indeterminacy`, `falsity` of a 3-D curve or a surface: two panels, one per
//!   lane (lower and upper, or positive and the negative degree's magnitude), coloured on the
//!   shared colour bar;
//! - the views that draw one value per degree (`controls`, `plane`, `score`, `data`, and
//!   `all` of a 3-D curve or surface) are refused with the reason
//!   ([`PlotModel::check_view`]); `band` draws the position, which the lanes share.
//!
//! The `data` view ([`View::Data`]) draws a curve with the data points it was fitted to
//! ([`PlotModel::with_data`]): the fitted curve (its crisp positions) as a dark line over the
//! data; each data point as a marker filled with the viridis colour of one of its degrees
//! ([`DataOverlay::color_by`], truth unless set), with a colour bar titled, for example,
//! "truth of the data"; and a red residual whisker from each point to the curve point it was
//! fitted to: the curve at the point's parameter when the parameters are given, else the
//! nearest point of the curve. 2-D curves are drawn on x-y axes (like `controls`), 3-D
//! curves in the 3-D box with the curve's shadow on the floor. The control points are not
//! drawn, nor are the points named: past 200 points the markers shrink, so that thousands
//! stay readable. Its default title is "{label} fitted to data". It is an error for a model
//! without data ([`PlotError::NoData`]); for a surface it draws the fitted mesh with the data over it;
//! the other views ignore the data.
//!
//! ```
//! use neutrospline_plot::{render_svg, DataOverlay, PlotModel, PlotOptions, View};
//!
//! let model = PlotModel::from(&neutrospline::example1()).with_data(DataOverlay::new(
//!     vec![[2.0, 4.0, 0.0], [6.0, 3.0, 0.0]],
//!     vec![[0.9, 0.1, 0.0], [0.3, 0.4, 0.5]],
//! ))?;
//! let svg = render_svg(&model, View::Data, &PlotOptions::default())?;
//! assert!(svg.contains("Neutrosophic Bézier curve fitted to data"));
//! assert_eq!(svg.matches("class=\"residual\"").count(), 2);
//! # Ok::<(), neutrospline_plot::PlotError>(())
//! ```
//!
//! A surface that shows no area (a single row or column, all points equal, or a flat one
//! seen edge on) is drawn as a coloured curve or a point.
//!
//! Every figure has a title (a default per view, or [`PlotOptions::with_title`]), an optional
//! caption ([`PlotOptions::with_caption`], for sources and errata), labelled axes with
//! 1-2-5 ticks and a legend column on the right. 3-D views use an orthographic camera
//! ([`PlotOptions::with_camera`]; azimuth measured from the x axis in the x-y plane,
//! elevation above it) and draw back panes, grid and labels like common 3-D plotting tools.
//!
//! ## Inside the crate
//! [`render_drawing`] (module `render`) checks the options, samples the model and builds the
//! context every view draws from (`ctx`), then hands it to the view, which draws into a
//! `drawing::Painter` and returns the [`Drawing`] it recorded. The views sit behind one
//! dispatch, `views::figure`, the only `match` on [`View`] that draws: each view is one
//! module of `views` that draws its three cases (a 2-D curve, a 3-D curve, a surface) and its
//! default title:
//! - `views::controls`: `controls`; `views::single`: `truth`, `indeterminacy`, `falsity` and
//!   `score` (one body for the four: a `quantity::Quantity` is a degree or the score);
//!   `views::all`: `all`; `views::wide`: the degree views and `all` of the wide families;
//!   `views::plane`: `plane`; `views::data`: `data` (the one view that
//!   draws the model's data overlay: `render_svg` gives it the data points and the curve
//!   points their whiskers go to, and no control points).
//!
//! They draw with shared helpers, which never import a view module:
//! - figure pieces: `curve3d` (a 3-D curve in its box: shadow, drop lines, control polygon,
//!   the curve coloured by a quantity), `lifted` (2-D curves with a quantity as the height),
//!   `mesh` (a surface as a shaded mesh coloured by a quantity), `net` (a surface's control
//!   net, faint where the surface hides it), `glyph` (degree glyphs of a surface's control
//!   points), `callout` (callouts and point names placed clear of the drawing), `panels` (the
//!   three-panel figures);
//! - layout and axes: `layout` (rectangles, text, legends, colour bars, title and caption),
//!   `axes2` (2-D axes at equal scale), `axes3` (the 3-D box), `ticks`, `camera`;
//! - what is drawn: `quantity` (a degree or the score: its name, colour and value from a
//!   point's degrees, taken by `lifted`, `curve3d` and `mesh`);
//! - geometry: `nearest` (the point of a curve nearest to a given point: dense samples, then
//!   a golden-section search);
//! - style: `style` (colours, shape and text styles, and `num`, the number formatting of both
//!   encodings), `theme` (sizes and colours), `font` (the bundled font and its metrics);
//!   `style` and `point` (the sampled point, a position and its degrees) import nothing from
//!   the crate;
//! - output: `scene` (depth-sorted drawing), `drawing` (the `Painter` and the [`Drawing`] it
//!   records), `encode` (the `Encoder` trait, one method per primitive, and `Drawing::encode`,
//!   the one `match` over the primitives), its two implementations `svg` (the SVG encoding)
//!   and `display_list` (the canvas encoding), and `png` (rasterizing);
//! - the public types: `model`, `overlay` (the data overlay and its checks), `options`,
//!   `view`, `error`.
//!
//! No two modules import each other: `drawing` knows neither encoding, and a view module
//! takes its `Figure` trait from `views::figure`, not from the dispatch that imports it.
//!
//! Adding a view means adding its variant and name to [`View`], one module in `views`, and
//! its arm in `views::figure`.
//!
//! ## Output
//! SVG is written from the recorded drawing (coordinates with two decimals, fixed element
//! order), with real `<text>` elements in the bundled DejaVu Sans ([`FONT_FAMILY`],
//! fallback `sans-serif`). PNG is rasterized from that SVG with resvg using only the bundled
//! font. Both are byte-for-byte reproducible. Degenerate models (one point, all points equal,
//! a straight line, all degrees 0 or 1, a 1 x 1 or flat surface) render with padded axis
//! ranges and never produce NaN. A surface figure at the default 40 x 40 samples is about
//! 0.3 MB of SVG (the three-panel `all`, about 0.8 MB).
//!
//! ## Font
//! DejaVu Sans (regular and bold), bundled in the crate under its own free license (see
//! `fonts/LICENSE-DejaVu.txt`).
#![deny(missing_docs)]
#![forbid(unsafe_code)]

#[cfg(test)]
mod audit;
mod axes2;
mod axes3;
mod callout;
mod camera;
mod ctx;
mod curve3d;
mod display_list;
mod drawing;
mod encode;
mod error;
mod figure;
mod font;
mod glyph;
mod layout;
mod lifted;
mod mesh;
mod model;
mod nearest;
mod net;
mod options;
mod overlay;
mod page;
mod panels;
mod pdf;
mod png;
mod point;
mod quantity;
mod render;
mod request;
mod scene;
mod style;
mod subset;
mod svg;
mod theme;
mod ticks;
mod view;
mod views;

pub use drawing::Drawing;
pub use error::PlotError;
pub use figure::{render_figure, FigureFormat};
pub use font::FONT_FAMILY;
pub use model::PlotModel;
pub use options::PlotOptions;
pub use overlay::DataOverlay;
pub use page::{FigureSize, FigureStyle, Length, LengthUnit};
pub use png::{render_png, svg_to_png};
pub use render::{render_drawing, render_svg};
pub use request::FigureRequest;
pub use view::View;
