//! [`FigureRequest`]: the options of a figure, defined once for the command line, Python and
//! the studio (docs/architecture.md, "one definition of every option").

use neutrospline::options::{
    find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind,
};
use neutrospline::DegreeKind;

use crate::error::PlotError;
use crate::options::PlotOptions;
use crate::page::{FigureSize, FigureStyle};
use crate::view::View;

/// The options of a figure as every front end gives them, set by name with
/// [`OptionSet::set`]; [`FigureRequest::plot_options`] checks them into [`PlotOptions`].
///
/// The defaults are [`PlotOptions`]'s: 1600 x 1200 pixels, the camera at azimuth -55 and
/// elevation 25 degrees, the kind's samples (200 along a curve, 40 per direction of a
/// surface), alpha levels 0, 0.5, 1, data coloured by truth; no view (`data` when data is
/// drawn, else `all`), title or caption (each view's own title; the model's description).
///
/// ```
/// use neutrospline::options::{OptionSet, OptionValue};
/// use neutrospline_plot::{FigureRequest, View};
/// let mut request = FigureRequest::default();
/// request.set("view", OptionValue::Text("truth".into()))?;
/// request.set("alpha", OptionValue::Word("0,0.25,1".into()))?;
/// assert_eq!(request.view(false), View::Truth);
/// assert_eq!(request.plot_options().unwrap().alphas(), vec![0.0, 0.25, 1.0]);
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FigureRequest {
    /// `view`: which view; `None` for the default ([`FigureRequest::view`]).
    pub view: Option<View>,
    /// `width` and `height` in pixels, or `size` (pixels or a print size); `None` for the
    /// style's size.
    pub size: Option<FigureSize>,
    /// `dpi`: the resolution of a PNG (its pixels for a print size, and the resolution it
    /// records); `None` for 300 on paper and none for a size in pixels.
    pub dpi: Option<f64>,
    /// `style`: `default` or `paper`.
    pub style: FigureStyle,
    /// `no-title`: draw no title.
    pub no_title: bool,
    /// `no-caption`: draw no caption (not even the model's description).
    pub no_caption: bool,
    /// `title` above the figure; `None` for the view's own, `""` for none.
    pub title: Option<String>,
    /// `caption` under the figure; `None` for the model's description.
    pub caption: Option<String>,
    /// `azimuth`: the 3-D camera's angle around the vertical axis, in degrees.
    pub azimuth: f64,
    /// `elevation`: the 3-D camera's angle above the horizontal plane, in degrees.
    pub elevation: f64,
    /// `samples` along a curve (per direction of a surface's mesh); `None` for the kind's.
    pub samples: Option<usize>,
    /// `alpha`: the alpha levels of the band view.
    pub alpha: Vec<f64>,
    /// `color-by`: the degree that colours data points in the data view.
    pub color_by: DegreeKind,
}

impl Default for FigureRequest {
    /// [`PlotOptions::default`]'s values, no view, title, caption or samples of its own, data
    /// coloured by truth.
    fn default() -> Self {
        let plot = PlotOptions::default();
        FigureRequest {
            view: None,
            size: None,
            dpi: None,
            style: plot.style(),
            no_title: false,
            no_caption: false,
            title: None,
            caption: None,
            azimuth: plot.azimuth(),
            elevation: plot.elevation(),
            samples: None,
            alpha: plot.alphas(),
            color_by: DegreeKind::Truth,
        }
    }
}

