//! What the core says to a person, as a message id of `web/locales/LANG/core-*.ftl` and its
//! arguments: the page renders it in the reader's language, and the CLI (and every text the core
//! writes for a file, such as a CSV's causes) in English from the same English messages, so the two
//! say the same thing.

use serde::de::{MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::borrow::Cow;
use std::fmt;

/// A message: its id in the message files and its arguments by name. Its `Display` is its
/// English text. It reads back from the object it is written as, so that a message the run's
/// module gives (why a challenge's run failed) can be said inside the tools' verdict.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Message {
    /// The message's id (`scenario-unknown-key`).
    #[cfg_attr(target_arch = "wasm32", tsify(type = "string"))]
    pub id: Cow<'static, str>,
    /// Its arguments, by the names the message files use, in the order of their names (a map,
    /// kept as a sorted list: the run's module then carries no map's code).
    #[serde(serialize_with = "as_map", deserialize_with = "from_map")]
    #[cfg_attr(target_arch = "wasm32", tsify(type = "Record<string, Arg>"))]
    pub args: Vec<(Cow<'static, str>, Arg)>,
}

/// A message's arguments.
type Args = Vec<(Cow<'static, str>, Arg)>;

/// `args` as the object the page reads: each name a key.
fn as_map<S: Serializer>(args: &Args, serializer: S) -> Result<S::Ok, S::Error> {
    serializer.collect_map(args.iter().map(|(name, arg)| (name, arg)))
}

/// The arguments from that object, in the order of their names.
fn from_map<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Args, D::Error> {
    struct Names;
    impl<'de> Visitor<'de> for Names {
        type Value = Args;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str("a message's arguments by name")
        }
        fn visit_map<M: MapAccess<'de>>(self, mut map: M) -> Result<Args, M::Error> {
            let mut args = Args::new();
            while let Some((name, arg)) = map.next_entry::<String, Arg>()? {
                args.push((Cow::Owned(name), arg));
            }
            args.sort_by(|a, b| a.0.cmp(&b.0));
            Ok(args)
        }
    }
    deserializer.deserialize_map(Names)
}

/// An argument of a [`Message`]: words the reader gave or a name (shown as they are), a count (a
/// whole number, which a language may choose a plural by), a number written with its shortest
/// digits, a number with a fixed number of decimals, or another message.
#[cfg_attr(
    target_arch = "wasm32",
    derive(tsify::Tsify),
    tsify(missing_as_null, hashmap_as_object)
)]
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Arg {
    /// Text shown as it is: a name, a key, quoted input.
    Text(String),
    /// A whole number.
    Count(i64),
    /// A number written with the fewest digits that read back to it (Rust's `{}`).
    Real {
        /// The number.
        real: f64,
    },
    /// A number written with `fraction` decimals.
    Fixed {
        /// The number.
        fixed: f64,
        /// Its decimals.
        fraction: u8,
    },
    /// A number in scientific notation with `places` decimals in its mantissa (1.58e-4).
    Sci {
        /// The number.
        sci: f64,
        /// The mantissa's decimals.
        places: u8,
    },
    /// A message said inside this one.
    Said(Box<Message>),
    /// Messages listed, in order.
    List(Vec<Message>),
}

impl Message {
    /// The message `id`, with no arguments yet (a constant's, too: a table's words).
    pub const fn new(id: &'static str) -> Message {
        Message {
            id: Cow::Borrowed(id),
            args: Vec::new(),
        }
    }

    /// With `arg` as `name`, in place of any argument of that name.
    fn with(mut self, name: &'static str, arg: Arg) -> Message {
        match self.args.binary_search_by(|(n, _)| n.as_ref().cmp(name)) {
            Ok(i) => self.args[i].1 = arg,
            Err(i) => self.args.insert(i, (Cow::Borrowed(name), arg)),
        }
        self
    }

    /// With text `value` as `name`.
    pub fn text(self, name: &'static str, value: impl Into<String>) -> Message {
        self.with(name, Arg::Text(value.into()))
    }

    /// With the whole number `value` as `name`.
    pub fn count(self, name: &'static str, value: impl TryInto<i64>) -> Message {
        let value = value.try_into().unwrap_or(i64::MAX);
        self.with(name, Arg::Count(value))
    }

    /// With `value` as `name`, in its shortest digits.
    pub fn real(self, name: &'static str, value: f64) -> Message {
        self.with(name, Arg::Real { real: value })
    }

    /// With `value` as `name`, with `fraction` decimals.
    pub fn fixed(self, name: &'static str, value: f64, fraction: u8) -> Message {
        self.with(
            name,
            Arg::Fixed {
                fixed: value,
                fraction,
            },
        )
    }

    /// With `value` as `name`, in scientific notation with `places` decimals in its mantissa.
    pub fn sci(self, name: &'static str, value: f64, places: u8) -> Message {
        self.with(name, Arg::Sci { sci: value, places })
    }

    /// With `value` as `name`, as [`short`](super::short) writes it: its shortest digits, in
    /// scientific notation past twelve characters.
    pub fn short(self, name: &'static str, value: f64) -> Message {
        self.digits(name, super::short(value))
    }

    /// With `value` as `name`, as [`rounded`](super::rounded) writes it to `digits` significant
    /// digits.
    pub fn rounded(self, name: &'static str, value: f64, digits: i32) -> Message {
        self.digits(name, super::rounded(value, digits))
    }

    /// With the time `t` (s) as `name`: a message of its own (`time-ms` below 1 s, else
    /// `time-s`), with up to 4 significant digits.
    pub fn time(self, name: &'static str, t: f64) -> Message {
        self.said(name, time_of(t))
    }

