//! The walk over the document tree: which elements are drawn, with what transform, and the
//! record of every one that is not imported ([module docs](super)).

use std::collections::{HashMap, HashSet};
use std::str::FromStr;

use neutrospline_io::{InputError, Limits, Model, ReadError};
use roxmltree::{Document, Node, NodeId};

use super::path_data::{ellipse, path_data, point_list, rectangle, Segment};
use super::style::{in_svg, is_svg, Sheets};
use super::transform::{compose, transform, Matrix, IDENTITY};
use crate::report::{ImportOptions, ImportReport, SkipReason};

/// The shape elements, each imported as curves.
const SHAPES: [&str; 7] = [
    "path", "polyline", "polygon", "line", "rect", "circle", "ellipse",
];
/// Elements that are drawn but are not curves. Inkscape's `<flowRoot>` (flowed text of the
/// SVG 1.2 draft) is text that Inkscape draws; the shapes of its `<flowRegion>` are the frame
/// the text flows in, never drawn (browsers draw none of it).
const NOT_CURVES: [&str; 4] = ["text", "image", "foreignObject", "flowRoot"];
/// Containers whose content is not drawn where it stands.
const NOT_DRAWN: [&str; 6] = ["defs", "clipPath", "mask", "marker", "pattern", "symbol"];
/// How deep `<use>` elements may nest.
const MAX_USE_DEPTH: usize = 64;
/// The xlink namespace of `xlink:href`.
const XLINK_NS: &str = "http://www.w3.org/1999/xlink";

/// What an element inherits from where it is drawn.
#[derive(Clone, Copy, Debug)]
struct Context {
    /// From the element's user space to the root's.
    matrix: Matrix,
    /// The size of the viewport that percentages refer to.
    viewport: [f64; 2],
    /// The inherited `visibility` (false for hidden or collapse).
    visible: bool,
}

/// Which viewport dimension a length refers to when it is a percentage.
#[derive(Clone, Copy, Debug)]
enum Axis {
    X,
    Y,
    /// The normalised diagonal, `sqrt((w^2 + h^2) / 2)` (SVG 1.1, section 7.10).
    Diagonal,
}

/// The walk's state: the document, the options and what has been read so far.
pub(super) struct Walker<'a, 'input> {
    file: &'a str,
    document: &'a Document<'input>,
    options: &'a ImportOptions,
    limits: &'a Limits,
    sheets: Sheets<'a>,
    ids: HashMap<&'a str, Node<'a, 'input>>,
    used: HashSet<NodeId>,
    models: Vec<Model>,
    report: ImportReport,
    control_points: u64,
    uses: Vec<NodeId>,
}

/// The user units of one `length` (CSS units at 96 per inch; `em` as 16 and `ex` as 8 user
/// units, the default font size; a percentage of `reference`).
fn user_units(length: svgtypes::Length, reference: f64) -> f64 {
    use svgtypes::LengthUnit as U;
    let n = length.number;
    match length.unit {
        U::None | U::Px => n,
        U::In => n * 96.0,
        U::Cm => n * 96.0 / 2.54,
        U::Mm => n * 96.0 / 25.4,
        U::Pt => n * 4.0 / 3.0,
        U::Pc => n * 16.0,
        U::Em => n * 16.0,
        U::Ex => n * 8.0,
        U::Percent => n / 100.0 * reference,
    }
}

/// The matrix of a viewBox `(x, y, w, h)` shown in a viewport of `size` with
/// `preserveAspectRatio` (SVG 1.1, section 7.8).
fn viewbox_matrix(view: svgtypes::ViewBox, ratio: svgtypes::AspectRatio, size: [f64; 2]) -> Matrix {
    use svgtypes::Align as A;
    let (sx, sy) = (size[0] / view.w, size[1] / view.h);
    if ratio.align == A::None {
        return [sx, 0.0, 0.0, sy, -view.x * sx, -view.y * sy];
    }
    let s = if ratio.slice { sx.max(sy) } else { sx.min(sy) };
    let (free_x, free_y) = (size[0] - view.w * s, size[1] - view.h * s);
    let (ax, ay) = match ratio.align {
        A::XMinYMin => (0.0, 0.0),
        A::XMidYMin => (0.5, 0.0),
        A::XMaxYMin => (1.0, 0.0),
        A::XMinYMid => (0.0, 0.5),
        A::XMidYMid | A::None => (0.5, 0.5),
        A::XMaxYMid => (1.0, 0.5),
        A::XMinYMax => (0.0, 1.0),
        A::XMidYMax => (0.5, 1.0),
        A::XMaxYMax => (1.0, 1.0),
    };
    [
        s,
        0.0,
        0.0,
        s,
        -view.x * s + ax * free_x,
        -view.y * s + ay * free_y,
    ]
}

