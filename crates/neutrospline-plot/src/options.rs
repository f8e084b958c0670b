//! Figure options.

use crate::error::PlotError;
use crate::page::{FigureSize, FigureStyle, Length};

/// How to draw a figure: size, texts, camera and sampling.
///
/// Every length in a figure (fonts, lines, markers, margins) scales with
/// `min(width / 1600, height / 1200)`, so a figure looks the same at any size.
///
/// The defaults and the limits that [`PlotOptions::validate`] enforces are associated
/// constants: the size ([`PlotOptions::DEFAULT_WIDTH`], [`PlotOptions::DEFAULT_HEIGHT`], each
/// side within [`PlotOptions::MIN_SIDE`]..=[`PlotOptions::MAX_SIDE`]), the camera
/// ([`PlotOptions::DEFAULT_AZIMUTH`], [`PlotOptions::DEFAULT_ELEVATION`]) and the sampling
/// ([`PlotOptions::DEFAULT_SAMPLES`] curve points, at most [`PlotOptions::MAX_SAMPLES`];
/// [`PlotOptions::DEFAULT_SURFACE_SAMPLES`] surface samples per direction, at most
/// [`PlotOptions::MAX_SURFACE_SAMPLES`]; at least [`PlotOptions::MIN_SAMPLES`] for both).
///
/// ```
/// use neutrospline_plot::PlotOptions;
/// let options = PlotOptions::default()
///     .with_size(800, 600)
///     .with_title("Example 1")
///     .with_camera(-60.0, 30.0);
/// assert_eq!(options.width(), 800);
/// assert_eq!(options.title(), Some("Example 1"));
/// assert_eq!(PlotOptions::default().height(), PlotOptions::DEFAULT_HEIGHT);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PlotOptions {
    /// `None`: the style's size.
    size: Option<FigureSize>,
    style: FigureStyle,
    dpi: Option<f64>,
    title: Option<String>,
    caption: Option<String>,
    azimuth: f64,
    elevation: f64,
    /// `None`: the default of the model's kind.
    samples: Option<usize>,
    /// The alpha levels of the band view.
    alphas: Vec<f64>,
}

impl Default for PlotOptions {
    fn default() -> PlotOptions {
        PlotOptions {
            size: None,
            style: FigureStyle::Default,
            dpi: None,
            title: None,
            caption: None,
            azimuth: PlotOptions::DEFAULT_AZIMUTH,
            elevation: PlotOptions::DEFAULT_ELEVATION,
            samples: None,
            alphas: PlotOptions::DEFAULT_ALPHAS.to_vec(),
        }
    }
}

impl PlotOptions {
    /// The alpha levels the band view draws by default.
    pub const DEFAULT_ALPHAS: [f64; 3] = [0.0, 0.5, 1.0];

    /// With these alpha levels for the band view (each in \[0, 1\]; order and repeats do
    /// not matter; checked by [`PlotOptions::validate`]).
    #[must_use]
    pub fn with_alphas(mut self, alphas: impl IntoIterator<Item = f64>) -> PlotOptions {
        self.alphas = alphas.into_iter().collect();
        self
    }

    /// The alpha levels of the band view, ascending, without repeats.
    pub fn alphas(&self) -> Vec<f64> {
        let mut a = self.alphas.clone();
        a.sort_by(f64::total_cmp);
        a.dedup();
        a
    }

