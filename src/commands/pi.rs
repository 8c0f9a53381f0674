//! `collide pi N`: the pi-billiards count for mass ratio 100^N, exact, and simulated.

use std::time::Instant;

use anyhow::Result;
use collide::line::inertia::Mass;
use collide::report::pi as report;
use collide::track::{DEFAULT_MAX_COLLISIONS, Limits, Track, TrackReport, pi::pi_digits};
use collide::values::number::Number;

use super::Outcome;
use crate::cli::{Format, PiArgs};

/// Up to this N the simulation runs unless `--no-simulate` (N = 10: 31 billion collisions, about
/// 5 minutes); above it, it is refused (N = 11 would take about an hour).
const SIMULATE_UP_TO: u32 = 10;

/// Seconds a collision of pi billiards takes, for the expected time said before a run
/// (measured: 7 to 9 ns on the 2-core CI machine, `cargo bench --bench track`).
const SECONDS_PER_COLLISION: f64 = 1e-8;

/// A run expected to take longer than this says so on stderr before it starts.
const SAY_ABOVE_SECONDS: f64 = 10.0;

/// The expected time of `N`'s simulation for people: "31 s", "5.2 minutes", "8.7 hours",
/// "1e12 years" (about pi 10^N collisions).
fn expected(n: u32) -> String {
    let log10_seconds = std::f64::consts::PI.log10() + f64::from(n) + SECONDS_PER_COLLISION.log10();
    let seconds = 10f64.powf(log10_seconds);
    let round = |x: f64| collide::values::number::num((x * 10.0).round() / 10.0);
    const YEAR: f64 = 365.25 * 86400.0;
    if seconds < 120.0 {
        format!("{} s", round(seconds))
    } else if seconds < 7200.0 {
        format!("{} minutes", round(seconds / 60.0))
    } else if seconds < 2.0 * YEAR {
        format!("{} hours", round(seconds / 3600.0))
    } else {
        format!("1e{} years", (log10_seconds - YEAR.log10()).floor())
    }
}

pub fn run(args: PiArgs) -> Result<Outcome> {
    let count = pi_digits(args.n);
    if args.simulate && args.n > SIMULATE_UP_TO {
        anyhow::bail!(
            "pi {} --simulate would make {} collisions: about {} at about {} ns a collision; \
             the simulation runs for N up to {SIMULATE_UP_TO} (about {}); without --simulate the \
             exact count is given at once",
            args.n,
            if args.n <= 20 {
                count.to_string()
            } else {
                format!("about 3.1e{}", args.n)
            },
            expected(args.n),
            SECONDS_PER_COLLISION * 1e9,
            expected(SIMULATE_UP_TO),
        );
    }
    let simulate = !args.no_simulate && (args.simulate || args.n <= SIMULATE_UP_TO);
    let seconds = std::f64::consts::PI * 10f64.powi(args.n as i32) * SECONDS_PER_COLLISION;
    if simulate && seconds > SAY_ABOVE_SECONDS {
        collide::values::output::diagnostic(format_args!(
            "simulating {count} collisions: about {} (--no-simulate gives the exact count alone)",
            expected(args.n)
        ));
    }
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
