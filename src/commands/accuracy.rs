//! `collide accuracy`: every method's error against exact arithmetic beside its run time.

use anyhow::Result;
use collide::accuracy::{Cost, families, report};
use collide::report::{accuracy, json};
use collide::values::output::write_file;

use super::Outcome;
use crate::cli::{AccuracyArgs, Format};

/// The least time the exact references and errors may take, whatever the budget.
const FLOOR_SECONDS: f64 = 2.0;

pub fn run(args: AccuracyArgs) -> Result<Outcome> {
    within_budget(&args)?;
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

/// Refuses `--cases` whose exact references and errors would take longer than the timing budget
/// (`--budget-ms` for each method on each family) or [`FLOOR_SECONDS`], whichever is longer:
/// `--cases 100000 --budget-ms 1` took 38 s and 270 MB. Estimated from a sample before any case
/// of the report is drawn, and said with what would fit.
fn within_budget(args: &AccuracyArgs) -> Result<()> {
    let cost = Cost::measure(args.seed, &args.methods);
    let pairs = (args.methods.len() * cost.families) as f64;
    let timing = args.budget_ms as f64 / 1000.0 * pairs;
    let allowed = timing.max(FLOOR_SECONDS);
    let needed = cost.seconds(args.cases);
    if needed <= allowed {
        return Ok(());
    }
    let fits = ((allowed / cost.per_case - 5.0) / (cost.families as f64 - 1.0)).floor();
    let budget_ms = (needed / pairs * 1000.0).ceil();
    let or_budget = if budget_ms <= 60_000.0 {
        format!(", or --budget-ms {budget_ms} or more")
    } else {
        String::new()
    };
    anyhow::bail!(
        "--cases {} would spend about {} s on exact references and errors ({} cases at about {} \
         us each) besides the timing, more than the budget allows (--budget-ms {} for {} methods \
         on {} families: {} s, and at least {} s): give --cases {} or fewer{or_budget}",
        args.cases,
        collide::values::number::num((needed * 10.0).round() / 10.0),
        cost.cases(args.cases),
        collide::values::number::num((cost.per_case * 1e7).round() / 10.0),
        args.budget_ms,
        args.methods.len(),
        cost.families,
        collide::values::number::num(timing),
        FLOOR_SECONDS,
        fits.max(1.0),
    )
}
