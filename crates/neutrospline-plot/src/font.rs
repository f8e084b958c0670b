//! The bundled font (DejaVu Sans, regular and bold) and its horizontal metrics.
//!
//! Every figure uses this font only: the SVG names its family (with `sans-serif` as the browser
//! fallback) and the PNG rasterizer loads nothing else, so no output depends on system fonts.
//! Layout measures text with the advance widths read here from the same font files, so legends
//! and labels are sized to the glyphs that are actually drawn (kerning is ignored; it changes
//! widths by a fraction of a percent).

use std::sync::{Arc, OnceLock};

use resvg::usvg::fontdb;

/// The family name of the bundled font, as written in the SVG `font-family` attribute.
pub const FONT_FAMILY: &str = "DejaVu Sans";

/// The `font-family` attribute value: the bundled family, then the generic fallback.
pub(crate) const FONT_FAMILY_CSS: &str = "'DejaVu Sans', sans-serif";

static REGULAR: &[u8] = include_bytes!("../fonts/DejaVuSans.ttf");
static BOLD: &[u8] = include_bytes!("../fonts/DejaVuSans-Bold.ttf");

/// Font database holding only the bundled faces; every generic family resolves to them.
pub(crate) fn database() -> Arc<fontdb::Database> {
    static DB: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = fontdb::Database::new();
        db.load_font_data(REGULAR.to_vec());
        db.load_font_data(BOLD.to_vec());
        db.set_sans_serif_family(FONT_FAMILY);
        db.set_serif_family(FONT_FAMILY);
        db.set_monospace_family(FONT_FAMILY);
        db.set_cursive_family(FONT_FAMILY);
        db.set_fantasy_family(FONT_FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// Width in pixels of `text` set at `size` pixels, regular or bold.
pub(crate) fn text_width(text: &str, size: f64, bold: bool) -> f64 {
    let m = if bold {
        bold_metrics()
    } else {
        regular_metrics()
    };
    text.chars().map(|c| m.advance(c)).sum::<f64>() * size
}

/// The metrics (and font file) of the regular or bold face.
pub(crate) fn metrics(bold: bool) -> &'static Metrics {
    if bold {
        bold_metrics()
    } else {
        regular_metrics()
    }
}

/// The PostScript name of the regular or bold face (as a PDF names the embedded font).
pub(crate) fn postscript_name(bold: bool) -> &'static str {
    if bold {
        "DejaVuSans-Bold"
    } else {
        "DejaVuSans"
    }
}

fn regular_metrics() -> &'static Metrics {
    static M: OnceLock<Metrics> = OnceLock::new();
    M.get_or_init(|| Metrics::parse(REGULAR).unwrap_or_else(Metrics::fallback))
}

fn bold_metrics() -> &'static Metrics {
    static M: OnceLock<Metrics> = OnceLock::new();
    M.get_or_init(|| Metrics::parse(BOLD).unwrap_or_else(Metrics::fallback))
}

/// Advance widths (in em) of the Basic Multilingual Plane, read from `cmap` (format 4),
/// `hmtx`, `hhea` and `head`.
pub(crate) struct Metrics {
    pub(crate) data: &'static [u8],
    pub(crate) units_per_em: f64,
    /// Advance width per glyph id (the last one repeats, as `hmtx` specifies).
    advances: Vec<u16>,
    /// Offset of the format 4 `cmap` subtable, if the font has one.
    cmap4: Option<usize>,
}

pub(crate) fn u16_at(data: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes([*data.get(at)?, *data.get(at + 1)?]))
}

pub(crate) fn u32_at(data: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_be_bytes([
        *data.get(at)?,
        *data.get(at + 1)?,
        *data.get(at + 2)?,
        *data.get(at + 3)?,
    ]))
}

impl Metrics {
    /// Metrics used only if the bundled font could not be read: 0.6 em per character.
    fn fallback() -> Metrics {
        Metrics {
            data: &[],
            units_per_em: 1000.0,
            advances: vec![600],
            cmap4: None,
        }
    }

