//! Renders every view of Example 1 (2-D) and of a 3-D cubic to SVG and PNG.
//!
//! ```text
//! cargo run -p neutrospline-plot --example render_all -- [OUT_DIR] [--degenerate]
//! ```
//!
//! `OUT_DIR` defaults to `/tmp/plots`. With `--degenerate`, also renders models that test the
//! layout's edge cases (a single point, a straight line, all degrees 0 or 1).

use std::error::Error;
use std::path::PathBuf;

use neutrospline::{AnyCurve, BSpline, Bezier, ControlPoint, Degrees};
use neutrospline_plot::{render_svg, svg_to_png, PlotModel, PlotOptions, View};

const ERRATUM: &str = "Example 1 of Mahmud et al., Table 1 data. Erratum: the paper's Table 3 \
gives C3 an indeterminacy of 0.1; Table 1, which defines the example, gives 0.4, used here.";

fn space_curve() -> Result<Bezier<3>, Box<dyn Error>> {
    let p = |x, y, z, t, i, f| -> Result<ControlPoint<3>, Box<dyn Error>> {
        Ok(ControlPoint::new([x, y, z], Degrees::new(t, i, f)?))
    };
    Ok(Bezier::new(vec![
        p(0.0, 0.0, 0.0, 0.9, 0.1, 0.0)?,
        p(2.0, 5.0, 1.0, 0.6, 0.5, 0.2)?,
        p(6.0, -1.0, 3.0, 0.3, 0.2, 0.6)?,
        p(8.0, 4.0, 4.0, 0.1, 0.3, 0.9)?,
    ])?)
}

fn line(points: &[[f64; 5]]) -> Result<PlotModel, Box<dyn Error>> {
    let controls = points
        .iter()
        .map(|&[x, y, t, i, f]| Ok(ControlPoint::new([x, y], Degrees::new(t, i, f)?)))
        .collect::<Result<Vec<_>, Box<dyn Error>>>()?;
    Ok(PlotModel::from(&Bezier::new(controls)?))
}

fn degenerate(out: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let models = [
        ("single", line(&[[2.0, 3.0, 0.5, 0.2, 0.3]])?),
        (
            "horizontal",
            line(&[
                [0.0, 2.0, 0.1, 0.5, 0.9],
                [1.0, 2.0, 0.5, 0.5, 0.5],
                [3.0, 2.0, 0.9, 0.5, 0.1],
            ])?,
        ),
        (
            "zeros",
            line(&[
                [0.0, 0.0, 0.0, 0.0, 0.0],
                [1.0, 2.0, 0.0, 0.0, 0.0],
                [3.0, 1.0, 0.0, 0.0, 0.0],
            ])?,
        ),
        (
            "ones",
            line(&[
                [0.0, 0.0, 1.0, 1.0, 1.0],
                [1.0, 2.0, 1.0, 1.0, 1.0],
                [3.0, 1.0, 1.0, 1.0, 1.0],
            ])?,
        ),
    ];
    for (tag, model) in &models {
        for view in [View::Controls, View::Truth, View::All, View::Plane] {
            let options = PlotOptions::default();
            let svg = render_svg(model, view, &options)?;
            let png = svg_to_png(&svg, options.width(), options.height())?;
            std::fs::write(out.join(format!("degenerate-{tag}-{view}.png")), &png)?;
        }
    }
    Ok(())
}

/// A cubic B-spline with 14 control points (more than the callouts show in full).
fn wave() -> Result<PlotModel, Box<dyn Error>> {
    let controls = (0..14)
        .map(|i| {
            let x = f64::from(i);
            let s = (x * 0.9).sin();
            let d = Degrees::new(0.5 + 0.45 * s, 0.5 - 0.4 * (x * 0.5).cos(), 0.05 * x)?;
            Ok(ControlPoint::new([x, 2.0 * s + 0.2 * x], d))
        })
        .collect::<Result<Vec<_>, Box<dyn Error>>>()?;
    let curve = AnyCurve::from(BSpline::clamped_uniform(controls, 3)?);
    Ok(PlotModel::from_any(&curve)?)
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = PathBuf::from(
        args.iter()
            .find(|a| !a.starts_with("--"))
            .cloned()
            .unwrap_or_else(|| "/tmp/plots".into()),
    );
    std::fs::create_dir_all(&out)?;
    let plane =
        PlotModel::from(&neutrospline::example1()).with_names(neutrospline::EXAMPLE1_NAMES)?;
    let space = PlotModel::from(&space_curve()?).with_names(["P0", "P1", "P2", "P3"])?;
    let options = PlotOptions::default().with_caption(ERRATUM);
    for (tag, model, options) in [
        ("2d", &plane, &options),
        ("3d", &space, &PlotOptions::default()),
    ] {
        for view in View::ALL {
            let svg = render_svg(model, view, options)?;
            let png = svg_to_png(&svg, options.width(), options.height())?;
            std::fs::write(out.join(format!("{tag}-{view}.svg")), &svg)?;
            std::fs::write(out.join(format!("{tag}-{view}.png")), &png)?;
            println!(
                "{tag}-{view}: svg {} bytes, png {} bytes",
                svg.len(),
                png.len()
            );
        }
    }
    let wave = wave()?;
    for view in [View::Controls, View::Plane, View::All, View::Truth] {
        let options = PlotOptions::default().with_samples(400);
        let svg = render_svg(&wave, view, &options)?;
        let png = svg_to_png(&svg, options.width(), options.height())?;
        std::fs::write(out.join(format!("bspline-{view}.png")), &png)?;
    }
    // Another camera: from the other side, steeper.
    let turned = PlotOptions::default().with_camera(130.0, 50.0);
    for (tag, model) in [("2d", &plane), ("3d", &space)] {
        let svg = render_svg(model, View::Truth, &turned)?;
        let png = svg_to_png(&svg, turned.width(), turned.height())?;
        std::fs::write(out.join(format!("{tag}-truth-az130-el50.png")), &png)?;
    }
    if args.iter().any(|a| a == "--degenerate") {
        degenerate(&out)?;
    }
    Ok(())
}
