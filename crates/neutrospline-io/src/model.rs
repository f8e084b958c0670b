//! [`Model`]: what a model file holds once validated, in any format.

use neutrospline::{DegreeError, Degrees, Family, FamilyValues, Spread};

use crate::settings::{Kind, KnotRule, KnotSpec};
use crate::{ReadOptions, Shape};

/// How the knots of one direction were given; see [`Model::knot_sources`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum KnotSource {
    /// Not given: the default rule, clamped-uniform.
    Default,
    /// Computed by a named rule (`knots = "chord-length"`, `--knots centripetal`).
    Rule(KnotRule),
    /// Given as values: in the file, in the options, or in the shape a program built.
    Explicit,
}

/// A model that a program cannot build ([`Model::with_membership`],
/// [`Model::with_point_names`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ModelError {
    /// Not one name (or `None`) per control point.
    #[error("{names} point names for {points} control points (give one name, or none, per control point)")]
    NameCount {
        /// Names given.
        names: usize,
        /// Control points of the shape.
        points: usize,
    },
    /// A control point's degrees do not obey the membership rule exactly as a reader would
    /// produce them (intuitionistic: indeterminacy = 1 - truth - falsity to the last bit; fuzzy:
    /// indeterminacy and falsity 0).
    #[error("control point {index}: {error}")]
    Family {
        /// The control point (surfaces: row by row).
        index: usize,
        /// The rule broken.
        #[source]
        error: DegreeError,
    },
    /// Lanes that do not make a model of the family (docs/model.md, "Lanes"): a wide family
    /// given one lane, a family of one lane given two, or lanes whose geometry differs.
    #[error("{0}")]
    Lanes(String),
    /// Spreads that a model cannot carry: not one per control point, negative or not finite,
    /// a spread of `z` on a planar curve, or spreads on a surface.
    #[error("{0}")]
    Spread(String),
}

/// A curve or surface with what a model file says about it: an optional name and description,
/// the membership rule of the degrees, and optional names of the control points.
///
/// Readers ([`crate::load`], [`crate::parse`], [`crate::read_csv`]) produce one; a program
/// builds one from a core curve or surface with [`Model::new`] and the `with_` methods, and
/// writes it with [`crate::save`] or [`crate::to_toml_string`] and the like. Every `Model`
/// writes to a file that reads back to an equal `Model` (CSV: see [`crate::to_csv_string`]).
///
/// ```
/// use neutrospline::{example1, AnyCurve, Family};
/// use neutrospline_io::{parse, to_toml_string, Format, Model, ReadOptions};
///
/// let model = Model::new(AnyCurve::Bezier(example1()))
///     .with_name("Example 1")
///     .with_point_names(["C0", "C1", "C2", "C3"].map(Some))?;
/// let text = to_toml_string(&model);
/// let back = parse("example1.toml", Format::Toml, text.as_bytes(), &ReadOptions::default())?;
/// assert_eq!(back, model);
/// assert_eq!(back.membership(), Family::Neutrosophic);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Model {
    name: Option<String>,
    description: Option<String>,
    membership: Family,
    point_names: Vec<Option<String>>,
    shape: Shape,
    /// The second lane of an interval-valued or bipolar family (`Family::lanes`): the same
    /// geometry as `shape`, with the second lane's degrees.
    second: Option<Shape>,
    knot_sources: Vec<KnotSource>,
    /// One per control point (all zero when the model has none; `z` zero for planar curves).
    spreads: Vec<Spread<3>>,
}

impl PartialEq for Model {
    /// Equal name, description, membership rule, point names and shape; how the knots were
    /// given ([`Model::knot_sources`]) is not part of the value.
    fn eq(&self, other: &Model) -> bool {
        self.name == other.name
            && self.description == other.description
            && self.membership == other.membership
            && self.point_names == other.point_names
            && self.shape == other.shape
            && self.second == other.second
            && self.spreads == other.spreads
    }
}

/// The knot directions of a shape: none (Bézier), one (curves), two (surfaces).
fn knot_directions(shape: &Shape) -> usize {
    match (shape.kind().has_knots(), shape.is_surface()) {
        (false, _) => 0,
        (true, false) => 1,
        (true, true) => 2,
    }
}

/// `lower and upper`, `positive and negative`: the names of a family's lanes.
fn lane_names(membership: Family) -> String {
    let names: Vec<&str> = membership.lanes().iter().map(|l| l.name).collect();
    names.join(" and ")
}

