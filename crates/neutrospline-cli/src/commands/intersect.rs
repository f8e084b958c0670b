//! `neutrospline intersect A B`: every point where two plane curves meet (or where one curve
//! crosses itself, when B is A), ordered by the parameter on A.

use neutrospline::{Degrees, DynCurve, Family, Intersection};

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
The interval-valued and bipolar families give a column per channel instead of the three\n\
degrees (truth_lower_a, truth_upper_a, ..., negative_falsity_b).\n\
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

/// A plane curve read from a file: its lanes (docs/model.md, "Lanes": one, or two of the
/// same geometry for the interval-valued and bipolar families) and its family.
struct PlaneCurve {
    lanes: Vec<DynCurve>,
    family: Family,
}

impl PlaneCurve {
    /// The degree column names (without the `_a`/`_b` suffix): `truth, indeterminacy,
    /// falsity` for a family of one lane, else the family's channels.
    fn degree_names(&self) -> Vec<&'static str> {
        if self.family.lane_count() > 1 {
            self.family.channels().to_vec()
        } else {
            vec!["truth", "indeterminacy", "falsity"]
        }
    }

    /// The values of [`PlaneCurve::degree_names`] at `t`, where the first lane's degrees are
    /// `first` (the intersection's point).
    fn degrees(&self, t: f64, first: &Degrees) -> anyhow::Result<Vec<f64>> {
        if self.family.lane_count() == 1 {
            return Ok(first.to_array().to_vec());
        }
        let mut lanes = vec![*first];
        for lane in &self.lanes[1..] {
            lanes.push(lane.evaluate_point(t)?.degrees);
        }
        Ok(self.family.join(&lanes).to_vec())
    }
}

/// The plane curve of `file`, or an error naming what it holds.
fn plane_curve(file: &str, model: &ModelArgs) -> anyhow::Result<PlaneCurve> {
    let model = input::read_model(file, model)?;
    let family = model.membership();
    let others: Vec<DynCurve> = model.lanes()[1..]
        .iter()
        .filter_map(|s| s.curve().cloned())
        .collect();
    match model.into_shape() {
        Shape::Curve(curve) if curve.dimension() == 2 => Ok(PlaneCurve {
            lanes: std::iter::once(curve).chain(others).collect(),
            family,
        }),
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
    let found = if a.lanes == b.lanes {
        a.lanes[0].self_intersections()
    } else {
        a.lanes[0].intersections(&b.lanes[0])
    }
    .map_err(|e| {
        anyhow::Error::msg(format!(
            "{} and {}: {e}",
            input::label(&args.a),
            input::label(&args.b)
        ))
    })?;
    let mut columns: Vec<String> = ["index", "t_a", "t_b", "x", "y"]
        .map(str::to_owned)
        .to_vec();
    columns.extend(a.degree_names().iter().map(|n| format!("{n}_a")));
    columns.extend(b.degree_names().iter().map(|n| format!("{n}_b")));
    columns.push("contact".to_owned());
    let rows = found
        .iter()
        .enumerate()
        .map(|(index, i)| row(index, i, &a, &b));
    args.table.write(&columns, rows)
}

fn row(
    index: usize,
    i: &Intersection,
    a: &PlaneCurve,
    b: &PlaneCurve,
) -> anyhow::Result<Vec<Cell>> {
    let mut row = vec![index as f64, i.parameter_a, i.parameter_b];
    row.extend(i.point_a.position);
    row.extend(a.degrees(i.parameter_a, &i.point_a.degrees)?);
    row.extend(b.degrees(i.parameter_b, &i.point_b.degrees)?);
    let mut cells: Vec<Cell> = row.into_iter().map(Cell::Number).collect();
    cells.push(Cell::Word(i.contact.name()));
    Ok(cells)
}
