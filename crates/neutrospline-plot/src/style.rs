//! The style vocabulary of the figures: colours, the stroke and fill of shapes, how text is
//! set, and how numbers are written.
//!
//! A leaf module: it imports nothing from the crate, so the views, the drawing and both
//! encodings (`svg`, `display_list`) take their colours, styles and numbers from here.
//!
//! Numbers (coordinates, lengths, opacities) are written by [`num`] with at most two
//! decimals (trailing zeros removed, `-0` written as `0`); a non-finite number is written as
//! `0`, so no output ever contains `NaN` or `inf`. Both encodings use it, so they place every
//! primitive on the same pixel.

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Color(pub u8, pub u8, pub u8);

impl Color {
    pub(crate) const WHITE: Color = Color(255, 255, 255);

    /// Linear interpolation in sRGB between `self` (at 0) and `other` (at 1).
    pub(crate) fn mix(self, other: Color, t: f64) -> Color {
        let t = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        };
        let f = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * t).round() as u8;
        Color(f(self.0, other.0), f(self.1, other.1), f(self.2, other.2))
    }

    pub(crate) fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

/// Formats a number with at most two decimals, deterministically: `format!("{v:.2}")` (which
/// rounds the exact binary value), trailing zeros and a trailing point removed, `-0` as `0`,
/// and a non-finite number as `0`.
pub(crate) fn num(v: f64) -> String {
    if !v.is_finite() {
        return "0".to_string();
    }
    // Fast path (figures write hundreds of thousands of numbers): hundredths as an integer,
    // when rounding `100 v` cannot differ from rounding the exact decimal expansion of `v`:
    // `100 v` is computed with a relative error below 2^-52, so below 1e9 its absolute error
    // is under 1e-6, and only fractions within that of one half could round differently.
    let scaled = v * 100.0;
    let fraction = scaled - scaled.floor();
    if scaled.abs() < 1e9 && (fraction - 0.5).abs() > 1e-6 {
        let hundredths = scaled.round() as i64;
        if hundredths == 0 {
            return "0".to_string();
        }
        let (whole, cents) = (hundredths.abs() / 100, hundredths.abs() % 100);
        let sign = if hundredths < 0 { "-" } else { "" };
        return match (cents / 10, cents % 10) {
            (0, 0) => format!("{sign}{whole}"),
            (tenths, 0) => format!("{sign}{whole}.{tenths}"),
            _ => format!("{sign}{whole}.{cents:02}"),
        };
    }
    num_by_format(v)
}

/// Appends `points` to `out` as `x,y` pairs written by [`num`], the pairs separated by
/// `separator` (a space in an SVG `points` attribute, a comma in a flat JSON list).
pub(crate) fn write_points(out: &mut String, points: &[(f64, f64)], separator: char) {
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            out.push(separator);
        }
        out.push_str(&num(p.0));
        out.push(',');
        out.push_str(&num(p.1));
    }
}

/// [`num`] the slow way, which defines it: `format!("{v:.2}")`, trailing zeros and a trailing
/// point removed, `-0` as `0`.
fn num_by_format(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".to_string()
    } else {
        s
    }
}

/// Stroke and fill of a shape.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Style {
    pub stroke: Option<Color>,
    pub stroke_width: f64,
    pub dash: Option<[f64; 2]>,
    pub fill: Option<Color>,
    pub fill_opacity: f64,
    pub stroke_opacity: f64,
    /// Round caps and joins (else butt caps, miter joins).
    pub round: bool,
    pub class: Option<String>,
}

impl Style {
    pub(crate) fn stroke(color: Color, width: f64) -> Style {
        Style {
            stroke: Some(color),
            stroke_width: width,
            dash: None,
            fill: None,
            fill_opacity: 1.0,
            stroke_opacity: 1.0,
            round: true,
            class: None,
        }
    }

    pub(crate) fn fill(color: Color) -> Style {
        Style {
            stroke: None,
            stroke_width: 0.0,
            dash: None,
            fill: Some(color),
            fill_opacity: 1.0,
            stroke_opacity: 1.0,
            round: true,
            class: None,
        }
    }

    pub(crate) fn with_fill(mut self, color: Color) -> Style {
        self.fill = Some(color);
        self
    }

