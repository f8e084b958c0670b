//! End-to-end tests of the surface figures: every view for every surface kind, the structure
//! of the SVG (mesh, control net, colour bar, legend), determinism, degenerate surfaces and
//! the sample limit.

use neutrospline::{ControlPoint, Degrees, KnotVector, Surface};
use neutrospline_plot::{render_png, render_svg, PlotError, PlotModel, PlotOptions, View};

fn point(p: [f64; 3], d: [f64; 3]) -> ControlPoint<3> {
    ControlPoint::new(p, Degrees::new(d[0], d[1], d[2]).unwrap())
}

/// A bicubic Bézier bump whose truth grows along u and falsity along v.
fn bicubic() -> Surface {
    let grid = (0..16)
        .map(|k| {
            let (i, j) = (f64::from(k / 4), f64::from(k % 4));
            let z = i * (3.0 - i) * j * (3.0 - j) / 4.0;
            point([i, j, z], [0.1 + 0.25 * i, 0.5, 0.05 + 0.3 * j])
        })
        .collect();
    Surface::bezier(4, 4, grid).unwrap()
}

/// A biquadratic B-spline over a 4 x 4 net (one interior knot each way).
fn bspline() -> Surface {
    let grid = (0..16)
        .map(|k| {
            let (i, j) = (f64::from(k / 4), f64::from(k % 4));
            point([i, j, (i - j).sin()], [0.2, 0.1 * (i + j), 0.3])
        })
        .collect();
    let knots = KnotVector::clamped_uniform(2, 4).unwrap();
    Surface::bspline(4, 4, grid, knots.clone(), knots).unwrap()
}

/// A NURBS quarter cylinder of radius 2 and height 3.
fn quarter_cylinder() -> Surface {
    let arc = [[2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let mut grid = Vec::new();
    let mut weights = Vec::new();
    for (i, p) in arc.iter().enumerate() {
        for h in [0.0, 3.0] {
            grid.push(point([p[0], p[1], h], [0.3 * i as f64, 0.2, h / 4.0]));
            weights.push(if i == 1 { w } else { 1.0 });
        }
    }
    Surface::nurbs(
        3,
        2,
        grid,
        weights,
        KnotVector::clamped_uniform(2, 3).unwrap(),
        KnotVector::clamped_uniform(1, 2).unwrap(),
    )
    .unwrap()
}

fn small() -> PlotOptions {
    PlotOptions::default().with_size(480, 360).with_samples(9)
}

/// Checks that hold for every figure: a closed document without NaN.
fn check_svg(svg: &str) {
    assert!(svg.starts_with("<?xml"));
    assert!(svg.trim_end().ends_with("</svg>"));
    for bad in ["NaN", "inf"] {
        assert!(!svg.contains(bad), "SVG contains {bad}");
    }
}

/// The part of `svg` inside the first group of class `class`.
fn group<'a>(svg: &'a str, class: &str) -> &'a str {
    let start = svg
        .find(&format!("<g class=\"{class}\""))
        .unwrap_or_else(|| panic!("no group {class}"));
    let rest = &svg[start..];
    let mut depth = 0usize;
    for (i, line) in rest.lines().enumerate() {
        let line = line.trim_start();
        if line.starts_with("<g ") {
            depth += 1;
        } else if line.starts_with("</g>") {
            depth -= 1;
            if depth == 0 {
                let end: usize = rest.lines().take(i + 1).map(|l| l.len() + 1).sum();
                return &rest[..end];
            }
        }
    }
    rest
}

#[test]
fn surfaces_model_labels_and_grid() {
    for (surface, label, grid) in [
        (bicubic(), "Neutrosophic Bézier surface", (4, 4)),
        (bspline(), "Neutrosophic B-spline surface", (4, 4)),
        (quarter_cylinder(), "Neutrosophic NURBS surface", (3, 2)),
    ] {
        let model = PlotModel::from_surface(&surface).unwrap();
        assert_eq!(model.label(), label);
        assert_eq!(model.grid(), Some(grid));
        assert!(model.is_surface());
        assert_eq!(model.dimension(), 3);
        assert_eq!(model.control_count(), grid.0 * grid.1);
    }
    let curve = PlotModel::from(&neutrospline::example1());
    assert!(!curve.is_surface());
    assert_eq!(curve.grid(), None);
}

#[test]
fn surfaces_every_view_every_kind_renders() {
    for surface in [bicubic(), bspline(), quarter_cylinder()] {
        let model = PlotModel::from_surface(&surface).unwrap();
        for view in View::MODEL {
            let svg = render_svg(&model, view, &small()).unwrap();
            check_svg(&svg);
            assert!(
                svg.contains(model.label()) || view == View::Controls,
                "{view}: title"
            );
            assert!(svg.contains("class=\"legend\""), "{view}: legend");
        }
    }
}

