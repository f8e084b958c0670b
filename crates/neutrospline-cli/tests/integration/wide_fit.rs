//! End-to-end tests of `neutrospline fit` on the data of the families of two lanes
//! (docs/model.md, "Lanes"): the channel columns read with located errors, the curve and
//! surface fitted with every channel under the whole rule (the fitted model passes `check`,
//! and its control channels are checked here against the rule written out by hand), the
//! report naming the family's channels, and the refusals.

use crate::util::{load_model as load, run_in, succeeds as ok};

/// Interval-intuitionistic data on the rule's boundary with jumps (T_U + F_U = 1, collapsed
/// intervals, channels at 0 and 1): the free least squares breaks the rule.
fn interval_intuitionistic_csv() -> String {
    let mut text = String::from("x,y,truth_lower,truth_upper,falsity_lower,falsity_upper\n");
    for k in 0..30 {
        let t = f64::from(k) / 29.0;
        let tu = if (k / 5) % 2 == 0 { 1.0 } else { 0.25 };
        let fu = 1.0 - tu;
        let tl = if k % 3 == 0 { tu } else { tu * 0.5 };
        text.push_str(&format!(
            "{},{},{tl},{tu},{},{fu}\n",
            4.0 * t,
            (3.0 * t).sin(),
            fu * 0.5
        ));
    }
    text
}

/// The rule of interval-intuitionistic channels `[T_L, T_U, F_L, F_U]`, written out.
fn interval_intuitionistic_rule(c: &[f64]) -> bool {
    c.iter().all(|v| (0.0..=1.0).contains(v)) && c[0] <= c[1] && c[2] <= c[3] && c[1] + c[3] <= 1.0
}

#[test]
fn a_curve_is_fitted_to_interval_intuitionistic_data_under_the_whole_rule() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("ii.csv"), interval_intuitionistic_csv()).unwrap();
    let out = ok(
        d,
        &[
            "fit",
            "ii.csv",
            "--membership",
            "interval-intuitionistic",
            "--control-points",
            "8",
            "-o",
            "ii.toml",
        ],
    );
    // The text report lists the positions and the four channels by name.
    let channels: Vec<&str> = out
        .stderr
        .lines()
        .skip_while(|l| !l.starts_with("channel"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .map(|l| l.split_whitespace().next().unwrap())
        .collect();
    assert_eq!(
        channels,
        [
            "x",
            "y",
            "truth_lower",
            "truth_upper",
            "falsity_lower",
            "falsity_upper"
        ]
    );
    assert!(
        out.stderr.contains("truth_upper + falsity_upper = 1"),
        "{}",
        out.stderr
    );
    let check = ok(d, &["check", "ii.toml"]);
    assert!(
        check.stdout.starts_with("ii.toml: valid"),
        "{}",
        check.stdout
    );
    let model = load(&d.join("ii.toml"));
    assert_eq!(model.membership().to_string(), "interval-intuitionistic");
    let controls = model.control_channels();
    assert_eq!(controls.len(), 8);
    for (i, c) in controls.iter().enumerate() {
        assert!(interval_intuitionistic_rule(c), "control point {i}: {c:?}");
    }
    // The rule binds: some control point sits on T_U + F_U = 1 and some interval collapses
    // or reaches a box end.
    assert!(controls.iter().any(|c| c[1] + c[3] == 1.0));
    // The JSON report names the same channels.
    let json = run_in(
        d,
        &[
            "fit",
            "ii.csv",
            "--membership",
            "interval-intuitionistic",
            "--control-points",
            "8",
            "--report",
            "json",
            "-o",
            "again.toml",
        ],
        None,
    );
    let report: serde_json::Value = serde_json::from_str(json.stderr.trim()).unwrap();
    let mut keys: Vec<&str> = report["max_error"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        [
            "falsity_lower",
            "falsity_upper",
            "truth_lower",
            "truth_upper",
            "x",
            "y"
        ]
    );
    assert_eq!(
        std::fs::read(d.join("ii.toml")).unwrap(),
        std::fs::read(d.join("again.toml")).unwrap()
    );
}

#[test]
fn a_surface_is_fitted_to_bipolar_data_and_passes_check() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut text = String::from(
        "x,y,z,truth,indeterminacy,falsity,negative_truth,negative_indeterminacy,\
         negative_falsity\n",
    );
    for k in 0..6 {
        for l in 0..5 {
            let high = (k + l) % 2 == 0;
            let (p, n) = if high {
                ("1,0,0", "-1,0,0")
            } else {
                ("0,1,1", "0,-1,-1")
            };
            text.push_str(&format!("{k},{l},{},{p},{n}\n", 0.1 * f64::from(k * l)));
        }
    }
    std::fs::write(d.join("b.csv"), text).unwrap();
    ok(
        d,
        &[
            "fit",
            "b.csv",
            "--surface",
            "--grid",
            "6x5",
            "--control-points",
            "4,4",
            "--membership",
            "bipolar-neutrosophic",
            "-o",
            "b.toml",
        ],
    );
    let check = ok(d, &["check", "b.toml"]);
    assert!(
        check.stdout.starts_with("b.toml: valid"),
        "{}",
        check.stdout
    );
    let model = load(&d.join("b.toml"));
    let controls = model.control_channels();
    assert_eq!(controls.len(), 16);
    for (i, c) in controls.iter().enumerate() {
        let positive = c[..3].iter().all(|v| (0.0..=1.0).contains(v));
        let negative = c[3..].iter().all(|v| (-1.0..=0.0).contains(v));
        assert!(positive && negative, "control point {i}: {c:?}");
    }
    // The alternating data overshoots the boxes in a free fit: some channel is held at an end.
    assert!(controls
        .iter()
        .any(|c| c.iter().any(|v| *v == 1.0 || *v == -1.0 || *v == 0.0)));
}

