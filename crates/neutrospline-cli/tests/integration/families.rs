//! The membership families beyond the original three (SPEC section 10; the examples in
//! `examples/families/`) from end to end: `eval` columns, derived degrees and scores against
//! their closed forms, `check`'s rule line, refusals with the rule they break, the writers'
//! `membership = "q-rung"` with `q = 4`, `fit` under a round rule passing `check`, and the
//! plot views that would misdraw a family refused with the reason, and the DXF export read
//! back with its family.

use std::path::Path;

use crate::util::{dir_with, run_in, Output};

const PYTHAGOREAN: &str = include_str!("../../../../examples/families/pythagorean.toml");
const Q_RUNG: &str = include_str!("../../../../examples/families/q-rung.toml");
const PICTURE: &str = include_str!("../../../../examples/families/picture.toml");
const SPHERICAL: &str = include_str!("../../../../examples/families/spherical.toml");
const T_SPHERICAL: &str = include_str!("../../../../examples/families/t-spherical.toml");
const FERMATEAN: &str = include_str!("../../../../examples/families/fermatean.toml");

fn ok(dir: &Path, args: &[&str]) -> Output {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    out
}

fn fails(dir: &Path, args: &[&str]) -> String {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, 1, "{args:?} should fail: {}", out.stdout);
    assert!(out.stdout.is_empty(), "{args:?}: {}", out.stdout);
    out.stderr
}

/// The header and the rows of a CSV table.
fn table(out: &Output) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = out.stdout.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-15 * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// The cubic Bernstein blend of four values at `t`.
fn cubic(values: [f64; 4], t: f64) -> f64 {
    let s = 1.0 - t;
    values[0] * s * s * s
        + 3.0 * values[1] * s * s * t
        + 3.0 * values[2] * s * t * t
        + values[3] * t * t * t
}

