//! Layout audit of finished figures (tests only): reads the SVG back, measures every text
//! with the bundled font's metrics, and checks that texts and the legend lie on the canvas
//! and that the legend covers no label of the drawing.

use crate::font::text_width;
use crate::layout::Rect;

/// Ascent and descent of a text run, in units of its font size (DejaVu Sans, rounded up from
/// the tallest Latin letters and the deepest descenders).
const ASCENT: f64 = 0.76;
const DESCENT: f64 = 0.24;

/// A `<text>` element as drawn: its class, content and bounding box.
#[derive(Debug, Clone)]
pub(crate) struct TextBox {
    pub class: String,
    pub text: String,
    pub rect: Rect,
    /// Inside the legend's group.
    pub in_legend: bool,
}

/// What the audit reads from a figure.
#[derive(Debug, Clone, Default)]
pub(crate) struct Drawn {
    pub texts: Vec<TextBox>,
    /// The legend's frame (the first rectangle of its group).
    pub legend: Option<Rect>,
}

fn attr<'a>(element: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = element.find(&key)? + key.len();
    let rest = &element[start..];
    Some(&rest[..rest.find('"')?])
}

fn number(element: &str, name: &str) -> f64 {
    attr(element, name)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("attribute {name} in {element}"))
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

fn text_box(line: &str) -> (String, String, Rect) {
    let open_end = line.find('>').expect("end of the text tag");
    let tag = &line[..open_end];
    let content = unescape(&line[open_end + 1..line.rfind("</text>").expect("closed text")]);
    let (x, y, size) = (number(tag, "x"), number(tag, "y"), number(tag, "font-size"));
    let bold = attr(tag, "font-weight") == Some("bold");
    let w = text_width(&content, size, bold);
    let (before, after) = match attr(tag, "text-anchor") {
        Some("middle") => (w / 2.0, w / 2.0),
        Some("end") => (w, 0.0),
        _ => (0.0, w),
    };
    let rect = if tag.contains("rotate(-90") {
        // Rotated about the anchor: the text runs upwards, its ascent points left.
        Rect::new(
            x - ASCENT * size,
            y - after,
            (ASCENT + DESCENT) * size,
            before + after,
        )
    } else {
        assert!(!tag.contains("rotate("), "unexpected rotation: {tag}");
        Rect::new(
            x - before,
            y - ASCENT * size,
            before + after,
            (ASCENT + DESCENT) * size,
        )
    };
    let class = attr(tag, "class").unwrap_or("").to_string();
    (class, content, rect)
}

/// Reads the texts and the legend frame of an SVG written by this crate (one element per
/// line).
pub(crate) fn read(svg: &str) -> Drawn {
    let mut drawn = Drawn::default();
    // Open groups: whether each is the legend.
    let mut groups: Vec<bool> = Vec::new();
    let mut legend_open = false;
    for line in svg.lines().map(str::trim_start) {
        if line.starts_with("<g ") {
            let is_legend = line.starts_with("<g class=\"legend\"");
            legend_open |= is_legend;
            groups.push(is_legend);
        } else if line.starts_with("</g>") {
            if groups.pop() == Some(true) {
                legend_open = false;
            }
        } else if line.starts_with("<text ") {
            let (class, text, rect) = text_box(line);
            drawn.texts.push(TextBox {
                class,
                text,
                rect,
                in_legend: legend_open,
            });
        } else if line.starts_with("<rect ") && legend_open && drawn.legend.is_none() {
            drawn.legend = Some(Rect::new(
                number(line, "x"),
                number(line, "y"),
                number(line, "width"),
                number(line, "height"),
            ));
        }
    }
    drawn
}

/// A text box less its descent and a sliver of each side: glyphs rarely fill their box, so
/// boxes that merely touch are not a collision.
fn shrunk(r: &Rect) -> Rect {
    let (dx, dy) = (0.04 * r.w.min(r.h), 0.12 * r.w.min(r.h));
    Rect::new(r.x + dx, r.y + dy, r.w - 2.0 * dx, r.h - 2.0 * dy)
}

