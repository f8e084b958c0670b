//! Numeric tables as the command line writes them (`eval`, `query`, `intersect`): CSV and JSON
//! with every digit, and LaTeX (booktabs) and Markdown for reading and for papers, with the
//! numbers rounded to what the computation justifies ([`format_justified`]) or to `--digits`
//! significant digits ([`format_significant`]).
//!
//! [`TableOutput`] holds the two options, `format` and `digits`, defined once here for every
//! front end ([`OptionSet`]); [`write_table`] writes a table with them.
//!
//! ```
//! use neutrospline::options::{OptionSet, OptionValue};
//! use neutrospline_io::{write_table, TableOutput};
//!
//! let mut output = TableOutput::default();
//! output.set("format", OptionValue::Word("latex".into()))?;
//! output.set("digits", OptionValue::Word("3".into()))?;
//! output.validate()?;
//! let columns = ["t".to_owned(), "truth".to_owned(), "indeterminacy".to_owned()];
//! let rows = vec![Ok::<_, std::io::Error>(vec![Some(0.5), Some(0.6), Some(1.0 - 0.6 - 0.3)])];
//! let mut text = Vec::new();
//! write_table(&mut text, &output, &columns, rows).unwrap();
//! assert_eq!(
//!     String::from_utf8(text).unwrap(),
//!     "\\begin{tabular}{rrr}\n\\toprule\n$t$ & $T$ & $I$ \\\\\n\\midrule\n\
//!      0.500 & 0.600 & 0.100 \\\\\n\\bottomrule\n\\end{tabular}\n"
//! );
//! # Ok::<(), neutrospline::options::OptionError>(())
//! ```

use std::io::{self, Write};

use neutrospline::options::{
    find, OptionError, OptionSet, OptionSpec, OptionValue, Read, ValueKind,
};

use crate::number::{format_justified, format_significant, push_number};

/// The formats of a numeric table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum TableFormat {
    /// A header row, then one comma-separated row per line of the table; every digit.
    #[default]
    Csv,
    /// An array of objects keyed by column name; every digit.
    Json,
    /// A booktabs `tabular` (no caption, no float) to `\input` into a LaTeX document: the
    /// headings typeset (`$t$`, `$T$`, `$x'$`), the numbers rounded.
    Latex,
    /// A Markdown (GitHub) table, the numbers rounded.
    Markdown,
}

impl TableFormat {
    /// Every format, in the order of [`TableFormat::NAMES`].
    pub const ALL: [TableFormat; 4] = [
        TableFormat::Csv,
        TableFormat::Json,
        TableFormat::Latex,
        TableFormat::Markdown,
    ];

    /// The names of the formats, as options spell them.
    pub const NAMES: [&'static str; 4] = ["csv", "json", "latex", "markdown"];

    /// The format's name (`csv`, `json`, `latex`, `markdown`).
    pub fn name(self) -> &'static str {
        match self {
            TableFormat::Csv => "csv",
            TableFormat::Json => "json",
            TableFormat::Latex => "latex",
            TableFormat::Markdown => "markdown",
        }
    }

    /// The format named `name` (case-insensitive).
    pub fn from_name(name: &str) -> Option<TableFormat> {
        TableFormat::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(name))
    }

    /// Whether the format rounds its numbers for reading (LaTeX, Markdown) rather than keeping
    /// every digit (CSV, JSON).
    pub fn rounds(self) -> bool {
        matches!(self, TableFormat::Latex | TableFormat::Markdown)
    }
}

/// The most significant digits `digits` may ask for: 17 tell every `f64` apart.
pub const MAX_DIGITS: usize = 17;

/// How a table is written: its `format` and, for LaTeX and Markdown, the significant `digits`
/// of its numbers; the options of every command that writes a table, set by name
/// ([`OptionSet`]). The default is CSV with every digit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TableOutput {
    /// `format`: csv, json, latex or markdown.
    pub format: TableFormat,
    /// `digits`: significant digits of every number of a LaTeX or Markdown table (trailing
    /// zeros kept); `None` rounds each number to what the computation justifies instead
    /// ([`format_justified`]).
    pub digits: Option<usize>,
}

