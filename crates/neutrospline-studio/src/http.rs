//! A small HTTP/1.1 server on `std::net`: one thread per connection, keep-alive, bodies by
//! `Content-Length` only, and the guards of a local tool that a web page elsewhere must not
//! drive: the `Host` and `Origin` headers must name this server (DNS rebinding), and bodies
//! are limited in size.

use std::io::{self, BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// The largest request body accepted (16 MiB): a model or a data file.
pub const MAX_BODY: usize = 16 * 1024 * 1024;

/// The largest request head (request line and headers).
const MAX_HEAD: usize = 64 * 1024;

/// Connections served at once; more are answered 503 and closed.
const MAX_CONNECTIONS: usize = 64;

/// An idle keep-alive connection is closed after this long.
const IDLE: Duration = Duration::from_secs(120);

/// A request: method, path (without the query), headers (names in lower case) and body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Request {
    /// `GET`, `POST`, ...
    pub method: String,
    /// The path of the target, without `?query`.
    pub path: String,
    /// Header names in lower case, values trimmed, in order.
    pub headers: Vec<(String, String)>,
    /// The body (empty without `Content-Length`).
    pub body: Vec<u8>,
}

impl Request {
    /// The first header named `name` (lower case).
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

/// A response: status, content type, extra headers and body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Response {
    /// The status code.
    pub status: u16,
    /// The `Content-Type`.
    pub content_type: String,
    /// Other headers.
    pub headers: Vec<(String, String)>,
    /// The body.
    pub body: Vec<u8>,
}

impl Response {
    /// A response with `status`, `content_type` and `body`.
    pub fn new(status: u16, content_type: &str, body: impl Into<Vec<u8>>) -> Response {
        Response {
            status,
            content_type: content_type.to_owned(),
            headers: Vec::new(),
            body: body.into(),
        }
    }

    /// A JSON response.
    pub fn json(status: u16, body: impl Into<Vec<u8>>) -> Response {
        Response::new(status, "application/json; charset=utf-8", body)
    }

    /// A JSON error `{"error": {"message": ...}}`.
    pub fn error(status: u16, message: &str) -> Response {
        let body = serde_json::json!({ "error": { "message": message } });
        Response::json(status, body.to_string())
    }

    /// Adds a header.
    pub fn with_header(mut self, name: &str, value: &str) -> Response {
        self.headers.push((name.to_owned(), value.to_owned()));
        self
    }

    fn write_to(&self, w: &mut impl Write, close: bool) -> io::Result<()> {
        let mut head = format!(
            "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\n\
             Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n\
             X-Frame-Options: DENY\r\nReferrer-Policy: no-referrer\r\n",
            self.status,
            reason(self.status),
            self.content_type,
            self.body.len()
        );
        for (n, v) in &self.headers {
            head.push_str(&format!("{n}: {v}\r\n"));
        }
        if close {
            head.push_str("Connection: close\r\n");
        }
        head.push_str("\r\n");
        w.write_all(head.as_bytes())?;
        w.write_all(&self.body)?;
        w.flush()
    }
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        204 => "No Content",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        409 => "Conflict",
        411 => "Length Required",
        413 => "Payload Too Large",
        422 => "Unprocessable Entity",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        501 => "Not Implemented",
        503 => "Service Unavailable",
        _ => "Status",
    }
}

/// Why a request could not be read: answered with `status` and the connection closed.
#[derive(Debug)]
pub(crate) struct Refusal {
    pub status: u16,
    pub message: String,
}

fn refuse(status: u16, message: impl Into<String>) -> Refusal {
    Refusal {
        status,
        message: message.into(),
    }
}

