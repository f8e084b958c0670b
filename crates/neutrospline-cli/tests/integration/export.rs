//! End-to-end tests of `neutrospline export`: the files are the library's exports byte for
//! byte, small exports are checked line by line, and every refusal has its exact message, its
//! exit status and leaves no output file.

use std::path::Path;

use neutrospline_exchange::{ColorBy, ExportFormat, ExportOptions};
use neutrospline_io::{load, ReadOptions};

use crate::util::{example, Output};

/// Runs the binary in `dir`, with the file `stdin` as standard input if given.
fn run_in(dir: &Path, args: &[&str], stdin: Option<&Path>) -> Output {
    let input = stdin.map(|path| std::fs::read(path).expect("stdin file"));
    crate::util::run_in(dir, args, input.as_deref())
}

/// Exports `model` with `args` in a fresh directory and expects `code` and exactly `message`
/// on standard error, nothing on standard output, and no file left in the directory.
fn assert_refused(model: &Path, out: &str, args: &[&str], code: i32, message: &str) {
    let dir = tempfile::tempdir().unwrap();
    let mut all = vec!["export", model.to_str().unwrap(), "-o", out];
    all.extend_from_slice(args);
    let result = run_in(dir.path(), &all, None);
    assert_eq!(
        (result.code, result.stderr.as_str(), result.stdout.as_str()),
        (code, format!("{message}\n").as_str(), ""),
        "{all:?}"
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "a file was left"
    );
}

#[test]
fn export_writes_the_library_bytes_for_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &str, &[&str], ExportOptions); 7] = [
        ("example1.toml", "a.dxf", &[], ExportOptions::new()),
        ("nurbs-circle.toml", "b.dxf", &[], ExportOptions::new()),
        (
            "surface.toml",
            "c.dxf",
            &["--mesh", "--samples", "7"],
            ExportOptions::new().with_mesh(true).with_samples(Some(7)),
        ),
        (
            "nurbs-surface.json",
            "d.glb",
            &["--color-by", "falsity"],
            ExportOptions::new().with_color_by(ColorBy::Falsity),
        ),
        (
            "helix3d.toml",
            "e.gltf",
            &["--samples", "50"],
            ExportOptions::new().with_samples(Some(50)),
        ),
        (
            "bspline.toml",
            "f.ply",
            &["--ascii", "--color-by", "score"],
            ExportOptions::new()
                .with_ascii(true)
                .with_color_by(ColorBy::Score),
        ),
        (
            "surface.toml",
            "g.obj",
            &["--samples", "9"],
            ExportOptions::new().with_samples(Some(9)),
        ),
    ];
    for (model, out, args, options) in cases {
        let path = example(model);
        let mut all = vec!["export", path.to_str().unwrap(), "-o", out];
        all.extend_from_slice(args);
        let result = run_in(dir.path(), &all, None);
        assert_eq!(
            (result.code, result.stderr.as_str(), result.stdout.as_str()),
            (0, "", ""),
            "{all:?}"
        );
        let written = std::fs::read(dir.path().join(out)).unwrap();
        let model = load(&path, &ReadOptions::default()).unwrap();
        let format = ExportFormat::from_path(out).unwrap();
        let expected = neutrospline_exchange::export(&model, format, &options).unwrap();
        assert!(written == expected, "{out}: not the library's export");
    }
    // Nothing but the seven files (no temporary file left behind).
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 7);
}

#[test]
fn export_ply_ascii_of_example1_line_by_line() {
    // CSV from standard input; three samples at t = 0, 0.5, 1. At t = 0.5 the curve is at
    // (4.625, 4) with truth 0.625, indeterminacy 0.2 and falsity 0.175 (docs/model.md,
    // section 5), written to the last bit of their rounded values; the colour is viridis of
    // the score (2 + T - I - F) / 3.
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "export",
        "-",
        "-o",
        "e.ply",
        "--ascii",
        "--samples",
        "3",
        "--color-by",
        "score",
    ];
    let result = run_in(dir.path(), &args, Some(&example("example1.csv")));
    assert_eq!((result.code, result.stderr.as_str()), (0, ""));
    let text = std::fs::read_to_string(dir.path().join("e.ply")).unwrap();
    let expected = "\
ply
format ascii 1.0
comment neutrospline export of a bezier
comment membership: neutrosophic
comment red green blue: viridis of score
element vertex 3
property double x
property double y
property double z
property uchar red
property uchar green
property uchar blue
property double truth
property double indeterminacy
property double falsity
element edge 2
property uint vertex1
property uint vertex2
end_header
1 3 0 33 153 137 0.3 0.6 0.1
4.625 4 0 95 200 97 0.625 0.2 0.17500000000000002
9 5 0 36 137 141 0.2 0.4 0.4
0 1
1 2
";
    assert_eq!(text, expected);
    let score = |t: f64, i: f64, f: f64| neutrospline::color::viridis((2.0 + t - i - f) / 3.0);
    assert_eq!(score(0.3, 0.6, 0.1), [33, 153, 137]);
    assert_eq!(score(0.2, 0.4, 0.4), [36, 137, 141]);
}

