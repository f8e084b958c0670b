//! A small HTTP/1.1 server on `std::net`: one thread per connection, keep-alive, bodies by
//! `Content-Length` only, and the guards of a local tool that neither a web page elsewhere nor
//! another local process may take over.
//!
//! ## What a request must be
//! - The head (request line and header lines) is at most 64 KiB. A header name is a token
//!   directly followed by `:` (RFC 9112 5.1: `Host : x` is answered 400, as is a folded line,
//!   5.2), and a value holds no control character but tab.
//! - Exactly one `Host` header, `host[:port]` in the syntax of RFC 3986 3.2.2 (RFC 9112 3.2:
//!   none, two or a malformed one is 400). It must then name this server, `127.0.0.1:PORT` or
//!   `localhost:PORT`, and an `Origin` header, when present, the same with `http://`
//!   ([`check_origin`], 403): a page elsewhere, or a DNS-rebinding name, is refused.
//! - A body has a `Content-Length` of digits only and at most [`ServerConfig::max_body`]
//!   bytes (413 otherwise); `Transfer-Encoding` is refused (411).
//! - `Expect: 100-continue` (HTTP/1.1) is answered `HTTP/1.1 100 Continue` once the head has
//!   passed every check above, and with the final refusal instead, without reading the body,
//!   when it has not (RFC 9110 10.1.1); any other expectation is 417.
//! - `HEAD` is answered with the head `GET` would have, `Content-Length` included, and no body
//!   (RFC 9110 9.3.2).
//!
//! A request that passes is answered by the [`Handler`], except `GET /modules/NAME.js`, the
//! page's modules (the `assets` module), which the server answers itself.
//!
//! After a refusal the connection is closed; a body that was not read is drained for at most
//! [`LINGER`] first, so that the client reads the answer rather than a reset.
//!
//! ## Deadlines ([`ServerConfig`])
//! Each phase of a request has a total deadline, not a timeout per read, so a client that sends
//! one byte at a time gains nothing:
//! - a new connection has `head_timeout` (10 s) from its accept to the end of its first head;
//! - a kept-alive connection waits at most `idle_timeout` (30 s) for the first byte of its next
//!   request, which then has `head_timeout` for its head;
//! - a body of `n` bytes has `body_timeout + n / body_rate` (10 s plus 1 s per 256 KiB);
//! - writing an answer has `write_timeout` (30 s).
//!
//! A head or body past its deadline is answered 408 and closed; an idle connection past its
//! deadline is closed without an answer.
//!
//! ## How many connections
//! Every connection is `127.0.0.1` on both ends, whichever local process opened it, so a cap per
//! peer address would limit the browser together with the process that floods: the server has
//! one global limit, `max_connections` (64), and makes room rather than refuse. When a new
//! connection arrives at the limit, the server closes the connection that has waited longest
//! for a request (idle kept-alive ones and new ones that have sent nothing; the browser opens
//! another when it needs one), else the one whose request has been arriving longest (it has at
//! most `head_timeout` or its body's deadline anyway). Connections whose request is being
//! answered are never closed; only when all are, is the new one answered 503. A process holding
//! every slot thus keeps none of them from the next client, and each slot for at most its
//! deadline.

use std::io::{self, BufRead, BufReader, Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The largest request body accepted by default (16 MiB): a model or a data file.
pub(crate) const MAX_BODY: usize = 16 * 1024 * 1024;

/// The largest request head (request line and headers).
const MAX_HEAD: usize = 64 * 1024;

/// How long the server reads (and discards) an unread body after a refusal before it closes,
/// and how much of it at most (1 MiB), so that the client reads the refusal.
pub(crate) const LINGER: Duration = Duration::from_secs(2);

/// The limits and deadlines of a [`Server`](crate::Server) (the module documentation of the
/// server says how they apply: one deadline per phase of a request, eviction of the
/// longest-waiting connection at the limit).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ServerConfig {
    /// The largest request body, in bytes (default 16 MiB).
    pub max_body: usize,
    /// Connections open at once (default 64); at the limit the longest-waiting one is closed.
    pub max_connections: usize,
    /// From a new connection's accept, or from the first byte of a request on a kept-alive
    /// one, to the end of the request head (default 10 s).
    pub head_timeout: Duration,
    /// How long a kept-alive connection waits for its next request (default 30 s).
    pub idle_timeout: Duration,
    /// The floor of a body's deadline (default 10 s).
    pub body_timeout: Duration,
    /// The slowest rate a body may arrive at, in bytes per second, on top of the floor
    /// (default 256 KiB/s: 64 s more for a 16 MiB body).
    pub body_rate: usize,
    /// The time to write one answer (default 30 s).
    pub write_timeout: Duration,
}

