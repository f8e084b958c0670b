//! The studio's pages and JSON API. Every model the page sends is the JSON object that saving
//! to `.json` writes, as text; it is read by `neutrospline-io` (so refusals carry the CLI's
//! messages), drawn by `neutrospline-plot` and written back by `neutrospline-io`. The page
//! computes no geometry of its own.
//!
//! | route | body | answer |
//! |---|---|---|
//! | `GET /`, `/studio.js`, `/studio.css`, `/paint.js` | | the page (embedded in the binary) |
//! | `GET /api/state` | | `{model, file, canSave, families}`: the model the studio was started with, and the description of every family the membership list offers |
//! | `POST /api/render` | `{model, views, encoding: svg\|display-list, at, data, figure}` | `{model, figures (SVG) or drawings (display lists), errors, refused (each view the model's family cannot draw, with the reason), handles, table, info, family, pointDegrees, ms}` |
//! | `POST /api/export` | `{model, format: svg\|png, data, figure}` | the figure's bytes |
//! | `POST /api/open` | `{name, text}` | `{model}`: a TOML, JSON or CSV model read like a file |
//! | `POST /api/convert` | `{model, format: toml\|json}` | `{text, filename}` (a download) |
//! | `POST /api/save` | `{model}` | `{saved}`: written atomically to the file the studio was started with |
//! | `POST /api/data` | `{name, text, membership}` | `{points, dimension}` |
//! | `POST /api/fit` | `{data: {name, text}, options, surface}` | `{model, report}` |
//!
//! `figure` holds the figure's options by the names of the plot crate's `FigureRequest` (view,
//! width, height, size, dpi, style, no-title, no-caption, title, caption, azimuth, elevation,
//! samples, alpha, color-by), `options` the
//! fit's by those of `neutrospline::fit::FitRequest` (with `surface: true`, those of
//! `neutrospline::fit::SurfaceFitRequest`: `neutrospline fit --surface`), the membership rule
//! among them: the
//! command line's flags, read by the libraries, so a wrong type, an unknown name or a value out
//! of range is a 400 with the command line's message.
//! A refused model is answered 422 with `{"error": {"message", "field", "line"}}`.
//!
//! A family is described to the page by the core's `Family` data (`family` and `families`:
//! its channels with their boxes, its lanes, its parameter, its derived degrees and its rule
//! in words; see `family_json`), so the page draws one field and slider per channel and holds
//! no family knowledge of its own. `pointDegrees` holds the values of those fields at every
//! control point, as the model holds them (the intuitionistic hesitation among them).

use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::Mutex;
use std::time::Instant;

use neutrospline::fit::{FitRequest, SurfaceFitRequest};
use neutrospline::{
    uniform_parameter, AnyCurve, ControlPolygon, DegreeKind, DynCurve, EvaluateSurface, Family,
};
use neutrospline_io::{format_number, DataTable, Format, Model, ReadError, ReadOptions, Shape};
use neutrospline_plot::{
    render_drawing, render_png, render_svg, DataOverlay, Drawing, FigureRequest, PlotModel,
    PlotOptions, View,
};
use serde_json::{json, Map, Value};

use crate::figure::{handles, space_handles};
use crate::http::{Handler, Request, Response};

const INDEX_HTML: &str = include_str!("assets/index.html");
const STUDIO_JS: &str = include_str!("assets/studio.js");
const STUDIO_CSS: &str = include_str!("assets/studio.css");
const PAINT_JS: &str = include_str!("assets/paint.js");

/// The paper's Example 1, opened when the studio is started without a file.
const EXAMPLE1_JSON: &str = include_str!("../../../examples/example1.json");

/// The name models sent by the page have in messages.
const PAGE_MODEL: &str = "model";

/// The studio: the model it was started with, and the one file it may write.
pub struct Studio {
    file: Option<PathBuf>,
    current: Mutex<Model>,
}

impl Studio {
    /// A studio on the paper's Example 1 (`examples/example1.json`), with no file to save to.
    pub fn example() -> Studio {
        // The file is part of the repository and is tested to read back; a failure here is a
        // bug in the build, not bad input.
        let model = neutrospline_io::parse(
            "example1.json",
            Format::Json,
            EXAMPLE1_JSON.as_bytes(),
            &ReadOptions::default(),
        )
        .unwrap_or_else(|_| Model::new(AnyCurve::from(neutrospline::example1())));
        Studio {
            file: None,
            current: Mutex::new(model),
        }
    }

