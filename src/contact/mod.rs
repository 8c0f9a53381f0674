//! Collisions in time: bodies on a track that push with a contact force while they overlap,
//! integrated through each impact (`collide contact`), where `track` treats every collision as an
//! instantaneous impulse.
//!
//! A single contact is not stiff: a larger stiffness only rescales its time. Stiffness needs two
//! time scales at once (a soft contact pressed against a hard one, a stack on a stiff floor,
//! Newton's cradle), and there the time-domain answer can differ from the sequential impulses of
//! `track` even in the stiff limit, which the run shows beside it (`impulse_model`).
//!
//! - `setup`: the layout and the laws as asked; `settings`: the method, its step or tolerance;
//! - `law`: the contact forces; `closed`: the closed forms of a single contact;
//! - `system`: the equations of motion; `fixed`: the fixed-step methods (ours);
//!   `adaptive`: tsit45, bdf and sdirk (diffsol); `run`: the event-driven integration;
//! - `work`: error against run time for each method; `scales`: the setup's time scales, default
//!   steps and tolerances; `error`: every refusal.

pub mod adaptive;
pub mod closed;
mod error;
pub mod fixed;
pub mod law;
pub mod run;
mod scales;
mod settings;
mod setup;
pub mod system;
pub mod work;

use serde::Serialize;

use crate::values::number::num;

use crate::track::{self, Contact};

pub use adaptive::Adaptive;
pub use error::ContactError;
pub use fixed::{Counts, Fixed};
pub use law::Law;
pub use run::Failure;
pub use scales::Scales;
use scales::{SHORTEST, steps_for, too_short};
pub use settings::{AUTO_TOL, AUTO_TOL_HERTZ, DEFAULT_MAX_STEPS, Method, STIFF_RATIO, Settings};
pub use setup::{Damping, LawKind, Laws, Setup, Spec};
use system::{Slot, System};

/// One contact from its start to its end.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContactRecord {
    /// Bodies, 1-based, or "left"/"right" for a wall.
    pub between: [serde_json::Value; 2],
    pub start: f64,
    /// `None` while still active at the end of the run (`--until`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub duration: Option<f64>,
    pub max_overlap: f64,
    /// Approach speed at the start.
    pub speed: f64,
    /// `-(rate of overlap at the end) / (rate at the start)`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    #[serde(skip)]
    pub slot: usize,
}

/// The energy at the start and the end, and what the contacts dissipated (never negative).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EnergyBudget {
    pub start: f64,
    pub end: f64,
    pub dissipated: f64,
}

/// What `collide track` gives for the same layout with the calibrated restitutions.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpulseModel {
    pub e: f64,
    pub e_wall: f64,
    pub v: Vec<f64>,
    pub collisions: u64,
}

/// A finished run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContactRun {
    pub law: &'static str,
    pub method: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tol: Option<f64>,
    pub time: f64,
    pub x: Vec<f64>,
    pub v: Vec<f64>,
    pub contacts: Vec<ContactRecord>,
    pub energy: EnergyBudget,
    pub stats: Counts,
    /// `None` where restitution depends on the impact speed (Hunt-Crossley) or differs between
    /// pairs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impulse_model: Option<ImpulseModel>,
    /// Why the run ended: "done" (no contact active and none can begin) or "until".
    pub stop: &'static str,
    /// Overlap and force of the active contacts after every step, when asked
    /// (`Settings::trace`).
    #[serde(skip)]
    pub history: Vec<run::Sample>,
}

/// Runs `setup` with `settings`.
pub fn simulate(setup: &Setup, settings: &Settings) -> Result<ContactRun, ContactError> {
    // Bodies that overlap at the start are refused by `slots` (the track's order check, the
    // same comparison: `x2 - x1 < (s1 + s2) / 2`).
    let slots = setup.slots()?;
    if let Some(i) = setup.bodies.iter().position(|b| b.size <= 0.0) {
        return Err(ContactError::PointBody(i + 1));
    }
    // Between two walls a moving body meets a wall or another body again and again: no run ends
    // by itself (each contact leaves it some speed: e > 0 for every law).
    if setup.left_wall.is_some()
        && setup.right_wall.is_some()
        && settings.until.is_none()
        && setup.bodies.iter().any(|b| b.v != 0.0)
    {
        return Err(ContactError::Forever);
    }
    let scales = Scales::of(setup, &slots);
    // Measured: contacts of 1e-75 run as well as any; at 1e-150 the solvers stall on steps.
    if scales.t_min < SHORTEST {
        return Err(too_short(&slots, &scales));
    }
    let method = settings.method.unwrap_or(scales.auto());
    let (dt, tol) = steps_for(method, settings, &scales)?;
    if let (Method::Fixed(f), Some(dt)) = (method, dt)
        && let Some(limit) = f.stability_limit()
        && let Some((who, w)) = scales.fastest(setup)
        // At the limit itself the method is not stable either (symplectic Euler and Verlet
        // at omega h = 2: a double eigenvalue -1, so the error grows linearly).
        && w * dt >= limit
    {
        return Err(ContactError::Unstable {
            method: method.name(),
            dt,
            who,
            wh: w * dt,
            limit,
            safe: limit / w,
        });
    }
    let mut run = integrate(setup, &slots, &scales, method, dt, tol, settings)?;
    run.impulse_model = impulse_model(setup, &slots, settings.until)?;
    Ok(run)
}

