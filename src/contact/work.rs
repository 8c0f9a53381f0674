//! Error against run time (`collide contact --work-precision`): each method on a ladder of
//! tolerances (adaptive) or steps (fixed), each run timed (the fastest of several after a
//! warm-up) and its final velocities compared with a reference: the exact answer where there is
//! one (a single possible contact, linear or elastic Hertz: the impulse form with the closed-form
//! restitution), else two independent runs at tolerance 1e-13 (tsit45 and sdirk), whose
//! difference is reported as the reference's own uncertainty.
//!
//! Error = the largest difference of a final velocity from the reference, over the largest
//! initial relative speed. A run that fails, blows up, gains energy or steps past its stability
//! limit is a row marked `unstable`, never a crash.

use std::time::{Duration, Instant};

use serde::Serialize;

use super::{
    ContactError, ContactRun, DEFAULT_MAX_STEPS, Law, Method, Scales, Settings, Setup, closed,
    simulate,
};
use crate::track::Contact;

/// What the errors are measured against.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Reference {
    /// "exact" or "run".
    pub kind: &'static str,
    /// For a run reference: the methods and tolerance.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub methods: Option<[&'static str; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tol: Option<f64>,
    pub v: Vec<f64>,
    /// For a run reference: the two runs' largest difference, relative like the errors.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<f64>,
}

/// One run of the ladder.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    pub method: &'static str,
    /// "explicit" or "implicit".
    pub kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tol: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// `None` when unstable.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<f64>,
    /// Fastest wall time of the run, in nanoseconds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ns: Option<f64>,
    pub rhs_evals: u64,
    pub steps: u64,
    pub unstable: bool,
    /// Why a row is unstable.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
}

/// The diagram's data.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Work {
    pub reference: Reference,
    /// Fastest over slowest contact frequency at the initial relative speed.
    pub stiffness_ratio: f64,
    pub rows: Vec<Row>,
}

/// Adaptive tolerances tried.
pub const TOLS: [f64; 10] = [
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
];

/// Most steps a fixed-step rung may take; the ladder stops before it.
pub const LADDER_STEPS: f64 = 1e6;

/// A method's ladder stops after a rung that took longer than this, or reached this error.
pub const RUNG_SECONDS: f64 = 1.0;
pub const ENOUGH: f64 = 1e-11;

/// The exact final velocities where a single contact can happen, with a law whose restitution
/// is known in closed form (linear, or elastic Hertz: e = 1).
pub fn exact(setup: &Setup) -> Result<Option<Vec<f64>>, ContactError> {
    let slots = setup.slots()?;
    let [slot] = slots.as_slice() else {
        return Ok(None);
    };
    let e = match slot.law {
        Law::Linear { k, c } => closed::Linear::new(k, c, slot.mu).restitution(),
        Law::Hertz { chi: 0.0, .. } => 1.0,
        Law::Hertz { .. } => return Ok(None),
    };
    let v: Vec<f64> = setup.bodies.iter().map(|b| b.v).collect();
    Ok(Some(match slot.who {
        Contact::Pair(_) => {
            let (m1, m2) = (setup.bodies[0].m.value(), setup.bodies[1].m.value());
            let u = v[0] - v[1];
            if u <= 0.0 {
                v
            } else {
                // Impulse form: J = (1 + e) mu u.
                let j = (1.0 + e) * slot.mu * u;
                vec![v[0] - j / m1, v[1] + j / m2]
            }
        }
        Contact::LeftWall if v[0] < 0.0 => vec![-e * v[0]],
        Contact::RightWall if v[0] > 0.0 => vec![-e * v[0]],
        _ => v,
    }))
}

/// The largest difference from the reference over `speed`; NaN if any difference is (`f64::max`
/// would drop it and report 0 against a NaN reference).
fn error(v: &[f64], reference: &[f64], speed: f64) -> f64 {
    v.iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        // Once NaN, NaN: `f64::max` of a NaN and a number is the number.
        .fold(0.0, |m: f64, d| {
            if m.is_nan() || d.is_nan() {
                f64::NAN
            } else {
                m.max(d)
            }
        })
        / speed
}

/// Runs `f` once, then again while the total stays under a budget (at most 10 times), and gives
/// the result with the fastest time.
fn timed<T>(mut f: impl FnMut() -> T) -> (T, Duration) {
    let start = Instant::now();
    let out = f();
    let mut best = start.elapsed();
    let budget = Duration::from_millis(150);
    let mut spent = best;
    for _ in 0..10 {
        if spent + best > budget {
            break;
        }
        let t = Instant::now();
        let _ = f();
        let d = t.elapsed();
        spent += d;
        best = best.min(d);
    }
    (out, best)
}

