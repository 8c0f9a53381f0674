//! The adaptive methods, from diffsol 0.18 (M. Robinson et al., <https://github.com/martinjrobins/diffsol>):
//! `tsit45` (Tsitouras 5(4), explicit), `bdf` (variable-order BDF/NDF after MATLAB's ode15s and
//! SciPy) and `sdirk` (ESDIRK3(4) of Kennedy & Carpenter, L-stable), each with error control on
//! `rtol` and a per-component `atol`, and dense output that the event search reads between steps.
//! The Jacobian is given exactly (`System::jac_mul`).

use std::cell::Cell;

use diffsol::{NalgebraLU, NalgebraMat, OdeBuilder, OdeSolverMethod, OdeSolverStopReason, Vector};

use super::run::{Ask, End, Failure, Ledger, segment};
use super::system::System;

type M = NalgebraMat<f64>;
type LS = NalgebraLU<f64>;

/// An adaptive method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Adaptive {
    Tsit45,
    Bdf,
    Sdirk,
}

/// How a stretch is integrated adaptively.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    pub rtol: f64,
    /// Absolute tolerance for displacements and for velocities.
    pub atol_u: f64,
    pub atol_v: f64,
    /// First step to try.
    pub h0: f64,
}

/// Integrates one stretch from `(t0, y0)` with `method` until an event or `t_stop`.
pub fn stretch(
    (method, tol): (Adaptive, Tolerances),
    sys: &System,
    (t0, y0): (f64, &[f64]),
    t_stop: f64,
    ledger: &mut Ledger,
) -> Result<End, Failure> {
    let n = sys.n();
    // A stop within the solver's rounding of the start (diffsol refuses a stop time within
    // 100 ulps of `|t| + |h|`: `--until 1e-300`): nothing measurable happens before it, and the
    // state there is the start's, each body carried on at its velocity.
    if t_stop > t0 && t_stop - t0 <= 200.0 * f64::EPSILON * (t0.abs() + tol.h0) {
        let dt = t_stop - t0;
        let mut y = y0.to_vec();
        for i in 0..n {
            y[i] += y0[n + i] * dt;
        }
        return Ok(End {
            t: t_stop,
            y,
            event: None,
        });
    }
    let rhs_evals = Cell::new(0u64);
    let atol: Vec<f64> = (0..2 * n)
        .map(|i| if i < n { tol.atol_u } else { tol.atol_v })
        .collect();
    let mut problem = OdeBuilder::<M>::new()
        .t0(t0)
        .h0(tol.h0)
        .rtol(tol.rtol)
        .atol(atol)
        .rhs_implicit(
            |y, _p, _t, f| {
                rhs_evals.set(rhs_evals.get() + 1);
                sys.rhs(y, f);
            },
            |y, _p, _t, w, out| sys.jac_mul(y, w, out),
        )
        .init(|_p, _t, y| y.copy_from_slice(y0), 2 * n)
        .build()
        .map_err(|e| Failure::Solver {
            t: t0,
            why: e.to_string(),
        })?;
    // diffsol's floor on the step is an absolute 1e-13, which a contact of a light body
    // (1e-24 against 1 with k = 1 lasts 3e-12) goes below: scale it with the shortest contact.
    problem.ode_options.min_timestep = (tol.h0 * 1e-9).max(f64::MIN_POSITIVE);
    let fail = |e: diffsol::error::DiffsolError| Failure::Solver {
        t: t0,
        why: e.to_string(),
    };
    macro_rules! go {
        ($solver:expr) => {{
            let mut solver = $solver.map_err(fail)?;
            if t_stop.is_finite() {
                solver.set_stop_time(t_stop).map_err(fail)?;
            }
            let end = {
                let mut drive = |ask: Ask| -> Result<(f64, Vec<f64>), Failure> {
                    match ask {
                        Ask::Step => {
                            let t = solver.state().t;
                            match solver.step() {
                                Ok(
                                    OdeSolverStopReason::InternalTimestep
                                    | OdeSolverStopReason::TstopReached
                                    | OdeSolverStopReason::RootFound(..),
                                ) => {}
                                Err(e) => {
                                    return Err(Failure::Solver {
                                        t,
                                        why: e.to_string(),
                                    });
                                }
                            }
                            let state = solver.state();
                            Ok((state.t, state.y.clone_as_vec()))
                        }
                        Ask::At(t) => solver
                            .interpolate(t)
                            .map(|y| (t, y.clone_as_vec()))
                            .map_err(|e| Failure::Solver {
                                t,
                                why: e.to_string(),
                            }),
                    }
                };
                segment(&mut drive, sys, (t0, y0), t_stop, ledger)
            };
            let stats = solver.get_statistics();
            let counts = &mut ledger.counts;
            counts.steps += stats.number_of_steps as u64;
            counts.rejected += (stats.number_of_error_test_failures
                + stats.number_of_nonlinear_solver_fails) as u64;
            counts.jacobians += stats.number_of_linear_solver_setups as u64;
            end
        }};
    }
    let end = match method {
        Adaptive::Tsit45 => go!(problem.tsit45()),
        Adaptive::Bdf => go!(problem.bdf::<LS>()),
        Adaptive::Sdirk => go!(problem.esdirk34::<LS>()),
    };
    ledger.counts.rhs_evals += rhs_evals.get();
    end
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stop within the solver's rounding of a LATER stretch's start (after an event at
    /// t0 = 1: `--until` a few ulps past it) is the start's state carried on by its velocity,
    /// for each method: the bodies move x + v dt with dt = t_stop - t0 = 8 ulps of 1.
    #[test]
    fn a_stop_within_rounding_of_a_later_start_is_the_start_carried_on() {
        let sys = System {
            m: vec![1.0, 2.0],
            slots: Vec::new(),
            active: Vec::new(),
            d0: Vec::new(),
        };
        let tol = Tolerances {
            rtol: 1e-10,
            atol_u: 1e-12,
            atol_v: 1e-12,
            h0: 1e-3,
        };
        let (t0, y0) = (1.0, [0.0, 5.0, 3.0, -1.0]);
        let t_stop = 1.0 + 8.0 * f64::EPSILON;
        let dt = t_stop - t0;
        for method in [Adaptive::Tsit45, Adaptive::Bdf, Adaptive::Sdirk] {
            let mut ledger = Ledger {
                steps_left: 1000,
                energy_cap: f64::INFINITY,
                ..Ledger::default()
            };
            let end = stretch((method, tol), &sys, (t0, &y0), t_stop, &mut ledger)
                .unwrap_or_else(|_| panic!("{method:?} refused a stop 8 ulps after its start"));
            assert_eq!(end.t, t_stop);
            assert_eq!(end.y, vec![3.0 * dt, 5.0 - dt, 3.0, -1.0]);
            assert_eq!(end.event, None);
            assert_eq!(ledger.counts.steps, 0, "{method:?} stepped");
        }
    }
}
