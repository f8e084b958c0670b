//! Renders every view of Example 1 (2-D), a 3-D cubic, a B-spline, a NURBS circle and three
//! surfaces (bicubic Bézier, B-spline, NURBS quarter cylinder) to SVG and PNG.
//!
//! ```text
//! cargo run -p neutrospline-plot --example render_all -- [OUT_DIR] [--degenerate]
//! ```
//!
//! `OUT_DIR` defaults to `/tmp/plots`. With `--degenerate`, also renders models that test the
//! layout's edge cases (a single point, a straight line, all degrees 0 or 1, a 1 x 1
//! surface, a flat one, one whose points are all equal, a single row).

use std::error::Error;
use std::path::{Path, PathBuf};

use neutrospline::{AnyCurve, BSpline, Bezier, ControlPoint, Degrees, KnotVector, Nurbs, Surface};
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

fn cp3(p: [f64; 3], d: [f64; 3]) -> Result<ControlPoint<3>, Box<dyn Error>> {
    Ok(ControlPoint::new(p, Degrees::new(d[0], d[1], d[2])?))
}

/// A bicubic Bézier patch: a saddle-like bump whose truth grows along u, falsity along v and
/// indeterminacy peaks in the middle.
fn bezier_surface() -> Result<Surface, Box<dyn Error>> {
    let z = [
        [0.0, 0.6, 0.4, 0.0],
        [0.8, 2.6, 1.8, 0.4],
        [0.4, 2.2, 3.0, 1.0],
        [0.0, 0.6, 1.2, 0.2],
    ];
    let mut grid = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let (u, v) = (f64::from(i) / 3.0, f64::from(j) / 3.0);
            let mid = 1.0 - ((u - 0.5).powi(2) + (v - 0.5).powi(2)) * 2.0;
            grid.push(cp3(
                [
                    2.0 * f64::from(i),
                    2.0 * f64::from(j),
                    z[i as usize][j as usize],
                ],
                [0.1 + 0.8 * u, 0.1 + 0.8 * mid.max(0.0), 0.05 + 0.9 * v * v],
            )?);
        }
    }
    Ok(Surface::bezier(4, 4, grid)?)
}

/// A bicubic B-spline surface over a 6 x 6 net (knot lines at thirds).
fn bspline_surface() -> Result<Surface, Box<dyn Error>> {
    let mut grid = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            let (x, y) = (f64::from(i), f64::from(j));
            let z = 1.5 * (0.9 * x).sin() * (0.7 * y).cos() + 0.2 * y;
            let t = 0.5 + 0.45 * (0.8 * x - 0.5 * y).sin();
            let ind = 0.15 + 0.7 * ((x - 2.5).abs() / 2.5) * ((y - 2.5).abs() / 2.5);
            grid.push(cp3([x, y, z], [t, ind, 1.0 - t])?);
        }
    }
    let knots = KnotVector::clamped_uniform(3, 6)?;
    Ok(Surface::bspline(6, 6, grid, knots.clone(), knots)?)
}

/// A NURBS quarter cylinder of radius 2 and height 4: the exact circular arc (degree 2,
/// weights 1, 1/sqrt 2, 1) along u, a quadratic along the axis in v.
fn quarter_cylinder() -> Result<Surface, Box<dyn Error>> {
    let arc = [[2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    let w = [1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0];
    let mut grid = Vec::new();
    let mut weights = Vec::new();
    for (i, p) in arc.iter().enumerate() {
        for j in 0..3 {
            let (a, h) = (i as f64 / 2.0, f64::from(j) / 2.0);
            grid.push(cp3(
                [p[0], p[1], 4.0 * h],
                [0.2 + 0.7 * a, 0.6 - 0.5 * h, 0.1 + 0.5 * h * (1.0 - a)],
            )?);
            weights.push(w[i]);
        }
    }
    let knots = KnotVector::clamped_uniform(2, 3)?;
    Ok(Surface::nurbs(3, 3, grid, weights, knots.clone(), knots)?)
}

/// A NURBS full circle of radius 2 (nine control points, degree 2) whose degrees change
/// around it.
fn nurbs_circle() -> Result<PlotModel, Box<dyn Error>> {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let square = [
        [2.0, 0.0],
        [2.0, 2.0],
        [0.0, 2.0],
        [-2.0, 2.0],
        [-2.0, 0.0],
        [-2.0, -2.0],
        [0.0, -2.0],
        [2.0, -2.0],
        [2.0, 0.0],
    ];
    let controls = square
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            let a = k as f64 / 8.0 * std::f64::consts::TAU;
            let d = Degrees::new(
                0.5 + 0.4 * a.cos(),
                0.3 + 0.25 * (2.0 * a).sin(),
                0.5 - 0.4 * a.cos(),
            )?;
            Ok(ControlPoint::new(p, d))
        })
        .collect::<Result<Vec<_>, Box<dyn Error>>>()?;
    let weights = (0..9).map(|k| if k % 2 == 0 { 1.0 } else { h }).collect();
    let knots = KnotVector::new(
        vec![
            0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
        ],
        2,
        9,
    )?;
    let curve = AnyCurve::from(Nurbs::new(controls, weights, knots)?);
    Ok(PlotModel::from_any(&curve)?)
}

