//! The picture of a report (`Report._repr_svg_`): the words of `collide plot` for the case a
//! report's command solved, so the SVG is the one `collide plot` draws for it.

use clap::CommandFactory;

use crate::cli::Cli;

/// Flags of `solve` and `frames` that change what is printed, not the collision drawn.
const NOT_DRAWN: [&str; 3] = ["exact", "show", "contact-time"];

/// `plot` with the case's flags of `args` (`solve ...` or `frames ...`), or `None` when the
/// picture would not be the case's: another command, an unknown (`?`), or a flag `plot` does not
/// take that changes the collision (a homework known, `--fin`); `--reverse` and `frames`' extra
/// `--frame` rows are not drawn, so those pictures are the lab's collision.
pub fn plot_args(args: &[String]) -> Option<Vec<String>> {
    let (command, flags) = args.split_first()?;
    if !matches!(command.as_str(), "solve" | "frames") {
        return None;
    }
    let cli = Cli::command();
    let of = |name: &str| cli.find_subcommand(name).cloned();
    let (from, plot) = (of(command)?, of("plot")?);
    let long = |c: &clap::Command, name: &str| {
        c.get_arguments()
            .find(|a| a.get_long() == Some(name))
            .cloned()
    };
    let mut out = vec!["plot".to_string()];
    let mut words = flags.iter();
    while let Some(word) = words.next() {
        let name = word.strip_prefix("--")?;
        let arg = long(&from, name)?;
        let value = match arg.get_action().takes_values() {
            true => Some(words.next()?),
            false => None,
        };
        if value.is_some_and(|v| v.split(',').any(|part| part.trim() == "?")) {
            return None;
        }
        let skip = NOT_DRAWN.contains(&name)
            || name == "reverse"
            || (command == "frames" && name == "frame");
        if skip {
            continue;
        }
        long(&plot, name)?;
        out.push(word.clone());
        out.extend(value.cloned());
    }
    Some(out)
}
