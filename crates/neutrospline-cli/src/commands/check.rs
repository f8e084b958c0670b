//! `neutrospline check FILE`: validate a file and summarise the curve or surface (for curves
//! with the length and the arc-length averages of the degrees).

use neutrospline::{DegreeKind, DynCurve, EvaluateSurface, Family, GeometryError, KnotVector};
use neutrospline_io::{KnotRule, KnotSource};

use crate::commands::options::ModelArgs;
use crate::input;
use crate::output::{self, number};
use crate::shape::{DegreeView, Shape};

/// Arguments of `check`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "Prints `FILE: valid`, then one `label: value` line each: kind, name (if \
any), degree (curves) or degree_u and degree_v (surfaces), dimension, control points (with \
rows x columns for surfaces), membership, knots (B-spline and NURBS; knots_u and knots_v for \
surfaces), domain (domain_u and domain_v), weights (NURBS: min..max), and the truth, \
indeterminacy and falsity ranges (min..max over the control points), the spreads' ranges \
when a control point has a fuzzy position (`spread_x: left min..max, right min..max`, per \
axis); for curves then the \
length and the arc-length averages (1/L) * integral of q |C'(t)| dt of truth, indeterminacy, \
falsity and score (2 + T - I - F) / 3, to 12 significant digits (relative accuracy 1e-12; \
curves of at most 1000 control points and degree 30).\n\
The interval-valued and bipolar families print a range per channel (truth_lower, ..., \
negative_falsity), their rule in one line (boxes, lower <= upper, the sum with its largest \
value at the control points, derived degrees) and the average of every channel.\n\
Model options: a CSV file lists control points only, so these give its kind, degree, knots and \
grid; with a TOML/JSON file an option fills in a key the file leaves out, and must agree with \
the file where it declares the key."
)]
pub struct CheckArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Shape settings for CSV files.
    #[command(flatten)]
    pub model: ModelArgs,
}

/// Knot lists longer than this are shortened to their first and last [`KNOTS_SHOWN`].
const KNOTS_IN_FULL: usize = 16;
/// Knots shown at each end of a long list.
const KNOTS_SHOWN: usize = 6;

/// `0, 0, 0, 0.5, 1, 1, 1 (7 knots, clamped-uniform)` or `... (9 knots, given, unclamped)`;
/// long lists show their ends only.
fn knots_line(knots: &KnotVector, source: Option<KnotSource>, periodic: bool) -> String {
    let values = knots.knots();
    let shown: Vec<String> = if values.len() > KNOTS_IN_FULL {
        let head = values[..KNOTS_SHOWN].iter().map(|&k| number(k));
        let tail = values[values.len() - KNOTS_SHOWN..]
            .iter()
            .map(|&k| number(k));
        head.chain(["...".to_owned()]).chain(tail).collect()
    } else {
        values.iter().map(|&k| number(k)).collect()
    };
    let source = match source {
        Some(KnotSource::Rule(rule)) if periodic => format!("{}, periodic", rule.name()),
        Some(KnotSource::Rule(rule)) => rule.name().to_owned(),
        Some(KnotSource::Explicit) if knots.is_clamped() => "given, clamped".to_owned(),
        Some(KnotSource::Explicit) if periodic => "given, periodic".to_owned(),
        Some(KnotSource::Explicit) => "given, unclamped".to_owned(),
        _ if periodic => format!("{}, periodic", KnotRule::Uniform.name()),
        _ => KnotRule::ClampedUniform.name().to_owned(),
    };
    format!("{} ({} knots, {source})", shown.join(", "), values.len())
}

/// `value` rounded to 12 significant digits, in shortest form: the quadrature's accuracy.
fn twelve_digits(value: f64) -> String {
    let rounded: f64 = format!("{value:.11e}").parse().unwrap_or(value);
    number(rounded)
}

/// `check` measures curves of at most this many control points (larger ones say so: the
/// quadrature's cost grows with the number of pieces and the degree).
const MEASURED_CONTROL_POINTS: usize = 1000;
/// `check` measures curves of at most this polynomial degree.
const MEASURED_DEGREE: usize = 30;

