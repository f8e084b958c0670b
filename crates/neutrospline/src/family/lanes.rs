//! Lanes: how a family's channels ride in the three degree slots of a curve (docs/model.md,
//! "Lanes: the interval-valued and bipolar families").
//!
//! Every curve kind carries truth, indeterminacy and falsity as three extra coordinates of
//! its control points. A family whose channels are among those three rides in one lane. The
//! interval-valued and bipolar families carry up to six channels; they ride in two lanes: two
//! curves with the same positions, weights and knots, each holding three of the channels.
//! Blending is linear in each channel with the same basis functions, so evaluating both lanes
//! at a parameter gives exactly the blended channels of the wide family; every operation that
//! forms new control values as combinations with the basis (evaluation, insertion, elevation,
//! splitting, transforms) serves the wide family lane by lane, unchanged.
//!
//! | family | lane 0 (T, I, F slots) | lane 1 (T, I, F slots) |
//! |---|---|---|
//! | `interval-neutrosophic` | `lower`: T_L, I_L, F_L | `upper`: T_U, I_U, F_U |
//! | `interval-intuitionistic` | `lower`: T_L, 0, F_L | `upper`: T_U, 0, F_U |
//! | `interval-type2` | `lower`: M_L, 0, 0 | `upper`: M_U, 0, 0 |
//! | `bipolar-neutrosophic` | `positive`: T+, I+, F+ | `negative`: -T-, -I-, -F- |
//!
//! A lane's values are in \[0, 1\] (the negative bipolar degrees are stored negated), so a
//! lane is a valid neutrosophic triple; the rule joining the lanes (lower <= upper, `T_U +
//! F_U <= 1`) is checked on the channels, and is kept by blending since it is convex.

use super::{Family, FamilyValues};
use crate::degrees::{DegreeError, Degrees};

/// One lane of a family: which channel fills each of the truth, indeterminacy and falsity
/// slots of a curve's degrees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lane {
    /// `degrees` for the families of one lane; `lower` and `upper` for the interval-valued
    /// families; `positive` and `negative` for the bipolar one.
    pub name: &'static str,
    /// The channel index held by the truth, indeterminacy and falsity slots; `None`: the
    /// slot holds 0.
    pub slots: [Option<usize>; 3],
    /// Whether the slots hold the channels negated (the bipolar negative degrees, in \[-1, 0\],
    /// are held in \[0, 1\]).
    pub negated: bool,
}

const fn lane(name: &'static str, slots: [Option<usize>; 3], negated: bool) -> Lane {
    Lane {
        name,
        slots,
        negated,
    }
}

/// The channel values of a family split into its lanes' degrees; see [`Family::split`].
pub type LaneDegrees = ([Degrees; 2], usize);

