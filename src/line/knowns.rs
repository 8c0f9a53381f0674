//! Knowns a problem gives beyond masses, velocities and restitution (issue 27 §1), and the laws
//! they bring, solved exactly:
//!
//! - `--pass-through`: one body passes through the other (a bullet through a block). The
//!   collision is a perforation, not a contact: restitution is no law, only momentum holds, and
//!   the relative velocity keeps its sign, `(f1 - f2)(v1 - v2) > 0`, at most as large as before
//!   (the energy lost in the two bodies, `1/2 mu ((v1 - v2)^2 - (f1 - f2)^2)`, is not negative).
//! - `--impulse J`, the impulse on body 2: `J = m2 (f2 - v2)` (law `impulse2`), and by
//!   momentum `-J = m1 (f1 - v1)` (`impulse1`). With it these two laws replace momentum (their
//!   sum), so one more value can be unknown.
//!
//! - `--total-mass M`: `m1 + m2 = M` (law `total mass`) fixes one mass given as `?`.
//!
//! Every law is linear in each single value, so the unknowns are found one law at a time (a law
//! with one unknown left gives it), then, for what remains, two laws in two unknowns by Cramer's
//! rule; laws left over are checked.

use num_traits::Signed;

use crate::line::unknowns::{
    Law, Solved, UnknownError, Var, apart, linear_pair, momentum, positive_masses, restitution,
    solve as solve_two_laws, solve_one, starts_together,
};
use crate::values::quantity::fraction;
use crate::values::rational::Q;

/// The laws beyond momentum and restitution a problem brings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Laws {
    /// One body passes through the other: restitution is no law (`e` means nothing).
    pub pass_through: bool,
    /// The impulse on body 2, `J = m2 (f2 - v2) = -m1 (f1 - v1)`, in the case's units.
    pub impulse: Option<Q>,
    /// The total mass `m1 + m2`, in the case's units (`--total-mass`).
    pub total_mass: Option<Q>,
}

/// A law with its name and the values it holds.
struct Named<'a> {
    name: &'static str,
    vars: &'static [Var],
    law: Law<'a>,
}