/// The lines `length: L`, then `average truth: ...` and the others; for a curve of length
/// zero, or one whose length cannot be measured (its speed overflows a 64-bit float), one
/// line that says so instead of the averages (the file is still valid). The averages are those
/// of the degrees `view` shows, and the score's only for the original three families (the
/// score of the others is not linear in the degrees, so its average is not the average
/// curve's score).
///
/// A family of two lanes (docs/model.md, "Lanes") averages every lane's slots; the channels
/// are linear in the slots (`Family::join_slots`), so their averages are the same map of the
/// slots' averages: one line per channel (`average truth_lower: ...`).
fn geometry_lines(lanes: &[&DynCurve], family: Family) -> Vec<String> {
    let view = DegreeView::new(family);
    let curve = lanes[0];
    if curve.len() > MEASURED_CONTROL_POINTS || curve.degree() > MEASURED_DEGREE {
        return vec![format!(
            "length: not measured (check measures curves of at most {MEASURED_CONTROL_POINTS} \
             control points and degree {MEASURED_DEGREE}; `eval --geometry` gives the arc length)"
        )];
    }
    match curve.arc_averages(neutrospline::DEFAULT_ACCURACY) {
        Ok(a) if family.lane_count() > 1 => {
            let mut slots = vec![[a.truth, a.indeterminacy, a.falsity]];
            for lane in &lanes[1..] {
                match lane.arc_averages(neutrospline::DEFAULT_ACCURACY) {
                    Ok(b) => slots.push([b.truth, b.indeterminacy, b.falsity]),
                    Err(e) => return vec![format!("length: not measurable ({e})")],
                }
            }
            let mut lines = vec![format!("length: {}", twelve_digits(a.length))];
            for (name, value) in family
                .channels()
                .iter()
                .zip(family.join_slots(&slots).iter())
            {
                lines.push(format!("average {name}: {}", twelve_digits(*value)));
            }
            lines
        }
        Ok(a) => {
            let mut lines = vec![format!("length: {}", twelve_digits(a.length))];
            for (name, value) in [
                ("truth", a.truth),
                ("indeterminacy", a.indeterminacy),
                ("falsity", a.falsity),
            ] {
                if view.channel_names().contains(&name) {
                    lines.push(format!("average {name}: {}", twelve_digits(value)));
                }
            }
            if view.triple() {
                lines.push(format!("average score: {}", twelve_digits(a.score)));
            }
            lines
        }
        Err(GeometryError::ZeroLength) => vec![
            "length: 0".to_owned(),
            "averages: none (the curve has length zero: all its control positions coincide)"
                .to_owned(),
        ],
        Err(e) => vec![format!("length: not measurable ({e})")],
    }
}

fn domain_line(domain: std::ops::Range<f64>) -> String {
    format!("[{}, {}]", number(domain.start), number(domain.end))
}

