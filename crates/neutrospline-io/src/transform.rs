//! [`TransformRequest`]: the operations of `neutrospline transform` (one per call), defined
//! once for every front end, and [`transform`], which applies one to a model: the curve or
//! surface, its membership rule, point names and spreads.
//!
//! What each operation keeps (docs/cli.md, "transform"):
//! - the membership rule always: every exact operation forms new control degrees as convex
//!   combinations, which keep every rule; the degrees a rule derives (the intuitionistic
//!   hesitation) are derived again from the blended ones, exactly as a reader does;
//! - point names where the control points stay the same points (`reverse`, reversed;
//!   `reparametrize`); the other operations make new points, and the names are dropped,
//!   which the summary says;
//! - spreads (fuzzy positions) through the same exact operation (they are blended by the
//!   same basis); knot removal is not exact, so a model with spreads is refused there.

use std::fmt::Write as _;

use neutrospline::options::{
    find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind,
};
use neutrospline::{
    on_dimension, AnyCurve, BSpline, Bezier, ControlPoint, ControlPolygon, Degrees, Direction,
    DynCurve, Family, Nurbs, Split as _, Spread, Surface, SurfaceKind,
};

use crate::model::Model;
use crate::shape::Shape;

/// One operation of [`transform`].
#[derive(Debug, Clone, PartialEq)]
pub enum Operation {
    /// Raise the degree by this much.
    Elevate(usize),
    /// Lower the degree by `times` while the curve moves by at most `tolerance`.
    Reduce {
        /// How many degrees lower.
        times: usize,
        /// The largest deviation allowed.
        tolerance: f64,
    },
    /// Insert these knots, each once.
    InsertKnots(Vec<f64>),
    /// This many knots inside every span.
    Refine(usize),
    /// Remove the knot `value` up to `times` times (its multiplicity when `None`) while the
    /// curve moves by at most `tolerance`.
    RemoveKnot {
        /// The knot.
        value: f64,
        /// At most this many removals.
        times: Option<usize>,
        /// The largest deviation allowed.
        tolerance: f64,
    },
    /// Two pieces at this parameter.
    Split(f64),
    /// The piece between two parameters (reversed when the first is larger).
    Subsegment(f64, f64),
    /// The direction of travel reversed.
    Reverse,
    /// One Bézier piece per span.
    ToBezier,
    /// The domain mapped onto this interval.
    Reparametrize(f64, f64),
}

impl Operation {
    /// The operation's option name.
    pub fn name(&self) -> &'static str {
        match self {
            Operation::Elevate(_) => "elevate",
            Operation::Reduce { .. } => "reduce",
            Operation::InsertKnots(_) => "insert-knot",
            Operation::Refine(_) => "refine",
            Operation::RemoveKnot { .. } => "remove-knot",
            Operation::Split(_) => "split",
            Operation::Subsegment(..) => "subsegment",
            Operation::Reverse => "reverse",
            Operation::ToBezier => "to-bezier",
            Operation::Reparametrize(..) => "reparametrize",
        }
    }
}

/// The options of `neutrospline transform`: exactly one operation, and for a surface the
/// direction it acts in.
///
/// ```
/// use neutrospline::options::{OptionSet, OptionValue};
/// use neutrospline_io::{Operation, TransformRequest};
/// let mut request = TransformRequest::default();
/// request.set("insert-knot", OptionValue::Word("0.25,0.5,0.5".into()))?;
/// assert_eq!(request.operation().unwrap(), Operation::InsertKnots(vec![0.25, 0.5, 0.5]));
/// request.set("reverse", OptionValue::Flag(true))?;
/// assert_eq!(
///     request.operation().unwrap_err(),
///     "give one operation per call (given: insert-knot, reverse)"
/// );
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TransformRequest {
    /// `elevate`.
    pub elevate: Option<usize>,
    /// `reduce`.
    pub reduce: Option<usize>,
    /// `insert-knot`.
    pub insert_knot: Option<Vec<f64>>,
    /// `refine`.
    pub refine: Option<usize>,
    /// `remove-knot`.
    pub remove_knot: Option<f64>,
    /// `times`: at most this many removals.
    pub times: Option<usize>,
    /// `tolerance`: the largest deviation a removal may cause.
    pub tolerance: Option<f64>,
    /// `split`.
    pub split: Option<f64>,
    /// `subsegment`.
    pub subsegment: Option<(f64, f64)>,
    /// `reverse`.
    pub reverse: bool,
    /// `to-bezier`.
    pub to_bezier: bool,
    /// `reparametrize`.
    pub reparametrize: Option<(f64, f64)>,
    /// `direction` of a surface.
    pub direction: Option<Direction>,
}

/// The options that modify an operation rather than name one.
const MODIFIERS: [&str; 3] = ["times", "tolerance", "direction"];

/// `A:B` as two numbers.
fn interval(text: &str) -> Option<(f64, f64)> {
    let (a, b) = text.split_once(':')?;
    Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
}