/// The element's name as the report and messages write it: `<path>`.
fn kind(node: Node<'_, '_>) -> String {
    format!("<{}>", node.tag_name().name())
}

impl<'a, 'input> Walker<'a, 'input> {
    /// A walk over `document`.
    pub(super) fn new(
        file: &'a str,
        document: &'a Document<'input>,
        options: &'a ImportOptions,
        limits: &'a Limits,
    ) -> Self {
        let mut ids = HashMap::new();
        for node in document.descendants().filter(Node::is_element) {
            if let Some(id) = node.attribute("id") {
                ids.entry(id).or_insert(node);
            }
        }
        let mut walker = Walker {
            file,
            document,
            options,
            limits,
            sheets: Sheets::of(document),
            ids,
            used: HashSet::new(),
            models: Vec::new(),
            report: ImportReport::default(),
            control_points: 0,
            uses: Vec::new(),
        };
        let targets: Vec<NodeId> = document
            .descendants()
            .filter(|n| is_svg(n, "use"))
            .filter_map(|n| walker.target(n))
            .map(|n| n.id())
            .collect();
        walker.used.extend(targets);
        walker
    }

    /// The models and the report, walking from the root `<svg>`.
    pub(super) fn run(mut self) -> Result<(Vec<Model>, ImportReport), ReadError> {
        let root = self.document.root_element();
        let number = |name: &str| {
            root.attribute(name)
                .and_then(|v| svgtypes::Length::from_str(v).ok())
                .filter(|l| l.unit != svgtypes::LengthUnit::Percent)
                .map(|l| user_units(l, 0.0))
        };
        let viewport = match root
            .attribute("viewBox")
            .and_then(|v| svgtypes::ViewBox::from_str(v).ok())
        {
            Some(view) => [view.w, view.h],
            None => [
                number("width").unwrap_or(100.0),
                number("height").unwrap_or(100.0),
            ],
        };
        let context = Context {
            matrix: IDENTITY,
            viewport,
            visible: true,
        };
        match self.sheets.property(root, "display").as_deref() {
            Some("none") => self.count(root, SkipReason::Hidden, None),
            _ => {
                let context = self.inherit(root, context);
                self.children(root, context)?;
            }
        }
        Ok((self.models, self.report))
    }

    /// The 1-based line of `node`.
    fn line(&self, node: Node<'_, '_>) -> usize {
        self.document.text_pos_at(node.range().start).row as usize
    }

    /// `line L: <path id="a">`, naming an element in warnings.
    fn named(&self, node: Node<'_, '_>) -> String {
        match node.attribute("id") {
            Some(id) => format!(
                "line {}: <{} id=\"{id}\">",
                self.line(node),
                node.tag_name().name()
            ),
            None => format!("line {}: <{}>", self.line(node), node.tag_name().name()),
        }
    }

    /// An error at `node`.
    fn error(&self, node: Node<'_, '_>, message: String) -> ReadError {
        let name = match node.attribute("id") {
            Some(id) => format!("<{} id=\"{id}\">", node.tag_name().name()),
            None => kind(node),
        };
        InputError::new(
            self.file,
            Some(self.line(node)),
            None,
            format!("{name}: {message}"),
        )
        .into()
    }

    /// The element a `<use>` refers to (`href` or `xlink:href`, `#id`).
    fn target(&self, node: Node<'a, 'input>) -> Option<Node<'a, 'input>> {
        let href = node
            .attribute((XLINK_NS, "href"))
            .or_else(|| node.attribute("href"))?;
        self.ids.get(href.trim().strip_prefix('#')?).copied()
    }