/// Validates the file and prints its summary.
///
/// # Errors
/// An invalid file, or a write error.
pub fn run(args: &CheckArgs) -> anyhow::Result<()> {
    let model = input::read_model(&args.file, &args.model)?;
    let file = input::label(&args.file);
    let name = model.name().map(str::to_owned);
    let membership = model.membership();
    // How the knots were given: one source per knot direction (u, then v for surfaces).
    let sources = model.knot_sources().to_vec();
    let source = |i: usize| sources.get(i).copied();
    // A direction is periodic when its knots are and its points repeat (`periodic_counts`).
    let periodic = model.periodic_counts();
    let periodic = |i: usize| periodic.get(i).copied().flatten().is_some();
    let spreads = model.spreads().map(<[_]>::to_vec);
    let channels = model.control_channels();
    let geometry = match model.shape() {
        Shape::Curve(_) => {
            let lanes: Vec<&DynCurve> = model.lanes().iter().filter_map(|s| s.curve()).collect();
            geometry_lines(&lanes, membership)
        }
        Shape::Surface(_) => Vec::new(),
    };
    let shape = model.into_shape();
    output::emit(None, |w| {
        writeln!(w, "{file}: valid")?;
        writeln!(w, "kind: {}", shape.kind())?;
        if let Some(name) = &name {
            writeln!(w, "name: {name}")?;
        }
        match &shape {
            Shape::Surface(s) => {
                writeln!(w, "degree_u: {}", s.degree_u())?;
                writeln!(w, "degree_v: {}", s.degree_v())?;
                writeln!(w, "dimension: 3")?;
                let plural =
                    |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
                writeln!(
                    w,
                    "control points: {} ({} x {})",
                    shape.control_count(),
                    plural(s.rows(), "row"),
                    plural(s.cols(), "column")
                )?;
                writeln!(w, "membership: {membership}")?;
                if shape.kind().has_knots() {
                    writeln!(
                        w,
                        "knots_u: {}",
                        knots_line(s.knots_u(), source(0), periodic(0))
                    )?;
                    writeln!(
                        w,
                        "knots_v: {}",
                        knots_line(s.knots_v(), source(1), periodic(1))
                    )?;
                }
                let [domain_u, domain_v] = s.domain();
                writeln!(w, "domain_u: {}", domain_line(domain_u))?;
                writeln!(w, "domain_v: {}", domain_line(domain_v))?;
            }
            _ => {
                if let Some(degree) = shape.curve_degree() {
                    writeln!(w, "degree: {degree}")?;
                }
                writeln!(w, "dimension: {}", shape.dimension())?;
                writeln!(w, "control points: {}", shape.control_count())?;
                writeln!(w, "membership: {membership}")?;
                if let Some(knots) = shape.curve_knots() {
                    writeln!(w, "knots: {}", knots_line(knots, source(0), periodic(0)))?;
                }
                if let Some(domain) = shape.curve_domain() {
                    writeln!(w, "domain: {}", domain_line(domain))?;
                }
            }
        }
        if let Some(weights) = shape.weights() {
            let (min, max) = weights
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &w| {
                    (lo.min(w), hi.max(w))
                });
            writeln!(w, "weights: {}..{}", number(min), number(max))?;
        }
        let view = DegreeView::new(membership);
        // Degrees are computed from values in [0, 1] (under the intuitionistic rule the
        // indeterminacy is 1 - T - F): printed to the precision that justifies.
        let degree = |v: f64| neutrospline_io::format_justified(v, 1.0);
        if membership.lane_count() > 1 {
            // A line per channel: its range over the control points.
            for (c, name) in membership.channels().iter().enumerate() {
                let (min, max) = channels
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                        (lo.min(v[c]), hi.max(v[c]))
                    });
                writeln!(w, "{name}: {}..{}", degree(min), degree(max))?;
            }
        }
        for (kind, range) in DegreeKind::ALL.iter().zip(shape.degree_ranges()) {
            if membership.lane_count() == 1 && view.channel_names().contains(&kind.name()) {
                writeln!(w, "{kind}: {}..{}", degree(range.min), degree(range.max))?;
            }
        }
        // The rule's sum at the control points (the curve's stays below its largest: the
        // rule is convex), for the families with a sum rule beyond the original three; a
        // family of two lanes states its whole rule (`Family::rule_text`, without the name the
        // `membership` line gives).
        if !view.triple() {
            let sums: Vec<(String, f64)> = channels
                .iter()
                .filter_map(|values| membership.rule_sum(values))
                .collect();
            let largest = sums
                .iter()
                .map(|(_, s)| *s)
                .fold(f64::NEG_INFINITY, f64::max);
            if membership.lane_count() > 1 {
                let text = membership.rule_text();
                let rule = text
                    .strip_prefix(&format!("{membership}: "))
                    .unwrap_or(&text);
                match sums.first() {
                    Some((terms, _)) => writeln!(
                        w,
                        "rule: {rule} (largest {terms} at the control points: {})",
                        degree(largest)
                    )?,
                    None => writeln!(w, "rule: {rule}")?,
                }
            } else if let Some((terms, _)) = sums.first() {
                writeln!(
                    w,
                    "rule: {terms} <= 1 (largest at the control points: {})",
                    degree(largest)
                )?;
            }
        }
        if let Some(spreads) = &spreads {
            let range = |values: &mut dyn Iterator<Item = f64>| {
                let (min, max) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                });
                format!("{}..{}", number(min), number(max))
            };
            for (axis, name) in ["x", "y", "z"][..shape.dimension()].iter().enumerate() {
                writeln!(
                    w,
                    "spread_{name}: left {}, right {}",
                    range(&mut spreads.iter().map(|s| s.left[axis])),
                    range(&mut spreads.iter().map(|s| s.right[axis]))
                )?;
            }
        }
        for line in &geometry {
            writeln!(w, "{line}")?;
        }
        Ok(())
    })
}
