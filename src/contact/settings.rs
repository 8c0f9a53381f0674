//! How a run is integrated: the method (fixed-step or adaptive), its step or tolerance, when to
//! stop, and the defaults `auto` starts from.

use super::adaptive::Adaptive;
use super::fixed::Fixed;

/// A method, as asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Fixed(Fixed),
    Adaptive(Adaptive),
}

impl Method {
    pub const ALL: [Method; 8] = [
        Method::Fixed(Fixed::SymplecticEuler),
        Method::Fixed(Fixed::Verlet),
        Method::Fixed(Fixed::Rk4),
        Method::Fixed(Fixed::ImplicitEuler),
        Method::Fixed(Fixed::ImplicitMidpoint),
        Method::Adaptive(Adaptive::Tsit45),
        Method::Adaptive(Adaptive::Bdf),
        Method::Adaptive(Adaptive::Sdirk),
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Fixed(Fixed::SymplecticEuler) => "symplectic-euler",
            Method::Fixed(Fixed::Verlet) => "verlet",
            Method::Fixed(Fixed::Rk4) => "rk4",
            Method::Fixed(Fixed::ImplicitEuler) => "implicit-euler",
            Method::Fixed(Fixed::ImplicitMidpoint) => "implicit-midpoint",
            Method::Adaptive(Adaptive::Tsit45) => "tsit45",
            Method::Adaptive(Adaptive::Bdf) => "bdf",
            Method::Adaptive(Adaptive::Sdirk) => "sdirk",
        }
    }

    pub fn parse(s: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == s)
    }

    pub fn implicit(self) -> bool {
        matches!(
            self,
            Method::Fixed(Fixed::ImplicitEuler | Fixed::ImplicitMidpoint)
                | Method::Adaptive(Adaptive::Bdf | Adaptive::Sdirk)
        )
    }
}

/// How to integrate: a method with its step or tolerance, when to stop, a cap on steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// `None`: `auto`.
    pub method: Option<Method>,
    pub dt: Option<f64>,
    pub tol: Option<f64>,
    pub until: Option<f64>,
    pub max_steps: u64,
    /// Record the history of every contact (for `--plot`).
    pub trace: bool,
}

/// Default cap on steps (`--max-steps`).
pub const DEFAULT_MAX_STEPS: u64 = 20_000_000;

/// The default tolerance of the adaptive methods: final velocities within 1e-8 of the initial
/// relative speed over a run of a few dozen contacts (`tests/suite/contact.rs`).
pub const AUTO_TOL: f64 = 1e-10;

/// The default tolerance where a law is Hertzian: its force grows like d^(3/2) from the
/// contact's start, a kink the error estimates see poorly (about 1e-8 of the energy per contact
/// at 1e-10, 1e-10 at 1e-12, measured).
pub const AUTO_TOL_HERTZ: f64 = 1e-12;

/// Stiffness ratio (fastest over slowest contact frequency) above which `auto` picks an implicit
/// method.
pub const STIFF_RATIO: f64 = 100.0;
