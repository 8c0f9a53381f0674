//! Solving for what a homework problem hides (issue 8): any two of `m1, m2, v1, v2, f1, f2, e`
//! given as `?`, from the two laws of lecture Sec. 1 (exact rational arithmetic):
//!
//! - momentum: `m1 v1 + m2 v2 = m1 f1 + m2 f2`;
//! - restitution: `f2 - f1 = e (v1 - v2)`.
//!
//! Momentum is linear in each single unknown, and restitution holds no masses, so every pair of
//! unknowns is a linear problem (at most one solution, none, or infinitely many). With one
//! unknown, one law gives it and the other is checked; with none, both are checked.

use std::fmt;

use crate::values::rational::Q;
use num_traits::{One, Signed, Zero};

/// A law, as a residual of all seven values.
pub(crate) type Law<'a> = &'a dyn Fn(&[Q; 7]) -> Q;

/// A quantity of the problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Var {
    M1,
    M2,
    V1,
    V2,
    F1,
    F2,
    E,
}

impl Var {
    pub const ALL: [Var; 7] = [Var::M1, Var::M2, Var::V1, Var::V2, Var::F1, Var::F2, Var::E];

    pub fn name(self) -> &'static str {
        ["m1", "m2", "v1", "v2", "f1", "f2", "e"][self as usize]
    }

    pub(crate) fn is_mass(self) -> bool {
        matches!(self, Var::M1 | Var::M2)
    }
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why the unknowns cannot be given.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum UnknownError {
    #[error("{0} unknowns ({1}): at most two can be solved for from momentum and restitution")]
    TooMany(usize, String),
    #[error("{0}: against a wall only restitution holds, so one value can be solved for")]
    WallTooMany(String),
    #[error("no solution: {0}")]
    None(String),
    #[error("infinitely many solutions: {0}")]
    Many(String),
    #[error("the solution is unphysical: {0}")]
    Unphysical(String),
}

/// A solved problem: every value, which were unknown, and the residuals of the laws not used to
/// solve (a consistency check).
#[derive(Clone, Debug, PartialEq)]
pub struct Solved {
    pub values: [Q; 7],
    pub unknowns: Vec<Var>,
    /// `(law, residual)` for each law that was checked rather than used.
    pub checks: Vec<(&'static str, Q)>,
    /// The bodies start together (`V1 = V2`) and come apart (`f1 != f2`): an explosion or a
    /// recoil, where `e` is undefined and only momentum holds (`values[E]` means nothing).
    pub separation: bool,
    /// The body that is a wall (0 or 1), whose mass means nothing.
    pub wall: Option<usize>,
    /// One body passed through the other (`--pass-through`): only momentum holds, and `e`
    /// means nothing (`values[E]` is 0).
    pub pass_through: bool,
}

impl Solved {
    /// Whether `e` is among the values that mean something (not for a separation).
    pub fn has(&self, v: Var) -> bool {
        let wall_mass = match self.wall {
            Some(0) => Some(Var::M1),
            Some(_) => Some(Var::M2),
            None => None,
        };
        !((self.separation || self.pass_through) && v == Var::E) && Some(v) != wall_mass
    }

    pub fn get(&self, v: Var) -> &Q {
        &self.values[v as usize]
    }

