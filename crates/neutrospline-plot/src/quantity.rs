//! What a single-quantity figure shows: one of the three degrees, the neutrosophic score of
//! the degrees (docs/model.md section 7), or a family's measure (its score or a derived
//! degree, docs/model.md "Membership families") computed beforehand into a slot of the
//! point. The lifted curves, the coloured 3-D curves and the coloured meshes take a
//! [`Quantity`]: its name, colour, range and value from a point's degrees.

use neutrospline::DegreeKind;

use crate::point::Pt;
use crate::style::Color;
use crate::theme::{self, Marker};

/// A value read off a point's degrees: one degree, the score, or a family's measure held in
/// a slot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// The degree of this kind.
    Degree(DegreeKind),
    /// The score `(2 + T - I - F) / 3` ([`neutrospline::Degrees::score`]).
    Score,
    /// A family's score or derived degree, computed from the blended channels and held in
    /// degree slot `slot` of the measured points (`views::measure`).
    Measured {
        /// The slot (0, 1 or 2) of [`Pt::deg`] that holds it.
        slot: usize,
        /// Its name: `score`, `hesitation`, `refusal`, `type_reduced`, ...
        name: &'static str,
        /// Whether it ranges over \[-1, 1\] (the orthopair, picture, spherical and
        /// interval-intuitionistic scores) rather than \[0, 1\].
        signed: bool,
    },
}

impl From<DegreeKind> for Quantity {
    fn from(kind: DegreeKind) -> Quantity {
        Quantity::Degree(kind)
    }
}

/// The score of degrees `[T, I, F]`: the formula of [`neutrospline::Degrees::score`], for
/// sampled degrees that need no range check. Affine in the degrees, so the score of a curve
/// sample is the basis blend of the control points' scores.
pub(crate) fn score(deg: [f64; 3]) -> f64 {
    (2.0 + deg[0] - deg[1] - deg[2]) / 3.0
}

impl Quantity {
    /// Its name, in titles, axis and colour-bar labels and classes: `truth`, ..., `score`.
    pub(crate) const fn name(self) -> &'static str {
        match self {
            Quantity::Degree(kind) => kind.name(),
            Quantity::Score => "score",
            Quantity::Measured { name, .. } => name,
        }
    }

    /// What it is, in legend texts ("coloured by the degree", "crisp curve (degree 0)").
    pub(crate) fn noun(self) -> &'static str {
        match self {
            Quantity::Degree(_) => "degree",
            Quantity::Score => "score",
            Quantity::Measured { name: "score", .. } => "score",
            Quantity::Measured { .. } => "degree",
        }
    }

    /// The colour of its lifted curve.
    pub(crate) fn color(self) -> Color {
        match self {
            Quantity::Degree(kind) => theme::degree_color(kind),
            Quantity::Score | Quantity::Measured { slot: 0, .. } => theme::SCORE,
            Quantity::Measured { .. } => theme::DERIVED_SECOND,
        }
    }

    /// The marker of its lifted control points when several quantities share a box.
    pub(crate) fn marker(self) -> Marker {
        match self {
            Quantity::Degree(kind) => theme::degree_marker(kind),
            Quantity::Score | Quantity::Measured { slot: 0, .. } => Marker::Circle,
            Quantity::Measured { .. } => Marker::Square,
        }
    }

    /// Its value for degrees `[T, I, F]`.
    pub(crate) fn value(self, deg: [f64; 3]) -> f64 {
        match self {
            Quantity::Degree(kind) => deg[kind.index()],
            Quantity::Score => score(deg),
            Quantity::Measured { slot, .. } => deg[slot],
        }
    }

    /// Its value at a point.
    pub(crate) fn at(self, p: &Pt) -> f64 {
        self.value(p.deg)
    }

    /// The range of its values: \[-1, 1\] for a signed measure, else \[0, 1\].
    pub(crate) fn range(self) -> (f64, f64) {
        match self {
            Quantity::Measured { signed: true, .. } => (-1.0, 1.0),
            _ => (0.0, 1.0),
        }
    }

    /// Its value at a point for display: clamped to [`Quantity::range`], NaN as 0.
    pub(crate) fn height(self, p: &Pt) -> f64 {
        let v = self.at(p);
        let (lo, hi) = self.range();
        if v.is_finite() {
            v.clamp(lo, hi)
        } else {
            0.0
        }
    }

    /// Where value `v` lies in [`Quantity::range`], from 0 to 1: the colour map's argument.
    pub(crate) fn fraction(self, v: f64) -> f64 {
        let (lo, hi) = self.range();
        theme::unit((v - lo) / (hi - lo))
    }

    /// The colour of value `v` on the colour map over [`Quantity::range`].
    pub(crate) fn colour_of(self, v: f64) -> Color {
        theme::colormap(self.fraction(v))
    }

    /// Legend notes that say what it is (the score's formula, written without spaces so that
    /// the legend never breaks it; none for a degree).
    pub(crate) fn notes(self) -> Vec<String> {
        match self {
            Quantity::Degree(_) => Vec::new(),
            Quantity::Score => vec!["score = (2+T\u{2212}I\u{2212}F)/3".to_string()],
            Quantity::Measured { .. } => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::Degrees;

    #[test]
    fn quantity_values_and_names() {
        let deg = [0.7, 0.2, 0.4];
        for kind in DegreeKind::ALL {
            let q = Quantity::from(kind);
            assert_eq!(q.value(deg), deg[kind.index()]);
            assert_eq!(q.name(), kind.name());
            assert_eq!(q.noun(), "degree");
            assert_eq!(q.color(), theme::degree_color(kind));
        }
        let d = Degrees::new(0.7, 0.2, 0.4).unwrap();
        assert_eq!(Quantity::Score.value(deg), d.score());
        assert_eq!(Quantity::Score.name(), "score");
        assert_eq!(score([1.0, 0.0, 0.0]), 1.0);
        assert_eq!(score([0.0, 1.0, 1.0]), 0.0);
    }

    /// The score of the sampled curve (what the `score` view lifts and colours) is the
    /// Bernstein blend of the control points' scores; Example 1 at t = 1/2 gives exactly
    /// (1.6 + 3 * 2.6 + 3 * 2.4 + 1.4) / 24 = 0.75.
    #[test]
    fn quantity_score_of_samples_is_blend_of_control_scores() {
        let model = crate::PlotModel::from(&neutrospline::example1());
        let ctrl: Vec<f64> = model
            .controls()
            .iter()
            .map(|p| Quantity::Score.at(p))
            .collect();
        for (c, want) in ctrl.iter().zip([1.6, 2.6, 2.4, 1.4]) {
            assert!((c - want / 3.0).abs() < 1e-15, "{c} vs {want}/3");
        }
        let n = 201;
        let pts = model.curve_points(n).unwrap();
        assert_eq!(pts.len(), n);
        for (k, p) in pts.iter().enumerate() {
            let t = k as f64 / (n - 1) as f64;
            let s = 1.0 - t;
            let blend = s * s * s * ctrl[0]
                + 3.0 * s * s * t * ctrl[1]
                + 3.0 * s * t * t * ctrl[2]
                + t * t * t * ctrl[3];
            assert!((Quantity::Score.at(p) - blend).abs() < 1e-14, "t = {t}");
        }
        assert!((Quantity::Score.at(&pts[100]) - 0.75).abs() < 1e-15);
        let quarter = Quantity::Score.at(&pts[50]);
        let closed = (27.0 * 1.6 + 27.0 * 2.6 + 9.0 * 2.4 + 1.4) / 192.0;
        assert!((quarter - closed).abs() < 1e-15, "{quarter} vs {closed}");
    }
}
