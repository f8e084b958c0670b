//! The SVG opens in a real browser: headless Chromium renders Example 1's `all` view, and the
//! screenshot shows the three degree curves in their colours.
//!
//! Runs when `chromium` is on the PATH. CI installs it and sets `NEUTROSPLINE_REQUIRE_BROWSER=1`,
//! which turns a missing browser into a failure instead of a skipped check.

use std::path::Path;
use std::process::Command;

use neutrospline_plot::{render_svg, PlotModel, PlotOptions, View};

/// Pixels within `tolerance` (per channel) of `rgb`.
fn count_near(rgba: &[u8], channels: usize, rgb: [u8; 3], tolerance: i32) -> usize {
    rgba.chunks_exact(channels)
        .filter(|p| (0..3).all(|c| (i32::from(p[c]) - i32::from(rgb[c])).abs() <= tolerance))
        .count()
}

fn decode(path: &Path) -> (Vec<u8>, usize, u32, u32) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    buf.truncate(info.buffer_size());
    (buf, channels, info.width, info.height)
}

#[test]
fn svg_renders_in_headless_chromium() {
    let required = std::env::var("NEUTROSPLINE_REQUIRE_BROWSER").is_ok_and(|v| v == "1");
    let chromium = ["chromium", "chromium-browser"].into_iter().find(|name| {
        Command::new(name)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    });
    let Some(chromium) = chromium else {
        assert!(
            !required,
            "NEUTROSPLINE_REQUIRE_BROWSER=1 but no chromium on the PATH"
        );
        eprintln!("skipped: chromium is not installed");
        return;
    };
    let dir = tempfile_dir();
    let svg_path = dir.join("figure5.svg");
    let shot = dir.join("shot.png");
    let model = PlotModel::from_bezier(&neutrospline::example1()).unwrap();
    let svg = render_svg(&model, View::All, &PlotOptions::new()).unwrap();
    std::fs::write(&svg_path, svg).unwrap();
    let profile = dir.join("profile");
    let status = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--window-size=1600,1200",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", svg_path.display()))
        .output()
        .expect("run chromium");
    assert!(
        status.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&status.stderr)
    );
    let (pixels, channels, width, height) = decode(&shot);
    assert_eq!((width, height), (1600, 1200));
    // The truth, indeterminacy and falsity curves are drawn in these colours (theme.rs).
    for (name, rgb) in [
        ("truth", [0x00, 0x44, 0x88]),
        ("indeterminacy", [0xc8, 0x8a, 0x12]),
        ("falsity", [0xbb, 0x55, 0x66]),
    ] {
        let n = count_near(&pixels, channels, rgb, 24);
        assert!(
            n > 1000,
            "{name}: only {n} pixels of its colour in the browser's rendering"
        );
    }
    // Mostly a white page with a drawing, not an error page or a blank.
    let white = count_near(&pixels, channels, [255, 255, 255], 4);
    let total = pixels.len() / channels;
    assert!(
        white > total / 3 && white < total * 98 / 100,
        "white pixels: {white} of {total}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A fresh directory under the system temporary directory.
fn tempfile_dir() -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("neutrospline-browser-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