/// An open contact: when it began and how fast.
struct Open {
    start: f64,
    speed: f64,
}

fn between(who: Contact, n: usize) -> [serde_json::Value; 2] {
    use serde_json::json;
    match who {
        Contact::LeftWall => [json!("left"), json!(1)],
        Contact::Pair(i) => [json!(i + 1), json!(i + 2)],
        Contact::RightWall => [json!(n), json!("right")],
    }
}

/// The event-driven integration (see `run`).
fn integrate(
    setup: &Setup,
    slots: &[Slot],
    scales: &Scales,
    method: Method,
    dt: Option<f64>,
    tol: Option<f64>,
    settings: &Settings,
) -> Result<ContactRun, ContactError> {
    let n = setup.bodies.len();
    let m = setup.masses();
    let mut x: Vec<f64> = setup.bodies.iter().map(|b| b.x).collect();
    let mut v: Vec<f64> = setup.bodies.iter().map(|b| b.v).collect();
    let mut t = 0.0f64;
    let until = settings.until.unwrap_or(f64::INFINITY);
    let mut active = vec![false; slots.len()];
    let mut open: Vec<Option<Open>> = (0..slots.len()).map(|_| None).collect();
    let mut closed = vec![false; slots.len()];
    let mut records: Vec<ContactRecord> = Vec::new();
    let kinetic = |v: &[f64]| -> f64 { m.iter().zip(v).map(|(m, v)| 0.5 * (m * v) * v).sum() };
    let e_start = kinetic(&v);
    // Without walls the run is integrated in the centre-of-mass frame (velocity w): a large
    // common velocity would otherwise swamp the relative motion in the error control and the
    // energies; with walls that frame is not inertial for the contacts and w = 0.
    let w = if setup.left_wall.is_none() && setup.right_wall.is_none() {
        m.iter().zip(&v).map(|(m, v)| m * v).sum::<f64>() / m.iter().sum::<f64>()
    } else {
        0.0
    };
    for vi in v.iter_mut() {
        *vi -= w;
    }
    // Positions far from the origin are resolved coarsely (at 5e19 to 8192): where that is not
    // small beside the contacts' overlap, the run is integrated with its origin at the centre
    // of mass (without walls, where it is at rest), so that two bodies meet near 0 whatever
    // their lab positions; results are moved back at the end.
    let far = x.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    let shift = if setup.left_wall.is_none()
        && setup.right_wall.is_none()
        && ulp(far) > scales.overlap * RESOLUTION_SHIFT
    {
        // X_COM = x1 + sum (m_i / M) (x_i - x1): differences, so no product overflows.
        let total: f64 = m.iter().sum();
        x[0] + m
            .iter()
            .zip(&x)
            .map(|(mi, xi)| (mi / total) * (xi - x[0]))
            .sum::<f64>()
    } else {
        0.0
    };
    // How far each position may be from its exact value: the rounding errors so far, each
    // taken exactly (an error-free transformation) where it happens: the shift, each free
    // flight's product and sum, each stretch's sum. Typed positions are exact.
    let mut slack: Vec<f64> = vec![0.0; n];
    for (xi, si) in x.iter_mut().zip(slack.iter_mut()) {
        let moved = *xi - shift;
        *si += sum_error(*xi, -shift, moved).abs();
        *xi = moved;
    }
    let e_rel_start = kinetic(&v);
    let mut ledger = run::Ledger {
        counts: Counts::default(),
        steps_left: settings.max_steps,
        peaks: vec![0.0; slots.len()],
        energy_cap: 2.0 * e_rel_start.max(f64::MIN_POSITIVE),
        trace: settings.trace.then(Vec::new),
        origin: 0.0,
    };
    let fail = |failure: Failure| ContactError::Failed {
        method: method.name(),
        failure: match failure {
            Failure::Steps(_) => Failure::Steps(settings.max_steps),
            f => f,
        },
    };
    let system = |active: &[bool], x: &[f64]| System {
        m: m.clone(),
        slots: slots.to_vec(),
        active: active.to_vec(),
        d0: slots.iter().map(|s| setup.overlap(s.who, x)).collect(),
    };
    let tolerances = tol.map(|tol| adaptive::Tolerances {
        rtol: tol,
        atol_u: tol * scales.overlap,
        atol_v: tol * scales.speed.max(f64::MIN_POSITIVE),
        h0: scales.t_min * 1e-3,
    });
    let stop;
    loop {
        if !active.iter().any(|a| *a) {
            // Free flight: exact, to the first contact that begins.
            let sys = system(&active, &x);
            let mut y = vec![0.0; 2 * n];
            y[n..].copy_from_slice(&v);
            let mut next: Option<(f64, usize)> = None;
            for (s, &was_closed) in closed.iter().enumerate() {
                let (d, rate) = sys.overlap(s, &y);
                // In free flight a gate only falls while the pair separates (rate <= 0), so a
                // positive one is either the starting overlap or a closing's rounding: a closed
                // contact reopens only on approach (else it would chatter at its end).
                let wait = if sys.gate(s, &y) > 0.0 && (rate > 0.0 || !was_closed) {
                    0.0
                } else if rate > 0.0 && d <= 0.0 {
                    -d / rate
                } else {
                    continue;
                };
                if next.is_none_or(|(w, _)| wait < w) {
                    next = Some((wait, s));
                }
            }
            let Some((wait, s)) = next.filter(|(w, _)| t + w <= until) else {
                if until.is_finite() {
                    for i in 0..n {
                        x[i] += v[i] * (until - t);
                    }
                    t = until;
                }
                stop = if next.is_some() { "until" } else { "done" };
                break;
            };
            for i in 0..n {
                let dx = v[i] * wait;
                let moved = x[i] + dx;
                slack[i] += v[i].mul_add(wait, -dx).abs() + sum_error(x[i], dx, moved).abs();
                x[i] = moved;
            }
            t += wait;
            let (d, rate) = system(&active, &x).overlap(s, &y);
            // The flight ends where the overlap is 0; what the positions say instead is the
            // rounding of the flight's time and products (a flight of 1e20 at 1e10 lands the
            // centres on each other).
            slack[first_body(slots[s].who, n)] += d.abs();
            active[s] = true;
            ledger.peaks[s] = 0.0;
            open[s] = Some(Open {
                start: t,
                speed: rate,
            });
            continue;
        }
        if t >= until {
            stop = "until";
            break;
        }
        // A contact whose bodies' positions are known more coarsely than a thousandth of its
        // overlap cannot be followed (its overlap would be rounding): said, never integrated.
        if let Some((s, known)) = (0..slots.len())
            .filter(|&s| active[s])
            .map(|s| (s, slack_of(slots[s].who, &slack)))
            .find(|&(_, known)| known > scales.overlap * RESOLUTION_REFUSE)
        {
            return Err(ContactError::Resolution {
                who: slots[s].who.describe(n),
                at: shift + reach_of(slots[s].who, &x),
                slack: known,
                overlap: scales.overlap,
            });
        }
        let sys = system(&active, &x);
        let mut y0 = vec![0.0; 2 * n];
        y0[n..].copy_from_slice(&v);
        // A stretch that starts so late that the time's rounding is no longer small beside the
        // shortest contact (at t = 6e15, ulp(t) = 1: a step of 0.01 would be lost) steps in its
        // own time, from 0; any other in the run's time, as it always has (the event search's
        // tolerances are relative to the time).
        let origin = if ulp(t) > scales.t_min * 1e-10 {
            t
        } else {
            0.0
        };
        ledger.origin = origin;
        let end = match (method, dt, tolerances) {
            (Method::Fixed(f), Some(h), _) => {
                run::fixed_stretch((f, h), &sys, (t - origin, &y0), until - origin, &mut ledger)
            }
            (Method::Adaptive(a), _, Some(tol)) => adaptive::stretch(
                (a, tol),
                &sys,
                (t - origin, &y0),
                until - origin,
                &mut ledger,
            ),
            _ => unreachable!("steps_for gives a step to fixed methods and a tolerance otherwise"),
        }
        .map_err(|failure| failure.shifted(origin))
        .map_err(|failure| match failure {
            Failure::Through { t, slot, y } => {
                // Positions in the lab frame: the stretch's start moved by y's displacements,
                // and the frame's own motion.
                let at: Vec<f64> = x
                    .iter()
                    .zip(&y[..n])
                    .map(|(x, u)| shift + (x + u + w * t))
                    .collect();
                passed_through(setup, &slots[slot], t, &at, sys.overlap(slot, &y).0)
            }
            other => fail(other),
        })?;
        for ((xi, u), si) in x.iter_mut().zip(&end.y[..n]).zip(slack.iter_mut()) {
            let moved = *xi + u;
            *si += sum_error(*xi, *u, moved).abs();
            *xi = moved;
        }
        v.copy_from_slice(&end.y[n..]);
        // The stretch's end in its own time; in the run's: a stretch that ran to its stop ends
        // at --until itself (`origin + (until - origin)` may round beside it).
        let tau = end.t;
        t = if end.event.is_none() && until.is_finite() {
            until
        } else {
            origin + tau
        };
        let Some(s) = end.event else {
            stop = "until";
            break;
        };
        // The event's slot changes, and so does any other whose gate crossed at the same
        // instant (symmetric impacts end together; a crossing left for later would start the
        // next stretch on the wrong side and never be seen).
        for p in 0..slots.len() {
            if p != s && (sys.gate(p, &end.y) > 0.0) == active[p] {
                continue;
            }
            let (_, rate) = sys.overlap(p, &end.y);
            if active[p] {
                active[p] = false;
                closed[p] = true;
                let o = open[p].take().expect("an active contact is open");
                records.push(ContactRecord {
                    between: between(slots[p].who, n),
                    start: o.start,
                    // As `t - start`, with the part in this stretch in its own time (exact
                    // where the time's rounding is coarse).
                    duration: Some((origin - o.start) + tau),
                    max_overlap: ledger.peaks[p],
                    speed: o.speed,
                    // A contact that began without an impact (pressed by another) has no
                    // restitution.
                    restitution: (o.speed > 1e-8 * scales.speed).then(|| -rate / o.speed),
                    slot: p,
                });
            } else {
                active[p] = true;
                ledger.peaks[p] = 0.0;
                open[p] = Some(Open {
                    start: t,
                    speed: rate,
                });
            }
        }
    }
    // Contacts still active at --until.
    for s in 0..slots.len() {
        if let Some(o) = open[s].take() {
            records.push(ContactRecord {
                between: between(slots[s].who, n),
                start: o.start,
                duration: None,
                max_overlap: ledger.peaks[s],
                speed: o.speed,
                restitution: None,
                slot: s,
            });
        }
    }
    records.sort_by(|a, b| a.start.total_cmp(&b.start));
    let sys = system(&active, &x);
    let mut y = vec![0.0; 2 * n];
    y[n..].copy_from_slice(&v);
    let e_rel_end = sys.energy(&y);
    // Back to the lab frame.
    for (xi, vi) in x.iter_mut().zip(v.iter_mut()) {
        *xi = shift + (*xi + w * t);
        *vi += w;
    }
    y[n..].copy_from_slice(&v);
    let e_end = sys.energy(&y);
    let gain = (e_rel_end - e_rel_start) / e_rel_start.max(f64::MIN_POSITIVE);
    if gain > 1e-6 {
        return Err(ContactError::EnergyGain {
            method: method.name(),
            start: e_start,
            end: e_end,
            gain,
        });
    }
    Ok(ContactRun {
        law: setup.law.kind.name(),
        method: method.name(),
        dt,
        tol,
        time: t,
        x,
        v,
        contacts: records,
        energy: EnergyBudget {
            start: e_start,
            end: e_end,
            dissipated: (e_rel_start - e_rel_end).max(0.0),
        },
        stats: ledger.counts,
        impulse_model: None,
        stop,
        history: ledger.trace.unwrap_or_default(),
    })
}

