//! The one event-driven engine of `collide track`: every run, logged or not, with or without
//! `--until`, goes through it. Each body keeps `(x, v)` at its own last event time `t0` and is
//! advanced lazily; the candidate events (each adjacent pair and the two walls: only neighbours can
//! meet) are kept in a scheduler ordered by `(time, slot)`, so ties go left to right. Few bodies
//! use a plain array (a scan is cheaper than a heap), many a binary heap; both pick the same event.
//!
//! Under gravity a body that rests on the floor, or on a resting body, with no speed is supported:
//! it does not fall, and a body falling onto it hits it (a quadratic first-contact time). "No
//! speed" and "on" are judged per pair (the body and what holds it), as the approach rule is:
//! within what binary64 resolves there (see `Sim::rests`). Rounding left an elastic stack's bottom
//! ball a hover of a few ulps, from which it micro-bounced a billion times at 1.3e-7 m/s.

use std::collections::VecDeque;

use super::motion::{Kick, closing, event_at, first_contact, slack};
use super::schedule::Slots;
use super::zeno::{ZENO_WINDOW, extrapolate, few_contacts, zeno_tail};
use super::{Beyond, Broken, Contact, Event, Limits, Run, Stop, Track};

pub(super) struct Sim<'a> {
    track: &'a Track,
    x: Vec<f64>,
    v: Vec<f64>,
    t0: Vec<f64>,
    /// Under gravity: resting on the floor or on a resting body (no acceleration).
    supported: Vec<bool>,
    kick: Vec<Kick>,
    /// Half the sum of each adjacent pair's sizes: their centres' distance at contact.
    reach: Vec<f64>,
    slots: Slots,
    /// The track's starting extent: the largest magnitude of a wall or of a body's edge. Every
    /// position was computed from one of these, and keeps its rounding (see `check`).
    extent: f64,
    collisions: u64,
    /// Whether pi billiards may take the unrolled loop (tests compare it with the general one).
    unrolled: bool,
}

