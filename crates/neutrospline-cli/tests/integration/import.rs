//! End-to-end tests of `neutrospline import`: DXF files written by `export` come back as the
//! same model files, splines without extended data take the default degrees, several curves
//! are chosen with --index or written with --all, and every refusal has its exact message, its
//! exit status and writes no file.

use std::path::Path;

use neutrospline_io::{load, to_toml_string, ReadOptions};

use crate::util::{example, run as run_in};

/// The names of the files in `dir`, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A quadratic plane spline without extended data; its first group is the `0 SPLINE` line.
fn quadratic(y: &str) -> String {
    [
        "  0\nSPLINE\n  8\n0\n 70\n8\n 71\n2\n 72\n6\n 73\n3\n",
        " 40\n0\n 40\n0\n 40\n0\n 40\n1\n 40\n1\n 40\n1\n",
        &format!(" 10\n0\n 20\n0\n 30\n0\n 10\n1\n 20\n{y}\n 30\n0\n 10\n2\n 20\n0\n 30\n0\n"),
    ]
    .concat()
}

/// A DXF file with `entities` in its ENTITIES section (first entity on line 5).
fn dxf(entities: &str) -> String {
    format!("  0\nSECTION\n  2\nENTITIES\n{entities}  0\nENDSEC\n  0\nEOF\n")
}

#[test]
fn import_of_an_export_is_the_model() {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "example1.toml",
        "helix3d.toml",
        "bspline.toml",
        "nurbs-circle.toml",
    ] {
        let path = example(name);
        let code = run_in(
            dir.path(),
            &["export", path.to_str().unwrap(), "-o", "c.dxf"],
        )
        .0;
        assert_eq!(code, 0);
        let (code, stdout, stderr) = run_in(dir.path(), &["import", "c.dxf", "-o", "back.toml"]);
        assert_eq!(
            (code, stdout.as_str(), stderr.as_str()),
            (0, "", "c.dxf: imported 1 curve (1 SPLINE)\n"),
            "{name}"
        );
        let written = std::fs::read_to_string(dir.path().join("back.toml")).unwrap();
        let model = load(&path, &ReadOptions::default()).unwrap();
        assert_eq!(written, to_toml_string(&model), "{name}");
    }
    assert_eq!(files(dir.path()), ["back.toml", "c.dxf"]);
}

#[test]
fn import_chooses_among_several_curves_with_default_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let text = dxf(&format!(
        "  0\nTEXT\n  8\n0\n{}{}",
        quadratic("2"),
        quadratic("4")
    ));
    std::fs::write(dir.path().join("two.dxf"), text).unwrap();
    let (code, _, stderr) = run_in(dir.path(), &["import", "two.dxf", "-o", "q.toml"]);
    assert_eq!(
        (code, stderr.as_str()),
        (
            2,
            "two.dxf: imported 2 curves (2 SPLINE); skipped 1 TEXT (not a curve)\nerror: two.dxf holds 2 curves: choose one \
             with --index K (1 to 2) or write each to its own file with --all\n"
        )
    );
    let (code, _, stderr) = run_in(
        dir.path(),
        &["import", "two.dxf", "-o", "q.toml", "--index", "3"],
    );
    assert_eq!(
        (code, stderr.as_str()),
        (
            2,
            "two.dxf: imported 2 curves (2 SPLINE); skipped 1 TEXT (not a curve)\nerror: --index \
             3: two.dxf holds 2 curves (give 1 to 2)\n"
        )
    );
    assert_eq!(files(dir.path()), ["two.dxf"]);
    let args = [
        "import",
        "two.dxf",
        "-o",
        "q.json",
        "--index",
        "2",
        "--truth",
        "0.5",
        "--indeterminacy",
        "0.25",
    ];
    assert_eq!(run_in(dir.path(), &args).0, 0);
    let json = std::fs::read_to_string(dir.path().join("q.json")).unwrap();
    assert!(json.starts_with("{\n  \"kind\": \"bspline\",\n  \"membership\": \"neutrosophic\",\n  \"degree\": 2,\n  \"knots\": [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],"), "{json}");
    assert!(
        json.contains(
            "{ \"x\": 1.0, \"y\": 4.0, \"truth\": 0.5, \"indeterminacy\": 0.25, \"falsity\": 0.0 }"
        ),
        "{json}"
    );
    assert_eq!(
        run_in(dir.path(), &["import", "two.dxf", "-o", "q.toml", "--all"]).0,
        0
    );
    assert_eq!(
        files(dir.path()),
        ["q-1.toml", "q-2.toml", "q.json", "two.dxf"]
    );
    // The middle control points: y = 2, then y = 4; the degrees default to truth 1.
    let first = std::fs::read_to_string(dir.path().join("q-1.toml")).unwrap();
    assert!(
        first.contains("x = 1.0\ny = 2.0\ntruth = 1.0\nindeterminacy = 0.0\nfalsity = 0.0\n"),
        "{first}"
    );
    let second = std::fs::read_to_string(dir.path().join("q-2.toml")).unwrap();
    assert!(second.contains("x = 1.0\ny = 4.0\n"), "{second}");
}

