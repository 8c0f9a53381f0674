//! Repeated collisions on a track (the lecture's "BounceIt" simulator): bodies on a frictionless
//! line between optional walls, under optional uniform gravity, simulated event by event: no time
//! steps, each collision found at its exact time and solved with the two-body impulse form
//! (double-double from the exact masses, rounded once). A wall is a body of infinite mass.
//!
//! Rules, all deterministic, in one engine (`engine`) that every run goes through:
//! - Only neighbours can meet, so the candidate events are the adjacent pairs and the two walls.
//! - Simultaneous events (a body meeting two others, or a wall, at one instant) are resolved one
//!   pair at a time, left to right, each seeing the velocities the previous one left; the output
//!   counts such instants.
//! - Whether two bodies approach is decided from their own velocities only
//!   ([`motion::APPROACH`]): a closing speed below `2^-50` of the sum of their speeds is rounding,
//!   and they move together. A body approaches a wall when it moves toward it.
//! - After every event the bodies that moved are checked to be in order and inside the walls
//!   (allowing rounding, [`motion::slack`]); at the end, energy (elastic runs) and momentum (no
//!   walls, no gravity) are checked. A broken check stops the run with [`Broken`].
//! - Infinitely many collisions in finite time (inelastic collapse, a ball coming to rest on a
//!   floor) can only happen with e < 1 or gravity; then they are detected when 200 collisions fit
//!   in a relative time span of 1e-12, and the run stops there and reports the accumulation time,
//!   extrapolated geometrically. Elastic runs without gravity never stop for it.

mod budget;
mod engine;
pub mod motion;
pub mod pi;
mod schedule;
mod zeno;

use serde::Serialize;

use crate::line::inertia::{Mass, MassError};
use crate::line::restitution::{Restitution, RestitutionError};
use crate::values::number::Number;

pub use budget::{ENERGY_PER_COLLISION, ENERGY_TOLERANCE, energy_tolerance};
pub use pi::{PiTheory, TrackReport};

/// A body: mass (exact as typed), centre position, velocity, size (length along the track; 0
/// for a point).
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub m: Mass,
    pub x: f64,
    pub v: f64,
    pub size: f64,
}

/// A track and what is on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// Left to right, not overlapping.
    pub bodies: Vec<Body>,
    pub left_wall: Option<f64>,
    pub right_wall: Option<f64>,
    /// Restitution between bodies and at the walls ([`Track::walls_restitution`]).
    pub e: f64,
    pub e_wall: f64,
    /// Acceleration toward the left (so a left wall is a floor and positions are heights).
    pub gravity: f64,
}

/// Default cap on collisions (`--max-collisions`): enough for pi billiards with N = 8.
pub const DEFAULT_MAX_COLLISIONS: u64 = 1_000_000_000;

/// The cap that takes the default's place for a motion that cannot end ([`Track::endless`]):
/// such a run reaches any cap, and at the default it ran for minutes (the superball preset,
/// 0.3 us a collision) until an ulp of the time outgrew the spacing of its collisions (t =
/// 4.1e8, 853 million collisions). A million collisions take half a second (the preset: t =
/// 4.8e5, energy kept to 1.5e-14); `--until` or `--max-collisions` bound it otherwise.
pub const ENDLESS_MAX_COLLISIONS: u64 = 1_000_000;

/// When to stop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Give the state at this time (>= 0).
    pub until: Option<f64>,
    pub max_collisions: u64,
}

impl Limits {
    pub fn check(&self) -> Result<(), TrackError> {
        match self.until {
            Some(t) if !(t >= 0.0 && t.is_finite()) => Err(TrackError::Until(t)),
            _ => Ok(()),
        }
    }
}

/// A run that reached a state that cannot be: rounding (or a defect) put bodies through each
/// other or a wall, or broke a conservation law. The run stops instead of printing it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "the simulation reached a state that cannot be at t = {t} after {collisions} collisions: \
     {what}; nothing is reported (please report this case)"
)]
pub struct Broken {
    pub t: f64,
    pub collisions: u64,
    pub what: String,
}

/// Why a run stopped.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "reason")]
pub enum Stop {
    /// No collision can happen any more.
    Done,
    /// `--until T` was reached.
    Until,
    /// `--max-collisions` was reached.
    MaxCollisions,
    /// The motion cannot end ([`Track::endless`]) and no `--max-collisions` was given: the run
    /// stopped at `cap` ([`ENDLESS_MAX_COLLISIONS`]) instead of the default.
    Endless { cap: u64 },
    /// The next collision would leave binary64 (inelastic bounces slowing geometrically spread
    /// collisions out without end): its time (`next`, absent when beyond 1.8e308), the
    /// positions there, or the energy after it (below 2.2e-308, where it underflows), as
    /// `beyond` says. The state is the last collision's.
    Horizon {
        #[serde(skip_serializing_if = "Option::is_none")]
        next: Option<f64>,
        beyond: Beyond,
    },
    /// Infinitely many collisions accumulate at `accumulation` (near `x`, involving `who`).
    Zeno {
        at: f64,
        accumulation: f64,
        who: String,
        x: f64,
    },
}

