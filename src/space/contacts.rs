//! Several contacts at once (`../shared/physics.md` section 8): smooth balls that touch, each
//! contact `k` between bodies `a` and `b` with a line of impact `n_k` from `a` to `b` (any
//! length: the answer depends on `n_k` only through `n_k n_k^T / n_k.n_k`, so a rational
//! direction gives a rational answer).
//!
//! Newton's restitution at every contact at once, as a linear complementarity problem (Moreau;
//! Pfeiffer & Glocker, *Multibody Dynamics with Unilateral Contacts*, 1996): with the gap rates
//! `w = J V` (`w_k = n_k.(v_b - v_a)`, negative when the pair approaches), the impulses `P`
//! (`P_k n_k` on `b`, `-P_k n_k` on `a`) give `V' = V + M^-1 J^T P` and `w' = w + A P`,
//! `A = J M^-1 J^T`; Newton's law asks `P >= 0`, `y = w' + e min(w, 0) >= 0` and `P.y = 0`
//! (a pair that approaches leaves at `e` times its approach or faster, a pair at rest or
//! parting does not close; a contact that pushes leaves at exactly that). Solved exactly by
//! `super::lcp` and checked: every condition exactly, energy never created (`e <= 1`).
//!
//! The answer depends on the law: the sequential answer (`sequential`: the pairs collide one
//! at a time by the two-body rule, in a stated order, until none approaches) differs, and a
//! Newton's cradle under the simultaneous law does not send one ball out (Ceanga & Hurmuzlu,
//! J. Appl. Mech. 68, 2001).

use num_traits::{Signed, Zero};

use crate::values::rational::{Q, from_f64, to_f64};

use super::lcp::{self, Broken, LcpError};
use super::outcome::{dot, sub};

/// Balls closer than this fraction of `R_a + R_b` to touching touch: `|d - (R_a + R_b)| <=
/// 1e-3 (R_a + R_b)` (positions typed to four digits, `(1.732, 1)` for `(sqrt 3, 1)`, are
/// 2.2e-5 off). Closer than `1 - TOUCH` of it, they overlap, which is refused.
pub const TOUCH: f64 = 1e-3;

/// The most contacts solved at once: exact pivoting costs about m^3 rational operations, with
/// more digits per pivot in a dense packing (a chain of 101 takes 0.4 s, the rack's 31 0.2 s).
pub const MAX_CONTACTS: usize = 100;

/// The most two-body impacts the sequential answer takes before it gives up.
pub const MAX_SEQUENTIAL: usize = 10_000;

/// A contact between bodies `a < b` (0-based), with its line of impact from `a` to `b`.
#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    pub a: usize,
    pub b: usize,
    /// Any length; rational.
    pub normal: Vec<Q>,
}

/// Why several contacts cannot be posed or solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ContactsError {
    #[error(
        "balls {a} and {b} overlap: their centres are {d} apart and their radii add to {r} \
         (touching within {tol} of that is contact)",
        tol = TOUCH
    )]
    Overlap {
        a: usize,
        b: usize,
        d: String,
        r: String,
    },
    #[error("--positions has {0} values for {1} masses: give one per body")]
    Positions(usize, usize),
    #[error("--radii has {0} values for {1} masses: give one per body")]
    Radii(usize, usize),
    #[error("radius {0} of body {1} must be a number > 0")]
    Radius(String, usize),
    #[error("position {0} of body {1} has {2} components, the velocities {3}")]
    PositionSize(String, usize, usize, usize),
    #[error("contact '{0}': body {1} does not exist (there are {2} bodies)")]
    NoBody(String, usize, usize),
    #[error("contact '{0}': a contact is between two different bodies")]
    SameBody(String),
    #[error("contact '{0}': the pair is named twice")]
    Twice(String),
    #[error(
        "contact '{0}': give it as 'A-B @ N' with bodies A and B (numbered from 1) and the line \
         of impact N from A to B ('30deg', '(1,1)')"
    )]
    Form(String),
    #[error("contact '{0}': the line of impact has {1} components, the velocities {2}")]
    NormalSize(String, usize, usize),
    #[error("contact '{0}': the zero vector has no direction")]
    ZeroNormal(String),
    #[error("no two balls touch: there is no contact (touching is within {TOUCH} of R_a + R_b)")]
    None,
    #[error(
        "restitution e = {0} among several contacts: give e in [0, 1] (Newton's law at several \
         contacts at once with e > 1 is not supported)"
    )]
    Restitution(String),
    #[error(
        "{0} contacts: collide solves at most {MAX_CONTACTS} contacts at once (the exact \
         solution's cost grows as their cube); split the case"
    )]
    TooMany(usize),
    #[error(transparent)]
    Lcp(#[from] LcpError),
    #[error("internal check failed ({0}); nothing is printed: please report the case as a bug")]
    Check(String),
    #[error(
        "the sequential answer took more than {MAX_SEQUENTIAL} two-body impacts (the pairs keep \
         closing); drop --sequential"
    )]
    Sequential,
}

