//! Unit tests of the server: request parsing, and what only a custom handler can show.

use super::*;
use serde_json::Value;
use std::sync::{mpsc, Condvar, Mutex};

fn request(text: &str, max_body: usize) -> Result<Option<Request>, Refusal> {
    read_request(&mut BufReader::new(text.as_bytes()), max_body)
}

#[test]
fn read_request_parses_head_and_body() {
    let r = request(
        "POST /api/render?x=1 HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nContent-Length: 4\r\n\r\nabcdEXTRA",
        100,
    )
    .unwrap()
    .unwrap();
    assert_eq!(r.method, "POST");
    assert_eq!(r.path, "/api/render");
    assert_eq!(r.header("host"), Some("127.0.0.1:8080"));
    assert_eq!(r.body, b"abcd");
    assert!(request("", 100).unwrap().is_none());
}

#[test]
fn read_request_refuses_large_and_chunked_bodies() {
    let e = request(
        "POST / HTTP/1.1\r\nHost: a\r\nContent-Length: 101\r\n\r\n",
        100,
    )
    .unwrap_err();
    assert_eq!(e.status, 413);
    assert_eq!(
        e.message,
        "the request body of 101 bytes is larger than the limit of 100 bytes"
    );
    let e = request(
        "POST / HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n",
        100,
    )
    .unwrap_err();
    assert_eq!(e.status, 411);
    let e = request("GARBAGE\r\n\r\n", 100).unwrap_err();
    assert_eq!(
        (e.status, e.message.as_str()),
        (400, "malformed request line")
    );
    let huge = format!("GET / HTTP/1.1\r\nX: {}\r\n\r\n", "a".repeat(70_000));
    assert_eq!(request(&huge, 100).unwrap_err().status, 431);
}

fn refusal(text: &str) -> (u16, String) {
    let e = request(text, 100).unwrap_err();
    (e.status, e.message)
}

#[test]
fn read_request_parses_header_names_and_host_strictly() {
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nHost : 127.0.0.1:80\r\n\r\n"),
        (
            400,
            "header `Host`: whitespace between the name and the colon (RFC 9112 5.1)".into()
        )
    );
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nHost:\t127.0.0.1:80\r\nX-A\t: 1\r\n\r\n").0,
        400
    );
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nHost: 127.0.0.1:80\r\nX: a\r\n b\r\n\r\n").1,
        "a header line starts with whitespace (obsolete line folding, RFC 9112 5.2)"
    );
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nX-A: 1\r\n\r\n"),
        (400, "the request has no Host header".into())
    );
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nHost: localhost:80\r\nhost: localhost:80\r\n\r\n"),
        (400, "the request has 2 Host headers".into())
    );
    for bad in [
        "",
        ":80",
        "user@localhost:80",
        "localhost:80/x",
        "localhost:8a",
        "local host:80",
        "[::1",
        "[::1]x",
        "[zz]:80",
        "a%2",
        "a%zz",
    ] {
        assert_eq!(
            refusal(&format!("GET / HTTP/1.1\r\nHost: {bad}\r\n\r\n")),
            (
                400,
                format!("Host `{bad}` is not a host[:port] (RFC 9110 7.2)")
            ),
            "{bad:?}"
        );
    }
    for good in [
        "localhost",
        "127.0.0.1:8080",
        "[::1]:80",
        "[::1]",
        "a%20b:",
        "x-y.z~",
    ] {
        let text = format!("GET / HTTP/1.1\r\nHost: {good}\r\n\r\n");
        let r = request(&text, 100).unwrap().unwrap();
        assert_eq!(r.header("host"), Some(good));
    }
    // HTTP/1.0 needs no Host; its Expect is ignored.
    assert!(request("GET / HTTP/1.0\r\n\r\n", 100).unwrap().is_some());
    assert_eq!(refusal("GET / HTTP/2.0\r\n\r\n").0, 400);
    assert_eq!(
        refusal("POST / HTTP/1.1\r\nHost: a\r\nContent-Length: +5\r\n\r\n"),
        (400, "Content-Length `+5` is not a number".into())
    );
    assert_eq!(
        refusal("POST / HTTP/1.1\r\nHost: a\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\nab").1,
        "two different Content-Length headers"
    );
    assert_eq!(
        refusal("POST / HTTP/1.1\r\nHost: a\r\nExpect: 200-ok\r\n\r\n"),
        (417, "Expect `200-ok` is not supported".into())
    );
    assert_eq!(
        refusal("GET / HTTP/1.1\r\nHost: a\r\nX: a\u{1}b\r\n\r\n").1,
        "header `X`: the value holds a control character"
    );
}

