//! `neutrospline fit DATA.csv`: a neutrosophic curve (or, with `--surface`, a B-spline
//! surface) fitted to measured points, written as a model, with the error report on standard
//! error (docs/model.md section 8 and "Surface fitting").

use std::io::Write;
use std::path::PathBuf;

use neutrospline::fit::{DynFit, FitReport, FitRequest, SurfaceFitReport, SurfaceFitRequest};
use neutrospline::options::{OptionSet, OptionValue};
use neutrospline::DegreeKind;
use neutrospline_io::{DataTable, Format, Model, TableInput};
use neutrospline_plot::{DataOverlay, FigureRequest, PlotModel, PlotOptions, View};

use crate::commands::plot::{figure_format, write_figure};
use crate::input::{read_data, UsageError};
use crate::output::{self, number};
use crate::request::{RequestArgs, UnionArgs};

/// `--report` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ReportFormat {
    /// Aligned lines for reading.
    Text,
    /// One JSON object.
    Json,
}

/// Reads `--color-by` as the figure option `color-by` ([`FigureRequest`]): the same values
/// and message as `plot --color-by`.
fn parse_color_by(text: &str) -> Result<DegreeKind, String> {
    let mut figure = FigureRequest::default();
    figure
        .set("color-by", OptionValue::Word(text.to_owned()))
        .map_err(|e| e.to_string())?;
    Ok(figure.color_by)
}

/// Arguments of `fit`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "DATA.csv: a header row, then one measured point per row; columns x, y[, z], \
truth, indeterminacy, falsity (aliases T, I, F; which are required follows --membership), and \
optionally parameter (the point's parameter on the curve), weight (> 0, used with --weights \
column) and name.\n\
Target (one of): --interpolate (through every point), --control-points N (least squares), \
--tolerance E (least squares, knots refined until every position residual is within E); default: \
--tolerance of 1e-3 of the data's bounding-box diagonal.\n\
The degrees of the fitted control points are solved under the bounds of the membership rule, so \
the model always passes `neutrospline check`. The report (residuals per channel, worst point, \
Schoenberg-Whitney conditions, condition estimate, control degrees on a bound) goes to standard \
error.\n\
--surface: a B-spline surface of degrees --degree P[,Q] fitted to x, y, z data (columns u and v \
optional: the points' parameters): --grid ROWSxCOLS for a grid given row by row (interpolation \
or least squares, parameters averaged over rows and columns), else scattered points (least \
squares, parameters by --projection); targets --interpolate (grids), --control-points M[,N], \
--tolerance E; --smoothing adds the thin-plate energy."
)]
pub struct FitArgs {
    /// The data: a CSV file of measured points; `-` reads standard input
    #[arg(value_name = "DATA.csv")]
    pub data: String,

    /// Write the model here (.toml or .json, replaced atomically) instead of TOML on standard
    /// output
    #[arg(short = 'o', long = "output", value_name = "MODEL")]
    pub output: Option<PathBuf>,

    /// Fit a B-spline surface (the options of the library's `SurfaceFitRequest`) instead of
    /// a curve
    #[arg(long)]
    pub surface: bool,

    /// The fit's options (defined by the library's `FitRequest` and `SurfaceFitRequest`)
    #[command(flatten)]
    pub request: UnionArgs<FitRequest, SurfaceFitRequest>,

    /// How the data table is read (defined by neutrospline-io's `TableInput`)
    #[command(flatten)]
    pub table: RequestArgs<TableInput>,

    /// The report's format (on standard error)
    #[arg(long, value_enum, value_name = "FORMAT", default_value = "text")]
    pub report: ReportFormat,

    /// Also draw the data over the fitted curve or surface (the `data` view): FIG.svg or FIG.png
    #[arg(long, value_name = "FIG")]
    pub plot: Option<PathBuf>,

    /// The degree that colours the data points in --plot: truth, indeterminacy or falsity
    /// (the figure option color-by)
    #[arg(long, value_name = "DEGREE", default_value = "truth", value_parser = parse_color_by)]
    pub color_by: DegreeKind,

    /// The model's name
    #[arg(long, value_name = "TEXT")]
    pub name: Option<String>,
}

/// Reads the data, fits, writes the model, the report and the figure.
///
/// # Errors
/// Usage errors (contradicting options, an unsupported extension), a located data error, a
/// fitting error, a write error.
pub fn run(args: &FitArgs) -> anyhow::Result<()> {
    let model_format = model_format(args)?;
    if args.surface {
        return run_surface(args, model_format);
    }
    run_curve(args, model_format)
}

