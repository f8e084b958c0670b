//! Named options of a job, defined once for every front end (docs/architecture.md, "one
//! definition of every option").
//!
//! A job's request type (for example [`crate::fit::FitRequest`]) lists its options as
//! [`OptionSpec`]s: the canonical name (kebab-case, as the command line spells it), the kind
//! of value, a value name and a one-line help. Every front end sets options by name through
//! the request's `set`, with an [`OptionValue`] built from what it was given (a command-line
//! word, a JSON value, a Python object) without converting it first, so that a wrong type, an
//! unknown name or a value out of range gets the same [`OptionError`] message everywhere.
//!
//! ```
//! use neutrospline::options::{OptionError, OptionSet, OptionValue};
//! use neutrospline::fit::FitRequest;
//! let mut request = FitRequest::default();
//! request.set("degree", OptionValue::Integer(5))?;
//! assert_eq!(request.degree, 5);
//! // A float is not a whole number, whatever front end it came from.
//! let error = request.set("degree", OptionValue::Number(5.0)).unwrap_err();
//! assert_eq!(error.to_string(), "degree = 5.0: expected a whole number");
//! # Ok::<(), OptionError>(())
//! ```

use core::fmt;

/// The kind of value an option takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueKind {
    /// On or off (`true` / `false`; on the command line, present or absent).
    Flag,
    /// A whole number `>= 0`.
    Whole,
    /// A number (a whole number is one too).
    Number,
    /// A list of numbers (on the command line, comma-separated: `0,0.5,1`).
    Numbers,
    /// One of these names.
    Choice(&'static [&'static str]),
    /// Any text.
    Text,
}

impl ValueKind {
    /// What a value of this kind must be, as the error messages say it.
    pub fn expected(self) -> String {
        match self {
            ValueKind::Flag => "expected true or false".to_owned(),
            ValueKind::Whole => "expected a whole number".to_owned(),
            ValueKind::Number => "expected a number".to_owned(),
            ValueKind::Numbers => "expected a list of numbers".to_owned(),
            ValueKind::Choice(names) => format!("expected one of {}", names.join(", ")),
            ValueKind::Text => "expected text".to_owned(),
        }
    }
}

/// One option of a job: its canonical name, the kind of its value, the value's name in usage
/// lines and a one-line help.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OptionSpec {
    /// The canonical name: kebab-case, as the command line spells it (`control-points`).
    pub name: &'static str,
    /// The kind of value.
    pub kind: ValueKind,
    /// The value's name in usage lines (`N`, `E`, `RULE`).
    pub value_name: &'static str,
    /// What the option does, one line.
    pub help: &'static str,
}

impl OptionSpec {
    /// The name as a Python keyword argument: `control-points` becomes `control_points`.
    pub fn python_name(&self) -> String {
        self.name.replace('-', "_")
    }