/// Everything wrong with the layout of `svg` on a `width` x `height` canvas: texts or the
/// legend off the canvas, the legend over a label or title.
pub(crate) fn problems(svg: &str, width: u32, height: u32) -> Vec<String> {
    const TOL: f64 = 0.5;
    let (w, h) = (f64::from(width), f64::from(height));
    let inside =
        |r: &Rect| r.x >= -TOL && r.y >= -TOL && r.right() <= w + TOL && r.bottom() <= h + TOL;
    let drawn = read(svg);
    let mut out = Vec::new();
    for t in &drawn.texts {
        if !inside(&t.rect) {
            out.push(format!(
                "text {:?} ({}) off the canvas: {:?}",
                t.text, t.class, t.rect
            ));
        }
    }
    // Texts of the drawing (titles, labels, names) must not run into each other.
    for (i, a) in drawn.texts.iter().enumerate() {
        for b in &drawn.texts[i + 1..] {
            if a.in_legend || b.in_legend {
                continue;
            }
            if shrunk(&a.rect).overlap(&shrunk(&b.rect)) > 0.0 {
                out.push(format!(
                    "text {:?} ({}) at {:?} overlaps text {:?} ({}) at {:?}",
                    a.text, a.class, a.rect, b.text, b.class, b.rect
                ));
            }
        }
    }
    if let Some(legend) = drawn.legend {
        if !inside(&legend) {
            out.push(format!("legend off the canvas: {legend:?}"));
        }
        for t in drawn.texts.iter().filter(|t| !t.in_legend) {
            if legend.overlap(&t.rect) > 0.0 {
                out.push(format!(
                    "legend {legend:?} covers text {:?} ({}) at {:?}",
                    t.text, t.class, t.rect
                ));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{render_svg, PlotModel, PlotOptions, View};
    use neutrospline::{
        AnyCurve, BSpline, Bezier, ControlPoint, Degrees, KnotVector, Nurbs, Surface,
    };

    fn point3(p: [f64; 3], d: [f64; 3]) -> ControlPoint<3> {
        ControlPoint::new(p, Degrees::new(d[0], d[1], d[2]).unwrap())
    }

    fn models() -> Vec<(&'static str, PlotModel, PlotOptions)> {
        let example = PlotModel::from(&neutrospline::example1())
            .with_names(neutrospline::EXAMPLE1_NAMES)
            .unwrap();
        let space = Bezier::new(vec![
            point3([0.0, 0.0, 0.0], [0.9, 0.1, 0.0]),
            point3([2.0, 5.0, 1.0], [0.6, 0.5, 0.2]),
            point3([6.0, -1.0, 3.0], [0.3, 0.2, 0.6]),
            point3([8.0, 4.0, 4.0], [0.1, 0.3, 0.9]),
        ])
        .unwrap();
        let space = PlotModel::from(&space)
            .with_names(["P0", "P1", "P2", "P3"])
            .unwrap();
        let wave: Vec<ControlPoint<2>> = (0..14)
            .map(|i| {
                let x = f64::from(i);
                let s = (x * 0.9).sin();
                let d = Degrees::new(0.5 + 0.45 * s, 0.5 - 0.4 * (x * 0.5).cos(), 0.05 * x);
                ControlPoint::new([x, 2.0 * s + 0.2 * x], d.unwrap())
            })
            .collect();
        let wave = PlotModel::from_any(&AnyCurve::from(BSpline::clamped_uniform(wave, 3).unwrap()))
            .unwrap();
        let surface = |rows: usize, cols: usize, z: &dyn Fn(f64, f64) -> f64| {
            let grid = (0..rows * cols)
                .map(|k| {
                    let (i, j) = ((k / cols) as f64, (k % cols) as f64);
                    let d = [0.1 + 0.2 * i, 0.8 - 0.1 * j, 0.05 * (i + j)];
                    point3([i, j, z(i, j)], d.map(|v: f64| v.clamp(0.0, 1.0)))
                })
                .collect();
            PlotModel::from_surface(&Surface::bezier(rows, cols, grid).unwrap()).unwrap()
        };
        let bump = surface(4, 4, &|i, j| (i * (3.0 - i) * j * (3.0 - j)) / 4.0);
        let row = surface(1, 5, &|_, j| j * j / 4.0);
        let mesh = PlotOptions::default().with_samples(10);
        // A NURBS full circle: nine control points, the first and last equal.
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
        let ring: Vec<ControlPoint<2>> = square
            .iter()
            .enumerate()
            .map(|(k, &p)| {
                let a = k as f64 / 8.0 * std::f64::consts::TAU;
                let d = Degrees::new(0.5 + 0.4 * a.cos(), 0.3, 0.5 - 0.4 * a.cos());
                ControlPoint::new(p, d.unwrap())
            })
            .collect();
        let weights = (0..9).map(|k| if k % 2 == 0 { 1.0 } else { h }).collect();
        let knots = KnotVector::new(
            vec![
                0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
            ],
            2,
            9,
        )
        .unwrap();
        let circle =
            PlotModel::from_any(&AnyCurve::from(Nurbs::new(ring, weights, knots).unwrap()))
                .unwrap();
        let caption = "Example 1 of the paper, Table 1 data. Erratum: Table 3 gives C3 an \
                       indeterminacy of 0.1; Table 1 gives 0.4.";
        let curve = PlotOptions::default().with_samples(60);
        vec![
            ("example 1", example, curve.clone().with_caption(caption)),
            ("3-D cubic", space, curve.clone()),
            ("B-spline", wave, curve.clone()),
            ("NURBS circle", circle, curve),
            ("bicubic surface", bump, mesh.clone()),
            ("single-row surface", row, mesh),
        ]
    }

    const SIZES: [(u32, u32); 4] = [(1600, 1200), (800, 600), (1200, 1600), (2000, 800)];

    #[test]
    fn audit_reads_text_boxes() {
        let svg = "<g class=\"legend\">\n<rect x=\"10\" y=\"20\" width=\"30\" height=\"40\"/>\n\
                   <text x=\"12\" y=\"30\" class=\"legend-label\" font-size=\"10\" fill=\"#000\">a&amp;b</text>\n\
                   </g>\n<text x=\"100\" y=\"50\" font-size=\"10\" fill=\"#000\" text-anchor=\"middle\" \
                   transform=\"rotate(-90 100 50)\">y</text>\n";
        let drawn = read(svg);
        assert_eq!(drawn.legend, Some(Rect::new(10.0, 20.0, 30.0, 40.0)));
        assert_eq!(drawn.texts.len(), 2);
        assert!(drawn.texts[0].in_legend && !drawn.texts[1].in_legend);
        assert_eq!(drawn.texts[0].text, "a&b");
        let y = drawn.texts[1].rect;
        assert!((y.x - 92.4).abs() < 1e-9 && (y.w - 10.0).abs() < 1e-9);
        assert!((y.centre().1 - 50.0).abs() < 1e-9);
        // A legend over a label is reported.
        let covered = "<g class=\"legend\">\n<rect x=\"0\" y=\"0\" width=\"500\" height=\"500\"/>\n</g>\n\
                       <text x=\"100\" y=\"100\" class=\"axis-label\" font-size=\"10\" fill=\"#000\">x</text>\n";
        assert_eq!(problems(covered, 1000, 1000).len(), 1);
        assert_eq!(problems(covered, 400, 400).len(), 2);
        // Texts running into each other are reported; texts side by side are not.
        let text = |x: f64, y: f64, t: &str| {
            format!("<text x=\"{x}\" y=\"{y}\" class=\"tick-label\" font-size=\"20\" fill=\"#000\">{t}</text>\n")
        };
        let clash = text(100.0, 100.0, "0.5") + &text(120.0, 105.0, "1.0");
        assert_eq!(problems(&clash, 1000, 1000).len(), 1);
        let apart = text(100.0, 100.0, "0.5") + &text(100.0, 121.0, "1.0");
        assert!(problems(&apart, 1000, 1000).is_empty());
    }

    #[test]
    fn audit_data_view_every_size_keeps_texts_and_legend_clear() {
        use crate::DataOverlay;
        use neutrospline::DegreeKind;
        for (what, model, options) in models() {
            if model.is_surface() {
                continue;
            }
            // Points around the curve's samples, pushed off it, with parameters and without.
            let curve = model.curve_points(40).unwrap();
            let positions: Vec<[f64; 3]> = curve
                .iter()
                .enumerate()
                .map(|(k, p)| {
                    let w = 0.3 * (k as f64 * 1.3).sin();
                    [p.pos[0] + w, p.pos[1] - w, p.pos[2] + w]
                })
                .collect();
            let degrees = curve.iter().map(|p| p.deg).collect();
            let overlay = DataOverlay::new(positions, degrees);
            for (label, data) in [
                ("nearest", overlay.clone()),
                (
                    "indeterminacy",
                    overlay.clone().with_color_by(DegreeKind::Indeterminacy),
                ),
            ] {
                let model = model.clone().with_data(data).unwrap();
                for (w, h) in SIZES {
                    let options = options.clone().with_size(w, h);
                    let svg = render_svg(&model, View::Data, &options).unwrap();
                    let found = problems(&svg, w, h);
                    assert!(
                        found.is_empty(),
                        "{what}, data ({label}), {w}x{h}:\n{}",
                        found.join("\n")
                    );
                }
            }
        }
    }

    #[test]
    fn audit_every_view_every_size_keeps_texts_and_legend_clear() {
        for (what, model, options) in models() {
            for (w, h) in SIZES {
                let options = options.clone().with_size(w, h);
                for view in View::MODEL {
                    let svg = render_svg(&model, view, &options).unwrap();
                    let found = problems(&svg, w, h);
                    assert!(
                        found.is_empty(),
                        "{what}, {view}, {w}x{h}:\n{}",
                        found.join("\n")
                    );
                }
            }
        }
    }

    /// The wide families' figures (interval-valued and bipolar, tests/wide/) and two families'
    /// examples (their score and derived views) at every size,
    /// in every view they draw: texts on the canvas, the legend clear of the labels.
    #[test]
    fn audit_wide_families_every_size_keeps_texts_and_legend_clear() {
        let files = [
            ("interval.toml", include_str!("../tests/wide/interval.toml")),
            ("type2.toml", include_str!("../tests/wide/type2.toml")),
            ("bipolar.toml", include_str!("../tests/wide/bipolar.toml")),
            ("surface.toml", include_str!("../tests/wide/surface.toml")),
            (
                "bipolar-surface.toml",
                include_str!("../tests/wide/bipolar-surface.toml"),
            ),
            (
                "pythagorean.toml",
                include_str!("../../../examples/families/pythagorean.toml"),
            ),
            (
                "picture.toml",
                include_str!("../../../examples/families/picture.toml"),
            ),
        ];
        let mut drawn = 0;
        for (name, text) in files {
            let model = neutrospline_io::parse(
                name,
                neutrospline_io::Format::Toml,
                text.as_bytes(),
                &neutrospline_io::ReadOptions::default(),
            )
            .unwrap();
            let model = PlotModel::from_model(&model).unwrap();
            let options = if model.is_surface() {
                PlotOptions::default().with_samples(10)
            } else {
                PlotOptions::default().with_samples(60)
            };
            for (w, h) in SIZES {
                let options = options.clone().with_size(w, h);
                for view in View::MODEL.into_iter().chain([View::Derived]) {
                    if model.check_view(view).is_err() {
                        continue;
                    }
                    let svg = render_svg(&model, view, &options).unwrap();
                    let found = problems(&svg, w, h);
                    assert!(
                        found.is_empty(),
                        "{name}, {view}, {w}x{h}:\n{}",
                        found.join("\n")
                    );
                    drawn += 1;
                }
            }
        }
        // interval: truth, indeterminacy, falsity, all, score; type-2: truth, all, score,
        // derived; bipolar: four and score; surface: truth, indeterminacy, falsity, score;
        // bipolar surface: the same; pythagorean: truth, falsity, score, derived; picture:
        // every view of a model; at four sizes.
        assert_eq!(drawn, 4 * (5 + 4 + 5 + 4 + 4 + 4 + 8));
    }
}