    /// A studio on `model`, read from `file`: "save" replaces that file (atomically) and no
    /// other.
    pub fn with_file(model: Model, file: impl Into<PathBuf>) -> Studio {
        Studio {
            file: Some(file.into()),
            current: Mutex::new(model),
        }
    }

    /// The file "save" writes, if any.
    pub fn file(&self) -> Option<&Path> {
        self.file.as_deref()
    }

    fn current(&self) -> std::sync::MutexGuard<'_, Model> {
        self.current.lock().unwrap_or_else(|e| e.into_inner())
    }
}

impl Handler for Studio {
    fn handle(&self, request: &Request) -> Response {
        let post = |f: &dyn Fn(&Value) -> Result<Response, Response>| -> Response {
            if request.method != "POST" {
                return Response::error(405, "use POST").with_header("Allow", "POST");
            }
            let body: Value = match serde_json::from_slice(&request.body) {
                Ok(v) => v,
                Err(e) => return Response::error(400, &format!("the body is not JSON: {e}")),
            };
            f(&body).unwrap_or_else(|e| e)
        };
        match request.path.as_str() {
            "/" | "/index.html" | "/studio.js" | "/studio.css" | "/paint.js" | "/api/state"
                if request.method != "GET" && request.method != "HEAD" =>
            {
                Response::error(405, "use GET").with_header("Allow", "GET")
            }
            "/" | "/index.html" => Response::new(200, "text/html; charset=utf-8", INDEX_HTML)
                .with_header(
                "Content-Security-Policy",
                "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'",
            ),
            "/studio.js" => Response::new(200, "text/javascript; charset=utf-8", STUDIO_JS),
            "/studio.css" => Response::new(200, "text/css; charset=utf-8", STUDIO_CSS),
            "/paint.js" => Response::new(200, "text/javascript; charset=utf-8", PAINT_JS),
            "/api/state" => self.state(),
            "/favicon.ico" => Response::new(204, "image/x-icon", Vec::new()),
            "/api/render" => post(&render),
            "/api/export" => post(&export),
            "/api/open" => post(&open),
            "/api/convert" => post(&|b| self.convert(b)),
            "/api/save" => post(&|b| self.save(b)),
            "/api/data" => post(&data),
            "/api/fit" => post(&fit_data),
            _ => Response::error(404, &format!("no such page: {}", request.path)),
        }
    }
}

impl Studio {
    fn state(&self) -> Response {
        let model = neutrospline_io::to_json_string(&self.current());
        let file = self.file.as_ref().map(|f| f.display().to_string());
        let families: Vec<Value> = Family::EXAMPLES
            .iter()
            .map(|&f| family_json(new_family(f)))
            .collect();
        with_model(
            &model,
            json!({ "file": file, "canSave": self.file.is_some(), "families": families }),
            200,
        )
    }

    fn convert(&self, body: &Value) -> Result<Response, Response> {
        let model = page_model(body)?;
        let format = match body["format"].as_str() {
            Some("toml") => Format::Toml,
            Some("json") => Format::Json,
            other => {
                return Err(Response::error(
                    400,
                    &format!("format {other:?}: give \"toml\" or \"json\""),
                ))
            }
        };
        let text = neutrospline_io::to_string(&model, format)
            .map_err(|e| Response::error(422, &e.to_string()))?;
        let stem = self
            .file
            .as_deref()
            .and_then(Path::file_stem)
            .map_or("model".to_owned(), |s| s.to_string_lossy().into_owned());
        let filename = format!("{stem}.{}", format.extension());
        Ok(Response::json(
            200,
            json!({ "text": text, "filename": filename }).to_string(),
        ))
    }

    fn save(&self, body: &Value) -> Result<Response, Response> {
        let Some(path) = &self.file else {
            return Err(Response::error(
                409,
                "the studio was started without a file: download the model with \
                 \u{201c}Save as TOML\u{201d} or \u{201c}Save as JSON\u{201d}",
            ));
        };
        let model = page_model(body)?;
        let mut current = self.current();
        neutrospline_io::save(&model, path).map_err(|e| Response::error(500, &e.to_string()))?;
        *current = model;
        Ok(Response::json(
            200,
            json!({ "saved": path.display().to_string() }).to_string(),
        ))
    }
}

/// `{"model": MODEL_JSON, ...rest}` (the model as the JSON writer writes it).
fn with_model(model_json: &str, rest: Value, status: u16) -> Response {
    with_parts(&[("model", model_json)], rest, status)
}

