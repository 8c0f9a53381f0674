//! Why an unknown of a rigid problem (`unknowns`) cannot be solved for: each reason named, with
//! what would fix it.

/// Why the unknown cannot be solved for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum UnknownError {
    #[error(
        "{0} '{1}': '?' stands for a whole value or a size along a direction ('? @ -30deg', \
         '? kg'), not for a component"
    )]
    Where(&'static str, String),
    #[error(
        "{count} unknowns ({names}) and {knowns} given final value{}: give {more} more known \
         value{} (a rigid impact solves one unknown from one final value)",
        if *.knowns == 1 { "" } else { "s" },
        if *.more == 1 { "" } else { "s" }
    )]
    TooMany {
        count: usize,
        names: String,
        knowns: usize,
        more: usize,
    },
    #[error(
        "{0} = ?: nothing fixes it: give 1 more known value, a final velocity (--fin 'F1,F2'), \
         a final spin (--fin-spin 'W1,W2') or --pivot-impulse 0"
    )]
    NoKnown(String),
    #[error("--pivot-impulse 0 needs a pivoted target (--pivot end, centre or '(x,y)')")]
    NoPivot,
    #[error("--fin-spin: body {0} is a {1} and has no spin of its own: give the target's")]
    NoSpin(usize, &'static str),
    #[error(
        "{0} ?: with friction (--friction MU) the impact is piecewise (Routh's phases): only mu \
         can be the unknown; drop --friction, or give {0}"
    )]
    WithFriction(String),
    #[error(
        "--hit-at ? on a smooth {0} {1}: the contact's normal passes through its centre, so the \
         impulse has no moment about it and the spins and the pivot's impulse are the same for \
         every height b: b is not determined (a pivot off the centre, '(x,y)', or --join fixes \
         it)"
    )]
    Round(&'static str, &'static str),
    #[error("{0} ?: {1}")]
    Impossible(String, String),
    #[error("no value fits: {0}")]
    None(String),
    #[error("more than one value fits: {0}; give another known to choose")]
    Many(String),
    #[error(
        "--exact: {0} = {1} is irrational (a root of a quadratic), and exact arithmetic holds \
         rationals only: drop --exact"
    )]
    Irrational(String, String),
    #[error("{0}")]
    Pose(String),
}