/// Solves for the unknown (`None`) entries of `known` under `laws` (with no extra law, as
/// `unknowns::solve`). With `pass_through`, `known[E]` is ignored.
pub fn solve(known: [Option<Q>; 7], laws: &Laws) -> Result<Solved, UnknownError> {
    if *laws == Laws::default() {
        return solve_two_laws(known);
    }
    let j = laws.impulse.clone().unwrap_or_default();
    let impulse_1 = |x: &[Q; 7]| &x[0] * (&x[4] - &x[2]) + &j;
    let impulse_2 = |x: &[Q; 7]| &x[1] * (&x[5] - &x[3]) - &j;
    let total = laws.total_mass.clone().unwrap_or_default();
    let total_mass = |x: &[Q; 7]| &x[0] + &x[1] - &total;
    // Bodies that start together: restitution says nothing (e undefined, a separation).
    let together = known[Var::V1 as usize].is_some()
        && known[Var::V1 as usize] == known[Var::V2 as usize]
        && !laws.pass_through;
    let mut named: Vec<Named> = Vec::new();
    if laws.impulse.is_some() {
        named.push(Named {
            name: "impulse1",
            vars: &[Var::M1, Var::V1, Var::F1],
            law: &impulse_1,
        });
        named.push(Named {
            name: "impulse2",
            vars: &[Var::M2, Var::V2, Var::F2],
            law: &impulse_2,
        });
    } else {
        named.push(Named {
            name: "momentum",
            vars: &[Var::M1, Var::M2, Var::V1, Var::V2, Var::F1, Var::F2],
            law: &momentum,
        });
    }
    if laws.total_mass.is_some() {
        named.push(Named {
            name: "total mass",
            vars: &[Var::M1, Var::M2],
            law: &total_mass,
        });
    }
    if !laws.pass_through && !together {
        named.push(Named {
            name: "restitution",
            vars: &[Var::V1, Var::V2, Var::F1, Var::F2, Var::E],
            law: &restitution,
        });
    }
    let counted = |v: &Var| !(*v == Var::E && (laws.pass_through || together));
    let mut unknowns: Vec<Var> = Var::ALL
        .into_iter()
        .filter(|v| known[*v as usize].is_none() && counted(v))
        .collect();
    let all_unknowns = unknowns.clone();
    let names = |vs: &[Var]| vs.iter().map(|v| v.name()).collect::<Vec<_>>().join(", ");
    let laws_named = || names_of(&named);
    if unknowns.len() > named.len() {
        return Err(UnknownError::Many(format!(
            "{} unknowns ({}), and {} {} at most {}{}",
            unknowns.len(),
            names(&unknowns),
            laws_named(),
            if named.len() == 1 { "fixes" } else { "fix" },
            named.len(),
            if laws.pass_through
                && known[Var::F1 as usize].is_none()
                && known[Var::F2 as usize].is_none()
            {
                ": give a final velocity with --fin (a pass-through has no restitution to fix it)"
            } else {
                ""
            }
        )));
    }
    let mut x: [Q; 7] = known.map(|v| v.unwrap_or_default());
    let mut used = vec![false; named.len()];
    // One law at a time: a law with one unknown left gives it.
    loop {
        let mut progress = false;
        for (i, n) in named.iter().enumerate() {
            let open: Vec<Var> = n
                .vars
                .iter()
                .copied()
                .filter(|v| unknowns.contains(v))
                .collect();
            if used[i] || open.len() != 1 {
                continue;
            }
            let var = open[0];
            match solve_one(n.law, &x, var, n.name)? {
                Some(q) => x[var as usize] = q,
                None => {
                    return Err(UnknownError::Many(format!(
                        "{} holds for any {var}",
                        n.name
                    )));
                }
            }
            unknowns.retain(|v| *v != var);
            used[i] = true;
            progress = true;
        }
        if !progress {
            break;
        }
    }
    // Two left: two laws jointly linear in them.
    if let [a, b] = unknowns[..] {
        let open: Vec<usize> = (0..named.len()).filter(|i| !used[*i]).collect();
        let pair = match open[..] {
            [i, k] => linear_pair(&x, (a, b), named[i].law, named[k].law).map(|p| (p, i, k)),
            _ => None,
        };
        if let Some(((p, q), i, k)) = pair {
            x[a as usize] = p;
            x[b as usize] = q;
            used[i] = true;
            used[k] = true;
            unknowns.clear();
        }
    }
    if !unknowns.is_empty() {
        return Err(UnknownError::Many(format!(
            "{} do not fix {} separately",
            laws_named(),
            names(&unknowns)
        )));
    }
    let checks = named
        .iter()
        .zip(&used)
        .filter(|(_, used)| !**used)
        .map(|(n, _)| (n.name, (n.law)(&x)))
        .collect();
    positive_masses(&x)?;
    let mut separation = false;
    if laws.pass_through {
        passes_through(&x)?;
    } else if starts_together(&x) {
        separation = apart(&x, "e")?;
    } else if x[Var::E as usize].is_negative() {
        return Err(UnknownError::Unphysical(format!(
            "e = {} < 0: the bodies would pass through each other (one passing through the \
             other, a bullet through a block, is --pass-through)",
            fraction(&x[Var::E as usize])
        )));
    }
    Ok(Solved {
        values: x,
        unknowns: all_unknowns,
        checks,
        separation,
        wall: None,
        pass_through: laws.pass_through,
    })
}

/// `momentum`, or `impulse1, impulse2 and restitution` (`impulse1`: the impulse on body 1).
fn names_of(named: &[Named]) -> String {
    let n: Vec<&str> = named.iter().map(|n| n.name).collect();
    match n[..] {
        [one] => one.to_string(),
        _ => format!("{} and {}", n[..n.len() - 1].join(", "), n[n.len() - 1]),
    }
}