    /// The context of `node`'s content: its transform and visibility applied.
    fn inherit(&mut self, node: Node<'a, 'input>, context: Context) -> Context {
        let mut context = context;
        if let Some(text) = self.sheets.property(node, "transform") {
            if text != "none" {
                match transform(&text) {
                    Ok(m) => context.matrix = compose(&context.matrix, &m),
                    Err(e) => {
                        let message = format!(
                            "{}: transform = {text:?}: {e}; drawn without it, as renderers do",
                            self.named(node)
                        );
                        self.report.warn(message);
                    }
                }
            }
        }
        match self.sheets.property(node, "visibility").as_deref() {
            Some("hidden" | "collapse") => context.visible = false,
            Some("visible") => context.visible = true,
            _ => {}
        }
        context
    }

    /// The element children of `node`, each walked in `context`.
    fn children(&mut self, node: Node<'a, 'input>, context: Context) -> Result<(), ReadError> {
        for child in node.children().filter(Node::is_element) {
            self.element(child, context)?;
        }
        Ok(())
    }

    /// Records every shape of the subtree of `node` (itself included) as left out for
    /// `reason`: `<path> in <defs>` when `container` is given. Content that a `<use>` draws
    /// is not counted as not drawn.
    fn count(&mut self, node: Node<'a, 'input>, reason: SkipReason, container: Option<&str>) {
        if !node.is_element() || !in_svg(&node) {
            return;
        }
        if reason == SkipReason::NotDrawn && self.used.contains(&node.id()) {
            return;
        }
        let name = node.tag_name().name();
        if SHAPES.contains(&name) || NOT_CURVES.contains(&name) || name == "use" {
            let what = match container {
                Some(c) => format!("<{name}> in <{c}>"),
                None => format!("<{name}>"),
            };
            self.report.skip(&what, reason);
        }
        if NOT_CURVES.contains(&name) {
            // Its content is part of it (tspans, a flowed text's frame).
            return;
        }
        for child in node.children() {
            self.count(child, reason, container);
        }
    }

    /// One element in `context`.
    fn element(&mut self, node: Node<'a, 'input>, context: Context) -> Result<(), ReadError> {
        if !in_svg(&node) {
            // Another program's element (Inkscape's sodipodi:namedview, ...): not SVG drawing.
            return Ok(());
        }
        let name = node.tag_name().name();
        if self.sheets.property(node, "display").as_deref() == Some("none") {
            self.count(node, SkipReason::Hidden, None);
            return Ok(());
        }
        if NOT_DRAWN.contains(&name) {
            if self.used.contains(&node.id()) {
                // A <symbol> that a <use> draws: its content is counted where it is drawn.
                return Ok(());
            }
            for child in node.children() {
                self.count(child, SkipReason::NotDrawn, Some(name));
            }
            return Ok(());
        }
        let inner = self.inherit(node, context);
        match name {
            "g" | "a" => self.children(node, inner),
            "svg" => self.viewport(node, inner, None),
            "switch" => {
                let chosen = node
                    .children()
                    .filter(Node::is_element)
                    .find(|child| in_svg(child) && passes_conditions(*child));
                for child in node.children().filter(Node::is_element) {
                    if Some(child) == chosen {
                        self.element(child, inner)?;
                    } else {
                        self.count(child, SkipReason::NotDrawn, Some("switch"));
                    }
                }
                Ok(())
            }
            "use" => self.use_element(node, inner),
            _ if SHAPES.contains(&name) => self.shape(node, inner),
            _ if NOT_CURVES.contains(&name) => {
                let reason = if inner.visible {
                    SkipReason::NotACurve
                } else {
                    SkipReason::Hidden
                };
                self.report.skip(&kind(node), reason);
                Ok(())
            }
            // Not drawing elements: title, desc, metadata, style, gradients, filters,
            // animation, fonts.
            _ => Ok(()),
        }
    }

    /// A length attribute in user units; `None` when it is not given. A value that does not
    /// parse is reported and read as not given (SVG 2, "error processing").
    fn length(
        &mut self,
        node: Node<'a, 'input>,
        name: &str,
        axis: Axis,
        context: Context,
    ) -> Option<f64> {
        // SVG 2 makes the geometry attributes properties: CSS may set them.
        let text = self.sheets.property(node, name)?;
        let text = text.as_str();
        let [w, h] = context.viewport;
        let reference = match axis {
            Axis::X => w,
            Axis::Y => h,
            Axis::Diagonal => ((w * w + h * h) / 2.0).sqrt(),
        };
        match svgtypes::Length::from_str(text) {
            Ok(length) if length.number.is_finite() => Some(user_units(length, reference)),
            _ => {
                let message = format!(
                    "{}: {name} = {text:?} is not a length; read as not given",
                    self.named(node)
                );
                self.report.warn(message);
                None
            }
        }
    }

