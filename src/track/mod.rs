//! Repeated collisions on a track (the lecture's "BounceIt" simulator): bodies on a frictionless
//! line between optional walls, under optional uniform gravity, simulated event by event: no time
//! steps, each collision found at its exact time and solved with the two-body impulse form of
//! `collision` (double-double, rounded once). A wall is a body of infinite mass.
//!
//! Rules, all deterministic:
//! - Only neighbours can meet, so the candidate events are the adjacent pairs and the two walls,
//!   kept in a priority queue (O(log n) per event).
//! - Simultaneous events (a body meeting two others, or a wall, at one instant) are resolved one
//!   pair at a time, left to right, each seeing the velocities the previous one left; the output
//!   counts such instants.
//! - Bodies whose approach speed is below `1e-12` of the run's velocity scale are not approaching:
//!   they touch and move together (this is what makes whole-multiple pi-billiard ratios exact).
//! - Infinitely many collisions in finite time (inelastic collapse, a ball coming to rest on a
//!   floor) are detected when 200 collisions fit in a relative time span of 1e-12; the run stops
//!   there and reports the accumulation time, extrapolated geometrically.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

pub mod pi;

use serde::Serialize;

use crate::compensated::Dd;
use crate::inertia::{Mass, MassError};
use crate::number::Number;
use crate::restitution::{Restitution, RestitutionError};

pub use pi::{PiTheory, TrackReport};

/// A body: mass, centre position, velocity, size (length along the track; 0 for a point).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Body {
    pub m: f64,
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
    /// Restitution between bodies and at the walls.
    pub e: f64,
    pub e_wall: f64,
    /// Acceleration toward the left (so a left wall is a floor and positions are heights).
    pub gravity: f64,
}

/// Default cap on collisions (`--max-collisions`): enough for pi billiards with N = 8.
pub const DEFAULT_MAX_COLLISIONS: u64 = 1_000_000_000;

/// When to stop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    pub until: Option<f64>,
    pub max_collisions: u64,
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
    /// Infinitely many collisions accumulate at `accumulation` (near `x`, involving `who`).
    Zeno {
        at: f64,
        accumulation: f64,
        who: String,
        x: f64,
    },
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

/// `(v1', v2')` after a collision, from `kw = ((1 + e) w1, (1 + e) w2)` (COM weights times
/// `1 + e`, double-double): the impulse form `v1' = v1 + (1 + e) w2 (v2 - v1)`,
/// `v2' = v2 - (1 + e) w1 (v2 - v1)`, rounded once.
#[inline]
fn impulse(kw: (Dd, Dd), v1: f64, v2: f64) -> (f64, f64) {
    let d = Dd::sum(v2, -v1);
    (
        (Dd::new(v1) + kw.1 * d).value(),
        (Dd::new(v2) - kw.0 * d).value(),
    )
}

/// `((1 + e) w1, (1 + e) w2)` for bodies of masses `m1`, `m2`.
fn impulse_weights(m1: f64, m2: f64, e: f64) -> (Dd, Dd) {
    let (w1, w2) = weights(m1, m2);
    let k = Dd::sum(1.0, e);
    (k * w1, k * w2)
}

/// COM weights `m1/(m1+m2)`, `m2/(m1+m2)` as double-doubles.
fn weights(m1: f64, m2: f64) -> (Dd, Dd) {
    let (big, small) = if m1 >= m2 { (m1, m2) } else { (m2, m1) };
    // 1/(1 + small/big) for the heavy side, small/(big + small) for the light one: no overflow.
    let total = Dd::sum(m1, m2);
    if total.hi.is_finite() {
        (Dd::new(m1) / total, Dd::new(m2) / total)
    } else {
        let r = Dd::new(small) / Dd::new(big);
        let heavy = Dd::new(1.0) / (Dd::new(1.0) + r);
        let light = r * heavy;
        if m1 >= m2 {
            (heavy, light)
        } else {
            (light, heavy)
        }
    }
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
    #[error(
        "the track's energy or momentum is beyond binary64 (above 1.8e308): rescale the units \
         (e.g. tons and km/s instead of kg and m/s)"
    )]
    TooLarge,
}