#[test]
fn surfaces_degree_views_draw_mesh_net_and_colour_bar() {
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let n = 9;
    for (view, name) in [
        (View::Truth, "truth"),
        (View::Indeterminacy, "indeterminacy"),
        (View::Falsity, "falsity"),
        (View::Score, "score"),
    ] {
        let svg = render_svg(&model, view, &small()).unwrap();
        let mesh = group(&svg, "mesh");
        // One polygon per quad of the 9 x 9 sample grid.
        assert_eq!(
            mesh.matches("<polygon").count(),
            (n - 1) * (n - 1),
            "{view}"
        );
        let net = group(&svg, "control-net");
        assert_eq!(
            net.matches("class=\"control-point").count(),
            16,
            "{view}: 16 control points"
        );
        assert!(net.contains("stroke-dasharray"), "{view}: dashed net");
        assert!(svg.contains("linearGradient"), "{view}: colour bar");
        assert!(
            svg.lines().any(|l| l.contains("class=\"colorbar-label\"")
                && l.ends_with(&format!(">{name}</text>"))),
            "{view}: colour bar named {name}"
        );
        let legend = group(&svg, "legend");
        for entry in [">surface</text>", ">control net</text>"] {
            assert!(legend.contains(entry), "{view}: legend {entry}");
        }
        assert!(svg.contains(&format!("Neutrosophic Bézier surface: {name}")));
        for axis in [">x</text>", ">y</text>", ">z</text>"] {
            assert!(svg.contains(axis), "{view}: axis {axis}");
        }
    }
}

#[test]
fn surfaces_all_view_has_three_panels_and_one_colour_bar() {
    let model = PlotModel::from_surface(&bspline()).unwrap();
    let svg = render_svg(&model, View::All, &small()).unwrap();
    assert_eq!(svg.matches("class=\"panel-title\"").count(), 3);
    assert_eq!(svg.matches("<g class=\"mesh\"").count(), 3);
    assert_eq!(svg.matches("<g class=\"axes3d\"").count(), 3);
    assert_eq!(svg.matches("class=\"colorbar-label\"").count(), 1);
    for name in ["truth", "indeterminacy", "falsity"] {
        assert!(svg.contains(&format!(">{name}</text>")));
    }
}

#[test]
fn surfaces_controls_view_shows_degrees_of_every_point() {
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let svg = render_svg(&model, View::Controls, &small()).unwrap();
    let glyphs = group(&svg, "degree-glyphs");
    assert_eq!(glyphs.matches("class=\"degree-glyph\"").count(), 16);
    for kind in ["truth", "indeterminacy", "falsity"] {
        assert_eq!(glyphs.matches(&format!("class=\"bar {kind}\"")).count(), 16);
    }
    // The corners are named.
    for name in ["P00", "P03", "P30", "P33"] {
        assert!(svg.contains(&format!(">{name}</text>")), "{name}");
    }
    assert!(svg.contains("Neutrosophic control net"));
    // Given names are used.
    let names: Vec<String> = (0..16).map(|k| format!("Q{k}")).collect();
    let named = model.with_names(names).unwrap();
    let svg = render_svg(&named, View::Controls, &small()).unwrap();
    assert!(svg.contains(">Q15</text>") && !svg.contains(">P33</text>"));
}

#[test]
fn surfaces_large_net_shows_a_subset_of_glyphs() {
    let grid = (0..144)
        .map(|k| {
            let (i, j) = (f64::from(k / 12), f64::from(k % 12));
            point([i, j, (0.5 * i).sin() + (0.3 * j).cos()], [0.5, 0.5, 0.5])
        })
        .collect();
    let knots = KnotVector::clamped_uniform(3, 12).unwrap();
    let surface = Surface::bspline(12, 12, grid, knots.clone(), knots).unwrap();
    let model = PlotModel::from_surface(&surface).unwrap();
    let svg = render_svg(&model, View::Controls, &small()).unwrap();
    let glyphs = svg.matches("class=\"degree-glyph\"").count();
    assert!((4..=64).contains(&glyphs), "{glyphs} glyphs");
    assert!(svg.contains("Degrees shown at every"));
    assert!(svg.contains(">P11,11</text>"));
}

