//! Reading curves from DXF files: every SPLINE entity of the ENTITIES section becomes a model,
//! exactly (degree, knots, control points and weights as written, numbers parsed with Rust's
//! correctly rounded `f64` parser), with the degrees, kind, membership rule and names of its
//! `NEUTROSPLINE` extended data ([`crate::dxf_xdata`]) when it has them and the given default
//! degrees when it has none.
//!
//! A DXF file is a sequence of groups, each a line with an integer group code and a line with
//! its value. A SPLINE entity (AutoCAD's DXF reference, "SPLINE") has the flags (70: 4
//! rational), the degree (71), the numbers of knots (72), control points (73) and fit points
//! (74), the knots (40, in order), the weights (41, one per control point when the curve is
//! rational) and the control points (10, 20, 30: x, y, z, in order). A spline given by fit
//! points only is refused: its curve is defined by the CAD program's interpolation, not by the
//! file.
//!
//! Without extended data, a spline whose control points all have `z = 0` is a plane curve, and
//! its kind is `nurbs` when it has weights, `bspline` otherwise.

use std::path::Path;

use neutrospline::{
    AnyCurve, BSpline, Bezier, ControlPoint, CurveKind, Degrees, KnotVector, Nurbs,
};

use crate::dxf_xdata::{self, ModelInfo, XTag};
use crate::report::{Import, ImportOptions, ImportReport};
use neutrospline_io::read_whole;
use neutrospline_io::{InputError, Kind, Limits, Model, ReadError};

/// The first bytes of a binary DXF file (AutoCAD's DXF reference, "Binary DXF Files").
const BINARY_SENTINEL: &[u8] = b"AutoCAD Binary DXF";

/// One group: its code, its value and the line of its code (1-based).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Group<'a> {
    pub code: u16,
    pub value: &'a str,
    pub line: usize,
}

/// The groups of a DXF text: alternate lines of a group code (an integer, spaces allowed
/// around it) and a value (`\r\n` line ends allowed), up to the `0 EOF` group that ends the
/// file. After it only blank lines and DOS end-of-file bytes (0x1A) may follow, as programs
/// write them (Inkscape's R12 files end with a blank line); a file without `0 EOF` may end
/// with 0x1A bytes.
///
/// # Errors
/// A line and a message for a group code that is not an integer, a code without a value, or
/// something other than blank lines after `0 EOF`.
pub(crate) fn groups(text: &str) -> Result<Vec<Group<'_>>, (usize, String)> {
    let mut lines: Vec<&str> = text.lines().collect();
    let end = lines
        .chunks_exact(2)
        .position(|pair| pair[0].trim() == "0" && pair[1].trim() == "EOF");
    match end {
        Some(k) => {
            let after = 2 * k + 2;
            if let Some(extra) = lines[after..].iter().position(|line| {
                !line
                    .trim_matches(|c: char| c.is_whitespace() || c == '\u{1a}')
                    .is_empty()
            }) {
                return Err((
                    after + extra + 1,
                    "the file goes on after its end (`0 EOF`): only blank lines may follow it"
                        .to_owned(),
                ));
            }
            lines.truncate(after);
        }
        None => {
            // A DOS end-of-file byte ends the text.
            while lines.last().is_some_and(|line| {
                line.trim_end_matches('\u{1a}').is_empty() && line.contains('\u{1a}')
            }) {
                lines.pop();
            }
            if let Some(last) = lines.last_mut() {
                *last = last.trim_end_matches('\u{1a}');
            }
        }
    }
    if !lines.len().is_multiple_of(2) {
        return Err((
            lines.len(),
            format!(
                "group code `{}` has no value (the file ends)",
                lines[lines.len() - 1].trim()
            ),
        ));
    }
    lines
        .chunks_exact(2)
        .enumerate()
        .map(|(k, pair)| {
            let line = 2 * k + 1;
            let code = pair[0].trim().parse::<u16>().map_err(|_| {
                (
                    line,
                    format!(
                        "group code `{}` is not an integer from 0 to 1071",
                        pair[0].trim()
                    ),
                )
            })?;
            Ok(Group {
                code,
                value: pair[1],
                line,
            })
        })
        .collect()
}

