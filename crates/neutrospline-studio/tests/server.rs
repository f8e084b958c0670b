//! The studio's server over real sockets: the guards (Host, Origin, body limit, methods,
//! paths), the JSON API against figures drawn directly with the plot crate and the reader's
//! exact messages, and saving (only the started file, atomically); HTTP itself (HEAD,
//! `Expect: 100-continue`, the Host syntax) and the deadlines and connection limit, measured.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::time::{Duration, Instant};

use neutrospline::{ControlPolygon, Evaluate};
use neutrospline_io::{Format, Model, ReadOptions};
use neutrospline_plot::{render_png, render_svg, PlotModel, PlotOptions, View};
use neutrospline_studio::{Server, ServerConfig, Studio};
use serde_json::{json, Value};

const EXAMPLE1_JSON: &str = include_str!("../../../examples/example1.json");
const BSPLINE_TOML: &str = include_str!("../../../examples/bspline.toml");

/// One request on its own connection: (status, head, body).
fn http(port: u16, raw: &[u8]) -> (u16, String, Vec<u8>) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    // A server that never answers fails the test instead of hanging it.
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    s.write_all(raw).unwrap();
    let mut answer = Vec::new();
    let _ = s.read_to_end(&mut answer);
    let split = answer
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("a complete head");
    let head = String::from_utf8(answer[..split].to_vec()).unwrap();
    let status = head[9..12].parse().unwrap();
    (status, head, answer[split + 4..].to_vec())
}

fn get(port: u16, path: &str, headers: &str) -> (u16, String, Vec<u8>) {
    let raw = format!("GET {path} HTTP/1.1\r\n{headers}Connection: close\r\n\r\n");
    http(port, raw.as_bytes())
}

fn post(port: u16, path: &str, body: &Value) -> (u16, Value, Vec<u8>) {
    let body = body.to_string();
    let raw = format!(
        "POST {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: http://127.0.0.1:{port}\r\n\
         Content-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    let (status, _, bytes) = http(port, raw.as_bytes());
    let value = serde_json::from_slice(&bytes).unwrap_or(Value::Null);
    (status, value, bytes)
}

fn host(port: u16) -> String {
    format!("Host: 127.0.0.1:{port}\r\n")
}

fn example1() -> Model {
    neutrospline_io::parse(
        "example1.json",
        Format::Json,
        EXAMPLE1_JSON.as_bytes(),
        &ReadOptions::default(),
    )
    .unwrap()
}

fn example_server() -> u16 {
    Server::bind(0, Studio::example()).unwrap().spawn()
}

/// Example 1 with one value replaced, as the page sends it.
fn example_with(edit: impl FnOnce(&mut Value)) -> String {
    let mut v: Value = serde_json::from_str(EXAMPLE1_JSON).unwrap();
    edit(&mut v);
    v.to_string()
}

#[test]
fn server_refuses_foreign_host_and_origin() {
    let port = example_server();
    assert_eq!(get(port, "/", &host(port)).0, 200);
    assert_eq!(
        get(port, "/", &format!("Host: localhost:{port}\r\n")).0,
        200
    );
    let (status, _, body) = get(port, "/", &format!("Host: attacker.example:{port}\r\n"));
    assert_eq!(status, 403);
    assert_eq!(
        serde_json::from_slice::<Value>(&body).unwrap()["error"]["message"],
        format!("refused: Host `attacker.example:{port}` is not this studio")
    );
    let (status, _, _) = get(
        port,
        "/api/state",
        &format!("{}Origin: http://attacker.example\r\n", host(port)),
    );
    assert_eq!(status, 403);
    // No Host at all is malformed HTTP/1.1 (RFC 9112 3.2).
    assert_eq!(get(port, "/", "").0, 400, "no Host header");
}

#[test]
fn server_limits_bodies_methods_and_paths() {
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_max_body(1000)
        .spawn();
    let raw = format!(
        "POST /api/render HTTP/1.1\r\n{}Content-Length: 1001\r\n\r\n",
        host(port)
    );
    let (status, _, body) = http(port, raw.as_bytes());
    assert_eq!(status, 413);
    assert!(String::from_utf8_lossy(&body).contains("larger than the limit of 1000 bytes"));
    assert_eq!(get(port, "/api/render", &host(port)).0, 405);
    assert_eq!(get(port, "/../../etc/passwd", &host(port)).0, 404);
    assert_eq!(get(port, "/assets/studio.js", &host(port)).0, 404);
    let (status, head, body) = get(port, "/studio.js", &host(port));
    assert_eq!(status, 200);
    assert!(head.contains("Content-Type: text/javascript"));
    assert!(String::from_utf8_lossy(&body).contains("window.studio"));
    let (status, _, body) = get(port, "/paint.js", &host(port));
    assert_eq!(status, 200);
    assert!(String::from_utf8_lossy(&body).contains("function paintDisplayList"));
    // Garbage answers 400 and the server keeps serving.
    assert_eq!(http(port, b"NONSENSE\r\n\r\n").0, 400);
    assert_eq!(get(port, "/", &host(port)).0, 200);
}

#[test]
fn render_draws_what_the_plot_crate_draws() {
    let port = example_server();
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": EXAMPLE1_JSON, "views": ["plane", "all"] }),
    );
    assert_eq!(status, 200, "{answer}");
    // Drawn here without the studio's code: the names and the caption of the file.
    let model = example1();
    let Some(neutrospline::DynCurve::Planar(curve)) = model.shape().curve() else {
        panic!("a plane curve")
    };
    let plot = PlotModel::from_any(curve)
        .unwrap()
        .with_names(["C0", "C1", "C2", "C3"])
        .unwrap();
    let options = PlotOptions::new().with_caption(model.description().unwrap());
    for view in [View::Plane, View::All] {
        assert_eq!(
            answer["figures"][view.name()].as_str().unwrap(),
            render_svg(&plot, view, &options).unwrap(),
            "{view}"
        );
    }
    assert_eq!(answer["figures"].as_object().unwrap().len(), 2);
    // The views this model's family cannot draw, with the plot crate's reason: a neutrosophic
    // model derives no degrees.
    let refused = answer["refused"].as_object().unwrap();
    assert_eq!(refused.keys().collect::<Vec<_>>(), ["derived"]);
    assert_eq!(
        refused["derived"],
        plot.check_view(View::Derived).unwrap_err().to_string()
    );
    assert!(refused["derived"]
        .as_str()
        .unwrap()
        .starts_with("the view `derived` does not draw neutrosophic models"));
    // The model comes back as the JSON writer writes it.
    assert_eq!(
        answer["model"],
        serde_json::from_str::<Value>(&neutrospline_io::to_json_string(&model)).unwrap()
    );
    // The handles sit on the control points, at one scale on x and y.
    let frame: Vec<f64> = serde_json::from_value(answer["handles"]["frame"].clone()).unwrap();
    let pixels: Vec<[f64; 2]> =
        serde_json::from_value(answer["handles"]["pixels"].clone()).unwrap();
    for (p, px) in curve.control_points().iter().zip(&pixels) {
        assert!((frame[2] + frame[0] * p.position[0] - px[0]).abs() < 0.01);
        assert!((frame[3] + frame[1] * p.position[1] - px[1]).abs() < 0.01);
    }
    // The table: eval's columns and numbers, at 11 evenly spaced parameters.
    let table = &answer["table"];
    assert_eq!(
        table["columns"],
        json!(["t", "x", "y", "truth", "indeterminacy", "falsity"])
    );
    assert_eq!(
        table["rows"][5],
        json!(["0.5", "4.625", "4", "0.625", "0.2", "0.17500000000000002"])
    );
    let at_03 = curve.evaluate(0.3).unwrap();
    let (_, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": EXAMPLE1_JSON, "views": [], "at": "0.3, 1" }),
    );
    assert_eq!(
        answer["table"]["rows"][0][1].as_str().unwrap(),
        neutrospline_io::format_number(at_03.position[0])
    );
    assert_eq!(answer["table"]["rows"].as_array().unwrap().len(), 2);
    let (_, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": EXAMPLE1_JSON, "views": [], "at": "0.5, 2" }),
    );
    assert_eq!(
        answer["table"]["error"],
        "parameter t = 2 is outside the domain [0, 1]"
    );
}

