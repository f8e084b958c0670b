//! The figure's size on paper: lengths with units, sizes in pixels or in print units, the
//! resolution of a raster, and the figure styles.
//!
//! A figure is drawn on a canvas of whole units. A size in pixels (`1600x1200`) makes the
//! canvas that many pixels. A print size (`8.5cmx6cm`) makes the canvas that many PostScript
//! points (1/72 inch), rounded to whole points: the SVG states the size in the unit given
//! (`width="8.5cm"`), a PDF page is exactly that size, and a PNG has `size x dpi` pixels with
//! its resolution written into the file.

use std::fmt;
use std::str::FromStr;

/// A unit of physical length.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LengthUnit {
    /// The PostScript point, 1/72 inch (TeX's `bp`).
    Pt,
    /// The millimetre.
    Mm,
    /// The centimetre.
    Cm,
    /// The inch.
    In,
}

impl LengthUnit {
    /// The units as sizes spell them, in the order of [`LengthUnit::ALL`].
    pub const NAMES: [&'static str; 4] = ["pt", "mm", "cm", "in"];
    /// Every unit.
    pub const ALL: [LengthUnit; 4] = [
        LengthUnit::Pt,
        LengthUnit::Mm,
        LengthUnit::Cm,
        LengthUnit::In,
    ];

    /// Points (1/72 inch) in one of this unit.
    pub fn points(self) -> f64 {
        match self {
            LengthUnit::Pt => 1.0,
            LengthUnit::Mm => 72.0 / 25.4,
            LengthUnit::Cm => 72.0 / 2.54,
            LengthUnit::In => 72.0,
        }
    }

    /// The unit's name (`pt`, `mm`, `cm`, `in`).
    pub fn name(self) -> &'static str {
        match self {
            LengthUnit::Pt => "pt",
            LengthUnit::Mm => "mm",
            LengthUnit::Cm => "cm",
            LengthUnit::In => "in",
        }
    }
}

/// A physical length: a positive number and its unit.
///
/// ```
/// use neutrospline_plot::{Length, LengthUnit};
/// let width = Length::new(8.5, LengthUnit::Cm);
/// assert!((width.points() - 240.94).abs() < 0.01);
/// assert_eq!(width.to_string(), "8.5cm");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Length {
    /// The number of units.
    pub value: f64,
    /// The unit.
    pub unit: LengthUnit,
}

impl Length {
    /// `value` of `unit`.
    pub fn new(value: f64, unit: LengthUnit) -> Length {
        Length { value, unit }
    }

    /// The length in PostScript points (1/72 inch).
    pub fn points(self) -> f64 {
        self.value * self.unit.points()
    }

    /// The length in inches.
    pub fn inches(self) -> f64 {
        self.points() / 72.0
    }
}

impl fmt::Display for Length {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{}", self.value, self.unit.name())
    }
}

/// The size of a figure: pixels, or a print size.
///
/// Parsed from `WIDTHxHEIGHT`, each side a number with an optional unit (`px`, `pt`, `mm`,
/// `cm`, `in`); a side without a unit takes the other side's, and two bare numbers are
/// pixels. Spaces around the `x` are allowed.
///
/// ```
/// use neutrospline_plot::{FigureSize, Length, LengthUnit};
/// assert_eq!("800x600".parse::<FigureSize>(), Ok(FigureSize::Pixels(800, 600)));
/// assert_eq!(
///     "8.5cm x 6cm".parse::<FigureSize>(),
///     Ok(FigureSize::Print(Length::new(8.5, LengthUnit::Cm), Length::new(6.0, LengthUnit::Cm)))
/// );
/// assert_eq!("3.5x2.5in".parse::<FigureSize>().unwrap().to_string(), "3.5inx2.5in");
/// assert!("8.5cmx".parse::<FigureSize>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FigureSize {
    /// Width and height in pixels.
    Pixels(u32, u32),
    /// Width and height on paper.
    Print(Length, Length),
}

impl FigureSize {
    /// What a size must look like, as the error messages say it.
    pub const EXPECTED: &'static str = "expected WIDTHxHEIGHT in pixels or with a unit (px, \
pt, mm, cm, in), for example 1600x1200 or 8.5cmx6cm";
}

impl fmt::Display for FigureSize {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FigureSize::Pixels(w, h) => write!(f, "{w}x{h}"),
            FigureSize::Print(w, h) => write!(f, "{w}x{h}"),
        }
    }
}

