//! `neutrospline relation M.csv N.csv`: the paper's Def. 4 from the command line. The largest
//! admissible neutrosophic point relation of two axis sets (every pair, or the pairs of
//! `--pairs`, in order), written as the control points of a plane curve (Def. 5, as Tas and
//! Topal build them); or, with `--check MODEL`, whether a model's control points form a
//! relation of the two sets (docs/model.md section 2).

use std::io::Write;
use std::path::PathBuf;

use neutrospline::{AxisSetName, ControlPolygon, PointRelation, RelationError};
use neutrospline_io::{AxisTable, Format, TableInput};

use crate::commands::options::ModelArgs;
use crate::input::{self, UsageError};
use crate::output;

/// Arguments of `relation`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "M.csv, N.csv: the axis sets, one member per row; columns value (or r \
for M, s for N), truth, indeterminacy, falsity (aliases T, I, F), each degree in [0, 1], each \
value once.\n\
The relation gives the pair (r, s) the smaller of M's degree at r and N's at s, degree by \
degree (the largest relation Def. 4 admits). Without --pairs every pair of M x N, r varying \
slowest; --pairs PAIRS.csv (columns r, s) chooses and orders them.\n\
The pairs are written as the control points of a plane curve: CSV (x = r, y = s, truth, \
indeterminacy, falsity) on standard output, or -o OUT.csv|.toml|.json; --kind, --degree and \
--knots make the model (default a Bezier curve), as they read a CSV model.\n\
--check MODEL: instead checks that the control points of a plane-curve model are a relation of \
M and N (every degree at most M's at r and N's at s); the first violation names the control \
point, the degree, both values and the set's line (exit status 1)."
)]
pub struct RelationArgs {
    /// The axis set M (coordinates r): CSV
    #[arg(value_name = "M.csv")]
    pub m: PathBuf,

    /// The axis set N (coordinates s): CSV
    #[arg(value_name = "N.csv")]
    pub n: PathBuf,

    /// The pairs of the relation, in order: CSV with columns r, s (default: all of M x N)
    #[arg(long, value_name = "PAIRS.csv", conflicts_with = "check")]
    pub pairs: Option<PathBuf>,

    /// Check this model's control points against M and N instead of building the relation
    #[arg(long, value_name = "MODEL")]
    pub check: Option<String>,

    /// Write the model here (.csv, .toml or .json, replaced atomically) instead of CSV on
    /// standard output
    #[arg(
        short = 'o',
        long = "output",
        value_name = "OUT",
        conflicts_with = "check"
    )]
    pub output: Option<PathBuf>,

    /// The model's kind, degree and knots (and, for --check, how a CSV model is read).
    #[command(flatten)]
    pub model: ModelArgs,
}