/// The contacts among balls at `positions` with `radii` (any one length unit): every pair whose
/// centres are `R_a + R_b` apart within [`TOUCH`] of it, in the order (a, b); a pair closer
/// than that overlaps (an error). The line of impact is the centre line as typed.
pub fn touching(positions: &[Vec<Q>], radii: &[Q]) -> Result<Vec<Contact>, ContactsError> {
    let tol = from_f64(TOUCH);
    let (low, high) = ((Q::ONE - &tol).sqr(), (Q::ONE + &tol).sqr());
    let mut out = Vec::new();
    for a in 0..positions.len() {
        for b in a + 1..positions.len() {
            let n = sub(&positions[b], &positions[a]);
            let d2 = dot(&n, &n);
            let r = &radii[a] + &radii[b];
            let r2 = r.sqr();
            if d2 < &low * &r2 {
                let f = |q: &Q| crate::values::number::num(to_f64(q).unwrap_or(f64::NAN));
                return Err(ContactsError::Overlap {
                    a: a + 1,
                    b: b + 1,
                    d: crate::values::number::num(to_f64(&d2).unwrap_or(f64::NAN).sqrt()),
                    r: f(&r),
                });
            }
            if d2 <= &high * &r2 {
                out.push(Contact { a, b, normal: n });
            }
        }
    }
    if out.is_empty() {
        return Err(ContactsError::None);
    }
    Ok(out)
}

/// The solved impact: the final velocities and each contact's impulse.
#[derive(Clone, Debug, PartialEq)]
pub struct Solved {
    pub fin: Vec<Vec<Q>>,
    /// `P_k`: the impulse on `b` is `P_k n_k` (in the units of `n_k`'s length).
    pub impulses: Vec<Q>,
    /// Gap rates `w_k = n_k.(v_b - v_a)` before and after (over `|n_k|` for a speed).
    pub w_in: Vec<Q>,
    pub w_fin: Vec<Q>,
    /// The impulses are one of many (the contacts are more than the bodies can feel:
    /// `rank A < m`); the final velocities are unique all the same.
    pub indeterminate: bool,
}

/// The gap rates `w_k = n_k.(v_b - v_a)`.
pub fn gap_rates(contacts: &[Contact], v: &[Vec<Q>]) -> Vec<Q> {
    contacts
        .iter()
        .map(|c| dot(&c.normal, &sub(&v[c.b], &v[c.a])))
        .collect()
}

/// `V + M^-1 J^T P`.
fn apply(masses: &[Q], v: &[Vec<Q>], contacts: &[Contact], p: &[Q]) -> Vec<Vec<Q>> {
    let mut out = v.to_vec();
    for (c, pk) in contacts.iter().zip(p) {
        if pk.is_zero() {
            continue;
        }
        for (k, nk) in c.normal.iter().enumerate() {
            let j = pk * nk;
            out[c.b][k] += &j / &masses[c.b];
            out[c.a][k] -= &j / &masses[c.a];
        }
    }
    out
}

/// `A = J M^-1 J^T`: `A_kl = sum over the bodies i of both contacts of s_ki s_li n_k.n_l /
/// m_i`, with `s = +1` for `b`, `-1` for `a`.
fn collision_matrix(masses: &[Q], contacts: &[Contact]) -> Vec<Vec<Q>> {
    let sign = |c: &Contact, i: usize| -> i8 {
        if c.b == i {
            1
        } else if c.a == i {
            -1
        } else {
            0
        }
    };
    contacts
        .iter()
        .map(|k| {
            contacts
                .iter()
                .map(|l| {
                    let nn = dot(&k.normal, &l.normal);
                    [k.a, k.b]
                        .iter()
                        .filter(|&&i| sign(l, i) != 0)
                        .fold(Q::ZERO, |s, &i| {
                            let t = &nn / &masses[i];
                            if sign(k, i) == sign(l, i) {
                                s + t
                            } else {
                                s - t
                            }
                        })
                })
                .collect()
        })
        .collect()
}

