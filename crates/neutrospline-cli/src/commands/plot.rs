//! `neutrospline plot FILE -o OUT.svg|OUT.png|OUT.pdf --view VIEW`: a figure of a curve or surface.

use std::path::{Path, PathBuf};

use neutrospline_plot::{
    render_figure, DataOverlay, FigureFormat, FigureRequest, PlotModel, PlotOptions, View,
};

use crate::commands::options::ModelArgs;
use crate::input::read_data;
use crate::input::{self, UsageError};
use crate::output;
use crate::request::RequestArgs;

/// The format of figure file `path`, from its extension.
///
/// # Errors
/// A usage error naming the file and the accepted extensions.
pub fn figure_format(path: &Path) -> Result<FigureFormat, UsageError> {
    FigureFormat::from_path(path).map_err(|e| UsageError(e.to_string()))
}

/// Arguments of `plot`.
#[derive(Debug, clap::Args)]
#[command(after_help = "Views:\n  \
controls       the control points and polygon, each point with its truth, indeterminacy and\n                 \
falsity (paper Fig. 1)\n  \
truth          3-D axes x, y, truth: the space curve (x(t), y(t), truth(t)), its control\n                 \
polygon, and the crisp curve as its shadow (paper Fig. 2; 3-D models and surfaces:\n                 \
coloured by truth)\n  \
indeterminacy  the same for indeterminacy (paper Fig. 3)\n  \
falsity        the same for falsity (paper Fig. 4)\n  \
all            the three together (paper Fig. 5)\n  \
plane          the crisp curve with three bands along it whose widths follow the degrees\n  \
score          the space curve (x(t), y(t), score(t)) above the crisp curve, score =\n                 \
(2 + T - I - F) / 3 (3-D models and surfaces: coloured by the score)\n  \
data           the data points of --data coloured by a degree over the curve, with residual\n                 \
whiskers (curves only)\n  \
band           the fuzzy position (control point spreads): the regions swept by the\n                 \
alpha-cuts at alpha = 0, 0.5, 1 (or --alpha), lighter for lower alpha, the crisp curve\n                 \
on top, the centroid curve dashed (curves only; 3-D: the tube's silhouette)\n\
Interval-valued and bipolar models: truth, indeterminacy, falsity and all draw each degree's\n\
lower and upper curves (dashed and solid) with the band between them, or the positive degree\n\
above the crisp plane and the negative one below it (3-D curves and surfaces: one panel per\n\
lane); controls, plane, score and data draw one value per degree and refuse them.\n\
The format follows the extension of OUT: .svg, .png or .pdf (vector, the font embedded:\n\
for LaTeX). For a paper: --style paper (no title or caption, 8.5cm wide, text of 8.5 to 10\n\
points), or --size 8.5cmx6cm with --no-title / --no-caption; --dpi sets a PNG's resolution.")]
pub struct PlotArgs {
    /// The model file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// The figure to write: OUT.svg, OUT.png or OUT.pdf (replaced atomically)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,

    /// Measured points (a CSV data file, as `neutrospline fit` reads) to draw over the curve in
    /// the data view, with whiskers to the curve at their `parameter` column, or to the
    /// nearest point of the curve without one
    #[arg(long, value_name = "DATA.csv")]
    pub data: Option<String>,

    /// The figure's options (defined by the plot crate's `FigureRequest`)
    #[command(flatten)]
    pub figure: RequestArgs<FigureRequest>,

    #[command(flatten)]
    pub model: ModelArgs,
}

/// Renders `model` as `format` and writes it atomically to `path`.
///
/// # Errors
/// A rendering error or a write error naming the file.
pub fn write_figure(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
    path: &Path,
    format: FigureFormat,
) -> anyhow::Result<()> {
    let bytes = render_figure(model, view, options, format)?;
    output::emit(Some(path), |w| {
        w.write_all(&bytes)?;
        Ok(())
    })
}

/// Reads the model, renders the view and writes the figure.
///
/// # Errors
/// An invalid file, an unsupported output extension or option (usage errors), a rendering
/// error or a write error.
pub fn run(args: &PlotArgs) -> anyhow::Result<()> {
    let format = figure_format(&args.output)?;
    let request = args.figure.request()?;
    let mut options = request
        .plot_options()
        .map_err(|e| UsageError(e.to_string()))?;
    // A wide family (interval-valued, bipolar) is drawn lane by lane; the views that would
    // misdraw it are refused by `PlotModel::check_view` with the reason.
    let model = input::read_model(&args.file, &args.model)?;
    let membership = model.membership();
    let mut plot = PlotModel::from_model(&model)?;
    let description = model.description().map(str::to_owned);
    let shape = model.into_shape();
    if shape.is_surface() && request.samples.is_some() {
        options
            .validate_surface()
            .map_err(|e| UsageError(e.to_string()))?;
    }
    if let (None, Some(description)) = (options.caption(), description) {
        options = options.with_caption(description);
    }
    let view = request.view(args.data.is_some());
    match (&args.data, view) {
        (Some(file), View::Data) => {
            let table = read_data(file, membership, &args.model.table_input()?)?;
            if table.dimension() != shape.dimension() {
                return Err(anyhow::anyhow!(
                    "{}: the data is {}-D but the model is {}-D (give z for a 3-D curve, or \
                     none for a 2-D one)",
                    table.file(),
                    table.dimension(),
                    shape.dimension()
                ));
            }
            let overlay = DataOverlay::from_table(&table, request.color_by);
            plot = plot
                .with_data(overlay)
                .map_err(|e| anyhow::anyhow!("{}: {e}", table.file()))?;
        }
        (Some(_), other) => {
            return Err(UsageError(format!(
                "--data is drawn by the data view, not by --view {other} (give --view data or \
                 leave --view out)"
            ))
            .into())
        }
        (None, _) => {}
    }
    write_figure(&plot, view, &options, &args.output, format)
}
