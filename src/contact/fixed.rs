//! The fixed-step methods, written here because they are the objects being compared: one step
//! of size `h` from `y`, for `y' = f(y)` with `y = (u, v)`.
//!
//! - symplectic Euler: `v1 = v + h a(u, v)`, `u1 = u + h v1` (E. Hairer, C. Lubich, G. Wanner,
//!   *Geometric Numerical Integration*, 2nd ed., section I.1.2);
//! - velocity Verlet: `v_half = v + h/2 a(u, v)`, `u1 = u + h v_half`,
//!   `v1 = v_half + h/2 a(u1, v_half)` (the damping force is taken at `v_half`, as DEM codes do);
//! - classical Runge-Kutta of order 4;
//! - implicit Euler `y1 = y + h f(y1)` and implicit midpoint `y1 = y + h f((y + y1)/2)`, each
//!   solved by Newton's method with the exact Jacobian (E. Hairer, G. Wanner, *Solving Ordinary
//!   Differential Equations II*, section IV.8).
//!
//! Explicit methods are stable on an undamped contact of angular frequency `omega` only while
//! `omega h` stays below [`Fixed::stability_limit`] (2 for both Euler-Cromer and Verlet, `2 sqrt 2`
//! for RK4 on the imaginary axis); the implicit ones have no such limit.

use super::system::System;

/// A fixed-step method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fixed {
    SymplecticEuler,
    Verlet,
    Rk4,
    ImplicitEuler,
    ImplicitMidpoint,
}

/// Work counters of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Counts {
    pub steps: u64,
    pub rejected: u64,
    pub rhs_evals: u64,
    pub jacobians: u64,
}

/// Newton's iteration of an implicit step did not converge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoConvergence;

impl Fixed {
    /// `omega h` above which the method is unstable on an undamped oscillator (`None`: no limit).
    pub fn stability_limit(self) -> Option<f64> {
        match self {
            Fixed::SymplecticEuler | Fixed::Verlet => Some(2.0),
            Fixed::Rk4 => Some(2.0 * std::f64::consts::SQRT_2),
            Fixed::ImplicitEuler | Fixed::ImplicitMidpoint => None,
        }
    }

    /// One step of size `h` from `y` into `out`.
    pub fn step(
        self,
        sys: &System,
        y: &[f64],
        h: f64,
        out: &mut [f64],
        counts: &mut Counts,
    ) -> Result<(), NoConvergence> {
        let k = y.len();
        let n = k / 2;
        let mut f = vec![0.0; k];
        match self {
            Fixed::SymplecticEuler => {
                sys.rhs(y, &mut f);
                counts.rhs_evals += 1;
                for i in 0..n {
                    out[n + i] = y[n + i] + h * f[n + i];
                    out[i] = y[i] + h * out[n + i];
                }
            }
            Fixed::Verlet => {
                sys.rhs(y, &mut f);
                for i in 0..n {
                    out[n + i] = y[n + i] + 0.5 * h * f[n + i];
                    out[i] = y[i] + h * out[n + i];
                }
                sys.rhs(out, &mut f);
                counts.rhs_evals += 2;
                for i in 0..n {
                    out[n + i] += 0.5 * h * f[n + i];
                }
            }
            Fixed::Rk4 => {
                let mut stage = vec![0.0; k];
                let mut acc = vec![0.0; k];
                sys.rhs(y, &mut f);
                for (i, a) in acc.iter_mut().enumerate() {
                    *a = f[i];
                    stage[i] = y[i] + 0.5 * h * f[i];
                }
                sys.rhs(&stage, &mut f);
                for i in 0..k {
                    acc[i] += 2.0 * f[i];
                    stage[i] = y[i] + 0.5 * h * f[i];
                }
                sys.rhs(&stage, &mut f);
                for i in 0..k {
                    acc[i] += 2.0 * f[i];
                    stage[i] = y[i] + h * f[i];
                }
                sys.rhs(&stage, &mut f);
                counts.rhs_evals += 4;
                for i in 0..k {
                    out[i] = y[i] + h / 6.0 * (acc[i] + f[i]);
                }
            }
            Fixed::ImplicitEuler | Fixed::ImplicitMidpoint => {
                let theta = if self == Fixed::ImplicitEuler {
                    1.0
                } else {
                    0.5
                };
                implicit(sys, y, h, theta, out, counts)?;
            }
        }
        counts.steps += 1;
        Ok(())
    }
}

/// Solves `y1 = y + h f(y + theta (y1 - y))` (theta = 1: implicit Euler, 1/2: implicit midpoint)
/// by Newton's method from the explicit Euler guess, with a fresh Jacobian each iteration.
fn implicit(
    sys: &System,
    y: &[f64],
    h: f64,
    theta: f64,
    out: &mut [f64],
    counts: &mut Counts,
) -> Result<(), NoConvergence> {
    let k = y.len();
    let mut f = vec![0.0; k];
    sys.rhs(y, &mut f);
    counts.rhs_evals += 1;
    for i in 0..k {
        out[i] = y[i] + h * f[i];
    }
    let mut at = vec![0.0; k];
    let scale = y
        .iter()
        .fold(0.0f64, |a, b| a.max(b.abs()))
        .max(f64::MIN_POSITIVE);
    let mut last = f64::INFINITY;
    for _ in 0..30 {
        for i in 0..k {
            at[i] = y[i] + theta * (out[i] - y[i]);
        }
        sys.rhs(&at, &mut f);
        counts.rhs_evals += 1;
        let residual =
            nalgebra::DVector::from_iterator(k, (0..k).map(|i| out[i] - y[i] - h * f[i]));
        let mut j = sys.jacobian(&at);
        counts.jacobians += 1;
        j *= -h * theta;
        for i in 0..k {
            j[(i, i)] += 1.0;
        }
        let delta = j.lu().solve(&residual).ok_or(NoConvergence)?;
        let size = delta.amax();
        if !size.is_finite() {
            return Err(NoConvergence);
        }
        for i in 0..k {
            out[i] -= delta[i];
        }
        let small = scale.max(out.iter().fold(0.0f64, |a, b| a.max(b.abs()))) * 4.0 * f64::EPSILON;
        // Converged when the correction is at rounding level, or stopped shrinking near it.
        if size <= small || (size >= 0.5 * last && size <= 1e6 * small) {
            return Ok(());
        }
        last = size;
    }
    Err(NoConvergence)
}