/// `{KEY: JSON, ..., ...rest}`: `parts` are keys with JSON text written as it is (a model as
/// the JSON writer writes it, figures already encoded), followed by the members of `rest`.
fn with_parts(parts: &[(&str, &str)], rest: Value, status: u16) -> Response {
    let mut body = String::from("{");
    for (i, (key, json)) in parts.iter().enumerate() {
        if i > 0 {
            body.push(',');
        }
        body.push_str(&Value::from(*key).to_string());
        body.push(':');
        body.push_str(json);
    }
    let rest = rest.to_string();
    match rest.strip_prefix('{') {
        Some("}") | None => body.push('}'),
        Some(tail) => {
            body.push(',');
            body.push_str(tail);
        }
    }
    Response::json(status, body)
}

/// A 422 answer for a refused model or file: the message as the CLI prints it after
/// `error: `, and its field and line for the page to point at.
fn refused(error: &ReadError, shown_without_file: bool) -> Response {
    let (message, detail, field, line) = match error {
        ReadError::Input(e) => (
            match (&e.field, shown_without_file) {
                (Some(f), true) => format!("{f}: {}", e.message),
                (None, true) => e.message.clone(),
                (_, false) => e.to_string(),
            },
            Some(e.message.clone()),
            e.field.clone(),
            e.line,
        ),
        ReadError::Format(e) => (e.describe(Format::ACCEPTED), None, None, None),
        e => (e.to_string(), None, None, None),
    };
    let error = json!({ "message": message, "detail": detail, "field": field, "line": line });
    Response::json(422, json!({ "error": error }).to_string())
}

/// The model in `body["model"]`: the text of a `.json` model.
fn page_model(body: &Value) -> Result<Model, Response> {
    let text = body["model"]
        .as_str()
        .ok_or_else(|| Response::error(400, "`model` must be the text of a JSON model"))?;
    neutrospline_io::parse(
        PAGE_MODEL,
        Format::Json,
        text.as_bytes(),
        &ReadOptions::default(),
    )
    .map_err(|e| refused(&e, true))
}

/// The figure's request from the page: `figure` maps the canonical names of
/// [`FigureRequest`]'s options (those of `neutrospline plot`: view, width, height, title,
/// caption, azimuth, elevation, samples, alpha, color-by, and the print options) to values; a wrong type, an unknown
/// name or a value out of range is a 400 with the library's message.
fn figure_request(body: &Value) -> Result<FigureRequest, Response> {
    for key in [
        "azimuth",
        "elevation",
        "samples",
        "colorBy",
        "color-by",
        "view",
    ] {
        if body.get(key).is_some() {
            return Err(Response::error(
                400,
                &format!("{key} is a figure option: give it in `figure`"),
            ));
        }
    }
    match body.get("figure") {
        None | Some(Value::Null) => Ok(FigureRequest::default()),
        Some(figure) => neutrospline::options::deserialize::<FigureRequest, _>(figure.clone())
            .map_err(|e| Response::error(400, &e.to_string())),
    }
}

/// The plot options of `request`, with the model's description as the caption when the
/// request gives none (as `neutrospline plot` does).
fn figure_options(model: &Model, request: &FigureRequest) -> Result<PlotOptions, Response> {
    let options = request
        .plot_options()
        .map_err(|e| Response::error(400, &e.to_string()))?;
    Ok(match (&request.caption, model.description()) {
        (None, Some(description)) => options.with_caption(description),
        _ => options,
    })
}

fn membership(body: &Value, default: Family) -> Result<Family, Response> {
    match body.get("membership") {
        None | Some(Value::Null) => Ok(default),
        Some(Value::String(m)) => {
            Family::from_str(m).map_err(|e| Response::error(400, &e.to_string()))
        }
        Some(other) => Err(Response::error(
            400,
            &format!(
                "membership = {other}: expected a family name as a string, one of: {}",
                neutrospline::FAMILY_FORMS
            ),
        )),
    }
}

/// The data table of `data = {name, text}` (`name` is used in messages only).
fn data_table(data: &Value, membership: Family) -> Result<Option<DataTable>, Response> {
    if data.is_null() {
        return Ok(None);
    }
    let name = file_label(data["name"].as_str().unwrap_or("data.csv"));
    let text = data["text"]
        .as_str()
        .ok_or_else(|| Response::error(400, "`data.text` must be the CSV text"))?;
    neutrospline_io::read_data(&name, text.as_bytes(), membership)
        .map(Some)
        .map_err(|e| refused(&e, false))
}

