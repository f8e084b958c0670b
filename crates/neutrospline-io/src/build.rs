//! From what a file holds ([`Parsed`]) to a [`Model`] with the core's curve or surface: every
//! check of knots, weights and grids is the core's own (`KnotVector::new`, `Nurbs::new`,
//! `Surface::nurbs`, ...); this module only chooses the constructor and locates the core's
//! errors at the key, line or control point they concern.

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, CurveError, CurveKind, Direction, KnotError,
    KnotVector, Nurbs, Surface, SurfaceError, SurfaceKind,
};

use crate::model::KnotSource;
use crate::parsed::{Origin, Parsed};
use crate::settings::{Key, Kind, KnotRule, KnotSpec, KnotsSetting, Setting, Structure};
use crate::{InputError, Model, Shape};

/// A knot vector that could not be built: the located error, and the core's error when it
/// came from the core.
struct KnotFailure {
    located: InputError,
    error: Option<KnotError>,
    degree: usize,
}

impl Parsed {
    /// Builds the core curve or surface, and the model.
    ///
    /// # Errors
    /// The core's knot, weight and grid errors, located at the key (`degree`, `knots_u`, ...,
    /// or the command-line option that gave it), the knot's line, or the control point.
    pub(crate) fn into_model(mut self) -> Result<Model, InputError> {
        self.wrap_periodic()?;
        let shape = self.shape()?;
        // A wide family's second lane: the same construction with the second lane's degrees
        // (positions, weights and knots are the same, so it cannot fail where the first did not).
        let second = if self.membership.lane_count() == 2 {
            for p in &mut self.points {
                if let Some(second) = p.second {
                    p.degrees = second;
                }
            }
            Some(self.shape()?)
        } else {
            None
        };
        let source = |setting: &Option<KnotsSetting>| match setting.as_ref().map(|k| &k.spec) {
            None => KnotSource::Default,
            Some(KnotSpec::Rule(rule)) => KnotSource::Rule(*rule),
            Some(KnotSpec::Explicit(_)) => KnotSource::Explicit,
        };
        let knot_sources = match (&self.structure, self.kind.has_knots()) {
            (_, false) => Vec::new(),
            (Structure::Curve { knots, .. }, true) => vec![source(knots)],
            (
                Structure::Surface {
                    knots_u, knots_v, ..
                },
                true,
            ) => vec![source(knots_u), source(knots_v)],
        };
        let spreads = self.points.iter().map(|p| p.spread).collect();
        let names = self.points.into_iter().map(|p| p.name).collect();
        Ok(Model::from_parts(
            shape,
            second,
            self.name,
            self.description,
            self.membership,
            names,
            knot_sources,
            spreads,
        ))
    }

    /// Builds the core curve or surface.
    fn shape(&self) -> Result<Shape, InputError> {
        match &self.structure {
            Structure::Curve {
                degree,
                knots,
                periodic,
            } => {
                let (degree, knots) = (degree.as_ref(), knots.as_ref());
                let periodic = is_set(periodic.as_ref());
                if self.dimension == 3 {
                    self.curve::<3>(degree, knots, periodic).map(Shape::from)
                } else {
                    self.curve::<2>(degree, knots, periodic).map(Shape::from)
                }
            }
            Structure::Surface {
                rows,
                cols,
                degree_u,
                degree_v,
                knots_u,
                knots_v,
                periodic_u,
                periodic_v,
            } => self
                .surface(
                    rows,
                    cols,
                    [degree_u.as_ref(), degree_v.as_ref()],
                    [knots_u.as_ref(), knots_v.as_ref()],
                    [is_set(periodic_u.as_ref()), is_set(periodic_v.as_ref())],
                )
                .map(Shape::Surface),
        }
    }

    /// The control points with `D` coordinates (the parsers made every position that long).
    fn control_points<const D: usize>(&self) -> Vec<ControlPoint<D>> {
        self.points
            .iter()
            .map(|p| {
                let mut position = [0.0; D];
                for (slot, &value) in position.iter_mut().zip(&p.position) {
                    *slot = value;
                }
                ControlPoint::new(position, p.degrees)
            })
            .collect()
    }

    /// The weights of the control points (1 where a point has none).
    fn weights(&self) -> Vec<f64> {
        self.points
            .iter()
            .map(|p| p.weight.unwrap_or(1.0))
            .collect()
    }

