//! `collide pi N`: the pi-billiards count for mass ratio 100^N, exact, and simulated.

use std::time::Instant;

use anyhow::Result;
use collide::inertia::Mass;
use collide::number::Number;
use collide::report::pi as report;
use collide::track::{DEFAULT_MAX_COLLISIONS, Limits, Track, TrackReport, pi::pi_digits};

use super::Outcome;
use crate::cli::{Format, PiArgs};

/// Up to this N the simulation runs unless `--no-simulate` (N = 10: 31 billion collisions).
const SIMULATE_UP_TO: u32 = 10;

pub fn run(args: PiArgs) -> Result<Outcome> {
    let count = pi_digits(args.n);
    let simulate = if args.no_simulate {
        false
    } else {
        args.simulate || args.n <= SIMULATE_UP_TO
    };
    let simulation = if simulate {
        // The mass ratio 100^N must be a binary64 (1.8e308 at most: N <= 154).
        let big: Number = format!("1e{}", 2 * u64::from(args.n))
            .parse()
            .map_err(|_| {
                anyhow::anyhow!(
                    "pi {n} --simulate: the mass ratio 100^{n} = 1e{} is beyond binary64 (at \
                     most 1.8e308, so N <= 154); the count itself needs no simulation: collide \
                     pi {n} --no-simulate",
                    2 * u64::from(args.n),
                    n = args.n
                )
            })?;
        let track = Track::pi_billiards("1".parse()?, Mass::new(big)?);
        track.check()?;
        let limits = Limits {
            until: None,
            max_collisions: DEFAULT_MAX_COLLISIONS.max(u64::MAX / 2),
        };
        let start = Instant::now();
        let run = track.run(limits, None)?;
        let seconds = start.elapsed().as_secs_f64();
        Some((TrackReport::new(&track, run), seconds))
    } else {
        None
    };
    let result = report::Pi::new(args.n, count, simulation);
    let stdout = match args.format {
        Format::Json => collide::report::json::render(&result.json()),
        Format::Text => result.text(),
    };
    Ok(Outcome::print(stdout))
}
