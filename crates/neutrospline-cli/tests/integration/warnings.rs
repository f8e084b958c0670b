//! Warnings against misuse: `fit` of 3-D points that are no ordered path, `eval` of a table
//! that looks like measured data.

use crate::util::{example, run};

/// A helix sampled at t = 0.2 k, as CSV rows in the order `order` gives.
fn helix(order: impl Fn(usize) -> usize) -> String {
    let mut text = String::from("x,y,z,truth,indeterminacy,falsity\n");
    for k in 0..60 {
        let t = order(k) as f64 * 0.2;
        text.push_str(&format!(
            "{},{},{},0.8,0.1,0.1\n",
            t.cos(),
            t.sin(),
            0.1 * t
        ));
    }
    text
}

#[test]
fn fit_warns_of_points_out_of_path_order() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("ordered.csv"), helix(|k| k)).unwrap();
    // k -> 37 k mod 60 visits every point, far apart at each step.
    std::fs::write(dir.path().join("scrambled.csv"), helix(|k| (37 * k) % 60)).unwrap();
    let args = ["--control-points", "12", "-o", "m.toml"];
    let (code, _, stderr) = run(dir.path(), &[&["fit", "ordered.csv"][..], &args].concat());
    assert_eq!(code, 0, "{stderr}");
    assert!(!stderr.contains("warning"), "{stderr}");
    let (code, _, stderr) = run(dir.path(), &[&["fit", "scrambled.csv"][..], &args].concat());
    assert_eq!(code, 0, "{stderr}");
    let warning = stderr.lines().next().unwrap();
    assert!(
        warning.starts_with(
            "warning: scrambled.csv: the points do not look like an ordered path (consecutive \
             rows are "
        ),
        "{stderr}"
    );
    assert!(
        warning.ends_with("points scattered over an area are a surface: `fit --surface` fits one"),
        "{stderr}"
    );
    // Moving one row far from its place is two jumps.
    let mut rows: Vec<String> = helix(|k| k).lines().map(str::to_owned).collect();
    let row = rows.remove(6);
    rows.insert(51, row);
    std::fs::write(dir.path().join("moved.csv"), rows.join("\n") + "\n").unwrap();
    let (code, _, stderr) = run(dir.path(), &[&["fit", "moved.csv"][..], &args].concat());
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("(2 steps longer than 10 median steps, the longest "),
        "{stderr}"
    );
}

#[test]
fn eval_warns_of_a_table_that_looks_like_data() {
    let dir = tempfile::tempdir().unwrap();
    let survey = example("data/survey.csv").display().to_string();
    let (code, stdout, stderr) = run(dir.path(), &["eval", &survey, "--samples", "3"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout.lines().count(), 4);
    assert_eq!(
        stderr,
        format!(
            "warning: {survey}: its 80 rows are read as the control points of one Bézier curve \
             of degree 79; if they are measured points, `neutrospline fit {survey}` fits a \
             curve to them\n"
        )
    );
    // Example 1's four control points: no warning.
    let (code, _, stderr) = run(
        dir.path(),
        &["eval", &example("example1.csv").display().to_string()],
    );
    assert_eq!((code, stderr.as_str()), (0, ""));
    std::fs::write(
        dir.path().join("p.csv"),
        "x,y,truth,indeterminacy,falsity,parameter\n0,0,1,0,0,0\n1,1,1,0,0,1\n",
    )
    .unwrap();
    let (code, _, stderr) = run(dir.path(), &["eval", "p.csv"]);
    assert_eq!(code, 1);
    assert!(
        stderr.ends_with(
            "; a table of measured points (with a parameter or weight per point) is fitted by \
             `neutrospline fit FILE`, not evaluated\n"
        ),
        "{stderr}"
    );
}
