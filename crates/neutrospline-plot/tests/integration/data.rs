//! The `data` view: measured points next to the curve fitted to them, with residual
//! whiskers; the checks of the data overlay and their messages; other views ignore it.

use neutrospline::{
    uniform_parameter, AnyCurve, BSpline, Bezier, ControlPoint, CurvePoint, DegreeKind, Degrees,
    Evaluate, Surface,
};
use neutrospline_plot::{
    render_png, render_svg, DataOverlay, PlotError, PlotModel, PlotOptions, View,
};

fn cp2(x: f64, y: f64, d: [f64; 3]) -> ControlPoint<2> {
    ControlPoint::new([x, y], Degrees::new(d[0], d[1], d[2]).unwrap())
}

/// A cubic B-spline along y = sin x on [0, 2 pi].
fn sine_curve() -> AnyCurve<2> {
    let controls = (0..9)
        .map(|k| {
            let x = std::f64::consts::TAU * f64::from(k) / 8.0;
            cp2(x, 1.2 * x.sin(), [0.9 - 0.1 * f64::from(k), 0.3, 0.1])
        })
        .collect();
    AnyCurve::from(BSpline::clamped_uniform(controls, 3).unwrap())
}

/// `n` points off the sine curve at known parameters, pushed off it by a deterministic
/// wobble, with degrees that change along them.
fn sine_data(curve: &AnyCurve<2>, n: usize) -> (Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<f64>) {
    let domain = curve.domain();
    let mut positions = Vec::new();
    let mut degrees = Vec::new();
    let mut ts = Vec::new();
    for k in 0..n {
        let t = uniform_parameter(k, n, domain.clone());
        let p = curve.evaluate(t).unwrap().position;
        let wobble = 0.2 * ((k * 7919) % 13) as f64 / 13.0 - 0.1;
        positions.push([p[0] + 0.3 * wobble, p[1] + wobble, 0.0]);
        let s = k as f64 / (n - 1).max(1) as f64;
        degrees.push([1.0 - s, 0.5 * s, s * s]);
        ts.push(t);
    }
    (positions, degrees, ts)
}

fn sine_model(n: usize, parameters: bool) -> PlotModel {
    let curve = sine_curve();
    let (positions, degrees, ts) = sine_data(&curve, n);
    let mut overlay = DataOverlay::new(positions, degrees);
    if parameters {
        overlay = overlay.with_parameters(ts);
    }
    PlotModel::from_any(&curve)
        .unwrap()
        .with_data(overlay)
        .unwrap()
}

fn helix() -> Bezier<3> {
    let p = |x: f64, y: f64, z: f64, t: f64| {
        ControlPoint::new([x, y, z], Degrees::new(t, 0.2, 1.0 - t).unwrap())
    };
    Bezier::new(vec![
        p(2.0, 0.0, 0.0, 0.9),
        p(2.0, 3.0, 1.0, 0.6),
        p(-2.0, 3.0, 2.0, 0.4),
        p(-2.0, 0.0, 3.0, 0.1),
    ])
    .unwrap()
}

fn helix_model(parameters: bool) -> PlotModel {
    let curve = helix();
    let mut positions = Vec::new();
    let mut degrees = Vec::new();
    let mut ts = Vec::new();
    for k in 0..25 {
        let t = f64::from(k) / 24.0;
        let p = curve.evaluate(t).unwrap().position;
        let w = 0.15 * (f64::from(k) * 1.7).sin();
        positions.push([p[0] + w, p[1] - w, p[2] + 0.5 * w]);
        degrees.push([t, 0.3, 1.0 - t]);
        ts.push(t);
    }
    let mut overlay = DataOverlay::new(positions, degrees).with_color_by(DegreeKind::Falsity);
    if parameters {
        overlay = overlay.with_parameters(ts);
    }
    PlotModel::from(&curve).with_data(overlay).unwrap()
}

fn options() -> PlotOptions {
    PlotOptions::default().with_size(800, 600).with_samples(80)
}

fn count(svg: &str, class: &str) -> usize {
    svg.matches(&format!("class=\"{class}\"")).count()
}

/// Every `<line class="residual" .../>` as (x1, y1, x2, y2), as written.
fn whiskers(svg: &str) -> Vec<[String; 4]> {
    svg.lines()
        .filter(|l| l.contains("class=\"residual\""))
        .map(|l| {
            ["x1", "y1", "x2", "y2"].map(|a| {
                let key = format!(" {a}=\"");
                let start = l.find(&key).unwrap() + key.len();
                l[start..start + l[start..].find('"').unwrap()].to_string()
            })
        })
        .collect()
}

