//! STEP (ISO 10303-21 clear text) export, schema AP214 `AUTOMOTIVE_DESIGN`: the model's curve
//! or surface as one exact B-spline entity (or its exact pieces, see below), with the product
//! structure a CAD reader needs to transfer it as a shape. AP214 rather than AP242: it is the
//! schema OpenCASCADE writes by default and the one most CAD programs read.
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
//! - A spline with an interior knot of multiplicity degree + 1 (which ISO 10303-42 does not
//!   allow in one entity) is written as the exact pieces on either side of it
//!   ([`pieces`]): a curve as several curves of the `GEOMETRIC_CURVE_SET`, a surface as
//!   several faces of the shell.
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
//! name with the point; a script reads the last three space-separated fields. An
//! interval-valued or bipolar family names each channel instead: `NAME truth_lower=..
//! truth_upper=.. ...` (the header's `FILE_DESCRIPTION` lists them). Strings are
//! encoded as ISO 10303-21 says: `'` and `\` doubled, characters outside printable ASCII as
//! `\X2\hhhh\X0\` (`\X4\hhhhhhhh\X0\` beyond the Basic Multilingual Plane).
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

/// A STEP string literal (ISO 10303-21, 7.3.3): quoted, `'` and `\` doubled, a run of
/// characters outside printable ASCII as `\X2\hhhh..\X0\` (four hexadecimal digits each) or,
/// beyond the Basic Multilingual Plane, `\X4\hhhhhhhh..\X0\` (eight each).
fn string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('\'');
    // The hexadecimal digits per character of the run being written: 4 after `\X2\`, 8 after
    // `\X4\`, 0 in plain ASCII.
    let mut run = 0;
    for c in text.chars() {
        let width = match c {
            ' '..='~' => 0,
            '\u{0}'..='\u{ffff}' => 4,
            _ => 8,
        };
        if width != run {
            if run != 0 {
                out.push_str("\\X0\\");
            }
            match width {
                4 => out.push_str("\\X2\\"),
                8 => out.push_str("\\X4\\"),
                _ => {}
            }
            run = width;
        }
        match (width, c) {
            (0, '\'') => out.push_str("''"),
            (0, '\\') => out.push_str("\\\\"),
            (0, _) => out.push(c),
            _ => {
                let _ = write!(out, "{:0width$X}", u32::from(c));
            }
        }
    }
    if run != 0 {
        out.push_str("\\X0\\");
    }
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

/// The name of control point `index`: `NAME T=t I=i F=f`; for a family of two lanes
/// (`wide`: the channel values of every control point) `NAME truth_lower=.. truth_upper=..`,
/// each channel by its name.
fn point_label(
    model: &Model,
    index: usize,
    degrees: &neutrospline::Degrees,
    wide: Option<&[neutrospline::FamilyValues]>,
) -> String {
    let name = model
        .point_names()
        .get(index)
        .and_then(|n| n.clone())
        .unwrap_or_else(|| format!("P{index}"));
    if let Some(values) = wide {
        let mut label = name;
        for (channel, v) in model
            .membership()
            .channels()
            .iter()
            .zip(values[index].iter())
        {
            let _ = write!(label, " {channel}={}", plain(*v));
        }
        return label;
    }
    let [t, i, f] = degrees.to_array();
    format!("{name} T={} I={} F={}", plain(t), plain(i), plain(f))
}