impl OptionSet for TableOutput {
    const OPTIONS: &'static [OptionSpec] = &[
        OptionSpec {
            name: "format",
            kind: ValueKind::Choice(&TableFormat::NAMES),
            value_name: "FORMAT",
            help: "Table format: csv or json (every digit), latex (a booktabs tabular to \
                   \\input into a paper) or markdown (numbers rounded)",
        },
        OptionSpec {
            name: "digits",
            kind: ValueKind::Whole,
            value_name: "N",
            help: "latex and markdown: print every number with N significant digits, 1 to 17 \
                   (default: rounded to the precision the computation justifies)",
        },
    ];

    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        match (spec.name, spec.read(&value)?) {
            ("format", Read::Choice(word)) => {
                self.format = TableFormat::from_name(word)
                    .unwrap_or_else(|| unreachable!("{word} is one of TableFormat::NAMES"));
            }
            ("digits", Read::Whole(n)) => {
                if !(1..=MAX_DIGITS).contains(&n) {
                    return Err(OptionError::OutOfRange {
                        name: spec.name,
                        given: n.to_string(),
                        rule: "significant digits must be 1 to 17 (17 tell every 64-bit \
                               float apart)",
                    });
                }
                self.digits = Some(n);
            }
            (other, read) => unreachable!("option {other} read as {read:?}"),
        }
        Ok(())
    }

    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError> {
        let spec = find(Self::OPTIONS, name)?;
        Ok(match spec.name {
            "format" => Some(self.format.name().to_owned()),
            "digits" => self.digits.map(|n| n.to_string()),
            other => unreachable!("option {other} has no value"),
        })
    }
}

impl TableOutput {
    /// Checks that the options fit together: `digits` only with a format that rounds.
    ///
    /// # Errors
    /// [`OptionError::Conflict`] for `digits` with CSV or JSON.
    pub fn validate(&self) -> Result<(), OptionError> {
        if self.digits.is_some() && !self.format.rounds() {
            return Err(OptionError::Conflict {
                first: "format",
                second: "digits",
                rule: "csv and json keep every digit of every number; digits rounds the \
                       numbers of --format latex or markdown",
            });
        }
        Ok(())
    }

    /// A number as this output prints it in a column of magnitude `scale` (see
    /// [`write_table`]): every digit for CSV and JSON, else [`format_justified`], then
    /// [`format_significant`] with `digits`.
    pub fn number(&self, v: f64, scale: f64) -> String {
        if !self.format.rounds() {
            return crate::format_number(v);
        }
        let justified = format_justified(v, scale);
        match self.digits {
            // The justified text reads back exactly to the value it shows.
            Some(digits) => format_significant(justified.parse().unwrap_or(v), digits),
            None => justified,
        }
    }
}

/// One cell of a table, as [`TableCell::cell`] gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A number.
    Number(f64),
    /// A missing value: an empty CSV, LaTeX or Markdown cell, a JSON `null`.
    Missing,
    /// A word from a fixed list (letters, digits and `-` only, so that no format needs
    /// quotes), written as it is, and as a JSON string.
    Word(&'static str),
}

/// What a table's rows hold: a number or a missing value (`Option<f64>`), or a [`Cell`].
pub trait TableCell {
    /// The cell.
    fn cell(&self) -> Cell;
}

impl TableCell for Option<f64> {
    fn cell(&self) -> Cell {
        self.map_or(Cell::Missing, Cell::Number)
    }
}

impl TableCell for Cell {
    fn cell(&self) -> Cell {
        *self
    }
}

/// The columns whose values are degrees or their scores, computed from values in [0, 1]:
/// their precision is that of numbers of magnitude 1 ([`format_justified`] with scale 1),
/// whatever their own size.
fn is_degree_column(name: &str) -> bool {
    let base = name
        .strip_suffix("_a")
        .or_else(|| name.strip_suffix("_b"))
        .unwrap_or(name);
    matches!(
        base,
        "truth" | "indeterminacy" | "falsity" | "score" | "accuracy" | "certainty"
    )
}