impl<'a> Sim<'a> {
    pub(super) fn new(track: &'a Track) -> Sim<'a> {
        let n = track.bodies.len();
        let b = &track.bodies;
        let mut sim = Sim {
            track,
            x: b.iter().map(|b| b.x).collect(),
            v: b.iter().map(|b| b.v).collect(),
            t0: vec![0.0; n],
            supported: vec![false; n],
            kick: b
                .windows(2)
                .map(|p| Kick::new(&p[0].m.number().exact(), &p[1].m.number().exact(), track.e))
                .collect(),
            reach: b
                .windows(2)
                .map(|p| (p[0].size + p[1].size) / 2.0)
                .collect(),
            slots: Slots::new(n + 1),
            extent: b
                .iter()
                .map(|b| b.x.abs() + b.size / 2.0)
                .chain(track.left_wall.map(f64::abs))
                .chain(track.right_wall.map(f64::abs))
                .fold(0.0, f64::max),
            collisions: 0,
            unrolled: true,
        };
        if track.gravity > 0.0 {
            for i in 0..n {
                sim.supported[i] = sim.rests(i, 0.0);
                if sim.supported[i] {
                    sim.place(i);
                }
            }
        }
        sim
    }

    fn n(&self) -> usize {
        self.x.len()
    }

    fn acc(&self, i: usize) -> f64 {
        if self.supported[i] {
            0.0
        } else {
            -self.track.gravity
        }
    }

    /// Position and velocity of body `i` at time `t`.
    #[inline]
    fn at(&self, i: usize, t: f64) -> (f64, f64) {
        let dt = t - self.t0[i];
        let a = self.acc(i);
        if a == 0.0 {
            (self.x[i] + self.v[i] * dt, self.v[i])
        } else {
            (
                self.x[i] + self.v[i] * dt + 0.5 * a * dt * dt,
                self.v[i] + a * dt,
            )
        }
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

    fn half(&self, i: usize) -> f64 {
        self.track.bodies[i].size / 2.0
    }

    /// Whether body `i` (advanced to time `t`) rests on the floor or on a resting body below it:
    /// its gap to that support is at most the rounding allowed there (`slack` of the pair's
    /// positions), and its speed at most what gravity gives over that gap or over a time of
    /// rounding size (`slack(t)`): `|v| <= g slack(t) + sqrt(2 g slack(x))`. A speed below this
    /// cannot be told from zero here (the body would rise less than the positions resolve), as
    /// a closing speed below `APPROACH` cannot.
    fn rests(&self, i: usize, t: f64) -> bool {
        let g = self.track.gravity;
        let (gap, magnitudes) = if i == 0 {
            let Some(w) = self.track.left_wall else {
                return false;
            };
            let h = self.half(0);
            (self.x[0] - h - w, self.x[0].abs() + w.abs() + h)
        } else {
            if !(self.supported[i - 1] && self.v[i - 1] == 0.0) {
                return false;
            }
            let r = self.reach[i - 1];
            (
                self.x[i] - self.x[i - 1] - r,
                self.x[i].abs() + self.x[i - 1].abs() + r,
            )
        };
        let room = slack(magnitudes);
        gap <= room && self.v[i].abs() <= g * slack(t.abs()) + (2.0 * g * room).sqrt()
    }

    /// Puts a body found resting exactly on its support, at rest.
    fn place(&mut self, i: usize) {
        self.v[i] = 0.0;
        self.x[i] = if i == 0 {
            self.track.left_wall.unwrap_or(self.x[0]) + self.half(0)
        } else {
            self.x[i - 1] + self.reach[i - 1]
        };
    }

    /// Whether the collision of `contact` at `t` would leave the energy below binary64's normal
    /// range (`f64::MIN_POSITIVE`, 2.2e-308) while a body still moves: it would underflow, and
    /// print as 0 though it is not. Inelastic bounces slowing geometrically get there (a ball
    /// between walls, its speed halved at each: after 510 bounces). Looked at only when a body
    /// the collision moves is left with a kinetic energy below that range.
    fn underflows(&self, contact: Contact, t: f64) -> bool {
        let wall = |i: usize| (i, [-self.track.e_wall * self.at(i, t).1, 0.0], 1);
        let (lo, after, k) = match contact {
            Contact::Pair(i) => {
                let (a, b) = self.kick[i].apply(self.at(i, t).1, self.at(i + 1, t).1);
                (i, [a, b], 2)
            }
            Contact::LeftWall => wall(0),
            Contact::RightWall => wall(self.n() - 1),
        };
        let moved = (lo..).zip(after).take(k);
        let tiny = |(i, v): (usize, f64)| {
            let m = self.track.bodies[i].m.value();
            v != 0.0 && 0.5 * (m * v) * v < f64::MIN_POSITIVE
        };
        if !moved.clone().any(tiny) {
            return false;
        }
        let (x, mut v): (Vec<f64>, Vec<f64>) = (0..self.n()).map(|i| self.at(i, t)).unzip();
        for (i, u) in moved {
            v[i] = u;
        }
        v.iter().any(|v| *v != 0.0) && self.track.energy(&x, &v) < f64::MIN_POSITIVE
    }

    /// When the contact of `slot` next closes, from time `now`.
    fn next_time(&self, slot: usize, now: f64) -> Option<f64> {
        let s = match self.contact(slot) {
            Contact::Pair(i) => {
                let ((x1, v1), (x2, v2)) = (self.at(i, now), self.at(i + 1, now));
                let d0 = x2 - x1 - self.reach[i];
                let a = self.acc(i + 1) - self.acc(i);
                first_contact(d0, v2 - v1, a, closing(v1, v2))
            }
            Contact::LeftWall => {
                let wall = self.track.left_wall?;
                if self.supported[0] {
                    return None;
                }
                let (x, v) = self.at(0, now);
                first_contact(x - self.half(0) - wall, v, self.acc(0), v < 0.0)
            }
            Contact::RightWall => {
                let wall = self.track.right_wall?;
                let last = self.n() - 1;
                let (x, v) = self.at(last, now);
                first_contact(wall - x - self.half(last), -v, -self.acc(last), v > 0.0)
            }
        };
        event_at(now, s)
    }

    fn schedule(&mut self, slot: usize, now: f64) {
        let t = self.next_time(slot, now);
        self.slots.set(slot, t);
    }

    /// Puts a pair that just met exactly into contact (rounding may leave a gap of an ulp either
    /// way): the lighter body moves, unless that would put it through a wall.
    fn snap(&mut self, i: usize) {
        let r = self.reach[i];
        let b = &self.track.bodies;
        let v = (self.v[i], self.v[i + 1]);
        if b[i].m.value() <= b[i + 1].m.value() {
            self.shift(i, self.x[i + 1] - r);
        } else {
            self.shift(i + 1, self.x[i] + r);
        }
        if let Some(w) = self.track.left_wall
            && i == 0
            && self.x[0] - self.half(0) < w
        {
            self.shift(0, w + self.half(0));
            self.shift(1, self.x[0] + r);
        }
        if let Some(w) = self.track.right_wall
            && i + 2 == self.n()
            && self.x[i + 1] + self.half(i + 1) > w
        {
            self.shift(i + 1, w - self.half(i + 1));
            self.shift(i, self.x[i + 1] - r);
        }
        // At micro speeds the energy's correction could turn the approach around: then the
        // velocities stay as they came.
        if !closing(self.v[i], self.v[i + 1]) {
            (self.v[i], self.v[i + 1]) = v;
        }
    }

    /// Moves body `i` (advanced to the event) to `x`, a correction of rounding size onto a wall
    /// or into contact, keeping its energy: under gravity its speed becomes the one its parabola
    /// has at `x`, `v'^2 = v^2 + 2 a (x - x_old)`, its sign kept (`snap` keeps a pair's
    /// velocities as they came if this would end its approach). The event's time is rounded to an ulp of `t`,
    /// which grows with `t`; putting the body in place without this moved it up or down the
    /// gravity field by up to `|v| ulp(t)`, an energy error per collision growing with time (an
    /// elastic stack drifted by 1e-8 in a million collisions, 1.4e-9 in 300,000).
    fn shift(&mut self, i: usize, x: f64) {
        let a = self.acc(i);
        if a != 0.0 && x != self.x[i] {
            let v2 = self.v[i] * self.v[i] + 2.0 * a * (x - self.x[i]);
            self.v[i] = v2.max(0.0).sqrt().copysign(self.v[i]);
        }
        self.x[i] = x;
    }

    /// Checks, at time `t`, that bodies `lo..=hi` are in order with their neighbours and inside
    /// the walls, allowing rounding (see `motion::slack`): of the positions' magnitudes now and
    /// at the start (the track's extent, from which every position was computed), and of the
    /// time, where each body moves by `|v| slack(t)`. An event's time is rounded to an ulp of
    /// `t`: a body put exactly onto a wall at it stands where its neighbour, computed at that
    /// rounded time with the speed it had then, may be `|v| ulp(t)` away; near the origin the
    /// positions' magnitudes now allow nothing, and a pair at the left wall at 0 was "broken"
    /// by 2e-17 after 16 collisions (`-m 1,3 -x 1,3 -v -1,1 --left-wall 0 --right-wall 4
    /// -e 0.03`), and three bodies collapsing onto it by 1.2e-15 (issue 41).
    fn check(&self, lo: usize, hi: usize, t: f64) -> Result<(), Broken> {
        let n = self.n();
        let broken = |what: String| Broken {
            t,
            collisions: self.collisions,
            what,
        };
        let pos = |i: usize| self.at(i, t).0;
        // Body `i`'s rounding beyond its position's magnitude now: what the time's rounding
        // moves it by, and the track's extent.
        let drift = |i: usize| self.at(i, t).1.abs() * slack(t.abs()) + slack(self.extent);
        for i in lo.saturating_sub(1)..(hi + 1).min(n - 1) {
            let (x1, x2) = (pos(i), pos(i + 1));
            let gap = x2 - x1 - self.reach[i];
            let room = slack(x1.abs() + x2.abs() + self.x[i].abs() + self.x[i + 1].abs())
                + slack(self.reach[i])
                + drift(i)
                + drift(i + 1);
            if gap.is_nan() || gap < -room {
                return Err(broken(format!(
                    "bodies {} and {} overlap (x = {}, {})",
                    i + 1,
                    i + 2,
                    x1,
                    x2
                )));
            }
        }
        if let Some(w) = self.track.left_wall
            && lo == 0
        {
            let x = pos(0);
            let room = slack(x.abs() + self.x[0].abs() + w.abs() + self.half(0)) + drift(0);
            if x - self.half(0) - w < -room {
                return Err(broken(format!(
                    "body 1 is left of the left wall at {w} (x = {x})"
                )));
            }
        }
        if let Some(w) = self.track.right_wall
            && hi == n - 1
        {
            let x = pos(n - 1);
            let h = self.half(n - 1);
            if w - x - h < -(slack(x.abs() + self.x[n - 1].abs() + w.abs() + h) + drift(n - 1)) {
                return Err(broken(format!(
                    "body {n} is right of the right wall at {w} (x = {x})"
                )));
            }
        }
        Ok(())
    }

    /// Updates which bodies rest after an event that changed bodies `lo..=hi` at `t`; returns
    /// the highest body whose state changed.
    fn resupport(&mut self, lo: usize, hi: usize, t: f64) -> usize {
        let mut top = hi;
        for i in lo..self.n() {
            self.advance(i, t);
            let now = self.rests(i, t);
            if now != self.supported[i] {
                self.supported[i] = now;
                if now {
                    self.place(i);
                }
                top = top.max(i);
            } else if i > hi {
                break;
            }
        }
        top
    }

    pub(super) fn run(
        mut self,
        limits: Limits,
        mut log: Option<&mut dyn FnMut(&Event)>,
    ) -> Result<Run, Broken> {
        let n = self.n();
        let track = self.track;
        let dissipative = track.e < 1.0 || track.e_wall < 1.0 || track.gravity > 0.0;
        if self.unrolled
            && n == 2
            && track.left_wall.is_some()
            && track.right_wall.is_none()
            && !dissipative
        {
            let (counts, now, stop) = self.two_and_wall(limits, log)?;
            return self.finish(limits, counts, now, stop);
        }
        for slot in 0..=n {
            self.schedule(slot, 0.0);
        }
        let (mut pairs, mut walls, mut same) = (0u64, 0u64, 0u64);
        let mut now = 0.0f64;
        let mut last_t = f64::NAN;
        let mut recent: VecDeque<(f64, usize)> = VecDeque::with_capacity(ZENO_WINDOW + 1);
        let until = limits.until.unwrap_or(f64::INFINITY);
        let stop = loop {
            if self.collisions >= limits.max_collisions {
                break Stop::MaxCollisions;
            }
            let Some((t, slot)) = self.slots.pop() else {
                break Stop::Done;
            };
            if t > until {
                break Stop::Until;
            }
            if t == f64::INFINITY {
                break Stop::Horizon {
                    next: None,
                    beyond: Beyond::Time,
                };
            }
            // Only far out in time can a position overflow; then stop before the event.
            if t > 1e250 && (0..n).any(|i| !self.at(i, t).0.is_finite()) {
                break Stop::Horizon {
                    next: Some(t),
                    beyond: Beyond::Position,
                };
            }
            let contact = self.contact(slot);
            // Only a run that loses energy can lose it below binary64's range.
            if dissipative && self.underflows(contact, t) {
                break Stop::Horizon {
                    next: Some(t),
                    beyond: Beyond::Energy,
                };
            }
            now = t;
            let (lo, hi, before) = match contact {
                Contact::Pair(i) => {
                    self.advance(i, t);
                    self.advance(i + 1, t);
                    self.snap(i);
                    let before = [self.v[i], self.v[i + 1]];
                    (self.v[i], self.v[i + 1]) = self.kick[i].apply(before[0], before[1]);
                    pairs += 1;
                    (i, i + 1, before)
                }
                Contact::LeftWall | Contact::RightWall => {
                    let (i, wall) = match contact {
                        Contact::LeftWall => (0, track.left_wall),
                        _ => (n - 1, track.right_wall),
                    };
                    self.advance(i, t);
                    // Exactly at the wall: rounding must not put it through.
                    let half = self.half(i);
                    if let Some(w) = wall {
                        let x = if contact == Contact::LeftWall {
                            w + half
                        } else {
                            w - half
                        };
                        self.shift(i, x);
                    }
                    let before = [self.v[i], f64::NAN];
                    self.v[i] *= -track.e_wall;
                    walls += 1;
                    (i, i, before)
                }
            };
            self.collisions += 1;
            if t == last_t {
                same += 1;
            }
            last_t = t;
            let top = if track.gravity > 0.0 {
                self.resupport(lo, hi, t)
            } else {
                hi
            };
            self.check(lo, top, t)?;
            if let Some(log) = log.as_mut() {
                let k = hi - lo + 1;
                log(&Event {
                    n: self.collisions,
                    t,
                    who: contact.describe(n),
                    before: before[..k].to_vec(),
                    after: self.v[lo..=hi].to_vec(),
                });
            }
            if dissipative {
                // Zeno: many collisions of the same few contacts in a vanishing span of time.
                recent.push_back((t, slot));
                if recent.len() > ZENO_WINDOW {
                    recent.pop_front();
                    let span = t - recent[0].0;
                    if span <= 1e-12 * t.abs().max(f64::MIN_POSITIVE) && few_contacts(&recent) {
                        let times: Vec<f64> = recent.iter().map(|r| r.0).collect();
                        break Stop::Zeno {
                            at: t,
                            accumulation: extrapolate(&times).unwrap_or(t),
                            who: contact.describe(n),
                            x: self.at(lo, t).0,
                        };
                    }
                }
            }
            for s in lo..=(top + 1).min(n) {
                self.schedule(s, t);
            }
        };
        // Ending after collisions of a few contacts with geometrically shrinking gaps (a ball
        // bouncing to rest, an inelastic collapse) is a Zeno sequence that fell below the
        // resolution of binary64 before the window above filled: say so.
        let stop = match stop {
            Stop::Done if dissipative => match zeno_tail(&recent) {
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
        self.finish(limits, [pairs, walls, same], now, stop)
    }

    /// The state at the end: at --until when the run got there (free flight after the last
    /// event), else at the last event; checked, and settled.
    fn finish(
        mut self,
        limits: Limits,
        counts: [u64; 3],
        now: f64,
        stop: Stop,
    ) -> Result<Run, Broken> {
        let n = self.n();
        let end = match (&stop, limits.until) {
            (Stop::Until | Stop::Done, Some(u)) => u,
            _ => now,
        };
        self.check(0, n - 1, end)?;
        for i in 0..n {
            self.advance(i, end);
        }
        self.settle();
        let collisions = self.collisions;
        self.track
            .finish(counts, end, self.x, self.v, stop, collisions)
    }

    /// Two bodies and a left wall, elastic, no gravity (pi billiards): the loop of `run` for
    /// this layout, with the same rules (`closing`, a body approaches the wall when it moves
    /// toward it, the wall first on a tie), the same impulses (`Kick::apply`, so the same
    /// velocities to the bit) and hence the same events. Only the bookkeeping of time differs:
    /// instead of absolute positions it keeps body 1's distance `w` from the wall and the gap
    /// `g` between the bodies, so each event costs a multiply and a fused multiply-add on that
    /// chain (`s = w / -v1`, from a reciprocal that depends on the velocities only) instead of a
    /// division of a difference of positions. A test compares it with the general loop.
    fn two_and_wall(
        &mut self,
        limits: Limits,
        log: Option<&mut dyn FnMut(&Event)>,
    ) -> Result<([u64; 3], f64, Stop), Broken> {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has FMA, checked just above, the one feature the function enables.
            return unsafe { self.two_and_wall_fma(limits, log) };
        }
        self.two_and_wall_loop(limits, log)
    }

    /// The loop compiled with hardware fused multiply-add (the impulse's error-free products):
    /// the same results as the library call used otherwise (a fused multiply-add is exactly
    /// specified), 1.7 times faster.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "fma")]
    fn two_and_wall_fma(
        &mut self,
        limits: Limits,
        log: Option<&mut dyn FnMut(&Event)>,
    ) -> Result<([u64; 3], f64, Stop), Broken> {
        self.two_and_wall_loop(limits, log)
    }

    #[inline(always)]
    fn two_and_wall_loop(
        &mut self,
        limits: Limits,
        mut log: Option<&mut dyn FnMut(&Event)>,
    ) -> Result<([u64; 3], f64, Stop), Broken> {
        let xw = self.track.left_wall.unwrap_or(0.0) + self.half(0);
        let reach = self.reach[0];
        let kick = self.kick[0];
        let e_wall = self.track.e_wall;
        let (mut v1, mut v2) = (self.v[0], self.v[1]);
        let mut w = (self.x[0] - xw).max(0.0);
        let mut g = (self.x[1] - self.x[0] - reach).max(0.0);
        let (mut pairs, mut walls, mut same) = (0u64, 0u64, 0u64);
        let (mut now, mut last_t) = (0.0f64, f64::NAN);
        let until = limits.until.unwrap_or(f64::INFINITY);
        let stop = loop {
            if pairs + walls >= limits.max_collisions {
                break Stop::MaxCollisions;
            }
            let hit = v1 < 0.0;
            let meet = closing(v1, v2);
            // The event and its delay: only one candidate but at the start.
            let (is_pair, s) = match (hit, meet) {
                (false, false) => break Stop::Done,
                (true, false) => (false, w * (1.0 / -v1)),
                (false, true) => (true, g * (1.0 / (v1 - v2))),
                (true, true) => {
                    let (sw, sp) = (w / -v1, g / (v1 - v2));
                    match (event_at(now, Some(sw)), event_at(now, Some(sp))) {
                        (Some(a), Some(b)) if b.total_cmp(&a).is_lt() => (true, sp),
                        (None, Some(_)) => (true, sp),
                        _ => (false, sw),
                    }
                }
            };
            let Some(t) = event_at(now, Some(s)) else {
                break Stop::Done;
            };
            if t > until {
                break Stop::Until;
            }
            if t == f64::INFINITY {
                break Stop::Horizon {
                    next: None,
                    beyond: Beyond::Time,
                };
            }
            now = t;
            let before = [v1, v2];
            if is_pair {
                w += v1 * s;
                g = 0.0;
                (v1, v2) = kick.apply(v1, v2);
                pairs += 1;
            } else {
                g += (v2 - v1) * s;
                w = 0.0;
                v1 *= -e_wall;
                walls += 1;
            }
            // `check`: in order and right of the wall, allowing rounding; then exactly so.
            if !(w >= 0.0 && g >= 0.0) {
                let room = slack(xw.abs() + w.abs() + g.abs() + reach);
                if w < -room || g < -room || !(w + g).is_finite() {
                    return Err(Broken {
                        t,
                        collisions: pairs + walls,
                        what: format!("body 1 at {w} from the wall, {g} from body 2"),
                    });
                }
                (w, g) = (w.max(0.0), g.max(0.0));
            }
            if t == last_t {
                same += 1;
            }
            last_t = t;
            if let Some(log) = log.as_mut() {
                let (who, before, after) = if is_pair {
                    ("1 & 2", before.to_vec(), vec![v1, v2])
                } else {
                    ("left wall & 1", vec![before[0]], vec![v1])
                };
                log(&Event {
                    n: pairs + walls,
                    t,
                    who: who.to_string(),
                    before,
                    after,
                });
            }
        };
        self.collisions = pairs + walls;
        let x1 = xw + w;
        (self.x[0], self.v[0], self.t0[0]) = (x1, v1, now);
        (self.x[1], self.v[1], self.t0[1]) = (x1 + reach + g, v2, now);
        Ok(([pairs, walls, same], now, stop))
    }

    /// Removes overlaps of rounding size (checked before): bodies in contact end exactly in
    /// contact, never an ulp through each other or a wall, by the test `Track::check` applies
    /// (`x2 - x1 >= (s1 + s2) / 2` in binary64).
    fn settle(&mut self) {
        let n = self.n();
        if let Some(w) = self.track.left_wall {
            let h = self.half(0);
            while self.x[0] - h < w {
                self.x[0] = (w + h).max(self.x[0].next_up());
            }
        }
        for i in 0..n - 1 {
            let r = self.reach[i];
            if self.x[i + 1] - self.x[i] < r {
                self.x[i + 1] = self.x[i] + r;
                while self.x[i + 1] - self.x[i] < r {
                    self.x[i + 1] = self.x[i + 1].next_up();
                }
            }
        }
        if let Some(w) = self.track.right_wall {
            let h = self.half(n - 1);
            while self.x[n - 1] + h > w {
                self.x[n - 1] = (w - h).min(self.x[n - 1].next_down());
            }
            for i in (0..n - 1).rev() {
                let r = self.reach[i];
                if self.x[i + 1] - self.x[i] < r {
                    self.x[i] = self.x[i + 1] - r;
                    while self.x[i + 1] - self.x[i] < r {
                        self.x[i] = self.x[i].next_down();
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::line::inertia::Mass;
    use crate::track::Body;
    use proptest::prelude::*;

    /// Times and positions kept two ways agree to rounding.
    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
    }

    fn both(track: &Track, limits: Limits) -> [(Result<Run, Broken>, Vec<Event>); 2] {
        [true, false].map(|unrolled| {
            let mut events = Vec::new();
            let mut sim = Sim::new(track);
            sim.unrolled = unrolled;
            let run = sim.run(limits, Some(&mut |e: &Event| events.push(e.clone())));
            (run, events)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]
        /// The unrolled pi-billiards loop and the general loop make the same events with the same
        /// velocities to the bit; their times and positions agree to rounding.
        #[test]
        fn the_unrolled_loop_is_the_general_loop(
            m1 in -6.0f64..6.0, m2 in -6.0f64..6.0,
            x1 in 0.0f64..2.0, gap in 0.0f64..3.0,
            v1 in -2.0f64..2.0, v2 in -2.0f64..2.0,
            s1 in 0.0f64..1.0, s2 in 0.0f64..1.0,
            until in proptest::option::of(0.0f64..20.0),
        ) {
            let body = |m: f64, x: f64, v: f64, size: f64| Body {
                m: Mass::from_f64(10f64.powf(m)).unwrap(),
                x,
                v,
                size,
            };
            let track = Track {
                bodies: vec![
                    body(m1, x1 + s1 / 2.0, v1, s1),
                    body(m2, x1 + s1 + gap + s2 / 2.0, v2, s2),
                ],
                left_wall: Some(0.0),
                right_wall: None,
                e: 1.0,
                e_wall: 1.0,
                gravity: 0.0,
            };
            track.check().unwrap();
            let limits = Limits { until, max_collisions: 20_000 };
            let [(fast, fast_log), (general, general_log)] = both(&track, limits);
            let (fast, general) = (fast.unwrap(), general.unwrap());
            prop_assert_eq!(fast.collisions, general.collisions);
            prop_assert_eq!(fast.pair_collisions, general.pair_collisions);
            prop_assert_eq!(&fast.v, &general.v);
            prop_assert_eq!(&fast.stop, &general.stop);
            prop_assert_eq!(fast_log.len(), general_log.len());
            for (a, b) in fast_log.iter().zip(&general_log) {
                prop_assert_eq!((&a.who, &a.before, &a.after), (&b.who, &b.before, &b.after));
                prop_assert!(close(a.t, b.t), "t {} vs {}", a.t, b.t);
            }
            prop_assert!(close(fast.time, general.time));
            for (a, b) in fast.x.iter().zip(&general.x) {
                prop_assert!(close(*a, *b), "x {a} vs {b}");
            }
        }
    }
}