#[test]
fn render_gives_display_lists_for_drag_frames() {
    let port = example_server();
    let views = [
        "plane",
        "controls",
        "truth",
        "indeterminacy",
        "falsity",
        "all",
    ];
    let ask = |encoding: &str| {
        let (status, answer, _) = post(
            port,
            "/api/render",
            &json!({ "model": EXAMPLE1_JSON, "views": views, "encoding": encoding, "figure": { "samples": 40 } }),
        );
        assert_eq!(status, 200, "{answer}");
        answer
    };
    let (svg, lists) = (ask("svg"), ask("display-list"));
    assert!(svg.get("drawings").is_none() && lists.get("figures").is_none());
    // The display lists of the figures the SVG answer has, drawn here with the plot crate.
    let model = example1();
    let plot = PlotModel::from_model(&model).unwrap();
    let options = PlotOptions::new()
        .with_caption(model.description().unwrap())
        .with_samples(40);
    for view in views {
        let drawing =
            neutrospline_plot::render_drawing(&plot, view.parse().unwrap(), &options).unwrap();
        let expected: Value = serde_json::from_str(&drawing.to_display_list()).unwrap();
        assert_eq!(lists["drawings"][view], expected, "{view}");
        assert_eq!(
            svg["figures"][view].as_str().unwrap(),
            drawing.to_svg(),
            "{view}"
        );
    }
    // The same handles, the same model and table, whatever the encoding.
    for key in ["handles", "model", "table", "info", "errors"] {
        assert_eq!(svg[key], lists[key], "{key}");
    }
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": EXAMPLE1_JSON, "views": ["plane"], "encoding": "png" }),
    );
    assert_eq!(status, 400);
    assert_eq!(
        answer["error"]["message"],
        "encoding `png`: give \"svg\" or \"display-list\""
    );
}

#[test]
fn render_refuses_invalid_models_with_the_readers_message() {
    let port = example_server();
    let cases = [
        (
            example_with(|v| v["control_points"][1]["truth"] = json!(1.2)),
            "control_points[1]: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])",
        ),
        (
            example_with(|v| {
                v["kind"] = json!("bspline");
                v["degree"] = json!(2);
                v["knots"] = json!([0, 0, 0, 0.7, 0.5, 1, 1]);
            }),
            "knots: knot 4 = 0.5 is less than knot 3 = 0.7 (knots must be non-decreasing)",
        ),
        (
            example_with(|v| {
                v["membership"] = json!("intuitionistic");
                for p in v["control_points"].as_array_mut().unwrap() {
                    p.as_object_mut().unwrap().remove("indeterminacy");
                }
                v["control_points"][1]["falsity"] = json!(0.5);
            }),
            "control_points[1]: truth + falsity = 0.8 + 0.5 = 1.3 exceeds 1 (intuitionistic rule: truth + falsity <= 1)",
        ),
    ];
    for (model, message) in cases {
        let (status, answer, _) = post(
            port,
            "/api/render",
            &json!({ "model": model, "views": ["plane"] }),
        );
        assert_eq!(status, 422, "{message}");
        assert_eq!(answer["error"]["message"], message);
    }
    // Not JSON at all, and no model: 400, and the server goes on.
    let (status, _, _) = post(port, "/api/render", &json!({ "views": [] }));
    assert_eq!(status, 400);
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": "{ not json", "views": [] }),
    );
    assert_eq!(status, 422);
    assert_eq!(answer["error"]["line"], 1, "{answer}");
    assert_eq!(
        post(port, "/api/render", &json!({ "model": EXAMPLE1_JSON })).0,
        200
    );
}

#[test]
fn open_reads_the_text_given_never_a_path() {
    let port = example_server();
    let (status, answer, _) = post(
        port,
        "/api/open",
        &json!({ "name": "/some/dir/bspline.toml", "text": BSPLINE_TOML }),
    );
    assert_eq!(status, 200);
    assert_eq!(answer["name"], "bspline.toml");
    assert_eq!(answer["model"]["knots"][4], 0.2);
    // A path to a real file is only a name: its text is what the page sent.
    let (status, answer, _) = post(
        port,
        "/api/open",
        &json!({ "name": "/etc/passwd", "text": "" }),
    );
    assert_eq!(status, 422);
    assert_eq!(
        answer["error"]["message"],
        "passwd: the file name has no extension (accepted: .csv, .toml, .json)"
    );
    let broken = BSPLINE_TOML.replace("degree = 3", "degree = -3");
    let (status, answer, _) = post(
        port,
        "/api/open",
        &json!({ "name": "broken.toml", "text": broken }),
    );
    assert_eq!(status, 422);
    let message = answer["error"]["message"].as_str().unwrap();
    assert_eq!(
        message,
        "broken.toml:9: degree: expected a non-negative integer, found -3"
    );
}

#[test]
fn export_gives_the_figure_bytes() {
    let port = example_server();
    let model = example1();
    let plot = neutrospline_plot::PlotModel::from_model(&model).unwrap();
    let options = PlotOptions::new().with_caption(model.description().unwrap());
    let (status, _, svg) = post(
        port,
        "/api/export",
        &json!({ "model": EXAMPLE1_JSON, "format": "svg", "figure": { "view": "truth" } }),
    );
    assert_eq!(status, 200);
    assert_eq!(
        String::from_utf8(svg).unwrap(),
        render_svg(&plot, View::Truth, &options).unwrap()
    );
    let (status, _, png) = post(
        port,
        "/api/export",
        &json!({ "model": EXAMPLE1_JSON, "format": "png", "figure": { "view": "controls", "azimuth": 10, "elevation": 40 } }),
    );
    assert_eq!(status, 200);
    assert_eq!(
        png,
        render_png(&plot, View::Controls, &options.with_camera(10.0, 40.0)).unwrap()
    );
}