#[test]
fn pythagorean_eval_has_its_channels_hesitation_and_scores() {
    let dir = dir_with(&[("p.toml", PYTHAGOREAN)]);
    let out = ok(
        dir.path(),
        &["eval", "p.toml", "--at", "0,0.25,0.5,1", "--scores"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header,
        [
            "t",
            "x",
            "y",
            "truth",
            "falsity",
            "hesitation",
            "score",
            "accuracy"
        ]
    );
    for row in rows {
        let t = row[0];
        let truth = cubic([0.9, 0.8, 0.6, 0.5], t);
        let falsity = cubic([0.3, 0.6, 0.8, 0.5], t);
        close(row[3], truth, "truth");
        close(row[4], falsity, "falsity");
        // Yager: hesitation sqrt(1 - T^2 - F^2), score T^2 - F^2, accuracy T^2 + F^2.
        let sum = truth * truth + falsity * falsity;
        assert!(sum <= 1.0 + 1e-15, "t = {t}: {sum}");
        close(row[5], (1.0 - sum).sqrt(), "hesitation");
        close(row[6], truth * truth - falsity * falsity, "score");
        close(row[7], sum, "accuracy");
    }
}

#[test]
fn every_family_example_stays_inside_its_rule_at_ten_thousand_parameters() {
    // (file, text, channel columns, power of the rule's sum)
    let cases: [(&str, &str, &[&str], i32); 6] = [
        ("p.toml", PYTHAGOREAN, &["truth", "falsity"], 2),
        ("f.toml", FERMATEAN, &["truth", "falsity"], 3),
        ("q.toml", Q_RUNG, &["truth", "falsity"], 4),
        ("c.toml", PICTURE, &["truth", "indeterminacy", "falsity"], 1),
        (
            "s.toml",
            SPHERICAL,
            &["truth", "indeterminacy", "falsity"],
            2,
        ),
        (
            "t.toml",
            T_SPHERICAL,
            &["truth", "indeterminacy", "falsity"],
            3,
        ),
    ];
    for (name, text, channels, power) in cases {
        let dir = dir_with(&[(name, text)]);
        let (header, rows) = table(&ok(dir.path(), &["eval", name, "--samples", "10000"]));
        let index: Vec<usize> = channels
            .iter()
            .map(|c| header.iter().position(|h| h == c).unwrap())
            .collect();
        assert!(!header.iter().any(|h| h == "indeterminacy") || channels.len() == 3);
        let derived = index[index.len() - 1] + 1;
        let mut largest: f64 = 0.0;
        for row in &rows {
            let sum: f64 = index.iter().map(|&c| row[c].powi(power)).sum();
            largest = largest.max(sum);
            assert!(sum <= 1.0 + 1e-12, "{name} at t = {}: {sum}", row[0]);
            // The derived degree: (1 - sum)^(1/p), or the picture refusal 1 - T - I - F.
            let want = (1.0 - sum).max(0.0).powf(1.0 / f64::from(power));
            assert!((row[derived] - want).abs() <= 1e-9, "{name}: {row:?}");
        }
        // The examples put control points on the boundary; the curve reaches it at an end
        // or stays inside.
        assert!(largest > 0.5, "{name}: {largest}");
    }
}

#[test]
fn check_prints_the_channels_and_the_rule() {
    let dir = dir_with(&[("q.toml", Q_RUNG), ("p.toml", PYTHAGOREAN)]);
    let out = ok(dir.path(), &["check", "q.toml"]).stdout;
    assert!(out.contains("membership: q-rung:4\n"), "{out}");
    assert!(out.contains("truth: 0.4..1\nfalsity: 0..0.9\n"), "{out}");
    assert!(
        out.contains("rule: truth^4 + falsity^4 <= 1 (largest at the control points: 1)\n"),
        "{out}"
    );
    assert!(!out.contains("indeterminacy"), "{out}");
    let out = ok(dir.path(), &["check", "p.toml"]).stdout;
    assert!(out.contains("rule: truth^2 + falsity^2 <= 1"), "{out}");
}

#[test]
fn a_value_that_breaks_the_rule_is_refused_with_the_rule() {
    let table = "x,y,truth,falsity\n0,0,0.5,0.5\n1,1,0.9,0.7\n2,0,0.1,0.1\n";
    let broken = PYTHAGOREAN.replacen(
        "truth = 0.8\nfalsity = 0.6",
        "truth = 0.9\nfalsity = 0.7",
        1,
    );
    let no_q = Q_RUNG.replacen("q = 4\n", "", 1);
    let zero_q = Q_RUNG.replacen("q = 4\n", "q = 0\n", 1);
    let other_q = Q_RUNG.replacen("membership = \"q-rung\"", "membership = \"q-rung:3\"", 1);
    let q_on_pythagorean = PYTHAGOREAN.replacen(
        "membership = \"pythagorean\"",
        "membership = \"pythagorean\"\nq = 2",
        1,
    );
    let with_indeterminacy =
        PYTHAGOREAN.replacen("falsity = 0.3", "falsity = 0.3\nindeterminacy = 0.1", 1);
    let spherical_out = SPHERICAL.replacen(
        "truth = 0.6\nindeterminacy = 0.0",
        "truth = 0.6\nindeterminacy = 0.1",
        1,
    );
    let interval = PYTHAGOREAN.replacen("\"pythagorean\"", "\"interval-type2\"", 1);
    let dir = dir_with(&[
        ("bad.csv", table.to_owned()),
        ("bad.toml", broken),
        ("noq.toml", no_q),
        ("zeroq.toml", zero_q),
        ("otherq.toml", other_q),
        ("qp.toml", q_on_pythagorean),
        ("ind.toml", with_indeterminacy),
        ("sph.toml", spherical_out),
        ("int.toml", interval),
    ]);
    let cases: [(&[&str], &str); 10] = [
        (
            &["check", "bad.csv", "--membership", "pythagorean"],
            "error: bad.csv:3: truth^2 + falsity^2 = 1.3 exceeds 1 (pythagorean rule)\n",
        ),
        (
            &["check", "bad.csv", "--membership", "q-rung:1"],
            "error: bad.csv:3: truth + falsity = 1.6 exceeds 1 (q-rung:1 rule)\n",
        ),
        (
            &["check", "bad.toml"],
            "error: bad.toml:18: control_points[1]: truth^2 + falsity^2 = 1.3 exceeds 1 (pythagorean rule)\n",
        ),
        (
            &["check", "noq.toml"],
            "error: noq.toml:7: membership: membership \"q-rung\" needs its parameter: add `q = 4` (an integer >= 1) or write \"q-rung:4\"\n",
        ),
        (
            &["check", "zeroq.toml"],
            "error: zeroq.toml:8: q: `q` must be an integer >= 1 (the parameter of membership \"q-rung\"), found 0\n",
        ),
        (
            &["check", "otherq.toml"],
            "error: otherq.toml:7: membership: membership \"q-rung:3\" has q = 3 but key `q` says 4\n",
        ),
        (
            &["check", "qp.toml"],
            "error: qp.toml:10: q: key `q` is the parameter of membership \"q-rung\"; this model's membership is \"pythagorean\"\n",
        ),
        (
            &["check", "ind.toml"],
            "error: ind.toml:17: control_points[0]: indeterminacy = 0.1 is not allowed (pythagorean rule: only truth and falsity are given; indeterminacy must be absent or 0)\n",
        ),
        (
            &["check", "sph.toml"],
            "error: sph.toml:16: control_points[1]: truth^2 + indeterminacy^2 + falsity^2 = 1.01 exceeds 1 (spherical rule)\n",
        ),
        (
            &["check", "int.toml"],
            "error: int.toml:15: control_points[0]: key `truth` does not apply to membership interval-type2 (its channels: truth_lower, truth_upper)\n",
        ),
    ];
    for (args, want) in cases {
        assert_eq!(fails(dir.path(), args), want, "{args:?}");
    }
    let out = run_in(
        dir.path(),
        &["check", "bad.csv", "--membership", "q-rung"],
        None,
    );
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr.contains("the parameter is missing"),
        "{}",
        out.stderr
    );
}

