//! Usage errors as clap renders them, with what a person most likely meant: an option whose value
//! is missing (`-m -v 60,10`: clap takes `-v` as the masses, since a value may start with a
//! minus), a list typed with spaces instead of commas (`-m 4 1`) or after them (`-m 4, 1`), and
//! a case typed without its subcommand (`collide -m 4,1 -v 60,10`).

use std::ffi::OsString;

use clap::error::{ContextKind, ContextValue, ErrorKind};
use collide::view::shell::word;

/// The message for a usage error `e` of `command` run with `args`.
pub fn explain(e: &clap::Error, command: &clap::Command, args: &[OsString]) -> String {
    let words: Vec<String> = args
        .iter()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    if let Some(sub) = subcommand(command, &words) {
        let options = options(sub);
        if let Some(message) = missing_value(&options, &words) {
            return format!("error: {message}\n\nFor more information, try '--help'.");
        }
        if let Some(tip) = spaced_list(e, &options, &words) {
            return with_tip(e, &tip);
        }
    } else if let Some(tip) = no_subcommand(e, command, &words) {
        return with_tip(e, &tip);
    }
    escaped(e)
}

/// clap's message with `tip` after its first line.
fn with_tip(e: &clap::Error, tip: &str) -> String {
    let text = e.render().to_string();
    let (first, rest) = text.split_once('\n').unwrap_or((&text, ""));
    format!("{first}\n\n  tip: {tip}\n{rest}")
}

/// `collide -m 4,1 -v 60,10`: an option of `solve` typed with no subcommand: the same words
/// after `collide solve`.
fn no_subcommand(e: &clap::Error, command: &clap::Command, words: &[String]) -> Option<String> {
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(unexpected)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let solve = options(command.find_subcommand("solve")?);
    if !solve.iter().any(|o| o.is(unexpected)) {
        return None;
    }
    let typed: Vec<String> = words.iter().skip(1).map(|w| word(w)).collect();
    Some(format!(
        "a collision is solved by a subcommand: collide solve {}",
        typed.join(" ")
    ))
}

/// clap's message, but with control characters in a rejected value escaped (`'5\u{7},1'`):
/// clap's rendering drops them, which quotes a value that was not typed.
fn escaped(e: &clap::Error) -> String {
    if e.kind() == ErrorKind::ValueValidation
        && let (Some(ContextValue::String(arg)), Some(ContextValue::String(value))) = (
            e.get(ContextKind::InvalidArg),
            e.get(ContextKind::InvalidValue),
        )
        && value.chars().any(char::is_control)
        && let Some(source) = std::error::Error::source(e)
    {
        return format!(
            "error: invalid value '{}' for '{arg}': {source}\n\nFor more information, try \
             '--help'.",
            collide::values::number::printable(value)
        );
    }
    e.render().to_string()
}

/// An option of a subcommand: how it is typed, and the name of its value when it takes one.
struct Opt {
    short: Option<String>,
    long: Option<String>,
    value: Option<String>,
}

impl Opt {
    fn is(&self, word: &str) -> bool {
        self.short.as_deref() == Some(word)
            || self
                .long
                .as_deref()
                .is_some_and(|l| word == l || word.starts_with(&format!("{l}=")))
    }

    /// `-m (--masses)`, as the user may have typed either.
    fn name(&self, typed: &str) -> String {
        match (&self.short, &self.long) {
            (Some(s), Some(l)) if typed == s => format!("{s} ({l})"),
            _ => typed.to_string(),
        }
    }
}

/// The subcommand named in `words` (after the program and any global flags).
fn subcommand<'a>(command: &'a clap::Command, words: &[String]) -> Option<&'a clap::Command> {
    words
        .iter()
        .skip(1)
        .take_while(|w| *w != "--")
        .find_map(|w| command.find_subcommand(w))
}

fn options(sub: &clap::Command) -> Vec<Opt> {
    sub.get_arguments()
        .filter(|a| !a.is_positional())
        .map(|a| Opt {
            short: a.get_short().map(|c| format!("-{c}")),
            long: a.get_long().map(|l| format!("--{l}")),
            value: a.get_action().takes_values().then(|| {
                a.get_value_names()
                    .and_then(|n| n.first())
                    .map_or_else(|| "VALUE".to_string(), |n| n.to_string())
            }),
        })
        .collect()
}

/// `-m -v 60,10`: an option that takes a value followed by another option.
fn missing_value(options: &[Opt], words: &[String]) -> Option<String> {
    let position = |w: &str| options.iter().find(|o| o.is(w));
    words.windows(2).take_while(|w| w[0] != "--").find_map(|w| {
        let o = position(&w[0])?;
        let value = o.value.as_ref()?;
        // `--masses=...` carries its value; a negative number is a value, not an option.
        if w[0].contains('=') || position(&w[1]).is_none() {
            return None;
        }
        Some(format!(
            "{} needs a value {value}, but the next word is the option {}",
            o.name(&w[0]),
            w[1]
        ))
    })
}

/// A word that reads as a value rather than an option: not starting with `-`, or a negative
/// number.
fn bare(word: &str) -> bool {
    let mut chars = word.chars();
    match chars.next() {
        Some('-') => chars.next().is_some_and(|c| c.is_ascii_digit() || c == '.'),
        Some(_) => true,
        None => false,
    }
}

/// `-m 4 1`: clap found an unexpected word right after the value of an option that takes a
/// comma-separated list: the tip to join them with commas.
fn spaced_list(e: &clap::Error, options: &[Opt], words: &[String]) -> Option<String> {
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(unexpected)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let at = words.iter().position(|w| w == unexpected)?;
    let (option, first) = (words.get(at.checked_sub(2)?)?, &words[at - 1]);
    let o = options.iter().find(|o| o.is(option))?;
    // Only for lists: M1,M2, V1,V2,..., COLUMNS.
    if option.contains('=') || !o.value.as_ref().is_some_and(|v| v.contains(',')) {
        return None;
    }
    // `-m 4, 1`: a space after a comma ends the value; the words that follow go on the list.
    if first.ends_with(',') && bare(first) {
        let mut joined = first.clone();
        for w in &words[at..] {
            if !joined.ends_with(',') || !bare(w) {
                break;
            }
            joined.push_str(w);
        }
        return Some(format!(
            "no space after a comma in a list: {option} {joined}"
        ));
    }
    if first.contains(',') || !bare(first) {
        return None;
    }
    let values: Vec<&str> = std::iter::once(first.as_str())
        .chain(
            words[at..]
                .iter()
                .map(String::as_str)
                .take_while(|w| bare(w)),
        )
        .collect();
    let joined = values.join(",");
    Some(if values.len() == 2 {
        format!("separate the two values with a comma: {option} {joined}")
    } else {
        format!("separate the values with commas: {option} {joined}")
    })
}