impl Default for ServerConfig {
    fn default() -> ServerConfig {
        ServerConfig {
            max_body: MAX_BODY,
            max_connections: 64,
            head_timeout: Duration::from_secs(10),
            idle_timeout: Duration::from_secs(30),
            body_timeout: Duration::from_secs(10),
            body_rate: 256 * 1024,
            write_timeout: Duration::from_secs(30),
        }
    }
}

impl ServerConfig {
    /// The deadline of a body of `length` bytes: `body_timeout + length / body_rate`.
    pub fn body_deadline(&self, length: usize) -> Duration {
        let rate = self.body_rate.max(1) as f64;
        self.body_timeout
            .saturating_add(Duration::from_secs_f64(length as f64 / rate))
    }
}

/// A request: method, path (without the query), headers (names in lower case) and body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Request {
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

    /// How many headers are named `name` (lower case).
    fn count(&self, name: &str) -> usize {
        self.headers.iter().filter(|(n, _)| n == name).count()
    }
}

/// A response: status, content type, extra headers and body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Response {
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

    /// Writes the answer; `head_only` (a `HEAD` request) leaves out the body but keeps its
    /// `Content-Length`.
    fn write_to(&self, w: &mut impl Write, close: bool, head_only: bool) -> io::Result<()> {
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
        let mut bytes = head.into_bytes();
        if !head_only {
            bytes.extend_from_slice(&self.body);
        }
        w.write_all(&bytes)?;
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
        408 => "Request Timeout",
        409 => "Conflict",
        411 => "Length Required",
        413 => "Payload Too Large",
        417 => "Expectation Failed",
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

/// A read error as a refusal: past the deadline is 408.
fn read_failure(e: &io::Error, what: &str) -> Refusal {
    if e.kind() == io::ErrorKind::TimedOut {
        refuse(408, format!("{what} did not arrive in time"))
    } else {
        refuse(400, format!("cannot read {what}: {e}"))
    }
}

/// A request head that passed the checks of the syntax, before its body is read.
#[derive(Debug)]
pub(crate) struct Head {
    /// The request, its body still empty.
    pub request: Request,
    /// `Content-Length` (0 without one).
    pub body_length: usize,
    /// `Expect: 100-continue` on an HTTP/1.1 request.
    pub expect_continue: bool,
    /// The connection stays open after the answer (HTTP/1.1 without `Connection: close`).
    pub keep_alive: bool,
}

/// `tchar` of RFC 9110 5.6.2: the characters of a header name or a method.
fn is_token_char(c: u8) -> bool {
    c.is_ascii_alphanumeric() || b"!#$%&'*+-.^_`|~".contains(&c)
}

/// Whether `value` is `host[:port]` (RFC 9110 7.2, RFC 3986 3.2.2): an IP literal in brackets,
/// or a name of unreserved characters, sub-delimiters and %-escapes; a port of digits.
pub(crate) fn is_valid_host(value: &str) -> bool {
    let (host, port) = if let Some(rest) = value.strip_prefix('[') {
        let Some((literal, after)) = rest.split_once(']') else {
            return false;
        };
        let literal_ok = !literal.is_empty()
            && literal
                .bytes()
                .all(|c| c.is_ascii_hexdigit() || c == b':' || c == b'.');
        if !literal_ok {
            return false;
        }
        match after {
            "" => return true,
            _ => match after.strip_prefix(':') {
                Some(port) => ("x", Some(port)),
                None => return false,
            },
        }
    } else {
        match value.split_once(':') {
            Some((host, port)) => (host, Some(port)),
            None => (value, None),
        }
    };
    if host.is_empty() {
        return false;
    }
    let bytes = host.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if c == b'%' {
            if !(bytes.get(i + 1).is_some_and(u8::is_ascii_hexdigit)
                && bytes.get(i + 2).is_some_and(u8::is_ascii_hexdigit))
            {
                return false;
            }
            i += 3;
            continue;
        }
        if !(c.is_ascii_alphanumeric() || b"-._~!$&'()*+,;=".contains(&c)) {
            return false;
        }
        i += 1;
    }
    port.is_none_or(|p| p.bytes().all(|c| c.is_ascii_digit()))
}