/// One side of a size as written: its number and its unit (`None` when bare, `Some(None)`
/// for `px`).
fn side(text: &str) -> Option<(f64, Option<Option<LengthUnit>>)> {
    let text = text.trim();
    let split = text
        .find(|c: char| c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    let (number, unit) = text.split_at(split);
    let value: f64 = number.trim().parse().ok()?;
    if !(value.is_finite() && value > 0.0) {
        return None;
    }
    let unit = match unit.trim().to_ascii_lowercase().as_str() {
        "" => None,
        "px" => Some(None),
        word => Some(Some(
            LengthUnit::ALL.into_iter().find(|u| u.name() == word)?,
        )),
    };
    Some((value, unit))
}

impl FromStr for FigureSize {
    type Err = String;

    fn from_str(text: &str) -> Result<FigureSize, String> {
        let refused = || format!("{text:?}: {}", FigureSize::EXPECTED);
        let lower = text.to_ascii_lowercase();
        // The `x` between the sides (not the one of a `px` unit): the first split whose two
        // sides both read.
        let ((wv, wu), (hv, hu)) = lower
            .match_indices('x')
            .find_map(|(at, _)| Some((side(&lower[..at])?, side(&lower[at + 1..])?)))
            .ok_or_else(refused)?;
        // A side without a unit takes the other's; pixels and print units do not mix.
        let (wu, hu) = match (wu, hu) {
            (Some(a), Some(b)) => (a, b),
            (Some(a), None) | (None, Some(a)) => (a, a),
            (None, None) => (None, None),
        };
        match (wu, hu) {
            (Some(wu), Some(hu)) => Ok(FigureSize::Print(Length::new(wv, wu), Length::new(hv, hu))),
            (None, None) => {
                let whole =
                    |v: f64| (v.fract() == 0.0 && v <= f64::from(u32::MAX)).then_some(v as u32);
                match (whole(wv), whole(hv)) {
                    (Some(w), Some(h)) => Ok(FigureSize::Pixels(w, h)),
                    _ => Err(format!("{text:?}: pixels are whole numbers")),
                }
            }
            _ => Err(format!(
                "{text:?}: give both sides in pixels or both in print units"
            )),
        }
    }
}

/// The look of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum FigureStyle {
    /// A stand-alone figure: a title above, the caption under it, 1600 x 1200 pixels.
    #[default]
    Default,
    /// A figure for a paper: no title and no caption (LaTeX sets them), one column wide
    /// ([`FigureStyle::PAPER_WIDTH`] x [`FigureStyle::PAPER_HEIGHT`]) unless a size is given,
    /// and text of 8.5 to 10 points, the sizes of a paper's footnotes and body text.
    Paper,
}

impl FigureStyle {
    /// The styles as options spell them.
    pub const NAMES: [&'static str; 2] = ["default", "paper"];
    /// The width of a paper figure: one column of a two-column journal page.
    pub const PAPER_WIDTH: Length = Length {
        value: 8.5,
        unit: LengthUnit::Cm,
    };
    /// The height of a paper figure: room for the plot and the legend under it.
    pub const PAPER_HEIGHT: Length = Length {
        value: 7.0,
        unit: LengthUnit::Cm,
    };

    /// The style's name.
    pub fn name(self) -> &'static str {
        match self {
            FigureStyle::Default => "default",
            FigureStyle::Paper => "paper",
        }
    }
}

impl FromStr for FigureStyle {
    type Err = String;

    fn from_str(text: &str) -> Result<FigureStyle, String> {
        match text {
            "default" => Ok(FigureStyle::Default),
            "paper" => Ok(FigureStyle::Paper),
            _ => Err(format!(
                "unknown figure style {text:?} (expected one of {})",
                FigureStyle::NAMES.join(", ")
            )),
        }
    }
}

impl fmt::Display for FigureStyle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_with_units_and_refuse_the_rest() {
        let cm = |w, h| {
            FigureSize::Print(
                Length::new(w, LengthUnit::Cm),
                Length::new(h, LengthUnit::Cm),
            )
        };
        assert_eq!("8.5cmx6cm".parse(), Ok(cm(8.5, 6.0)));
        assert_eq!("8.5CM X 6".parse(), Ok(cm(8.5, 6.0)));
        assert_eq!("8.5 x 6cm".parse(), Ok(cm(8.5, 6.0)));
        assert_eq!("640pxx480".parse(), Ok(FigureSize::Pixels(640, 480)));
        assert_eq!("640px x 480px".parse(), Ok(FigureSize::Pixels(640, 480)));
        for bad in [
            "", "8.5cm", "8.5cmx", "x6cm", "0x5", "-1x5", "2ftx3ft", "8.5x6.5", "nanx1cm",
        ] {
            assert!(bad.parse::<FigureSize>().is_err(), "{bad}");
        }
        assert_eq!(
            "2cmx3in".parse(),
            Ok(FigureSize::Print(
                Length::new(2.0, LengthUnit::Cm),
                Length::new(3.0, LengthUnit::In)
            ))
        );
        assert_eq!(
            "200pxx3in".parse::<FigureSize>().unwrap_err(),
            "\"200pxx3in\": give both sides in pixels or both in print units"
        );
        assert_eq!(
            "8.5x6.5".parse::<FigureSize>().unwrap_err(),
            "\"8.5x6.5\": pixels are whole numbers"
        );
    }

    #[test]
    fn units_convert_to_points() {
        assert_eq!(Length::new(1.0, LengthUnit::In).points(), 72.0);
        assert!((Length::new(2.54, LengthUnit::Cm).points() - 72.0).abs() < 1e-12);
        assert!((Length::new(25.4, LengthUnit::Mm).points() - 72.0).abs() < 1e-12);
        assert_eq!(Length::new(10.0, LengthUnit::Pt).inches(), 10.0 / 72.0);
    }
}
