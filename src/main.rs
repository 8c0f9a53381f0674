//! `collide`: parse, dispatch, print, exit. Exit 0 ok, 1 a scene's check failed, 2 bad input.

use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches};
use collide::values::output::diagnostic;
use collide::values::terminal;
use collide::{cli, commands, usage};

fn main() -> ExitCode {
    // Signals remove partial output files; a file-size limit is an error, not a silent death.
    collide::values::output::guard_signals();
    let args: Vec<OsString> = std::env::args_os().collect();
    // Text, --help and errors fit the terminal: COLUMNS, else 80; --wide lifts the limit. Read
    // before parsing, so that --help and usage errors are laid out for it too.
    let wide = args
        .iter()
        .skip(1)
        .take_while(|a| *a != "--")
        .any(|a| a == "--wide");
    let width = terminal::width_for(wide, std::env::var("COLUMNS").ok().as_deref());
    terminal::set_width(width);
    let command = cli::Cli::command()
        .term_width(if width == terminal::UNLIMITED {
            0
        } else {
            width
        })
        .after_help(after_help(width));
    let cli = match command
        .clone()
        .try_get_matches_from(&args)
        .and_then(|m| cli::Cli::from_arg_matches(&m))
    {
        Ok(cli) => cli,
        // Usage errors on stderr (cut to a sane length), --help and --version on stdout; a
        // closed stream is no reason to panic.
        Err(e) if e.use_stderr() => {
            diagnostic(format_args!(
                "{}",
                usage::explain(&e, &command, &args).trim_end()
            ));
            return ExitCode::from(2);
        }
        Err(e) => {
            let _ = write!(std::io::stdout().lock(), "{}", e.render());
            return ExitCode::SUCCESS;
        }
    };
    if cli.wide {
        terminal::set_width(terminal::UNLIMITED);
    }
    if let Some(digits) = cli.sig {
        collide::values::number::set_text_digits(digits);
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

/// The end of `collide --help`: the lecture's words and the exit statuses, each wrapped to
/// `width` under its meaning's first column.
fn after_help(width: usize) -> String {
    let hanging = |label: &str, column: usize, meaning: &str| {
        let line = format!("  {label:<column$}{meaning}", column = column - 2);
        terminal::wrap(&line, width, &" ".repeat(column))
    };
    let mut out = String::from("Words:\n");
    for (word, meaning) in cli::WORDS {
        out.push_str(&hanging(word, 16, meaning));
    }
    out.push_str("\nExit status:\n");
    for line in cli::EXIT_STATUS.lines().skip(1) {
        let (status, meaning) = line.trim_start().split_once(' ').unwrap_or((line, ""));
        out.push_str(&hanging(status, 7, meaning.trim_start()));
    }
    out.trim_end().to_string()
}

/// Whether the error is a closed stdout, wherever it is in the chain.
fn broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}
