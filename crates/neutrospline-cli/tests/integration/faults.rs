//! Faults and limits: an interrupted `eval -o FILE` (SIGINT, SIGTERM) leaves no partial file
//! and the old output untouched; CSV is streamed, so a bad line is reported while the writer is
//! still writing; the control-point, sample and file-size limits give clear errors.

use std::io::Write;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::util::BIN;

const OLD: &[u8] = b"the old output\n";

const MODEL: &str = "x,y,truth,indeterminacy,falsity\n1,3,0.3,0.6,0.1\n3,6,0.8,0.1,0.1\n\
                     6,2,0.7,0.1,0.2\n9,5,0.2,0.4,0.4\n";

fn spawn(dir: &Path, args: &[&str]) -> Child {
    Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs")
}

/// Waits for `child` at most `limit`, killing it (and failing) if it takes longer.
fn wait_bounded(mut child: Child, limit: Duration) -> (i32, String) {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let out = child.wait_with_output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
            assert!(!stderr.contains("panicked"), "{stderr}");
            return (status.code().expect("exited, not killed"), stderr);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("the command did not finish within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn temp_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect()
}

fn interrupt(signal: &str, expected_code: i32, expected_message: &str) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("m.csv"), MODEL).unwrap();
    std::fs::write(dir.path().join("out.csv"), OLD).unwrap();
    let child = spawn(
        dir.path(),
        &["eval", "m.csv", "--samples", "100000000", "-o", "out.csv"],
    );
    // Wait until the temporary file exists and has grown (the row loop is running).
    let start = Instant::now();
    loop {
        let growing = std::fs::read_dir(dir.path()).unwrap().any(|e| {
            let e = e.unwrap();
            e.file_name().to_string_lossy().ends_with(".tmp")
                && e.metadata().is_ok_and(|m| m.len() > 0)
        });
        if growing {
            break;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no temporary file appeared"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    let status = Command::new("kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let (code, stderr) = wait_bounded(child, Duration::from_secs(30));
    assert_eq!(
        (code, stderr.as_str()),
        (expected_code, expected_message),
        "SIG{signal}"
    );
    assert_eq!(
        temp_files(dir.path()),
        Vec::<String>::new(),
        "temporary file removed"
    );
    assert_eq!(std::fs::read(dir.path().join("out.csv")).unwrap(), OLD);
}

#[test]
fn fault_sigint_leaves_no_partial_file() {
    interrupt(
        "INT",
        130,
        "error: out.csv: not written: interrupted by SIGINT\n",
    );
}

#[test]
fn fault_sigterm_leaves_no_partial_file() {
    interrupt(
        "TERM",
        143,
        "error: out.csv: not written: interrupted by SIGTERM\n",
    );
}

/// A FIFO whose writer sends a header, two good rows and a bad line 4, then keeps writing good
/// rows and never closes: `check` must report line 4 at once, not wait for the end.
fn streaming_case(extra: &[&str], first_rows: &str, expected: &str) {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("stream.csv");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let writer = {
        let fifo = fifo.clone();
        let stop = std::sync::Arc::clone(&stop);
        let first_rows = first_rows.to_owned();
        std::thread::spawn(move || {
            // Opening blocks until the reader opens the FIFO.
            let mut f = std::fs::OpenOptions::new().write(true).open(&fifo).unwrap();
            let _ = f.write_all(first_rows.as_bytes());
            let _ = f.flush();
            let start = Instant::now();
            while !stop.load(std::sync::atomic::Ordering::Relaxed)
                && start.elapsed() < Duration::from_secs(60)
            {
                // Fails (broken pipe) once the reader has gone.
                if f.write_all(b"1,2,0.5,0.1,0.1\n").is_err() {
                    break;
                }
            }
        })
    };
    let mut args = vec!["check", "stream.csv"];
    args.extend_from_slice(extra);
    let child = spawn(dir.path(), &args);
    let started = Instant::now();
    let (code, stderr) = wait_bounded(child, Duration::from_secs(20));
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    writer.join().unwrap();
    assert_eq!((code, stderr.as_str()), (1, expected));
    assert!(started.elapsed() < Duration::from_secs(20));
}

#[test]
fn fault_csv_is_streamed_error_on_line_4_while_the_writer_goes_on() {
    streaming_case(
        &[],
        "x,y,truth,indeterminacy,falsity\n1,2,0.5,0.1,0.1\n3,4,0.5,0.1,0.1\n5,6,7,0.1,0.1\n",
        "error: stream.csv:4: truth = 7 is outside [0, 1] (every degree must be in [0, 1])\n",
    );
}

#[test]
fn fault_csv_control_point_limit_stops_reading_at_the_limit_line() {
    streaming_case(
        &["--max-control-points", "3"],
        "x,y,truth,indeterminacy,falsity\n",
        "error: stream.csv:5: more than 3 control points (the limit; raise it with \
         --max-control-points or NEUTROSPLINE_MAX_CONTROL_POINTS)\n",
    );
}

#[test]
fn fault_csv_overlong_line_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = b"x,y,truth,indeterminacy,falsity\n1,2,0.5,0.1,0.1\n".to_vec();
    text.extend(std::iter::repeat_n(b'7', 2 * 1024 * 1024));
    std::fs::write(dir.path().join("long.csv"), text).unwrap();
    let (code, stderr) = wait_bounded(
        spawn(dir.path(), &["check", "long.csv"]),
        Duration::from_secs(20),
    );
    assert_eq!(
        (code, stderr.as_str()),
        (
            1,
            "error: long.csv:3: the line is longer than 1048576 bytes (a row of control point \
             values is short; is this a CSV file?)\n"
        )
    );
}