/// What the next collision would take out of binary64's range (a [`Stop::Horizon`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Beyond {
    /// Its time is above 1.8e308.
    Time,
    /// A position at its time is.
    Position,
    /// The energy after it is below 2.2e-308 (`f64::MIN_POSITIVE`) though bodies move: it
    /// would underflow, and print as 0.
    Energy,
}

/// What collided.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Contact {
    LeftWall,
    /// Bodies `i` and `i + 1` (0-based).
    Pair(usize),
    RightWall,
}

impl Contact {
    pub fn describe(self, n: usize) -> String {
        match self {
            Contact::LeftWall => "left wall & 1".into(),
            Contact::Pair(i) => format!("{} & {}", i + 1, i + 2),
            Contact::RightWall => format!("{n} & right wall"),
        }
    }
}

/// One collision, for `--log`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Event {
    pub n: u64,
    pub t: f64,
    pub who: String,
    pub before: Vec<f64>,
    pub after: Vec<f64>,
}

/// The result of a run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Run {
    pub collisions: u64,
    pub pair_collisions: u64,
    pub wall_collisions: u64,
    /// Instants at which more than one collision happened.
    pub simultaneous: u64,
    pub time: f64,
    pub x: Vec<f64>,
    pub v: Vec<f64>,
    pub stop: Stop,
    pub momentum: Budget,
    pub energy: Budget,
}

/// A quantity at the start and the end of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Budget {
    pub start: f64,
    pub end: f64,
}

/// Why a track cannot be run.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TrackError {
    #[error("a track needs at least one body")]
    Empty,
    #[error("body {body}: {error}")]
    Mass { body: usize, error: MassError },
    #[error("body {0}: size {1} must be finite and >= 0")]
    Size(usize, f64),
    #[error("body {0}: position and velocity must be finite")]
    NotFinite(usize),
    #[error(
        "bodies {0} and {next} overlap or are out of order: positions must increase left to right \
         by at least half the sum of their sizes", next = .0 + 1
    )]
    Order(usize),
    #[error("body 1 is left of the left wall at {0}")]
    LeftOfWall(f64),
    #[error("body {0} is right of the right wall at {1}")]
    RightOfWall(usize, f64),
    #[error(transparent)]
    Restitution(#[from] RestitutionError),
    #[error("gravity {0} must be finite and >= 0 (it pulls toward the left)")]
    Gravity(f64),
    #[error("gravity pulls toward the left: give a --left-wall as the floor")]
    NoFloor,
    #[error("the time to stop at (until) is {0}: it must be a finite number >= 0")]
    Until(f64),
    #[error(
        "the track's energy or momentum is beyond binary64 (above 1.8e308): rescale the units \
         (e.g. tons and km/s instead of kg and m/s)"
    )]
    TooLarge,
    #[error(
        "the bodies fill the space between the walls (their sizes add up to {sizes}, the walls \
         are {width} apart): none can move, so any velocity means infinitely many collisions at \
         t = 0; leave a gap, or give every body velocity 0"
    )]
    Jammed { sizes: f64, width: f64 },
    #[error(transparent)]
    Broken(#[from] Broken),
}

/// A list given with the wrong number of values (one per body is needed).
#[derive(Clone, Debug, PartialEq)]
pub struct Miscount {
    /// Which list: `positions`, `velocities` or `sizes`.
    pub list: &'static str,
    pub got: usize,
    pub bodies: usize,
}

/// Why lists cannot be bodies.
#[derive(Clone, Debug, PartialEq)]
pub enum BodiesError {
    Miscount(Miscount),
    Track(TrackError),
}

/// The bodies of a track from its lists as typed, one value per body (sizes default to 0,
/// points); the layout is checked by `Track::check`.
pub fn bodies(
    masses: &[Number],
    positions: &[Number],
    velocities: &[Number],
    sizes: Option<&[Number]>,
) -> Result<Vec<Body>, BodiesError> {
    let n = masses.len();
    let zeros = vec![Number::from_f64(0.0).expect("0 is a number"); n];
    let sizes = sizes.unwrap_or(&zeros);
    for (list, values) in [
        ("positions", positions),
        ("velocities", velocities),
        ("sizes", sizes),
    ] {
        if values.len() != n {
            return Err(BodiesError::Miscount(Miscount {
                list,
                got: values.len(),
                bodies: n,
            }));
        }
    }
    (0..n)
        .map(|i| {
            Ok(Body {
                m: Mass::new(masses[i].clone())
                    .map_err(|error| BodiesError::Track(TrackError::Mass { body: i + 1, error }))?,
                x: positions[i].value(),
                v: velocities[i].value(),
                size: sizes[i].value(),
            })
        })
        .collect()
}

