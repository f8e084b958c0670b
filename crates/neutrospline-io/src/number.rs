//! Numbers as text: the shortest form that reads back to the same `f64`.
//!
//! [`format_number`] and [`push_number`] write the form of Rust's `Display` (never an
//! exponent, so that every CSV or JSON reader parses it), for messages and numeric tables. The
//! model writers use [`file_number`], Ryu's form, which switches to an exponent for very large
//! and very small magnitudes (`1e-300` rather than three hundred zeros) and always reads as a
//! float in TOML and JSON (`1.0`, not `1`).

/// A number in the shortest form that reads back to the same `f64`, in the form of Rust's
/// `Display` (never an exponent, so every CSV or JSON reader parses it); see [`push_number`].
pub fn format_number(v: f64) -> String {
    let mut text = Vec::with_capacity(24);
    push_number(&mut text, v);
    // `push_number` writes ASCII only.
    String::from_utf8(text).unwrap_or_default()
}

/// Appends [`format_number`]`(v)` to `out`: the form of `format!("{v}")` (no exponent, no trailing
/// `.0`, `-0` for negative zero) from Ryu's shortest round-trip digits, several times as fast.
/// The digits are `Display`'s except in an exact tie between two shortest candidates (such as
/// `2^-25 = 0.0000000298023223876953125`), which Ryu rounds to even where `Display` rounds up;
/// both read back to the same `f64`.
pub fn push_number(out: &mut Vec<u8>, v: f64) {
    if !v.is_finite() {
        out.extend_from_slice(format!("{v}").as_bytes());
        return;
    }
    let mut buffer = ryu::Buffer::new();
    // Ryu writes `[-]DIGITS[.DIGITS][eEXP]`: split it into the significant digits and the
    // position of the decimal point relative to their start.
    let text = buffer.format_finite(v).as_bytes();
    let (negative, text) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
        Some(e) => (&text[..e], parse_exponent(&text[e + 1..])),
        // Without an exponent (1e-5 <= |v| < 1e16) Ryu's form is `Display`'s, but for the
        // `.0` of a whole number.
        None => {
            if negative {
                out.push(b'-');
            }
            out.extend_from_slice(text.strip_suffix(b".0").unwrap_or(text));
            return;
        }
    };
    let mut digits = [0u8; 24];
    let mut count = 0usize;
    let mut point = None;
    for &b in mantissa {
        if b == b'.' {
            point = Some(count);
        } else {
            digits[count] = b;
            count += 1;
        }
    }
    let mut point = point.unwrap_or(count) as i32 + exponent;
    let mut digits = &digits[..count];
    while let Some((b'0', rest)) = digits.split_first() {
        digits = rest;
        point -= 1;
    }
    while let Some((b'0', rest)) = digits.split_last() {
        digits = rest;
    }
    if negative {
        out.push(b'-');
    }
    if digits.is_empty() {
        out.push(b'0');
    } else if point <= 0 {
        out.extend_from_slice(b"0.");
        out.extend(std::iter::repeat_n(b'0', point.unsigned_abs() as usize));
        out.extend_from_slice(digits);
    } else {
        let point = point as usize;
        if point >= digits.len() {
            out.extend_from_slice(digits);
            out.extend(std::iter::repeat_n(b'0', point - digits.len()));
        } else {
            out.extend_from_slice(&digits[..point]);
            out.push(b'.');
            out.extend_from_slice(&digits[point..]);
        }
    }
}

