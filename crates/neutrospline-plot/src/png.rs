//! Rasterizing the SVG to PNG with resvg, using only the bundled font.

use resvg::{tiny_skia, usvg};

use crate::error::PlotError;
use crate::font::{database, FONT_FAMILY};
use crate::model::PlotModel;
use crate::options::{check_size, PlotOptions};
use crate::render::render_svg;
use crate::view::View;

/// Rasterizes an SVG document to a PNG of `width` x `height` pixels (the drawing is scaled to
/// fill it), on an opaque white background.
///
/// Text is set in the bundled font only (no system fonts are read), and rendering is pure
/// Rust (resvg, tiny-skia), so equal input gives byte-identical PNG files on every machine.
///
/// # Errors
/// [`PlotError::InvalidSize`], [`PlotError::Svg`] when the text is not an SVG document the
/// rasterizer accepts, or [`PlotError::Png`] when encoding fails.
pub fn svg_to_png(svg: &str, width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    check_size(width, height)?;
    let options = usvg::Options {
        font_family: FONT_FAMILY.to_string(),
        fontdb: database(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| PlotError::Svg {
        message: e.to_string(),
    })?;
    let mut pixmap = tiny_skia::Pixmap::new(width, height).ok_or(PlotError::InvalidSize {
        width,
        height,
        min: PlotOptions::MIN_SIDE,
        max: PlotOptions::MAX_SIDE,
    })?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let size = tree.size();
    let transform = tiny_skia::Transform::from_scale(
        width as f32 / size.width(),
        height as f32 / size.height(),
    );
    resvg::render(&tree, transform, &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| PlotError::Png {
        message: e.to_string(),
    })
}

/// Draws `view` of `model` as a PNG of `options.width()` x `options.height()` pixels:
/// [`render_svg`] followed by [`svg_to_png`].
///
/// # Errors
/// Those of [`render_svg`] and [`svg_to_png`].
///
/// # Examples
/// ```
/// use neutrospline_plot::{render_png, PlotModel, PlotOptions, View};
/// let model = PlotModel::from(&neutrospline::example1());
/// let png = render_png(&model, View::Plane, &PlotOptions::default().with_size(400, 300))?;
/// assert_eq!(&png[1..4], b"PNG");
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
pub fn render_png(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
) -> Result<Vec<u8>, PlotError> {
    let svg = render_svg(model, view, options)?;
    svg_to_png(&svg, options.width(), options.height())
}
