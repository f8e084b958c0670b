//! `neutrospline query MODEL POINTS.csv`: for every query point the nearest point of the curve
//! (or surface), its parameter, the distance, and the degrees and score there.

use std::path::PathBuf;

use neutrospline::{Degrees as LaneDegrees, EvaluateSurface, Family, NearestError, RowLengthError};
use neutrospline_io::PointTable;

use crate::commands::options::{ModelArgs, TableArgs};
use crate::input;

use crate::shape::{DegreeView, Shape};

/// Arguments of `query`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Columns:\n  \
curves    index, t, distance, x, y[, z], truth, indeterminacy, falsity, score\n  \
surfaces  index, u, v, distance, x, y, z, truth, indeterminacy, falsity, score\n\
index is the query point's row (0 = the first point); t (or u, v) the parameter of the\n\
nearest point of the model, distance the Euclidean distance to it, x, y[, z] that nearest\n\
point, then its degrees and score (2 + truth - indeterminacy - falsity) / 3. The minimum is\n\
global, ends included; equally near points (to 1e-13 of the model's size) report the\n\
smallest parameter (for a surface the smallest u, then v).\n\
The interval-valued and bipolar families give, instead of truth, indeterminacy, falsity and\n\
score, a column per channel (truth_lower, truth_upper, ...), the derived degrees and the\n\
family's score (and accuracy) there.\n\
POINTS.csv: a header row, then one point per row; columns x, y and (for 3-D models) z, and\n\
an optional name; comments and quoting as in model CSV files.")]
pub struct QueryArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "MODEL")]
    pub model_file: String,

    /// The query points: CSV with columns x, y[, z]
    #[arg(value_name = "POINTS.csv")]
    pub points: PathBuf,

    /// Where the table goes.
    #[command(flatten)]
    pub table: TableArgs,

    /// Shape settings for CSV files.
    #[command(flatten)]
    pub model: ModelArgs,
}

/// Query points handled per parallel batch (rows are written between batches).
const BATCH: usize = 1 << 14;

/// Reads the model and the points, finds the nearest points and writes the table.
///
/// # Errors
/// An invalid model or points file, points of another dimension than the model, a point
/// whose distance overflows, or a write error.
pub fn run(args: &QueryArgs) -> anyhow::Result<()> {
    let model = input::read_model(&args.model_file, &args.model)?;
    let view = Degrees::of(model.membership());
    // The lanes after the first (docs/model.md, "Lanes"): evaluated at the nearest point's
    // parameter for the channels of the interval-valued and bipolar families.
    let others: Vec<Shape> = model.lanes()[1..].iter().map(|s| (*s).clone()).collect();
    let shape = model.into_shape();
    let model_file = input::label(&args.model_file);
    let table = neutrospline_io::load_points_with(&args.points, &args.model.table_input()?)
        .map_err(input::table_error)?;
    let dimension = shape.dimension();
    if table.dimension() != dimension {
        let what = if shape.is_surface() {
            format!("a {} (3-D)", shape.kind())
        } else {
            format!("a {}-D {} curve", dimension, shape.kind())
        };
        let columns = if dimension == 3 { "x, y, z" } else { "x, y" };
        return Err(anyhow::Error::msg(format!(
            "{}: {}-D points, but {model_file} holds {what} (query points need the columns \
             {columns})",
            table.file(),
            table.dimension()
        )));
    }
    let columns = columns(&shape, view);
    let rows: Box<dyn Iterator<Item = anyhow::Result<Vec<Option<f64>>>>> = match &shape {
        Shape::Curve(curve) => Box::new(batches(&table, |points: &[f64]| {
            Ok(curve
                .nearest_rows(points)?
                .into_iter()
                .map(|found| {
                    let n = found?;
                    let mut lanes = vec![n.point.degrees];
                    for other in &others {
                        let curve = other.curve().expect("the lanes of a curve are curves");
                        lanes.push(curve.evaluate_point(n.parameter)?.degrees);
                    }
                    let mut row = vec![n.parameter, n.distance];
                    push_point(&mut row, &n.point.position, view, &lanes);
                    Ok(row)
                })
                .collect())
        })),
        Shape::Surface(surface) => {
            let projector = surface.projector();
            Box::new(batches(&table, move |points: &[f64]| {
                let points: Vec<[f64; 3]> =
                    points.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect();
                Ok(projector
                    .nearest_many(&points)
                    .into_iter()
                    .map(|r| {
                        let n = r?;
                        let [u, v] = n.parameter;
                        let mut lanes = vec![n.point.degrees];
                        for other in &others {
                            if let Shape::Surface(s) = other {
                                lanes.push(s.evaluate(u, v)?.degrees);
                            }
                        }
                        let mut row = vec![u, v, n.distance];
                        push_point(&mut row, &n.point.position, view, &lanes);
                        Ok(row)
                    })
                    .collect())
            }))
        }
    };
    write(args, &columns, rows)
}

