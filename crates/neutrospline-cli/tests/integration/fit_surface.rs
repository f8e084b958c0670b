//! End-to-end tests of `neutrospline fit --surface`: the model reads back in `eval`, `check`
//! and `plot`, interpolation passes through the grid, the report, located refusals with no
//! output written.

use std::fs;

use crate::util::run;

/// A 5 x 4 grid of `z = x y / 4 + sin x` with its `(u, v)` and gently varying degrees.
fn grid_csv() -> String {
    let mut csv = String::from("u,v,x,y,z,T,I,F\n");
    for k in 0..5 {
        for l in 0..4 {
            let (u, v) = (k as f64 / 4.0, l as f64 / 3.0);
            let (x, y) = (2.0 * u + 0.1 * v, 3.0 * v);
            let z = x * y / 4.0 + x.sin();
            csv.push_str(&format!(
                "{u},{v},{x},{y},{z},{},{},{}\n",
                0.4 + 0.2 * u,
                0.2 + 0.1 * v,
                0.3 - 0.1 * u * v
            ));
        }
    }
    csv
}

fn numbers(line: &str) -> Vec<f64> {
    line.split(',').map(|c| c.parse().unwrap()).collect()
}

#[test]
fn grid_interpolation_reads_back_in_eval_check_and_plot() {
    let dir = tempfile::tempdir().unwrap();
    let csv = grid_csv();
    fs::write(dir.path().join("g.csv"), &csv).unwrap();
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "fit",
            "g.csv",
            "--surface",
            "--grid",
            "5x4",
            "--degree",
            "3,2",
            "--interpolate",
            "-o",
            "m.toml",
            "--report",
            "json",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(stderr.trim()).unwrap();
    assert_eq!(report["control_points"], serde_json::json!([5, 4]));
    assert_eq!(report["degrees"], serde_json::json!([3, 2]));
    assert_eq!(report["two_pass"], serde_json::json!(true));
    assert!(report["worst_distance"].as_f64().unwrap() < 1e-12);
    let rows: Vec<Vec<f64>> = csv.lines().skip(1).map(numbers).collect();
    let at: Vec<String> = rows.iter().map(|r| format!("{}:{}", r[0], r[1])).collect();
    let (code, table, stderr) = run(dir.path(), &["eval", "m.toml", "--at", &at.join(",")]);
    assert_eq!(code, 0, "{stderr}");
    let header = table.lines().next().unwrap();
    assert!(
        header.starts_with("u,v,x,y,z,truth,indeterminacy,falsity"),
        "{header}"
    );
    for (line, point) in table.lines().skip(1).zip(&rows) {
        let got = numbers(line);
        for c in 2..8 {
            assert!((got[c] - point[c]).abs() < 1e-12, "{got:?} {point:?}");
        }
    }
    let (code, _, stderr) = run(dir.path(), &["check", "m.toml"]);
    assert_eq!(code, 0, "{stderr}");
    let (code, _, stderr) = run(dir.path(), &["plot", "m.toml", "-o", "m.svg"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(fs::read_to_string(dir.path().join("m.svg"))
        .unwrap()
        .contains("<svg"));
}

#[test]
fn scattered_least_squares_reports_in_text() {
    let dir = tempfile::tempdir().unwrap();
    let mut csv = String::from("x,y,z,T,I,F\n");
    for k in 0..300 {
        let x = (k as f64 * 0.618_033_988_749_895).fract() * 4.0;
        let y = (k as f64 * 0.414_213_562_373_095_1).fract() * 2.0;
        csv.push_str(&format!("{x},{y},{},0.6,0.2,0.1\n", (x - 2.0) * (y - 1.0)));
    }
    fs::write(dir.path().join("s.csv"), &csv).unwrap();
    let (code, stdout, stderr) = run(
        dir.path(),
        &[
            "fit",
            "s.csv",
            "--surface",
            "--scattered",
            "--projection",
            "xy",
            "--control-points",
            "5,4",
            "--degree",
            "2",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("Fitted to s.csv (300 scattered points)"),
        "{stdout}"
    );
    // z = (x - 2)(y - 1) is bilinear: every spline space of degree 2 holds it.
    assert!(
        stderr.starts_with("control points       5 x 4 (degrees 2, 2; whole tensor system)\n"),
        "{stderr}"
    );
    assert!(stderr.contains("at bound             none\n"), "{stderr}");
    let (code, _, stderr) = run(
        dir.path(),
        &[
            "fit",
            "s.csv",
            "--surface",
            "--projection",
            "xy",
            "--control-points",
            "5,4",
            "--degree",
            "2",
            "--report",
            "json",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(stderr.trim()).unwrap();
    assert!(
        report["max_error"]["z"].as_f64().unwrap() < 1e-12,
        "{report}"
    );
    assert_eq!(report["two_pass"], serde_json::json!(false));
}

#[test]
fn refusals_name_the_rule_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("g.csv"), grid_csv()).unwrap();
    let cases: [(&[&str], &str); 5] = [
        (
            &["fit", "g.csv", "--surface", "--grid", "4x4", "-o", "m.toml"],
            "error: g.csv: a grid of 4 x 4 points does not hold 20 points (rows x cols must be \
             the number of points, each at least 1)\n",
        ),
        (
            &["fit", "g.csv", "--grid", "5x4", "-o", "m.toml"],
            "error: --grid applies only with --surface\n",
        ),
        (
            &["fit", "g.csv", "--surface", "--closed", "-o", "m.toml"],
            "error: --closed applies only without --surface\n",
        ),
        (
            &[
                "fit",
                "g.csv",
                "--surface",
                "--degree",
                "3,2,1",
                "-o",
                "m.toml",
            ],
            "error: degree = 3,2,1: a degree is one or two whole numbers (P or P,Q)\n",
        ),
        (
            &[
                "fit",
                "g.csv",
                "--surface",
                "--scattered",
                "--interpolate",
                "-o",
                "m.toml",
            ],
            "error: g.csv: interpolation needs gridded data (a grid of rows x cols points); \
             fit scattered data by least squares (control points or a tolerance)\n",
        ),
    ];
    for (args, want) in cases {
        let (code, stdout, stderr) = run(dir.path(), args);
        assert_ne!(code, 0, "{args:?}");
        assert_eq!(stderr, want, "{args:?}");
        assert!(stdout.is_empty());
        assert!(!dir.path().join("m.toml").exists(), "{args:?}");
    }
}

/// `fit --surface --plot`: the data view of the fitted surface, one marker and one whisker per
/// data point (the hill's 120), coloured by --color-by; and `plot --data` of the same model
/// draws the same counts (whiskers to the nearest points, the file having no u, v). A figure
/// format that is not one is refused before anything is written.
#[test]
fn the_data_view_of_a_surface_fit() {
    let dir = tempfile::tempdir().unwrap();
    let hill = crate::util::example("data/hill_grid.csv")
        .display()
        .to_string();
    let args = [
        "fit",
        &hill,
        "--surface",
        "--grid",
        "12x10",
        "--control-points",
        "6,5",
        "-o",
        "hill.toml",
        "--plot",
        "hill.svg",
        "--color-by",
        "indeterminacy",
    ];
    let (code, _, stderr) = run(dir.path(), &args);
    assert_eq!(code, 0, "{stderr}");
    let svg = fs::read_to_string(dir.path().join("hill.svg")).unwrap();
    assert_eq!(svg.matches("class=\"data-point\"").count(), 120);
    assert_eq!(svg.matches("class=\"residual\"").count(), 120);
    assert!(
        svg.contains(">indeterminacy</text>"),
        "the colour bar names the degree"
    );
    assert!(svg.contains("fitted to data</title>"));
    let plot = [
        "plot",
        "hill.toml",
        "--view",
        "data",
        "--data",
        &hill,
        "-o",
        "again.svg",
    ];
    let (code, _, stderr) = run(dir.path(), &plot);
    assert_eq!(code, 0, "{stderr}");
    let again = fs::read_to_string(dir.path().join("again.svg")).unwrap();
    assert_eq!(again.matches("class=\"residual\"").count(), 120);
    assert!(again.contains("nearest point of the"));

    let bad = [
        "fit",
        &hill,
        "--surface",
        "--grid",
        "12x10",
        "-o",
        "bad.toml",
        "--plot",
        "bad.gif",
    ];
    let (code, stdout, _) = run(dir.path(), &bad);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert!(!dir.path().join("bad.toml").exists());
    assert!(!dir.path().join("bad.gif").exists());
}

/// The real data set (examples/data/README.md): the topobathy grid and its scattered
/// subsample fit, each model passes `check`, and the reports give what docs/fitting.md shows
/// (z residuals: the grid's RMS 0.160 km, worst 0.841 km; the subsample's RMS 0.190 km).
#[test]
fn the_topobathy_example_fits_and_checks() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[&str], f64, f64); 2] = [
        (
            "data/topobathy_grid.csv",
            &["--grid", "60x46", "--control-points", "30,24"],
            0.1596,
            0.8405,
        ),
        (
            "data/topobathy_scattered.csv",
            &[
                "--projection",
                "xy",
                "--control-points",
                "20,16",
                "--smoothing",
                "1e-4",
            ],
            0.1900,
            1.0051,
        ),
    ];
    for (file, extra, rms_z, max_z) in cases {
        let data = crate::util::example(file).display().to_string();
        let mut args = vec![
            "fit",
            data.as_str(),
            "--surface",
            "--report",
            "json",
            "-o",
            "m.toml",
        ];
        args.extend(extra);
        let (code, _, stderr) = run(dir.path(), &args);
        assert_eq!(code, 0, "{file}: {stderr}");
        let report: serde_json::Value = serde_json::from_str(stderr.trim()).unwrap();
        let got = |key: &str| report[key]["z"].as_f64().unwrap();
        assert!((got("rms_error") - rms_z).abs() < 5e-4, "{file}: {report}");
        assert!((got("max_error") - max_z).abs() < 5e-4, "{file}: {report}");
        let (code, stdout, stderr) = run(dir.path(), &["check", "m.toml"]);
        assert_eq!(code, 0, "{file}: {stderr}");
        assert!(stdout.contains("m.toml: valid"), "{stdout}");
    }
}

