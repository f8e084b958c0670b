//! [`TableInput`]: how a CSV table is read (delimiter, decimal comma, which columns are which
//! and which are left out, the sheet of a spreadsheet), the options of every command that reads one (`eval`, `check`,
//! `fit`, `query`, `plot --data`), defined once here for every front end.

use neutrospline::options::{
    find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind,
};

/// How a CSV table is read, set by name ([`OptionSet`]). The default reads what the project
/// writes: the delimiter found in the header row (a comma, else a tab, else a semicolon; a tab
/// for a `.tsv` file), a decimal point, every column named as the format names it.
///
/// ```
/// use neutrospline::options::{OptionSet, OptionValue};
/// use neutrospline_io::TableInput;
///
/// let mut input = TableInput::default();
/// input.set("columns", OptionValue::Word("truth=mu,falsity=nu".into()))?;
/// input.set("ignore-columns", OptionValue::Word("note".into()))?;
/// input.set("delimiter", OptionValue::Word("semicolon".into()))?;
/// input.set("decimal-comma", OptionValue::Flag(true))?;
/// assert_eq!(input.delimiter, Some(b';'));
/// assert_eq!(input.columns, [("truth".to_owned(), "mu".to_owned()), ("falsity".to_owned(), "nu".to_owned())]);
/// input.validate()?;
/// # Ok::<(), neutrospline::options::OptionError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TableInput {
    /// `delimiter`: the byte between cells; `None` finds it in the header row.
    pub delimiter: Option<u8>,
    /// `decimal-comma`: numbers are written with a decimal comma (`0,3`), as spreadsheets in
    /// many locales save them.
    pub decimal_comma: bool,
    /// `columns`: (our name, the file's heading) pairs: the file's column is read as ours.
    pub columns: Vec<(String, String)>,
    /// `ignore-columns`: headings of columns left out (each must be in the header).
    pub ignore_columns: Vec<String>,
    /// `ignore-unknown-columns`: leave out every column whose heading names no column of the
    /// table, instead of refusing the file.
    pub ignore_unknown_columns: bool,
    /// `sheet`: the sheet of a spreadsheet (`.xlsx`, `.xlsm`, `.xls`, `.ods`) to read; `None`
    /// reads the first. Refused for a CSV file, which has no sheets.
    pub sheet: Option<String>,
}

impl OptionSet for TableInput {
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "delimiter",
            kind: ValueKind::Text,
            value_name: "CHAR",
            help: "The character between cells: one character, or comma, semicolon, tab \
                   (default: found in the header row; a tab for .tsv files)",
        },
        OptionSpec {
            name: "decimal-comma",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Numbers have a decimal comma (0,3), as spreadsheets save CSV in many locales \
                   (the cells must then be separated by another character, such as ;)",
        },
        OptionSpec {
            name: "columns",
            kind: ValueKind::Text,
            value_name: "OURS=THEIRS,...",
            help: "Read the file's column THEIRS as our column OURS, e.g. truth=mu,falsity=nu",
        },
        OptionSpec {
            name: "ignore-columns",
            kind: ValueKind::Text,
            value_name: "A,B,...",
            help: "Leave out these columns of the file (each must be in its header)",
        },
        OptionSpec {
            name: "ignore-unknown-columns",
            kind: ValueKind::Flag,
            value_name: "",
            help: "Leave out every column whose heading is not a known column, instead of \
                   refusing the file",
        },
        OptionSpec {
            name: "sheet",
            kind: ValueKind::Text,
            value_name: "NAME",
            help: "The sheet of a .xlsx, .xlsm, .xls or .ods spreadsheet to read (default: the \
                   first)",
        },
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let given = value.to_string();
        match (spec.name, spec.read(&value)?) {
            ("delimiter", Read::Text(text)) => {
                self.delimiter = Some(parse_delimiter(&text).ok_or(OptionError::OutOfRange {
                    name: spec.name,
                    given,
                    rule: "a delimiter is one ASCII character other than a quote, a line end or \
                           #, or one of comma, semicolon, tab",
                })?);
            }
            ("decimal-comma", Read::Flag(on)) => self.decimal_comma = on,
            ("columns", Read::Text(text)) => {
                self.columns = list(&text)
                    .map(|pair| {
                        pair.split_once('=')
                            .map(|(ours, theirs)| {
                                (ours.trim().to_owned(), theirs.trim().to_owned())
                            })
                            .filter(|(ours, theirs)| !ours.is_empty() && !theirs.is_empty())
                    })
                    .collect::<Option<_>>()
                    .ok_or(OptionError::OutOfRange {
                        name: spec.name,
                        given,
                        rule: "expected pairs OURS=THEIRS separated by commas, such as \
                               truth=mu,falsity=nu",
                    })?;
            }
            ("ignore-columns", Read::Text(text)) => {
                self.ignore_columns = list(&text).map(str::to_owned).collect();
            }
            ("ignore-unknown-columns", Read::Flag(on)) => self.ignore_unknown_columns = on,
            ("sheet", Read::Text(text)) => {
                let name = text.trim();
                if name.is_empty() {
                    return Err(OptionError::OutOfRange {
                        name: spec.name,
                        given,
                        rule: "a sheet's name is not empty",
                    });
                }
                self.sheet = Some(name.to_owned());
            }
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        let joined = |items: Vec<String>| (!items.is_empty()).then(|| items.join(","));
        Ok(match spec.name {
            "delimiter" => self.delimiter.map(delimiter_name),
            "decimal-comma" => Some(self.decimal_comma.to_string()),
            "columns" => joined(
                self.columns
                    .iter()
                    .map(|(ours, theirs)| format!("{ours}={theirs}"))
                    .collect(),
            ),
            "ignore-columns" => joined(self.ignore_columns.clone()),
            "ignore-unknown-columns" => Some(self.ignore_unknown_columns.to_string()),
            "sheet" => self.sheet.clone(),
            other => unreachable!("option {other} has no value"),
        })
    }
}

