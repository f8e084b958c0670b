//! End-to-end tests of `neutrospline fit` (and `plot --data`): the model it writes reads back
//! in `eval` and `check`, interpolation passes through the data, the report's values, exact
//! located messages for bad data and options, no output file left by a failure.

use std::fs;
use std::path::Path;

use crate::util::run;

fn survey() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/data/survey.csv")
}

/// Points on `y = x^2 / 4` at given parameters, with degrees varying gently along them (their
/// interpolant stays inside [0, 1], so no bound is active).
const PARABOLA: &str = "x,y,T,I,F,parameter\n\
    0,0,0.5,0.3,0.2,0\n1,0.25,0.55,0.32,0.22,0.1\n2,1,0.6,0.35,0.25,0.3\n\
    3,2.25,0.65,0.35,0.27,0.45\n4,4,0.7,0.33,0.28,0.7\n5,6.25,0.72,0.3,0.3,0.85\n\
    6,9,0.75,0.28,0.3,1\n";

#[test]
fn interpolation_passes_through_every_point_and_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("d.csv"), PARABOLA).unwrap();
    let (code, stdout, stderr) = run(dir.path(), &["fit", "d.csv", "--interpolate"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.starts_with("kind = \"bspline\"\n"), "{stdout}");
    assert!(
        stderr.starts_with("control points       7 (degree 3)\n"),
        "{stderr}"
    );
    fs::write(dir.path().join("m.toml"), &stdout).unwrap();
    let (code, table, stderr) = run(
        dir.path(),
        &["eval", "m.toml", "--at", "0,0.1,0.3,0.45,0.7,0.85,1"],
    );
    assert_eq!(code, 0, "{stderr}");
    let rows: Vec<Vec<f64>> = table
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    let data: Vec<Vec<f64>> = PARABOLA
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    for (row, point) in rows.iter().zip(&data) {
        // eval: t, x, y, truth, indeterminacy, falsity; data: x, y, T, I, F, parameter.
        assert_eq!(row[0], point[5]);
        for c in 0..5 {
            assert!((row[c + 1] - point[c]).abs() < 1e-12, "{row:?} {point:?}");
        }
    }
    let (code, _, stderr) = run(dir.path(), &["check", "m.toml"]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn degrees_jumping_between_bounds_stay_valid_and_are_reported() {
    let dir = tempfile::tempdir().unwrap();
    let data = "x,y,T,I,F\n0,0,0,1,1\n1,1,1,0,0\n2,0,0,1,1\n3,1,1,0,0\n4,0,0,1,1\n5,1,1,0,0\n";
    fs::write(dir.path().join("d.csv"), data).unwrap();
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "fit",
            "d.csv",
            "--interpolate",
            "-o",
            "m.toml",
            "--report",
            "json",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(stderr.trim()).unwrap();
    let at_bound = report["at_bound"].as_array().unwrap();
    assert!(!at_bound.is_empty(), "{report}");
    for entry in at_bound {
        let bound = entry["bound"].as_f64().unwrap();
        assert!(bound == 0.0 || bound == 1.0, "{entry}");
    }
    // The positions still interpolate; the degrees give way where they must.
    assert!(
        report["max_error"]["x"].as_f64().unwrap() < 1e-12,
        "{report}"
    );
    assert!(
        report["max_error"]["truth"].as_f64().unwrap() > 0.0,
        "{report}"
    );
    let (code, _, stderr) = run(dir.path(), &["check", "m.toml"]);
    assert_eq!(code, 0, "{stderr}");
    let (code, table, _) = run(dir.path(), &["eval", "m.toml", "--samples", "401"]);
    assert_eq!(code, 0);
    for line in table.lines().skip(1) {
        let row: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        assert!(row[3..6].iter().all(|d| (0.0..=1.0).contains(d)), "{line}");
    }
}

#[test]
fn tolerance_fit_of_the_survey_meets_the_default_tolerance() {
    let dir = tempfile::tempdir().unwrap();
    let data = survey();
    let data = data.to_str().unwrap();
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "fit", data, "-o", "m.json", "--report", "json", "--name", "survey",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(stderr.trim()).unwrap();
    let keys: Vec<&str> = report
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    for key in [
        "control_points",
        "max_error",
        "rms_error",
        "worst_index",
        "worst_parameter",
        "schoenberg_whitney",
        "condition_estimate",
        "at_bound",
        "tolerance_met",
    ] {
        assert!(keys.contains(&key), "{key} missing from {keys:?}");
    }
    let max = report["max_error"].as_object().unwrap();
    let channels: Vec<&str> = max.keys().map(String::as_str).collect();
    let mut sorted = vec!["x", "y", "truth", "indeterminacy", "falsity"];
    sorted.sort_unstable();
    assert_eq!(channels, sorted);
    // The default tolerance: 1e-3 of the bounding-box diagonal of the data.
    let text = fs::read_to_string(survey()).unwrap();
    let points: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| {
            let c: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
            (c[0], c[1])
        })
        .collect();
    let (xs, ys): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
    let span = |v: &[f64]| {
        v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            - v.iter().copied().fold(f64::INFINITY, f64::min)
    };
    let tolerance = 1e-3 * span(&xs).hypot(span(&ys));
    assert!((report["tolerance"].as_f64().unwrap() - tolerance).abs() < 1e-15);
    let met = report["tolerance_met"].as_bool().unwrap();
    let worst = report["worst_distance"].as_f64().unwrap();
    assert_eq!(met, worst <= tolerance, "{report}");
    assert!(report["schoenberg_whitney"].as_bool().unwrap());
    let model = fs::read_to_string(dir.path().join("m.json")).unwrap();
    assert!(model.contains("\"name\": \"survey\""));
    let (code, stdout, stderr) = run(dir.path(), &["check", "m.json"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("bspline"), "{stdout}");
}

#[test]
fn least_squares_with_a_plot_of_the_data() {
    let dir = tempfile::tempdir().unwrap();
    let data = survey();
    let (code, stdout, stderr) = run(
        dir.path(),
        &[
            "fit",
            data.to_str().unwrap(),
            "--control-points",
            "12",
            "--weights",
            "score",
            "--plot",
            "fit.svg",
            "--color-by",
            "indeterminacy",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.starts_with("control points       12 (degree 3)\n"),
        "{stderr}"
    );
    let svg = fs::read_to_string(dir.path().join("fit.svg")).unwrap();
    assert_eq!(svg.matches("class=\"data-point\"").count(), 80);
    assert_eq!(svg.matches("class=\"residual\"").count(), 80);
    assert!(svg.contains("indeterminacy"));
    // The same figure from the written model and the data file.
    fs::write(dir.path().join("m.toml"), stdout).unwrap();
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "plot",
            "m.toml",
            "--data",
            data.to_str().unwrap(),
            "-o",
            "again.svg",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let again = fs::read_to_string(dir.path().join("again.svg")).unwrap();
    assert_eq!(again.matches("class=\"data-point\"").count(), 80);
}

#[test]
fn bad_data_and_options_have_exact_messages_and_write_nothing() {
    let cases: &[(&str, &[&str], i32, &str)] = &[
        (
            "x,y,T,I,F,weight\n0,0,1,0,0,1\n1,1,1,0,0,0\n",
            &["--weights", "column"],
            1,
            "error: d.csv:3: column `weight`: weight = 0 is not positive (a data weight scales \
             how strongly the point pulls the curve: it must be a positive finite number)\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,0,0\n1,1,1,0,0\n",
            &["--interpolate"],
            1,
            "error: d.csv: 2 points are too few: interpolation with degree 3 needs at least 4\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,0,0\n1,1,1,0,0\n# again\n1,1,1,0,0\n2,0,1,0,0\n3,1,1,0,0\n",
            &["--interpolate"],
            1,
            "error: d.csv:5: repeats the position of line 3: chord-length and centripetal \
             parameters need distinct consecutive points (remove it, give a `parameter` \
             column, or use uniform parameters)\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,0,0\n",
            &["--tolerance", "0"],
            2,
            "error: tolerance = 0: the tolerance must be a positive finite number\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,0,0\n",
            &["--weights", "column"],
            2,
            "error: weights = column: d.csv has no `weight` column\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,inf,0\n",
            &[],
            1,
            "error: d.csv:2: column `I`: value `inf` is not a finite number (NaN and \
             infinities are not allowed)\n",
        ),
        (
            "x,y,T,I,F\n0,0,1,0,0\n1,0,1,0,0\n2,0,1,0,0\n3,0,1,0,0\n",
            &["-o", "m.csv"],
            2,
            "error: m.csv: unsupported model extension for a fitted curve (accepted: .toml, \
             .json)\n",
        ),
    ];
    for (data, options, want_code, want) in cases {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("d.csv"), data).unwrap();
        let mut args = vec!["fit", "d.csv", "--plot", "f.svg"];
        if !options.contains(&"-o") {
            args.extend(["-o", "m.toml"]);
        }
        args.extend_from_slice(options);
        let (code, stdout, stderr) = run(dir.path(), &args);
        assert_eq!((code, stderr.as_str()), (*want_code, *want), "{options:?}");
        assert_eq!(stdout, "");
        let left: Vec<_> = fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(left.len(), 1, "{options:?}: only d.csv remains");
    }
}

/// The studio's answer to `POST /api/fit` with `options`: the status and the error message.
fn studio_fit(port: u16, data: &str, options: &serde_json::Value) -> (u16, String) {
    use std::io::{Read, Write};
    let body = serde_json::json!({ "data": { "name": "d.csv", "text": data }, "options": options })
        .to_string();
    let raw = format!(
        "POST /api/fit HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nOrigin: http://127.0.0.1:{port}\r\n\
         Content-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    let mut stream = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    stream.write_all(raw.as_bytes()).unwrap();
    let mut answer = Vec::new();
    let _ = stream.read_to_end(&mut answer);
    let split = answer.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let status = String::from_utf8_lossy(&answer[9..12]).parse().unwrap();
    let value: serde_json::Value = serde_json::from_slice(&answer[split + 4..]).unwrap();
    let message = value["error"]["message"].as_str().unwrap_or("").to_owned();
    (status, message)
}

/// Contradictions and values out of range get one message, the library's `FitRequest`'s, on
/// the command line (exit 2) and in the studio (400); so does data whose weight column and
/// `weights` disagree (exit 2, 422).
#[test]
fn option_errors_are_the_same_on_the_command_line_and_in_the_studio() {
    use serde_json::json;
    let dir = tempfile::tempdir().unwrap();
    let plain = "x,y,T,I,F\n0,0,1,0,0\n1,1,1,0,0\n2,0,1,0,0\n3,1,1,0,0\n4,0,1,0,0\n";
    let weighted = "x,y,T,I,F,weight\n0,0,1,0,0,1\n1,1,1,0,0,2\n2,0,1,0,0,1\n3,1,1,0,0,1\n";
    let targets = "(give one target: interpolate, control-points or tolerance)";
    let cases: Vec<(&str, Vec<&str>, serde_json::Value, u16, String)> = vec![
        (
            plain,
            vec!["--interpolate", "--control-points", "4"],
            json!({ "interpolate": true, "control-points": 4 }),
            400,
            format!("interpolate and control-points exclude each other {targets}"),
        ),
        (
            plain,
            vec!["--tolerance", "0.5", "--control-points", "4"],
            json!({ "tolerance": 0.5, "control-points": 4 }),
            400,
            format!("control-points and tolerance exclude each other {targets}"),
        ),
        (
            plain,
            vec!["--tolerance", "0.5", "--interpolate"],
            json!({ "interpolate": true, "tolerance": 0.5 }),
            400,
            format!("interpolate and tolerance exclude each other {targets}"),
        ),
        (
            plain,
            vec!["--tolerance", "0"],
            json!({ "tolerance": 0 }),
            400,
            "tolerance = 0: the tolerance must be a positive finite number".to_owned(),
        ),
        (
            plain,
            vec!["--smoothing", "-1"],
            json!({ "smoothing": -1 }),
            400,
            "smoothing = -1: the smoothing weight must be a non-negative finite number".to_owned(),
        ),
        (
            plain,
            vec!["--weights", "column"],
            json!({ "weights": "column" }),
            422,
            "weights = column: d.csv has no `weight` column".to_owned(),
        ),
        (
            weighted,
            vec![],
            json!({}),
            422,
            "d.csv has a `weight` column: set weights to column to use it (or remove the column)"
                .to_owned(),
        ),
    ];
    let port = neutrospline_studio::Server::bind(0, neutrospline_studio::Studio::example())
        .unwrap()
        .spawn();
    for (data, args, options, status, message) in cases {
        fs::write(dir.path().join("d.csv"), data).unwrap();
        let mut argv = vec!["fit", "d.csv"];
        argv.extend(&args);
        let (code, stdout, stderr) = run(dir.path(), &argv);
        assert_eq!((code, stdout.as_str()), (2, ""), "{args:?}: {stderr}");
        assert_eq!(stderr, format!("error: {message}\n"), "{args:?}");
        assert_eq!(
            studio_fit(port, data, &options),
            (status, message),
            "{options}"
        );
    }
}

/// A value of the wrong type is named as it was given: a command-line word as typed, a JSON
/// value as JSON writes it; a misspelled option is refused with the list of options.
#[test]
fn wrong_types_and_unknown_options_are_refused() {
    use serde_json::json;
    let dir = tempfile::tempdir().unwrap();
    let plain = "x,y,T,I,F\n0,0,1,0,0\n1,1,1,0,0\n2,0,1,0,0\n3,1,1,0,0\n4,0,1,0,0\n";
    fs::write(dir.path().join("d.csv"), plain).unwrap();
    for (args, message) in [
        (
            vec!["--degree", "5.0"],
            "degree = 5.0: expected a whole number",
        ),
        (
            vec!["--degree", "-1"],
            "degree = -1: expected a whole number",
        ),
        (
            vec!["--parametrization", "even"],
            "parametrization = even: expected one of uniform, chord-length, centripetal",
        ),
    ] {
        let mut argv = vec!["fit", "d.csv"];
        argv.extend(&args);
        let (code, _, stderr) = run(dir.path(), &argv);
        assert_eq!(
            (code, stderr),
            (2, format!("error: {message}\n")),
            "{args:?}"
        );
    }
    let port = neutrospline_studio::Server::bind(0, neutrospline_studio::Studio::example())
        .unwrap()
        .spawn();
    let known = "degree, interpolate, control-points, tolerance, closed, parametrization, \
                 weights, smoothing, kind, membership";
    for (options, message) in [
        (
            json!({ "degree": 5.0 }),
            "degree = 5.0: expected a whole number".to_owned(),
        ),
        (
            json!({ "degree": "5" }),
            "degree = \"5\": expected a whole number".to_owned(),
        ),
        (
            json!({ "closed": "yes" }),
            "closed = \"yes\": expected true or false".to_owned(),
        ),
        (
            json!({ "controlPoints": 10 }),
            format!("unknown option \"controlPoints\" (the options are {known})"),
        ),
        (
            json!({ "kind": ["bspline"] }),
            "kind = [\"bspline\"]: expected one of bspline, bezier".to_owned(),
        ),
    ] {
        assert_eq!(
            studio_fit(port, plain, &options),
            (400, message),
            "{options}"
        );
    }
}
