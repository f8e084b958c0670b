//! A job's request on the command line: one flag per option of an
//! [`OptionSet`](neutrospline::options::OptionSet), defined in the library that owns the job
//! (names, help and defaults) and flattened into a command's arguments with
//! `#[command(flatten)]`.

use clap::{Arg, ArgAction, ArgMatches, Args, Command, FromArgMatches};
use neutrospline::options::{OptionError, OptionSet, OptionSpec, OptionValue, ValueKind};

use crate::input::UsageError;

/// The options of request `R` as command-line flags: `--NAME VALUE`, or `--NAME` for a flag.
/// Each value is handed to the request as given, so the messages are the library's; the first
/// refused one is kept and reported by [`RequestArgs::request`] as a usage error.
#[derive(Clone, Debug, PartialEq)]
pub struct RequestArgs<R> {
    request: R,
    refused: Option<OptionError>,
}

impl<R: OptionSet> RequestArgs<R> {
    /// The request, or the first option it refused.
    ///
    /// # Errors
    /// A [`UsageError`] with the library's message.
    pub fn request(&self) -> Result<&R, UsageError> {
        match &self.refused {
            Some(error) => Err(UsageError(error.to_string())),
            None => Ok(&self.request),
        }
    }

    /// The flag of each option, with its help and default from the library.
    fn args() -> Vec<Arg> {
        let defaults = R::default();
        R::OPTIONS
            .iter()
            .map(|spec| {
                let default = defaults.value_text(spec.name).ok().flatten();
                arg_of(spec, spec.help.to_owned(), default)
            })
            .collect()
    }
}

impl<R: OptionSet> FromArgMatches for RequestArgs<R> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut this = RequestArgs {
            request: R::default(),
            refused: None,
        };
        this.update_from_arg_matches(matches)?;
        Ok(this)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for spec in R::OPTIONS {
            let value = match spec.kind {
                ValueKind::Flag => matches
                    .get_flag(spec.name)
                    .then_some(OptionValue::Flag(true)),
                _ => matches
                    .get_one::<String>(spec.name)
                    .map(|word| OptionValue::Word(word.clone())),
            };
            if let Some(value) = value {
                if let Err(error) = self.request.set(spec.name, value) {
                    self.refused.get_or_insert(error);
                }
            }
        }
        Ok(())
    }
}

impl<R: OptionSet> Args for RequestArgs<R> {
    fn augment_args(command: Command) -> Command {
        command.args(Self::args())
    }

    fn augment_args_for_update(command: Command) -> Command {
        command.args(Self::args())
    }
}

/// The options of two requests on one command (a curve fit and a surface fit): one flag per
/// name in either list (the first request's help and default where both have it, the
/// second's help added). The values are kept as given and handed, by
/// [`UnionArgs::first`] or [`UnionArgs::second`], to the request the command runs, so the
/// messages are the library's; a flag only the other request knows is refused.
#[derive(Clone, Debug, PartialEq)]
pub struct UnionArgs<A, B> {
    words: Vec<(&'static str, OptionValue)>,
    requests: core::marker::PhantomData<(A, B)>,
}

impl<A: OptionSet, B: OptionSet> UnionArgs<A, B> {
    /// The request `A` from the values given.
    ///
    /// # Errors
    /// A [`UsageError`]: a value `A` refuses, or a flag of `B` only (`--NAME applies only
    /// {only_b}`).
    pub fn first(&self, only_b: &str) -> Result<A, UsageError> {
        Self::build::<A, B>(&self.words, only_b)
    }

    /// The request `B` from the values given (as [`UnionArgs::first`]).
    ///
    /// # Errors
    /// A [`UsageError`].
    pub fn second(&self, only_a: &str) -> Result<B, UsageError> {
        Self::build::<B, A>(&self.words, only_a)
    }

    fn build<R: OptionSet, S: OptionSet>(
        words: &[(&'static str, OptionValue)],
        only_other: &str,
    ) -> Result<R, UsageError> {
        let mut request = R::default();
        for (name, value) in words {
            if R::OPTIONS.iter().any(|s| s.name == *name) {
                request
                    .set(name, value.clone())
                    .map_err(|e| UsageError(e.to_string()))?;
            } else if S::OPTIONS.iter().any(|s| s.name == *name) {
                return Err(UsageError(format!("--{name} applies only {only_other}")));
            }
        }
        Ok(request)
    }

    /// Every option of either list, in order: `A`'s, then `B`'s own.
    fn specs() -> Vec<(OptionSpec, String, Option<String>)> {
        let (a, b) = (A::default(), B::default());
        let mut out: Vec<(OptionSpec, String, Option<String>)> = A::OPTIONS
            .iter()
            .map(|spec| {
                let mut help = spec.help.to_owned();
                if let Some(other) = B::OPTIONS.iter().find(|s| s.name == spec.name) {
                    if other.help != spec.help {
                        help.push_str(&format!("; {}", lowercase_first(other.help)));
                    }
                }
                (*spec, help, a.value_text(spec.name).ok().flatten())
            })
            .collect();
        for spec in B::OPTIONS {
            if !A::OPTIONS.iter().any(|s| s.name == spec.name) {
                let default = b.value_text(spec.name).ok().flatten();
                out.push((*spec, spec.help.to_owned(), default));
            }
        }
        out
    }
}

/// `Text` as `text` (a help joined after a semicolon).
fn lowercase_first(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map_or_else(String::new, |c| {
        c.to_lowercase().chain(chars).collect::<String>()
    })
}

/// A flag for one option spec, with its help and default.
fn arg_of(spec: &OptionSpec, mut help: String, default: Option<String>) -> Arg {
    if let ValueKind::Choice(names) = spec.kind {
        help.push_str(&format!(" [possible values: {}]", names.join(", ")));
    }
    let arg = Arg::new(spec.name).long(spec.name);
    match spec.kind {
        ValueKind::Flag => arg.action(ArgAction::SetTrue).help(help),
        _ => {
            if let Some(default) = default {
                help.push_str(&format!(" [default: {default}]"));
            }
            arg.value_name(spec.value_name)
                .action(ArgAction::Set)
                .allow_hyphen_values(matches!(spec.kind, ValueKind::Number | ValueKind::Whole))
                .help(help)
        }
    }
}

impl<A: OptionSet, B: OptionSet> FromArgMatches for UnionArgs<A, B> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut this = UnionArgs {
            words: Vec::new(),
            requests: core::marker::PhantomData,
        };
        this.update_from_arg_matches(matches)?;
        Ok(this)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for (spec, _, _) in Self::specs() {
            let value = match spec.kind {
                ValueKind::Flag => matches
                    .get_flag(spec.name)
                    .then_some(OptionValue::Flag(true)),
                _ => matches
                    .get_one::<String>(spec.name)
                    .map(|word| OptionValue::Word(word.clone())),
            };
            if let Some(value) = value {
                self.words.push((spec.name, value));
            }
        }
        Ok(())
    }
}

impl<A: OptionSet, B: OptionSet> Args for UnionArgs<A, B> {
    fn augment_args(command: Command) -> Command {
        command.args(
            Self::specs()
                .into_iter()
                .map(|(spec, help, default)| arg_of(&spec, help, default)),
        )
    }

    fn augment_args_for_update(command: Command) -> Command {
        Self::augment_args(command)
    }
}
