//! Writing models: TOML and JSON with the keys of the readers' schema, CSV tables of control
//! points, and [`save`], which replaces a file atomically.
//!
//! Numbers are written in Ryu's shortest round-trip form (at most 17 significant digits, with
//! an exponent for very large and very small magnitudes, always a float in TOML and JSON:
//! `1.0`, `0.30000000000000004`, `1e-300`); every reader gets the same `f64` back. Degrees,
//! rows and columns are integers. Knots are always written as values, a Bézier kind without
//! knots. Under the intuitionistic rule the indeterminacy is left out (the reader derives it
//! from truth and falsity, to the same bits); under the fuzzy rule indeterminacy and falsity
//! are.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

use neutrospline::{Family, Spread};

use crate::format::MAX_CSV_LINE;
use crate::number::file_number;
use crate::parsed::SPREAD_KEYS;
use crate::shape::PointData;
use crate::{AtomicFile, Format, Model, Shape, WriteError};

/// A structure key's value.
enum Setting {
    /// A degree or count.
    Integer(usize),
    /// Knot values.
    Knots(Vec<f64>),
    /// `true` (a periodic direction).
    Flag,
}

/// What a file writes of a model's shape: the structure keys in the readers' order, and the
/// indices of the control points it lists. A periodic direction ([`Model::periodic_counts`])
/// is written as `periodic = true`, its breakpoints as knots and its distinct control points.
fn layout(model: &Model) -> (Vec<(&'static str, Setting)>, Vec<usize>) {
    let shape = model.shape();
    let periodic = model.periodic_counts();
    let knots = |k: &neutrospline::KnotVector, periodic: Option<usize>| match periodic {
        Some(_) => Setting::Knots(k.periodic_breakpoints().unwrap_or_default().to_vec()),
        None => Setting::Knots(k.knots().to_vec()),
    };
    let flag = |key: &'static str, periodic: Option<usize>| periodic.map(|_| (key, Setting::Flag));
    match shape {
        Shape::Surface(s) => {
            let (pu, pv) = (
                periodic.first().copied().flatten(),
                periodic.get(1).copied().flatten(),
            );
            let (rows, cols) = (pu.unwrap_or(s.rows()), pv.unwrap_or(s.cols()));
            let mut keys = vec![
                ("rows", Setting::Integer(rows)),
                ("cols", Setting::Integer(cols)),
                ("degree_u", Setting::Integer(s.degree_u())),
                ("degree_v", Setting::Integer(s.degree_v())),
            ];
            if shape.kind().has_knots() {
                keys.push(("knots_u", knots(s.knots_u(), pu)));
                keys.push(("knots_v", knots(s.knots_v(), pv)));
                keys.extend(flag("periodic_u", pu));
                keys.extend(flag("periodic_v", pv));
            }
            let all_cols = s.cols();
            let kept = (0..rows)
                .flat_map(|i| (0..cols).map(move |j| i * all_cols + j))
                .collect();
            (keys, kept)
        }
        Shape::Curve(_) => {
            let p = periodic.first().copied().flatten();
            let mut keys = Vec::with_capacity(3);
            if let Some(degree) = shape.curve_degree() {
                keys.push(("degree", Setting::Integer(degree)));
            }
            if let Some(k) = shape.curve_knots() {
                keys.push(("knots", knots(k, p)));
            }
            keys.extend(flag("periodic", p));
            (keys, (0..p.unwrap_or(shape.control_count())).collect())
        }
    }
}

/// The keys and values of a control point in writing order: `x, y, [z,]` the channels of the
/// membership family (`truth, indeterminacy, falsity` for the neutrosophic rule, `truth,
/// falsity` for the orthopair rules, `truth_lower, truth_upper, ...` for the interval-valued
/// ones), `[weight]`. `channels` are the point's channel values ([`Model::control_channels`]).
fn point_values(
    point: &PointData,
    channels: &[f64],
    membership: Family,
) -> Vec<(&'static str, f64)> {
    let mut values: Vec<(&'static str, f64)> = ["x", "y", "z"]
        .into_iter()
        .zip(point.position.iter().copied())
        .collect();
    values.extend(
        membership
            .channels()
            .iter()
            .copied()
            .zip(channels.iter().copied()),
    );
    if let Some(w) = point.weight {
        values.push(("weight", w));
    }
    values
}

/// The spread keys and values of a control point (TOML, JSON): per axis of the point, none
/// when both sides are 0, `spread_x` when they are equal, else `spread_x_left` and
/// `spread_x_right`.
fn spread_values(spread: &Spread<3>, dimension: usize) -> Vec<(&'static str, f64)> {
    let mut values = Vec::new();
    for axis in 0..dimension.min(3) {
        let (l, r) = (spread.left[axis], spread.right[axis]);
        if l == 0.0 && r == 0.0 {
            continue;
        }
        if l.to_bits() == r.to_bits() {
            values.push((SPREAD_KEYS[3 * axis], l));
        } else {
            values.push((SPREAD_KEYS[3 * axis + 1], l));
            values.push((SPREAD_KEYS[3 * axis + 2], r));
        }
    }
    values
}

/// The spread columns of a CSV table: per axis, none when every spread is 0, `spread_x` when
/// every point's two sides are equal, else `spread_x_left` and `spread_x_right` (as indices
/// into [`SPREAD_KEYS`]).
fn spread_columns(spreads: &[Spread<3>], dimension: usize) -> Vec<usize> {
    let mut columns = Vec::new();
    for axis in 0..dimension.min(3) {
        if spreads
            .iter()
            .all(|s| s.left[axis] == 0.0 && s.right[axis] == 0.0)
        {
            continue;
        }
        if spreads
            .iter()
            .all(|s| s.left[axis].to_bits() == s.right[axis].to_bits())
        {
            columns.push(3 * axis);
        } else {
            columns.extend([3 * axis + 1, 3 * axis + 2]);
        }
    }
    columns
}

/// The value of spread column `key` (an index into [`SPREAD_KEYS`]).
fn spread_value(spread: &Spread<3>, key: usize) -> f64 {
    let axis = key / 3;
    match key % 3 {
        2 => spread.right[axis],
        _ => spread.left[axis],
    }
}

/// Writes `[v0, v1, ...]`.
fn push_setting(out: &mut String, setting: &Setting) {
    match setting {
        Setting::Integer(n) => {
            let _ = write!(out, "{n}");
        }
        Setting::Knots(k) => push_array(out, k),
        Setting::Flag => out.push_str("true"),
    }
}

fn push_array(out: &mut String, values: &[f64]) {
    out.push('[');
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        file_number(out, v);
    }
    out.push(']');
}

/// A TOML basic string: `"`, `\` and control characters escaped.
fn toml_string(out: &mut String, text: &str) {
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\t' => out.push_str("\\t"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

/// A JSON string literal.
fn json_string(out: &mut String, text: &str) {
    out.push_str(&serde_json::Value::from(text).to_string());
}

/// The model as a TOML document: `kind`, `name`, `description`, `membership`, the structure
/// keys (`degree`, `knots`; `rows`, `cols`, `degree_u`, `degree_v`, `knots_u`, `knots_v`),
/// then one `[[control_points]]` table per control point (`name`, `x`, `y`, `z`, `truth`,
/// `indeterminacy`, `falsity`, `weight`). [`crate::parse`] reads it back to an equal model.
pub fn to_toml_string(model: &Model) -> String {
    let mut out = String::new();
    out.push_str("kind = ");
    toml_string(&mut out, model.kind().name());
    out.push('\n');
    for (key, value) in [("name", model.name()), ("description", model.description())] {
        if let Some(value) = value {
            out.push_str(key);
            out.push_str(" = ");
            toml_string(&mut out, value);
            out.push('\n');
        }
    }
    let membership = model.membership();
    let _ = writeln!(out, "membership = \"{}\"", membership.name());
    if let Some((key, value)) = membership.parameter() {
        let _ = writeln!(out, "{key} = {value}");
    }
    let (settings, kept) = layout(model);
    for (key, setting) in settings {
        let _ = write!(out, "{key} = ");
        push_setting(&mut out, &setting);
        out.push('\n');
    }
    let spreads = model.spreads();
    let points = model.shape().point_data();
    let channels = model.control_channels();
    for i in kept {
        let (point, name) = (&points[i], &model.point_names()[i]);
        out.push_str("\n[[control_points]]\n");
        if let Some(name) = name {
            out.push_str("name = ");
            toml_string(&mut out, name);
            out.push('\n');
        }
        let mut values = point_values(point, &channels[i], model.membership());
        if let Some(spreads) = spreads {
            values.extend(spread_values(&spreads[i], point.position.len()));
        }
        for (key, value) in values {
            out.push_str(key);
            out.push_str(" = ");
            file_number(&mut out, value);
            out.push('\n');
        }
    }
    out
}

/// The model as a JSON document: an object with the keys of [`to_toml_string`] and
/// `control_points`, an array of one object per control point, one per line.
/// [`crate::parse`] reads it back to an equal model.
pub fn to_json_string(model: &Model) -> String {
    let mut out = String::from("{\n  \"kind\": ");
    json_string(&mut out, model.kind().name());
    for (key, value) in [("name", model.name()), ("description", model.description())] {
        if let Some(value) = value {
            let _ = write!(out, ",\n  \"{key}\": ");
            json_string(&mut out, value);
        }
    }
    let membership = model.membership();
    let _ = write!(out, ",\n  \"membership\": \"{}\"", membership.name());
    if let Some((key, value)) = membership.parameter() {
        let _ = write!(out, ",\n  \"{key}\": {value}");
    }
    let (settings, kept) = layout(model);
    for (key, setting) in settings {
        let _ = write!(out, ",\n  \"{key}\": ");
        push_setting(&mut out, &setting);
    }
    out.push_str(",\n  \"control_points\": [");
    let points = model.shape().point_data();
    let channels = model.control_channels();
    for (k, &i) in kept.iter().enumerate() {
        let (point, name) = (&points[i], &model.point_names()[i]);
        out.push_str(if k == 0 { "\n    { " } else { ",\n    { " });
        let mut first = true;
        if let Some(name) = name {
            out.push_str("\"name\": ");
            json_string(&mut out, name);
            first = false;
        }
        let mut values = point_values(point, &channels[i], model.membership());
        if let Some(spreads) = model.spreads() {
            values.extend(spread_values(&spreads[i], point.position.len()));
        }
        for (key, value) in values {
            if !first {
                out.push_str(", ");
            }
            first = false;
            let _ = write!(out, "\"{key}\": ");
            file_number(&mut out, value);
        }
        out.push_str(" }");
    }
    out.push_str("\n  ]\n}\n");
    out
}

/// Why a CSV cell cannot hold `name` (the reader trims cells and reads an empty one as no
/// name).
fn csv_name_problem(name: &str) -> Option<&'static str> {
    if name.is_empty() {
        Some("is empty, which a CSV cell reads as no name")
    } else if name.trim() != name {
        Some("has leading or trailing whitespace, which a CSV cell loses")
    } else {
        None
    }
}

/// A CSV cell for a name: quoted when it holds a comma, quote or line end, or starts with `#`
/// (which would make the row a comment) or U+FEFF (which the CSV parser drops as a byte order
/// mark at the start of a row).
fn csv_name(out: &mut String, name: &str) {
    if name.starts_with(['#', '\u{feff}']) || name.contains([',', '"', '\n', '\r']) {
        out.push('"');
        out.push_str(&name.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(name);
    }
}

/// The control points as a CSV table: a header, then one control point per row (columns
/// `name` when any point has a name, `x`, `y`, `z` for 3-D shapes, the degrees the membership
/// rule keeps, `weight` for NURBS). Surfaces are written row by row.
///
/// A CSV file cannot hold the kind, degree, knots, grid, membership rule, name or
/// description: reading the table back needs the options of [`Model::csv_read_options`]
/// (on the command line: `--kind`, `--degree`, `--knots K0,K1,...`, `--rows`, ...,
/// `--membership`), and gives this model without its name and description.
///
/// # Errors
/// [`WriteError::Unrepresentable`] for a control point name that a CSV cell cannot hold
/// (empty, or with leading or trailing whitespace), or a row longer than the CSV reader's
/// line limit (1 MiB: 1,048,576 bytes).
pub fn to_csv_string(model: &Model) -> Result<String, WriteError> {
    let unrepresentable = |message: String| WriteError::Unrepresentable {
        path: None,
        format: Format::Csv,
        message,
    };
    let names = model.point_names();
    let named = names.iter().any(Option::is_some);
    let points = model.shape().point_data();
    let channels = model.control_channels();
    let (_, kept) = layout(model);
    let mut out = String::new();
    let mut header: Vec<&str> = Vec::new();
    if named {
        header.push("name");
    }
    if let Some(point) = points.first() {
        header.extend(
            point_values(point, &channels[0], model.membership())
                .iter()
                .map(|v| v.0),
        );
    }
    let spreads = model.spreads();
    let dimension = points.first().map_or(0, |p| p.position.len());
    let spread_keys = spreads.map_or_else(Vec::new, |s| spread_columns(s, dimension));
    header.extend(spread_keys.iter().map(|&k| SPREAD_KEYS[k]));
    out.push_str(&header.join(","));
    out.push('\n');
    let mut row = String::new();
    for index in kept {
        let (point, name) = (&points[index], &names[index]);
        row.clear();
        if named {
            if let Some(name) = name {
                if let Some(problem) = csv_name_problem(name) {
                    return Err(unrepresentable(format!(
                        "control point {index}: the name {name:?} {problem} (write TOML or JSON \
                         to keep it)"
                    )));
                }
                csv_name(&mut row, name);
            }
            row.push(',');
        }
        for (i, (_, value)) in point_values(point, &channels[index], model.membership())
            .iter()
            .enumerate()
        {
            if i > 0 {
                row.push(',');
            }
            file_number(&mut row, *value);
        }
        if let Some(spreads) = spreads {
            for &key in &spread_keys {
                row.push(',');
                file_number(&mut row, spread_value(&spreads[index], key));
            }
        }
        row.push('\n');
        if row.len() > MAX_CSV_LINE {
            return Err(unrepresentable(format!(
                "control point {index}: the row is {} bytes long, more than the {MAX_CSV_LINE} a \
                 CSV line may have (write TOML or JSON)",
                row.len()
            )));
        }
        out.push_str(&row);
    }
    Ok(out)
}

/// The model in `format`: [`to_toml_string`], [`to_json_string`] or [`to_csv_string`].
///
/// # Errors
/// As [`to_csv_string`] (TOML and JSON hold every model).
pub fn to_string(model: &Model, format: Format) -> Result<String, WriteError> {
    match format {
        Format::Csv => to_csv_string(model),
        Format::Toml => Ok(to_toml_string(model)),
        Format::Json => Ok(to_json_string(model)),
    }
}

/// Writes the model to `path` in the format of its extension ([`Format::from_path`]),
/// atomically: the text goes to a temporary file in the same directory, which is flushed to
/// disk and renamed over `path` ([`AtomicFile`]). On any error the old file is left as it was
/// and the temporary file is removed. A symbolic link is followed: its target is replaced.
///
/// # Errors
/// [`WriteError::Format`] for an unsupported extension, as [`to_csv_string`] for CSV, and
/// [`WriteError::Io`] naming the file.
pub fn save(model: &Model, path: impl AsRef<Path>) -> Result<(), WriteError> {
    let path = path.as_ref();
    let format = Format::from_path(path)?;
    let shown = path.display().to_string();
    let text = to_string(model, format).map_err(|e| match e {
        WriteError::Unrepresentable {
            format, message, ..
        } => WriteError::Unrepresentable {
            path: Some(shown.clone()),
            format,
            message,
        },
        other => other,
    })?;
    write_file(path, text.as_bytes(), |file, bytes| file.write_all(bytes))
        .map_err(|error| WriteError::Io { path: shown, error })
}

/// Writes `bytes` to a new version of `path` with `write`, then commits it.
fn write_file(
    path: &Path,
    bytes: &[u8],
    write: impl FnOnce(&mut AtomicFile, &[u8]) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let mut file = AtomicFile::create(path)?;
    write(&mut file, bytes)?;
    file.commit()
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{example1, AnyCurve};
    use std::fs;

    #[test]
    fn save_leaves_the_old_file_on_a_write_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("model.toml");
        fs::write(&path, "old\n").unwrap();
        let error = write_file(&path, b"kind = \"bezier\"\n", |file, bytes| {
            file.write_all(&bytes[..5])?;
            file.flush()?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert_eq!(error.to_string(), "disk full");
        assert_eq!(fs::read_to_string(&path).unwrap(), "old\n");
        assert_eq!(
            fs::read_dir(dir.path()).unwrap().count(),
            1,
            "temporary file left behind"
        );
        let model = Model::new(AnyCurve::Bezier(example1()));
        save(&model, &path).unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), to_toml_string(&model));
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn csv_names_are_quoted_or_refused() {
        let model = Model::new(AnyCurve::Bezier(example1()))
            .with_point_names([Some("#1"), Some("a, \"b\""), None, Some("line\nbreak")])
            .unwrap();
        let text = to_csv_string(&model).unwrap();
        assert!(
            text.starts_with(
                "name,x,y,truth,indeterminacy,falsity\n\"#1\",1.0,3.0,0.3,0.6,0.1\n\
                 \"a, \"\"b\"\"\",3.0,6.0,0.8,0.1,0.1\n,6.0,2.0,0.7,0.1,0.2\n\"line\nbreak\","
            ),
            "{text}"
        );
        for bad in ["", " padded"] {
            let model = Model::new(AnyCurve::Bezier(example1()))
                .with_point_names([None, None, Some(bad), None])
                .unwrap();
            let e = to_csv_string(&model).unwrap_err().to_string();
            assert!(
                e.starts_with("cannot write CSV: control point 2: the name "),
                "{e}"
            );
        }
    }
}
