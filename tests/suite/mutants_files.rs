//! Every file of `src/rigid/`, `src/space/` and `src/view/` under mutation (issue 46, the
//! per-file sample `MUTANTS_PER_FILE=1 benches/mutants.sh AREA`): a test for each mutant the
//! sample missed, against values derived by hand, each with its tolerance. One submodule per
//! area, so that each test's name matches its area's filter in `benches/mutants.sh`
//! (`mutants_files::space::...` runs with `space::`).

mod space {
    use crate::common::solve_refused;

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
