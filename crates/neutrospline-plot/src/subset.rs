//! A subset of a TrueType font for embedding in a PDF: the glyphs a figure uses keep their
//! outlines and their glyph ids; every other glyph is left empty.
//!
//! Keeping the ids means the PDF can address glyphs directly (`/CIDToGIDMap /Identity`), and
//! the widths and hinting tables stay valid as they are. The subset holds the tables a PDF
//! reader needs for a CID-keyed TrueType font (`cvt `, `fpgm`, `glyf`, `head`, `hhea`,
//! `hmtx`, `loca`, `maxp`, `prep`); `glyf` has the used glyphs and the glyphs their
//! composites are made of, `loca` is rewritten in the long format.

use std::collections::BTreeSet;

use crate::font::{u16_at, u32_at, Metrics};

/// The tables copied into the subset, in tag order (the order of the table directory).
const TABLES: [&[u8; 4]; 9] = [
    b"cvt ", b"fpgm", b"glyf", b"head", b"hhea", b"hmtx", b"loca", b"maxp", b"prep",
];

/// The bytes of table `tag` of `font`, if it has one.
fn table<'a>(font: &'a [u8], tag: &[u8; 4]) -> Option<&'a [u8]> {
    let count = usize::from(u16_at(font, 4)?);
    (0..count).find_map(|i| {
        let rec = 12 + 16 * i;
        if font.get(rec..rec + 4)? != tag {
            return None;
        }
        let offset = u32_at(font, rec + 8)? as usize;
        let length = u32_at(font, rec + 12)? as usize;
        font.get(offset..offset.checked_add(length)?)
    })
}

/// The byte range of glyph `g` in `glyf`, from `loca` (short or long format).
fn glyph_range(loca: &[u8], long: bool, g: usize) -> Option<(usize, usize)> {
    if long {
        Some((
            u32_at(loca, 4 * g)? as usize,
            u32_at(loca, 4 * g + 4)? as usize,
        ))
    } else {
        Some((
            2 * usize::from(u16_at(loca, 2 * g)?),
            2 * usize::from(u16_at(loca, 2 * g + 2)?),
        ))
    }
}

/// The glyphs a composite glyph is made of (none for a simple glyph).
fn components(glyph: &[u8]) -> Vec<u16> {
    const ARGS_ARE_WORDS: u16 = 0x0001;
    const HAVE_SCALE: u16 = 0x0008;
    const MORE: u16 = 0x0020;
    const XY_SCALE: u16 = 0x0040;
    const TWO_BY_TWO: u16 = 0x0080;
    let mut out = Vec::new();
    let Some(contours) = u16_at(glyph, 0) else {
        return out;
    };
    if contours & 0x8000 == 0 {
        return out;
    }
    let mut at = 10;
    while let (Some(flags), Some(index)) = (u16_at(glyph, at), u16_at(glyph, at + 2)) {
        out.push(index);
        at += 4 + if flags & ARGS_ARE_WORDS != 0 { 4 } else { 2 };
        at += if flags & HAVE_SCALE != 0 {
            2
        } else if flags & XY_SCALE != 0 {
            4
        } else if flags & TWO_BY_TWO != 0 {
            8
        } else {
            0
        };
        if flags & MORE == 0 {
            break;
        }
    }
    out
}

fn checksum(data: &[u8]) -> u32 {
    data.chunks(4).fold(0u32, |sum, chunk| {
        let mut word = [0u8; 4];
        word[..chunk.len()].copy_from_slice(chunk);
        sum.wrapping_add(u32::from_be_bytes(word))
    })
}

