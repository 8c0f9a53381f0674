//! The swing after an impact (physics.md section 8, issue 42 section 3): a body on a pivot,
//! leaving the impact with spin `omega` and inertia `I_p` about the pivot, turns under gravity
//! until its kinetic energy is spent: `1/2 I_p omega^2 = M g dh_cm`. Gravity points along `-y`
//! (the homework layout: the ball moves along `+x`, a rod stands along `y`).
//!
//! With `r0 = (x0, y0)` the centre's place from the pivot (at distance `l`), `x0` taken in the
//! sense of the turn, the centre rises `dh = 1/2 I_p omega^2 / (M g)` (exact) to the height
//! `y1 = y0 + dh`, at `r1 = (sqrt(l^2 - y1^2), y1)` (it is still rising on the side it turns
//! towards), unless `y1 > l`: then it goes over the top, passing it with
//! `omega_top^2 = omega^2 - 2 M g (l - y0) / I_p`. The angle turned is
//! `2 asin(|r1 - r0| / 2l)` (or `2 pi` less that, past half a turn): for a centre that starts
//! straight below the pivot, `cos(theta) = 1 - dh / l`, and the chord form keeps small swings'
//! digits. Roots and the angle are taken to `line::spring::DIGITS` digits.

use num_traits::Signed;

use crate::line::pendulum::asin;
use crate::line::spring::{PI, root};
use crate::values::rational::{Q, half, int};

use super::algebra::{self, sub};
use super::body::Mobility;
use super::join::Joined;
use super::outcome::Outcome;

/// Which body swings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Who {
    /// The one body two joined bodies make (`--join`).
    Joined,
    /// Body `i` (0 or 1) alone.
    Body(usize),
}

/// A body on a pivot after the impact.
#[derive(Clone, Debug, PartialEq)]
pub struct Swing {
    pub who: Who,
    pub mass: Q,
    /// `I_p`, about the pivot.
    pub inertia: Q,
    pub pivot: Vec<Q>,
    /// The centre of mass from the pivot, `r0`.
    pub arm: Vec<Q>,
    /// `l = |r0|`, exact when a rational (`Ok`), else to `DIGITS` digits (`Err`).
    pub length: Result<Q, Q>,
    pub omega: Q,
    /// `1/2 I_p omega^2`.
    pub energy: Q,
    pub end: End,
}

/// How the swing ends.
#[derive(Clone, Debug, PartialEq)]
pub enum End {
    /// No spin after the impact: it stays where it is.
    Still,
    /// The centre is on the axle: gravity does no work, it turns on at `omega`.
    OnAxle,
    /// It stops after turning `degrees` (approximate), its centre risen `rise` (exact).
    Rises { rise: Q, degrees: Q },
    /// It just reaches the top (its centre straight above the pivot) with no spin left.
    Balanced { rise: Q },
    /// It goes over the top: its centre rises `rise` to get there and passes it at
    /// `omega_top` (both exact when roots are rational, `Ok`).
    OverTheTop {
        rise: Result<Q, Q>,
        omega_top: Result<Q, Q>,
    },
}

/// Why there is no swing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NoSwing {
    #[error(
        "no body is on a pivot: a free body flies on after the impact (the swing is for a \
         target on --pivot)"
    )]
    NoPivot,
    #[error("the swing is computed in the plane (a body on a pivot under gravity along -y)")]
    Space,
}

fn value(r: &Result<Q, Q>) -> &Q {
    match r {
        Ok(q) | Err(q) => q,
    }
}

impl Swing {
    /// The swing of the outcome's pivoted body (the joined body under `--join`) under gravity
    /// `g > 0` along `-y`.
    pub fn of(o: &Outcome, g: &Q) -> Result<Swing, NoSwing> {
        if o.dim() != 2 {
            return Err(NoSwing::Space);
        }
        let (who, mass, inertia, pivot, centre, omega) = match Joined::of(o) {
            Some(j) => {
                let pivot = j.pivot.ok_or(NoSwing::NoPivot)?;
                let inertia = j.inertia[0][0].clone();
                (
                    Who::Joined,
                    j.mass,
                    inertia,
                    pivot,
                    j.centre,
                    j.omega[0].clone(),
                )
            }
            None => {
                let (i, body) = o
                    .bodies()
                    .iter()
                    .enumerate()
                    .rev()
                    .find(|(_, b)| b.pivot().is_some())
                    .ok_or(NoSwing::NoPivot)?;
                let Mobility::Pivoted {
                    pivot, about_pivot, ..
                } = &body.mobility
                else {
                    return Err(NoSwing::NoPivot);
                };
                (
                    Who::Body(i),
                    body.mass.clone().ok_or(NoSwing::NoPivot)?,
                    about_pivot[0][0].clone(),
                    pivot.clone(),
                    body.position.clone(),
                    o.fin[i].omega[0].clone(),
                )
            }
        };
        let arm = sub(&centre, &pivot);
        let l2 = algebra::dot(&arm, &arm);
        let length = root(&l2);
        let energy = half() * &inertia * &omega * &omega;
        let end = end(&arm, &l2, &length, &omega, &energy, &mass, &inertia, g);
        Ok(Swing {
            who,
            mass,
            inertia,
            pivot,
            arm,
            length,
            omega,
            energy,
            end,
        })
    }

    /// Whether a value of the swing is a rounded root (printed with `≈` in exact output).
    pub fn length_approx(&self) -> bool {
        self.length.is_err()
    }
}

