//! `collide`: parse, dispatch, print, exit. Exit 0 ok, 1 a scene's check failed, 2 bad input.

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = collide::cli::Cli::parse();
    match collide::app::run(cli.command) {
        Ok(outcome) => {
            let mut out = std::io::stdout().lock();
            match out
                .write_all(outcome.stdout.as_bytes())
                .and_then(|()| out.flush())
            {
                // `collide ... | head`: the reader left; that is not an error.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: cannot write output: {e}");
                    ExitCode::from(2)
                }
                Ok(()) => ExitCode::from(outcome.status),
            }
        }
        // A table streamed into `collide ... | head`: the reader left; that is not an error.
        Err(e) if broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>().is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
            || c.downcast_ref::<collide::rows::RowsError>().is_some_and(|r| {
                matches!(r, collide::rows::RowsError::Io(io) if io.kind() == std::io::ErrorKind::BrokenPipe)
            })
    })
}