/// The last component of a name the page gives (a file's name, never a path to read).
fn file_label(name: &str) -> String {
    Path::new(name)
        .file_name()
        .map_or("file".to_owned(), |n| n.to_string_lossy().into_owned())
}

/// The plot model, with the data of `body["data"]` when there is any (and the data's error
/// when it cannot be drawn with the model); `Err` with the plot crate's message when it draws
/// no figure of the model at all.
fn prepare(
    model: &Model,
    body: &Value,
    color_by: DegreeKind,
) -> Result<(PlotModel, Option<String>), String> {
    let plot = PlotModel::from_model(model).map_err(|e| e.to_string())?;
    let table = match data_table(&body["data"], model.membership()) {
        Ok(t) => t,
        Err(r) => {
            let message = serde_json::from_slice::<Value>(&r.body)
                .ok()
                .and_then(|v| v["error"]["message"].as_str().map(str::to_owned));
            return Ok((plot, message));
        }
    };
    let Some(table) = table else {
        return Ok((plot, None));
    };
    if table.dimension() != model.shape().dimension() {
        let message = format!(
            "{}: the data is {}-D but the model is {}-D (give z for a 3-D curve, or none for a \
             2-D one)",
            table.file(),
            table.dimension(),
            model.shape().dimension()
        );
        return Ok((plot, Some(message)));
    }
    match plot
        .clone()
        .with_data(DataOverlay::from_table(&table, color_by))
    {
        Ok(p) => Ok((p, None)),
        Err(e) => Ok((plot, Some(format!("{}: {e}", table.file())))),
    }
}

fn parse_view(name: &str) -> Result<View, Response> {
    View::from_str(name).map_err(|e| Response::error(400, &e.to_string()))
}

/// How `/api/render` writes the figures: SVG documents (`figures`), or display lists for a
/// canvas (`drawings`: the frames while a point is dragged or a view turned, which the page
/// paints far faster than it lays out SVG).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Encoding {
    Svg,
    DisplayList,
}

fn render(body: &Value) -> Result<Response, Response> {
    let start = Instant::now();
    let model = page_model(body)?;
    let views = body["views"]
        .as_array()
        .map(|v| v.iter().filter_map(Value::as_str).map(parse_view).collect())
        .unwrap_or_else(|| Ok(Vec::new()))?;
    let encoding = match body["encoding"].as_str() {
        None | Some("svg") => Encoding::Svg,
        Some("display-list") => Encoding::DisplayList,
        Some(other) => {
            return Err(Response::error(
                400,
                &format!("encoding `{other}`: give \"svg\" or \"display-list\""),
            ))
        }
    };
    let mut request = figure_request(body)?;
    // A preview while a point is dragged: fewer samples along a curve (the figure after the
    // drag, and every export, use the default); a surface keeps its mesh.
    if model.shape().is_surface() {
        request.samples = None;
    }
    let options = figure_options(&model, &request)?;
    // A model the plot crate draws no figure of is still checked, evaluated and edited: each
    // view shows the plot crate's message.
    // The views the plot crate refuses for this model's family, with the reason: the page
    // greys their boxes out with the reason as their title, and draws no panel for them.
    let mut refused = Map::new();
    let (drawn, data_error) = match prepare(&model, body, request.color_by) {
        Ok((plot, data_error)) => {
            for view in View::ALL {
                if let Err(e) = plot.check_view(view) {
                    refused.insert(view.name().to_owned(), Value::String(e.to_string()));
                }
            }
            (render_views(&plot, &views, &options, encoding), data_error)
        }
        Err(e) => (views.iter().map(|&v| (v, Err(e.clone()))).collect(), None),
    };
    // Each view's figure as JSON text: an SVG string or a display-list object.
    let mut figures = Vec::new();
    let mut errors = Map::new();
    let mut plane_handles = Value::Null;
    for (view, drawn) in drawn {
        match drawn {
            Ok((json, drawing)) => {
                if view == View::Plane {
                    plane_handles = match model.shape() {
                        Shape::Curve(DynCurve::Planar(c)) => {
                            let points: Vec<[f64; 2]> =
                                c.control_points().iter().map(|p| p.position).collect();
                            let h = handles(&drawing, &points);
                            json!({ "pixels": h.pixels, "frame": h.frame, "drag": h.drag })
                        }
                        Shape::Curve(DynCurve::Spatial(c)) => {
                            let points: Vec<[f64; 3]> =
                                c.control_points().iter().map(|p| p.position).collect();
                            let h = space_handles(&drawing, &points);
                            json!({ "pixels": h.pixels, "frame": null, "drag": h.drag })
                        }
                        _ => json!({
                            "pixels": drawing.circle_centres("control-point"),
                            "frame": null,
                            "drag": null,
                        }),
                    };
                }
                figures.push((view, json));
            }
            Err(e) => {
                errors.insert(view.name().to_owned(), Value::String(e));
            }
        }
    }
    if let Some(e) = data_error {
        errors.insert("data".to_owned(), Value::String(e));
    }
    let table = match table(&model, body["at"].as_str().unwrap_or("")) {
        Ok((columns, rows)) => json!({ "columns": columns, "rows": rows }),
        Err(message) => json!({ "error": message }),
    };
    let mut figures_json = String::from("{");
    for (i, (view, json)) in figures.iter().enumerate() {
        if i > 0 {
            figures_json.push(',');
        }
        figures_json.push_str(&Value::from(view.name()).to_string());
        figures_json.push(':');
        figures_json.push_str(json);
    }
    figures_json.push('}');
    let key = match encoding {
        Encoding::Svg => "figures",
        Encoding::DisplayList => "drawings",
    };
    let ms = start.elapsed().as_secs_f64() * 1e3;
    Ok(with_parts(
        &[
            ("model", &neutrospline_io::to_json_string(&model)),
            (key, &figures_json),
        ],
        json!({
            "errors": errors,
            "refused": refused,
            "handles": plane_handles,
            "table": table,
            "info": info(&model),
            "family": family_json(model.membership()),
            "pointDegrees": point_degrees(&model),
            "ms": ms,
        }),
        200,
    ))
}

