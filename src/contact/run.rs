//! The event-driven integration shared by every method: exact free flight while no contact is
//! active, one integrator stretch per set of active contacts, and every opening and closing of a
//! contact found as a root of its gate (`Law::gate`) between two steps, never stepped over.
//!
//! A stretch asks its integrator for steps (`Ask::Step`) and for states inside the last step
//! (`Ask::At`: dense output for the adaptive methods, a partial step from the step's start for
//! the fixed ones). A gate that changes sign across a step is located by the Illinois variant of
//! regula falsi to a few ulps of time, on the side where the contact has already changed, and the
//! stretch ends there; the deepest overlap of each active contact is located the same way, as
//! the zero of the overlap rate.

use super::fixed::{Counts, Fixed};
use super::system::System;

/// What a stretch asks of its integrator.
pub enum Ask {
    /// Take the next step; answer the new time and state.
    Step,
    /// The state at this time, inside the last step.
    At(f64),
}

/// Why an integration cannot go on: the method failed or became unstable.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Failure {
    #[error("the state became infinite or NaN at t = {t}")]
    NotFinite { t: f64 },
    #[error(
        "the energy grew to {ratio:.3e} times its start at t = {t} (the method is unstable at this step size)"
    )]
    Blowup { t: f64, ratio: f64 },
    /// A step that does not move the time on: `t + h` rounds to `t`.
    #[error(
        "the step {h:e} no longer moves the time on at t = {t:e} (below its rounding); give a \
         larger --dt"
    )]
    Stalled { t: f64, h: f64 },
    #[error("Newton's iteration did not converge at t = {t}")]
    Newton { t: f64 },
    #[error("the solver failed at t = {t}: {why}")]
    Solver { t: f64, why: String },
    #[error(
        "more than {0} steps (raise --max-steps, or use a larger --dt / --tol or an implicit method)"
    )]
    Steps(u64),
    /// Slot `slot`'s overlap reached the depth where the centres meet (`Slot::reach`) at `t`,
    /// state `y`: a body went through another or through a wall.
    #[error("a body passed through another or a wall at t = {t}")]
    Through { t: f64, slot: usize, y: Vec<f64> },
}

impl Failure {
    /// The failure with its time moved by `origin` (a stretch runs in its own time, from 0).
    pub fn shifted(self, origin: f64) -> Failure {
        match self {
            Failure::NotFinite { t } => Failure::NotFinite { t: t + origin },
            Failure::Blowup { t, ratio } => Failure::Blowup {
                t: t + origin,
                ratio,
            },
            Failure::Stalled { t, h } => Failure::Stalled { t: t + origin, h },
            Failure::Newton { t } => Failure::Newton { t: t + origin },
            Failure::Solver { t, why } => Failure::Solver { t: t + origin, why },
            Failure::Steps(n) => Failure::Steps(n),
            Failure::Through { t, slot, y } => Failure::Through {
                t: t + origin,
                slot,
                y,
            },
        }
    }
}

/// Refuses a state in which any slot overlaps as deep as its reach (the centres met: a body
/// went through another or a wall). Checked at every accepted step and every located instant,
/// so a soft contact that lets the bodies through and back within one stretch is still caught.
fn in_order(sys: &System, t: f64, y: &[f64]) -> Result<(), Failure> {
    match (0..sys.slots.len()).find(|&s| sys.overlap(s, y).0 >= sys.slots[s].reach) {
        Some(slot) => Err(Failure::Through {
            t,
            slot,
            y: y.to_vec(),
        }),
        None => Ok(()),
    }
}

/// What a run keeps across its stretches: work, the step budget, the deepest overlap of each
/// slot, the energy above which a run has blown up, and (when asked) the history of forces.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ledger {
    pub counts: Counts,
    pub steps_left: u64,
    pub peaks: Vec<f64>,
    pub energy_cap: f64,
    /// `Some` to record `(t, slot, overlap, force)` of the active contacts after every step.
    pub trace: Option<Vec<Sample>>,
    /// The run's time at the start of the stretch, which steps in its own time from 0: the
    /// trace records `origin + t`.
    pub origin: f64,
}

