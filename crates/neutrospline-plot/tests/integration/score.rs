//! End-to-end tests of the `score` view: the score `(2 + T - I - F) / 3` of the degrees drawn
//! like a degree: as the height of the space curve of a 2-D curve (read back from the SVG and
//! checked against the closed form of Example 1), as the colour of a 3-D curve and of a
//! surface; names, titles and labels; parsing.

use neutrospline::{Bezier, ControlPoint, ControlPolygon, Degrees, Surface};
use neutrospline_plot::{render_png, render_svg, PlotModel, PlotOptions, View};

/// The control scores of Example 1: (2 + T - I - F) / 3 of Table 1's degrees.
const EXAMPLE1_SCORES: [f64; 4] = [1.6 / 3.0, 2.6 / 3.0, 2.4 / 3.0, 1.4 / 3.0];

fn example1_model() -> PlotModel {
    PlotModel::from(&neutrospline::example1())
        .with_names(neutrospline::EXAMPLE1_NAMES)
        .unwrap()
}

fn cp3(p: [f64; 3], d: [f64; 3]) -> ControlPoint<3> {
    ControlPoint::new(p, Degrees::new(d[0], d[1], d[2]).unwrap())
}

/// The helix quarter turn of the repository's `examples/helix3d.toml`.
fn helix() -> Bezier<3> {
    let k = 0.552_284_749_8;
    Bezier::new(vec![
        cp3([1.0, 0.0, 0.0], [0.9, 0.1, 0.0]),
        cp3([1.0, k, 0.25], [0.7, 0.2, 0.1]),
        cp3([k, 1.0, 0.5], [0.4, 0.3, 0.3]),
        cp3([0.0, 1.0, 0.75], [0.1, 0.2, 0.8]),
    ])
    .unwrap()
}

/// A bicubic Bézier hill whose truth falls along u and indeterminacy rises along v (like the
/// repository's `examples/surface.toml`).
fn hill() -> Surface {
    let grid = (0..16)
        .map(|k| {
            let (i, j) = (f64::from(k / 4), f64::from(k % 4));
            let z = i * (3.0 - i) * j * (3.0 - j) / 2.0;
            cp3([i, j, z], [0.9 - 0.2 * i, 0.1 + 0.1 * j, 0.05 * (i + j)])
        })
        .collect();
    Surface::bezier(4, 4, grid).unwrap()
}

fn score(d: Degrees) -> f64 {
    d.score()
}

fn hex(rgb: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2])
}

/// Checks that hold for every figure: a closed document without NaN.
fn check_svg(svg: &str) {
    assert!(svg.starts_with("<?xml"));
    assert!(svg.trim_end().ends_with("</svg>"));
    for bad in ["NaN", "inf"] {
        assert!(!svg.contains(bad), "SVG contains {bad}");
    }
}

/// The value of attribute `name` in the element `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> &'a str {
    let start = tag
        .find(&format!(" {name}=\""))
        .unwrap_or_else(|| panic!("no {name} in {tag}"))
        + name.len()
        + 3;
    let rest = &tag[start..];
    &rest[..rest.find('"').unwrap()]
}

/// The elements `<kind ...>` of `svg` whose class is exactly `class`.
fn elements<'a>(svg: &'a str, kind: &str, class: &str) -> Vec<&'a str> {
    svg.split(&format!("<{kind} "))
        .skip(1)
        .map(|part| &part[..part.find('>').unwrap()])
        .filter(|tag| tag.contains(&format!(" class=\"{class}\"")))
        .collect()
}

