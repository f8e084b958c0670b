//! A job's request on the command line: one flag per option of an
//! [`OptionSet`](neutrospline::options::OptionSet), defined in the library that owns the job
//! (names, help and defaults) and flattened into a command's arguments with
//! `#[command(flatten)]`.

use clap::{Arg, ArgAction, ArgMatches, Args, Command, FromArgMatches};
use neutrospline::options::{OptionError, OptionSet, OptionValue, ValueKind};

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
                let mut help = spec.help.to_owned();
                if let ValueKind::Choice(names) = spec.kind {
                    help.push_str(&format!(" [possible values: {}]", names.join(", ")));
                }
                let default = defaults.value_text(spec.name).ok().flatten();
                let arg = Arg::new(spec.name).long(spec.name);
                match spec.kind {
                    ValueKind::Flag => arg.action(ArgAction::SetTrue).help(help),
                    _ => {
                        if let Some(default) = default {
                            help.push_str(&format!(" [default: {default}]"));
                        }
                        arg.value_name(spec.value_name)
                            .action(ArgAction::Set)
                            .allow_hyphen_values(matches!(
                                spec.kind,
                                ValueKind::Number | ValueKind::Whole
                            ))
                            .help(help)
                    }
                }
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
