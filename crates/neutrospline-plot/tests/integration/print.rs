//! Figures for print: PDF pages that look like the PNG of the same figure (rendered by
//! Poppler's `pdftoppm`) with the bundled font embedded (`pdffonts`) and the text extractable
//! (`pdftotext`); print sizes in the SVG and the PDF; the resolution recorded in the PNG; the
//! paper style's text sizes.
//!
//! The Poppler checks run when `pdftoppm`, `pdffonts` and `pdftotext` are installed (Debian:
//! poppler-utils); `NEUTROSPLINE_REQUIRE_POPPLER=1` (set by CI) turns their absence into a
//! failure.

use std::path::{Path, PathBuf};
use std::process::Command;

use neutrospline_plot::{
    render_figure, FigureFormat, FigureStyle, Length, LengthUnit, PlotModel, PlotOptions, View,
};

fn poppler() -> bool {
    let found = ["pdftoppm", "pdffonts", "pdftotext"]
        .iter()
        .all(|tool| Command::new(tool).arg("-v").output().is_ok());
    let required = std::env::var("NEUTROSPLINE_REQUIRE_POPPLER").is_ok_and(|v| v == "1");
    assert!(
        found || !required,
        "NEUTROSPLINE_REQUIRE_POPPLER=1 but pdftoppm, pdffonts or pdftotext is missing"
    );
    if !found {
        eprintln!("skipped: poppler-utils is not installed");
    }
    found
}

fn temp_dir(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("neutrospline-print-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The pixels of a PNG as grey levels, with its size.
fn grey(png: &[u8]) -> (Vec<f64>, u32, u32) {
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    buf.truncate(info.buffer_size());
    let levels = buf
        .chunks_exact(channels)
        .map(|p| (f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2])) / 3.0)
        .collect();
    (levels, info.width, info.height)
}

/// Renders the PDF with pdftoppm to exactly `width` x `height` pixels.
fn pdf_to_png(dir: &Path, pdf: &[u8], width: u32, height: u32) -> Vec<u8> {
    let path = dir.join("figure.pdf");
    std::fs::write(&path, pdf).unwrap();
    let status = Command::new("pdftoppm")
        .args(["-png", "-singlefile", "-scale-to-x"])
        .arg(width.to_string())
        .arg("-scale-to-y")
        .arg(height.to_string())
        .arg(&path)
        .arg(dir.join("render"))
        .status()
        .unwrap();
    assert!(status.success());
    std::fs::read(dir.join("render.png")).unwrap()
}

/// Mean grey level of each of `n x n` blocks.
fn blocks(levels: &[f64], width: u32, height: u32, n: usize) -> Vec<f64> {
    let (w, h) = (width as usize, height as usize);
    let mut sums = vec![(0.0, 0usize); n * n];
    for (i, v) in levels.iter().enumerate() {
        let (x, y) = (i % w, i / w);
        let b = (y * n / h) * n + x * n / w;
        sums[b].0 += v;
        sums[b].1 += 1;
    }
    sums.into_iter().map(|(s, c)| s / c as f64).collect()
}

fn models() -> Vec<(&'static str, PlotModel, View)> {
    let example = || {
        PlotModel::from_bezier(&neutrospline::example1())
            .unwrap()
            .with_names(neutrospline::EXAMPLE1_NAMES)
            .unwrap()
    };
    let surface = neutrospline_io::load(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/surface.toml"),
        &neutrospline_io::ReadOptions::default(),
    )
    .unwrap();
    vec![
        ("example1 controls", example(), View::Controls),
        ("example1 all", example(), View::All),
        ("example1 plane", example(), View::Plane),
        (
            "surface truth",
            PlotModel::from_model(&surface).unwrap(),
            View::Truth,
        ),
    ]
}

