//! The real-file reference test: every file of `tests/realfiles/` imported and compared with
//! the geometry an independent reader sees (svgelements for SVG, ezdxf's data summed by an
//! exact de Boor sum for DXF), written by `scripts/realfiles/make_realfiles_reference.py` to
//! `tests/realfiles/reference/{svg,dxf}.json` (`tests/realfiles/README.md`, "The reference
//! test").
//!
//! For every file whose reference draws a shape:
//!
//! - the import does not fail;
//! - a reference shape is *covered* when each of its points lies within
//!   `POINT_TOLERANCE * size` of an imported curve (`size`: the diagonal of the bounding box
//!   of the file's reference points). The distance is the core's global nearest point
//!   ([`DynCurve::nearest_rows`]); a curve is asked only for the points inside its control
//!   points' bounding box grown by the tolerance (the curve lies in the convex hull of its
//!   control points, so a point outside is farther than the tolerance), and a point found
//!   within `NEAR_ENOUGH` of the tolerance is not asked again (its distance is then an upper
//!   bound of the nearest, good to that fraction of the tolerance). SVG coverage and DXF
//!   coverage, over all shapes, are each at least `MIN_COVERAGE`;
//! - every SPLINE written as is in a DXF file (not transformed by an INSERT) equals an
//!   imported curve exactly: degree, knots, control points and weights compared as `f64`s
//!   parsed from the reference's round-trip decimal strings;
//! - the total arc length of the imported curves is the reference total to within
//!   `LENGTH_TOLERANCE` relative (catches geometry imported twice or not drawn);
//! - every kind the reference counts as not a curve (`<text>`, `HATCH`, ...) is in the
//!   report's skipped counts at least as many times (kinds qualified by the importer, as
//!   `<text> in <defs>`, count for their kind).
//!
//! The shapes of `tests/realfiles/reference/exceptions.json` (known errors of the reference
//! readers, each citing the README) are left out of the geometry checks. The test prints the
//! coverage and the worst deviation per folder, then every failure with its file, shape,
//! point and distance.
//!
//! `NEUTROSPLINE_REALFILES=DIR` runs the same checks on another folder laid out as
//! `tests/realfiles/` (`DIR/svg/FOLDER/*.svg`, `DIR/dxf/FOLDER/*.dxf`, the reference written by
//! `make_realfiles_reference.py --root DIR` into `DIR/reference/`; `exceptions.json` there is
//! optional): files the tests have not seen, checked without committing them. It also prints
//! every failure and uncovered shape, and the import report of every file.

use std::collections::{BTreeMap, HashSet};
use std::path::PathBuf;

use neutrospline::{Degrees, DynCurve};
use neutrospline_exchange::{parse_dxf, parse_svg, Import, ImportOptions};
use neutrospline_io::{Limits, ReadError, Shape};
use serde_json::Value;

/// A reference point is on the import when within this fraction of the drawing's size: the
/// conversions are exact, so what is left is rounding (the old importers' worst case is
/// 8.5e-9 of the size), far below it; a shape imported wrongly is off by much more.
const POINT_TOLERANCE: f64 = 1e-6;

/// Relative difference allowed between the imported curves' total arc length and the
/// reference total: the reference lengths are accurate to about 1e-12 (svgelements'
/// `length(error=1e-12)`, Gauss-Legendre and closed forms), the core's to the accuracy asked
/// (`LENGTH_ACCURACY`), and pointwise agreement to 1e-6 of the size keeps lengths of smooth
/// shapes within about that fraction; one segment too many or too few changes the total by
/// far more in every real file.
const LENGTH_TOLERANCE: f64 = 1e-6;

/// The accuracy asked of the core's arc length.
const LENGTH_ACCURACY: f64 = 1e-10;

/// The least fraction of the reference shapes covered, SVG and DXF each.
const MIN_COVERAGE: f64 = 0.95;

/// A point already this close (as a fraction of the tolerance) to a curve is not asked again:
/// the deviation printed is exact to this fraction of the tolerance.
const NEAR_ENOUGH: f64 = 1e-4;

/// At most this many failures are printed in full.
const SHOWN_FAILURES: usize = 60;

/// The folder set by `NEUTROSPLINE_REALFILES` (module docs), if any.
fn other_folder() -> Option<PathBuf> {
    std::env::var_os("NEUTROSPLINE_REALFILES").map(PathBuf::from)
}

fn realfiles() -> PathBuf {
    other_folder()
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/realfiles"))
}

