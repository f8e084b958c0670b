//! What an import read and what it left: [`Import`] (the models and the [`ImportReport`]) and
//! the import's options, [`ImportRequest`], defined once for the command line and Python
//! (docs/architecture.md, "one definition of every option").
//!
//! An importer never drops a drawn shape silently: every element or entity it meets is either
//! imported (counted by kind), or recorded as a [`Skip`] with its [`SkipReason`], or, when it
//! was read only in part (an SVG path whose data breaks off), imported with a warning that
//! names the element and the position.
//!
//! ```
//! use neutrospline_exchange::{ImportReport, SkipReason};
//! let mut report = ImportReport::default();
//! report.imported("<path>");
//! report.imported("<path>");
//! report.imported("<rect>");
//! report.skip("<text>", SkipReason::NotACurve);
//! report.skip("<path>", SkipReason::Hidden);
//! assert_eq!(report.curve_count(), 3);
//! assert_eq!(
//!     report.summary(),
//!     "imported 3 curves (2 <path>, 1 <rect>); skipped 1 <text> (not a curve); \
//!      hidden: 1 <path> (not displayed)"
//! );
//! // --strict refuses a drawn shape that was not imported; hidden ones are not drawn.
//! assert_eq!(report.strict_violations(), ["skipped 1 <text> (not a curve)"]);
//! ```

use std::collections::BTreeSet;

use neutrospline::options::{
    find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind,
};
use neutrospline::Degrees;
use neutrospline_io::{InputError, Model, ReadError};

/// Why an element or entity was not imported.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SkipReason {
    /// Drawn, but not a curve: text, images, hatches, dimensions, points.
    NotACurve,
    /// Drawn, a curve, but of a form this importer cannot read exactly (a DXF spline given by
    /// fit points only, a 3-D entity such as a mesh).
    Unsupported,
    /// Not drawn: `display:none` or `visibility:hidden` in SVG; a layer turned off or frozen
    /// in DXF.
    Hidden,
    /// Not drawn where it stands: the content of SVG `<defs>`, `<clipPath>`, `<mask>`,
    /// `<marker>`, `<pattern>` and of a `<symbol>` that no `<use>` draws; a DXF block that no
    /// INSERT draws.
    NotDrawn,
    /// Draws nothing: a path without a segment, a rectangle or circle of size zero, a line of
    /// length zero.
    Empty,
    /// Left out by the `entities` option.
    Excluded,
}

impl SkipReason {
    /// Every reason, in the order a summary lists them.
    pub const ALL: [SkipReason; 6] = [
        SkipReason::NotACurve,
        SkipReason::Unsupported,
        SkipReason::Hidden,
        SkipReason::NotDrawn,
        SkipReason::Empty,
        SkipReason::Excluded,
    ];

    /// The reason's name in summaries and in Python's report (`not-a-curve`, `hidden`, ...).
    pub fn name(self) -> &'static str {
        match self {
            SkipReason::NotACurve => "not-a-curve",
            SkipReason::Unsupported => "unsupported",
            SkipReason::Hidden => "hidden",
            SkipReason::NotDrawn => "not-drawn",
            SkipReason::Empty => "empty",
            SkipReason::Excluded => "excluded",
        }
    }

    /// Whether `--strict` refuses it: a drawn shape that was not imported.
    pub fn is_drawn(self) -> bool {
        matches!(self, SkipReason::NotACurve | SkipReason::Unsupported)
    }
}

/// One kind of element or entity left out for one reason, with how many.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Skip {
    /// The kind: an SVG element as `<text>`, a DXF entity as `TEXT`.
    pub kind: String,
    /// Why.
    pub reason: SkipReason,
    /// How many.
    pub count: usize,
}

/// What an import read and what it left, for one file: every element or entity is imported,
/// skipped with its reason, or imported with a warning.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ImportReport {
    /// The curves imported by the kind of element or entity they came from (`<path>`,
    /// `LWPOLYLINE`), in the order the kinds were first met.
    pub imported: Vec<(String, usize)>,
    /// What was not imported, by kind and reason, in the order first met.
    pub skipped: Vec<Skip>,
    /// Shapes imported in part, or read with a repair, each message naming the element or
    /// entity (its line) and what was left.
    pub warnings: Vec<String>,
}

