//! STEP (ISO 10303-21 clear text) export, schema AP214 `AUTOMOTIVE_DESIGN`: the model's curve
//! or surface as one exact B-spline entity, with the product structure a CAD reader needs to
//! transfer it as a shape.
//!
//! # The file
//!
//! - `HEADER`: `FILE_DESCRIPTION` names the kind and the membership rule and says where the
//!   degrees are; `FILE_NAME` has the model's name and the fixed time stamp
//!   [`TIME_STAMP`] (the Unix epoch), so that the same model always gives the same bytes;
//!   `FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'))`.
//! - `DATA`: one `PRODUCT` named after the model (its id and name the model's name, or the
//!   kind when it has none; its description the model's description), its
//!   `PRODUCT_DEFINITION` and `PRODUCT_DEFINITION_SHAPE`, and a `SHAPE_DEFINITION_REPRESENTATION`
//!   tying that to the shape's representation, in a 3-D `GEOMETRIC_REPRESENTATION_CONTEXT`
//!   whose length unit is the millimetre (a model unit is written as 1 mm: the numbers are the
//!   model's, unscaled) with an uncertainty of [`UNCERTAINTY`].
//! - A curve: `B_SPLINE_CURVE_WITH_KNOTS` in a `GEOMETRIC_CURVE_SET` in a
//!   `GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION`. A plane curve is written in the
//!   plane z = 0.
//! - A surface: `B_SPLINE_SURFACE_WITH_KNOTS` as the face of an `ADVANCED_FACE` in an
//!   `OPEN_SHELL` in a `SHELL_BASED_SURFACE_MODEL` in a
//!   `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`. The face is bounded by its four boundary curves
//!   `S(u, v0)`, `S(u1, v)`, `S(u, v1)`, `S(u0, v)` (counter-clockwise in the parameter
//!   plane, so the face's normal is `S_u x S_v`), each an exact B-spline `EDGE_CURVE`: with
//!   clamped knots at that end, the edge row or column of the grid itself (its control points
//!   are the grid's entities), otherwise the surface's iso-parameter curve
//!   ([`Surface::iso_curve`]). A boundary collapsed to a point (all its control points equal)
//!   is left out of the loop.
//!
//! # The geometry
//!
//! A curve of degree p with control points `P_0 .. P_n`, weights `w_k` (1 without) and knots
//! `t_0 <= .. <= t_(n+p+1)` is `C(t) = sum_k N_(k,p)(t) w_k P_k / sum_k N_(k,p)(t) w_k`;
//! STEP writes the knots as the distinct values with their multiplicities. A Bézier curve of
//! degree p is the B-spline over p + 1 zeros and p + 1 ones. A surface's control point list
//! is STEP's `control_points_list[i][j]`, i along u (the outer list, the model's rows) and j
//! along v (the inner lists, its columns): `S(u, v) = sum_i sum_j N_i(u) N_j(v) w_ij P_ij /
//! sum_i sum_j N_i(u) N_j(v) w_ij`, the model's own formula. A rational curve or surface is
//! the complex entity of ISO 10303-21 (its partial entities in alphabetical order), with
//! `RATIONAL_B_SPLINE_CURVE((w..))` or `RATIONAL_B_SPLINE_SURFACE(((w..)..))`. The curve form
//! and the knot type are `.UNSPECIFIED.`, the self-intersection `.U.` (unknown), and
//! `closed_curve` (`u_closed`, `v_closed`) always `.F.`: ISO 10303-42 makes these flags
//! information only, but OpenCASCADE reads a B-spline flagged closed (`.T.` or `.U.`) as a
//! periodic one with other control points (the nine of the example circle become eight), and
//! `.F.` keeps every reader on the model's own control points, knots and weights.
//!
//! Every real is the shortest decimal that reads back to the same `f64`, in STEP's real
//! syntax (a decimal point always, an upper-case exponent): `1.`, `0.5`, `-2.5E-7`.
//!
//! # The degrees
//!
//! Each control point's `CARTESIAN_POINT` is named `NAME T=t I=i F=f`: the point's name in the
//! model (or `P` and its index from 0, row by row for a surface, when it has none), then its
//! truth, indeterminacy and falsity as shortest round-trip decimals. A CAD program shows the
//! name with the point; a script reads the last three space-separated fields. Strings are
//! encoded as ISO 10303-21 says: `'` and `\` doubled, a character outside printable ASCII as
//! `\X2\hhhh\X0\` (UTF-16 code units in hexadecimal).
//!
//! Not carried: the fuzzy spreads of the positions.

use std::fmt::Write as _;

