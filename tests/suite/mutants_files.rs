//! Every file of `src/rigid/`, `src/space/` and `src/view/` under mutation (issue 46, the
//! per-file sample `MUTANTS_PER_FILE=1 benches/mutants.sh AREA`): a test for each mutant the
//! sample missed, against values derived by hand, each with its tolerance. One submodule per
//! area, so that each test's name matches its area's filter in `benches/mutants.sh`
//! (`mutants_files::space::...` runs with `space::`).

mod space {
    use collide::space::lcp::lemke;
    use collide::values::rational::Q;
    use num_traits::Signed;

    use crate::common::{solve_refused, stdout};

    #[test]
    fn a_rational_root_of_the_energy_is_printed_exact() {
        // Equal pucks, (5, 0) onto one at rest, elastic, v1' = (4, ?): momentum gives v2' = (1,
        // -y), energy 16 + y^2 + 1 + y^2 = 25, y = +-2, rational. Under --exact both solutions
        // print as fractions, no `≈`: the parameter's root is exact (the sample of `space/
        // solve.rs` missed `:616`, `&&` to `||` in `rooted`, which marks every unknown the
        // parameter moves as approximate).
        let text = stdout(&[
            "solve",
            "-m",
            "1,1",
            "-v",
            "(5,0),(0,0)",
            "--fin",
            "(4,?),?",
            "-e",
            "1",
            "--exact",
        ]);
        for line in [
            "  v1' = (4, 2) = ",
            "  v2' = (1, -2) = ",
            "  v1' = (4, -2) = ",
        ] {
            assert!(text.contains(line), "{line:?} in\n{text}");
        }
        assert!(!text.contains('≈'), "{text}");
    }

    /// `A x = b` by Gaussian elimination in rationals; `None` when `A` is singular.
    fn solve_exact(mut a: Vec<Vec<Q>>, mut b: Vec<Q>) -> Option<Vec<Q>> {
        let n = b.len();
        for c in 0..n {
            let p = (c..n).find(|&r| a[r][c] != Q::ZERO)?;
            a.swap(c, p);
            b.swap(c, p);
            let (pivot_row, pivot_b) = (a[c].clone(), b[c].clone());
            for (r, (row, br)) in a.iter_mut().zip(b.iter_mut()).enumerate() {
                if r != c && row[c] != Q::ZERO {
                    let f = row[c].clone() / pivot_row[c].clone();
                    for (x, p) in row.iter_mut().zip(&pivot_row).skip(c) {
                        *x -= f.clone() * p.clone();
                    }
                    *br -= f * pivot_b.clone();
                }
            }
        }
        Some((0..n).map(|i| b[i].clone() / a[i][i].clone()).collect())
    }

    #[test]
    fn lemke_matches_the_enumerated_answer_of_positive_definite_problems() {
        // For a positive definite A, LCP(q, A) (y = q + A z >= 0, z >= 0, z.y = 0) has exactly
        // one solution (Cottle, Pang & Stone, theorem 3.3.7), found here by trying every
        // support S: z_S = -A_SS^-1 q_S, z = 0 elsewhere, kept when z >= 0 and y >= 0. Lemke's
        // method must return it exactly. 300 problems A = B B^T + I, B and q small integers
        // (m = 2 to 5), from a fixed linear congruential sequence; on such paths a z variable
        // leaves the basis and its complement w enters (`lcp.rs`, `leaving - m`: the mutant
        // `leaving + m` names no column and was missed by the per-file sample).
        let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = |n: i64| {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((seed >> 33) as i64).rem_euclid(2 * n + 1) - n
        };
        for case in 0..300 {
            let m = 2 + case % 4;
            let b: Vec<Vec<i64>> = (0..m).map(|_| (0..m).map(|_| next(3)).collect()).collect();
            let a: Vec<Vec<Q>> = (0..m)
                .map(|i| {
                    (0..m)
                        .map(|j| {
                            let dot: i64 = (0..m).map(|k| b[i][k] * b[j][k]).sum();
                            Q::from(dot + i64::from(i == j))
                        })
                        .collect()
                })
                .collect();
            let q: Vec<Q> = (0..m).map(|_| Q::from(next(6))).collect();
            let mut found = Vec::new();
            for support in 0u32..(1 << m) {
                let s: Vec<usize> = (0..m).filter(|&i| support & (1 << i) != 0).collect();
                let sub = s
                    .iter()
                    .map(|&i| s.iter().map(|&j| a[i][j].clone()).collect());
                let rhs = s.iter().map(|&i| -q[i].clone()).collect();
                let zs = solve_exact(sub.collect(), rhs).expect("A_SS is positive definite");
                let mut z = vec![Q::ZERO; m];
                for (&i, v) in s.iter().zip(zs) {
                    z[i] = v;
                }
                let y: Vec<Q> = (0..m)
                    .map(|i| (0..m).fold(q[i].clone(), |t, j| t + a[i][j].clone() * z[j].clone()))
                    .collect();
                if z.iter().chain(&y).all(|x| !x.is_negative()) {
                    found.push(z);
                }
            }
            found.sort();
            found.dedup();
            assert_eq!(found.len(), 1, "case {case}: {found:?}");
            let z = lemke(&a, &q).unwrap_or_else(|e| panic!("case {case}: {e}"));
            assert_eq!(z, found[0], "case {case}: A = {a:?}, q = {q:?}");
        }
    }