/// The channel values of every control point of a family of two lanes; `None` for one lane.
fn wide_channels(model: &Model) -> Option<Vec<neutrospline::FamilyValues>> {
    (model.membership().lane_count() == 2).then(|| model.control_channels())
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

/// A part of a spline between interior knots of multiplicity degree + 1: its control points
/// `start..end` and its knots `t_start ..= t_(end+p)`.
#[derive(Debug, PartialEq)]
struct Piece {
    start: usize,
    end: usize,
    knots: Vec<f64>,
}

/// The pieces of a spline: one, unless an interior knot appears degree + 1 times. There the
/// spline is two independent splines (the basis functions on either side share no control
/// point; the curve may jump), which STEP cannot write as one entity (ISO 10303-42 allows an
/// interior multiplicity of at most the degree, and OpenCASCADE refuses more). A run of
/// degree + 1 knots starting at index s splits the control points at s: `P_0 .. P_(s-1)` over
/// `t_0 .. t_(s+p)` and `P_s ..` over `t_s ..`, each the same curve on its part of the domain,
/// exactly. A piece with at most `degree` control points lies outside the domain (its run is
/// the domain's end) and is left out.
fn pieces(knots: &KnotVector) -> Vec<Piece> {
    let k = knots.knots();
    let p = knots.degree();
    let n = knots.control_count();
    let mut splits = Vec::new();
    let mut run = 0;
    while run < k.len() {
        let len = k[run..].iter().take_while(|&&x| x == k[run]).count();
        if len == p + 1 && run > 0 && run + p < k.len() - 1 {
            splits.push(run);
        }
        run += len;
    }
    let starts = std::iter::once(0).chain(splits.iter().copied());
    let ends = splits.iter().copied().chain(std::iter::once(n));
    starts
        .zip(ends)
        .filter(|&(start, end)| end - start > p && k[start + p] < k[end])
        .map(|(start, end)| Piece {
            start,
            end,
            knots: k[start..=end + p].to_vec(),
        })
        .collect()
}

/// The curve's entities: the control points (named with their degrees) and the B-spline, one
/// per [`pieces`] (one for every curve whose interior knots are not degree + 1 times).
fn write_curve<const D: usize>(data: &mut Data, model: &Model, curve: &AnyCurve<D>) -> Vec<usize> {
    let control = curve.control_points();
    let knots = curve_knots(curve);
    let weights = curve.weights();
    let wide = wide_channels(model);
    pieces(&knots)
        .into_iter()
        .map(|piece| {
            let points: Vec<usize> = (piece.start..piece.end)
                .map(|k| {
                    let p = &control[k];
                    data.point(
                        &point_label(model, k, &p.degrees, wide.as_deref()),
                        position(&p.position),
                    )
                })
                .collect();
            curve_entity(
                data,
                &CurveData {
                    degree: curve.degree(),
                    points,
                    weights: weights.map(|w| w[piece.start..piece.end].to_vec()),
                    knots: &piece.knots,
                },
            )
        })
        .collect()
}

/// The surface's faces: one, or one per pair of [`pieces`] in u and v (each piece a surface
/// of its own, its control points named with their indices in the whole grid).
fn write_surfaces(
    data: &mut Data,
    model: &Model,
    surface: &Surface,
) -> Result<Vec<usize>, ExportError> {
    let (rows, cols) = (surface.rows(), surface.cols());
    let control = surface.control_points();
    let wide = wide_channels(model);
    let label = |k: usize| point_label(model, k, &control[k].degrees, wide.as_deref());
    let pieces_u = pieces(surface.knots_u());
    let pieces_v = pieces(surface.knots_v());
    if pieces_u.len() == 1 && pieces_v.len() == 1 {
        let labels: Vec<String> = (0..rows * cols).map(label).collect();
        return Ok(vec![write_surface(data, surface, &labels)?]);
    }
    let mut faces = Vec::new();
    for pu in &pieces_u {
        for pv in &pieces_v {
            let indices: Vec<usize> = (pu.start..pu.end)
                .flat_map(|i| (pv.start..pv.end).map(move |j| i * cols + j))
                .collect();
            let points = indices.iter().map(|&k| control[k]).collect();
            let knots = |piece: &Piece, degree: usize| {
                KnotVector::new(piece.knots.clone(), degree, piece.end - piece.start)
            };
            let (ku, kv) = match (knots(pu, surface.degree_u()), knots(pv, surface.degree_v())) {
                (Ok(ku), Ok(kv)) => (ku, kv),
                // A piece has more than `degree` control points, non-decreasing knots of
                // multiplicity at most degree + 1 and a non-empty domain (`pieces`).
                (Err(e), _) | (_, Err(e)) => unreachable!("a piece's knots are valid: {e}"),
            };
            let (r, c) = (pu.end - pu.start, pv.end - pv.start);
            let piece = match surface.weights() {
                None => Surface::bspline(r, c, points, ku, kv),
                Some(w) => Surface::nurbs(
                    r,
                    c,
                    points,
                    indices.iter().map(|&k| w[k]).collect(),
                    ku,
                    kv,
                ),
            }
            .unwrap_or_else(|e| unreachable!("a piece of a valid surface is valid: {e}"));
            let labels: Vec<String> = indices.iter().map(|&k| label(k)).collect();
            faces.push(write_surface(data, &piece, &labels)?);
        }
    }
    Ok(faces)
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

/// The surface's entities: the grid (its points named `labels`, row by row), the surface, and
/// the face bounded by its boundaries; returns the face.
fn write_surface(
    data: &mut Data,
    surface: &Surface,
    labels: &[String],
) -> Result<usize, ExportError> {
    let (rows, cols) = (surface.rows(), surface.cols());
    let control = surface.control_points();
    let grid: Vec<usize> = control
        .iter()
        .zip(labels)
        .map(|(p, label)| data.point(label, p.position))
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
    Ok(data.add(format!("ADVANCED_FACE('',(#{bound}),#{surface_id},.T.)")))
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
            let curves = neutrospline::on_dimension!(c, c => write_curve(&mut data, model, c));
            let set = data.add(format!(
                "GEOMETRIC_CURVE_SET('',{})",
                list(curves, reference)
            ));
            data.add(format!(
                "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION({},(#{set}),#{geometric_context})",
                string(&title)
            ))
        }
        Shape::Surface(s) => {
            let faces = write_surfaces(&mut data, model, s)?;
            let shell = data.add(format!("OPEN_SHELL('',{})", list(faces, reference)));
            let shell_model = data.add(format!("SHELL_BASED_SURFACE_MODEL('',(#{shell}))"));
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
    let degrees = if model.membership().lane_count() == 2 {
        let channels: Vec<String> = model
            .membership()
            .channels()
            .iter()
            .map(|c| format!("{c}={c}"))
            .collect();
        format!(
            "degrees: each control point's CARTESIAN_POINT is named 'NAME {}'",
            channels.join(" ")
        )
    } else {
        "degrees: each control point's CARTESIAN_POINT is named 'NAME T=truth I=indeterminacy F=falsity'"
            .to_owned()
    };
    let description = [
        format!("neutrospline {kind} model"),
        format!("membership {}", model.membership()),
        degrees,
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

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use neutrospline::{Bezier, ControlPoint, Degrees, Nurbs};
    use neutrospline_io::{load, ReadOptions};
    use proptest::prelude::*;

    use super::super::{export, ExportFormat, ExportOptions};
    use super::*;

    fn degrees(t: f64, i: f64, f: f64) -> Degrees {
        Degrees::new(t, i, f).unwrap()
    }

    /// The HEADER and the product structure every file starts with, up to `#14`.
    fn preamble(kind: &str, title: &str, description: &str) -> String {
        let version = env!("CARGO_PKG_VERSION");
        format!(
            "ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('neutrospline {kind} model','membership neutrosophic','degrees: each control point''s CARTESIAN_POINT is named ''NAME T=truth I=indeterminacy F=falsity'''),'2;1');
FILE_NAME('{title}','1970-01-01T00:00:00',(''),(''),'neutrospline {version}','neutrospline {version}','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN {{ 1 0 10303 214 1 1 1 1 }}'));
ENDSEC;
DATA;
#1=APPLICATION_CONTEXT('automotive_design');
#2=APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#1);
#3=PRODUCT_CONTEXT('',#1,'mechanical');
#4=PRODUCT('{title}','{title}','{description}',(#3));
#5=PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#4));
#6=PRODUCT_DEFINITION_FORMATION('','',#4);
#7=PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');
#8=PRODUCT_DEFINITION('design','',#6,#7);
#9=PRODUCT_DEFINITION_SHAPE('','',#8);
#10=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));
#11=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));
#12=(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());
#13=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-7),#10,'distance_accuracy_value','confusion accuracy');
#14=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#13))GLOBAL_UNIT_ASSIGNED_CONTEXT((#10,#11,#12))REPRESENTATION_CONTEXT('3D','3D'));
"
        )
    }

    #[test]
    fn real_has_a_decimal_point_and_an_upper_case_exponent() {
        assert_eq!(real(1.0), "1.");
        assert_eq!(real(0.0), "0.");
        assert_eq!(real(-0.0), "-0.");
        assert_eq!(real(0.5), "0.5");
        assert_eq!(real(123456.0), "123456.");
        assert_eq!(real(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(real(1e-7), "1.E-7");
        assert_eq!(real(-2.5e-7), "-2.5E-7");
        assert_eq!(real(1e20), "1.E20");
        assert_eq!(real(f64::MAX), "1.7976931348623157E308");
        assert_eq!(real(5e-324), "5.E-324");
        for v in [
            std::f64::consts::FRAC_1_SQRT_2,
            1.0 / 3.0,
            6.02214076e23,
            -1.0e-300,
        ] {
            let text = real(v);
            assert!(text.contains('.'), "{text}");
            assert_eq!(text.replace('E', "e").parse::<f64>().unwrap(), v);
        }
    }

    #[test]
    fn string_escapes_quotes_backslashes_and_other_characters() {
        assert_eq!(string(""), "''");
        assert_eq!(string("it's a\\b"), "'it''s a\\\\b'");
        assert_eq!(string("caf\u{e9} au lait"), "'caf\\X2\\00E9\\X0\\ au lait'");
        // Two characters outside ASCII in a row share one \X2\ run; beyond the BMP, \X4\.
        assert_eq!(string("\u{3b1}\u{3b2}!"), "'\\X2\\03B103B2\\X0\\!'");
        assert_eq!(string("\u{1f600}"), "'\\X4\\0001F600\\X0\\'");
        assert_eq!(
            string("a\u{e9}\u{1f600}\u{1f601}b"),
            "'a\\X2\\00E9\\X0\\\\X4\\0001F6000001F601\\X0\\b'"
        );
        assert_eq!(string("a\nb"), "'a\\X2\\000A\\X0\\b'");
    }

    #[test]
    fn distinct_knots_count_multiplicities() {
        assert_eq!(
            distinct_knots(&[0.0, 0.0, 0.0, 0.25, 0.25, 1.0, 1.0, 1.0]),
            (vec![3, 2, 3], vec![0.0, 0.25, 1.0])
        );
        // Unclamped: every knot once.
        assert_eq!(
            distinct_knots(&[0.0, 1.0, 2.0, 3.0]),
            (vec![1, 1, 1, 1], vec![0.0, 1.0, 2.0, 3.0])
        );
    }

    /// The whole file of a quadratic plane Bézier curve, checked by hand against ISO 10303-21:
    /// one instance per line, the header's three entities, the points at z = 0 named with
    /// their degrees (the unnamed third as `P2`), the Bézier knots as 0 and 1 three times.
    #[test]
    fn step_text_of_a_small_curve() {
        let curve = Bezier::new(vec![
            ControlPoint::new([0.0, 0.0], degrees(1.0, 0.0, 0.0)),
            ControlPoint::new([0.5, 2.0], degrees(0.5, 0.25, 0.125)),
            ControlPoint::new([2.0, -1e-7], degrees(0.0, 0.0, 1.0)),
        ])
        .unwrap();
        let model = Model::new(AnyCurve::Bezier(curve))
            .with_name("arc")
            .with_description("it's small")
            .with_point_names([Some("A"), Some("B"), None])
            .unwrap();
        let expected = preamble("bezier", "arc", "it''s small")
            + "#15=CARTESIAN_POINT('A T=1 I=0 F=0',(0.,0.,0.));
#16=CARTESIAN_POINT('B T=0.5 I=0.25 F=0.125',(0.5,2.,0.));
#17=CARTESIAN_POINT('P2 T=0 I=0 F=1',(2.,-1.E-7,0.));
#18=B_SPLINE_CURVE_WITH_KNOTS('',2,(#15,#16,#17),.UNSPECIFIED.,.F.,.U.,(3,3),(0.,1.),.UNSPECIFIED.);
#19=GEOMETRIC_CURVE_SET('',(#18));
#20=GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('arc',(#19),#14);
#21=SHAPE_DEFINITION_REPRESENTATION(#9,#20);
ENDSEC;
END-ISO-10303-21;
";
        assert_eq!(document(&model).unwrap(), expected);
    }

    #[test]
    fn step_rational_curve_is_the_complex_entity() {
        let d = degrees(0.5, 0.5, 0.5);
        let curve = Nurbs::new(
            vec![
                ControlPoint::new([1.0, 0.0, 0.0], d),
                ControlPoint::new([1.0, 1.0, 0.5], d),
                ControlPoint::new([0.0, 1.0, 1.0], d),
            ],
            vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
            KnotVector::new(vec![0.0, 0.0, 0.0, 2.0, 2.0, 2.0], 2, 3).unwrap(),
        )
        .unwrap();
        let text = document(&Model::new(AnyCurve::Nurbs(curve))).unwrap();
        assert!(text.contains(
            "#18=(BOUNDED_CURVE()B_SPLINE_CURVE(2,(#15,#16,#17),.UNSPECIFIED.,.F.,.U.)\
             B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.,2.),.UNSPECIFIED.)CURVE()\
             GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE((1.,0.7071067811865476,1.))\
             REPRESENTATION_ITEM(''));\n"
        ));
        // No name: the kind names the product, the points are P0, P1, P2.
        assert!(text.contains("#4=PRODUCT('nurbs','nurbs','',(#3));"));
        assert!(text.contains("#17=CARTESIAN_POINT('P2 T=0.5 I=0.5 F=0.5',(0.,1.,1.));"));
    }

    fn grid(rows: usize, cols: usize, z: impl Fn(usize, usize) -> f64) -> Vec<ControlPoint<3>> {
        let mut points = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let t = i as f64 / (rows - 1) as f64;
                points.push(ControlPoint::new(
                    [i as f64, j as f64, z(i, j)],
                    degrees(t, 0.0, 1.0 - t),
                ));
            }
        }
        points
    }

    /// The lines of `text` that start with `prefix` after their `#n=`.
    fn instances<'a>(text: &'a str, prefix: &str) -> Vec<&'a str> {
        text.lines()
            .filter(|l| {
                l.split_once('=')
                    .is_some_and(|(_, b)| b.starts_with(prefix))
            })
            .collect()
    }

    /// A 2 x 3 grid (two rows along u, three columns along v): the outer list of STEP's
    /// control points is u, so it is two lists of three, row by row; the degrees are (1, 2).
    #[test]
    fn step_surface_grid_is_u_outer_v_inner() {
        let surface = Surface::bezier(2, 3, grid(2, 3, |i, j| (i * j) as f64)).unwrap();
        let text = document(&Model::new(surface)).unwrap();
        assert!(text.contains(
            "#21=B_SPLINE_SURFACE_WITH_KNOTS('',1,2,((#15,#16,#17),(#18,#19,#20)),\
             .UNSPECIFIED.,.F.,.F.,.U.,(2,2),(3,3),(0.,1.),(0.,1.),.UNSPECIFIED.);\n"
        ));
        assert!(text.contains("#16=CARTESIAN_POINT('P1 T=0 I=0 F=1',(0.,1.,0.));"));
        assert!(text.contains("#18=CARTESIAN_POINT('P3 T=1 I=0 F=0',(1.,0.,0.));"));
        // The corners P00, P10, P12, P02 are the grid's points; the four boundaries reuse the
        // grid's points too: v = v0 runs along u over column 0, u = u1 along v over row 1.
        assert_eq!(
            instances(&text, "VERTEX_POINT"),
            [
                "#22=VERTEX_POINT('',#15)",
                "#23=VERTEX_POINT('',#18)",
                "#24=VERTEX_POINT('',#20)",
                "#25=VERTEX_POINT('',#17)"
            ]
            .map(|l| format!("{l};"))
        );
        let edges = instances(&text, "B_SPLINE_CURVE_WITH_KNOTS");
        assert_eq!(edges.len(), 4);
        assert!(edges[0].contains("1,(#15,#18),"));
        assert!(edges[1].contains("2,(#18,#19,#20),"));
        assert!(edges[2].contains("1,(#17,#20),"));
        assert!(edges[3].contains("2,(#15,#16,#17),"));
        assert_eq!(
            instances(&text, "ORIENTED_EDGE")
                .iter()
                .map(|l| l.ends_with(".T.);"))
                .collect::<Vec<_>>(),
            [true, true, false, false]
        );
        assert_eq!(instances(&text, "EDGE_LOOP").len(), 1);
        assert!(text.contains("MANIFOLD_SURFACE_SHAPE_REPRESENTATION('bezier-surface',"));
    }

    /// Unclamped knots: the boundaries are the iso-parameter curves and the corners the
    /// surface's values, new points without names.
    #[test]
    fn step_unclamped_surface_bounds_by_iso_curves() {
        let knots = || KnotVector::new(vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0], 2, 3).unwrap();
        let surface =
            Surface::bspline(3, 3, grid(3, 3, |i, j| (i + j) as f64), knots(), knots()).unwrap();
        let text = document(&Model::new(surface.clone())).unwrap();
        let named = instances(&text, "CARTESIAN_POINT('P");
        assert_eq!(named.len(), 9);
        let unnamed = instances(&text, "CARTESIAN_POINT(''");
        // Four corners and 4 x 3 control points of the boundaries.
        assert_eq!(unnamed.len(), 16);
        let corner = surface.evaluate(2.0, 2.0).unwrap().position;
        assert_eq!(corner, [0.5, 0.5, 1.0]);
        assert!(text.contains("CARTESIAN_POINT('',(0.5,0.5,1.));"));
        assert!(instances(&text, "B_SPLINE_CURVE_WITH_KNOTS")
            .iter()
            .all(|l| l.contains("(1,1,1,1,1,1),(0.,1.,2.,3.,4.,5.)")));
    }

    /// A boundary collapsed to a point (the first row all at the apex) is left out of the
    /// loop, which then has three edges.
    #[test]
    fn step_collapsed_boundary_is_left_out() {
        let mut points = grid(3, 3, |_, _| 0.0);
        for p in &mut points[..3] {
            p.position = [0.0, 1.0, 2.0];
        }
        let surface = Surface::bezier(3, 3, points).unwrap();
        let text = document(&Model::new(surface)).unwrap();
        assert_eq!(instances(&text, "EDGE_CURVE").len(), 4);
        let edge_loop = instances(&text, "EDGE_LOOP");
        assert_eq!(edge_loop.len(), 1);
        assert_eq!(edge_loop[0].matches('#').count(), 4, "{}", edge_loop[0]);
    }

    fn example(name: &str) -> Model {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(name);
        load(&path, &ReadOptions::default()).expect("an example model")
    }

    /// Every example model exports, the same bytes twice, with one named point per control
    /// point and one B-spline of the model's kind.
    #[test]
    fn step_every_example_exports() {
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
        let mut count = 0;
        for entry in std::fs::read_dir(dir).unwrap() {
            let name = entry.unwrap().file_name().to_string_lossy().into_owned();
            if !(name.ends_with(".toml") || name.ends_with(".json")) {
                continue;
            }
            let model = example(&name);
            let text = document(&model).unwrap();
            assert_eq!(text, document(&model).unwrap(), "{name}: reproducible");
            let named = instances(&text, "CARTESIAN_POINT('")
                .into_iter()
                .filter(|l| l.contains(" T="))
                .count();
            assert_eq!(named, model.shape().control_count(), "{name}");
            let rational = text.contains("RATIONAL_B_SPLINE_");
            assert_eq!(rational, model.shape().weights().is_some(), "{name}");
            let surface = text.contains("ADVANCED_FACE(");
            assert_eq!(surface, model.shape().is_surface(), "{name}");
            assert!(text.ends_with("ENDSEC;\nEND-ISO-10303-21;\n"));
            assert!(text.is_ascii());
            count += 1;
        }
        assert!(count >= 8, "{count} examples");
    }

    #[test]
    fn step_export_options() {
        let model = example("example1.toml");
        let step = ExportFormat::Step;
        assert_eq!(
            export(&model, step, &ExportOptions::new()).unwrap().len(),
            document(&model).unwrap().len()
        );
        let e = export(&model, step, &ExportOptions::new().with_samples(Some(10))).unwrap_err();
        assert_eq!(
            e.to_string(),
            "--samples does not apply to STEP, which is exact (a B-spline curve or surface)"
        );
        assert!(export(&model, step, &ExportOptions::new().with_ascii(true)).is_err());
    }

    /// Every real of a STEP file's DATA section: the parameters outside strings that start
    /// with a digit or a sign and have a decimal point; each must read back as an `f64`.
    fn reals(text: &str) -> Vec<f64> {
        let data = &text[text.find("DATA;").unwrap()..];
        let mut outside = String::new();
        for (k, part) in data.split('\'').enumerate() {
            if k % 2 == 0 {
                outside.push_str(part);
            }
            outside.push(',');
        }
        outside
            .split(|c| "(),;=".contains(c))
            .filter(|t| t.contains('.') && t.starts_with(|c: char| c.is_ascii_digit() || c == '-'))
            .map(|t| t.replace('E', "e").parse::<f64>().unwrap())
            .collect()
    }

    fn value() -> impl Strategy<Value = f64> {
        prop_oneof![
            -1e6..1e6f64,
            Just(0.0),
            Just(-0.0),
            Just(1e-300),
            Just(5e-324),
            Just(1e300),
            Just(-f64::MAX),
        ]
    }

    proptest! {
        /// Any B-spline or NURBS surface (unclamped knots, extreme coordinates, collapsed
        /// boundaries) exports without a panic; every real of the file is a finite number in
        /// STEP's syntax, and the surface's control values are among them to the last bit.
        #[test]
        fn step_surface_export_never_panics(
            rows in 2usize..5,
            cols in 2usize..5,
            values in proptest::collection::vec(value(), 48),
            steps in proptest::collection::vec(0.0..2.0f64, 16),
            clamp in any::<bool>(),
            rational in any::<bool>(),
        ) {
            let degree_u = rows - 1;
            let degree_v = (cols - 1).min(2);
            let knots = |degree: usize, count: usize, offset: usize| {
                let mut k = Vec::new();
                let mut x = 0.0;
                for n in 0..count + degree + 1 {
                    k.push(x);
                    let clamped_end = clamp && (n < degree || n >= count);
                    if !clamped_end {
                        x += steps[(n + offset) % steps.len()].max(1e-3);
                    }
                }
                KnotVector::new(k, degree, count).unwrap()
            };
            let points: Vec<ControlPoint<3>> = (0..rows * cols)
                .map(|k| ControlPoint::new(
                    [values[3 * k], values[3 * k + 1], values[3 * k + 2]],
                    degrees(0.5, 0.25, 0.125),
                ))
                .collect();
            let surface = if rational {
                let weights = (0..rows * cols).map(|k| 0.5 + steps[k % 16]).collect();
                Surface::nurbs(rows, cols, points.clone(), weights, knots(degree_u, rows, 0), knots(degree_v, cols, 5))
            } else {
                Surface::bspline(rows, cols, points.clone(), knots(degree_u, rows, 0), knots(degree_v, cols, 5))
            }
            .unwrap();
            if let Ok(text) = document(&Model::new(surface)) {
                prop_assert!(text.is_ascii());
                let found = reals(&text);
                for p in &points {
                    for x in p.position {
                        prop_assert!(found.iter().any(|f| f.to_bits() == x.to_bits()), "{x} missing");
                    }
                }
            }
        }

        /// Any plane B-spline curve (repeated knots, extreme coordinates) exports; the
        /// control values of its pieces are in the file exactly.
        #[test]
        fn step_curve_export_never_panics(
            values in proptest::collection::vec(value(), 4..24),
            degree in 1usize..4,
            steps in proptest::collection::vec(prop_oneof![Just(0.0), Just(0.25), 0.01..1.0f64], 30),
        ) {
            let points: Vec<ControlPoint<2>> = values
                .chunks_exact(2)
                .map(|p| ControlPoint::new([p[0], p[1]], degrees(1.0, 0.0, 0.0)))
                .collect();
            let degree = degree.min(points.len() - 1);
            let count = points.len();
            let knots: Vec<f64> = steps[..count + degree + 1]
                .iter()
                .scan(0.0, |x, step| {
                    *x += step;
                    Some(*x)
                })
                .collect();
            let Ok(knots) = KnotVector::new(knots, degree, count) else {
                return Ok(());
            };
            let kept: Vec<usize> = pieces(&knots).iter().flat_map(|p| p.start..p.end).collect();
            let curve = neutrospline::BSpline::new(points.clone(), knots).unwrap();
            let text = document(&Model::new(AnyCurve::BSpline(curve))).unwrap();
            prop_assert!(!kept.is_empty());
            let found = reals(&text);
            for k in kept {
                for x in points[k].position {
                    prop_assert!(found.iter().any(|f| f.to_bits() == x.to_bits()), "{x} missing");
                }
            }
        }
    }

    #[test]
    fn pieces_split_at_interior_knots_of_full_multiplicity() {
        let one = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 5).unwrap();
        assert_eq!(
            pieces(&one),
            [Piece {
                start: 0,
                end: 5,
                knots: one.knots().to_vec()
            }]
        );
        let two = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 6).unwrap();
        assert_eq!(
            pieces(&two),
            [
                Piece {
                    start: 0,
                    end: 3,
                    knots: vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5]
                },
                Piece {
                    start: 3,
                    end: 6,
                    knots: vec![0.5, 0.5, 0.5, 1.0, 1.0, 1.0]
                },
            ]
        );
        // Unclamped, with the full run where the domain [t_2, t_5] = [1, 3] starts: the part
        // before it (one control point) is outside the domain and left out.
        let start = KnotVector::new(vec![0.0, 1.0, 1.0, 1.0, 2.0, 3.0, 4.0], 2, 4).unwrap();
        assert_eq!(
            pieces(&start),
            [Piece {
                start: 1,
                end: 4,
                knots: vec![1.0, 1.0, 1.0, 2.0, 3.0, 4.0]
            }]
        );
    }

    /// A quadratic curve with a triple knot at 0.5 (it jumps from (2, 0) to (3, 0)) is two
    /// curves; the points keep their indices in the model.
    #[test]
    fn step_curve_with_a_full_interior_knot_is_two_curves() {
        let d = degrees(1.0, 0.0, 0.0);
        let points = (0..6)
            .map(|k| ControlPoint::new([k as f64, (k % 2) as f64], d))
            .collect();
        let knots =
            KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0], 2, 6).unwrap();
        let curve = neutrospline::BSpline::new(points, knots).unwrap();
        let text = document(&Model::new(AnyCurve::BSpline(curve))).unwrap();
        let curves = instances(&text, "B_SPLINE_CURVE_WITH_KNOTS");
        assert_eq!(curves.len(), 2);
        assert!(curves[0].ends_with(",(3,3),(0.,0.5),.UNSPECIFIED.);"));
        assert!(curves[1].ends_with(",(3,3),(0.5,1.),.UNSPECIFIED.);"));
        assert!(text.contains("#19=CARTESIAN_POINT('P3 T=1 I=0 F=0',(3.,1.,0.));"));
        assert!(text.contains("GEOMETRIC_CURVE_SET('',(#18,#22));"));
    }

    /// A bilinear surface with a double knot in u is two faces of one shell.
    #[test]
    fn step_surface_with_a_full_interior_knot_is_two_faces() {
        let u = KnotVector::new(vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0], 1, 4).unwrap();
        let v = KnotVector::new(vec![0.0, 0.0, 1.0, 1.0], 1, 2).unwrap();
        let surface = Surface::bspline(4, 2, grid(4, 2, |i, _| i as f64), u, v).unwrap();
        let text = document(&Model::new(surface)).unwrap();
        assert_eq!(instances(&text, "ADVANCED_FACE").len(), 2);
        let surfaces = instances(&text, "B_SPLINE_SURFACE_WITH_KNOTS");
        assert!(surfaces[0].contains("(2,2),(2,2),(0.,1.),(0.,1.)"));
        assert!(surfaces[1].contains("(2,2),(2,2),(1.,2.),(0.,1.)"));
        assert!(text.contains("CARTESIAN_POINT('P7 T=1 I=0 F=0',(3.,1.,3.));"));
        assert_eq!(instances(&text, "OPEN_SHELL").len(), 1);
    }
}