impl OptionSet for FigureRequest {
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "view",
            kind: ValueKind::Choice(&View::NAMES),
            value_name: "VIEW",
            help: "Which view to draw (default: data when data points are drawn, else all)",
        },
        OptionSpec {
            name: "width",
            kind: ValueKind::Whole,
            value_name: "PX",
            help: "Width in pixels (the SVG's size too)",
        },
        OptionSpec {
            name: "height",
            kind: ValueKind::Whole,
            value_name: "PX",
            help: "Height in pixels",
        },
        OptionSpec {
            name: "size",
            kind: ValueKind::Text,
            value_name: "WxH",
            help: "Size in pixels (1600x1200) or on paper, with a unit: pt, mm, cm or in \
                   (8.5cmx6cm; the text stays at least 8.5 points)",
        },
        OptionSpec {
            name: "dpi",
            kind: ValueKind::Number,
            value_name: "DPI",
            help: "Resolution of a PNG: its pixels for a size on paper (default 300), and the \
                   resolution the file records",
        },
        OptionSpec {
            name: "style",
            kind: ValueKind::Choice(&FigureStyle::NAMES),
            value_name: "STYLE",
            help: "paper: no title or caption, one column wide (8.5cm x 7cm) unless --size, \
                   text of 8.5 to 10 points",
        },
        OptionSpec {
            name: "no-title",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Draw no title",
        },
        OptionSpec {
            name: "no-caption",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Draw no caption (not even the model's description)",
        },
        OptionSpec {
            name: "title",
            kind: ValueKind::Text,
            value_name: "TEXT",
            help: "Title above the figure (default: the kind of model and the view; \"\" for none)",
        },
        OptionSpec {
            name: "caption",
            kind: ValueKind::Text,
            value_name: "TEXT",
            help: "Caption under the figure (default: the model's description, if it has one)",
        },
        OptionSpec {
            name: "azimuth",
            kind: ValueKind::Number,
            value_name: "DEG",
            help: "3-D camera: angle around the vertical axis, in degrees",
        },
        OptionSpec {
            name: "elevation",
            kind: ValueKind::Number,
            value_name: "DEG",
            help: "3-D camera: angle above the horizontal plane, in degrees",
        },
        OptionSpec {
            name: "samples",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "Points sampled along a curve (surfaces: samples per direction of the mesh; \
                   default 200 for a curve, 40 for a surface)",
        },
        OptionSpec {
            name: "alpha",
            kind: ValueKind::Numbers,
            value_name: "A1,A2,...",
            help: "The alpha levels of the band view, each in [0, 1]",
        },
        OptionSpec {
            name: "color-by",
            kind: ValueKind::Choice(&["truth", "indeterminacy", "falsity"]),
            value_name: "DEGREE",
            help: "The degree that colours the data points in the data view",
        },
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let read = spec.read(&value)?;
        let side = |n: usize| {
            u32::try_from(n).map_err(|_| OptionError::Invalid {
                name: spec.name,
                given: value.to_string(),
                expected: format!(
                    "expected a number of pixels from {} to {}",
                    PlotOptions::MIN_SIDE,
                    PlotOptions::MAX_SIDE
                ),
            })
        };
        match (spec.name, read) {
            ("view", Read::Choice(word)) => {
                self.view =
                    Some(word.parse().unwrap_or_else(|e| {
                        unreachable!("view {word} is one of View::NAMES: {e}")
                    }));
            }
            ("width", Read::Whole(n)) => {
                let (_, height) = self.pixels();
                self.size = Some(FigureSize::Pixels(side(n)?, height));
            }
            ("height", Read::Whole(n)) => {
                let (width, _) = self.pixels();
                self.size = Some(FigureSize::Pixels(width, side(n)?));
            }
            ("size", Read::Text(text)) => {
                let size = text
                    .parse::<FigureSize>()
                    .map_err(|_| OptionError::Invalid {
                        name: spec.name,
                        given: value.to_string(),
                        expected: FigureSize::EXPECTED.to_owned(),
                    })?;
                self.size = Some(size);
            }
            ("dpi", Read::Number(x)) => self.dpi = Some(x),
            ("style", Read::Choice(word)) => {
                self.style = word
                    .parse()
                    .unwrap_or_else(|e| unreachable!("style {word} is a FigureStyle: {e}"));
            }
            ("no-title", Read::Flag(on)) => self.no_title = on,
            ("no-caption", Read::Flag(on)) => self.no_caption = on,
            ("title", Read::Text(text)) => self.title = Some(text),
            ("caption", Read::Text(text)) => self.caption = Some(text),
            ("azimuth", Read::Number(x)) => self.azimuth = x,
            ("elevation", Read::Number(x)) => self.elevation = x,
            ("samples", Read::Whole(n)) => self.samples = Some(n),
            ("alpha", Read::Numbers(levels)) => self.alpha = levels,
            ("color-by", Read::Choice(word)) => {
                self.color_by = word
                    .parse()
                    .unwrap_or_else(|e| unreachable!("degree {word} is a DegreeKind: {e}"));
            }
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        Ok(match spec.name {
            "view" => self.view.map(|v| v.name().to_owned()),
            "width" => Some(self.pixels().0.to_string()),
            "height" => Some(self.pixels().1.to_string()),
            "size" => self.size.map(|s| s.to_string()),
            "dpi" => self.dpi.map(|x| x.to_string()),
            "style" => Some(self.style.name().to_owned()),
            "no-title" => Some(self.no_title.to_string()),
            "no-caption" => Some(self.no_caption.to_string()),
            "title" => self.title.clone(),
            "caption" => self.caption.clone(),
            "azimuth" => Some(self.azimuth.to_string()),
            "elevation" => Some(self.elevation.to_string()),
            "samples" => self.samples.map(|n| n.to_string()),
            "alpha" => Some(
                self.alpha
                    .iter()
                    .map(f64::to_string)
                    .collect::<Vec<_>>()
                    .join(","),
            ),
            "color-by" => Some(self.color_by.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

impl FigureRequest {
    /// The view to draw: the one asked for, else `data` when data points are drawn, else `all`.
    pub fn view(&self, with_data: bool) -> View {
        self.view
            .unwrap_or(if with_data { View::Data } else { View::All })
    }

    /// The plot options of the request, with `caption` standing in for the model's
    /// description when none was asked for.
    ///
    /// # Errors
    /// The [`PlotOptions::validate`] errors: a size, a sample count, an alpha level or a
    /// camera angle out of range.
    pub fn plot_options(&self) -> Result<PlotOptions, PlotError> {
        self.checked(false)
    }

    /// [`FigureRequest::plot_options`] for a figure of a surface: `samples`, when given, is
    /// also held to [`PlotOptions::MAX_SURFACE_SAMPLES`] per direction.
    ///
    /// # Errors
    /// As [`FigureRequest::plot_options`]; [`PlotError::InvalidSamples`] above that.
    pub fn surface_plot_options(&self) -> Result<PlotOptions, PlotError> {
        self.checked(true)
    }

    /// The size in pixels: the one given, else the default (a print size has none; its
    /// canvas is in points).
    fn pixels(&self) -> (u32, u32) {
        match self.size {
            Some(FigureSize::Pixels(w, h)) => (w, h),
            _ => (PlotOptions::DEFAULT_WIDTH, PlotOptions::DEFAULT_HEIGHT),
        }
    }

    fn checked(&self, surface: bool) -> Result<PlotOptions, PlotError> {
        let mut options = PlotOptions::new()
            .with_style(self.style)
            .with_camera(self.azimuth, self.elevation)
            .with_alphas(self.alpha.iter().copied());
        if let Some(size) = self.size {
            options = options.with_figure_size(size);
        }
        if let Some(dpi) = self.dpi {
            options = options.with_dpi(dpi);
        }
        if self.no_title {
            options = options.with_title("");
        }
        if self.no_caption {
            options = options.with_caption("");
        }
        if let Some(n) = self.samples {
            options = options.with_samples(n);
        }
        if let (Some(title), false) = (&self.title, self.no_title) {
            options = options.with_title(title.clone());
        }
        if let (Some(caption), false) = (&self.caption, self.no_caption) {
            options = options.with_caption(caption.clone());
        }
        options.validate()?;
        if surface && self.samples.is_some() {
            options.validate_surface()?;
        }
        Ok(options)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defaults_are_plot_options_defaults() {
        let options = FigureRequest::default().plot_options().unwrap();
        assert_eq!(options, PlotOptions::default());
    }

    #[test]
    fn every_option_round_trips_through_its_text() {
        let mut changed = FigureRequest::default();
        for (name, word) in [
            ("view", "band"),
            ("width", "800"),
            ("height", "600"),
            ("size", "8.5cmx6cm"),
            ("dpi", "600"),
            ("style", "paper"),
            ("no-title", "true"),
            ("no-caption", "true"),
            ("title", "T"),
            ("caption", "C"),
            ("azimuth", "-30.5"),
            ("elevation", "10"),
            ("samples", "12"),
            ("alpha", "0,0.5"),
            ("color-by", "falsity"),
        ] {
            changed.set(name, OptionValue::Word(word.into())).unwrap();
        }
        for spec in FigureRequest::OPTIONS {
            let text = changed.value_text(spec.name).unwrap().unwrap();
            let mut again = FigureRequest::default();
            again.set(spec.name, OptionValue::Word(text)).unwrap();
            assert_eq!(
                again.value_text(spec.name).unwrap(),
                changed.value_text(spec.name).unwrap(),
                "{}",
                spec.name
            );
        }
    }

    #[test]
    fn out_of_range_values_get_the_plot_options_messages() {
        let mut request = FigureRequest::default();
        request.set("elevation", OptionValue::Number(95.0)).unwrap();
        assert_eq!(
            request.plot_options().unwrap_err().to_string(),
            "camera elevation = 95 degrees is not supported (must be between -90 and 90)"
        );
        let mut request = FigureRequest::default();
        request
            .set("alpha", OptionValue::Word("0,1.5".into()))
            .unwrap();
        assert_eq!(
            request.plot_options().unwrap_err().to_string(),
            "alpha level 1.5 is outside [0, 1] (the band view draws alpha-cuts at levels in [0, 1])"
        );
        let error = FigureRequest::default()
            .set("width", OptionValue::Integer(1 << 40))
            .unwrap_err();
        assert_eq!(
            error.to_string(),
            "width = 1099511627776: expected a number of pixels from 64 to 16384"
        );
    }
}
