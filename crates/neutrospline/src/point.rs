//! Neutrosophic points, derivative values, intervals and bounding boxes.

use crate::degrees::{DegreeKind, Degrees};

/// A position in `D`-dimensional space (`D` = 2 or 3) with its neutrosophic degrees.
///
/// Used both for control points ([`ControlPoint`]) and for points on a curve ([`CurvePoint`]).
///
/// ```
/// use neutrospline::{Degrees, NeutrosophicPoint};
/// let p = NeutrosophicPoint::new([1.0, 3.0], Degrees::new(0.3, 0.6, 0.1)?);
/// assert_eq!(p.degrees.truth(), 0.3);
/// # Ok::<(), neutrospline::DegreeError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NeutrosophicPoint<const D: usize> {
    /// Coordinates `x, y` (and `z` when `D = 3`).
    pub position: [f64; D],
    /// Truth, indeterminacy and falsity.
    pub degrees: Degrees,
}

/// A control point of a curve: a [`NeutrosophicPoint`].
pub type ControlPoint<const D: usize> = NeutrosophicPoint<D>;

/// A point on a curve: a [`NeutrosophicPoint`].
pub type CurvePoint<const D: usize> = NeutrosophicPoint<D>;

impl<const D: usize> NeutrosophicPoint<D> {
    /// A point from its position and degrees.
    pub const fn new(position: [f64; D], degrees: Degrees) -> Self {
        NeutrosophicPoint { position, degrees }
    }

    /// The degree of the given kind.
    pub const fn degree(&self, kind: DegreeKind) -> f64 {
        self.degrees.get(kind)
    }
}

#[cfg(feature = "serde")]
mod serde_impl {
    //! The serde form of a point is the control point of the model files (see `docs/model.md`):
    //! flat keys `x`, `y`, `z` (3-D only), `truth`, `indeterminacy`, `falsity`, in that order.
    use super::NeutrosophicPoint;
    use crate::degrees::Degrees;
    use serde::{
        de::Error, ser::SerializeStruct, Deserialize, Deserializer, Serialize, Serializer,
    };

    const AXES: [&str; 3] = ["x", "y", "z"];

    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct RawPoint {
        x: f64,
        y: f64,
        z: Option<f64>,
        truth: f64,
        indeterminacy: f64,
        falsity: f64,
    }

    impl<const D: usize> Serialize for NeutrosophicPoint<D> {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            let mut s = serializer.serialize_struct("ControlPoint", D + 3)?;
            for (axis, value) in self.position.iter().enumerate() {
                s.serialize_field(AXES.get(axis).copied().unwrap_or("coordinate"), value)?;
            }
            s.serialize_field("truth", &self.degrees.truth())?;
            s.serialize_field("indeterminacy", &self.degrees.indeterminacy())?;
            s.serialize_field("falsity", &self.degrees.falsity())?;
            s.end()
        }
    }

    impl<'de, const D: usize> Deserialize<'de> for NeutrosophicPoint<D> {
        /// Checks the dimension (`z` present exactly for 3-D points) and the degrees exactly
        /// as [`Degrees::new`] does.
        fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
            let raw = RawPoint::deserialize(deserializer)?;
            let coordinates: Vec<f64> = [raw.x, raw.y].into_iter().chain(raw.z).collect();
            let position: [f64; D] = coordinates.as_slice().try_into().map_err(|_| {
                De::Error::custom(format!(
                    "the point has {} coordinates, expected {D}",
                    coordinates.len()
                ))
            })?;
            let degrees = Degrees::new(raw.truth, raw.indeterminacy, raw.falsity)
                .map_err(De::Error::custom)?;
            Ok(NeutrosophicPoint { position, degrees })
        }
    }
}

/// The derivative of a curve at a parameter: rates of change of the position and of each degree.
///
/// Unlike degrees, rates may be any real number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DerivativeValue<const D: usize> {
    /// d position / dt.
    pub position: [f64; D],
    /// d truth / dt.
    pub truth: f64,
    /// d indeterminacy / dt.
    pub indeterminacy: f64,
    /// d falsity / dt.
    pub falsity: f64,
}