/// One point of a contact's history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    pub t: f64,
    pub slot: usize,
    pub overlap: f64,
    pub force: f64,
}

/// Most samples kept; beyond it every other one is dropped (and only every second step kept).
const TRACE_CAP: usize = 100_000;

impl Ledger {
    fn record(&mut self, sys: &System, t: f64, y: &[f64]) {
        let Some(trace) = &mut self.trace else {
            return;
        };
        if trace.len() >= TRACE_CAP {
            let mut i = 0;
            trace.retain(|_| {
                i += 1;
                i % 2 == 0
            });
        }
        for s in (0..sys.slots.len()).filter(|&s| sys.active[s]) {
            let (d, rate) = sys.overlap(s, y);
            trace.push(Sample {
                t: self.origin + t,
                slot: s,
                overlap: d,
                force: sys.slots[s].law.force(d, rate),
            });
        }
    }
}

/// How a stretch ended: at an event of slot `event`, or at the stop time.
pub struct End {
    pub t: f64,
    pub y: Vec<f64>,
    pub event: Option<usize>,
}

/// Finds where `f` changes side between `a` (old side, value `fa`) and `b` (new side, `fb`):
/// Illinois regula falsi, ending on the new side within a few ulps of the crossing.
///
/// Where the false position falls on an end of the bracket (that end's value is zero, or too
/// small beside the other's to move it: the search has reached the crossing to rounding), it
/// steps off that end by half the tolerance, doubling the step while it stays on that end's
/// side (a run of values that round to zero), never past the middle. Halving the whole bracket
/// instead took 53 evaluations to close on the crossing of a line that the first one had found.
fn locate(
    f: &mut dyn FnMut(f64) -> Result<f64, Failure>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    new_side: &dyn Fn(f64) -> bool,
) -> Result<f64, Failure> {
    let mut last = 0i8;
    let mut reach = 0.5;
    for _ in 0..200 {
        let close = 4.0 * f64::EPSILON * a.abs().max(b.abs()) + f64::MIN_POSITIVE;
        if b - a <= close {
            break;
        }
        let mut c = b - fb * (b - a) / (fb - fa);
        if c > a && c < b {
            reach = 0.5;
        } else {
            let mid = 0.5 * (a + b);
            c = if c >= b {
                (b - reach * close).max(mid)
            } else if c <= a {
                (a + reach * close).min(mid)
            } else {
                // Not a number (0/0 or inf/inf): halve the bracket.
                mid
            };
            reach *= 2.0;
        }
        if c <= a || c >= b {
            break;
        }
        let fc = f(c)?;
        if new_side(fc) {
            b = c;
            fb = fc;
            if last == 1 {
                fa *= 0.5;
            }
            last = 1;
        } else {
            a = c;
            fa = fc;
            if last == -1 {
                fb *= 0.5;
            }
            last = -1;
        }
    }
    Ok(b)
}