    /// Reads `value` as this option's kind.
    ///
    /// # Errors
    /// [`OptionError::Invalid`] when the value is of another kind (a float for a whole number,
    /// text for a flag) or not one of the choices.
    pub fn read(&self, value: &OptionValue) -> Result<Read, OptionError> {
        let invalid = || OptionError::Invalid {
            name: self.name,
            given: value.to_string(),
            expected: self.kind.expected(),
        };
        match (self.kind, value) {
            (ValueKind::Flag, OptionValue::Flag(on)) => Ok(Read::Flag(*on)),
            (ValueKind::Flag, OptionValue::Word(word)) => match word.as_str() {
                "true" => Ok(Read::Flag(true)),
                "false" => Ok(Read::Flag(false)),
                _ => Err(invalid()),
            },
            (ValueKind::Whole, OptionValue::Integer(n)) => {
                usize::try_from(*n).map(Read::Whole).map_err(|_| invalid())
            }
            (ValueKind::Whole, OptionValue::Word(word)) => word
                .parse::<usize>()
                .map(Read::Whole)
                .map_err(|_| invalid()),
            (ValueKind::Number, OptionValue::Number(x)) => Ok(Read::Number(*x)),
            // Every integer up to 2^53 is a float exactly; beyond, the nearest one.
            #[allow(clippy::cast_precision_loss)]
            (ValueKind::Number, OptionValue::Integer(n)) => Ok(Read::Number(*n as f64)),
            (ValueKind::Number, OptionValue::Word(word)) => word
                .trim()
                .parse::<f64>()
                .map(Read::Number)
                .map_err(|_| invalid()),
            (ValueKind::Numbers, OptionValue::Word(word)) => word
                .split(',')
                .map(|item| item.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map(Read::Numbers)
                .map_err(|_| invalid()),
            // Every integer up to 2^53 is a float exactly; beyond, the nearest one.
            #[allow(clippy::cast_precision_loss)]
            (ValueKind::Numbers, OptionValue::List(items)) => items
                .iter()
                .map(|item| match item {
                    OptionValue::Number(x) => Some(*x),
                    OptionValue::Integer(n) => Some(*n as f64),
                    _ => None,
                })
                .collect::<Option<_>>()
                .map(Read::Numbers)
                .ok_or_else(invalid),
            (ValueKind::Choice(names), OptionValue::Word(word) | OptionValue::Text(word)) => names
                .iter()
                .find(|name| name.eq_ignore_ascii_case(word.trim()))
                .map(|name| Read::Choice(name))
                .ok_or_else(invalid),
            (ValueKind::Text, OptionValue::Word(word) | OptionValue::Text(word)) => {
                Ok(Read::Text(word.clone()))
            }
            _ => Err(invalid()),
        }
    }
}

/// A value given for an option, as the front end received it.
#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    /// `true` or `false` (a JSON or Python boolean, a flag on the command line).
    Flag(bool),
    /// An integer (a JSON or Python integer).
    Integer(i64),
    /// A number with a fraction or exponent (a JSON number such as `5.0`, a Python float).
    Number(f64),
    /// A JSON or Python string: only a choice or text, never a number or a flag.
    Text(String),
    /// A command-line word, read as the option's kind (`5` for a whole number, `true` for a
    /// flag, `0,0.5,1` for a list of numbers).
    Word(String),
    /// A JSON array or a Python list or tuple.
    List(Vec<OptionValue>),
}

impl fmt::Display for OptionValue {
    /// As JSON would write it (`true`, `5`, `5.0`, `"yes"`), a command-line word as given.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OptionValue::Flag(on) => write!(f, "{on}"),
            OptionValue::Integer(n) => write!(f, "{n}"),
            OptionValue::Number(x) => write!(f, "{x:?}"),
            OptionValue::Text(text) => write!(f, "{text:?}"),
            OptionValue::Word(word) => f.write_str(word),
            OptionValue::List(items) => {
                f.write_str("[")?;
                for (i, item) in items.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{item}")?;
                }
                f.write_str("]")
            }
        }
    }
}

/// A value read as its option's kind by [`OptionSpec::read`].
#[derive(Clone, Debug, PartialEq)]
pub enum Read {
    /// A flag.
    Flag(bool),
    /// A whole number.
    Whole(usize),
    /// A number.
    Number(f64),
    /// A list of numbers.
    Numbers(Vec<f64>),
    /// One of the choices (its canonical spelling).
    Choice(&'static str),
    /// Text.
    Text(String),
}

/// Why an option cannot be set, or why a request's options do not fit together. The message
/// names the option by its canonical name, the value and the rule.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum OptionError {
    /// No option has this name.
    #[error("unknown option {name:?} (the options are {known})")]
    Unknown {
        /// The name given.
        name: String,
        /// The options there are, comma-separated.
        known: String,
    },
    /// The value is not of the option's kind.
    #[error("{name} = {given}: {expected}")]
    Invalid {
        /// The option.
        name: &'static str,
        /// The value, as JSON would write it.
        given: String,
        /// What it must be.
        expected: String,
    },
    /// The value is of the right kind but out of the option's range.
    #[error("{name} = {given}: {rule}")]
    OutOfRange {
        /// The option.
        name: &'static str,
        /// The value.
        given: String,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// The data has no weights to use, or has weights the options leave unused.
    #[error("{0}")]
    Data(String),
    /// Two options that exclude each other were both given.
    #[error("{first} and {second} exclude each other ({rule})")]
    Conflict {
        /// The first option, in the order of the request's list.
        first: &'static str,
        /// The second.
        second: &'static str,
        /// Why, and what to give instead.
        rule: &'static str,
    },
}

/// A job's request: its options, set by name. The command line, Python and the studio each
/// have one generic reader over this trait, so a new option is added once, here.
pub trait OptionSet: Default {
    /// Every option, in the order front ends list them.
    const OPTIONS: &'static [OptionSpec];

