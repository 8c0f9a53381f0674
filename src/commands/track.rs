//! `collide track`: repeated collisions of bodies on a track between walls.

use std::io::Write;
use std::path::Path;

use anyhow::{Context, Result};
use collide::report::{json, track as report};
use collide::table::batch::InputFormat;
use collide::track::{Event, Limits, Run, Track, TrackReport, bodies};

use super::Outcome;
use crate::cli::{Format, TrackArgs};

pub fn run(args: TrackArgs) -> Result<Outcome> {
    let bodies = bodies(
        &args.masses.0,
        &args.positions.0,
        &args.velocities.0,
        args.sizes.as_ref().map(|s| s.0.as_slice()),
    )
    .map_err(|m| {
        anyhow::anyhow!(
            "--{} has {} values for {} masses: give one per body",
            m.list,
            m.got,
            m.bodies
        )
    })?;
    let e = args.restitution.value();
    let track = Track {
        bodies,
        left_wall: args.left_wall.map(|x| x.value()),
        right_wall: args.right_wall.map(|x| x.value()),
        e,
        e_wall: args.wall_restitution.map_or(e, |r| r.value()),
        gravity: args.gravity.value(),
    };
    track.check()?;
    let limits = Limits {
        until: args.until.map(|t| t.value()),
        max_collisions: args.max_collisions,
    };
    let run = match &args.log {
        None => track.run(limits, None),
        Some(path) => run_logged(&track, limits, path, args.log_format)?,
    };
    let result = TrackReport::new(&track, run);
    let value = report::json(&result)?;
    let stdout = match args.format {
        Format::Json => json::render(&value),
        Format::Text => report::text(&track, &result, limits),
    };
    Ok(Outcome::print(stdout))
}

/// Runs `track`, writing each collision to `path` ('-': stderr) as CSV or JSON Lines.
fn run_logged(
    track: &Track,
    limits: Limits,
    path: &Path,
    format: Option<InputFormat>,
) -> Result<Run> {
    let jsonl = match format {
        Some(f) => f == InputFormat::Jsonl,
        None => path.extension().is_some_and(|e| e == "jsonl"),
    };
    let sink: Box<dyn Write> = if path == Path::new("-") {
        Box::new(std::io::stderr())
    } else {
        Box::new(
            std::fs::File::create(path)
                .with_context(|| format!("cannot write {}", path.display()))?,
        )
    };
    let out = std::io::BufWriter::new(sink);
    enum Log {
        Csv(Box<csv::Writer<std::io::BufWriter<Box<dyn Write>>>>),
        Jsonl(std::io::BufWriter<Box<dyn Write>>),
    }
    let mut log = if jsonl {
        Log::Jsonl(out)
    } else {
        Log::Csv(Box::new(csv::Writer::from_writer(out)))
    };
    let mut failed: Option<String> = None;
    if let Log::Csv(w) = &mut log {
        w.write_record(["n", "t", "who", "v_before", "v_after"])?;
    }
    let mut record = |ev: &Event| {
        if failed.is_some() {
            return;
        }
        let join = |v: &[f64]| {
            v.iter()
                .map(|x| ryu::Buffer::new().format(*x).to_string())
                .collect::<Vec<_>>()
                .join(" ")
        };
        let result = match &mut log {
            Log::Csv(w) => w
                .write_record([
                    ev.n.to_string(),
                    ryu::Buffer::new().format(ev.t).to_string(),
                    ev.who.clone(),
                    join(&ev.before),
                    join(&ev.after),
                ])
                .map_err(|e| e.to_string()),
            Log::Jsonl(w) => serde_json::to_writer(&mut *w, ev)
                .map_err(|e| e.to_string())
                .and_then(|()| w.write_all(b"\n").map_err(|e| e.to_string())),
        };
        failed = result.err();
    };
    let run = track.run(limits, Some(&mut record));
    if let Some(e) = failed {
        anyhow::bail!("cannot write the log {}: {e}", path.display());
    }
    match &mut log {
        Log::Csv(w) => w.flush()?,
        Log::Jsonl(w) => w.flush()?,
    }
    Ok(run)
}