impl OptionSet for TransformRequest {
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "elevate",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "Raise the degree by N (exact)",
        },
        OptionSpec {
            name: "reduce",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "Lower the degree by N within --tolerance (each Bézier piece replaced by its \
                   nearest of lower degree, then knots removed as the tolerance allows); reports \
                   the deviation",
        },
        OptionSpec {
            name: "insert-knot",
            kind: ValueKind::Numbers,
            value_name: "T1,T2,...",
            help: "Insert these knots (exact); a value given k times is inserted k times",
        },
        OptionSpec {
            name: "refine",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "Insert N knots evenly inside every span (exact)",
        },
        OptionSpec {
            name: "remove-knot",
            kind: ValueKind::Number,
            value_name: "T",
            help: "Remove the interior knot T as often as --tolerance allows (Tiller's \
                   algorithm); reports how many times and the deviation",
        },
        OptionSpec {
            name: "times",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "With --remove-knot: at most N removals (default: the knot's multiplicity)",
        },
        OptionSpec {
            name: "tolerance",
            kind: ValueKind::Number,
            value_name: "E",
            help: "With --remove-knot or --reduce: the largest deviation allowed, in model units \
                   (positions; degrees on their own scale)",
        },
        OptionSpec {
            name: "split",
            kind: ValueKind::Number,
            value_name: "T",
            help: "Two pieces at parameter T, written to OUT-1 and OUT-2",
        },
        OptionSpec {
            name: "subsegment",
            kind: ValueKind::Text,
            value_name: "A:B",
            help: "The piece between parameters A and B (reversed when A > B)",
        },
        OptionSpec {
            name: "reverse",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Reverse the direction of travel (the same points, in reverse order)",
        },
        OptionSpec {
            name: "to-bezier",
            kind: ValueKind::Flag,
            value_name: "",
            help: "One Bézier piece per knot span, written to OUT-1, OUT-2, ...",
        },
        OptionSpec {
            name: "reparametrize",
            kind: ValueKind::Text,
            value_name: "A:B",
            help: "Map the parameter domain onto [A, B] (the same curve)",
        },
        OptionSpec {
            name: "direction",
            kind: ValueKind::Choice(&["u", "v"]),
            value_name: "DIR",
            help: "For a surface: the parameter direction the operation acts in",
        },
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let read = spec.read(&value)?;
        let invalid = |expected: &str| OptionError::Invalid {
            name: spec.name,
            given: value.to_string(),
            expected: expected.to_owned(),
        };
        match (spec.name, read) {
            ("elevate", Read::Whole(n)) => self.elevate = Some(n),
            ("reduce", Read::Whole(n)) => self.reduce = Some(n),
            ("insert-knot", Read::Numbers(v)) => self.insert_knot = Some(v),
            ("refine", Read::Whole(n)) => self.refine = Some(n),
            ("remove-knot", Read::Number(x)) => self.remove_knot = Some(x),
            ("times", Read::Whole(n)) => self.times = Some(n),
            ("tolerance", Read::Number(x)) => {
                if !(x.is_finite() && x >= 0.0) {
                    return Err(invalid("expected a finite number >= 0"));
                }
                self.tolerance = Some(x);
            }
            ("split", Read::Number(x)) => self.split = Some(x),
            ("subsegment", Read::Text(t)) => {
                self.subsegment =
                    Some(interval(&t).ok_or_else(|| invalid("expected A:B, two numbers"))?);
            }
            ("reverse", Read::Flag(on)) => self.reverse = on,
            ("to-bezier", Read::Flag(on)) => self.to_bezier = on,
            ("reparametrize", Read::Text(t)) => {
                self.reparametrize =
                    Some(interval(&t).ok_or_else(|| invalid("expected A:B, two numbers"))?);
            }
            ("direction", Read::Choice(word)) => {
                self.direction = Some(if word == "u" {
                    Direction::U
                } else {
                    Direction::V
                });
            }
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let join = |v: &[f64]| v.iter().map(f64::to_string).collect::<Vec<_>>().join(",");
        Ok(match spec.name {
            "elevate" => self.elevate.map(|n| n.to_string()),
            "reduce" => self.reduce.map(|n| n.to_string()),
            "insert-knot" => self.insert_knot.as_deref().map(join),
            "refine" => self.refine.map(|n| n.to_string()),
            "remove-knot" => self.remove_knot.map(|x| x.to_string()),
            "times" => self.times.map(|n| n.to_string()),
            "tolerance" => self.tolerance.map(|x| x.to_string()),
            "split" => self.split.map(|x| x.to_string()),
            "subsegment" => self.subsegment.map(|(a, b)| format!("{a}:{b}")),
            "reverse" => Some(self.reverse.to_string()),
            "to-bezier" => Some(self.to_bezier.to_string()),
            "reparametrize" => self.reparametrize.map(|(a, b)| format!("{a}:{b}")),
            "direction" => self.direction.map(|d| d.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

impl TransformRequest {
    /// The one operation asked for.
    ///
    /// # Errors
    /// No operation or more than one; `--times` or `--tolerance` without `--remove-knot`;
    /// `--remove-knot` without `--tolerance`.
    pub fn operation(&self) -> Result<Operation, String> {
        let mut given = Vec::new();
        if let Some(n) = self.elevate {
            given.push(Operation::Elevate(n));
        }
        if let Some(times) = self.reduce {
            let tolerance = self.tolerance.ok_or(
                "--reduce needs --tolerance E: the largest deviation the reduction may cause",
            )?;
            given.push(Operation::Reduce { times, tolerance });
        }
        if let Some(k) = &self.insert_knot {
            given.push(Operation::InsertKnots(k.clone()));
        }
        if let Some(n) = self.refine {
            given.push(Operation::Refine(n));
        }
        if let Some(value) = self.remove_knot {
            let tolerance = self.tolerance.ok_or(
                "--remove-knot needs --tolerance E: the largest deviation the removal may cause",
            )?;
            given.push(Operation::RemoveKnot {
                value,
                times: self.times,
                tolerance,
            });
        } else if self.times.is_some() {
            return Err("--times goes with --remove-knot".to_owned());
        } else if self.tolerance.is_some() && self.reduce.is_none() {
            return Err("--tolerance goes with --remove-knot or --reduce".to_owned());
        }
        if let Some(t) = self.split {
            given.push(Operation::Split(t));
        }
        if let Some((a, b)) = self.subsegment {
            given.push(Operation::Subsegment(a, b));
        }
        if self.reverse {
            given.push(Operation::Reverse);
        }
        if self.to_bezier {
            given.push(Operation::ToBezier);
        }
        if let Some((a, b)) = self.reparametrize {
            given.push(Operation::Reparametrize(a, b));
        }
        match given.len() {
            1 => Ok(given.remove(0)),
            0 => Err(format!(
                "give one operation: {}",
                Self::OPTIONS
                    .iter()
                    .map(|o| o.name)
                    .filter(|n| !MODIFIERS.contains(n))
                    .map(|n| format!("--{n}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
            _ => Err(format!(
                "give one operation per call (given: {})",
                given
                    .iter()
                    .map(Operation::name)
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
        }
    }
}

/// The models an operation made, and what it did.
#[derive(Debug, Clone)]
pub struct Transformed {
    /// One model, or the pieces of `split` and `to-bezier` in order.
    pub models: Vec<Model>,
    /// One line on what was done (for example how many removals, the deviation, what was
    /// dropped).
    pub summary: String,
    /// For a knot removal: how many removals were asked for and how many were made.
    pub removals: Option<(usize, usize)>,
}

/// Values within this of the degree box are rounding.
const ROUNDING: f64 = 1e-12;

/// The degrees as the membership rule's reader makes them from the blended channels: the
/// intuitionistic hesitation derived from truth and falsity again (a sum of rounding-free
/// terms differs from the blended one by an ulp), a truth + falsity above 1 by rounding
/// brought back to 1; under any other family, channels that break the rule by rounding
/// projected onto it.
fn conform(membership: Family, degrees: Degrees) -> Result<Degrees, String> {
    let [t, i, f] = degrees.to_array();
    let made = match membership {
        Family::Neutrosophic => return Ok(degrees),
        Family::Intuitionistic => {
            let f = if t + f > 1.0 && t + f <= 1.0 + ROUNDING {
                1.0 - t
            } else {
                f
            };
            Degrees::with_membership(membership, t, None, Some(f))
        }
        family => {
            let mut values = family.from_degrees(&degrees).unwrap_or_default();
            if family.check(&values).is_err() && family.check_within(&values, ROUNDING).is_ok() {
                family.project(&mut values);
            }
            family.to_degrees(&values)
        }
    };
    made.map_err(|e| format!("a new control point's degrees ({t}, {i}, {f}) break the rule: {e}"))
}

fn conform_points<const D: usize>(
    points: Vec<ControlPoint<D>>,
    membership: Family,
) -> Result<Vec<ControlPoint<D>>, String> {
    points
        .into_iter()
        .map(|p| {
            Ok(ControlPoint::new(
                p.position,
                conform(membership, p.degrees)?,
            ))
        })
        .collect()
}

/// A curve of `curve`'s kind, knots and weights through `points` (of any dimension).
fn with_points<const D: usize, const E: usize>(
    curve: &AnyCurve<D>,
    points: Vec<ControlPoint<E>>,
) -> Result<AnyCurve<E>, String> {
    match curve {
        AnyCurve::Bezier(_) => Bezier::new(points).map(Into::into),
        AnyCurve::BSpline(c) => BSpline::new(points, c.knots().clone()).map(Into::into),
        AnyCurve::Nurbs(c) => Nurbs::new(
            points,
            c.weights().unwrap_or(&[]).to_vec(),
            c.knots().clone(),
        )
        .map(Into::into),
    }
    .map_err(|e| e.to_string())
}

/// The curve with its control degrees conformed to `membership`.
fn conform_curve<const D: usize>(
    curve: AnyCurve<D>,
    membership: Family,
) -> Result<AnyCurve<D>, String> {
    if membership == Family::Neutrosophic {
        return Ok(curve);
    }
    with_points(&curve, conform_points(curve.control_points(), membership)?)
}

fn conform_surface(surface: Surface, membership: Family) -> Result<Surface, String> {
    if membership == Family::Neutrosophic {
        return Ok(surface);
    }
    let points = conform_points(surface.control_points(), membership)?;
    surface_with_points(&surface, points)
}

/// A surface of `surface`'s kind, net, knots and weights through `points`.
fn surface_with_points(surface: &Surface, points: Vec<ControlPoint<3>>) -> Result<Surface, String> {
    let (rows, cols) = (surface.rows(), surface.cols());
    let (ku, kv) = (surface.knots_u().clone(), surface.knots_v().clone());
    match surface.kind() {
        SurfaceKind::Bezier => Surface::bezier(rows, cols, points),
        SurfaceKind::BSpline => Surface::bspline(rows, cols, points, ku, kv),
        SurfaceKind::Nurbs => Surface::nurbs(
            rows,
            cols,
            points,
            surface.weights().unwrap_or(&[]).to_vec(),
            ku,
            kv,
        ),
    }
    .map_err(|e| e.to_string())
}

/// The shape with its control degrees replaced by `degrees` (one per control point; surfaces
/// row by row), the geometry kept.
fn shape_with_degrees(shape: &Shape, degrees: &[Degrees]) -> Result<Shape, String> {
    fn replaced<const D: usize>(
        points: Vec<ControlPoint<D>>,
        degrees: &[Degrees],
    ) -> Vec<ControlPoint<D>> {
        points
            .into_iter()
            .zip(degrees)
            .map(|(p, d)| ControlPoint::new(p.position, *d))
            .collect()
    }
    Ok(match shape {
        Shape::Curve(curve) => {
            let curve: DynCurve = on_dimension!(curve, c => {
                with_points(c, replaced(c.control_points(), degrees))?.into()
            });
            Shape::from(curve)
        }
        Shape::Surface(s) => Shape::from(surface_with_points(
            s,
            replaced(s.control_points(), degrees),
        )?),
    })
}

/// The lanes of a wide family joined into one model: the first lane's model (its name,
/// description, names and spreads) with `second` as its second lane; channels that break the
/// rule by rounding only (within 1e-12; for example `T_U + F_U` an ulp above 1 after blending)
/// projected onto it, as a reader of the channels would refuse them otherwise.
fn join_lanes(first: Model, second: &Shape, family: Family) -> Result<Model, String> {
    let lanes = [first.shape().control_degrees(), second.control_degrees()];
    let mut changed = false;
    let mut out = lanes.clone();
    for i in 0..lanes[0].len() {
        let mut values = family.join(&[lanes[0][i], lanes[1][i]]).to_vec();
        if family.check(&values).is_err() && family.check_within(&values, ROUNDING).is_ok() {
            family.project(&mut values);
            let (split, _) = family.split(&values).map_err(|e| {
                format!("control point {i}: the channels projected onto the rule break it: {e}")
            })?;
            out[0][i] = split[0];
            out[1][i] = split[1];
            changed = true;
        }
    }
    let (first, second) = if changed {
        let shape = shape_with_degrees(first.shape(), &out[0])?;
        let second = shape_with_degrees(second, &out[1])?;
        let mut model = Model::new(shape);
        if let Some(s) = first.spreads() {
            model = model.with_spreads(s.to_vec()).map_err(|e| e.to_string())?;
        }
        if first.point_names().iter().any(Option::is_some) {
            model = model
                .with_point_names(first.point_names().to_vec())
                .map_err(|e| e.to_string())?;
        }
        if let Some(n) = first.name() {
            model = model.with_name(n);
        }
        if let Some(d) = first.description() {
            model = model.with_description(d);
        }
        (model, second)
    } else {
        (first, second.clone())
    };
    first
        .with_lanes(family, second)
        .map_err(|e| format!("the transformed lanes: {e}"))
}

/// A model of one lane of `model` (a neutrosophic triple per control point) with its name,
/// description, point names and, for the first lane, its spreads.
fn lane_model(model: &Model, lane: usize) -> Result<Model, String> {
    let mut out = Model::new(model.lanes()[lane].clone());
    if lane == 0 {
        if let Some(s) = model.spreads() {
            out = out.with_spreads(s.to_vec()).map_err(|e| e.to_string())?;
        }
    }
    if model.point_names().iter().any(Option::is_some) {
        out = out
            .with_point_names(model.point_names().to_vec())
            .map_err(|e| e.to_string())?;
    }
    if let Some(n) = model.name() {
        out = out.with_name(n);
    }
    if let Some(d) = model.description() {
        out = out.with_description(d);
    }
    Ok(out)
}

/// What a joint operation on two lanes made: the lanes, a note, and for a knot removal the
/// removals asked for and made.
type LaneOutcome<T = DynCurve> = ([T; 2], String, Option<(usize, usize)>);

/// [`transform`] for an interval-valued or bipolar family (two lanes, `Family::lanes`): an
/// exact operation applied to each lane alike (the lanes keep one geometry, and blending keeps
/// `lower <= upper` and every other convex rule); degree reduction and knot removal applied to
/// both lanes as one spline, their channels solved jointly under the family's rule
/// (`AnyCurve::reduced_lanes`, `AnyCurve::without_knot_lanes`; for a surface every line of
/// both nets at once, `Surface::reduced_lanes`, `Surface::remove_knot_lanes`).
fn transform_lanes(
    model: &Model,
    op: &Operation,
    direction: Option<Direction>,
) -> Result<Transformed, String> {
    let family = model.membership();
    let first = lane_model(model, 0)?;
    if !matches!(op, Operation::Reduce { .. } | Operation::RemoveKnot { .. }) {
        let a = transform(&first, op, direction)?;
        let b = transform(&lane_model(model, 1)?, op, direction)?;
        let models = a
            .models
            .into_iter()
            .zip(&b.models)
            .map(|(m, other)| join_lanes(m, other.shape(), family))
            .collect::<Result<Vec<_>, String>>()?;
        return Ok(Transformed {
            models,
            summary: a.summary,
            removals: a.removals,
        });
    }
    if model.spreads().is_some() {
        return Err(format!(
            "--{} is not exact, so the spreads (fuzzy positions) of this model cannot \
             follow it; remove them first",
            op.name()
        ));
    }
    let lanes = model.lanes();
    let (c0, c1) = match (lanes[0], lanes[1]) {
        (Shape::Curve(c0), Shape::Curve(c1)) => (c0, c1),
        (Shape::Surface(s0), Shape::Surface(s1)) => {
            let (pieces, note, removals) = surface_lanes_op([s0, s1], op, direction, family)?;
            return lanes_model(model, op, pieces.map(Shape::from), note, removals);
        }
        _ => return Err("the lanes are not both curves or both surfaces".to_owned()),
    };
    if let Some(d) = direction {
        return Err(format!(
            "--direction {d} is for surfaces; this model is a curve"
        ));
    }
    use neutrospline::Dimensional::{Planar, Spatial};
    let mismatch = || "the lanes have different dimensions".to_owned();
    let (pieces, note, removals): LaneOutcome = match op {
        Operation::Reduce { times, tolerance } => {
            fn reduce<const D: usize>(
                a: &neutrospline::AnyCurve<D>,
                b: &neutrospline::AnyCurve<D>,
                times: usize,
                tolerance: f64,
                family: Family,
            ) -> Result<([DynCurve; 2], String), String>
            where
                DynCurve: From<neutrospline::AnyCurve<D>>,
            {
                let r = neutrospline::AnyCurve::reduced_lanes([a, b], times, tolerance, family)
                    .map_err(|e| e.to_string())?;
                let note = format!(
                    "degree {} -> {}; largest deviation found {:e} over both lanes (tolerance \
                     {tolerance:e}); the channels solved jointly under the {family} rule",
                    a.degree(),
                    r.curve[0].degree(),
                    r.error
                );
                Ok((r.curve.map(DynCurve::from), note))
            }
            let (pieces, note) = match (c0, c1) {
                (Planar(a), Planar(b)) => reduce(a, b, *times, *tolerance, family)?,
                (Spatial(a), Spatial(b)) => reduce(a, b, *times, *tolerance, family)?,
                _ => return Err(mismatch()),
            };
            (pieces, note, None)
        }
        Operation::RemoveKnot {
            value,
            times,
            tolerance,
        } => {
            fn remove<const D: usize>(
                a: &neutrospline::AnyCurve<D>,
                b: &neutrospline::AnyCurve<D>,
                value: f64,
                times: Option<usize>,
                tolerance: f64,
                family: Family,
            ) -> Result<LaneOutcome, String>
            where
                DynCurve: From<neutrospline::AnyCurve<D>>,
            {
                let times = times.unwrap_or_else(|| a.knots().map_or(0, |k| k.multiplicity(value)));
                let r = neutrospline::AnyCurve::without_knot_lanes(
                    [a, b],
                    value,
                    times,
                    tolerance,
                    family,
                )
                .map_err(|e| e.to_string())?;
                let note = removal_note(&value.to_string(), times, r.removed, r.error, tolerance);
                Ok((r.curve.map(DynCurve::from), note, Some((times, r.removed))))
            }
            match (c0, c1) {
                (Planar(a), Planar(b)) => remove(a, b, *value, *times, *tolerance, family)?,
                (Spatial(a), Spatial(b)) => remove(a, b, *value, *times, *tolerance, family)?,
                _ => return Err(mismatch()),
            }
        }
        _ => unreachable!("the exact operations are handled above"),
    };
    lanes_model(model, op, pieces.map(Shape::from), note, removals)
}

/// The model of two transformed lanes: `model`'s name, its description marked as
/// transformed by `op`, the family's rule kept ([`join_lanes`]); point names dropped (the
/// joint operations make new control points), which the summary says after `note`.
fn lanes_model(
    model: &Model,
    op: &Operation,
    pieces: [Shape; 2],
    note: String,
    removals: Option<(usize, usize)>,
) -> Result<Transformed, String> {
    let family = model.membership();
    let [p0, p1] = pieces;
    let mut m = Model::new(p0);
    if let Some(n) = model.name() {
        m = m.with_name(n);
    }
    let description = match model.description() {
        Some(d) => format!("{d} (transformed: {})", op.name()),
        None => format!("Transformed by neutrospline transform --{}", op.name()),
    };
    m = m.with_description(description);
    let mut summary = note;
    if model.point_names().iter().any(Option::is_some) {
        let _ = write!(
            summary,
            "; point names dropped (--{} makes new control points)",
            op.name()
        );
    }
    Ok(Transformed {
        models: vec![join_lanes(m, &p1, family)?],
        summary,
        removals,
    })
}

/// Degree reduction or knot removal in `direction` on the two lanes of a surface of an
/// interval-valued or bipolar family: every line of both nets a curve of two lanes, their
/// channels solved jointly under the family's rule (`Surface::reduced_lanes`,
/// `Surface::remove_knot_lanes`).
fn surface_lanes_op(
    lanes: [&Surface; 2],
    op: &Operation,
    direction: Option<Direction>,
    family: Family,
) -> Result<LaneOutcome<Surface>, String> {
    let direction = direction
        .ok_or_else(|| format!("--{} on a surface needs --direction u or v", op.name()))?;
    match op {
        Operation::Reduce { times, tolerance } => {
            let r = Surface::reduced_lanes(lanes, direction, *times, *tolerance, family)
                .map_err(|e| format!("{direction}: {e}"))?;
            let note = format!(
                "degree_{direction} {} -> {}; largest deviation found {:e} over both lanes \
                 (tolerance {tolerance:e}); the channels solved jointly under the {family} rule",
                degree_of(lanes[0], direction),
                degree_of(&r.curve[0], direction),
                r.error
            );
            Ok((r.curve, note, None))
        }
        Operation::RemoveKnot {
            value,
            times,
            tolerance,
        } => {
            let times = times.unwrap_or_else(|| lanes[0].knots(direction).multiplicity(*value));
            let r = Surface::remove_knot_lanes(lanes, direction, *value, times, *tolerance, family)
                .map_err(|e| format!("knots_{direction}: {e}"))?;
            let note = removal_note(
                &format!("{direction} = {value}"),
                times,
                r.removed,
                r.error,
                *tolerance,
            );
            Ok((r.curve, note, Some((times, r.removed))))
        }
        _ => unreachable!("only the joint operations come here"),
    }
}

/// A curve of the same kind, knots and weights whose positions are `positions` (the spreads'
/// companion: blended by the same basis, so the same operation carries them).
fn companion<const D: usize>(curve: &AnyCurve<D>, positions: &[[f64; 3]]) -> AnyCurve<3> {
    let d = Degrees::new(0.0, 0.0, 0.0).unwrap_or_else(|e| unreachable!("zeros are degrees: {e}"));
    let points = positions.iter().map(|&p| ControlPoint::new(p, d)).collect();
    with_points(curve, points)
        .unwrap_or_else(|e| unreachable!("the companion has the curve's valid layout: {e}"))
}

/// What an operation made: the pieces, a note, and for a knot removal the removals asked for
/// and made.
type Outcome<T> = (Vec<T>, String, Option<(usize, usize)>);

/// The curve operation on any kind and dimension: the pieces and a note.
fn curve_op<const D: usize>(
    curve: &AnyCurve<D>,
    op: &Operation,
    membership: Family,
) -> Result<Outcome<AnyCurve<D>>, String> {
    let (pieces, note) = match op {
        Operation::Elevate(n) => (vec![curve.elevated(*n)], String::new()),
        Operation::Reduce { times, tolerance } => {
            let r = curve
                .reduced(*times, *tolerance, membership)
                .map_err(|e| e.to_string())?;
            let note = format!(
                "degree {} -> {}; largest deviation found {:e} (tolerance {tolerance:e})",
                curve.degree(),
                r.curve.degree(),
                r.error
            );
            (vec![r.curve], note)
        }
        Operation::InsertKnots(k) => (
            vec![curve.with_knots_inserted(k).map_err(|e| e.to_string())?],
            String::new(),
        ),
        Operation::Refine(n) => (vec![curve.refined(*n)], String::new()),
        Operation::RemoveKnot {
            value,
            times,
            tolerance,
        } => {
            let times =
                times.unwrap_or_else(|| curve.knots().map_or(0, |k| k.multiplicity(*value)));
            let r = curve
                .without_knot(*value, times, *tolerance)
                .map_err(|e| e.to_string())?;
            let note = removal_note(&value.to_string(), times, r.removed, r.error, *tolerance);
            return Ok((vec![r.curve], note, Some((times, r.removed))));
        }
        Operation::Split(t) => {
            let (a, b) = curve.split(*t).map_err(|e| e.to_string())?;
            (vec![a, b], String::new())
        }
        Operation::Subsegment(a, b) => (
            vec![curve.subsegment(*a, *b).map_err(|e| e.to_string())?],
            String::new(),
        ),
        Operation::Reverse => (vec![curve.reversed()], String::new()),
        Operation::ToBezier => (
            curve.bezier_pieces().into_iter().map(|(_, c)| c).collect(),
            String::new(),
        ),
        Operation::Reparametrize(a, b) => (
            vec![curve.reparametrized(*a, *b).map_err(|e| e.to_string())?],
            String::new(),
        ),
    };
    Ok((pieces, note, None))
}

fn surface_op(
    surface: &Surface,
    op: &Operation,
    direction: Option<Direction>,
    membership: Family,
) -> Result<Outcome<Surface>, String> {
    if let Operation::ToBezier = op {
        return Ok((surface.to_bezier_patches(), String::new(), None));
    }
    let direction = direction
        .ok_or_else(|| format!("--{} on a surface needs --direction u or v", op.name()))?;
    let (pieces, note) = match op {
        Operation::Elevate(n) => {
            let mut s = surface.clone();
            for _ in 0..*n {
                s = s.elevate(direction);
            }
            (vec![s], String::new())
        }
        Operation::Reduce { times, tolerance } => {
            let mut s = surface.clone();
            for _ in 0..*times {
                s = s
                    .reduce_degree(direction, *tolerance, membership)
                    .map_err(|e| format!("{direction}: {e}"))?
                    .curve;
            }
            let error = surface.deviation_from(&s);
            if error.is_nan() || error > *tolerance {
                return Err(format!(
                    "{direction}: {}",
                    neutrospline::ReduceError::NotWithin {
                        degree: degree_of(&s, direction),
                        tolerance: *tolerance,
                        error,
                    }
                ));
            }
            let note = format!(
                "degree_{direction} {} -> {}; largest deviation found {error:e} (tolerance {tolerance:e})",
                degree_of(surface, direction),
                degree_of(&s, direction)
            );
            (vec![s], note)
        }
        Operation::InsertKnots(k) => {
            let mut s = surface.clone();
            for &u in k {
                s = s
                    .insert_knot(direction, u, 1)
                    .map_err(|e| format!("knots_{direction}: {e}"))?;
            }
            (vec![s], String::new())
        }
        Operation::Refine(n) => (vec![surface.refine(direction, *n)], String::new()),
        Operation::RemoveKnot {
            value,
            times,
            tolerance,
        } => {
            let times = times.unwrap_or_else(|| surface.knots(direction).multiplicity(*value));
            let r = surface
                .remove_knot(direction, *value, times, *tolerance)
                .map_err(|e| format!("knots_{direction}: {e}"))?;
            let note = removal_note(
                &format!("{direction} = {value}"),
                times,
                r.removed,
                r.error,
                *tolerance,
            );
            return Ok((vec![r.curve], note, Some((times, r.removed))));
        }
        Operation::Split(t) => {
            let (a, b) = surface
                .split(direction, *t)
                .map_err(|e| format!("{direction}: {e}"))?;
            (vec![a, b], String::new())
        }
        Operation::Subsegment(a, b) => (
            vec![surface
                .subsegment(direction, *a, *b)
                .map_err(|e| format!("{direction}: {e}"))?],
            String::new(),
        ),
        Operation::Reverse => (vec![surface.reversed(direction)], String::new()),
        Operation::Reparametrize(a, b) => (
            vec![surface
                .reparametrized(direction, *a, *b)
                .map_err(|e| e.to_string())?],
            String::new(),
        ),
        Operation::ToBezier => unreachable!("handled above"),
    };
    Ok((pieces, note, None))
}

fn degree_of(surface: &Surface, direction: Direction) -> usize {
    match direction {
        Direction::U => surface.degree_u(),
        Direction::V => surface.degree_v(),
    }
}

/// Applies `op` to `model` (`direction` for a surface; a curve refuses one): the new
/// model(s), each passing `check`, and a summary.
///
/// # Errors
/// The operation's own (a parameter outside the domain, a knot that is not interior, a
/// multiplicity above the degree + 1, an empty piece), `--direction` missing for a surface
/// or given for a curve, knot removal on a model with spreads.
///
/// ```
/// use neutrospline_io::{transform, Model, Operation};
/// let model = Model::new(neutrospline::AnyCurve::from(neutrospline::example1()));
/// let out = transform(&model, &Operation::Split(0.5), None)?;
/// assert_eq!(out.models.len(), 2);
/// # Ok::<(), String>(())
/// ```
pub fn transform(
    model: &Model,
    op: &Operation,
    direction: Option<Direction>,
) -> Result<Transformed, String> {
    if model.membership().lane_count() == 2 {
        return transform_lanes(model, op, direction);
    }
    let membership = model.membership();
    let spreads = model.spreads();
    let mut summary = String::new();
    let mut models = Vec::new();
    let removals;
    let keep_names = matches!(op, Operation::Reverse | Operation::Reparametrize(..));
    match model.shape() {
        Shape::Curve(curve) => {
            if let Some(d) = direction {
                return Err(format!(
                    "--direction {d} is for surfaces; this model is a curve"
                ));
            }
            if spreads.is_some()
                && matches!(op, Operation::RemoveKnot { .. } | Operation::Reduce { .. })
            {
                return Err(format!(
                    "--{} is not exact, so the spreads (fuzzy positions) of this model cannot \
                     follow it; remove them first",
                    op.name()
                ));
            }
            let (pieces, note, spread_pieces): (
                Vec<DynCurve>,
                String,
                Option<Vec<Vec<Spread<3>>>>,
            ) = on_dimension!(curve, c => {
                let (pieces, note, counts) = curve_op(c, op, membership)?;
                removals = counts;
                let spread_pieces = match spreads {
                    None => None,
                    Some(s) => {
                        let left: Vec<[f64; 3]> = s.iter().map(|x| x.left).collect();
                        let right: Vec<[f64; 3]> = s.iter().map(|x| x.right).collect();
                        let (lp, _, _) = curve_op(&companion(c, &left), op, membership)?;
                        let (rp, _, _) = curve_op(&companion(c, &right), op, membership)?;
                        Some(lp.iter().zip(&rp).map(|(l, r)| {
                            l.control_points().iter().zip(r.control_points()).map(|(a, b)| {
                                let clean = |v: [f64; 3]| v.map(|x| if x < 0.0 && x > -ROUNDING { 0.0 } else { x });
                                Spread { left: clean(a.position), right: clean(b.position) }
                            }).collect()
                        }).collect())
                    }
                };
                let pieces = pieces
                    .into_iter()
                    .map(|p| conform_curve(p, membership).map(DynCurve::from))
                    .collect::<Result<Vec<_>, String>>()?;
                (pieces, note, spread_pieces)
            });
            summary.push_str(&note);
            for (k, piece) in pieces.into_iter().enumerate() {
                let mut m = Model::new(piece)
                    .with_membership(membership)
                    .map_err(|e| e.to_string())?;
                if let Some(s) = &spread_pieces {
                    m = m.with_spreads(s[k].clone()).map_err(|e| e.to_string())?;
                }
                models.push(m);
            }
        }
        Shape::Surface(surface) => {
            let (pieces, note, counts) = surface_op(surface, op, direction, membership)?;
            removals = counts;
            summary.push_str(&note);
            for piece in pieces {
                let piece = conform_surface(piece, membership)?;
                models.push(
                    Model::new(piece)
                        .with_membership(membership)
                        .map_err(|e| e.to_string())?,
                );
            }
        }
    }
    let names = model.point_names();
    let named = names.iter().any(Option::is_some);
    for m in &mut models {
        if let Some(name) = model.name() {
            *m = m.clone().with_name(name);
        }
        let what = op.name();
        let description = match model.description() {
            Some(d) => format!("{d} (transformed: {what})"),
            None => format!("Transformed by neutrospline transform --{what}"),
        };
        *m = m.clone().with_description(description);
        if named && keep_names {
            let mut kept = names.to_vec();
            if matches!(op, Operation::Reverse) && !model.shape().is_surface() {
                kept.reverse();
            }
            if kept.len() == m.shape().control_count() && !model.shape().is_surface() {
                *m = m
                    .clone()
                    .with_point_names(kept)
                    .map_err(|e| e.to_string())?;
            }
        }
    }
    let names_kept = keep_names && !model.shape().is_surface();
    if named && !names_kept {
        if !summary.is_empty() {
            summary.push_str("; ");
        }
        let _ = write!(
            summary,
            "point names dropped (--{} makes new control points)",
            op.name()
        );
    }
    Ok(Transformed {
        models,
        summary,
        removals,
    })
}

/// What a knot removal did: how many times of the `times` asked, and the deviation, or
/// that the first removal already broke the tolerance.
fn removal_note(knot: &str, times: usize, removed: usize, error: f64, tolerance: f64) -> String {
    if removed == 0 {
        format!(
            "knot {knot} not removed: removing it once would move the curve by more than the \
             tolerance {tolerance:e}"
        )
    } else {
        format!(
            "removed knot {knot} {removed} of {times} times; largest deviation found {error:e} \
             (tolerance {tolerance:e})"
        )
    }
}
