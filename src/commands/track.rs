//! `collide track`: repeated collisions of bodies on a track between walls.

use std::io::Write;
use std::path::Path;

use anyhow::{Context, Result};
use collide::report::{json, track as report};
use collide::table::batch::InputFormat;
use collide::table::runs::track::TrackSweep;
use collide::track::{Event, Limits, Run, Track, TrackReport};
use collide::values::output::Output;

use super::Outcome;
use crate::cli::{Format, RunFormat, TrackArgs};

pub fn run(args: TrackArgs) -> Result<Outcome> {
    if !args.table.vary.is_empty() {
        return sweep(args);
    }
    let format = RunFormat::report(args.format)?;
    let (track, limits) = base(&args)?;
    let (run, log) = match &args.log {
        None => (track.run(limits, None)?, None),
        Some(path) => run_logged(&track, limits, path, args.log_format)?,
    };
    let result = TrackReport::new(&track, run);
    let value = report::json(&result)?;
    let stdout = match format {
        Format::Json => json::render(&value),
        Format::Text => report::text(&track, &result, limits),
    };
    // The log takes the place of an old one only now that the whole command succeeded.
    if let (Some(log), Some(path)) = (log, &args.log) {
        log.commit()
            .with_context(|| format!("cannot write the log {}", path.display()))?;
    }
    Ok(Outcome::print(stdout))
}

/// `--vary`: a table of runs, one row each (`collide::table::runs::track`).
fn sweep(args: TrackArgs) -> Result<Outcome> {
    super::table::run_table(&sweep_kind(&args)?, &args.table, args.format)
}

/// The base run that `--vary` changes (`collide::table::runs::track`).
pub fn sweep_kind(args: &TrackArgs) -> Result<TrackSweep> {
    let (track, limits) = base(args)?;
    Ok(TrackSweep {
        track,
        limits,
        wall_restitution: wall_restitution(args),
    })
}

/// `--wall-restitution` as given (`None`: the walls take `-e`).
fn wall_restitution(args: &TrackArgs) -> Option<f64> {
    args.rules.wall_restitution.as_ref().map(|r| r.value())
}

/// The track and limits as given, checked.
fn base(args: &TrackArgs) -> Result<(Track, Limits)> {
    let bodies = args.layout.bodies()?;
    let e = args.rules.restitution.value();
    let track = Track {
        bodies,
        left_wall: args.layout.left_wall.as_ref().map(|x| x.value()),
        right_wall: args.layout.right_wall.as_ref().map(|x| x.value()),
        e,
        e_wall: Track::walls_restitution(e, wall_restitution(args)),
        gravity: args.rules.gravity.value(),
    };
    track.check()?;
    let limits = Limits {
        until: args.until.as_ref().map(|t| t.value()),
        max_collisions: args.max_collisions,
    };
    limits.check()?;
    Ok((track, limits))
}

/// Runs `track`, writing each collision to `path` ('-': stderr) as CSV or JSON Lines. A file is
/// written like `-o`: to a temporary file beside it, which the caller renames into place
/// (`Output::commit`) when the command succeeds, and which is removed otherwise.
fn run_logged(
    track: &Track,
    limits: Limits,
    path: &Path,
    format: Option<InputFormat>,
) -> Result<(Run, Option<Output>)> {
    let jsonl = match format {
        Some(f) => f == InputFormat::Jsonl,
        None => path.extension().is_some_and(|e| e == "jsonl"),
    };
    let named = || format!("cannot write the log {}", path.display());
    let mut out = if path == Path::new("-") {
        None
    } else {
        Some(Output::open(Some(path)).with_context(named)?)
    };
    let mut stderr = std::io::stderr().lock();
    let sink: &mut dyn Write = match &mut out {
        Some(o) => o,
        None => &mut stderr,
    };
    let mut failed: Option<std::io::Error> = None;
    if !jsonl {
        failed = sink.write_all(b"n,t,who,v_before,v_after\n").err();
    }
    let mut line = String::new();
    let mut record = |ev: &Event| {
        if failed.is_some() {
            return;
        }
        line.clear();
        if jsonl {
            line.push_str(&serde_json::to_string(ev).expect("events serialize"));
        } else {
            let join = |v: &[f64]| {
                v.iter()
                    .map(|x| ryu::Buffer::new().format(*x).to_string())
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            line.push_str(&format!(
                "{},{},{},{},{}",
                ev.n,
                ryu::Buffer::new().format(ev.t),
                ev.who,
                join(&ev.before),
                join(&ev.after)
            ));
        }
        line.push('\n');
        failed = sink.write_all(line.as_bytes()).err();
    };
    let run = track.run(limits, Some(&mut record))?;
    if let Some(e) = failed {
        return Err(e).with_context(named);
    }
    stderr.flush().with_context(named)?;
    Ok((run, out))
}