/// The vertices of the fitted curve's polylines, as written ("x,y").
fn curve_vertices(svg: &str) -> Vec<String> {
    svg.lines()
        .filter(|l| l.contains("class=\"curve fitted\""))
        .flat_map(|l| {
            let start = l.find(" points=\"").unwrap() + 9;
            let end = start + l[start..].find('"').unwrap();
            l[start..end]
                .split(' ')
                .map(str::to_string)
                .collect::<Vec<_>>()
        })
        .collect()
}

/// The texts of the figure, in order, joined by spaces (wrapped notes read as one).
fn texts(svg: &str) -> String {
    svg.lines()
        .filter_map(|l| {
            let start = l.find("<text ")?;
            let l = &l[start..];
            let open = l.find('>')? + 1;
            let close = l.find("</text>")?;
            Some(l[open..close].replace("&apos;", "'"))
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn check_document(svg: &str, width: u32, height: u32) {
    assert!(svg.starts_with("<?xml") && svg.trim_end().ends_with("</svg>"));
    for bad in ["NaN", "inf", "Infinity"] {
        assert!(!svg.contains(bad), "SVG contains {bad}");
    }
    assert!(svg.contains(&format!("viewBox=\"0 0 {width} {height}\"")));
}

#[test]
fn data_view_2d_draws_curve_points_whiskers_and_legend() {
    let model = sine_model(60, true);
    let svg = render_svg(&model, View::Data, &options()).unwrap();
    check_document(&svg, 800, 600);
    assert_eq!(count(&svg, "data-point"), 60);
    assert_eq!(count(&svg, "residual"), 60);
    assert_eq!(count(&svg, "curve fitted"), 1);
    for label in ["fitted curve", "data point", "residual"] {
        assert!(
            svg.lines().any(|l| l.contains("class=\"legend-label\"")
                && l.ends_with(&format!(">{label}</text>"))),
            "legend entry {label}"
        );
    }
    assert!(svg.contains(">truth of the data</text>"));
    assert!(svg.contains(">Neutrosophic B-spline curve fitted to data</text>"));
    assert!(svg.contains(">x</text>") && svg.contains(">y</text>"));
    assert!(texts(&svg)
        .contains("60 data points. Residuals run to the curve at each point's parameter."));
    // No control points, no callouts, no names.
    assert!(!svg.contains("control-point") && !svg.contains("control-polygon"));
    assert!(!svg.contains("callout"));
    // The markers are filled with the viridis colour of truth: the first point (truth 1)
    // yellow, the last (truth 0) dark purple.
    let fills: Vec<&str> = svg
        .lines()
        .filter(|l| l.contains("class=\"data-point\""))
        .map(|l| {
            let s = l.find(" fill=\"").unwrap() + 7;
            &l[s..s + 7]
        })
        .collect();
    assert_eq!(fills[0], "#fde725");
    assert_eq!(fills[59], "#440154");
}

#[test]
fn data_view_whiskers_end_on_the_curve_at_the_parameters() {
    // The data's parameters are the curve's sample parameters (60 points, 60 samples), so
    // each whisker must end exactly on a vertex of the fitted curve's polyline.
    let model = sine_model(60, true);
    let svg = render_svg(&model, View::Data, &options().with_samples(60)).unwrap();
    let vertices = curve_vertices(&svg);
    assert_eq!(vertices.len(), 60);
    let ends = whiskers(&svg);
    assert_eq!(ends.len(), 60);
    for (k, w) in ends.iter().enumerate() {
        assert_eq!(format!("{},{}", w[2], w[3]), vertices[k], "whisker {k}");
    }
}

#[test]
fn data_view_without_parameters_goes_to_the_nearest_point() {
    // A straight line y = x / 2 from (0, 0) to (4, 2): the nearest point to (x, y) is the
    // foot of the perpendicular, t = (x + y / 2) / 5 along it.
    let line = Bezier::new(vec![
        cp2(0.0, 0.0, [0.5, 0.5, 0.5]),
        cp2(4.0, 2.0, [0.5, 0.5, 0.5]),
    ])
    .unwrap();
    let pts = [[1.0, 2.0, 0.0], [3.0, 0.0, 0.0], [2.0, 1.0, 0.0]];
    let overlay = DataOverlay::new(pts.to_vec(), vec![[0.2, 0.4, 0.6]; 3]);
    let model = PlotModel::from(&line).with_data(overlay).unwrap();
    let svg = render_svg(&model, View::Data, &options()).unwrap();
    assert!(texts(&svg).contains("Residuals run to the nearest point of the curve."));
    let ends = whiskers(&svg);
    // The whisker of the point on the line has zero length, and all three are
    // perpendicular to the line: (dx, dy) . (2, 1) = 0 up to the two decimals written.
    let px = |s: &String| s.parse::<f64>().unwrap();
    for w in &ends {
        let (dx, dy) = (px(&w[2]) - px(&w[0]), px(&w[3]) - px(&w[1]));
        // Pixels have y down: the line's direction on screen is (2, -1).
        assert!((2.0 * dx - dy).abs() < 0.05, "{w:?}");
    }
    assert_eq!((&ends[2][0], &ends[2][1]), (&ends[2][2], &ends[2][3]));
    // The feet of (1, 2) and (3, 0) are (1.6, 0.8) and (2.4, 1.2): mirror images about the
    // line's middle (2, 1), whose pixel is the third whisker.
    let mid = (px(&ends[2][0]), px(&ends[2][1]));
    let (a, b) = (
        (px(&ends[0][2]), px(&ends[0][3])),
        (px(&ends[1][2]), px(&ends[1][3])),
    );
    assert!((a.0 + b.0 - 2.0 * mid.0).abs() < 0.02 && (a.1 + b.1 - 2.0 * mid.1).abs() < 0.02);
}

#[test]
fn data_view_3d_draws_in_the_box() {
    for parameters in [true, false] {
        let model = helix_model(parameters);
        let svg = render_svg(&model, View::Data, &options()).unwrap();
        check_document(&svg, 800, 600);
        assert_eq!(count(&svg, "data-point"), 25);
        assert_eq!(count(&svg, "residual"), 25);
        assert!(
            count(&svg, "curve fitted") >= 2,
            "curve in depth-sorted pieces"
        );
        assert!(svg.contains("class=\"curve shadow\""));
        assert!(svg.contains(">falsity of the data</text>"));
        assert!(svg.contains(">shadow on the floor</text>"));
        assert!(svg.contains(">z</text>"));
        assert!(svg.contains(">Neutrosophic Bézier curve fitted to data</text>"));
    }
}

#[test]
fn data_view_thousands_of_points_shrink_markers() {
    let radius = |svg: &str| -> f64 {
        let l = svg
            .lines()
            .find(|l| l.contains("class=\"data-point\""))
            .unwrap();
        let s = l.find(" r=\"").unwrap() + 4;
        l[s..s + l[s..].find('"').unwrap()].parse().unwrap()
    };
    let few = render_svg(&sine_model(150, true), View::Data, &options()).unwrap();
    let many = render_svg(&sine_model(3000, false), View::Data, &options()).unwrap();
    assert_eq!(count(&many, "data-point"), 3000);
    assert_eq!(count(&many, "residual"), 3000);
    assert!(
        radius(&many) < 0.5 * radius(&few),
        "{} vs {}",
        radius(&many),
        radius(&few)
    );
    assert!(texts(&many).contains("3000 data points"));
}

#[test]
fn data_view_of_samples_and_single_points() {
    // A model given as samples has the domain [0, 1], joined by straight lines.
    let samples: Vec<CurvePoint<2>> = (0..5)
        .map(|k| cp2(f64::from(k), 0.0, [0.5, 0.5, 0.5]))
        .collect();
    let model = PlotModel::from_samples(&samples, &samples[..1]).unwrap();
    let overlay = DataOverlay::new(vec![[1.5, 1.0, 0.0], [3.0, -1.0, 0.0]], vec![[0.5; 3]; 2]);
    let with_t = model
        .clone()
        .with_data(overlay.clone().with_parameters(vec![0.375, 0.75]))
        .unwrap();
    let nearest = model.with_data(overlay).unwrap();
    let a = whiskers(&render_svg(&with_t, View::Data, &options()).unwrap());
    let b = whiskers(&render_svg(&nearest, View::Data, &options()).unwrap());
    assert_eq!(
        a, b,
        "t = 0.375 is x = 1.5 and t = 0.75 is x = 3 on the polyline"
    );
    // One data point, a one-point curve.
    let one = PlotModel::from_samples(&samples[..1], &samples[..1])
        .unwrap()
        .with_data(DataOverlay::new(
            vec![[0.0, 0.0, 0.0]],
            vec![[1.0, 0.0, 0.0]],
        ))
        .unwrap();
    let svg = render_svg(&one, View::Data, &options()).unwrap();
    check_document(&svg, 800, 600);
    assert!(texts(&svg).contains("1 data point. Residuals run to the nearest point of the curve."));
}

#[test]
fn data_view_png_and_determinism() {
    let model = sine_model(60, true);
    let png = render_png(&model, View::Data, &options()).unwrap();
    assert!(png.starts_with(b"\x89PNG"));
    let a = render_svg(&model, View::Data, &options()).unwrap();
    let b = render_svg(&sine_model(60, true), View::Data, &options()).unwrap();
    assert_eq!(a, b);
}

#[test]
fn data_other_views_ignore_the_overlay() {
    let curve = sine_curve();
    let bare = PlotModel::from_any(&curve).unwrap();
    let with = sine_model(60, true);
    for view in View::MODEL {
        assert_eq!(
            render_svg(&bare, view, &options()).unwrap(),
            render_svg(&with, view, &options()).unwrap(),
            "{view}"
        );
    }
    let space = PlotModel::from(&helix());
    let with = helix_model(false);
    for view in View::MODEL {
        assert_eq!(
            render_svg(&space, view, &options()).unwrap(),
            render_svg(&with, view, &options()).unwrap(),
            "{view}"
        );
    }
}

#[test]
fn data_errors_and_messages() {
    let model = PlotModel::from_any(&sine_curve()).unwrap();
    let good = || DataOverlay::new(vec![[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]], vec![[0.5; 3]; 2]);
    let err = |data: DataOverlay| model.clone().with_data(data).unwrap_err();
    let message = |e: PlotError| e.to_string();

    // No data: the data view says how to give some.
    let e = render_svg(&model, View::Data, &options()).unwrap_err();
    assert_eq!(e, PlotError::NoData);
    assert_eq!(
        message(e),
        "the data view needs data points (neutrospline plot MODEL --data DATA.csv, or neutrospline fit --plot)"
    );

    // A surface takes (u, v) parameters, inside its domain; a curve takes t.
    let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
    let grid = (0..4)
        .map(|k| ControlPoint::new([f64::from(k / 2), f64::from(k % 2), 0.0], d))
        .collect();
    let surface = PlotModel::from_surface(&Surface::bezier(2, 2, grid).unwrap()).unwrap();
    assert_eq!(
        render_svg(&surface, View::Data, &options()).unwrap_err(),
        PlotError::NoData
    );
    let on_surface = |data: DataOverlay| surface.clone().with_data(data).unwrap_err();
    assert_eq!(
        message(on_surface(good().with_parameters(vec![0.0, 1.0]))),
        "the data points' curve parameters t do not fit a surface"
    );
    assert_eq!(
        message(on_surface(
            good().with_surface_parameters(vec![[0.0, 0.5], [0.5, 1.5]])
        )),
        "data point 1: parameter v = 1.5 is outside the surface's domain [0, 1] in v"
    );
    assert_eq!(
        message(on_surface(good().with_surface_parameters(vec![[0.0, 0.5]]))),
        "1 (u, v) parameters given for 2 data points"
    );
    assert_eq!(
        message(err(good().with_surface_parameters(vec![[0.0, 0.5]; 2]))),
        "the data points' surface parameters (u, v) do not fit a curve"
    );

    assert_eq!(
        message(err(DataOverlay::new(Vec::new(), Vec::new()))),
        "the data overlay has no data points (give at least one)"
    );
    assert_eq!(
        err(DataOverlay::new(Vec::new(), Vec::new())),
        PlotError::EmptyData
    );
    assert_eq!(
        message(err(DataOverlay::new(vec![[0.0; 3]; 3], vec![[0.5; 3]; 2]))),
        "2 degree triples given for 3 data points"
    );
    assert_eq!(
        err(good().with_parameters(vec![0.5])),
        PlotError::DataCount {
            what: "parameters",
            count: 1,
            points: 2
        }
    );
    assert_eq!(
        message(err(good().with_parameters(vec![0.5]))),
        "1 parameters given for 2 data points"
    );
    let mut nan = good();
    nan.positions[1][1] = f64::NAN;
    assert_eq!(
        message(err(nan)),
        "data point 1: y = NaN is not a finite number"
    );
    let mut inf = good();
    inf.degrees[0][1] = f64::INFINITY;
    assert_eq!(
        message(err(inf)),
        "data point 0: indeterminacy = inf is not a finite number"
    );
    assert_eq!(
        message(err(good().with_parameters(vec![0.0, f64::NAN]))),
        "data point 1: t = NaN is not a finite number"
    );
    let mut high = good();
    high.degrees[1][2] = 1.25;
    assert_eq!(
        message(err(high)),
        "data point 1: falsity = 1.25 is outside [0, 1]"
    );
    // The B-spline's domain is [0, 1].
    let e = err(good().with_parameters(vec![0.5, 1.5]));
    assert_eq!(
        e,
        PlotError::ParameterOutsideDomain {
            index: 1,
            value: 1.5,
            start: 0.0,
            end: 1.0
        }
    );
    assert_eq!(
        message(e),
        "data point 1: parameter t = 1.5 is outside the curve's domain [0, 1]"
    );
    assert_eq!(
        message(err(good().with_parameters(vec![-0.25, 0.5]))),
        "data point 0: parameter t = -0.25 is outside the curve's domain [0, 1]"
    );
    // The ends of the domain are inside it.
    assert!(model
        .clone()
        .with_data(good().with_parameters(vec![0.0, 1.0]))
        .is_ok());
    // A view name that does not exist lists the data view.
    assert_eq!(
        message("scatter".parse::<View>().unwrap_err()),
        "unknown view \"scatter\" (expected one of: controls, truth, indeterminacy, falsity, all, plane, score, derived, data, band)"
    );
}

#[test]
fn data_overlay_accessors() {
    let model = sine_model(10, true);
    let data = model.data().unwrap();
    assert_eq!(data.positions.len(), 10);
    assert_eq!(data.color_by, DegreeKind::Truth);
    assert_eq!(data.parameters.as_ref().map(Vec::len), Some(10));
    assert!(PlotModel::from_any(&sine_curve()).unwrap().data().is_none());
    assert!(format!("{model:?}").ends_with("with 10 data points"));
}

/// The data view of a surface: the plane z = x + y/2 (a bilinear Bezier patch over the unit
/// square, degrees varying) with points above and below it; each whisker runs from the point
/// to the surface at its (u, v), here straight down or up (the patch is S(u, v) = (u, v,
/// u + v / 2)), so its ends have the same x and y on screen only through the camera: checked
/// in the model's coordinates by the whisker count and the points' colours.
#[test]
fn the_data_view_of_a_surface_draws_the_mesh_points_and_whiskers() {
    let corners = [
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.5],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.5],
    ];
    let grid = corners
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            let truth = 0.2 + 0.2 * k as f64;
            ControlPoint::new(p, Degrees::new(truth, 0.1, 0.1).unwrap())
        })
        .collect();
    let surface = Surface::bezier(2, 2, grid).unwrap();
    let model = PlotModel::from_surface(&surface).unwrap();
    let (mut positions, mut degrees, mut uv) = (Vec::new(), Vec::new(), Vec::new());
    for k in 0..25 {
        let (u, v) = (f64::from(k / 5) / 4.0, f64::from(k % 5) / 4.0);
        let lift = if k % 2 == 0 { 0.1 } else { -0.1 };
        positions.push([u, v, u + v / 2.0 + lift]);
        degrees.push([u, 0.1, 0.1]);
        uv.push([u, v]);
    }
    let data = DataOverlay::new(positions, degrees).with_surface_parameters(uv.clone());
    let with_data = model.clone().with_data(data).unwrap();
    let options = PlotOptions::default().with_size(800, 600);
    let svg = render_svg(&with_data, View::Data, &options).unwrap();
    assert_eq!(svg.matches("class=\"data-point\"").count(), 25);
    assert_eq!(svg.matches("class=\"residual\"").count(), 25);
    assert!(
        svg.contains("fitted surface"),
        "the legend names the surface"
    );
    // The legend's note, its wrapped lines joined.
    let words: Vec<&str> = svg
        .split("</text>")
        .filter_map(|chunk| chunk.rsplit_once('>').map(|(_, text)| text))
        .collect();
    let note = words.join(" ").replace("&apos;", "'");
    assert!(
        note.contains("25 data points. Residuals run to the surface at each point's (u, v)."),
        "{note}"
    );
    assert!(
        note.contains("Points and surface coloured by truth."),
        "{note}"
    );
    // Without parameters the whiskers run to the nearest points: for a plane, the feet of the
    // perpendiculars, which differ from the points at the same (u, v).
    let nearest = model
        .with_data(DataOverlay::new(
            (0..25)
                .map(|k| {
                    let (u, v) = (f64::from(k / 5) / 4.0, f64::from(k % 5) / 4.0);
                    [u, v, u + v / 2.0 + 0.1]
                })
                .collect(),
            vec![[0.5, 0.1, 0.1]; 25],
        ))
        .unwrap();
    let svg = render_svg(&nearest, View::Data, &options).unwrap();
    assert_eq!(svg.matches("class=\"residual\"").count(), 25);
    assert!(svg.contains("nearest point of the"));
    assert!(render_png(&with_data, View::Data, &options).is_ok());
}
