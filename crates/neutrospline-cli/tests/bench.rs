//! End-to-end test of `neutrospline bench`: the JSON object and its fields.

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_neutrospline");

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
        text.starts_with("batch evaluation: random(seed=1) (degree 15), 5000 points, 2 threads"),
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
