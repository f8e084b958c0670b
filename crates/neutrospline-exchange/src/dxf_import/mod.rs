//! Reading curves from DXF files (AutoCAD's DXF reference): every curve entity drawn in model
//! space becomes a model, exactly, every control point with the given default degrees (a
//! SPLINE with neutrospline's `NEUTROSPLINE` extended data keeps the degrees, kind,
//! membership and names written there, [`crate::dxf_xdata`]).
//!
//! - SPLINE: degree, knots, weights and control points as written ([`spline`]);
//! - LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE (with its VERTEX entities): exact
//!   pieces joined into one curve per entity, lines of degree 1 and circular or elliptical
//!   arcs as rational quadratic pieces of at most 90° ([`entities`], [`geometry`]), in the
//!   entity's object coordinate system (its extrusion direction, by the Arbitrary Axis
//!   Algorithm) mapped to the world;
//! - INSERT: the entities of the block it names (BLOCKS section), mapped by
//!   `ocs ∘ translate(insertion point + array offset) ∘ rotate(50) ∘ scale(41, 42, 43) ∘
//!   translate(-base point)`, for each of its column / row copies (70, 71, spacings 44, 45,
//!   offsets rotated with the block); nested INSERTs are followed, a block that inserts
//!   itself is an error, and the expansion is capped by `limits` (the control points of all
//!   curves, and as many expanded entities);
//! - the layers of the LAYER table: an entity on a layer that is off (negative colour 62) or
//!   frozen (flag 70 bit 1) is hidden; an entity of a block on layer `0` takes the layer of
//!   its INSERT; layer names compare without regard to case;
//! - model space is read: the entities of paper space (group 67 = 1) are recorded as not
//!   drawn under `KIND (paper space)`, unless model space has no curve at all, when paper
//!   space is read instead, with a warning (a drawing laid out on a sheet only); the entities
//!   of a block no INSERT draws are recorded as not drawn;
//! - every other entity is recorded: text, hatches, dimensions, points, faces, solids,
//!   images and viewports are not curves; other kinds (RAY, XLINE, MLINE, HELIX, meshes,
//!   a SPLINE given by fit points only, kinds this reader does not know) are unsupported.
//!
//! A DXF file is a sequence of groups, each a line with an integer group code and a line with
//! its value ([`groups`]).

mod entities;
mod geometry;
mod groups;
mod spline;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_unseen;

use std::collections::HashMap;
use std::path::Path;

use neutrospline_io::read_whole;
use neutrospline_io::{InputError, Limits, Model, ReadError};

use crate::report::{Import, ImportOptions, ImportReport, SkipReason};
use entities::Drawn;
use geometry::{curve_of, ocs, sin_cos_degrees, spline_of, Affine};
pub(crate) use groups::{groups, Group};

/// The first bytes of a binary DXF file (AutoCAD's DXF reference, "Binary DXF Files").
const BINARY_SENTINEL: &[u8] = b"AutoCAD Binary DXF";

/// The entity kinds that draw something other than a curve.
const NOT_CURVES: &[&str] = &[
    "TEXT",
    "MTEXT",
    "ATTDEF",
    "ATTRIB",
    "HATCH",
    "DIMENSION",
    "ARC_DIMENSION",
    "LARGE_RADIAL_DIMENSION",
    "LEADER",
    "MULTILEADER",
    "MLEADER",
    "TOLERANCE",
    "POINT",
    "SOLID",
    "TRACE",
    "3DFACE",
    "3DSOLID",
    "BODY",
    "REGION",
    "SURFACE",
    "PLANESURFACE",
    "IMAGE",
    "WIPEOUT",
    "VIEWPORT",
    "OLE2FRAME",
    "OLEFRAME",
    "ACAD_TABLE",
    "LIGHT",
    "SHAPE",
    "UNDERLAY",
    "PDFUNDERLAY",
    "DWFUNDERLAY",
    "DGNUNDERLAY",
    "SUN",
];

