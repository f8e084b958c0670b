//! End-to-end tests of the figures: every view for 2-D and 3-D models, determinism,
//! degenerate inputs, and the structure of the SVG.

use neutrospline::{Bezier, ControlPoint, CurvePoint, Degrees, EXAMPLE1_NAMES};
use neutrospline_plot::{
    render_png, render_svg, svg_to_png, PlotError, PlotModel, PlotOptions, View,
};

const ERRATUM: &str =
    "Erratum: the paper's Table 3 gives C3 an indeterminacy of 0.1; Table 1 gives 0.4.";

fn example1_model() -> PlotModel {
    PlotModel::from(&neutrospline::example1())
        .with_names(EXAMPLE1_NAMES)
        .unwrap()
}

fn point2(x: f64, y: f64, t: f64, i: f64, f: f64) -> ControlPoint<2> {
    ControlPoint::new([x, y], Degrees::new(t, i, f).unwrap())
}

fn point3(x: f64, y: f64, z: f64, t: f64, i: f64, f: f64) -> ControlPoint<3> {
    ControlPoint::new([x, y, z], Degrees::new(t, i, f).unwrap())
}

fn space_model() -> PlotModel {
    let curve = Bezier::new(vec![
        point3(0.0, 0.0, 0.0, 0.9, 0.1, 0.0),
        point3(2.0, 5.0, 1.0, 0.6, 0.5, 0.2),
        point3(6.0, -1.0, 3.0, 0.3, 0.2, 0.6),
        point3(8.0, 4.0, 4.0, 0.1, 0.3, 0.9),
    ])
    .unwrap();
    PlotModel::from(&curve)
        .with_names(["P0", "P1", "P2", "P3"])
        .unwrap()
}

/// Small PNGs keep the tests fast; the layout scales with the size.
fn small() -> PlotOptions {
    PlotOptions::default().with_size(400, 300).with_samples(60)
}

fn decode_png(bytes: &[u8]) -> (u32, u32) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().expect("PNG header");
    let mut buf = vec![0; reader.output_buffer_size().expect("buffer size")];
    let info = reader.next_frame(&mut buf).expect("PNG data");
    (info.width, info.height)
}

/// Checks that hold for every figure.
fn check_svg(svg: &str, width: u32, height: u32) {
    assert!(svg.starts_with("<?xml"), "XML declaration");
    assert!(svg.trim_end().ends_with("</svg>"), "closed document");
    for bad in ["NaN", "inf", "Infinity"] {
        assert!(!svg.contains(bad), "SVG contains {bad}");
    }
    assert!(svg.contains("font-family=\"'DejaVu Sans', sans-serif\""));
    assert!(svg.contains(&format!("viewBox=\"0 0 {width} {height}\"")));
    // Every text anchor lies on the canvas.
    for part in svg.split("<text ").skip(1) {
        let attr = |name: &str| -> f64 {
            let start = part
                .find(&format!(" {name}=\""))
                .or_else(|| part.starts_with(&format!("{name}=\"")).then_some(0));
            let start = start.expect("text position") + name.len() + 2;
            let start = if part[start..].starts_with('"') {
                start + 1
            } else {
                start
            };
            let rest = &part[start..];
            rest[..rest.find('"').unwrap()].parse().unwrap()
        };
        let (x, y) = (attr("x"), attr("y"));
        assert!(
            (0.0..=f64::from(width)).contains(&x) && (0.0..=f64::from(height)).contains(&y),
            "text outside the canvas at ({x}, {y}): {}",
            &part[..part.len().min(120)]
        );
    }
}

#[test]
fn views_names_parse() {
    assert_eq!(View::ALL.len(), 10);
    assert_eq!(View::MODEL, View::ALL[..7]);
    assert_eq!(View::ALL[7], View::Derived);
    for (name, view) in [
        ("controls", View::Controls),
        ("truth", View::Truth),
        ("indeterminacy", View::Indeterminacy),
        ("falsity", View::Falsity),
        ("all", View::All),
        ("plane", View::Plane),
        ("score", View::Score),
        ("derived", View::Derived),
        ("data", View::Data),
    ] {
        assert_eq!(name.parse::<View>().unwrap(), view);
        assert_eq!(view.to_string(), name);
    }
    assert!(matches!(
        "surface".parse::<View>(),
        Err(PlotError::UnknownView { .. })
    ));
}

