//! The groups of a DXF file: code / value pairs of its text.

/// One group: its code, its value and the line of its code (1-based).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Group<'a> {
    pub code: u16,
    pub value: &'a str,
    pub line: usize,
}

/// The groups of a DXF text: alternate lines of a group code (an integer, spaces allowed
/// around it) and a value (`\r\n` line ends allowed), up to the `0 EOF` group that ends the
/// file. After it, blank lines and DOS end-of-file bytes (0x1A) are what programs write
/// (Inkscape's R12 files end with a blank line) and are passed over; anything else there is
/// not read, as CAD programs and ezdxf do (a file with data appended after its end), and the
/// second value is a warning that says so. A file without `0 EOF` may end with 0x1A bytes.
///
/// # Errors
/// A line and a message for a group code that is not an integer or a code without a value.
#[allow(clippy::type_complexity)]
pub(crate) fn groups(text: &str) -> Result<(Vec<Group<'_>>, Option<String>), (usize, String)> {
    let mut lines: Vec<&str> = text.lines().collect();
    let end = lines
        .chunks_exact(2)
        .position(|pair| pair[0].trim() == "0" && pair[1].trim() == "EOF");
    let mut warning = None;
    match end {
        Some(k) => {
            let after = 2 * k + 2;
            if let Some(extra) = lines[after..].iter().position(|line| {
                !line
                    .trim_matches(|c: char| c.is_whitespace() || c == '\u{1a}')
                    .is_empty()
            }) {
                let left = lines.len() - after - extra;
                warning = Some(format!(
                    "line {}: the file goes on after its end (`0 EOF` at line {}): the {left} \
                     line{} from there on {} not read, as CAD programs do",
                    after + extra + 1,
                    after - 1,
                    if left == 1 { "" } else { "s" },
                    if left == 1 { "is" } else { "are" },
                ));
            }
            lines.truncate(after);
        }
        None => {
            // A DOS end-of-file byte ends the text.
            while lines.last().is_some_and(|line| {
                line.trim_end_matches('\u{1a}').is_empty() && line.contains('\u{1a}')
            }) {
                lines.pop();
            }
            if let Some(last) = lines.last_mut() {
                *last = last.trim_end_matches('\u{1a}');
            }
        }
    }
    if !lines.len().is_multiple_of(2) {
        return Err((
            lines.len(),
            format!(
                "group code `{}` has no value (the file ends)",
                lines[lines.len() - 1].trim()
            ),
        ));
    }
    lines
        .chunks_exact(2)
        .enumerate()
        .map(|(k, pair)| {
            let line = 2 * k + 1;
            let code = pair[0].trim().parse::<u16>().map_err(|_| {
                (
                    line,
                    format!(
                        "group code `{}` is not an integer from 0 to 1071",
                        pair[0].trim()
                    ),
                )
            })?;
            Ok(Group {
                code,
                value: pair[1],
                line,
            })
        })
        .collect::<Result<Vec<_>, _>>()
        .map(|groups| (groups, warning))
}

/// The upper halves (bytes 0x80 to 0xFF) of the DOS code pages 437 and 850, which
/// `encoding_rs` does not have, as Python's codecs give them
/// (`bytes(range(128, 256)).decode("cp437")`, `... "cp850"`).
const DOS437: &str = "ÇüéâäàåçêëèïîìÄÅÉæÆôöòûùÿÖÜ¢£¥₧ƒáíóúñÑªº¿⌐¬½¼¡«»░▒▓│┤╡╢╖╕╣║╗╝╜╛┐└┴┬├─┼╞╟╚╔╩╦╠═╬╧╨╤╥╙╘╒╓╫╪┘┌█▄▌▐▀αßΓπΣσµτΦΘΩδ∞φε∩≡±≥≤⌠⌡÷≈°∙·√ⁿ²■\u{a0}";
const DOS850: &str = "ÇüéâäàåçêëèïîìÄÅÉæÆôöòûùÿÖÜø£Ø×ƒáíóúñÑªº¿®¬½¼¡«»░▒▓│┤ÁÂÀ©╣║╗╝¢¥┐└┴┬├─┼ãÃ╚╔╩╦╠═╬¤ðÐÊËÈıÍÎÏ┘┌█▄¦Ì▀ÓßÔÒõÕµþÞÚÛÙýÝ¯´\u{ad}±‗¾¶§÷¸°¨·¹³²■\u{a0}";