#[test]
fn surfaces_plane_view_maps_three_degrees_over_uv() {
    let model = PlotModel::from_surface(&bspline()).unwrap();
    let svg = render_svg(&model, View::Plane, &small()).unwrap();
    for name in ["truth", "indeterminacy", "falsity"] {
        let map = group(&svg, &format!("heat-map {name}"));
        assert_eq!(
            map.matches("<rect").count(),
            8 * 8,
            "{name}: one cell per quad"
        );
    }
    assert_eq!(svg.matches(">u</text>").count(), 3);
    assert_eq!(svg.matches(">v</text>").count(), 3);
    // One interior knot in each direction, drawn in each panel.
    assert_eq!(svg.matches("class=\"knot-line\"").count(), 6);
    assert!(group(&svg, "legend").contains(">knot lines</text>"));
    assert!(svg.contains("class=\"colorbar-label\""));
    // A Bézier surface has no interior knots.
    let bezier = PlotModel::from_surface(&bicubic()).unwrap();
    let svg = render_svg(&bezier, View::Plane, &small()).unwrap();
    assert!(!svg.contains("knot"));
}

#[test]
fn surfaces_determinism_same_input_same_bytes() {
    let model = PlotModel::from_surface(&quarter_cylinder()).unwrap();
    for view in View::MODEL {
        let a = render_svg(&model, view, &small()).unwrap();
        let b = render_svg(&model.clone(), view, &small()).unwrap();
        assert_eq!(a, b, "{view}");
    }
    let a = render_png(&model, View::Truth, &small()).unwrap();
    let b = render_png(&model, View::Truth, &small()).unwrap();
    assert_eq!(a, b);
}

#[test]
fn surfaces_default_samples_and_size() {
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let options = PlotOptions::default();
    assert_eq!(options.surface_samples(), 40);
    let svg = render_svg(&model, View::Truth, &options).unwrap();
    assert_eq!(group(&svg, "mesh").matches("<polygon").count(), 39 * 39);
    assert!(svg.len() < 400_000, "{} bytes", svg.len());
    let all = render_svg(&model, View::All, &options).unwrap();
    assert!(all.len() < 1_000_000, "{} bytes", all.len());
}

#[test]
fn surfaces_too_many_samples_is_an_error() {
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let err = render_svg(&model, View::Truth, &small().with_samples(101)).unwrap_err();
    assert_eq!(
        err,
        PlotError::InvalidSamples {
            samples: 101,
            min: 2,
            max: PlotOptions::MAX_SURFACE_SAMPLES
        }
    );
    // Curves keep their own limit.
    let curve = PlotModel::from(&neutrospline::example1());
    assert!(render_svg(&curve, View::Truth, &small().with_samples(101)).is_ok());
}

fn degenerate_surfaces() -> Vec<(&'static str, Surface)> {
    let d = [0.6, 0.3, 0.2];
    vec![
        (
            "1 x 1",
            Surface::bezier(1, 1, vec![point([1.0, 2.0, 3.0], d)]).unwrap(),
        ),
        (
            "all points equal",
            Surface::bezier(2, 2, vec![point([1.0, 1.0, 1.0], d); 4]).unwrap(),
        ),
        (
            "flat",
            Surface::bezier(
                3,
                3,
                (0..9)
                    .map(|k| point([f64::from(k / 3), f64::from(k % 3), 5.0], d))
                    .collect(),
            )
            .unwrap(),
        ),
        (
            "single row",
            Surface::bezier(
                1,
                4,
                (0..4)
                    .map(|j| point([f64::from(j), f64::from(j * j), 0.0], d))
                    .collect(),
            )
            .unwrap(),
        ),
        (
            "single column, all degrees 0",
            Surface::bezier(
                3,
                1,
                (0..3)
                    .map(|i| point([0.0, 0.0, f64::from(i)], [0.0, 0.0, 0.0]))
                    .collect(),
            )
            .unwrap(),
        ),
        (
            "huge coordinates",
            Surface::bezier(
                2,
                2,
                (0..4)
                    .map(|k| point([1e9 + f64::from(k / 2), 1e9 + f64::from(k % 2), 1e9], d))
                    .collect(),
            )
            .unwrap(),
        ),
    ]
}

#[test]
fn surfaces_degenerate_render_without_nan() {
    for (what, surface) in degenerate_surfaces() {
        let model = PlotModel::from_surface(&surface).unwrap();
        for view in View::MODEL {
            let svg = render_svg(&model, view, &small())
                .unwrap_or_else(|e| panic!("{what}, {view}: {e}"));
            check_svg(&svg);
        }
        // Edge-on and from below.
        for (az, el) in [(0.0, 0.0), (30.0, -60.0), (0.0, 90.0)] {
            let svg = render_svg(&model, View::Truth, &small().with_camera(az, el)).unwrap();
            check_svg(&svg);
        }
    }
    // The smallest grid that the samples allow.
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let svg = render_svg(&model, View::All, &small().with_samples(2)).unwrap();
    check_svg(&svg);
}

#[test]
fn surfaces_png_decodes_at_requested_size() {
    let model = PlotModel::from_surface(&bicubic()).unwrap();
    let png = render_png(&model, View::All, &small()).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(&png));
    let reader = decoder.read_info().unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (480, 360));
}