#[test]
fn views_2d_every_view_renders() {
    let model = example1_model();
    let options = PlotOptions::default().with_caption(ERRATUM);
    for view in View::MODEL {
        let svg = render_svg(&model, view, &options).unwrap();
        check_svg(&svg, 1600, 1200);
        assert!(svg.contains("Table 3"), "{view}: caption with the erratum");
        assert!(svg.contains("<polyline"), "{view}: polylines");
        assert!(svg.contains("class=\"curve"), "{view}: curve");
        assert!(
            svg.contains("class=\"control-polygon"),
            "{view}: control polygon"
        );
        assert!(svg.contains("class=\"axis-label\""), "{view}: axis labels");
        assert!(
            svg.contains(">x</text>") && svg.contains(">y</text>"),
            "{view}: x, y labels"
        );
        for name in EXAMPLE1_NAMES {
            assert!(
                svg.contains(&format!(">{name}</text>")),
                "{view}: name {name}"
            );
        }
        assert!(svg.contains("class=\"legend\""), "{view}: legend");
    }
}

#[test]
fn views_2d_degree_views_show_their_degree() {
    let model = example1_model();
    for (view, name) in [
        (View::Truth, "truth"),
        (View::Indeterminacy, "indeterminacy"),
        (View::Falsity, "falsity"),
    ] {
        let svg = render_svg(&model, view, &PlotOptions::default()).unwrap();
        assert!(
            svg.contains(&format!("class=\"curve {name}\"")),
            "{name} curve"
        );
        assert!(
            svg.contains(&format!(">{name} curve</text>")),
            "{name} legend"
        );
        let rotated = svg.split("<text ").any(|t| {
            t.contains("class=\"axis-label\"")
                && t.contains("rotate(-90")
                && t.contains(&format!(">{name}</text>"))
        });
        assert!(rotated, "{name}: vertical axis label");
        assert!(
            svg.contains(&format!(">{name}</text>")),
            "{name} axis label"
        );
        assert!(
            svg.contains("crisp curve (degree 0)"),
            "shadow in the legend"
        );
        assert!(
            svg.contains(&format!("Neutrosophic Bézier curve: {name}")),
            "title"
        );
        assert!(svg.contains("class=\"curtain\""));
    }
}

#[test]
fn views_2d_all_and_plane_legends_name_three_degrees() {
    let model = example1_model();
    for view in [View::All, View::Plane, View::Controls] {
        let svg = render_svg(&model, view, &PlotOptions::default()).unwrap();
        for name in ["truth", "indeterminacy", "falsity"] {
            assert!(svg.contains(name), "{view}: legend names {name}");
            let legend = &svg[svg.find("class=\"legend\"").unwrap()..];
            assert!(legend.contains(name), "{view}: {name} inside the legend");
        }
    }
    let all = render_svg(&model, View::All, &PlotOptions::default()).unwrap();
    for name in ["truth", "indeterminacy", "falsity"] {
        assert!(all.contains(&format!("class=\"curve {name}\"")));
    }
    assert!(all.contains(">degree</text>"));
    let plane = render_svg(&model, View::Plane, &PlotOptions::default()).unwrap();
    for name in ["truth", "indeterminacy", "falsity"] {
        assert!(plane.contains(&format!("class=\"band {name}\"")));
    }
}

#[test]
fn views_controls_callouts_show_values() {
    let svg = render_svg(&example1_model(), View::Controls, &PlotOptions::default()).unwrap();
    assert!(svg.contains("class=\"callouts\""));
    assert_eq!(svg.matches("class=\"callout\"").count(), 4);
    // C0's degrees (0.3, 0.6, 0.1) and C3's indeterminacy 0.4 (Table 1, not Table 3).
    for v in [
        ">0.3<", ">0.6<", ">0.1<", ">0.4<", ">0.8<", ">0.7<", ">0.2<",
    ] {
        assert!(svg.contains(v), "value {v}");
    }
    assert!(svg.contains("Neutrosophic control points"));
}

#[test]
fn views_3d_every_view_renders() {
    let model = space_model();
    for view in View::MODEL {
        let svg = render_svg(&model, view, &PlotOptions::default()).unwrap();
        check_svg(&svg, 1600, 1200);
        assert!(svg.contains(">z</text>"), "{view}: z axis label");
        assert!(svg.contains("class=\"axes3d\""), "{view}: 3-D box");
        assert!(svg.contains("class=\"curve"), "{view}: curve");
        for name in ["P0", "P1", "P2", "P3"] {
            assert!(svg.contains(&format!(">{name}</text>")), "{view}: {name}");
        }
    }
    let truth = render_svg(&model, View::Truth, &PlotOptions::default()).unwrap();
    assert!(truth.contains("class=\"colorbar-label\""));
    assert!(truth.contains("linearGradient"));
    let all = render_svg(&model, View::All, &PlotOptions::default()).unwrap();
    assert_eq!(all.matches("class=\"panel-title\"").count(), 3);
    assert_eq!(all.matches("class=\"axes3d\"").count(), 3);
}

