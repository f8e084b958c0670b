//! Reading curves from SVG files: every drawn shape element (`<path>`, `<polyline>`,
//! `<polygon>`, `<line>`, `<rect>`, `<circle>`, `<ellipse>`) becomes plane curves, one per
//! subpath, in the user units of the root `<svg>` (its viewBox coordinates when it has one;
//! x to the right, y down, as SVG draws), with the given degrees at every control point.
//!
//! The XML is parsed by roxmltree (namespaces resolved: `svg:path` under a prefix bound to the
//! SVG namespace is a path; elements of other namespaces, such as Inkscape's, are not SVG
//! drawing elements; a file without `xmlns` is read as SVG, as renderers do), path data,
//! point lists, transforms, lengths and viewBoxes by svgtypes, `style` attributes and
//! `<style>` sheets by simplecss. A file that is not UTF-8 is decoded in the encoding its XML
//! declaration names.
//!
//! Where a shape is drawn: the `transform` of the element and of its ancestors (the attribute,
//! or the CSS property, which wins), nested `<svg>` viewports (x, y, width, height, viewBox,
//! preserveAspectRatio: SVG 1.1, section 7.8; the content is not clipped), `<use>` clones (x,
//! y, the use's transform; a `<symbol>` or `<svg>` shown in the use's width and height) and
//! `<switch>` (its first child whose conditions pass: no `requiredExtensions`, English in
//! `systemLanguage`). Lengths in px, in, cm, mm, pt, pc (96 user units per inch), em and ex
//! (16 and 8: the default font size), and percentages of the viewport.
//!
//! What is not imported is recorded in the [`ImportReport`](crate::ImportReport), never
//! dropped without a word: hidden shapes (`display:none` on the element or an ancestor,
//! `visibility:hidden` or `collapse` inherited), content not drawn where it stands (in
//! `<defs>`, `<clipPath>`, `<mask>`, `<marker>`, `<pattern>`, an unused `<symbol>`, the
//! `<switch>` children not chosen), drawn elements that are not curves (`<text>`, `<image>`,
//! `<foreignObject>`, Inkscape's flowed text `<flowRoot>`, whose `<flowRegion>` shapes are
//! the frame its text flows in and are not drawn), shapes that draw nothing (a rectangle or circle of size zero, a path
//! with only movetos, a zero-length line), kinds left out by the `entities` option. Data
//! that breaks off is drawn up to its error with a warning naming the element, its line and
//! the position (SVG 2, path data error handling); an attribute value that does not parse (a
//! transform, a length, a viewBox) is read as not given, as renderers do, with a warning.
//!
//! The curves, exactly:
//!
//! - lines, quadratic and cubic Bézier segments keep their control points; when a subpath
//!   mixes degrees, every segment is raised to the highest by degree elevation (exact: the same
//!   curve, [`neutrospline::Elevate`]);
//! - an elliptical arc is converted exactly (SVG 1.1, appendix F.6: its centre, radii and
//!   angles) into rational quadratic pieces of at most 90 degrees each: the piece from angle a
//!   to b of the unit circle has the control points (cos a, sin a), (cos m, sin m) / cos(h) and
//!   (cos b, sin b) with m = (a + b) / 2 and h = (b - a) / 2, weights 1, cos(h), 1, mapped by
//!   the ellipse's scaling, rotation and translation (an affine map, under which a rational
//!   curve keeps its weights). An arc with a zero radius is the straight line the SVG rules
//!   make it; radii too small to reach the end point are scaled up as the rules say;
//! - a `<circle>` or `<ellipse>` is four such quarter pieces from `(cx + rx, cy)` (SVG 2,
//!   section 10.4); a `<rect>` is its four sides, with quarter-ellipse corners when it has
//!   `rx` / `ry` (an auto radius takes the other's value, each clamped to half its side: SVG 2,
//!   section 10.2); a `<line>` one segment; a `<polygon>` is closed back to its first point;
//! - one segment is a Bézier curve (a NURBS curve for one arc piece); several segments are a
//!   B-spline (NURBS when an arc is among them) with the segments' control points joined and
//!   the knots 0, 1, ..., m each repeated degree times (degree + 1 at the ends), segment k over
//!   \[k, k + 1\].
//!
//! A model is named by its element's `id`; the report counts curves by element kind (a clone
//! under the kind of the element it clones).

mod path_data;
mod style;
mod transform;
mod walk;

use std::path::Path;

use neutrospline::{
    AnyCurve, Bezier, ControlPoint, ControlPolygon, Degrees, Elevate, KnotVector, Nurbs,
};

use crate::report::{Import, ImportOptions};
use neutrospline_io::read_whole;
use neutrospline_io::{InputError, Limits, ReadError};

use path_data::Segment;
use transform::{apply, Matrix};

/// A segment raised to `degree` by degree elevation in the core (the same curve).
///
/// # Errors
/// The core's message for a segment it refuses (a coordinate that overflowed to infinity).
fn elevated(
    segment: &Segment,
    degree: usize,
    defaults: Degrees,
) -> Result<(Vec<[f64; 2]>, Vec<f64>), String> {
    let points: Vec<ControlPoint<2>> = segment
        .points
        .iter()
        .map(|&p| ControlPoint::new(p, defaults))
        .collect();
    let count = points.len();
    let mut curve = match &segment.weights {
        Some(w) => {
            let clamped = [vec![0.0; count], vec![1.0; count]].concat();
            let knots = KnotVector::new(clamped, count - 1, count).map_err(|e| e.to_string())?;
            AnyCurve::Nurbs(Nurbs::new(points, w.clone(), knots).map_err(|e| e.to_string())?)
        }
        None => AnyCurve::Bezier(Bezier::new(points).map_err(|e| e.to_string())?),
    };
    while curve.degree() < degree {
        curve = curve.elevate();
    }
    let weights = curve
        .weights()
        .map_or_else(|| vec![1.0; degree + 1], <[f64]>::to_vec);
    let positions = curve.control_points().iter().map(|p| p.position).collect();
    Ok((positions, weights))
}

