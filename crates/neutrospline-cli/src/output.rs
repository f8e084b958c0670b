//! Writing results: numeric tables as CSV or JSON, aligned text tables, and the choice between
//! standard output and an atomically replaced file.

use std::fs::{self, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::Path;

use anyhow::Context as _;
use neutrospline_io::AtomicFile;

/// The formats of `eval`'s table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TableFormat {
    /// A header row then one comma-separated row per parameter.
    Csv,
    /// An array of objects, one per parameter, keyed by column name.
    Json,
}

pub use neutrospline_io::{format_number as number, push_number};

/// A number rounded to `decimals` places for reading, without trailing zeros (`-0` prints `0`).
pub fn rounded(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

/// A cell of a table: a number (or a missing value), or a word (a name from a fixed list, such
/// as an intersection's contact, written as it is in CSV and as a JSON string).
pub trait TableCell {
    /// Appends the cell as CSV.
    fn push_csv(&self, line: &mut Vec<u8>);
    /// Appends the cell as a JSON value.
    fn push_json(&self, line: &mut Vec<u8>);
}

impl TableCell for Option<f64> {
    fn push_csv(&self, line: &mut Vec<u8>) {
        if let Some(v) = self {
            push_number(line, *v);
        }
    }

    fn push_json(&self, line: &mut Vec<u8>) {
        match self {
            Some(v) => push_number(line, *v),
            None => line.extend_from_slice(b"null"),
        }
    }
}

/// A numeric cell or a word (see [`TableCell`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A number.
    Number(f64),
    /// A word: letters, digits and `-` only, so that CSV needs no quotes.
    Word(&'static str),
}

impl TableCell for Cell {
    fn push_csv(&self, line: &mut Vec<u8>) {
        match self {
            Cell::Number(v) => push_number(line, *v),
            Cell::Word(w) => line.extend_from_slice(w.as_bytes()),
        }
    }

    fn push_json(&self, line: &mut Vec<u8>) {
        match self {
            Cell::Number(v) => push_number(line, *v),
            Cell::Word(w) => line.extend_from_slice(json_string(w).as_bytes()),
        }
    }
}

/// Writes a numeric table. Rows are produced lazily, so that any number of samples streams.
///
/// CSV: the header, then one line per row. JSON: `[` then one object per row with the columns
/// as keys in column order, then `]`. A missing value (`None`) is an empty CSV cell or a JSON
/// `null`.
///
/// # Errors
/// The first error of `rows`, or a write error.
pub fn write_table<W: Write + ?Sized, C: TableCell>(
    w: &mut W,
    format: TableFormat,
    columns: &[String],
    rows: impl IntoIterator<Item = anyhow::Result<Vec<C>>>,
) -> anyhow::Result<()> {
    // Each row is formatted into one reused buffer and written with one call.
    let mut line: Vec<u8> = Vec::with_capacity(32 * columns.len());
    match format {
        TableFormat::Csv => {
            writeln!(w, "{}", columns.join(","))?;
            for row in rows {
                crate::signals::check()?;
                let row = row?;
                line.clear();
                for (i, value) in row.iter().enumerate() {
                    if i > 0 {
                        line.push(b',');
                    }
                    value.push_csv(&mut line);
                }
                line.push(b'\n');
                w.write_all(&line)?;
            }
        }
        TableFormat::Json => {
            let keys: Vec<String> = columns
                .iter()
                .map(|c| format!("{}: ", json_string(c)))
                .collect();
            write!(w, "[")?;
            let mut first = true;
            for row in rows {
                crate::signals::check()?;
                let row = row?;
                line.clear();
                line.extend_from_slice(if first { b"\n  {" } else { b",\n  {" });
                for (i, (key, value)) in keys.iter().zip(&row).enumerate() {
                    if i > 0 {
                        line.extend_from_slice(b", ");
                    }
                    line.extend_from_slice(key.as_bytes());
                    value.push_json(&mut line);
                }
                line.push(b'}');
                w.write_all(&line)?;
                first = false;
            }
            writeln!(w, "{}]", if first { "" } else { "\n" })?;
        }
    }
    Ok(())
}

/// A JSON string literal.
fn json_string(s: &str) -> String {
    serde_json::Value::String(s.to_owned()).to_string()
}

/// How a column of a text table is aligned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Align {
    /// Padded on the right (names).
    Left,
    /// Padded on the left (numbers).
    Right,
}

