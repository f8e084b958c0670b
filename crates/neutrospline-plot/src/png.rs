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

/// Draws `view` of `model` as a PNG of [`PlotOptions::png_size`] pixels (the size in pixels,
/// or a print size at the resolution), with the resolution written into the file (a `pHYs`
/// chunk) when the figure has one ([`PlotOptions::png_dpi`]): [`render_svg`] followed by
/// [`svg_to_png`].
///
/// # Errors
/// Those of [`render_svg`] and [`svg_to_png`]; [`PlotError::InvalidRaster`] when a print
/// size at the resolution gives too many or too few pixels.
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
    let (width, height) = options.png_size();
    if let (Some((w, h)), Err(_)) = (options.print_size(), check_size(width, height)) {
        return Err(PlotError::InvalidRaster {
            size: format!("{w}x{h}"),
            dpi: options.png_dpi().unwrap_or(PlotOptions::DEFAULT_PRINT_DPI),
            width,
            height,
            min: PlotOptions::MIN_SIDE,
            max: PlotOptions::MAX_SIDE,
        });
    }
    let png = svg_to_png(&svg, width, height)?;
    Ok(match options.png_dpi() {
        Some(dpi) => with_resolution(png, dpi),
        None => png,
    })
}

/// The PNG with a `pHYs` chunk (pixels per metre, both axes) right after its header.
fn with_resolution(png: Vec<u8>, dpi: f64) -> Vec<u8> {
    // The signature (8 bytes) and the IHDR chunk (4 + 4 + 13 + 4 bytes) come first.
    const AFTER_IHDR: usize = 8 + 25;
    if png.len() < AFTER_IHDR || &png[12..16] != b"IHDR" {
        return png;
    }
    let per_metre = (dpi / 0.0254).round() as u32;
    let mut chunk = Vec::with_capacity(21);
    chunk.extend_from_slice(&9u32.to_be_bytes());
    chunk.extend_from_slice(b"pHYs");
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.push(1); // the unit is the metre
    let crc = crc32fast::hash(&chunk[4..]);
    chunk.extend_from_slice(&crc.to_be_bytes());
    let mut out = Vec::with_capacity(png.len() + chunk.len());
    out.extend_from_slice(&png[..AFTER_IHDR]);
    out.extend_from_slice(&chunk);
    out.extend_from_slice(&png[AFTER_IHDR..]);
    out
}
