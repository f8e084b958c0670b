//! What the reference tests (`reference`, `spline_reference`) share: reading a reference file
//! of `tests/data`, the channels of a point as a row, and the [`Checker`] that collects every
//! failure and the worst error relative to its tolerance per band.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use neutrospline::{CurvePoint, DerivativeValue};

/// The reference file `tests/data/{name}`; `script` (under `scripts/reference/`) made it.
pub fn read_data(name: &str, script: &str) -> String {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!("cannot read {path}: {e} (regenerate with scripts/reference/{script})")
    })
}

/// The name of channel `c` of a point of dimension `dim`: `x`, `y`, `z`, then the degrees.
pub fn channel_name(c: usize, dim: usize) -> &'static str {
    const AXES: [&str; 3] = ["x", "y", "z"];
    const DEGREES: [&str; 3] = ["truth", "indeterminacy", "falsity"];
    if c < dim {
        AXES[c]
    } else {
        DEGREES[c - dim]
    }
}

/// `x, y[, z], truth, indeterminacy, falsity`.
pub fn point_channels<const D: usize>(p: &CurvePoint<D>) -> Vec<f64> {
    let mut v = p.position.to_vec();
    v.extend_from_slice(&p.degrees.to_array());
    v
}

/// The rates in the order of [`point_channels`].
pub fn derivative_channels<const D: usize>(d: &DerivativeValue<D>) -> Vec<f64> {
    let mut v = d.position.to_vec();
    v.extend_from_slice(&[d.truth, d.indeterminacy, d.falsity]);
    v
}

/// Collects failures (all of them, reported together) and the largest error / tolerance.
#[derive(Default)]
pub struct Checker {
    failures: Vec<String>,
    /// The worst error / tolerance seen, keyed by a label (a degree band and what is checked),
    /// with its location.
    worst: BTreeMap<String, (f64, String)>,
}

impl Checker {
    /// `got` is within `tol` of `expected` (a NaN fails); `at` names the case and parameter.
    #[allow(clippy::too_many_arguments)]
    pub fn close(
        &mut self,
        band: &str,
        at: &str,
        what: &str,
        channel: &str,
        got: f64,
        expected: f64,
        tol: f64,
    ) {
        let err = (got - expected).abs();
        let ratio = if tol > 0.0 {
            err / tol
        } else if err == 0.0 {
            0.0
        } else {
            f64::INFINITY
        };
        if err.is_nan() || err > tol {
            self.failures.push(format!(
                "{at}, {what} {channel}: got {got:e}, expected {expected:e}, \
                 error {err:e} > tolerance {tol:e} ({ratio:.3} x tolerance)"
            ));
        }
        let kind = if matches!(channel, "x" | "y" | "z") {
            "position"
        } else {
            "degrees"
        };
        let entry = self
            .worst
            .entry(format!("{band}, {what} {kind}"))
            .or_insert((0.0, String::new()));
        if ratio > entry.0 || ratio.is_nan() {
            *entry = (ratio, format!("{at} {what} {channel}"));
        }
    }

    /// `a` and `b` are the same float, bit for bit.
    pub fn same_bits(&mut self, at: &str, what: &str, a: f64, b: f64) {
        if a.to_bits() != b.to_bits() {
            self.failures.push(format!(
                "{at}: {what}: {a:e} ({:#018x}) != {b:e} ({:#018x})",
                a.to_bits(),
                b.to_bits()
            ));
        }
    }

    /// A failure unless `ok`.
    pub fn check(&mut self, ok: bool, message: impl FnOnce() -> String) {
        if !ok {
            self.failures.push(message());
        }
    }

    /// Prints the worst errors, and panics with every failure if there is one.
    pub fn finish(self, test: &str) {
        let mut summary = String::new();
        for (band, (ratio, at)) in &self.worst {
            let _ = writeln!(
                summary,
                "  {band:<46} max error / tolerance = {ratio:.3e}  ({at})"
            );
        }
        println!("{test}: worst errors relative to tolerance\n{summary}");
        if !self.failures.is_empty() {
            let n = self.failures.len();
            let shown: Vec<&str> = self.failures.iter().take(40).map(String::as_str).collect();
            panic!(
                "{test}: {n} check(s) failed{}:\n  {}\n\nworst errors relative to tolerance:\n{summary}",
                if n > 40 { " (first 40 shown)" } else { "" },
                shown.join("\n  ")
            );
        }
    }
}