/// Reads one request. `Ok(None)`: the peer closed the connection before a request.
pub(crate) fn read_request(
    reader: &mut impl BufRead,
    max_body: usize,
) -> Result<Option<Request>, Refusal> {
    let mut head = Vec::new();
    let mut lines: Vec<String> = Vec::new();
    loop {
        let mut line = Vec::new();
        let n = (&mut *reader)
            .take((MAX_HEAD + 1 - head.len().min(MAX_HEAD)) as u64)
            .read_until(b'\n', &mut line)
            .map_err(|e| refuse(400, format!("cannot read the request: {e}")))?;
        if n == 0 {
            if lines.is_empty() && head.is_empty() {
                return Ok(None);
            }
            return Err(refuse(400, "the request ends inside its head"));
        }
        head.extend_from_slice(&line);
        if head.len() > MAX_HEAD {
            return Err(refuse(431, "the request head is larger than 64 KiB"));
        }
        let text =
            String::from_utf8(line).map_err(|_| refuse(400, "the request head is not UTF-8"))?;
        let text = text.trim_end_matches(['\r', '\n']).to_owned();
        if text.is_empty() {
            if lines.is_empty() {
                continue; // blank lines before a request are allowed (RFC 9112 2.2)
            }
            break;
        }
        lines.push(text);
    }
    let mut parts = lines[0].split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(refuse(400, "malformed request line"));
    };
    if !version.starts_with("HTTP/1.") {
        return Err(refuse(400, "only HTTP/1.x is served"));
    }
    let mut headers = Vec::new();
    for line in &lines[1..] {
        let Some((name, value)) = line.split_once(':') else {
            return Err(refuse(400, "malformed header line"));
        };
        headers.push((name.trim().to_ascii_lowercase(), value.trim().to_owned()));
    }
    let path = target.split(['?', '#']).next().unwrap_or("").to_owned();
    let mut request = Request {
        method: method.to_owned(),
        path,
        headers,
        body: Vec::new(),
    };
    if request.header("transfer-encoding").is_some() {
        return Err(refuse(
            411,
            "chunked request bodies are not supported (send Content-Length)",
        ));
    }
    if let Some(length) = request.header("content-length") {
        let length: usize = length
            .parse()
            .map_err(|_| refuse(400, "Content-Length is not a number"))?;
        if length > max_body {
            return Err(refuse(
                413,
                format!(
                    "the request body of {length} bytes is larger than the limit of {max_body} bytes"
                ),
            ));
        }
        let mut body = vec![0; length];
        reader
            .read_exact(&mut body)
            .map_err(|e| refuse(400, format!("cannot read the request body: {e}")))?;
        request.body = body;
    }
    Ok(Some(request))
}

/// Whether a request comes from this server's own page: the `Host` header must be
/// `127.0.0.1:PORT` or `localhost:PORT`, and an `Origin` header, when present, the same with
/// `http://`. Anything else (another site's page, a DNS-rebinding name) is refused.
///
/// # Errors
/// The reason, for a 403 answer.
pub fn check_origin(request: &Request, port: u16) -> Result<(), String> {
    let hosts = [format!("127.0.0.1:{port}"), format!("localhost:{port}")];
    match request.header("host") {
        Some(host) if hosts.iter().any(|h| h.eq_ignore_ascii_case(host)) => {}
        Some(host) => return Err(format!("refused: Host `{host}` is not this studio")),
        None => return Err("refused: the request has no Host header".to_owned()),
    }
    if let Some(origin) = request.header("origin") {
        if !hosts
            .iter()
            .any(|h| origin.eq_ignore_ascii_case(&format!("http://{h}")))
        {
            return Err(format!("refused: Origin `{origin}` is not this studio"));
        }
    }
    if request.header("sec-fetch-site") == Some("cross-site") {
        return Err("refused: a cross-site request".to_owned());
    }
    Ok(())
}

/// What answers requests.
pub trait Handler: Send + Sync + 'static {
    /// The response to a request that passed [`check_origin`].
    fn handle(&self, request: &Request) -> Response;
}

/// A listening server.
pub struct Server<H: Handler> {
    listener: TcpListener,
    handler: Arc<H>,
    max_body: usize,
}

