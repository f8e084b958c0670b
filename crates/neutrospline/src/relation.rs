//! Neutrosophic point relations (paper Def. 3 and 4, docs/model.md section 2).
//!
//! Two neutrosophic sets on the axes, `M` on the first (`r` values) and `N` on the second
//! (`s` values), each give every coordinate value its own degrees. A relation on `R x S` gives
//! each pair `(r, s)` degrees; it is *admissible* when, for every pair and every one of the
//! three degrees, the relation's degree is `<=` that degree of `M` at `r` and `<=` that degree
//! of `N` at `s`. The largest admissible relation takes the degree-wise minimum.

use core::fmt;

use crate::degrees::{DegreeKind, Degrees};
use crate::point::{ControlPoint, NeutrosophicPoint};

/// Which of the two axis sets of Def. 4.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AxisSetName {
    /// `M`, the set on the first axis (values `r`).
    M,
    /// `N`, the set on the second axis (values `s`).
    N,
}

impl fmt::Display for AxisSetName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            AxisSetName::M => "M",
            AxisSetName::N => "N",
        })
    }
}

impl AxisSetName {
    fn coordinate(self) -> &'static str {
        match self {
            AxisSetName::M => "r",
            AxisSetName::N => "s",
        }
    }
}

/// Why a point relation or an axis set is invalid.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RelationError {
    /// A coordinate of an axis set is NaN or infinite.
    #[error("{set}: member {index} has coordinate {value}, which is not a finite number")]
    CoordinateNotFinite {
        /// The axis set.
        set: AxisSetName,
        /// Index of the member.
        index: usize,
        /// The coordinate.
        value: f64,
    },
    /// An axis set lists the same coordinate twice (a set gives each value one set of degrees).
    #[error("{set}: coordinate {value} appears twice (members {first} and {second})")]
    DuplicateCoordinate {
        /// The axis set.
        set: AxisSetName,
        /// The coordinate.
        value: f64,
        /// Index of its first occurrence.
        first: usize,
        /// Index of the repeat.
        second: usize,
    },
    /// A pair uses a coordinate the axis set does not contain.
    #[error("pair {index} at ({r}, {s}): {coordinate} = {value} is not a member of {set}", coordinate = set.coordinate())]
    NotInAxisSet {
        /// Index of the pair.
        index: usize,
        /// First coordinate of the pair.
        r: f64,
        /// Second coordinate of the pair.
        s: f64,
        /// The axis set lacking the value.
        set: AxisSetName,
        /// The missing coordinate.
        value: f64,
    },
    /// A degree of the relation exceeds the same degree of an axis set (Def. 4).
    #[error(
        "pair {index} at ({r}, {s}): {kind} = {value} exceeds {bound}, the {kind} of {set} at {coordinate} = {at} (Def. 4: each degree of the relation must be <= the same degree of M at r and of N at s)",
        coordinate = set.coordinate()
    )]
    NotAdmissible {
        /// Index of the pair.
        index: usize,
        /// First coordinate of the pair.
        r: f64,
        /// Second coordinate of the pair.
        s: f64,
        /// The degree that is too large.
        kind: DegreeKind,
        /// The relation's degree.
        value: f64,
        /// The axis set whose degree is exceeded.
        set: AxisSetName,
        /// The coordinate on that axis.
        at: f64,
        /// The axis set's degree.
        bound: f64,
    },
}

/// A neutrosophic set on one axis: distinct coordinate values, each with its degrees.
///
/// ```
/// use neutrospline::{AxisSet, AxisSetName, Degrees};
/// let m = AxisSet::new(AxisSetName::M, vec![(1.0, Degrees::new(0.3, 0.6, 0.1)?)])?;
/// assert_eq!(m.degrees_at(1.0).unwrap().truth(), 0.3);
/// assert!(m.degrees_at(2.0).is_none());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct AxisSet {
    name: AxisSetName,
    members: Vec<(f64, Degrees)>,
}