/// Newton's restitution at every contact at once (the module's LCP), solved exactly and
/// checked: every complementarity condition exactly, momentum kept, energy never created.
pub fn simultaneous(
    masses: &[Q],
    v_in: &[Vec<Q>],
    contacts: &[Contact],
    e: &Q,
) -> Result<Solved, ContactsError> {
    if e.is_negative() || *e > Q::ONE {
        return Err(ContactsError::Restitution(
            crate::values::quantity::fraction(e),
        ));
    }
    if contacts.len() > MAX_CONTACTS {
        return Err(ContactsError::TooMany(contacts.len()));
    }
    let w = gap_rates(contacts, v_in);
    let a = collision_matrix(masses, contacts);
    let q: Vec<Q> = w
        .iter()
        .map(|wk| {
            if wk.is_negative() {
                wk + e * wk
            } else {
                wk.clone()
            }
        })
        .collect();
    let p = lcp::lemke(&a, &q)?;
    lcp::check(&a, &q, &p).map_err(|b| {
        let (what, k) = match b {
            Broken::Negative(k) => ("a negative impulse", k),
            Broken::Closing(k) => ("a pair that closes", k),
            Broken::Complementarity(k) => ("an impulse at a pair that parts", k),
        };
        ContactsError::Check(format!("{what} at contact {}", k + 1))
    })?;
    let fin = apply(masses, v_in, contacts, &p);
    let w_fin = gap_rates(contacts, &fin);
    verify(masses, v_in, &fin)?;
    Ok(Solved {
        fin,
        impulses: p,
        w_in: w,
        w_fin,
        indeterminate: lcp::rank(&a) < contacts.len(),
    })
}

/// Momentum kept and energy never created, exactly.
fn verify(masses: &[Q], v_in: &[Vec<Q>], fin: &[Vec<Q>]) -> Result<(), ContactsError> {
    let momentum = |v: &[Vec<Q>]| -> Vec<Q> {
        (0..v[0].len())
            .map(|k| {
                masses
                    .iter()
                    .zip(v)
                    .fold(Q::ZERO, |s, (m, vi)| s + m * &vi[k])
            })
            .collect()
    };
    if momentum(v_in) != momentum(fin) {
        return Err(ContactsError::Check("momentum changed".into()));
    }
    if kinetic(masses, fin) > kinetic(masses, v_in) {
        return Err(ContactsError::Check("energy created".into()));
    }
    Ok(())
}

/// `KE = 1/2 sum m_i |v_i|^2`.
pub fn kinetic(masses: &[Q], v: &[Vec<Q>]) -> Q {
    masses
        .iter()
        .zip(v)
        .fold(Q::ZERO, |s, (m, vi)| s + m * dot(vi, vi))
        / Q::from(2)
}

/// The sequential answer: the final velocities, the total impulse per contact and the number
/// of two-body impacts.
#[derive(Clone, Debug, PartialEq)]
pub struct Sequential {
    pub fin: Vec<Vec<Q>>,
    pub impulses: Vec<Q>,
    pub impacts: usize,
}

/// The sequential answer: sweeps over the contacts in their order (by first body, then
/// second), each pair that approaches (`w_k < 0`) colliding alone by the two-body rule
/// `P = -(1 + e) w_k / A_kk`, until none approaches; `None` beyond [`MAX_SEQUENTIAL`]
/// impacts.
pub fn sequential(
    masses: &[Q],
    v_in: &[Vec<Q>],
    contacts: &[Contact],
    e: &Q,
) -> Result<Sequential, ContactsError> {
    let a = collision_matrix(masses, contacts);
    let mut v = v_in.to_vec();
    let mut total = vec![Q::ZERO; contacts.len()];
    let mut impacts = 0;
    loop {
        let mut any = false;
        for (k, c) in contacts.iter().enumerate() {
            let w = dot(&c.normal, &sub(&v[c.b], &v[c.a]));
            if !w.is_negative() {
                continue;
            }
            if impacts == MAX_SEQUENTIAL {
                return Err(ContactsError::Sequential);
            }
            let mut p = vec![Q::ZERO; contacts.len()];
            p[k] = -(Q::ONE + e) * &w / &a[k][k];
            v = apply(masses, &v, contacts, &p);
            total[k] += &p[k];
            impacts += 1;
            any = true;
        }
        if !any {
            verify(masses, v_in, &v)?;
            return Ok(Sequential {
                fin: v,
                impulses: total,
                impacts,
            });
        }
    }
}

