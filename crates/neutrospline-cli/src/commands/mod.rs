//! The subcommands: each parses nothing itself, calls the input layer and the core library,
//! and writes through the output layer.

pub mod bench;
pub mod bench_fit;
pub mod check;
pub mod eval;
pub mod example;
pub mod export;
pub mod fit;
pub mod import;
pub mod intersect;
pub mod options;
pub mod plot;
pub mod query;
pub mod relation;
pub mod studio;
pub mod transform;

use neutrospline::Membership;

/// The `--membership` values, mirroring the core's [`Membership`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MembershipArg {
    /// Truth, indeterminacy and falsity, independent, each in [0, 1].
    Neutrosophic,
    /// Truth and falsity with truth + falsity <= 1; indeterminacy optional (= 1 - T - F).
    Intuitionistic,
    /// Truth only; indeterminacy and falsity absent or 0.
    Fuzzy,
}

impl From<MembershipArg> for Membership {
    fn from(m: MembershipArg) -> Membership {
        match m {
            MembershipArg::Neutrosophic => Membership::Neutrosophic,
            MembershipArg::Intuitionistic => Membership::Intuitionistic,
            MembershipArg::Fuzzy => Membership::Fuzzy,
        }
    }
}