impl<const D: usize> DerivativeValue<D> {
    /// The rate of the given degree.
    pub const fn degree(&self, kind: DegreeKind) -> f64 {
        match kind {
            DegreeKind::Truth => self.truth,
            DegreeKind::Indeterminacy => self.indeterminacy,
            DegreeKind::Falsity => self.falsity,
        }
    }
}

/// A closed interval `[min, max]` of values (the extent of a channel in a
/// [`BoundingBox`]); parameter domains are `core::ops::Range<f64>` instead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub min: f64,
    /// Upper end.
    pub max: f64,
}

impl Interval {
    /// `[min, max]`.
    pub const fn new(min: f64, max: f64) -> Self {
        Interval { min, max }
    }

    /// `max - min`.
    pub fn length(&self) -> f64 {
        self.max - self.min
    }

    /// Whether `min <= value <= max`.
    pub fn contains(&self, value: f64) -> bool {
        self.min <= value && value <= self.max
    }
}

/// Axis-aligned bounds of the positions and of each degree of a curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingBox<const D: usize> {
    /// Range of each coordinate.
    pub position: [Interval; D],
    /// Range of the truth degree.
    pub truth: Interval,
    /// Range of the indeterminacy degree.
    pub indeterminacy: Interval,
    /// Range of the falsity degree.
    pub falsity: Interval,
}

impl<const D: usize> BoundingBox<D> {
    /// The box as two rows, the minima then the maxima of `x, y[, z], truth, indeterminacy,
    /// falsity`.
    ///
    /// ```
    /// use neutrospline::Bounded;
    /// let [min, max] = neutrospline::example1().control_bounding_box().min_max_rows();
    /// assert_eq!(min, [1.0, 2.0, 0.2, 0.1, 0.1]);
    /// assert_eq!(max, [9.0, 6.0, 0.8, 0.6, 0.4]);
    /// ```
    pub fn min_max_rows(&self) -> [Vec<f64>; 2] {
        let intervals: Vec<Interval> = self
            .position
            .iter()
            .copied()
            .chain([self.truth, self.indeterminacy, self.falsity])
            .collect();
        [
            intervals.iter().map(|i| i.min).collect(),
            intervals.iter().map(|i| i.max).collect(),
        ]
    }

    /// The range of the given degree.
    pub const fn degree(&self, kind: DegreeKind) -> Interval {
        match kind {
            DegreeKind::Truth => self.truth,
            DegreeKind::Indeterminacy => self.indeterminacy,
            DegreeKind::Falsity => self.falsity,
        }
    }

    /// The box whose channel `c` (coordinates, then truth, indeterminacy, falsity) spans
    /// `range(c)`.
    pub(crate) fn from_channel_ranges(range: impl Fn(usize) -> (f64, f64)) -> Self {
        let r = |c| {
            let (lo, hi) = range(c);
            Interval::new(lo, hi)
        };
        BoundingBox {
            position: core::array::from_fn(r),
            truth: r(D),
            indeterminacy: r(D + 1),
            falsity: r(D + 2),
        }
    }

    /// The smallest box containing both boxes.
    pub fn union(&self, other: &BoundingBox<D>) -> BoundingBox<D> {
        let u = |a: Interval, b: Interval| Interval::new(a.min.min(b.min), a.max.max(b.max));
        BoundingBox {
            position: core::array::from_fn(|i| u(self.position[i], other.position[i])),
            truth: u(self.truth, other.truth),
            indeterminacy: u(self.indeterminacy, other.indeterminacy),
            falsity: u(self.falsity, other.falsity),
        }
    }

    /// Whether the point's position and degrees are all inside the box.
    pub fn contains(&self, point: &NeutrosophicPoint<D>) -> bool {
        self.position
            .iter()
            .zip(point.position)
            .all(|(r, v)| r.contains(v))
            && DegreeKind::ALL
                .iter()
                .all(|&k| self.degree(k).contains(point.degree(k)))
    }
}