    /// Default image width in pixels.
    pub const DEFAULT_WIDTH: u32 = 1600;
    /// Default image height in pixels.
    pub const DEFAULT_HEIGHT: u32 = 1200;
    /// The resolution of a PNG of a print size, unless one is set.
    pub const DEFAULT_PRINT_DPI: f64 = 300.0;
    /// Pixels per inch of a screen (CSS): the PDF page of a size in pixels, unless a
    /// resolution is set.
    pub const SCREEN_DPI: f64 = 96.0;
    /// Resolutions accepted, in dots per inch.
    pub const DPI_RANGE: std::ops::RangeInclusive<f64> = 10.0..=10_000.0;
    /// The smallest text size on paper, in points: the tick labels; the other texts keep
    /// their proportions to it (axis names 10 points, the title 12.75).
    pub const PRINT_TICK_POINTS: f64 = 8.5;
    /// Smallest image side accepted, in pixels.
    pub const MIN_SIDE: u32 = 64;
    /// Largest image side accepted, in pixels.
    pub const MAX_SIDE: u32 = 16384;
    /// Default camera azimuth in degrees (measured in the x-y plane from the x axis).
    pub const DEFAULT_AZIMUTH: f64 = -55.0;
    /// Default camera elevation in degrees (above the x-y plane).
    pub const DEFAULT_ELEVATION: f64 = 25.0;
    /// Default number of curve samples.
    pub const DEFAULT_SAMPLES: usize = 200;
    /// Smallest number of samples accepted (curves, and surfaces per direction).
    pub const MIN_SAMPLES: usize = 2;
    /// Largest number of curve samples accepted.
    pub const MAX_SAMPLES: usize = 100_000;
    /// Default number of surface samples per parameter direction (a 40 x 40 grid, 39 x 39
    /// quads).
    pub const DEFAULT_SURFACE_SAMPLES: usize = 40;
    /// Largest number of surface samples per direction accepted (keeps an SVG near 1 MB).
    pub const MAX_SURFACE_SAMPLES: usize = 100;

    /// The same as [`PlotOptions::default`].
    pub fn new() -> PlotOptions {
        PlotOptions::default()
    }

    /// Sets width and height in pixels (default 1600 x 1200).
    pub fn with_size(mut self, width: u32, height: u32) -> PlotOptions {
        self.size = Some(FigureSize::Pixels(width, height));
        self
    }

    /// Sets the width in pixels (default 1600).
    pub fn with_width(self, width: u32) -> PlotOptions {
        let height = self.height();
        self.with_size(width, height)
    }

    /// Sets the height in pixels (default 1200).
    pub fn with_height(self, height: u32) -> PlotOptions {
        let width = self.width();
        self.with_size(width, height)
    }

    /// Sets the size in pixels or on paper ([`FigureSize`]).
    pub fn with_figure_size(mut self, size: FigureSize) -> PlotOptions {
        self.size = Some(size);
        self
    }

    /// Sets a print size: the canvas is the size in PostScript points (1/72 inch), rounded to
    /// whole points; the SVG states the size in the units given, a PDF page is exactly this
    /// size, a PNG has `size x dpi` pixels ([`PlotOptions::DEFAULT_PRINT_DPI`] unless
    /// [`PlotOptions::with_dpi`]). Text is never smaller than [`PlotOptions::PRINT_TICK_POINTS`]
    /// (the tick labels) on paper.
    ///
    /// ```
    /// use neutrospline_plot::{Length, LengthUnit, PlotOptions};
    /// let cm = |v| Length::new(v, LengthUnit::Cm);
    /// let options = PlotOptions::default().with_print_size(cm(8.5), cm(6.0));
    /// assert_eq!((options.width(), options.height()), (241, 170));
    /// assert_eq!(options.png_size(), (1004, 709));
    /// ```
    pub fn with_print_size(self, width: Length, height: Length) -> PlotOptions {
        self.with_figure_size(FigureSize::Print(width, height))
    }

    /// Sets the resolution in dots per inch: the pixels of a PNG of a print size, and the
    /// resolution written into every PNG (its `pHYs` chunk). Without it, a print size is
    /// rasterized at [`PlotOptions::DEFAULT_PRINT_DPI`] and a size in pixels writes none.
    pub fn with_dpi(mut self, dpi: f64) -> PlotOptions {
        self.dpi = Some(dpi);
        self
    }