    /// A nested `<svg>` (or one a `<use>` draws, with its `size`): its x, y, width, height,
    /// viewBox and preserveAspectRatio make the user space of its content (SVG 1.1, section
    /// 7.9). Its content is not clipped to the viewport.
    fn viewport(
        &mut self,
        node: Node<'a, 'input>,
        context: Context,
        size: Option<[Option<f64>; 2]>,
    ) -> Result<(), ReadError> {
        let x = self.length(node, "x", Axis::X, context).unwrap_or(0.0);
        let y = self.length(node, "y", Axis::Y, context).unwrap_or(0.0);
        let given = size.unwrap_or([None, None]);
        let width = given[0]
            .or_else(|| self.length(node, "width", Axis::X, context))
            .unwrap_or(context.viewport[0]);
        let height = given[1]
            .or_else(|| self.length(node, "height", Axis::Y, context))
            .unwrap_or(context.viewport[1]);
        self.viewbox_content(node, context, [x, y], [width, height])
    }

    /// The content of `node` (a `<svg>` or `<symbol>`) shown at `origin` in a viewport of
    /// `size`, through its viewBox and preserveAspectRatio.
    fn viewbox_content(
        &mut self,
        node: Node<'a, 'input>,
        context: Context,
        origin: [f64; 2],
        size: [f64; 2],
    ) -> Result<(), ReadError> {
        if !(size[0] > 0.0 && size[1] > 0.0) {
            // A viewport of no size draws nothing (SVG 1.1, section 7.9).
            for child in node.children() {
                self.count(child, SkipReason::Empty, Some(node.tag_name().name()));
            }
            return Ok(());
        }
        let mut inner = context;
        inner.matrix = compose(&context.matrix, &[1.0, 0.0, 0.0, 1.0, origin[0], origin[1]]);
        inner.viewport = size;
        if let Some(text) = node.attribute("viewBox") {
            match svgtypes::ViewBox::from_str(text) {
                Ok(view) if view.w > 0.0 && view.h > 0.0 => {
                    let ratio = node
                        .attribute("preserveAspectRatio")
                        .and_then(|t| svgtypes::AspectRatio::from_str(t).ok())
                        .unwrap_or_default();
                    inner.matrix = compose(&inner.matrix, &viewbox_matrix(view, ratio, size));
                    inner.viewport = [view.w, view.h];
                }
                _ => {
                    let message = format!(
                        "{}: viewBox = {text:?} is not four numbers with a positive width and \
                         height; read as not given",
                        self.named(node)
                    );
                    self.report.warn(message);
                }
            }
        }
        self.children(node, inner)
    }

    /// A `<use>`: the element it refers to, drawn in the use's user space translated by its
    /// x and y; a `<symbol>` or `<svg>` with the use's width and height as its viewport.
    fn use_element(&mut self, node: Node<'a, 'input>, context: Context) -> Result<(), ReadError> {
        let Some(target) = self.target(node) else {
            let message = format!(
                "{}: it refers to no element of the file (href {:?})",
                self.named(node),
                node.attribute((XLINK_NS, "href"))
                    .or_else(|| node.attribute("href"))
                    .unwrap_or("")
            );
            self.report.warn(message);
            self.report.skip("<use>", SkipReason::Empty);
            return Ok(());
        };
        if target.ancestors().any(|a| a == node)
            || node.ancestors().any(|a| a == target)
            || self.uses.contains(&node.id())
        {
            return Err(self.error(node, "it draws itself (the element it refers to contains it, or a <use> chain comes back to it)".to_owned()));
        }
        if self.uses.len() >= MAX_USE_DEPTH {
            return Err(self.error(
                node,
                format!("<use> elements nest deeper than {MAX_USE_DEPTH}"),
            ));
        }
        let x = self.length(node, "x", Axis::X, context).unwrap_or(0.0);
        let y = self.length(node, "y", Axis::Y, context).unwrap_or(0.0);
        let width = self.length(node, "width", Axis::X, context);
        let height = self.length(node, "height", Axis::Y, context);
        let mut inner = context;
        inner.matrix = compose(&context.matrix, &[1.0, 0.0, 0.0, 1.0, x, y]);
        self.uses.push(node.id());
        let result = if is_svg(&target, "symbol") {
            if self.sheets.property(target, "display").as_deref() == Some("none") {
                self.count(target, SkipReason::Hidden, None);
                Ok(())
            } else {
                let inner = self.inherit(target, inner);
                let size = [
                    width.unwrap_or(inner.viewport[0]),
                    height.unwrap_or(inner.viewport[1]),
                ];
                self.viewbox_content(target, inner, [0.0, 0.0], size)
            }
        } else if is_svg(&target, "svg") {
            if self.sheets.property(target, "display").as_deref() == Some("none") {
                self.count(target, SkipReason::Hidden, None);
                Ok(())
            } else {
                let inner = self.inherit(target, inner);
                self.viewport(target, inner, Some([width, height]))
            }
        } else {
            self.element(target, inner)
        };
        self.uses.pop();
        result
    }