/// A figure as JSON text in its encoding, with the drawing it encodes.
type Drawn = (String, Drawing);

/// Draws `views` on up to [`std::thread::available_parallelism`] threads (a drag redraws
/// every view shown), in the order given: each figure as JSON text in `encoding` (an SVG
/// string or a display-list object), with its drawing.
fn render_views(
    plot: &PlotModel,
    views: &[View],
    options: &PlotOptions,
    encoding: Encoding,
) -> Vec<(View, Result<Drawn, String>)> {
    let draw = |v: View| {
        let drawn = render_drawing(plot, v, options)
            .map(|d| {
                let json = match encoding {
                    Encoding::Svg => Value::String(d.to_svg()).to_string(),
                    Encoding::DisplayList => d.to_display_list(),
                };
                (json, d)
            })
            .map_err(|e| e.to_string());
        (v, drawn)
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    if views.len() < 2 || threads < 2 {
        return views.iter().map(|&v| draw(v)).collect();
    }
    let chunk = views.len().div_ceil(threads);
    std::thread::scope(|scope| {
        let handles: Vec<_> = views
            .chunks(chunk)
            .map(|part| {
                let draw = &draw;
                scope.spawn(move || part.iter().map(|&v| draw(v)).collect::<Vec<_>>())
            })
            .collect();
        handles
            .into_iter()
            .zip(views.chunks(chunk))
            .flat_map(|(h, part)| {
                h.join().unwrap_or_else(|_| {
                    part.iter()
                        .map(|&v| (v, Err("internal error while drawing".to_owned())))
                        .collect()
                })
            })
            .collect()
    })
}

/// What the page shows about the model besides the figures.
fn info(model: &Model) -> Value {
    let shape = model.shape();
    let domain = shape.curve_domain().map(|d| [d.start, d.end]);
    json!({
        "kind": model.kind().to_string(),
        "dimension": shape.dimension(),
        "surface": shape.is_surface(),
        "domain": domain,
    })
}

/// The table of `eval` (columns `t, x, y[, z]`, then the degrees as
/// [`DegreeView`](neutrospline_io::DegreeView) shows the model's family: `truth,
/// indeterminacy, falsity`, or its channels and derived degrees; surfaces `u, v, x, y, z, ...`)
/// at the parameters of `at` (`T1,T2,...` or `U:V,...`), or at 11 evenly spaced parameters (a
/// 3 x 3 grid on a surface) when it is empty. Numbers as `eval` writes them. A wide family's
/// channels are its lanes evaluated at the parameter and joined (docs/model.md, "Lanes"): each
/// lane is blended with the same basis, so they are the channels blended exactly.
fn table(model: &Model, at: &str) -> Result<(Vec<String>, Vec<Vec<String>>), String> {
    let view = neutrospline_io::DegreeView::new(model.membership());
    let lanes = model.lanes();
    let shape = model.shape();
    let mut columns: Vec<String> = if shape.is_surface() {
        vec!["u".into(), "v".into()]
    } else {
        vec!["t".into()]
    };
    columns.extend(
        ["x", "y", "z"][..shape.dimension()]
            .iter()
            .map(|s| (*s).into()),
    );
    columns.extend(view.names().into_iter().map(String::from));
    let number = |item: &str| -> Result<f64, String> {
        match item.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(format!(
                "parameter `{}` is not a finite number",
                item.trim()
            )),
            Err(_) => Err(format!("parameter `{}` is not a number", item.trim())),
        }
    };
    let items: Vec<&str> = at.split(',').filter(|s| !s.trim().is_empty()).collect();
    let cell = |v: f64| format_number(v);
    let mut rows = Vec::new();
    match shape {
        Shape::Surface(s) => {
            let [du, dv] = s.domain();
            let params: Vec<(f64, f64)> = if items.is_empty() {
                (0..9)
                    .map(|k| {
                        (
                            uniform_parameter(k / 3, 3, du.clone()),
                            uniform_parameter(k % 3, 3, dv.clone()),
                        )
                    })
                    .collect()
            } else {
                items
                    .iter()
                    .map(|item| match item.split_once(':') {
                        Some((u, v)) => Ok((number(u)?, number(v)?)),
                        None => Err(format!(
                            "`{}` is not a pair U:V (a surface is evaluated at U:V,U:V,...)",
                            item.trim()
                        )),
                    })
                    .collect::<Result<_, _>>()?
            };
            for (u, v) in params {
                let p = s.evaluate(u, v).map_err(|e| e.to_string())?;
                let mut degrees = vec![p.degrees];
                for lane in &lanes[1..] {
                    if let Shape::Surface(other) = lane {
                        degrees.push(other.evaluate(u, v).map_err(|e| e.to_string())?.degrees);
                    }
                }
                let mut row = vec![cell(u), cell(v)];
                row.extend(p.position.iter().map(|&x| cell(x)));
                row.extend(view.values(&degrees).into_iter().map(cell));
                rows.push(row);
            }
        }
        Shape::Curve(curve) => {
            let domain = curve.domain();
            let params: Vec<f64> = if items.is_empty() {
                (0..11)
                    .map(|k| uniform_parameter(k, 11, domain.clone()))
                    .collect()
            } else {
                items.iter().map(|i| number(i)).collect::<Result<_, _>>()?
            };
            for t in params {
                let mut row = vec![cell(t)];
                let p = curve.evaluate_point(t).map_err(|e| e.to_string())?;
                let mut degrees = vec![p.degrees];
                for lane in &lanes[1..] {
                    if let Shape::Curve(other) = lane {
                        degrees.push(other.evaluate_point(t).map_err(|e| e.to_string())?.degrees);
                    }
                }
                row.extend(p.position.iter().map(|&x| cell(x)));
                row.extend(view.values(&degrees).into_iter().map(cell));
                rows.push(row);
            }
        }
    }
    Ok((columns, rows))
}

