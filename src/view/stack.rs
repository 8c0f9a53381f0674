//! A track for the page's superball stack (the lecture's "BounceIt"): the inputs as typed
//! (`collide track`'s flags), run by the one track engine, answered with the JSON `collide track
//! --until T --format json` prints, the motion sampled in time for the animation (each sample is
//! the engine's own state at that time, as `--until t` gives it), and the velocity amplification
//! of the top ball (Harter 1971: 3, 7, ..., 2^n - 1 times the drop speed in the limit of light
//! upper balls).

use serde::Serialize;

use crate::line::restitution::Restitution;
use crate::report::json;
use crate::track::{Contact, Event, Limits, Run, Track, TrackReport};
use crate::values::number::{Number, NumberList};

use super::InputError;
use super::input::TrackInput;

/// Collisions the page runs at most (a pi-billiards layout of mass ratio 1e10 makes 314,159).
pub const MAX_COLLISIONS: u64 = 100_000;
/// Runs with more collisions than this are not animated (each sample is a run from t = 0).
pub const MAX_ANIMATED: usize = 400;
/// Samples in time, beside the collisions' own times.
pub const SAMPLES: usize = 240;

/// The answer to a layout.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Stack {
    /// `collide track ... --until T --format json`, as the command line prints it.
    pub state: String,
    pub command: String,
    pub scene: String,
    /// The end of the run (`--until`, as used).
    pub until: f64,
    pub floor: Option<f64>,
    pub ceiling: Option<f64>,
    pub gravity: f64,
    pub masses: Vec<f64>,
    pub sizes: Vec<f64>,
    /// The collisions: time, who, velocities after.
    pub events: Vec<Event>,
    /// The motion: times, and each body's position and velocity at them (empty when the run has
    /// more than `MAX_ANIMATED` collisions).
    pub t: Vec<f64>,
    pub x: Vec<Vec<f64>>,
    pub v: Vec<Vec<f64>>,
    pub amplification: Option<Amplification>,
}

/// The top ball's velocity after its first collision over the bottom ball's speed when it first
/// hits the floor.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Amplification {
    pub drop_speed: f64,
    pub top_velocity: f64,
    pub ratio: f64,
    /// `2^n - 1`: the ratio for elastic balls each much lighter than the one below.
    pub limit: f64,
}

