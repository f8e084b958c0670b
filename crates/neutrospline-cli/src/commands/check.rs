//! `neutrospline check FILE`: validate a file and summarise the curve.

use crate::commands::MembershipArg;
use crate::input;
use crate::output::{self, number};

/// Arguments of `check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The curve file: .csv, .toml or .json; `-` reads CSV from standard input
    #[arg(value_name = "FILE")]
    pub file: String,

    /// Membership rule for the degrees. For CSV it chooses the rule (default neutrosophic); for
    /// TOML/JSON it applies when the file declares none and must agree with the file otherwise
    #[arg(long, value_enum, value_name = "RULE")]
    pub membership: Option<MembershipArg>,
}

/// Validates the file and prints its summary.
///
/// # Errors
/// An invalid file, or a write error.
pub fn run(args: &CheckArgs) -> anyhow::Result<()> {
    let model = input::load(&args.file, args.membership.map(Into::into))?;
    let file = model.file.clone();
    let kind = model.kind;
    let name = model.name.clone();
    let membership = model.membership;
    let curve = model.into_curve()?;
    output::emit(None, |w| {
        writeln!(w, "{file}: valid")?;
        writeln!(w, "kind: {kind}")?;
        if let Some(name) = &name {
            writeln!(w, "name: {name}")?;
        }
        writeln!(w, "degree: {}", curve.degree())?;
        writeln!(w, "dimension: {}", curve.dimension())?;
        writeln!(w, "control points: {}", curve.len())?;
        writeln!(w, "membership: {membership}")?;
        for (label, range) in ["truth", "indeterminacy", "falsity"]
            .iter()
            .zip(curve.degree_ranges())
        {
            writeln!(w, "{label}: {}..{}", number(range.min), number(range.max))?;
        }
        Ok(())
    })
}