    /// Repeats the first `degree` control points (surfaces: rows and columns) after the
    /// listed ones along each periodic direction, so that the points are those of the
    /// unclamped spline the periodic one is (`KnotVector::periodic`); names, weights and
    /// spreads come along.
    ///
    /// # Errors
    /// A periodic direction of degree 0, located at the `periodic` key; the grid error of a
    /// surface whose rows and columns do not multiply to the number of points.
    fn wrap_periodic(&mut self) -> Result<(), InputError> {
        let check = |parsed: &Parsed,
                     periodic: Option<&Setting<bool>>,
                     degree: Option<&Setting<usize>>| {
            match (is_set(periodic), degree) {
                (true, Some(d)) if d.value == 0 => Err(parsed.error_at(
                    &periodic.map(|p| p.origin.clone()).unwrap_or_default(),
                    "a periodic spline needs degree >= 1 (degree 0 has nothing to join)".to_owned(),
                )),
                (true, Some(d)) => Ok(d.value),
                _ => Ok(0),
            }
        };
        let count = self.points.len();
        let (rows, cols, extra_u, extra_v) = match &self.structure {
            Structure::Curve {
                degree, periodic, ..
            } => (
                count,
                1,
                check(self, periodic.as_ref(), degree.as_ref())?,
                0,
            ),
            Structure::Surface {
                rows,
                cols,
                degree_u,
                degree_v,
                periodic_u,
                periodic_v,
                ..
            } => {
                let extra_u = check(self, periodic_u.as_ref(), degree_u.as_ref())?;
                let extra_v = check(self, periodic_v.as_ref(), degree_v.as_ref())?;
                if rows.value.checked_mul(cols.value) != Some(count) {
                    // Left for `surface` to refuse with the grid's message.
                    return Ok(());
                }
                (rows.value, cols.value, extra_u, extra_v)
            }
        };
        if (extra_u == 0 && extra_v == 0) || count == 0 {
            return Ok(());
        }
        let mut wrapped = Vec::with_capacity((rows + extra_u) * (cols + extra_v));
        for i in 0..rows + extra_u {
            for j in 0..cols + extra_v {
                wrapped.push(self.points[(i % rows) * cols + j % cols].clone());
            }
        }
        self.points = wrapped;
        Ok(())
    }

    fn curve<const D: usize>(
        &self,
        degree: Option<&Setting<usize>>,
        knots: Option<&KnotsSetting>,
        periodic: bool,
    ) -> Result<AnyCurve<D>, InputError> {
        let points = self.control_points::<D>();
        let count = points.len();
        let kind = match self.kind {
            Kind::Curve(kind) => kind,
            Kind::Surface(_) => return Err(self.internal("a surface kind with curve settings")),
        };
        if kind == CurveKind::Bezier {
            if let Some(degree) = degree.filter(|d| d.value + 1 != count) {
                return Err(self.error_at(
                    &degree.origin,
                    format!(
                        "degree {} does not match the {count} control points (a bezier curve of \
                         n + 1 control points has degree n = {})",
                        degree.value,
                        count - 1
                    ),
                ));
            }
            return Bezier::new(points)
                .map(AnyCurve::Bezier)
                .map_err(|e| self.curve_error(&e));
        }
        let degree = degree.ok_or_else(|| self.missing(Key::Degree))?;
        let positions: Vec<[f64; D]> = points.iter().map(|p| p.position).collect();
        let knots = self
            .knot_vector(degree, count, knots, Some(&positions), periodic)
            .map_err(|e| e.located)?;
        match kind {
            CurveKind::Nurbs => Nurbs::new(points, self.weights(), knots).map(AnyCurve::Nurbs),
            _ => BSpline::new(points, knots).map(AnyCurve::BSpline),
        }
        .map_err(|e| self.curve_error(&e))
    }