#[test]
fn read_head_reads_expect_and_keep_alive() {
    let head = |text: &str| {
        read_head(&mut BufReader::new(text.as_bytes()))
            .unwrap()
            .unwrap()
    };
    let h = head("POST / HTTP/1.1\r\nHost: a\r\nExpect: 100-Continue\r\nContent-Length: 7\r\n\r\n");
    assert!(h.expect_continue && h.keep_alive);
    assert_eq!(h.body_length, 7);
    let h = head("POST / HTTP/1.0\r\nExpect: 100-continue\r\n\r\n");
    assert!(!h.expect_continue && !h.keep_alive);
    let h = head("GET / HTTP/1.1\r\nHost: a\r\nConnection: keep-alive, Close\r\n\r\n");
    assert!(!h.keep_alive);
}

#[test]
fn body_deadline_is_the_floor_plus_the_size_over_the_rate() {
    let config = ServerConfig::default();
    assert_eq!(config.body_deadline(0), Duration::from_secs(10));
    assert_eq!(config.body_deadline(MAX_BODY), Duration::from_secs(10 + 64));
}

fn with_headers(headers: &[(&str, &str)]) -> Request {
    Request {
        method: "GET".into(),
        path: "/".into(),
        headers: headers
            .iter()
            .map(|(n, v)| ((*n).to_owned(), (*v).to_owned()))
            .collect(),
        body: Vec::new(),
    }
}

#[test]
fn check_origin_accepts_only_this_server() {
    assert_eq!(
        check_origin(&with_headers(&[("host", "127.0.0.1:4000")]), 4000),
        Ok(())
    );
    assert_eq!(
        check_origin(
            &with_headers(&[
                ("host", "localhost:4000"),
                ("origin", "http://localhost:4000")
            ]),
            4000
        ),
        Ok(())
    );
    assert_eq!(
        check_origin(&with_headers(&[("host", "evil.example:4000")]), 4000).unwrap_err(),
        "refused: Host `evil.example:4000` is not this studio"
    );
    assert_eq!(
        check_origin(&with_headers(&[("host", "127.0.0.1:4001")]), 4000).unwrap_err(),
        "refused: Host `127.0.0.1:4001` is not this studio"
    );
    assert_eq!(
        check_origin(
            &with_headers(&[
                ("host", "127.0.0.1:4000"),
                ("origin", "http://evil.example")
            ]),
            4000
        )
        .unwrap_err(),
        "refused: Origin `http://evil.example` is not this studio"
    );
    assert_eq!(
        check_origin(
            &with_headers(&[("host", "127.0.0.1:4000"), ("origin", "null")]),
            4000
        )
        .unwrap_err(),
        "refused: Origin `null` is not this studio"
    );
    assert!(check_origin(&with_headers(&[]), 4000).is_err());
    assert_eq!(
        check_origin(
            &with_headers(&[("host", "127.0.0.1:4000"), ("host", "evil.example")]),
            4000
        )
        .unwrap_err(),
        "refused: the request has 2 Host headers"
    );
}

/// Status, head and body of a `GET path` with `Connection: close`.
fn get(port: u16, path: &str) -> (u16, String, Vec<u8>) {
    use std::io::{Read, Write};
    let mut stream = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    let raw = format!("GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n");
    stream.write_all(raw.as_bytes()).unwrap();
    let mut answer = Vec::new();
    let _ = stream.read_to_end(&mut answer);
    let split = answer.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let head = String::from_utf8(answer[..split].to_vec()).unwrap();
    let status = head[9..12].parse().unwrap();
    (status, head, answer[split + 4..].to_vec())
}

/// Holds every request until released, and says when one has arrived.
struct Gate {
    arrived: Mutex<mpsc::Sender<()>>,
    open: Arc<(Mutex<bool>, Condvar)>,
}

impl Handler for Gate {
    fn handle(&self, _: &Request) -> Response {
        let _ = self.arrived.lock().unwrap().send(());
        let (open, changed) = &*self.open;
        let mut is_open = open.lock().unwrap();
        while !*is_open {
            is_open = changed.wait(is_open).unwrap();
        }
        Response::new(200, "text/plain", "done")
    }
}

#[test]
fn connections_being_answered_are_never_closed_for_a_new_one() {
    let (arrived, arrivals) = mpsc::channel();
    let open = Arc::new((Mutex::new(false), Condvar::new()));
    let gate = Gate {
        arrived: Mutex::new(arrived),
        open: Arc::clone(&open),
    };
    let config = ServerConfig {
        max_connections: 2,
        ..ServerConfig::default()
    };
    let port = Listener::bind(0, gate).unwrap().with_config(config).spawn();
    let busy: Vec<_> = (0..2)
        .map(|_| std::thread::spawn(move || get(port, "/")))
        .collect();
    for _ in 0..2 {
        arrivals.recv_timeout(Duration::from_secs(10)).unwrap();
    }
    let (status, _, body) = get(port, "/");
    assert_eq!(status, 503);
    assert_eq!(
        serde_json::from_slice::<Value>(&body).unwrap()["error"]["message"],
        "too many connections: every one is being answered"
    );
    *open.0.lock().unwrap() = true;
    open.1.notify_all();
    for b in busy {
        let (status, _, body) = b.join().unwrap();
        assert_eq!((status, body.as_slice()), (200, b"done".as_slice()));
    }
}