use neutrospline::{AnyCurve, ControlPolygon, Direction, EvaluateSurface, KnotVector, Surface};
use neutrospline_io::{push_number, Model, Shape};

use super::ExportError;

/// The time stamp of `FILE_NAME`: fixed (the Unix epoch), so that the output is the same byte
/// for byte on every export of the same model.
pub(crate) const TIME_STAMP: &str = "1970-01-01T00:00:00";

/// The `distance_accuracy_value` of the representation context, in model units.
pub(crate) const UNCERTAINTY: f64 = 1e-7;

/// A STEP real: the shortest decimal that reads back to `v`, with a decimal point always and
/// an upper-case exponent (`1.`, `0.5`, `-2.5E-7`, `1.E20`).
fn real(v: f64) -> String {
    // `{:?}` writes Rust's shortest round-trip form: `1.0`, `0.5`, `1e-7`, `1.5e20`.
    let text = format!("{v:?}");
    let (mantissa, exponent) = match text.split_once('e') {
        Some((m, e)) => (m, Some(e)),
        None => (text.as_str(), None),
    };
    let mut out = String::with_capacity(text.len() + 2);
    match mantissa.strip_suffix(".0") {
        Some(whole) => {
            out.push_str(whole);
            out.push('.');
        }
        None if mantissa.contains('.') => out.push_str(mantissa),
        None => {
            out.push_str(mantissa);
            out.push('.');
        }
    }
    if let Some(e) = exponent {
        out.push('E');
        out.push_str(e);
    }
    out
}

/// A number as the model's files write it (shortest round-trip, no exponent), for names.
fn plain(v: f64) -> String {
    let mut digits = Vec::with_capacity(24);
    push_number(&mut digits, v);
    String::from_utf8_lossy(&digits).into_owned()
}

/// A STEP string literal: quoted, `'` and `\` doubled, characters outside printable ASCII as
/// `\X2\hhhh\X0\` (UTF-16 code units).
fn string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('\'');
    let mut wide = String::new();
    let flush = |out: &mut String, wide: &mut String| {
        if !wide.is_empty() {
            out.push_str("\\X2\\");
            out.push_str(wide);
            out.push_str("\\X0\\");
            wide.clear();
        }
    };
    for c in text.chars() {
        if (' '..='~').contains(&c) {
            flush(&mut out, &mut wide);
            match c {
                '\'' => out.push_str("''"),
                '\\' => out.push_str("\\\\"),
                _ => out.push(c),
            }
        } else {
            let mut units = [0u16; 2];
            for unit in c.encode_utf16(&mut units) {
                let _ = write!(wide, "{unit:04X}");
            }
        }
    }
    flush(&mut out, &mut wide);
    out.push('\'');
    out
}

/// `(a,b,c)` of the items.
fn list<T>(items: impl IntoIterator<Item = T>, item: impl Fn(T) -> String) -> String {
    let parts: Vec<String> = items.into_iter().map(item).collect();
    format!("({})", parts.join(","))
}

fn reference(id: usize) -> String {
    format!("#{id}")
}

fn logical(value: bool) -> &'static str {
    if value {
        ".T."
    } else {
        ".F."
    }
}

/// The distinct knots and their multiplicities, as STEP lists them.
fn distinct_knots(knots: &[f64]) -> (Vec<usize>, Vec<f64>) {
    let mut multiplicities = Vec::new();
    let mut values: Vec<f64> = Vec::new();
    for &k in knots {
        if values.last() == Some(&k) {
            if let Some(m) = multiplicities.last_mut() {
                *m += 1;
            }
        } else {
            values.push(k);
            multiplicities.push(1);
        }
    }
    (multiplicities, values)
}

/// The `DATA` section being written: one instance per line, numbered from 1.
struct Data {
    out: String,
    next: usize,
}

impl Data {
    fn new() -> Data {
        Data {
            out: String::with_capacity(16 * 1024),
            next: 1,
        }
    }

    /// Writes `#n=BODY;` and returns n.
    fn add(&mut self, body: impl AsRef<str>) -> usize {
        let id = self.next;
        self.next += 1;
        let _ = writeln!(self.out, "#{id}={};", body.as_ref());
        id
    }

    /// A `CARTESIAN_POINT` in space.
    fn point(&mut self, name: &str, p: [f64; 3]) -> usize {
        self.add(format!(
            "CARTESIAN_POINT({},{})",
            string(name),
            list(p, real)
        ))
    }
}

/// A B-spline curve to write: degree, its control points' entities, weights, knots.
struct CurveData<'a> {
    degree: usize,
    points: Vec<usize>,
    weights: Option<Vec<f64>>,
    knots: &'a [f64],
}