/// A list given with the wrong number of values (one per body is needed).
#[derive(Clone, Debug, PartialEq)]
pub struct Miscount {
    /// Which list: `positions`, `velocities` or `sizes`.
    pub list: &'static str,
    pub got: usize,
    pub bodies: usize,
}

/// The bodies of a track from its lists as typed, one value per body (sizes default to 0,
/// points); checked by `Track::check`.
pub fn bodies(
    masses: &[Number],
    positions: &[Number],
    velocities: &[Number],
    sizes: Option<&[Number]>,
) -> Result<Vec<Body>, Miscount> {
    let n = masses.len();
    let zeros = vec![Number::from_f64(0.0).expect("0 is a number"); n];
    let sizes = sizes.unwrap_or(&zeros);
    for (list, values) in [
        ("positions", positions),
        ("velocities", velocities),
        ("sizes", sizes),
    ] {
        if values.len() != n {
            return Err(Miscount {
                list,
                got: values.len(),
                bodies: n,
            });
        }
    }
    Ok((0..n)
        .map(|i| Body {
            m: masses[i].value(),
            x: positions[i].value(),
            v: velocities[i].value(),
            size: sizes[i].value(),
        })
        .collect())
}

impl Track {
    /// Pi billiards: a block of mass `m` at rest at x = 1 between a wall at 0 and a block of mass
    /// `big_m` at x = 2 moving toward it at speed 1, elastic.
    pub fn pi_billiards(m: f64, big_m: f64) -> Track {
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
        let number = |x: f64| Number::from_f64(x).map_err(MassError::from);
        for (i, b) in self.bodies.iter().enumerate() {
            let body = i + 1;
            number(b.m)
                .and_then(Mass::new)
                .map_err(|error| TrackError::Mass { body, error })?;
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
        let first = self.bodies[0];
        let last = self.bodies[self.bodies.len() - 1];
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
            Restitution::new(Number::from_f64(e).map_err(RestitutionError::from)?)?;
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

    /// Total momentum `sum m v`.
    pub fn momentum(&self, v: &[f64]) -> f64 {
        self.bodies.iter().zip(v).map(|(b, v)| b.m * v).sum()
    }

    /// Kinetic plus potential energy `sum (1/2 (m v) v + m g (x - floor))`.
    pub fn energy(&self, x: &[f64], v: &[f64]) -> f64 {
        let floor = self.left_wall.unwrap_or(0.0);
        self.bodies
            .iter()
            .zip(x.iter().zip(v))
            .map(|(b, (x, v))| 0.5 * (b.m * v) * v + b.m * self.gravity * (x - floor))
            .sum()
    }

    /// The largest speed the run can reach, `sqrt(2 E / m_min)` (with E counting potential
    /// energy): the scale for deciding that two velocities are equal.
    fn velocity_scale(&self) -> f64 {
        let x: Vec<f64> = self.bodies.iter().map(|b| b.x).collect();
        let v: Vec<f64> = self.bodies.iter().map(|b| b.v).collect();
        let m_min = self
            .bodies
            .iter()
            .map(|b| b.m)
            .fold(f64::INFINITY, f64::min);
        let s = (2.0 * self.energy(&x, &v).max(0.0) / m_min).sqrt();
        if s > 0.0 && s.is_finite() {
            s
        } else {
            v.iter()
                .fold(0.0f64, |a, v| a.max(v.abs()))
                .max(f64::MIN_POSITIVE)
        }
    }

    /// Runs the track. `log` sees every collision.
    pub fn run(&self, limits: Limits, log: Option<&mut dyn FnMut(&Event)>) -> Run {
        let two_and_wall = self.bodies.len() == 2
            && self.left_wall.is_some()
            && self.right_wall.is_none()
            && self.gravity == 0.0
            && log.is_none();
        if two_and_wall {
            self.run_two_and_wall(limits)
        } else {
            Sim::new(self).run(limits, log)
        }
    }

    fn finish(&self, n: [u64; 3], time: f64, x: Vec<f64>, v: Vec<f64>, stop: Stop) -> Run {
        let (x0, v0): (Vec<f64>, Vec<f64>) = self.bodies.iter().map(|b| (b.x, b.v)).unzip();
        Run {
            collisions: n[0] + n[1],
            pair_collisions: n[0],
            wall_collisions: n[1],
            simultaneous: n[2],
            time,
            momentum: Budget {
                start: self.momentum(&v0),
                end: self.momentum(&v),
            },
            energy: Budget {
                start: self.energy(&x0, &v0),
                end: self.energy(&x, &v),
            },
            x,
            v,
            stop,
        }
    }

    /// Two bodies and a left wall, no gravity (pi billiards): a tight loop, same rules.
    fn run_two_and_wall(&self, limits: Limits) -> Run {
        let [a, b] = [self.bodies[0], self.bodies[1]];
        let wall = self.left_wall.unwrap_or(0.0);
        let tol = 1e-12 * self.velocity_scale();
        let kw = impulse_weights(a.m, b.m, self.e);
        let (mut x1, mut x2, mut v1, mut v2, mut t) = (a.x, b.x, a.v, b.v, 0.0f64);
        let reach = (a.size + b.size) / 2.0;
        let (mut pairs, mut walls, mut same) = (0u64, 0u64, 0u64);
        let until = limits.until.unwrap_or(f64::INFINITY);
        let mut last_t = f64::NAN;
        let stop = loop {
            if pairs + walls >= limits.max_collisions {
                break Stop::MaxCollisions;
            }
            // The next event: the pair if approaching, the wall if body 1 moves toward it.
            let pair = (v1 - v2 > tol).then(|| ((x2 - x1 - reach).max(0.0) / (v1 - v2), true));
            let hit = (v1 < -tol).then(|| ((x1 - a.size / 2.0 - wall).max(0.0) / -v1, false));
            let next = match (pair, hit) {
                (Some(p), Some(h)) => Some(if h.0 < p.0 { h } else { p }),
                (p, h) => p.or(h),
            };
            let Some((dt, is_pair)) = next else {
                break Stop::Done;
            };
            if t + dt > until {
                break Stop::Until;
            }
            t += dt;
            x1 += v1 * dt;
            x2 += v2 * dt;
            if t == last_t {
                same += 1;
            }
            last_t = t;
            if is_pair {
                (v1, v2) = impulse(kw, v1, v2);
                pairs += 1;
            } else {
                x1 = wall + a.size / 2.0;
                v1 *= -self.e_wall;
                walls += 1;
            }
        };
        if let Some(u) = limits.until.filter(|_| stop == Stop::Until) {
            x1 += v1 * (u - t);
            x2 += v2 * (u - t);
            t = u;
        }
        self.finish([pairs, walls, same], t, vec![x1, x2], vec![v1, v2], stop)
    }
}

/// A time for the priority queue, ordered totally.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Time(f64);

impl Eq for Time {}
impl PartialOrd for Time {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Time {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&o.0)
    }
}

/// The general event-driven simulation. Bodies are advanced lazily: each keeps `(x, v)` at its
/// own last time `t0`.
struct Sim<'a> {
    track: &'a Track,
    x: Vec<f64>,
    v: Vec<f64>,
    t0: Vec<f64>,
    /// `(1 + e)` times the COM weights of each adjacent pair.
    kw: Vec<(Dd, Dd)>,
    /// Version of each slot: 0 = left wall, i + 1 = pair (i, i+1), n = right wall.
    version: Vec<u64>,
    queue: BinaryHeap<Reverse<(Time, usize, u64)>>,
    tol: f64,
}