impl Family {
    /// The lanes the family rides in (see the module documentation): one for the families
    /// whose channels are among truth, indeterminacy and falsity ([`Family::fits_degrees`]),
    /// two for the interval-valued and bipolar families.
    ///
    /// ```
    /// use neutrospline::Family;
    /// let lanes = Family::IntervalNeutrosophic.lanes();
    /// assert_eq!(lanes.len(), 2);
    /// assert_eq!(lanes[1].name, "upper");
    /// assert_eq!(lanes[1].slots, [Some(1), Some(3), Some(5)]); // T_U, I_U, F_U
    /// assert!(Family::BipolarNeutrosophic.lanes()[1].negated);
    /// assert_eq!(Family::Pythagorean.lanes().len(), 1);
    /// ```
    pub fn lanes(&self) -> &'static [Lane] {
        const ONE: &[Lane] = &[lane("degrees", [None; 3], false)];
        const INTERVAL_NEUTROSOPHIC: &[Lane] = &[
            lane("lower", [Some(0), Some(2), Some(4)], false),
            lane("upper", [Some(1), Some(3), Some(5)], false),
        ];
        const INTERVAL_INTUITIONISTIC: &[Lane] = &[
            lane("lower", [Some(0), None, Some(2)], false),
            lane("upper", [Some(1), None, Some(3)], false),
        ];
        const INTERVAL_TYPE2: &[Lane] = &[
            lane("lower", [Some(0), None, None], false),
            lane("upper", [Some(1), None, None], false),
        ];
        const BIPOLAR: &[Lane] = &[
            lane("positive", [Some(0), Some(1), Some(2)], false),
            lane("negative", [Some(3), Some(4), Some(5)], true),
        ];
        match self {
            Family::IntervalNeutrosophic => INTERVAL_NEUTROSOPHIC,
            Family::IntervalIntuitionistic => INTERVAL_INTUITIONISTIC,
            Family::IntervalType2 => INTERVAL_TYPE2,
            Family::BipolarNeutrosophic => BIPOLAR,
            _ => ONE,
        }
    }

    /// The number of lanes: 1 or 2.
    pub fn lane_count(&self) -> usize {
        self.lanes().len()
    }

    /// Checks channel values against the rule and splits them into the degrees of each lane:
    /// `(lanes, count)` with `lanes[..count]` used. A family of one lane gives its
    /// [`Family::to_degrees`] (the intuitionistic indeterminacy is the hesitation); a wide
    /// family gives each lane's slots, a missing slot 0 and a negated lane negated.
    ///
    /// ```
    /// use neutrospline::Family;
    /// let (lanes, count) = Family::BipolarNeutrosophic.split(&[0.7, 0.2, 0.1, -0.3, -0.4, 0.0])?;
    /// assert_eq!(count, 2);
    /// assert_eq!(lanes[1].to_array(), [0.3, 0.4, 0.0]);
    /// let back = Family::BipolarNeutrosophic.join(&lanes[..count]);
    /// assert_eq!(&*back, &[0.7, 0.2, 0.1, -0.3, -0.4, 0.0]);
    /// # Ok::<(), neutrospline::DegreeError>(())
    /// ```
    ///
    /// # Errors
    /// The rule broken ([`DegreeError::Rule`], with the channels named), or, for a family of
    /// one lane, the errors of [`Family::to_degrees`].
    pub fn split(&self, values: &[f64]) -> Result<LaneDegrees, DegreeError> {
        if self.fits_degrees() {
            return Ok(([self.to_degrees(values)?, Degrees::default()], 1));
        }
        self.check(values)?;
        let mut out = [Degrees::default(); 2];
        for (slot, lane) in out.iter_mut().zip(self.lanes()) {
            *slot = {
                let [t, i, f] = lane.slot_values(values);
                Degrees::new_unchecked(t, i, f)
            };
        }
        Ok((out, 2))
    }

    /// The channel values held by the lanes' degrees (`lanes` has [`Family::lane_count`]
    /// entries; the values are not re-checked). The inverse of [`Family::split`].
    ///
    /// # Panics
    /// If `lanes` has fewer entries than the family has lanes.
    pub fn join(&self, lanes: &[Degrees]) -> FamilyValues {
        let arrays: Vec<[f64; 3]> = lanes.iter().map(Degrees::to_array).collect();
        self.join_slots(&arrays)
    }

    /// The channel values (or channel rates) held by the lanes' three slots: the linear map
    /// of [`Family::join`] applied to any triples, such as the rates `[dT, dI, dF]` of each
    /// lane's derivative. A family of one lane keeps the channels it carries
    /// ([`Family::from_degrees`] order).
    ///
    /// # Panics
    /// If `lanes` has fewer entries than the family has lanes.
    pub fn join_slots(&self, lanes: &[[f64; 3]]) -> FamilyValues {
        assert!(
            lanes.len() >= self.lane_count(),
            "{} lanes given; the {self} family has {}",
            lanes.len(),
            self.lane_count()
        );
        let count = self.channel_count();
        let mut values = FamilyValues::from_slice(&[0.0; super::MAX_CHANNELS][..count]);
        if self.fits_degrees() {
            let carried = crate::degrees::DegreeKind::ALL
                .into_iter()
                .filter(|k| self.carries(*k));
            for (value, kind) in values.iter_mut().zip(carried) {
                *value = lanes[0][kind.index()];
            }
            return values;
        }
        for (lane, slots) in self.lanes().iter().zip(lanes) {
            for (channel, value) in lane.slots.iter().zip(slots) {
                if let Some(c) = channel {
                    values[*c] = if lane.negated { 0.0 - value } else { *value };
                }
            }
        }
        values
    }
}

impl Lane {
    /// The values of the lane's truth, indeterminacy and falsity slots from a family's
    /// channel `values` (not checked against the rule): each slot's channel, negated for a
    /// negated lane, 0 for a slot without one. The linear map inverse to
    /// [`Family::join_slots`] on the slots that hold a channel.
    ///
    /// ```
    /// use neutrospline::Family;
    /// let negative = Family::BipolarNeutrosophic.lanes()[1];
    /// assert_eq!(negative.slot_values(&[0.7, 0.2, 0.1, -0.3, -0.4, 0.0]), [0.3, 0.4, 0.0]);
    /// ```
    pub fn slot_values(&self, values: &[f64]) -> [f64; 3] {
        self.slots.map(|c| match c {
            // 0.0 - v, not -v: a negative zero channel is held as +0.
            Some(c) if self.negated => 0.0 - values[c],
            Some(c) => values[c],
            None => 0.0,
        })
    }
}