/// The figure's options are the plot crate's `FigureRequest`, under `figure`: a value out of
/// range gets `neutrospline plot`'s message, a misspelled or misplaced option is refused, never
/// drawn with a default in its place.
#[test]
fn figure_options_are_refused_with_the_librarys_messages() {
    let port = example_server();
    for (body, message) in [
        (
            json!({ "model": EXAMPLE1_JSON, "figure": { "view": "truth", "elevation": 95 } }),
            "camera elevation = 95 degrees is not supported (must be between -90 and 90)"
                .to_owned(),
        ),
        (
            json!({ "model": EXAMPLE1_JSON, "figure": { "azimuth": "30" } }),
            "azimuth = \"30\": expected a number".to_owned(),
        ),
        (
            json!({ "model": EXAMPLE1_JSON, "figure": { "colorBy": "truth" } }),
            "unknown option \"colorBy\" (the options are view, width, height, size, dpi, style, \
             no-title, no-caption, title, caption, azimuth, elevation, samples, alpha, color-by)"
                .to_owned(),
        ),
        (
            json!({ "model": EXAMPLE1_JSON, "azimuth": 30 }),
            "azimuth is a figure option: give it in `figure`".to_owned(),
        ),
    ] {
        let (status, answer, _) = post(port, "/api/export", &body);
        assert_eq!(
            (status, answer["error"]["message"].as_str().unwrap_or("")),
            (400, message.as_str()),
            "{body}"
        );
    }
}

/// A membership rule that is not a string is refused, not read as the default.
#[test]
fn a_membership_of_another_type_is_refused() {
    let port = example_server();
    let body = json!({ "name": "d.csv", "text": "x,y,T\n0,0,1\n", "membership": 3 });
    let (status, answer, _) = post(port, "/api/data", &body);
    assert_eq!(
        (status, answer["error"]["message"].as_str().unwrap_or("")),
        (
            400,
            "membership = 3: expected a family name as a string, one of: neutrosophic, \
             intuitionistic, fuzzy, pythagorean, fermatean, q-rung:Q, picture, spherical, \
             t-spherical:N, interval-neutrosophic, interval-intuitionistic, interval-type2, \
             bipolar-neutrosophic (Q and N integers >= 1)"
        )
    );
}

fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn save_writes_only_the_started_file_atomically() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("curve.toml");
    std::fs::write(&file, BSPLINE_TOML).unwrap();
    let model = neutrospline_io::load(&file, &ReadOptions::default()).unwrap();
    let port = Server::bind(0, Studio::with_file(model, &file))
        .unwrap()
        .spawn();
    let edited: Value = {
        let (_, state, _) = post(
            port,
            "/api/render",
            &json!({ "model": neutrospline_io::to_json_string(&neutrospline_io::load(&file, &ReadOptions::default()).unwrap()) }),
        );
        let mut m = state["model"].clone();
        m["control_points"][3]["y"] = json!(1.5);
        m
    };
    let other = dir.path().join("other.toml");
    let (status, answer, _) = post(
        port,
        "/api/save",
        &json!({ "model": edited.to_string(), "path": other.display().to_string(), "file": other.display().to_string() }),
    );
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["saved"], file.display().to_string());
    let saved = neutrospline_io::load(&file, &ReadOptions::default()).unwrap();
    let expected = neutrospline_io::parse(
        "edited.json",
        Format::Json,
        edited.to_string().as_bytes(),
        &ReadOptions::default(),
    )
    .unwrap();
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        neutrospline_io::to_toml_string(&expected)
    );
    assert_eq!(saved, expected);
    // Nothing else was written, no temporary file left behind.
    assert_eq!(listing(dir.path()), ["curve.toml"]);
    // The state now holds the saved model (a reloaded page opens it).
    let (_, _, body) = get(port, "/api/state", &host(port));
    let state: Value = serde_json::from_slice(&body).unwrap();
    assert_eq!(state["model"]["control_points"][3]["y"], 1.5);
    assert_eq!(state["canSave"], true);
    // A refused model writes nothing.
    let bad = edited.to_string().replace("\"truth\":0.9", "\"truth\":9");
    let before = std::fs::read(&file).unwrap();
    let (status, _, _) = post(port, "/api/save", &json!({ "model": bad }));
    assert_eq!(status, 422);
    assert_eq!(std::fs::read(&file).unwrap(), before);
}

#[test]
fn save_errors_leave_the_server_running() {
    let dir = tempfile::tempdir().unwrap();
    let gone = dir.path().join("gone");
    std::fs::create_dir(&gone).unwrap();
    let file = gone.join("model.json");
    let port = Server::bind(0, Studio::with_file(example1(), &file))
        .unwrap()
        .spawn();
    std::fs::remove_dir(&gone).unwrap();
    let (status, answer, _) = post(port, "/api/save", &json!({ "model": EXAMPLE1_JSON }));
    assert_eq!(status, 500);
    let message = answer["error"]["message"].as_str().unwrap();
    assert!(
        message.starts_with(&file.display().to_string()),
        "{message}"
    );
    assert_eq!(get(port, "/api/state", &host(port)).0, 200);
    // Without a file there is nothing to save to.
    let port = example_server();
    let (status, _, _) = post(port, "/api/save", &json!({ "model": EXAMPLE1_JSON }));
    assert_eq!(status, 409);
}

#[test]
fn data_and_fit_use_the_readers_and_the_fit() {
    let port = example_server();
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data/survey.csv"),
    )
    .unwrap();
    let data = json!({ "name": "survey.csv", "text": text });
    let (status, answer, _) = post(
        port,
        "/api/data",
        &json!({ "name": "survey.csv", "text": text }),
    );
    assert_eq!(status, 200);
    assert_eq!(answer["points"], 80);
    let (status, answer, _) = post(
        port,
        "/api/fit",
        &json!({ "data": data, "options": { "control-points": 12, "weights": "score" } }),
    );
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["report"]["control_points"], 12);
    assert_eq!(
        answer["model"]["control_points"].as_array().unwrap().len(),
        12
    );
    assert_eq!(
        answer["model"]["description"],
        "Fitted to survey.csv (80 points) by neutrospline fit"
    );
    // The fitted model renders with its data in the data view.
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": answer["model"].to_string(), "views": ["data"], "data": data }),
    );
    assert_eq!(status, 200);
    assert!(answer["figures"]["data"]
        .as_str()
        .unwrap()
        .contains("class=\"residual\""));
    let bad =
        json!({ "name": "bad.csv", "text": "x,y,truth,indeterminacy,falsity\n1,2,1.5,0,0\n" });
    let (status, answer, _) = post(port, "/api/data", &bad);
    assert_eq!(status, 422);
    assert_eq!(
        answer["error"]["message"],
        "bad.csv:2: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"
    );
}

