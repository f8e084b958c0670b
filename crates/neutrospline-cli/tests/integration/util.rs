//! Helpers shared by the modules: the binary under test, the repository's examples, and
//! running the binary in a directory.

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

/// Runs the binary in `dir` with no standard input: (exit code, stdout, stderr); fails on a
/// panic message.
pub fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("binary runs");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(!stderr.contains("panicked"), "panic for {args:?}: {stderr}");
    (
        out.status.code().expect("exit code"),
        String::from_utf8(out.stdout).unwrap(),
        stderr,
    )
}

/// Runs the binary in `dir` and expects exit 0 with nothing on stderr; returns stdout.
pub fn ok(dir: &Path, args: &[&str]) -> String {
    let (code, stdout, stderr) = run(dir, args);
    assert_eq!((code, stderr.as_str()), (0, ""), "{args:?}");
    stdout
}
