//! `neutrospline eval FILE`: a table of the curve or surface (and its derivatives) at chosen
//! parameters, written row by row as it is computed.

use std::ops::Range;

use neutrospline::{
    alpha_cut, centroid_curve, map_dimension, on_dimension, uniform_parameter, AnyCurve,
    CurveGeometry, Dimensional, Evaluate, EvaluateSurface, Spread,
};

use crate::commands::options::{ModelArgs, TableArgs};
use crate::input::{self, UsageError};

use crate::progress::Progress;
use crate::shape::{lanes_sampler, Extras, Param, Sampler, Shape, Table};
use neutrospline_io::Cell;

/// Arguments of `eval`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Columns:\n  \
curves    t, x, y[, z], truth, indeterminacy, falsity; with --scores score, accuracy,\n            \
certainty; with --derivative the rates d/dt dx, dy[, dz], dtruth, dindeterminacy,\n            \
dfalsity (--derivative 2 adds d2x, ..., d2falsity, --derivative 3 also d3x, ...,\n            \
d3falsity); with --geometry arc_length (from the start of the domain) and curvature\n            \
(empty in CSV, null in JSON, where |C'(t)| = 0); then with --alpha A the alpha-cut\n            \
x_lo, x_hi, y_lo, y_hi[, z_lo, z_hi] of the fuzzy position (control point spreads),\n            \
with --centroid its centroid x_centroid, y_centroid[, z_centroid]\n  \
surfaces  u, v, x, y, z, truth, indeterminacy, falsity; with --scores score, accuracy,\n            \
certainty; with --derivative the partial derivatives dx_du, dy_du, dz_du, dtruth_du,\n            \
dindeterminacy_du, dfalsity_du, then dx_dv, ..., dfalsity_dv (--derivative 2 adds\n            \
dx_duu, ..., dx_duv, ..., dx_dvv, ...; --derivative 3 also _duuu, _duuv, _duvv, _dvvv);\n            \
with --normal the unit normal nx, ny, nz (empty in CSV, null in JSON, where the surface\n            \
is degenerate)\n  \
--type-reduce  degree, t_lower, t_upper, t, x_lower, x_upper, x, y_lower, ...[, z]\n            \
(surfaces: u_lower, u_upper, u, v_lower, v_upper, v, x_lower, ..., z): one row per\n            \
interval-valued degree; for each column q, [q_lower, q_upper] is the centroid interval\n            \
[min, max over weights w_k in [lower_k, upper_k] of sum q_k w_k / sum w_k] over the\n            \
samples k and q its midpoint (exact: the Karnik-Mendel switch point is found by a scan)\n\
The domain of a curve is [knot_p, knot_{m-p}] ([0, 1] for Bezier curves and for the default\n\
clamped-uniform knots); `neutrospline check FILE` prints it.\n\
Model options: a CSV file lists control points only, so these give its kind, degree, knots and\n\
grid; with a TOML/JSON file an option fills in a key the file leaves out, and must agree with\n\
the file where it declares the key.\n\
Progress: a job of 100,000 rows or more that runs longer than 0.4 s shows a progress bar on\n\
standard error when that is a terminal (and the table is not printed on it); it is cleared at\n\
the end.")]
pub struct EvalArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Curves: evaluate at N evenly spaced parameters t_k = a + (b - a) k / (N - 1),
    /// k = 0..N-1, over the whole domain [a, b], ends exact (N = 1: t = a only). Surfaces: the
    /// N x N grid of such u and v, u varying slowest
    #[arg(
        long,
        value_name = "N",
        default_value_t = 101,
        value_parser = clap::value_parser!(u64).range(1..),
        conflicts_with = "at"
    )]
    pub samples: u64,

    /// Curves: evaluate at N points evenly spaced along the curve by arc length: the
    /// parameters at the arc lengths k L / (N - 1), k = 0..N-1 (L the length), each to
    /// --accuracy of L (ends exact); the t column gives them
    #[arg(
        long,
        value_name = "N",
        value_parser = clap::value_parser!(u64).range(1..),
        conflicts_with_all = ["at", "samples"]
    )]
    pub arc_length_samples: Option<u64>,

    /// Evaluate at these parameters, in this order: T1,T2,... for a curve, U:V,U:V,... for a
    /// surface (each inside the domain)
    #[arg(
        long,
        value_name = "T1,T2,...|U:V,...",
        value_parser = parse_at,
        allow_hyphen_values = true
    )]
    pub at: Option<AtList>,

    /// Add the derivatives of orders 1 to N, N = 1, 2 or 3 (alone: 1). Curves: d/dt,
    /// d2/dt2, d3/dt3; surfaces: the partials d/du and d/dv, then the mixed partials of
    /// order 2 and 3 (see Columns below)
    #[arg(
        long,
        value_name = "N",
        num_args = 0..=1,
        default_missing_value = "1",
        value_parser = parse_order
    )]
    pub derivative: Option<usize>,

    /// Add the score, accuracy and certainty of the degrees: (2 + T - I - F) / 3, T - F, T
    #[arg(long)]
    pub scores: bool,

    /// Surfaces: add the unit normal (S_u x S_v normalised) as columns nx, ny, nz
    #[arg(long)]
    pub normal: bool,

    /// Curves: add the arc length from the start of the domain (adaptive Gauss-Legendre
    /// quadrature on the curve's pieces) and the curvature |C' x C''| / |C'|^3 as columns
    /// arc_length, curvature
    #[arg(long)]
    pub geometry: bool,

    /// The relative accuracy of the arc length with --geometry or --arc-length-samples (a
    /// positive number; values below 1.8e-15 act as 1.8e-15) [default: 1e-12]
    #[arg(
        long,
        value_name = "E",
        value_parser = parse_accuracy,
        allow_hyphen_values = true
    )]
    pub accuracy: Option<f64>,

    /// Curves: add the alpha-cut of the fuzzy position at level A in [0, 1] as columns
    /// x_lo, x_hi, y_lo, y_hi[, z_lo, z_hi]: the curves of the control points' cut ends
    /// (spreads `spread_x`, ... in the file; without spreads both equal the curve)
    #[arg(long, value_name = "A", value_parser = parse_alpha, allow_hyphen_values = true)]
    pub alpha: Option<f64>,

    /// Curves: add the centroid (defuzzified) curve of the fuzzy position as columns
    /// x_centroid, y_centroid[, z_centroid]: the curve of the control points' centroids
    /// x + (right - left) / 3
    #[arg(long)]
    pub centroid: bool,

    /// Interval-valued families (interval-type2, interval-neutrosophic,
    /// interval-intuitionistic): instead of the samples, one row per interval-valued degree
    /// (truth, indeterminacy, falsity): its type-reduced centroid over the --samples
    /// parameters, the centroid interval [c_l, c_r] and midpoint of t (u, v) and of each
    /// coordinate weighted by the degree's [lower, upper] membership (see Columns below)
    #[arg(
        long,
        conflicts_with_all = [
            "at", "arc_length_samples", "derivative", "scores", "normal", "geometry",
            "alpha", "centroid"
        ]
    )]
    pub type_reduce: bool,

    /// Where the table goes.
    #[command(flatten)]
    pub table: TableArgs,

    /// Shape settings for CSV files.
    #[command(flatten)]
    pub model: ModelArgs,
}