/// Issue 25: a dropped CSV of 3-D data fitted as a surface, with `neutrospline fit --surface`'s
/// options and report (the command line's JSON report object), drawn in the data view.
#[test]
fn fit_fits_a_surface_with_the_command_lines_options() {
    let port = example_server();
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data/hill_grid.csv"),
    )
    .unwrap();
    let data = json!({ "name": "hill_grid.csv", "text": text });
    let options = json!({ "grid": "12x10", "control-points": [8, 6], "degree": [3] });
    let (status, answer, _) = post(
        port,
        "/api/fit",
        &json!({ "data": data, "options": options, "surface": true }),
    );
    assert_eq!(status, 200, "{answer}");
    let report = &answer["report"];
    assert_eq!(report["control_points"], json!([8, 6]));
    assert_eq!(report["degrees"], json!([3, 3]));
    assert_eq!(report["two_pass"], true);
    assert_eq!(report["warning"], Value::Null);
    // The z residuals of docs/fitting.md's hill report.
    let max_z = report["max_error"]["z"].as_f64().unwrap();
    assert!((max_z - 0.0650216358887433).abs() < 1e-12, "{max_z}");
    assert_eq!(answer["model"]["kind"], "bspline-surface");
    assert_eq!(
        answer["model"]["description"],
        "Fitted to hill_grid.csv (a grid of 12 x 10 points) by neutrospline fit --surface"
    );
    let (status, drawn, _) = post(
        port,
        "/api/render",
        &json!({ "model": answer["model"].to_string(), "views": ["data"], "data": data }),
    );
    assert_eq!(status, 200, "{drawn}");
    let svg = drawn["figures"]["data"].as_str().unwrap();
    assert_eq!(svg.matches("class=\"residual\"").count(), 120);
    // Refusals carry the library's messages: a curve's option, a grid that does not hold
    // the points.
    for (options, status, message) in [
        (
            json!({ "closed": true }),
            400,
            "unknown option \"closed\" (the options are degree, interpolate, control-points",
        ),
        (
            json!({ "grid": "5x5" }),
            422,
            "hill_grid.csv: a grid of 5 x 5 points does not hold 120 points",
        ),
    ] {
        let (got, answer, _) = post(
            port,
            "/api/fit",
            &json!({ "data": data, "options": options, "surface": true }),
        );
        assert_eq!(got, status, "{answer}");
        let text = answer["error"]["message"].as_str().unwrap();
        assert!(text.contains(message), "{text}");
    }
}

/// Issue 27: data of an interval-valued family (two lanes) fitted in the studio as on the
/// command line: every channel under the whole rule, the model with both lanes, drawn in the
/// truth view as a band.
#[test]
fn fit_fits_interval_type2_data_in_two_lanes() {
    let port = example_server();
    let mut text = String::from("x,y,truth_lower,truth_upper\n");
    for k in 0..24 {
        let t = f64::from(k) / 23.0;
        // Steps between a collapsed interval at 1 and a wide one from 0: the free fit of the
        // lanes rings past [0, 1] and crosses.
        let (lower, upper) = if (k / 4) % 2 == 0 {
            (1.0, 1.0)
        } else {
            (0.0, 0.5)
        };
        text.push_str(&format!(
            "{},{},{lower},{upper}\n",
            3.0 * t,
            (2.0 * t).sin()
        ));
    }
    let data = json!({ "name": "t2.csv", "text": text });
    let (status, answer, _) = post(
        port,
        "/api/fit",
        &json!({
            "data": data,
            "options": { "control-points": 9, "membership": "interval-type2" }
        }),
    );
    assert_eq!(status, 200, "{answer}");
    let model = &answer["model"];
    assert_eq!(model["membership"], "interval-type2");
    let points = model["control_points"].as_array().unwrap();
    assert_eq!(points.len(), 9);
    for (i, point) in points.iter().enumerate() {
        let (lower, upper) = (
            point["truth_lower"].as_f64().unwrap(),
            point["truth_upper"].as_f64().unwrap(),
        );
        assert!(
            (0.0..=upper).contains(&lower) && upper <= 1.0,
            "control point {i}: {lower} {upper}"
        );
    }
    let max = &answer["report"]["max_error"];
    assert!(
        max["truth_lower"].is_number() && max["truth_upper"].is_number(),
        "{max}"
    );
    assert!(max.get("truth").is_none(), "{max}");
    let (status, drawn, _) = post(
        port,
        "/api/render",
        &json!({ "model": model.to_string(), "views": ["truth"] }),
    );
    assert_eq!(status, 200, "{drawn}");
    assert!(drawn["figures"]["truth"].as_str().unwrap().contains("<svg"));
}

const STUDIO_CSS: &str = include_str!("../src/assets/studio.css");

/// Reads one answer of a kept-alive connection: (head, body), by its `Content-Length`
/// (`head_only`: a HEAD answer, which has none of the body).
fn read_answer(s: &mut TcpStream, head_only: bool) -> (String, Vec<u8>) {
    let mut bytes = Vec::new();
    let mut byte = [0];
    while !bytes.ends_with(b"\r\n\r\n") {
        assert_eq!(
            s.read(&mut byte).unwrap(),
            1,
            "the head ends early: {bytes:?}"
        );
        bytes.push(byte[0]);
    }
    let head = String::from_utf8(bytes).unwrap();
    let length: usize = head
        .lines()
        .find_map(|l| l.strip_prefix("Content-Length: "))
        .unwrap()
        .parse()
        .unwrap();
    let mut body = vec![0; if head_only { 0 } else { length }];
    s.read_exact(&mut body).unwrap();
    (head, body)
}

fn content_length(head: &str) -> usize {
    head.lines()
        .find_map(|l| l.strip_prefix("Content-Length: "))
        .unwrap()
        .parse()
        .unwrap()
}

fn first_line(answer: &[u8]) -> String {
    let text = String::from_utf8_lossy(answer);
    text.split("\r\n").next().unwrap().to_owned()
}

#[test]
fn head_has_the_get_head_and_no_body() {
    let port = example_server();
    let (status, get_head, page) = get(port, "/", &host(port));
    assert_eq!(status, 200);
    // HEAD then GET on one connection: were HEAD to send a body, the next answer would start
    // inside it.
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let raw = format!(
        "HEAD / HTTP/1.1\r\n{h}\r\nGET /studio.css HTTP/1.1\r\n{h}Connection: close\r\n\r\n",
        h = host(port)
    );
    s.write_all(raw.as_bytes()).unwrap();
    let mut answer = Vec::new();
    s.read_to_end(&mut answer).unwrap();
    let text = String::from_utf8(answer).unwrap();
    let (head, rest) = text.split_once("\r\n\r\n").unwrap();
    assert_eq!(Some(head), get_head.strip_suffix("\r\nConnection: close"));
    assert_eq!(content_length(head), page.len());
    let (css_head, css) = rest.split_once("\r\n\r\n").unwrap();
    assert!(css_head.starts_with("HTTP/1.1 200 OK\r\n"), "{css_head}");
    assert_eq!(css, STUDIO_CSS);
}

