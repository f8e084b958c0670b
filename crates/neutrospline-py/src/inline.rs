//! The figure a notebook shows for a curve or surface (`_repr_svg_`, `_repr_png_`), and the
//! module setting that chooses it: `neutrospline.inline(...)`.
//!
//! The inline figure is a [`FigureRequest`] (the plot crate's options, as `to_svg` takes them)
//! at a notebook size, 800 x 600 pixels, and a format: `"svg"`, `"png"` or `"both"` (the
//! default: the SVG, and a PNG for the programs that show no SVG, such as an export to PDF).
//! The SVG is responsive: its root has `width="100%"` and its `viewBox`, so it shrinks with a
//! narrow cell and never overflows it, up to its own width. A surface's mesh is sampled
//! [`SURFACE_SAMPLES`] times per direction unless `samples` is set, which keeps its SVG under
//! 200 KB.

use std::sync::Mutex;

use neutrospline::options::{OptionSet, OptionValue};
use neutrospline_io::Model;
use neutrospline_plot::{render_png, FigureRequest, FigureSize};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

use crate::errors::{invalid, invalid_at};
use crate::model;
use crate::options::set_from_kwargs;

/// The inline figure's width and height in pixels, unless set.
const NOTEBOOK_SIZE: (u32, u32) = (800, 600);

/// Samples per direction of a surface's inline mesh, unless `samples` is set.
pub const SURFACE_SAMPLES: usize = 14;

/// Which representations a notebook is given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Svg,
    Png,
    Both,
}

impl Format {
    const NAMES: [(&'static str, Format); 3] = [
        ("svg", Format::Svg),
        ("png", Format::Png),
        ("both", Format::Both),
    ];

    fn name(self) -> &'static str {
        Format::NAMES
            .iter()
            .find(|(_, f)| *f == self)
            .map_or("both", |(n, _)| n)
    }
}

/// The module's inline setting.
#[derive(Clone, Debug)]
struct Inline {
    request: FigureRequest,
    format: Format,
}

impl Default for Inline {
    fn default() -> Self {
        Inline {
            request: FigureRequest {
                size: Some(FigureSize::Pixels(NOTEBOOK_SIZE.0, NOTEBOOK_SIZE.1)),
                ..FigureRequest::default()
            },
            format: Format::Both,
        }
    }
}

static INLINE: Mutex<Option<Inline>> = Mutex::new(None);

fn current() -> Inline {
    INLINE
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .clone()
        .unwrap_or_default()
}

/// Chooses the figure that a notebook shows for every curve and surface, and returns the
/// setting (a dictionary of every option's value as text, and `format`).
///
/// `format` is `"svg"`, `"png"` or `"both"` (the default); the other keyword options are
/// `to_svg`'s (`view`, `width`, `height`, `samples`, `color_by`, ..., `figure_options()` lists
/// them), with a notebook size of 800 x 600 pixels; `reset=True` restores the defaults first.
/// Called with no options, it only returns the setting.
///
/// >>> import neutrospline as ns
/// >>> ns.inline(view="truth", format="svg")["view"]
/// 'truth'
/// >>> ns.example1()._repr_png_() is None
/// True
/// >>> ns.inline(reset=True)["format"], ns.inline()["width"]
/// ('both', '800')
#[pyfunction]
#[pyo3(signature = (*, reset = false, format = None, **options))]
pub fn inline<'py>(
    py: Python<'py>,
    reset: bool,
    format: Option<&str>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let mut setting = if reset { Inline::default() } else { current() };
    if let Some(format) = format {
        setting.format = Format::NAMES
            .iter()
            .find(|(name, _)| name.eq_ignore_ascii_case(format.trim()))
            .map(|(_, f)| *f)
            .ok_or_else(|| {
                invalid_at(
                    "format",
                    format!("{format:?} is not an inline format (one of svg, png, both)"),
                )
            })?;
    }
    set_from_kwargs(&mut setting.request, options)?;
    *INLINE
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(setting.clone());
    let dict = PyDict::new(py);
    dict.set_item("format", setting.format.name())?;
    for spec in FigureRequest::OPTIONS {
        let value = setting.request.value_text(spec.name).map_err(invalid)?;
        dict.set_item(spec.name.replace('-', "_"), value)?;
    }
    Ok(dict)
}