/// An error in `file` at `line`.
fn error(file: &str, line: usize, message: String) -> ReadError {
    InputError::new(file, Some(line), None, message).into()
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

/// One entity: its kind (`LINE`), the line of its `0 LINE`, its groups after that, and the
/// entities that belong to it (a POLYLINE's VERTEX entities, an INSERT's ATTRIBs).
#[derive(Debug, Clone)]
pub(crate) struct Entity<'a> {
    kind: &'a str,
    line: usize,
    groups: Vec<Group<'a>>,
    children: Vec<Entity<'a>>,
}

impl<'a> Entity<'a> {
    /// The groups before the extended data (1001).
    fn body(&self) -> &[Group<'a>] {
        let end = self
            .groups
            .iter()
            .position(|g| g.code >= 1000)
            .unwrap_or(self.groups.len());
        &self.groups[..end]
    }

    /// The first group with `code`.
    fn first(&self, code: u16) -> Option<Group<'a>> {
        self.body().iter().find(|g| g.code == code).copied()
    }

    /// The trimmed text of the first group with `code`.
    fn text(&self, code: u16) -> Option<&'a str> {
        self.first(code).map(|g| g.value.trim())
    }

    /// The number of `code`, or `default` when absent.
    fn real_or(&self, file: &str, code: u16, default: f64, what: &str) -> Result<f64, ReadError> {
        self.first(code).map_or(Ok(default), |g| {
            real(file, g, &format!("{}: {what}", self.kind))
        })
    }

    /// The number of `code`, required.
    fn required(&self, file: &str, code: u16, what: &str) -> Result<f64, ReadError> {
        let g = self.first(code).ok_or_else(|| {
            error(
                file,
                self.line,
                format!("the {} has no {what} (group code {code})", self.kind),
            )
        })?;
        real(file, g, &format!("{}: {what}", self.kind))
    }

    /// The point of the codes `code`, `code + 10`, `code + 20`, each 0 when absent unless
    /// the whole point is absent (then `default`).
    fn point(&self, file: &str, code: u16, default: [f64; 3]) -> Result<[f64; 3], ReadError> {
        if [code, code + 10, code + 20]
            .iter()
            .all(|&c| self.first(c).is_none())
        {
            return Ok(default);
        }
        let mut p = [0.0; 3];
        for (axis, c) in [code, code + 10, code + 20].into_iter().enumerate() {
            p[axis] = self.real_or(file, c, 0.0, ["x", "y", "z"][axis])?;
        }
        Ok(p)
    }

    /// The point of `code`, `code + 10` (both required) and `code + 20` (0 when absent).
    fn required_point(&self, file: &str, code: u16, what: &str) -> Result<[f64; 3], ReadError> {
        let x = self.required(file, code, &format!("{what} x"))?;
        let y = self.required(file, code + 10, &format!("{what} y"))?;
        let z = self.real_or(file, code + 20, 0.0, &format!("{what} z"))?;
        Ok([x, y, z])
    }

    /// The integer of `code`, or `default` when absent.
    fn int_or(&self, file: &str, code: u16, default: i64) -> Result<i64, ReadError> {
        match self.first(code) {
            None => Ok(default),
            Some(g) => g.value.trim().parse::<i64>().map_err(|_| {
                error(
                    file,
                    g.line,
                    format!(
                        "{}: group code {code} = `{}` is not an integer",
                        self.kind,
                        g.value.trim()
                    ),
                )
            }),
        }
    }
}

