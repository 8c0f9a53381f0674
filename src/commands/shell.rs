//! `collide completions SHELL` and `collide man`: both generated from the clap definition in
//! `cli.rs`, so they list exactly the subcommands, flags and values the binary takes.

use anyhow::Result;
use clap::CommandFactory;

use super::Outcome;
use crate::cli::Cli;

/// A completion script for `shell` (clap_complete).
pub fn completions(shell: clap_complete::Shell) -> Result<Outcome> {
    let mut command = Cli::command();
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut command, "collide", &mut script);
    Ok(Outcome::print(String::from_utf8(script)?))
}

/// Sections of the man page beyond the flags: exit status, scenes, an example per subcommand.
const EXTRA: &[(&str, &[&str])] = &[
    (
        "EXIT STATUS",
        &[
            "0 success; 1 a scene's [expect] check failed; 2 bad input or usage (a message on \
             stderr names the bad value and says what is expected; nothing is written to stdout).",
        ],
    ),
    (
        "SCENES",
        &[
            "A scene is a TOML file: a two-body case (masses or inertia, velocities, \
             restitution, frame, show, exact), a [sweep] table, a [track] table or a [contact] \
             table, with title, source and an [expect] table of report keys and expected values \
             ({ value = ..., abs = ..., rel = ... } for a tolerance). collide scene FILE... \
             solves each and checks it; unknown keys are errors with the file and line.",
        ],
    ),
    (
        "EXAMPLES",
        &[
            "collide solve -m 4,1 -v 60,10",
            "collide scene scenarios/fig-1-3-elastic.toml",
            "collide frames -m 4,1 -v 60,10 -e 2/3",
            "collide sweep -m 4,1 -v 60,10 --vary e=0:1:11",
            "collide batch scenarios/cases.csv",
            "collide track -m 1,10000 -x 1,2 -v 0,-1 --left-wall 0",
            "collide contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --zeta 0.2",
            "collide pi 5",
            "collide plot -m 4,1 -v 60,10 -o case-a.svg",
            "collide accuracy --cases 8",
            "collide completions bash > ~/.local/share/bash-completion/completions/collide",
        ],
    ),
];

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
    for (title, paragraphs) in EXTRA {
        roff.push_str(&format!(".SH \"{title}\"\n"));
        for p in *paragraphs {
            let text = roff_text(p);
            if p.starts_with("collide ") {
                roff.push_str(&format!(".TP\n.B {text}\n"));
            } else {
                roff.push_str(&format!(".PP\n{text}\n"));
            }
        }
    }
    Ok(Outcome::print(roff))
}

/// Text for roff: backslashes and hyphens escaped.
fn roff_text(s: &str) -> String {
    s.replace('\\', "\\e").replace('-', "\\-")
}
