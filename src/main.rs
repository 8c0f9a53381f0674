//! `collide`: parse, dispatch, print, exit. Exit 0 ok, 1 a scene's check failed, 2 bad input.

mod cli;
mod commands;

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use collide::output::diagnostic;

fn main() -> ExitCode {
    // Signals remove partial output files; a file-size limit is an error, not a silent death.
    collide::output::guard_signals();
    let cli = match cli::Cli::try_parse() {
        Ok(cli) => cli,
        // Usage errors on stderr (cut to a sane length), --help and --version on stdout; a
        // closed stream is no reason to panic.
        Err(e) if e.use_stderr() => {
            diagnostic(format_args!("{}", usage_error(&e).trim_end()));
            return ExitCode::from(2);
        }
        Err(e) => {
            let _ = write!(std::io::stdout().lock(), "{}", e.render());
            return ExitCode::SUCCESS;
        }
    };
    if let Some(digits) = cli.sig {
        collide::number::set_text_digits(digits);
    }
    match commands::run(cli.command) {
        Ok(outcome) => {
            let mut out = std::io::stdout().lock();
            match out
                .write_all(outcome.stdout.as_bytes())
                .and_then(|()| out.flush())
            {
                // `collide ... | head`: the reader left; that is not an error.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    diagnostic(format_args!("error: cannot write output: {e}"));
                    ExitCode::from(2)
                }
                Ok(()) => ExitCode::from(outcome.status),
            }
        }
        // A table streamed into `collide ... | head`: the reader left; that is not an error.
        Err(e) if broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            diagnostic(format_args!("error: {e:#}"));
            ExitCode::from(2)
        }
    }
}

/// clap's message, but with control characters in a rejected value escaped (`'5\u{7},1'`):
/// clap's rendering drops them, which quotes a value that was not typed.
fn usage_error(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
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
            collide::number::printable(value)
        );
    }
    e.render().to_string()
}

/// Whether the error is a closed stdout, wherever it is in the chain.
fn broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}
