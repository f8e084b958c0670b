//! The colour map of degrees, one definition for every front end: the figures of
//! `neutrospline-plot` and the vertex colours of exported meshes and polylines
//! (`neutrospline-io`) paint a degree with the same [`viridis`] colour.
//!
//! ```
//! use neutrospline::color::{srgb_to_linear, viridis, VIRIDIS};
//! assert_eq!(viridis(0.0), VIRIDIS[0]);
//! assert_eq!(viridis(1.0), [0xfd, 0xe7, 0x25]);
//! assert_eq!(viridis(0.05), [0x46, 0x13, 0x65]); // halfway between the first two stops
//! assert_eq!(srgb_to_linear(255), 1.0);
//! ```

/// Viridis (the perceptually uniform colour map of matplotlib), sampled at 0, 0.1, ..., 1, as
/// sRGB bytes `[red, green, blue]`.
pub const VIRIDIS: [[u8; 3]; 11] = [
    [0x44, 0x01, 0x54],
    [0x48, 0x24, 0x75],
    [0x41, 0x44, 0x87],
    [0x35, 0x5f, 0x8d],
    [0x2a, 0x78, 0x8e],
    [0x21, 0x91, 0x8c],
    [0x22, 0xa8, 0x84],
    [0x44, 0xbf, 0x70],
    [0x7a, 0xd1, 0x51],
    [0xbd, 0xdf, 0x26],
    [0xfd, 0xe7, 0x25],
];

/// The colour of a value `x` in \[0, 1\] (a degree, or a score): the two [`VIRIDIS`] stops
/// around `x` mixed linearly in sRGB, each channel rounded to the nearest byte. Values outside
/// \[0, 1\] are clamped for display and NaN shows as 0.
pub fn viridis(x: f64) -> [u8; 3] {
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        0.0
    } * 10.0;
    // x is in [0, 10]: the cast cannot truncate anything but the fraction.
    let i = (x.floor() as usize).min(9);
    let t = (x - i as f64).clamp(0.0, 1.0);
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * t).round() as u8;
    [mix(a[0], b[0]), mix(a[1], b[1]), mix(a[2], b[2])]
}

/// An sRGB byte as linear light in \[0, 1\] (the sRGB transfer function of IEC 61966-2-1), for
/// formats whose colours are linear, such as glTF's vertex colours: a viewer that converts them
/// back to sRGB shows the bytes of [`viridis`].
pub fn srgb_to_linear(channel: u8) -> f64 {
    let c = f64::from(channel) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_stops_ends_and_clamping() {
        for (k, stop) in VIRIDIS.iter().enumerate() {
            assert_eq!(viridis(k as f64 / 10.0), *stop, "stop {k}");
        }
        assert_eq!(viridis(-3.0), VIRIDIS[0]);
        assert_eq!(viridis(7.0), VIRIDIS[10]);
        assert_eq!(viridis(f64::NAN), VIRIDIS[0]);
        assert_eq!(viridis(f64::INFINITY), VIRIDIS[0]);
        // 0.55: halfway between stops 5 and 6, rounded per channel.
        assert_eq!(viridis(0.55), [0x22, 0x9d, 0x88]);
    }

    #[test]
    fn srgb_to_linear_is_the_standard_curve() {
        assert_eq!(srgb_to_linear(0), 0.0);
        assert_eq!(srgb_to_linear(255), 1.0);
        // 10 / 255 is on the linear segment; 128 / 255 on the power segment (0.2158605).
        assert_eq!(srgb_to_linear(10), 10.0 / 255.0 / 12.92);
        assert!((srgb_to_linear(128) - 0.215_860_500_113_899_16).abs() < 1e-15);
        let mut last = -1.0;
        for c in 0..=255 {
            let v = srgb_to_linear(c);
            assert!(v > last, "increasing at {c}");
            last = v;
        }
    }
}