#[test]
fn views_png_decode_at_requested_size() {
    let model = example1_model();
    for view in View::MODEL {
        let png = render_png(&model, view, &small()).unwrap();
        assert_eq!(decode_png(&png), (400, 300), "{view}");
    }
    let png = render_png(&space_model(), View::All, &small()).unwrap();
    assert_eq!(decode_png(&png), (400, 300));
}

#[test]
fn views_full_size_png() {
    let png = render_png(&example1_model(), View::Truth, &PlotOptions::default()).unwrap();
    assert_eq!(decode_png(&png), (1600, 1200));
}

#[test]
fn determinism_same_input_same_bytes() {
    let options = PlotOptions::default()
        .with_caption(ERRATUM)
        .with_samples(80);
    for model in [example1_model(), space_model()] {
        for view in View::MODEL {
            let a = render_svg(&model, view, &options).unwrap();
            let b = render_svg(&model.clone(), view, &options.clone()).unwrap();
            assert_eq!(a, b, "{view}: SVG");
        }
        for view in [View::Controls, View::All] {
            let a = render_png(&model, view, &small()).unwrap();
            let b = render_png(&model, view, &small()).unwrap();
            assert_eq!(a, b, "{view}: PNG");
        }
    }
}

fn models_2d(points: &[ControlPoint<2>]) -> PlotModel {
    PlotModel::from(&Bezier::new(points.to_vec()).unwrap())
}

fn models_3d(points: &[ControlPoint<3>]) -> PlotModel {
    PlotModel::from(&Bezier::new(points.to_vec()).unwrap())
}