    /// Sets the style ([`FigureStyle::Paper`]: no title or caption unless given, one column
    /// wide unless a size is given, text of 8.5 to 10 points).
    pub fn with_style(mut self, style: FigureStyle) -> PlotOptions {
        self.style = style;
        self
    }

    /// The size as set: pixels, a print size, or the style's own.
    pub fn figure_size(&self) -> FigureSize {
        match (self.size, self.style) {
            (Some(size), _) => size,
            (None, FigureStyle::Default) => {
                FigureSize::Pixels(PlotOptions::DEFAULT_WIDTH, PlotOptions::DEFAULT_HEIGHT)
            }
            (None, FigureStyle::Paper) => {
                FigureSize::Print(FigureStyle::PAPER_WIDTH, FigureStyle::PAPER_HEIGHT)
            }
        }
    }

    /// The print size, when the figure has one (set, or the paper style's).
    pub fn print_size(&self) -> Option<(Length, Length)> {
        match self.figure_size() {
            FigureSize::Print(w, h) => Some((w, h)),
            FigureSize::Pixels(..) => None,
        }
    }

    /// The style.
    pub fn style(&self) -> FigureStyle {
        self.style
    }

    /// The resolution set, if any.
    pub fn dpi(&self) -> Option<f64> {
        self.dpi
    }

    /// The pixels of a PNG of the figure: the size in pixels, or a print size times the
    /// resolution (rounded).
    pub fn png_size(&self) -> (u32, u32) {
        match self.figure_size() {
            FigureSize::Pixels(w, h) => (w, h),
            FigureSize::Print(w, h) => {
                let dpi = self.dpi.unwrap_or(PlotOptions::DEFAULT_PRINT_DPI);
                let px = |l: Length| {
                    let v = (l.inches() * dpi).round();
                    if v.is_finite() && v >= 0.0 && v <= f64::from(u32::MAX) {
                        v as u32
                    } else {
                        u32::MAX
                    }
                };
                (px(w), px(h))
            }
        }
    }

    /// The size of a PDF page of the figure, in points: a print size exactly, a size in
    /// pixels at the resolution set (else [`PlotOptions::SCREEN_DPI`] pixels per inch).
    pub fn page_points(&self) -> (f64, f64) {
        match self.figure_size() {
            FigureSize::Print(w, h) => (w.points(), h.points()),
            FigureSize::Pixels(w, h) => {
                let dpi = self.dpi.unwrap_or(PlotOptions::SCREEN_DPI);
                (f64::from(w) * 72.0 / dpi, f64::from(h) * 72.0 / dpi)
            }
        }
    }

    /// The resolution a PNG records: the one set, else [`PlotOptions::DEFAULT_PRINT_DPI`]
    /// for a print size; `None` for a size in pixels without one.
    pub fn png_dpi(&self) -> Option<f64> {
        match (self.dpi, self.figure_size()) {
            (Some(dpi), _) => Some(dpi),
            (None, FigureSize::Print(..)) => Some(PlotOptions::DEFAULT_PRINT_DPI),
            (None, FigureSize::Pixels(..)) => None,
        }
    }

    /// Sets the title; an empty title draws none. Without one, each view has its own title
    /// built from the model's label (for example "Neutrosophic Bézier curve: truth").
    pub fn with_title(mut self, title: impl Into<String>) -> PlotOptions {
        self.title = Some(title.into());
        self
    }

    /// Sets a caption, drawn under the plot and wrapped to the figure width (for example the
    /// source of the data, or an erratum).
    pub fn with_caption(mut self, caption: impl Into<String>) -> PlotOptions {
        self.caption = Some(caption.into());
        self
    }

    /// Sets the 3-D camera azimuth in degrees (default -55).
    pub fn with_azimuth(mut self, degrees: f64) -> PlotOptions {
        self.azimuth = degrees;
        self
    }