/// The entities of a run of groups (a section's or a block's), each from its `0 KIND` to the
/// next code 0; VERTEX entities (and their SEQEND) belong to the POLYLINE before them, ATTRIB
/// entities (and their SEQEND) to the INSERT before them.
fn split_entities<'a>(groups: &[Group<'a>]) -> Vec<Entity<'a>> {
    let mut out: Vec<Entity<'a>> = Vec::new();
    let mut open = false;
    for g in groups {
        if g.code == 0 {
            let kind = g.value.trim();
            let entity = Entity {
                kind,
                line: g.line,
                groups: Vec::new(),
                children: Vec::new(),
            };
            let owner = out.last().map(|e| e.kind);
            let belongs = open
                && matches!(
                    (owner, kind),
                    (Some("POLYLINE"), "VERTEX" | "SEQEND") | (Some("INSERT"), "ATTRIB" | "SEQEND")
                );
            if belongs {
                if let Some(last) = out.last_mut() {
                    last.children.push(entity);
                }
                open = kind != "SEQEND";
            } else {
                open = kind == "POLYLINE" || kind == "INSERT";
                out.push(entity);
            }
        } else if let Some(last) = out.last_mut() {
            match last.children.last_mut() {
                Some(child) if open || child.kind != "SEQEND" => child.groups.push(*g),
                Some(_) => {}
                None => last.groups.push(*g),
            }
        }
    }
    out
}

/// The sections of a file by name: the groups between `0 SECTION`, `2 NAME` and `0 ENDSEC`,
/// with the line of the last `0 ENDSEC`. A name that comes back (a file written by joining
/// several drawings: ezdxf's `recover01.dxf` has 397 ENTITIES sections) is one section of
/// all its parts in order, with a warning: nothing in a later part is dropped.
fn sections<'a>(
    file: &str,
    groups: &[Group<'a>],
    report: &mut ImportReport,
) -> Result<HashMap<&'a str, (Vec<Group<'a>>, usize)>, ReadError> {
    let mut out: HashMap<&'a str, (Vec<Group<'a>>, usize)> = HashMap::new();
    // Each repeated name with its number of parts and the line of its first part.
    let mut parts: Vec<(&'a str, usize, usize)> = Vec::new();
    let mut k = 0;
    // A fragment that starts at `2 ENTITIES` (without `0 SECTION`), as hand-written files do.
    let fragment = groups
        .first()
        .is_some_and(|g| g.code == 2 && g.value.trim() == "ENTITIES");
    if fragment {
        report.warn("the file starts at `2 ENTITIES` without `0 SECTION` before it: read as the ENTITIES section");
    }
    while k < groups.len() {
        let starts = (fragment && k == 0)
            || (groups[k].code == 0
                && groups[k].value.trim() == "SECTION"
                && groups.get(k + 1).is_some_and(|g| g.code == 2));
        if !starts {
            k += 1;
            continue;
        }
        let name_at = if fragment && k == 0 { 0 } else { k + 1 };
        let name = groups[name_at].value.trim();
        let body = name_at + 1;
        let end = groups[body..]
            .iter()
            .position(|g| g.code == 0 && g.value.trim() == "ENDSEC")
            .map(|e| body + e)
            .ok_or_else(|| {
                InputError::new(
                    file,
                    None,
                    None,
                    format!("the {name} section has no end (`0 ENDSEC`): the file is cut short"),
                )
            })?;
        let section = out.entry(name).or_default();
        section.0.extend_from_slice(&groups[body..end]);
        section.1 = groups[end].line;
        match parts.iter_mut().find(|p| p.0 == name) {
            Some(p) => p.1 += 1,
            None => parts.push((name, 1, groups[name_at].line)),
        }
        k = end + 1;
    }
    for (name, count, line) in parts.into_iter().filter(|p| p.1 > 1) {
        report.warn(format!(
            "the file has {count} {name} sections (the first at line {line}): read as one, \
             their content in order"
        ));
    }
    Ok(out)
}

/// A block of the BLOCKS section.
struct Block<'a> {
    /// The base point (10/20/30), subtracted from its entities when inserted.
    base: [f64; 3],
    entities: Vec<Entity<'a>>,
}