/// The error for slot `slot` overlapping as deep as its reach at `t`, with the lab positions
/// `x`: who went through what, where, and what to change.
fn passed_through(setup: &Setup, slot: &Slot, t: f64, x: &[f64], overlap: f64) -> ContactError {
    let n = x.len();
    let at = |i: usize| format!("x{} = {}", i + 1, num(x[i]));
    let (who, positions, spec, flag) = match slot.who {
        Contact::Pair(i) => (
            format!("bodies {} and {} passed through each other", i + 1, i + 2),
            format!("{}, {}", at(i), at(i + 1)),
            setup.law,
            "--stiffness",
        ),
        Contact::LeftWall => (
            "body 1 passed through the left wall".to_string(),
            format!(
                "{} with the wall at {}",
                at(0),
                num(setup.left_wall.unwrap_or(f64::NAN))
            ),
            setup.wall,
            "--wall-stiffness",
        ),
        Contact::RightWall => (
            format!("body {n} passed through the right wall"),
            format!(
                "{} with the wall at {}",
                at(n - 1),
                num(setup.right_wall.unwrap_or(f64::NAN))
            ),
            setup.wall,
            "--wall-stiffness",
        ),
    };
    ContactError::Through {
        who,
        t,
        positions,
        overlap,
        reach: slot.reach,
        flag,
        k: spec.k,
    }
}