    /// Sets the 3-D camera elevation in degrees, in \[-90, 90\] (default 25).
    pub fn with_elevation(mut self, degrees: f64) -> PlotOptions {
        self.elevation = degrees;
        self
    }

    /// Sets azimuth and elevation of the 3-D camera, in degrees.
    pub fn with_camera(self, azimuth: f64, elevation: f64) -> PlotOptions {
        self.with_azimuth(azimuth).with_elevation(elevation)
    }

    /// Sets the number of points at which a curve is evaluated (default 200, evenly spaced in
    /// the parameter, at most [`PlotOptions::MAX_SAMPLES`]), or for a surface the number per
    /// parameter direction (default 40, at most [`PlotOptions::MAX_SURFACE_SAMPLES`]): the
    /// mesh is `samples x samples` points. Models built from samples are drawn as given.
    pub fn with_samples(mut self, samples: usize) -> PlotOptions {
        self.samples = Some(samples);
        self
    }

    /// The canvas width: pixels, or whole points for a print size.
    pub fn width(&self) -> u32 {
        self.canvas().0
    }

    /// The canvas height: pixels, or whole points for a print size.
    pub fn height(&self) -> u32 {
        self.canvas().1
    }

    fn canvas(&self) -> (u32, u32) {
        match self.figure_size() {
            FigureSize::Pixels(w, h) => (w, h),
            FigureSize::Print(w, h) => {
                let pt = |l: Length| {
                    let v = l.points().round();
                    if v.is_finite() && v >= 0.0 && v <= f64::from(u32::MAX) {
                        v as u32
                    } else {
                        u32::MAX
                    }
                };
                (pt(w), pt(h))
            }
        }
    }

    /// The title, if one was set (`Some("")` draws none; the paper style draws none unless
    /// one is set).
    pub fn title(&self) -> Option<&str> {
        match (&self.title, self.style) {
            (None, FigureStyle::Paper) => Some(""),
            (title, _) => title.as_deref(),
        }
    }

    /// The caption, if one was set (`Some("")` draws none; the paper style draws none unless
    /// one is set).
    pub fn caption(&self) -> Option<&str> {
        match (&self.caption, self.style) {
            (None, FigureStyle::Paper) => Some(""),
            (caption, _) => caption.as_deref(),
        }
    }

    /// Camera azimuth in degrees.
    pub fn azimuth(&self) -> f64 {
        self.azimuth
    }

    /// Camera elevation in degrees.
    pub fn elevation(&self) -> f64 {
        self.elevation
    }

    /// Number of curve samples: the one set, else [`PlotOptions::DEFAULT_SAMPLES`].
    pub fn samples(&self) -> usize {
        self.samples.unwrap_or(PlotOptions::DEFAULT_SAMPLES)
    }

    /// Number of surface samples per parameter direction: the one set, else
    /// [`PlotOptions::DEFAULT_SURFACE_SAMPLES`].
    pub fn surface_samples(&self) -> usize {
        self.samples.unwrap_or(PlotOptions::DEFAULT_SURFACE_SAMPLES)
    }

    /// Checks the options for drawing a surface: [`PlotOptions::validate`], and at most
    /// [`PlotOptions::MAX_SURFACE_SAMPLES`] samples per direction.
    ///
    /// # Errors
    /// Those of [`PlotOptions::validate`]; [`PlotError::InvalidSamples`] above the maximum.
    pub fn validate_surface(&self) -> Result<(), PlotError> {
        self.validate()?;
        let n = self.surface_samples();
        if n > PlotOptions::MAX_SURFACE_SAMPLES {
            return Err(PlotError::InvalidSamples {
                samples: n,
                min: PlotOptions::MIN_SAMPLES,
                max: PlotOptions::MAX_SURFACE_SAMPLES,
            });
        }
        Ok(())
    }

