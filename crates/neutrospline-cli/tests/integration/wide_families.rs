//! The interval-valued and bipolar families (two lanes, docs/model.md "Lanes") in the table
//! commands: `eval` columns against Bernstein blending by hand, the rule along a curve whose
//! control channels sit on its boundary, derived degrees and scores against SPEC section 10,
//! rates against the hodograph by hand, `check`'s lines, `query` and `intersect` channels,
//! the refusals, and `eval --type-reduce` against a brute force over the vertices of the
//! membership box.

use std::path::Path;

use crate::util::{dir_with, run_in, Output};

/// An interval-neutrosophic quadratic Bézier curve.
const INTERVAL: &str = r#"kind = "bezier"
membership = "interval-neutrosophic"
[[control_points]]
x = 0
y = 0
truth_lower = 0.2
truth_upper = 0.5
indeterminacy_lower = 0.1
indeterminacy_upper = 0.3
falsity_lower = 0.0
falsity_upper = 0.4
[[control_points]]
x = 1
y = 2
truth_lower = 0.6
truth_upper = 0.9
indeterminacy_lower = 0.0
indeterminacy_upper = 0.2
falsity_lower = 0.1
falsity_upper = 0.1
[[control_points]]
x = 3
y = 0
truth_lower = 0.3
truth_upper = 0.3
indeterminacy_lower = 0.5
indeterminacy_upper = 0.7
falsity_lower = 0.2
falsity_upper = 0.25
"#;
/// Its control positions and channels (truth_lower, truth_upper, indeterminacy_lower, ...).
const INTERVAL_POSITIONS: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 2.0], [3.0, 0.0]];
const INTERVAL_CHANNELS: [[f64; 6]; 3] = [
    [0.2, 0.5, 0.1, 0.3, 0.0, 0.4],
    [0.6, 0.9, 0.0, 0.2, 0.1, 0.1],
    [0.3, 0.3, 0.5, 0.7, 0.2, 0.25],
];

/// A bipolar-neutrosophic quadratic Bézier curve (same positions).
const BIPOLAR: &str = r#"kind = "bezier"
membership = "bipolar-neutrosophic"
[[control_points]]
x = 0
y = 0
truth = 0.2
indeterminacy = 0.5
falsity = 0.1
negative_truth = -0.3
negative_indeterminacy = 0.0
negative_falsity = -1.0
[[control_points]]
x = 1
y = 2
truth = 1.0
indeterminacy = 0.0
falsity = 0.4
negative_truth = -0.6
negative_indeterminacy = -0.2
negative_falsity = -0.5
[[control_points]]
x = 3
y = 0
truth = 0.6
indeterminacy = 0.3
falsity = 0.0
negative_truth = 0.0
negative_indeterminacy = -0.9
negative_falsity = -0.1
"#;
const BIPOLAR_CHANNELS: [[f64; 6]; 3] = [
    [0.2, 0.5, 0.1, -0.3, 0.0, -1.0],
    [1.0, 0.0, 0.4, -0.6, -0.2, -0.5],
    [0.6, 0.3, 0.0, 0.0, -0.9, -0.1],
];

/// An interval type-2 line from (0, 0) to (2, 1): memberships [0.2, 0.6] to [0.5, 0.9].
const TYPE2: &str = r#"kind = "bezier"
membership = "interval-type2"
[[control_points]]
x = 0
y = 0
truth_lower = 0.2
truth_upper = 0.6
[[control_points]]
x = 2
y = 1
truth_lower = 0.5
truth_upper = 0.9
"#;

/// An interval-intuitionistic cubic whose control channels all sit on the boundary of the
/// rule: truth_upper + falsity_upper = 1, and lower = upper or lower = 0.
const BOUNDARY: &str = r#"kind = "bezier"
membership = "interval-intuitionistic"
control_points = [
  { x = 0, y = 0, truth_lower = 0.0, truth_upper = 0.3, falsity_lower = 0.0, falsity_upper = 0.7 },
  { x = 1, y = 3, truth_lower = 0.6, truth_upper = 0.6, falsity_lower = 0.4, falsity_upper = 0.4 },
  { x = 2, y = -1, truth_lower = 1.0, truth_upper = 1.0, falsity_lower = 0.0, falsity_upper = 0.0 },
  { x = 4, y = 1, truth_lower = 0.0, truth_upper = 0.0, falsity_lower = 1.0, falsity_upper = 1.0 },
]
"#;

