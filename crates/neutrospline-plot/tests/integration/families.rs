//! The `score` and `derived` views of the membership families (docs/model.md, "Membership
//! families"): the family's own score and its derived degrees, sampled from the blended
//! channels. Heights are read back from the SVG and checked against the Bernstein blend of
//! the example files' channels computed here by hand; titles, legends and the refusals.

use neutrospline_io::{parse, Format, ReadOptions};
use neutrospline_plot::{render_svg, PlotModel, PlotOptions, View};

const PYTHAGOREAN: &str = include_str!("../../../../examples/families/pythagorean.toml");
const PICTURE: &str = include_str!("../../../../examples/families/picture.toml");
const TYPE2: &str = include_str!("../../../../examples/families/interval-type2.toml");
const BIPOLAR_SURFACE: &str = include_str!("../wide/bipolar-surface.toml");

fn model(name: &str, text: &str) -> PlotModel {
    let model = parse(name, Format::Toml, text.as_bytes(), &ReadOptions::default()).unwrap();
    PlotModel::from_model(&model).unwrap()
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
    let start = tag.find("points=\"").unwrap() + 8;
    let rest = &tag[start..];
    rest[..rest.find('"').unwrap()]
        .split(' ')
        .map(|xy| {
            let (x, y) = xy.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The polyline drawn in pieces of class `class` (pieces sharing their end points), joined
/// from the piece that starts at `first_x`.
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

/// The cubic Bernstein blend of four control values at `t`.
fn bernstein(c: [f64; 4], t: f64) -> f64 {
    let s = 1.0 - t;
    s * s * s * c[0] + 3.0 * s * s * t * c[1] + 3.0 * s * t * t * c[2] + t * t * t * c[3]
}

/// examples/families/pythagorean.toml: truth 0.9, 0.8, 0.6, 0.5; falsity 0.3, 0.6, 0.8, 0.5.
const PYTHAGOREAN_TRUTH: [f64; 4] = [0.9, 0.8, 0.6, 0.5];
const PYTHAGOREAN_FALSITY: [f64; 4] = [0.3, 0.6, 0.8, 0.5];

/// The heights of the lifted curve of class `class` over the crisp curve, in pixels, one per
/// sample (the orthographic camera draws a height as a vertical offset, one scale per box).
fn heights(svg: &str, class: &str, n: usize) -> Vec<f64> {
    let floor = points(elements(svg, "polyline", "curve crisp")[0]);
    assert_eq!(floor.len(), n);
    let lifted = joined(svg, class, floor[0].0);
    assert_eq!(lifted.len(), n);
    floor
        .iter()
        .zip(&lifted)
        .map(|(f, l)| {
            assert!((f.0 - l.0).abs() <= 0.011, "straight above: {f:?} {l:?}");
            f.1 - l.1
        })
        .collect()
}

/// The Pythagorean score T^2 - F^2 is sampled: at t = 1/2 the blended channels are
/// T = (0.9 + 2.4 + 1.8 + 0.5) / 8 = 0.7 and F = (0.3 + 1.8 + 2.4 + 0.5) / 8 = 0.625, so the
/// score is 0.49 - 0.390625 = 0.099375, not the blend of the control scores (0.72, 0.28,
/// -0.28, 0) = 0.09. The SVG's heights are k * score at every sample, for one k.
#[test]
fn families_pythagorean_score_is_sampled_from_the_blended_channels() {
    let n = 201;
    let figure = model("pythagorean.toml", PYTHAGOREAN);
    let options = PlotOptions::default().with_samples(n);
    let svg = render_svg(&figure, View::Score, &options).unwrap();
    let h = heights(&svg, "curve score", n);
    let score = |t: f64| {
        let (tr, fa) = (
            bernstein(PYTHAGOREAN_TRUTH, t),
            bernstein(PYTHAGOREAN_FALSITY, t),
        );
        tr * tr - fa * fa
    };
    assert!((score(0.5) - 0.099375).abs() < 1e-15, "{}", score(0.5));
    let k = h[0] / score(0.0);
    assert!(k > 100.0, "a visible scale: {k}");
    for (i, hi) in h.iter().enumerate() {
        let t = i as f64 / (n - 1) as f64;
        assert!(
            (hi - k * score(t)).abs() < 0.03,
            "t = {t}: {hi} vs {}",
            k * score(t)
        );
    }
    let blended_controls = bernstein([0.72, 0.28, -0.28, 0.0], 0.5);
    assert!((blended_controls - 0.09).abs() < 1e-15);
    assert!(
        (h[100] - k * blended_controls).abs() > 0.5,
        "not the control blend"
    );
    // The score goes below 0 (P2: 0.36 - 0.64): the axis reaches -1, the crisp curve at 0.
    assert!(h.iter().any(|&v| v < -1.0));
    assert!(svg.contains(">\u{2212}1.0<"), "the axis reaches -1");
    // Not affine: no lifted control polygon, and the legend says so.
    assert!(elements(&svg, "polyline", "control-polygon score").is_empty());
    for text in [
        ">Pythagorean fuzzy Bézier curve: score</text>",
        ">score T^2\u{2212}F^2 (pythagorean)</text>",
        ">score T^2\u{2212}F^2</text>",
        ">crisp curve (score 0)</text>",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    assert!(
        svg.contains("Control polygon not lifted"),
        "the legend says why"
    );
}

/// The Pythagorean hesitation sqrt(1 - T^2 - F^2) of the blended channels: at t = 1/2,
/// sqrt(1 - 0.49 - 0.390625) = sqrt(0.119375).
#[test]
fn families_pythagorean_hesitation_is_sampled() {
    let n = 101;
    let figure = model("pythagorean.toml", PYTHAGOREAN);
    let options = PlotOptions::default().with_samples(n);
    let svg = render_svg(&figure, View::Derived, &options).unwrap();
    let h = heights(&svg, "curve hesitation", n);
    let hesitation = |t: f64| {
        let (tr, fa) = (
            bernstein(PYTHAGOREAN_TRUTH, t),
            bernstein(PYTHAGOREAN_FALSITY, t),
        );
        (1.0 - tr * tr - fa * fa).max(0.0).sqrt()
    };
    let k = h[0] / hesitation(0.0);
    assert!((hesitation(0.0) - 0.1f64.sqrt()).abs() < 1e-15);
    assert!((h[50] - k * 0.119375f64.sqrt()).abs() < 0.03);
    for (i, hi) in h.iter().enumerate() {
        let t = i as f64 / (n - 1) as f64;
        assert!((hi - k * hesitation(t)).abs() < 0.03, "t = {t}");
    }
    assert!(svg.contains(">Pythagorean fuzzy Bézier curve: hesitation</text>"));
    assert!(svg.contains(">hesitation = (1\u{2212}T^2\u{2212}F^2)^(1/2) (pythagorean)</text>"));
    assert!(elements(&svg, "polyline", "control-polygon hesitation").is_empty());
}

/// The picture refusal 1 - T - I - F is affine in the channels: its control polygon is
/// lifted to the control points' refusals (and the curve's heights are its blend).
#[test]
fn families_picture_refusal_lifts_its_control_polygon() {
    let n = 101;
    let figure = model("picture.toml", PICTURE);
    let options = PlotOptions::default().with_samples(n);
    let svg = render_svg(&figure, View::Derived, &options).unwrap();
    assert_eq!(
        elements(&svg, "polyline", "control-polygon refusal").len(),
        3,
        "three segments"
    );
    let h = heights(&svg, "curve refusal", n);
    assert!(h.iter().all(|&v| v >= -0.011));
    assert!(svg.contains(">refusal curve</text>"));
    assert!(svg.contains(">refusal = 1\u{2212}T\u{2212}I\u{2212}F (picture)</text>"));
    assert!(!svg.contains("Control polygon not lifted"));
    // The picture score T - F is affine too.
    let score = render_svg(&figure, View::Score, &options).unwrap();
    assert_eq!(
        elements(&score, "polyline", "control-polygon score").len(),
        3
    );
    assert!(score.contains(">score T\u{2212}F (picture)</text>"));
}

/// Interval type-2: the type-reduced membership (M_L + M_U) / 2 and the footprint M_U - M_L,
/// two curves in one box; its score is the type-reduced membership.
#[test]
fn families_interval_type2_derived_draws_both_degrees() {
    let figure = model("interval-type2.toml", TYPE2);
    let options = PlotOptions::default().with_samples(61);
    let svg = render_svg(&figure, View::Derived, &options).unwrap();
    for class in ["curve type_reduced", "curve footprint"] {
        assert!(!elements(&svg, "polyline", class).is_empty(), "{class}");
    }
    assert!(
        svg.contains("B-spline curve: derived degrees<"),
        "the title"
    );
    assert!(svg.contains(">control polygons</text>"));
    assert!(svg.contains(">footprint = M_U\u{2212}M_L (interval-type2)</text>"));
    assert!(svg.contains(">derived degree</text>"), "the axis");
    let score = render_svg(&figure, View::Score, &options).unwrap();
    assert!(score.contains(">score (M_L+M_U)/2 (interval-type2)</text>"));
}

/// A bipolar surface's score is drawn as the mesh's colour over [0, 1]; the family derives
/// no degrees, and the refusal names the views it has.
#[test]
fn families_bipolar_surface_score_and_derived_refusal() {
    let figure = model("bipolar-surface.toml", BIPOLAR_SURFACE);
    let options = PlotOptions::default().with_size(800, 600).with_samples(10);
    let svg = render_svg(&figure, View::Score, &options).unwrap();
    if let Some(out) = std::env::var_os("NEUTROSPLINE_FAMILY_PNGS") {
        let png = neutrospline_plot::render_png(&figure, View::Score, &options).unwrap();
        std::fs::write(
            std::path::Path::new(&out).join("bipolar-surface-score.png"),
            png,
        )
        .unwrap();
    }
    assert!(svg.contains("class=\"mesh\""));
    assert!(svg.contains("class=\"colorbar-label\""));
    assert!(svg.contains(
        "(3+T\u{207a}\u{2212}I\u{207a}\u{2212}F\u{207a}+T\u{207b}\u{2212}I\u{207b}\u{2212}F\u{207b})/6"
    ));
    assert_eq!(
        render_svg(&figure, View::Derived, &options)
            .unwrap_err()
            .to_string(),
        "the view `derived` does not draw bipolar-neutrosophic models: the derived view draws \
         the degrees a family derives from its channels (hesitation, refusal, footprint, ...), \
         and bipolar-neutrosophic degrees derive none; the views of this model are `truth`, \
         `indeterminacy`, `falsity`, `score`"
    );
}

/// A neutrosophic model derives no degrees: refused, naming the views it has.
#[test]
fn families_derived_refused_for_neutrosophic() {
    let figure = PlotModel::from(&neutrospline::example1());
    assert_eq!(
        figure.check_view(View::Derived).unwrap_err().to_string(),
        "the view `derived` does not draw neutrosophic models: the derived view draws the \
         degrees a family derives from its channels (hesitation, refusal, footprint, ...), and \
         neutrosophic degrees derive none; the views of this model are `controls`, `truth`, \
         `indeterminacy`, `falsity`, `all`, `plane`, `score`"
    );
    assert_eq!("derived".parse::<View>().unwrap(), View::Derived);
}

/// Every family's example draws its score view and (where it derives any) its derived view,
/// as SVG and PNG; both written to the folder $NEUTROSPLINE_FAMILY_PNGS when set, to look at.
#[test]
fn families_every_example_draws_score_and_derived() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/families");
    let mut drawn = 0;
    let mut entries: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    let out = std::env::var_os("NEUTROSPLINE_FAMILY_PNGS");
    for path in entries {
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let figure = model(&name, &text);
        for view in [View::Score, View::Derived] {
            if figure.family().derived_names().is_empty() && view == View::Derived {
                assert!(figure.check_view(view).is_err(), "{name}");
                continue;
            }
            let options = PlotOptions::default()
                .with_size(1200, 900)
                .with_samples(120);
            let svg = render_svg(&figure, view, &options).unwrap();
            assert!(!svg.contains("NaN"), "{name} {view}");
            if let Some(out) = &out {
                let png = neutrospline_plot::render_png(&figure, view, &options).unwrap();
                let stem = name.trim_end_matches(".toml");
                std::fs::write(
                    std::path::Path::new(out).join(format!("{stem}-{view}.svg")),
                    &svg,
                )
                .unwrap();
                std::fs::write(
                    std::path::Path::new(out).join(format!("{stem}-{view}.png")),
                    png,
                )
                .unwrap();
            }
            drawn += 1;
        }
    }
    // 10 examples: every score; derived for all but interval-neutrosophic and bipolar.
    assert_eq!(drawn, 10 + 8);
}

/// Interval type-2's `all` and `truth` views name their vertical axis alike: membership.
#[test]
fn families_interval_type2_axes_say_membership() {
    let figure = model("interval-type2.toml", TYPE2);
    let options = PlotOptions::default().with_samples(31);
    for view in [View::All, View::Truth] {
        let svg = render_svg(&figure, view, &options).unwrap();
        assert!(
            svg.lines()
                .any(|l| l.contains("class=\"axis-label\"") && l.ends_with(">membership</text>")),
            "{view}"
        );
        assert!(!svg.contains(">degree</text>"), "{view}");
        assert!(svg.contains(">crisp curve (membership 0)</text>"), "{view}");
    }
}