/// Integrates one stretch (fixed set of active contacts) from `(t0, y0)` until a contact opens
/// or closes, or `t_stop`. Records the deepest overlap of each active slot in `peaks`.
pub fn segment(
    drive: &mut dyn FnMut(Ask) -> Result<(f64, Vec<f64>), Failure>,
    sys: &System,
    (t0, y0): (f64, &[f64]),
    t_stop: f64,
    ledger: &mut Ledger,
) -> Result<End, Failure> {
    let slots = sys.slots.len();
    let agrees = |s: usize, g: f64| (g > 0.0) == sys.active[s];
    let (mut ta, mut ya) = (t0, y0.to_vec());
    let mut ga: Vec<f64> = (0..slots).map(|s| sys.gate(s, &ya)).collect();
    // A slot on the wrong side at the start (a contact opened at an overlap of -0 by rounding,
    // or one whose end came at the same instant as another's) counts as just on its own side,
    // so that its next crossing (at once, for the second) is found.
    for (s, g) in ga.iter_mut().enumerate() {
        if !agrees(s, *g) {
            *g = if sys.active[s] {
                f64::MIN_POSITIVE
            } else {
                0.0
            };
        }
    }
    ledger.record(sys, ta, &ya);
    loop {
        if ta >= t_stop {
            return Ok(End {
                t: ta,
                y: ya,
                event: None,
            });
        }
        if ledger.steps_left == 0 {
            return Err(Failure::Steps(0));
        }
        ledger.steps_left -= 1;
        let (tb, yb) = drive(Ask::Step)?;
        if !tb.is_finite() || yb.iter().any(|q| !q.is_finite()) {
            return Err(Failure::NotFinite { t: tb });
        }
        let e = sys.energy(&yb);
        if e > ledger.energy_cap {
            return Err(Failure::Blowup {
                t: tb,
                ratio: e / (ledger.energy_cap / 2.0),
            });
        }
        in_order(sys, tb, &yb)?;
        let gb: Vec<f64> = (0..slots).map(|s| sys.gate(s, &yb)).collect();
        let mut first: Option<(f64, usize)> = None;
        for s in 0..slots {
            if agrees(s, ga[s]) && !agrees(s, gb[s]) {
                let mut f = |t: f64| -> Result<f64, Failure> {
                    let (_, y) = drive(Ask::At(t))?;
                    Ok(sys.gate(s, &y))
                };
                let t = locate(&mut f, (ta, ga[s]), (tb, gb[s]), &|g| !agrees(s, g))?;
                if first.is_none_or(|(t0, _)| t < t0) {
                    first = Some((t, s));
                }
            }
        }
        let t_end = first.map_or(tb, |(t, _)| t);
        for s in (0..slots).filter(|&s| sys.active[s]) {
            let (_, ra) = sys.overlap(s, &ya);
            let (_, rb) = sys.overlap(s, &yb);
            if ra > 0.0 && rb <= 0.0 {
                let mut f = |t: f64| -> Result<f64, Failure> {
                    let (_, y) = drive(Ask::At(t))?;
                    Ok(sys.overlap(s, &y).1)
                };
                let tp = locate(&mut f, (ta, ra), (tb, rb), &|r| r <= 0.0)?;
                if tp <= t_end {
                    let (_, y) = drive(Ask::At(tp))?;
                    in_order(sys, tp, &y)?;
                    ledger.peaks[s] = ledger.peaks[s].max(sys.overlap(s, &y).0);
                }
            }
        }
        if let Some((t, s)) = first {
            let (_, y) = drive(Ask::At(t))?;
            in_order(sys, t, &y)?;
            for p in (0..slots).filter(|&p| sys.active[p]) {
                ledger.peaks[p] = ledger.peaks[p].max(sys.overlap(p, &y).0);
            }
            ledger.record(sys, t, &y);
            return Ok(End {
                t,
                y,
                event: Some(s),
            });
        }
        for p in (0..slots).filter(|&p| sys.active[p]) {
            ledger.peaks[p] = ledger.peaks[p].max(sys.overlap(p, &yb).0);
        }
        ledger.record(sys, tb, &yb);
        (ta, ya, ga) = (tb, yb, gb);
    }
}