/// Reads one request head and checks its syntax. `Ok(None)`: the peer closed the connection
/// before a request. A read past the reader's deadline is 408.
pub(crate) fn read_head(reader: &mut impl BufRead) -> Result<Option<Head>, Refusal> {
    let mut head = Vec::new();
    let mut lines: Vec<String> = Vec::new();
    loop {
        let mut line = Vec::new();
        let n = (&mut *reader)
            .take((MAX_HEAD + 1 - head.len().min(MAX_HEAD)) as u64)
            .read_until(b'\n', &mut line)
            .map_err(|e| read_failure(&e, "the request head"))?;
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
    if method.is_empty() || !method.bytes().all(is_token_char) || target.is_empty() {
        return Err(refuse(400, "malformed request line"));
    }
    let http11 = match version {
        "HTTP/1.0" => false,
        v if v.len() == 8 && v.starts_with("HTTP/1.") && v.as_bytes()[7].is_ascii_digit() => true,
        _ => return Err(refuse(400, "only HTTP/1.x is served")),
    };
    let mut headers = Vec::new();
    for line in &lines[1..] {
        if line.starts_with([' ', '\t']) {
            return Err(refuse(
                400,
                "a header line starts with whitespace (obsolete line folding, RFC 9112 5.2)",
            ));
        }
        let Some((name, value)) = line.split_once(':') else {
            return Err(refuse(400, format!("malformed header line `{line}`")));
        };
        if name.ends_with([' ', '\t']) {
            return Err(refuse(
                400,
                format!(
                    "header `{}`: whitespace between the name and the colon (RFC 9112 5.1)",
                    name.trim_end()
                ),
            ));
        }
        if name.is_empty() || !name.bytes().all(is_token_char) {
            return Err(refuse(400, format!("malformed header name `{name}`")));
        }
        let value = value.trim_matches([' ', '\t']);
        if value.bytes().any(|c| c != b'\t' && (c < 0x20 || c == 0x7f)) {
            return Err(refuse(
                400,
                format!("header `{name}`: the value holds a control character"),
            ));
        }
        headers.push((name.to_ascii_lowercase(), value.to_owned()));
    }
    let path = target.split(['?', '#']).next().unwrap_or("").to_owned();
    let request = Request {
        method: method.to_owned(),
        path,
        headers,
        body: Vec::new(),
    };
    match (request.count("host"), request.header("host")) {
        (0, _) if http11 => return Err(refuse(400, "the request has no Host header")),
        (0, _) => {}
        (1, Some(host)) if is_valid_host(host) => {}
        (1, Some(host)) => {
            return Err(refuse(
                400,
                format!("Host `{host}` is not a host[:port] (RFC 9110 7.2)"),
            ))
        }
        (n, _) => return Err(refuse(400, format!("the request has {n} Host headers"))),
    }
    if request.header("transfer-encoding").is_some() {
        return Err(refuse(
            411,
            "chunked request bodies are not supported (send Content-Length)",
        ));
    }
    let mut body_length = None;
    for (name, value) in &request.headers {
        if name != "content-length" {
            continue;
        }
        let length: usize = (!value.is_empty() && value.bytes().all(|c| c.is_ascii_digit()))
            .then(|| value.parse().ok())
            .flatten()
            .ok_or_else(|| refuse(400, format!("Content-Length `{value}` is not a number")))?;
        if body_length.is_some_and(|l| l != length) {
            return Err(refuse(400, "two different Content-Length headers"));
        }
        body_length = Some(length);
    }
    let expect_continue = match request.header("expect") {
        None => false,
        Some(e) if e.eq_ignore_ascii_case("100-continue") && request.count("expect") == 1 => {
            http11 // an HTTP/1.0 client's expectation is ignored (RFC 9110 10.1.1)
        }
        Some(e) => return Err(refuse(417, format!("Expect `{e}` is not supported"))),
    };
    let connection_has = |token: &str| {
        request
            .headers
            .iter()
            .filter(|(n, _)| n == "connection")
            .flat_map(|(_, v)| v.split(','))
            .any(|t| t.trim().eq_ignore_ascii_case(token))
    };
    let keep_alive = http11 && !connection_has("close");
    Ok(Some(Head {
        request,
        body_length: body_length.unwrap_or(0),
        expect_continue,
        keep_alive,
    }))
}

/// Reads one whole request (head and body) from a reader with no deadlines: the tests of the
/// syntax. `Ok(None)`: the peer closed the connection before a request.
#[cfg(test)]
pub(crate) fn read_request(
    reader: &mut impl BufRead,
    max_body: usize,
) -> Result<Option<Request>, Refusal> {
    let Some(head) = read_head(reader)? else {
        return Ok(None);
    };
    let mut request = head.request;
    check_length(head.body_length, max_body)?;
    let mut body = vec![0; head.body_length];
    reader
        .read_exact(&mut body)
        .map_err(|e| read_failure(&e, "the request body"))?;
    request.body = body;
    Ok(Some(request))
}

fn check_length(length: usize, max_body: usize) -> Result<(), Refusal> {
    if length > max_body {
        return Err(refuse(
            413,
            format!(
                "the request body of {length} bytes is larger than the limit of {max_body} bytes"
            ),
        ));
    }
    Ok(())
}

/// Whether a request comes from this server's own page: exactly one `Host` header, and it is
/// `127.0.0.1:PORT` or `localhost:PORT`; an `Origin` header, when present, is the one such
/// value with `http://`. Anything else (another site's page, a DNS-rebinding name) is refused.
///
/// # Errors
/// The reason, for a 403 answer.
pub(crate) fn check_origin(request: &Request, port: u16) -> Result<(), String> {
    let hosts = [format!("127.0.0.1:{port}"), format!("localhost:{port}")];
    match (request.count("host"), request.header("host")) {
        (1, Some(host)) if hosts.iter().any(|h| h.eq_ignore_ascii_case(host)) => {}
        (1, Some(host)) => return Err(format!("refused: Host `{host}` is not this studio")),
        (0, _) => return Err("refused: the request has no Host header".to_owned()),
        (n, _) => return Err(format!("refused: the request has {n} Host headers")),
    }
    if request.count("origin") > 1 {
        return Err("refused: the request has several Origin headers".to_owned());
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
pub(crate) trait Handler: Send + Sync + 'static {
    /// The response to a request that passed [`check_origin`].
    fn handle(&self, request: &Request) -> Response;
}

/// What a connection is doing, for the choice of the one to close at the limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Phase {
    /// Waiting for a request (new, or kept alive): closed first.
    Waiting,
    /// A request is arriving: closed when no connection waits.
    Arriving,
    /// A request is being answered: never closed.
    Answering,
}

struct Slot {
    id: u64,
    /// A handle on the socket, to shut it down from the accepting thread.
    stream: TcpStream,
    phase: Phase,
    since: Instant,
}

/// The open connections.
#[derive(Default)]
struct Slots {
    next_id: u64,
    open: Vec<Slot>,
}

type SharedSlots = Arc<Mutex<Slots>>;

fn lock(slots: &SharedSlots) -> std::sync::MutexGuard<'_, Slots> {
    slots.lock().unwrap_or_else(|e| e.into_inner())
}

