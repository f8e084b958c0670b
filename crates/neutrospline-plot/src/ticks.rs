//! Axis ranges and "nice" tick values (steps of 1, 2 or 5 times a power of ten).

/// A closed axis range with its tick values.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ticks {
    /// Lower end of the axis.
    pub lo: f64,
    /// Upper end of the axis.
    pub hi: f64,
    /// Distance between ticks.
    pub step: f64,
    /// Tick values inside `[lo, hi]`, ascending.
    pub values: Vec<f64>,
    /// Decimals needed to tell the ticks apart.
    pub decimals: usize,
}

impl Ticks {
    /// The tick labels, formatted alike.
    pub(crate) fn labels(&self) -> Vec<String> {
        let sci = self.scientific();
        self.values
            .iter()
            .map(|&v| format_tick(v, self.decimals, sci))
            .collect()
    }

    fn scientific(&self) -> bool {
        let big = self.lo.abs().max(self.hi.abs());
        big >= 1e6 || self.decimals > 5
    }

    /// Maps `v` to `[0, 1]` along the axis.
    pub(crate) fn unit(&self, v: f64) -> f64 {
        (v - self.lo) / (self.hi - self.lo)
    }
}

/// Widens an empty or tiny range `[lo, hi]` to a sensible one around its centre.
///
/// A range is too small when its span is below `1e-9` times its magnitude (or is zero); it
/// becomes the centre plus or minus `max(0.5, 10% of |centre|)`.
pub(crate) fn widen_degenerate(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    let magnitude = lo.abs().max(hi.abs());
    if hi - lo > 1e-9 * magnitude && hi - lo > 1e-300 {
        return (lo, hi);
    }
    let centre = lo / 2.0 + hi / 2.0;
    let half = (0.1 * centre.abs()).max(0.5);
    (centre - half, centre + half)
}

/// Pads `[lo, hi]` by `fraction` of its span on each side (after widening a degenerate range).
pub(crate) fn padded(lo: f64, hi: f64, fraction: f64) -> (f64, f64) {
    let (lo, hi) = widen_degenerate(lo, hi);
    let pad = (hi - lo) * fraction;
    (lo - pad, hi + pad)
}

/// The nice step (1, 2 or 5 times a power of ten) giving about `target` intervals on `span`.
pub(crate) fn nice_step(span: f64, target: usize) -> f64 {
    let target = target.max(1) as f64;
    let raw = span / target;
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let magnitude = 10f64.powf(raw.log10().floor());
    let f = raw / magnitude;
    let nice = if f < 1.5 {
        1.0
    } else if f < 3.0 {
        2.0
    } else if f < 7.0 {
        5.0
    } else {
        10.0
    };
    nice * magnitude
}

fn decimals_for(step: f64) -> usize {
    let d = -(step.log10() + 1e-9).floor();
    if d.is_finite() && d > 0.0 {
        (d as usize).min(12)
    } else {
        0
    }
}

fn values_in(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step - 1e-9).ceil();
    let last = (hi / step + 1e-9).floor();
    if !(first.is_finite() && last.is_finite()) || last < first || last - first > 1000.0 {
        return vec![lo, hi];
    }
    let mut out = Vec::new();
    let mut k = first;
    while k <= last {
        let v = k * step;
        out.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        k += 1.0;
    }
    out
}

/// Ticks inside the range `[lo, hi]`, about `target` intervals apart (the range is kept).
pub(crate) fn ticks_inside(lo: f64, hi: f64, target: usize) -> Ticks {
    let (lo, hi) = widen_degenerate(lo, hi);
    let step = nice_step(hi - lo, target);
    Ticks {
        lo,
        hi,
        step,
        values: values_in(lo, hi, step),
        decimals: decimals_for(step),
    }
}