/// Whether `degrees` are exactly what a reader produces under `membership` from the degrees
/// the rule keeps (truth and falsity; truth alone).
fn obeys(membership: Family, degrees: &Degrees) -> Result<(), DegreeError> {
    let [t, i, f] = degrees.to_array();
    let derived = Degrees::with_membership(membership, t, Some(i), Some(f))?;
    if derived.indeterminacy() != i {
        return Err(DegreeError::HesitationMismatch {
            given: i,
            hesitation: derived.indeterminacy(),
        });
    }
    Ok(())
}

impl Model {
    /// A model of `shape`: no name, description or point names, neutrosophic degrees, knots
    /// explicit.
    pub fn new(shape: impl Into<Shape>) -> Model {
        let shape = shape.into();
        Model {
            name: None,
            description: None,
            membership: Family::Neutrosophic,
            point_names: vec![None; shape.control_count()],
            knot_sources: vec![KnotSource::Explicit; knot_directions(&shape)],
            spreads: vec![Spread::ZERO; shape.control_count()],
            shape,
            second: None,
        }
    }

    /// A model from parts a reader validated.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts(
        shape: Shape,
        second: Option<Shape>,
        name: Option<String>,
        description: Option<String>,
        membership: Family,
        point_names: Vec<Option<String>>,
        knot_sources: Vec<KnotSource>,
        spreads: Vec<Spread<3>>,
    ) -> Model {
        Model {
            name,
            description,
            membership,
            point_names,
            shape,
            second,
            knot_sources,
            spreads,
        }
    }

    /// With these spreads (SPEC section 9), one per control point: each control point's
    /// coordinates become triangular fuzzy numbers `(x - left, x, x + right)`. Planar curves
    /// take the `x` and `y` spreads (`z` must be 0); surfaces take none (all must be 0).
    ///
    /// # Errors
    /// [`ModelError::Spread`]: not one spread per control point, a spread that is negative
    /// or not finite, a `z` spread on a planar curve, or a non-zero spread on a surface.
    pub fn with_spreads(mut self, spreads: Vec<Spread<3>>) -> Result<Model, ModelError> {
        Spread::check_all(&spreads, self.shape.control_count())
            .map_err(|e| ModelError::Spread(e.to_string()))?;
        for (index, spread) in spreads.iter().enumerate() {
            let bad = match &self.shape {
                Shape::Surface(_) => !spread.is_zero(),
                Shape::Curve(c) => {
                    c.dimension() == 2 && (spread.left[2] != 0.0 || spread.right[2] != 0.0)
                }
            };
            if bad {
                return Err(ModelError::Spread(format!(
                    "control point {index}: {}",
                    if self.shape.is_surface() {
                        "spreads apply to curves only, not to surfaces"
                    } else {
                        "a planar curve has no z to spread"
                    }
                )));
            }
        }
        self.spreads = spreads;
        Ok(self)
    }

    /// The spreads of the control points (SPEC section 9), in order, when any is non-zero;
    /// `None` for a crisp model. Planar curves have `z` spreads 0.
    pub fn spreads(&self) -> Option<&[Spread<3>]> {
        self.spreads
            .iter()
            .any(|s| !s.is_zero())
            .then_some(self.spreads.as_slice())
    }

    /// With this name (TOML / JSON `name`).
    #[must_use]
    pub fn with_name(mut self, name: impl Into<String>) -> Model {
        self.name = Some(name.into());
        self
    }

    /// With this description (TOML / JSON `description`; `plot` uses it as the caption).
    #[must_use]
    pub fn with_description(mut self, description: impl Into<String>) -> Model {
        self.description = Some(description.into());
        self
    }

    /// The model of `membership` from the shape of each of its lanes, as a fit returns them:
    /// [`Model::with_membership`] for a family of one lane (`second` must be `None`),
    /// [`Model::with_lanes`] with `second` for a family of two (docs/model.md, "Lanes").
    ///
    /// # Errors
    /// As [`Model::with_membership`] and [`Model::with_lanes`]; [`ModelError::Lanes`] for a
    /// second lane missing or given where the family has one.
    pub fn with_family(
        self,
        membership: Family,
        second: Option<impl Into<Shape>>,
    ) -> Result<Model, ModelError> {
        match (membership.lane_count(), second) {
            (1, None) => self.with_membership(membership),
            (1, Some(_)) => Err(ModelError::Lanes(format!(
                "the {membership} family has one lane; a second lane was given"
            ))),
            (_, Some(second)) => self.with_lanes(membership, second),
            (_, None) => Err(ModelError::Lanes(format!(
                "the {membership} family rides in two lanes; its {} lane is missing",
                membership.lanes()[1].name
            ))),
        }
    }

    /// With this membership rule for the degrees.
    ///
    /// # Errors
    /// [`ModelError::Family`] for the first control point whose degrees do not obey the
    /// rule exactly as a reader would build them: intuitionistic degrees need truth + falsity
    /// <= 1 and indeterminacy equal to `(1 - truth - falsity).max(0)` (as
    /// [`Degrees::intuitionistic`] computes it); fuzzy degrees need indeterminacy and falsity 0.
    pub fn with_membership(mut self, membership: Family) -> Result<Model, ModelError> {
        if membership.lane_count() != 1 {
            return Err(ModelError::Lanes(format!(
                "the {membership} family rides in two lanes ({}); give the second lane with \
                 Model::with_lanes",
                lane_names(membership)
            )));
        }
        self.second = None;
        for (index, degrees) in self.shape.control_degrees().iter().enumerate() {
            obeys(membership, degrees).map_err(|error| ModelError::Family { index, error })?;
        }
        self.membership = membership;
        Ok(self)
    }

    /// With an interval-valued or bipolar family (`Family::lanes`): this model's shape is the
    /// first lane (`lower`, or `positive`), `second` the second lane (`upper`, or the negated
    /// `negative` degrees), with the same geometry.
    ///
    /// ```
    /// use neutrospline::{AnyCurve, Bezier, ControlPoint, Degrees, Family};
    /// use neutrospline_io::Model;
    /// let lane = |t: f64| -> Result<AnyCurve<2>, neutrospline::CurveError> {
    ///     let d = Degrees::new(t, 0.0, 0.0).unwrap();
    ///     let points = vec![ControlPoint::new([0.0, 0.0], d), ControlPoint::new([1.0, 1.0], d)];
    ///     Ok(AnyCurve::Bezier(Bezier::new(points)?))
    /// };
    /// let model = Model::new(lane(0.2)?).with_lanes(Family::IntervalType2, lane(0.7)?)?;
    /// assert_eq!(&*model.control_channels()[0], &[0.2, 0.7]); // truth_lower, truth_upper
    /// assert!(Model::new(lane(0.9)?).with_lanes(Family::IntervalType2, lane(0.7)?).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`ModelError::Lanes`] for a family of one lane or a second lane of another geometry;
    /// [`ModelError::Family`] for the first control point whose channels break the rule (or
    /// whose lanes hold what no channel values give, such as a non-zero slot the family does
    /// not use).
    pub fn with_lanes(
        mut self,
        membership: Family,
        second: impl Into<Shape>,
    ) -> Result<Model, ModelError> {
        let second = second.into();
        if membership.lane_count() != 2 {
            return Err(ModelError::Lanes(format!(
                "the {membership} family has one lane; use Model::with_membership"
            )));
        }
        if !self.shape.same_geometry(&second) {
            return Err(ModelError::Lanes(format!(
                "the {} lane has another geometry than the {} lane (positions, weights, degree \
                 and knots must be the same)",
                membership.lanes()[1].name,
                membership.lanes()[0].name
            )));
        }
        let (first, other) = (self.shape.control_degrees(), second.control_degrees());
        for (index, (a, b)) in first.iter().zip(&other).enumerate() {
            let channels = membership.join(&[*a, *b]);
            let fail = |error| ModelError::Family { index, error };
            let (lanes, _) = membership.split(&channels).map_err(fail)?;
            if lanes[0] != *a || lanes[1] != *b {
                return Err(ModelError::Lanes(format!(
                    "control point {index}: the lanes hold degrees {:?} and {:?}, which no {membership} \
                     channel values give (a slot the family does not use must be 0, lanes hold \
                     values in [0, 1])",
                    a.to_array(),
                    b.to_array()
                )));
            }
        }
        self.membership = membership;
        self.second = Some(second);
        Ok(self)
    }

    /// The lanes of the model (`Family::lanes`): the shape, and the second lane of an
    /// interval-valued or bipolar family; all have the same geometry.
    pub fn lanes(&self) -> Vec<&Shape> {
        core::iter::once(&self.shape)
            .chain(self.second.as_ref())
            .collect()
    }

    /// The channel values of every control point (surfaces row by row), in the family's
    /// channel order (`Family::channels`).
    pub fn control_channels(&self) -> Vec<FamilyValues> {
        let lanes: Vec<Vec<Degrees>> = self.lanes().iter().map(|s| s.control_degrees()).collect();
        (0..self.shape.control_count())
            .map(|i| {
                let at: Vec<Degrees> = lanes.iter().map(|lane| lane[i]).collect();
                self.membership.join(&at)
            })
            .collect()
    }

    /// The same model with every lane replaced by `map(lane)`: for operations that act on the
    /// geometry and blend the degrees with the basis (docs/model.md, "Lanes"), applied to each
    /// lane alike so the lanes keep one geometry.
    ///
    /// # Errors
    /// The first error of `map`.
    pub fn map_lanes<E>(
        mut self,
        mut map: impl FnMut(Shape) -> Result<Shape, E>,
    ) -> Result<Model, E> {
        self.shape = map(self.shape)?;
        self.second = self.second.map(map).transpose()?;
        Ok(self)
    }

    /// With names for the control points (in order; surfaces row by row), `None` for a point
    /// without one.
    ///
    /// # Errors
    /// [`ModelError::NameCount`] unless there is one item per control point.
    pub fn with_point_names<S: Into<String>>(
        mut self,
        names: impl IntoIterator<Item = Option<S>>,
    ) -> Result<Model, ModelError> {
        let names: Vec<Option<String>> = names.into_iter().map(|n| n.map(Into::into)).collect();
        let points = self.shape.control_count();
        if names.len() != points {
            return Err(ModelError::NameCount {
                names: names.len(),
                points,
            });
        }
        self.point_names = names;
        Ok(self)
    }

    /// The name, if any.
    pub fn name(&self) -> Option<&str> {
        self.name.as_deref()
    }

    /// The description, if any.
    pub fn description(&self) -> Option<&str> {
        self.description.as_deref()
    }

    /// The rule the degrees obey.
    pub fn membership(&self) -> Family {
        self.membership
    }

    /// The kind of curve or surface.
    pub fn kind(&self) -> Kind {
        self.shape.kind()
    }

    /// One name (or `None`) per control point, in order (surfaces row by row).
    pub fn point_names(&self) -> &[Option<String>] {
        &self.point_names
    }

    /// The curve or surface.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// The curve or surface, taken out of the model.
    pub fn into_shape(self) -> Shape {
        self.shape
    }

    /// How the knots were given, per knot direction: none for the Bézier kinds, one for a
    /// B-spline or NURBS curve, two (u, then v) for a B-spline or NURBS surface.
    ///
    /// This is provenance, for reports such as `neutrospline check`'s `knots: ...
    /// (chord-length)`: it is not part of the model's value (ignored by `==`), and the writers
    /// always write the knots as values ([`KnotSource::Explicit`] once read back).
    pub fn knot_sources(&self) -> &[KnotSource] {
        &self.knot_sources
    }

    /// For each knot direction (as [`Model::knot_sources`]), the number of distinct control
    /// points when the direction is periodic (`KnotVector::periodic_breakpoints`) and
    /// everything a file holds of a control point (position, degrees, weight, name, spread)
    /// repeats after them; `None` otherwise. The writers write such a model in its periodic
    /// form: `periodic = true`, the breakpoints as knots and the distinct control points.
    pub fn periodic_counts(&self) -> Vec<Option<usize>> {
        let points = self.shape.point_data();
        let same = |a: usize, b: usize| {
            let (p, q) = (&points[a], &points[b]);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            bits(&p.position) == bits(&q.position)
                && bits(&p.degrees.to_array()) == bits(&q.degrees.to_array())
                && p.weight.map(f64::to_bits) == q.weight.map(f64::to_bits)
                && self.point_names[a] == self.point_names[b]
                && self.spreads[a] == self.spreads[b]
        };
        // (knots, points along the direction, lines across it, the index of (along, across))
        type Direction<'a> = (
            &'a neutrospline::KnotVector,
            usize,
            usize,
            Box<dyn Fn(usize, usize) -> usize>,
        );
        let directions: Vec<Direction<'_>> = match &self.shape {
            Shape::Curve(_) => self
                .shape
                .curve_knots()
                .map(|k| -> Direction<'_> { (k, points.len(), 1, Box::new(|i, _| i)) })
                .into_iter()
                .collect(),
            Shape::Surface(s) if self.kind().has_knots() => {
                let cols = s.cols();
                vec![
                    (
                        s.knots_u(),
                        s.rows(),
                        cols,
                        Box::new(move |i, j| i * cols + j),
                    ),
                    (
                        s.knots_v(),
                        cols,
                        s.rows(),
                        Box::new(move |j, i| i * cols + j),
                    ),
                ]
            }
            Shape::Surface(_) => Vec::new(),
        };
        directions
            .into_iter()
            .map(|(knots, count, across, index)| {
                knots.periodic_breakpoints()?;
                let n = count - knots.degree();
                (n..count)
                    .all(|i| (0..across).all(|line| same(index(i, line), index(i - n, line))))
                    .then_some(n)
            })
            .collect()
    }

    /// The options that read [`crate::to_csv_string`]`(self)` back into this model (without its
    /// name and description, which a CSV file cannot hold): the kind, the membership rule, the
    /// degree(s), explicit knots and the grid.
    pub fn csv_read_options(&self) -> ReadOptions {
        let mut options = ReadOptions {
            kind: Some(self.kind()),
            membership: Some(self.membership),
            ..ReadOptions::default()
        };
        let periodic = self.periodic_counts();
        let periodic = |k: usize| periodic.get(k).copied().flatten();
        // Periodic directions as the writers write them: breakpoints, distinct points.
        let explicit = |k: &neutrospline::KnotVector, periodic: Option<usize>| {
            let values = match periodic {
                Some(_) => k.periodic_breakpoints().unwrap_or_default(),
                None => k.knots(),
            };
            Some(KnotSpec::Explicit(values.to_vec()))
        };
        let flag = |periodic: Option<usize>| periodic.map(|_| true);
        match &self.shape {
            Shape::Curve(_) => {
                if let Some(knots) = self.shape.curve_knots() {
                    options.degree = self.shape.curve_degree();
                    options.knots = explicit(knots, periodic(0));
                    options.periodic = flag(periodic(0));
                }
            }
            Shape::Surface(s) => {
                options.rows = Some(periodic(0).unwrap_or(s.rows()));
                options.cols = Some(periodic(1).unwrap_or(s.cols()));
                if self.kind().has_knots() {
                    options.degree_u = Some(s.degree_u());
                    options.degree_v = Some(s.degree_v());
                    options.knots_u = explicit(s.knots_u(), periodic(0));
                    options.knots_v = explicit(s.knots_v(), periodic(1));
                    options.periodic_u = flag(periodic(0));
                    options.periodic_v = flag(periodic(1));
                }
            }
        }
        options
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{example1, AnyCurve, ControlPoint, Surface};

    #[test]
    fn model_builders() {
        let model = Model::new(AnyCurve::Bezier(example1()))
            .with_name("n")
            .with_description("d");
        assert_eq!(model.name(), Some("n"));
        assert_eq!(model.description(), Some("d"));
        assert_eq!(model.point_names(), [None, None, None, None]);
        assert!(model.knot_sources().is_empty());
        assert_eq!(
            model
                .clone()
                .with_point_names([Some("a")])
                .unwrap_err()
                .to_string(),
            "1 point names for 4 control points (give one name, or none, per control point)"
        );
        assert_eq!(
            model
                .clone()
                .with_membership(Family::Fuzzy)
                .unwrap_err()
                .to_string(),
            "control point 0: indeterminacy = 0.6 is not allowed (fuzzy rule: only truth is \
             given; indeterminacy must be absent or 0)"
        );
        assert_eq!(
            model
                .with_membership(Family::Intuitionistic)
                .unwrap_err()
                .to_string(),
            "control point 1: indeterminacy = 0.1 differs from the hesitation 1 - truth - \
             falsity = 0.09999999999999995 (intuitionistic rule: indeterminacy is derived; \
             omit it or give 1 - truth - falsity)"
        );
    }

    #[test]
    fn intuitionistic_membership_is_exact() {
        let exact = Degrees::intuitionistic(0.8, 0.1).unwrap();
        let close = Degrees::new(0.8, 0.1, 0.1).unwrap();
        assert_ne!(exact, close, "1 - 0.8 - 0.1 is not 0.1 in binary");
        assert!(close.check_membership(Family::Intuitionistic).is_ok());
        let surface = |d| Surface::bezier(1, 1, vec![ControlPoint::new([0.0; 3], d)]).unwrap();
        assert!(Model::new(surface(exact))
            .with_membership(Family::Intuitionistic)
            .is_ok());
        let e = Model::new(surface(close))
            .with_membership(Family::Intuitionistic)
            .unwrap_err();
        assert!(matches!(
            e,
            ModelError::Family {
                index: 0,
                error: DegreeError::HesitationMismatch { .. }
            }
        ));
    }
}
