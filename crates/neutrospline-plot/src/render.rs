//! From a model and options to a drawing (and SVG text): checks the options, samples the model, builds the
//! [`Ctx`] every view draws from, and hands it to the view's [`Figure`](crate::views::Figure)
//! for the kind of model.

use crate::ctx::{BandCtx, Ctx, DataCtx, WideCtx};
use crate::drawing::Drawing;
use crate::error::PlotError;
use crate::model::PlotModel;
use crate::options::PlotOptions;
use crate::theme::Theme;
use crate::view::View;
use crate::views;

/// Draws `view` of `model` as an SVG document: [`render_drawing`] written out with
/// [`Drawing::to_svg`].
///
/// The SVG is `options.width()` x `options.height()` pixels, uses only the bundled font
/// (family "DejaVu Sans", generic fallback `sans-serif`), and depends only on its inputs:
/// equal inputs give byte-identical output. Texts (title, axis names, legend, point names)
/// are real SVG `<text>` elements.
///
/// # Errors
/// As [`render_drawing`].
///
/// # Examples
/// ```
/// use neutrospline_plot::{render_svg, PlotModel, PlotOptions, View};
/// let model = PlotModel::from(&neutrospline::example1()).with_names(neutrospline::EXAMPLE1_NAMES)?;
/// let svg = render_svg(&model, View::Truth, &PlotOptions::default())?;
/// assert!(svg.contains("truth"));
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
pub fn render_svg(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
) -> Result<String, PlotError> {
    render_drawing(model, view, options).map(|d| d.to_svg())
}

/// Draws `view` of `model` as a [`Drawing`]: the figure's primitives in drawing order, which
/// [`Drawing::to_svg`] writes as the figure file and [`Drawing::to_display_list`] as a list
/// for an HTML canvas.
///
/// # Errors
/// The `data` view of a model without data ([`PlotError::NoData`]), invalid options ([`PlotOptions::validate`]; for a surface
/// [`PlotOptions::validate_surface`], which caps the samples per direction), a curve or
/// surface that cannot be sampled
/// ([`PlotError::Evaluate`], [`PlotError::NotFinite`]), or coordinates whose range overflows
/// ([`PlotError::RangeTooLarge`]).
///
/// # Examples
/// ```
/// use neutrospline_plot::{render_drawing, render_svg, PlotModel, PlotOptions, View};
/// let model = PlotModel::from(&neutrospline::example1());
/// let options = PlotOptions::default();
/// let drawing = render_drawing(&model, View::All, &options)?;
/// assert_eq!(drawing.to_svg(), render_svg(&model, View::All, &options)?);
/// assert!(drawing.to_display_list().starts_with("{\"width\":1600,\"height\":1200,"));
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
pub fn render_drawing(
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
) -> Result<Drawing, PlotError> {
    model.check_view(view)?;
    let wide_figure = views::family_figure(view, model.family()).or_else(|| {
        model
            .second_lane()
            .and_then(|_| views::wide_figure(view, model.family()))
    });
    let figure: &dyn views::Figure = match &wide_figure {
        Some(f) => f.as_ref(),
        None => views::figure(view),
    };
    if figure.draws_data() && model.data().is_none() {
        return Err(PlotError::NoData);
    }
    if view == View::Band && model.is_surface() {
        return Err(PlotError::BandOnSurface);
    }
    if model.is_surface() {
        options.validate_surface()?;
    } else {
        options.validate()?;
    }
    let mesh = model.mesh(options.surface_samples())?;
    let curve = match &mesh {
        Some(mesh) => mesh.points.clone(),
        None => model.curve_points(options.samples())?,
    };
    // The data view draws the data and the curve, not the control points (they would only
    // take room).
    let (data, controls, names) = if figure.draws_data() {
        let overlay = model.data().ok_or(PlotError::NoData)?;
        let (points, feet) = model.residuals()?.ok_or(PlotError::NoData)?;
        let data = DataCtx {
            points,
            feet,
            color_by: overlay.color_by,
            at_parameters: overlay.parameters.is_some() || overlay.surface_parameters.is_some(),
        };
        (Some(data), &[][..], &[][..])
    } else {
        // A periodic curve's polygon closes after its distinct points: P0 .. P(n-1), P0
        // (its other repeated points add nothing to the picture).
        let controls = model.controls();
        let shown = if model.labelled() < controls.len() {
            model.labelled() + 1
        } else {
            controls.len()
        };
        (None, &controls[..shown], model.names())
    };
    let title = match options.title() {
        Some(t) => t.to_string(),
        None => figure.title(model.label(), model.is_surface()),
    };
    let band = if view == View::Band {
        let (levels, centroid) = model.band_points(&options.alphas(), options.samples())?;
        Some(BandCtx { levels, centroid })
    } else {
        None
    };
    // The second lane of a wide family: the same parameters and positions.
    let second_controls;
    let wide = match model.second_lane() {
        Some(lane) if !figure.draws_data() => {
            let lane_mesh = lane.mesh(options.surface_samples())?;
            let lane_curve = match &lane_mesh {
                Some(mesh) => mesh.points.clone(),
                None => lane.curve_points(options.samples())?,
            };
            second_controls = lane.controls()[..controls.len()].to_vec();
            Some(WideCtx {
                curve: lane_curve,
                controls: &second_controls,
                mesh: lane_mesh,
            })
        }
        _ => None,
    };
    let ctx = Ctx {
        theme: Theme::of(options),
        options,
        curve,
        controls,
        names,
        labelled: model.labelled().min(controls.len()),
        title,
        caption: options.caption().unwrap_or("").to_string(),
        data,
        band,
        wide,
    };
    for axis in 0..model.dimension() {
        let (lo, hi) = ctx.extent(axis);
        if !(hi - lo).is_finite()
            || !(lo / 2.0 + hi / 2.0).is_finite()
            || (hi - lo) * 1.2 > f64::MAX / 4.0
        {
            return Err(PlotError::RangeTooLarge {
                axis: ["x", "y", "z"][axis],
            });
        }
    }
    let mut drawing = match (&mesh, model.grid()) {
        (Some(mesh), Some(grid)) => figure.surface(&ctx, mesh, grid),
        _ if model.dimension() == 2 => figure.curve_2d(&ctx),
        _ => figure.curve_3d(&ctx),
    };
    drawing.print = options.print_size();
    Ok(drawing)
}
