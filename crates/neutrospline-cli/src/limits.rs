//! Resource limits: how many control points a file may hold, how many rows `eval` may write
//! and how large a file read whole (TOML, JSON, DXF, SVG) may be, so that an absurd input is
//! refused with a clear error instead of exhausting memory or running for days.
//!
//! The limits are global options (`--max-control-points`, `--max-samples`, `--max-file-size`),
//! also read from the environment (`NEUTROSPLINE_MAX_CONTROL_POINTS`, ...). `main` installs
//! them once for the process ([`install`]); the commands consult [`current`] and pass the file
//! limits to the readers of `neutrospline-io` ([`Limits::file_limits`]).
//!
//! CSV files are read as a stream, line by line, so their size is not limited: a CSV file is
//! refused at the first bad line, or at the line that exceeds the control-point limit, without
//! reading further. TOML, JSON, DXF and SVG documents are read whole to be parsed
//! (`neutrospline_io::read_whole`), hence the file size limit, checked before reading.

use std::sync::OnceLock;

pub use neutrospline_io::{DEFAULT_MAX_CONTROL_POINTS, DEFAULT_MAX_FILE_SIZE};

/// Default of `--max-samples` (rows of an `eval` table; a surface's N x N grid counts N²).
pub const DEFAULT_MAX_SAMPLES: u64 = 10_000_000_000;

/// The limits in force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// The most control points a model may have (surfaces: rows x cols).
    pub max_control_points: u64,
    /// The most rows `eval` may produce.
    pub max_samples: u64,
    /// The largest file read whole (TOML, JSON, DXF, SVG), in bytes.
    pub max_file_size: u64,
}

impl Limits {
    /// The limits of reading a file, for `neutrospline-io`.
    pub fn file_limits(&self) -> neutrospline_io::Limits {
        let mut limits = neutrospline_io::Limits::default();
        limits.max_control_points = self.max_control_points;
        limits.max_file_size = self.max_file_size;
        limits
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_control_points: DEFAULT_MAX_CONTROL_POINTS,
            max_samples: DEFAULT_MAX_SAMPLES,
            max_file_size: DEFAULT_MAX_FILE_SIZE,
        }
    }
}

/// Declares [`LimitArgs`], one global option per limit (a positive whole number, also read
/// from its environment variable), and [`LimitArgs::limits`], which copies each option into
/// the [`Limits`] field of the same name.
macro_rules! limit_args {
    ($($(#[doc = $help:literal])* $field:ident: $value_name:literal, $env:literal, $default:expr;)*) => {
        /// The global options that set the limits.
        #[derive(Debug, Clone, clap::Args)]
        #[command(next_help_heading = "Limits")]
        pub struct LimitArgs {
            $(
                $(#[doc = $help])*
                #[arg(
                    long,
                    global = true,
                    value_name = $value_name,
                    env = $env,
                    default_value_t = $default,
                    value_parser = clap::value_parser!(u64).range(1..)
                )]
                pub $field: u64,
            )*
        }

        impl LimitArgs {
            /// The limits these options set.
            pub fn limits(&self) -> Limits {
                Limits {
                    $($field: self.$field,)*
                }
            }
        }
    };
}

limit_args! {
    /// Refuse a model with more control points than this (a CSV file is refused at the line
    /// that exceeds it, without reading further)
    max_control_points: "N", "NEUTROSPLINE_MAX_CONTROL_POINTS", DEFAULT_MAX_CONTROL_POINTS;
    /// Refuse to evaluate more rows than this (--samples N gives N rows for a curve, N x N for
    /// a surface)
    max_samples: "N", "NEUTROSPLINE_MAX_SAMPLES", DEFAULT_MAX_SAMPLES;
    /// Refuse a file read whole (TOML, JSON, DXF, SVG) larger than this many bytes (default
    /// 256 MiB; CSV files are streamed and not limited in size)
    max_file_size: "BYTES", "NEUTROSPLINE_MAX_FILE_SIZE", DEFAULT_MAX_FILE_SIZE;
}

static LIMITS: OnceLock<Limits> = OnceLock::new();

/// Sets the limits for the rest of the process (the first call wins).
pub fn install(limits: Limits) {
    let _ = LIMITS.set(limits);
}

/// The limits in force: those installed, else the defaults.
pub fn current() -> Limits {
    LIMITS.get().copied().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use clap::{Args, Parser};

    use super::*;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        limits: LimitArgs,
    }

    #[test]
    fn limits_options_set_their_own_fields() {
        let cli = Cli::try_parse_from([
            "neutrospline",
            "--max-control-points",
            "3",
            "--max-samples",
            "5",
            "--max-file-size",
            "7",
        ])
        .unwrap();
        let expected = Limits {
            max_control_points: 3,
            max_samples: 5,
            max_file_size: 7,
        };
        assert_eq!(cli.limits.limits(), expected);
        for option in ["--max-control-points", "--max-samples", "--max-file-size"] {
            assert!(
                Cli::try_parse_from(["neutrospline", option, "0"]).is_err(),
                "{option} 0"
            );
        }
    }

    #[test]
    fn limits_file_size_help_names_every_file_read_whole() {
        // The files `neutrospline_io::read_whole` reads (its message names the same four).
        let command = LimitArgs::augment_args(clap::Command::new("neutrospline"));
        let option = command
            .get_arguments()
            .find(|a| a.get_id() == "max_file_size")
            .unwrap();
        let help = option.get_help().unwrap().to_string();
        for format in ["TOML", "JSON", "DXF", "SVG"] {
            assert!(help.contains(format), "{format} not in {help:?}");
        }
        assert!(help.contains("CSV files are streamed"), "{help:?}");
    }
}