fn set_phase(slots: &SharedSlots, id: u64, phase: Phase) {
    if let Some(slot) = lock(slots).open.iter_mut().find(|s| s.id == id) {
        slot.phase = phase;
        slot.since = Instant::now();
    }
}

/// Removes a connection's slot when its thread ends, panic or not.
struct Release {
    slots: SharedSlots,
    id: u64,
}

impl Drop for Release {
    fn drop(&mut self) {
        lock(&self.slots).open.retain(|s| s.id != self.id);
    }
}

/// A listening server.
pub(crate) struct Listener<H: Handler> {
    listener: TcpListener,
    handler: Arc<H>,
    config: ServerConfig,
}

impl<H: Handler> Listener<H> {
    /// Listens on `127.0.0.1:port` (0: any free port), with the default [`ServerConfig`].
    ///
    /// # Errors
    /// The port cannot be bound.
    pub fn bind(port: u16, handler: H) -> io::Result<Listener<H>> {
        let listener = TcpListener::bind(SocketAddr::from(([127, 0, 0, 1], port)))?;
        Ok(Listener {
            listener,
            handler: Arc::new(handler),
            config: ServerConfig::default(),
        })
    }

    /// Sets the body limit (tests).
    pub fn with_max_body(mut self, max_body: usize) -> Listener<H> {
        self.config.max_body = max_body;
        self
    }

