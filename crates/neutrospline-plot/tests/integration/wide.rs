//! The figures of the wide families (interval-valued and bipolar, docs/model.md "Lanes"):
//! the band between the lower and upper curves, the negative degrees below the crisp plane,
//! the two-panel views of surfaces, the titles, and the refused views with their messages.

use neutrospline_io::{parse, Format, ReadOptions};
use neutrospline_plot::{render_png, render_svg, PlotModel, PlotOptions, View};

const INTERVAL: &str = include_str!("../wide/interval.toml");
const TYPE2: &str = include_str!("../wide/type2.toml");
const BIPOLAR: &str = include_str!("../wide/bipolar.toml");
const SURFACE: &str = include_str!("../wide/surface.toml");

fn model(name: &str, text: &str) -> PlotModel {
    let model = parse(name, Format::Toml, text.as_bytes(), &ReadOptions::default()).unwrap();
    PlotModel::from_model(&model).unwrap()
}

/// 61 samples: the lifted curves are cut into chunks of 6 segments, starting at samples
/// 0, 6, ..., 54.
fn options() -> PlotOptions {
    PlotOptions::default().with_size(800, 600).with_samples(61)
}

/// The points of every `<polygon>` whose class is `class`.
fn polygons(svg: &str, class: &str) -> Vec<Vec<(f64, f64)>> {
    svg.lines()
        .filter(|l| l.contains("<polygon") && l.contains(&format!("class=\"{class}\"")))
        .map(|l| {
            let start = l.find("points=\"").unwrap() + 8;
            let rest = &l[start..];
            rest[..rest.find('"').unwrap()]
                .split(' ')
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

/// The cubic Bernstein blend of four control values at `t`.
fn bernstein(values: [f64; 4], t: f64) -> f64 {
    let s = 1.0 - t;
    s * s * s * values[0]
        + 3.0 * s * s * t * values[1]
        + 3.0 * s * t * t * values[2]
        + t * t * t * values[3]
}

/// The band of the truth view is the ruled strip between the lower and the upper lifted
/// curves at equal parameters: under the orthographic camera a height difference dz is the
/// screen offset (0, -k dz), so each rung of the strip is vertical and its length is k times
/// the width of the truth interval, the Bernstein blend of the control points' widths
/// truth_upper - truth_lower = 0.3, 0.3, 0.15, 0.1 (tests/wide/interval.toml).
#[test]
fn wide_interval_band_rungs_are_the_blended_interval_widths() {
    let figure = model("interval.toml", INTERVAL);
    let svg = render_svg(&figure, View::Truth, &options()).unwrap();
    let bands = polygons(&svg, "band truth");
    assert_eq!(bands.len(), 10, "60 segments in chunks of 6");
    let widths = [0.5 - 0.2, 0.9 - 0.6, 0.55 - 0.4, 0.8 - 0.7];
    // The first rung of every chunk (its first lower vertex and its last, upper, vertex),
    // in any order (the scene sorts them by depth): rung lengths over k are the widths at
    // t = 0, 0.1, ..., 0.9.
    let mut rungs: Vec<f64> = bands
        .iter()
        .map(|poly| {
            assert_eq!(poly.len(), 14, "7 lower and 7 upper vertices");
            let (lower, upper) = (poly[0], poly[13]);
            assert!(
                (lower.0 - upper.0).abs() <= 0.011,
                "a vertical rung: {poly:?}"
            );
            lower.1 - upper.1
        })
        .collect();
    rungs.sort_by(f64::total_cmp);
    let mut expected: Vec<f64> = (0..10)
        .map(|k| bernstein(widths, f64::from(k) * 6.0 / 60.0))
        .collect();
    expected.sort_by(f64::total_cmp);
    let k = rungs[9] / expected[9];
    assert!(k > 50.0, "a visible band: {k} pixels per unit");
    for (rung, width) in rungs.iter().zip(&expected) {
        assert!((rung - k * width).abs() < 0.03, "{rung} vs {}", k * width);
    }
    // Every rung inside a chunk, too: vertex i (lower) and 13 - i (upper) at one parameter.
    for poly in &bands {
        for i in 0..7 {
            assert!((poly[i].0 - poly[13 - i].0).abs() <= 0.011);
            assert!(poly[i].1 - poly[13 - i].1 > 0.0, "upper above lower");
        }
    }
    for text in [
        ">truth_lower<",
        ">truth_upper<",
        ">truth interval<",
        "Interval-valued neutrosophic Bézier curve: truth_lower and truth_upper",
    ] {
        assert!(svg.contains(text), "{text}");
    }
}

/// The bipolar truth view: the positive truth above the crisp plane, the negative truth
/// below it, each with a curtain to the plane. At a parameter both curtains hang from the
/// same crisp point, one up by k T+(t), one down by k |T-(t)|, so the ratio of their lengths
/// is |T-(t)| / T+(t), with T+ = 0.8, 0.6, 0.3, 0.1 and T- = -0.1, -0.3, -0.7, -0.9
/// (tests/wide/bipolar.toml).
#[test]
fn wide_bipolar_negative_degrees_hang_below_the_crisp_plane() {
    let figure = model("bipolar.toml", BIPOLAR);
    let svg = render_svg(&figure, View::Truth, &options()).unwrap();
    let curtains = polygons(&svg, "curtain truth");
    assert_eq!(curtains.len(), 20, "10 chunks per lane");
    // Pair the curtains by their shared crisp point (the last vertex: floor at the chunk's
    // first parameter).
    let mut by_floor: std::collections::BTreeMap<String, (f64, f64)> = Default::default();
    for poly in &curtains {
        let (top, floor) = (poly[0], poly[poly.len() - 1]);
        let entry = by_floor
            .entry(format!("{:.2},{:.2}", floor.0, floor.1))
            .or_default();
        let dy = top.1 - floor.1;
        if dy < 0.0 {
            entry.0 = -dy;
        } else {
            entry.1 = dy;
        }
    }
    assert_eq!(by_floor.len(), 10);
    let mut ratios: Vec<f64> = by_floor
        .values()
        .map(|&(up, down)| {
            assert!(up > 0.0 && down > 0.0, "one curtain up, one down");
            down / up
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    let mut expected: Vec<f64> = (0..10)
        .map(|k| {
            let t = f64::from(k) * 6.0 / 60.0;
            bernstein([0.1, 0.3, 0.7, 0.9], t) / bernstein([0.8, 0.6, 0.3, 0.1], t)
        })
        .collect();
    expected.sort_by(f64::total_cmp);
    for (r, e) in ratios.iter().zip(&expected) {
        assert!((r - e).abs() < 2e-3 * e.max(1.0), "{r} vs {e}");
    }
    assert!(svg.contains("class=\"crisp-plane\""));
    for text in [
        ">\u{2212}1.0<",
        ">1.0<",
        ">truth (above 0)<",
        ">negative_truth (below 0)<",
        "Bipolar neutrosophic Bézier curve: truth and negative_truth",
    ] {
        assert!(svg.contains(text), "{text}");
    }
}

/// The `all` views draw each carried degree's pair in its colour, and name the family.
#[test]
fn wide_all_views_draw_every_carried_degree() {
    let svg = render_svg(&model("interval.toml", INTERVAL), View::All, &options()).unwrap();
    for kind in ["truth", "indeterminacy", "falsity"] {
        assert_eq!(polygons(&svg, &format!("band {kind}")).len(), 10, "{kind}");
    }
    assert!(svg.contains(">upper (*_upper)<") && svg.contains(">lower (*_lower)<"));
    let svg = render_svg(&model("type2.toml", TYPE2), View::All, &options()).unwrap();
    assert_eq!(polygons(&svg, "band truth").len(), 10);
    assert_eq!(polygons(&svg, "band falsity").len(), 0);
    assert!(svg.contains("Interval type-2 fuzzy B-spline curve: lower and upper membership"));
    let svg = render_svg(&model("type2.toml", TYPE2), View::Truth, &options()).unwrap();
    for text in [
        ">lower membership<",
        ">upper membership<",
        ">footprint of uncertainty<",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    let svg = render_svg(&model("bipolar.toml", BIPOLAR), View::All, &options()).unwrap();
    assert!(svg.contains("Bipolar neutrosophic Bézier curve: positive and negative degrees"));
    for kind in ["truth", "indeterminacy", "falsity"] {
        assert!(
            svg.contains(&format!("class=\"curve {kind} lane1\"")),
            "{kind}"
        );
    }
}

/// A wide surface's degree view: two panels, the lower and the upper truth.
#[test]
fn wide_surface_truth_is_two_panels() {
    let figure = model("surface.toml", SURFACE);
    let options = PlotOptions::default().with_size(800, 600).with_samples(8);
    let svg = render_svg(&figure, View::Truth, &options).unwrap();
    assert_eq!(svg.matches("class=\"panel-title\"").count(), 2);
    assert!(svg.contains(">truth_lower</text>") && svg.contains(">truth_upper</text>"));
    assert!(
        svg.contains("Interval-valued neutrosophic Bézier surface: truth_lower and truth_upper")
    );
    let png = render_png(&figure, View::Truth, &options).unwrap();
    assert!(png.starts_with(b"\x89PNG"));
}

/// The views that would misdraw a wide family are refused, with the reason; the score view
/// draws every wide family's own score.
#[test]
fn wide_refused_views_say_why() {
    let interval = model("interval.toml", INTERVAL);
    let refusal =
        |m: &PlotModel, view: View| render_svg(m, view, &options()).unwrap_err().to_string();
    assert!(render_svg(&interval, View::Score, &options()).is_ok());
    assert_eq!(
        refusal(&interval, View::Derived),
        "the view `derived` does not draw interval-neutrosophic models: the derived view draws \
         the degrees a family derives from its channels (hesitation, refusal, footprint, ...), \
         and interval-neutrosophic degrees derive none; the views of this model are `truth`, \
         `indeterminacy`, `falsity`, `all`, `score`"
    );
    assert_eq!(
        refusal(&interval, View::Controls),
        "the view `controls` does not draw interval-neutrosophic models: the controls view \
         draws one truth, indeterminacy and falsity bar per control point, and \
         interval-neutrosophic points carry a lower and an upper value per degree \
         (truth_lower, truth_upper, indeterminacy_lower, indeterminacy_upper, falsity_lower, \
         falsity_upper); draw the view `truth`, `indeterminacy`, `falsity` or `all`"
    );
    let bipolar = model("bipolar.toml", BIPOLAR);
    assert_eq!(
        refusal(&bipolar, View::Plane),
        "the view `plane` does not draw bipolar-neutrosophic models: the plane view widens \
         three lanes by one truth, indeterminacy and falsity, and bipolar-neutrosophic degrees \
         carry a positive and a negative value each (truth, indeterminacy, falsity, \
         negative_truth, negative_indeterminacy, negative_falsity); draw the view `truth`, \
         `indeterminacy`, `falsity` or `all`"
    );
    let type2 = model("type2.toml", TYPE2);
    assert_eq!(
        refusal(&type2, View::Indeterminacy),
        "the view `indeterminacy` does not draw interval-type2 models: interval type-2 degrees \
         are a lower and an upper membership, held as truth_lower and truth_upper; draw the \
         view `truth` (or `all`) for the footprint of uncertainty between them"
    );
    let surface = model("surface.toml", SURFACE);
    assert_eq!(
        refusal(&surface, View::All),
        "the view `all` does not draw interval-neutrosophic models: the all view of a 3-D curve \
         or a surface draws one panel per degree, and interval-neutrosophic degrees carry a \
         lower and an upper value each; draw the view `truth`, `indeterminacy` or `falsity` \
         for two panels, one per lane"
    );
}
