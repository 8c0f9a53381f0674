//! The hostile review of the 1D homework features (issue 27): each defect's reproduction, held
//! to the tester's hand values (derived in the comments). Binary64 results are held to `REL`
//! (4 ulps) of the exact value, or to the stated number of ulps; `--exact` ones to the fraction.

use crate::common;

use common::{REL, assert_close, number as f, run_solve as run, solve_json, solve_refused};
use serde_json::json;

#[test]
fn released_alone_is_released_with_both_final_velocities_unknown() {
    // Review #1: --released without --fin was ignored (an elastic non-collision, exit 0). A
    // 3 kg body at rest splits into 1 kg and 2 kg pieces given 48 J: mu = 2/3,
    // |f1 - f2| = sqrt(96 / (2/3)) = 12, momentum 0 = f1 + 2 f2: (-8, 4) or (8, -4) m/s,
    // exactly as --fin '?,?' gives.
    let args = ["-m", "1 kg,2 kg", "-v", "0,0 m/s", "--released", "48 J"];
    let (code, j) = solve_json(&[&args[..], &["--exact", "--show", "vectors,energy"]].concat());
    assert_eq!(code, 0, "{j}");
    let s = j["solutions"].as_array().expect("two solutions");
    assert_eq!(s[0]["fin"], json!(["-8", "4"]));
    assert_eq!(s[1]["fin"], json!(["8", "-4"]));
    for one in s {
        assert_eq!(one["energy"]["released"], "48");
    }
    let (_, with_fin) = solve_json(
        &[
            &args[..],
            &["--exact", "--fin", "?,?", "--show", "vectors,energy"],
        ]
        .concat(),
    );
    assert_eq!(j, with_fin, "the same as --fin '?,?'");
    // Bodies that do not start together: refused as with --fin '?,?' (it was "elastic: energy is
    // conserved", exit 0).
    solve_refused(
        &["-m", "1 kg,2 kg", "-v", "3 m/s,0", "--released", "5 J"],
        &["--released 5 J", "start together", "V1 != V2"],
    );
}
