//! Rigid bodies at impact (physics.md section 7, the lecture's 12 degrees of freedom): each body
//! has a generalized velocity `u_i = (v_i, omega_i)` (3 numbers in the plane, 6 in space), the
//! inertia tensor is explicit and block diagonal, `M = diag(m1 I, I1, m2 I, I2)`, and a contact
//! at `c` with normal `n` has the Jacobian row `J_n` (`J_n u = n.(v1 + omega1 x r1 - v2 -
//! omega2 x r2)`) and the collision matrix `K = J M^-1 J^T`. Without friction the impact is the
//! lecture's 1D collision along the normal with the effective mass `1/K_nn`.
//!
//! - `algebra`: exact small matrices and the cross products of the plane and space;
//! - `units`, `shape`: quantities as typed, uniform bodies and their moments of inertia;
//! - `body`: mobility (free, particle, pivoted, immovable), `u`, the block of `M`, point
//!   Jacobians; `jacobian`: the contact, `J_n`, `K`, the effective mass;
//! - `laws`: Newton, Poisson, Stronge; `routh`: friction in the plane (piecewise linear);
//!   `slip`: friction in space (an ODE in the normal impulse, diffsol); `impact`: one impact by
//!   the law asked; `outcome`: what follows from it; `join`: the one body two joined bodies
//!   make (`--join`); `swing`, `rolling`: what follows it (a body on a pivot swings up under
//!   gravity, a ball sliding on the floor starts to roll);
//! - `pose`, `homework`: typed input (scenes, the command line's homework shapes) to a problem;
//!   `unknowns`: one value typed `?`, fixed by a given final spin, a final velocity (`fin`) or
//!   a pivot without impulse, from the impact as a rational function of it (`interpolate`), or
//!   why not (`unsolvable`).

pub mod algebra;
pub mod body;
pub mod fin;
pub mod homework;
pub mod impact;
pub mod interpolate;
pub mod jacobian;
pub mod join;
pub mod laws;
pub mod outcome;
pub mod pose;
pub mod rolling;
pub mod routh;
pub mod shape;
pub mod slip;
pub mod swing;
pub mod units;
pub mod unknowns;
pub mod unsolvable;

/// Solves a posed problem.
pub fn solve(problem: impact::Problem) -> Result<outcome::Outcome, impact::ImpactError> {
    let impact = problem.solve()?;
    Ok(outcome::Outcome::new(problem, impact))
}
