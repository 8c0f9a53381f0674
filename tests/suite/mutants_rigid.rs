//! Rigid impacts that catch mutants no other test did (issue 46, the mutation samples): each case
//! derived by hand in its comments.

use crate::common::solve_refused;

/// A point mass 1 at (2, 1) onto a free box (2, 2) of mass 1 at rest, hit on its left face at
/// 1/2 above its centre, under Stronge's law with e = 1/2, `--friction ?` and a given final spin
/// of the box, exact.
fn box_hit(spin: &str) -> Vec<String> {
    [
        "-m",
        "1,1",
        "-v",
        "(2,1),0",
        "--target",
        "box (2,2)",
        "--hit-at",
        "1/2",
        "--law",
        "stronge",
        "-e",
        "1/2",
        "--friction",
        "?",
        "--fin-spin",
        spin,
        "--exact",
    ]
    .map(String::from)
    .to_vec()
}

#[test]
fn a_sticking_value_that_only_an_irrational_stronge_root_reaches_is_compared_to_a_tolerance() {
    // `friction_of` (src/rigid/unknowns.rs) checks a given value against the outcome at mu =
    // 2^30; under --exact that outcome is approximate when its Stronge root is irrational, and
    // the check must then allow for it (the mutant `given.approx && stuck.approx()` compares it
    // exactly and says no mu gives the value it has just computed).
    //
    // By hand. The box: I = (2^2 + 2^2)/12 = 2/3, contact r = (-1, 1/2) from its centre, n =
    // (1, 0), t = (0, 1). An impulse P = (P_n, P_t) on the box gives it omega' = (r x P)/I =
    // -(3/4) P_n - (3/2) P_t, and the slip g = v1 - v2 + omega2 (1/2, 1) of the contact points
    // changes by -K P, K = [[2 + 3/8, 3/4], [3/4, 2 + 3/2]] = [[19/8, 3/4], [3/4, 7/2]]; g starts
    // at (2, 1). Sliding (P_t = mu P_n) the slip stops at P_n = 1/(3/4 + 7 mu/2): a finite mu
    // first slides and then sticks (mu K_tt >= K_tn from mu = 3/14), so the work of compression
    // is a trapezoid and a triangle and Stronge's end is a square root, irrational at 2^30.
    // As mu grows the slide shrinks to a tangential impulse 2/7 alone, after which g_n = 2 -
    // (3/4)(2/7) = 25/14; sticking, g_n falls at k = 19/8 - (3/4)^2/(7/2) = 31/14, so P_c =
    // 25/31 and Stronge's end is (1 + e) P_c = 75/62 (one slope: W_r = e^2 W_c gives e P_c).
    // The tangential impulse: P_t = 2/7 - (3/14)(75/62) = 23/868, and omega2' = -(3/4)(75/62)
    // - (3/2)(23/868) = -1644/1736 = -411/434 = -0.94700460829493...; at mu = 2^30 the spin is
    // within 4e-12 of it (a slip of O(1/mu), computed to 60 digits: -0.947004608298352), well
    // inside the check's 1e-9.
    //
    // So -411/434 is the value every large mu gives: accepted as the sticking value, and then
    // refused because mu is not determined (the least mu that sticks, from the sliding fit, mu
    // = 1/78, gives -30/31: the contact there slides to the end).
    let a = box_hit(",-411/434");
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    solve_refused(
        &a,
        &[
            "more than one value fits",
            "the given value needs the contact to stick",
        ],
    );
    let (_, _, err) = crate::common::run_solve(&a);
    assert!(!err.contains("no mu gives"), "{err}");
    // A value 5e-5 away is what no mu gives: refused, naming the sticking spin at 2^30 to the
    // 11 digits it shares with -411/434.
    let a = box_hit(",-0.94705");
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    solve_refused(
        &a,
        &[
            "no mu gives omega2' = -0.94705",
            "sticking gives -0.94700460829",
        ],
    );
}