/// The model's format: by the extension of `-o`, TOML on standard output.
fn model_format(args: &FitArgs) -> anyhow::Result<Format> {
    let what = if args.surface { "surface" } else { "curve" };
    Ok(match &args.output {
        Some(path) => match Format::from_path(path) {
            Ok(Format::Toml) => Format::Toml,
            Ok(Format::Json) => Format::Json,
            _ => {
                return Err(UsageError(format!(
                    "{}: unsupported model extension for a fitted {what} (accepted: .toml, .json)",
                    path.display()
                ))
                .into())
            }
        },
        None => Format::Toml,
    })
}

/// The curve fit.
fn run_curve(args: &FitArgs, model_format: Format) -> anyhow::Result<()> {
    let figure_format = args.plot.as_deref().map(figure_format).transpose()?;
    let request = args.request.first("with --surface")?;
    let options = request.validate().map_err(|e| UsageError(e.to_string()))?;
    let membership = request.membership;
    let input = crate::commands::options::table_input(&args.table)?;
    let table = read_data(&args.data, membership, &input)?;
    if let Some(warning) = disorder_warning(&table) {
        eprintln!("{warning}");
    }
    request
        .check_data_weights(table.file(), table.weights().is_some())
        .map_err(|e| UsageError(e.to_string()))?;
    let fitted = table
        .fit(&options)
        .map_err(|e| anyhow::Error::msg(e.to_string()))?;
    let mut model = Model::new(fitted.curve.clone())
        .with_family(membership, fitted.second_lane.clone())?
        .with_description(format!(
            "Fitted to {} ({} points) by neutrospline fit",
            table.file(),
            table.len()
        ));
    if let Some(name) = &args.name {
        model = model.with_name(name.clone());
    }
    let text = neutrospline_io::to_string(&model, model_format)?;
    if let (Some(path), Some(format)) = (&args.plot, figure_format) {
        let plot = data_plot(&model, &fitted, &table, args.color_by)?;
        let options = PlotOptions::new().with_caption(format!("Data: {}", table.file()));
        write_figure(&plot, View::Data, &options, path, format)?;
    }
    output::emit(args.output.as_deref(), |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })?;
    let report = &fitted.report;
    let mut err = std::io::stderr().lock();
    match args.report {
        ReportFormat::Text => write!(err, "{}", report_text(report, &table))?,
        ReportFormat::Json => writeln!(err, "{}", report_json(report))?,
    }
    Ok(())
}
/// The surface fit: the same data file, model and report channels as a curve's.
fn run_surface(args: &FitArgs, model_format: Format) -> anyhow::Result<()> {
    let figure_format = args.plot.as_deref().map(figure_format).transpose()?;
    let request = args.request.second("without --surface")?;
    let options = request.validate().map_err(|e| UsageError(e.to_string()))?;
    let membership = request.membership;
    let input = crate::commands::options::table_input(&args.table)?;
    let table = read_data(&args.data, membership, &input)?;
    request
        .weights
        .check_data(table.file(), table.weights().is_some())
        .map_err(|e| UsageError(e.to_string()))?;
    let fitted = table
        .fit_surface(request.grid, &options)
        .map_err(|e| anyhow::Error::msg(e.to_string()))?;
    if let Some(warning) = neutrospline_io::surface_fit_warning(table.file(), &fitted.report) {
        eprintln!("warning: {warning}");
    }
    let shape = match request.grid {
        Some([rows, cols]) => format!("a grid of {rows} x {cols} points"),
        None => format!("{} scattered points", table.len()),
    };
    let mut model = Model::new(fitted.surface.clone())
        .with_family(membership, fitted.second_lane.clone())?
        .with_description(format!(
            "Fitted to {} ({shape}) by neutrospline fit --surface",
            table.file()
        ));
    if let Some(name) = &args.name {
        model = model.with_name(name.clone());
    }
    let text = neutrospline_io::to_string(&model, model_format)?;
    if let (Some(path), Some(format)) = (&args.plot, figure_format) {
        // The data view: the fitted surface, the data coloured by --color-by, whiskers to the
        // surface at each point's fitted (u, v).
        let overlay = DataOverlay::new(
            table.positions().to_vec(),
            table.degrees().iter().map(|d| d.to_array()).collect(),
        )
        .with_surface_parameters(fitted.parameters.clone())
        .with_color_by(args.color_by);
        // A wide family's figure knows its lanes (the plot crate says which views draw them).
        let plot = if fitted.second_lane.is_some() {
            PlotModel::from_model(&model)?
        } else {
            PlotModel::from_surface(&fitted.surface)?
        };
        let plot = plot.with_data(overlay)?;
        let options = PlotOptions::new().with_caption(format!("Data: {}", table.file()));
        write_figure(&plot, View::Data, &options, path, format)?;
    }
    output::emit(args.output.as_deref(), |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })?;
    let report = &fitted.report;
    let mut err = std::io::stderr().lock();
    match args.report {
        ReportFormat::Text => write!(err, "{}", surface_report_text(report, &table))?,
        ReportFormat::Json => {
            writeln!(err, "{}", neutrospline_io::surface_fit_report_json(report))?
        }
    }
    Ok(())
}

