//! `collide completions SHELL` and `collide man`: both generated from the clap definition in
//! `cli.rs`, so they list exactly the subcommands, flags and values the binary takes.

use anyhow::Result;
use clap::CommandFactory;

use super::Outcome;
use crate::cli::{Cli, EXIT_STATUS};

/// A completion script for `shell` (clap_complete).
pub fn completions(shell: clap_complete::Shell) -> Result<Outcome> {
    let mut command = Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut command, "collide", &mut script);
    Ok(Outcome::print(String::from_utf8(script)?))
}

/// The man page's section on scene files.
const SCENES: &str = "A scene is a TOML file: a two-body case (masses or inertia, velocities, \
restitution, frame, show, exact), a [sweep] table, a [track] table or a [contact] table, with \
title, source and an [expect] table of report keys and expected values ({ value = ..., abs = ..., \
rel = ... } for a tolerance). collide scene FILE... solves each and checks it; unknown keys are \
errors with the file and line.";

/// Where the rest is written.
const SEE_ALSO: &str = "The guide, docs/README.md in collide's source: every subcommand with \
examples, the JSON schema, accuracy and limits, exit status, files and signals.";

/// `(status, meaning)` for each line of `cli::EXIT_STATUS` (the same text as `--help`).
fn exit_statuses() -> impl Iterator<Item = (&'static str, &'static str)> {
    EXIT_STATUS.lines().skip(1).filter_map(|line| {
        let (status, meaning) = line.trim_start().split_once(' ')?;
        Some((status, meaning.trim_start()))
    })
}

/// Every subcommand's examples, from the `Examples:` of its `--help`, a line each as typed there:
/// a long example ends its lines with ` \` and goes on, indented, on the next (so the page's
/// EXAMPLES fit 80 columns, as `--help` does).
fn examples(top: &clap::Command) -> Vec<String> {
    let mut lines = Vec::new();
    for help in top.get_subcommands().filter_map(|sub| sub.get_after_help()) {
        let mut continued = false;
        for line in help.to_string().lines() {
            let example = line.trim_start().starts_with("collide ");
            if example || continued {
                // Two columns of indent off: `collide` at the margin, continuations below it.
                lines.push(line.strip_prefix("  ").unwrap_or(line).to_string());
                continued = line.ends_with(" \\");
            }
        }
    }
    lines
}

/// The man page (clap_mangen), in roff: one page with every subcommand's synopsis and options.
pub fn man() -> Result<Outcome> {
    let top = Cli::command();
    let man = clap_mangen::Man::new(top.clone());
    let mut page = Vec::new();
    man.render_title(&mut page)?;
    man.render_name_section(&mut page)?;
    man.render_synopsis_section(&mut page)?;
    man.render_description_section(&mut page)?;
    for sub in top.get_subcommands() {
        let name = format!("collide {}", sub.get_name());
        let sub = sub.clone().bin_name(name.clone());
        let about = sub.get_about().map(|a| a.to_string()).unwrap_or_default();
        let man = clap_mangen::Man::new(sub);
        let mut part = Vec::new();
        man.render_synopsis_section(&mut part)?;
        man.render_options_section(&mut part)?;
        let part = String::from_utf8(part)?
            .replace(
                ".SH SYNOPSIS",
                &format!(
                    ".SH \"{}\"\n{}\n.PP",
                    name.to_uppercase(),
                    roff_text(&about)
                ),
            )
            .replace(".SH OPTIONS", ".SS Options");
        page.extend_from_slice(part.as_bytes());
    }
    let mut roff = String::from_utf8(page)?;
    roff.push_str(".SH \"EXIT STATUS\"\n");
    for (status, meaning) in exit_statuses() {
        roff.push_str(&format!(".TP\n.B {status}\n{}\n", roff_text(meaning)));
    }
    roff.push_str(&format!(".SH \"SCENES\"\n.PP\n{}\n", roff_text(SCENES)));
    // Examples as typed: one a line, not filled or justified.
    roff.push_str(".SH \"EXAMPLES\"\n.nf\n");
    for example in examples(&top) {
        roff.push_str(&format!("{}\n", roff_text(&example)));
    }
    roff.push_str(".fi\n");
    roff.push_str(&format!(".SH \"SEE ALSO\"\n.PP\n{}\n", roff_text(SEE_ALSO)));
    Ok(Outcome::print(roff))
}

/// Text for roff: backslashes and hyphens escaped.
fn roff_text(s: &str) -> String {
    s.replace('\\', "\\e").replace('-', "\\-")
}