/// The subset of the font of `metrics` holding the outlines of `used` (glyph 0, the missing
/// glyph, always), or `None` when the font file cannot be read as TrueType outlines.
pub(crate) fn subset(metrics: &Metrics, used: &BTreeSet<u16>) -> Option<Vec<u8>> {
    let font = metrics.data;
    let head = table(font, b"head")?;
    let maxp = table(font, b"maxp")?;
    let loca = table(font, b"loca")?;
    let glyf = table(font, b"glyf")?;
    let long = u16_at(head, 50)? == 1;
    let count = usize::from(u16_at(maxp, 4)?);

    // The glyphs to keep: the used ones, 0, and every component of a kept composite.
    let mut keep = vec![false; count];
    let mut stack: Vec<u16> = used.iter().copied().chain([0]).collect();
    while let Some(g) = stack.pop() {
        let g = usize::from(g);
        if g >= count || keep[g] {
            continue;
        }
        keep[g] = true;
        let (start, end) = glyph_range(loca, long, g)?;
        stack.extend(components(glyf.get(start..end)?));
    }

    let mut new_glyf = Vec::new();
    let mut new_loca = Vec::with_capacity(4 * (count + 1));
    for (g, &kept) in keep.iter().enumerate() {
        new_loca.extend_from_slice(&(new_glyf.len() as u32).to_be_bytes());
        if kept {
            let (start, end) = glyph_range(loca, long, g)?;
            new_glyf.extend_from_slice(glyf.get(start..end)?);
            while new_glyf.len() % 4 != 0 {
                new_glyf.push(0);
            }
        }
    }
    new_loca.extend_from_slice(&(new_glyf.len() as u32).to_be_bytes());
    let mut new_head = head.to_vec();
    new_head.get_mut(8..12)?.copy_from_slice(&[0; 4]);
    new_head
        .get_mut(50..52)?
        .copy_from_slice(&1u16.to_be_bytes());

    let tables: Vec<(&[u8; 4], Vec<u8>)> = TABLES
        .iter()
        .filter_map(|&tag| {
            let data = match tag {
                b"glyf" => new_glyf.clone(),
                b"loca" => new_loca.clone(),
                b"head" => new_head.clone(),
                _ => table(font, tag)?.to_vec(),
            };
            Some((tag, data))
        })
        .collect();

    let n = tables.len() as u16;
    let entry_selector = 15 - n.leading_zeros() as u16;
    let search_range = 16u16 << entry_selector;
    let mut out = Vec::new();
    out.extend_from_slice(&0x0001_0000u32.to_be_bytes());
    out.extend_from_slice(&n.to_be_bytes());
    out.extend_from_slice(&search_range.to_be_bytes());
    out.extend_from_slice(&entry_selector.to_be_bytes());
    out.extend_from_slice(&(n * 16 - search_range).to_be_bytes());
    let mut offset = 12 + 16 * tables.len();
    for (tag, data) in &tables {
        out.extend_from_slice(*tag);
        out.extend_from_slice(&checksum(data).to_be_bytes());
        out.extend_from_slice(&(offset as u32).to_be_bytes());
        out.extend_from_slice(&(data.len() as u32).to_be_bytes());
        offset += data.len().div_ceil(4) * 4;
    }
    let mut head_at = 0;
    for (tag, data) in &tables {
        if *tag == b"head" {
            head_at = out.len();
        }
        out.extend_from_slice(data);
        while out.len() % 4 != 0 {
            out.push(0);
        }
    }
    let adjustment = 0xB1B0_AFBAu32.wrapping_sub(checksum(&out));
    out.get_mut(head_at + 8..head_at + 12)?
        .copy_from_slice(&adjustment.to_be_bytes());
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::font::metrics;

    /// The subset keeps the used glyphs' bytes and ids, empties the others, and is a
    /// well-formed font file (its checksum adjustment makes the whole file sum to the magic).
    #[test]
    fn subset_keeps_used_glyphs_only() {
        let m = metrics(false);
        let a = m.glyph('a');
        let e_acute = m.glyph('é');
        let used: BTreeSet<u16> = [a, e_acute].into_iter().collect();
        let font = subset(m, &used).unwrap();
        assert!(font.len() < m.data.len() / 4, "{} bytes", font.len());
        assert_eq!(checksum(&font), 0xB1B0_AFBA);
        let loca = table(&font, b"loca").unwrap();
        let glyf = table(&font, b"glyf").unwrap();
        let original_loca = table(m.data, b"loca").unwrap();
        let original_glyf = table(m.data, b"glyf").unwrap();
        let long = u16_at(table(m.data, b"head").unwrap(), 50) == Some(1);
        let bytes = |loca, glyf: &[u8], long, g: u16| {
            let (s, e) = glyph_range(loca, long, usize::from(g)).unwrap();
            glyf[s..e].to_vec()
        };
        for g in [a, e_acute] {
            let kept = bytes(loca, glyf, true, g);
            let original = bytes(original_loca, original_glyf, long, g);
            assert_eq!(kept[..original.len()], original[..]);
            assert!(!original.is_empty());
        }
        // 'é' is a composite of 'e' and the accent: both components are kept.
        let original_e_acute = bytes(original_loca, original_glyf, long, e_acute);
        for c in components(&original_e_acute) {
            assert!(!bytes(loca, glyf, true, c).is_empty(), "component {c}");
        }
        // 'z' is not used: empty.
        assert!(bytes(loca, glyf, true, m.glyph('z')).is_empty());
    }
}