impl Track {
    /// The walls' restitution: the one given for the walls (`--wall-restitution`,
    /// `wall_restitution` in a scene or a sweep), else the bodies' `e`: `-e` sets every
    /// collision's restitution unless the walls have their own. The one rule for every way a
    /// track is given (command line, `--vary`, scenes, the page).
    pub fn walls_restitution(e: f64, wall: Option<f64>) -> f64 {
        wall.unwrap_or(e)
    }

    /// Pi billiards: a block of mass `m` at rest at x = 1 between a wall at 0 and a block of mass
    /// `big_m` at x = 2 moving toward it at speed 1, elastic.
    pub fn pi_billiards(m: Mass, big_m: Mass) -> Track {
        Track {
            bodies: vec![
                Body {
                    m,
                    x: 1.0,
                    v: 0.0,
                    size: 0.0,
                },
                Body {
                    m: big_m,
                    x: 2.0,
                    v: -1.0,
                    size: 0.0,
                },
            ],
            left_wall: Some(0.0),
            right_wall: None,
            e: 1.0,
            e_wall: 1.0,
            gravity: 0.0,
        }
    }

    /// Checks the layout: positive masses, sizes >= 0, bodies left to right without overlap,
    /// inside the walls, restitutions in [0, 1], gravity >= 0 and only with a left wall (a floor).
    pub fn check(&self) -> Result<(), TrackError> {
        if self.bodies.is_empty() {
            return Err(TrackError::Empty);
        }
        for (i, b) in self.bodies.iter().enumerate() {
            let body = i + 1;
            if b.size.is_nan() || b.size < 0.0 || !b.size.is_finite() {
                return Err(TrackError::Size(body, b.size));
            }
            if !b.x.is_finite() || !b.v.is_finite() {
                return Err(TrackError::NotFinite(body));
            }
        }
        for (i, w) in self.bodies.windows(2).enumerate() {
            if w[1].x - w[0].x < (w[0].size + w[1].size) / 2.0 {
                return Err(TrackError::Order(i + 1));
            }
        }
        let first = &self.bodies[0];
        let last = &self.bodies[self.bodies.len() - 1];
        if let Some(l) = self.left_wall
            && first.x - first.size / 2.0 < l
        {
            return Err(TrackError::LeftOfWall(l));
        }
        if let Some(r) = self.right_wall
            && last.x + last.size / 2.0 > r
        {
            return Err(TrackError::RightOfWall(self.bodies.len(), r));
        }
        for e in [self.e, self.e_wall] {
            Restitution::dissipative(Number::from_f64(e).map_err(RestitutionError::from)?)?;
        }
        if self.gravity.is_nan() || self.gravity < 0.0 || !self.gravity.is_finite() {
            return Err(TrackError::Gravity(self.gravity));
        }
        if self.gravity > 0.0 && self.left_wall.is_none() {
            return Err(TrackError::NoFloor);
        }
        let (x, v): (Vec<f64>, Vec<f64>) = self.bodies.iter().map(|b| (b.x, b.v)).unzip();
        let energy = self.energy(&x, &v);
        if !energy.is_finite() || !self.momentum(&v).is_finite() {
            return Err(TrackError::TooLarge);
        }
        Ok(())
    }

    /// Refuses bodies that fill the space between two walls to within rounding (the free space
    /// `(right - left) - sum of sizes` at most `motion::slack` of the walls and sizes) while any
    /// of them moves: rigid bodies with no room collide without end at t = 0 (48 s to the 1e9
    /// cap, reported as 1e9 collisions at t = 0). Soft contacts (`collide contact`) have room.
    pub fn jammed(&self) -> Result<(), TrackError> {
        let (Some(l), Some(r)) = (self.left_wall, self.right_wall) else {
            return Ok(());
        };
        if self.bodies.iter().all(|b| b.v == 0.0) {
            return Ok(());
        }
        let sizes: f64 = self.bodies.iter().map(|b| b.size).sum();
        if (r - l) - sizes <= motion::slack(l.abs() + r.abs() + sizes) {
            return Err(TrackError::Jammed {
                sizes,
                width: r - l,
            });
        }
        Ok(())
    }

    /// Total momentum `sum m v`.
    pub fn momentum(&self, v: &[f64]) -> f64 {
        self.bodies
            .iter()
            .zip(v)
            .map(|(b, v)| b.m.value() * v)
            .sum()
    }