impl AxisSet {
    /// The set with the given `(coordinate, degrees)` members.
    ///
    /// # Errors
    /// A coordinate not finite, or listed twice.
    pub fn new(name: AxisSetName, members: Vec<(f64, Degrees)>) -> Result<Self, RelationError> {
        for (index, &(value, _)) in members.iter().enumerate() {
            if !value.is_finite() {
                return Err(RelationError::CoordinateNotFinite {
                    set: name,
                    index,
                    value,
                });
            }
            if let Some(first) = members[..index].iter().position(|&(v, _)| v == value) {
                return Err(RelationError::DuplicateCoordinate {
                    set: name,
                    value,
                    first,
                    second: index,
                });
            }
        }
        Ok(AxisSet { name, members })
    }

    /// Which axis this set is on.
    pub fn name(&self) -> AxisSetName {
        self.name
    }

    /// The members, in the order given.
    pub fn members(&self) -> &[(f64, Degrees)] {
        &self.members
    }

    /// The degrees of `value`, if it is a member.
    pub fn degrees_at(&self, value: f64) -> Option<Degrees> {
        self.members
            .iter()
            .find(|&&(v, _)| v == value)
            .map(|&(_, d)| d)
    }
}

/// A neutrosophic point relation: pairs `(r, s)` of the plane, each with degrees (Def. 3).
///
/// Its entries, in order, are the control points of a planar curve (Def. 5).
#[derive(Clone, Debug, PartialEq)]
pub struct PointRelation {
    entries: Vec<NeutrosophicPoint<2>>,
}

impl PointRelation {
    /// A relation with the given entries (not yet checked against any axis sets; see
    /// [`PointRelation::check_admissible`]).
    pub fn new(entries: Vec<NeutrosophicPoint<2>>) -> Self {
        PointRelation { entries }
    }

    /// The largest admissible relation on all of `M x N` (Def. 4): every pair `(r, s)`, `r`
    /// varying slowest, with the degree-wise minimum of `M` at `r` and `N` at `s`.
    ///
    /// ```
    /// use neutrospline::{AxisSet, AxisSetName, Degrees, PointRelation};
    /// let m = AxisSet::new(AxisSetName::M, vec![(1.0, Degrees::new(0.3, 0.6, 0.1)?)])?;
    /// let n = AxisSet::new(AxisSetName::N, vec![(3.0, Degrees::new(0.5, 0.2, 0.4)?)])?;
    /// let relation = PointRelation::largest(&m, &n);
    /// assert_eq!(relation.entries()[0].degrees.to_array(), [0.3, 0.2, 0.1]);
    /// assert!(relation.check_admissible(&m, &n).is_ok());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn largest(m: &AxisSet, n: &AxisSet) -> PointRelation {
        let entries = m
            .members
            .iter()
            .flat_map(|&(r, dm)| {
                n.members
                    .iter()
                    .map(move |&(s, dn)| NeutrosophicPoint::new([r, s], dm.min(dn)))
            })
            .collect();
        PointRelation { entries }
    }

    /// The largest admissible relation restricted to the given pairs, in their order: the
    /// usual way to turn two axis sets into an ordered list of control points.
    ///
    /// # Errors
    /// [`RelationError::NotInAxisSet`] for a pair whose `r` is not in `M` or `s` not in `N`.
    pub fn largest_on_pairs(
        m: &AxisSet,
        n: &AxisSet,
        pairs: &[(f64, f64)],
    ) -> Result<PointRelation, RelationError> {
        let entries = pairs
            .iter()
            .enumerate()
            .map(|(index, &(r, s))| {
                let dm = lookup(m, index, r, s, r)?;
                let dn = lookup(n, index, r, s, s)?;
                Ok(NeutrosophicPoint::new([r, s], dm.min(dn)))
            })
            .collect::<Result<_, _>>()?;
        Ok(PointRelation { entries })
    }

    /// The entries, in order.
    pub fn entries(&self) -> &[NeutrosophicPoint<2>] {
        &self.entries
    }

    /// The entries as control points of a planar curve (Def. 5).
    pub fn to_control_points(&self) -> Vec<ControlPoint<2>> {
        self.entries.clone()
    }

    /// Checks Def. 4: every degree of every pair is `<=` the same degree of `M` at `r` and of
    /// `N` at `s`.
    ///
    /// # Errors
    /// The first violation, naming the pair, the degree, both values and the axis set:
    /// [`RelationError::NotAdmissible`], or [`RelationError::NotInAxisSet`].
    pub fn check_admissible(&self, m: &AxisSet, n: &AxisSet) -> Result<(), RelationError> {
        for (index, entry) in self.entries.iter().enumerate() {
            let [r, s] = entry.position;
            for (set, at) in [(m, r), (n, s)] {
                let bound = lookup(set, index, r, s, at)?;
                for kind in DegreeKind::ALL {
                    let value = entry.degrees.get(kind);
                    if value > bound.get(kind) {
                        return Err(RelationError::NotAdmissible {
                            index,
                            r,
                            s,
                            kind,
                            value,
                            set: set.name,
                            at,
                            bound: bound.get(kind),
                        });
                    }
                }
            }
        }
        Ok(())
    }
}

