//! The band view: the fuzzy position (control point spreads) of a curve drawn as the regions
//! swept by its alpha-cuts; nothing else in the figure moves when the spreads are zero, and
//! the other views ignore spreads.

use neutrospline::{AnyCurve, Spread};
use neutrospline_io::{parse, Format, Model, ReadOptions};
use neutrospline_plot::{render_png, render_svg, PlotError, PlotModel, PlotOptions, View};

fn model(path: &str) -> Model {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(path);
    let bytes = std::fs::read(&file).unwrap();
    let format = if path.ends_with(".json") {
        Format::Json
    } else {
        Format::Toml
    };
    parse(path, format, &bytes, &ReadOptions::default()).unwrap()
}

fn crisp(model: &Model) -> Model {
    Model::new(model.shape().clone())
        .with_membership(model.membership())
        .unwrap()
        .with_point_names(model.point_names().to_vec())
        .unwrap()
}

#[test]
fn band_view_draws_each_level_and_the_centroid() {
    let fuzzy = model("fuzzy-bspline.toml");
    assert!(fuzzy.spreads().is_some());
    let plot = PlotModel::from_model(&fuzzy).unwrap();
    let svg = render_svg(&plot, View::Band, &PlotOptions::default()).unwrap();
    assert!(svg.contains("band alpha-0\""), "the alpha = 0 band");
    assert!(svg.contains("band alpha-0.5\""), "the alpha = 0.5 band");
    assert!(
        !svg.contains("band alpha-1\""),
        "alpha = 1 is the crisp curve"
    );
    assert!(svg.contains("curve centroid"));
    assert!(svg.contains("curve crisp"));
    assert!(svg.contains("alpha = 0.5"));
    let svg = render_svg(
        &plot,
        View::Band,
        &PlotOptions::default().with_alphas([0.75, 0.25]),
    )
    .unwrap();
    assert!(svg.contains("band alpha-0.25\"") && svg.contains("band alpha-0.75\""));
    assert!(!svg.contains("band alpha-0\""));
    let png = render_png(&plot, View::Band, &PlotOptions::default()).unwrap();
    assert!(png.starts_with(b"\x89PNG"));
}

#[test]
fn zero_spreads_draw_the_crisp_curve_and_nothing_moves() {
    let fuzzy = model("fuzzy-bspline.toml");
    let plain = crisp(&fuzzy);
    let zero = crisp(&fuzzy)
        .with_spreads(vec![Spread::ZERO; fuzzy.shape().control_count()])
        .unwrap();
    let options = PlotOptions::default();
    let plain_svg = render_svg(
        &PlotModel::from_model(&plain).unwrap(),
        View::Band,
        &options,
    )
    .unwrap();
    let zero_svg =
        render_svg(&PlotModel::from_model(&zero).unwrap(), View::Band, &options).unwrap();
    assert_eq!(plain_svg, zero_svg);
    assert!(!plain_svg.contains("band alpha"));
    assert!(!plain_svg.contains("curve centroid"));
    // A curve without a model file (no spreads at all) draws the same figure.
    let Some(neutrospline::DynCurve::Planar(curve)) = plain.shape().curve() else {
        panic!("a planar curve")
    };
    let names: Vec<String> = plain
        .point_names()
        .iter()
        .map(|n| n.clone().unwrap())
        .collect();
    let bare = PlotModel::from_any::<2>(&AnyCurve::clone(curve))
        .unwrap()
        .with_names(names)
        .unwrap();
    assert_eq!(render_svg(&bare, View::Band, &options).unwrap(), plain_svg);
}

#[test]
fn other_views_ignore_spreads() {
    let fuzzy = model("fuzzy-bspline.toml");
    let plain = crisp(&fuzzy);
    for view in View::MODEL {
        let a = render_svg(
            &PlotModel::from_model(&fuzzy).unwrap(),
            view,
            &PlotOptions::default(),
        );
        let b = render_svg(
            &PlotModel::from_model(&plain).unwrap(),
            view,
            &PlotOptions::default(),
        );
        assert_eq!(a.unwrap(), b.unwrap(), "{view}");
    }
}

#[test]
fn band_view_of_3d_curves_and_errors() {
    let helix = model("helix3d.toml");
    let spreads =
        vec![Spread::new([0.1, 0.0, 0.05], [0.1, 0.2, 0.3]); helix.shape().control_count()];
    let fuzzy = helix.clone().with_spreads(spreads).unwrap();
    let svg = render_svg(
        &PlotModel::from_model(&fuzzy).unwrap(),
        View::Band,
        &PlotOptions::default(),
    )
    .unwrap();
    assert!(svg.contains("band alpha-0\"") && svg.contains("silhouette"));
    let surface = PlotModel::from_model(&model("surface.toml")).unwrap();
    assert_eq!(
        render_svg(&surface, View::Band, &PlotOptions::default()).unwrap_err(),
        PlotError::BandOnSurface
    );
    let plot = PlotModel::from_model(&helix).unwrap();
    let e = render_svg(
        &plot,
        View::Band,
        &PlotOptions::default().with_alphas([1.5]),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "alpha level 1.5 is outside [0, 1] (the band view draws alpha-cuts at levels in [0, 1])"
    );
    assert_eq!("band".parse::<View>().unwrap(), View::Band);
}
