//! Friction at impact in the plane by Routh's method (E. J. Routh, *Dynamics of a System of
//! Rigid Bodies*, 1860; Wang & Mason 1992; Stronge, *Impact Mechanics*, ch. 4): with Coulomb
//! friction the contact velocity `w = (w_n, w_t)` is piecewise linear in the normal impulse. While
//! the contact slips one way (`s = sign w_t`) the tangential impulse grows as `mu s` times the
//! normal one and `dw/dP_n = -K (1, mu s)`; where the slip stops it sticks if
//! `mu K_tt >= |K_tn|` (then `dP_t/dP_n = -K_tn/K_tt`, `dw_n/dP_n = -det K / K_tt`) or slips
//! back with `s = -sign K_tn`. Compression ends where `w_n = 0`; the impact ends by the law:
//! Poisson `P_n = (1 + e) P_c`, Newton `w_n = -e w_n0`, Stronge when the normal work
//! `W = int w_n dP_n` has fallen from its compression value `W_c` to `(1 - e^2) W_c`.
//!
//! Every phase is a closed form, computed in exact rationals; Stronge's law ends a phase at the
//! root of a quadratic, held to 40 digits when irrational. The normal `n` and tangent `t` are
//! any vectors of equal length (`t = n` turned a quarter): `P = l_n n + l_t t` and
//! `w~ = (n.w, t.w)`, `K~ = [n t]^T K [n t]`, so nothing irrational enters for a rational `n`.

use num_traits::Signed;

use crate::values::rational::{Q, half, int, sqrt_exact};

use super::laws::{Law, Mode};

/// A point of the impulse path, `(l_n, l_t)`, and what happened there.
#[derive(Clone, Debug, PartialEq)]
pub struct Corner {
    pub at: [Q; 2],
    pub event: Event,
}

/// What ends a phase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    Start,
    /// Compression ends: `w_n = 0`.
    Compression,
    /// The slip stops: `w_t = 0`.
    Stick,
    /// The impact ends.
    End,
}

/// The impulse of a planar impact with friction.
#[derive(Clone, Debug, PartialEq)]
pub struct Routh {
    /// `(l_n, l_t)` at the end: `P = l_n n + l_t t`.
    pub impulse: [Q; 2],
    /// The path of the impulse, corner by corner.
    pub path: Vec<Corner>,
    pub mode: Mode,
    /// Some value is held to 40 digits (Stronge's quadratic).
    pub approx: bool,
}

/// Why the impact has no end.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RouthError {
    #[error(
        "the impact does not end: along this path the normal velocity never reaches the law's \
         end (a singular collision matrix?)"
    )]
    Endless,
}

/// Digits kept of an irrational root.
const DIGITS: usize = 40;

/// The state along the path.
#[derive(Clone, Debug)]
struct State {
    l: [Q; 2],
    w: [Q; 2],
    /// `int w_n dl_n`.
    work: Q,
}

fn sign(q: &Q) -> Q {
    if q.is_negative() { -Q::ONE } else { Q::ONE }
}

/// `sqrt(q)` exactly, or to 40 digits and marked.
pub(crate) fn root(q: &Q, approx: &mut bool) -> Q {
    sqrt_exact(q).unwrap_or_else(|| {
        *approx = true;
        crate::values::quantity::sqrt(q, DIGITS)
    })
}