fn lookup(
    set: &AxisSet,
    index: usize,
    r: f64,
    s: f64,
    value: f64,
) -> Result<Degrees, RelationError> {
    set.degrees_at(value).ok_or(RelationError::NotInAxisSet {
        index,
        r,
        s,
        set: set.name,
        value,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(t: f64, i: f64, f: f64) -> Degrees {
        Degrees::new(t, i, f).unwrap()
    }

    fn sets() -> (AxisSet, AxisSet) {
        let m = AxisSet::new(
            AxisSetName::M,
            vec![(1.0, d(0.3, 0.6, 0.1)), (3.0, d(0.8, 0.1, 0.5))],
        )
        .unwrap();
        let n = AxisSet::new(
            AxisSetName::N,
            vec![(3.0, d(0.5, 0.7, 0.1)), (6.0, d(0.9, 0.2, 0.3))],
        )
        .unwrap();
        (m, n)
    }

    #[test]
    fn point_relation_largest_is_minimum_over_product() {
        let (m, n) = sets();
        let rel = PointRelation::largest(&m, &n);
        let got: Vec<([f64; 2], [f64; 3])> = rel
            .entries()
            .iter()
            .map(|e| (e.position, e.degrees.to_array()))
            .collect();
        assert_eq!(
            got,
            vec![
                ([1.0, 3.0], [0.3, 0.6, 0.1]),
                ([1.0, 6.0], [0.3, 0.2, 0.1]),
                ([3.0, 3.0], [0.5, 0.1, 0.1]),
                ([3.0, 6.0], [0.8, 0.1, 0.3]),
            ]
        );
        assert!(rel.check_admissible(&m, &n).is_ok());
    }

    #[test]
    fn point_relation_on_pairs() {
        let (m, n) = sets();
        let rel = PointRelation::largest_on_pairs(&m, &n, &[(3.0, 6.0), (1.0, 3.0)]).unwrap();
        assert_eq!(rel.entries()[0].degrees.to_array(), [0.8, 0.1, 0.3]);
        let e = PointRelation::largest_on_pairs(&m, &n, &[(1.0, 3.0), (2.0, 3.0)]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "pair 1 at (2, 3): r = 2 is not a member of M"
        );
    }

    #[test]
    fn point_relation_checker_names_pair_and_degree() {
        let (m, n) = sets();
        let rel = PointRelation::new(vec![
            NeutrosophicPoint::new([1.0, 3.0], d(0.3, 0.6, 0.1)),
            NeutrosophicPoint::new([3.0, 6.0], d(0.8, 0.1, 0.4)),
        ]);
        assert_eq!(
            rel.check_admissible(&m, &n).unwrap_err().to_string(),
            "pair 1 at (3, 6): falsity = 0.4 exceeds 0.3, the falsity of N at s = 6 (Def. 4: each degree of the relation must be <= the same degree of M at r and of N at s)"
        );
    }

    #[test]
    fn axis_set_rejects_duplicates_and_nan() {
        let e = AxisSet::new(
            AxisSetName::N,
            vec![(1.0, d(0.0, 0.0, 0.0)), (1.0, d(0.0, 0.0, 0.0))],
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "N: coordinate 1 appears twice (members 0 and 1)"
        );
        assert!(AxisSet::new(AxisSetName::M, vec![(f64::NAN, d(0.0, 0.0, 0.0))]).is_err());
    }
}
