//! Why a contact run cannot be made or stopped half-way: every refusal names the value and what
//! to give instead.

use super::run::Failure;
use crate::track;
use crate::values::number::num;

/// Why a contact run cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ContactError {
    #[error(transparent)]
    Track(#[from] track::TrackError),
    #[error("{which}stiffness {} must be a finite number > 0", num(*.k))]
    Stiffness { which: &'static str, k: f64 },
    #[error("{which}damping {} must be a finite number >= 0", num(*.value))]
    Damping { which: &'static str, value: f64 },
    #[error(
        "{which}restitution {} cannot be reached by a linear contact: give a value in (0, 1] \
         (e = 0, sticking, would need infinite damping)", num(*.e)
    )]
    Restitution { which: &'static str, e: f64 },
    #[error("{which}{kind} contacts take no --zeta or -e: {why}")]
    NotForLaw {
        which: &'static str,
        kind: &'static str,
        why: &'static str,
    },
    #[error(
        "the shortest contact lasts {0:e}, too short to integrate (below 1e-100): rescale the \
         units (masses, stiffness) so that contact times are nearer 1"
    )]
    TooShort(f64),
    #[error(
        "the shortest contact lasts {:.3e}, too short to integrate (below 1e-100): its damping \
         (zeta = {:.3e}{}) ends it that fast; {}",
        .t, .zeta, restitution_note(*.e), damping_way_out(*.e_min, *.zeta_max)
    )]
    TooDamped {
        t: f64,
        zeta: f64,
        /// The contact's restitution, when it is not too small to compute.
        e: f64,
        /// The least restitution (and the most damping) whose contact lasts 1e-100.
        e_min: f64,
        zeta_max: f64,
    },
    #[error(
        "the reference final velocities are not finite ({}): no error can be measured against \
         them",
        num(*.0)
    )]
    Reference(f64),
    #[error(
        "walls on both sides: the bodies bounce between them for ever, so the run never ends by \
         itself; give --until T (until = T in a scene) for the state at time T"
    )]
    Forever,
    #[error(
        "{who} at t = {}: {positions} (an overlap of {} where {} means the centres met); the \
         result is not printed: the contact is too soft for this speed and these sizes. Use a \
         stiffer law ({flag}, now {}), a smaller speed or larger --sizes",
        num(*.t), num(*.overlap), num(*.reach), num(*.k)
    )]
    Through {
        /// "bodies 1 and 2 passed through each other", "body 1 passed through the right wall".
        who: String,
        t: f64,
        /// "x1 = 1.6, x2 = 1.5" or "x1 = 0.6 with the wall at 0.5", in the lab frame.
        positions: String,
        overlap: f64,
        reach: f64,
        /// The flag of the law that let them through, and its stiffness.
        flag: &'static str,
        k: f64,
    },
    #[error(
        "body {0} has size 0: contact forces act while bodies overlap, and a point overlaps \
         another only by passing through it; give --sizes (sizes = [...] in a scene)"
    )]
    PointBody(usize),
    #[error("--dt {} must be a finite number > 0", num(*.0))]
    Dt(f64),
    #[error(
        "--dt {} is too small: the shortest contact (lasting about {}) would take {} steps, \
         more than --max-steps {max_steps}; give --dt {} or more, or raise --max-steps",
        num(*.dt), num(*.t), step_count(.t / .dt), num(.t / *.max_steps as f64)
    )]
    DtTooSmall {
        dt: f64,
        /// The time a run must step through: the shortest contact, or --until when sooner.
        t: f64,
        max_steps: u64,
    },
    #[error("--tol {} must be a number in [1e-14, 0.1]", num(*.0))]
    Tol(f64),
    #[error(
        "--dt is for the fixed-step methods and --tol for the adaptive ones; {0} takes the other"
    )]
    WrongStep(&'static str),
    #[error(
        "{method} with --dt {} is unstable on the stiffest contact ({who}: omega dt = {}, not \
         below {limit:.3}); use --dt below {safe:.3e} or an implicit method (implicit-euler, \
         implicit-midpoint, bdf, sdirk)",
        num(*.dt),
        three(*.wh)
    )]
    Unstable {
        method: &'static str,
        dt: f64,
        who: String,
        wh: f64,
        limit: f64,
        safe: f64,
    },
    #[error(
        "contact {who} begins at x = {} with its bodies' positions known only to +-{:.3e} \
         (binary64's rounding of the positions and of the free flight before it), too coarse \
         for an overlap of about {:.3e}: measure the positions from a nearer origin, or start \
         the bodies nearer each other (only differences matter)",
        num(*.at),
        .slack,
        .overlap
    )]
    Resolution {
        who: String,
        at: f64,
        slack: f64,
        overlap: f64,
    },
    #[error("{method} failed: {failure}")]
    Failed {
        method: &'static str,
        failure: Failure,
    },
    #[error(
        "{method} gained energy: {end} at the end against {start} at the start ({gain:.3e} \
         relative) though no contact law can create any; the result is not printed (use a \
         smaller --dt or --tol)"
    )]
    EnergyGain {
        method: &'static str,
        start: f64,
        end: f64,
        gain: f64,
    },
}

/// ", e = 1e-300" beside a damping ratio, when the restitution is above 0 in binary64.
fn restitution_note(e: f64) -> String {
    if e > 0.0 {
        format!(", restitution e = {e:.3e}")
    } else {
        String::new()
    }
}

/// What to give instead of a damping so heavy that the contact is too short to integrate.
fn damping_way_out(e_min: f64, zeta_max: f64) -> String {
    let bound = if e_min > 0.0 {
        format!(" (e >= {e_min:.3e} here, zeta <= {zeta_max:.3e})")
    } else {
        format!(" (zeta <= {zeta_max:.3e} here)")
    };
    format!(
        "give less damping or a larger restitution{bound}; for bodies that stick (e = 0), use \
         collide track -e 0"
    )
}

/// `x` to three decimals, or in scientific notation when large.
fn three(x: f64) -> String {
    if x < 1e6 {
        format!("{x:.3}")
    } else {
        format!("{x:.3e}")
    }
}

/// A number of steps, to 4 digits; past binary64's range, "more than 1.797e308".
fn step_count(steps: f64) -> String {
    if steps.is_finite() {
        format!("{steps:.3e}")
    } else {
        format!("more than {:.3e}", f64::MAX)
    }
}
