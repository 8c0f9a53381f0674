//! `collide accuracy`: every method's error against exact arithmetic beside its run time.

use anyhow::Result;
use collide::accuracy::{families, report};
use collide::output::write_file;
use collide::report::{accuracy, json};

use super::Outcome;
use crate::cli::{AccuracyArgs, Format};

pub fn run(args: AccuracyArgs) -> Result<Outcome> {
    let fams = families(args.seed, args.cases as usize);
    let rows = report(&fams, &args.methods, args.budget_ms);
    if let Some(path) = &args.plot {
        write_file(
            path,
            collide::plot::accuracy::svg(&rows, args.seed).as_bytes(),
        )?;
    }
    let stdout = match args.format {
        Format::Json => json::render(&accuracy::json(args.seed, &fams, &rows)),
        Format::Text => accuracy::text(args.seed, &fams, &rows),
    };
    Ok(Outcome::print(stdout))
}