/// Writes a `B_SPLINE_CURVE_WITH_KNOTS` (the rational complex entity with weights).
fn curve_entity(data: &mut Data, curve: &CurveData<'_>) -> usize {
    let (multiplicities, knots) = distinct_knots(curve.knots);
    let points = list(curve.points.iter().copied(), reference);
    let common = format!("{},{points},.UNSPECIFIED.,.F.,.U.", curve.degree);
    let with_knots = format!(
        "{},{},.UNSPECIFIED.",
        list(multiplicities, |m| m.to_string()),
        list(knots, real)
    );
    match &curve.weights {
        None => data.add(format!(
            "B_SPLINE_CURVE_WITH_KNOTS('',{common},{with_knots})"
        )),
        Some(w) => data.add(format!(
            "(BOUNDED_CURVE()B_SPLINE_CURVE({common})B_SPLINE_CURVE_WITH_KNOTS({with_knots})\
             CURVE()GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE({})\
             REPRESENTATION_ITEM(''))",
            list(w.iter().copied(), real)
        )),
    }
}

/// The name of control point `index`: `NAME T=t I=i F=f`.
fn point_label(model: &Model, index: usize, degrees: &neutrospline::Degrees) -> String {
    let name = model
        .point_names()
        .get(index)
        .and_then(|n| n.clone())
        .unwrap_or_else(|| format!("P{index}"));
    let [t, i, f] = degrees.to_array();
    format!("{name} T={} I={} F={}", plain(t), plain(i), plain(f))
}

/// A position with `z = 0` for a plane curve.
fn position<const D: usize>(p: &[f64; D]) -> [f64; 3] {
    let mut out = [0.0; 3];
    out[..D].copy_from_slice(p);
    out
}

/// The knots of a curve: its own, or a Bézier curve's clamped ones.
fn curve_knots<const D: usize>(curve: &AnyCurve<D>) -> KnotVector {
    match curve {
        AnyCurve::Bezier(c) => c.to_bspline().knots().clone(),
        AnyCurve::BSpline(c) => c.knots().clone(),
        AnyCurve::Nurbs(c) => c.knots().clone(),
    }
}

/// The curve's entities: the control points (named with their degrees) and the B-spline.
fn write_curve<const D: usize>(data: &mut Data, model: &Model, curve: &AnyCurve<D>) -> usize {
    let control = curve.control_points();
    let points: Vec<usize> = control
        .iter()
        .enumerate()
        .map(|(k, p)| data.point(&point_label(model, k, &p.degrees), position(&p.position)))
        .collect();
    let knots = curve_knots(curve);
    curve_entity(
        data,
        &CurveData {
            degree: curve.degree(),
            points,
            weights: curve.weights().map(<[f64]>::to_vec),
            knots: knots.knots(),
        },
    )
}

/// One boundary of a surface: fixed `u` or `v` at the start or the end of its domain.
#[derive(Clone, Copy)]
struct Side {
    fixed: Direction,
    at_end: bool,
}

/// Whether `knots` repeat their first (or last) value degree + 1 times.
fn clamped_at(knots: &KnotVector, at_end: bool) -> bool {
    let k = knots.knots();
    let p = knots.degree();
    if at_end {
        k[k.len() - 1 - p..].iter().all(|&x| x == k[k.len() - 1])
    } else {
        k[..=p].iter().all(|&x| x == k[0])
    }
}

