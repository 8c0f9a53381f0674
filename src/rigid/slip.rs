//! Friction at impact in space: the slip direction turns during the impact, so the contact
//! velocity is an ODE in the normal impulse `P_n` (Stronge, *Impact Mechanics*, ch. 5; Bhatt &
//! Koechling 1995). In the contact frame `(n, t1, t2)`, while the contact slips with direction
//! `s = w_t/|w_t|`:
//!
//! ```text
//! dw/dP_n = -K (1, mu s),   dW/dP_n = w_n (the normal work),   dP_t/dP_n = mu s
//! ```
//!
//! integrated with diffsol's Tsitouras 5(4) with events located on its dense output (bisection): the end of compression (`w_n = 0`), the law's end (Poisson `P_n = (1 + e) P_c`, Newton
//! `w_n = -e w_n0`, Stronge `W = (1 - e^2) W_c`) and stick (`|w_t|` down to `delta`, a hundred
//! times the tolerance times the speed, then closed linearly). After a stick the contact holds if
//! `|K_tt^-1 K_tn| <= mu` (`dP_t/dP_n = -K_tt^-1 K_tn`) or slips again in the one direction `s`
//! that the flow keeps, `-(K_tn + mu K_tt s) = lambda s`, `lambda > 0`: both phases have
//! constant rates. The error is estimated by a second run at a hundredth of the tolerance.

use super::laws::{Law, Mode};

// The ODE and its solver (diffsol) are the command line's: without the feature `cli` (the
// page's WebAssembly module) an impact that needs them is refused by name (`SlipError::NoOde`).
#[cfg(feature = "cli")]
mod ode;

/// An impact with friction in the contact frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slip {
    /// The collision matrix in `(n, t1, t2)`.
    pub k: [[f64; 3]; 3],
    /// The contact velocity before, `w_n > 0`.
    pub w0: [f64; 3],
    pub mu: f64,
    pub e: f64,
    pub law: Law,
}

/// One run's answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    /// `(P_n, P_t1, P_t2)`.
    pub impulse: [f64; 3],
    pub mode: Mode,
    /// `P_n` at the end of compression, and where the slip stopped.
    pub compression: f64,
    pub stick: Option<f64>,
    pub steps: u64,
    pub rhs_evals: u64,
}

/// The answer with its error estimate and cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimated {
    pub run: Run,
    pub rtol: f64,
    /// `|P(rtol) - P(rtol/100)| / |P|`: the error of the coarser run, an estimate of the finer
    /// one's (whose answer is `run`) but not a bound: it misses the rounding floor. Against
    /// Routh's exact answer (tests/suite/rigid_ode.rs, 300 planar cases) the error exceeded it
    /// in 193, and was always below `2 error + 1e-13`.
    pub error: f64,
    /// Wall time of both runs, in seconds.
    pub seconds: f64,
    /// Steps of both runs.
    pub steps: u64,
}

/// Why the integration failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SlipError {
    #[error("the ODE of the slip in the normal impulse failed: {0}")]
    Solver(String),
    #[error("the ODE of the slip took more than {0} steps (the impact does not end?)")]
    Steps(u64),
    #[error(
        "the tangential part of the collision matrix is singular: the contact cannot be held by \
         friction in a defined way (a body on a pivot whose lever is along the normal?)"
    )]
    Singular,
    #[error("the impact does not end: the normal velocity never reaches the law's end")]
    Endless,
    #[error(
        "friction in space needs the ODE of the slip in the normal impulse, which this build of \
         collide leaves out (the page's WebAssembly core): run it with collide solve"
    )]
    NoOde,
}

/// The default tolerance.
pub const DEFAULT_RTOL: f64 = 1e-10;

/// Without the feature `cli` there is no ODE solver: friction in space is refused by name.
#[cfg(not(feature = "cli"))]
impl Slip {
    /// Refuses: the ODE is the command line's (`SlipError::NoOde`).
    pub fn estimated(&self, _rtol: f64) -> Result<Estimated, SlipError> {
        Err(SlipError::NoOde)
    }
}
