//! Independent readers accept the exports: `scripts/readers/check_exports.py` exports the
//! examples with this binary and reads them with ezdxf (DXF: the SPLINE entities evaluated by
//! ezdxf agree with `eval` to 1e-12 of scale, positions and degrees; splines that ezdxf writes
//! import to curves that `eval` evaluates as ezdxf does), plyfile (PLY: the `eval`
//! values exactly), pygltflib (glTF: the `eval` values in float32 exactly), the Khronos glTF
//! validator (no errors), OpenCASCADE (STEP: every example model read back through
//! `STEPControl_Reader` as a `Geom_BSplineCurve` or `Geom_BSplineSurface` with the model's
//! degrees, poles, weights and knots exactly, evaluating to `eval` within 1e-12 of scale, the
//! degrees in the point names) and three.js in headless Chromium (the surface drawn in its
//! viridis vertex colours).
//!
//! Runs when the readers are installed (`scripts/readers/install`, which `scripts/check` runs,
//! puts the Python ones into the virtual environment `scripts/readers/.venv`).
//! CI sets `NEUTROSPLINE_REQUIRE_READERS=1`, which turns a missing reader into a failure
//! instead of a skipped check.

use std::path::Path;
use std::process::Command;

/// The exit status of `check_exports.py` when a reader is missing.
const MISSING: i32 = 77;

#[test]
fn independent_readers_accept_the_exports() {
    let required = std::env::var("NEUTROSPLINE_REQUIRE_READERS").is_ok_and(|v| v == "1");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readers = root.join("scripts/readers");
    let work = tempfile::tempdir().unwrap();
    // The readers' virtual environment (scripts/readers/install makes it), else any python3.
    let venv = readers.join(".venv/bin/python");
    let python = if venv.exists() {
        venv
    } else {
        "python3".into()
    };
    let result = Command::new(&python)
        .arg(readers.join("check_exports.py"))
        .arg(env!("CARGO_BIN_EXE_neutrospline"))
        .arg(root.join("examples"))
        .arg(work.path())
        .arg(readers.join("node_modules"))
        .output();
    let skip = |why: &str| {
        assert!(!required, "NEUTROSPLINE_REQUIRE_READERS=1 but {why}");
        eprintln!("skipped: {why}");
    };
    let output = match result {
        Ok(output) => output,
        Err(error) => return skip(&format!("python3 does not run ({error})")),
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    if output.status.code() == Some(MISSING) {
        return skip(stderr.trim());
    }
    assert!(
        output.status.success(),
        "the independent readers refused an export:\n{stdout}{stderr}"
    );
    assert!(stdout.contains("checks passed"), "{stdout}");
}