    /// A shape element: its subpaths as curves.
    fn shape(&mut self, node: Node<'a, 'input>, context: Context) -> Result<(), ReadError> {
        let name = node.tag_name().name();
        let what = kind(node);
        if !self.options.wants(name) {
            self.report.skip(&what, SkipReason::Excluded);
            return Ok(());
        }
        if !context.visible {
            self.report.skip(&what, SkipReason::Hidden);
            return Ok(());
        }
        let [a, b, c, d, ..] = context.matrix;
        if a * d - b * c == 0.0 {
            // A transform that flattens the plane to a line or a point draws nothing
            // (resvg's zeroed-matrix test).
            self.report.skip(&what, SkipReason::Empty);
            return Ok(());
        }
        let subpaths = self.subpaths(node, context);
        if subpaths.is_empty() {
            self.report.skip(&what, SkipReason::Empty);
            return Ok(());
        }
        let count = subpaths.len();
        for segments in subpaths {
            let curve = super::curve(&segments, &context.matrix, self.options.defaults)
                .map_err(|m| self.error(node, m))?;
            let points = neutrospline::ControlPolygon::len(&curve) as u64;
            if points > self.limits.max_control_points {
                return Err(self.error(node, self.limits.too_many_control_points()));
            }
            self.control_points += points;
            if self.control_points > self.limits.max_control_points.saturating_mul(16) {
                return Err(self.error(
                    node,
                    format!(
                        "the file's curves hold more than {} control points in all (16 times \
                         the limit of one curve; raise it with --max-control-points)",
                        self.limits.max_control_points.saturating_mul(16)
                    ),
                ));
            }
            let mut model = Model::new(curve);
            if let Some(id) = node.attribute("id") {
                model = model.with_name(id);
            }
            self.models.push(model);
        }
        self.report.imported_many(&what, count);
        Ok(())
    }