    /// The offset of table `tag` in the font file.
    pub(crate) fn table(data: &[u8], tag: &[u8; 4]) -> Option<usize> {
        let count = usize::from(u16_at(data, 4)?);
        (0..count).find_map(|i| {
            let rec = 12 + 16 * i;
            (data.get(rec..rec + 4)? == tag).then(|| u32_at(data, rec + 8).map(|o| o as usize))?
        })
    }

    fn parse(data: &'static [u8]) -> Option<Metrics> {
        let head = Self::table(data, b"head")?;
        let hhea = Self::table(data, b"hhea")?;
        let hmtx = Self::table(data, b"hmtx")?;
        let cmap = Self::table(data, b"cmap")?;
        let units_per_em = f64::from(u16_at(data, head + 18)?);
        let n_metrics = usize::from(u16_at(data, hhea + 34)?);
        let advances = (0..n_metrics)
            .map(|g| u16_at(data, hmtx + 4 * g))
            .collect::<Option<Vec<u16>>>()?;
        let n_sub = usize::from(u16_at(data, cmap + 2)?);
        let cmap4 = (0..n_sub).find_map(|i| {
            let rec = cmap + 4 + 8 * i;
            let platform = u16_at(data, rec)?;
            let encoding = u16_at(data, rec + 2)?;
            let offset = cmap + u32_at(data, rec + 4)? as usize;
            let unicode = platform == 0 || (platform == 3 && encoding == 1);
            (unicode && u16_at(data, offset)? == 4).then_some(offset)
        });
        if units_per_em <= 0.0 || advances.is_empty() {
            return None;
        }
        Some(Metrics {
            data,
            units_per_em,
            advances,
            cmap4,
        })
    }

    /// The glyph of `c` (0, the missing glyph, when the font has none).
    pub(crate) fn glyph(&self, c: char) -> u16 {
        self.glyph_checked(c).unwrap_or(0)
    }

    /// The advance width of glyph `g`, in font units.
    pub(crate) fn glyph_advance(&self, g: u16) -> u16 {
        self.advances
            .get(usize::from(g))
            .or(self.advances.last())
            .copied()
            .unwrap_or(0)
    }

    fn glyph_checked(&self, c: char) -> Option<u16> {
        let code = u16::try_from(u32::from(c)).ok()?;
        let t = self.cmap4?;
        let d = self.data;
        let seg_x2 = usize::from(u16_at(d, t + 6)?);
        let ends = t + 14;
        let starts = ends + seg_x2 + 2;
        let deltas = starts + seg_x2;
        let range_offsets = deltas + seg_x2;
        for s in (0..seg_x2).step_by(2) {
            if code > u16_at(d, ends + s)? {
                continue;
            }
            let start = u16_at(d, starts + s)?;
            if code < start {
                return None;
            }
            let delta = u16_at(d, deltas + s)?;
            let ro = usize::from(u16_at(d, range_offsets + s)?);
            if ro == 0 {
                return Some(code.wrapping_add(delta));
            }
            let at = range_offsets + s + ro + 2 * usize::from(code - start);
            let g = u16_at(d, at)?;
            return Some(if g == 0 { 0 } else { g.wrapping_add(delta) });
        }
        None
    }

    fn advance(&self, c: char) -> f64 {
        f64::from(self.glyph_advance(self.glyph(c))) / self.units_per_em
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metrics_reads_bundled_font() {
        let m = regular_metrics();
        assert_eq!(m.units_per_em, 2048.0);
        // DejaVu Sans digits are 1303 units wide; the space 651.
        assert!((m.advance('0') - 1303.0 / 2048.0).abs() < 1e-12);
        assert!((m.advance(' ') - 651.0 / 2048.0).abs() < 1e-12);
        assert!(m.glyph_checked('é').is_some());
        assert!(m.glyph_checked('\u{2212}').is_some());
        assert!(text_width("truth", 10.0, true) > text_width("truth", 10.0, false));
    }

    #[test]
    fn database_has_only_bundled_faces() {
        let db = database();
        assert_eq!(db.len(), 2);
        assert!(db
            .faces()
            .all(|f| f.families.iter().any(|(n, _)| n == FONT_FAMILY)));
    }
}
