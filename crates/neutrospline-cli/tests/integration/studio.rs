//! End-to-end tests of `neutrospline studio`: the printed URL, exports equal to `plot`'s
//! bytes, refusals of bad arguments. (The page itself is tested in a browser by
//! `scripts/studio-e2e`.)

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

use crate::util::{example, BIN};

/// A running `studio --no-open`, killed when dropped.
struct Running {
    child: Child,
    port: u16,
}

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn studio(args: &[&str]) -> Running {
    let mut child = Command::new(BIN)
        .arg("studio")
        .arg("--no-open")
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("run neutrospline");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let rest = line
        .strip_prefix("neutrospline studio: http://127.0.0.1:")
        .unwrap_or_else(|| panic!("unexpected first line {line:?}"));
    let port = rest.trim_end().trim_end_matches('/').parse().unwrap();
    Running { child, port }
}

fn post(port: u16, path: &str, body: &str) -> (u16, Vec<u8>) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    write!(
        s,
        "POST {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )
    .unwrap();
    let mut answer = Vec::new();
    s.read_to_end(&mut answer).unwrap();
    let split = answer.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let status = String::from_utf8_lossy(&answer[9..12]).parse().unwrap();
    (status, answer[split + 4..].to_vec())
}

#[test]
fn studio_exports_the_bytes_plot_writes() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bspline.toml");
    std::fs::copy(example("bspline.toml"), &file).unwrap();
    let running = studio(&[file.to_str().unwrap()]);
    // The model as the page holds it: the JSON the studio sends at start.
    let mut s = TcpStream::connect(("127.0.0.1", running.port)).unwrap();
    write!(
        s,
        "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nConnection: close\r\n\r\n",
        running.port
    )
    .unwrap();
    let mut answer = String::new();
    s.read_to_string(&mut answer).unwrap();
    let state: serde_json::Value =
        serde_json::from_str(answer.split("\r\n\r\n").nth(1).unwrap()).unwrap();
    let model = state["model"].to_string();
    for (view, ext) in [("plane", "svg"), ("truth", "svg"), ("controls", "png")] {
        let body = serde_json::json!({ "model": model, "format": ext, "figure": { "view": view } });
        let (status, bytes) = post(running.port, "/api/export", &body.to_string());
        assert_eq!(status, 200, "{}", String::from_utf8_lossy(&bytes));
        let reference = dir.path().join(format!("plot-{view}.{ext}"));
        let out = Command::new(BIN)
            .args(["plot", file.to_str().unwrap(), "--view", view, "-o"])
            .arg(&reference)
            .output()
            .unwrap();
        assert!(out.status.success());
        assert!(
            bytes == std::fs::read(&reference).unwrap(),
            "{view}.{ext} differs from plot's"
        );
    }
    // A foreign origin is refused, and the studio keeps serving.
    let mut s = TcpStream::connect(("127.0.0.1", running.port)).unwrap();
    write!(
        s,
        "GET / HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nOrigin: http://evil.example\r\nConnection: close\r\n\r\n",
        running.port
    )
    .unwrap();
    let mut answer = String::new();
    s.read_to_string(&mut answer).unwrap();
    assert!(answer.starts_with("HTTP/1.1 403 "), "{answer}");
    assert_eq!(post(running.port, "/api/render", "{}").0, 400);
}

#[test]
fn studio_refuses_bad_arguments() {
    let out = Command::new(BIN)
        .args(["studio", "--no-open", "-"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "error: the studio reads a model file, not standard input (give FILE or none)\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(
        &bad,
        "x,y,truth,indeterminacy,falsity\n1,2,1.2,0,0\n1,3,0,0,0\n",
    )
    .unwrap();
    let out = Command::new(BIN)
        .args(["studio", "--no-open"])
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        format!(
            "error: {}:2: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])\n",
            bad.display()
        )
    );
}