#[test]
fn limit_control_points_for_every_format_and_by_environment() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let run = |args: &[&str], env: Option<&str>| {
        let mut command = Command::new(BIN);
        command
            .args(args)
            .current_dir(&examples)
            .stdin(Stdio::null());
        if let Some(v) = env {
            command.env("NEUTROSPLINE_MAX_CONTROL_POINTS", v);
        }
        let out = command.output().unwrap();
        (
            out.status.code().unwrap(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let rule = "more than 3 control points (the limit; raise it with --max-control-points or \
                NEUTROSPLINE_MAX_CONTROL_POINTS)";
    assert_eq!(
        run(
            &["check", "example1.csv", "--max-control-points", "3"],
            None
        ),
        (1, format!("error: example1.csv:8: {rule}\n"))
    );
    assert_eq!(
        run(
            &["--max-control-points", "3", "check", "example1.toml"],
            None
        ),
        (
            1,
            format!("error: example1.toml:34: control_points[3]: {rule}\n")
        )
    );
    assert_eq!(
        run(&["check", "example1.json"], Some("3")),
        (
            1,
            format!("error: example1.json: control_points[3]: {rule}\n")
        )
    );
    assert_eq!(run(&["check", "example1.json"], Some("4")).0, 0);
    // A surface counts rows x cols.
    assert_eq!(
        run(
            &["check", "surface.toml", "--max-control-points", "15"],
            None
        )
        .0,
        1
    );
    assert_eq!(
        run(
            &["check", "surface.toml", "--max-control-points", "16"],
            None
        )
        .0,
        0
    );
}

#[test]
fn limit_file_size_for_toml_and_json() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for name in ["example1.toml", "example1.json"] {
        let out = Command::new(BIN)
            .args(["check", name, "--max-file-size", "100"])
            .current_dir(&examples)
            .output()
            .unwrap();
        assert_eq!(
            (
                out.status.code(),
                String::from_utf8_lossy(&out.stderr).as_ref()
            ),
            (
                Some(1),
                format!(
                    "error: {name}: the file is larger than 100 bytes, the limit for a file read \
                     whole (TOML, JSON, DXF, SVG; raise it with --max-file-size or \
                     NEUTROSPLINE_MAX_FILE_SIZE; CSV files are streamed and have no size limit)\n"
                )
                .as_str()
            )
        );
    }
}

#[test]
fn limit_samples_curves_and_surfaces() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let run = |args: &[&str]| {
        let out = Command::new(BIN)
            .args(args)
            .current_dir(&examples)
            .output()
            .unwrap();
        (
            out.status.code().unwrap(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    assert_eq!(
        run(&[
            "eval",
            "example1.csv",
            "--samples",
            "11",
            "--max-samples",
            "10"
        ]),
        (
            2,
            "error: --samples 11 gives 11 rows, more than the limit of 10 (raise it with \
             --max-samples or NEUTROSPLINE_MAX_SAMPLES)\n"
                .to_owned()
        )
    );
    assert_eq!(
        run(&[
            "eval",
            "surface.toml",
            "--samples",
            "4",
            "--max-samples",
            "10"
        ]),
        (
            2,
            "error: --samples 4 gives 4 x 4 = 16 rows on a surface, more than the limit of 10 \
             (raise it with --max-samples or NEUTROSPLINE_MAX_SAMPLES)\n"
                .to_owned()
        )
    );
    // The default limit (10^10 rows) refuses a 10^6 x 10^6 surface grid at once.
    assert_eq!(
        run(&["eval", "surface.toml", "--samples", "1000000"]),
        (
            2,
            "error: --samples 1000000 gives 1000000 x 1000000 = 1000000000000 rows on a \
             surface, more than the limit of 10000000000 (raise it with --max-samples or \
             NEUTROSPLINE_MAX_SAMPLES)\n"
                .to_owned()
        )
    );
    assert_eq!(
        run(&[
            "eval",
            "example1.csv",
            "--at",
            "0,0.5,1",
            "--max-samples",
            "2"
        ])
        .0,
        2
    );
    assert_eq!(
        run(&[
            "eval",
            "example1.csv",
            "--samples",
            "10",
            "--max-samples",
            "10"
        ])
        .0,
        0
    );
    // Help documents the limits, their defaults and their variables.
    let out = Command::new(BIN).args(["eval", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "--max-control-points <N>",
        "NEUTROSPLINE_MAX_CONTROL_POINTS",
        "default: 1000000",
        "--max-samples <N>",
        "NEUTROSPLINE_MAX_SAMPLES",
        "--max-file-size <BYTES>",
        "NEUTROSPLINE_MAX_FILE_SIZE",
    ] {
        assert!(help.contains(needle), "{needle} not in:\n{help}");
    }
}

#[test]
fn fault_csv_stray_quote_in_a_name_reads_every_row() {
    // Issue 22: `C"0` made `check` report one control point and exit 0.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("quote.csv"),
        "name,x,y,truth,indeterminacy,falsity\nC\"0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\n\
         C2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n",
    )
    .unwrap();
    let out = Command::new(BIN)
        .args(["check", "quote.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("\ncontrol points: 4\n"), "{stdout}");
    assert!(stdout.contains("\ndegree: 3\n"), "{stdout}");
}

#[test]
fn fault_csv_quoted_cell_open_at_the_end_is_refused_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("open.csv"),
        "name,x,y,truth,indeterminacy,falsity\nC0,1,3,0.3,0.6,0.1\n\"C1,3,6,0.8,0.1,0.1\n\
         C2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n",
    )
    .unwrap();
    let out = Command::new(BIN)
        .args(["check", "open.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_eq!(
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).as_ref()
        ),
        (
            Some(1),
            "error: open.csv:3: the file ends inside a quoted cell of the row starting on this \
             line (a cell that starts with `\"` ends at the next `\"` that is not doubled)\n"
        )
    );
}