    /// Sets the limits and deadlines.
    pub fn with_config(mut self, config: ServerConfig) -> Listener<H> {
        self.config = config;
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
        let config = Arc::new(self.config.clone());
        let slots: SharedSlots = Arc::default();
        for stream in self.listener.incoming() {
            let Ok(stream) = stream else {
                // Out of file descriptors, say: wait a little rather than spin.
                std::thread::sleep(Duration::from_millis(20));
                continue;
            };
            let Some(id) = admit(&slots, &stream, config.max_connections) else {
                let mut stream = stream;
                let _ = stream.set_write_timeout(Some(Duration::from_secs(1)));
                let _ = Response::error(503, "too many connections: every one is being answered")
                    .write_to(&mut stream, true, false);
                continue;
            };
            let handler = Arc::clone(&self.handler);
            let release = Release {
                slots: Arc::clone(&slots),
                id,
            };
            let config = Arc::clone(&config);
            // Without a thread the closure, the stream and the release are dropped: the
            // connection is closed and its slot freed.
            let _ = std::thread::Builder::new()
                .name("studio-connection".to_owned())
                .spawn(move || {
                    connection(stream, port, &*handler, &config, release);
                });
        }
    }

    /// Serves on a background thread (for tests and embedding); returns the port.
    pub fn spawn(self) -> u16 {
        let port = self.port();
        std::thread::spawn(move || self.serve());
        port
    }
}

/// Gives a new connection a slot, closing the longest-waiting (else longest-arriving) open one
/// at the limit; `None` when every open connection is being answered.
fn admit(slots: &SharedSlots, stream: &TcpStream, max_connections: usize) -> Option<u64> {
    let handle = stream.try_clone().ok()?;
    let mut slots = lock(slots);
    while slots.open.len() >= max_connections.max(1) {
        let victim = slots
            .open
            .iter()
            .enumerate()
            .filter(|(_, s)| s.phase != Phase::Answering)
            .min_by_key(|(_, s)| (s.phase, s.since))
            .map(|(i, _)| i)?;
        let victim = slots.open.swap_remove(victim);
        // Its thread's read ends; its release then finds no slot.
        let _ = victim.stream.shutdown(Shutdown::Both);
    }
    let id = slots.next_id;
    slots.next_id += 1;
    slots.open.push(Slot {
        id,
        stream: handle,
        phase: Phase::Waiting,
        since: Instant::now(),
    });
    Some(id)
}

/// A socket read with one deadline for a whole phase (not per read).
struct Deadline {
    stream: TcpStream,
    deadline: Instant,
}

impl Read for Deadline {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let left = self.deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            return Err(io::ErrorKind::TimedOut.into());
        }
        self.stream.set_read_timeout(Some(left))?;
        match self.stream.read(buf) {
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => Err(io::ErrorKind::TimedOut.into()),
            other => other,
        }
    }
}