/// Routh's method: `k` the collision matrix in `(n, t)` (`K~`), `w0 = (n.w, t.w)` before, with
/// `w0[0] > 0` (approaching), friction `mu > 0`, restitution `e` by `law`.
pub fn solve(k: &[[Q; 2]; 2], w0: &[Q; 2], mu: &Q, law: Law, e: &Q) -> Result<Routh, RouthError> {
    let mut s = State {
        l: [Q::ZERO, Q::ZERO],
        w: w0.clone(),
        work: Q::ZERO,
    };
    let mut approx = false;
    let mut path = vec![Corner {
        at: s.l.clone(),
        event: Event::Start,
    }];
    let mut compression: Option<(Q, Q)> = None;
    let mut stopped = false;
    let mut resumed = false;
    let mut slid = false;
    for _ in 0..8 {
        // The rates of this phase: dl_t/dl_n, and dw/dl_n.
        let (rate, slipping) = if !s.w[1].is_zero() {
            (mu * sign(&s.w[1]), true)
        } else if k[1][1].is_zero() {
            (Q::ZERO, false)
        } else if mu * &k[1][1] >= k[1][0].clone().abs() {
            (-(&k[1][0] / &k[1][1]), false)
        } else {
            resumed |= stopped;
            (-(mu * sign(&k[1][0])), true)
        };
        slid |= slipping;
        let an = -(&k[0][0] + &rate * &k[0][1]);
        let at = if slipping {
            -(&k[1][0] + &rate * &k[1][1])
        } else {
            Q::ZERO
        };
        // The first event ahead, as a step in l_n.
        let mut next: Option<(Q, Event)> = None;
        let offer = |d: Q, ev: Event, next: &mut Option<(Q, Event)>| {
            if d >= Q::ZERO && next.as_ref().is_none_or(|(b, _)| d < *b) {
                *next = Some((d, ev));
            }
        };
        if slipping && (&at * &s.w[1]).is_negative() {
            offer(-(&s.w[1] / &at), Event::Stick, &mut next);
        }
        match &compression {
            None => {
                if an.is_negative() {
                    offer(-(&s.w[0] / &an), Event::Compression, &mut next);
                }
            }
            Some((lc, wc)) => {
                let end = match law {
                    Law::Poisson => Some((Q::ONE + e) * lc - &s.l[0]),
                    Law::Newton => an.is_negative().then(|| (-(e * &w0[0]) - &s.w[0]) / &an),
                    Law::Stronge => {
                        // 1/2 an d^2 + w_n d + (W - W_end) = 0, the root where W falls.
                        let c = &s.work - (Q::ONE - e * e) * wc;
                        let a = &an * half();
                        let b = s.w[0].clone();
                        if a.is_zero() {
                            b.is_negative().then(|| -(c / b))
                        } else {
                            let disc = &b * &b - int(4) * &a * &c;
                            (!disc.is_negative()).then(|| {
                                let r = root(&disc, &mut approx);
                                (-b - r) / (int(2) * a)
                            })
                        }
                    }
                };
                if let Some(d) = end {
                    offer(d.max(Q::ZERO), Event::End, &mut next);
                }
            }
        }
        let Some((d, event)) = next else {
            return Err(RouthError::Endless);
        };
        // Advance along the phase.
        s.work += &s.w[0] * &d + half() * &an * &d * &d;
        s.l[0] += &d;
        s.l[1] += &rate * &d;
        s.w[0] += &an * &d;
        s.w[1] += &at * &d;
        path.push(Corner {
            at: s.l.clone(),
            event,
        });
        match event {
            Event::Compression => {
                s.w[0] = Q::ZERO;
                compression = Some((s.l[0].clone(), s.work.clone()));
            }
            Event::Stick => {
                s.w[1] = Q::ZERO;
                stopped = true;
            }
            Event::End => {
                let mode = if resumed {
                    Mode::Reverse
                } else if stopped || !slid {
                    Mode::Stick
                } else {
                    Mode::Slip
                };
                return Ok(Routh {
                    impulse: s.l,
                    path,
                    mode,
                    approx,
                });
            }
            Event::Start => {}
        }
    }
    Err(RouthError::Endless)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::ratio;

    /// A sphere (m = 1, R = 1, I = 2/5) on a floor: n = (0, -1) from ball to floor, t = (1, 0).
    /// K in (n, t): K_nn = 1/m = 1 (the lever is along n), K_tt = 1/m + R^2/I = 7/2, K_nt = 0.
    fn floor() -> [[Q; 2]; 2] {
        [[int(1), int(0)], [int(0), ratio(7, 2)]]
    }

    #[test]
    fn a_sliding_ball_ends_rolling_at_five_sevenths() {
        // w0 = (falling at 1, sliding at 1); mu = 1 is plenty: the slip stops at
        // l_n = 2/7 (w_t = 1 - 7/2 l_n while l_t = l_n), then sticks; poisson e = 1/2.
        let r = solve(
            &floor(),
            &[int(1), int(1)],
            &int(1),
            Law::Poisson,
            &ratio(1, 2),
        )
        .unwrap();
        assert_eq!(r.mode, Mode::Stick);
        // The tangential impulse on the floor that stops the slip: 1 - 7/2 l_t = 0, so
        // l_t = 2/7, and -2/7 on the ball: v' = 1 - 2/7 = 5/7 of the sliding speed
        // (physics.md section 7); compression ends at l_n = 1, poisson at 3/2.
        assert_eq!(r.impulse[1], ratio(2, 7));
        assert_eq!(r.impulse[0], ratio(3, 2));
    }

    #[test]
    fn too_little_friction_slips_throughout() {
        let r = solve(
            &floor(),
            &[int(1), int(1)],
            &ratio(1, 10),
            Law::Poisson,
            &ratio(1, 2),
        )
        .unwrap();
        assert_eq!(r.mode, Mode::Slip);
        assert_eq!(r.impulse[1], ratio(1, 10) * &r.impulse[0]);
    }

    #[test]
    fn the_laws_agree_when_central() {
        // K_nt = 0 and no slip: w_n is linear in l_n, all three laws end at (1 + e) l_c.
        let k = [[int(2), int(0)], [int(0), int(3)]];
        for law in [Law::Newton, Law::Poisson, Law::Stronge] {
            let r = solve(&k, &[int(4), int(0)], &int(1), law, &ratio(1, 3)).unwrap();
            assert_eq!(r.impulse, [ratio(8, 3), int(0)], "{law:?}");
            assert_eq!(r.mode, Mode::Stick);
        }
    }
}