/// The PDF page, rendered by Poppler, looks like our PNG of the same figure: the mean grey
/// level of each block of an 8 x 8 grid within 5 levels (of 255; measured: at most 3.3), and the share of ink
/// (pixels darker than 200) within 10 % of the PNG's (measured: 8 %): the same shapes, colours and text in
/// the same places (the two rasterizers differ in anti-aliasing and kerning only).
#[test]
fn pdf_pages_render_like_the_png() {
    if !poppler() {
        return;
    }
    let dir = temp_dir("render");
    for (name, model, view) in models() {
        for options in [
            PlotOptions::default().with_size(800, 600),
            PlotOptions::default().with_style(FigureStyle::Paper),
        ] {
            let png = render_figure(&model, view, &options, FigureFormat::Png).unwrap();
            let pdf = render_figure(&model, view, &options, FigureFormat::Pdf).unwrap();
            let (ours, w, h) = grey(&png);
            let (theirs, tw, th) = grey(&pdf_to_png(&dir, &pdf, w, h));
            assert_eq!((tw, th), (w, h), "{name}");
            let (a, b) = (blocks(&ours, w, h, 8), blocks(&theirs, w, h, 8));
            let worst = a
                .iter()
                .zip(&b)
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max);
            let ink = |v: &[f64]| v.iter().filter(|&&g| g < 200.0).count() as f64 / v.len() as f64;
            let (ink_ours, ink_theirs) = (ink(&ours), ink(&theirs));
            eprintln!(
                "{name} {:?}: worst block {worst:.2} levels, ink {ink_ours:.4} vs {ink_theirs:.4}",
                options.style()
            );
            assert!(
                worst < 5.0,
                "{name}: block differs by {worst:.2} grey levels"
            );
            assert!(
                (ink_ours - ink_theirs).abs() < 0.1 * ink_ours,
                "{name}: ink {ink_ours} vs {ink_theirs}"
            );
        }
    }
}

/// The PDF embeds its fonts as subsets with Unicode maps, and its text reads back.
#[test]
fn pdf_fonts_are_embedded_and_the_text_extracts() {
    if !poppler() {
        return;
    }
    let dir = temp_dir("fonts");
    let (_, model, _) = models().remove(0);
    let pdf = render_figure(
        &model,
        View::Controls,
        &PlotOptions::default(),
        FigureFormat::Pdf,
    )
    .unwrap();
    let path = dir.join("controls.pdf");
    std::fs::write(&path, &pdf).unwrap();
    let fonts = Command::new("pdffonts").arg(&path).output().unwrap();
    let fonts = String::from_utf8(fonts.stdout).unwrap();
    let rows: Vec<&str> = fonts.lines().skip(2).collect();
    assert_eq!(rows.len(), 2, "{fonts}");
    for row in rows {
        let words: Vec<&str> = row.split_whitespace().collect();
        assert!(
            words[0].ends_with("+DejaVuSans") || words[0].ends_with("+DejaVuSans-Bold"),
            "{row}"
        );
        assert_eq!(words[1..4], ["CID", "TrueType", "Identity-H"], "{row}");
        assert_eq!(words[4..7], ["yes", "yes", "yes"], "emb sub uni: {row}");
    }
    let text = Command::new("pdftotext")
        .arg(&path)
        .arg("-")
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    for expected in [
        "Neutrosophic control points",
        "C1",
        "0.8",
        "control polygon",
        "falsity (F)",
    ] {
        assert!(text.contains(expected), "{expected:?} not in\n{text}");
    }
}

/// A print size: the SVG states it, the PDF page is exactly it, the PNG has its pixels at
/// the resolution and records the resolution; a size in pixels records none unless asked.
#[test]
fn print_sizes_reach_every_format() {
    let (_, model, _) = models().remove(1);
    let cm = |v| Length::new(v, LengthUnit::Cm);
    let options = PlotOptions::default().with_print_size(cm(8.5), cm(6.0));
    let svg =
        String::from_utf8(render_figure(&model, View::Truth, &options, FigureFormat::Svg).unwrap())
            .unwrap();
    assert!(svg.contains("width=\"8.5cm\" height=\"6cm\" viewBox=\"0 0 241 170\""));
    let pdf = render_figure(&model, View::Truth, &options, FigureFormat::Pdf).unwrap();
    let text = String::from_utf8_lossy(&pdf);
    // 8.5 cm = 240.944882 pt, 6 cm = 170.07874 pt.
    assert!(
        text.contains("/MediaBox [0 0 240.944882 170.07874]"),
        "{}",
        &text[..400]
    );
    for (dpi, pixels, per_metre) in [(None, (1004, 709), 11811), (Some(150.0), (502, 354), 5906)] {
        let options = match dpi {
            Some(dpi) => options.clone().with_dpi(dpi),
            None => options.clone(),
        };
        let png = render_figure(&model, View::Truth, &options, FigureFormat::Png).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(&png))
            .read_info()
            .unwrap();
        let info = reader.info();
        assert_eq!((info.width, info.height), pixels);
        let dims = info.pixel_dims.unwrap();
        assert_eq!((dims.xppu, dims.yppu), (per_metre, per_metre));
        assert_eq!(dims.unit, png::Unit::Meter);
    }
    let pixels = PlotOptions::default().with_size(400, 300);
    let png = render_figure(&model, View::Truth, &pixels, FigureFormat::Png).unwrap();
    let reader = png::Decoder::new(std::io::Cursor::new(&png))
        .read_info()
        .unwrap();
    assert!(reader.info().pixel_dims.is_none());
    let png = render_figure(
        &model,
        View::Truth,
        &pixels.with_dpi(96.0),
        FigureFormat::Png,
    )
    .unwrap();
    let reader = png::Decoder::new(std::io::Cursor::new(&png))
        .read_info()
        .unwrap();
    assert_eq!(reader.info().pixel_dims.unwrap().xppu, 3780);
}