#[test]
fn expect_100_continue_is_answered_before_the_body() {
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_max_body(100_000)
        .spawn();
    let body = json!({ "model": EXAMPLE1_JSON, "views": ["plane"] }).to_string();
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    let asked = Instant::now();
    let raw = format!(
        "POST /api/render HTTP/1.1\r\n{}Content-Length: {}\r\nExpect: 100-continue\r\n\r\n",
        host(port),
        body.len()
    );
    s.write_all(raw.as_bytes()).unwrap();
    let mut interim = [0; 25];
    s.read_exact(&mut interim).unwrap();
    assert_eq!(&interim, b"HTTP/1.1 100 Continue\r\n\r\n");
    // curl waits 1 s for it before sending the body anyway.
    assert!(
        asked.elapsed() < Duration::from_millis(900),
        "{:?}",
        asked.elapsed()
    );
    s.write_all(body.as_bytes()).unwrap();
    let (head, answer) = read_answer(&mut s, false);
    assert!(head.starts_with("HTTP/1.1 200 OK\r\n"), "{head}");
    let answer: Value = serde_json::from_slice(&answer).unwrap();
    assert!(answer["figures"]["plane"]
        .as_str()
        .unwrap()
        .contains("<svg"));

    // Refused heads get their final status, never 100, and the body is not awaited.
    let cases = [
        (
            format!("{}Content-Length: 100001\r\n", host(port)),
            "HTTP/1.1 413 Payload Too Large",
        ),
        (
            format!(
                "{}Origin: http://attacker.example\r\nContent-Length: 10\r\n",
                host(port)
            ),
            "HTTP/1.1 403 Forbidden",
        ),
        (
            format!("Host: attacker.example:{port}\r\nContent-Length: 10\r\n"),
            "HTTP/1.1 403 Forbidden",
        ),
    ];
    for (headers, status) in cases {
        let raw = format!("POST /api/render HTTP/1.1\r\n{headers}Expect: 100-continue\r\n\r\n");
        let started = Instant::now();
        let (_, head, _) = http(port, raw.as_bytes());
        assert_eq!(head.lines().next().unwrap(), status, "{headers}");
        assert!(started.elapsed() < Duration::from_secs(2), "{headers}");
    }
    let raw = format!(
        "POST /api/render HTTP/1.1\r\n{}Expect: 200-ok\r\n\r\n",
        host(port)
    );
    assert_eq!(http(port, raw.as_bytes()).0, 417);
}

#[test]
fn host_must_be_one_strict_header() {
    let port = example_server();
    let cases = [
        format!("Host : 127.0.0.1:{port}\r\n"),
        format!("Host\t: 127.0.0.1:{port}\r\n"),
        format!("Host: 127.0.0.1:{port}\r\nHost: 127.0.0.1:{port}\r\n"),
        format!("Host: 127.0.0.1:{port}\r\nhost: attacker.example\r\n"),
        format!("Host: 127.0.0.1:{port} attacker.example\r\n"),
        format!("Host: attacker.example@127.0.0.1:{port}\r\n"),
        format!("Host: 127.0.0.1:{port}/\r\n"),
        format!("Host: 127.0.0.1:{port}\r\n folded\r\n"),
        "Host:\r\n".to_owned(),
        String::new(),
    ];
    for headers in cases {
        let (_, head, body) = get(port, "/", &headers);
        assert_eq!(
            head.lines().next().unwrap(),
            "HTTP/1.1 400 Bad Request",
            "{headers:?}"
        );
        assert!(!String::from_utf8_lossy(&body).contains("<html"));
    }
    let (_, _, body) = get(port, "/", &format!("Host : 127.0.0.1:{port}\r\n"));
    assert_eq!(
        serde_json::from_slice::<Value>(&body).unwrap()["error"]["message"],
        "header `Host`: whitespace between the name and the colon (RFC 9112 5.1)"
    );
    // Well-formed but not this server: 403; this server: 200.
    assert_eq!(get(port, "/", "Host: 127.0.0.1\r\n").0, 403);
    assert_eq!(
        get(port, "/", &format!("Host: 127.0.0.1:0{port}\r\n")).0,
        403
    );
    assert_eq!(get(port, "/", &format!("Host:127.0.0.1:{port}\r\n")).0, 200);
    assert_eq!(
        get(port, "/", &format!("host: LOCALHOST:{port}\r\n")).0,
        200
    );
}

fn short_deadlines() -> ServerConfig {
    ServerConfig {
        head_timeout: Duration::from_millis(600),
        idle_timeout: Duration::from_millis(400),
        body_timeout: Duration::from_millis(500),
        body_rate: 1 << 30,
        ..ServerConfig::default()
    }
}

