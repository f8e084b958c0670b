//! `neutrospline studio [FILE]`: the studio in the browser (the `neutrospline-studio` crate).

use std::io::Write;
use std::path::PathBuf;

use anyhow::Context as _;
use neutrospline_studio::{open_browser, Server, Studio};

use crate::commands::options::ModelArgs;
use crate::input::{self, UsageError};

/// Arguments of `studio`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "The studio listens on 127.0.0.1 only and refuses requests whose Host or \
Origin is not its own. \"Save\" writes FILE (atomically) and no other file; without FILE the \
page opens the paper's Example 1 and saving downloads the model. Stop it with Ctrl+C."
)]
pub struct StudioArgs {
    /// The model to open: .toml, .json or .csv (default: the paper's Example 1)
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// The port to listen on (0: any free port; the URL is printed)
    #[arg(long, value_name = "P", default_value_t = 0)]
    pub port: u16,

    /// Do not open the default browser; only print the URL
    #[arg(long)]
    pub no_open: bool,

    #[command(flatten)]
    pub model: ModelArgs,
}

/// Reads the model, starts the server, prints its URL, opens the browser and serves.
///
/// # Errors
/// An invalid file (the command's message), `-` (the studio needs a file to save to), or a
/// port that cannot be bound.
pub fn run(args: &StudioArgs) -> anyhow::Result<()> {
    let studio = match &args.file {
        Some(file) if file.as_os_str() == "-" => {
            return Err(UsageError(
                "the studio reads a model file, not standard input (give FILE or none)".into(),
            )
            .into())
        }
        Some(file) => {
            let model = input::read_model(&file.to_string_lossy(), &args.model)?;
            Studio::with_file(model, file.clone())
        }
        None => Studio::example(),
    };
    let server = Server::bind(args.port, studio)
        .with_context(|| format!("cannot listen on 127.0.0.1:{}", args.port))?;
    let url = server.url();
    let mut out = std::io::stdout().lock();
    writeln!(out, "neutrospline studio: {url}")?;
    out.flush()?;
    drop(out);
    if !args.no_open && !open_browser(&url) {
        eprintln!("could not start a browser: open {url}");
    }
    server.serve();
    Ok(())
}