    /// Whether a law checked rather than used misses (the given data contradict each other).
    pub fn inconsistent(&self) -> bool {
        self.checks.iter().any(|(_, residual)| !residual.is_zero())
    }
}

pub(crate) fn momentum(x: &[Q; 7]) -> Q {
    &x[0] * &x[2] + &x[1] * &x[3] - &x[0] * &x[4] - &x[1] * &x[5]
}

pub(crate) fn restitution(x: &[Q; 7]) -> Q {
    &x[5] - &x[4] - &x[6] * (&x[2] - &x[3])
}

/// `law` with `var` set to `t` (all else as in `x`).
fn at(law: Law, x: &[Q; 7], var: Var, t: &Q) -> Q {
    let mut y = x.clone();
    y[var as usize] = t.clone();
    law(&y)
}

/// Solves `law = 0` for `var` (the law is linear in it): `Ok(None)` when any value satisfies it.
pub(crate) fn solve_one(
    law: Law,
    x: &[Q; 7],
    var: Var,
    what: &str,
) -> Result<Option<Q>, UnknownError> {
    let b = at(law, x, var, &Q::zero());
    let a = at(law, x, var, &Q::one()) - &b;
    if a.is_zero() {
        return if b.is_zero() {
            Ok(None)
        } else {
            Err(UnknownError::None(format!(
                "{what} does not involve {var} here and does not hold"
            )))
        };
    }
    Ok(Some(-b / a))
}

/// Solves for the unknown (`None`) entries of `known`.
pub fn solve(known: [Option<Q>; 7]) -> Result<Solved, UnknownError> {
    let unknowns: Vec<Var> = Var::ALL
        .into_iter()
        .filter(|v| known[*v as usize].is_none())
        .collect();
    if unknowns.len() > 2 {
        let names: Vec<&str> = unknowns.iter().map(|v| v.name()).collect();
        return Err(UnknownError::TooMany(unknowns.len(), names.join(", ")));
    }
    let mut x: [Q; 7] = known.map(|v| v.unwrap_or_default());
    let set = |x: &mut [Q; 7], v: Var, q: Q| x[v as usize] = q;
    let many = |why: String| Err(UnknownError::Many(why));
    let mut checks = Vec::new();
    let mut separation = false;
    match unknowns.as_slice() {
        [] => {}
        [u] => {
            // One law gives it; the other is checked.
            let (law, other, lname, oname): (Law, Law, _, _) = if *u == Var::E {
                (&restitution, &momentum, "restitution", "momentum")
            } else {
                (&momentum, &restitution, "momentum", "restitution")
            };
            if *u == Var::E && starts_together(&x) {
                separation = apart(&x, "e")?;
                checks.push(("momentum", momentum(&x)));
            } else {
                match solve_one(law, &x, *u, lname)? {
                    Some(q) => set(&mut x, *u, q),
                    None => return many(format!("{lname} holds for any {u}")),
                }
                checks.push((oname, other(&x)));
            }
        }
        [a, b] if *a == Var::E || *b == Var::E => {
            let other = if *a == Var::E { *b } else { *a };
            match solve_one(&momentum, &x, other, "momentum")? {
                Some(q) => set(&mut x, other, q),
                None => return many(format!("momentum holds for any {other}")),
            }
            if starts_together(&x) {
                separation = apart(&x, "e")?;
            } else if let Some(q) = solve_one(&restitution, &x, Var::E, "restitution")? {
                set(&mut x, Var::E, q);
            }
        }
        [a, b] if a.is_mass() && b.is_mass() => {
            if !restitution(&x).is_zero() {
                return Err(UnknownError::None(
                    "restitution does not hold for the given velocities".into(),
                ));
            }
            // m1 (v1 - f1) + m2 (v2 - f2) = 0 fixes only the ratio.
            let ratio = if (&x[2] - &x[4]).is_zero() {
                "any".to_string()
            } else {
                crate::values::quantity::fraction(&((&x[5] - &x[3]) / (&x[2] - &x[4])))
            };
            return many(format!(
                "momentum fixes only the ratio m1/m2 = {ratio}; give one mass"
            ));
        }
        [a, b] if a.is_mass() || b.is_mass() => {
            let (mass, vel) = if a.is_mass() { (*a, *b) } else { (*b, *a) };
            match solve_one(&restitution, &x, vel, "restitution")? {
                Some(q) => set(&mut x, vel, q),
                None => {
                    return many(format!(
                        "with e = 0, restitution does not fix {vel}, and momentum fixes only {mass} {vel}"
                    ));
                }
            }
            match solve_one(&momentum, &x, mass, "momentum")? {
                Some(q) => set(&mut x, mass, q),
                None => return many(format!("momentum holds for any {mass}")),
            }
        }
        [a, b] => {
            // Two velocities: momentum and restitution are linear in both.
            let (a, b) = (*a, *b);
            match linear_pair(&x, (a, b), &momentum, &restitution) {
                Some((p, q)) => {
                    set(&mut x, a, p);
                    set(&mut x, b, q);
                }
                None => {
                    return many(format!(
                        "momentum and restitution do not fix {a} and {b} separately"
                    ));
                }
            }
        }
        _ => unreachable!("more than two unknowns were refused above"),
    }
    if unknowns.is_empty() {
        checks.push(("momentum", momentum(&x)));
        checks.push(("restitution", restitution(&x)));
    }
    // Physical: positive masses, e >= 0 (above 1: superelastic, energy released).
    positive_masses(&x)?;
    let e = &x[Var::E as usize];
    if e.is_negative() {
        return Err(UnknownError::Unphysical(format!(
            "e = {} < 0: the bodies would pass through each other (one passing through the \
             other, a bullet through a block, is --pass-through)",
            crate::values::quantity::fraction(e)
        )));
    }
    Ok(Solved {
        values: x,
        unknowns,
        checks,
        separation,
        wall: None,
        pass_through: false,
    })
}

/// Refuses a mass that is not positive (a solved one can be anything).
pub(crate) fn positive_masses(x: &[Q; 7]) -> Result<(), UnknownError> {
    for m in [Var::M1, Var::M2] {
        if !x[m as usize].is_positive() {
            return Err(UnknownError::Unphysical(format!(
                "{m} = {} is not a positive mass: no bodies collide that way",
                crate::values::quantity::fraction(&x[m as usize])
            )));
        }
    }
    Ok(())
}

/// Solves two laws for two unknowns `(a, b)` in which both are jointly linear (no product `a b`
/// term: checked), by Cramer's rule; `None` when they do not fix both (a zero determinant, or
/// a product term).
pub(crate) fn linear_pair(x: &[Q; 7], (a, b): (Var, Var), l1: Law, l2: Law) -> Option<(Q, Q)> {
    let z = |law: Law, p: &Q, q: &Q| {
        let mut y = x.clone();
        y[a as usize] = p.clone();
        y[b as usize] = q.clone();
        law(&y)
    };
    let (zero, one) = (Q::zero(), Q::one());
    let coeffs = |law: Law| {
        let c = z(law, &zero, &zero);
        let (p, q) = (z(law, &one, &zero) - &c, z(law, &zero, &one) - &c);
        let bilinear = z(law, &one, &one) - &p - &q - &c;
        (p, q, c, bilinear.is_zero())
    };
    let (p1, q1, c1, linear1) = coeffs(l1);
    let (p2, q2, c2, linear2) = coeffs(l2);
    let det = &p1 * &q2 - &q1 * &p2;
    if det.is_zero() || !(linear1 && linear2) {
        return None;
    }
    Some((
        (&q1 * &c2 - &q2 * &c1) / &det,
        (&p2 * &c1 - &p1 * &c2) / &det,
    ))
}

/// `V1 = V2`: no relative velocity at IN, so restitution cannot say anything about FIN.
pub(crate) fn starts_together(x: &[Q; 7]) -> bool {
    x[Var::V1 as usize] == x[Var::V2 as usize]
}

/// With `V1 = V2`, whether the bodies come apart (`f1 != f2`): an explosion or recoil, where
/// `e` is undefined; if they stay together nothing happened and `e` is not determined. Either
/// piece may end up on the right (`line::order`: the one faster in `+x`), whichever was typed
/// first.
pub(crate) fn apart(x: &[Q; 7], what: &str) -> Result<bool, UnknownError> {
    if x[Var::F1 as usize] == x[Var::F2 as usize] {
        return Err(UnknownError::Many(format!(
            "V1 = V2 and f1 = f2: the bodies never meet or push apart, so {what} is not determined"
        )));
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Option<Q> {
        (s != "?").then(|| s.parse::<crate::values::number::Number>().unwrap().exact())
    }

    /// m1 m2 v1 v2 f1 f2 e, "?" for unknown.
    fn run(vals: [&str; 7]) -> Result<Solved, UnknownError> {
        solve(vals.map(q))
    }

    fn show(s: &Solved, v: Var) -> String {
        crate::values::quantity::fraction(s.get(v))
    }

    /// Every pair of unknowns of a problem whose values (m1 m2 v1 v2 f1 f2 e) are `full` comes
    /// back as `full`; two unknown masses give infinitely many, with their ratio `ratio`.
    fn every_pair(full: [&str; 7], ratio: &str) {
        for i in 0..7 {
            for j in (i + 1)..7 {
                let mut p = full;
                p[i] = "?";
                p[j] = "?";
                let (a, b) = (Var::ALL[i], Var::ALL[j]);
                match run(p) {
                    Ok(s) => assert_eq!(
                        (show(&s, a), show(&s, b)),
                        (full[i].to_string(), full[j].to_string()),
                        "{a}, {b}"
                    ),
                    Err(UnknownError::Many(m)) => {
                        assert!(a.is_mass() && b.is_mass(), "{a}, {b}: {m}");
                        assert!(m.contains(&format!("m1/m2 = {ratio}")), "{m}");
                    }
                    Err(e) => panic!("{a}, {b}: {e}"),
                }
            }
        }
    }

    #[test]
    fn every_pair_of_unknowns_in_case_a() {
        // Fig. 1.3, elastic: m = (4, 1), V = (60, 10), FIN = (40, 90), e = 1.
        every_pair(["4", "1", "60", "10", "40", "90", "1"], "4");
    }

    #[test]
    fn every_pair_of_unknowns_in_case_b_ka_whump() {
        // Fig. 2.3, e = 2/3: m = (6, 1), V = (3, -4), FIN = (4/3, 6).
        every_pair(["6", "1", "3", "-4", "4/3", "6", "2/3"], "6");
    }

    #[test]
    fn one_unknown_is_a_consistency_check() {
        // f2 from momentum; restitution checked: it holds exactly for e = 1.
        let s = run(["4", "1", "60", "10", "40", "?", "1"]).unwrap();
        assert_eq!(show(&s, Var::F2), "90");
        assert_eq!(s.checks, vec![("restitution", Q::zero())]);
        // With e = 1/2 given, momentum gives f2 = 90 but restitution misses by 25.
        let s = run(["4", "1", "60", "10", "40", "?", "1/2"]).unwrap();
        assert_eq!(crate::values::quantity::fraction(&s.checks[0].1), "25");
    }

    #[test]
    fn none_many_and_unphysical_say_why() {
        // Too many.
        assert!(matches!(
            run(["?", "?", "?", "10", "40", "90", "1"]),
            Err(UnknownError::TooMany(3, _))
        ));
        // Equal IN velocities: e is not determined.
        let e = run(["1", "1", "5", "5", "5", "5", "?"]).unwrap_err();
        assert!(
            matches!(e, UnknownError::Many(_)) || matches!(e, UnknownError::None(_)),
            "{e}"
        );
        // Negative mass: FIN (40, 90) from m1 = 4, V = (60, 10) needs m2 = 1; asking for FIN (70, 90)...
        let e = run(["4", "?", "60", "10", "70", "90", "?"]).unwrap_err();
        assert!(
            matches!(e, UnknownError::Unphysical(_)) && e.to_string().contains("m2"),
            "{e}"
        );
        // Bodies passing through each other: f1 > f2 after an approach.
        // e = 3/2 is superelastic, not refused: FIN (35, 110) releases energy.
        let s = run(["4", "1", "60", "10", "?", "?", "1.5"]).unwrap();
        assert_eq!(
            (show(&s, Var::F1), show(&s, Var::F2)),
            ("35".into(), "110".into())
        );
        let e = run(["4", "1", "60", "10", "55", "30", "?"]).unwrap_err();
        assert!(e.to_string().contains("pass through each other"), "{e}");
        // A rifle (4 kg) fires a 10 g bullet from rest, the bullet typed first at +550 m/s:
        // 0 = 0.01 * 550 + 4 f2, f2 = -5.5/4 = -11/8 (the bullet ends up on the right).
        let s = run(["0.01", "4", "0", "0", "550", "?", "?"]).unwrap();
        assert!(s.separation);
        assert_eq!(show(&s, Var::F2), "-11/8");
        // e = 0 with a mass and an IN velocity unknown: restitution cannot fix the velocity.
        let e = run(["?", "1", "?", "10", "50", "50", "0"]).unwrap_err();
        assert!(matches!(e, UnknownError::Many(_)), "{e}");
    }
}