/// The rows of the table, computed a batch at a time (index, then what `solve` gives). A
/// batch with an error yields its first error only, so that [`write`] sees an error of the
/// first batch before it writes anything.
fn batches<'a>(
    table: &'a PointTable,
    solve: impl Fn(&[f64]) -> Result<Vec<Result<Vec<f64>, NearestError>>, RowLengthError> + 'a,
) -> impl Iterator<Item = anyhow::Result<Vec<Option<f64>>>> + 'a {
    let positions = table.positions();
    let dimension = table.dimension();
    let batches = (0..positions.len()).step_by(BATCH).map(
        move |first| -> anyhow::Result<Vec<Vec<Option<f64>>>> {
            let end = (first + BATCH).min(positions.len());
            let points: Vec<f64> = positions[first..end]
                .iter()
                .flat_map(|p| &p[..dimension])
                .copied()
                .collect();
            solve(&points)?
                .into_iter()
                .enumerate()
                .map(|(k, result)| {
                    let index = first + k;
                    let values = result.map_err(|e| {
                        anyhow::Error::msg(format!(
                            "{}:{}: cannot find the nearest point: {e}",
                            table.file(),
                            table.line(index)
                        ))
                    })?;
                    let mut row = Vec::with_capacity(values.len() + 1);
                    row.push(Some(index as f64));
                    row.extend(values.into_iter().map(Some));
                    Ok(row)
                })
                .collect()
        },
    );
    batches.flat_map(|batch| match batch {
        Ok(rows) => rows.into_iter().map(Ok).collect::<Vec<_>>(),
        Err(e) => vec![Err(e)],
    })
}

/// Writes the table; an error in the first row is reported before anything is written.
fn write(
    args: &QueryArgs,
    columns: &[String],
    rows: impl Iterator<Item = anyhow::Result<Vec<Option<f64>>>>,
) -> anyhow::Result<()> {
    let mut rows = rows.peekable();
    if let Some(Err(_)) = rows.peek() {
        if let Some(Err(e)) = rows.next() {
            return Err(e);
        }
    }
    args.table.write(columns, rows)
}

/// The degree columns of a family in `query`'s table.
#[derive(Clone, Copy)]
enum Degrees {
    /// `truth, indeterminacy, falsity, score` ((2 + T - I - F) / 3) of the first lane: the
    /// families of one lane.
    Triple,
    /// The channels, derived degrees and scores of [`DegreeView`]: the interval-valued and
    /// bipolar families (docs/model.md, "Lanes").
    Channels(DegreeView),
}

impl Degrees {
    fn of(family: Family) -> Self {
        if family.lane_count() > 1 {
            Degrees::Channels(DegreeView::new(family))
        } else {
            Degrees::Triple
        }
    }
}

fn push_point(row: &mut Vec<f64>, position: &[f64], view: Degrees, lanes: &[LaneDegrees]) {
    row.extend_from_slice(position);
    match view {
        Degrees::Triple => {
            row.extend(lanes[0].to_array());
            row.push(lanes[0].score());
        }
        Degrees::Channels(view) => {
            row.extend(view.values(lanes));
            row.extend(view.scores(lanes));
        }
    }
}

/// `index,t,distance,x,y[,z],truth,indeterminacy,falsity,score` (`u,v` for surfaces); for
/// a family of two lanes its channels, derived degrees and scores instead of the degrees and
/// score.
fn columns(shape: &Shape, view: Degrees) -> Vec<String> {
    let mut names: Vec<&str> = vec!["index"];
    if shape.is_surface() {
        names.extend(["u", "v"]);
    } else {
        names.push("t");
    }
    names.push("distance");
    names.extend(&["x", "y", "z"][..shape.dimension()]);
    match view {
        Degrees::Triple => names.extend(["truth", "indeterminacy", "falsity", "score"]),
        Degrees::Channels(view) => {
            names.extend(view.names());
            names.extend(view.score_names());
        }
    }
    names.into_iter().map(str::to_owned).collect()
}