    /// With the number written `text` as `name`: as a number when `text` is its shortest digits
    /// (so that a language writes it with its own decimal separator), else as the text.
    fn digits(self, name: &'static str, text: String) -> Message {
        match text.parse::<f64>() {
            Ok(value) if value.to_string() == text => self.real(name, value),
            _ => self.text(name, text),
        }
    }

    /// With the messages `items` as `name`, a list (joined by ", " in English).
    pub fn list(self, name: &'static str, items: Vec<Message>) -> Message {
        self.with(name, Arg::List(items))
    }

    /// With the message `said` as `name`.
    pub fn said(self, name: &'static str, said: Message) -> Message {
        self.with(name, Arg::Said(Box::new(said)))
    }

    /// With `arg` as `name`, as it came: a message, or the text the page already said it as.
    pub fn arg(self, name: &'static str, arg: Arg) -> Message {
        self.with(name, arg)
    }
}

impl From<Message> for Arg {
    fn from(message: Message) -> Arg {
        Arg::Said(Box::new(message))
    }
}

/// The time `t` (s) as a message: in ms below 1 s, in s from 1 s on, to 4 significant digits.
fn time_of(t: f64) -> Message {
    if t.abs() < 1.0 {
        Message::new("time-ms").digits("ms", super::significant(t * 1e3, 4))
    } else {
        Message::new("time-s").digits("s", super::significant(t, 4))
    }
}

#[cfg(feature = "english")]
mod english {
    use super::{Arg, Message};
    use fluent_bundle::concurrent::FluentBundle;
    use fluent_bundle::{FluentArgs, FluentResource, FluentValue};
    use std::sync::OnceLock;

    /// The English message files of the core, as the page has them.
    const FILES: &[(&str, &str)] = &[
        (
            "core-scenario.ftl",
            include_str!("../../../web/locales/en/core-scenario.ftl"),
        ),
        (
            "core-law.ftl",
            include_str!("../../../web/locales/en/core-law.ftl"),
        ),
        (
            "core-formula.ftl",
            include_str!("../../../web/locales/en/core-formula.ftl"),
        ),
        (
            "core-run.ftl",
            include_str!("../../../web/locales/en/core-run.ftl"),
        ),
        (
            "core-challenge.ftl",
            include_str!("../../../web/locales/en/core-challenge.ftl"),
        ),
        (
            "core-analysis.ftl",
            include_str!("../../../web/locales/en/core-analysis.ftl"),
        ),
    ];

    fn bundle() -> &'static FluentBundle<FluentResource> {
        static BUNDLE: OnceLock<FluentBundle<FluentResource>> = OnceLock::new();
        BUNDLE.get_or_init(|| {
            let mut bundle =
                FluentBundle::new_concurrent(vec!["en".parse().expect("a language id")]);
            bundle.set_use_isolating(false);
            for (name, text) in FILES {
                let resource = FluentResource::try_new((*text).to_owned())
                    .unwrap_or_else(|(_, e)| panic!("web/locales/en/{name} does not parse: {e:?}"));
                bundle
                    .add_resource(resource)
                    .unwrap_or_else(|e| panic!("web/locales/en/{name}: {e:?}"));
            }
            bundle
        })
    }

    /// `message` in English.
    pub(super) fn render(message: &Message) -> String {
        let bundle = bundle();
        let Some(pattern) = bundle.get_message(&message.id).and_then(|m| m.value()) else {
            panic!("no English message {}", message.id);
        };
        let mut args = FluentArgs::new();
        for (name, arg) in &message.args {
            let value: FluentValue = match arg {
                Arg::Text(text) => FluentValue::from(text.as_str()),
                Arg::Count(n) => FluentValue::from(*n),
                Arg::Real { real } => FluentValue::from(real.to_string()),
                Arg::Fixed { fixed, fraction } => {
                    FluentValue::from(format!("{fixed:.*}", *fraction as usize))
                }
                Arg::Sci { sci, places } => {
                    FluentValue::from(format!("{sci:.*e}", *places as usize))
                }
                Arg::Said(inner) => FluentValue::from(render(inner)),
                Arg::List(items) => {
                    FluentValue::from(items.iter().map(render).collect::<Vec<_>>().join(", "))
                }
            };
            args.set(name.as_ref(), value);
        }
        let mut errors = vec![];
        let text = bundle.format_pattern(pattern, Some(&args), &mut errors);
        assert!(errors.is_empty(), "message {}: {errors:?}", message.id);
        text.into_owned()
    }
}

#[cfg(feature = "english")]
impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&english::render(self))
    }
}

#[cfg(not(feature = "english"))]
impl fmt::Display for Message {
    /// The run's module carries no message files and sends its messages as they are, for the
    /// page to render; a message written as text there names its id and arguments.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{:?}", self.id, self.args)
    }
}

#[cfg(all(test, feature = "english"))]
mod tests {
    use super::time_of;

    #[test]
    fn times_read_with_up_to_4_significant_digits() {
        for (t, text) in [
            (0.0, "0 ms"),
            (5.0 / 1200.0, "4.167 ms"),
            (84.0 * 50e-6, "4.2 ms"),
            (0.00045, "0.45 ms"),
            (0.09995, "99.95 ms"),
            (0.05, "50 ms"),
            (0.6, "600 ms"),
            (1.0, "1 s"),
            (12.34567, "12.35 s"),
        ] {
            assert_eq!(time_of(t).to_string(), text);
        }
    }
}