    /// Checks every option.
    ///
    /// # Errors
    /// [`PlotError::InvalidSize`], [`PlotError::InvalidSamples`] or
    /// [`PlotError::InvalidCamera`].
    pub fn validate(&self) -> Result<(), PlotError> {
        if let Some(dpi) = self.dpi {
            if !PlotOptions::DPI_RANGE.contains(&dpi) {
                return Err(PlotError::InvalidDpi {
                    dpi,
                    min: *PlotOptions::DPI_RANGE.start(),
                    max: *PlotOptions::DPI_RANGE.end(),
                });
            }
        }
        if let Some((w, h)) = self.print_size() {
            let (cw, ch) = self.canvas();
            let ok = |s: u32| (PlotOptions::MIN_SIDE..=PlotOptions::MAX_SIDE).contains(&s);
            if !(ok(cw) && ok(ch)) {
                return Err(PlotError::InvalidPrintSize {
                    size: format!("{w}x{h}"),
                    min: PlotOptions::MIN_SIDE,
                    max: PlotOptions::MAX_SIDE,
                });
            }
            return self.validate_rest();
        }
        let (w, h) = self.canvas();
        check_size(w, h)?;
        self.validate_rest()
    }

    fn validate_rest(&self) -> Result<(), PlotError> {
        if let Some(&alpha) = self.alphas.iter().find(|a| !(0.0..=1.0).contains(*a)) {
            return Err(PlotError::InvalidAlpha { alpha });
        }
        if !(PlotOptions::MIN_SAMPLES..=PlotOptions::MAX_SAMPLES).contains(&self.samples()) {
            return Err(PlotError::InvalidSamples {
                samples: self.samples(),
                min: PlotOptions::MIN_SAMPLES,
                max: PlotOptions::MAX_SAMPLES,
            });
        }
        if !self.azimuth.is_finite() {
            return Err(PlotError::InvalidCamera {
                angle: "azimuth",
                value: self.azimuth,
                rule: "must be finite",
            });
        }
        if !(self.elevation.is_finite() && (-90.0..=90.0).contains(&self.elevation)) {
            return Err(PlotError::InvalidCamera {
                angle: "elevation",
                value: self.elevation,
                rule: "must be between -90 and 90",
            });
        }
        Ok(())
    }
}

pub(crate) fn check_size(width: u32, height: u32) -> Result<(), PlotError> {
    let ok = |s: u32| (PlotOptions::MIN_SIDE..=PlotOptions::MAX_SIDE).contains(&s);
    if ok(width) && ok(height) {
        Ok(())
    } else {
        Err(PlotError::InvalidSize {
            width,
            height,
            min: PlotOptions::MIN_SIDE,
            max: PlotOptions::MAX_SIDE,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_defaults() {
        let o = PlotOptions::default();
        assert_eq!((o.width(), o.height()), (1600, 1200));
        assert_eq!((o.azimuth(), o.elevation()), (-55.0, 25.0));
        assert_eq!(o.samples(), 200);
        assert_eq!(o.surface_samples(), 40);
        assert_eq!(o.clone().with_samples(12).surface_samples(), 12);
        assert_eq!(o.title(), None);
        assert_eq!(o.validate(), Ok(()));
    }

    #[test]
    fn options_validate_messages() {
        let e = PlotOptions::default()
            .with_size(0, 10)
            .validate()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "image size 0x10 is not supported (each side must be between 64 and 16384 pixels)"
        );
        let e = PlotOptions::default()
            .with_samples(1)
            .validate()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "samples = 1 is not supported (must be between 2 and 100000)"
        );
        let e = PlotOptions::default()
            .with_samples(101)
            .validate_surface()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "samples = 101 is not supported (must be between 2 and 100)"
        );
        let e = PlotOptions::default()
            .with_elevation(95.0)
            .validate()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "camera elevation = 95 degrees is not supported (must be between -90 and 90)"
        );
        let e = PlotOptions::default()
            .with_azimuth(f64::NAN)
            .validate()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "camera azimuth = NaN degrees is not supported (must be finite)"
        );
    }
}
