//! The page's module files, embedded in the binary. `index.html`, `studio.css`, `paint.js` and
//! the entry module `studio.js` are answered by the `api` module; the modules `studio.js`
//! imports (plain ES modules, no bundler) are answered at `/modules/NAME.js` by the server
//! ([`module`]), for `GET` and `HEAD`, after the `Host` and `Origin` checks.

/// The modules of the page, by the path they are served at.
const MODULES: &[(&str, &str)] = &[
    ("/modules/state.js", include_str!("modules/state.js")),
    ("/modules/queue.js", include_str!("modules/queue.js")),
    ("/modules/figures.js", include_str!("modules/figures.js")),
    ("/modules/panel.js", include_str!("modules/panel.js")),
    ("/modules/files.js", include_str!("modules/files.js")),
    ("/modules/fitting.js", include_str!("modules/fitting.js")),
];

/// The text of the page's module served at `path`, if there is one.
pub(crate) fn module(path: &str) -> Option<&'static str> {
    MODULES
        .iter()
        .find(|(p, _)| *p == path)
        .map(|(_, text)| *text)
}