/// The bad input, one located error each and nothing written: too few points for the
/// degree, NaN, grid rows that coincide (repeated points with chord-length parameters); and
/// data that leaves most of the domain empty, without smoothing: fitted, with a warning that
/// names the file and says what to give, and no warning once smoothing is given.
#[test]
fn bad_surface_data_is_refused_or_warned_of() {
    let dir = tempfile::tempdir().unwrap();
    let header = "x,y,z,truth,indeterminacy,falsity\n";
    let grid = |n: usize, row_of: &dyn Fn(usize) -> usize, z: &dyn Fn(usize, usize) -> String| {
        let mut csv = header.to_owned();
        for i in 0..n {
            for j in 0..n {
                let r = row_of(i);
                csv.push_str(&format!("{r},{j},{},0.5,0.2,0.1\n", z(r, j)));
            }
        }
        csv
    };
    fs::write(
        dir.path().join("few.csv"),
        grid(3, &|i| i, &|i, j| (i * j).to_string()),
    )
    .unwrap();
    let nan = |i: usize, j: usize| {
        if (i, j) == (2, 1) {
            "NaN".to_owned()
        } else {
            (i * j).to_string()
        }
    };
    fs::write(dir.path().join("nan.csv"), grid(5, &|i| i, &nan)).unwrap();
    let repeated = |i: usize| if i == 2 { 1 } else { i };
    fs::write(
        dir.path().join("rep.csv"),
        grid(5, &repeated, &|i, j| (i * j).to_string()),
    )
    .unwrap();
    let cases: [(&[&str], &str); 3] = [
        (
            &[
                "fit",
                "few.csv",
                "--surface",
                "--grid",
                "3x3",
                "--interpolate",
                "-o",
                "m.toml",
            ],
            "error: few.csv: 9 points are too few: interpolation with degree 3 needs at least 4 \
             rows (3 here)\n",
        ),
        (
            &[
                "fit",
                "nan.csv",
                "--surface",
                "--grid",
                "5x5",
                "-o",
                "m.toml",
            ],
            "error: nan.csv:13: column `z`: value `NaN` is not a finite number (NaN and \
             infinities are not allowed)\n",
        ),
        (
            &[
                "fit",
                "rep.csv",
                "--surface",
                "--grid",
                "5x5",
                "--interpolate",
                "-o",
                "m.toml",
            ],
            "error: rep.csv: grid rows 1 and 2 have one parameter (0.25): interpolation needs \
             distinct ones (the rows coincide; remove one, or give parameters)\n",
        ),
    ];
    for (args, want) in cases {
        let (code, stdout, stderr) = run(dir.path(), args);
        assert_eq!(
            (code, stdout.as_str(), stderr.as_str()),
            (1, "", want),
            "{args:?}"
        );
        assert!(!dir.path().join("m.toml").exists(), "{args:?}");
    }
    // 200 points in the corner [0, 0.3]^2 and three at the other corners: the knots follow the
    // data, so every cell has data, but the cells between the cluster and the corners barely.
    let mut csv = header.to_owned();
    let mut seed = 1u64;
    let mut next = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..200 {
        let (x, y) = (0.3 * next(), 0.3 * next());
        csv.push_str(&format!("{x},{y},{},0.5,0.2,0.1\n", x + y));
    }
    csv.push_str("1,1,2,0.5,0.2,0.1\n1,0,1,0.5,0.2,0.1\n0,1,1,0.5,0.2,0.1\n");
    fs::write(dir.path().join("corner.csv"), csv).unwrap();
    let fit = [
        "fit",
        "corner.csv",
        "--surface",
        "--projection",
        "xy",
        "--control-points",
        "10,10",
    ];
    let (code, _, stderr) = run(dir.path(), &[&fit[..], &["-o", "c.toml"]].concat());
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.starts_with("warning: corner.csv: the least-squares system is nearly singular"),
        "{stderr}"
    );
    assert!(
        stderr.contains("Give smoothing (--smoothing LAMBDA"),
        "{stderr}"
    );
    let (code, _, stderr) = run(
        dir.path(),
        &[&fit[..], &["--smoothing", "1e-6", "-o", "s.toml"]].concat(),
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(!stderr.contains("warning"), "{stderr}");
}