/// Reads the axis sets, then builds and writes the relation, or checks a model against them.
///
/// # Errors
/// A located error in an axis set, the pairs or the model; a pair outside the sets; a
/// violation of Def. 4 (`--check`); options that do not make a model; a write error.
pub fn run(args: &RelationArgs) -> anyhow::Result<()> {
    let table_input = args.model.table_input()?;
    let m = read_axis(&args.m, AxisSetName::M, &table_input)?;
    let n = read_axis(&args.n, AxisSetName::N, &table_input)?;
    if let Some(model_file) = &args.check {
        return check(model_file, &args.model, &m, &n);
    }
    let format = match &args.output {
        None => Format::Csv,
        Some(path) => Format::from_path(path).map_err(|e| {
            UsageError(e.describe("the relation is written as .csv, .toml or .json"))
        })?,
    };
    let relation = match &args.pairs {
        None => PointRelation::largest(m.set(), n.set()),
        Some(path) => {
            let pairs =
                neutrospline_io::load_pairs(path).map_err(|e| anyhow::Error::msg(e.to_string()))?;
            PointRelation::largest_on_pairs(m.set(), n.set(), pairs.pairs()).map_err(|e| {
                let line = match &e {
                    RelationError::NotInAxisSet { index, .. } => Some(pairs.line(*index)),
                    _ => None,
                };
                located(pairs.file(), line, &e)
            })?
        }
    };
    // The relation is a table of control points: the model is what a CSV model file with
    // these rows reads as under the model options, with their defaults and messages.
    let mut table = String::from("x,y,truth,indeterminacy,falsity\n");
    for entry in relation.entries() {
        let [r, s] = entry.position;
        let [truth, indeterminacy, falsity] = entry.degrees.to_array();
        for (k, value) in [r, s, truth, indeterminacy, falsity]
            .into_iter()
            .enumerate()
        {
            if k > 0 {
                table.push(',');
            }
            table.push_str(&neutrospline_io::format_number(value));
        }
        table.push('\n');
    }
    let source = format!("the relation of {} and {}", m.file(), n.file());
    // The table above is plain CSV, whatever the axis files' delimiter or decimal mark.
    let mut options = input::read_options(&args.model)?;
    options.table = TableInput::default();
    let model = neutrospline_io::read_csv(&source, table.as_bytes(), &options)
        .map_err(|e| anyhow::Error::msg(e.to_string()))?;
    if model.shape().curve().is_none() {
        return Err(UsageError(format!(
            "--kind {}: a relation makes the control points of a plane curve (bezier, bspline \
             or nurbs)",
            model.shape().kind()
        ))
        .into());
    }
    let model = model.with_description(format!(
        "The largest neutrosophic point relation of {} (M) and {} (N) (Def. 4), {} pairs",
        m.file(),
        n.file(),
        relation.entries().len()
    ));
    let text = neutrospline_io::to_string(&model, format)?;
    output::emit(args.output.as_deref(), |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}

/// Reads an axis set, with its file's located errors.
fn read_axis(
    path: &std::path::Path,
    name: AxisSetName,
    table_input: &TableInput,
) -> anyhow::Result<AxisTable> {
    neutrospline_io::load_axis_set_with(path, name, table_input).map_err(input::table_error)
}

/// Checks that the control points of the plane curve in `model_file` form a relation of `m`
/// and `n`, and says so on standard output.
fn check(model_file: &str, args: &ModelArgs, m: &AxisTable, n: &AxisTable) -> anyhow::Result<()> {
    let model = input::one_lane(
        model_file,
        input::read_model(model_file, args)?,
        "relation --check",
        "compares each control point's single truth, indeterminacy and falsity with the \
         axis sets' (Def. 4); its control points carry intervals or bipolar pairs of degrees \
         instead, which a neutrosophic point relation does not have",
    )?;
    let shown = input::label(model_file);
    let Some(points) = model
        .shape()
        .curve()
        .and_then(|c| c.planar())
        .map(|c| c.control_points())
    else {
        return Err(anyhow::Error::msg(format!(
            "{shown}: a {} is not a relation: Def. 4 relates the control points of a plane \
             curve (x = r, y = s)",
            model.shape().kind()
        )));
    };
    let count = points.len();
    PointRelation::new(points)
        .check_admissible(m.set(), n.set())
        .map_err(|e| {
            let (index, set_line) = match &e {
                RelationError::NotAdmissible { index, set, at, .. } => {
                    let table = if *set == AxisSetName::M { m } else { n };
                    (*index, table.line_of(*at).map(|line| (table.file(), line)))
                }
                RelationError::NotInAxisSet { index, .. } => (*index, None),
                _ => (0, None),
            };
            let name = model
                .point_names()
                .get(index)
                .and_then(Option::as_deref)
                .map(|name| format!(" ({name})"))
                .unwrap_or_default();
            let source = set_line
                .map(|(file, line)| format!("; {file}:{line}"))
                .unwrap_or_default();
            anyhow::Error::msg(format!("{shown}: control point {index}{name}: {e}{source}"))
        })?;
    let mut out = std::io::stdout().lock();
    writeln!(
        out,
        "{shown}: the {count} control points form a neutrosophic point relation of {} (M) and \
         {} (N) (Def. 4)",
        m.file(),
        n.file()
    )?;
    Ok(())
}

/// An error of the pairs file, at `line` when known.
fn located(file: &str, line: Option<usize>, error: &RelationError) -> anyhow::Error {
    match line {
        Some(line) => anyhow::Error::msg(format!("{file}:{line}: {error}")),
        None => anyhow::Error::msg(format!("{file}: {error}")),
    }
}