#[test]
fn export_obj_of_example1_line_by_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = example("example1.toml");
    let args = [
        "export",
        path.to_str().unwrap(),
        "-o",
        "e.obj",
        "--samples",
        "3",
    ];
    assert_eq!(run_in(dir.path(), &args, None).code, 0);
    let text = std::fs::read_to_string(dir.path().join("e.obj")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "# neutrospline export of a bezier \"Example 1\"");
    assert!(lines[1].starts_with("# description: Example 1 of \"A Neutrosophic Bezier Curve Model"));
    assert_eq!(
        lines[5..],
        [
            "o Example 1",
            "v 1 3 0 0.207843 0.372549 0.552941",
            "v 4.625 4 0 0.168627 0.682353 0.498039",
            "v 9 5 0 0.254902 0.266667 0.529412",
            "l 1 2 3",
            "#deg 0.3 0.6 0.1",
            "#deg 0.625 0.2 0.17500000000000002",
            "#deg 0.2 0.4 0.4",
        ]
    );
}

#[test]
fn export_dxf_of_example1_holds_the_exact_spline() {
    let dir = tempfile::tempdir().unwrap();
    let path = example("example1.toml");
    let args = ["export", path.to_str().unwrap(), "-o", "e.DXF"];
    assert_eq!(run_in(dir.path(), &args, None).code, 0);
    let text = std::fs::read_to_string(dir.path().join("e.DXF")).unwrap();
    let spline =
        &text[text.find("  0\nSPLINE\n").unwrap()..text.find("1001\nNEUTROSPLINE\n").unwrap()];
    let tail = spline.split_once(" 71\n").unwrap().1;
    assert_eq!(
        tail,
        [
            "3\n 72\n8\n 73\n4\n 74\n0\n 42\n0.0000000001\n 43\n0.0000000001\n",
            " 40\n0\n 40\n0\n 40\n0\n 40\n0\n 40\n1\n 40\n1\n 40\n1\n 40\n1\n",
            " 10\n1\n 20\n3\n 30\n0\n 10\n3\n 20\n6\n 30\n0\n",
            " 10\n6\n 20\n2\n 30\n0\n 10\n9\n 20\n5\n 30\n0\n",
        ]
        .concat()
    );
}

#[test]
fn export_refusals_have_exact_messages_and_leave_no_file() {
    let curve = example("example1.toml");
    let surface = example("surface.toml");
    assert_refused(
        &curve,
        "e.stl",
        &[],
        2,
        "error: e.stl: unsupported file extension `.stl` (accepted: .dxf, .glb, .gltf, .ply, .obj, .step, .stp)",
    );
    assert_refused(
        &surface,
        "s.dxf",
        &[],
        1,
        &format!(
            "error: {}: a bezier-surface cannot be a DXF SPLINE (a SPLINE entity is a curve): \
             export it as a mesh with --mesh (a POLYFACE mesh), or to .glb, .gltf, .ply or .obj",
            surface.display()
        ),
    );
    assert_refused(
        &curve,
        "e.obj",
        &["--ascii"],
        2,
        "error: --ascii applies to PLY files only (the output is OBJ)",
    );
    assert_refused(
        &surface,
        "s.glb",
        &["--mesh"],
        2,
        "error: --mesh applies to DXF files only (GLB holds surfaces as meshes anyway)",
    );
    assert_refused(
        &curve,
        "e.dxf",
        &["--mesh"],
        2,
        "error: --mesh applies to surfaces only (a curve is written as an exact SPLINE entity)",
    );
    assert_refused(
        &curve,
        "e.dxf",
        &["--samples", "20"],
        2,
        "error: --samples does not apply to a DXF SPLINE, which is exact (it applies to --mesh)",
    );
    assert_refused(
        &curve,
        "e.ply",
        &["--samples", "1"],
        2,
        "error: --samples 1 is out of range (2 to 10000000 along a curve)",
    );
    assert_refused(
        &surface,
        "s.ply",
        &["--samples", "5000"],
        2,
        "error: --samples 5000 is out of range (2 to 4096 per direction of a surface)",
    );
    assert_refused(
        &curve,
        "e.ply",
        &["--color-by", "Truth"],
        2,
        "error: invalid value 'Truth' for '--color-by <VALUE>': unknown colouring `Truth` (known: truth, indeterminacy, falsity, score)\n\n\
         For more information, try '--help'.",
    );
}

#[test]
fn export_of_an_invalid_model_is_located_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bad.csv"),
        "x,y,truth,indeterminacy,falsity\n1,2,0.5,0,0\n3,4,1.2,0,0\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("out.glb"), "old").unwrap();
    let result = run_in(dir.path(), &["export", "bad.csv", "-o", "out.glb"], None);
    assert_eq!(
        (result.code, result.stderr.as_str()),
        (
            1,
            "error: bad.csv:3: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])\n"
        )
    );
    // The old file is untouched and no temporary file is left.
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.glb")).unwrap(),
        "old"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    let missing = run_in(dir.path(), &["export", "none.toml", "-o", "out.glb"], None);
    assert_eq!(missing.code, 1);
    assert!(
        missing
            .stderr
            .starts_with("error: none.toml: cannot read: "),
        "{}",
        missing.stderr
    );
    let result = run_in(
        dir.path(),
        &["export", "bad.csv", "-o", "no/such/dir/out.ply"],
        None,
    );
    assert_eq!(result.code, 1);
    let dir_path = example("example1.toml");
    let result = run_in(
        dir.path(),
        &[
            "export",
            dir_path.to_str().unwrap(),
            "-o",
            "no/such/dir/out.ply",
        ],
        None,
    );
    assert_eq!(result.code, 1);
    assert!(
        result
            .stderr
            .starts_with("error: no/such/dir/out.ply: cannot write: "),
        "{}",
        result.stderr
    );
}