/// `count kind` items joined by `, `.
fn counted<'a>(items: impl Iterator<Item = (&'a str, usize)>) -> String {
    items
        .map(|(kind, count)| format!("{count} {kind}"))
        .collect::<Vec<_>>()
        .join(", ")
}

impl ImportReport {
    /// Counts one curve imported from an element or entity of `kind`.
    pub fn imported(&mut self, kind: &str) {
        self.imported_many(kind, 1);
    }

    /// Counts `count` curves imported from elements or entities of `kind`.
    pub fn imported_many(&mut self, kind: &str, count: usize) {
        if count == 0 {
            return;
        }
        match self.imported.iter_mut().find(|(k, _)| k == kind) {
            Some((_, n)) => *n += count,
            None => self.imported.push((kind.to_owned(), count)),
        }
    }

    /// Records one element or entity of `kind` left out for `reason`.
    pub fn skip(&mut self, kind: &str, reason: SkipReason) {
        self.skip_many(kind, reason, 1);
    }

    /// Records `count` elements or entities of `kind` left out for `reason`.
    pub fn skip_many(&mut self, kind: &str, reason: SkipReason, count: usize) {
        if count == 0 {
            return;
        }
        match self
            .skipped
            .iter_mut()
            .find(|s| s.kind == kind && s.reason == reason)
        {
            Some(s) => s.count += count,
            None => self.skipped.push(Skip {
                kind: kind.to_owned(),
                reason,
                count,
            }),
        }
    }

    /// Records a warning (a message naming the element or entity).
    pub fn warn(&mut self, message: impl Into<String>) {
        self.warnings.push(message.into());
    }

    /// The number of curves imported.
    pub fn curve_count(&self) -> usize {
        self.imported.iter().map(|(_, n)| n).sum()
    }

    /// The number of elements or entities left out for `reason`.
    pub fn skipped_count(&self, reason: SkipReason) -> usize {
        self.skipped
            .iter()
            .filter(|s| s.reason == reason)
            .map(|s| s.count)
            .sum()
    }

    /// The kinds left out for `reason`, as `count kind` items.
    fn listed(&self, reason: SkipReason) -> String {
        counted(
            self.skipped
                .iter()
                .filter(|s| s.reason == reason)
                .map(|s| (s.kind.as_str(), s.count)),
        )
    }

    /// One line: `imported 12 curves (10 <path>, 2 <rect>); skipped 3 <text> (not a curve);
    /// hidden: 14 <path> (not displayed); not drawn: 2 <path> in <clipPath> (definitions never
    /// used); ...; 1 warning: ...`. An importer may qualify a kind (`<path> in <clipPath>`).
    pub fn summary(&self) -> String {
        let count = self.curve_count();
        let mut parts = vec![if count == 0 {
            "imported no curve".to_owned()
        } else {
            format!(
                "imported {count} curve{} ({})",
                if count == 1 { "" } else { "s" },
                counted(self.imported.iter().map(|(k, n)| (k.as_str(), *n)))
            )
        }];
        for reason in SkipReason::ALL {
            if self.skipped_count(reason) == 0 {
                continue;
            }
            let list = self.listed(reason);
            parts.push(match reason {
                SkipReason::NotACurve => format!("skipped {list} (not a curve)"),
                SkipReason::Unsupported => {
                    format!("skipped {list} (a curve this importer cannot read exactly)")
                }
                SkipReason::Hidden => format!("hidden: {list} (not displayed)"),
                SkipReason::NotDrawn => format!("not drawn: {list} (definitions never used)"),
                SkipReason::Empty => format!("empty: {list} (draws nothing)"),
                SkipReason::Excluded => format!("excluded by --entities: {list}"),
            });
        }
        match self.warnings.len() {
            0 => {}
            1 => parts.push(format!("1 warning: {}", self.warnings[0])),
            n => parts.push(format!("{n} warnings: {}", self.warnings.join("; "))),
        }
        parts.join("; ")
    }

    /// What `--strict` refuses: every drawn shape that was not imported (not a curve, or a
    /// curve this importer cannot read) and every warning. Hidden, not drawn, empty and
    /// excluded shapes are not refused: the import draws what the file draws.
    pub fn strict_violations(&self) -> Vec<String> {
        let mut out = Vec::new();
        for reason in [SkipReason::NotACurve, SkipReason::Unsupported] {
            if self.skipped_count(reason) > 0 {
                out.push(format!(
                    "skipped {} ({})",
                    self.listed(reason),
                    if reason == SkipReason::NotACurve {
                        "not a curve"
                    } else {
                        "a curve this importer cannot read exactly"
                    }
                ));
            }
        }
        out.extend(self.warnings.iter().map(|w| format!("warning: {w}")));
        out
    }
}