/// Sends `prefix`, then one byte of `trickle` every 50 ms (cycling) until the server closes
/// or 20 s pass; returns when the connection was closed and the bytes the server sent.
fn slow_client(port: u16, prefix: String, trickle: &'static [u8]) -> (Instant, Vec<u8>) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.write_all(prefix.as_bytes()).unwrap();
    let mut writer = s.try_clone().unwrap();
    let sender = std::thread::spawn(move || {
        let started = Instant::now();
        for &byte in trickle.iter().cycle() {
            if started.elapsed() > Duration::from_secs(20) || writer.write_all(&[byte]).is_err() {
                return;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    });
    s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
    let mut answer = Vec::new();
    let _ = s.read_to_end(&mut answer);
    let closed = Instant::now();
    drop(s);
    sender.join().unwrap();
    (closed, answer)
}

#[test]
fn a_slow_head_is_dropped_at_its_deadline_while_others_are_served() {
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_config(ServerConfig {
            // Long enough for the other client to be served under load.
            head_timeout: Duration::from_millis(1500),
            ..short_deadlines()
        })
        .spawn();
    let started = Instant::now();
    // A header byte every 50 ms: each read is quick, the head never ends.
    let loris = std::thread::spawn(move || {
        slow_client(
            port,
            format!("GET / HTTP/1.1\r\n{}X-Slow: ", host(port)),
            b"abcdefgh",
        )
    });
    // Meanwhile another client is served at once.
    std::thread::sleep(Duration::from_millis(100));
    let (status, _, _) = get(port, "/api/state", &host(port));
    let served = Instant::now();
    assert_eq!(status, 200);
    let (closed, answer) = loris.join().unwrap();
    assert_eq!(first_line(&answer), "HTTP/1.1 408 Request Timeout");
    let held = closed - started;
    assert!(
        held >= Duration::from_millis(1450) && held < Duration::from_secs(5),
        "{held:?}"
    );
    assert!(served < closed, "the other client waited for the slow one");
}

#[test]
fn a_slow_body_is_dropped_at_its_deadline() {
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_config(short_deadlines())
        .spawn();
    let started = Instant::now();
    let (closed, answer) = slow_client(
        port,
        format!(
            "POST /api/render HTTP/1.1\r\n{}Content-Length: 100000\r\n\r\n{{",
            host(port)
        ),
        b" ",
    );
    assert_eq!(first_line(&answer), "HTTP/1.1 408 Request Timeout");
    let held = closed - started;
    // The body's deadline: 500 ms plus 100 kB at 1 GiB/s.
    assert!(
        held >= Duration::from_millis(450) && held < Duration::from_secs(5),
        "{held:?}"
    );
}

#[test]
fn idle_and_silent_connections_are_closed_at_their_deadlines() {
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_config(short_deadlines())
        .spawn();
    // Kept alive after an answer: closed after the idle timeout, without a byte.
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    s.write_all(format!("GET /api/state HTTP/1.1\r\n{}\r\n", host(port)).as_bytes())
        .unwrap();
    let (head, _) = read_answer(&mut s, false);
    assert!(head.starts_with("HTTP/1.1 200 OK\r\n"));
    let answered = Instant::now();
    let mut rest = Vec::new();
    s.read_to_end(&mut rest).unwrap();
    let idle = answered.elapsed();
    assert_eq!(rest, b"");
    assert!(
        idle >= Duration::from_millis(350) && idle < Duration::from_secs(5),
        "{idle:?}"
    );
    // A connection that never sends anything: closed after the head timeout.
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    let opened = Instant::now();
    let mut rest = Vec::new();
    s.read_to_end(&mut rest).unwrap();
    let silent = opened.elapsed();
    assert_eq!(rest, b"");
    assert!(
        silent >= Duration::from_millis(550) && silent < Duration::from_secs(5),
        "{silent:?}"
    );
}

/// Whether the server closed `s` (within `wait`).
fn is_closed(s: &mut TcpStream, wait: Duration) -> bool {
    s.set_read_timeout(Some(wait)).unwrap();
    let mut byte = [0];
    match s.read(&mut byte) {
        Ok(0) => true,
        Ok(_) => panic!("unexpected bytes"),
        Err(e)
            if matches!(
                e.kind(),
                std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
            ) =>
        {
            false
        }
        Err(_) => true, // reset
    }
}

#[test]
fn at_the_limit_the_longest_waiting_connection_makes_room() {
    let config = ServerConfig {
        max_connections: 3,
        ..ServerConfig::default()
    };
    let port = Server::bind(0, Studio::example())
        .unwrap()
        .with_config(config)
        .spawn();
    // Three connections that send nothing hold every slot (for 10 s each, by default)...
    let mut silent: Vec<TcpStream> = (0..3)
        .map(|_| TcpStream::connect(("127.0.0.1", port)).unwrap())
        .collect();
    // ... and one that is kept alive after a request, the most recent to wait.
    let mut kept = silent.pop().unwrap();
    kept.write_all(format!("GET /api/state HTTP/1.1\r\n{}\r\n", host(port)).as_bytes())
        .unwrap();
    kept.set_read_timeout(Some(Duration::from_secs(10)))
        .unwrap();
    assert!(read_answer(&mut kept, false).0.starts_with("HTTP/1.1 200"));
    // A new client is served at once: the oldest silent one was closed for it.
    let started = Instant::now();
    assert_eq!(get(port, "/api/state", &host(port)).0, 200);
    assert!(started.elapsed() < Duration::from_secs(2));
    assert!(is_closed(&mut silent[0], Duration::from_secs(5)));
    assert!(!is_closed(&mut silent[1], Duration::from_millis(200)));
    // Full again: the next oldest goes, then the kept-alive one, which waited after it.
    let mut newer = TcpStream::connect(("127.0.0.1", port)).unwrap();
    assert_eq!(get(port, "/api/state", &host(port)).0, 200);
    assert!(is_closed(&mut silent[1], Duration::from_secs(5)));
    assert!(!is_closed(&mut kept, Duration::from_millis(200)));
    let _newest = TcpStream::connect(("127.0.0.1", port)).unwrap();
    assert_eq!(get(port, "/api/state", &host(port)).0, 200);
    assert!(is_closed(&mut kept, Duration::from_secs(5)));
    assert!(!is_closed(&mut newer, Duration::from_millis(200)));
}

/// The `./NAME.js` modules a page script imports.
fn imports_of(script: &str) -> Vec<String> {
    script
        .lines()
        .filter(|l| l.starts_with("import "))
        .map(|l| {
            let from = l.split(" from '").nth(1).expect("import ... from '...'");
            from.split('\'').next().unwrap().to_owned()
        })
        .collect()
}

#[test]
fn every_module_the_page_imports_is_served() {
    let port = example_server();
    let (_, _, page) = get(port, "/", &host(port));
    assert!(String::from_utf8(page)
        .unwrap()
        .contains(r#"<script type="module" src="/studio.js"></script>"#));
    // From the entry module, each import resolved against the importer's path, as the browser
    // does; all six modules are reached.
    let mut seen = std::collections::BTreeSet::new();
    let mut todo = vec!["/studio.js".to_owned()];
    while let Some(path) = todo.pop() {
        if !seen.insert(path.clone()) {
            continue;
        }
        let (status, head, body) = get(port, &path, &host(port));
        assert_eq!(status, 200, "{path}");
        assert!(head.contains("Content-Type: text/javascript"), "{path}");
        let dir = &path[..path.rfind('/').unwrap()];
        for import in imports_of(&String::from_utf8(body).unwrap()) {
            todo.push(format!("{dir}/{}", import.strip_prefix("./").unwrap()));
        }
    }
    let modules: Vec<_> = seen.into_iter().collect();
    assert_eq!(
        modules,
        [
            "/modules/figures.js",
            "/modules/files.js",
            "/modules/fitting.js",
            "/modules/panel.js",
            "/modules/queue.js",
            "/modules/state.js",
            "/studio.js"
        ]
    );
    let (status, head, _) = http(
        port,
        format!(
            "HEAD /modules/queue.js HTTP/1.1\r\n{}Connection: close\r\n\r\n",
            host(port)
        )
        .as_bytes(),
    );
    assert_eq!(status, 200);
    assert!(head.contains("Content-Type: text/javascript"));
    assert_eq!(get(port, "/modules/other.js", &host(port)).0, 404);
    // The Host check comes first.
    assert_eq!(
        get(port, "/modules/state.js", "Host: attacker.example\r\n").0,
        403
    );
}

// ------------------------------------------------------------------------------------------
// The wide families (interval-valued and bipolar): described to the page, tabled through their
// lanes, refused with their rule.

/// The family of `/api/state`'s list named `name`.
fn described(families: &Value, name: &str) -> Value {
    families
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["name"] == name)
        .unwrap_or_else(|| panic!("{name} not in {families}"))
        .clone()
}

#[test]
fn state_describes_every_family_from_the_core() {
    let port = example_server();
    let (status, _, body) = get(port, "/api/state", &host(port));
    assert_eq!(status, 200);
    let state: Value = serde_json::from_slice(&body).unwrap();
    let families = &state["families"];
    let names: Vec<&str> = families
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "neutrosophic",
            "intuitionistic",
            "fuzzy",
            "pythagorean",
            "fermatean",
            "q-rung",
            "picture",
            "spherical",
            "t-spherical",
            "interval-neutrosophic",
            "interval-intuitionistic",
            "interval-type2",
            "bipolar-neutrosophic"
        ]
    );
    let type2 = described(families, "interval-type2");
    assert_eq!(
        type2,
        json!({
            "name": "interval-type2",
            "label": "interval-type2",
            "parameter": null,
            "lanes": 2,
            "channels": [
                { "name": "truth_lower", "min": 0.0, "max": 1.0 },
                { "name": "truth_upper", "min": 0.0, "max": 1.0 }
            ],
            "fields": [
                { "name": "truth_lower", "min": 0.0, "max": 1.0, "derived": false },
                { "name": "truth_upper", "min": 0.0, "max": 1.0, "derived": false }
            ],
            "derived": ["type_reduced", "footprint"],
            "rule": "interval-type2: truth_lower, truth_upper each in [0, 1]; \
                     truth_lower <= truth_upper; derived: type_reduced, footprint"
        })
    );
    // Bipolar: six fields, the negative ones in [-1, 0].
    let bipolar = described(families, "bipolar-neutrosophic");
    let fields: Vec<(String, f64, f64)> = bipolar["fields"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            (
                f["name"].as_str().unwrap().to_owned(),
                f["min"].as_f64().unwrap(),
                f["max"].as_f64().unwrap(),
            )
        })
        .collect();
    let expected: Vec<(String, f64, f64)> = [
        ("truth", 0.0, 1.0),
        ("indeterminacy", 0.0, 1.0),
        ("falsity", 0.0, 1.0),
        ("negative_truth", -1.0, 0.0),
        ("negative_indeterminacy", -1.0, 0.0),
        ("negative_falsity", -1.0, 0.0),
    ]
    .iter()
    .map(|(n, a, b)| ((*n).to_owned(), *a, *b))
    .collect();
    assert_eq!(fields, expected);
    assert_eq!(
        bipolar["rule"],
        "bipolar-neutrosophic: truth, indeterminacy, falsity each in [0, 1]; negative_truth, \
         negative_indeterminacy, negative_falsity each in [-1, 0]"
    );
    assert_eq!(
        described(families, "interval-intuitionistic")["rule"],
        "interval-intuitionistic: truth_lower, truth_upper, falsity_lower, falsity_upper each in \
         [0, 1]; truth_lower <= truth_upper, falsity_lower <= falsity_upper; truth_upper + \
         falsity_upper <= 1; derived: hesitation_lower, hesitation_upper"
    );
    // A family of one lane shows the three degree slots of its curve, the ones it does not
    // carry derived (the intuitionistic hesitation, a Pythagorean 0).
    let intuitionistic = described(families, "intuitionistic");
    assert_eq!(intuitionistic["lanes"], 1);
    let derived: Vec<(&str, bool)> = intuitionistic["fields"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["name"].as_str().unwrap(), f["derived"].as_bool().unwrap()))
        .collect();
    assert_eq!(
        derived,
        [
            ("truth", false),
            ("indeterminacy", true),
            ("falsity", false)
        ]
    );
    assert_eq!(
        intuitionistic["channels"],
        json!([{ "name": "truth", "min": 0.0, "max": 1.0 }, { "name": "falsity", "min": 0.0, "max": 1.0 }])
    );
    assert_eq!(
        intuitionistic["rule"],
        "intuitionistic: truth, falsity each in [0, 1]; truth + falsity <= 1; derived: hesitation"
    );
    // The parametrised families: the parameter's key, and 3 for a model switched to them.
    let q = described(families, "q-rung");
    assert_eq!(q["parameter"], json!({ "key": "q", "value": 3 }));
    assert_eq!(q["label"], "q-rung (q = 3 unless the file gives q)");
    assert_eq!(
        q["rule"],
        "q-rung:3: truth, falsity each in [0, 1]; truth^3 + falsity^3 <= 1; derived: hesitation"
    );
    assert_eq!(
        described(families, "t-spherical")["parameter"],
        json!({ "key": "n", "value": 3 })
    );
}

