//! End-to-end test of `neutrospline bench`: the JSON object and its fields.

use std::process::Command;

use crate::util::BIN;

#[test]
fn bench_json_small() {
    let out = Command::new(BIN)
        .args(["bench", "--points", "1000", "--format", "json"])
        .output()
        .expect("binary runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert_eq!(
        text.lines().count(),
        1,
        "one JSON object on one line: {text}"
    );
    let v: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(v["degree"], 3);
    assert_eq!(v["points"], 1000);
    assert_eq!(v["threads"], 1);
    assert_eq!(v["curve"], "example1");
    for key in ["mpts_per_s", "write_reference_mpts_per_s", "best_seconds"] {
        assert!(v[key].as_f64().is_some_and(|x| x > 0.0), "{key}: {text}");
    }
}

#[test]
fn bench_spline_kinds() {
    for (kind, name) in [("bspline", "B-spline"), ("nurbs", "NURBS")] {
        let out = Command::new(BIN)
            .args(["bench", "--points", "2000", "--degree", "4", "--kind", kind])
            .args(["--pieces", "9", "--runs", "1", "--format", "json"])
            .output()
            .expect("binary runs");
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        assert_eq!(v["kind"], kind);
        assert_eq!(
            (v["degree"].as_u64(), v["pieces"].as_u64()),
            (Some(4), Some(9))
        );
        assert_eq!(v["curve"], "random(seed=1, pieces=9)");
        let out = Command::new(BIN)
            .args(["bench", "--points", "100", "--kind", kind, "--runs", "1"])
            .output()
            .expect("binary runs");
        let text = String::from_utf8(out.stdout).expect("UTF-8");
        assert!(
            text.starts_with(&format!(
                "batch evaluation: {name} random(seed=1, pieces=64) (degree 3)"
            )),
            "{text}"
        );
    }
    let out = Command::new(BIN)
        .args(["bench", "--kind", "nurbs", "--pieces", "0"])
        .output()
        .expect("binary runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--pieces"), "{err}");
}

#[test]
fn bench_text_random_curve_and_threads() {
    let out = Command::new(BIN)
        .args([
            "bench",
            "--points",
            "5000",
            "--degree",
            "15",
            "--threads",
            "2",
            "--runs",
            "1",
        ])
        .output()
        .expect("binary runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        text.starts_with(
            "batch evaluation: Bézier random(seed=1) (degree 15), 5000 points, 2 threads"
        ),
        "{text}"
    );
    assert!(text.contains("Mpts/s"), "{text}");
}

#[test]
fn bench_rejects_zero_runs() {
    let out = Command::new(BIN)
        .args(["bench", "--runs", "0"])
        .output()
        .expect("binary runs");
    assert_eq!(out.status.code(), Some(2));
}