fn optional<T: std::str::FromStr>(text: &str, field: &'static str) -> Result<Option<T>, InputError>
where
    T::Err: std::fmt::Display,
{
    let t = text.trim();
    if t.is_empty() {
        return Ok(None);
    }
    t.parse()
        .map(Some)
        .map_err(|e| InputError::new(field, format!("{field}: {e}")))
}

fn list(text: &str, field: &'static str) -> Result<NumberList, InputError> {
    optional(text, field)?.ok_or_else(|| InputError::new(field, format!("{field}: give a value")))
}

fn restitution(text: &str, field: &'static str) -> Result<Option<Restitution>, InputError> {
    let t = text.trim();
    if t.is_empty() {
        return Ok(None);
    }
    Restitution::parse_dissipative(t)
        .map(Some)
        .map_err(|e| InputError::new(field, e))
}

impl TrackInput {
    /// The track, checked as `collide track` checks it.
    pub fn track(&self) -> Result<Track, InputError> {
        let masses = list(&self.masses, "masses")?;
        let positions = list(&self.positions, "positions")?;
        let velocities = list(&self.velocities, "velocities")?;
        let sizes: Option<NumberList> = optional(&self.sizes, "sizes")?;
        let bodies = crate::track::bodies(
            &masses.0,
            &positions.0,
            &velocities.0,
            sizes.as_ref().map(|s| s.0.as_slice()),
        )
        .map_err(|e| match e {
            crate::track::BodiesError::Miscount(m) => InputError::new(
                m.list,
                format!(
                    "{} has {} values for {} masses: give one per body",
                    m.list, m.got, m.bodies
                ),
            ),
            crate::track::BodiesError::Track(e) => InputError::new("masses", e),
        })?;
        let e = restitution(&self.e, "e")?.unwrap_or_else(Restitution::elastic);
        let e_wall = restitution(&self.e_wall, "e_wall")?;
        let value = |n: Option<Number>| n.map(|n| n.value());
        let track = Track {
            bodies,
            left_wall: value(optional(&self.left_wall, "left_wall")?),
            right_wall: value(optional(&self.right_wall, "right_wall")?),
            e: e.value(),
            e_wall: Track::walls_restitution(e.value(), e_wall.map(|r| r.value())),
            gravity: value(optional(&self.gravity, "gravity")?).unwrap_or(0.0),
        };
        track.check().map_err(|e| {
            let field = match e {
                crate::track::TrackError::Gravity(_) | crate::track::TrackError::NoFloor => {
                    "gravity"
                }
                crate::track::TrackError::LeftOfWall(_) => "left_wall",
                crate::track::TrackError::RightOfWall(..) => "right_wall",
                crate::track::TrackError::Size(..) => "sizes",
                _ => "positions",
            };
            InputError::new(field, e)
        })?;
        Ok(track)
    }

    /// Runs the layout and samples its motion.
    pub fn run(&self) -> Result<Stack, InputError> {
        let track = self.track()?;
        let until = match optional::<Number>(&self.until, "until")? {
            Some(t) => t.value(),
            None => default_until(&track)?,
        };
        let limits = Limits {
            until: Some(until),
            max_collisions: MAX_COLLISIONS,
        };
        limits.check().map_err(|e| InputError::new("until", e))?;
        let mut events = Vec::new();
        let mut record = |ev: &Event| events.push(ev.clone());
        let run = track.run(limits, Some(&mut record)).map_err(broken)?;
        let amplification = amplification(&track, &events);
        let report = TrackReport::new(&track, run);
        let value =
            crate::report::track::json(&report).map_err(|e| InputError::new("masses", e))?;
        let (t, x, v) = if events.len() <= MAX_ANIMATED {
            sample(&track, &events, report.run.time)?
        } else {
            Default::default()
        };
        Ok(Stack {
            state: json::render(&value),
            command: super::shell::track_command(self, until),
            scene: super::shell::track_scene(self, until),
            until,
            floor: track.left_wall,
            ceiling: track.right_wall,
            gravity: track.gravity,
            masses: track.bodies.iter().map(|b| b.m.value()).collect(),
            sizes: track.bodies.iter().map(|b| b.size).collect(),
            events,
            t,
            x,
            v,
            amplification,
        })
    }
}

/// A run refused or stopped (a jammed layout, a state that cannot be).
fn broken(e: crate::track::TrackError) -> InputError {
    InputError::new("positions", e)
}

/// Eight times the first collision's time (two significant digits), so that a dropped stack
/// bounces and its top ball comes back down; 10 when nothing collides.
fn default_until(track: &Track) -> Result<f64, InputError> {
    let first = Limits {
        until: None,
        max_collisions: 1,
    };
    let run = track.run(first, None).map_err(broken)?;
    let t = 8.0 * run.time;
    if run.collisions == 0 || !(t > 0.0 && t.is_finite()) {
        return Ok(10.0);
    }
    Ok(crate::values::number::round_significant(t, 2))
}

/// The state at `SAMPLES + 1` evenly spaced times from 0 to `end` and just before and at each
/// collision, each the engine's own (a run to that time).
#[allow(clippy::type_complexity)]
fn sample(
    track: &Track,
    events: &[Event],
    end: f64,
) -> Result<(Vec<f64>, Vec<Vec<f64>>, Vec<Vec<f64>>), InputError> {
    let mut times: Vec<f64> = (0..=SAMPLES)
        .map(|k| end * k as f64 / SAMPLES as f64)
        .chain(events.iter().map(|e| e.t))
        .filter(|t| t.is_finite() && *t <= end)
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    let n = track.bodies.len();
    let (mut x, mut v) = (vec![Vec::new(); n], vec![Vec::new(); n]);
    for &t in &times {
        let run: Run = track
            .run(
                Limits {
                    until: Some(t),
                    max_collisions: MAX_COLLISIONS,
                },
                None,
            )
            .map_err(broken)?;
        for i in 0..n {
            x[i].push(run.x[i]);
            v[i].push(run.v[i]);
        }
    }
    Ok((times, x, v))
}

/// The top ball's velocity after its first collision with the ball below, over the bottom ball's
/// speed at its first bounce on the floor (a single ball: its rebound velocity, `e`).
fn amplification(track: &Track, events: &[Event]) -> Option<Amplification> {
    let n = track.bodies.len();
    let floor = Contact::LeftWall.describe(n);
    let bounce = events.iter().position(|e| e.who == floor)?;
    let drop_speed = -events[bounce].before[0];
    let top = if n == 1 {
        Contact::LeftWall.describe(n)
    } else {
        Contact::Pair(n - 2).describe(n)
    };
    let hit = events[bounce..].iter().find(|e| e.who == top)?;
    let top_velocity = *hit.after.last()?;
    (drop_speed > 0.0).then(|| Amplification {
        drop_speed,
        top_velocity,
        ratio: top_velocity / drop_speed,
        limit: (2.0f64).powi(n as i32) - 1.0,
    })
}