/// The parameters given with `--at`, each with its text for messages.
#[derive(Debug, Clone, PartialEq)]
pub struct AtList(pub Vec<(Param, String)>);

/// Parses the order of `--derivative`: 1, 2 or 3.
fn parse_order(text: &str) -> Result<usize, String> {
    match text.trim() {
        "1" => Ok(1),
        "2" => Ok(2),
        "3" => Ok(3),
        _ => Err(format!(
            "`{text}` is not a derivative order 1, 2 or 3 (--derivative alone means 1; a file \
             named right after it is read as the order: put the file first)"
        )),
    }
}

/// Parses `--accuracy`: a positive finite number.
fn parse_accuracy(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(e) if e > 0.0 && e.is_finite() => Ok(e),
        Ok(_) => Err(format!(
            "`{text}` is not a positive finite number (a relative accuracy such as 1e-12)"
        )),
        Err(_) => Err(format!("`{text}` is not a number")),
    }
}

/// Parses `--alpha`: a number in [0, 1].
fn parse_alpha(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(a) if (0.0..=1.0).contains(&a) => Ok(a),
        _ => Err(format!(
            "`{text}` is not a number in [0, 1] (the membership level of the alpha-cut: 0 is \
             the widest band, 1 the crisp curve)"
        )),
    }
}