#[test]
fn the_writers_keep_the_family_and_its_parameter() {
    let dir = dir_with(&[("q.toml", Q_RUNG), ("t.toml", T_SPHERICAL)]);
    for (input, output, key) in [
        ("q.toml", "q2.toml", "q = 4\n"),
        ("q.toml", "q2.json", "\"q\": 4"),
        ("t.toml", "t2.toml", "n = 3\n"),
    ] {
        ok(
            dir.path(),
            &["transform", input, "--elevate", "1", "-o", output],
        );
        let text = std::fs::read_to_string(dir.path().join(output)).unwrap();
        assert!(text.contains(key), "{output}: {text}");
        let before = table(&ok(
            dir.path(),
            &["eval", input, "--samples", "9", "--scores"],
        ));
        let after = table(&ok(
            dir.path(),
            &["eval", output, "--samples", "9", "--scores"],
        ));
        assert_eq!(before.0, after.0);
        for (a, b) in before.1.iter().zip(&after.1) {
            for (x, y) in a.iter().zip(b) {
                assert!((x - y).abs() <= 1e-14, "{output}: {a:?} vs {b:?}");
            }
        }
    }
    let text = std::fs::read_to_string(dir.path().join("q2.toml")).unwrap();
    assert!(text.contains("membership = \"q-rung\"\nq = 4\n"), "{text}");
}

#[test]
fn fit_under_a_round_rule_passes_check() {
    // Data on the rule's boundary with jumps, so that the unconstrained least squares leaves
    // the rule: T^2 + F^2 = 1 (orthopair), T^2 + I^2 + F^2 = 1 (spherical, I = 0.6),
    // T + I + F = 1 (picture, I = 0.25).
    let mut pairs = String::from("x,y,truth,falsity\n");
    let mut spherical = String::from("x,y,truth,indeterminacy,falsity\n");
    let mut picture = spherical.clone();
    for k in 0..30 {
        let angle = f64::from(k % 6) / 5.0 * std::f64::consts::FRAC_PI_2;
        let (f, t) = angle.sin_cos();
        let y = (f64::from(k) / 4.0).sin();
        pairs.push_str(&format!("{k},{y},{t},{f}\n"));
        spherical.push_str(&format!("{k},{y},{},0.6,{}\n", 0.8 * t, 0.8 * f));
        // Binary fractions: T + I + F = 1 exactly (the linear rules are checked exactly).
        let share = f64::from(k % 4) / 4.0 * 0.75;
        picture.push_str(&format!("{k},{y},{share},0.25,{}\n", 0.75 - share));
    }
    let dir = dir_with(&[
        ("pairs.csv", pairs),
        ("spherical.csv", spherical),
        ("picture.csv", picture),
    ]);
    for (data, family) in [
        ("pairs.csv", "pythagorean"),
        ("pairs.csv", "fermatean"),
        ("pairs.csv", "q-rung:5"),
        ("spherical.csv", "spherical"),
        ("spherical.csv", "t-spherical:3"),
        ("picture.csv", "picture"),
    ] {
        let out = ok(
            dir.path(),
            &[
                "fit",
                data,
                "--membership",
                family,
                "--control-points",
                "12",
                "-o",
                "fit.toml",
            ],
        );
        let check = ok(dir.path(), &["check", "fit.toml"]).stdout;
        assert!(
            check.contains(&format!("membership: {family}\n")),
            "{check}"
        );
        assert!(out.stderr.contains("at bound"), "{family}: {}", out.stderr);
    }
}