    pub(crate) fn with_dash(mut self, on: f64, off: f64) -> Style {
        self.dash = Some([on, off]);
        self
    }

    pub(crate) fn with_fill_opacity(mut self, a: f64) -> Style {
        self.fill_opacity = a;
        self
    }

    pub(crate) fn square(mut self) -> Style {
        self.round = false;
        self
    }

    pub(crate) fn with_class(mut self, class: &str) -> Style {
        self.class = Some(class.to_string());
        self
    }
}

/// Horizontal alignment of a text run relative to its anchor point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Anchor {
    Start,
    Middle,
    End,
}

/// How a text run is set.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TextStyle {
    pub size: f64,
    pub bold: bool,
    pub color: Color,
    pub anchor: Anchor,
    /// Rotation in degrees about the anchor point (negative is counter-clockwise on screen).
    pub rotate: f64,
    /// Width of a white halo drawn behind the glyphs (0 for none).
    pub halo: f64,
    pub class: Option<String>,
}

impl TextStyle {
    pub(crate) fn new(size: f64, color: Color) -> TextStyle {
        TextStyle {
            size,
            bold: false,
            color,
            anchor: Anchor::Start,
            rotate: 0.0,
            halo: 0.0,
            class: None,
        }
    }

    pub(crate) fn bold(mut self) -> TextStyle {
        self.bold = true;
        self
    }

    pub(crate) fn anchor(mut self, anchor: Anchor) -> TextStyle {
        self.anchor = anchor;
        self
    }

    pub(crate) fn rotate(mut self, degrees: f64) -> TextStyle {
        self.rotate = degrees;
        self
    }

    pub(crate) fn halo(mut self, width: f64) -> TextStyle {
        self.halo = width;
        self
    }

    pub(crate) fn with_class(mut self, class: &str) -> TextStyle {
        self.class = Some(class.to_string());
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn num_formats_two_decimals() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.234), "1.23");
        assert_eq!(num(1.5), "1.5");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-2.0), "-2");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(f64::INFINITY), "0");
        assert_eq!(num(100.0), "100");
        assert_eq!(num(-0.004), "0");
        assert_eq!(num(-0.005), "-0.01");
        assert_eq!(num(0.125), "0.12");
        assert_eq!(num(-12.34), "-12.34");
        assert_eq!(num(1e12 + 0.25), "1000000000000.25");
    }

    /// The fast path agrees with `format!("{v:.2}")` trimmed, on numbers of every size and on
    /// the ties and near-ties of the rounding.
    #[test]
    fn num_matches_the_formatter() {
        let slow = num_by_format;
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..200_000 {
            let r = next();
            let magnitude = 10f64.powi((r % 14) as i32 - 4);
            let unit = (next() >> 11) as f64 / (1u64 << 53) as f64;
            let v = (unit - 0.5) * magnitude;
            assert_eq!(num(v), slow(v), "{v:e}");
            // Ties in hundredths: x.xx5 and its neighbours.
            let tie = ((next() % 2_000_000) as f64 - 1_000_000.0 + 0.5) / 100.0;
            for w in [
                tie,
                f64::from_bits(tie.to_bits() + 1),
                f64::from_bits(tie.to_bits() - 1),
            ] {
                assert_eq!(num(w), slow(w), "{w:e}");
            }
        }
    }

    #[test]
    fn points_with_either_separator() {
        let mut out = String::new();
        write_points(&mut out, &[(0.0, -1.005), (2.5, 1e-3)], ' ');
        assert_eq!(out, "0,-1 2.5,0");
        out.clear();
        write_points(&mut out, &[(1.0, 2.0), (3.25, 4.0)], ',');
        assert_eq!(out, "1,2,3.25,4");
        out.clear();
        write_points(&mut out, &[], ',');
        assert_eq!(out, "");
    }

    #[test]
    fn color_mix_endpoints() {
        let a = Color(0, 0, 0);
        let b = Color(200, 100, 50);
        assert_eq!(a.mix(b, 0.0), a);
        assert_eq!(a.mix(b, 1.0), b);
        assert_eq!(a.mix(b, 0.5), Color(100, 50, 25));
    }
}