/// The fuzzy-position columns of a curve (`--alpha`, `--centroid`): the cut curves and the
/// centroid curve, evaluated beside the crisp one.
struct FuzzyColumns<const D: usize> {
    cut: Option<(AnyCurve<D>, AnyCurve<D>)>,
    centroid: Option<AnyCurve<D>>,
}

impl<const D: usize> FuzzyColumns<D> {
    fn new(
        curve: &AnyCurve<D>,
        spreads: &[Spread<D>],
        alpha: Option<f64>,
        centroid: bool,
    ) -> anyhow::Result<Self> {
        Ok(FuzzyColumns {
            cut: alpha.map(|a| alpha_cut(curve, spreads, a)).transpose()?,
            centroid: centroid
                .then(|| centroid_curve(curve, spreads))
                .transpose()?,
        })
    }

    fn names(&self) -> Vec<String> {
        let axes = &["x", "y", "z"][..D];
        let mut names = Vec::new();
        if self.cut.is_some() {
            for a in axes {
                names.push(format!("{a}_lo"));
                names.push(format!("{a}_hi"));
            }
        }
        if self.centroid.is_some() {
            names.extend(axes.iter().map(|a| format!("{a}_centroid")));
        }
        names
    }

    fn push(&self, t: f64, row: &mut Vec<Option<f64>>) -> anyhow::Result<()> {
        if let Some((lower, upper)) = &self.cut {
            let lo = lower.evaluate(t)?.position;
            let hi = upper.evaluate(t)?.position;
            for k in 0..D {
                row.push(Some(lo[k]));
                row.push(Some(hi[k]));
            }
        }
        if let Some(centroid) = &self.centroid {
            row.extend(centroid.evaluate(t)?.position.map(Some));
        }
        Ok(())
    }
}

/// The fuzzy columns of a planar or spatial curve.
struct Fuzzy(Dimensional<FuzzyColumns<2>, FuzzyColumns<3>>);

impl Fuzzy {
    fn new(
        model: &neutrospline_io::Model,
        alpha: Option<f64>,
        centroid: bool,
    ) -> anyhow::Result<Self> {
        let count = model.shape().control_count();
        let spreads: Vec<Spread<3>> = model
            .spreads()
            .map_or_else(|| vec![Spread::ZERO; count], <[_]>::to_vec);
        let Shape::Curve(curve) = model.shape() else {
            anyhow::bail!("internal error: fuzzy columns of a surface")
        };
        Ok(Fuzzy(map_dimension!(curve, c => {
            let spreads: Vec<_> = spreads.iter().map(Spread::resize).collect();
            FuzzyColumns::new(c, &spreads, alpha, centroid)?
        })))
    }

    fn names(&self) -> Vec<String> {
        on_dimension!(&self.0, f => f.names())
    }

    fn push(&self, param: Param, row: &mut Vec<Option<f64>>) -> anyhow::Result<()> {
        let Param::T(t) = param else {
            anyhow::bail!("a curve takes one parameter t")
        };
        on_dimension!(&self.0, f => f.push(t, row))
    }
}

/// Parses a finite number of `--at`.
fn parse_value(item: &str) -> Result<f64, String> {
    match item.parse::<f64>() {
        Ok(t) if t.is_finite() => Ok(t),
        Ok(_) => Err(format!("parameter `{item}` is not a finite number")),
        Err(_) => Err(format!("parameter `{item}` is not a number")),
    }
}

