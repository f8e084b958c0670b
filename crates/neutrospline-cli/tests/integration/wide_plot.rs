//! `neutrospline plot` of the wide families (interval-valued and bipolar): figures written,
//! the views that would misdraw them refused with the reason.

use crate::util::{dir_with, ok, run};

const INTERVAL: &str = "kind = \"bezier\"
membership = \"interval-neutrosophic\"
control_points = [
  { x = 0, y = 0, truth_lower = 0.2, truth_upper = 0.5, indeterminacy_lower = 0.1, indeterminacy_upper = 0.3, falsity_lower = 0.0, falsity_upper = 0.4 },
  { x = 1, y = 2, truth_lower = 0.6, truth_upper = 0.9, indeterminacy_lower = 0.0, indeterminacy_upper = 0.2, falsity_lower = 0.1, falsity_upper = 0.1 },
  { x = 3, y = 0, truth_lower = 0.3, truth_upper = 0.3, indeterminacy_lower = 0.5, indeterminacy_upper = 0.7, falsity_lower = 0.2, falsity_upper = 0.25 },
]
";

const BIPOLAR: &str = "kind = \"bezier\"
membership = \"bipolar-neutrosophic\"
control_points = [
  { x = 0, y = 0, truth = 0.8, indeterminacy = 0.2, falsity = 0.1, negative_truth = -0.1, negative_indeterminacy = -0.3, negative_falsity = -0.6 },
  { x = 1, y = 2, truth = 0.6, indeterminacy = 0.4, falsity = 0.2, negative_truth = -0.3, negative_indeterminacy = -0.2, negative_falsity = -0.4 },
  { x = 3, y = 0, truth = 0.1, indeterminacy = 0.3, falsity = 0.9, negative_truth = -0.9, negative_indeterminacy = -0.1, negative_falsity = -0.05 },
]
";

/// Width and height from a PNG's IHDR chunk, after checking the signature.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    (w, h)
}

#[test]
fn plot_draws_interval_and_bipolar_models() {
    let dir = dir_with(&[("interval.toml", INTERVAL), ("bipolar.toml", BIPOLAR)]);
    for (file, view) in [
        ("interval.toml", "truth"),
        ("interval.toml", "all"),
        ("bipolar.toml", "all"),
        ("bipolar.toml", "falsity"),
    ] {
        let out = format!("{file}-{view}.png");
        ok(
            dir.path(),
            &[
                "plot", file, "-o", &out, "--view", view, "--size", "640x480",
            ],
        );
        let png = std::fs::read(dir.path().join(&out)).unwrap();
        assert_eq!(png_size(&png), (640, 480), "{out}");
    }
    ok(
        dir.path(),
        &["plot", "interval.toml", "-o", "i.svg", "--view", "truth"],
    );
    let svg = std::fs::read_to_string(dir.path().join("i.svg")).unwrap();
    assert!(svg.contains("Interval-valued neutrosophic Bézier curve: truth_lower and truth_upper"));
    assert_eq!(
        svg.matches("class=\"band truth\"").count(),
        34,
        "200 samples, chunks of 6"
    );
    ok(
        dir.path(),
        &["plot", "bipolar.toml", "-o", "b.svg", "--view", "all"],
    );
    let svg = std::fs::read_to_string(dir.path().join("b.svg")).unwrap();
    assert!(svg.contains("Bipolar neutrosophic Bézier curve: positive and negative degrees"));
    assert!(svg.contains(">\u{2212}1.0<"), "the axis reaches -1");
}

#[test]
fn plot_refuses_views_that_misdraw_wide_models() {
    let dir = dir_with(&[("interval.toml", INTERVAL), ("bipolar.toml", BIPOLAR)]);
    let (code, _, stderr) = run(
        dir.path(),
        &["plot", "interval.toml", "-o", "s.png", "--view", "derived"],
    );
    assert_eq!(code, 1);
    assert_eq!(
        stderr,
        "error: the view `derived` does not draw interval-neutrosophic models: the derived view \
         draws the degrees a family derives from its channels (hesitation, refusal, footprint, \
         ...), and interval-neutrosophic degrees derive none; the views of this model are \
         `truth`, `indeterminacy`, `falsity`, `all`, `score`\n"
    );
    let (code, _, stderr) = run(
        dir.path(),
        &["plot", "bipolar.toml", "-o", "c.png", "--view", "controls"],
    );
    assert_eq!(code, 1);
    assert_eq!(
        stderr,
        "error: the view `controls` does not draw bipolar-neutrosophic models: the controls \
         view draws one truth, indeterminacy and falsity bar per control point, and \
         bipolar-neutrosophic points carry a positive and a negative value per degree (truth, \
         indeterminacy, falsity, negative_truth, negative_indeterminacy, negative_falsity); \
         draw the view `truth`, `indeterminacy`, `falsity` or `all`\n"
    );
    assert!(!dir.path().join("s.png").exists() && !dir.path().join("c.png").exists());
}
