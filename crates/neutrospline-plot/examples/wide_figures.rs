//! Renders the figures of the wide families (interval-valued and bipolar, docs/model.md
//! "Lanes") from the model files under `tests/wide/`, to PNG:
//!
//! ```text
//! cargo run -p neutrospline-plot --example wide_figures -- [OUT_DIR]
//! ```
//!
//! `OUT_DIR` defaults to `/tmp/wide-figures`.

use std::error::Error;
use std::path::PathBuf;

use neutrospline_io::{parse, Format, ReadOptions};
use neutrospline_plot::{render_png, PlotModel, PlotOptions, View};

const FIGURES: [(&str, &str, View); 6] = [
    (
        "interval-truth",
        include_str!("../tests/wide/interval.toml"),
        View::Truth,
    ),
    (
        "interval-all",
        include_str!("../tests/wide/interval.toml"),
        View::All,
    ),
    (
        "type2-truth",
        include_str!("../tests/wide/type2.toml"),
        View::Truth,
    ),
    (
        "bipolar-all",
        include_str!("../tests/wide/bipolar.toml"),
        View::All,
    ),
    (
        "bipolar-truth",
        include_str!("../tests/wide/bipolar.toml"),
        View::Truth,
    ),
    (
        "surface-truth",
        include_str!("../tests/wide/surface.toml"),
        View::Truth,
    ),
];

fn main() -> Result<(), Box<dyn Error>> {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("/tmp/wide-figures"), PathBuf::from);
    std::fs::create_dir_all(&out)?;
    for (name, text, view) in FIGURES {
        let model = parse(
            &format!("{name}.toml"),
            Format::Toml,
            text.as_bytes(),
            &ReadOptions::default(),
        )?;
        let figure = PlotModel::from_model(&model)?;
        let png = render_png(&figure, view, &PlotOptions::default())?;
        let path = out.join(format!("{name}.png"));
        std::fs::write(&path, png)?;
        println!("{}", path.display());
    }
    Ok(())
}
