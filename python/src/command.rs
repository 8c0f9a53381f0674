//! The command line inside the module: Python's keyword arguments become the command's words
//! (`hit_at="0.6 m"` is `--hit-at '0.6 m'`), which the binary's own flags (`src/cli.rs`, compiled
//! into the module from the same file) parse and the binary's own commands (`src/commands/`)
//! solve and render as `--format json`. So a report is the command's JSON by construction: one
//! parser, one solver path, one renderer, and the command's message for a value it refuses.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

use crate::cli::Cli;
use crate::refused;
use crate::values::{list, scalar};

/// What the command printed and its exit status (0, or 1: a scene's check failed, or given
/// values that contradict each other).
pub struct Printed {
    pub stdout: String,
    pub status: u8,
}

/// `collide ARGS...` (without the program's name), run in this process with the GIL released.
/// A usage error or a refused value is a `CollideError` with the command's message (what it
/// prints after `error:`).
pub fn run(py: Python<'_>, args: &[String]) -> PyResult<Printed> {
    let cli = parse(args)?;
    let outcome = py
        .detach(|| crate::commands::run(cli.command))
        .map_err(|e| refused(format!("{e:#}")))?;
    Ok(Printed {
        stdout: outcome.stdout,
        status: outcome.status,
    })
}

/// `collide ARGS...` parsed by the command line's flags, or the command's message.
pub fn parse(args: &[String]) -> PyResult<Cli> {
    use clap::{CommandFactory, FromArgMatches};
    let words: Vec<std::ffi::OsString> = std::iter::once("collide")
        .chain(args.iter().map(String::as_str))
        .map(Into::into)
        .collect();
    let command = Cli::command().term_width(0);
    command
        .clone()
        .try_get_matches_from(&words)
        .and_then(|m| Cli::from_arg_matches(&m))
        .map_err(|e| refused(usage(&e, &command, &words)))
}

/// The message of a usage error: for a value a flag's parser refused, the parser's own message
/// (the library's, as `collide.solve` gives it for every value); otherwise what the command
/// prints after `error:` (with its tip, if any), without the usage line and the hint to try
/// `--help`, which are about the command line's syntax.
fn usage(e: &clap::Error, command: &clap::Command, words: &[std::ffi::OsString]) -> String {
    use clap::error::ErrorKind;
    if e.kind() == ErrorKind::ValueValidation
        && let Some(source) = std::error::Error::source(e)
    {
        return source.to_string();
    }
    let text = crate::usage::explain(e, command, words);
    let text = text.trim_end();
    let text = text.strip_prefix("error: ").unwrap_or(text);
    let text = text
        .split("\n\nFor more information")
        .next()
        .unwrap_or(text);
    let text = text.split("\n\nUsage:").next().unwrap_or(text);
    text.trim_end().to_string()
}

/// Flags whose value is one vector: a pair given for them is `(x,y)`, not a list of two.
const VECTORS: [&str; 2] = ["normal", "pivot"];

/// Python's short names for the command's long flags.
const ALIASES: [(&str, &str); 4] = [
    ("m", "masses"),
    ("v", "velocities"),
    ("e", "restitution"),
    ("b", "impact-parameter"),
];

/// The command's words for keyword arguments: `name=value` is `--name VALUE` (underscores as
/// dashes), `True` the bare flag, `False` and `None` nothing, a list a comma-separated list (a
/// pair inside it a vector `(x,y)`), and a list for a flag given many times (`--vary`) one
/// flag per item.
pub fn words(flags: Option<&Bound<'_, PyDict>>, repeated: &[&str]) -> PyResult<Vec<String>> {
    let mut out = Vec::new();
    let Some(flags) = flags else {
        return Ok(out);
    };
    for (key, value) in flags.iter() {
        let key: String = key.extract()?;
        let name = ALIASES
            .iter()
            .find(|(short, _)| *short == key)
            .map_or(key.replace('_', "-"), |(_, long)| (*long).to_string());
        if value.is_none() {
            continue;
        }
        if value.is_instance_of::<PyBool>() {
            if value.extract::<bool>()? {
                out.push(format!("--{name}"));
            }
            continue;
        }
        if repeated.contains(&name.as_str()) && !value.is_instance_of::<pyo3::types::PyString>() {
            for (i, item) in value.try_iter()?.enumerate() {
                out.push(format!("--{name}"));
                out.push(scalar(&item?, &format!("{key}[{i}]"))?);
            }
            continue;
        }
        out.push(format!("--{name}"));
        out.push(if VECTORS.contains(&name.as_str()) {
            crate::values::vector(&value, &key)?
        } else {
            list(&value, &key)?
        });
    }
    Ok(out)
}
