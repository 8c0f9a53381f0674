//! Error against run time of the ODE of friction in space (`rigid::slip`): each tolerance's run
//! timed (the fastest of several), its impulse compared with a reference, beside the error
//! estimate collide reports (the run against one at a hundredth of the tolerance).
//! `cargo bench --bench rigid`.
//!
//! - planar: a slip that stays on one line, so Routh's exact closed form is the reference;
//! - turning: a slip whose direction turns in the tangent plane until it sticks; the reference is
//!   a run at the smallest tolerance (1e-13).

use std::time::Instant;

use collide::rigid::laws::Law;
use collide::rigid::routh;
use collide::rigid::slip::Slip;
use collide::values::rational::{Q, int, ratio, to_f64};

fn fastest(s: &Slip, rtol: f64) -> (f64, collide::rigid::slip::Run) {
    let mut best = f64::INFINITY;
    let mut run = None;
    let reps = 20;
    for _ in 0..reps {
        let t = Instant::now();
        let r = s.run(rtol).expect("the ODE runs");
        best = best.min(t.elapsed().as_secs_f64());
        run = Some(r);
    }
    (best, run.expect("ran"))
}

fn error(p: [f64; 3], reference: [f64; 3]) -> f64 {
    let d = (0..3).fold(0.0f64, |s, k| s.hypot(p[k] - reference[k]));
    d / reference.iter().fold(0.0f64, |s, x| s.hypot(*x))
}

fn ladder(name: &str, s: &Slip, reference: [f64; 3]) {
    println!("\n{name}: reference impulse {reference:?}");
    println!(
        "{:>8}  {:>9}  {:>9}  {:>6}  {:>9}",
        "rtol", "error", "estimate", "steps", "time"
    );
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
        let (secs, run) = fastest(s, rtol);
        let estimate = s
            .estimated(rtol * 100.0)
            .map(|e| e.error)
            .unwrap_or(f64::NAN);
        println!(
            "{rtol:>8.0e}  {:>9.1e}  {:>9.1e}  {:>6}  {:>6.1} us",
            error(run.impulse, reference),
            estimate,
            run.steps,
            secs * 1e6
        );
    }
}

fn main() {
    // Planar: K in (n, t1, t2) with the slip along t1 and no coupling to t2; Routh in exact
    // rationals on the (n, t1) block gives the impulse.
    let planar = Slip {
        k: [[2.0, 0.5, 0.0], [0.5, 1.0, 0.0], [0.0, 0.0, 3.0]],
        w0: [3.0, 1.0, 0.0],
        mu: 1.0,
        e: 0.5,
        law: Law::Poisson,
    };
    let k: [[Q; 2]; 2] = [[int(2), ratio(1, 2)], [ratio(1, 2), int(1)]];
    let r = routh::solve(&k, &[int(3), int(1)], &int(1), Law::Poisson, &ratio(1, 2))
        .expect("Routh solves it");
    let f = |q: &Q| to_f64(q).expect("finite");
    ladder(
        "planar slip to stick (Routh exact)",
        &planar,
        [f(&r.impulse[0]), f(&r.impulse[1]), 0.0],
    );
    let turning = Slip {
        k: [[2.0, 0.3, -0.2], [0.3, 1.5, 0.4], [-0.2, 0.4, 1.0]],
        w0: [3.0, 1.0, 2.0],
        mu: 0.5,
        e: 0.7,
        law: Law::Stronge,
    };
    let reference = turning.run(1e-13).expect("reference").impulse;
    ladder("turning slip (reference: rtol 1e-13)", &turning, reference);
}