/// The models an import read, in file order, and its [`ImportReport`].
#[derive(Clone, Debug, PartialEq)]
pub struct Import {
    /// One model per curve.
    pub models: Vec<Model>,
    /// What was read and what was left.
    pub report: ImportReport,
}

impl Import {
    /// The import when `--strict` holds, or an error naming `file` and everything it refuses
    /// ([`ImportReport::strict_violations`]).
    ///
    /// # Errors
    /// [`ReadError::Input`] listing the violations.
    pub fn strict(self, file: &str) -> Result<Import, ReadError> {
        let violations = self.report.strict_violations();
        if violations.is_empty() {
            Ok(self)
        } else {
            Err(InputError::new(
                file,
                None,
                None,
                format!(
                    "--strict: the import leaves out what the file draws: {}",
                    violations.join("; ")
                ),
            )
            .into())
        }
    }
}

/// The entity kinds the DXF importer reads (the `entities` option's names for a DXF file).
pub const DXF_ENTITIES: &[&str] = &[
    "SPLINE",
    "LINE",
    "ARC",
    "CIRCLE",
    "ELLIPSE",
    "LWPOLYLINE",
    "POLYLINE",
];

/// The elements the SVG importer reads (the `entities` option's names for an SVG file).
pub const SVG_ELEMENTS: &[&str] = &[
    "path", "polyline", "polygon", "line", "rect", "circle", "ellipse",
];

/// The options of an import, defined once for the command line and Python: the default
/// degrees (`truth`, `indeterminacy`, `falsity`) of every control point without degrees in
/// the file, `entities` (the kinds to import, comma-separated: DXF entity names such as
/// `SPLINE,LWPOLYLINE` or SVG element names such as `path,rect`; all when unset) and `strict`
/// (refuse the file when the import leaves out a drawn shape).
///
/// ```
/// use neutrospline::options::{OptionSet, OptionValue};
/// use neutrospline_exchange::{ImportRequest, SourceFormat};
/// let mut request = ImportRequest::default();
/// request.set("entities", OptionValue::Word("spline, lwpolyline".into()))?;
/// let kinds = request.entities_for(SourceFormat::Dxf)?.unwrap();
/// assert!(kinds.contains("SPLINE") && kinds.contains("LWPOLYLINE") && kinds.len() == 2);
/// request.set("entities", OptionValue::Word("TEXT".into()))?;
/// assert_eq!(
///     request.entities_for(SourceFormat::Dxf).unwrap_err().to_string(),
///     "entities = TEXT: not an entity kind the DXF importer reads (one of SPLINE, LINE, ARC, \
///      CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE)"
/// );
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ImportRequest {
    /// `truth` (default 1).
    pub truth: f64,
    /// `indeterminacy` (default 0).
    pub indeterminacy: f64,
    /// `falsity` (default 0).
    pub falsity: f64,
    /// `entities`: the kinds to import, as given (comma-separated); `None` for all.
    pub entities: Option<String>,
    /// `strict`: refuse a file whose import leaves out a drawn shape.
    pub strict: bool,
}

impl Default for ImportRequest {
    fn default() -> Self {
        ImportRequest {
            truth: 1.0,
            indeterminacy: 0.0,
            falsity: 0.0,
            entities: None,
            strict: false,
        }
    }
}

/// The format an import reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SourceFormat {
    /// A DXF drawing.
    Dxf,
    /// An SVG drawing.
    Svg,
}

