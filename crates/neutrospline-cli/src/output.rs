//! Writing results: numeric tables as CSV or JSON, aligned text tables, and the choice between
//! standard output and an atomically replaced file.

use std::fs::{self, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::Path;

use anyhow::Context as _;
use neutrospline_io::AtomicFile;

pub use neutrospline_io::format_number as number;
use neutrospline_io::{TableCell, TableOutput};

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

/// Writes a numeric table with neutrospline-io's [`neutrospline_io::write_table`] (CSV and
/// JSON streamed; LaTeX and Markdown once every row is read), checking between rows for an
/// interruption (SIGINT, SIGTERM). Rows are produced lazily, so that any number of samples
/// streams.
///
/// # Errors
/// The first error of `rows`, an interruption, or a write error.
pub fn write_table<W: Write + ?Sized, C: TableCell>(
    w: &mut W,
    output: &TableOutput,
    columns: &[String],
    rows: impl IntoIterator<Item = anyhow::Result<Vec<C>>>,
) -> anyhow::Result<()> {
    let rows = rows.into_iter().map(|row| {
        crate::signals::check()?;
        row
    });
    neutrospline_io::write_table(w, output, columns, rows)
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

    #[test]
    fn rounded_trims() {
        assert_eq!(rounded(4.625, 6), "4.625");
        assert_eq!(rounded(4.0, 6), "4");
        assert_eq!(rounded(0.30000000000000004, 6), "0.3");
        assert_eq!(rounded(-1e-9, 6), "0");
        assert_eq!(rounded(1.23456789, 6), "1.234568");
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