/// The blocks of the BLOCKS section by upper-case name.
fn blocks<'a>(file: &str, groups: &[Group<'a>]) -> Result<HashMap<String, Block<'a>>, ReadError> {
    let mut out = HashMap::new();
    let all = split_entities(groups);
    let mut k = 0;
    while k < all.len() {
        if all[k].kind != "BLOCK" {
            k += 1;
            continue;
        }
        let head = &all[k];
        let end = all[k + 1..]
            .iter()
            .position(|e| e.kind == "ENDBLK")
            .map_or(all.len(), |e| k + 1 + e);
        let name = head.text(2).unwrap_or("");
        let base = head.point(file, 10, [0.0; 3])?;
        out.entry(name.to_uppercase()).or_insert(Block {
            base,
            entities: all[k + 1..end].to_vec(),
        });
        k = end + 1;
    }
    Ok(out)
}

/// A layer of the LAYER table: whether it is off (negative colour) or frozen (flag 1).
#[derive(Clone, Copy, Default)]
struct Layer {
    off: bool,
    frozen: bool,
}

/// The layers of the TABLES section by upper-case name.
fn layers(file: &str, groups: &[Group<'_>]) -> Result<HashMap<String, Layer>, ReadError> {
    let mut out = HashMap::new();
    for e in split_entities(groups).iter().filter(|e| e.kind == "LAYER") {
        let Some(name) = e.text(2) else { continue };
        let colour = e.int_or(file, 62, 7)?;
        let flags = e.int_or(file, 70, 0)?;
        out.insert(
            name.to_uppercase(),
            Layer {
                off: colour < 0,
                frozen: flags & 1 != 0,
            },
        );
    }
    Ok(out)
}

/// The import of one file in progress.
struct Drawer<'a, 'o> {
    file: &'o str,
    options: &'o ImportOptions,
    limits: &'o Limits,
    layers: HashMap<String, Layer>,
    blocks: HashMap<String, Block<'a>>,
    /// The blocks inserted at least once (upper-case names).
    inserted: std::collections::HashSet<String>,
    /// The blocks being inserted, outermost first (the recursion guard).
    stack: Vec<String>,
    /// The degree of a spline-fit POLYLINE without its own curve type: 2 when the header's
    /// `$SPLINETYPE` is 5, 3 otherwise.
    spline_degree: usize,
    models: Vec<Model>,
    report: ImportReport,
    /// The entities drawn so far (INSERTs expanded) and the control points of every curve.
    visited: u64,
    points: u64,
}

impl Drawer<'_, '_> {
    fn layer(&self, name: &str) -> Layer {
        self.layers
            .get(&name.to_uppercase())
            .copied()
            .unwrap_or_default()
    }

    /// Draws `e` through `map` (the INSERTs it is drawn through; identity in model space), its
    /// layer `0` read as `inherited` inside a block.
    fn draw(
        &mut self,
        e: &Entity<'_>,
        map: &Affine,
        inherited: Option<&str>,
    ) -> Result<(), ReadError> {
        let file = self.file;
        self.visited += 1;
        if self.visited > self.limits.max_control_points {
            return Err(error(
                file,
                e.line,
                format!(
                    "the drawing's INSERTs expand to more than {} entities (the limit of control points; raise it with --max-control-points or NEUTROSPLINE_MAX_CONTROL_POINTS)",
                    self.limits.max_control_points
                ),
            ));
        }
        let kind = e.kind;
        let own = e.text(8).unwrap_or("0");
        let layer_name = match inherited {
            Some(outer) if own == "0" => outer,
            _ => own,
        };
        let layer = self.layer(layer_name);
        if layer.frozen || (layer.off && kind != "INSERT") {
            self.report.skip(kind, SkipReason::Hidden);
            return Ok(());
        }
        let drawn = match kind {
            "INSERT" => return self.insert(e, map, layer_name),
            "SPLINE" | "LINE" | "ARC" | "CIRCLE" | "ELLIPSE" | "LWPOLYLINE" | "POLYLINE"
                if !self.options.wants(kind) =>
            {
                self.report.skip(kind, SkipReason::Excluded);
                return Ok(());
            }
            "SPLINE" => {
                let s = spline::collect(file, e.line, &e.groups)?;
                match spline::model(file, &s, map, self.options.defaults, self.limits)? {
                    Some(model) => self.push(kind, e.line, model)?,
                    None => self.report.skip(kind, SkipReason::Unsupported),
                }
                return Ok(());
            }
            "LINE" => entities::line(file, e)?,
            "ARC" => entities::arc(file, e)?,
            "CIRCLE" => entities::circle(file, e)?,
            "ELLIPSE" => entities::ellipse(file, e)?,
            "LWPOLYLINE" => entities::lwpolyline(file, e)?,
            "POLYLINE" => entities::polyline(file, e, self.spline_degree)?,
            _ if NOT_CURVES.contains(&kind) => {
                self.report.skip(kind, SkipReason::NotACurve);
                return Ok(());
            }
            _ => {
                self.report.skip(kind, SkipReason::Unsupported);
                return Ok(());
            }
        };
        let defaults = self.options.defaults;
        let shape = match drawn {
            Drawn::Empty => {
                self.report.skip(kind, SkipReason::Empty);
                return Ok(());
            }
            Drawn::Unsupported => {
                self.report.skip(kind, SkipReason::Unsupported);
                return Ok(());
            }
            Drawn::Pieces(pieces, local) => curve_of(&pieces, &local.then(map), defaults),
            Drawn::Spline {
                points,
                knots,
                degree,
                map: local,
            } => spline_of(&points, knots, degree, &local.then(map), defaults),
        }
        .map_err(|m| error(file, e.line, format!("{kind}: {m}")))?;
        self.push(kind, e.line, Model::new(shape))
    }

    /// Adds the model of an entity of `kind` at `line`, within the limits.
    fn push(&mut self, kind: &str, line: usize, model: Model) -> Result<(), ReadError> {
        let count = model.shape().control_count() as u64;
        self.points += count;
        if count > self.limits.max_control_points || self.points > self.limits.max_control_points {
            return Err(error(
                self.file,
                line,
                self.limits.too_many_control_points(),
            ));
        }
        self.models.push(model);
        self.report.imported(kind);
        Ok(())
    }

    /// Draws the block an INSERT names, for each copy of its array.
    fn insert(&mut self, e: &Entity<'_>, map: &Affine, layer: &str) -> Result<(), ReadError> {
        let file = self.file;
        for attribute in e.children.iter().filter(|c| c.kind == "ATTRIB") {
            self.report.skip(attribute.kind, SkipReason::NotACurve);
        }
        let name = e.text(2).ok_or_else(|| {
            error(
                file,
                e.line,
                "the INSERT has no block name (group code 2)".to_owned(),
            )
        })?;
        let key = name.to_uppercase();
        if !self.blocks.contains_key(&key) {
            return Err(error(
                file,
                e.line,
                format!(
                    "the INSERT draws the block `{name}`, which the BLOCKS section does not define"
                ),
            ));
        }
        if self.stack.contains(&key) {
            return Err(error(
                file,
                e.line,
                format!(
                    "the block `{name}` inserts itself (through {})",
                    self.stack.join(" > ")
                ),
            ));
        }
        let point = e.point(file, 10, [0.0; 3])?;
        let scale = [
            e.real_or(file, 41, 1.0, "x scale")?,
            e.real_or(file, 42, 1.0, "y scale")?,
            e.real_or(file, 43, 1.0, "z scale")?,
        ];
        let rotation = e.real_or(file, 50, 0.0, "rotation")?;
        let columns = e.int_or(file, 70, 1)?;
        let rows = e.int_or(file, 71, 1)?;
        if columns < 0 || rows < 0 {
            return Err(error(file, e.line, format!("the INSERT's column and row counts (group codes 70, 71) = {columns}, {rows} are negative")));
        }
        let spacing = [
            e.real_or(file, 44, 0.0, "column spacing")?,
            e.real_or(file, 45, 0.0, "row spacing")?,
        ];
        let object = ocs(e.point(file, 210, [0.0, 0.0, 1.0])?)
            .map_err(|m| error(file, e.line, format!("INSERT: {m}")))?;
        let base = self.blocks[&key].base;
        let (s, c) = sin_cos_degrees(rotation);
        let rotate = |v: [f64; 2]| [c * v[0] - s * v[1], s * v[0] + c * v[1]];
        self.inserted.insert(key.clone());
        self.stack.push(key.clone());
        let entities = self.blocks[&key].entities.clone();
        for row in 0..rows.max(1) {
            for column in 0..columns.max(1) {
                let offset = rotate([column as f64 * spacing[0], row as f64 * spacing[1]]);
                // p -> R S (p - base) + point + offset, then the INSERT's OCS, then `map`.
                let placed = Affine::from_columns(
                    [c * scale[0], s * scale[0], 0.0],
                    [-s * scale[1], c * scale[1], 0.0],
                    [0.0, 0.0, scale[2]],
                    [0.0; 3],
                );
                let moved = placed.apply([-base[0], -base[1], -base[2]]);
                let local = Affine {
                    linear: placed.linear,
                    offset: [
                        moved[0] + point[0] + offset[0],
                        moved[1] + point[1] + offset[1],
                        moved[2] + point[2],
                    ],
                };
                let whole = local.then(&object).then(map);
                for inner in &entities {
                    self.draw(inner, &whole, Some(layer))?;
                }
            }
        }
        self.stack.pop();
        Ok(())
    }
}

/// The curves of a DXF file held in memory (text in UTF-8 or the code page of its
/// `$DWGCODEPAGE`, or binary DXF): one model per curve entity drawn in model space, in the
/// order of the ENTITIES section (an INSERT's in the order of its block), with the report of
/// every entity met. `file` names it in messages; `options.defaults` are the degrees of every
/// control point (but a SPLINE's with `NEUTROSPLINE` extended data), `options.entities` the
/// curve kinds to import (the others recorded as excluded; INSERTs are always followed, the
/// filter applying inside them).
///
/// Every curve is exact: a SPLINE as written; a LINE a degree-1 Bézier curve; an ARC, CIRCLE,
/// ELLIPSE, and a polyline segment of bulge b (included angle 4 atan b) rational quadratic
/// pieces of at most 90° (the piece from angle a to b of the unit circle has the control
/// points (cos a, sin a), (cos m, sin m) / cos h, (cos b, sin b), m = (a + b) / 2,
/// h = (b - a) / 2, weights 1, cos h, 1, mapped onto the circle or ellipse); a polyline's
/// pieces joined into one B-spline (NURBS with an arc) whose piece k spans the knots
/// \[k, k + 1\]; a spline-fit POLYLINE the uniform B-spline of its frame. Entities in an
/// object coordinate system (ARC, CIRCLE, LWPOLYLINE, 2-D POLYLINE, INSERT) are mapped to the
/// world by the Arbitrary Axis Algorithm of their extrusion direction; an INSERT maps its
/// block by `ocs ∘ translate(point + array offset) ∘ rotate ∘ scale ∘ translate(-base)`.
/// Layers off or frozen hide their entities; paper space, blocks never inserted, entities
/// that are not curves or not read exactly are recorded in the report, never dropped
/// silently.
///
/// # Errors
/// [`ReadError::Input`] naming the file and line: groups that do not parse or content after
/// `0 EOF`, no ENTITIES section or a section cut short, an entity without a required group
/// (a LINE's end point, a CIRCLE's radius) or with a number that does not parse, a SPLINE
/// whose counts do not match its knots or control points or whose extended data breaks its
/// layout, an INSERT of an undefined block or of a block that inserts itself, more control
/// points than `limits` allow, and a file with no curve to import (naming what it held).
pub fn parse_dxf(
    file: &str,
    bytes: &[u8],
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let mut report = ImportReport::default();
    let text;
    let binary: Vec<(u16, String)>;
    let groups: Vec<Group<'_>> = if bytes.starts_with(BINARY_SENTINEL) {
        let (read, warning) =
            groups::binary_groups(bytes).map_err(|(line, message)| error(file, line, message))?;
        binary = read;
        report.warnings.extend(warning);
        binary
            .iter()
            .enumerate()
            .map(|(k, (code, value))| Group {
                code: *code,
                value,
                line: 2 * k + 1,
            })
            .collect()
    } else {
        let (decoded, warning) = groups::decode_text(bytes);
        text = decoded;
        report.warnings.extend(warning);
        let (read, warning) =
            groups(&text).map_err(|(line, message)| error(file, line, message))?;
        report.warnings.extend(warning);
        read
    };
    let sections = sections(file, &groups, &mut report)?;
    let Some((entities, end_line)) = sections.get("ENTITIES") else {
        return Err(InputError::new(
            file,
            None,
            None,
            "the file has no ENTITIES section (a DXF file holds its curves there)".to_owned(),
        )
        .into());
    };
    let end_line = *end_line;
    let header = sections.get("HEADER").map_or(&[][..], |s| &s.0[..]);
    let spline_degree = header
        .windows(2)
        .find(|w| w[0].code == 9 && w[0].value.trim() == "$SPLINETYPE")
        .map_or(3, |w| if w[1].value.trim() == "5" { 2 } else { 3 });
    let mut drawer = Drawer {
        file,
        options,
        limits,
        layers: layers(file, sections.get("TABLES").map_or(&[][..], |s| &s.0[..]))?,
        blocks: blocks(file, sections.get("BLOCKS").map_or(&[][..], |s| &s.0[..]))?,
        inserted: Default::default(),
        stack: Vec::new(),
        spline_degree,
        models: Vec::new(),
        report,
        visited: 0,
        points: 0,
    };
    let (paper, model): (Vec<Entity<'_>>, Vec<Entity<'_>>) = split_entities(entities)
        .into_iter()
        .filter(|e| e.kind != "SEQEND")
        .partition(|e| e.text(67) == Some("1"));
    for e in &model {
        drawer.draw(e, &Affine::IDENTITY, None)?;
    }
    if drawer.models.is_empty() && !paper.is_empty() {
        drawer.report.warn(format!(
            "model space has no curve: the {} entities of paper space (group code 67 = 1) are read instead, in the sheet's coordinates",
            paper.len()
        ));
        for e in &paper {
            drawer.draw(e, &Affine::IDENTITY, None)?;
        }
    } else {
        for e in &paper {
            drawer
                .report
                .skip(&format!("{} (paper space)", e.kind), SkipReason::NotDrawn);
        }
    }
    let mut never: Vec<(&String, &Block<'_>)> = drawer
        .blocks
        .iter()
        .filter(|(key, _)| !drawer.inserted.contains(*key))
        .collect();
    never.sort_by_key(|(key, _)| *key);
    let mut unused = Vec::new();
    for (_, block) in never {
        for e in &block.entities {
            unused.push(e.kind);
        }
    }
    for kind in unused {
        drawer.report.skip(kind, SkipReason::NotDrawn);
    }
    let Drawer { models, report, .. } = drawer;
    if models.is_empty() {
        let summary = report.summary();
        let held = match summary.strip_prefix("imported no curve; ") {
            Some(rest) => rest.to_owned(),
            None => "it is empty".to_owned(),
        };
        return Err(error(
            file,
            end_line,
            format!("the file has no curve to import ({held})"),
        ));
    }
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
