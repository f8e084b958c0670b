//! Helpers shared by the modules: the binary under test, the repository's examples, and
//! running the binary in a directory.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The `neutrospline` binary built for these tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_neutrospline");

/// The repository's `examples/` directory.
pub fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The file `name` in the repository's `examples/` directory.
pub fn example(name: &str) -> PathBuf {
    examples_dir().join(name)
}

/// What a run of the binary gave.
pub struct Output {
    /// The exit code (a run ended by a signal fails the test).
    pub code: i32,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

/// Runs the binary in `dir` with `args` and, if given, `stdin` as standard input (else none);
/// fails on a panic or a backtrace on standard error.
pub fn run_in(dir: &Path, args: &[&str], stdin: Option<&[u8]>) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdin(if stdin.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    if let Some(bytes) = stdin {
        child
            .stdin
            .take()
            .expect("stdin piped")
            .write_all(bytes)
            .expect("stdin written");
    }
    let out = child.wait_with_output().expect("binary finishes");
    let result = Output {
        code: out.status.code().expect("exit code (no signal)"),
        stdout: String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(out.stderr).expect("stderr is UTF-8"),
    };
    assert!(
        !result.stderr.contains("panicked") && !result.stderr.contains("RUST_BACKTRACE"),
        "panic for {args:?}:\n{}",
        result.stderr
    );
    result
}

/// Runs the binary in `dir` with no standard input: (exit code, stdout, stderr).
pub fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = run_in(dir, args, None);
    (out.code, out.stdout, out.stderr)
}

/// Runs the binary in `dir` and expects exit 0 with nothing on stderr; returns stdout.
pub fn ok(dir: &Path, args: &[&str]) -> String {
    let (code, stdout, stderr) = run(dir, args);
    assert_eq!((code, stderr.as_str()), (0, ""), "{args:?}");
    stdout
}

/// Runs the binary in `dir` and expects exit 0 (standard error may hold a report); returns
/// the whole output.
pub fn succeeds(dir: &Path, args: &[&str]) -> Output {
    let out = run_in(dir, args, None);
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    out
}

/// The model file at `path`, read with the default options.
pub fn load_model(path: &Path) -> neutrospline_io::Model {
    neutrospline_io::load(path, &neutrospline_io::ReadOptions::default())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A temporary directory holding the given files (name, contents).
pub fn dir_with<C: AsRef<[u8]>>(files: &[(&str, C)]) -> tempfile::TempDir {
    dir_with_examples(&[], files)
}

/// A temporary directory holding copies of the named files of `examples/` and the given files.
pub fn dir_with_examples<C: AsRef<[u8]>>(
    examples: &[&str],
    files: &[(&str, C)],
) -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("temp dir");
    for name in examples {
        std::fs::copy(example(name), dir.path().join(name)).expect("example copied");
    }
    for (name, contents) in files {
        std::fs::write(dir.path().join(name), contents).expect("file written");
    }
    dir
}

/// The numbers of a CSV table without its header row, row by row.
pub fn rows(table: &str) -> Vec<Vec<f64>> {
    table
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect()
}

/// Writes `source` to `paper.tex` in `dir` and compiles it with pdflatex (failing the test
/// with pdflatex's log when it fails); returns the text of `paper.pdf` by pdftotext with
/// `pdftotext_args` (for example `-layout`).
pub fn compile_latex(dir: &Path, source: &str, pdftotext_args: &[&str]) -> String {
    std::fs::write(dir.join("paper.tex"), source).unwrap();
    let latex = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "paper.tex"])
        .current_dir(dir)
        .output()
        .unwrap();
    assert!(
        latex.status.success(),
        "{}",
        String::from_utf8_lossy(&latex.stdout)
    );
    let text = Command::new("pdftotext")
        .args(pdftotext_args)
        .args(["paper.pdf", "-"])
        .current_dir(dir)
        .output()
        .unwrap();
    String::from_utf8_lossy(&text.stdout).into_owned()
}