#[allow(clippy::too_many_arguments)]
fn end(
    arm: &[Q],
    l2: &Q,
    length: &Result<Q, Q>,
    omega: &Q,
    energy: &Q,
    mass: &Q,
    inertia: &Q,
    g: &Q,
) -> End {
    if omega.is_zero() {
        return End::Still;
    }
    if l2.is_zero() {
        return End::OnAxle;
    }
    // The turn taken counterclockwise: a clockwise turn is its mirror image in x.
    let x0 = if omega.is_negative() {
        -arm[0].clone()
    } else {
        arm[0].clone()
    };
    let y0 = arm[1].clone();
    let rise = energy / (mass * g);
    let y1 = &y0 + &rise;
    let top = y1.is_positive() && &(&y1 * &y1) >= l2;
    if top && &(&y1 * &y1) == l2 {
        return End::Balanced { rise };
    }
    if top {
        let l = value(length);
        let to_top = l - &y0;
        let w2 = omega * omega - int(2) * mass * g * &to_top / inertia;
        let w = root(&w2);
        let signed = |r: Result<Q, Q>| -> Result<Q, Q> {
            let s = |q: Q| if omega.is_negative() { -q } else { q };
            r.map(s).map_err(s)
        };
        let rise = match length {
            Ok(_) => Ok(to_top),
            Err(_) => Err(to_top),
        };
        let exact = rise.is_ok();
        let omega_top = match (signed(w), exact) {
            (Ok(q), true) => Ok(q),
            (Ok(q) | Err(q), _) => Err(q),
        };
        return End::OverTheTop { rise, omega_top };
    }
    let x1 = value(&root(&(l2 - &y1 * &y1))).clone();
    let dx = &x1 - &x0;
    let chord2 = &dx * &dx + &rise * &rise;
    let s = value(&root(&(chord2 / (int(4) * l2)))).clone();
    let pi = PI
        .parse::<crate::values::number::Number>()
        .map(|n| n.exact())
        .unwrap_or_default();
    let mut alpha = int(2) * asin(&s.min(Q::ONE));
    // Past half a turn the chord's angle is the shorter way round.
    if (&x0 * &y1 - &y0 * &x1).is_negative() {
        alpha = int(2) * &pi - alpha;
    }
    End::Rises {
        rise,
        degrees: alpha * int(180) / pi,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::ratio;

    fn deg(e: &End) -> f64 {
        match e {
            End::Rises { degrees, .. } => crate::values::rational::to_f64(degrees).unwrap(),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn hanging_centre_gives_acos() {
        // Straight below at l = 1, rise 1/2: cos(theta) = 1/2, theta = 60 degrees; rise 1
        // gives 90, rise 3/2 gives 120 (past the horizontal, a rigid arm).
        let arm = [Q::ZERO, int(-1)];
        for (rise, want) in [(ratio(1, 2), 60.0), (int(1), 90.0), (ratio(3, 2), 120.0)] {
            // energy = M g rise with M = g = 1; omega only sets the sense.
            let e = end(
                &arm,
                &int(1),
                &Ok(int(1)),
                &int(1),
                &rise,
                &int(1),
                &int(1),
                &int(1),
            );
            let got = deg(&e);
            assert!(
                (got - want).abs() <= 4.0 * f64::EPSILON * want,
                "{got} vs {want}"
            );
            // Clockwise is the mirror image: the same angle.
            let e = end(
                &arm,
                &int(1),
                &Ok(int(1)),
                &int(-1),
                &rise,
                &int(1),
                &int(1),
                &int(1),
            );
            assert_eq!(deg(&e), got);
        }
    }

    #[test]
    fn centre_beside_the_pivot() {
        // The centre level with the pivot at (1, 0), turning counterclockwise (up): rise 1/2
        // reaches sin(psi) = 1/2, 30 degrees; turning clockwise it first falls through the
        // bottom and comes up the far side to height 1/2: 180 + 30 = 210 degrees.
        let arm = [int(1), Q::ZERO];
        let up = end(
            &arm,
            &int(1),
            &Ok(int(1)),
            &int(1),
            &ratio(1, 2),
            &int(1),
            &int(1),
            &int(1),
        );
        assert!((deg(&up) - 30.0).abs() <= 4.0 * f64::EPSILON * 30.0);
        let down = end(
            &arm,
            &int(1),
            &Ok(int(1)),
            &int(-1),
            &ratio(1, 2),
            &int(1),
            &int(1),
            &int(1),
        );
        assert!((deg(&down) - 210.0).abs() <= 4.0 * f64::EPSILON * 210.0);
    }

    #[test]
    fn over_the_top_and_balanced() {
        // Straight below at l = 1 (M = g = I = 1): energy 2 just reaches the top; energy 5/2
        // passes it with omega_top^2 = 5 - 4 = 1 (omega^2 = 2 E / I = 5).
        let arm = [Q::ZERO, int(-1)];
        let b = end(
            &arm,
            &int(1),
            &Ok(int(1)),
            &int(1),
            &int(2),
            &int(1),
            &int(1),
            &int(1),
        );
        assert_eq!(b, End::Balanced { rise: int(2) });
        // omega = sqrt(5) is not needed exactly: omega^2 enters, so give omega^2 = 5 through
        // omega = 5/2 and I = 4/5 (energy 1/2 4/5 25/4 = 5/2).
        let o = end(
            &arm,
            &int(1),
            &Ok(int(1)),
            &ratio(5, 2),
            &ratio(5, 2),
            &int(1),
            &ratio(4, 5),
            &int(1),
        );
        // omega_top^2 = 25/4 - 2 (2) / (4/5) = 25/4 - 5 = 5/4: not a square, rounded.
        match o {
            End::OverTheTop { rise, omega_top } => {
                assert_eq!(rise, Ok(int(2)));
                let w = crate::values::rational::to_f64(value(&omega_top)).unwrap();
                assert!((w - 1.25f64.sqrt()).abs() <= 2.0 * f64::EPSILON);
            }
            other => panic!("{other:?}"),
        }
    }
}
