//! The plane's solvers, timed (issue 25): the fast binary64 impact (`space::impact::general`,
//! double-double with an error bound, exact where the bound cannot decide) against the exact
//! form it falls back to, and a whole `collide solve` in the plane (pose, exact laws, report).
//! `cargo bench --bench plane`.

use std::hint::black_box;
use std::time::Instant;

use collide::space::impact::{bounded, by_normal_parts, exact, general};

/// Masses, velocities, line of impact, restitution.
type Case = ([f64; 2], [[f64; 2]; 2], [f64; 2], f64);

/// A small linear congruential generator: the same cases every run.
fn cases(n: usize) -> Vec<Case> {
    let mut x: u64 = 2026;
    let mut next = || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0
    };
    (0..n)
        .map(|_| {
            (
                [1.0 + next().abs() * 9.0, 10f64.powf(next() * 3.0)],
                [[next() * 10.0, next() * 10.0], [next(), next() * 10.0]],
                [next(), next()],
                next().abs(),
            )
        })
        .collect()
}

fn time<F: Fn(&Case) -> [[f64; 2]; 2]>(name: &str, cases: &[Case], f: F) {
    let start = Instant::now();
    let mut sum = 0.0;
    for c in cases {
        sum += black_box(f(c))[0][0];
    }
    let secs = start.elapsed().as_secs_f64();
    println!(
        "{name:<34} {:>8.1} ns a case, {:>6.2} M cases/s  (checksum {sum:.3e})",
        secs * 1e9 / cases.len() as f64,
        cases.len() as f64 / secs / 1e6
    );
}

fn main() {
    let many = cases(2_000_000);
    let fell_back = many
        .iter()
        .filter(|(m, v, n, e)| bounded(*m, *v, *n, *e).is_none())
        .count();
    println!(
        "exact fallbacks: {fell_back} of {} cases ({:.3}%)",
        many.len(),
        100.0 * fell_back as f64 / many.len() as f64
    );
    time("general (double-double, bounded)", &many, |(m, v, n, e)| {
        general(*m, *v, *n, *e)
    });
    time("by the normal parts (check form)", &many, |(m, v, n, e)| {
        by_normal_parts(*m, *v, *n, *e)
    });
    let few = &many[..20_000];
    time("exact rationals, rounded once", few, |(m, v, n, e)| {
        exact(*m, *v, *n, *e)
    });
}