/// Parses `T1,T2,...` or `U:V,U:V,...`: finite numbers, all items of the same form. Domains
/// are checked once the file is read.
fn parse_at(text: &str) -> Result<AtList, String> {
    let mut items: Vec<(Param, String)> = Vec::new();
    for item in text.split(',') {
        let item = item.trim();
        let param = match item.split_once(':') {
            None => Param::T(parse_value(item)?),
            Some((u, v)) => {
                let pair = parse_value(u.trim()).and_then(|u| Ok((u, parse_value(v.trim())?)));
                match pair {
                    Ok((u, v)) => Param::Uv(u, v),
                    Err(_) => {
                        return Err(format!(
                            "`{item}` is not a pair U:V of finite numbers (such as 0.5:0.25)"
                        ))
                    }
                }
            }
        };
        if let Some((first, first_text)) = items.first() {
            if matches!(first, Param::T(_)) != matches!(param, Param::T(_)) {
                return Err(format!(
                    "`{first_text}` and `{item}` mix single parameters and pairs (give \
                     T1,T2,... for a curve or U:V,U:V,... for a surface)"
                ));
            }
        }
        items.push((param, item.to_owned()));
    }
    Ok(AtList(items))
}

/// Sample `k` of `n` evenly spaced over `[a, b]` (the library's [`uniform_parameter`]: both
/// ends exact, never beyond `b`; for `n = 1`, `a`).
fn sample(k: u64, n: u64, domain: Range<f64>) -> f64 {
    // Sample counts are limited far below `usize::MAX` (`--max-samples`).
    let index = |v: u64| usize::try_from(v).unwrap_or(usize::MAX);
    uniform_parameter(index(k), index(n), domain)
}

/// The parameters to evaluate at, lazily.
fn parameters<'a>(
    args: &'a EvalArgs,
    shape: &Shape,
    along: &'a [f64],
) -> Box<dyn Iterator<Item = Param> + 'a> {
    if let Some(AtList(items)) = &args.at {
        return Box::new(items.iter().map(|(p, _)| *p));
    }
    if args.arc_length_samples.is_some() {
        return Box::new(along.iter().map(|&t| Param::T(t)));
    }
    let n = args.samples;
    match shape {
        Shape::Surface(s) => {
            let [du, dv] = s.domain();
            Box::new((0..n).flat_map(move |i| {
                let u = sample(i, n, du.clone());
                let dv = dv.clone();
                (0..n).map(move |j| Param::Uv(u, sample(j, n, dv.clone())))
            }))
        }
        _ => {
            let domain = shape.curve_domain().unwrap_or(0.0..1.0);
            Box::new((0..n).map(move |k| Param::T(sample(k, n, domain.clone()))))
        }
    }
}

/// The number of rows `eval` writes (saturating: a surface's N x N may exceed `u64`).
fn row_count(args: &EvalArgs, shape: &Shape) -> u64 {
    if let Some(n) = args.arc_length_samples {
        return n;
    }
    match &args.at {
        Some(AtList(items)) => items.len() as u64,
        None if shape.is_surface() => args.samples.saturating_mul(args.samples),
        None => args.samples,
    }
}

/// A CSV table read as a Bézier curve of more control points than [`DATA_LIKE_ROWS`] is
/// more likely measured points than a curve's control polygon.
const DATA_LIKE_ROWS: usize = 50;

/// The warning that a CSV file read as a Bézier curve of more than [`DATA_LIKE_ROWS`] control
/// points may be data for `fit`.
fn data_warning(file: &str, model: &neutrospline_io::Model) -> Option<String> {
    let csv = file == "-"
        || std::path::Path::new(file).extension().is_some_and(|e| {
            ["csv", "tsv", "txt"]
                .iter()
                .any(|x| e.eq_ignore_ascii_case(x))
        });
    let count = model.shape().control_count();
    let bezier = model.kind() == neutrospline_io::Kind::Curve(neutrospline::CurveKind::Bezier);
    (csv && bezier && count > DATA_LIKE_ROWS).then(|| {
        format!(
            "warning: {}: its {count} rows are read as the control points of one Bézier curve of \
             degree {}; if they are measured points, `neutrospline fit {}` fits a curve to them",
            input::label(file),
            count - 1,
            input::label(file)
        )
    })
}