/// Writes a table with `columns` and `rows` in the format of `output`.
///
/// CSV (the header, then one line per row) and JSON (`[`, one object per row with the columns
/// as keys in column order, `]`) are streamed, every number in its shortest round-trip form
/// ([`crate::format_number`]). LaTeX and Markdown are written once every row is read: each
/// number is rounded to the precision of its column ([`format_justified`]: 15 significant
/// digits of the column's largest magnitude, of 1 for the degrees and scores), then to
/// `output.digits` significant digits when given ([`format_significant`]), so that an
/// indeterminacy `1 - 0.6 - 0.3` prints `0.1`, not `0.09999999999999998`. LaTeX: a booktabs
/// `tabular` (`\toprule`, `\midrule`, `\bottomrule`; numbers right-aligned, words left; a
/// negative number as `$-0.5$`), headings typeset as the paper writes them (`$t$`, `$x$`,
/// `$T$`, `$I$`, `$F$`, `$x'$`, `$T_{uv}$`), no caption or float, for `\input` into a
/// document that loads `booktabs`. A missing value is an empty CSV, LaTeX or Markdown cell and
/// a JSON `null`.
///
/// # Errors
/// The first error of `rows`, or a write error.
pub fn write_table<W, C, E>(
    w: &mut W,
    output: &TableOutput,
    columns: &[String],
    rows: impl IntoIterator<Item = Result<Vec<C>, E>>,
) -> Result<(), E>
where
    W: Write + ?Sized,
    C: TableCell,
    E: From<io::Error>,
{
    match output.format {
        TableFormat::Csv => write_csv(w, columns, rows),
        TableFormat::Json => write_json(w, columns, rows),
        TableFormat::Latex | TableFormat::Markdown => {
            let rows = rows.into_iter().collect::<Result<Vec<_>, E>>()?;
            let text = rounded_table(output, columns, &rows);
            w.write_all(text.as_bytes())?;
            Ok(())
        }
    }
}

fn write_csv<W, C, E>(
    w: &mut W,
    columns: &[String],
    rows: impl IntoIterator<Item = Result<Vec<C>, E>>,
) -> Result<(), E>
where
    W: Write + ?Sized,
    C: TableCell,
    E: From<io::Error>,
{
    // Each row is formatted into one reused buffer and written with one call.
    let mut line: Vec<u8> = Vec::with_capacity(32 * columns.len());
    writeln!(w, "{}", columns.join(","))?;
    for row in rows {
        let row = row?;
        line.clear();
        for (i, value) in row.iter().enumerate() {
            if i > 0 {
                line.push(b',');
            }
            match value.cell() {
                Cell::Number(v) => push_number(&mut line, v),
                Cell::Missing => {}
                Cell::Word(word) => line.extend_from_slice(word.as_bytes()),
            }
        }
        line.push(b'\n');
        w.write_all(&line)?;
    }
    Ok(())
}

fn write_json<W, C, E>(
    w: &mut W,
    columns: &[String],
    rows: impl IntoIterator<Item = Result<Vec<C>, E>>,
) -> Result<(), E>
where
    W: Write + ?Sized,
    C: TableCell,
    E: From<io::Error>,
{
    let mut line: Vec<u8> = Vec::with_capacity(32 * columns.len());
    let keys: Vec<String> = columns
        .iter()
        .map(|c| format!("{}: ", json_string(c)))
        .collect();
    write!(w, "[")?;
    let mut first = true;
    for row in rows {
        let row = row?;
        line.clear();
        line.extend_from_slice(if first { b"\n  {" } else { b",\n  {" });
        for (i, (key, value)) in keys.iter().zip(&row).enumerate() {
            if i > 0 {
                line.extend_from_slice(b", ");
            }
            line.extend_from_slice(key.as_bytes());
            match value.cell() {
                Cell::Number(v) => push_number(&mut line, v),
                Cell::Missing => line.extend_from_slice(b"null"),
                Cell::Word(word) => line.extend_from_slice(json_string(word).as_bytes()),
            }
        }
        line.push(b'}');
        w.write_all(&line)?;
        first = false;
    }
    writeln!(w, "{}]", if first { "" } else { "\n" })?;
    Ok(())
}

/// A JSON string literal.
fn json_string(s: &str) -> String {
    serde_json::Value::String(s.to_owned()).to_string()
}