/// An interval type-2 bilinear Bézier surface.
const SURFACE: &str = r#"kind = "bezier-surface"
membership = "interval-type2"
rows = 2
cols = 2
control_points = [
  { x = 0, y = 0, z = 0, truth_lower = 0.1, truth_upper = 0.3 },
  { x = 0, y = 1, z = 1, truth_lower = 0.2, truth_upper = 0.8 },
  { x = 1, y = 0, z = 0, truth_lower = 0.0, truth_upper = 1.0 },
  { x = 1, y = 1, z = 2, truth_lower = 0.5, truth_upper = 0.5 },
]
"#;

fn files() -> tempfile::TempDir {
    dir_with(&[
        ("interval.toml", INTERVAL),
        ("bipolar.toml", BIPOLAR),
        ("type2.toml", TYPE2),
        ("boundary.toml", BOUNDARY),
        ("surface.toml", SURFACE),
        (
            "pythagorean.toml",
            include_str!("../../../../examples/families/pythagorean.toml"),
        ),
        ("m.csv", "value,truth,indeterminacy,falsity\n0,1,0,0\n"),
        ("n.csv", "value,truth,indeterminacy,falsity\n0,1,0,0\n"),
        ("points.csv", "x,y\n3,0\n"),
        (
            "line.toml",
            "kind = \"bezier\"\ncontrol_points = [\n  { x = 0, y = 2, truth = 1, \
             indeterminacy = 0, falsity = 0 },\n  { x = 3, y = -1, truth = 0, indeterminacy = 0, \
             falsity = 1 },\n]\n",
        ),
    ])
}

fn ok(dir: &Path, args: &[&str]) -> Output {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    assert!(out.stderr.is_empty(), "{args:?}: {}", out.stderr);
    out
}

/// The message of a refusal with exit status `code`.
fn fails(dir: &Path, args: &[&str], code: i32) -> String {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, code, "{args:?} should fail: {}", out.stdout);
    assert!(out.stdout.is_empty(), "{args:?}: {}", out.stdout);
    out.stderr.trim_end().to_owned()
}

/// The header and the rows of a CSV table of numbers (a word cell parses as NaN).
fn table(out: &Output) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = out.stdout.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    (header, rows)
}

/// The value of `column` in `row`.
fn get(header: &[String], row: &[f64], column: &str) -> f64 {
    let k = header
        .iter()
        .position(|h| h == column)
        .unwrap_or_else(|| panic!("no column {column} in {header:?}"));
    row[k]
}

/// The quadratic Bernstein blend of three values at t.
fn quadratic(values: [f64; 3], t: f64) -> f64 {
    let s = 1.0 - t;
    s * s * values[0] + 2.0 * s * t * values[1] + t * t * values[2]
}

/// The channel `c` of three control points.
fn channel(points: &[[f64; 6]; 3], c: usize) -> [f64; 3] {
    [points[0][c], points[1][c], points[2][c]]
}

fn close(a: f64, b: f64, tolerance: f64, what: &str) {
    assert!((a - b).abs() <= tolerance, "{what}: {a} vs {b}");
}

const INTERVAL_NAMES: [&str; 6] = [
    "truth_lower",
    "truth_upper",
    "indeterminacy_lower",
    "indeterminacy_upper",
    "falsity_lower",
    "falsity_upper",
];
const BIPOLAR_NAMES: [&str; 6] = [
    "truth",
    "indeterminacy",
    "falsity",
    "negative_truth",
    "negative_indeterminacy",
    "negative_falsity",
];