/// Evaluates and writes the table.
///
/// # Errors
/// An invalid file, a usage error (`--at` outside the domain, `--normal` for a curve,
/// `--geometry` for a surface), an
/// evaluation error, or a write error.
pub fn run(args: &EvalArgs) -> anyhow::Result<()> {
    // The table's options are refused before the file is read.
    args.table.table_output()?;
    let model = input::read_model(&args.file, &args.model)?;
    let file = input::label(&args.file);
    if let Some(warning) = data_warning(&args.file, &model) {
        eprintln!("{warning}");
    }
    let fuzzy = if args.alpha.is_some() || args.centroid {
        if model.shape().is_surface() {
            let option = if args.alpha.is_some() {
                "--alpha"
            } else {
                "--centroid"
            };
            return Err(UsageError(format!(
                "{option} applies only to curves ({file} holds a {}; spreads are given per \
                 control point of a curve)",
                model.kind()
            ))
            .into());
        }
        Some(Fuzzy::new(&model, args.alpha, args.centroid)?)
    } else {
        None
    };
    let family = model.membership();
    if args.type_reduce && family.interval_pairs().is_empty() {
        return Err(UsageError(format!(
            "--type-reduce applies to the interval-valued families (interval-type2, \
             interval-neutrosophic, interval-intuitionistic): {file} has membership {family}, \
             which has no interval-valued degree (a [lower, upper] pair of channels) to reduce"
        ))
        .into());
    }
    // Every lane has the geometry of the first (docs/model.md, "Lanes").
    let lanes = model.lanes();
    let shape = lanes[0];
    if args.normal && !shape.is_surface() {
        return Err(UsageError(format!(
            "--normal applies only to surfaces ({file} holds a {} curve)",
            shape.kind()
        ))
        .into());
    }
    if args.geometry && shape.is_surface() {
        return Err(UsageError(format!(
            "--geometry applies only to curves ({file} holds a {}; arc length and curvature \
             are measured along a curve)",
            shape.kind()
        ))
        .into());
    }
    if let Some(AtList(items)) = &args.at {
        for (param, text) in items {
            shape
                .check_param(*param, text)
                .map_err(|m| UsageError(format!("--at: {m}")))?;
        }
    }
    if args.accuracy.is_some() && !args.geometry && args.arc_length_samples.is_none() {
        return Err(UsageError(
            "--accuracy goes with --geometry or --arc-length-samples (the accuracy of arc \
             lengths)"
                .to_owned(),
        )
        .into());
    }
    let extras = Extras {
        derivative: args.derivative.unwrap_or(0),
        normal: args.normal,
        scores: args.scores,
        geometry: args.geometry,
        accuracy: args.accuracy.unwrap_or(neutrospline::DEFAULT_ACCURACY),
        family,
    };
    let mut columns = shape.columns(extras);
    if let Some(fuzzy) = &fuzzy {
        columns.extend(fuzzy.names());
    }
    let sampler = lanes_sampler(&lanes, extras);
    let limit = crate::limits::current().max_samples;
    let count = row_count(args, shape);
    if count > limit {
        let what = match &args.at {
            Some(_) => format!("--at gives {count} parameters"),
            None if shape.is_surface() => format!(
                "--samples {0} gives {0} x {0} = {count} rows on a surface",
                args.samples
            ),
            None => format!("--samples {count} gives {count} rows"),
        };
        return Err(UsageError(format!(
            "{what}, more than the limit of {limit} (raise it with --max-samples or \
             NEUTROSPLINE_MAX_SAMPLES)"
        ))
        .into());
    }
    // Arc-length samples: the parameters are found first (each by inverse arc length).
    let along: Vec<f64> = match (args.arc_length_samples, shape.curve()) {
        (None, _) => Vec::new(),
        (Some(n), Some(curve)) => {
            let n = usize::try_from(n).unwrap_or(usize::MAX);
            let accuracy = args.accuracy.unwrap_or(neutrospline::DEFAULT_ACCURACY);
            on_dimension!(curve, c => c.arc_length_parameters(n, accuracy))
                .map_err(|e| anyhow::anyhow!("{file}: --arc-length-samples: {e}"))?
        }
        (Some(_), None) => {
            return Err(UsageError(format!(
                "--arc-length-samples applies only to curves ({file} holds a {}; evaluate a \
                 surface at --samples or --at)",
                shape.kind()
            ))
            .into())
        }
    };
    if args.type_reduce {
        return type_reduce(args, file, shape, &sampler, &columns, family);
    }
    let mut progress = Progress::new(count, args.table.output.is_none());
    let rows = parameters(args, shape, &along).map(|param| {
        progress.tick();
        let cannot =
            |e: &dyn std::fmt::Display| anyhow::anyhow!("{file}: cannot evaluate at {param}: {e}");
        let mut row = sampler.row(param).map_err(|e| cannot(&e))?;
        if let Some(fuzzy) = &fuzzy {
            fuzzy.push(param, &mut row).map_err(|e| cannot(&e))?;
        }
        // Never write an infinity or NaN: the core reports overflow, this is a safety net.
        if let Some((column, value)) = columns
            .iter()
            .zip(&row)
            .find_map(|(c, v)| v.filter(|v| !v.is_finite()).map(|v| (c, v)))
        {
            return Err(cannot(&format!(
                "{column} = {value} is not a finite number (it overflows a 64-bit float; \
                 control values too large)"
            )));
        }
        Ok(row)
    });
    args.table.write(&columns, rows)
}

