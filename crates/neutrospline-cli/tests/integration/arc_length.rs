//! `eval --arc-length-samples N`: points evenly spaced along the curve. Example 1's arc lengths
//! at the samples are k L / (N - 1) with L from mpmath (scripts/reference/
//! make_arc_length_reference.py), and the misuses are refused.

use crate::util::{example, run_in};

/// Printed by scripts/reference/make_arc_length_reference.py (mpmath.quad at 50 digits).
const EXAMPLE1_LENGTH: f64 = 8.786730707839524;

#[test]
fn arc_length_samples_are_evenly_spaced_along_example1() {
    let dir = tempfile::tempdir().unwrap();
    let model = example("example1.toml");
    let out = run_in(
        dir.path(),
        &[
            "eval",
            model.to_str().unwrap(),
            "--arc-length-samples",
            "9",
            "--geometry",
            "--accuracy",
            "1e-13",
        ],
        None,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let mut lines = out.stdout.lines();
    assert_eq!(
        lines.next(),
        Some("t,x,y,truth,indeterminacy,falsity,arc_length,curvature")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 9);
    assert_eq!((rows[0][0], rows[8][0]), (0.0, 1.0));
    for (k, row) in rows.iter().enumerate() {
        let want = EXAMPLE1_LENGTH * k as f64 / 8.0;
        assert!(
            (row[6] - want).abs() <= 1e-12 * EXAMPLE1_LENGTH,
            "k = {k}: {} vs {want}",
            row[6]
        );
    }
    for (args, message) in [
        (vec!["--arc-length-samples", "3", "--at", "0.5"], "cannot be used with"),
        (vec!["--accuracy", "1e-9"], "error: --accuracy goes with --geometry or --arc-length-samples (the accuracy of arc lengths)"),
        (vec!["--arc-length-samples", "0"], "invalid value '0' for '--arc-length-samples <N>'"),
    ] {
        let mut argv = vec!["eval", model.to_str().unwrap()];
        argv.extend(&args);
        let out = run_in(dir.path(), &argv, None);
        assert_eq!(out.code, 2, "{args:?}");
        assert!(out.stderr.contains(message), "{args:?}: {}", out.stderr);
    }
    let surface = example("surface.toml");
    let out = run_in(
        dir.path(),
        &[
            "eval",
            surface.to_str().unwrap(),
            "--arc-length-samples",
            "3",
        ],
        None,
    );
    assert_eq!(out.code, 2);
    assert!(
        out.stderr
            .contains("--arc-length-samples applies only to curves"),
        "{}",
        out.stderr
    );
}