/// The LaTeX or Markdown text of a table whose rows are all read.
fn rounded_table<C: TableCell>(
    output: &TableOutput,
    columns: &[String],
    rows: &[Vec<C>],
) -> String {
    let scales: Vec<f64> = (0..columns.len())
        .map(|c| {
            if is_degree_column(&columns[c]) {
                return 1.0;
            }
            rows.iter()
                .filter_map(|row| match row.get(c).map(TableCell::cell) {
                    Some(Cell::Number(v)) => Some(v.abs()),
                    _ => None,
                })
                .fold(0.0, f64::max)
        })
        .collect();
    let words: Vec<bool> = (0..columns.len())
        .map(|c| {
            rows.iter()
                .any(|row| matches!(row.get(c).map(TableCell::cell), Some(Cell::Word(_))))
        })
        .collect();
    let latex = output.format == TableFormat::Latex;
    let text = |cell: Cell, scale: f64| match cell {
        Cell::Number(v) => {
            let number = output.number(v, scale);
            // A minus sign, not a hyphen.
            if latex && number.starts_with('-') {
                format!("${number}$")
            } else {
                number
            }
        }
        Cell::Missing => String::new(),
        Cell::Word(word) if latex => escape_latex(word),
        Cell::Word(word) => word.to_owned(),
    };
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|row| {
            row.iter()
                .zip(&scales)
                .map(|(value, &scale)| text(value.cell(), scale))
                .collect()
        })
        .collect();
    let mut out = String::new();
    if latex {
        let spec: String = words.iter().map(|&w| if w { 'l' } else { 'r' }).collect();
        out.push_str(&format!("\\begin{{tabular}}{{{spec}}}\n\\toprule\n"));
        let headings: Vec<String> = columns.iter().map(|c| latex_heading(c)).collect();
        out.push_str(&format!("{} \\\\\n\\midrule\n", headings.join(" & ")));
        for row in &body {
            out.push_str(&format!("{} \\\\\n", row.join(" & ")));
        }
        out.push_str("\\bottomrule\n\\end{tabular}\n");
    } else {
        let cells = |cells: Vec<String>| format!("| {} |\n", cells.join(" | "));
        out.push_str(&cells(
            columns.iter().map(|c| c.replace('|', "\\|")).collect(),
        ));
        out.push_str(&cells(
            words
                .iter()
                .map(|&w| if w { ":---" } else { "---:" }.to_owned())
                .collect(),
        ));
        for row in body {
            out.push_str(&cells(row));
        }
    }
    out
}

/// `text` with LaTeX's special characters escaped, for text mode.
fn escape_latex(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '~' => out.push_str("\\textasciitilde{}"),
            '^' => out.push_str("\\textasciicircum{}"),
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(c);
            }
            c => out.push(c),
        }
    }
    out
}

/// The symbol of a quantity in math mode: `x`, `T` for truth, `I`, `F`; `None` for a word
/// that is no symbol.
fn symbol(name: &str) -> Option<&'static str> {
    Some(match name {
        "t" => "t",
        "u" => "u",
        "v" => "v",
        "x" => "x",
        "y" => "y",
        "z" => "z",
        "truth" => "T",
        "indeterminacy" => "I",
        "falsity" => "F",
        _ => return None,
    })
}

/// A column's heading as a LaTeX table writes it: the paper's symbols in math mode (`$t$`,
/// `$x$`, `$T$` for truth, `$I$`, `$F$`; derivatives `$x'$`, `$T''$`, partials `$x_{u}$`,
/// `$T_{uv}$`; `$n_x$`, `$\kappa$`, `$x_{\mathrm{lo}}$`, `$t_a$`), other names as words
/// (`score`, `arc length`), escaped.
pub fn latex_heading(name: &str) -> String {
    let math = |body: String| format!("${body}$");
    if let Some(s) = symbol(name) {
        return math(s.to_owned());
    }
    match name {
        "curvature" => return math("\\kappa".to_owned()),
        "arc_length" => return "arc length".to_owned(),
        "nx" | "ny" | "nz" => return math(format!("n_{}", &name[1..])),
        _ => {}
    }
    // Surface partials: d{name}_d{uv...}.
    if let Some((base, partial)) = name
        .strip_prefix('d')
        .and_then(|rest| rest.split_once("_d"))
    {
        if let Some(s) = symbol(base) {
            if !partial.is_empty() && partial.chars().all(|c| c == 'u' || c == 'v') {
                return math(format!("{s}_{{{partial}}}"));
            }
        }
    }
    // Curve derivatives: d{name}, d2{name}, d3{name}.
    if let Some(rest) = name.strip_prefix('d') {
        let (order, base) = match rest.as_bytes().first() {
            Some(digit @ b'2'..=b'3') => (usize::from(digit - b'0'), &rest[1..]),
            _ => (1, rest),
        };
        if let Some(s) = symbol(base) {
            return math(format!("{s}{}", "'".repeat(order)));
        }
    }
    // Suffixed quantities: x_lo, x_hi, x_centroid, t_a, truth_b.
    if let Some((base, suffix)) = name.rsplit_once('_') {
        if let Some(s) = symbol(base) {
            return match suffix {
                "a" | "b" => math(format!("{s}_{suffix}")),
                _ => math(format!("{s}_{{\\mathrm{{{}}}}}", escape_latex(suffix))),
            };
        }
    }
    escape_latex(&name.replace('_', " "))
}

#[cfg(test)]
mod tests;
