//! # neutrospline-studio
//!
//! `neutrospline studio`: a page in the browser where a curve is shaped and the degrees of its
//! membership family edited, one field and slider per channel (truth, indeterminacy and
//! falsity, or the interval bounds and bipolar degrees of the wide families), while the
//! paper's views redraw (docs/model.md sections 4-6 for what is drawn). The page is plain HTML, CSS and JavaScript embedded in the
//! binary; it computes nothing itself. Each edit sends the model (the JSON object a `.json`
//! save writes) to a small HTTP server on 127.0.0.1, which reads it with `neutrospline-io`
//! (so a refused value carries the CLI's message), draws the views shown with
//! `neutrospline-plot` and evaluates the table with the core's traits. Settled figures are the
//! SVG `neutrospline plot` writes; while a point is dragged the page asks for the same drawings
//! as display lists (`neutrospline_plot::Drawing::to_display_list`) and paints them on
//! canvases (`paint.js`), which is several times faster for the browser than laying out SVG.
//!
//! ## The public items
//! What starts the studio, as the CLI's `studio` command does:
//! - [`Studio`]: the model the studio was started with and the one file it may write; it
//!   answers the page's requests (the routes are listed in the `api` module).
//! - [`Server`]: the HTTP/1.1 server, one thread per connection, listening on 127.0.0.1
//!   only; it refuses requests whose `Host` or `Origin` is not its own, and bodies over its
//!   limit.
//! - [`open_browser`]: asks the desktop to open a URL, quietly.
//!
//! The figures are `neutrospline_plot::PlotModel::from_model` (and `DataOverlay::from_table`
//! for data), the `plot` command's own code path, so an exported SVG is the command's bytes.
//!
//! ```no_run
//! use neutrospline_studio::{Server, Studio};
//! let server = Server::bind(0, Studio::example())?;
//! println!("{}", server.url());
//! server.serve();
//! # Ok::<(), std::io::Error>(())
//! ```

#![deny(missing_docs)]

mod api;
mod assets;
mod figure;
mod http;

pub use api::Studio;
pub use http::ServerConfig;

/// The studio's HTTP/1.1 server on 127.0.0.1, answering with a [`Studio`]: one thread per
/// connection, the limits and deadlines of [`ServerConfig`] (its module documents the policy).
pub struct Server(http::Listener<Studio>);

impl Server {
    /// Listens on `127.0.0.1:port` (0: any free port), with the default [`ServerConfig`].
    ///
    /// # Errors
    /// The port cannot be bound.
    pub fn bind(port: u16, studio: Studio) -> std::io::Result<Server> {
        http::Listener::bind(port, studio).map(Server)
    }

    /// Sets the body limit.
    pub fn with_max_body(self, max_body: usize) -> Server {
        Server(self.0.with_max_body(max_body))
    }

    /// Sets the limits and deadlines.
    pub fn with_config(self, config: ServerConfig) -> Server {
        Server(self.0.with_config(config))
    }

    /// The port it listens on.
    pub fn port(&self) -> u16 {
        self.0.port()
    }

    /// The page's address, `http://127.0.0.1:PORT/`.
    pub fn url(&self) -> String {
        self.0.url()
    }

    /// Serves until the process ends; bad requests never stop it.
    pub fn serve(self) {
        self.0.serve();
    }

    /// Serves on a background thread (for tests and embedding); returns the port.
    pub fn spawn(self) -> u16 {
        self.0.spawn()
    }
}

/// Asks the desktop to open `url` in the default browser (`xdg-open`, or `open` on macOS),
/// without waiting and without output. Returns whether a program could be started.
pub fn open_browser(url: &str) -> bool {
    use std::process::{Command, Stdio};
    let program = if cfg!(target_os = "macos") {
        "open"
    } else {
        "xdg-open"
    };
    let child = Command::new(program)
        .arg(url)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn();
    match child {
        Ok(mut child) => {
            // Reap it in the background so that it leaves no zombie.
            std::thread::spawn(move || child.wait());
            true
        }
        Err(_) => false,
    }
}