impl TableInput {
    /// Checks that the options fit together: a decimal comma needs another delimiter.
    ///
    /// # Errors
    /// [`OptionError::Conflict`] for `decimal-comma` with the delimiter `,`.
    pub fn validate(&self) -> Result<(), OptionError> {
        if self.decimal_comma && self.delimiter == Some(b',') {
            return Err(OptionError::Conflict {
                first: "delimiter",
                second: "decimal-comma",
                rule: "with a decimal comma the cells must be separated by another character, \
                       such as ; or a tab",
            });
        }
        Ok(())
    }

    /// Our name for the file's `heading`, if `columns` maps it.
    pub(crate) fn ours(&self, heading: &str) -> Option<&str> {
        self.columns
            .iter()
            .find(|(_, t)| t.eq_ignore_ascii_case(heading))
            .map(|(o, _)| o.as_str())
    }

    /// Whether `ignore-columns` names `heading`.
    pub(crate) fn ignores(&self, heading: &str) -> bool {
        self.ignore_columns
            .iter()
            .any(|i| i.eq_ignore_ascii_case(heading))
    }
}

/// The comma-separated items of `text`, trimmed, empty ones dropped.
fn list(text: &str) -> impl Iterator<Item = &str> {
    text.split(',').map(str::trim).filter(|s| !s.is_empty())
}

/// The delimiter a word names: `comma`, `semicolon`, `tab` (or `\t`), or one ASCII character
/// other than a quote, a line end or `#` (the comment mark).
fn parse_delimiter(text: &str) -> Option<u8> {
    match text.to_ascii_lowercase().as_str() {
        "comma" => Some(b','),
        "semicolon" => Some(b';'),
        "tab" | "\\t" | "\t" => Some(b'\t'),
        _ => match text.as_bytes() {
            [b] if b.is_ascii() && !matches!(b, b'"' | b'\r' | b'\n' | b'#') => Some(*b),
            _ => None,
        },
    }
}

/// The delimiter as messages and defaults show it.
pub(crate) fn delimiter_name(delimiter: u8) -> String {
    match delimiter {
        b'\t' => "tab".to_owned(),
        b',' => "comma".to_owned(),
        b';' => "semicolon".to_owned(),
        b => char::from(b).to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_read_and_refuse() {
        let mut input = TableInput::default();
        input
            .set("delimiter", OptionValue::Word("\\t".into()))
            .unwrap();
        assert_eq!(input.delimiter, Some(b'\t'));
        assert_eq!(
            input.value_text("delimiter").unwrap().as_deref(),
            Some("tab")
        );
        assert_eq!(
            input
                .set("delimiter", OptionValue::Word("::".into()))
                .unwrap_err()
                .to_string(),
            "delimiter = ::: a delimiter is one ASCII character other than a quote, a line end \
             or #, or one of comma, semicolon, tab"
        );
        assert_eq!(
            input
                .set("columns", OptionValue::Word("truth:mu".into()))
                .unwrap_err()
                .to_string(),
            "columns = truth:mu: expected pairs OURS=THEIRS separated by commas, such as \
             truth=mu,falsity=nu"
        );
        input
            .set("delimiter", OptionValue::Word(",".into()))
            .unwrap();
        input.set("decimal-comma", OptionValue::Flag(true)).unwrap();
        assert_eq!(
            input.validate().unwrap_err().to_string(),
            "delimiter and decimal-comma exclude each other (with a decimal comma the cells \
             must be separated by another character, such as ; or a tab)"
        );
    }
}
