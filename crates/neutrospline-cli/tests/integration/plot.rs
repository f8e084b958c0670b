//! End-to-end tests of `neutrospline plot` and `neutrospline example --out`.

use std::fs;
use std::process::{Command, Output};

use crate::util::{example, BIN};

fn run(args: &[&str]) -> Output {
    let out = Command::new(BIN)
        .args(args)
        .output()
        .expect("run neutrospline");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    out
}

/// Width and height from a PNG's IHDR chunk, after checking the signature.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    assert_eq!(&bytes[12..16], b"IHDR");
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    (w, h)
}

#[test]
fn example_out_writes_ten_figures_and_the_table() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("figures");
    let out = run(&["example", "--out", out_dir.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(stdout.contains("0.5  4.625      4   0.625            0.2    0.175"));
    for k in 1..=5 {
        let svg = fs::read_to_string(out_dir.join(format!("figure{k}.svg"))).unwrap();
        assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"));
        assert!(
            svg.contains("Erratum"),
            "figure{k} lacks the erratum caption"
        );
        assert!(!svg.contains("NaN"));
        let png = fs::read(out_dir.join(format!("figure{k}.png"))).unwrap();
        assert_eq!(png_size(&png), (1600, 1200));
        assert!(stdout.contains(&format!("figure{k}.png")));
    }
    // Figure 5 shows all three degrees with a legend; figure 1 names the control points.
    let fig5 = fs::read_to_string(out_dir.join("figure5.svg")).unwrap();
    for word in ["truth", "indeterminacy", "falsity"] {
        assert!(fig5.contains(word), "figure5 lacks {word}");
    }
    let fig1 = fs::read_to_string(out_dir.join("figure1.svg")).unwrap();
    for name in ["C0", "C1", "C2", "C3"] {
        assert!(fig1.contains(&format!(">{name}<")), "figure1 lacks {name}");
    }
    // The table is eval's CSV at t = k/10.
    let table = fs::read_to_string(out_dir.join("example1.csv")).unwrap();
    let eval = run(&[
        "eval",
        example("example1.csv").to_str().unwrap(),
        "--at",
        "0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1",
    ]);
    assert_eq!(table, String::from_utf8(eval.stdout).unwrap());
    assert_eq!(fs::read_dir(&out_dir).unwrap().count(), 11, "stray files");
}

#[test]
fn plot_every_view_of_every_example_kind() {
    let dir = tempfile::tempdir().unwrap();
    for file in [
        "example1.toml",
        "helix3d.toml",
        "bspline.toml",
        "nurbs-circle.toml",
        "surface.toml",
        "nurbs-surface.json",
    ] {
        for view in [
            "controls",
            "truth",
            "indeterminacy",
            "falsity",
            "all",
            "plane",
        ] {
            let out_path = dir.path().join(format!("{file}-{view}.svg"));
            let out = run(&[
                "plot",
                example(file).to_str().unwrap(),
                "-o",
                out_path.to_str().unwrap(),
                "--view",
                view,
                "--samples",
                "30",
            ]);
            assert_eq!(
                out.status.code(),
                Some(0),
                "{file} {view}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            let svg = fs::read_to_string(&out_path).unwrap();
            assert!(
                svg.contains("</svg>") && !svg.contains("NaN"),
                "{file} {view}"
            );
        }
    }
}

#[test]
fn plot_png_options_and_determinism() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.png");
    let b = dir.path().join("b.PNG");
    for path in [&a, &b] {
        let out = run(&[
            "plot",
            example("bspline.toml").to_str().unwrap(),
            "-o",
            path.to_str().unwrap(),
            "--view",
            "truth",
            "--width",
            "800",
            "--height",
            "500",
            "--title",
            "My B-spline",
            "--azimuth",
            "-30",
            "--elevation",
            "40",
        ]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let (pa, pb) = (fs::read(&a).unwrap(), fs::read(&b).unwrap());
    assert_eq!(png_size(&pa), (800, 500));
    assert_eq!(pa, pb, "same input, different bytes");
    let svg = dir.path().join("t.svg");
    run(&[
        "plot",
        example("bspline.toml").to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
        "--title",
        "My B-spline",
    ]);
    assert!(fs::read_to_string(&svg).unwrap().contains("My B-spline"));
}

#[test]
fn plot_usage_errors_exit_2_and_keep_old_output() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("keep.svg");
    fs::write(&target, "old figure").unwrap();
    let file = example("example1.csv");
    let out = run(&[
        "plot",
        file.to_str().unwrap(),
        "-o",
        target.to_str().unwrap(),
        "--view",
        "side",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "error: view = side: expected one of controls, truth, indeterminacy, falsity, all, plane, \
         score, derived, data, band\n"
    );
    let eps = dir.path().join("fig.eps");
    let out = run(&["plot", file.to_str().unwrap(), "-o", eps.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).trim_end(),
        format!(
            "error: {}: unsupported figure extension (accepted: .svg, .png, .pdf)",
            eps.display()
        )
    );
    assert!(!eps.exists());
    let out = run(&[
        "plot",
        file.to_str().unwrap(),
        "-o",
        target.to_str().unwrap(),
        "--width",
        "10",
    ]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Invalid input: exit 1, the old figure is untouched and no temporary file remains.
    let bad = dir.path().join("bad.csv");
    fs::write(&bad, "x,y,truth,indeterminacy,falsity\n1,2,1.5,0,0\n").unwrap();
    let out = run(&[
        "plot",
        bad.to_str().unwrap(),
        "-o",
        target.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("error: "));
    assert_eq!(fs::read_to_string(&target).unwrap(), "old figure");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "stray files");
}

/// The numbers of `name="..."` attributes of an SVG element's text.
fn svg_numbers(element: &str, names: &[&str]) -> Vec<f64> {
    names
        .iter()
        .map(|name| {
            let key = format!(" {name}=\"");
            let at = element
                .find(&key)
                .unwrap_or_else(|| panic!("{name} in {element}"))
                + key.len();
            let end = at + element[at..].find('"').unwrap();
            element[at..end].parse().unwrap()
        })
        .collect()
}

/// The elements `<TAG ...>` of `svg` whose attributes hold `marker`.
fn svg_elements<'s>(svg: &'s str, tag: &str, marker: &str) -> Vec<&'s str> {
    svg.match_indices(&format!("<{tag} "))
        .map(|(at, _)| &svg[at..at + svg[at..].find('>').unwrap()])
        .filter(|element| element.contains(marker))
        .collect()
}

/// Issue 28: the `controls` view of examples/bspline.toml drew B6's callout under the legend
/// and B4's over the B6 point. For every example curve, at the default size and at a notebook's
/// (800 x 600): no callout box over the legend, over a control point's marker or over another
/// callout.
#[test]
fn controls_callouts_keep_clear_of_the_legend_the_markers_and_each_other() {
    let dir = tempfile::tempdir().unwrap();
    let overlap = |a: &[f64], b: &[f64]| {
        let w = (a[0] + a[2]).min(b[0] + b[2]) - a[0].max(b[0]);
        let h = (a[1] + a[3]).min(b[1] + b[3]) - a[1].max(b[1]);
        w > 0.5 && h > 0.5
    };
    let mut checked = 0;
    for name in [
        "example1.toml",
        "bspline.toml",
        "fuzzy-bspline.toml",
        "nurbs-circle.toml",
        "helix3d.toml",
    ] {
        for size in [&[][..], &["--width", "800", "--height", "600"]] {
            let path = example(name).display().to_string();
            let example = name;
            let mut args = vec!["plot", path.as_str(), "--view", "controls", "-o", "c.svg"];
            args.extend(size);
            crate::util::ok(dir.path(), &args);
            let svg = std::fs::read_to_string(dir.path().join("c.svg")).unwrap();
            let boxes: Vec<Vec<f64>> = svg_elements(&svg, "rect", "class=\"callout\"")
                .iter()
                .map(|e| svg_numbers(e, &["x", "y", "width", "height"]))
                .collect();
            assert!(!boxes.is_empty(), "{example} {size:?}: no callouts");
            let legend_at = svg.find("<g class=\"legend\">").expect("a legend");
            let legend = svg_numbers(
                svg_elements(&svg[legend_at..], "rect", "")[0],
                &["x", "y", "width", "height"],
            );
            let markers: Vec<Vec<f64>> = svg_elements(&svg, "circle", "class=\"control-point\"")
                .iter()
                .map(|e| {
                    let [cx, cy, r] = svg_numbers(e, &["cx", "cy", "r"])[..] else {
                        unreachable!()
                    };
                    vec![cx - r, cy - r, 2.0 * r, 2.0 * r]
                })
                .collect();
            assert!(!markers.is_empty(), "{example}: no markers");
            for (i, b) in boxes.iter().enumerate() {
                assert!(
                    !overlap(b, &legend),
                    "{example} {size:?}: callout {b:?} over the legend"
                );
                for m in &markers {
                    assert!(
                        !overlap(b, m),
                        "{example} {size:?}: callout {b:?} over marker {m:?}"
                    );
                }
                for other in &boxes[i + 1..] {
                    assert!(
                        !overlap(b, other),
                        "{example} {size:?}: callouts {b:?} {other:?}"
                    );
                }
            }
            checked += boxes.len();
        }
    }
    assert!(checked >= 30, "{checked}");
}

/// `example --formats pdf --style paper`: the five figures as one-column PDF pages (8.5 cm x
/// 7 cm) without the title or the erratum caption; `--view` is refused (each figure has its
/// own), and so is an unknown format.
#[test]
fn example_writes_paper_pdfs() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("paper");
    let out = run(&[
        "example",
        "--out",
        out_dir.to_str().unwrap(),
        "--formats",
        "pdf",
        "--style",
        "paper",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for k in 1..=5 {
        let pdf = fs::read(out_dir.join(format!("figure{k}.pdf"))).unwrap();
        assert!(pdf.starts_with(b"%PDF-1.7"));
        let text = String::from_utf8_lossy(&pdf);
        // 8.5 cm x 7 cm in points.
        assert!(text.contains("/MediaBox [0 0 240.944882 198.425197]"));
        assert!(text.contains("/FontFile2"));
        assert!(!out_dir.join(format!("figure{k}.png")).exists());
    }
    let out = run(&[
        "example",
        "--out",
        out_dir.to_str().unwrap(),
        "--view",
        "truth",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "error: --view truth: example draws the paper's five views (figure1 to figure5); draw \
         one view with `neutrospline plot`\n"
    );
    let out = run(&[
        "example",
        "--out",
        out_dir.to_str().unwrap(),
        "--formats",
        "eps",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("invalid value 'eps' for '--formats"));
}

/// `plot -o fig.pdf --size 8.5cmx6cm --no-title`: a PDF a LaTeX paper takes. Compiled with
/// pdflatex when it is installed (NEUTROSPLINE_REQUIRE_LATEX=1 makes it required): the
/// paper's PDF holds the figure's text in the embedded DejaVu Sans. Bad sizes and resolutions
/// get the plot crate's messages and write nothing.
#[test]
fn plot_pdf_goes_into_a_latex_paper() {
    let dir = tempfile::tempdir().unwrap();
    let model = example("example1.toml");
    let model = model.to_str().unwrap();
    let fig = dir.path().join("fig.pdf");
    let out = run(&[
        "plot",
        model,
        "-o",
        fig.to_str().unwrap(),
        "--view",
        "all",
        "--size",
        "8.5cmx6cm",
        "--no-title",
        "--no-caption",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&fs::read(&fig).unwrap()).into_owned();
    assert!(text.contains("/MediaBox [0 0 240.944882 170.07874]"));
    let png = dir.path().join("fig.png");
    let out = run(&[
        "plot",
        model,
        "-o",
        png.to_str().unwrap(),
        "--size",
        "8.5cmx6cm",
        "--dpi",
        "600",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(png_size(&fs::read(&png).unwrap()), (2008, 1417));

    for (args, message) in [
        (
            vec!["--size", "8.5cm"],
            "error: size = 8.5cm: expected WIDTHxHEIGHT in pixels or with a unit (px, pt, mm, \
             cm, in), for example 1600x1200 or 8.5cmx6cm\n",
        ),
        (
            vec!["--size", "1cmx6cm"],
            "error: figure size 1cmx6cm is not supported (each side must be between 64 and \
             16384 points, 2.26 cm to 5.78 m)\n",
        ),
        (
            vec!["--dpi", "5"],
            "error: dpi = 5 is not supported (must be between 10 and 10000)\n",
        ),
    ] {
        let bad = dir.path().join("bad.pdf");
        let mut argv = vec!["plot", model, "-o", bad.to_str().unwrap()];
        argv.extend(args);
        let out = run(&argv);
        assert_eq!(out.status.code(), Some(2));
        assert_eq!(String::from_utf8_lossy(&out.stderr), message);
        assert!(!bad.exists());
    }

    let required = std::env::var("NEUTROSPLINE_REQUIRE_LATEX").is_ok_and(|v| v == "1");
    let have = |tool: &str| Command::new(tool).arg("-v").output().is_ok();
    if !(have("pdflatex") && have("pdffonts") && have("pdftotext")) {
        assert!(
            !required,
            "NEUTROSPLINE_REQUIRE_LATEX=1 but pdflatex or poppler-utils is missing"
        );
        eprintln!("plot_pdf_goes_into_a_latex_paper: LaTeX part skipped");
        return;
    }
    let text = crate::util::compile_latex(
        dir.path(),
        "\\documentclass{article}\n\\usepackage{graphicx}\n\\begin{document}\n\
         \\begin{figure}\\centering\\includegraphics{fig.pdf}\\caption{Example 1.}\\end{figure}\n\
         \\end{document}\n",
        &[],
    );
    let fonts = Command::new("pdffonts")
        .arg("paper.pdf")
        .current_dir(dir.path())
        .output()
        .unwrap();
    let fonts = String::from_utf8_lossy(&fonts.stdout);
    assert!(fonts.contains("+DejaVuSans "), "{fonts}");
    for expected in [
        "truth curve",
        "crisp control polygon",
        "degree",
        "Example 1.",
    ] {
        assert!(text.contains(expected), "{expected:?} not in {text}");
    }
}
