//! End-to-end tests of `neutrospline relation M.csv N.csv`: the paper's Def. 4. The axis sets of
//! `examples/relation/` are built so that the largest relation on the pairs of Example 1's
//! control points is exactly Table 1 of the paper (each degree the smaller of M's at r and N's
//! at s, worked out by hand below), so the model it writes evaluates as `examples/example1.toml`.

use crate::util::{dir_with, example, ok, rows, run};

/// A temporary directory with the relation examples and Example 1, and the given files.
fn dir(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = dir_with(files);
    for name in ["m.csv", "n.csv", "pairs.csv"] {
        std::fs::copy(example(&format!("relation/{name}")), dir.path().join(name)).unwrap();
    }
    std::fs::copy(example("example1.toml"), dir.path().join("example1.toml")).unwrap();
    dir
}

#[test]
fn the_relation_on_example_1s_pairs_is_table_1_of_the_paper() {
    let d = dir(&[]);
    let table = ok(
        d.path(),
        &["relation", "m.csv", "n.csv", "--pairs", "pairs.csv"],
    );
    assert_eq!(
        table.lines().next().unwrap(),
        "x,y,truth,indeterminacy,falsity"
    );
    // Table 1: C0 (1, 3) 0.3 0.6 0.1; C1 (3, 6) 0.8 0.1 0.1; C2 (6, 2) 0.7 0.1 0.2;
    // C3 (9, 5) 0.2 0.4 0.4. E.g. C0: M at 1 is (0.3, 0.9, 0.5), N at 3 is (0.8, 0.6, 0.1).
    assert_eq!(
        rows(&table),
        vec![
            vec![1.0, 3.0, 0.3, 0.6, 0.1],
            vec![3.0, 6.0, 0.8, 0.1, 0.1],
            vec![6.0, 2.0, 0.7, 0.1, 0.2],
            vec![9.0, 5.0, 0.2, 0.4, 0.4],
        ]
    );
    // As a model file, it is the paper's cubic: the same curve table as Example 1.
    ok(
        d.path(),
        &[
            "relation",
            "m.csv",
            "n.csv",
            "--pairs",
            "pairs.csv",
            "-o",
            "c.toml",
        ],
    );
    let ours = ok(d.path(), &["eval", "c.toml", "--samples", "11"]);
    let paper = ok(d.path(), &["eval", "example1.toml", "--samples", "11"]);
    assert_eq!(ours, paper);
}

#[test]
fn the_full_relation_lists_m_x_n_with_r_slowest_in_the_files_order() {
    let d = dir(&[]);
    let r = rows(&ok(d.path(), &["relation", "m.csv", "n.csv"]));
    assert_eq!(r.len(), 16);
    // N's members in its file's order: s = 3, 6, 2, 5.
    let pairs: Vec<(f64, f64)> = r.iter().map(|row| (row[0], row[1])).collect();
    assert_eq!(
        &pairs[..5],
        &[(1.0, 3.0), (1.0, 6.0), (1.0, 2.0), (1.0, 5.0), (3.0, 3.0)]
    );
    // (3, 2): min((0.9, 0.1, 0.3), (0.9, 0.1, 0.6)) = (0.9, 0.1, 0.3).
    assert_eq!(r[6], vec![3.0, 2.0, 0.9, 0.1, 0.3]);
    // (9, 6): min((0.6, 0.4, 0.4), (0.8, 0.7, 0.1)) = (0.6, 0.4, 0.1).
    assert_eq!(r[13], vec![9.0, 6.0, 0.6, 0.4, 0.1]);
    // A cubic B-spline through the 16 control points passes `check`.
    ok(
        d.path(),
        &[
            "relation", "m.csv", "n.csv", "--kind", "bspline", "--degree", "3", "-o", "b.json",
        ],
    );
    let report = ok(d.path(), &["check", "b.json"]);
    assert!(report.contains("control points: 16\n"), "{report}");
}

#[test]
fn check_accepts_a_relation_and_names_the_first_violation() {
    let d = dir(&[(
        "bad.csv",
        "x,y,truth,indeterminacy,falsity,name\n1,3,0.3,0.6,0.1,C0\n3,6,0.85,0.1,0.1,C1\n",
    )]);
    let out = ok(
        d.path(),
        &["relation", "m.csv", "n.csv", "--check", "example1.toml"],
    );
    assert_eq!(
        out,
        "example1.toml: the 4 control points form a neutrosophic point relation of m.csv (M) \
         and n.csv (N) (Def. 4)\n"
    );
    let (code, stdout, stderr) = run(
        d.path(),
        &["relation", "m.csv", "n.csv", "--check", "bad.csv"],
    );
    assert_eq!((code, stdout.as_str()), (1, ""));
    // C1's truth 0.85 is below M's 0.9 at r = 3 but above N's 0.8 at s = 6 (n.csv line 4).
    assert_eq!(
        stderr,
        "error: bad.csv: control point 1 (C1): pair 1 at (3, 6): truth = 0.85 exceeds 0.8, the \
         truth of N at s = 6 (Def. 4: each degree of the relation must be <= the same degree of M \
         at r and of N at s); n.csv:4\n"
    );
}

#[test]
fn bad_input_is_refused_with_its_place() {
    let d = dir(&[
        ("p.csv", "r,s\n1,3\n2,3\n"),
        ("m2.csv", "r,T,I,F\n1,0.3,0.6,0.1\n1,0.5,0.5,0.5\n"),
        (
            "surface.toml",
            &std::fs::read_to_string(example("surface.toml")).unwrap(),
        ),
    ]);
    let cases: &[(&[&str], i32, &str)] = &[
        (
            &["relation", "m.csv", "n.csv", "--pairs", "p.csv"],
            1,
            "error: p.csv:3: pair 1 at (2, 3): r = 2 is not a member of M\n",
        ),
        (
            &["relation", "m2.csv", "n.csv"],
            1,
            "error: m2.csv:3: column `value`: value = 1 repeats line 2 (a set gives each value one set of degrees)\n",
        ),
        (
            &["relation", "m.csv", "n.csv", "--check", "surface.toml"],
            1,
            "error: surface.toml: a bezier-surface is not a relation: Def. 4 relates the control points of a plane curve (x = r, y = s)\n",
        ),
        (
            &["relation", "m.csv", "n.csv", "--kind", "bspline", "--degree", "20"],
            1,
            "",
        ),
    ];
    for (args, want_code, want) in cases {
        let (code, stdout, stderr) = run(d.path(), args);
        assert_eq!(code, *want_code, "{args:?}: {stderr}");
        assert_eq!(stdout, "", "{args:?}");
        if want.is_empty() {
            assert!(
                stderr.starts_with("error: the relation of m.csv and n.csv"),
                "{stderr}"
            );
        } else {
            assert_eq!(stderr, *want, "{args:?}");
        }
    }
    // An unknown output extension is a usage error, and no file is written.
    let (code, _, stderr) = run(d.path(), &["relation", "m.csv", "n.csv", "-o", "r.txt"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(!d.path().join("r.txt").exists());
}