#[test]
fn eval_blends_every_interval_neutrosophic_channel_with_the_bernstein_basis() {
    let dir = files();
    let out = ok(
        dir.path(),
        &["eval", "interval.toml", "--at", "0.25,0.5", "--scores"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "t,x,y,truth_lower,truth_upper,indeterminacy_lower,indeterminacy_upper,falsity_lower,\
         falsity_upper,score"
    );
    for (row, t) in rows.iter().zip([0.25, 0.5]) {
        for (axis, name) in ["x", "y"].iter().enumerate() {
            let want = quadratic(INTERVAL_POSITIONS.map(|p| p[axis]), t);
            close(get(&header, row, name), want, 1e-15, name);
        }
        let mut v = [0.0; 6];
        for (c, name) in INTERVAL_NAMES.iter().enumerate() {
            v[c] = quadratic(channel(&INTERVAL_CHANNELS, c), t);
            close(get(&header, row, name), v[c], 1e-15, name);
        }
        // SPEC section 10: (4 + T_L + T_U - I_L - I_U - F_L - F_U) / 6.
        let score = (4.0 + v[0] + v[1] - v[2] - v[3] - v[4] - v[5]) / 6.0;
        close(get(&header, row, "score"), score, 1e-15, "score");
    }
    // t = 0.25 by hand: truth_lower = 0.5625 * 0.2 + 0.375 * 0.6 + 0.0625 * 0.3.
    close(get(&header, &rows[0], "truth_lower"), 0.35625, 1e-15, "T_L");
}

#[test]
fn eval_of_a_bipolar_curve_gives_negative_channels_in_minus_one_to_zero() {
    let dir = files();
    let out = ok(
        dir.path(),
        &["eval", "bipolar.toml", "--at", "0.25,0.5", "--scores"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "t,x,y,truth,indeterminacy,falsity,negative_truth,negative_indeterminacy,\
         negative_falsity,score"
    );
    for (row, t) in rows.iter().zip([0.25, 0.5]) {
        let mut v = [0.0; 6];
        for (c, name) in BIPOLAR_NAMES.iter().enumerate() {
            v[c] = quadratic(channel(&BIPOLAR_CHANNELS, c), t);
            close(get(&header, row, name), v[c], 1e-15, name);
            if c >= 3 {
                assert!((-1.0..=0.0).contains(&v[c]), "{name} = {}", v[c]);
            }
        }
        // SPEC section 10: (3 + T+ - I+ - F+ + T- - I- - F-) / 6.
        let score = (3.0 + v[0] - v[1] - v[2] + v[3] - v[4] - v[5]) / 6.0;
        close(get(&header, row, "score"), score, 1e-15, "score");
    }
    // t = 0.5 by hand: negative_falsity = 0.25 * -1 + 0.5 * -0.5 + 0.25 * -0.1 = -0.525.
    close(
        get(&header, &rows[1], "negative_falsity"),
        -0.525,
        1e-15,
        "F-",
    );
}

#[test]
fn rates_of_every_channel_are_the_hodograph_by_hand() {
    let dir = files();
    for (file, names, points) in [
        ("interval.toml", INTERVAL_NAMES, INTERVAL_CHANNELS),
        ("bipolar.toml", BIPOLAR_NAMES, BIPOLAR_CHANNELS),
    ] {
        let out = ok(
            dir.path(),
            &["eval", file, "--at", "0.25,0.5", "--derivative", "2"],
        );
        let (header, rows) = table(&out);
        let mut want: Vec<String> = vec!["t", "x", "y"].into_iter().map(String::from).collect();
        want.extend(names.iter().map(|n| (*n).to_owned()));
        for prefix in ["d", "d2"] {
            want.extend(["x", "y"].iter().map(|n| format!("{prefix}{n}")));
            want.extend(names.iter().map(|n| format!("{prefix}{n}")));
        }
        assert_eq!(header, want);
        for (row, t) in rows.iter().zip([0.25, 0.5]) {
            for (c, name) in names.iter().enumerate() {
                let [p0, p1, p2] = channel(&points, c);
                // C'(t) = 2 ((1 - t)(P1 - P0) + t (P2 - P1)), C'' = 2 (P2 - 2 P1 + P0).
                let first = 2.0 * ((1.0 - t) * (p1 - p0) + t * (p2 - p1));
                let second = 2.0 * (p2 - 2.0 * p1 + p0);
                close(get(&header, row, &format!("d{name}")), first, 1e-14, name);
                close(get(&header, row, &format!("d2{name}")), second, 1e-14, name);
            }
            close(get(&header, row, "dx"), 2.0 * (1.0 + t), 1e-14, "dx");
            close(get(&header, row, "dy"), 2.0 * (2.0 - 4.0 * t), 1e-14, "dy");
        }
    }
}

#[test]
fn the_rule_holds_along_a_curve_on_its_boundary_and_the_derived_degrees_follow_spec_10() {
    let dir = files();
    let out = ok(
        dir.path(),
        &["eval", "boundary.toml", "--samples", "10000", "--scores"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "t,x,y,truth_lower,truth_upper,falsity_lower,falsity_upper,hesitation_lower,\
         hesitation_upper,score,accuracy"
    );
    assert_eq!(rows.len(), 10000);
    let tolerance = 1e-12;
    for row in &rows {
        let [tl, tu, fl, fu] = [3, 4, 5, 6].map(|k| row[k]);
        for v in [tl, tu, fl, fu] {
            assert!((-tolerance..=1.0 + tolerance).contains(&v), "{row:?}");
        }
        assert!(tl <= tu + tolerance && fl <= fu + tolerance, "{row:?}");
        // Every control point has truth_upper + falsity_upper = 1: so does the curve.
        close(tu + fu, 1.0, tolerance, "T_U + F_U");
        // SPEC section 10: hesitation [1 - T_U - F_U, 1 - T_L - F_L]; score
        // (T_L - F_L + T_U - F_U) / 2, accuracy (T_L + T_U + F_L + F_U) / 2.
        close(row[7], (1.0 - tu - fu).max(0.0), 1e-15, "hesitation_lower");
        close(row[8], (1.0 - tl - fl).max(0.0), 1e-15, "hesitation_upper");
        close(row[9], (tl - fl + tu - fu) / 2.0, 1e-15, "score");
        close(row[10], (tl + tu + fl + fu) / 2.0, 1e-15, "accuracy");
    }
    // Type 2: the type-reduced membership (L + U) / 2 and the footprint U - L.
    let out = ok(
        dir.path(),
        &["eval", "type2.toml", "--at", "0.5", "--scores"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "t,x,y,truth_lower,truth_upper,type_reduced,footprint,score"
    );
    let want = [0.5, 1.0, 0.5, 0.35, 0.75, 0.55, 0.4, 0.55];
    for (value, want) in rows[0].iter().zip(want) {
        close(*value, want, 1e-15, "type 2 row");
    }
}

#[test]
fn a_wide_surface_evaluates_every_lane_at_the_same_parameters() {
    let dir = files();
    let out = ok(
        dir.path(),
        &[
            "eval",
            "surface.toml",
            "--at",
            "0.5:0.5,0.25:1",
            "--derivative",
        ],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "u,v,x,y,z,truth_lower,truth_upper,type_reduced,footprint,dx_du,dy_du,dz_du,\
         dtruth_lower_du,dtruth_upper_du,dx_dv,dy_dv,dz_dv,dtruth_lower_dv,dtruth_upper_dv"
    );
    // Bilinear: P00 (1-u)(1-v) + P01 (1-u) v + P10 u (1-v) + P11 u v.
    let lower = [0.1, 0.2, 0.0, 0.5];
    let upper = [0.3, 0.8, 1.0, 0.5];
    let blend = |p: [f64; 4], u: f64, v: f64| {
        p[0] * (1.0 - u) * (1.0 - v) + p[1] * (1.0 - u) * v + p[2] * u * (1.0 - v) + p[3] * u * v
    };
    let du = |p: [f64; 4], v: f64| (p[2] - p[0]) * (1.0 - v) + (p[3] - p[1]) * v;
    let dv = |p: [f64; 4], u: f64| (p[1] - p[0]) * (1.0 - u) + (p[3] - p[2]) * u;
    for (row, (u, v)) in rows.iter().zip([(0.5, 0.5), (0.25, 1.0)]) {
        let (l, h) = (blend(lower, u, v), blend(upper, u, v));
        close(get(&header, row, "truth_lower"), l, 1e-15, "L");
        close(get(&header, row, "truth_upper"), h, 1e-15, "U");
        close(get(&header, row, "type_reduced"), (l + h) / 2.0, 1e-15, "M");
        close(get(&header, row, "footprint"), h - l, 1e-15, "FOU");
        close(
            get(&header, row, "dtruth_lower_du"),
            du(lower, v),
            1e-15,
            "dL/du",
        );
        close(
            get(&header, row, "dtruth_upper_du"),
            du(upper, v),
            1e-15,
            "dU/du",
        );
        close(
            get(&header, row, "dtruth_lower_dv"),
            dv(lower, u),
            1e-15,
            "dL/dv",
        );
        close(
            get(&header, row, "dtruth_upper_dv"),
            dv(upper, u),
            1e-15,
            "dU/dv",
        );
    }
}

#[test]
fn check_prints_the_channels_the_rule_in_words_and_their_averages() {
    let dir = files();
    let out = ok(dir.path(), &["check", "type2.toml"]);
    // A line at constant speed: the arc-length averages are the endpoints' means.
    assert_eq!(
        out.stdout,
        "type2.toml: valid\nkind: bezier\ndegree: 1\ndimension: 2\ncontrol points: 2\n\
         membership: interval-type2\ndomain: [0, 1]\ntruth_lower: 0.2..0.5\n\
         truth_upper: 0.6..0.9\nrule: truth_lower, truth_upper each in [0, 1]; truth_lower <= \
         truth_upper; derived: type_reduced, footprint\n\
         length: 2.2360679775\naverage truth_lower: 0.35\naverage truth_upper: 0.75\n"
    );
    let out = ok(dir.path(), &["check", "boundary.toml"]);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert!(lines.contains(&"truth_lower: 0..1"), "{lines:?}");
    assert!(lines.contains(&"falsity_upper: 0..1"), "{lines:?}");
    assert!(
        lines.contains(
            &"rule: truth_lower, truth_upper, falsity_lower, falsity_upper each in [0, 1]; \
              truth_lower <= truth_upper, falsity_lower <= falsity_upper; truth_upper + \
              falsity_upper <= 1; derived: hesitation_lower, hesitation_upper (largest \
              truth_upper + falsity_upper at the control points: 1)"
        ),
        "{lines:?}"
    );
    let out = ok(dir.path(), &["check", "bipolar.toml"]);
    let lines: Vec<&str> = out.stdout.lines().collect();
    for line in [
        "membership: bipolar-neutrosophic",
        "truth: 0.2..1",
        "negative_truth: -0.6..0",
        "negative_indeterminacy: -0.9..0",
        "negative_falsity: -1..-0.1",
        "rule: truth, indeterminacy, falsity each in [0, 1]; negative_truth, \
         negative_indeterminacy, negative_falsity each in [-1, 0]",
    ] {
        assert!(lines.contains(&line), "{line} not in {lines:?}");
    }
    // The averages of a channel: (1/L) integral of channel |C'(t)| dt, by Simpson's rule
    // on 2000 panels (the speed of this quadratic is smooth).
    let speed = |t: f64| (2.0f64 * (1.0 + t)).hypot(2.0 * (2.0 - 4.0 * t));
    let n = 2000;
    let simpson = |f: &dyn Fn(f64) -> f64| {
        let h = 1.0 / f64::from(n);
        let mut sum = f(0.0) + f(1.0);
        for k in 1..n {
            sum += if k % 2 == 1 { 4.0 } else { 2.0 } * f(f64::from(k) * h);
        }
        sum * h / 3.0
    };
    let length = simpson(&speed);
    for (c, name) in BIPOLAR_NAMES.iter().enumerate() {
        let average = simpson(&|t| quadratic(channel(&BIPOLAR_CHANNELS, c), t) * speed(t)) / length;
        let line = lines
            .iter()
            .find_map(|l| l.strip_prefix(&format!("average {name}: ")))
            .unwrap_or_else(|| panic!("no average {name} in {lines:?}"));
        close(line.parse().unwrap(), average, 1e-10, name);
    }
}

#[test]
fn query_and_intersect_give_the_channels() {
    let dir = files();
    let out = ok(dir.path(), &["query", "interval.toml", "points.csv"]);
    // (3, 0) is the end of the curve: t = 1, the last control point's channels, and the
    // score (4 + 0.3 + 0.3 - 0.5 - 0.7 - 0.2 - 0.25) / 6 = 2.95 / 6.
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "index,t,distance,x,y,truth_lower,truth_upper,indeterminacy_lower,indeterminacy_upper,\
         falsity_lower,falsity_upper,score"
    );
    let want = [
        0.0,
        1.0,
        0.0,
        3.0,
        0.0,
        0.3,
        0.3,
        0.5,
        0.7,
        0.2,
        0.25,
        2.95 / 6.0,
    ];
    for (value, want) in rows[0].iter().zip(want) {
        close(*value, want, 1e-15, "query row");
    }
    let out = ok(dir.path(), &["intersect", "interval.toml", "line.toml"]);
    let (header, rows) = table(&out);
    let mut want: Vec<String> = ["index", "t_a", "t_b", "x", "y"].map(String::from).to_vec();
    want.extend(INTERVAL_NAMES.iter().map(|n| format!("{n}_a")));
    want.extend(["truth_b", "indeterminacy_b", "falsity_b", "contact"].map(String::from));
    assert_eq!(header, want);
    assert_eq!(rows.len(), 1);
    // x + y = 2 on the line: 2t + t^2 + 4t - 4t^2 = 2, so 3t^2 - 6t + 2 = 0.
    let t = 1.0 - (1.0f64 / 3.0).sqrt();
    close(get(&header, &rows[0], "t_a"), t, 1e-12, "t_a");
    for (c, name) in INTERVAL_NAMES.iter().enumerate() {
        let want = quadratic(channel(&INTERVAL_CHANNELS, c), t);
        close(
            get(&header, &rows[0], &format!("{name}_a")),
            want,
            1e-12,
            name,
        );
    }
}

#[test]
fn refusals_say_why() {
    let dir = files();
    assert_eq!(
        fails(
            dir.path(),
            &["eval", "pythagorean.toml", "--type-reduce"],
            2
        ),
        "error: --type-reduce applies to the interval-valued families (interval-type2, \
         interval-neutrosophic, interval-intuitionistic): pythagorean.toml has membership \
         pythagorean, which has no interval-valued degree (a [lower, upper] pair of channels) \
         to reduce"
    );
    assert_eq!(
        fails(dir.path(), &["eval", "bipolar.toml", "--type-reduce"], 2),
        "error: --type-reduce applies to the interval-valued families (interval-type2, \
         interval-neutrosophic, interval-intuitionistic): bipolar.toml has membership \
         bipolar-neutrosophic, which has no interval-valued degree (a [lower, upper] pair of \
         channels) to reduce"
    );
    assert!(fails(
        dir.path(),
        &["eval", "type2.toml", "--type-reduce", "--at", "0.5"],
        2
    )
    .starts_with("error: the argument '--type-reduce' cannot be used with '--at"));
    assert_eq!(
        fails(
            dir.path(),
            &["relation", "m.csv", "n.csv", "--check", "interval.toml"],
            1
        ),
        "error: interval.toml: membership interval-neutrosophic: `neutrospline relation \
         --check` compares each control point's single truth, indeterminacy and falsity with \
         the axis sets' (Def. 4); its control points carry intervals or bipolar pairs of \
         degrees instead, which a neutrosophic point relation does not have"
    );
}

/// The centroid interval over every vertex of the box (w_k at L_k or U_k): the brute force.
fn brute_force(q: &[f64], lower: &[f64], upper: &[f64]) -> (f64, f64) {
    let mut extremes = (f64::INFINITY, f64::NEG_INFINITY);
    for mask in 0u32..1 << q.len() {
        let (mut moment, mut mass) = (0.0, 0.0);
        for k in 0..q.len() {
            let w = if mask >> k & 1 == 1 {
                upper[k]
            } else {
                lower[k]
            };
            moment += q[k] * w;
            mass += w;
        }
        if mass > 0.0 {
            extremes = (extremes.0.min(moment / mass), extremes.1.max(moment / mass));
        }
    }
    extremes
}

/// Checks a `--type-reduce` row for the columns `names` sampled as `columns`, weighted by
/// `lower` and `upper`.
fn check_row(
    header: &[String],
    row: &[f64],
    names: &[&str],
    columns: &[Vec<f64>],
    lower: &[f64],
    upper: &[f64],
) {
    for (name, q) in names.iter().zip(columns) {
        let (lo, hi) = brute_force(q, lower, upper);
        close(get(header, row, &format!("{name}_lower")), lo, 1e-12, name);
        close(get(header, row, &format!("{name}_upper")), hi, 1e-12, name);
        close(get(header, row, name), (lo + hi) / 2.0, 1e-12, name);
    }
}

#[test]
fn type_reduction_rows_equal_a_brute_force_over_the_vertices() {
    let dir = files();
    // The type-2 line at t_k = k / 8: x = 2t, y = t, L = 0.2 + 0.3 t, U = 0.6 + 0.3 t.
    let out = ok(
        dir.path(),
        &["eval", "type2.toml", "--type-reduce", "--samples", "9"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "degree,t_lower,t_upper,t,x_lower,x_upper,x,y_lower,y_upper,y"
    );
    assert!(out.stdout.lines().nth(1).unwrap().starts_with("truth,"));
    assert_eq!(rows.len(), 1);
    let t: Vec<f64> = (0..9).map(|k| f64::from(k) / 8.0).collect();
    let x: Vec<f64> = t.iter().map(|t| 2.0 * t).collect();
    let lower: Vec<f64> = t.iter().map(|t| 0.2 + 0.3 * t).collect();
    let upper: Vec<f64> = t.iter().map(|t| 0.6 + 0.3 * t).collect();
    check_row(
        &header,
        &rows[0],
        &["t", "x", "y"],
        &[t.clone(), x, t],
        &lower,
        &upper,
    );

    // The interval-neutrosophic curve at 8 samples: a row per degree.
    let out = ok(
        dir.path(),
        &[
            "eval",
            "interval.toml",
            "--type-reduce",
            "--samples",
            "8",
            "--format",
            "csv",
        ],
    );
    let words: Vec<&str> = out
        .stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(words, ["truth", "indeterminacy", "falsity"]);
    let (header, rows) = table(&out);
    let t: Vec<f64> = (0..8).map(|k| f64::from(k) / 7.0).collect();
    let coordinate = |axis: usize| -> Vec<f64> {
        t.iter()
            .map(|&t| quadratic(INTERVAL_POSITIONS.map(|p| p[axis]), t))
            .collect()
    };
    let columns = [t.clone(), coordinate(0), coordinate(1)];
    for (d, row) in rows.iter().enumerate() {
        let along = |c: usize| -> Vec<f64> {
            t.iter()
                .map(|&t| quadratic(channel(&INTERVAL_CHANNELS, c), t))
                .collect()
        };
        check_row(
            &header,
            row,
            &["t", "x", "y"],
            &columns,
            &along(2 * d),
            &along(2 * d + 1),
        );
    }

    // A surface: the 3 x 3 grid of (u, v), u slowest.
    let out = ok(
        dir.path(),
        &["eval", "surface.toml", "--type-reduce", "--samples", "3"],
    );
    let (header, rows) = table(&out);
    assert_eq!(
        header.join(","),
        "degree,u_lower,u_upper,u,v_lower,v_upper,v,x_lower,x_upper,x,y_lower,y_upper,y,\
         z_lower,z_upper,z"
    );
    let grid: Vec<(f64, f64)> = (0..3)
        .flat_map(|i| (0..3).map(move |j| (f64::from(i) / 2.0, f64::from(j) / 2.0)))
        .collect();
    let blend = |p: [f64; 4], (u, v): (f64, f64)| {
        p[0] * (1.0 - u) * (1.0 - v) + p[1] * (1.0 - u) * v + p[2] * u * (1.0 - v) + p[3] * u * v
    };
    let of = |p: [f64; 4]| -> Vec<f64> { grid.iter().map(|&uv| blend(p, uv)).collect() };
    let u: Vec<f64> = grid.iter().map(|g| g.0).collect();
    let v: Vec<f64> = grid.iter().map(|g| g.1).collect();
    check_row(
        &header,
        &rows[0],
        &["u", "v", "x", "y", "z"],
        &[u.clone(), v.clone(), u, v, of([0.0, 1.0, 0.0, 2.0])],
        &of([0.1, 0.2, 0.0, 0.5]),
        &of([0.3, 0.8, 1.0, 0.5]),
    );
}