    /// Kinetic plus potential energy `sum (1/2 (m v) v + m g (x - floor))`.
    pub fn energy(&self, x: &[f64], v: &[f64]) -> f64 {
        let floor = self.left_wall.unwrap_or(0.0);
        self.bodies
            .iter()
            .zip(x.iter().zip(v))
            .map(|(b, (x, v))| {
                let m = b.m.value();
                0.5 * (m * v) * v + m * self.gravity * (x - floor)
            })
            .sum()
    }

    /// Whether the motion can never end: every collision elastic (`e = 1` between bodies and
    /// at the walls) and the bodies confined (gravity toward a floor, or walls on both sides),
    /// so energy is kept and nothing escapes; unless everything is at rest, collisions go on
    /// without end. (An open elastic track ends: pi billiards; a dissipative one ends at rest,
    /// in a Zeno sequence or at the horizon.)
    pub fn endless(&self) -> bool {
        self.e == 1.0
            && self.e_wall == 1.0
            && (self.gravity > 0.0 || (self.left_wall.is_some() && self.right_wall.is_some()))
    }

    /// Runs the track through the one engine (`engine`); `log` sees every collision. A state
    /// that cannot be (bodies through each other or a wall beyond rounding, an elastic run that
    /// changed its energy) stops the run with [`Broken`] instead of being reported.
    ///
    /// A jammed layout ([`Track::jammed`]) is refused before anything runs. A motion that
    /// cannot end ([`Track::endless`]) left at the default cap ([`DEFAULT_MAX_COLLISIONS`])
    /// stops at [`ENDLESS_MAX_COLLISIONS`] ([`Stop::Endless`]).
    pub fn run(
        &self,
        limits: Limits,
        log: Option<&mut dyn FnMut(&Event)>,
    ) -> Result<Run, TrackError> {
        self.jammed()?;
        let endless = self.endless() && limits.max_collisions == DEFAULT_MAX_COLLISIONS;
        let capped = Limits {
            max_collisions: if endless {
                ENDLESS_MAX_COLLISIONS
            } else {
                limits.max_collisions
            },
            ..limits
        };
        let mut run = engine::Sim::new(self).run(capped, log)?;
        budget::budgets_hold(self, &run)?;
        if endless && run.stop == Stop::MaxCollisions {
            run.stop = Stop::Endless {
                cap: ENDLESS_MAX_COLLISIONS,
            };
        }
        Ok(run)
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        n: [u64; 3],
        time: f64,
        x: Vec<f64>,
        v: Vec<f64>,
        stop: Stop,
        collisions: u64,
    ) -> Result<Run, Broken> {
        let (x0, v0): (Vec<f64>, Vec<f64>) = self.bodies.iter().map(|b| (b.x, b.v)).unzip();
        let values = [self.energy(&x, &v), self.momentum(&v)];
        if let Some(bad) = x.iter().chain(&v).chain(&values).find(|q| !q.is_finite()) {
            return Err(Broken {
                t: time,
                collisions,
                what: format!("a position, velocity or budget became {bad}"),
            });
        }
        Ok(Run {
            collisions: n[0] + n[1],
            pair_collisions: n[0],
            wall_collisions: n[1],
            simultaneous: n[2],
            time,
            momentum: Budget {
                start: self.momentum(&v0),
                end: values[1],
            },
            energy: Budget {
                start: self.energy(&x0, &v0),
                end: values[0],
            },
            x,
            v,
            stop,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pi_track(m: &str, big_m: &str) -> Track {
        Track::pi_billiards(m.parse().unwrap(), big_m.parse().unwrap())
    }

    const FOREVER: Limits = Limits {
        until: None,
        max_collisions: u64::MAX,
    };

    #[test]
    fn pi_digits() {
        for (n, digits) in [
            (0, 3),
            (1, 31),
            (2, 314),
            (3, 3141),
            (4, 31415),
            (5, 314159),
        ] {
            let big = format!("1e{}", 2 * n);
            let run = pi_track("1", &big).run(FOREVER, None).unwrap();
            assert_eq!(run.collisions, digits, "mass ratio 100^{n}");
            assert_eq!(run.stop, Stop::Done);
        }
    }

    #[test]
    fn whole_multiple_ratios() {
        // m/M = 1: theta = pi/4, 3 collisions; M = 3 m: pi/6, 5; M = m/3: pi/3, 2, ending together.
        let count = |m: &str, big: &str| pi_track(m, big).run(FOREVER, None).unwrap();
        assert_eq!(count("1", "1").collisions, 3);
        assert_eq!(count("1", "3").collisions, 5);
        let r = count("3", "1");
        assert_eq!(r.collisions, 2);
        assert_eq!(r.v[0], r.v[1], "both blocks end at the same velocity");
        // Decimal masses whose ratio is 3 as typed (not in binary64) behave the same.
        assert_eq!(count("0.1", "0.3").collisions, 5);
        assert_eq!(count("0.3", "0.1").collisions, 2);
    }
}