/// Answers a refusal and closes, draining for at most [`LINGER`] a body not read.
fn refuse_and_close(
    writer: &mut TcpStream,
    reader: &mut BufReader<Deadline>,
    refusal: &Refusal,
    unread_body: bool,
) {
    let answered = Response::error(refusal.status, &refusal.message)
        .write_to(writer, true, false)
        .is_ok();
    if answered && unread_body {
        let _ = writer.shutdown(Shutdown::Write);
        reader.get_mut().deadline = Instant::now() + LINGER;
        let _ = io::copy(&mut reader.take(1024 * 1024), &mut io::sink());
    }
}

/// Serves the requests of one connection until it closes, a deadline passes or a request is
/// refused.
fn connection(
    stream: TcpStream,
    port: u16,
    handler: &impl Handler,
    config: &ServerConfig,
    release: Release,
) {
    let _ = stream.set_nodelay(true);
    let _ = stream.set_write_timeout(Some(config.write_timeout));
    let Ok(mut writer) = stream.try_clone() else {
        return;
    };
    let mut reader = BufReader::new(Deadline {
        stream,
        deadline: Instant::now() + config.head_timeout,
    });
    // Declared after the socket, so dropped before it: the slot is free when the peer sees
    // the connection close.
    let release = release;
    let (slots, id) = (&release.slots, release.id);
    let mut first = true;
    loop {
        if !first {
            set_phase(slots, id, Phase::Waiting);
            reader.get_mut().deadline = Instant::now() + config.idle_timeout;
        }
        // The first byte of a request (a new connection's deadline is its head's).
        match reader.fill_buf() {
            Ok([]) | Err(_) => return,
            Ok(_) => {}
        }
        set_phase(slots, id, Phase::Arriving);
        if !first {
            reader.get_mut().deadline = Instant::now() + config.head_timeout;
        }
        first = false;
        let head = match read_head(&mut reader) {
            Ok(Some(head)) => head,
            Ok(None) => return,
            Err(refusal) => {
                refuse_and_close(&mut writer, &mut reader, &refusal, false);
                return;
            }
        };
        let checked = check_origin(&head.request, port)
            .map_err(|message| refuse(403, message))
            .and_then(|()| check_length(head.body_length, config.max_body));
        if let Err(refusal) = checked {
            // Unread: with `Expect: 100-continue` the client has not sent it.
            let unread = head.body_length > 0 && !head.expect_continue;
            refuse_and_close(&mut writer, &mut reader, &refusal, unread);
            return;
        }
        let mut request = head.request;
        if head.body_length > 0 || head.expect_continue {
            if head.expect_continue
                && writer
                    .write_all(b"HTTP/1.1 100 Continue\r\n\r\n")
                    .and_then(|()| writer.flush())
                    .is_err()
            {
                return;
            }
            reader.get_mut().deadline = Instant::now() + config.body_deadline(head.body_length);
            let mut body = vec![0; head.body_length];
            if let Err(e) = reader.read_exact(&mut body) {
                if e.kind() == io::ErrorKind::UnexpectedEof {
                    return; // the client went away
                }
                refuse_and_close(
                    &mut writer,
                    &mut reader,
                    &read_failure(&e, "the request body"),
                    false,
                );
                return;
            }
            request.body = body;
        }
        set_phase(slots, id, Phase::Answering);
        let page_module = crate::assets::module(&request.path)
            .filter(|_| request.method == "GET" || request.method == "HEAD");
        let response = if let Some(text) = page_module {
            Response::new(200, "text/javascript; charset=utf-8", text)
        } else {
            // A bug in a handler answers 500 and leaves the server running.
            match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                handler.handle(&request)
            })) {
                Ok(r) => r,
                Err(_) => Response::error(500, "internal error (the studio keeps running)"),
            }
        };
        let head_only = request.method == "HEAD";
        if response
            .write_to(&mut writer, !head.keep_alive, head_only)
            .is_err()
            || !head.keep_alive
        {
            return;
        }
    }
}

#[cfg(test)]
mod tests;