/// An error in `file` at `line`.
fn error(file: &str, line: usize, message: String) -> ReadError {
    InputError::new(file, Some(line), None, message).into()
}

/// The SPLINE entities of the ENTITIES section: the line of each `0 SPLINE` and its groups.
fn spline_entities<'a>(
    file: &str,
    groups: &[Group<'a>],
) -> Result<Vec<(usize, Vec<Group<'a>>)>, ReadError> {
    let start = groups
        .windows(2)
        .position(|w| {
            w[0].code == 0
                && w[0].value.trim() == "SECTION"
                && w[1].code == 2
                && w[1].value.trim() == "ENTITIES"
        })
        .ok_or_else(|| {
            InputError::new(
                file,
                None,
                None,
                "the file has no ENTITIES section (a DXF file holds its curves there)".to_owned(),
            )
        })?
        + 2;
    let mut out: Vec<(usize, Vec<Group<'a>>)> = Vec::new();
    let mut others: Vec<&str> = Vec::new();
    let mut in_spline = false;
    for g in &groups[start..] {
        if g.code == 0 {
            let kind = g.value.trim();
            if kind == "ENDSEC" {
                if out.is_empty() {
                    others.sort_unstable();
                    others.dedup();
                    let found = if others.is_empty() {
                        "it is empty".to_owned()
                    } else {
                        format!("it holds {}", others.join(", "))
                    };
                    return Err(error(
                        file,
                        g.line,
                        format!("the ENTITIES section has no SPLINE entity ({found})"),
                    ));
                }
                return Ok(out);
            }
            in_spline = kind == "SPLINE";
            if in_spline {
                out.push((g.line, Vec::new()));
            } else {
                others.push(kind);
            }
        } else if in_spline {
            if let Some((_, entity)) = out.last_mut() {
                entity.push(*g);
            }
        }
    }
    Err(InputError::new(
        file,
        None,
        None,
        "the ENTITIES section has no end (`0 ENDSEC`): the file is cut short".to_owned(),
    )
    .into())
}

/// What one SPLINE entity says, before it becomes a model.
struct SplineGroups<'a> {
    line: usize,
    flags: Option<Group<'a>>,
    degree: Option<Group<'a>>,
    knot_count: Option<Group<'a>>,
    point_count: Option<Group<'a>>,
    fit_count: Option<Group<'a>>,
    knots: Vec<Group<'a>>,
    weights: Vec<Group<'a>>,
    /// x, then y and z when given.
    points: Vec<[Option<Group<'a>>; 3]>,
    fit_points: usize,
    xdata: Option<(usize, Vec<XTag<'a>>)>,
}

fn collect<'a>(
    file: &str,
    line: usize,
    entity: &[Group<'a>],
) -> Result<SplineGroups<'a>, ReadError> {
    let mut s = SplineGroups {
        line,
        flags: None,
        degree: None,
        knot_count: None,
        point_count: None,
        fit_count: None,
        knots: Vec::new(),
        weights: Vec::new(),
        points: Vec::new(),
        fit_points: 0,
        xdata: None,
    };
    let mut k = 0;
    while k < entity.len() {
        let g = entity[k];
        match g.code {
            70 => s.flags = Some(g),
            71 => s.degree = Some(g),
            72 => s.knot_count = Some(g),
            73 => s.point_count = Some(g),
            74 => s.fit_count = Some(g),
            40 => s.knots.push(g),
            41 => s.weights.push(g),
            10 => s.points.push([Some(g), None, None]),
            20 | 30 => {
                let axis = usize::from(g.code / 10 - 1);
                match s.points.last_mut() {
                    Some(p) if p[axis].is_none() => p[axis] = Some(g),
                    _ => {
                        return Err(error(
                            file,
                            g.line,
                            format!("group code {} = `{}` is not after the x (group code 10) of a control point", g.code, g.value),
                        ))
                    }
                }
            }
            11 => s.fit_points += 1,
            1001 => {
                // Extended data: ours is read, another application's skipped.
                let end = entity[k + 1..]
                    .iter()
                    .position(|x| x.code == 1001)
                    .map_or(entity.len(), |e| k + 1 + e);
                if g.value.trim() == dxf_xdata::APP {
                    let tags = entity[k + 1..end]
                        .iter()
                        .map(|x| (x.code, x.value, x.line))
                        .collect();
                    s.xdata = Some((g.line, tags));
                }
                k = end;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    Ok(s)
}

/// A group's value as a number, or a located error naming the group and what it is.
fn real(file: &str, g: Group<'_>, what: &str) -> Result<f64, ReadError> {
    let v = g.value.trim();
    match v.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(error(
            file,
            g.line,
            format!(
                "{what} (group code {}) = `{v}` is not a finite number",
                g.code
            ),
        )),
    }
}

/// A required integer group.
fn count(
    file: &str,
    line: usize,
    g: Option<Group<'_>>,
    what: &str,
    code: u16,
) -> Result<usize, ReadError> {
    let g = g.ok_or_else(|| {
        error(
            file,
            line,
            format!("the SPLINE has no {what} (group code {code})"),
        )
    })?;
    g.value.trim().parse::<usize>().map_err(|_| {
        error(
            file,
            g.line,
            format!(
                "{what} (group code {code}) = `{}` is not a whole number",
                g.value.trim()
            ),
        )
    })
}

/// The model of one SPLINE entity.
fn model(
    file: &str,
    s: &SplineGroups<'_>,
    defaults: Degrees,
    limits: &Limits,
) -> Result<Model, ReadError> {
    let at = |line: usize, message: String| error(file, line, message);
    let degree = count(file, s.line, s.degree, "degree", 71)?;
    let knot_count = count(file, s.line, s.knot_count, "number of knots", 72)?;
    let point_count = count(file, s.line, s.point_count, "number of control points", 73)?;
    let fit_count = match s.fit_count {
        Some(g) => count(file, s.line, Some(g), "number of fit points", 74)?,
        None => s.fit_points,
    };
    if point_count == 0 && s.points.is_empty() {
        let message = if fit_count > 0 {
            format!("the SPLINE is given by {fit_count} fit points and no control points: its curve is the CAD program's interpolation, which this program does not repeat (save it with control points)")
        } else {
            "the SPLINE has no control points".to_owned()
        };
        return Err(at(s.line, message));
    }
    if s.points.len() as u64 > limits.max_control_points {
        return Err(at(s.line, limits.too_many_control_points()));
    }
    if s.knots.len() != knot_count {
        return Err(at(
            s.knot_count.map_or(s.line, |g| g.line),
            format!("the number of knots (group code 72) is {knot_count}, but the SPLINE has {} knots (group code 40)", s.knots.len()),
        ));
    }
    if s.points.len() != point_count {
        return Err(at(
            s.point_count.map_or(s.line, |g| g.line),
            format!("the number of control points (group code 73) is {point_count}, but the SPLINE has {} (group code 10)", s.points.len()),
        ));
    }
    let knots = s
        .knots
        .iter()
        .map(|&g| real(file, g, "knot"))
        .collect::<Result<Vec<_>, _>>()?;
    let weights = s
        .weights
        .iter()
        .map(|&g| real(file, g, "weight"))
        .collect::<Result<Vec<_>, _>>()?;
    if !weights.is_empty() && weights.len() != point_count {
        return Err(at(
            s.weights[0].line,
            format!("{} weights (group code 41) for {point_count} control points (give one weight per control point, or none)", weights.len()),
        ));
    }
    let mut positions = Vec::with_capacity(point_count);
    for p in &s.points {
        let mut xyz = [0.0; 3];
        for (axis, g) in p.iter().enumerate() {
            match g {
                Some(g) => xyz[axis] = real(file, *g, ["x", "y", "z"][axis])?,
                None if axis == 1 => {
                    let x = p[0].map_or(s.line, |g| g.line);
                    return Err(at(
                        x,
                        "the control point has an x (group code 10) but no y (group code 20)"
                            .to_owned(),
                    ));
                }
                None => {}
            }
        }
        positions.push(xyz);
    }
    if let Some(g) = s.flags {
        let flags = g.value.trim().parse::<i64>().map_err(|_| {
            at(
                g.line,
                format!(
                    "flags (group code 70) = `{}` is not an integer",
                    g.value.trim()
                ),
            )
        })?;
        if flags & 4 != 0 && weights.is_empty() {
            return Err(at(g.line, format!("flags (group code 70) = {flags} say the SPLINE is rational (4), but it has no weights (group code 41)")));
        }
    }
    let info = match &s.xdata {
        Some((line, tags)) => Some(
            dxf_xdata::read(tags, *line)
                .map_err(|(l, m)| at(l, format!("NEUTROSPLINE extended data: {m}")))?,
        ),
        None => None,
    };
    let xdata_line = s.xdata.as_ref().map_or(s.line, |x| x.0);
    let planar = positions.iter().all(|p| p[2] == 0.0);
    let dimension = match &info {
        Some(info) if info.dimension == 2 && !planar => {
            return Err(at(
                xdata_line,
                "the extended data says the curve is 2-D, but a control point has z other than 0"
                    .to_owned(),
            ));
        }
        Some(info) => info.dimension,
        None if planar => 2,
        None => 3,
    };
    let kind = match &info {
        Some(ModelInfo {
            kind: Kind::Curve(kind),
            ..
        }) => *kind,
        Some(ModelInfo { kind, .. }) => {
            return Err(at(
                xdata_line,
                format!(
                    "the extended data says `{}`, but a SPLINE entity is a curve",
                    kind.name()
                ),
            ));
        }
        None if !weights.is_empty() => CurveKind::Nurbs,
        None => CurveKind::BSpline,
    };
    if kind == CurveKind::Nurbs && weights.is_empty() {
        return Err(at(
            s.line,
            "a NURBS curve without weights (group code 41, one per control point)".to_owned(),
        ));
    }
    if kind != CurveKind::Nurbs && weights.iter().any(|&w| w != 1.0) {
        return Err(at(
            s.weights[0].line,
            format!(
                "the extended data says `{}`, but the SPLINE has weights other than 1",
                Kind::Curve(kind).name()
            ),
        ));
    }
    let degrees = match &info {
        Some(info) if !info.degrees.is_empty() => {
            if info.degrees.len() != point_count {
                return Err(at(xdata_line, format!("the extended data has degrees for {} control points, the SPLINE has {point_count}", info.degrees.len())));
            }
            info.degrees.clone()
        }
        _ => vec![defaults; point_count],
    };
    let shape: neutrospline_io::Shape = match dimension {
        2 => curve::<2>(file, s, kind, degree, knots, weights, &positions, &degrees)?.into(),
        _ => curve::<3>(file, s, kind, degree, knots, weights, &positions, &degrees)?.into(),
    };
    let mut model = Model::new(shape);
    if let Some(info) = info {
        if let Some(name) = info.name {
            model = model.with_name(name);
        }
        if let Some(description) = info.description {
            model = model.with_description(description);
        }
        model = model
            .with_membership(info.membership)
            .map_err(|e| at(xdata_line, format!("NEUTROSPLINE extended data: {e}")))?;
        if !info.point_names.is_empty() {
            model = model
                .with_point_names(info.point_names)
                .map_err(|e| at(xdata_line, format!("NEUTROSPLINE extended data: {e}")))?;
        }
    }
    Ok(model)
}

/// The curve of one SPLINE entity, in `D` dimensions.
#[allow(clippy::too_many_arguments)]
fn curve<const D: usize>(
    file: &str,
    s: &SplineGroups<'_>,
    kind: CurveKind,
    degree: usize,
    knots: Vec<f64>,
    weights: Vec<f64>,
    positions: &[[f64; 3]],
    degrees: &[Degrees],
) -> Result<AnyCurve<D>, ReadError> {
    let points: Vec<ControlPoint<D>> = positions
        .iter()
        .zip(degrees)
        .map(|(p, d)| {
            let mut position = [0.0; D];
            position.copy_from_slice(&p[..D]);
            ControlPoint::new(position, *d)
        })
        .collect();
    let count = points.len();
    let knot_line = s.knot_count.map_or(s.line, |g| g.line);
    if kind == CurveKind::Bezier {
        let clamped: Vec<f64> = [vec![0.0; count], vec![1.0; count]].concat();
        if degree + 1 != count || knots != clamped {
            return Err(error(
                file,
                knot_line,
                format!(
                    "the extended data says `bezier`, but the SPLINE is not a Bezier curve \
                     (degree {degree} with {count} control points and knots 0 and 1 each \
                     degree + 1 times)"
                ),
            ));
        }
        return Bezier::new(points)
            .map(AnyCurve::Bezier)
            .map_err(|e| error(file, s.line, e.to_string()));
    }
    let knots =
        KnotVector::new(knots, degree, count).map_err(|e| error(file, knot_line, e.to_string()))?;
    let built = match kind {
        CurveKind::Nurbs => Nurbs::new(points, weights, knots).map(AnyCurve::Nurbs),
        _ => BSpline::new(points, knots).map(AnyCurve::BSpline),
    };
    built.map_err(|e| error(file, s.line, e.to_string()))
}

/// The curves of a DXF file held in memory: one model per SPLINE entity of its ENTITIES
/// section, in order. `file` names it in messages; `defaults` are the degrees of every control
/// point of a spline without `NEUTROSPLINE` extended data.
///
/// The text is UTF-8 (DXF R2007 and later); a file that is not is read as Latin-1 (the code
/// page of older files; the groups this reader uses are ASCII either way).
///
/// # Errors
/// [`ReadError::Input`] naming the file and line: a binary DXF file (refused as such), groups
/// that do not parse or content after `0 EOF`, no ENTITIES
/// section or one cut short, no SPLINE entity, a SPLINE without its degree or counts, counts
/// that do not match the knots or control points (the core's rule: control points + degree +
/// 1 knots, non-decreasing), a spline given by fit points only, extended data that breaks its
/// layout or the degrees' rules, more control points than `limits` allow.
pub fn parse_dxf(
    file: &str,
    bytes: &[u8],
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let defaults = options.defaults;
    if bytes.starts_with(BINARY_SENTINEL) {
        return Err(InputError::new(
            file,
            None,
            None,
            "a binary DXF file (it starts with `AutoCAD Binary DXF`), which this program does \
             not read: save the drawing as an ASCII DXF file"
                .to_owned(),
        )
        .into());
    }
    let text: std::borrow::Cow<'_, str> = match std::str::from_utf8(bytes) {
        Ok(text) => text.into(),
        Err(_) => bytes
            .iter()
            .map(|&b| char::from(b))
            .collect::<String>()
            .into(),
    };
    let groups = groups(&text).map_err(|(line, message)| error(file, line, message))?;
    let models = spline_entities(file, &groups)?
        .iter()
        .map(|(line, entity)| {
            let s = collect(file, *line, entity)?;
            model(file, &s, defaults, limits)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut report = ImportReport::default();
    report.imported_many("SPLINE", models.len());
    Ok(Import { models, report })
}

/// The curves of the DXF file at `path` ([`parse_dxf`]), read whole up to
/// [`Limits::max_file_size`] bytes.
///
/// # Errors
/// [`ReadError::Io`] and [`ReadError::IsDirectory`] when the file cannot be read, as
/// [`parse_dxf`] otherwise.
pub fn load_dxf(
    path: impl AsRef<Path>,
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let (shown, bytes) = read_whole(path.as_ref(), limits.max_file_size, "a .dxf file")?;
    parse_dxf(&shown, &bytes, options, limits)
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use proptest::prelude::*;

    use neutrospline::{Evaluate, Membership};

    use super::*;
    use crate::{export, ExportFormat, ExportOptions};
    use neutrospline_io::{load, ReadOptions};

    fn example(name: &str) -> Model {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name);
        load(&path, &ReadOptions::default()).unwrap()
    }

    fn defaults() -> Degrees {
        Degrees::new(0.7, 0.2, 0.1).unwrap()
    }

    /// A DXF text with `entities` in its ENTITIES section, whose first group is on line 5.
    fn dxf(entities: &str) -> String {
        format!("  0\nSECTION\n  2\nENTITIES\n{entities}  0\nENDSEC\n  0\nEOF\n")
    }

    /// A quadratic spline in the plane through three control points, without extended data.
    const QUADRATIC: &str = concat!(
        "  0\nSPLINE\n  8\n0\n 70\n8\n 71\n2\n 72\n6\n 73\n3\n",
        " 40\n0\n 40\n0\n 40\n0\n 40\n1\n 40\n1\n 40\n1\n",
        " 10\n0\n 20\n0\n 30\n0\n 10\n1\n 20\n2\n 30\n0\n 10\n2\n 20\n0\n 30\n0\n",
    );

    fn message(text: &str) -> String {
        parse_dxf(
            "f.dxf",
            text.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap_err()
        .to_string()
    }

    #[test]
    fn dxf_export_then_import_gives_back_every_example_curve() {
        for file in [
            "example1.toml",
            "helix3d.toml",
            "bspline.toml",
            "nurbs-circle.toml",
        ] {
            let model = example(file);
            let bytes = export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap();
            let back = parse_dxf(
                file,
                &bytes,
                &ImportOptions::new(defaults()),
                &Limits::default(),
            )
            .map(|i| i.models)
            .unwrap();
            assert_eq!(back, [model], "{file}");
        }
        // Membership, names with escapes and a long description survive too.
        let model = Model::new(AnyCurve::Bezier(neutrospline::example1()))
            .with_name("caf\u{e9} ^ \\U+0041 \u{1F600}")
            .with_description("d".repeat(700))
            .with_point_names([None, Some("a\nb"), Some(""), Some(" C3 ")])
            .unwrap();
        let fuzzy = Model::new(AnyCurve::Bezier(
            Bezier::new(vec![
                ControlPoint::new([0.0, 0.0, 1.0], Degrees::fuzzy(0.1).unwrap()),
                ControlPoint::new(
                    [1.0, 1.0, 1.0],
                    Degrees::fuzzy(0.30000000000000004).unwrap(),
                ),
            ])
            .unwrap(),
        ))
        .with_membership(Membership::Fuzzy)
        .unwrap();
        for model in [model, fuzzy] {
            let bytes = export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap();
            let back = parse_dxf(
                "m.dxf",
                &bytes,
                &ImportOptions::new(defaults()),
                &Limits::default(),
            )
            .map(|i| i.models)
            .unwrap();
            assert_eq!(back, [model]);
        }
    }

    #[test]
    fn dxf_spline_without_extended_data_takes_the_default_degrees() {
        let models = parse_dxf(
            "q.dxf",
            dxf(QUADRATIC).as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .unwrap()
        .models;
        assert_eq!(models.len(), 1);
        let model = &models[0];
        assert_eq!(model.kind(), Kind::Curve(CurveKind::BSpline));
        assert_eq!(
            (model.name(), model.membership()),
            (None, Membership::Neutrosophic)
        );
        let Some(neutrospline::DynCurve::Planar(curve)) = model.shape().curve() else {
            panic!("a plane curve")
        };
        // (P0 + 2 P1 + P2) / 4 at t = 0.5, with the default degrees everywhere.
        let p = curve.evaluate(0.5).unwrap();
        assert_eq!(p.position, [1.0, 1.0]);
        assert_eq!(p.degrees, defaults());
        // CRLF line ends, a weight per point and a second spline in 3-D.
        let weighted = QUADRATIC.replace(" 10\n0\n", " 41\n1\n 41\n0.5\n 41\n1\n 10\n0\n");
        let spatial = QUADRATIC.replace(" 30\n0\n 10\n2\n", " 30\n5\n 10\n2\n");
        let text = dxf(&format!("  0\nLINE\n  8\n0\n{weighted}{spatial}")).replace('\n', "\r\n");
        let models = parse_dxf(
            "w.dxf",
            text.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap();
        assert_eq!(models.len(), 2);
        assert_eq!(models[0].kind(), Kind::Curve(CurveKind::Nurbs));
        assert_eq!(models[0].shape().weights(), Some(&[1.0, 0.5, 1.0][..]));
        assert_eq!(
            (models[1].kind(), models[1].shape().dimension()),
            (Kind::Curve(CurveKind::BSpline), 3)
        );
    }

    /// Inkscape's R12 export (dxf2gcode's `Inkspace_dxf_export_kreis_splines.dxf`) ends with a
    /// blank line after `0 EOF`; DOS programs end a file with 0x1A. Both read as the file
    /// without them, curve for curve.
    #[test]
    fn dxf_blank_lines_and_dos_end_bytes_after_the_end_are_ignored() {
        let plain = parse_dxf(
            "f.dxf",
            dxf(QUADRATIC).as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .unwrap()
        .models;
        assert_eq!(plain.len(), 1);
        for ending in ["\n", "\n\n  \n", "\u{1a}", "\r\n\u{1a}", "\n\u{1a}\n"] {
            let text = format!("{}{ending}", dxf(QUADRATIC));
            let read = parse_dxf(
                "f.dxf",
                text.as_bytes(),
                &ImportOptions::new(defaults()),
                &Limits::default(),
            )
            .map(|i| i.models);
            assert_eq!(
                read.as_ref().ok(),
                Some(&plain),
                "ending {ending:?}: {read:?}"
            );
        }
        // Without `0 EOF`, a final 0x1A still ends the text.
        let cut = dxf(QUADRATIC).replace("  0\nEOF\n", "\u{1a}");
        let read = parse_dxf(
            "f.dxf",
            cut.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models);
        assert_eq!(read.as_ref().ok(), Some(&plain), "{read:?}");
    }

    #[test]
    fn dxf_errors_are_located() {
        assert_eq!(
            message(&dxf(&QUADRATIC.replace(" 71\n2\n", ""))),
            "f.dxf:5: the SPLINE has no degree (group code 71)"
        );
        assert_eq!(
            message(&dxf(&QUADRATIC.replace(" 72\n6\n", " 72\n7\n"))),
            "f.dxf:13: the number of knots (group code 72) is 7, but the SPLINE has 6 knots (group code 40)"
        );
        assert_eq!(
            message(&dxf(&QUADRATIC.replace(" 72\n6\n 73\n3\n", " 72\n6\n 73\n2\n"))),
            "f.dxf:15: the number of control points (group code 73) is 2, but the SPLINE has 3 (group code 10)"
        );
        assert_eq!(
            message(&dxf(&QUADRATIC.replace(" 71\n2\n", " 71\n1\n"))),
            "f.dxf:13: knot vector has 6 knots, expected 5 (number of control points + degree + 1)"
        );
        assert_eq!(
            message(&dxf(&QUADRATIC.replacen(" 40\n1\n", " 40\nx\n", 1))),
            "f.dxf:23: knot (group code 40) = `x` is not a finite number"
        );
        assert_eq!(
            message(&dxf("  0\nSPLINE\n 71\n3\n 72\n0\n 73\n0\n 74\n4\n 11\n0\n 21\n0\n")),
            "f.dxf:5: the SPLINE is given by 4 fit points and no control points: its curve is the CAD program's interpolation, which this program does not repeat (save it with control points)"
        );
        assert_eq!(
            message(&dxf(&QUADRATIC.replace(" 70\n8\n", " 70\n12\n"))),
            "f.dxf:9: flags (group code 70) = 12 say the SPLINE is rational (4), but it has no weights (group code 41)"
        );
        assert_eq!(
            message(&dxf("  0\nLINE\n  8\n0\n  0\nCIRCLE\n")),
            "f.dxf:11: the ENTITIES section has no SPLINE entity (it holds CIRCLE, LINE)"
        );
        assert_eq!(
            message("  0\nSECTION\n  2\nHEADER\n  0\nENDSEC\n"),
            "f.dxf: the file has no ENTITIES section (a DXF file holds its curves there)"
        );
        assert_eq!(
            message(&format!("  0\nSECTION\n  2\nENTITIES\n{QUADRATIC}")),
            "f.dxf: the ENTITIES section has no end (`0 ENDSEC`): the file is cut short"
        );
        assert_eq!(
            message("  0\nSECTION\n  2\n"),
            "f.dxf:3: group code `2` has no value (the file ends)"
        );
        assert_eq!(
            message("  0\nSECTION\nxx\nENTITIES\n"),
            "f.dxf:3: group code `xx` is not an integer from 0 to 1071"
        );
        // The first bytes of ezdxf's and netDxf's binary test files.
        assert_eq!(
            message("AutoCAD Binary DXF\r\n\u{1a}\0\0\0SECTION\0"),
            "f.dxf: a binary DXF file (it starts with `AutoCAD Binary DXF`), which this program \
             does not read: save the drawing as an ASCII DXF file"
        );
        // Something after the end, other than blank lines.
        assert_eq!(
            message(&format!("{}  0\nLINE\n", dxf(QUADRATIC))),
            format!(
                "f.dxf:{}: the file goes on after its end (`0 EOF`): only blank lines may follow it",
                dxf(QUADRATIC).lines().count() + 1
            )
        );
        // Extended data that contradicts the entity.
        let model = example("example1.toml");
        let text =
            String::from_utf8(export(&model, ExportFormat::Dxf, &ExportOptions::new()).unwrap())
                .unwrap();
        // The first control point's z, after the SPLINE's normal (210, 220, 230).
        let at = text.find("\n230\n1\n").unwrap();
        let moved = format!(
            "{}{}",
            &text[..at],
            text[at..].replacen(" 30\n0\n", " 30\n1\n", 1)
        );
        let error = parse_dxf(
            "e.dxf",
            moved.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap_err()
        .to_string();
        assert!(
            error.ends_with(
                ": the extended data says the curve is 2-D, but a control point has z other than 0"
            ),
            "{error}"
        );
        let wrong = text.replacen("1040\n0.3\n", "1040\n1.5\n", 1);
        let error = parse_dxf(
            "e.dxf",
            wrong.as_bytes(),
            &ImportOptions::new(defaults()),
            &Limits::default(),
        )
        .map(|i| i.models)
        .unwrap_err()
        .to_string();
        assert!(
            error.contains(": NEUTROSPLINE extended data: truth = 1.5 is outside [0, 1]"),
            "{error}"
        );
    }

    proptest! {
        /// Any groups in a SPLINE entity (and in its extended data) give models or a message,
        /// never a panic.
        #[test]
        fn dxf_never_panics(
            groups in proptest::collection::vec(
                (
                    prop_oneof![Just("10"), Just("20"), Just("30"), Just("40"), Just("41"),
                                Just("70"), Just("71"), Just("72"), Just("73"), Just("74"),
                                Just("11"), Just("1001"), Just("1000"), Just("1040"),
                                Just("1070"), Just("1071"), Just("0"), Just("x")],
                    prop_oneof![Just("0".to_owned()), Just("1".to_owned()), Just("3".to_owned()),
                                Just("-1".to_owned()), Just("NEUTROSPLINE".to_owned()),
                                Just("neutrospline 1".to_owned()), Just("kind".to_owned()),
                                Just("degrees".to_owned()), Just("bezier".to_owned()),
                                Just("SPLINE".to_owned()), "[0-9.e-]{1,6}"],
                ),
                0..40,
            ),
        ) {
            let body: String = groups.iter().map(|(c, v)| format!("{c}\n{v}\n")).collect();
            let text = dxf(&format!("  0\nSPLINE\n{body}"));
            let _ = parse_dxf("p.dxf", text.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
            let with_quadratic = dxf(&format!("{QUADRATIC}1001\nNEUTROSPLINE\n{body}"));
            let _ = parse_dxf("p.dxf", with_quadratic.as_bytes(), &ImportOptions::new(defaults()), &Limits::default()).map(|i| i.models);
        }
    }
}
