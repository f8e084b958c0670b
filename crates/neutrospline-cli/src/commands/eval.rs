//! `neutrospline eval FILE`: a table of the curve (and its derivative) at chosen parameters.

use std::path::PathBuf;

use crate::commands::MembershipArg;
use crate::input;
use crate::output::{self, TableFormat};

/// Arguments of `eval`.
#[derive(Debug, clap::Args)]
pub struct EvalArgs {
    /// The curve file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Evaluate at N evenly spaced parameters t_k = k / (N - 1), k = 0..N-1, from 0 to 1
    /// inclusive (N = 1: t = 0 only)
    #[arg(
        long,
        value_name = "N",
        default_value_t = 101,
        value_parser = clap::value_parser!(u64).range(1..),
        conflicts_with = "at"
    )]
    pub samples: u64,

    /// Evaluate at these parameters, in this order (each in [0, 1])
    #[arg(
        long,
        value_name = "T1,T2,...",
        value_parser = parse_parameters,
        allow_negative_numbers = true
    )]
    pub at: Option<Parameters>,

    /// Add the first derivative: columns dx, dy[, dz], dtruth, dindeterminacy, dfalsity
    #[arg(long)]
    pub derivative: bool,

    /// Output format: csv (a header row, then one row per parameter) or json (an array of
    /// objects keyed by column name)
    #[arg(long, value_enum, value_name = "FORMAT", default_value_t = TableFormat::Csv)]
    pub format: TableFormat,

    /// Write to OUT instead of standard output (replaced atomically: on error the old file is
    /// left untouched)
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,

    /// Membership rule for the degrees. For CSV it chooses the rule (default neutrosophic); for
    /// TOML/JSON it applies when the file declares none and must agree with the file otherwise
    #[arg(long, value_enum, value_name = "RULE")]
    pub membership: Option<MembershipArg>,
}

/// The parameters given with `--at`.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameters(pub Vec<f64>);

/// Parses `T1,T2,...`: each a finite number in [0, 1].
fn parse_parameters(text: &str) -> Result<Parameters, String> {
    text.split(',')
        .map(|item| {
            let item = item.trim();
            match item.parse::<f64>() {
                Ok(t) if (0.0..=1.0).contains(&t) => Ok(t),
                Ok(t) if t.is_nan() => Err(format!(
                    "parameter `{item}` is not a number (every parameter must be in [0, 1])"
                )),
                Ok(_) => Err(format!(
                    "parameter `{item}` is outside [0, 1] (every parameter must be in [0, 1])"
                )),
                Err(_) => Err(format!("parameter `{item}` is not a number")),
            }
        })
        .collect::<Result<_, _>>()
        .map(Parameters)
}

/// The parameters to evaluate at.
fn parameters(args: &EvalArgs) -> Box<dyn Iterator<Item = f64> + '_> {
    match &args.at {
        Some(Parameters(ts)) => Box::new(ts.iter().copied()),
        None if args.samples <= 1 => Box::new(std::iter::once(0.0)),
        None => {
            let last = args.samples - 1;
            Box::new((0..=last).map(move |k| k as f64 / last as f64))
        }
    }
}

/// Evaluates and writes the table.
///
/// # Errors
/// An invalid file, an evaluation error, or a write error.
pub fn run(args: &EvalArgs) -> anyhow::Result<()> {
    let model = input::load(&args.file, args.membership.map(Into::into))?;
    let file = model.file.clone();
    let curve = model.into_curve()?;
    let columns = curve.columns(args.derivative);
    let sampler = curve.sampler(args.derivative);
    let rows = parameters(args).map(|t| {
        sampler
            .row(t)
            .map_err(|e| anyhow::anyhow!("{file}: cannot evaluate at t = {t}: {e}"))
    });
    output::emit(args.output.as_deref(), |w| {
        output::write_table(w, args.format, &columns, rows)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_parameters_accepts_and_rejects() {
        assert_eq!(
            parse_parameters("0, 0.5,1"),
            Ok(Parameters(vec![0.0, 0.5, 1.0]))
        );
        assert_eq!(
            parse_parameters("0,1.5").unwrap_err(),
            "parameter `1.5` is outside [0, 1] (every parameter must be in [0, 1])"
        );
        assert!(parse_parameters("-0.1").is_err());
        assert!(parse_parameters("NaN").is_err());
        assert!(parse_parameters("inf").is_err());
        assert_eq!(
            parse_parameters("0,,1").unwrap_err(),
            "parameter `` is not a number"
        );
    }
}
