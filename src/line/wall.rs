//! A body against a wall or floor: an immovable body (issue 15), the limit of the two-body
//! collision as one mass grows without bound (lecture Sec. 1: the weights become 0 and 1, the
//! reduced mass becomes the ball's mass `m`, and `V_COM` the wall's velocity `w`). Only
//! restitution holds (the wall takes any momentum): the ball leaves at
//! `f = w - e (v - w)`, and the wall keeps `w`. The crunch energy is `1/2 m (v - w)^2`, lost
//! `(1 - e^2)` of it; the wall's kinetic energy and the centre of mass mean nothing, and are
//! left out. Everything is exact from the typed values, rounded once when printed.

use crate::values::rational::{Q, half};
use num_traits::{One, Signed};

use crate::line::restitution::Restitution;
use crate::line::unknowns::{UnknownError, Var};
use crate::values::number::Number;
use crate::values::units::Units;

/// A ball against a wall.
#[derive(Clone, Debug, PartialEq)]
pub struct WallCase {
    /// Which body is the wall: 0 (on the left) or 1 (on the right).
    pub wall: usize,
    /// The ball's mass as typed; `None` when not given (`-m 'wall,?'`): a rebound asked in
    /// speeds and e does not depend on it (issue 45 §5), only momentum and energy do.
    pub mass: Option<Number>,
    pub velocities: [Number; 2],
    pub restitution: Restitution,
    pub units: Units,
}

impl WallCase {
    pub fn ball(&self) -> usize {
        1 - self.wall
    }
    pub fn m(&self) -> Option<Q> {
        self.mass.as_ref().map(Number::exact)
    }
    pub fn e(&self) -> Q {
        self.restitution.number().exact()
    }
    pub fn v(&self) -> [Q; 2] {
        [self.velocities[0].exact(), self.velocities[1].exact()]
    }
    /// `(ball, wall)` initial velocities.
    fn ball_wall(&self) -> (Q, Q) {
        let v = self.v();
        (v[self.ball()].clone(), v[self.wall].clone())
    }
    /// FIN: the ball at `w - e (v - w)`, the wall unchanged.
    pub fn fin(&self) -> [Q; 2] {
        let (v, w) = self.ball_wall();
        let mut f = self.v();
        f[self.ball()] = &w - self.e() * (&v - &w);
        f
    }
    /// Whether the ball moves toward the wall (`V1 > V2`: body 1 on the left catches body 2).
    pub fn approaching(&self) -> bool {
        let v = self.v();
        v[0] > v[1]
    }
    /// `1/2 m (v - w)^2`: the kinetic energy in the wall's frame (`None`: no mass given).
    pub fn crunch(&self) -> Option<Q> {
        let (v, w) = self.ball_wall();
        let d = v - w;
        Some(half() * self.m()? * &d * &d)
    }
    /// `(1 - e^2) crunch` (negative when superelastic).
    pub fn lost(&self) -> Option<Q> {
        let e = self.e();
        Some((Q::one() - &e * &e) * self.crunch()?)
    }
    /// `lost / crunch = 1 - e^2`, the share of the ball's energy in the wall's frame lost,
    /// whatever the mass; `None` when there is no crunch (the ball at the wall's speed).
    pub fn lost_fraction(&self) -> Option<Q> {
        let (v, w) = self.ball_wall();
        let e = self.e();
        (v != w).then(|| Q::one() - &e * &e)
    }
    /// The ball's kinetic energy at a velocity.
    pub fn ke(&self, v: &Q) -> Option<Q> {
        Some(half() * (self.m()? * v) * v)
    }
    /// The ball's momentum at a velocity.
    pub fn p(&self, v: &Q) -> Option<Q> {
        Some(self.m()? * v)
    }
    /// The ball's change of velocity `f - v = -(1 + e)(v - w)`.
    pub fn dv(&self) -> Q {
        let (v, w) = self.ball_wall();
        -(Q::one() + self.e()) * (v - w)
    }
}

/// The values of a wall problem, `None` for `?`: the ball's initial and final velocity, the
/// wall's, and `e`; and which body the wall is (0: on the left, 1: on the right).
pub struct WallProblem {
    pub ball: (Option<Q>, Option<Q>),
    pub wall: (Option<Q>, Option<Q>),
    pub e: Option<Q>,
    pub side: usize,
}

