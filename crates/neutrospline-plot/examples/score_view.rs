//! Renders the `score` view of the paper's Example 1 (2-D), of the repository's
//! `examples/helix3d.toml` (a 3-D curve) and of `examples/surface.toml` (a bicubic surface),
//! at the default size and small, to SVG and PNG.
//!
//! ```text
//! cargo run --release -p neutrospline-plot --example score_view -- [OUT_DIR]
//! ```
//!
//! `OUT_DIR` defaults to `/tmp/scoreview`. The two TOML files are read by a small line reader
//! that knows only their control-point tables (one inline table per line, with `name`,
//! `x`, `y`, `z` and `T`, `I`, `F` or `truth`, `indeterminacy`, `falsity`): this crate does
//! not depend on `neutrospline-io`.

use std::error::Error;
use std::path::{Path, PathBuf};

use neutrospline::{Bezier, ControlPoint, Degrees, Surface};
use neutrospline_plot::{render_svg, svg_to_png, PlotModel, PlotOptions, View};

/// A control point of an example file: its name, position and degrees.
struct Row {
    name: String,
    pos: [f64; 3],
    deg: [f64; 3],
}

/// The control points of an example TOML file: every line holding an inline table.
fn rows(path: &Path) -> Result<Vec<Row>, Box<dyn Error>> {
    let text = std::fs::read_to_string(path)?;
    let mut out = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        let Some(body) = line
            .strip_prefix('{')
            .and_then(|l| l.trim_end_matches(',').strip_suffix('}'))
        else {
            continue;
        };
        let mut row = Row {
            name: String::new(),
            pos: [0.0; 3],
            deg: [0.0; 3],
        };
        for field in body.split(',') {
            let (key, value) = field.split_once('=').ok_or("a field without '='")?;
            let value = value.trim();
            let slot = match key.trim() {
                "name" => {
                    row.name = value.trim_matches('"').to_string();
                    continue;
                }
                "x" => &mut row.pos[0],
                "y" => &mut row.pos[1],
                "z" => &mut row.pos[2],
                "T" | "truth" => &mut row.deg[0],
                "I" | "indeterminacy" => &mut row.deg[1],
                "F" | "falsity" => &mut row.deg[2],
                other => return Err(format!("unknown field {other}").into()),
            };
            *slot = value.parse()?;
        }
        out.push(row);
    }
    Ok(out)
}

fn control(row: &Row) -> Result<ControlPoint<3>, Box<dyn Error>> {
    let [t, i, f] = row.deg;
    Ok(ControlPoint::new(row.pos, Degrees::new(t, i, f)?))
}

fn repo_file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
}

fn write(
    out: &Path,
    stem: &str,
    model: &PlotModel,
    options: &PlotOptions,
) -> Result<(), Box<dyn Error>> {
    let svg = render_svg(model, View::Score, options)?;
    let png = svg_to_png(&svg, options.width(), options.height())?;
    std::fs::write(out.join(format!("{stem}.svg")), &svg)?;
    std::fs::write(out.join(format!("{stem}.png")), &png)?;
    println!("{stem}: svg {} bytes, png {} bytes", svg.len(), png.len());
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("/tmp/scoreview"), PathBuf::from);
    std::fs::create_dir_all(&out)?;

    let example1 =
        PlotModel::from(&neutrospline::example1()).with_names(neutrospline::EXAMPLE1_NAMES)?;

    let helix_rows = rows(&repo_file("helix3d.toml"))?;
    let helix = Bezier::new(helix_rows.iter().map(control).collect::<Result<_, _>>()?)?;
    let helix = PlotModel::from(&helix).with_names(helix_rows.iter().map(|r| r.name.clone()))?;

    let surface_rows = rows(&repo_file("surface.toml"))?;
    let surface = Surface::bezier(
        4,
        4,
        surface_rows.iter().map(control).collect::<Result<_, _>>()?,
    )?;
    let surface = PlotModel::from_surface(&surface)?
        .with_names(surface_rows.iter().map(|r| r.name.clone()))?;

    for (stem, model) in [
        ("example1", &example1),
        ("helix3d", &helix),
        ("surface", &surface),
    ] {
        write(
            &out,
            &format!("{stem}-score"),
            model,
            &PlotOptions::default(),
        )?;
        let small = PlotOptions::default().with_size(640, 480);
        write(&out, &format!("{stem}-score-small"), model, &small)?;
    }
    Ok(())
}