/// Writes `view` of `model` as `tag-view.svg` and `.png`, and reports the sizes.
fn write(
    out: &Path,
    tag: &str,
    model: &PlotModel,
    view: View,
    options: &PlotOptions,
) -> Result<(), Box<dyn Error>> {
    let svg = render_svg(model, view, options)?;
    let png = svg_to_png(&svg, options.width(), options.height())?;
    std::fs::write(out.join(format!("{tag}-{view}.svg")), &svg)?;
    std::fs::write(out.join(format!("{tag}-{view}.png")), &png)?;
    println!(
        "{tag}-{view}: svg {} bytes, png {} bytes",
        svg.len(),
        png.len()
    );
    Ok(())
}

fn degenerate_surfaces() -> Result<Vec<(&'static str, Surface)>, Box<dyn Error>> {
    let d = [0.6, 0.3, 0.2];
    let flat = (0..9)
        .map(|k| {
            cp3(
                [f64::from(k / 3), f64::from(k % 3), 1.0],
                [0.1 * f64::from(k), 0.5, 0.2],
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(vec![
        (
            "surface-1x1",
            Surface::bezier(1, 1, vec![cp3([1.0, 2.0, 3.0], d)?])?,
        ),
        ("surface-flat", Surface::bezier(3, 3, flat)?),
        (
            "surface-equal",
            Surface::bezier(2, 2, vec![cp3([1.0, 1.0, 1.0], d)?; 4])?,
        ),
        (
            "surface-row",
            Surface::bezier(
                1,
                4,
                (0..4)
                    .map(|j| cp3([f64::from(j), 0.5 * f64::from(j * j), 0.0], d))
                    .collect::<Result<Vec<_>, _>>()?,
            )?,
        ),
    ])
}

fn degenerate(out: &std::path::Path) -> Result<(), Box<dyn Error>> {
    for (tag, surface) in degenerate_surfaces()? {
        let model = PlotModel::from_surface(&surface)?;
        for view in View::MODEL {
            write(
                out,
                &format!("degenerate-{tag}"),
                &model,
                view,
                &PlotOptions::default(),
            )?;
        }
    }
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
        for view in [
            View::Controls,
            View::Truth,
            View::All,
            View::Plane,
            View::Score,
        ] {
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
        for view in View::MODEL {
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
    let curves = [("bspline", wave()?), ("nurbs-circle", nurbs_circle()?)];
    for (tag, model) in &curves {
        for view in View::MODEL {
            write(
                &out,
                tag,
                model,
                view,
                &PlotOptions::default().with_samples(400),
            )?;
        }
    }
    let surfaces = [
        ("bezier-surface", bezier_surface()?),
        ("bspline-surface", bspline_surface()?),
        ("nurbs-surface", quarter_cylinder()?),
    ];
    for (tag, surface) in &surfaces {
        let model = PlotModel::from_surface(surface)?;
        for view in View::MODEL {
            write(&out, tag, &model, view, &PlotOptions::default())?;
        }
    }
    // The multi-panel views at other sizes and aspects.
    let bezier_surface = PlotModel::from_surface(&surfaces[0].1)?;
    for (w, h) in [(800, 600), (1200, 1600), (2000, 800)] {
        let options = PlotOptions::default().with_size(w, h);
        for (tag, model) in [("3d", &space), ("bezier-surface", &bezier_surface)] {
            for view in [View::All, View::Plane, View::Truth] {
                let svg = render_svg(model, view, &options)?;
                let png = svg_to_png(&svg, w, h)?;
                std::fs::write(out.join(format!("{tag}-{view}-{w}x{h}.png")), &png)?;
            }
        }
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