/// The paper style: no title or caption unless given, one column wide, tick labels at 8.5 pt
/// and axis names at 42/36 of that.
#[test]
fn paper_style_sets_print_text_sizes() {
    let (_, model, _) = models().remove(0);
    let paper = PlotOptions::default()
        .with_style(FigureStyle::Paper)
        .with_caption("");
    let svg = String::from_utf8(
        render_figure(&model, View::Controls, &paper, FigureFormat::Svg).unwrap(),
    )
    .unwrap();
    assert!(
        svg.contains("width=\"8.5cm\" height=\"7cm\" viewBox=\"0 0 241 198\""),
        "{}",
        &svg[..300]
    );
    assert!(!svg.contains("class=\"title\""));
    assert!(!svg.contains("class=\"caption\""));
    assert!(svg.contains("class=\"tick-label\" font-size=\"8.5\""));
    assert!(svg.contains("class=\"axis-label\" font-size=\"9.92\""));
    let titled = paper.clone().with_title("Fig. 1");
    let svg = String::from_utf8(
        render_figure(&model, View::Controls, &titled, FigureFormat::Svg).unwrap(),
    )
    .unwrap();
    assert!(svg.contains(">Fig. 1</text>"));
    // The default style keeps its title, and a size in pixels its proportional text.
    let svg = String::from_utf8(
        render_figure(
            &model,
            View::Controls,
            &PlotOptions::default(),
            FigureFormat::Svg,
        )
        .unwrap(),
    )
    .unwrap();
    assert!(svg.contains("class=\"tick-label\" font-size=\"36\""));
}

/// Sizes and resolutions out of range are refused with their rule.
#[test]
fn print_options_out_of_range_are_refused() {
    let (_, model, _) = models().remove(0);
    let cm = |v| Length::new(v, LengthUnit::Cm);
    let tiny = PlotOptions::default().with_print_size(cm(2.0), cm(6.0));
    assert_eq!(
        render_figure(&model, View::All, &tiny, FigureFormat::Pdf)
            .unwrap_err()
            .to_string(),
        "figure size 2cmx6cm is not supported (each side must be between 64 and 16384 points, \
         2.26 cm to 5.78 m)"
    );
    let dpi = PlotOptions::default().with_dpi(0.0);
    assert_eq!(
        render_figure(&model, View::All, &dpi, FigureFormat::Png)
            .unwrap_err()
            .to_string(),
        "dpi = 0 is not supported (must be between 10 and 10000)"
    );
    let poster = PlotOptions::default()
        .with_print_size(cm(100.0), cm(80.0))
        .with_dpi(600.0);
    assert_eq!(
        render_figure(&model, View::All, &poster, FigureFormat::Png)
            .unwrap_err()
            .to_string(),
        "a PNG of 100cmx80cm at 600 dpi would be 23622x18898 pixels (each side must be between \
         64 and 16384; change --dpi or give the size in pixels)"
    );
    // The same poster is fine as vector output.
    assert!(render_figure(&model, View::All, &poster, FigureFormat::Pdf).is_ok());
}