/// The family a model switched to `family` in the page gets: `family`, or for the families
/// with a parameter (`q-rung`, `t-spherical`) that parameter = 3 (the page keeps a parameter
/// the model already gives).
fn new_family(family: Family) -> Family {
    match family.parameter() {
        Some(_) => Family::with_parameter(family.name(), 3).unwrap_or(family),
        None => family,
    }
}

/// The page's description of `family`, all from the core's `Family` data (docs/model.md,
/// "Membership families" and "Lanes"), so that the page holds no knowledge of its own:
///
/// - `name`: the family's name without its parameter (the model's `membership`);
/// - `label`: the name as the membership list shows it;
/// - `parameter`: `{key, value}` of the parameter (`q` of `q-rung`, `n` of `t-spherical`) or
///   null;
/// - `lanes`: how many lanes the family rides in (1, or 2 for the interval-valued and bipolar
///   families);
/// - `channels`: `{name, min, max}` of each channel (`Family::channels`, the box of
///   `Family::channel_range`: \[0, 1\], or \[-1, 0\] for the negative bipolar degrees), the
///   keys of a control point in the model;
/// - `fields`: the degree fields of the panel, `{name, min, max, derived}`: for a family of one
///   lane the three degree slots truth, indeterminacy, falsity of its curve, `derived` for a
///   slot that is not a channel (shown as the curve holds it: the intuitionistic hesitation
///   `1 - T - F`, else 0); for a wide family its channels;
/// - `derived`: the names of the derived degrees (`Family::derived_names`);
/// - `rule`: the rule in one line (`Family::rule_text`).
fn family_json(family: Family) -> Value {
    let channels: Vec<Value> = family
        .channels()
        .iter()
        .enumerate()
        .map(|(c, name)| {
            let (min, max) = family.channel_range(c);
            json!({ "name": name, "min": min, "max": max })
        })
        .collect();
    let fields: Vec<Value> = if family.lane_count() == 1 {
        DegreeKind::ALL
            .iter()
            .map(|&kind| {
                json!({ "name": kind.name(), "min": 0.0, "max": 1.0, "derived": !family.carries(kind) })
            })
            .collect()
    } else {
        family
            .channels()
            .iter()
            .enumerate()
            .map(|(c, name)| {
                let (min, max) = family.channel_range(c);
                json!({ "name": name, "min": min, "max": max, "derived": false })
            })
            .collect()
    };
    let label = match family.parameter() {
        Some((key, value)) => {
            format!(
                "{} ({key} = {value} unless the file gives {key})",
                family.name()
            )
        }
        None => family.name().to_owned(),
    };
    json!({
        "name": family.name(),
        "label": label,
        "parameter": family.parameter().map(|(key, value)| json!({ "key": key, "value": value })),
        "lanes": family.lane_count(),
        "channels": channels,
        "fields": fields,
        "derived": family.derived_names(),
        "rule": family.rule_text(),
    })
}