    /// Sets the option `name` (canonical, as in [`OptionSet::OPTIONS`]) to `value`.
    ///
    /// # Errors
    /// [`OptionError::Unknown`] for a name that is not an option, [`OptionError::Invalid`]
    /// for a value of another kind or not one of the choices.
    fn set(&mut self, name: &str, value: OptionValue) -> Result<(), OptionError>;

    /// The value of option `name` as a command-line word, or `None` while an optional option
    /// is unset: front ends show the defaults as `Self::default().value_text(name)`.
    ///
    /// # Errors
    /// [`OptionError::Unknown`].
    fn value_text(&self, name: &str) -> Result<Option<String>, OptionError>;

    /// Sets every `(name, value)` in turn.
    ///
    /// # Errors
    /// The first [`OptionSet::set`] error.
    fn set_all(
        &mut self,
        values: impl IntoIterator<Item = (String, OptionValue)>,
    ) -> Result<(), OptionError> {
        for (name, value) in values {
            self.set(&name, value)?;
        }
        Ok(())
    }
}

/// The spec named `name` in `specs`.
///
/// # Errors
/// [`OptionError::Unknown`], listing the names there are.
pub fn find(specs: &'static [OptionSpec], name: &str) -> Result<&'static OptionSpec, OptionError> {
    specs
        .iter()
        .find(|spec| spec.name == name)
        .ok_or_else(|| OptionError::Unknown {
            name: name.to_owned(),
            known: specs
                .iter()
                .map(|spec| spec.name)
                .collect::<Vec<_>>()
                .join(", "),
        })
}

/// Reads a map of canonical option names to values into `R` through [`OptionSet::set`], so
/// that an unknown key or a value of another kind is refused with the message every front end
/// prints (a JSON `5.0` for a whole number stays a float; a string is never read as a number).
///
/// # Errors
/// The first [`OptionError`], as a custom error of the deserializer; a value that is not a
/// boolean, a number, a string or a list of them.
#[cfg(feature = "serde")]
pub fn deserialize<'de, R: OptionSet, D: serde::Deserializer<'de>>(
    deserializer: D,
) -> Result<R, D::Error> {
    struct MapVisitor<R>(core::marker::PhantomData<R>);
    impl<'de, R: OptionSet> serde::de::Visitor<'de> for MapVisitor<R> {
        type Value = R;
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("a map of options")
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<R, A::Error> {
            let mut request = R::default();
            while let Some(name) = map.next_key::<String>()? {
                let value: OptionValue = map.next_value()?;
                request
                    .set(&name, value)
                    .map_err(serde::de::Error::custom)?;
            }
            Ok(request)
        }
    }
    deserializer.deserialize_map(MapVisitor(core::marker::PhantomData))
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for OptionValue {
    /// A boolean, an integer, a float, a string or a list of them, kept as it came.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct ValueVisitor;
        impl<'de> serde::de::Visitor<'de> for ValueVisitor {
            type Value = OptionValue;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a boolean, a number or a string")
            }
            fn visit_bool<E>(self, v: bool) -> Result<OptionValue, E> {
                Ok(OptionValue::Flag(v))
            }
            fn visit_u64<E>(self, v: u64) -> Result<OptionValue, E> {
                // Beyond i64, the nearest float: too large for any count anyway.
                #[allow(clippy::cast_precision_loss)]
                Ok(i64::try_from(v).map_or(OptionValue::Number(v as f64), OptionValue::Integer))
            }
            fn visit_i64<E>(self, v: i64) -> Result<OptionValue, E> {
                Ok(OptionValue::Integer(v))
            }
            fn visit_f64<E>(self, v: f64) -> Result<OptionValue, E> {
                Ok(OptionValue::Number(v))
            }
            fn visit_str<E>(self, v: &str) -> Result<OptionValue, E> {
                Ok(OptionValue::Text(v.to_owned()))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<OptionValue, A::Error> {
                let mut items = Vec::new();
                while let Some(item) = seq.next_element()? {
                    items.push(item);
                }
                Ok(OptionValue::List(items))
            }
        }
        deserializer.deserialize_any(ValueVisitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPEC: OptionSpec = OptionSpec {
        name: "count",
        kind: ValueKind::Whole,
        value_name: "N",
        help: "how many",
    };

    #[test]
    fn whole_numbers_come_as_integers_or_words_never_as_floats() {
        assert_eq!(SPEC.read(&OptionValue::Integer(4)), Ok(Read::Whole(4)));
        assert_eq!(
            SPEC.read(&OptionValue::Word("4".into())),
            Ok(Read::Whole(4))
        );
        for bad in [
            OptionValue::Number(4.0),
            OptionValue::Word("4.0".into()),
            OptionValue::Word("-1".into()),
            OptionValue::Text("4".into()),
            OptionValue::Flag(true),
        ] {
            let error = SPEC.read(&bad).unwrap_err();
            assert_eq!(
                error.to_string(),
                format!("count = {bad}: expected a whole number")
            );
        }
    }

    #[test]
    fn flags_are_not_words_other_than_true_and_false() {
        let flag = OptionSpec {
            kind: ValueKind::Flag,
            ..SPEC
        };
        assert_eq!(
            flag.read(&OptionValue::Word("true".into())),
            Ok(Read::Flag(true))
        );
        assert_eq!(
            flag.read(&OptionValue::Text("yes".into()))
                .unwrap_err()
                .to_string(),
            "count = \"yes\": expected true or false"
        );
        assert_eq!(
            flag.read(&OptionValue::Word("yes".into()))
                .unwrap_err()
                .to_string(),
            "count = yes: expected true or false"
        );
    }

    #[test]
    fn choices_ignore_case_and_name_the_alternatives() {
        let choice = OptionSpec {
            kind: ValueKind::Choice(&["uniform", "chord-length"]),
            ..SPEC
        };
        assert_eq!(
            choice.read(&OptionValue::Word("Uniform".into())),
            Ok(Read::Choice("uniform"))
        );
        assert_eq!(
            choice
                .read(&OptionValue::Text("even".into()))
                .unwrap_err()
                .to_string(),
            "count = \"even\": expected one of uniform, chord-length"
        );
    }

    #[test]
    fn lists_of_numbers_are_words_with_commas_or_lists() {
        let list = OptionSpec {
            kind: ValueKind::Numbers,
            ..SPEC
        };
        assert_eq!(
            list.read(&OptionValue::Word("0, 0.5,1".into())),
            Ok(Read::Numbers(vec![0.0, 0.5, 1.0]))
        );
        assert_eq!(
            list.read(&OptionValue::List(vec![
                OptionValue::Integer(0),
                OptionValue::Number(0.5)
            ])),
            Ok(Read::Numbers(vec![0.0, 0.5]))
        );
        let bad = OptionValue::List(vec![OptionValue::Text("a".into())]);
        assert_eq!(
            list.read(&bad).unwrap_err().to_string(),
            "count = [\"a\"]: expected a list of numbers"
        );
    }

    #[test]
    fn an_unknown_name_lists_the_known_ones() {
        static SPECS: [OptionSpec; 1] = [SPEC];
        assert_eq!(
            find(&SPECS, "cuont").unwrap_err().to_string(),
            "unknown option \"cuont\" (the options are count)"
        );
    }
}
