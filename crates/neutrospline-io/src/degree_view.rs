//! How a membership family's degrees appear as table columns, shared by `eval`, `check` and the
//! studio's table (docs/model.md, "Membership families").

use neutrospline::{DegreeKind, Degrees, Family};

/// Column names of the neutrosophic scores (docs/model.md section 7); the other families use
/// the first one or two.
const SCORES: [&str; 3] = ["score", "accuracy", "certainty"];

/// The score, accuracy and certainty of a neutrosophic point's degrees (docs/model.md
/// section 7).
fn scores(degrees: &Degrees) -> [f64; 3] {
    [degrees.score(), degrees.accuracy(), degrees.certainty()]
}

/// The degree columns of a family's table (docs/model.md, "Membership families"). The three
/// families of the original model (neutrosophic, intuitionistic, fuzzy) keep the columns
/// `truth, indeterminacy, falsity` (the intuitionistic indeterminacy is the hesitation). Every
/// other family has a column per channel (`truth_lower, truth_upper, ...` for the
/// interval-valued ones, read from both lanes), then its derived degrees computed from the
/// blended channels (the hesitation `(1 - T^q - F^q)^(1/q)`, the picture refusal, ...). The
/// scores are the family's: `score, accuracy, certainty` of section 7 for the neutrosophic
/// family, `score` and, where its literature has one, `accuracy` for every other family
/// (SPEC section 10: intuitionistic T - F and T + F, fuzzy T). Rates (derivatives) are given
/// for the channels only: a derived degree is not linear in them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DegreeView {
    family: Family,
}

impl DegreeView {
    /// The view of `family`'s degrees.
    pub fn new(family: Family) -> Self {
        DegreeView { family }
    }

    /// Whether the view keeps the columns `truth, indeterminacy, falsity` (the three
    /// families of the original model).
    pub fn triple(&self) -> bool {
        matches!(
            self.family,
            Family::Neutrosophic | Family::Intuitionistic | Family::Fuzzy
        )
    }

    /// The degrees shown by a three-column view, in `truth, indeterminacy, falsity` order.
    fn kinds(&self) -> Vec<DegreeKind> {
        DegreeKind::ALL
            .into_iter()
            .filter(|k| self.triple() || self.family.carries(*k))
            .collect()
    }

    /// The channel column names (also the names of the rates): `truth, indeterminacy,
    /// falsity` for the three original families, else the family's channels
    /// (`truth_lower, truth_upper, ...` for the interval-valued ones).
    pub fn channel_names(&self) -> Vec<&'static str> {
        if self.triple() {
            self.kinds().into_iter().map(DegreeKind::name).collect()
        } else {
            self.family.channels().to_vec()
        }
    }

    /// The channel columns, then the derived degrees.
    pub fn names(&self) -> Vec<&'static str> {
        let mut names = self.channel_names();
        if !self.triple() {
            names.extend(self.family.derived_names());
        }
        names
    }

    /// The score column names: `score, accuracy, certainty` for the neutrosophic family
    /// (docs/model.md section 7), else the family's `score` and, where its literature has
    /// one, `accuracy` (SPEC section 10: the intuitionistic score is T - F with accuracy
    /// T + F, the fuzzy score is T).
    pub fn score_names(&self) -> &'static [&'static str] {
        let zeros = vec![0.0; self.family.channel_count()];
        if self.family == Family::Neutrosophic {
            &SCORES
        } else if self.family.accuracy(&zeros).is_some() {
            &SCORES[..2]
        } else {
            &SCORES[..1]
        }
    }

    /// The channel values of a point from the degrees of each lane (`Family::lanes`: one
    /// lane for most families, two for the interval-valued and bipolar ones).
    fn channels(&self, lanes: &[Degrees]) -> Vec<f64> {
        if self.triple() {
            self.kinds().into_iter().map(|k| lanes[0].get(k)).collect()
        } else {
            self.family.join(lanes).to_vec()
        }
    }

    /// The values of [`DegreeView::names`] for a point whose lanes hold `lanes` (one
    /// [`Degrees`] per lane of the family, in lane order).
    ///
    /// # Panics
    /// If `lanes` has fewer entries than the family has lanes.
    pub fn values(&self, lanes: &[Degrees]) -> Vec<f64> {
        let mut values = self.channels(lanes);
        if !self.triple() {
            let derived = self.family.derived(&values);
            values.extend(derived.iter());
        }
        values
    }

    /// The values of [`DegreeView::score_names`] for a point whose lanes hold `lanes`.
    ///
    /// # Panics
    /// If `lanes` has fewer entries than the family has lanes.
    pub fn scores(&self, lanes: &[Degrees]) -> Vec<f64> {
        if self.family == Family::Neutrosophic {
            return scores(&lanes[0]).to_vec();
        }
        let channels = self.family.join(lanes);
        let mut values = vec![self.family.score(&channels)];
        values.extend(self.family.accuracy(&channels));
        values
    }

    /// The rates of the shown channels from each lane's rates `[dT, dI, dF]` (the channels
    /// are linear in the lanes' slots, so their rates are the same map of the slots' rates).
    ///
    /// # Panics
    /// If `lanes` has fewer entries than the family has lanes.
    pub fn rates(&self, lanes: &[[f64; 3]]) -> Vec<f64> {
        if self.triple() {
            self.kinds()
                .into_iter()
                .map(|k| lanes[0][k.index()])
                .collect()
        } else {
            self.family.join_slots(lanes).to_vec()
        }
    }
}