fn reference(name: &str) -> Value {
    let path = realfiles().join("reference").join(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (run scripts/realfiles)", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A reference shape's identity for messages and exceptions: its id, or `#index`.
fn shape_name(shape: &Value) -> String {
    match shape.get("id").and_then(Value::as_str) {
        Some(id) if !id.is_empty() => id.to_owned(),
        _ => format!("#{}", shape["index"].as_u64().unwrap_or(0)),
    }
}

/// The (file, shape) pairs excluded from the geometry checks.
fn exceptions() -> HashSet<(String, String)> {
    if other_folder().is_some() && !realfiles().join("reference/exceptions.json").exists() {
        return HashSet::new();
    }
    let value = reference("exceptions.json");
    value["exceptions"]
        .as_array()
        .expect("exceptions.json: an array `exceptions`")
        .iter()
        .map(|e| {
            let reason = e["reason"].as_str().unwrap_or("");
            assert!(!reason.is_empty(), "exceptions.json: {e} has no reason");
            (
                e["file"].as_str().unwrap().to_owned(),
                e["shape"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

/// An imported curve with its control points' bounding box (3-D, z = 0 for a plane curve).
struct Candidate {
    curve: DynCurve,
    low: [f64; 3],
    high: [f64; 3],
}

fn candidates(import: &Import) -> Vec<Candidate> {
    import
        .models
        .iter()
        .filter_map(|model| match model.shape() {
            Shape::Curve(curve) => Some(curve.clone()),
            Shape::Surface(_) => None,
        })
        .map(|curve| {
            let dimension = curve.dimension();
            let mut low = [0.0; 3];
            let mut high = [0.0; 3];
            for (k, row) in curve.control_rows().iter().enumerate() {
                for a in 0..dimension {
                    if k == 0 || row[a] < low[a] {
                        low[a] = row[a];
                    }
                    if k == 0 || row[a] > high[a] {
                        high[a] = row[a];
                    }
                }
            }
            Candidate { curve, low, high }
        })
        .collect()
}

/// The distance from every point to the imported curves, as the module docs say: `f64::INFINITY`
/// for a point no curve's grown bounding box holds.
fn distances(curves: &[Candidate], points: &[[f64; 3]], tolerance: f64) -> Vec<f64> {
    let mut best = vec![f64::INFINITY; points.len()];
    for candidate in curves {
        let inside: Vec<usize> = (0..points.len())
            .filter(|&k| {
                best[k] > NEAR_ENOUGH * tolerance
                    && (0..3).all(|a| {
                        points[k][a] >= candidate.low[a] - tolerance
                            && points[k][a] <= candidate.high[a] + tolerance
                    })
            })
            .collect();
        if inside.is_empty() {
            continue;
        }
        let dimension = candidate.curve.dimension();
        let rows: Vec<f64> = inside
            .iter()
            .flat_map(|&k| points[k][..dimension].to_vec())
            .collect();
        let found = candidate
            .curve
            .nearest_rows(&rows)
            .expect("whole rows of the curve's dimension");
        for (&k, result) in inside.iter().zip(found) {
            if let Ok(nearest) = result {
                // A plane curve lies in z = 0: the point's z adds to the distance.
                let z = if dimension == 2 { points[k][2] } else { 0.0 };
                let distance = nearest.distance.hypot(z);
                best[k] = best[k].min(distance);
            }
        }
    }
    best
}

/// The reference's exact numbers (round-trip decimal strings) as `f64`s.
fn numbers(value: &Value) -> Vec<f64> {
    value
        .as_array()
        .map(|a| {
            a.iter()
                .map(|x| x.as_str().unwrap().parse::<f64>().unwrap())
                .collect()
        })
        .unwrap_or_default()
}

/// A spline's numbers in one list for exact comparison: degree, knots, control points (x, y,
/// z), weights (empty for a polynomial curve); `-0.0` as `0.0`.
fn spline_key(degree: usize, knots: &[f64], points: &[[f64; 3]], weights: &[f64]) -> Vec<u64> {
    let mut key = vec![degree as u64, knots.len() as u64, points.len() as u64];
    let bits = |x: f64| (x + 0.0).to_bits();
    key.extend(knots.iter().map(|&x| bits(x)));
    key.extend(points.iter().flatten().map(|&x| bits(x)));
    key.extend(weights.iter().map(|&x| bits(x)));
    key
}

fn imported_key(curve: &DynCurve) -> Vec<u64> {
    let degree = curve.degree();
    let count = curve.len();
    let knots = curve.knots().map_or_else(
        || [vec![0.0; count], vec![1.0; count]].concat(),
        |k| k.knots().to_vec(),
    );
    let dimension = curve.dimension();
    let points: Vec<[f64; 3]> = curve
        .control_rows()
        .iter()
        .map(|row| {
            let mut p = [0.0; 3];
            p[..dimension].copy_from_slice(&row[..dimension]);
            p
        })
        .collect();
    spline_key(degree, &knots, &points, curve.weights().unwrap_or_default())
}

/// One folder's tally.
#[derive(Default)]
struct Tally {
    files: usize,
    shapes: usize,
    covered: usize,
    /// The largest distance of a point of a covered shape, as a fraction of the size.
    worst: f64,
    worst_at: String,
    /// SPLINEs written as is, and those an imported curve equals exactly.
    splines: usize,
    exact_splines: usize,
}

/// Checks one format's reference; returns the tallies per folder and pushes failures.
fn check_format(
    name: &str,
    json: &str,
    exceptions: &HashSet<(String, String)>,
    failures: &mut Vec<String>,
    uncovered: &mut Vec<String>,
) -> BTreeMap<String, Tally> {
    let options = ImportOptions::new(Degrees::new(1.0, 0.0, 0.0).unwrap());
    let limits = Limits::default();
    let data = reference(json);
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    for entry in data["files"].as_array().expect("an array `files`") {
        let file = entry["file"].as_str().unwrap();
        let folder = file.rsplit_once('/').map_or(file, |(f, _)| f).to_owned();
        let tally = tallies.entry(folder).or_default();
        tally.files += 1;
        let shapes: Vec<&Value> = entry["shapes"]
            .as_array()
            .map(|a| a.iter().collect())
            .unwrap_or_default();
        let bytes = std::fs::read(realfiles().join(file)).unwrap();
        // A panic is a failure of this file, not the end of the run.
        let parsed = std::panic::catch_unwind(|| -> Result<Import, ReadError> {
            if name == "svg" {
                parse_svg(file, &bytes, &options, &limits)
            } else {
                parse_dxf(file, &bytes, &options, &limits)
            }
        });
        let Ok(result) = parsed else {
            failures.push(format!("{file}: the import panics"));
            continue;
        };
        let checked: Vec<&Value> = shapes
            .iter()
            .copied()
            .filter(|s| !exceptions.contains(&(file.to_owned(), shape_name(s))))
            .collect();
        tally.shapes += checked.len();
        let import = match result {
            Ok(import) => {
                if other_folder().is_some() {
                    println!("report {file}: {}", import.report.summary());
                }
                import
            }
            Err(error) => {
                if other_folder().is_some() {
                    println!("error {file}: {error}");
                }
                if !checked.is_empty() {
                    failures.push(format!(
                        "{file}: the import fails where the reference draws {} shapes: {error}",
                        checked.len()
                    ));
                }
                continue;
            }
        };
        let size = entry["size"].as_f64().unwrap_or(0.0);
        let tolerance = POINT_TOLERANCE * size;
        let curves = candidates(&import);
        let mut points: Vec<[f64; 3]> = Vec::new();
        let mut owner: Vec<usize> = Vec::new();
        for (s, shape) in checked.iter().enumerate() {
            for p in shape["points"].as_array().unwrap() {
                let p: Vec<f64> = p
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect();
                points.push([p[0], p[1], p.get(2).copied().unwrap_or(0.0)]);
                owner.push(s);
            }
        }
        let best = distances(&curves, &points, tolerance);
        let mut worst_of_shape = vec![0.0_f64; checked.len()];
        let mut far: Vec<Option<usize>> = vec![None; checked.len()];
        for (k, &d) in best.iter().enumerate() {
            let s = owner[k];
            if d > tolerance {
                far[s].get_or_insert(k);
            }
            worst_of_shape[s] = worst_of_shape[s].max(d);
        }
        for (s, shape) in checked.iter().enumerate() {
            match far[s] {
                None => {
                    tally.covered += 1;
                    let relative = if size > 0.0 {
                        worst_of_shape[s] / size
                    } else {
                        0.0
                    };
                    if relative > tally.worst {
                        tally.worst = relative;
                        tally.worst_at = format!("{file} {}", shape_name(shape));
                    }
                }
                Some(k) => uncovered.push(format!(
                    "{file}: {} {} not covered: point {:?} is {} from every imported curve \
                     (tolerance {tolerance:.3e})",
                    shape["kind"].as_str().unwrap_or("?"),
                    shape_name(shape),
                    points[k],
                    if best[k].is_finite() {
                        format!("{:.3e}", best[k])
                    } else {
                        "far".to_owned()
                    }
                )),
            }
        }
        // Exact splines.
        let keys: HashSet<Vec<u64>> = curves.iter().map(|c| imported_key(&c.curve)).collect();
        for shape in &checked {
            let Some(spline) = shape.get("spline") else {
                continue;
            };
            if spline["exact"] != Value::Bool(true) {
                continue;
            }
            let points: Vec<[f64; 3]> = spline["control_points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    let p = numbers(p);
                    [p[0], p[1], p.get(2).copied().unwrap_or(0.0)]
                })
                .collect();
            let key = spline_key(
                spline["degree"].as_u64().unwrap() as usize,
                &numbers(&spline["knots"]),
                &points,
                &numbers(&spline["weights"]),
            );
            tally.splines += 1;
            if keys.contains(&key) {
                tally.exact_splines += 1;
            } else {
                failures.push(format!(
                    "{file}: SPLINE {}: no imported curve equals it exactly (degree {}, {} \
                     control points)",
                    shape_name(shape),
                    spline["degree"],
                    points.len()
                ));
            }
        }
        // Total length, when the reference draws something and nothing of it is excepted.
        let length_excepted = exceptions.contains(&(file.to_owned(), "length".to_owned()));
        if !checked.is_empty() && checked.len() == shapes.len() && !length_excepted {
            let expected = entry["length"].as_f64().unwrap_or(0.0);
            let total: f64 = curves
                .iter()
                .map(|c| {
                    c.curve
                        .arc_length(c.curve.domain(), LENGTH_ACCURACY)
                        .unwrap_or(f64::NAN)
                })
                .sum();
            let difference = (total - expected).abs();
            if difference.is_nan() || difference > LENGTH_TOLERANCE * expected {
                failures.push(format!(
                    "{file}: the imported curves are {total} long, the reference's shapes \
                     {expected} (relative difference {:.3e})",
                    difference / expected
                ));
            }
        }
        // What is not a curve is in the report.
        if let Some(kinds) = entry["not_curves"].as_object() {
            for (label, count) in kinds {
                let kind = label.split(" (").next().unwrap_or(label);
                let count = count.as_u64().unwrap_or(0) as usize;
                let reported: usize = import
                    .report
                    .skipped
                    .iter()
                    .filter(|s| s.kind == kind || s.kind.starts_with(&format!("{kind} ")))
                    .map(|s| s.count)
                    .sum();
                if reported < count {
                    failures.push(format!(
                        "{file}: the reference counts {count} {label}, the report skips \
                         {reported} (report: {})",
                        import.report.summary()
                    ));
                }
            }
        }
    }
    tallies
}

fn print_tallies(name: &str, tallies: &BTreeMap<String, Tally>) -> f64 {
    println!(
        "{:<24} {:>5} {:>7} {:>7} {:>9}  worst deviation / size",
        name, "files", "shapes", "covered", "coverage"
    );
    let mut all = Tally::default();
    for (folder, t) in tallies {
        all.files += t.files;
        all.shapes += t.shapes;
        all.covered += t.covered;
        all.splines += t.splines;
        all.exact_splines += t.exact_splines;
        if t.worst > all.worst {
            all.worst = t.worst;
            all.worst_at.clone_from(&t.worst_at);
        }
        println!(
            "{folder:<24} {:>5} {:>7} {:>7} {:>8.1}%  {:.2e} {}",
            t.files,
            t.shapes,
            t.covered,
            100.0 * t.covered as f64 / t.shapes.max(1) as f64,
            t.worst,
            t.worst_at
        );
    }
    let coverage = all.covered as f64 / all.shapes.max(1) as f64;
    println!(
        "{:<24} {:>5} {:>7} {:>7} {:>8.1}%  {:.2e} {}",
        format!("{name} overall"),
        all.files,
        all.shapes,
        all.covered,
        100.0 * coverage,
        all.worst,
        all.worst_at
    );
    if all.splines > 0 {
        println!(
            "{name}: {} of {} SPLINEs written as is imported exactly",
            all.exact_splines, all.splines
        );
    }
    coverage
}

#[test]
fn realfiles_match_the_reference_readers() {
    let shown = if other_folder().is_some() {
        usize::MAX
    } else {
        SHOWN_FAILURES
    };
    let exceptions = exceptions();
    let mut failures = Vec::new();
    let mut uncovered = Vec::new();
    for (name, json) in [("svg", "svg.json"), ("dxf", "dxf.json")] {
        let tallies = check_format(name, json, &exceptions, &mut failures, &mut uncovered);
        let coverage = print_tallies(name, &tallies);
        if coverage < MIN_COVERAGE {
            failures.push(format!(
                "{name}: {:.1}% of the reference shapes covered, at least {:.0}% required",
                100.0 * coverage,
                100.0 * MIN_COVERAGE
            ));
        }
    }
    println!("{} shapes not covered", uncovered.len());
    for line in uncovered.iter().take(shown) {
        println!("  {line}");
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}{}",
        failures.len(),
        failures
            .iter()
            .take(shown)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n"),
        if failures.len() > shown {
            format!("\n... and {} more", failures.len() - shown)
        } else {
            String::new()
        }
    );
}
