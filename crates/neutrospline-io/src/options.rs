//! [`ReadOptions`]: what the caller says about the shape besides the file (the command line's
//! `--kind`, `--degree`, `--knots`, `--rows`, ..., `--membership`), and the limits.

use neutrospline::Family;

use crate::settings::{Key, KeyValue, Kind, KnotSpec};
use crate::{Format, Limits, ReadError, TableInput};

/// How to read a model: the shape settings a file does not hold, and the limits.
///
/// For a CSV file, which lists control points only, the settings are the only source of the
/// kind (default `bezier`), degree, knots, grid and membership rule. For a TOML or JSON model
/// they fill in what the file leaves out, and must agree with what it declares (a contradiction
/// is an error naming both). Messages name a setting by its command-line option (`--degree`).
///
/// ```
/// use neutrospline_io::{Kind, ReadOptions};
/// use neutrospline::CurveKind;
///
/// let mut options = ReadOptions::default();
/// options.kind = Some(Kind::Curve(CurveKind::BSpline));
/// options.degree = Some(2);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct ReadOptions {
    /// The membership rule of the degrees (`--membership`; default neutrosophic).
    pub membership: Option<Family>,
    /// The kind (`--kind`).
    pub kind: Option<Kind>,
    /// The degree of a curve (`--degree`).
    pub degree: Option<usize>,
    /// The knots of a B-spline or NURBS curve (`--knots`).
    pub knots: Option<KnotSpec>,
    /// A surface's control points along u (`--rows`).
    pub rows: Option<usize>,
    /// A surface's control points along v (`--cols`).
    pub cols: Option<usize>,
    /// A surface's degree along u (`--degree-u`).
    pub degree_u: Option<usize>,
    /// A surface's degree along v (`--degree-v`).
    pub degree_v: Option<usize>,
    /// A surface's knots along u (`--knots-u`).
    pub knots_u: Option<KnotSpec>,
    /// A surface's knots along v (`--knots-v`).
    pub knots_v: Option<KnotSpec>,
    /// Whether a B-spline or NURBS curve is periodic (closed; `--periodic`): the control
    /// points listed are the distinct ones and the knots are breakpoints
    /// (`KnotVector::periodic`).
    pub periodic: Option<bool>,
    /// Whether a surface is periodic along u (`--periodic-u`).
    pub periodic_u: Option<bool>,
    /// Whether a surface is periodic along v (`--periodic-v`).
    pub periodic_v: Option<bool>,
    /// The size limits.
    pub limits: Limits,
    /// How a CSV table is read: delimiter, decimal comma, columns mapped or left out
    /// (`--delimiter`, `--decimal-comma`, `--columns`, ...).
    pub table: TableInput,
}

impl ReadOptions {
    /// The value given for `key`, if any.
    pub(crate) fn get(&self, key: Key) -> Option<KeyValue> {
        let number = |v: Option<usize>| v.map(KeyValue::Number);
        let knots = |v: &Option<KnotSpec>| v.clone().map(KeyValue::Knots);
        match key {
            Key::Degree => number(self.degree),
            Key::Knots => knots(&self.knots),
            Key::Rows => number(self.rows),
            Key::Cols => number(self.cols),
            Key::DegreeU => number(self.degree_u),
            Key::DegreeV => number(self.degree_v),
            Key::KnotsU => knots(&self.knots_u),
            Key::KnotsV => knots(&self.knots_v),
            Key::Periodic => self.periodic.map(KeyValue::Flag),
            Key::PeriodicU => self.periodic_u.map(KeyValue::Flag),
            Key::PeriodicV => self.periodic_v.map(KeyValue::Flag),
        }
    }

    /// The first setting given that does not apply to `kind`, as a message.
    pub(crate) fn inapplicable(&self, kind: Kind) -> Option<String> {
        Key::ALL
            .into_iter()
            .find(|&key| self.get(key).is_some() && !key.applies_to(kind))
            .map(|key| {
                format!(
                    "{} does not apply to kind `{kind}` ({} is for: {})",
                    key.option(),
                    key.option(),
                    key.kinds_list()
                )
            })
    }

    /// Checks the settings among themselves, before any file is read: each must apply to the
    /// kind when it is given, and a CSV file (which declares nothing) needs the kind's required
    /// settings.
    pub(crate) fn check(&self, format: Format) -> Result<(), ReadError> {
        let kind = match (self.kind, format) {
            (Some(kind), _) => kind,
            (None, Format::Csv) => Kind::DEFAULT,
            (None, _) => return Ok(()),
        };
        if let Some(message) = self.inapplicable(kind) {
            let message = if self.kind.is_none() {
                format!("{message}; choose the kind with --kind")
            } else {
                message
            };
            return Err(ReadError::Options(message));
        }
        if format == Format::Csv {
            if let Some(key) = Key::ALL
                .into_iter()
                .find(|&k| k.required_for(kind) && self.get(k).is_none())
            {
                return Err(ReadError::Options(format!(
                    "kind `{kind}` needs {} for a CSV file ({}; a CSV file only lists control \
                     points)",
                    key.option(),
                    key.purpose()
                )));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use neutrospline::{CurveKind, SurfaceKind};

    #[test]
    fn options_inapplicable() {
        let o = ReadOptions {
            rows: Some(3),
            ..ReadOptions::default()
        };
        assert_eq!(
            o.inapplicable(Kind::Curve(CurveKind::BSpline)).unwrap(),
            "--rows does not apply to kind `bspline` (--rows is for: bezier-surface, bspline-surface, nurbs-surface)"
        );
        assert!(o.inapplicable(Kind::Surface(SurfaceKind::Bezier)).is_none());
    }

    #[test]
    fn options_check() {
        let o = ReadOptions {
            rows: Some(3),
            ..ReadOptions::default()
        };
        assert_eq!(
            o.check(Format::Csv).unwrap_err().to_string(),
            "--rows does not apply to kind `bezier` (--rows is for: bezier-surface, \
             bspline-surface, nurbs-surface); choose the kind with --kind"
        );
        assert!(o.check(Format::Toml).is_ok(), "the file declares the kind");
        let o = ReadOptions {
            kind: Some(Kind::Curve(CurveKind::Nurbs)),
            ..ReadOptions::default()
        };
        assert_eq!(
            o.check(Format::Csv).unwrap_err().to_string(),
            "kind `nurbs` needs --degree for a CSV file (the polynomial degree; a CSV file only \
             lists control points)"
        );
        assert!(o.check(Format::Json).is_ok());
    }
}