/// The values of the panel's degree fields (`fields` of [`family_json`]) at every control
/// point (surfaces row by row): for a family of one lane the three degree slots its curve
/// holds (the intuitionistic indeterminacy is the hesitation `1 - T - F`, a slot the family
/// does not carry 0), for a wide family its channels.
fn point_degrees(model: &Model) -> Vec<Vec<f64>> {
    if model.membership().lane_count() == 1 {
        model
            .shape()
            .control_degrees()
            .iter()
            .map(|d| d.to_array().to_vec())
            .collect()
    } else {
        model
            .control_channels()
            .iter()
            .map(|values| values.to_vec())
            .collect()
    }
}

fn export(body: &Value) -> Result<Response, Response> {
    let model = page_model(body)?;
    let request = figure_request(body)?;
    let options = figure_options(&model, &request)?;
    let (plot, _) =
        prepare(&model, body, request.color_by).map_err(|e| Response::error(422, &e))?;
    let view = request.view(body.get("data").is_some_and(|d| !d.is_null()));
    let fail = |e: neutrospline_plot::PlotError| Response::error(422, &e.to_string());
    match body["format"].as_str() {
        Some("png") => Ok(Response::new(
            200,
            "image/png",
            render_png(&plot, view, &options).map_err(fail)?,
        )),
        Some("svg") | None => Ok(Response::new(
            200,
            "image/svg+xml; charset=utf-8",
            render_svg(&plot, view, &options).map_err(fail)?,
        )),
        Some(other) => Err(Response::error(
            400,
            &format!("format `{other}`: give \"svg\" or \"png\""),
        )),
    }
}

fn open(body: &Value) -> Result<Response, Response> {
    let name = file_label(body["name"].as_str().unwrap_or(""));
    let text = body["text"]
        .as_str()
        .ok_or_else(|| Response::error(400, "`text` must be the file's text"))?;
    let format = Format::from_path(&name)
        .map_err(|e| Response::error(422, &e.describe(Format::ACCEPTED)))?;
    let model = neutrospline_io::parse(&name, format, text.as_bytes(), &ReadOptions::default())
        .map_err(|e| refused(&e, false))?;
    Ok(with_model(
        &neutrospline_io::to_json_string(&model),
        json!({ "name": name }),
        200,
    ))
}

fn data(body: &Value) -> Result<Response, Response> {
    let membership = membership(body, Family::Neutrosophic)?;
    let table =
        data_table(body, membership)?.ok_or_else(|| Response::error(400, "no data given"))?;
    Ok(Response::json(
        200,
        json!({ "name": table.file(), "points": table.len(), "dimension": table.dimension() })
            .to_string(),
    ))
}

