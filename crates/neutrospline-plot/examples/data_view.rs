//! Renders the `data` view of curves fitted to noisy data: 60 points along y = sin x (with
//! the fit's parameters, and without them: whiskers to the nearest point), coloured by each
//! degree; a noisy 3-D helix; 3,000 points; and a small figure.
//!
//! ```text
//! cargo run --release -p neutrospline-plot --example data_view -- [OUT_DIR]
//! ```
//!
//! `OUT_DIR` defaults to `/tmp/dataview`.

use std::error::Error;
use std::path::PathBuf;

use neutrospline::fit::{fit, FitData, FitOptions, FitTarget};
use neutrospline::{DegreeKind, Degrees};
use neutrospline_plot::{render_svg, svg_to_png, DataOverlay, PlotModel, PlotOptions, View};

/// A deterministic noise source (a 64-bit LCG), uniform in [-1, 1).
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// `n` noisy points along y = sin x, x in [0, 2 pi], with degrees that change along them.
fn sine(n: usize, noise: f64) -> (Vec<[f64; 2]>, Vec<Degrees>) {
    let mut rng = Noise(7);
    let mut positions = Vec::new();
    let mut degrees = Vec::new();
    for k in 0..n {
        let x = std::f64::consts::TAU * k as f64 / (n - 1) as f64;
        positions.push([x + 0.3 * noise * rng.next(), x.sin() + noise * rng.next()]);
        let s = k as f64 / (n - 1) as f64;
        let t = (0.9 - 0.8 * s + 0.05 * rng.next()).clamp(0.0, 1.0);
        let i = (0.5 + 0.4 * (3.0 * x).sin() * (x / 2.0).sin()).clamp(0.0, 1.0);
        let f = (0.1 + 0.8 * s * s).clamp(0.0, 1.0);
        degrees.push(Degrees::new(t, i, f).expect("degrees in [0, 1]"));
    }
    (positions, degrees)
}

fn overlay<const D: usize>(positions: &[[f64; D]], degrees: &[Degrees]) -> DataOverlay {
    DataOverlay::new(
        positions
            .iter()
            .map(|p| {
                let mut q = [0.0; 3];
                q[..D].copy_from_slice(p);
                q
            })
            .collect(),
        degrees.iter().map(|d| d.to_array()).collect(),
    )
}

fn write(
    out: &std::path::Path,
    name: &str,
    model: &PlotModel,
    options: &PlotOptions,
) -> Result<(), Box<dyn Error>> {
    let svg = render_svg(model, View::Data, options)?;
    std::fs::write(out.join(format!("{name}.svg")), &svg)?;
    let png = svg_to_png(&svg, options.width(), options.height())?;
    std::fs::write(out.join(format!("{name}.png")), png)?;
    println!("{name}: {} bytes of SVG", svg.len());
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "/tmp/dataview".to_string()),
    );
    std::fs::create_dir_all(&out)?;
    let options = PlotOptions::default();

    // 60 noisy points along y = sin x, fitted by a cubic B-spline of 10 control points.
    let (positions, degrees) = sine(60, 0.15);
    let data = FitData::new(positions.clone(), degrees.clone())?;
    let fitted = fit(
        &data,
        &FitOptions::default().with_target(FitTarget::ControlPoints(10)),
    )?;
    let model = PlotModel::from_any(&fitted.curve)?;
    let at_parameters = overlay(&positions, &degrees).with_parameters(fitted.parameters.clone());
    for kind in DegreeKind::ALL {
        let m = model
            .clone()
            .with_data(at_parameters.clone().with_color_by(kind))?;
        write(&out, &format!("sine-{}", kind.name()), &m, &options)?;
    }
    let nearest = model.clone().with_data(overlay(&positions, &degrees))?;
    write(&out, "sine-nearest", &nearest, &options)?;
    write(
        &out,
        "sine-small",
        &model.clone().with_data(at_parameters.clone())?,
        &PlotOptions::default().with_size(640, 480),
    )?;
    write(
        &out,
        "sine-tall",
        &model.with_data(at_parameters)?,
        &PlotOptions::default()
            .with_size(900, 1200)
            .with_caption("60 noisy points along y = sin x; a cubic B-spline of 10 control points fitted by least squares."),
    )?;

    // A noisy helix in 3-D.
    let mut rng = Noise(11);
    let helix: Vec<[f64; 3]> = (0..80)
        .map(|k| {
            let a = k as f64 / 79.0 * 3.0 * std::f64::consts::PI;
            [
                2.0 * a.cos() + 0.15 * rng.next(),
                2.0 * a.sin() + 0.15 * rng.next(),
                0.5 * a + 0.15 * rng.next(),
            ]
        })
        .collect();
    let helix_degrees: Vec<Degrees> = (0..80)
        .map(|k| {
            let s = k as f64 / 79.0;
            Degrees::new(0.2 + 0.7 * s, 0.3, 0.8 - 0.6 * s)
        })
        .collect::<Result<_, _>>()?;
    let data = FitData::new(helix.clone(), helix_degrees.clone())?;
    let fitted = fit(
        &data,
        &FitOptions::default().with_target(FitTarget::ControlPoints(12)),
    )?;
    let model = PlotModel::from_any(&fitted.curve)?
        .with_data(overlay(&helix, &helix_degrees).with_parameters(fitted.parameters.clone()))?;
    write(&out, "helix", &model, &options)?;

    // 3,000 noisy points: small markers, no callouts.
    let (positions, degrees) = sine(3000, 0.2);
    let data = FitData::new(positions.clone(), degrees.clone())?;
    let fitted = fit(
        &data,
        &FitOptions::default().with_target(FitTarget::ControlPoints(12)),
    )?;
    let model = PlotModel::from_any(&fitted.curve)?
        .with_data(overlay(&positions, &degrees).with_parameters(fitted.parameters.clone()))?;
    write(&out, "sine-3000", &model, &options)?;
    Ok(())
}