/// `--type-reduce`: for each interval-valued degree of `family` (a pair of channels
/// `Family::interval_pairs`, such as `truth_lower, truth_upper`), the centroid interval of each
/// column q among the parameters and coordinates (docs/model.md, "Type reduction"):
///
/// ```text
/// [q_lower, q_upper] = [min, max over w_k in [L_k, U_k] of sum q_k w_k / sum w_k]
/// q = (q_lower + q_upper) / 2
/// ```
///
/// over the samples k at the `--samples` parameters (curves: t_k; surfaces: the grid of
/// (u, v)), with `L_k, U_k` the degree's lower and upper membership there
/// ([`neutrospline::centroid_interval`], exact). The centroid point `(x, y[, z])` is the
/// type-reduced centroid of the curve (surface) weighted by that degree; each coordinate's
/// interval ends are reached by their own embedded sets.
fn type_reduce(
    args: &EvalArgs,
    file: &str,
    shape: &Shape,
    sampler: &Sampler<'_>,
    columns: &[String],
    family: neutrospline::Family,
) -> anyhow::Result<()> {
    let coordinates = if shape.is_surface() { 2 } else { 1 } + shape.dimension();
    let mut samples: Vec<Vec<f64>> = vec![Vec::new(); columns.len()];
    for param in parameters(args, shape, &[]) {
        let row = sampler
            .row(param)
            .map_err(|e| anyhow::anyhow!("{file}: cannot evaluate at {param}: {e}"))?;
        for (column, value) in samples.iter_mut().zip(row) {
            column.push(value.unwrap_or(f64::NAN));
        }
    }
    // The channel columns follow the parameters and coordinates, in the family's order.
    let channel = |c: usize| &samples[coordinates + c];
    let mut names = vec!["degree".to_owned()];
    for name in &columns[..coordinates] {
        names.extend([
            format!("{name}_lower"),
            format!("{name}_upper"),
            name.clone(),
        ]);
    }
    let mut rows = Vec::new();
    for &(lower, upper) in family.interval_pairs() {
        let name = family.channels()[lower];
        let degree = name.strip_suffix("_lower").unwrap_or(name);
        // Blending keeps 0 <= lower <= upper; only rounding could break it, by an ulp.
        let lows: Vec<f64> = channel(lower).iter().map(|l| l.max(0.0)).collect();
        let highs: Vec<f64> = channel(upper)
            .iter()
            .zip(&lows)
            .map(|(u, l)| u.max(*l))
            .collect();
        let mut row = vec![Cell::Word(degree)];
        for (q, name) in samples[..coordinates].iter().zip(columns) {
            let c = neutrospline::centroid_interval(q, &lows, &highs).map_err(|e| {
                anyhow::anyhow!("{file}: --type-reduce: the {degree} centroid of {name}: {e}")
            })?;
            row.extend([c.lower, c.upper, c.midpoint()].map(Cell::Number));
        }
        rows.push(Ok(row));
    }
    args.table.write(&names, rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ts(list: &AtList) -> Vec<Param> {
        list.0.iter().map(|(p, _)| *p).collect()
    }

    #[test]
    fn parse_at_accepts_and_rejects() {
        assert_eq!(
            ts(&parse_at("0, 0.5,1").unwrap()),
            [Param::T(0.0), Param::T(0.5), Param::T(1.0)]
        );
        assert_eq!(ts(&parse_at("-2.5").unwrap()), [Param::T(-2.5)]);
        assert_eq!(
            ts(&parse_at("0:1, 0.5 : 0.25").unwrap()),
            [Param::Uv(0.0, 1.0), Param::Uv(0.5, 0.25)]
        );
        assert_eq!(
            parse_at("0,NaN").unwrap_err(),
            "parameter `NaN` is not a finite number"
        );
        assert_eq!(
            parse_at("0,,1").unwrap_err(),
            "parameter `` is not a number"
        );
        assert_eq!(
            parse_at("0.5:").unwrap_err(),
            "`0.5:` is not a pair U:V of finite numbers (such as 0.5:0.25)"
        );
        assert!(parse_at("1:2:3").is_err());
        assert!(parse_at("inf:0").is_err());
        assert_eq!(
            parse_at("0.5,0.5:0.5").unwrap_err(),
            "`0.5` and `0.5:0.5` mix single parameters and pairs (give T1,T2,... for a curve or U:V,U:V,... for a surface)"
        );
    }

    #[test]
    fn parse_order_accepts_1_to_3() {
        assert_eq!(["1", "2", "3"].map(|t| parse_order(t).unwrap()), [1, 2, 3]);
        assert_eq!(
            parse_order("c.toml").unwrap_err(),
            "`c.toml` is not a derivative order 1, 2 or 3 (--derivative alone means 1; a file \
             named right after it is read as the order: put the file first)"
        );
        assert!(parse_order("0").is_err() && parse_order("4").is_err());
    }

    #[test]
    fn parse_accuracy_accepts_positive_numbers_only() {
        assert_eq!(parse_accuracy("1e-9"), Ok(1e-9));
        for text in ["0", "-1e-12", "inf", "NaN"] {
            assert_eq!(
                parse_accuracy(text).unwrap_err(),
                format!(
                    "`{text}` is not a positive finite number (a relative accuracy such as 1e-12)"
                )
            );
        }
        assert_eq!(
            parse_accuracy("fine").unwrap_err(),
            "`fine` is not a number"
        );
    }

    #[test]
    fn sample_ends_are_exact() {
        let d = 0.1..0.7;
        assert_eq!(sample(0, 7, d.clone()), 0.1);
        assert_eq!(sample(6, 7, d.clone()), 0.7);
        assert_eq!(sample(0, 1, d), 0.1);
        for k in 0..1000 {
            let t = sample(k, 1000, 1.0 / 3.0..2.0 / 3.0);
            assert!((1.0 / 3.0..=2.0 / 3.0).contains(&t));
        }
        // On [0, 1] the samples are exactly k / (n - 1).
        for k in 0..=100 {
            assert_eq!(sample(k, 101, 0.0..1.0), k as f64 / 100.0);
        }
    }
}
