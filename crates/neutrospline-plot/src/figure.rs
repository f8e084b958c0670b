//! The figure file formats, chosen by extension, and [`render_figure`], which writes a view
//! in any of them.

use std::path::Path;

use crate::error::PlotError;
use crate::model::PlotModel;
use crate::options::PlotOptions;
use crate::png::render_png;
use crate::render::{render_drawing, render_svg};
use crate::view::View;

/// The formats of a figure file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FigureFormat {
    /// Scalable vector graphics: text stays text (in the bundled font's family).
    Svg,
    /// A raster image, rendered with the bundled font, its resolution recorded.
    Png,
    /// A one-page PDF, vector, with the bundled font embedded: for LaTeX's
    /// `\includegraphics`.
    Pdf,
}

impl FigureFormat {
    /// Every format, in the order of [`FigureFormat::NAMES`].
    pub const ALL: [FigureFormat; 3] = [FigureFormat::Svg, FigureFormat::Png, FigureFormat::Pdf];
    /// The formats' names, which are their file extensions.
    pub const NAMES: [&'static str; 3] = ["svg", "png", "pdf"];

    /// The format's name and file extension.
    pub fn name(self) -> &'static str {
        match self {
            FigureFormat::Svg => "svg",
            FigureFormat::Png => "png",
            FigureFormat::Pdf => "pdf",
        }
    }

    /// The format of `path`, from its extension (case-insensitive).
    ///
    /// # Errors
    /// [`PlotError::FigureExtension`], naming the file and the accepted extensions.
    ///
    /// ```
    /// use neutrospline_plot::FigureFormat;
    /// assert_eq!(FigureFormat::from_path("fig.PDF".as_ref()), Ok(FigureFormat::Pdf));
    /// assert_eq!(
    ///     FigureFormat::from_path("fig.eps".as_ref()).unwrap_err().to_string(),
    ///     "fig.eps: unsupported figure extension (accepted: .svg, .png, .pdf)"
    /// );
    /// ```
    pub fn from_path(path: &Path) -> Result<FigureFormat, PlotError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        FigureFormat::ALL
            .into_iter()
            .find(|f| ext.as_deref() == Some(f.name()))
            .ok_or_else(|| PlotError::FigureExtension {
                path: path.display().to_string(),
            })
    }
}

/// Draws `view` of `model` in `format`: the SVG text, the PNG or the PDF file's bytes.
///
/// A PDF page is [`PlotOptions::page_points`] in size: the print size exactly, or a size in
/// pixels at the resolution set (96 pixels per inch unless one is).
///
/// # Errors
/// Those of [`render_drawing`] and [`render_png`].
///
/// ```
/// use neutrospline_plot::{render_figure, FigureFormat, Length, LengthUnit, PlotModel, PlotOptions, View};
/// let model = PlotModel::from(&neutrospline::example1());
/// let cm = |v| Length::new(v, LengthUnit::Cm);
/// let options = PlotOptions::default().with_print_size(cm(8.5), cm(6.0));
/// let pdf = render_figure(&model, View::Truth, &options, FigureFormat::Pdf)?;
/// assert!(pdf.starts_with(b"%PDF"));
/// let svg = String::from_utf8(render_figure(&model, View::Truth, &options, FigureFormat::Svg)?).unwrap();
/// assert!(svg.contains("width=\"8.5cm\" height=\"6cm\" viewBox=\"0 0 241 170\""));
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
pub fn render_figure(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
    format: FigureFormat,
) -> Result<Vec<u8>, PlotError> {
    match format {
        FigureFormat::Svg => render_svg(model, view, options).map(String::into_bytes),
        FigureFormat::Png => render_png(model, view, options),
        FigureFormat::Pdf => {
            let drawing = render_drawing(model, view, options)?;
            let (w, h) = options.page_points();
            Ok(drawing.to_pdf(w, h))
        }
    }
}
