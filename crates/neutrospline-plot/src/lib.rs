//! # neutrospline-plot
//!
//! Figures of neutrosophic curves as SVG and PNG: the paper's figures 1-5 (control points;
//! truth, indeterminacy and falsity curves; all three together) and a flat `plane` view.
//!
//! A [`PlotModel`] holds what to draw: a curve (any kind implementing
//! [`neutrospline::Evaluate`], sampled when drawn, or precomputed samples), its control
//! points and optionally their names. [`render_svg`] draws one [`View`] of it with
//! [`PlotOptions`]; [`svg_to_png`] and [`render_png`] rasterize.
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
//!
//! For 3-D models (positions x, y, z) the three spatial axes are taken, so:
//! - `truth`, `indeterminacy`, `falsity`: the 3-D curve coloured by that degree (viridis,
//!   0 to 1) with a colour bar, control polygon, points coloured alike, drop lines and the
//!   curve's shadow on the floor of the box;
//! - `all`: three such panels side by side, one per degree, sharing the colour bar;
//! - `controls`: the 3-D control polygon with the same callouts as in 2-D, drop lines and
//!   shadow;
//! - `plane`: the same lanes as in 2-D, drawn along the curve's projection in the 3-D view
//!   (the lanes are flat on the screen; the box keeps the 3-D context).
//!
//! Every figure has a title (a default per view, or [`PlotOptions::with_title`]), an optional
//! caption ([`PlotOptions::with_caption`], for sources and errata), labelled axes with
//! 1-2-5 ticks and a legend column on the right. 3-D views use an orthographic camera
//! ([`PlotOptions::with_camera`]; azimuth measured from the x axis in the x-y plane,
//! elevation above it) and draw back panes, grid and labels like common 3-D plotting tools.
//!
//! ## Output
//! SVG is written by a small deterministic writer (coordinates with two decimals, fixed
//! element order), with real `<text>` elements in the bundled DejaVu Sans ([`FONT_FAMILY`],
//! fallback `sans-serif`). PNG is rasterized from that SVG with resvg using only the bundled
//! font. Both are byte-for-byte reproducible. Degenerate models (one point, all points equal,
//! a straight line, all degrees 0 or 1) render with padded axis ranges and never produce NaN.
//!
//! ## Font
//! DejaVu Sans (regular and bold), bundled in the crate under its own free license (see
//! `fonts/LICENSE-DejaVu.txt`).
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod axes;
mod callout;
mod camera;
mod error;
mod font;
mod layout;
mod model;
mod options;
mod png;
mod render;
mod scene;
mod svg;
mod theme;
mod ticks;
mod view;

pub use error::PlotError;
pub use font::FONT_FAMILY;
pub use model::{PlotModel, BEZIER_LABEL, BSPLINE_LABEL, CURVE_LABEL, NURBS_LABEL};
pub use options::{
    PlotOptions, DEFAULT_AZIMUTH, DEFAULT_ELEVATION, DEFAULT_HEIGHT, DEFAULT_SAMPLES,
    DEFAULT_WIDTH, MAX_SAMPLES, MAX_SIDE, MIN_SAMPLES, MIN_SIDE,
};
pub use png::{render_png, svg_to_png};
pub use render::render_svg;
pub use view::View;