#[test]
fn wide_data_errors_are_located_and_say_why() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fails = |file: &str, text: &str, family: &str, extra: &[&str]| -> String {
        std::fs::write(d.join(file), text).unwrap();
        let mut args = vec!["fit", file, "--membership", family, "-o", "out.toml"];
        args.extend_from_slice(extra);
        let out = run_in(d, &args, None);
        assert_ne!(out.code, 0, "{args:?}");
        assert!(!d.join("out.toml").exists(), "{args:?}");
        out.stderr
    };
    assert_eq!(
        fails(
            "t2.csv",
            "x,y,truth_lower,truth_upper\n0,0,0.1,0.2\n1,1,0.5,0.4\n2,0,0.3,0.3\n",
            "interval-type2",
            &[],
        ),
        "error: t2.csv:3: truth_lower = 0.5 exceeds truth_upper = 0.4 (interval-type2 rule: \
         lower <= upper)\n"
    );
    assert_eq!(
        fails("t.csv", "x,y,truth_lower\n0,0,0.1\n", "interval-type2", &[]),
        "error: t.csv:1: missing column `truth_upper` (interval-type2 rule requires it)\n"
    );
    assert_eq!(
        fails(
            "n.csv",
            "x,y,truth,falsity,negative_truth\n0,0,0.1,0.2,0\n",
            "pythagorean",
            &[],
        ),
        "error: n.csv:1: column `negative_truth` does not apply to membership pythagorean \
         (its channels: truth, falsity); `negative_truth` is a channel of \
         bipolar-neutrosophic\n"
    );
    assert_eq!(
        fails(
            "u.csv",
            "x,y,truth_lower,truth_uper\n0,0,0.1,0.2\n",
            "interval-type2",
            &[],
        ),
        "error: u.csv:1: unknown column `truth_uper` (known columns: x, y, z, truth (T), \
         indeterminacy (I), falsity (F), weight, name, parameter, u, v (membership \
         interval-type2: truth_lower, truth_upper))\n"
    );
    // The data view colours points by one degree: a wide fit's figure is refused with the
    // plot crate's reason, and nothing is written.
    std::fs::write(d.join("ii.csv"), interval_intuitionistic_csv()).unwrap();
    let out = run_in(
        d,
        &[
            "fit",
            "ii.csv",
            "--membership",
            "interval-intuitionistic",
            "-o",
            "out.toml",
            "--plot",
            "fit.png",
        ],
        None,
    );
    assert_eq!(out.code, 1);
    assert!(
        out.stderr
            .contains("the data view colours data points by one degree"),
        "{}",
        out.stderr
    );
    assert!(!d.join("out.toml").exists() && !d.join("fit.png").exists());
}

/// The JSON report of a family of one lane lists the channels it carries by their own names
/// (a Pythagorean fit's report once labelled its falsity residual `indeterminacy`).
#[test]
fn a_pythagorean_reports_channels_keep_their_names() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(
        d.join("p.csv"),
        "x,y,truth,falsity\n0,0,1,0\n1,1,0,1\n2,0,0.6,0.8\n3,1,1,0\n4,0,0,1\n",
    )
    .unwrap();
    let out = ok(
        d,
        &[
            "fit",
            "p.csv",
            "--membership",
            "pythagorean",
            "--control-points",
            "4",
            "--degree",
            "2",
            "--report",
            "json",
            "-o",
            "p.toml",
        ],
    );
    let report: serde_json::Value = serde_json::from_str(out.stderr.trim()).unwrap();
    let text = ok(
        d,
        &[
            "fit",
            "p.csv",
            "--membership",
            "pythagorean",
            "--control-points",
            "4",
            "--degree",
            "2",
            "-o",
            "p2.toml",
        ],
    );
    let max = report["max_error"].as_object().unwrap();
    let mut keys: Vec<&str> = max.keys().map(String::as_str).collect();
    keys.sort_unstable();
    assert_eq!(keys, ["falsity", "truth", "x", "y"]);
    // The text report's falsity line holds the JSON's falsity value.
    let line = text
        .stderr
        .lines()
        .find(|l| l.trim_start().starts_with("falsity "))
        .unwrap();
    let value: f64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    assert_eq!(value, max["falsity"].as_f64().unwrap());
}