/// `v` rounded to the precision a computation at magnitude `scale` justifies, in shortest
/// form: to 15 significant digits of `scale` (the decimal place `10^(floor(log10 scale) - 14)`),
/// trailing zeros dropped, `-0` written `0`. A value computed in 64-bit floats from inputs of
/// magnitude up to `scale` carries an error of a few units in the 16th or 17th digit of
/// `scale`; those digits are noise, and rounding them away prints what the inputs said. So
/// with `scale` 1 (degrees, which are in [0, 1]) the intuitionistic indeterminacy
/// `1 - 0.6 - 0.3 = 0.09999999999999998` prints `0.1`, and `1 - 0.7 - 0.3 = 5.55e-17` prints
/// `0`. A `scale` of 0 or one that is not finite is `|v|`'s own. Not finite `v`: as `Display`.
///
/// ```
/// use neutrospline_io::format_justified;
/// assert_eq!(format_justified(1.0 - 0.6 - 0.3, 1.0), "0.1");
/// assert_eq!(format_justified(1.0 - 0.7 - 0.3, 1.0), "0");
/// assert_eq!(format_justified(0.1 + 0.2, 1.0), "0.3");
/// assert_eq!(format_justified(2.0 / 3.0, 1.0), "0.66666666666667");
/// assert_eq!(format_justified(2.0 / 3.0, 1000.0), "0.66666666667");
/// assert_eq!(format_justified(2.0 / 3.0e6, 1e-5), "0.0000006666666666667");
/// ```
pub fn format_justified(v: f64, scale: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let scale = if scale.is_finite() && scale > 0.0 {
        scale
    } else {
        v.abs()
    };
    if scale == 0.0 {
        return "0".to_owned();
    }
    let decimals = 14 - decimal_exponent(scale);
    if decimals < 0 {
        // Beyond 1e15: 15 significant digits of v itself.
        let rounded: f64 = format!("{v:.14e}").parse().unwrap_or(v);
        return format_number(rounded);
    }
    let decimals = decimals.unsigned_abs() as usize;
    let text = format!("{v:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        &text
    };
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// `v` with `digits` significant digits (at least 1), positional (never an exponent), trailing
/// zeros kept so that the digits show (`0.100` for 3 digits); zero is `0.00`, never `-0.00`.
/// Correctly rounded (the decimal nearest `v`'s exact binary value; an exact tie such as
/// 4.625 to 3 digits goes to the even digit, 4.62, as C's `printf` does).
///
/// ```
/// use neutrospline_io::format_significant;
/// assert_eq!(format_significant(0.1, 3), "0.100");
/// assert_eq!(format_significant(-2.0 / 3.0, 4), "-0.6667");
/// assert_eq!(format_significant(12345.0, 3), "12300");
/// assert_eq!(format_significant(0.000123456, 2), "0.00012");
/// assert_eq!(format_significant(-0.0, 3), "0.00");
/// assert_eq!(format_significant(9.996, 3), "10.0");
/// ```
pub fn format_significant(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let precision = digits.max(1) - 1;
    let text = format!("{v:.precision$e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let exponent: i64 = exponent.parse().unwrap_or(0);
    let negative = mantissa.starts_with('-');
    let figures: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let mut out = String::new();
    if negative && figures.bytes().any(|b| b != b'0') {
        out.push('-');
    }
    if exponent >= 0 {
        let whole = usize::try_from(exponent).unwrap_or(0) + 1;
        if whole >= figures.len() {
            out.push_str(&figures);
            out.extend(std::iter::repeat_n('0', whole - figures.len()));
        } else {
            out.push_str(&figures[..whole]);
            out.push('.');
            out.push_str(&figures[whole..]);
        }
    } else {
        out.push_str("0.");
        out.extend(std::iter::repeat_n(
            '0',
            usize::try_from(-exponent - 1).unwrap_or(0),
        ));
        out.push_str(&figures);
    }
    out
}

/// The decimal exponent of a positive finite `v`: `floor(log10 v)`, exactly (read from the
/// correctly rounded scientific form, so that 1000 is 3 and 999.9999999999999 is 2).
fn decimal_exponent(v: f64) -> i32 {
    let text = format!("{v:e}");
    text.split_once('e')
        .and_then(|(_, e)| e.parse().ok())
        .unwrap_or(0)
}

/// The decimal exponent after Ryu's `e` (at most three digits, optionally negative).
fn parse_exponent(text: &[u8]) -> i32 {
    let (sign, digits) = match text.split_first() {
        Some((b'-', rest)) => (-1, rest),
        _ => (1, text),
    };
    sign * digits
        .iter()
        .fold(0i32, |acc, &d| acc * 10 + i32::from(d - b'0'))
}

/// A number in a written model file: Ryu's shortest round-trip form, always with a fraction or
/// an exponent (`1.0`, `0.1`, `-0.0`, `1e-300`, `1.7976931348623157e308`), so that TOML and
/// JSON readers see a float, and every reader gets the same `f64` back.
pub(crate) fn file_number(out: &mut String, v: f64) {
    debug_assert!(v.is_finite(), "models hold finite numbers only");
    let mut buffer = ryu::Buffer::new();
    out.push_str(buffer.format(v));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `push_number` against the standard library's `Display`, the independent reference: the
    /// special values, every power of ten and of two, and a million seeded random bit patterns
    /// (all exponents, subnormals included).
    #[test]
    fn push_number_is_display() {
        let mut values = vec![
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.3,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            f64::EPSILON,
            5e-324,
            -5e-324,
            // The largest subnormal.
            f64::from_bits(0x000F_FFFF_FFFF_FFFF),
            9007199254740993.0,
            123456789012345680000.0,
            1e15,
            1e16,
            1e17,
            1e-5,
            1e-6,
            1e-7,
        ];
        values.extend((-324..=308).map(|e| format!("1e{e}").parse::<f64>().unwrap()));
        values.extend((-1074..=1023).map(|e| 2f64.powi(e)));
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..1_000_000 {
            // xorshift64*
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            let bits = state.wrapping_mul(0x2545_F491_4F6C_DD1D);
            values.push(f64::from_bits(bits));
        }
        let mut text = Vec::new();
        for v in values.into_iter().filter(|v| v.is_finite()) {
            text.clear();
            push_number(&mut text, v);
            let ours = std::str::from_utf8(&text).unwrap();
            let display = format!("{v}");
            if ours != display {
                assert_tie(v, ours, &display);
            }
        }
    }

    /// `ours` and `display` are the two shortest decimals nearest `v`, equally near: they differ
    /// by one unit in the last digit, ours ends in an even digit, and `v`'s exact decimal
    /// expansion is the lower one with a 5 appended.
    fn assert_tie(v: f64, ours: &str, display: &str) {
        assert_eq!(ours.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{v:e}");
        assert_eq!(ours.len(), display.len(), "{v:e}: {ours} vs {display}");
        let (o, d) = (ours.as_bytes(), display.as_bytes());
        let last = o.len() - 1;
        assert_eq!(o[..last], d[..last], "{v:e}: {ours} vs {display}");
        assert_eq!(
            (o[last] - b'0') % 2,
            0,
            "{v:e}: {ours} does not end in an even digit"
        );
        assert_eq!(d[last] - o[last], 1, "{v:e}: {ours} vs {display}");
        assert!(ours.contains('.'), "{v:e}: {ours}");
        let exact = format!("{v:.1100}");
        assert_eq!(exact.trim_end_matches('0'), format!("{ours}5"), "{v:e}");
    }

    #[test]
    fn number_round_trips() {
        for v in [0.1, 1.0 / 3.0, 1e-20, 1e300, -0.0, 4.625, f64::MIN_POSITIVE] {
            assert_eq!(
                format_number(v).parse::<f64>().unwrap().to_bits(),
                v.to_bits()
            );
        }
        assert_eq!(format_number(1.0), "1");
        assert_eq!(format_number(0.5), "0.5");
        assert_eq!(format_number(1e-20), "0.00000000000000000001");
    }

    /// Random bit patterns (every exponent, subnormals included): at most 17 significant
    /// digits, a fraction or an exponent, and the same bits back.
    #[test]
    fn file_number_is_short_and_exact() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut out = String::new();
        for _ in 0..200_000 {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            let v = f64::from_bits(state.wrapping_mul(0x9E37_79B9_7F4A_7C15));
            if !v.is_finite() {
                continue;
            }
            out.clear();
            file_number(&mut out, v);
            assert_eq!(out.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{out}");
            let mantissa = out.split('e').next().unwrap_or_default();
            let digits = mantissa
                .trim_start_matches(['-', '0', '.'])
                .replace('.', "");
            assert!(digits.trim_end_matches('0').len() <= 17, "{out}");
            assert!(
                out.contains(['.', 'e']),
                "{out} would read as a TOML integer"
            );
        }
    }

    #[test]
    fn file_number_round_trips_and_reads_as_float() {
        let cases = [
            (1.0, "1.0"),
            (-0.0, "-0.0"),
            (0.1, "0.1"),
            (0.1 + 0.2, "0.30000000000000004"),
            (1e-300, "1e-300"),
            (f64::MAX, "1.7976931348623157e308"),
            (5e-324, "5e-324"),
            (123456.0, "123456.0"),
        ];
        for (v, text) in cases {
            let mut out = String::new();
            file_number(&mut out, v);
            assert_eq!(out, text);
            assert_eq!(out.parse::<f64>().unwrap().to_bits(), v.to_bits());
        }
    }
}