/// Control values on a bound listed one by one in the text report; more are counted.
const AT_BOUND_LISTED: usize = 12;

/// A surface fit's report as aligned text lines.
fn surface_report_text(report: &SurfaceFitReport, table: &DataTable) -> String {
    let mut out = String::new();
    let mut line = |label: &str, value: String| {
        out.push_str(&format!("{label:<21}{value}\n"));
    };
    let ([m, n], [p, q]) = (report.control_points, report.degrees);
    line(
        "control points",
        format!(
            "{m} x {n} (degrees {p}, {q}; {})",
            if report.two_pass {
                "two passes of the curve solver"
            } else {
                "whole tensor system"
            }
        ),
    );
    if let Some(e) = report.tolerance {
        let met = match report.tolerance_met {
            Some(true) => "met".to_owned(),
            _ => format!(
                "NOT met: no knot span with a point beyond it can be split further (achieved {})",
                number(report.worst_distance)
            ),
        };
        line("tolerance", format!("{}, {met}", output::rounded(e, 6)));
    }
    let [u, v] = report.worst_parameters;
    line(
        "worst point",
        format!(
            "{} (line {}, u = {}, v = {}): position residual {}",
            report.worst_index,
            table.line(report.worst_index),
            output::rounded(u, 6),
            output::rounded(v, 6),
            number(report.worst_distance)
        ),
    );
    line("channel", "max error              rms error".to_owned());
    for ((name, max), (_, rms)) in report.max_error.iter().zip(&report.rms_error) {
        line(
            &format!("  {name}"),
            format!("{:<22} {}", number(*max), number(*rms)),
        );
    }
    line(
        "data in supports",
        if report.data_in_every_support {
            "every control point has data in its support".to_owned()
        } else {
            "not every control point (smoothing determines the others)".to_owned()
        },
    );
    line(
        "condition estimate",
        format!("{:.3e}", report.condition_estimate),
    );
    if report.at_bound.is_empty() {
        line("at bound", "none".to_owned());
    } else if report.at_bound.len() > AT_BOUND_LISTED {
        // Many: counted by channel and bound (the JSON report lists each).
        let mut counts: Vec<(String, usize)> = Vec::new();
        for a in &report.at_bound {
            let key = format!("{} = {}", a.channel, a.bound);
            match counts.iter_mut().find(|(k, _)| *k == key) {
                Some((_, c)) => *c += 1,
                None => counts.push((key, 1)),
            }
        }
        counts.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let counted: Vec<String> = counts.iter().map(|(k, c)| format!("{k}: {c}")).collect();
        line(
            "at bound",
            format!(
                "{} control values ({}; --report json lists them)",
                report.at_bound.len(),
                counted.join(", ")
            ),
        );
    } else {
        let list: Vec<String> = report
            .at_bound
            .iter()
            .map(|a| {
                format!(
                    "({}, {}) {} = {}",
                    a.index / n,
                    a.index % n,
                    a.channel,
                    a.bound
                )
            })
            .collect();
        line("at bound", list.join(", "));
    }
    out
}

/// The warning for 3-D data without parameters that does not look like an ordered path
/// ([`DataTable::path_disorder`]): a curve is fitted through the rows in their order.
fn disorder_warning(table: &DataTable) -> Option<String> {
    if table.dimension() != 3 || table.parameters().is_some() {
        return None;
    }
    let d = table.path_disorder()?;
    let mut found = Vec::new();
    if d.median_step > neutrospline_io::PATH_SPREAD * d.median_nearest {
        found.push(format!(
            "consecutive rows are {} times as far apart as a point from its nearest neighbour \
             (medians)",
            output::rounded(d.median_step / d.median_nearest, 1)
        ));
    }
    if d.jumps > 0 {
        found.push(format!(
            "{} step{} longer than {} median steps, the longest {} median steps to line {}",
            d.jumps,
            if d.jumps == 1 { "" } else { "s" },
            neutrospline_io::PATH_JUMP,
            output::rounded(d.longest_ratio, 1),
            table.line(d.longest)
        ));
    }
    Some(format!(
        "warning: {}: the points do not look like an ordered path ({}): `fit` fits a curve \
         through them in the order of the rows. Order the rows along the path (or give a \
         `parameter` column); points scattered over an area are a surface: `fit --surface` \
         fits one",
        table.file(),
        found.join("; ")
    ))
}