/// Ticks whose range is `[lo, hi]` widened outwards to the nearest multiples of the step.
pub(crate) fn ticks_loose(lo: f64, hi: f64, target: usize) -> Ticks {
    let (lo, hi) = widen_degenerate(lo, hi);
    let step = nice_step(hi - lo, target);
    let l = (lo / step + 1e-9).floor() * step;
    let h = (hi / step - 1e-9).ceil() * step;
    let (l, h) = if l.is_finite() && h.is_finite() && h > l {
        (l, h)
    } else {
        (lo, hi)
    };
    Ticks {
        lo: l,
        hi: h,
        step,
        values: values_in(l, h, step),
        decimals: decimals_for(step),
    }
}

/// Formats a tick value with `decimals` decimals, or in scientific notation; the minus sign
/// is U+2212.
pub(crate) fn format_tick(v: f64, decimals: usize, scientific: bool) -> String {
    let s = if scientific && v != 0.0 {
        let s = format!("{v:.3e}");
        // Trim the mantissa's trailing zeros: "1.500e6" -> "1.5e6".
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                format!("{m}e{e}")
            }
            None => s,
        }
    } else {
        format!("{v:.decimals$}")
    };
    let s = if s.chars().all(|c| c == '-' || c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    };
    s.replace('-', "\u{2212}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_step_is_1_2_5() {
        assert_eq!(nice_step(10.0, 5), 2.0);
        assert_eq!(nice_step(1.0, 5), 0.2);
        assert_eq!(nice_step(8.0, 8), 1.0);
        assert_eq!(nice_step(100.0, 4), 20.0);
        assert_eq!(nice_step(0.03, 6), 0.005);
        assert_eq!(nice_step(7.0, 1), 10.0);
        assert_eq!(nice_step(0.0, 5), 1.0);
        assert_eq!(nice_step(f64::NAN, 5), 1.0);
        for span in [0.0137, 0.9, 3.3, 47.0, 1234.5, 9.9e7] {
            let s = nice_step(span, 5);
            let m = s / 10f64.powf(s.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|n| (m - n).abs() < 1e-9),
                "{span} -> {s}"
            );
        }
    }

    #[test]
    fn ticks_inside_unit_interval() {
        let t = ticks_inside(0.0, 1.0, 5);
        assert_eq!(t.step, 0.2);
        assert_eq!(t.values.len(), 6);
        assert_eq!(t.labels(), vec!["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        assert_eq!((t.lo, t.hi), (0.0, 1.0));
    }

    #[test]
    fn ticks_loose_expands_to_multiples() {
        let t = ticks_loose(0.6, 9.4, 5);
        assert_eq!(t.step, 2.0);
        assert_eq!((t.lo, t.hi), (0.0, 10.0));
        assert_eq!(t.labels(), vec!["0", "2", "4", "6", "8", "10"]);
    }

    #[test]
    fn ticks_degenerate_range_is_widened() {
        let t = ticks_inside(5.0, 5.0, 5);
        assert!(t.lo < 5.0 && t.hi > 5.0);
        assert!(t.values.iter().all(|v| v.is_finite()));
        assert!(t.values.len() >= 3);
        let z = ticks_loose(0.0, 0.0, 5);
        assert!(z.lo < 0.0 && z.hi > 0.0 && z.values.contains(&0.0));
        let big = ticks_inside(1e6, 1e6, 5);
        assert!(big.hi - big.lo > 1e4);
    }

    #[test]
    fn ticks_negative_labels_use_minus_sign() {
        let t = ticks_inside(-1.0, 1.0, 4);
        let labels = t.labels();
        assert_eq!(labels.first().map(String::as_str), Some("\u{2212}1.0"));
        assert!(labels.contains(&"0.0".to_string()));
    }

    #[test]
    fn ticks_large_values_scientific() {
        let t = ticks_inside(0.0, 3e7, 3);
        assert_eq!(t.labels()[1], "1e7");
        assert_eq!(format_tick(1.5e6, 0, true), "1.5e6");
        assert_eq!(format_tick(-0.0, 1, false), "0.0");
    }

    #[test]
    fn padded_adds_fraction() {
        assert_eq!(padded(0.0, 10.0, 0.05), (-0.5, 10.5));
        let (lo, hi) = padded(2.0, 2.0, 0.05);
        assert!(lo < 2.0 && hi > 2.0);
    }
}