    #[test]
    fn a_position_of_the_wrong_size_names_its_body_from_1() {
        // `read_positions` (balls.rs) names the body of a position whose components do not
        // match the velocities' by `i + 1`, i its index from 0: body 2 here (three components
        // in the plane). The mutant `i - 1` names body 0 (and for body 1 overflows: a panic in
        // a build with overflow checks, body 18446744073709551615 without).
        for (positions, body) in [("(0,0),(2,0,0)", "body 2"), ("(0,0,0),(2,0)", "body 1")] {
            solve_refused(
                &[
                    "-m",
                    "1,1",
                    "-v",
                    "(1,0),(0,0)",
                    "--positions",
                    positions,
                    "--radii",
                    "1,1",
                ],
                &[&format!("of {body} has 3 components, the velocities 2")],
            );
        }
    }
}

mod view {
    use serde_json::{Value, json};

    use crate::view::ask;

    /// A pair of numbers of an answer's JSON.
    fn pair(v: &Value) -> [f64; 2] {
        [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
    }

    #[test]
    fn the_rail_picture_s_energies_are_fig_1_3_s() {
        // The rail panel's energy bars (`kinetic` in two_body.rs), which only the browser tests
        // read otherwise (the area's filter skips them): Fig. 1.3, M = (4, 1), IN = (60, 10),
        // e = 1, FIN = (40, 90) (physics.md). Each body's 1/2 M_i V_i^2, computed as
        // P_i (V_i / 2): IN (4 60 30, 1 10 5) = (7200, 50), FIN (4 40 20, 1 90 45) = (3200,
        // 4050); every product an integer below 2^53, exact in binary64, so compared exactly.
        // The mutant `P_1 / (V_1 / 2)` (body 1's product) gives 240 / 30 = 8 before and 160 /
        // 20 = 8 after.
        let a = ask(
            json!({"op": "solve", "m1": "4", "m2": "1", "v1": "60", "v2": "10",
                           "e": "1"}),
        );
        assert_eq!(a["ok"], true, "{a}");
        let k = &a["picture"]["kinetic"];
        assert_eq!(pair(&k["in"]), [7200.0, 50.0], "{k}");
        assert_eq!(pair(&k["fin"]), [3200.0, 4050.0], "{k}");
    }
}

mod rigid {
    use collide::rigid::laws::{Law, Mode, Tangential};
    use collide::values::rational::{Q, int, ratio};

    use crate::common::solve_refused;
    use crate::rigid_ode::on_floor;

    #[test]
    fn a_normal_of_any_length_joins_and_grips_the_same() {
        // The floor case of `rigid_ode::on_floor` (m = 1, I = 1/3 centred at (0, 1), touching
        // at (1/2, 0), v = (0, -1), omega = 1: w = (1, -1/2), K = [[4, 3/2], [3/2, 7/4]], K^-1 =
        // [[7, -6], [-6, 16]]/19) with its normal (0, -1) and (0, -2). Bodies that join: P =
        // K^-1 w = (10/19, -14/19), all of it compression, P.n / n.n = 14/19 and 7/19 (times |n|
        // in the reports: 14/19). Garwin's rough contact with beta = 0, e = 1/2 (no limit): w' =
        // -e (n.w / n.n) n = (0, 1/4), P = K^-1 (1, -3/4) = (23/38, -18/19), and the contact
        // does not slip after: stick. The sample of every mutant of `rigid/impact.rs` (sixth)
        // missed `:218` (`/` to `*` in the joined compression) and `:276` (`/` to `*` in the
        // slip after a rough contact): both are the same as the right code when |n| = 1.
        for (n, compression) in [(int(-1), ratio(14, 19)), (int(-2), ratio(7, 19))] {
            let posed = |tangential| {
                let mut p = on_floor(2, None, tangential, Law::Poisson, int(0));
                p.pair.contact.normal = vec![Q::ZERO, n.clone()];
                p
            };
            let o = collide::rigid::solve(posed(Tangential::Join)).unwrap();
            assert_eq!(o.impact.impulse, vec![ratio(10, 19), ratio(-14, 19)], "{n}");
            assert_eq!(o.impact.compression, compression, "{n}");
            assert_eq!(o.compression_impulse(), ratio(14, 19), "{n}");
            let rough = Tangential::Rough {
                beta: Q::ZERO,
                mu: None,
            };
            let o = collide::rigid::solve(posed(rough)).unwrap();
            assert_eq!(o.impact.impulse, vec![ratio(23, 38), ratio(-18, 19)], "{n}");
            assert_eq!(o.impact.mode, Mode::Stick, "{n}");
        }
    }

    #[test]
    fn a_round_target_has_no_end_to_pivot_at() {
        // `--pivot end` is the end of a rod, door or box (homework.rs, `Homework::pose`); a disk
        // or sphere has none and is refused by name. The mutant that drops the guard pivots a
        // disk at (0, -R), a point of its rim, and solves (missed by the per-file sample of
        // `MUTANTS_PER_FILE=1`: no test gave a round target `--pivot end`).
        for shape in ["disk", "sphere"] {
            solve_refused(
                &[
                    "-m",
                    "1,2",
                    "-v",
                    "1,0",
                    "--target",
                    &format!("{shape} 1"),
                    "--pivot",
                    "end",
                    "--hit-at",
                    "1/2",
                ],
                &[&format!(
                    "--pivot end is an end of a rod, door or box; a {shape} takes centre"
                )],
            );
        }
    }
}