    fn surface(
        &self,
        rows: &Setting<usize>,
        cols: &Setting<usize>,
        degrees: [Option<&Setting<usize>>; 2],
        knots: [Option<&KnotsSetting>; 2],
        periodic: [bool; 2],
    ) -> Result<Surface, InputError> {
        let count = self.points.len();
        // Periodic directions were wrapped (`wrap_periodic`): `degree` more rows or columns.
        let extra = |k: usize| degrees[k].filter(|_| periodic[k]).map_or(0, |d| d.value);
        let (rows_all, cols_all) = (rows.value + extra(0), cols.value + extra(1));
        if rows_all.checked_mul(cols_all) != Some(count) {
            let grid = CurveError::GridSize {
                points: count,
                rows: rows.value,
                cols: cols.value,
            };
            return Err(self.error_at(&rows.origin, grid.to_string()));
        }
        let kind = match self.kind {
            Kind::Surface(kind) => kind,
            Kind::Curve(_) => return Err(self.internal("a curve kind with surface settings")),
        };
        let points = self.control_points::<3>();
        let sizes = [(Key::DegreeU, rows), (Key::DegreeV, cols)];
        if kind == SurfaceKind::Bezier {
            for ((key, size), degree) in sizes.into_iter().zip(degrees) {
                if let Some(degree) = degree.filter(|d| d.value + 1 != size.value) {
                    let count_key = if key == Key::DegreeU { "rows" } else { "cols" };
                    return Err(self.error_at(
                        &degree.origin,
                        format!(
                            "{} {} does not match {count_key} = {} (a bezier surface has {} = \
                             {count_key} - 1 = {})",
                            key.name(),
                            degree.value,
                            size.value,
                            key.name(),
                            size.value - 1
                        ),
                    ));
                }
            }
            return Surface::bezier(rows_all, cols_all, points).map_err(|e| self.surface_error(&e));
        }
        let [knots_u, knots_v] = knots;
        let [degree_u, degree_v] = degrees;
        let degree_u = degree_u.ok_or_else(|| self.missing(Key::DegreeU))?;
        let degree_v = degree_v.ok_or_else(|| self.missing(Key::DegreeV))?;
        let knots_u = self
            .knot_vector::<3>(degree_u, rows_all, knots_u, None, periodic[0])
            .map_err(|e| self.surface_knot_error(*e, Direction::U))?;
        let knots_v = self
            .knot_vector::<3>(degree_v, cols_all, knots_v, None, periodic[1])
            .map_err(|e| self.surface_knot_error(*e, Direction::V))?;
        match kind {
            SurfaceKind::Nurbs => {
                Surface::nurbs(rows_all, cols_all, points, self.weights(), knots_u, knots_v)
            }
            _ => Surface::bspline(rows_all, cols_all, points, knots_u, knots_v),
        }
        .map_err(|e| self.surface_error(&e))
    }

    /// Rewords the count-related knot errors of a surface direction in terms of its rows or
    /// columns and its degree key (the core speaks of "control points" and "degree").
    fn surface_knot_error(&self, e: KnotFailure, direction: Direction) -> InputError {
        let (count_key, degree_key, axis) = match direction {
            Direction::U => ("rows", "degree_u", "u"),
            Direction::V => ("cols", "degree_v", "v"),
        };
        let message = match &e.error {
            Some(KnotError::TooFewControlPoints { count, degree }) => format!(
                "{count_key} = {count} control points along {axis} are too few for degree \
                 {degree} (need at least {degree_key} + 1 = {})",
                degree + 1
            ),
            Some(KnotError::WrongLength { got, expected }) => format!(
                "knot vector has {got} knots, expected {expected} ({count_key} + {degree_key} \
                 + 1 = {} + {} + 1)",
                expected - e.degree - 1,
                e.degree
            ),
            _ => e.located.message.clone(),
        };
        InputError {
            message,
            ..e.located
        }
    }

    /// The knots of one direction, by the core's constructor for the rule, or validated by
    /// `KnotVector::new`. `positions` is the control polygon, for the rules that need it
    /// (curves only). A periodic direction (`count` counting the repeated points) takes
    /// breakpoints: given, uniform by default, or spaced along the closed polygon.
    fn knot_vector<const D: usize>(
        &self,
        degree: &Setting<usize>,
        count: usize,
        knots: Option<&KnotsSetting>,
        positions: Option<&[[f64; D]]>,
        periodic: bool,
    ) -> Result<KnotVector, Box<KnotFailure>> {
        let failure = |located: InputError, error: Option<KnotError>| {
            Box::new(KnotFailure {
                located,
                error,
                degree: degree.value,
            })
        };
        let p = degree.value;
        let spec = knots.map(|k| &k.spec);
        if periodic {
            return self
                .periodic_knots(degree, count - p, knots, positions)
                .map_err(|(located, error)| failure(located, error));
        }
        let result = match (spec, positions) {
            (None | Some(KnotSpec::Rule(KnotRule::ClampedUniform)), _) => {
                KnotVector::clamped_uniform(p, count)
            }
            (Some(KnotSpec::Rule(KnotRule::ChordLength)), Some(positions)) => {
                KnotVector::chord_length(p, positions)
            }
            (Some(KnotSpec::Rule(KnotRule::Centripetal)), Some(positions)) => {
                KnotVector::centripetal(p, positions)
            }
            (Some(KnotSpec::Rule(rule)), None) => {
                let origin = knots.map(|k| k.origin.clone()).unwrap_or_default();
                let located = self.error_at(
                    &origin,
                    format!(
                        "{} knots are only available for curves (for surfaces use {} or an \
                         array of knot values)",
                        rule.name(),
                        KnotRule::ClampedUniform.name()
                    ),
                );
                return Err(failure(located, None));
            }
            (Some(KnotSpec::Rule(KnotRule::Uniform)), _) => KnotVector::uniform(p, count),
            (Some(KnotSpec::Explicit(values)), _) => KnotVector::new(values.clone(), p, count),
        };
        result.map_err(|e| {
            let located = match (&e, knots) {
                (KnotError::TooFewControlPoints { .. }, _) | (_, None) => {
                    self.error_at(&degree.origin, e.to_string())
                }
                (_, Some(k)) => self.knot_error_at(&e, k, e.to_string()),
            };
            failure(located, Some(e))
        })
    }