    /// The subpaths of a shape element, each a list of segments; errors in its data are
    /// reported and the shape drawn up to them.
    fn subpaths(&mut self, node: Node<'a, 'input>, context: Context) -> Vec<Vec<Segment>> {
        let name = node.tag_name().name();
        let warn = |walker: &mut Self, message: String| {
            let named = walker.named(node);
            walker.report.warn(format!("{named}: {message}"));
        };
        let number = |walker: &mut Self, attribute: &str, axis: Axis| {
            walker.length(node, attribute, axis, context)
        };
        match name {
            "path" => {
                let Some(d) = node.attribute("d") else {
                    return Vec::new();
                };
                let data = path_data(d);
                if let Some(e) = data.error {
                    let kept: usize = data.subpaths.iter().map(Vec::len).sum();
                    warn(self, format!("d: {e}; drawn up to it ({kept} segment{} kept), as the SVG specification says", if kept == 1 { "" } else { "s" }));
                }
                data.subpaths
            }
            "polyline" | "polygon" => {
                let (mut points, error) = point_list(node.attribute("points").unwrap_or(""));
                if let Some(e) = error {
                    warn(
                        self,
                        format!(
                            "points: {e}; drawn up to it ({} point{} kept)",
                            points.len(),
                            if points.len() == 1 { "" } else { "s" }
                        ),
                    );
                }
                if name == "polygon" && points.len() > 1 && points.first() != points.last() {
                    points.push(points[0]);
                }
                let segments: Vec<Segment> = points
                    .windows(2)
                    .map(|w| Segment::polynomial(w.to_vec()))
                    .collect();
                if segments.is_empty() {
                    Vec::new()
                } else {
                    vec![segments]
                }
            }
            "line" => {
                let x1 = number(self, "x1", Axis::X).unwrap_or(0.0);
                let y1 = number(self, "y1", Axis::Y).unwrap_or(0.0);
                let x2 = number(self, "x2", Axis::X).unwrap_or(0.0);
                let y2 = number(self, "y2", Axis::Y).unwrap_or(0.0);
                if [x1, y1] == [x2, y2] {
                    Vec::new()
                } else {
                    vec![vec![Segment::polynomial(vec![[x1, y1], [x2, y2]])]]
                }
            }
            "rect" => {
                let x = number(self, "x", Axis::X).unwrap_or(0.0);
                let y = number(self, "y", Axis::Y).unwrap_or(0.0);
                let w = number(self, "width", Axis::X).unwrap_or(0.0);
                let h = number(self, "height", Axis::Y).unwrap_or(0.0);
                if w < 0.0 || h < 0.0 {
                    warn(
                        self,
                        format!("a negative width or height ({w} x {h}) is an error; not drawn"),
                    );
                    return Vec::new();
                }
                if w == 0.0 || h == 0.0 {
                    return Vec::new();
                }
                // SVG 2, section 10.2: an auto (absent or negative) radius takes the other's
                // value; each is clamped to half its side.
                let given = |v: Option<f64>| v.filter(|r| *r >= 0.0);
                let rx = number(self, "rx", Axis::X);
                let ry = number(self, "ry", Axis::Y);
                let (rx, ry) = (given(rx), given(ry));
                let (rx, ry) = match (rx, ry) {
                    (Some(a), Some(b)) => (a, b),
                    (Some(a), None) => (a, a),
                    (None, Some(b)) => (b, b),
                    (None, None) => (0.0, 0.0),
                };
                vec![rectangle(x, y, w, h, [rx.min(w / 2.0), ry.min(h / 2.0)])]
            }
            "circle" => {
                let cx = number(self, "cx", Axis::X).unwrap_or(0.0);
                let cy = number(self, "cy", Axis::Y).unwrap_or(0.0);
                let r = number(self, "r", Axis::Diagonal).unwrap_or(0.0);
                if r < 0.0 {
                    warn(
                        self,
                        format!("a negative radius ({r}) is an error; not drawn"),
                    );
                }
                if r > 0.0 {
                    vec![ellipse([cx, cy], [r, r])]
                } else {
                    Vec::new()
                }
            }
            "ellipse" => {
                let cx = number(self, "cx", Axis::X).unwrap_or(0.0);
                let cy = number(self, "cy", Axis::Y).unwrap_or(0.0);
                let rx = number(self, "rx", Axis::X).filter(|r| *r >= 0.0);
                let ry = number(self, "ry", Axis::Y).filter(|r| *r >= 0.0);
                // SVG 2, section 10.4: an auto radius takes the other's value.
                let (rx, ry) = match (rx, ry) {
                    (Some(a), Some(b)) => (a, b),
                    (Some(a), None) => (a, a),
                    (None, Some(b)) => (b, b),
                    (None, None) => (0.0, 0.0),
                };
                if rx > 0.0 && ry > 0.0 {
                    vec![ellipse([cx, cy], [rx, ry])]
                } else {
                    Vec::new()
                }
            }
            _ => Vec::new(),
        }
    }
}

/// Whether a child of `<switch>` passes its conditions (SVG 1.1, section 5.8): no
/// `requiredExtensions` (this reader supports none), `systemLanguage` naming English (the
/// language this reader assumes) when given; `requiredFeatures` always passes (SVG 2).
fn passes_conditions(node: Node<'_, '_>) -> bool {
    if node.attribute("requiredExtensions").is_some() {
        return false;
    }
    match node.attribute("systemLanguage") {
        Some(languages) => languages
            .split(',')
            .map(str::trim)
            .any(|l| l == "en" || l.starts_with("en-")),
        None => true,
    }
}