fn degenerate_models() -> Vec<(&'static str, PlotModel)> {
    let d = (0.5, 0.2, 0.3);
    vec![
        (
            "single point",
            models_2d(&[point2(2.0, 3.0, d.0, d.1, d.2)]),
        ),
        (
            "all points equal",
            models_2d(&[point2(1.0, 1.0, 0.1, 0.2, 0.3); 4]),
        ),
        (
            "origin only",
            models_2d(&[point2(0.0, 0.0, 0.0, 0.0, 0.0); 3]),
        ),
        (
            "horizontal line",
            models_2d(&[
                point2(0.0, 2.0, 0.1, 0.5, 0.9),
                point2(1.0, 2.0, 0.5, 0.5, 0.5),
                point2(3.0, 2.0, 0.9, 0.5, 0.1),
            ]),
        ),
        (
            "vertical line",
            models_2d(&[
                point2(5.0, -1.0, 0.3, 0.3, 0.3),
                point2(5.0, 4.0, 0.6, 0.6, 0.6),
            ]),
        ),
        (
            "all degrees 0",
            models_2d(&[
                point2(0.0, 0.0, 0.0, 0.0, 0.0),
                point2(1.0, 2.0, 0.0, 0.0, 0.0),
                point2(3.0, 1.0, 0.0, 0.0, 0.0),
            ]),
        ),
        (
            "all degrees 1",
            models_2d(&[
                point2(0.0, 0.0, 1.0, 1.0, 1.0),
                point2(1.0, 2.0, 1.0, 1.0, 1.0),
                point2(3.0, 1.0, 1.0, 1.0, 1.0),
            ]),
        ),
        (
            "huge coordinates",
            models_2d(&[
                point2(1e9, 1e9, 0.2, 0.2, 0.2),
                point2(1e9 + 1.0, 1e9, 0.4, 0.4, 0.4),
            ]),
        ),
        (
            "tiny extent",
            models_2d(&[
                point2(1.0, 1.0, 0.2, 0.2, 0.2),
                point2(1.0 + 1e-12, 1.0, 0.4, 0.4, 0.4),
            ]),
        ),
        (
            "3-D single point",
            models_3d(&[point3(1.0, 2.0, 3.0, d.0, d.1, d.2)]),
        ),
        (
            "3-D all equal",
            models_3d(&[point3(1.0, 2.0, 3.0, 1.0, 1.0, 1.0); 3]),
        ),
        (
            "3-D vertical line",
            models_3d(&[
                point3(0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
                point3(0.0, 0.0, 5.0, 0.0, 0.0, 0.0),
            ]),
        ),
        (
            "3-D planar",
            models_3d(&[
                point3(0.0, 0.0, 1.0, 0.1, 0.2, 0.3),
                point3(1.0, 2.0, 1.0, 0.4, 0.5, 0.6),
                point3(3.0, 1.0, 1.0, 0.7, 0.8, 0.9),
            ]),
        ),
    ]
}

#[test]
fn degenerate_inputs_render_without_nan() {
    for (what, model) in degenerate_models() {
        for view in View::MODEL {
            let svg = render_svg(&model, view, &small())
                .unwrap_or_else(|e| panic!("{what}, {view}: {e}"));
            check_svg(&svg, 400, 300);
        }
        let png = render_png(&model, View::Truth, &small()).unwrap();
        assert_eq!(decode_png(&png), (400, 300), "{what}");
    }
}

#[test]
fn degenerate_cameras_and_sizes() {
    let model = example1_model();
    for (az, el) in [
        (0.0, 0.0),
        (90.0, 90.0),
        (-90.0, -90.0),
        (180.0, 45.0),
        (725.0, -30.0),
    ] {
        let options = small().with_camera(az, el);
        for view in View::MODEL {
            let svg = render_svg(&model, view, &options).unwrap();
            check_svg(&svg, 400, 300);
        }
        for view in View::MODEL {
            let svg = render_svg(&space_model(), view, &options).unwrap();
            check_svg(&svg, 400, 300);
        }
    }
    for (w, h) in [(64, 64), (64, 2000), (3000, 200)] {
        let options = PlotOptions::default().with_size(w, h).with_samples(20);
        for view in View::MODEL {
            let svg = render_svg(&model, view, &options).unwrap();
            check_svg(&svg, w, h);
        }
    }
}

#[test]
fn model_from_samples_and_curve() {
    let controls = [
        point2(0.0, 0.0, 0.1, 0.2, 0.3),
        point2(4.0, 1.0, 0.5, 0.5, 0.5),
    ];
    let samples: Vec<CurvePoint<2>> = (0..5)
        .map(|k| {
            let t = k as f64 / 4.0;
            point2(4.0 * t, t, 0.1 + 0.4 * t, 0.2 + 0.3 * t, 0.3 + 0.2 * t)
        })
        .collect();
    let model = PlotModel::from_samples(&samples, &controls).unwrap();
    assert_eq!(model.label(), "Neutrosophic curve");
    let svg = render_svg(&model, View::Truth, &small()).unwrap();
    assert!(svg.contains("Neutrosophic curve: truth"));
    let curve = Bezier::new(controls.to_vec()).unwrap();
    let model = PlotModel::from_curve(curve.clone(), &controls)
        .unwrap()
        .with_label("Neutrosophic line");
    let svg = render_svg(&model, View::All, &small()).unwrap();
    assert!(svg.contains("Neutrosophic line: all three degrees"));
    let model = PlotModel::from_bezier(&curve).unwrap();
    assert_eq!(model.label(), "Neutrosophic Bézier curve");
}

#[test]
fn options_title_and_errors() {
    let model = example1_model();
    let svg = render_svg(&model, View::Truth, &small().with_title("Fig. 2")).unwrap();
    assert!(svg.contains(">Fig. 2</text>"));
    let svg = render_svg(&model, View::Truth, &small().with_title("")).unwrap();
    assert!(!svg.contains("class=\"title\""));
    assert_eq!(
        render_svg(&model, View::Truth, &small().with_size(10, 300)).unwrap_err(),
        PlotError::InvalidSize {
            width: 10,
            height: 300,
            min: 64,
            max: 16384
        }
    );
    assert!(matches!(
        render_svg(&model, View::Truth, &small().with_samples(0)),
        Err(PlotError::InvalidSamples { .. })
    ));
    assert!(matches!(
        svg_to_png("not svg", 100, 100),
        Err(PlotError::Svg { .. })
    ));
}

#[test]
fn text_escaped_in_svg() {
    let model = PlotModel::from(&neutrospline::example1())
        .with_names(["<a>", "b&c", "\"d\"", "e"])
        .unwrap();
    let svg = render_svg(&model, View::Controls, &small().with_title("T < F & I")).unwrap();
    assert!(svg.contains("T &lt; F &amp; I"));
    assert!(svg.contains("&lt;a&gt;"));
    let png = svg_to_png(&svg, 400, 300).unwrap();
    assert_eq!(decode_png(&png), (400, 300));
}