/// Writes an aligned text table: columns separated by two spaces, no trailing spaces.
///
/// # Errors
/// A write error.
pub fn write_text_table<W: Write + ?Sized>(
    w: &mut W,
    header: &[&str],
    align: &[Align],
    rows: &[Vec<String>],
) -> io::Result<()> {
    let widths: Vec<usize> = (0..header.len())
        .map(|c| {
            rows.iter()
                .filter_map(|r| r.get(c))
                .map(|s| s.chars().count())
                .chain([header[c].chars().count()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |cells: Vec<&str>| {
        let mut out = String::new();
        for (c, cell) in cells.iter().enumerate() {
            let width = widths.get(c).copied().unwrap_or(0);
            if c > 0 {
                out.push_str("  ");
            }
            match align.get(c).copied().unwrap_or(Align::Left) {
                Align::Left => out.push_str(&format!("{cell:<width$}")),
                Align::Right => out.push_str(&format!("{cell:>width$}")),
            }
        }
        out.trim_end().to_owned()
    };
    writeln!(w, "{}", line(header.to_vec()))?;
    for row in rows {
        writeln!(w, "{}", line(row.iter().map(String::as_str).collect()))?;
    }
    Ok(())
}

/// Runs `write` against standard output (`out` = `None`) or against a new version of the file
/// `out`, which replaces the old one only when everything was written.
///
/// The new version is written to a temporary file in the same directory, flushed to disk and
/// renamed over `out` (keeping the old file's permissions). On any error the temporary file is
/// removed and the old file is left untouched.
///
/// # Errors
/// The error of `write`, or an I/O error naming the file.
pub fn emit(
    out: Option<&Path>,
    write: impl FnOnce(&mut dyn Write) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    match out {
        None => {
            let stdout = io::stdout();
            let mut w = BufWriter::new(stdout.lock());
            write(&mut w)?;
            w.flush()?;
            Ok(())
        }
        Some(path) => {
            // Write through a symbolic link to its target, and into special files (a device
            // such as /dev/null, a FIFO) directly: renaming over them would replace them.
            if path.as_os_str().is_empty() {
                anyhow::bail!(": cannot write: an empty path");
            }
            let target = fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
            match fs::metadata(&target) {
                Ok(meta) if meta.is_dir() => {
                    anyhow::bail!("{}: cannot write: it is a directory", path.display())
                }
                Ok(meta) if !meta.is_file() && !meta.is_dir() => write_directly(path, write),
                _ => write_atomically(path, &target, write),
            }
        }
    }
}

fn write_directly(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let cannot = || format!("{}: cannot write", path.display());
    let file = OpenOptions::new()
        .write(true)
        .open(path)
        .with_context(cannot)?;
    let mut w = BufWriter::new(file);
    write(&mut w)?;
    w.flush().with_context(cannot)
}

/// Writes `target` (the resolved `path`, named in messages as given) through an
/// [`AtomicFile`]: a temporary file in the same directory, renamed over `target` at the end.
fn write_atomically(
    path: &Path,
    target: &Path,
    write: impl FnOnce(&mut dyn Write) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let shown = path.display();
    let cannot = || format!("{shown}: cannot write");
    if target.file_name().is_none() {
        anyhow::bail!("{shown}: not a file name");
    }
    // From here on SIGINT and SIGTERM only set a flag (checked between rows and before the
    // rename), so that an interruption removes the temporary file.
    crate::signals::install();
    let mut file = AtomicFile::create(target).with_context(cannot)?;
    let not_written = || format!("{shown}: not written");
    write(&mut file).map_err(|e| match e.downcast_ref::<crate::signals::Interrupted>() {
        Some(_) => e.context(not_written()),
        None => e,
    })?;
    file.sync_all().with_context(cannot)?;
    crate::signals::check().with_context(not_written)?;
    // Dropped on an error: the temporary file is removed and the old file left as it was.
    file.commit().with_context(cannot)
}

/// Whether `error` is (caused by) a closed pipe on the reading side, such as `| head -1`.
pub fn is_broken_pipe(error: &anyhow::Error) -> bool {
    error.chain().any(|cause| {
        cause
            .downcast_ref::<io::Error>()
            .is_some_and(|e| e.kind() == io::ErrorKind::BrokenPipe)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(format: TableFormat, rows: Vec<Vec<f64>>) -> String {
        table_with_gaps(
            format,
            rows.into_iter()
                .map(|r| r.into_iter().map(Some).collect())
                .collect(),
        )
    }

    fn table_with_gaps(format: TableFormat, rows: Vec<Vec<Option<f64>>>) -> String {
        let columns = vec!["t".to_owned(), "x".to_owned()];
        let mut out = Vec::new();
        write_table(&mut out, format, &columns, rows.into_iter().map(Ok)).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn rounded_trims() {
        assert_eq!(rounded(4.625, 6), "4.625");
        assert_eq!(rounded(4.0, 6), "4");
        assert_eq!(rounded(0.30000000000000004, 6), "0.3");
        assert_eq!(rounded(-1e-9, 6), "0");
        assert_eq!(rounded(1.23456789, 6), "1.234568");
    }

    #[test]
    fn write_table_csv() {
        assert_eq!(
            table(TableFormat::Csv, vec![vec![0.0, 1.5], vec![1.0, -2.0]]),
            "t,x\n0,1.5\n1,-2\n"
        );
    }

    #[test]
    fn write_table_json() {
        let s = table(TableFormat::Json, vec![vec![0.0, 1.5], vec![1.0, 1e-20]]);
        assert_eq!(
            s,
            "[\n  {\"t\": 0, \"x\": 1.5},\n  {\"t\": 1, \"x\": 0.00000000000000000001}\n]\n"
        );
        let v: serde_json::Value = serde_json::from_str(&s).unwrap();
        assert_eq!(v[1]["x"].as_f64(), Some(1e-20));
        assert_eq!(table(TableFormat::Json, vec![]), "[]\n");
    }

    #[test]
    fn write_table_missing_values() {
        let rows = vec![vec![Some(0.5), None]];
        assert_eq!(
            table_with_gaps(TableFormat::Csv, rows.clone()),
            "t,x\n0.5,\n"
        );
        assert_eq!(
            table_with_gaps(TableFormat::Json, rows),
            "[\n  {\"t\": 0.5, \"x\": null}\n]\n"
        );
    }

    #[test]
    fn write_text_table_aligns() {
        let mut out = Vec::new();
        write_text_table(
            &mut out,
            &["point", "x"],
            &[Align::Left, Align::Right],
            &[
                vec!["C0".into(), "1".into()],
                vec!["C10".into(), "12.5".into()],
            ],
        )
        .unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "point     x\nC0        1\nC10    12.5\n"
        );
    }

    #[test]
    fn emit_file_atomic_replaces_or_keeps() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        fs::write(&path, "old\n").unwrap();
        let err = emit(Some(&path), |w| {
            writeln!(w, "partial")?;
            anyhow::bail!("evaluation failed")
        })
        .unwrap_err();
        assert_eq!(err.to_string(), "evaluation failed");
        assert_eq!(fs::read_to_string(&path).unwrap(), "old\n");
        assert_eq!(
            fs::read_dir(dir.path()).unwrap().count(),
            1,
            "temp file left behind"
        );

        emit(Some(&path), |w| Ok(writeln!(w, "new")?)).unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new\n");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[cfg(unix)]
    #[test]
    fn emit_file_through_symlink_and_into_special_file() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.csv");
        let link = dir.path().join("link.csv");
        fs::write(&real, "old\n").unwrap();
        std::os::unix::fs::symlink(&real, &link).unwrap();
        emit(Some(&link), |w| Ok(writeln!(w, "new")?)).unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read_to_string(&real).unwrap(), "new\n");

        let null = Path::new("/dev/null");
        emit(Some(null), |w| Ok(writeln!(w, "discarded")?)).unwrap();
        assert!(!fs::metadata(null).unwrap().is_file(), "/dev/null replaced");
    }

    #[test]
    fn emit_file_into_missing_directory_fails_cleanly() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/out.csv");
        let err = emit(Some(&path), |w| Ok(writeln!(w, "x")?)).unwrap_err();
        assert!(format!("{err:#}").contains("cannot write"), "{err:#}");
    }

    #[test]
    fn broken_pipe_detected_through_context() {
        let e = anyhow::Error::from(io::Error::from(io::ErrorKind::BrokenPipe)).context("writing");
        assert!(is_broken_pipe(&e));
        assert!(!is_broken_pipe(&anyhow::anyhow!("other")));
    }
}