    /// The knots of a periodic direction with `distinct` control points before wrapping.
    fn periodic_knots<const D: usize>(
        &self,
        degree: &Setting<usize>,
        distinct: usize,
        knots: Option<&KnotsSetting>,
        positions: Option<&[[f64; D]]>,
    ) -> Result<KnotVector, (InputError, Option<KnotError>)> {
        let p = degree.value;
        let origin = knots.map(|k| k.origin.clone()).unwrap_or_default();
        let uniform = || {
            let breakpoints: Vec<f64> =
                (0..=distinct).map(|j| j as f64 / distinct as f64).collect();
            KnotVector::periodic(p, &breakpoints)
        };
        let result =
            match (knots.map(|k| &k.spec), positions) {
                (None | Some(KnotSpec::Rule(KnotRule::Uniform)), _) => uniform(),
                (
                    Some(KnotSpec::Rule(rule @ (KnotRule::ChordLength | KnotRule::Centripetal))),
                    Some(positions),
                ) => KnotVector::periodic_averaged(
                    p,
                    &positions[..distinct],
                    *rule == KnotRule::Centripetal,
                ),
                (Some(KnotSpec::Rule(rule)), _) => {
                    let message =
                        format!(
                    "{} knots cannot close a periodic {} (give uniform{}, or the breakpoints: \
                     {} values from the start of one period to its end)",
                    rule.name(),
                    if positions.is_some() { "curve" } else { "surface" },
                    if positions.is_some() { ", chord-length, centripetal" } else { "" },
                    distinct + 1
                );
                    return Err((self.error_at(&origin, message), None));
                }
                (Some(KnotSpec::Explicit(values)), _) if values.len() != distinct + 1 => {
                    let error = KnotError::BreakpointCount {
                        got: values.len(),
                        count: distinct,
                    };
                    return Err((self.error_at(&origin, error.to_string()), Some(error)));
                }
                (Some(KnotSpec::Explicit(values)), _) => KnotVector::periodic(p, values),
            };
        result.map_err(|e| {
            let message = format!("{e} (periodic breakpoints)");
            let located = match knots {
                Some(k) => self.knot_error_at(&e, k, message),
                None => self.error_at(&origin, message),
            };
            (located, Some(e))
        })
    }

    /// `message` about knot error `e` at the line of the knot it names (the declaration's
    /// line for the others).
    fn knot_error_at(&self, e: &KnotError, knots: &KnotsSetting, message: String) -> InputError {
        match e {
            KnotError::Decreasing { index, .. } | KnotError::NotFinite { index, .. } => self
                .error_at(
                    &Origin {
                        line: knots.line_of_knot(*index),
                        field: knots.origin.field.clone(),
                    },
                    message,
                ),
            _ => self.error_at(&knots.origin, message),
        }
    }

    fn curve_error(&self, e: &CurveError) -> InputError {
        let point = |index: usize| self.points.get(index);
        match e {
            CurveError::WeightNotPositive { index, value } => self.error_at(
                &point(*index)
                    .map(|p| p.weight_origin.clone())
                    .unwrap_or_default(),
                format!(
                    "weight = {value} is not a positive finite number (NURBS weights must be > 0)"
                ),
            ),
            CurveError::PositionNotFinite { index, .. } => self.error_at(
                &point(*index).map(|p| p.origin.clone()).unwrap_or_default(),
                e.to_string(),
            ),
            _ => self.error_at(&Origin::default(), e.to_string()),
        }
    }

    fn surface_error(&self, e: &SurfaceError) -> InputError {
        match e {
            SurfaceError::Curve(e) => self.curve_error(e),
            _ => self.error_at(&Origin::default(), e.to_string()),
        }
    }

    fn missing(&self, key: Key) -> InputError {
        self.error_at(
            &Origin::default(),
            format!(
                "missing {} (kind `{}` needs {}: give `{}` in a model file, or {})",
                key.name(),
                self.kind,
                key.purpose(),
                key.name(),
                key.option()
            ),
        )
    }

    fn internal(&self, what: &str) -> InputError {
        self.error_at(&Origin::default(), format!("internal error: {what}"))
    }
}

/// Whether a flag is given and true.
fn is_set(flag: Option<&Setting<bool>>) -> bool {
    flag.is_some_and(|f| f.value)
}
