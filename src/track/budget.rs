//! The budgets a track run must keep: energy (elastic runs keep it, no run gains it) to a stated
//! tolerance that grows with the collisions, and momentum where nothing outside acts.

use super::{Broken, Budget, Run, Track};

/// The energy check's tolerance, relative to the start energy (the relative change the report
/// prints, `(end - start) / start`), after `collisions` collisions: `ENERGY_TOLERANCE` (1e-9),
/// or `ENERGY_PER_COLLISION` (8 ulps of 1, 1.8e-15) times the collisions when that is more. A
/// collision rounds each velocity it sets once (a kinetic term: 1 ulp) and each position once
/// (a potential term: 1 ulp), and puts bodies in place keeping their energy (`Sim::shift`): a
/// few ulps of the energy each, adding up at worst linearly (an elastic stack under gravity
/// measured 8e-13 over 1e7 collisions, 1e-19 a collision). Stated in docs/track.md.
pub fn energy_tolerance(collisions: u64) -> f64 {
    ENERGY_TOLERANCE.max(ENERGY_PER_COLLISION * collisions as f64)
}

/// The energy check's tolerance for short runs, relative ([`energy_tolerance`]).
pub const ENERGY_TOLERANCE: f64 = 1e-9;
/// The energy check's tolerance per collision, relative: 8 ulps of 1 ([`energy_tolerance`]).
pub const ENERGY_PER_COLLISION: f64 = 8.0 * f64::EPSILON;

/// Whether a `Budget` kept what the physics says it must (rounding allowed): elastic runs keep
/// their energy and no run gains energy, to [`energy_tolerance`] of the start energy, and with
/// no walls and no gravity momentum is kept (1e-9 of the momenta's magnitudes).
pub(super) fn budgets_hold(track: &Track, run: &Run) -> Result<(), Broken> {
    let broken = |what: String| Broken {
        t: run.time,
        collisions: run.collisions,
        what,
    };
    let scale = |b: &Budget, terms: f64| b.start.abs().max(b.end.abs()).max(terms);
    let (e, p) = (&run.energy, &run.momentum);
    // The sum of the momenta's magnitudes, at the start and the end: the scale of their
    // rounding. Every energy term is >= 0 (positions are above the floor): the start energy is
    // its own scale.
    let mut momentum_terms = 0.0f64;
    for (i, b) in track.bodies.iter().enumerate() {
        let m = b.m.value();
        momentum_terms += (m * b.v).abs() + (m * run.v[i]).abs();
    }
    let tol = energy_tolerance(run.collisions) * e.start.abs();
    let elastic = track.e == 1.0 && track.e_wall == 1.0;
    if elastic && (e.end - e.start).abs() > tol {
        return Err(broken(format!(
            "an elastic run changed the energy from {} to {}",
            e.start, e.end
        )));
    }
    if e.end - e.start > tol {
        return Err(broken(format!(
            "the energy rose from {} to {}",
            e.start, e.end
        )));
    }
    let closed = track.left_wall.is_none() && track.right_wall.is_none() && track.gravity == 0.0;
    if closed && (p.end - p.start).abs() > 1e-9 * scale(p, momentum_terms) {
        return Err(broken(format!(
            "momentum changed from {} to {} with no walls",
            p.start, p.end
        )));
    }
    Ok(())
}