/// The surface's entities: the grid, the surface, and the face bounded by its boundaries.
fn write_surface(
    data: &mut Data,
    model: &Model,
    surface: &Surface,
) -> Result<(usize, usize), ExportError> {
    let (rows, cols) = (surface.rows(), surface.cols());
    let control = surface.control_points();
    let grid: Vec<usize> = control
        .iter()
        .enumerate()
        .map(|(k, p)| data.point(&point_label(model, k, &p.degrees), p.position))
        .collect();
    let weights = surface.weights();
    let grid_list = list(0..rows, |i| {
        list(grid[i * cols..(i + 1) * cols].iter().copied(), reference)
    });
    let (mu, ku) = distinct_knots(surface.knots_u().knots());
    let (mv, kv) = distinct_knots(surface.knots_v().knots());
    let common = format!(
        "{},{},{grid_list},.UNSPECIFIED.,.F.,.F.,.U.",
        surface.degree_u(),
        surface.degree_v()
    );
    let with_knots = format!(
        "{},{},{},{},.UNSPECIFIED.",
        list(mu, |m| m.to_string()),
        list(mv, |m| m.to_string()),
        list(ku, real),
        list(kv, real)
    );
    let surface_id =
        match weights {
            None => data.add(format!(
                "B_SPLINE_SURFACE_WITH_KNOTS('',{common},{with_knots})"
            )),
            Some(w) => data.add(format!(
            "(BOUNDED_SURFACE()B_SPLINE_SURFACE({common})B_SPLINE_SURFACE_WITH_KNOTS({with_knots})\
             GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE({})\
             REPRESENTATION_ITEM('')SURFACE())",
            list(0..rows, |i| list(w[i * cols..(i + 1) * cols].iter().copied(), real))
        )),
        };

    // The corners (u0, v0), (u1, v0), (u1, v1), (u0, v1): the grid's corner points where the
    // knots of both directions are clamped there, else the surface's value.
    let [du, dv] = surface.domain();
    let corner =
        |data: &mut Data, i_end: bool, j_end: bool| -> Result<(usize, [f64; 3]), ExportError> {
            let i = if i_end { rows - 1 } else { 0 };
            let j = if j_end { cols - 1 } else { 0 };
            if clamped_at(surface.knots_u(), i_end) && clamped_at(surface.knots_v(), j_end) {
                let k = i * cols + j;
                return Ok((grid[k], control[k].position));
            }
            let u = if i_end { du.end } else { du.start };
            let v = if j_end { dv.end } else { dv.start };
            let p = surface.evaluate(u, v)?.position;
            Ok((data.point("", p), p))
        };
    let mut corners = Vec::with_capacity(4);
    for (i_end, j_end) in [(false, false), (true, false), (true, true), (false, true)] {
        let (point, p) = corner(data, i_end, j_end)?;
        corners.push((data.add(format!("VERTEX_POINT('',#{point})")), p));
    }

    // The loop: v = v0 forward, u = u1 forward, v = v1 backward, u = u0 backward.
    let sides = [
        (
            Side {
                fixed: Direction::V,
                at_end: false,
            },
            true,
            0,
            1,
        ),
        (
            Side {
                fixed: Direction::U,
                at_end: true,
            },
            true,
            1,
            2,
        ),
        (
            Side {
                fixed: Direction::V,
                at_end: true,
            },
            false,
            3,
            2,
        ),
        (
            Side {
                fixed: Direction::U,
                at_end: false,
            },
            false,
            0,
            3,
        ),
    ];
    let mut edges = Vec::with_capacity(4);
    let mut collapsed = Vec::with_capacity(4);
    for (side, forward, start, end) in sides {
        let (curve, positions) = boundary(data, surface, &grid, &control, side)?;
        let edge = data.add(format!(
            "EDGE_CURVE('',#{},#{},#{curve},.T.)",
            corners[start].0, corners[end].0
        ));
        let oriented = data.add(format!(
            "ORIENTED_EDGE('',*,*,#{edge},{})",
            logical(forward)
        ));
        collapsed.push(positions.windows(2).all(|w| w[0] == w[1]));
        edges.push(oriented);
    }
    let kept: Vec<usize> = if collapsed.iter().all(|&c| c) {
        edges
    } else {
        edges
            .into_iter()
            .zip(&collapsed)
            .filter(|(_, &c)| !c)
            .map(|(e, _)| e)
            .collect()
    };
    let edge_loop = data.add(format!("EDGE_LOOP('',{})", list(kept, reference)));
    let bound = data.add(format!("FACE_OUTER_BOUND('',#{edge_loop},.T.)"));
    let face = data.add(format!("ADVANCED_FACE('',(#{bound}),#{surface_id},.T.)"));
    let shell = data.add(format!("OPEN_SHELL('',(#{face}))"));
    let model_id = data.add(format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"));
    Ok((model_id, surface_id))
}

/// The boundary curve of `side` and its control points' positions: the grid's edge row or
/// column where the knots of the fixed direction are clamped at that end (`S(u0, v) = sum_j
/// N_j(v) w_0j P_0j / sum_j N_j(v) w_0j`, exactly), else the iso-parameter curve.
fn boundary(
    data: &mut Data,
    surface: &Surface,
    grid: &[usize],
    control: &[neutrospline::ControlPoint<3>],
    side: Side,
) -> Result<(usize, Vec<[f64; 3]>), ExportError> {
    let (rows, cols) = (surface.rows(), surface.cols());
    let (fixed_knots, along_knots) = match side.fixed {
        Direction::U => (surface.knots_u(), surface.knots_v()),
        Direction::V => (surface.knots_v(), surface.knots_u()),
    };
    if clamped_at(fixed_knots, side.at_end) {
        let indices: Vec<usize> = match side.fixed {
            Direction::U => {
                let i = if side.at_end { rows - 1 } else { 0 };
                (0..cols).map(|j| i * cols + j).collect()
            }
            Direction::V => {
                let j = if side.at_end { cols - 1 } else { 0 };
                (0..rows).map(|i| i * cols + j).collect()
            }
        };
        let positions: Vec<[f64; 3]> = indices.iter().map(|&k| control[k].position).collect();
        let curve = CurveData {
            degree: along_knots.degree(),
            points: indices.iter().map(|&k| grid[k]).collect(),
            weights: surface
                .weights()
                .map(|w| indices.iter().map(|&k| w[k]).collect()),
            knots: along_knots.knots(),
        };
        return Ok((curve_entity(data, &curve), positions));
    }
    let domain = fixed_knots.domain();
    let value = if side.at_end {
        domain.end
    } else {
        domain.start
    };
    let iso = surface.iso_curve(side.fixed, value)?;
    let positions: Vec<[f64; 3]> = iso.control_points().iter().map(|p| p.position).collect();
    let points = positions.iter().map(|&p| data.point("", p)).collect();
    let knots = curve_knots(&iso);
    let curve = CurveData {
        degree: iso.degree(),
        points,
        weights: iso.weights().map(<[f64]>::to_vec),
        knots: knots.knots(),
    };
    Ok((curve_entity(data, &curve), positions))
}

/// The model as a STEP file (ISO 10303-21, AP214): see the module's documentation.
///
/// # Errors
/// [`ExportError::Eval`] when a corner of a surface with unclamped knots cannot be evaluated
/// (a value that is not finite).
pub(super) fn document(model: &Model) -> Result<String, ExportError> {
    let kind = model.kind().name();
    let title = model.name().unwrap_or(kind).to_owned();
    let mut data = Data::new();
    let context = data.add("APPLICATION_CONTEXT('automotive_design')");
    data.add(format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{context})"
    ));
    let product_context = data.add(format!("PRODUCT_CONTEXT('',#{context},'mechanical')"));
    let product = data.add(format!(
        "PRODUCT({},{},{},(#{product_context}))",
        string(&title),
        string(&title),
        string(model.description().unwrap_or(""))
    ));
    data.add(format!(
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#{product}))"
    ));
    let formation = data.add(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
    let definition_context = data.add(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{context},'design')"
    ));
    let definition = data.add(format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{definition_context})"
    ));
    let shape = data.add(format!("PRODUCT_DEFINITION_SHAPE('','',#{definition})"));
    let length = data.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
    let angle = data.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
    let solid_angle = data.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
    let uncertainty = data.add(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE({}),#{length},'distance_accuracy_value',\
         'confusion accuracy')",
        real(UNCERTAINTY)
    ));
    let geometric_context = data.add(format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{uncertainty}))\
         GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid_angle}))\
         REPRESENTATION_CONTEXT('3D','3D'))"
    ));
    let representation = match model.shape() {
        Shape::Curve(c) => {
            let curve = neutrospline::on_dimension!(c, c => write_curve(&mut data, model, c));
            let set = data.add(format!("GEOMETRIC_CURVE_SET('',(#{curve}))"));
            data.add(format!(
                "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION({},(#{set}),#{geometric_context})",
                string(&title)
            ))
        }
        Shape::Surface(s) => {
            let (shell_model, _) = write_surface(&mut data, model, s)?;
            data.add(format!(
                "MANIFOLD_SURFACE_SHAPE_REPRESENTATION({},(#{shell_model}),#{geometric_context})",
                string(&title)
            ))
        }
    };
    data.add(format!(
        "SHAPE_DEFINITION_REPRESENTATION(#{shape},#{representation})"
    ));

    let version = env!("CARGO_PKG_VERSION");
    let mut out = String::with_capacity(data.out.len() + 1024);
    out.push_str("ISO-10303-21;\nHEADER;\n");
    let description = [
        format!("neutrospline {kind} model"),
        format!("membership {}", model.membership().name()),
        "degrees: each control point's CARTESIAN_POINT is named 'NAME T=truth I=indeterminacy F=falsity'"
            .to_owned(),
    ];
    let _ = writeln!(
        out,
        "FILE_DESCRIPTION({},'2;1');",
        list(description.iter(), |d| string(d))
    );
    let system = string(&format!("neutrospline {version}"));
    let _ = writeln!(
        out,
        "FILE_NAME({},'{TIME_STAMP}',(''),(''),{system},{system},'');",
        string(&title)
    );
    out.push_str("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n");
    out.push_str(&data.out);
    out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    Ok(out)
}
