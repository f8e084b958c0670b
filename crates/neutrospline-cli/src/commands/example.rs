//! `neutrospline example`: the paper's Example 1 from built-in data, and its five figures.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::Context;
use neutrospline::{example1, AnyCurve, ControlPolygon, Evaluate, EXAMPLE1_NAMES};
use neutrospline_plot::{FigureFormat, FigureRequest, PlotModel, PlotOptions, View};

use crate::commands::plot::write_figure;
use crate::input::UsageError;
use crate::output::{self, number, rounded, Align};
use crate::request::RequestArgs;
use crate::shape::{Extras, Param, Shape, Table};

/// Arguments of `example`.
#[derive(Debug, clap::Args)]
pub struct ExampleArgs {
    /// Also write the paper's figures 1 to 5 (figure1.svg, figure1.png, ..., figure5.png) and
    /// the curve table (example1.csv) into DIR, created if needed
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,

    /// The formats of the figures written by --out, comma-separated
    #[arg(long, value_name = "FORMATS", value_delimiter = ',', default_value = "svg,png",
          value_parser = clap::builder::PossibleValuesParser::new(FigureFormat::NAMES))]
    pub formats: Vec<String>,

    /// The figures' options (defined by the plot crate's `FigureRequest`; each figure has its
    /// own view): for a paper, `--style paper` or `--size 8.5cmx6cm --no-title --no-caption`
    #[command(flatten)]
    pub figure: RequestArgs<FigureRequest>,
}

/// The paper's figures: file stem and view (Fig. 1 control points; Fig. 2, 3, 4 the truth,
/// indeterminacy and falsity curves; Fig. 5 all three).
pub const FIGURES: [(&str, View); 5] = [
    ("figure1", View::Controls),
    ("figure2", View::Truth),
    ("figure3", View::Indeterminacy),
    ("figure4", View::Falsity),
    ("figure5", View::All),
];

/// The caption of every figure: where the data comes from, with the erratum (docs/model.md section 5).
pub const CAPTION: &str = "Example 1 of Mahmud et al., Table 1 data. Erratum: the paper's \
Table 3 gives C3 an indeterminacy of 0.1; Table 1, which defines the example, gives 0.4, \
used here.";

/// Number of intervals of the curve table: t = k / STEPS.
const STEPS: u32 = 10;
/// Decimals shown in the curve table.
const DECIMALS: usize = 6;

/// The note printed under the tables (docs/model.md section 5).
pub const ERRATUM: &str =
    "Note: the paper's Table 3 gives C3 an indeterminacy of 0.1, but Table 1, \
which defines the example, gives 0.4; this output follows Table 1.";

/// Prints the control points and the curve at t = 0, 0.1, ..., 1.
///
/// # Errors
/// A write error, or an evaluation error (none for the built-in data).
pub fn run(args: &ExampleArgs) -> anyhow::Result<()> {
    let curve = example1();
    let written = match &args.out {
        Some(dir) => write_outputs(dir, &args.formats, args.figure.request()?)?,
        None => Vec::new(),
    };
    let header = ["t", "x", "y", "truth", "indeterminacy", "falsity"];
    let right = [Align::Right; 6];

    let mut points = Vec::new();
    for (i, p) in curve.control_points().iter().enumerate() {
        let mut row = vec![EXAMPLE1_NAMES
            .get(i)
            .map_or_else(|| format!("C{i}"), |n| (*n).to_owned())];
        row.extend(
            p.position
                .iter()
                .chain(&p.degrees.to_array())
                .map(|&v| number(v)),
        );
        points.push(row);
    }
    let mut samples = Vec::new();
    for k in 0..=STEPS {
        let t = f64::from(k) / f64::from(STEPS);
        let p = curve.evaluate(t)?;
        let mut row = vec![number(t)];
        row.extend(
            p.position
                .iter()
                .chain(&p.degrees.to_array())
                .map(|&v| rounded(v, DECIMALS)),
        );
        samples.push(row);
    }

    output::emit(None, |w| {
        writeln!(
            w,
            "Example 1 of \"A Neutrosophic Bezier Curve Model using Control Points\": \
             a cubic (degree {}) neutrosophic Bezier curve in the plane.",
            curve.degree()
        )?;
        writeln!(w)?;
        writeln!(w, "Control points")?;
        let mut point_header = header;
        point_header[0] = "point";
        let mut point_align = right;
        point_align[0] = Align::Left;
        output::write_text_table(w, &point_header, &point_align, &points)?;
        writeln!(w)?;
        writeln!(
            w,
            "Curve at t = k/{STEPS}, k = 0..{STEPS} (values rounded to {DECIMALS} decimals)"
        )?;
        output::write_text_table(w, &header, &right, &samples)?;
        writeln!(w)?;
        writeln!(w, "{ERRATUM}")?;
        if !written.is_empty() {
            writeln!(w)?;
            writeln!(w, "Wrote:")?;
            for path in &written {
                writeln!(w, "  {}", path.display())?;
            }
        }
        Ok(())
    })
}

/// The options of the example's figures: the request's, with [`CAPTION`] unless a caption
/// (or none) was asked for.
///
/// # Errors
/// A usage error for `--view` (each figure has its view) or an option out of range.
fn figure_options(request: &FigureRequest) -> Result<PlotOptions, UsageError> {
    if let Some(view) = request.view {
        return Err(UsageError(format!(
            "--view {view}: example draws the paper's five views (figure1 to figure5); draw \
             one view with `neutrospline plot`"
        )));
    }
    let options = request
        .plot_options()
        .map_err(|e| UsageError(e.to_string()))?;
    Ok(match options.caption() {
        None => options.with_caption(CAPTION),
        Some(_) => options,
    })
}

/// Writes the five figures in `formats` and the curve table into `dir`; returns the paths.
///
/// # Errors
/// The directory cannot be created, or a file cannot be rendered or written.
fn write_outputs(
    dir: &Path,
    formats: &[String],
    request: &FigureRequest,
) -> anyhow::Result<Vec<PathBuf>> {
    let options = figure_options(request)?;
    fs::create_dir_all(dir)
        .with_context(|| format!("{}: cannot create directory", dir.display()))?;
    let curve = example1();
    let model = PlotModel::from_bezier(&curve)?.with_names(EXAMPLE1_NAMES)?;
    let formats: Vec<FigureFormat> = FigureFormat::ALL
        .into_iter()
        .filter(|f| formats.iter().any(|name| name == f.name()))
        .collect();
    let mut written = Vec::new();
    for (stem, view) in FIGURES {
        for &format in &formats {
            let path = dir.join(format!("{stem}.{}", format.name()));
            write_figure(&model, view, &options, &path, format)?;
            written.push(path);
        }
    }
    // The curve table at t = k/10 in full precision, in `eval`'s CSV format.
    let shape = Shape::from(AnyCurve::Bezier(curve));
    let extras = Extras::default();
    let columns = shape.columns(extras);
    let sampler = shape.sampler(extras);
    let rows = (0..=STEPS).map(|k| {
        let param = Param::T(f64::from(k) / f64::from(STEPS));
        sampler.row(param)
    });
    let path = dir.join("example1.csv");
    output::emit(Some(&path), |w| {
        output::write_table(w, &neutrospline_io::TableOutput::default(), &columns, rows)
    })?;
    written.push(path);
    Ok(written)
}