/// `collide track` on the same layout with the restitutions the contact laws give, where they do
/// not depend on the impact speed and are the same for every pair (and for both walls).
fn impulse_model(
    setup: &Setup,
    slots: &[Slot],
    until: Option<f64>,
) -> Result<Option<ImpulseModel>, ContactError> {
    let e_of = |s: &Slot| match s.law {
        Law::Linear { k, c } => {
            Some(closed::Linear::new(k, c, s.mu).restitution()).filter(|e| e.is_finite())
        }
        Law::Hertz { chi, .. } => (chi == 0.0).then_some(1.0),
    };
    let mut pair: Option<f64> = None;
    let mut wall: Option<f64> = None;
    for s in slots {
        let Some(e) = e_of(s) else { return Ok(None) };
        let which = if matches!(s.who, Contact::Pair(_)) {
            &mut pair
        } else {
            &mut wall
        };
        match which {
            Some(prev) if (*prev - e).abs() > 1e-12 * e.max(*prev) => return Ok(None),
            _ => *which = Some(e),
        }
    }
    let mut track = setup.track();
    track.e = pair.unwrap_or(1.0);
    track.e_wall = wall.unwrap_or(track.e);
    let limits = track::Limits {
        until,
        max_collisions: 10_000_000,
    };
    let Ok(run) = track.run(limits, None) else {
        return Ok(None);
    };
    Ok(Some(ImpulseModel {
        e: track.e,
        e_wall: track.e_wall,
        v: run.v,
        collisions: run.collisions,
    }))
}