/// An affine map of positions, `p -> linear * p + translation`. Degrees are not affected.
///
/// ```
/// use neutrospline::Affine;
/// let rotate = Affine::new([[0.0, -1.0], [1.0, 0.0]], [1.0, 0.0]);
/// assert_eq!(rotate.apply([2.0, 3.0]), [-2.0, 2.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine<const D: usize> {
    /// Row-major matrix: `linear[r][c]` multiplies coordinate `c` into coordinate `r`.
    pub linear: [[f64; D]; D],
    /// Added after the linear part.
    pub translation: [f64; D],
}

impl<const D: usize> Affine<D> {
    /// `p -> linear * p + translation`.
    pub const fn new(linear: [[f64; D]; D], translation: [f64; D]) -> Self {
        Affine {
            linear,
            translation,
        }
    }

    /// The control points with their positions mapped; degrees unchanged.
    pub(crate) fn apply_to_points(
        &self,
        points: Vec<NeutrosophicPoint<D>>,
    ) -> Vec<NeutrosophicPoint<D>> {
        points
            .into_iter()
            .map(|p| NeutrosophicPoint::new(self.apply(p.position), p.degrees))
            .collect()
    }

    /// The map applied to a position.
    pub fn apply(&self, p: [f64; D]) -> [f64; D] {
        let mut out = self.translation;
        for (r, row) in self.linear.iter().enumerate() {
            for (c, &m) in row.iter().enumerate() {
                out[r] += m * p[c];
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounding_box_contains() {
        let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
        let r = Interval::new(0.0, 1.0);
        let b = BoundingBox {
            position: [Interval::new(0.0, 2.0), Interval::new(-1.0, 1.0)],
            truth: r,
            indeterminacy: r,
            falsity: Interval::new(0.0, 0.4),
        };
        assert!(!b.contains(&NeutrosophicPoint::new([1.0, 0.0], d)));
        let d = Degrees::new(0.5, 0.5, 0.25).unwrap();
        assert!(b.contains(&NeutrosophicPoint::new([1.0, 0.0], d)));
        assert!(!b.contains(&NeutrosophicPoint::new([3.0, 0.0], d)));
    }

    #[cfg(feature = "serde")]
    #[test]
    fn neutrosophic_point_serde_is_the_file_schema() {
        let p = NeutrosophicPoint::new([1.0, 3.0], Degrees::new(0.3, 0.6, 0.1).unwrap());
        let json = serde_json::to_string(&p).unwrap();
        assert_eq!(
            json,
            r#"{"x":1.0,"y":3.0,"truth":0.3,"indeterminacy":0.6,"falsity":0.1}"#
        );
        assert_eq!(
            serde_json::from_str::<NeutrosophicPoint<2>>(&json).unwrap(),
            p
        );
        let q: NeutrosophicPoint<3> =
            serde_json::from_str(r#"{"x":1,"y":2,"z":3,"truth":0,"indeterminacy":0,"falsity":1}"#)
                .unwrap();
        assert_eq!(q.position, [1.0, 2.0, 3.0]);
        let e = serde_json::from_str::<NeutrosophicPoint<3>>(&json).unwrap_err();
        assert!(
            e.to_string()
                .contains("the point has 2 coordinates, expected 3"),
            "{e}"
        );
        let e = serde_json::from_str::<NeutrosophicPoint<2>>(
            r#"{"x":1,"y":2,"truth":1.2,"indeterminacy":0,"falsity":0}"#,
        )
        .unwrap_err();
        assert!(
            e.to_string().contains("truth = 1.2 is outside [0, 1]"),
            "{e}"
        );
        assert!(serde_json::from_str::<NeutrosophicPoint<2>>(
            r#"{"x":1,"y":2,"w":0,"truth":0,"indeterminacy":0,"falsity":0}"#
        )
        .is_err());
    }

    #[test]
    fn affine_apply_3d() {
        let a = Affine::new(
            [[2.0, 0.0, 0.0], [0.0, 1.0, 1.0], [0.0, 0.0, -1.0]],
            [1.0, 1.0, 1.0],
        );
        assert_eq!(a.apply([1.0, 2.0, 3.0]), [3.0, 6.0, -2.0]);
    }
}