impl<H: Handler> Server<H> {
    /// Listens on `127.0.0.1:port` (0: any free port).
    ///
    /// # Errors
    /// The port cannot be bound.
    pub fn bind(port: u16, handler: H) -> io::Result<Server<H>> {
        let listener = TcpListener::bind(SocketAddr::from(([127, 0, 0, 1], port)))?;
        Ok(Server {
            listener,
            handler: Arc::new(handler),
            max_body: MAX_BODY,
        })
    }

    /// Sets the body limit (tests).
    pub fn with_max_body(mut self, max_body: usize) -> Server<H> {
        self.max_body = max_body;
        self
    }

    /// The port it listens on.
    pub fn port(&self) -> u16 {
        self.listener.local_addr().map(|a| a.port()).unwrap_or(0)
    }

    /// The page's address, `http://127.0.0.1:PORT/`.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port())
    }

    /// Serves until the process ends; bad requests never stop it.
    pub fn serve(self) {
        let port = self.port();
        let active = Arc::new(AtomicUsize::new(0));
        for stream in self.listener.incoming() {
            let Ok(stream) = stream else {
                // Out of file descriptors, say: wait a little rather than spin.
                std::thread::sleep(Duration::from_millis(20));
                continue;
            };
            if active.load(Ordering::SeqCst) >= MAX_CONNECTIONS {
                let mut stream = stream;
                let _ = Response::error(503, "too many connections").write_to(&mut stream, true);
                continue;
            }
            active.fetch_add(1, Ordering::SeqCst);
            let handler = Arc::clone(&self.handler);
            let active = Arc::clone(&active);
            let max_body = self.max_body;
            let spawned = std::thread::Builder::new()
                .name("studio-connection".to_owned())
                .spawn(move || {
                    connection(stream, port, &*handler, max_body);
                    active.fetch_sub(1, Ordering::SeqCst);
                });
            if spawned.is_err() {
                // No thread: the stream was moved into the closure and is dropped (closed).
                continue;
            }
        }
    }

    /// Serves on a background thread (for tests and embedding); returns the port.
    pub fn spawn(self) -> u16 {
        let port = self.port();
        std::thread::spawn(move || self.serve());
        port
    }
}

/// Serves the requests of one connection until it closes or a request is refused.
fn connection(stream: TcpStream, port: u16, handler: &impl Handler, max_body: usize) {
    let _ = stream.set_read_timeout(Some(IDLE));
    let _ = stream.set_nodelay(true);
    let Ok(mut writer) = stream.try_clone() else {
        return;
    };
    let mut reader = BufReader::new(stream);
    loop {
        let request = match read_request(&mut reader, max_body) {
            Ok(Some(r)) => r,
            Ok(None) => return,
            Err(refusal) => {
                let _ =
                    Response::error(refusal.status, &refusal.message).write_to(&mut writer, true);
                return;
            }
        };
        let close = request
            .header("connection")
            .is_some_and(|c| c.eq_ignore_ascii_case("close"));
        let response = match check_origin(&request, port) {
            Err(message) => Response::error(403, &message),
            Ok(()) => {
                // A bug in a handler answers 500 and leaves the server running.
                match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    handler.handle(&request)
                })) {
                    Ok(r) => r,
                    Err(_) => Response::error(500, "internal error (the studio keeps running)"),
                }
            }
        };
        if response.write_to(&mut writer, close).is_err() || close {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let e = request("POST / HTTP/1.1\r\nContent-Length: 101\r\n\r\n", 100).unwrap_err();
        assert_eq!(e.status, 413);
        assert_eq!(
            e.message,
            "the request body of 101 bytes is larger than the limit of 100 bytes"
        );
        let e = request("POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 100).unwrap_err();
        assert_eq!(e.status, 411);
        let e = request("GARBAGE\r\n\r\n", 100).unwrap_err();
        assert_eq!(
            (e.status, e.message.as_str()),
            (400, "malformed request line")
        );
        let huge = format!("GET / HTTP/1.1\r\nX: {}\r\n\r\n", "a".repeat(70_000));
        assert_eq!(request(&huge, 100).unwrap_err().status, 431);
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
    }
}