/// Where a contact is: the position of its body farther from the origin.
fn reach_of(who: Contact, x: &[f64]) -> f64 {
    let n = x.len();
    match who {
        Contact::LeftWall => x[0],
        Contact::Pair(i) if x[i].abs() >= x[i + 1].abs() => x[i],
        Contact::Pair(i) => x[i + 1],
        Contact::RightWall => x[n - 1],
    }
}

/// The first body a contact touches (the wall's body for a wall).
fn first_body(who: Contact, n: usize) -> usize {
    match who {
        Contact::LeftWall => 0,
        Contact::Pair(i) => i,
        Contact::RightWall => n - 1,
    }
}

/// How well a contact's overlap is known: the rounding bounds of its bodies' positions.
fn slack_of(who: Contact, slack: &[f64]) -> f64 {
    let n = slack.len();
    match who {
        Contact::LeftWall => slack[0],
        Contact::Pair(i) => slack[i] + slack[i + 1],
        Contact::RightWall => slack[n - 1],
    }
}

/// The origin moves to the centre of mass where the positions' spacing exceeds this fraction of
/// the contacts' overlap (positions of 1e3 and overlaps of 1e-3 stay as they are: 1e-13).
const RESOLUTION_SHIFT: f64 = 1e-10;

/// A contact whose bodies' positions are known more coarsely than this fraction of its overlap
/// is refused: its starting overlap would be rounding.
const RESOLUTION_REFUSE: f64 = 1e-3;

/// The rounding error of `s = a + b` (Knuth's TwoSum: `a + b = s + error` exactly).
fn sum_error(a: f64, b: f64, s: f64) -> f64 {
    let bb = s - a;
    (a - (s - bb)) + (b - bb)
}

/// The spacing of binary64 numbers at `t` (`t >= 0`).
fn ulp(t: f64) -> f64 {
    f64::from_bits(t.abs().to_bits() + 1) - t.abs()
}