#[test]
fn plot_refuses_the_views_that_would_misdraw_a_family() {
    let dir = dir_with(&[("p.toml", PYTHAGOREAN), ("s.toml", SPHERICAL)]);
    assert_eq!(
        fails(
            dir.path(),
            &["plot", "p.toml", "--view", "all", "-o", "p.svg"]
        ),
        "error: the view `all` does not draw pythagorean models: pythagorean degrees are truth \
         and falsity (no indeterminacy); draw the view `truth` or `falsity`\n"
    );
    assert!(!dir.path().join("p.svg").exists());
    // A neutrosophic model derives no degrees.
    std::fs::write(
        dir.path().join("n.csv"),
        "x,y,truth,indeterminacy,falsity\n0,0,0.2,0.1,0.7\n1,2,0.5,0.3,0.1\n3,1,0.9,0.0,0.0\n",
    )
    .unwrap();
    assert_eq!(
        fails(
            dir.path(),
            &["plot", "n.csv", "--view", "derived", "-o", "n.svg"]
        ),
        "error: the view `derived` does not draw neutrosophic models: the derived view draws \
         the degrees a family derives from its channels (hesitation, refusal, footprint, ...), \
         and neutrosophic degrees derive none; the views of this model are `controls`, `truth`, \
         `indeterminacy`, `falsity`, `all`, `plane`, `score`\n"
    );
    assert!(!dir.path().join("n.svg").exists());
    // The intuitionistic score T - F (SPEC section 7) is the score view's height.
    std::fs::write(
        dir.path().join("i.csv"),
        "x,y,truth,falsity\n0,0,0.2,0.7\n1,2,0.5,0.1\n3,1,0.9,0.0\n",
    )
    .unwrap();
    ok(
        dir.path(),
        &[
            "plot",
            "i.csv",
            "--membership",
            "intuitionistic",
            "--view",
            "score",
            "-o",
            "i.svg",
        ],
    );
    let svg = std::fs::read_to_string(dir.path().join("i.svg")).unwrap();
    assert!(
        svg.contains(">score T\u{2212}F (intuitionistic)</text>"),
        "legend"
    );
    ok(
        dir.path(),
        &["plot", "p.toml", "--view", "falsity", "-o", "p.svg"],
    );
    let svg = std::fs::read_to_string(dir.path().join("p.svg")).unwrap();
    assert!(svg.contains("Pythagorean fuzzy Bézier curve"), "title");
    ok(
        dir.path(),
        &["plot", "s.toml", "--view", "all", "-o", "s.svg"],
    );
}

/// Every family's example (examples/families/) plots its score view, and its derived view
/// where the family derives degrees (the others are refused with the reason), as PNG.
#[test]
fn plot_draws_every_family_score_and_derived() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/families");
    let mut names: Vec<String> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 10);
    let files: Vec<(String, String)> = names
        .iter()
        .map(|n| (n.clone(), std::fs::read_to_string(root.join(n)).unwrap()))
        .collect();
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    let dir = dir_with(&refs);
    let mut refused = Vec::new();
    for name in &names {
        for view in ["score", "derived"] {
            let out = format!("{name}-{view}.png");
            let args = ["plot", name, "--view", view, "-o", &out, "--samples", "40"];
            let done = run_in(dir.path(), &args, None);
            if done.code == 0 {
                let png = std::fs::read(dir.path().join(&out)).unwrap();
                assert!(png.starts_with(b"\x89PNG"), "{name} {view}");
            } else {
                assert_eq!(done.code, 1, "{name} {view}: {}", done.stderr);
                assert!(
                    done.stderr
                        .starts_with("error: the view `derived` does not draw "),
                    "{}",
                    done.stderr
                );
                refused.push(name.clone());
            }
        }
    }
    assert_eq!(
        refused,
        ["bipolar-neutrosophic.toml", "interval-neutrosophic.toml"]
    );
}

#[test]
fn dxf_export_and_import_keep_the_family() {
    let dir = dir_with(&[("q.toml", Q_RUNG), ("t.toml", T_SPHERICAL)]);
    for (model, family) in [("q.toml", "q-rung:4"), ("t.toml", "t-spherical:3")] {
        ok(dir.path(), &["export", model, "-o", "out.dxf"]);
        ok(dir.path(), &["import", "out.dxf", "-o", "back.toml"]);
        let check = ok(dir.path(), &["check", "back.toml"]).stdout;
        assert!(
            check.contains(&format!("membership: {family}\n")),
            "{check}"
        );
        let before = table(&ok(
            dir.path(),
            &["eval", model, "--samples", "5", "--scores"],
        ));
        let after = table(&ok(
            dir.path(),
            &["eval", "back.toml", "--samples", "5", "--scores"],
        ));
        assert_eq!(before.0, after.0);
        for (a, b) in before.1.iter().zip(&after.1) {
            for (x, y) in a.iter().zip(b) {
                assert!((x - y).abs() <= 1e-14, "{model}: {a:?} vs {b:?}");
            }
        }
    }
}