/// An interval-type2 cubic Bézier curve, as the page sends it.
const TYPE2_BEZIER: &str = r#"{"kind": "bezier", "membership": "interval-type2",
  "control_points": [
    {"x": 0.0, "y": 0.0, "truth_lower": 0.2, "truth_upper": 0.5},
    {"x": 1.0, "y": 2.0, "truth_lower": 0.6, "truth_upper": 0.9},
    {"x": 3.0, "y": 2.0, "truth_lower": 0.1, "truth_upper": 0.3},
    {"x": 4.0, "y": 0.0, "truth_lower": 0.4, "truth_upper": 0.4}]}"#;

/// A bipolar neutrosophic quadratic Bézier curve.
const BIPOLAR_BEZIER: &str = r#"{"kind": "bezier", "membership": "bipolar-neutrosophic",
  "control_points": [
    {"x": 0, "y": 0, "truth": 0.8, "indeterminacy": 0.2, "falsity": 0.1,
     "negative_truth": -0.1, "negative_indeterminacy": -0.3, "negative_falsity": -0.7},
    {"x": 1, "y": 2, "truth": 0.5, "indeterminacy": 0.4, "falsity": 0.3,
     "negative_truth": -0.4, "negative_indeterminacy": 0.0, "negative_falsity": -0.5},
    {"x": 3, "y": 1, "truth": 0.2, "indeterminacy": 0.1, "falsity": 0.7,
     "negative_truth": -0.8, "negative_indeterminacy": -0.1, "negative_falsity": -0.2}]}"#;

/// The Bernstein blend `sum_i C(n, i) t^i (1 - t)^(n - i) values[i]`, written out here.
fn bernstein_blend(values: &[f64], t: f64) -> f64 {
    let n = values.len() - 1;
    let mut binomial = 1.0;
    let mut sum = 0.0;
    for (i, v) in values.iter().enumerate() {
        sum += binomial * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32) * v;
        binomial = binomial * (n - i) as f64 / (i + 1) as f64;
    }
    sum
}

/// The table's cells as numbers.
fn numbers(row: &Value) -> Vec<f64> {
    row.as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap().parse().unwrap())
        .collect()
}