impl<'a> Sim<'a> {
    fn new(track: &'a Track) -> Sim<'a> {
        let n = track.bodies.len();
        Sim {
            track,
            x: track.bodies.iter().map(|b| b.x).collect(),
            v: track.bodies.iter().map(|b| b.v).collect(),
            t0: vec![0.0; n],
            kw: track
                .bodies
                .windows(2)
                .map(|p| impulse_weights(p[0].m, p[1].m, track.e))
                .collect(),
            version: vec![0; n + 1],
            queue: BinaryHeap::new(),
            tol: 1e-12 * track.velocity_scale(),
        }
    }

    fn n(&self) -> usize {
        self.x.len()
    }

    /// Position and velocity of body `i` at time `t`.
    fn at(&self, i: usize, t: f64) -> (f64, f64) {
        let dt = t - self.t0[i];
        let g = self.track.gravity;
        (
            self.x[i] + self.v[i] * dt - 0.5 * g * dt * dt,
            self.v[i] - g * dt,
        )
    }

    fn advance(&mut self, i: usize, t: f64) {
        (self.x[i], self.v[i]) = self.at(i, t);
        self.t0[i] = t;
    }

    fn contact(&self, slot: usize) -> Contact {
        match slot {
            0 => Contact::LeftWall,
            s if s == self.n() => Contact::RightWall,
            s => Contact::Pair(s - 1),
        }
    }

    /// When the contact of `slot` next closes, from time `now`.
    fn next_time(&self, slot: usize, now: f64) -> Option<f64> {
        let b = &self.track.bodies;
        let g = self.track.gravity;
        match self.contact(slot) {
            Contact::Pair(i) => {
                // Equal accelerations: the gap closes at a constant rate.
                let ((x1, v1), (x2, v2)) = (self.at(i, now), self.at(i + 1, now));
                let rate = v1 - v2;
                (rate > self.tol)
                    .then(|| now + (x2 - x1 - (b[i].size + b[i + 1].size) / 2.0).max(0.0) / rate)
            }
            Contact::LeftWall => {
                let wall = self.track.left_wall?;
                let (x, v) = self.at(0, now);
                let h = (x - b[0].size / 2.0 - wall).max(0.0);
                // h + v s - g/2 s^2 = 0, the positive root in a stable form.
                if g == 0.0 {
                    (v < -self.tol).then(|| now + h / -v)
                } else {
                    // sqrt(v^2 + 2 g h) without overflow.
                    let root = v.hypot((std::f64::consts::SQRT_2 * g.sqrt()) * h.sqrt());
                    let s = if v <= 0.0 {
                        2.0 * h / (root - v)
                    } else {
                        (v + root) / g
                    };
                    // A return too far away for binary64 (tiny gravity) is no event.
                    if !s.is_finite() {
                        return None;
                    }
                    // Under gravity a body always comes back down, unless it rests on the floor
                    // (no height, no speed).
                    let resting = h <= 0.0 && v.abs() <= self.tol;
                    (!resting).then_some(now + s)
                }
            }
            Contact::RightWall => {
                let wall = self.track.right_wall?;
                let last = self.n() - 1;
                let (x, v) = self.at(last, now);
                let h = (wall - x - b[last].size / 2.0).max(0.0);
                if g == 0.0 {
                    (v > self.tol).then(|| now + h / v)
                } else if v > self.tol {
                    // h - v s + g/2 s^2 = 0: reached only if v >= sqrt(2 g h) (no overflow).
                    let q = (std::f64::consts::SQRT_2 * g.sqrt()) * h.sqrt();
                    (v >= q).then(|| now + 2.0 * h / (v + ((v - q) * (v + q)).sqrt()))
                } else {
                    None
                }
            }
        }
    }

    fn schedule(&mut self, slot: usize, now: f64) {
        self.version[slot] += 1;
        if let Some(t) = self.next_time(slot, now) {
            self.queue
                .push(Reverse((Time(t), slot, self.version[slot])));
        }
    }

    fn run(mut self, limits: Limits, mut log: Option<&mut dyn FnMut(&Event)>) -> Run {
        let n = self.n();
        for slot in 0..=n {
            self.schedule(slot, 0.0);
        }
        let (mut pairs, mut walls, mut same) = (0u64, 0u64, 0u64);
        let mut now = 0.0f64;
        let mut last_t = f64::NAN;
        let mut recent = std::collections::VecDeque::with_capacity(ZENO_WINDOW + 1);
        let until = limits.until.unwrap_or(f64::INFINITY);
        let stop = loop {
            if pairs + walls >= limits.max_collisions {
                break Stop::MaxCollisions;
            }
            let Some(Reverse((Time(t), slot, version))) = self.queue.pop() else {
                break Stop::Done;
            };
            if version != self.version[slot] {
                continue;
            }
            if t > until {
                break Stop::Until;
            }
            now = t;
            let contact = self.contact(slot);
            let (who, before, after) = match contact {
                Contact::Pair(i) => {
                    self.advance(i, t);
                    self.advance(i + 1, t);
                    let before = vec![self.v[i], self.v[i + 1]];
                    (self.v[i], self.v[i + 1]) = impulse(self.kw[i], self.v[i], self.v[i + 1]);
                    pairs += 1;
                    (vec![i, i + 1], before, vec![self.v[i], self.v[i + 1]])
                }
                Contact::LeftWall | Contact::RightWall => {
                    let i = if contact == Contact::LeftWall {
                        0
                    } else {
                        n - 1
                    };
                    self.advance(i, t);
                    // At contact: exactly at the wall (rounding must not put it through).
                    let half = self.track.bodies[i].size / 2.0;
                    self.x[i] = match contact {
                        Contact::LeftWall => self.track.left_wall.map_or(self.x[i], |w| w + half),
                        _ => self.track.right_wall.map_or(self.x[i], |w| w - half),
                    };
                    let before = vec![self.v[i]];
                    self.v[i] *= -self.track.e_wall;
                    walls += 1;
                    (vec![i], before, vec![self.v[i]])
                }
            };
            if t == last_t {
                same += 1;
            }
            last_t = t;
            if let Some(log) = log.as_mut() {
                log(&Event {
                    n: pairs + walls,
                    t,
                    who: contact.describe(n),
                    before,
                    after,
                });
            }
            // Zeno: many collisions of the same few contacts in a vanishing span of time (many
            // collisions at one instant in different places are not one).
            recent.push_back((t, slot));
            if recent.len() > ZENO_WINDOW {
                recent.pop_front();
                let span = t - recent[0].0;
                if span <= 1e-12 * t.abs().max(f64::MIN_POSITIVE) && few_contacts(&recent) {
                    let times: std::collections::VecDeque<f64> =
                        recent.iter().map(|r| r.0).collect();
                    let accumulation = extrapolate(&times).unwrap_or(t);
                    let x = self.at(who[0], t).0;
                    break Stop::Zeno {
                        at: t,
                        accumulation,
                        who: contact.describe(n),
                        x,
                    };
                }
            }
            // Reschedule the slots touching the bodies that changed.
            let lo = who[0];
            let hi = *who.last().unwrap_or(&lo);
            for s in lo..=(hi + 1).min(n) {
                self.schedule(s, t);
            }
        };
        // Ending after collisions of a few contacts with geometrically shrinking gaps (a ball
        // bouncing to rest, an inelastic collapse) is a Zeno sequence that fell below the
        // resolution of binary64 before the window above filled: say so.
        let stop = match stop {
            Stop::Done => match zeno_tail(&recent) {
                Some(accumulation) => {
                    let (t_last, slot) = recent.back().copied().unwrap_or((now, 0));
                    let i = match self.contact(slot) {
                        Contact::LeftWall => 0,
                        Contact::Pair(i) => i,
                        Contact::RightWall => n - 1,
                    };
                    Stop::Zeno {
                        at: t_last,
                        accumulation,
                        who: self.contact(slot).describe(n),
                        x: self.at(i, t_last).0,
                    }
                }
                None => Stop::Done,
            },
            other => other,
        };
        let end = if stop == Stop::Until { until } else { now };
        for i in 0..n {
            self.advance(i, end);
        }
        self.track
            .finish([pairs, walls, same], end, self.x, self.v, stop)
    }
}

/// Collisions that must fit in a vanishing span of time to call it a Zeno sequence.
const ZENO_WINDOW: usize = 200;

/// The accumulation time of the run's last collisions, if they are a Zeno tail: at least 20 of
/// them, among at most 8 contacts, the gaps between them shrinking geometrically (each of the
/// last ten at most 0.99 of the one before).
fn zeno_tail(recent: &std::collections::VecDeque<(f64, usize)>) -> Option<f64> {
    if recent.len() < 20 {
        return None;
    }
    let tail: std::collections::VecDeque<(f64, usize)> =
        recent.iter().skip(recent.len() - 20).copied().collect();
    if !few_contacts(&tail) {
        return None;
    }
    let times: std::collections::VecDeque<f64> = tail.iter().map(|r| r.0).collect();
    let gaps: Vec<f64> = times
        .iter()
        .zip(times.iter().skip(1))
        .map(|(a, b)| b - a)
        .collect();
    let shrinking = gaps[gaps.len() - 11..]
        .windows(2)
        .all(|w| w[1] <= 0.99 * w[0]);
    if shrinking { extrapolate(&times) } else { None }
}

/// Whether the window's collisions involve at most 8 distinct contacts.
fn few_contacts(recent: &std::collections::VecDeque<(f64, usize)>) -> bool {
    let mut seen: Vec<usize> = Vec::with_capacity(9);
    for &(_, slot) in recent {
        if !seen.contains(&slot) {
            seen.push(slot);
            if seen.len() > 8 {
                return false;
            }
        }
    }
    true
}

/// The limit of event times shrinking geometrically: `t + dt r / (1 - r)` from the last gaps,
/// where the gaps are still resolved (not yet lost to rounding).
fn extrapolate(times: &std::collections::VecDeque<f64>) -> Option<f64> {
    let gaps: Vec<f64> = times
        .iter()
        .zip(times.iter().skip(1))
        .map(|(a, b)| b - a)
        .collect();
    // The last three gaps that are positive and shrinking.
    let g: Vec<f64> = gaps.iter().copied().filter(|g| *g > 0.0).collect();
    let [.., a, b] = g.as_slice() else {
        return None;
    };
    let r = b / a;
    (r > 0.0 && r < 1.0).then(|| times.back().copied().unwrap_or(0.0) + b * r / (1.0 - r))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pi_track(m: f64, big_m: f64) -> Track {
        Track::pi_billiards(m, big_m)
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
            let big = 100f64.powi(n);
            let run = pi_track(1.0, big).run(FOREVER, None);
            assert_eq!(run.collisions, digits, "mass ratio 100^{n}");
            assert_eq!(pi::pi_count(1.0, big), digits);
            assert_eq!(run.stop, Stop::Done);
        }
    }