impl OptionSet for ImportRequest {
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "truth",
            kind: ValueKind::Number,
            value_name: "T",
            help: "Truth of every control point without degrees in the file",
        },
        OptionSpec {
            name: "indeterminacy",
            kind: ValueKind::Number,
            value_name: "I",
            help: "Indeterminacy of every control point without degrees in the file",
        },
        OptionSpec {
            name: "falsity",
            kind: ValueKind::Number,
            value_name: "F",
            help: "Falsity of every control point without degrees in the file",
        },
        OptionSpec {
            name: "entities",
            kind: ValueKind::Text,
            value_name: "KINDS",
            help: "The kinds to import, comma-separated: DXF entities (SPLINE, LINE, ARC, \
                   CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE) or SVG elements (path, polyline, \
                   polygon, line, rect, circle, ellipse); all when not given",
        },
        OptionSpec {
            name: "strict",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Refuse the file when the import leaves out a shape it draws (a kind it \
                   cannot read, a path read only in part)",
        },
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let read = spec.read(&value)?;
        match (spec.name, read) {
            ("truth", Read::Number(x)) => self.truth = x,
            ("indeterminacy", Read::Number(x)) => self.indeterminacy = x,
            ("falsity", Read::Number(x)) => self.falsity = x,
            ("entities", Read::Text(text)) => self.entities = Some(text),
            ("strict", Read::Flag(on)) => self.strict = on,
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        Ok(match spec.name {
            "truth" => Some(self.truth.to_string()),
            "indeterminacy" => Some(self.indeterminacy.to_string()),
            "falsity" => Some(self.falsity.to_string()),
            "entities" => self.entities.clone(),
            "strict" => Some(self.strict.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

/// The resolved options of one import: what [`ImportRequest::options`] makes of the request
/// for a file's format, and what the importers take.
#[derive(Clone, Debug, PartialEq)]
pub struct ImportOptions {
    /// The degrees of every control point without degrees in the file.
    pub defaults: Degrees,
    /// The kinds to import (DXF upper case, SVG lower case without the brackets); `None` for
    /// all.
    pub entities: Option<BTreeSet<String>>,
}

impl ImportOptions {
    /// Every kind, with the degrees `defaults`.
    pub fn new(defaults: Degrees) -> Self {
        ImportOptions {
            defaults,
            entities: None,
        }
    }

    /// Whether the kind `name` (DXF `LINE`, SVG `rect`) is imported.
    pub fn wants(&self, name: &str) -> bool {
        self.entities.as_ref().is_none_or(|set| set.contains(name))
    }
}

impl ImportRequest {
    /// The options of an import of a file of `format`.
    ///
    /// # Errors
    /// As [`ImportRequest::defaults`] and [`ImportRequest::entities_for`].
    pub fn options(&self, format: SourceFormat) -> Result<ImportOptions, OptionError> {
        Ok(ImportOptions {
            defaults: self.defaults()?,
            entities: self.entities_for(format)?,
        })
    }

    /// The degrees of every control point without degrees in the file.
    ///
    /// # Errors
    /// [`OptionError::Data`] naming the three options and the rule the degrees break.
    pub fn defaults(&self) -> Result<Degrees, OptionError> {
        Degrees::new(self.truth, self.indeterminacy, self.falsity)
            .map_err(|e| OptionError::Data(format!("truth, indeterminacy, falsity: {e}")))
    }

    /// The kinds to import from a file of `format`, in the importer's spelling (DXF upper
    /// case, SVG lower case), or `None` for all.
    ///
    /// # Errors
    /// [`OptionError::Data`] for a name that is not a kind the format's importer reads, or no
    /// name at all.
    pub fn entities_for(
        &self,
        format: SourceFormat,
    ) -> Result<Option<BTreeSet<String>>, OptionError> {
        let Some(text) = &self.entities else {
            return Ok(None);
        };
        let (known, what, spelled): (&[&str], &str, fn(&str) -> String) = match format {
            SourceFormat::Dxf => (
                DXF_ENTITIES,
                "an entity kind the DXF importer reads",
                str::to_ascii_uppercase,
            ),
            SourceFormat::Svg => (
                SVG_ELEMENTS,
                "an element the SVG importer reads",
                str::to_ascii_lowercase,
            ),
        };
        let mut out = BTreeSet::new();
        for word in text.split(',').map(str::trim).filter(|w| !w.is_empty()) {
            let name = spelled(word.trim_start_matches('<').trim_end_matches('>'));
            if !known.contains(&name.as_str()) {
                return Err(OptionError::Data(format!(
                    "entities = {word}: not {what} (one of {})",
                    known.join(", ")
                )));
            }
            out.insert(name);
        }
        if out.is_empty() {
            return Err(OptionError::Data(format!(
                "entities = {text:?}: no kind given (one or more of {}, comma-separated)",
                known.join(", ")
            )));
        }
        Ok(Some(out))
    }
}