/// Solves a wall problem for its unknown (restitution is the one law, so at most one of the
/// ball's velocities and `e`; the wall's final velocity is its initial one).
pub fn solve(p: WallProblem) -> Result<WallSolution, UnknownError> {
    let (w0, w1) = p.wall;
    let w = match (w0, w1) {
        (Some(a), Some(b)) if a != b => {
            return Err(UnknownError::Unphysical(format!(
                "a wall does not move: its final velocity {} must be its initial {}",
                crate::values::quantity::fraction(&b),
                crate::values::quantity::fraction(&a)
            )));
        }
        (Some(a), _) | (None, Some(a)) => a,
        (None, None) => {
            return Err(UnknownError::WallTooMany(
                "the wall's initial and final velocity are both unknown".into(),
            ));
        }
    };
    // Restitution with the wall on either side: f_ball - w = -e (v_ball - w).
    let (v, f, e) = (p.ball.0, p.ball.1, p.e);
    let names = |list: &[(bool, &str)]| -> Vec<String> {
        list.iter()
            .filter(|(unknown, _)| *unknown)
            .map(|(_, n)| n.to_string())
            .collect()
    };
    let unknown = names(&[(v.is_none(), "v"), (f.is_none(), "f"), (e.is_none(), "e")]);
    if unknown.len() > 1 {
        return Err(UnknownError::WallTooMany(format!(
            "{} unknowns ({})",
            unknown.len(),
            unknown.join(", ")
        )));
    }
    let mut residual = None;
    let (v, f, e) = match (v, f, e) {
        (Some(v), Some(f), Some(e)) => {
            residual = Some(&f - &w + &e * (&v - &w));
            (v, f, e)
        }
        (Some(v), None, Some(e)) => {
            let f = &w - &e * (&v - &w);
            (v, f, e)
        }
        (None, Some(f), Some(e)) => {
            if e.is_zero() {
                return Err(UnknownError::Many(
                    "with e = 0 the ball leaves with the wall whatever its speed".into(),
                ));
            }
            let v = &w - (&f - &w) / &e;
            (v, f, e)
        }
        (Some(v), Some(f), None) => {
            if v == w {
                return Err(UnknownError::Many(
                    "the ball moves with the wall, never meets it, so e is not determined".into(),
                ));
            }
            let e = -(&f - &w) / (&v - &w);
            (v, f, e)
        }
        _ => unreachable!("more than one unknown was refused above"),
    };
    if e.is_negative() {
        return Err(UnknownError::Unphysical(format!(
            "e = {} < 0: the ball would pass through the wall",
            crate::values::quantity::fraction(&e)
        )));
    }
    // A value solved from FIN (the ball's IN velocity, or e) must describe a bounce: the ball
    // moving toward the wall at IN (a wall on the left is met by a ball moving left, v < w). A
    // ball moving away never meets it, so restitution says nothing about it (`v2 = 1` from
    // FIN -0.5 and e = 1/2: refused, as e < 0 is). FIN from IN is the forward case, which
    // prints with a note.
    let receding = if p.side == 0 { v > w } else { v < w };
    let from_fin = unknown.iter().any(|u| u == "v" || u == "e");
    if from_fin && receding {
        let (name, side) = if p.side == 0 {
            ("v2", "left")
        } else {
            ("v1", "right")
        };
        let v_text = crate::values::quantity::fraction(&v);
        let solved = if unknown[0] == "v" {
            format!("{name} = {v_text}")
        } else {
            format!(
                "e = {} with {name} = {v_text}",
                crate::values::quantity::fraction(&e)
            )
        };
        return Err(UnknownError::Unphysical(format!(
            "{solved}: the ball moves away from the wall (on the {side}, at {}), so they never \
             meet and nothing bounces; check the signs of the velocities",
            crate::values::quantity::fraction(&w)
        )));
    }
    Ok(WallSolution {
        v,
        f,
        w,
        e,
        residual,
    })
}

/// A solved wall problem.
pub struct WallSolution {
    pub v: Q,
    pub f: Q,
    pub w: Q,
    pub e: Q,
    /// Restitution's residual when every value was given (a consistency check).
    pub residual: Option<Q>,
}

/// The `Var`s of the ball and the wall when the wall is body `wall` (0 or 1).
pub fn vars(wall: usize) -> ((Var, Var), (Var, Var)) {
    if wall == 0 {
        ((Var::V2, Var::F2), (Var::V1, Var::F1))
    } else {
        ((Var::V1, Var::F1), (Var::V2, Var::F2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Q {
        s.parse::<Number>().unwrap().exact()
    }

    #[test]
    fn a_drop_and_rebound_gives_e_and_the_forward_case_gives_fin() {
        // Down at 4 onto a floor (wall first, at rest), up at 3: e = 3/4.
        let s = solve(WallProblem {
            ball: (Some(q("-4")), Some(q("3"))),
            wall: (Some(q("0")), None),
            e: None,
            side: 0,
        })
        .unwrap();
        assert_eq!(s.e, q("3/4"));
        // A wall moving at 1 toward a ball at rest, e = 1: the ball leaves at 2 (w - e (0 - w)).
        let s = solve(WallProblem {
            ball: (Some(q("0")), None),
            wall: (Some(q("1")), None),
            e: Some(q("1")),
            side: 0,
        })
        .unwrap();
        assert_eq!(s.f, q("2"));
        // Passing through the wall: refused, as unphysical, with the restitution it would take
        // (e = -(f - w)/(v - w) = -(-3)/(-4) = -3/4).
        let e = solve(WallProblem {
            ball: (Some(q("-4")), Some(q("-3"))),
            wall: (Some(q("0")), None),
            e: None,
            side: 0,
        });
        match e {
            Err(UnknownError::Unphysical(m)) => {
                assert_eq!(m, "e = -3/4 < 0: the ball would pass through the wall");
            }
            Err(other) => panic!("expected the unphysical refusal, got {other}"),
            Ok(_) => panic!("a ball through a wall was solved"),
        }
    }
}