/// The fit's request from the page: `options` maps the canonical names of
/// [`FitRequest`](neutrospline::fit::FitRequest)'s options (those of `neutrospline fit`) to
/// values; a wrong type, an unknown name or a contradiction is a 400 with the library's
/// message, the one the command line prints.
fn fit_request(body: &Value) -> Result<FitRequest, Response> {
    if body.get("membership").is_some() {
        return Err(Response::error(
            400,
            "membership is a fit option: give it in `options`",
        ));
    }
    match body.get("options") {
        None | Some(Value::Null) => Ok(FitRequest::default()),
        Some(options) => serde_json::from_value(options.clone())
            .map_err(|e| Response::error(400, &e.to_string())),
    }
}

fn fit_data(body: &Value) -> Result<Response, Response> {
    if body.get("surface").and_then(Value::as_bool) == Some(true) {
        return fit_surface_data(body);
    }
    let request = fit_request(body)?;
    let options = request
        .validate()
        .map_err(|e| Response::error(400, &e.to_string()))?;
    let membership = request.membership;
    let table = data_table(&body["data"], membership)?
        .ok_or_else(|| Response::error(400, "no data given"))?;
    request
        .check_data_weights(table.file(), table.weights().is_some())
        .map_err(|e| Response::error(422, &e.to_string()))?;
    let fitted = table
        .fit(&options)
        .map_err(|e| Response::error(422, &e.to_string()))?;
    let (model, report) = (Model::new(fitted.curve), fitted.report);
    let model = model
        .with_family(membership, fitted.second_lane)
        .map_err(|e| Response::error(422, &e.to_string()))?
        .with_description(format!(
            "Fitted to {} ({} points) by neutrospline fit",
            table.file(),
            table.len()
        ));
    let channels = |values: &[(&'static str, f64)]| -> Value {
        Value::Object(
            values
                .iter()
                .map(|(n, v)| ((*n).to_owned(), json!(v)))
                .collect(),
        )
    };
    let report = json!({
        "control_points": report.control_points,
        "degree": report.degree,
        "max_error": channels(&report.max_error),
        "rms_error": channels(&report.rms_error),
        "worst_index": report.worst_index,
        "worst_distance": report.worst_distance,
        "schoenberg_whitney": report.schoenberg_whitney,
        "tolerance": report.tolerance,
        "tolerance_met": report.tolerance_met,
    });
    Ok(with_model(
        &neutrospline_io::to_json_string(&model),
        json!({ "report": report }),
        200,
    ))
}

/// `POST /api/fit` with `surface: true`: `neutrospline fit --surface`. `options` holds the
/// options of [`SurfaceFitRequest`](neutrospline::fit::SurfaceFitRequest) by their canonical
/// names (`degree` "P,Q", `control-points` "M,N", `grid` "ROWSxCOLS", `smoothing`, ...); the
/// answer's `report` is the command line's `--report json` object, with `warning` when the
/// system is nearly singular.
fn fit_surface_data(body: &Value) -> Result<Response, Response> {
    if body.get("membership").is_some() {
        return Err(Response::error(
            400,
            "membership is a fit option: give it in `options`",
        ));
    }
    let request: SurfaceFitRequest = match body.get("options") {
        None | Some(Value::Null) => SurfaceFitRequest::default(),
        Some(options) => neutrospline::options::deserialize(options.clone())
            .map_err(|e: serde_json::Error| Response::error(400, &e.to_string()))?,
    };
    let options = request
        .validate()
        .map_err(|e| Response::error(400, &e.to_string()))?;
    let membership = request.membership;
    let table = data_table(&body["data"], membership)?
        .ok_or_else(|| Response::error(400, "no data given"))?;
    request
        .weights
        .check_data(table.file(), table.weights().is_some())
        .map_err(|e| Response::error(422, &e.to_string()))?;
    let fitted = table
        .fit_surface(request.grid, &options)
        .map_err(|e| Response::error(422, &e.to_string()))?;
    let shape = match request.grid {
        Some([rows, cols]) => format!("a grid of {rows} x {cols} points"),
        None => format!("{} scattered points", table.len()),
    };
    let model = Model::new(fitted.surface)
        .with_family(membership, fitted.second_lane.clone())
        .map_err(|e| Response::error(422, &e.to_string()))?
        .with_description(format!(
            "Fitted to {} ({shape}) by neutrospline fit --surface",
            table.file()
        ));
    let mut report: Value =
        serde_json::from_str(&neutrospline_io::surface_fit_report_json(&fitted.report))
            .map_err(|e| Response::error(500, &e.to_string()))?;
    report["warning"] = json!(neutrospline_io::surface_fit_warning(
        table.file(),
        &fitted.report
    ));
    Ok(with_model(
        &neutrospline_io::to_json_string(&model),
        json!({ "report": report }),
        200,
    ))
}
