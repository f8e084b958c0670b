//! `neutrospline intersect A B`: every point where two plane curves meet (or where one curve
//! crosses itself, when B is A), ordered by the parameter on A.

use neutrospline::{DynCurve, Intersection};

use crate::commands::options::{ModelArgs, TableArgs};
use crate::input;
use crate::shape::Shape;
use neutrospline_io::Cell;

/// Arguments of `intersect`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Columns:\n  \
index, t_a, t_b, x, y, truth_a, indeterminacy_a, falsity_a, truth_b, indeterminacy_b, falsity_b,\n\
contact\n\
One row per intersection, ordered by t_a: the parameters on A and on B, the point (A's), the\n\
degrees of each curve there, and how the curves meet: crossing (at an angle), tangent (the\n\
tangents agree: touching, osculating or crossing tangentially) or end (an end of either\n\
curve). Tangential and end-point intersections are included, each contact once. When B is the same curve as A the rows are its self-intersections, t_a < t_b. Curves\n\
that share a stretch are refused with the parameters of the stretch.\n\
Both files must hold plane (2-D) curves, of any kinds.")]
pub struct IntersectArgs {
    /// The first curve: .csv, .toml or .json
    #[arg(value_name = "A")]
    pub a: String,

    /// The second curve (the same file as A for self-intersections)
    #[arg(value_name = "B")]
    pub b: String,

    /// Where the table goes.
    #[command(flatten)]
    pub table: TableArgs,

    /// Shape settings for CSV files (both files).
    #[command(flatten)]
    pub model: ModelArgs,
}

/// The table's columns.
const COLUMNS: [&str; 12] = [
    "index",
    "t_a",
    "t_b",
    "x",
    "y",
    "truth_a",
    "indeterminacy_a",
    "falsity_a",
    "truth_b",
    "indeterminacy_b",
    "falsity_b",
    "contact",
];

/// The plane curve of `file`, or an error naming what it holds.
fn plane_curve(file: &str, model: &ModelArgs) -> anyhow::Result<DynCurve> {
    match input::one_lane(
        file,
        input::read_model(file, model)?,
        "intersect",
        "LANES_TODO",
    )?
    .into_shape()
    {
        Shape::Curve(curve) if curve.dimension() == 2 => Ok(curve),
        shape => {
            let what = if shape.is_surface() {
                format!("a {}", shape.kind())
            } else {
                format!("a 3-D {} curve", shape.kind())
            };
            Err(anyhow::Error::msg(format!(
                "{}: holds {what} (intersect takes plane curves: positions x, y only)",
                input::label(file)
            )))
        }
    }
}

/// Reads both curves, intersects them and writes the table.
///
/// # Errors
/// An invalid file, a curve that is not a plane curve, curves that overlap, or a write error.
pub fn run(args: &IntersectArgs) -> anyhow::Result<()> {
    let a = plane_curve(&args.a, &args.model)?;
    let b = plane_curve(&args.b, &args.model)?;
    let found = if a == b {
        a.self_intersections()
    } else {
        a.intersections(&b)
    }
    .map_err(|e| {
        anyhow::Error::msg(format!(
            "{} and {}: {e}",
            input::label(&args.a),
            input::label(&args.b)
        ))
    })?;
    let columns: Vec<String> = COLUMNS.map(str::to_owned).to_vec();
    let rows = found.iter().enumerate().map(|(index, i)| Ok(row(index, i)));
    args.table.write(&columns, rows)
}

fn row(index: usize, i: &Intersection) -> Vec<Cell> {
    let mut row = vec![index as f64, i.parameter_a, i.parameter_b];
    row.extend(i.point_a.position);
    row.extend(i.point_a.degrees.to_array());
    row.extend(i.point_b.degrees.to_array());
    let mut cells: Vec<Cell> = row.into_iter().map(Cell::Number).collect();
    cells.push(Cell::Word(i.contact.name()));
    cells
}