/// A DXF code page (`$DWGCODEPAGE`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum CodePage {
    Encoding(&'static encoding_rs::Encoding),
    /// A DOS code page by its upper half.
    Dos(&'static str),
}

/// The code page of a `$DWGCODEPAGE` value (case-insensitive): `ANSI_874`, `ANSI_932`
/// (Shift_JIS), `ANSI_936` (GBK), `ANSI_949` (EUC-KR), `ANSI_950` (Big5), `ANSI_1250` to
/// `ANSI_1258` (windows-125x), `DOS437`, `DOS850`, `DOS866`, `ISO8859-1` to `-15` (also
/// written `ISO8859_n`), `KOI8-R`, `MACINTOSH`, `UTF-8`; `ASCII` reads as windows-1252 (its
/// superset); `None` for any other.
pub(super) fn code_page(name: &str) -> Option<CodePage> {
    let upper = name.trim().to_ascii_uppercase().replace('-', "_");
    let label = match upper.as_str() {
        "DOS437" => return Some(CodePage::Dos(DOS437)),
        "DOS850" => return Some(CodePage::Dos(DOS850)),
        "DOS866" => "ibm866".to_owned(),
        "ASCII" => "windows-1252".to_owned(),
        "ANSI_874" => "windows-874".to_owned(),
        "ANSI_932" => "shift_jis".to_owned(),
        "ANSI_936" => "gbk".to_owned(),
        "ANSI_949" => "euc-kr".to_owned(),
        "ANSI_950" => "big5".to_owned(),
        "KOI8_R" => "koi8-r".to_owned(),
        "MACINTOSH" => "macintosh".to_owned(),
        "UTF_8" | "UTF8" => "utf-8".to_owned(),
        other => {
            if let Some(n) = other.strip_prefix("ANSI_") {
                format!("windows-{n}")
            } else if let Some(n) = other.strip_prefix("ISO8859_") {
                format!("iso-8859-{n}")
            } else {
                return None;
            }
        }
    };
    encoding_rs::Encoding::for_label(label.as_bytes()).map(CodePage::Encoding)
}

impl CodePage {
    /// `bytes` decoded (a malformed sequence becomes U+FFFD).
    pub fn decode(self, bytes: &[u8]) -> String {
        match self {
            CodePage::Encoding(encoding) => {
                encoding.decode_without_bom_handling(bytes).0.into_owned()
            }
            CodePage::Dos(upper) => {
                let high: Vec<char> = upper.chars().collect();
                bytes
                    .iter()
                    .map(|&b| {
                        if b < 0x80 {
                            char::from(b)
                        } else {
                            high[usize::from(b - 0x80)]
                        }
                    })
                    .collect()
            }
        }
    }
}

/// The value of the header variable `$DWGCODEPAGE` in the raw bytes of a text file: the
/// value line of the group after the line `$DWGCODEPAGE` (the header is ASCII).
fn declared_code_page(bytes: &[u8]) -> Option<String> {
    let key = b"$DWGCODEPAGE";
    let at = bytes.windows(key.len()).position(|w| w == key)?;
    let rest = &bytes[at + key.len()..];
    let mut lines = rest.split(|&b| b == b'\n').skip(1);
    let code = lines.next()?;
    let value = lines.next()?;
    (String::from_utf8_lossy(code).trim() == "3")
        .then(|| String::from_utf8_lossy(value).trim().to_owned())
}

/// The text of a DXF file: its bytes as UTF-8 when they are (DXF R2007 and later write UTF-8;
/// an ASCII file is UTF-8 too), otherwise decoded by the code page of its `$DWGCODEPAGE`. A
/// file that is not UTF-8 and names no code page, or one this reader does not know, is read
/// as windows-1252 (the most common) with a warning.
pub(super) fn decode_text(bytes: &[u8]) -> (std::borrow::Cow<'_, str>, Option<String>) {
    if let Ok(text) = std::str::from_utf8(bytes) {
        return (text.into(), None);
    }
    let declared = declared_code_page(bytes);
    match declared.as_deref().and_then(code_page) {
        Some(page) => (page.decode(bytes).into(), None),
        None => {
            let fallback = CodePage::Encoding(encoding_rs::WINDOWS_1252);
            let warning = match declared {
                Some(name) => format!("the code page `{name}` ($DWGCODEPAGE) is not one this reader knows: the text is read as windows-1252"),
                None => "the file is not UTF-8 and names no code page ($DWGCODEPAGE): the text is read as windows-1252".to_owned(),
            };
            (fallback.decode(bytes).into(), Some(warning))
        }
    }
}

/// The groups of a binary file as (code, text) pairs, with a warning about its code page.
pub(super) type BinaryGroups = (Vec<(u16, String)>, Option<String>);

/// The sentinel that starts a binary DXF file.
pub(super) const BINARY_START: &[u8] = b"AutoCAD Binary DXF\r\n\x1a\0";

/// A value of a binary DXF group before its text is decoded.
enum Raw {
    Text(Vec<u8>),
    Number(String),
}

/// The groups of a binary DXF file (AutoCAD's DXF reference, "Binary DXF Files"): after the
/// sentinel `AutoCAD Binary DXF\r\n\x1a\0`, each group is its code (1 byte in R12 files, 255
/// followed by a 2-byte code for codes above 254; 2 bytes little-endian in R13 and later,
/// told apart by the first group, `0 SECTION`) and its value, typed by the code's range:
/// strings end with a 0 byte (codes 0-9, 100-109, 300-309, 320-369, 390-399, 410-419,
/// 430-439, 470-481, 999, 1000-1003, 1005-1009), binary chunks have a length byte (310-319,
/// 1004), reals are 8-byte doubles (10-59, 110-149, 210-239, 460-469, 1010-1059), integers
/// 2 bytes (60-79, 170-179, 270-289, 370-389, 400-409, 1060-1070), 4 bytes (90-99, 420-429,
/// 440-459, 1071), 8 bytes (160-169), booleans 1 byte (290-299). The groups are returned as
/// text, each real in its shortest round-trip form (the same number), strings decoded by the
/// file's `$DWGCODEPAGE` (UTF-8 from R2007), and numbered as the lines of the same groups in
/// an ASCII file (group k's code on line 2k + 1) for the messages.
///
/// # Errors
/// The position and a message for a group cut short or of a code outside every range.
pub(super) fn binary_groups(bytes: &[u8]) -> Result<BinaryGroups, (usize, String)> {
    let body = &bytes[BINARY_START.len().min(bytes.len())..];
    let wide = body.starts_with(b"\0\0SECTION");
    let mut raw: Vec<(u16, Raw)> = Vec::new();
    let mut at = 0;
    let cut = |k: usize| {
        (
            2 * k + 1,
            format!("the binary group {} is cut short (the file ends)", k + 1),
        )
    };
    let take = |at: &mut usize, n: usize, k: usize| -> Result<&[u8], (usize, String)> {
        let s = body.get(*at..*at + n).ok_or_else(|| cut(k))?;
        *at += n;
        Ok(s)
    };
    while at < body.len() {
        let k = raw.len();
        let code = if wide {
            let b = take(&mut at, 2, k)?;
            u16::from_le_bytes([b[0], b[1]])
        } else {
            let b = take(&mut at, 1, k)?[0];
            if b == 255 {
                let b = take(&mut at, 2, k)?;
                u16::from_le_bytes([b[0], b[1]])
            } else {
                u16::from(b)
            }
        };
        let value = match code {
            0..=9
            | 100..=109
            | 300..=309
            | 320..=369
            | 390..=399
            | 410..=419
            | 430..=439
            | 470..=481
            | 999
            | 1000..=1003
            | 1005..=1009 => {
                let end = body[at..]
                    .iter()
                    .position(|&b| b == 0)
                    .ok_or_else(|| cut(k))?;
                let text = body[at..at + end].to_vec();
                at += end + 1;
                Raw::Text(text)
            }
            310..=319 | 1004 => {
                let n = usize::from(take(&mut at, 1, k)?[0]);
                let chunk = take(&mut at, n, k)?;
                Raw::Number(chunk.iter().map(|b| format!("{b:02X}")).collect())
            }
            10..=59 | 110..=149 | 210..=239 | 460..=469 | 1010..=1059 => {
                let b = take(&mut at, 8, k)?;
                let x = f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]);
                Raw::Number(format!("{x}"))
            }
            60..=79 | 170..=179 | 270..=289 | 370..=389 | 400..=409 | 1060..=1070 => {
                let b = take(&mut at, 2, k)?;
                Raw::Number(i16::from_le_bytes([b[0], b[1]]).to_string())
            }
            90..=99 | 420..=429 | 440..=459 | 1071 => {
                let b = take(&mut at, 4, k)?;
                Raw::Number(i32::from_le_bytes([b[0], b[1], b[2], b[3]]).to_string())
            }
            160..=169 => {
                let b = take(&mut at, 8, k)?;
                Raw::Number(
                    i64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]])
                        .to_string(),
                )
            }
            290..=299 => Raw::Number(take(&mut at, 1, k)?[0].to_string()),
            _ => {
                return Err((
                    2 * k + 1,
                    format!(
                        "binary group {}: group code {code} is not one of the DXF reference's",
                        k + 1
                    ),
                ))
            }
        };
        let end = code == 0 && matches!(&value, Raw::Text(t) if t == b"EOF");
        raw.push((code, value));
        if end {
            break;
        }
    }
    let declared = raw.windows(2).find_map(|w| match (&w[0], &w[1]) {
        ((9, Raw::Text(name)), (3, Raw::Text(page))) if name == b"$DWGCODEPAGE" => {
            Some(String::from_utf8_lossy(page).trim().to_owned())
        }
        _ => None,
    });
    let all_utf8 = raw.iter().all(|(_, v)| match v {
        Raw::Text(t) => std::str::from_utf8(t).is_ok(),
        Raw::Number(_) => true,
    });
    let mut warning = None;
    let page = if all_utf8 {
        CodePage::Encoding(encoding_rs::UTF_8)
    } else {
        match declared.as_deref().and_then(code_page) {
            Some(page) => page,
            None => {
                warning = Some(format!(
                    "the code page {} is not one this reader knows: the text is read as windows-1252",
                    declared.map_or("(none named)".to_owned(), |d| format!("`{d}` ($DWGCODEPAGE)"))
                ));
                CodePage::Encoding(encoding_rs::WINDOWS_1252)
            }
        }
    };
    let groups = raw
        .into_iter()
        .map(|(code, v)| {
            let text = match v {
                Raw::Text(t) => page.decode(&t),
                Raw::Number(n) => n,
            };
            (code, text)
        })
        .collect();
    Ok((groups, warning))
}