/// A pass-through: the relative velocity keeps its sign and does not grow.
fn passes_through(x: &[Q; 7]) -> Result<(), UnknownError> {
    let d_in = &x[Var::V1 as usize] - &x[Var::V2 as usize];
    let d_fin = &x[Var::F1 as usize] - &x[Var::F2 as usize];
    let show = |v: Var| fraction(&x[v as usize]);
    if d_in.is_zero() {
        return Err(UnknownError::Unphysical(format!(
            "v1 = v2 = {}: the bodies never meet, so neither passes through the other",
            show(Var::V1)
        )));
    }
    if !(&d_fin * &d_in).is_positive() {
        return Err(UnknownError::Unphysical(format!(
            "f1 = {}, f2 = {}: the body behind does not come out ahead of the other, so it does \
             not pass through (drop --pass-through: a collision with e = {})",
            show(Var::F1),
            show(Var::F2),
            fraction(&(-&d_fin / &d_in))
        )));
    }
    if d_fin.abs() > d_in.abs() {
        return Err(UnknownError::Unphysical(format!(
            "|f1 - f2| = {} > |v1 - v2| = {}: passing through would create kinetic energy",
            fraction(&d_fin.abs()),
            fraction(&d_in.abs())
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Option<Q> {
        (s != "?").then(|| s.parse::<crate::values::number::Number>().unwrap().exact())
    }

    fn run(vals: [&str; 7], laws: &Laws) -> Result<Solved, UnknownError> {
        solve(vals.map(q), laws)
    }

    fn show(s: &Solved, v: Var) -> String {
        fraction(s.get(v))
    }

    #[test]
    fn a_bullet_through_a_block() {
        // Serway & Jewett 9.?: 5.00 g at 400 m/s through a 1.00 kg block, which leaves at
        // 1.50 m/s: 0.005 400 = 0.005 f1 + 1.5, f1 = 0.5 / 0.005 = 100 m/s.
        let through = Laws {
            pass_through: true,
            impulse: None,
            total_mass: None,
        };
        let s = run(["0.005", "1", "400", "0", "?", "1.5", "?"], &through).unwrap();
        assert_eq!(show(&s, Var::F1), "100");
        assert!(s.pass_through && !s.has(Var::E) && s.checks.is_empty());
        assert_eq!(s.unknowns, vec![Var::F1]);
        // All given: momentum is checked.
        let s = run(["0.005", "1", "400", "0", "100", "1.5", "?"], &through).unwrap();
        assert_eq!(s.checks, vec![("momentum", Q::ZERO)]);
        // Two unknowns: momentum alone cannot fix them.
        let e = run(["0.005", "1", "400", "0", "?", "?", "?"], &through).unwrap_err();
        assert!(e.to_string().contains("2 unknowns (f1, f2)"), "{e}");
        // Bounced back (f1 = 1 < f2 = 3): not through.
        let e = run(["1", "1", "4", "0", "1", "?", "?"], &through).unwrap_err();
        assert!(e.to_string().contains("does not come out ahead"), "{e}");
        // Through and faster relative to the block than before: energy from nowhere.
        let e = run(["1", "1", "4", "0", "5", "?", "?"], &through).unwrap_err();
        assert!(e.to_string().contains("create kinetic energy"), "{e}");
    }

    #[test]
    fn an_impulse_replaces_an_unknown() {
        // m = (3, 1), V = (2, -1), impulse on body 2 J = 12/5: f2 = -1 + 12/5 = 7/5,
        // f1 = 2 - (12/5)/3 = 6/5, e = (7/5 - 6/5)/(2 + 1) = 1/15: three unknowns.
        let j = Laws {
            pass_through: false,
            impulse: q("12/5"),
            total_mass: None,
        };
        let s = run(["3", "1", "2", "-1", "?", "?", "?"], &j).unwrap();
        assert_eq!(
            [Var::F1, Var::F2, Var::E].map(|v| show(&s, v)),
            ["6/5", "7/5", "1/15"]
        );
        // m2 and e unknown, f2 given: J = m2 (f2 - v2) gives m2 = (12/5)/(12/5) = 1.
        let s = run(["3", "?", "2", "-1", "?", "7/5", "?"], &j).unwrap();
        assert_eq!(show(&s, Var::M2), "1");
        // Everything given but e: both impulses are checked, and hold.
        let s = run(["3", "1", "2", "-1", "6/5", "7/5", "?"], &j).unwrap();
        assert_eq!(show(&s, Var::E), "1/15");
        assert_eq!(s.checks, vec![("impulse1", Q::ZERO), ("impulse2", Q::ZERO)]);
        // An impulse of the wrong sign sends the bodies through each other: J = -1 gives
        // f2 = -2, f1 = 7/3, e = (-2 - 7/3)/3 = -13/9.
        let big = Laws {
            pass_through: false,
            impulse: q("-1"),
            total_mass: None,
        };
        let e = run(["3", "1", "2", "-1", "?", "?", "?"], &big).unwrap_err();
        assert!(e.to_string().contains("e = -13/9 < 0"), "{e}");
    }
}