/// The `data` view's model: the fitted curve, the data coloured by `color_by`, whiskers to
/// the curve at the fitted parameters. A wide family's figure is built from the fitted
/// `model`, which knows its lanes (the plot crate says which views draw them).
fn data_plot(
    model: &Model,
    fitted: &DynFit,
    table: &DataTable,
    color_by: DegreeKind,
) -> anyhow::Result<PlotModel> {
    let model = if fitted.second_lane.is_some() {
        PlotModel::from_model(model)?
    } else {
        PlotModel::from_dyn(&fitted.curve)?
    };
    let overlay = DataOverlay::new(
        table.positions().to_vec(),
        table.degrees().iter().map(|d| d.to_array()).collect(),
    )
    .with_parameters(fitted.parameters.clone())
    .with_color_by(color_by);
    Ok(model.with_data(overlay)?)
}

/// The report as aligned text lines.
fn report_text(report: &FitReport, table: &DataTable) -> String {
    let mut out = String::new();
    let mut line = |label: &str, value: String| {
        out.push_str(&format!("{label:<21}{value}\n"));
    };
    line(
        "control points",
        format!("{} (degree {})", report.control_points, report.degree),
    );
    if let Some(e) = report.tolerance {
        let met = match report.tolerance_met {
            Some(true) => "met",
            _ => {
                "NOT met: no span with a point beyond it can be split with data left on both halves"
            }
        };
        line("tolerance", format!("{}, {met}", output::rounded(e, 6)));
    }
    line(
        "worst point",
        format!(
            "{} (line {}, t = {}): position residual {}",
            report.worst_index,
            table.line(report.worst_index),
            output::rounded(report.worst_parameter, 6),
            number(report.worst_distance)
        ),
    );
    line("channel", "max error              rms error".to_owned());
    for ((name, max), (_, rms)) in report.max_error.iter().zip(&report.rms_error) {
        line(
            &format!("  {name}"),
            format!("{:<22} {}", number(*max), number(*rms)),
        );
    }
    line(
        "schoenberg-whitney",
        if report.schoenberg_whitney {
            "hold (every control point has data of its own)".to_owned()
        } else {
            "fail (smoothing determines the control points without data)".to_owned()
        },
    );
    line(
        "condition estimate",
        format!("{:.3e}", report.condition_estimate),
    );
    if report.at_bound.is_empty() {
        line("at bound", "none".to_owned());
    } else {
        let list: Vec<String> = report
            .at_bound
            .iter()
            .map(|a| format!("{} {} = {}", a.index, a.channel, a.bound))
            .collect();
        line("at bound", list.join(", "));
    }
    out
}

/// The report as one JSON object (keys as in docs/model.md section 8; the channels the
/// report lists, by their names: the positions and the family's channels).
fn report_json(report: &FitReport) -> String {
    let channels = |values: &[(&'static str, f64)]| {
        serde_json::Value::Object(
            values
                .iter()
                .map(|(name, v)| ((*name).to_owned(), json_number(*v)))
                .collect(),
        )
    };
    let value = serde_json::json!({
        "control_points": report.control_points,
        "degree": report.degree,
        "max_error": channels(&report.max_error),
        "rms_error": channels(&report.rms_error),
        "worst_index": report.worst_index,
        "worst_parameter": json_number(report.worst_parameter),
        "worst_distance": json_number(report.worst_distance),
        "schoenberg_whitney": report.schoenberg_whitney,
        "condition_estimate": json_number(report.condition_estimate),
        "at_bound": report.at_bound.iter().map(|a| serde_json::json!({
            "index": a.index,
            "channel": a.channel,
            "bound": a.bound,
        })).collect::<Vec<_>>(),
        "tolerance": report.tolerance.map(json_number),
        "tolerance_met": report.tolerance_met,
    });
    value.to_string()
}

/// A finite number as JSON (an infinite condition estimate of a singular system as `null`).
fn json_number(v: f64) -> serde_json::Value {
    serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
}