fn channel(model: &Value, name: &str) -> Vec<f64> {
    model["control_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p[name].as_f64().unwrap())
        .collect()
}

#[test]
fn the_table_of_a_wide_model_blends_every_channel() {
    let port = example_server();
    let at = [0.0, 0.3, 0.5, 0.85, 1.0];
    let at_text = "0, 0.3, 0.5, 0.85, 1";
    // Whatever the plot crate draws of a wide model, the model, its table and its family come
    // back: figures are asked for none here.
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": TYPE2_BEZIER, "views": [], "at": at_text }),
    );
    assert_eq!(status, 200, "{answer}");
    assert_eq!(
        answer["table"]["columns"],
        json!([
            "t",
            "x",
            "y",
            "truth_lower",
            "truth_upper",
            "type_reduced",
            "footprint"
        ])
    );
    let model: Value = serde_json::from_str(TYPE2_BEZIER).unwrap();
    let (lower, upper) = (
        channel(&model, "truth_lower"),
        channel(&model, "truth_upper"),
    );
    let (xs, ys) = (channel(&model, "x"), channel(&model, "y"));
    for (row, &t) in answer["table"]["rows"].as_array().unwrap().iter().zip(&at) {
        let cells = numbers(row);
        let (l, u) = (bernstein_blend(&lower, t), bernstein_blend(&upper, t));
        let expected = [
            t,
            bernstein_blend(&xs, t),
            bernstein_blend(&ys, t),
            l,
            u,
            (l + u) / 2.0,
            u - l,
        ];
        for (k, (got, want)) in cells.iter().zip(expected).enumerate() {
            assert!(
                (got - want).abs() < 1e-12,
                "t = {t}, column {k}: {got} vs {want}"
            );
        }
    }
    assert_eq!(answer["table"]["rows"].as_array().unwrap().len(), 5);
    assert_eq!(answer["family"]["name"], "interval-type2");
    assert_eq!(
        answer["pointDegrees"],
        json!([[0.2, 0.5], [0.6, 0.9], [0.1, 0.3], [0.4, 0.4]])
    );
    assert_eq!(answer["model"]["control_points"], model["control_points"]);

    // Bipolar: the negative degrees ride negated in the second lane and come back negative.
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": BIPOLAR_BEZIER, "views": [], "at": "0.25, 0.6" }),
    );
    assert_eq!(status, 200, "{answer}");
    let names = [
        "truth",
        "indeterminacy",
        "falsity",
        "negative_truth",
        "negative_indeterminacy",
        "negative_falsity",
    ];
    let mut columns = vec!["t", "x", "y"];
    columns.extend(names);
    assert_eq!(answer["table"]["columns"], json!(columns));
    let model: Value = serde_json::from_str(BIPOLAR_BEZIER).unwrap();
    for (row, t) in answer["table"]["rows"]
        .as_array()
        .unwrap()
        .iter()
        .zip([0.25, 0.6])
    {
        let cells = numbers(row);
        for (k, name) in names.iter().enumerate() {
            let want = bernstein_blend(&channel(&model, name), t);
            assert!((cells[3 + k] - want).abs() < 1e-12, "t = {t}, {name}");
        }
        assert!(cells[6] < 0.0 && cells[8] < 0.0, "{cells:?}");
    }
    assert_eq!(
        answer["pointDegrees"][1],
        json!([0.5, 0.4, 0.3, -0.4, 0.0, -0.5])
    );

    // A one-lane family's point degrees are its curve's three slots: the intuitionistic
    // indeterminacy is the hesitation 1 - T - F.
    let intuitionistic = example_with(|v| {
        v["membership"] = json!("intuitionistic");
        for p in v["control_points"].as_array_mut().unwrap() {
            p.as_object_mut().unwrap().remove("indeterminacy");
        }
    });
    let (_, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": intuitionistic, "views": [] }),
    );
    let slots = numbers_of(&answer["pointDegrees"][1]);
    assert_eq!(slots[0], 0.8);
    assert!((slots[1] - 0.1).abs() < 1e-15, "{slots:?}");
    assert_eq!(slots[2], 0.1);
}

fn numbers_of(values: &Value) -> Vec<f64> {
    values
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect()
}

#[test]
fn the_interval_type2_example_file_is_tabled_and_its_rule_refused() {
    let port = example_server();
    let text = include_str!("../../../examples/families/interval-type2.toml");
    let (status, opened, _) = post(
        port,
        "/api/open",
        &json!({ "name": "interval-type2.toml", "text": text }),
    );
    assert_eq!(status, 200, "{opened}");
    let model_text = opened["model"].to_string();
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": model_text, "views": [] }),
    );
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["table"]["rows"].as_array().unwrap().len(), 11);
    // At t = 0 the clamped B-spline is at its first control point: 0.2 and 0.5.
    assert_eq!(
        answer["table"]["rows"][0],
        json!(["0", "0", "0", "0.2", "0.5", "0.35", "0.3"])
    );
    // truth_lower above truth_upper: the reader's message, with the rule.
    let mut bad = opened["model"].clone();
    bad["control_points"][1]["truth_lower"] = json!(0.6);
    bad["control_points"][1]["truth_upper"] = json!(0.4);
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": bad.to_string(), "views": ["plane"] }),
    );
    assert_eq!(status, 422);
    assert_eq!(
        answer["error"]["message"],
        "control_points[1]: truth_lower = 0.6 exceeds truth_upper = 0.4 (interval-type2 rule: \
         lower <= upper)"
    );
    assert_eq!(answer["error"]["field"], "control_points[1]");
    assert_eq!(
        answer["error"]["detail"],
        "truth_lower = 0.6 exceeds truth_upper = 0.4 (interval-type2 rule: lower <= upper)"
    );
    // A negative bipolar degree above 0: its box.
    let mut bad: Value = serde_json::from_str(BIPOLAR_BEZIER).unwrap();
    bad["control_points"][2]["negative_falsity"] = json!(0.2);
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": bad.to_string(), "views": [] }),
    );
    assert_eq!(status, 422);
    assert_eq!(
        answer["error"]["message"],
        "control_points[2]: negative_falsity = 0.2 is outside [-1, 0] (bipolar-neutrosophic rule)"
    );
}

#[test]
fn the_table_of_a_wide_surface_blends_its_lanes() {
    let port = example_server();
    // A bilinear interval-intuitionistic patch; rows along u, columns along v.
    let points = [
        (0.0, 0.0, [0.1, 0.3, 0.2, 0.4]),
        (0.0, 1.0, [0.5, 0.6, 0.1, 0.2]),
        (1.0, 0.0, [0.2, 0.2, 0.5, 0.7]),
        (1.0, 1.0, [0.0, 0.4, 0.3, 0.5]),
    ];
    let names = [
        "truth_lower",
        "truth_upper",
        "falsity_lower",
        "falsity_upper",
    ];
    let control_points: Vec<Value> = points
        .iter()
        .map(|(x, y, values)| {
            let mut p = json!({ "x": x, "y": y, "z": x * y });
            for (name, v) in names.iter().zip(values) {
                p[*name] = json!(v);
            }
            p
        })
        .collect();
    let model = json!({
        "kind": "bezier-surface", "rows": 2, "cols": 2,
        "membership": "interval-intuitionistic", "control_points": control_points,
    });
    let (status, answer, _) = post(
        port,
        "/api/render",
        &json!({ "model": model.to_string(), "views": [], "at": "0.25:0.5, 0.8:0.1" }),
    );
    assert_eq!(status, 200, "{answer}");
    assert_eq!(
        answer["table"]["columns"],
        json!([
            "u",
            "v",
            "x",
            "y",
            "z",
            "truth_lower",
            "truth_upper",
            "falsity_lower",
            "falsity_upper",
            "hesitation_lower",
            "hesitation_upper"
        ])
    );
    for (row, (u, v)) in answer["table"]["rows"]
        .as_array()
        .unwrap()
        .iter()
        .zip([(0.25, 0.5), (0.8, 0.1)])
    {
        let cells = numbers(row);
        // The bilinear weights of the corners (0,0), (0,1), (1,0), (1,1).
        let w = [(1.0 - u) * (1.0 - v), (1.0 - u) * v, u * (1.0 - v), u * v];
        let blend = |k: usize| -> f64 { points.iter().zip(w).map(|(p, w)| w * p.2[k]).sum() };
        let channels = [blend(0), blend(1), blend(2), blend(3)];
        let expected = [
            u,
            v,
            u,
            v,
            u * v,
            channels[0],
            channels[1],
            channels[2],
            channels[3],
            1.0 - channels[1] - channels[3],
            1.0 - channels[0] - channels[2],
        ];
        for (k, (got, want)) in cells.iter().zip(expected).enumerate() {
            assert!(
                (got - want).abs() < 1e-12,
                "({u}, {v}) column {k}: {got} vs {want}"
            );
        }
    }
}