/// The curve of one subpath's segments ([module docs](self)), mapped by `matrix`.
fn curve(segments: &[Segment], matrix: &Matrix, defaults: Degrees) -> Result<AnyCurve<2>, String> {
    let degree = segments.iter().map(Segment::degree).max().unwrap_or(1);
    let rational = segments.iter().any(|s| s.weights.is_some());
    let mut positions: Vec<[f64; 2]> = Vec::new();
    let mut weights: Vec<f64> = Vec::new();
    for (k, segment) in segments.iter().enumerate() {
        let (p, w) = elevated(segment, degree, defaults)?;
        // Consecutive segments share an end point: keep it once.
        let skip = usize::from(k > 0);
        positions.extend(&p[skip..]);
        weights.extend(&w[skip..]);
    }
    let points: Vec<ControlPoint<2>> = positions
        .iter()
        .map(|&p| ControlPoint::new(apply(matrix, p), defaults))
        .collect();
    crate::pieces::joined(points, weights, segments.len(), degree, rational)
}

/// The text of an SVG file: UTF-8, or the encoding its XML declaration names
/// (`encoding="windows-1251"`, any label of the WHATWG Encoding standard, decoded by
/// encoding_rs).
///
/// # Errors
/// A file that is not UTF-8 and names no encoding, or one that is not known, or bytes that
/// are not text in it.
fn decoded<'b>(file: &str, bytes: &'b [u8]) -> Result<std::borrow::Cow<'b, str>, ReadError> {
    let utf8_error = match std::str::from_utf8(bytes) {
        Ok(text) => return Ok(text.into()),
        Err(e) => e,
    };
    let error =
        |message: String| -> ReadError { InputError::new(file, None, None, message).into() };
    // The declaration is ASCII in every encoding it may name.
    let head = String::from_utf8_lossy(&bytes[..bytes.len().min(256)]);
    let label = head
        .strip_prefix("<?xml")
        .and_then(|rest| rest.split("?>").next())
        .and_then(|declaration| {
            let at = declaration.find("encoding")?;
            let value = declaration[at + "encoding".len()..]
                .trim_start()
                .strip_prefix('=')?
                .trim_start();
            let quote = value.chars().next().filter(|q| *q == '"' || *q == '\'')?;
            value[1..].split(quote).next().map(str::to_owned)
        });
    let Some(label) = label else {
        return Err(error(format!(
            "the file is not UTF-8 text (byte {}) and its XML declaration names no encoding",
            utf8_error.valid_up_to()
        )));
    };
    let encoding = encoding_rs::Encoding::for_label(label.as_bytes()).ok_or_else(|| {
        error(format!(
            "the XML declaration's encoding {label:?} is not one this reader knows"
        ))
    })?;
    let (text, _, malformed) = encoding.decode(bytes);
    if malformed {
        return Err(error(format!(
            "the file is not {} text, as its XML declaration says",
            encoding.name()
        )));
    }
    Ok(text.into_owned().into())
}

/// The curves of an SVG file held in memory, in document order, every control point with the
/// degrees `options.defaults`, and the report of what was drawn but not imported. `file`
/// names it in messages. The [module docs](self) say what is read and how.
///
/// # Errors
/// [`ReadError::Input`] naming the file and line: text that is not UTF-8, XML that does not
/// parse (roxmltree's message, line and column), a root that is not `<svg>`, a `<use>` that
/// refers to its own ancestor or nests deeper than 64, a coordinate that overflows, more
/// control points in a curve or in the whole file than `limits` allow, no curve in the file
/// (the message then says what the file holds).
pub fn parse_svg(
    file: &str,
    bytes: &[u8],
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let text = decoded(file, bytes)?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let parsing = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let document = roxmltree::Document::parse_with_options(text, parsing).map_err(|e| {
        let at = e.pos();
        InputError::new(
            file,
            Some(at.row as usize),
            None,
            format!("the XML does not parse: {e}"),
        )
    })?;
    let root = document.root_element();
    if !style::is_svg(&root, "svg") {
        return Err(InputError::new(
            file,
            Some(document.text_pos_at(root.range().start).row as usize),
            None,
            format!(
                "the root element is <{}>, not <svg>",
                root.tag_name().name()
            ),
        )
        .into());
    }
    let (models, report) = walk::Walker::new(file, &document, options, limits).run()?;
    if models.is_empty() {
        return Err(InputError::new(
            file,
            None,
            None,
            format!("the file has no curve to import ({})", report.summary()),
        )
        .into());
    }
    Ok(Import { models, report })
}

/// The curves of the SVG file at `path` ([`parse_svg`]), read whole up to
/// [`Limits::max_file_size`] bytes.
///
/// # Errors
/// [`ReadError::Io`] and [`ReadError::IsDirectory`] when the file cannot be read, as
/// [`parse_svg`] otherwise.
pub fn load_svg(
    path: impl AsRef<Path>,
    options: &ImportOptions,
    limits: &Limits,
) -> Result<Import, ReadError> {
    let (shown, bytes) = read_whole(path.as_ref(), limits.max_file_size, "a .svg file")?;
    parse_svg(&shown, &bytes, options, limits)
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_unseen;