/// The work-precision ladder for `methods` on `setup` (stopping at `until`, if given).
pub fn work_precision(
    setup: &Setup,
    methods: &[Method],
    until: Option<f64>,
) -> Result<Work, ContactError> {
    let slots = setup.slots()?;
    let scales = Scales::of(setup, &slots);
    let speed = if scales.speed > 0.0 {
        scales.speed
    } else {
        1.0
    };
    let settings = |method: Method, dt: Option<f64>, tol: Option<f64>| Settings {
        method: Some(method),
        dt,
        tol,
        until,
        max_steps: DEFAULT_MAX_STEPS,
        trace: false,
    };
    let reference = match (until, exact(setup)?) {
        (None, Some(v)) => Reference {
            kind: "exact",
            methods: None,
            tol: None,
            v,
            uncertainty: None,
        },
        _ => {
            let tsit = Method::Adaptive(super::Adaptive::Tsit45);
            let sdirk = Method::Adaptive(super::Adaptive::Sdirk);
            let a = simulate(setup, &settings(tsit, None, Some(1e-13)))?;
            let b = simulate(setup, &settings(sdirk, None, Some(1e-13)))?;
            Reference {
                kind: "run",
                methods: Some([tsit.name(), sdirk.name()]),
                tol: Some(1e-13),
                uncertainty: Some(error(&a.v, &b.v, speed)),
                v: a.v,
            }
        }
    };
    if let Some(v) = reference.v.iter().find(|v| !v.is_finite()) {
        return Err(ContactError::Reference(*v));
    }
    let horizon = simulate(
        setup,
        &Settings {
            method: None,
            ..settings(Method::Adaptive(super::Adaptive::Bdf), None, None)
        },
    )?
    .time;
    let mut rows = Vec::new();
    for &method in methods {
        let rungs: Vec<(Option<f64>, Option<f64>)> = match method {
            Method::Fixed(_) => (0..40)
                .map(|k| scales.t_max / 8.0 * 0.5f64.powi(k))
                .take_while(|dt| horizon / dt <= LADDER_STEPS)
                .map(|dt| (Some(dt), None))
                .collect(),
            Method::Adaptive(_) => TOLS.iter().map(|t| (None, Some(*t))).collect(),
        };
        for (dt, tol) in rungs {
            let (result, time) = timed(|| simulate(setup, &settings(method, dt, tol)));
            let row = |run: Option<&ContactRun>, why: Option<String>| Row {
                method: method.name(),
                kind: if method.implicit() {
                    "implicit"
                } else {
                    "explicit"
                },
                tol,
                dt,
                error: run.map(|r| error(&r.v, &reference.v, speed)),
                ns: run.map(|_| time.as_nanos() as f64),
                rhs_evals: run.map_or(0, |r| r.stats.rhs_evals),
                steps: run.map_or(0, |r| r.stats.steps),
                unstable: run.is_none(),
                why,
            };
            match result {
                Ok(run) => {
                    let r = row(Some(&run), None);
                    let done =
                        r.error.is_some_and(|e| e < ENOUGH) || time.as_secs_f64() > RUNG_SECONDS;
                    rows.push(r);
                    if done {
                        break;
                    }
                }
                Err(
                    e @ (ContactError::Unstable { .. }
                    | ContactError::Failed { .. }
                    | ContactError::EnergyGain { .. }
                    | ContactError::Through { .. }),
                ) => rows.push(row(None, Some(e.to_string()))),
                Err(e) => return Err(e),
            }
        }
    }
    Ok(Work {
        reference,
        stiffness_ratio: scales.stiffness_ratio(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The error of a run is its largest velocity difference from the reference over the speed
    /// scale (a relative error): |3 - 1| / 4 = 1/2; a NaN difference is NaN, never dropped (it
    /// was when a number followed it: `f64::max(NaN, x)` is x).
    #[test]
    fn the_error_is_relative_to_the_speed_and_keeps_a_nan() {
        assert_eq!(error(&[3.0, 1.0], &[1.0, 1.0], 4.0), 0.5);
        assert_eq!(error(&[1.0, -5.0], &[1.0, 1.0], 3.0), 2.0);
        assert!(error(&[f64::NAN, 1.0], &[1.0, 1.0], 2.0).is_nan());
        assert!(error(&[1.0, 1.0], &[f64::NAN, 9.0], 2.0).is_nan());
    }
}