/// Contacts named as pairs with their lines of impact, `'1-2 @ 30deg, 1-3 @ (1,-1)'`, for `n`
/// bodies in `dim` dimensions (bodies numbered from 1); components as typed (`typed`) or their
/// binary64 values. Returns the contacts and whether a direction was rounded (an angle).
pub fn named(
    text: &str,
    n: usize,
    dim: usize,
    typed: bool,
) -> Result<(Vec<Contact>, bool), ContactsError> {
    let items = super::typed::split_bodies(text)
        .map_err(|_| ContactsError::Form(text.trim().to_string()))?;
    let mut out: Vec<Contact> = Vec::new();
    let mut rounded = false;
    for item in items {
        let form = || ContactsError::Form(item.to_string());
        let (pair, normal) = item.split_once('@').ok_or_else(form)?;
        let (a, b) = pair.split_once('-').ok_or_else(form)?;
        let body = |s: &str| -> Result<usize, ContactsError> {
            let i: usize = s.trim().parse().map_err(|_| form())?;
            if i == 0 || i > n {
                return Err(ContactsError::NoBody(item.to_string(), i, n));
            }
            Ok(i - 1)
        };
        let (a, b) = (body(a)?, body(b)?);
        if a == b {
            return Err(ContactsError::SameBody(item.to_string()));
        }
        let given: super::pose::NormalGiven = normal.trim().parse().map_err(|_| form())?;
        let (v, r) = match given {
            super::pose::NormalGiven::Components(c) => {
                let q = |x| super::pose::q_of(x, typed);
                (c.iter().map(q).collect::<Vec<Q>>(), false)
            }
            super::pose::NormalGiven::Angle(an) => an.direction(),
            super::pose::NormalGiven::Geometry { .. } => return Err(form()),
        };
        if v.len() != dim {
            return Err(ContactsError::NormalSize(item.to_string(), v.len(), dim));
        }
        if v.iter().all(Zero::is_zero) {
            return Err(ContactsError::ZeroNormal(item.to_string()));
        }
        rounded |= r;
        // Held with the first body first: `b-a @ n` is `a-b @ -n`.
        let (a, b, v) = if a < b {
            (a, b, v)
        } else {
            (b, a, v.iter().map(|x| -x).collect())
        };
        if out.iter().any(|c| c.a == a && c.b == b) {
            return Err(ContactsError::Twice(item.to_string()));
        }
        out.push(Contact { a, b, normal: v });
    }
    Ok((out, rounded))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::{int, ratio};

    fn v2(x: i64, y: i64) -> Vec<Q> {
        vec![int(x), int(y)]
    }

    #[test]
    fn a_cradle_of_five_by_hand() {
        // Tridiagonal A (2, -1), w = (-1, 0, 0, 0), e = 1: A P = (2, 0, 0, 0), P = 2 A^-1 e1
        // = (8, 6, 4, 2)/5; v1' = 1 - 8/5 = -3/5, the others 2/5 (energy 9/25 + 4 (4/25) = 1).
        let masses = vec![int(1); 5];
        let pos: Vec<Vec<Q>> = (0..5).map(|i| v2(2 * i, 0)).collect();
        let c = touching(&pos, &vec![int(1); 5]).unwrap();
        assert_eq!(c.len(), 4);
        let mut v = vec![v2(0, 0); 5];
        v[0] = v2(1, 0);
        let s = simultaneous(&masses, &v, &c, &int(1)).unwrap();
        let two = vec![ratio(2, 5), int(0)];
        assert_eq!(s.fin[0], vec![ratio(-3, 5), int(0)]);
        assert!(s.fin[1..].iter().all(|f| *f == two));
        let seq = sequential(&masses, &v, &c, &int(1)).unwrap();
        assert_eq!(seq.impacts, 4);
        assert_eq!(seq.fin[4], v2(1, 0));
        assert!(seq.fin[..4].iter().all(|f| *f == v2(0, 0)));
    }

    #[test]
    fn overlap_and_no_contact_are_refused() {
        let r = vec![int(1), int(1)];
        assert!(matches!(
            touching(&[v2(0, 0), v2(1, 0)], &r),
            Err(ContactsError::Overlap { a: 1, b: 2, .. })
        ));
        assert_eq!(
            touching(&[v2(0, 0), v2(3, 0)], &r),
            Err(ContactsError::None)
        );
    }

    #[test]
    fn named_pairs_read_both_ways() {
        let (c, rounded) = named("2-1 @ (1,1), 1-3 @ 90deg", 3, 2, true).unwrap();
        assert!(!rounded);
        assert_eq!(
            c[0],
            Contact {
                a: 0,
                b: 1,
                normal: v2(-1, -1)
            }
        );
        assert_eq!(c[1].normal, v2(0, 1));
        assert!(matches!(
            named("1-4 @ 0deg", 3, 2, true),
            Err(ContactsError::NoBody(_, 4, 3))
        ));
        assert!(matches!(
            named("1-1 @ 0deg", 3, 2, true),
            Err(ContactsError::SameBody(_))
        ));
        assert!(matches!(
            named("1 2", 3, 2, true),
            Err(ContactsError::Form(_))
        ));
    }
}