fn points(tag: &str) -> Vec<(f64, f64)> {
    let list = tag
        .strip_prefix("points=\"")
        .map_or_else(|| attr(tag, "points"), |r| &r[..r.find('"').unwrap()]);
    list.split(' ')
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The polyline drawn in pieces of class `class` (pieces that share their end points, in any
/// order), joined from the piece that starts at `first_x`.
fn joined(svg: &str, class: &str, first_x: f64) -> Vec<(f64, f64)> {
    let mut pieces: Vec<Vec<(f64, f64)>> = elements(svg, "polyline", class)
        .iter()
        .map(|t| points(t))
        .collect();
    let start = pieces
        .iter()
        .position(|p| (p[0].0 - first_x).abs() < 1e-9)
        .expect("the first piece");
    let mut out = pieces.swap_remove(start);
    while !pieces.is_empty() {
        let last = *out.last().unwrap();
        let next = pieces
            .iter()
            .position(|p| p[0] == last)
            .expect("a piece that continues the curve");
        out.extend_from_slice(&pieces.swap_remove(next)[1..]);
    }
    out
}

#[test]
fn score_view_parses_and_is_listed() {
    assert_eq!("score".parse::<View>().unwrap(), View::Score);
    assert_eq!(View::Score.to_string(), "score");
    assert_eq!(View::Score.degree(), None);
    assert!(View::ALL.contains(&View::Score));
    assert!(View::MODEL.contains(&View::Score));
    let err = "Score".parse::<View>().unwrap_err().to_string();
    assert_eq!(
        err,
        "unknown view \"Score\" (expected one of: controls, truth, indeterminacy, falsity, all, plane, score, derived, data, band)"
    );
}

#[test]
fn score_2d_names_titles_labels() {
    let svg = render_svg(&example1_model(), View::Score, &PlotOptions::default()).unwrap();
    check_svg(&svg);
    assert!(svg.contains(">Neutrosophic Bézier curve: score</text>"));
    for label in [">x</text>", ">y</text>", ">score</text>"] {
        assert!(svg.contains(label), "axis label {label}");
    }
    assert!(svg
        .lines()
        .any(|l| l.contains("class=\"axis-label\"") && l.ends_with(">score</text>")));
    for entry in [
        ">score curve</text>",
        ">control polygon</text>",
        ">crisp curve (score 0)</text>",
        ">crisp control polygon</text>",
        ">score = (2+T\u{2212}I\u{2212}F)/3</text>",
    ] {
        assert!(svg.contains(entry), "legend {entry}");
    }
    for name in neutrospline::EXAMPLE1_NAMES {
        assert!(svg.contains(&format!(">{name}</text>")), "name {name}");
    }
    assert!(svg.contains("class=\"curtain\""));
    // The lifted control polygon, drawn segment by segment.
    assert_eq!(elements(&svg, "polyline", "control-polygon score").len(), 3);
    assert_eq!(elements(&svg, "circle", "control-point").len(), 4);
    // No degree is drawn: the view shows only the score.
    for degree in ["truth", "indeterminacy", "falsity"] {
        assert!(!svg.contains(&format!("curve {degree}")), "{degree}");
    }
}

/// The lifted curve's heights, read back from the SVG, are the scores: the orthographic
/// camera draws the height as a vertical offset `k * score` above the crisp curve on the
/// floor, one `k` for the whole box, and the control points sit at their scores.
#[test]
fn score_2d_heights_are_the_scores() {
    let n = 201;
    let options = PlotOptions::default().with_samples(n);
    let svg = render_svg(&example1_model(), View::Score, &options).unwrap();
    let floor = points(elements(&svg, "polyline", "curve crisp")[0]);
    assert_eq!(floor.len(), n);
    let lifted = joined(&svg, "curve score", floor[0].0);
    assert_eq!(lifted.len(), n);
    // Control points: the lifted markers above the crisp control polygon's corners.
    let crisp_ctrl = joined(&svg, "control-polygon crisp", floor[0].0);
    let lifted_ctrl = joined(&svg, "control-polygon score", floor[0].0);
    assert_eq!(crisp_ctrl.len(), 4);
    assert_eq!(lifted_ctrl.len(), 4);
    assert_eq!(crisp_ctrl[0], floor[0]);
    assert_eq!(lifted_ctrl[0], lifted[0]);
    let mut ks = Vec::new();
    for ((c, l), s) in crisp_ctrl.iter().zip(&lifted_ctrl).zip(EXAMPLE1_SCORES) {
        assert!((c.0 - l.0).abs() <= 0.011, "straight above");
        ks.push((c.1 - l.1) / s);
    }
    let k = ks.iter().sum::<f64>() / 4.0;
    assert!(k > 100.0, "a visible height scale: {k}");
    for kk in &ks {
        assert!((kk - k).abs() < 0.05, "one scale: {ks:?}");
    }
    let blend = |t: f64| {
        let s = 1.0 - t;
        s * s * s * EXAMPLE1_SCORES[0]
            + 3.0 * s * s * t * EXAMPLE1_SCORES[1]
            + 3.0 * s * t * t * EXAMPLE1_SCORES[2]
            + t * t * t * EXAMPLE1_SCORES[3]
    };
    for (i, (f, l)) in floor.iter().zip(&lifted).enumerate() {
        let t = i as f64 / (n - 1) as f64;
        assert!((f.0 - l.0).abs() <= 0.011, "sample {i} straight above");
        let height = (f.1 - l.1) / k;
        assert!(
            (height - blend(t)).abs() < 1e-4,
            "t = {t}: height {height}, score {}",
            blend(t)
        );
    }
    // Closed forms: t = 1/2 gives (1.6 + 3 * 2.6 + 3 * 2.4 + 1.4) / 24 = 0.75 exactly.
    assert_eq!(blend(0.5), 0.75);
    let mid = (floor[100].1 - lifted[100].1) / k;
    assert!((mid - 0.75).abs() < 1e-4, "{mid}");
    let quarter = (floor[50].1 - lifted[50].1) / k;
    let closed = (27.0 * 1.6 + 27.0 * 2.6 + 9.0 * 2.4 + 1.4) / 192.0;
    assert!((quarter - closed).abs() < 1e-4, "{quarter} vs {closed}");
}

#[test]
fn score_3d_curve_coloured_by_score() {
    let curve = helix();
    let model = PlotModel::from(&curve)
        .with_names(["H0", "H1", "H2", "H3"])
        .unwrap();
    let svg = render_svg(&model, View::Score, &PlotOptions::default()).unwrap();
    check_svg(&svg);
    assert!(svg.contains(">Neutrosophic Bézier curve: score</text>"));
    assert!(svg.contains("class=\"axes3d\""));
    for label in [">x</text>", ">y</text>", ">z</text>"] {
        assert!(svg.contains(label), "axis {label}");
    }
    assert!(svg
        .lines()
        .any(|l| l.contains("class=\"colorbar-label\"") && l.ends_with(">score</text>")));
    assert!(svg.contains("linearGradient"));
    assert!(svg.contains(">score = (2+T\u{2212}I\u{2212}F)/3</text>"));
    assert!(!elements(&svg, "polyline", "curve score").is_empty());
    for name in ["H0", "H1", "H2", "H3"] {
        assert!(svg.contains(&format!(">{name}</text>")), "{name}");
    }
    // Each control point is filled with the colour of its score.
    let fills: Vec<&str> = elements(&svg, "circle", "control-point")
        .iter()
        .map(|t| attr(t, "fill"))
        .collect();
    let mut want: Vec<String> = curve
        .control_points()
        .iter()
        .map(|p| hex(neutrospline::color::viridis(score(p.degrees))))
        .collect();
    let mut got: Vec<String> = fills.iter().map(|s| s.to_string()).collect();
    want.sort();
    got.sort();
    assert_eq!(got, want);
    // The ends of the curve: the first and last segments are coloured near the end scores.
    let ends = [0.9 + 2.0 - 0.1, 0.1 + 2.0 - 0.2 - 0.8].map(|v: f64| v / 3.0);
    let segs = elements(&svg, "polyline", "curve score");
    for end in ends {
        let c = hex(neutrospline::color::viridis(end));
        let near = segs.iter().any(|t| {
            let s = attr(t, "stroke");
            s == c
                || (0..=20).any(|d| {
                    let v = end + (f64::from(d) - 10.0) * 0.002;
                    s == hex(neutrospline::color::viridis(v))
                })
        });
        assert!(near, "a segment coloured near score {end}");
    }
}

#[test]
fn score_surface_mesh_coloured_by_score() {
    let surface = hill();
    let model = PlotModel::from_surface(&surface).unwrap();
    let options = PlotOptions::default().with_size(800, 600).with_samples(9);
    let svg = render_svg(&model, View::Score, &options).unwrap();
    check_svg(&svg);
    assert!(svg.contains(">Neutrosophic Bézier surface: score</text>"));
    assert!(svg
        .lines()
        .any(|l| l.contains("class=\"colorbar-label\"") && l.ends_with(">score</text>")));
    for entry in [">surface</text>", ">control net</text>"] {
        assert!(svg.contains(entry), "legend {entry}");
    }
    assert!(svg.contains("class=\"mesh\""));
    assert!(svg.matches("<polygon").count() >= 64, "8 x 8 faces");
    assert!(svg.contains("class=\"control-net\""));
    // Every visible control point is filled with the colour of its score.
    let want: Vec<String> = surface
        .control_points()
        .iter()
        .map(|p| hex(neutrospline::color::viridis(score(p.degrees))))
        .collect();
    let shown = elements(&svg, "circle", "control-point");
    assert!(!shown.is_empty());
    for tag in shown {
        let fill = attr(tag, "fill");
        assert!(want.iter().any(|w| w == fill), "{fill} is a control score");
    }
}

#[test]
fn score_view_png_of_every_kind() {
    let small = PlotOptions::default().with_size(400, 300).with_samples(9);
    for model in [
        example1_model(),
        PlotModel::from(&helix()),
        PlotModel::from_surface(&hill()).unwrap(),
    ] {
        let png = render_png(&model, View::Score, &small).unwrap();
        assert!(png.starts_with(b"\x89PNG"));
    }
}