#[test]
fn import_refusals_have_exact_messages_and_write_nothing() {
    let cases: [(&str, String, &[&str], i32, &str); 9] = [
        (
            "a.dxf",
            dxf(&quadratic("2").replace(" 71\n2\n", "")),
            &[],
            1,
            "error: a.dxf:5: the SPLINE has no degree (group code 71)",
        ),
        (
            "a.dxf",
            dxf(&quadratic("2").replace(" 72\n6\n", " 72\n5\n")),
            &[],
            1,
            "error: a.dxf:13: the number of knots (group code 72) is 5, but the SPLINE has 6 knots (group code 40)",
        ),
        (
            "a.dxf",
            dxf(&quadratic("2").replace(" 71\n2\n", " 71\n1\n")),
            &[],
            1,
            "error: a.dxf:13: knot vector has 6 knots, expected 5 (number of control points + degree + 1)",
        ),
        (
            "a.dxf",
            dxf("  0\nCIRCLE\n  8\n0\n"),
            &[],
            1,
            "error: a.dxf:5: the CIRCLE has no centre x (group code 10)",
        ),
        (
            "a.txt",
            "<svg/>".to_owned(),
            &[],
            2,
            "error: a.txt: unsupported file extension `.txt` (accepted: .dxf, .svg)",
        ),
        (
            "a.svg",
            "<svg>\n<path d=\"M 0 0 Q 1 1\"/>\n</svg>".to_owned(),
            &[],
            1,
            "error: a.svg: the file has no curve to import (imported no curve; empty: 1 <path> \
             (draws nothing); 1 warning: line 2: <path>: d: unexpected end of stream; drawn up to \
             it (0 segments kept), as the SVG specification says)",
        ),
        (
            "a.svg",
            "<svg><rect width=\"3\" height=\"0\"/><text>a</text></svg>".to_owned(),
            &[],
            1,
            "error: a.svg: the file has no curve to import (imported no curve; skipped 1 <text> \
             (not a curve); empty: 1 <rect> (draws nothing))",
        ),
        (
            "a.dxf",
            dxf(&quadratic("2")),
            &["--falsity", "-0.5"],
            2,
            "error: truth, indeterminacy, falsity: falsity = -0.5 is outside [0, 1] (every degree must be in [0, 1])",
        ),
        (
            "a.dxf",
            dxf(&quadratic("2")),
            &["--index", "0"],
            2,
            "error: invalid value '0' for '--index <K>': 0 is not in 1..18446744073709551615\n\nFor more information, try '--help'.",
        ),
    ];
    for (name, text, extra, code, message) in cases {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join(name), &text).unwrap();
        let mut args = vec!["import", name, "-o", "m.toml"];
        args.extend_from_slice(extra);
        let (got, stdout, stderr) = run_in(dir.path(), &args);
        assert_eq!(
            (got, stdout.as_str(), stderr.as_str()),
            (code, "", format!("{message}\n").as_str()),
            "{args:?}"
        );
        assert_eq!(files(dir.path()), [name], "{args:?}: a file was written");
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("big.svg"),
        "<svg><path d='M 0 0 L 1 1'/></svg>",
    )
    .unwrap();
    let args = ["--max-file-size", "20", "import", "big.svg", "-o", "m.toml"];
    let (code, _, stderr) = run_in(dir.path(), &args);
    assert_eq!(
        (code, stderr.as_str()),
        (
            1,
            "error: big.svg: the file is larger than 20 bytes, the limit for a file read whole \
             (TOML, JSON, DXF, SVG; raise it with --max-file-size or NEUTROSPLINE_MAX_FILE_SIZE; \
             CSV files are streamed and have no size limit)\n"
        )
    );
    let (code, _, stderr) = run_in(dir.path(), &["import", "none.dxf", "-o", "m.toml"]);
    assert_eq!(code, 1);
    assert!(
        stderr.starts_with("error: none.dxf: cannot read: "),
        "{stderr}"
    );
}