/// The inline request for `model`: a surface's samples unless set.
fn request_for(model: &Model, setting: &Inline) -> PyResult<FigureRequest> {
    let mut request = setting.request.clone();
    if model.shape().is_surface() && request.samples.is_none() {
        request
            .set(
                "samples",
                OptionValue::Integer(i64::try_from(SURFACE_SAMPLES).unwrap_or(14)),
            )
            .map_err(invalid)?;
    }
    Ok(request)
}

/// Whether the figure of `request` draws `model`'s family (the plot crate refuses a view that
/// would misdraw it, such as the `all` view of a 3-D curve of an interval-valued family).
fn draws(model: &Model, request: &FigureRequest) -> PyResult<bool> {
    let (figure, view, _) = model::prepare(model, request)?;
    Ok(figure.check_view(view).is_ok())
}

/// The inline SVG of `model`, responsive, or `None` when the setting gives PNG only (or the
/// inline view would misdraw the model's family: Jupyter then shows the text `repr`).
pub fn svg(py: Python<'_>, model: &Model) -> PyResult<Option<String>> {
    let setting = current();
    let request = request_for(model, &setting)?;
    if setting.format == Format::Png || !draws(model, &request)? {
        return Ok(None);
    }
    let text = model::svg(py, model, &request)?;
    Ok(Some(responsive(&text)))
}

/// The inline PNG of `model`, or `None` when the setting gives SVG only (or the inline view
/// would misdraw the model's family, as for [`svg`]).
pub fn png<'py>(py: Python<'py>, model: &Model) -> PyResult<Option<Bound<'py, PyBytes>>> {
    let setting = current();
    let request = request_for(model, &setting)?;
    if setting.format == Format::Svg || !draws(model, &request)? {
        return Ok(None);
    }
    let (figure, view, options) = model::prepare(model, &request)?;
    let bytes = py
        .detach(|| render_png(&figure, view, &options))
        .map_err(invalid)?;
    Ok(Some(PyBytes::new(py, &bytes)))
}

/// The SVG with its root's `width="W" height="H"` replaced by `width="100%"` and a style that
/// keeps its aspect (from the `viewBox`, which the renderer always writes) and caps it at `W`
/// pixels.
fn responsive(svg: &str) -> String {
    let Some(start) = svg.find("<svg ") else {
        return svg.to_owned();
    };
    let end = svg[start..].find('>').map_or(svg.len(), |e| start + e);
    let root = &svg[start..end];
    let attribute = |name: &str| {
        let key = format!(" {name}=\"");
        let at = root.find(&key)?;
        let value_start = at + key.len();
        let value_end = value_start + root[value_start..].find('"')?;
        Some((at, value_end + 1, root[value_start..value_end].to_owned()))
    };
    let (Some((w0, w1, width)), Some((h0, h1, _))) = (attribute("width"), attribute("height"))
    else {
        return svg.to_owned();
    };
    if !root.contains(" viewBox=\"") || h0 != w1 {
        return svg.to_owned();
    }
    // A size in pixels is a bare number; a print size keeps its unit (`8.5cm`), which CSS reads.
    let unit = if width.bytes().all(|b| b.is_ascii_digit() || b == b'.') {
        "px"
    } else {
        ""
    };
    let new_root = format!(
        "{} width=\"100%\" style=\"max-width: {width}{unit}; height: auto\"{}",
        &root[..w0],
        &root[h1..]
    );
    format!("{}{}{}", &svg[..start], new_root, &svg[end..])
}

#[cfg(test)]
mod tests {
    use super::responsive;

    #[test]
    fn the_root_becomes_responsive_and_nothing_else_changes() {
        let svg = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" \
                   width=\"800\" height=\"600\" viewBox=\"0 0 800 600\"><rect width=\"800\" \
                   height=\"600\"/></svg>";
        assert_eq!(
            responsive(svg),
            "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100%\" \
             style=\"max-width: 800px; height: auto\" viewBox=\"0 0 800 600\"><rect \
             width=\"800\" height=\"600\"/></svg>"
        );
    }
}
