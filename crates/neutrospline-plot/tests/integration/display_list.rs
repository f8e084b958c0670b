//! The display list is the SVG's drawing: for every view of a 2-D curve, a 3-D curve, a fuzzy
//! curve and two surfaces, the display list's operations and the SVG's elements are the same
//! primitives in the same order, with the same numbers, texts and colours.

use neutrospline_io::{load, ReadOptions};
use neutrospline_plot::{render_drawing, PlotModel, PlotOptions, View};
use serde_json::Value;

/// One primitive, as both encodings can state it.
#[derive(Debug, PartialEq)]
enum Prim {
    /// A group opening (plain, mesh or clipped: the number is the mesh width or the clip
    /// rectangle's x).
    Open(Option<f64>),
    Close,
    Rect([f64; 4]),
    Line([f64; 4]),
    Poly(Vec<f64>, bool),
    Circle([f64; 3]),
    Text(f64, f64, String),
    Gradient(Vec<String>),
}

fn attr(line: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let start = line.find(&key)? + key.len();
    let end = start + line[start..].find('"')?;
    Some(line[start..end].to_string())
}

fn num(line: &str, name: &str) -> f64 {
    attr(line, name)
        .unwrap_or_else(|| panic!("{name} in {line}"))
        .parse()
        .unwrap()
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// The primitives of an SVG written by the plot crate (one element per line), without the
/// background rectangle.
fn from_svg(svg: &str) -> Vec<Prim> {
    let mut prims = Vec::new();
    let mut stops = None::<Vec<String>>;
    // The declaration, the <svg> element, the title and the white background come first.
    let body = svg
        .lines()
        .map(str::trim)
        .skip(2)
        .skip_while(|l| l.starts_with("<title>"));
    for line in body.skip(1) {
        if line == "</svg>" {
            continue;
        }
        let tag = line[1..].split([' ', '>', '/']).next().unwrap_or("");
        match tag {
            "g" if line.contains("clip-path=") => {}
            "g" => prims.push(Prim::Open(
                attr(line, "stroke-width").map(|w| w.parse().unwrap()),
            )),
            "clipPath" => prims.push(Prim::Open(Some(num(line, "x")))),
            "" if line == "</g>" => prims.push(Prim::Close),
            "rect" if line.contains("fill=\"url(") => {}
            "rect" => prims.push(Prim::Rect(
                ["x", "y", "width", "height"].map(|n| num(line, n)),
            )),
            "line" => prims.push(Prim::Line(["x1", "y1", "x2", "y2"].map(|n| num(line, n)))),
            "polyline" | "polygon" => prims.push(Prim::Poly(
                attr(line, "points")
                    .unwrap()
                    .split([' ', ','])
                    .map(|v| v.parse().unwrap())
                    .collect(),
                tag == "polygon",
            )),
            "circle" => prims.push(Prim::Circle(["cx", "cy", "r"].map(|n| num(line, n)))),
            "text" => {
                let start = line.find('>').unwrap() + 1;
                let end = line.rfind("</text>").unwrap();
                prims.push(Prim::Text(
                    num(line, "x"),
                    num(line, "y"),
                    unescape(&line[start..end]),
                ));
            }
            "defs" => stops = Some(Vec::new()),
            "stop" => stops
                .as_mut()
                .unwrap()
                .push(attr(line, "stop-color").unwrap()),
            "" if line == "</linearGradient></defs>" => {
                prims.push(Prim::Gradient(stops.take().unwrap()));
            }
            _ => panic!("unexpected SVG line {line}"),
        }
    }
    prims
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

fn from_list(list: &Value) -> Vec<Prim> {
    let flat = |v: &Value| v.as_array().unwrap().iter().map(f).collect::<Vec<_>>();
    list["ops"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|op| {
            let code = op[0].as_str().unwrap();
            Some(match code {
                "g" => Prim::Open(None),
                "m" => Prim::Open(Some(f(&op[1]))),
                "c" => Prim::Open(Some(f(&op[1]))),
                "e" => Prim::Close,
                "r" => Prim::Rect([1, 2, 3, 4].map(|i| f(&op[i]))),
                "l" | "k" => Prim::Line([1, 2, 3, 4].map(|i| f(&op[i]))),
                "p" | "P" | "f" => Prim::Poly(flat(&op[1]), code != "p"),
                "o" => Prim::Circle([1, 2, 3].map(|i| f(&op[i]))),
                "t" => Prim::Text(f(&op[1]), f(&op[2]), op[3].as_str().unwrap().to_string()),
                "G" => Prim::Gradient(
                    op[2]
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|c| c.as_str().unwrap().to_string())
                        .collect(),
                ),
                "R" => return None,
                other => panic!("unknown op {other}"),
            })
        })
        .collect()
}

fn check(path: &str, views: &[View]) {
    let model = load(
        format!("{}/../../examples/{path}", env!("CARGO_MANIFEST_DIR")),
        &ReadOptions::default(),
    )
    .unwrap();
    let plot = PlotModel::from_model(&model).unwrap();
    let options = PlotOptions::new().with_samples(60).with_camera(30.0, 20.0);
    for &view in views {
        let drawing = render_drawing(&plot, view, &options).unwrap();
        let svg = drawing.to_svg();
        let list: Value = serde_json::from_str(&drawing.to_display_list())
            .unwrap_or_else(|e| panic!("{path} {view:?}: not JSON: {e}"));
        assert_eq!(
            (list["width"].as_u64(), list["height"].as_u64()),
            (Some(1600), Some(1200))
        );
        let (a, b) = (from_svg(&svg), from_list(&list));
        assert!(a.len() > 20, "{path} {view:?}: {} primitives", a.len());
        assert_eq!(a.len(), b.len(), "{path} {view:?}");
        for (k, (x, y)) in a.iter().zip(&b).enumerate() {
            assert_eq!(x, y, "{path} {view:?}: primitive {k}");
        }
        // Every style and text style an op names exists, with the SVG's colours.
        let styles = list["styles"].as_array().unwrap();
        let texts = list["texts"].as_array().unwrap();
        for op in list["ops"].as_array().unwrap() {
            let index = |i: usize| op[i].as_u64().unwrap() as usize;
            match op[0].as_str().unwrap() {
                "r" | "l" => assert!(index(5) < styles.len()),
                "p" | "P" => assert!(index(2) < styles.len()),
                "o" => assert!(index(4) < styles.len()),
                "t" => assert!(index(4) < texts.len()),
                _ => {}
            }
        }
        for style in styles {
            for key in ["fill", "stroke"] {
                if let Some(c) = style[key].as_str() {
                    assert!(svg.contains(&format!("\"{c}\"")), "{path} {view:?}: {c}");
                }
            }
        }
    }
}

#[test]
fn display_lists_are_the_svg_drawings() {
    let curve_views = [
        View::Plane,
        View::Controls,
        View::Truth,
        View::Indeterminacy,
        View::Falsity,
        View::All,
        View::Score,
        View::Band,
    ];
    check("example1.toml", &curve_views);
    check("helix3d.toml", &curve_views);
    check("fuzzy-bspline.toml", &curve_views);
    let surface_views = &curve_views[..7];
    check("surface.toml", surface_views);
    check("nurbs-surface.json", surface_views);
}
