//! The studio's server over real sockets: the guards (Host, Origin, body limit, methods,
//! paths), the JSON API against figures drawn directly with the plot crate and the reader's
//! exact messages, and saving (only the started file, atomically).

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;

use neutrospline::{ControlPolygon, Evaluate};
use neutrospline_io::{Format, Model, ReadOptions, Shape};
use neutrospline_plot::{render_png, render_svg, PlotModel, PlotOptions, View};
use neutrospline_studio::{Server, Studio};
use serde_json::{json, Value};

const EXAMPLE1_JSON: &str = include_str!("../../../examples/example1.json");
const BSPLINE_TOML: &str = include_str!("../../../examples/bspline.toml");

/// One request on its own connection: (status, head, body).
fn http(port: u16, raw: &[u8]) -> (u16, String, Vec<u8>) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
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
    assert_eq!(get(port, "/", "").0, 403, "no Host header");
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
    let Shape::Planar(curve) = model.shape() else {
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
        json!([
            "0.5",
            "4.625",
            "4",
            "0.625",
            "0.19999999999999998",
            "0.17500000000000002"
        ])
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
            &json!({ "model": EXAMPLE1_JSON, "views": views, "encoding": encoding, "samples": 40 }),
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
        &json!({ "model": EXAMPLE1_JSON, "view": "truth", "format": "svg" }),
    );
    assert_eq!(status, 200);
    assert_eq!(
        String::from_utf8(svg).unwrap(),
        render_svg(&plot, View::Truth, &options).unwrap()
    );
    let (status, _, png) = post(
        port,
        "/api/export",
        &json!({ "model": EXAMPLE1_JSON, "view": "controls", "format": "png", "azimuth": 10, "elevation": 40 }),
    );
    assert_eq!(status, 200);
    assert_eq!(
        png,
        render_png(&plot, View::Controls, &options.with_camera(10.0, 40.0)).unwrap()
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
