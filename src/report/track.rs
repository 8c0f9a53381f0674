//! `collide track`'s result for people: the stop, the counts, the bodies, the bookkeeping.

use super::text::{Block, paragraph};
use crate::track::{Beyond, DEFAULT_MAX_COLLISIONS, Limits, Stop, Track, TrackReport};
use crate::values::number::num;

/// A quantity of a track's result beyond binary64.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "{0} is not representable in binary64 (its magnitude is outside 2.2e-308 to 1.8e308): \
     rescale the units (e.g. tons and km/s instead of kg and m/s)"
)]
pub struct Unrepresentable(pub String);

/// The result as JSON, refusing by name a quantity that is not a real result.
pub fn json(r: &TrackReport) -> Result<serde_json::Value, Unrepresentable> {
    let v = serde_json::to_value(r).expect("track reports serialize");
    match super::first_unrepresentable(&v) {
        Some(quantity) => Err(Unrepresentable(quantity)),
        None => Ok(v),
    }
}

/// `collide track` for people.
pub fn text(t: &Track, r: &TrackReport, limits: Limits) -> String {
    let run = &r.run;
    let mut out = String::new();
    let walls = match (t.left_wall, t.right_wall) {
        (Some(l), Some(rw)) => format!("walls at {} and {}", num(l), num(rw)),
        (Some(l), None) => format!("a left wall at {}", num(l)),
        (None, Some(rw)) => format!("a right wall at {}", num(rw)),
        (None, None) => "no walls".into(),
    };
    let gravity = if t.gravity > 0.0 {
        format!(", gravity {} toward the left wall", num(t.gravity))
    } else {
        String::new()
    };
    let n = t.bodies.len();
    // A wall's restitution only where there is a wall (issue 28: "1 at walls" with none).
    let at_walls = if t.left_wall.is_some() || t.right_wall.is_some() {
        format!(", {} at walls", num(t.e_wall))
    } else {
        String::new()
    };
    out.push_str(&paragraph(&format!(
        "{n} {}, {walls}{gravity}; e = {} between bodies{at_walls}",
        if n == 1 { "body" } else { "bodies" },
        num(t.e),
    )));
    let why = match &run.stop {
        Stop::Done => match limits.until {
            Some(u) => format!(
                "no collision can happen any more; the state at --until {}",
                num(u)
            ),
            None => "no collision can happen any more".to_string(),
        },
        Stop::Until => "reached --until".to_string(),
        Stop::Horizon { next, beyond } => {
            let at = next.map_or_else(
                || "after t = 1.8e308 (beyond binary64's times)".to_string(),
                |t| format!("at t = {}", num(t)),
            );
            let what = match beyond {
                Beyond::Time => "",
                Beyond::Position => ", where positions are beyond binary64",
                Beyond::Energy => {
                    " and leave the energy below binary64's range (2.2e-308): it would underflow"
                }
            };
            format!(
                "the collisions go on, but the next would come {at}{what}; the state is the \
                 last collision's"
            )
        }
        Stop::MaxCollisions => format!(
            "at the --max-collisions cap of {}{}, before the motion ended (it may never end): \
             give --until T for the state at a time T, or a --max-collisions N to go further",
            limits.max_collisions,
            if limits.max_collisions == DEFAULT_MAX_COLLISIONS {
                " (the default)"
            } else {
                ""
            }
        ),
        Stop::Endless { cap } => format!(
            "the motion never ends (every collision elastic, the bodies held by gravity or \
             walls), so it stops at {cap} collisions, the cap for such a run: give --until T \
             for the state at a time T, or a --max-collisions N to go further"
        ),
        Stop::Zeno {
            at,
            accumulation,
            who,
            x,
        } => format!(
            "infinitely many collisions in finite time (inelastic collapse or coming to rest): \
             collisions {who} near x = {} \
             accumulate at t = {}; stopped at t = {}",
            num(*x),
            num(*accumulation),
            num(*at)
        ),
    };
    out.push_str(&paragraph(&format!("Stopped: {why}")));
    let mut b = Block::new(format!(
        "After {} collision{} at t = {}",
        run.collisions,
        if run.collisions == 1 { "" } else { "s" },
        num(run.time)
    ));
    b.row(
        "collisions",
        run.collisions.to_string(),
        format!(
            "{} between bodies, {} with walls",
            run.pair_collisions, run.wall_collisions
        ),
    );
    if run.simultaneous > 0 {
        b.row(
            "simultaneous",
            run.simultaneous.to_string(),
            "instants with more than one collision, resolved left to right",
        );
    }
    if let Some(pi) = &r.pi {
        let verdict = match pi.agrees {
            Some(true) => "agrees",
            Some(false) => "DISAGREES",
            None => "not compared: the run did not end by itself",
        };
        b.row(
            "pi billiards",
            pi.theory.clone(),
            format!("{verdict}: ceil(pi/theta) - 1"),
        );
        b.row("theta", num(pi.theta), "atan(sqrt(m1/m2))");
    }
    b.render(&mut out);
    let mut bodies = Block::new("Bodies");
    bodies.cells(["body".to_string(), "m".into(), "x".into(), "v".into()]);
    for (i, body) in t.bodies.iter().enumerate() {
        bodies.cells([
            (i + 1).to_string(),
            body.m.number().to_string(),
            num(run.x[i]),
            num(run.v[i]),
        ]);
    }
    bodies.render(&mut out);
    let mut book = Block::new("Bookkeeping");
    let walled = t.left_wall.is_some() || t.right_wall.is_some();
    let walls_note = match (walled, t.gravity > 0.0) {
        (true, true) => "walls and gravity change it",
        (true, false) => "the walls change it",
        (false, true) => "gravity changes it",
        (false, false) => "conserved",
    };
    book.cells_noted(vec![
        "momentum".to_string(),
        num(run.momentum.start),
        num(run.momentum.end),
        walls_note.into(),
    ]);
    let rel = (run.energy.end - run.energy.start) / run.energy.start.abs().max(f64::MIN_POSITIVE);
    let energy_note = if t.e == 1.0 && t.e_wall == 1.0 {
        format!("elastic: relative change {rel:.1e}")
    } else {
        format!("relative change {rel:.1e} (lost to heat)")
    };
    book.cells_noted(vec![
        "energy".to_string(),
        num(run.energy.start),
        num(run.energy.end),
        energy_note,
    ]);
    book.render(&mut out);
    out
}