    #[test]
    fn whole_multiple_ratios() {
        // m/M = 1: theta = pi/4, 3 collisions; M = 3 m: pi/6, 5; M = m/3: pi/3, 2, ending together.
        assert_eq!(pi_track(1.0, 1.0).run(FOREVER, None).collisions, 3);
        assert_eq!(pi_track(1.0, 3.0).run(FOREVER, None).collisions, 5);
        let r = pi_track(3.0, 1.0).run(FOREVER, None);
        assert_eq!(r.collisions, 2);
        assert_eq!(r.v[0], r.v[1], "both blocks end at the same velocity");
        assert_eq!(
            (
                pi::pi_count(1.0, 1.0),
                pi::pi_count(1.0, 3.0),
                pi::pi_count(3.0, 1.0)
            ),
            (3, 5, 2)
        );
        // Decimal masses whose ratio is 3 only up to rounding behave the same.
        assert_eq!(pi_track(0.1, 0.3).run(FOREVER, None).collisions, 5);
    }

    #[test]
    fn the_general_engine_agrees_with_the_tight_loop() {
        for n in 0..4 {
            let t = pi_track(1.0, 100f64.powi(n));
            let fast = t.run(FOREVER, None);
            let mut events = 0;
            let general = t.run(FOREVER, Some(&mut |_: &Event| events += 1));
            assert_eq!(
                (fast.collisions, general.collisions, events),
                (general.collisions, fast.collisions, fast.collisions as i32)
            );
            assert_eq!(fast.v, general.v);
        }
    }
}