/// Integrates one stretch with a fixed-step method of step `h` (the last step is cut to land
/// on `t_stop`; events cut a step, and the next stretch starts a fresh grid there).
pub fn fixed_stretch(
    (method, h): (Fixed, f64),
    sys: &System,
    (t0, y0): (f64, &[f64]),
    t_stop: f64,
    ledger: &mut Ledger,
) -> Result<End, Failure> {
    let mut counts = ledger.counts;
    let (mut t_prev, mut y_prev) = (t0, y0.to_vec());
    let (mut t, mut y) = (t0, y0.to_vec());
    let mut out = vec![0.0; y0.len()];
    let mut drive = |ask: Ask| -> Result<(f64, Vec<f64>), Failure> {
        match ask {
            Ask::Step => {
                t_prev = t;
                y_prev.copy_from_slice(&y);
                let (step, next) = if t_stop - t <= h {
                    (t_stop - t, t_stop)
                } else {
                    (h, t + h)
                };
                // A step lost in the time's rounding would repeat for ever (each one ending the
                // stretch at the same instant), so it is an error.
                if next <= t {
                    return Err(Failure::Stalled { t, h });
                }
                method
                    .step(sys, &y_prev, step, &mut y, &mut counts)
                    .map_err(|_| Failure::Newton { t })?;
                t = next;
                Ok((t, y.clone()))
            }
            Ask::At(at) => {
                let mut scratch = Counts::default();
                method
                    .step(sys, &y_prev, at - t_prev, &mut out, &mut scratch)
                    .map_err(|_| Failure::Newton { t: at })?;
                counts.rhs_evals += scratch.rhs_evals;
                counts.jacobians += scratch.jacobians;
                Ok((at, out.clone()))
            }
        }
    };
    let end = segment(&mut drive, sys, (t0, y0), t_stop, ledger);
    ledger.counts = counts;
    end
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The event search is Illinois regula falsi: superlinear, so a smooth crossing is found to
    /// a few ulps in a handful of evaluations where bisection needs about 50. `t^2 - 2` on [1, 2]
    /// (convex: plain regula falsi would keep one end and crawl): sqrt 2, within 4 ulps, on the
    /// new side (`f >= 0`), in at most 12 evaluations; and the same from the other side
    /// (`2 - t^2`, the old side positive).
    #[test]
    fn the_event_search_is_superlinear_and_ends_on_the_new_side() {
        for sign in [1.0, -1.0] {
            let mut calls = 0;
            let mut f = |t: f64| -> Result<f64, Failure> {
                calls += 1;
                Ok(sign * (t * t - 2.0))
            };
            let new_side = |v: f64| sign * v >= 0.0;
            let (a, b) = (1.0, 2.0);
            let root = locate(&mut f, (a, -sign), (b, sign * 2.0), &new_side).unwrap();
            let exact = std::f64::consts::SQRT_2;
            assert!((root - exact).abs() <= 4.0 * f64::EPSILON * exact, "{root}");
            assert!(
                root * root - 2.0 >= 0.0 || root >= exact,
                "{root} is on the old side"
            );
            assert!(calls <= 12, "{calls} evaluations");
        }
    }

    /// Two free bodies (masses 1 and 2, no contact slots) and a state of theirs.
    fn free_pair() -> (System, [f64; 4]) {
        let sys = System {
            m: vec![1.0, 2.0],
            slots: Vec::new(),
            active: Vec::new(),
            d0: Vec::new(),
        };
        (sys, [0.0, 5.0, 3.0, -1.0])
    }

    /// A fixed step lost in the time's rounding (`1e20 + 1e-3 = 1e20`) stops the stretch with
    /// `Stalled` at once (it used to repeat until the step budget was spent); one that moves
    /// the time on from the same state runs to the stop time in its count of steps.
    #[test]
    fn a_step_below_the_time_rounding_stalls() {
        let (sys, y0) = free_pair();
        let ledger = || Ledger {
            steps_left: 1000,
            energy_cap: f64::INFINITY,
            ..Ledger::default()
        };
        let mut l = ledger();
        let end = fixed_stretch((Fixed::Rk4, 1e-3), &sys, (1e20, &y0), 2e20, &mut l);
        assert!(matches!(end, Err(Failure::Stalled { t, h }) if t == 1e20 && h == 1e-3));
        assert_eq!(l.counts.steps, 0);
        let mut l = ledger();
        let end = fixed_stretch((Fixed::Rk4, 0.25), &sys, (1.0, &y0), 2.0, &mut l);
        assert!(matches!(end, Ok(End { t: 2.0, .. })));
        assert_eq!(l.counts.steps, 4);
    }

    /// A step that gives a time or a state not finite stops the stretch with `NotFinite` at
    /// that time, whichever of the two it is (either alone is enough), before any other check
    /// reads the state; a finite step goes on.
    #[test]
    fn a_state_or_time_not_finite_stops_the_stretch() {
        let (sys, y0) = free_pair();
        for (t, y, bad) in [
            (0.5, [0.0, f64::NAN, 3.0, -1.0], true),
            (0.5, [0.0, 5.0, f64::INFINITY, -1.0], true),
            (f64::NAN, y0, true),
            (f64::INFINITY, y0, true),
            (0.5, y0, false),
        ] {
            let mut ledger = Ledger {
                steps_left: 10,
                energy_cap: f64::INFINITY,
                ..Ledger::default()
            };
            let mut drive = |_: Ask| -> Result<(f64, Vec<f64>), Failure> { Ok((t, y.to_vec())) };
            let end = segment(&mut drive, &sys, (0.0, &y0), 1.0, &mut ledger);
            match end {
                Err(Failure::NotFinite { t: at }) => {
                    assert!(bad, "{t} {y:?} stopped");
                    assert!(at.to_bits() == t.to_bits(), "at {at}, not {t}");
                }
                // The finite step repeats (the stub never reaches t = 1): the step budget.
                Err(Failure::Steps(0)) => assert!(!bad, "{t} {y:?} went on"),
                Err(other) => panic!("{t} {y:?}: {other}"),
                Ok(_) => panic!("{t} {y:?}: ended"),
            }
        }
    }

    /// A bracket narrower than the smallest normal number (where a relative tolerance of the
    /// ends is zero) is closed as it is: no evaluation, its new end returned.
    #[test]
    fn a_bracket_below_the_smallest_normal_is_already_closed() {
        let mut calls = 0;
        let mut f = |t: f64| -> Result<f64, Failure> {
            calls += 1;
            Ok(t - 1e-310)
        };
        let t = locate(&mut f, (0.0, -1e-310), (2e-310, 1e-310), &|v| v >= 0.0).unwrap();
        assert_eq!((t, calls), (2e-310, 0));
    }

    /// The search's points, to 4 ulps: regula falsi's on `t^2 - 2` from [1, 2], with Illinois's
    /// halving of the end kept twice. In exact rationals (`f` at each point in brackets):
    /// 4/3 [-2/9] and 7/5 [-1/25] keep b twice, so b's value 2 is halved to 1 for the third,
    /// 37/26 [17/676], which moves b; the fourth uses a's value unhalved (a was kept once):
    /// 519/367 [< 0]; then 38287/27073.
    #[test]
    fn the_event_search_takes_the_illinois_points() {
        let mut points = Vec::new();
        let mut f = |t: f64| -> Result<f64, Failure> {
            points.push(t);
            Ok(t * t - 2.0)
        };
        locate(&mut f, (1.0, -1.0), (2.0, 2.0), &|v| v >= 0.0).unwrap();
        let exact = [
            4.0 / 3.0,
            1.4,
            37.0 / 26.0,
            519.0 / 367.0,
            38287.0 / 27073.0,
        ];
        for (k, (got, want)) in points.iter().zip(exact).enumerate() {
            assert!(
                (got - want).abs() <= 4.0 * f64::EPSILON * want,
                "point {}: {got}, not {want}",
                k + 1
            );
        }
        // Mirrored (t -> 3 - t: `(3 - t)^2 - 2` from 2 on the old side at 1 to -1 on the new
        // side at 2), the first two points fall on the new side, so it is a's value that is
        // halved: the points are 3 less the ones above, 5/3, 8/5, 41/26, 582/367,
        // 42932/27073. (Above, a's end is never kept twice.)
        points.clear();
        let mut g = |t: f64| -> Result<f64, Failure> {
            points.push(t);
            Ok((3.0 - t) * (3.0 - t) - 2.0)
        };
        locate(&mut g, (1.0, 2.0), (2.0, -1.0), &|v| v <= 0.0).unwrap();
        let exact = [
            5.0 / 3.0,
            1.6,
            41.0 / 26.0,
            582.0 / 367.0,
            42932.0 / 27073.0,
        ];
        for (k, (got, want)) in points.iter().zip(exact).enumerate() {
            assert!(
                (got - want).abs() <= 4.0 * f64::EPSILON * want,
                "mirrored point {}: {got}, not {want}",
                k + 1
            );
        }
    }

    /// Where the false position lands on an end (the crossing found to rounding), the search
    /// steps off that end rather than halving the bracket: a line's crossing, found by the
    /// first point, in at most 3 evaluations (that point, one step of the tolerance, and one
    /// spare), from either side (`t - 0.3` and `0.3 - t`: the value at the crossing rounds to
    /// zero, which is the new side); `-cos t` on [0, 3] (the fifth point is pi/2 to rounding,
    /// on the old side with a value of 6e-17, too small to move the next false position off
    /// it) in at most 7. Halving took 53 and 25.
    #[test]
    fn the_event_search_steps_off_a_crossing_it_has_found() {
        // The function, its bracket, its crossing and the most evaluations allowed.
        type Case = (fn(f64) -> f64, f64, f64, f64, usize);
        let cases: [Case; 3] = [
            (|t| t - 0.3, 0.0, 1.0, 0.3, 3),
            (|t| 0.3 - t, 0.0, 1.0, 0.3, 3),
            (|t| -t.cos(), 0.0, 3.0, std::f64::consts::FRAC_PI_2, 7),
        ];
        for (g, a, b, root, most) in cases {
            let mut calls = 0;
            let mut f = |t: f64| -> Result<f64, Failure> {
                calls += 1;
                Ok(g(t))
            };
            let sign = g(b).signum();
            let new_side = |v: f64| sign * v >= 0.0;
            let t = locate(&mut f, (a, g(a)), (b, g(b)), &new_side).unwrap();
            assert!((t - root).abs() <= 4.0 * f64::EPSILON * root, "{t}");
            assert!(new_side(g(t)), "{t} is on the old side");
            assert!(calls <= most, "{calls} evaluations for {root}");
        }
    }

    /// A run of points whose values round to zero (here exactly zero from 0.3 to 0.3 + 1e-9,
    /// millions of half-tolerances, 1.3e-16, wide): the steps off the end double until one
    /// leaves the run, and the bracket then halves back to its first point, 0.3: about
    /// 2 log2(1e-9 / 1.3e-16) = 46 evaluations; at most 50 (fixed steps would need millions and
    /// stop at the 200-point cap short of it).
    #[test]
    fn the_event_search_crosses_a_run_of_zeros_by_doubling() {
        let g = |t: f64| {
            if t < 0.3 {
                t - 0.3
            } else if t > 0.3 + 1e-9 {
                t - (0.3 + 1e-9)
            } else {
                0.0
            }
        };
        let mut calls = 0;
        let mut f = |t: f64| -> Result<f64, Failure> {
            calls += 1;
            Ok(g(t))
        };
        let t = locate(&mut f, (0.0, g(0.0)), (1.0, g(1.0)), &|v| v >= 0.0).unwrap();
        assert!(t >= 0.3 && t - 0.3 <= 4.0 * f64::EPSILON * 0.3, "{t}");
        assert!(calls <= 50, "{calls} evaluations");
    }
}