/// The numbers of every `points="..."` of the `<polyline>` elements of an SVG text, as points.
fn polylines(svg: &str) -> Vec<Vec<[f64; 2]>> {
    svg.match_indices("<polyline")
        .map(|(k, _)| {
            let tag = &svg[k..k + svg[k..].find('>').unwrap()];
            let start = tag.find("points=\"").unwrap() + 8;
            let text = &tag[start..start + tag[start..].find('"').unwrap()];
            let numbers: Vec<f64> = text
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|s| !s.is_empty())
                .map(|s| s.parse().unwrap())
                .collect();
            numbers.chunks_exact(2).map(|p| [p[0], p[1]]).collect()
        })
        .collect()
}

#[test]
fn import_of_a_plot_gives_curves_through_the_drawn_points() {
    let dir = tempfile::tempdir().unwrap();
    let path = example("example1.toml");
    let args = [
        "plot",
        path.to_str().unwrap(),
        "-o",
        "p.svg",
        "--view",
        "plane",
    ];
    assert_eq!(run_in(dir.path(), &args).0, 0);
    let svg = std::fs::read_to_string(dir.path().join("p.svg")).unwrap();
    let drawn = polylines(&svg);
    assert!(
        !drawn.is_empty() && drawn.iter().any(|p| p.len() > 20),
        "{drawn:?}"
    );
    let (code, _, stderr) = run_in(
        dir.path(),
        &["import", "p.svg", "-o", "c.json", "--all", "--truth", "0.5"],
    );
    // The figure's frame, axes, ticks and legend are shapes too; its labels are text.
    assert_eq!(
        (code, stderr.as_str()),
        (
            0,
            "p.svg: imported 46 curves (9 <rect>, 24 <line>, 2 <polyline>, 6 <polygon>, 5 \
             <circle>); skipped 31 <text> (not a curve); not drawn: 1 <rect> in <clipPath> \
             (definitions never used)\n"
        )
    );
    let curves: Vec<neutrospline_io::Model> = files(dir.path())
        .iter()
        .filter(|name| name.starts_with("c-"))
        .map(|name| load(dir.path().join(name), &ReadOptions::default()).unwrap())
        .collect();
    for points in &drawn {
        // Some imported curve is the polyline: a degree-1 B-spline whose value at knot k is
        // the k-th drawn point, exactly.
        let found = curves.iter().any(|model| {
            let Some(neutrospline::DynCurve::Planar(curve)) = model.shape().curve() else {
                return false;
            };
            curve.degree() == 1
                && neutrospline::ControlPolygon::len(curve) == points.len()
                && points.iter().enumerate().all(|(k, p)| {
                    let q = neutrospline::Evaluate::evaluate(curve, k as f64).unwrap();
                    q.position == *p && q.degrees.truth() == 0.5
                })
        });
        assert!(
            found,
            "no imported curve through the {} drawn points",
            points.len()
        );
    }
}

#[test]
fn import_reports_what_it_skipped_and_strict_refuses_it() {
    let dir = tempfile::tempdir().unwrap();
    let drawing = example("drawing.svg");
    let shown = drawing.to_str().unwrap();
    let (code, stdout, stderr) = run_in(dir.path(), &["import", shown, "-o", "c.toml", "--all"]);
    assert_eq!(
        (code, stdout.as_str(), stderr.as_str()),
        (
            0,
            "",
            format!(
                "{shown}: imported 2 curves (1 <path>, 1 <rect>); skipped 1 <text> (not a \
                 curve); hidden: 1 <line> (not displayed)\n"
            )
            .as_str()
        )
    );
    assert_eq!(files(dir.path()), ["c-1.toml", "c-2.toml"]);
    // --strict: the text is a drawn shape left out; nothing is written.
    let out = tempfile::tempdir().unwrap();
    let (code, _, stderr) = run_in(
        out.path(),
        &["import", shown, "-o", "c.toml", "--all", "--strict"],
    );
    assert_eq!(code, 1);
    assert!(
        stderr.ends_with(&format!(
            "error: {shown}: --strict: the import leaves out what the file draws: skipped 1 \
             <text> (not a curve)\n"
        )),
        "{stderr}"
    );
    assert!(files(out.path()).is_empty());
    // --entities: only the rectangle; the path is reported as excluded.
    let (code, _, stderr) = run_in(
        out.path(),
        &["import", shown, "-o", "r.toml", "--entities", "rect"],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("excluded by --entities: 1 <path>"),
        "{stderr}"
    );
    let rect = std::fs::read_to_string(out.path().join("r.toml")).unwrap();
    assert!(rect.contains("name = \"plot\""), "{rect}");
    let (code, _, stderr) = run_in(
        out.path(),
        &["import", shown, "-o", "r.toml", "--entities", "SPLINE"],
    );
    assert_eq!(
        (code, stderr.as_str()),
        (
            2,
            "error: entities = SPLINE: not an element the SVG importer reads (one of path, \
             polyline, polygon, line, rect, circle, ellipse)\n"
        )
    );
}
