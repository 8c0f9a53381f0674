//! Shared test helpers: the tolerances every physics test states, and a way to run the binary.
#![allow(dead_code)]

use assert_cmd::Command;

/// Lecture numbers are exact small rationals; binary64 results must match them to a few ulps.
pub const REL: f64 = 4.0 * f64::EPSILON;

/// `|actual - expected| <= rel * |expected|` (exact equality for an expected 0), with a message.
#[track_caller]
pub fn assert_close(actual: f64, expected: f64, rel: f64, what: &str) {
    let ok = (actual - expected).abs() <= rel * expected.abs();
    assert!(
        ok,
        "{what}: expected {expected}, got {actual} (rel tolerance {rel:e})"
    );
}

/// `actual == expected` exactly: for values exact in binary64 (the lecture's 40, 90, 7250), or
/// the correctly rounded value of an exact one, where the README claims correct rounding.
#[track_caller]
pub fn assert_exact(actual: f64, expected: f64, what: &str) {
    assert!(
        actual == expected,
        "{what}: expected exactly {expected:e}, got {actual:e}"
    );
}

/// Both entries exactly (see [`assert_exact`]).
#[track_caller]
pub fn assert_pair(actual: [f64; 2], expected: [f64; 2], what: &str) {
    assert_exact(actual[0], expected[0], &format!("{what}[0]"));
    assert_exact(actual[1], expected[1], &format!("{what}[1]"));
}

/// `|actual - expected| <= n` ulps of `expected`, an ulp being
/// `2^max(floor(log2 |expected|) - 52, -1074)` as in the README's accuracy table
/// ([`collide::accuracy::ulp`]: the spacing of binary64, subnormal below `2^-970`).
#[track_caller]
pub fn assert_ulps(actual: f64, expected: f64, n: f64, what: &str) {
    let ulp = collide::accuracy::ulp(expected);
    assert!(
        (actual - expected).abs() <= n * ulp,
        "{what}: expected {expected:e} to {n} ulps, got {actual:e} ({:.2} ulps)",
        (actual - expected).abs() / ulp
    );
}

/// The nearest binary64 to an exact rational (ties to even).
pub fn rounded(q: &collide::values::rational::Q) -> f64 {
    collide::values::rational::to_f64(q).expect("within binary64")
}

/// The exact value of a binary64.
pub fn exact(x: f64) -> collide::values::rational::Q {
    collide::values::rational::from_f64(x)
}

/// Runs `collide args` whatever its exit status: (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = collide().args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The binary, with text as wide as it comes (`COLUMNS` very large): these tests read what is
/// printed, not how it is laid out, and a message wrapped to 80 columns splits the phrases they
/// look for. Layout is tested at the default width by `width.rs` and the guide's examples
/// (`readme.rs`), which use [`collide_at_default_width`].
pub fn collide() -> Command {
    let mut c = collide_at_default_width();
    c.env("COLUMNS", "100000");
    c
}

/// The binary as a user runs it: `COLUMNS` unset, so text fits 80 columns.
pub fn collide_at_default_width() -> Command {
    let mut c = Command::cargo_bin("collide").expect("the collide binary is built");
    c.env_remove("COLUMNS");
    c
}

/// proptest configuration: `cases` cases from a fixed seed, so CI is reproducible; set
/// `COLLIDE_PROPTEST_SEED` to explore others.
pub fn proptest_config(cases: u32) -> proptest::test_runner::Config {
    let seed = std::env::var("COLLIDE_PROPTEST_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2026);
    proptest::test_runner::Config {
        cases,
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..proptest::test_runner::Config::default()
    }
}

/// A seed taken from the clock (or `COLLIDE_PROPTEST_SEED`), printed to stderr, which the test
/// harness shows with a failure, so the failing run can be replayed.
pub fn fresh_seed() -> u64 {
    let seed = std::env::var("COLLIDE_PROPTEST_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| {
            let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH);
            now.map_or(0, |d| d.as_nanos() as u64 ^ u64::from(std::process::id()))
        });
    eprintln!("proptest seed {seed} (COLLIDE_PROPTEST_SEED={seed} replays this run)");
    seed
}

/// proptest configuration for a run that draws new cases each time: `cases` cases from a seed
/// taken from the clock (or `COLLIDE_PROPTEST_SEED`). The seed goes to stderr, which the test
/// harness prints with a failure, so the failing run can be replayed.
pub fn proptest_config_fresh(cases: u32) -> proptest::test_runner::Config {
    let seed = fresh_seed();
    proptest::test_runner::Config {
        cases,
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed),
        ..proptest::test_runner::Config::default()
    }
}

/// Runs `collide args`, expects success, returns stdout.
#[track_caller]
pub fn stdout(args: &[&str]) -> String {
    let out = collide().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A folder of this test run's own (under Cargo's temporary folder for tests), made if missing.
pub fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("scratch")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `collide solve ARGS --format json` (any exit code), with the code.
pub fn solve_json(args: &[&str]) -> (i32, serde_json::Value) {
    let out = collide()
        .args([&["solve"], args, &["--format", "json"]].concat())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    (
        out.status.code().unwrap_or(-1),
        serde_json::from_str(&text).unwrap_or(serde_json::Value::Null),
    )
}

/// `collide solve ARGS`: code, stdout, stderr.
pub fn run_solve(args: &[&str]) -> (i32, String, String) {
    run(&[&["solve"], args].concat())
}

/// Exit 2, nothing on stdout, and stderr naming each of `needles`.
#[track_caller]
pub fn solve_refused(args: &[&str], needles: &[&str]) {
    let (code, out, err) = run_solve(args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty(), "{args:?}: {out}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: stderr lacks {n:?}:\n{err}");
    }
}

/// A JSON number (a test failure when it is not one).
pub fn number(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[cfg(test)]
mod tests {
    use super::assert_ulps;

    #[test]
    fn assert_ulps_measures_tiny_values_in_their_own_ulps() {
        // 1 ulp at 1e-300 is 2^-1049; next_up is one of them, a half-ulp tolerance refuses it.
        let x = 1e-300f64;
        assert_ulps(x.next_up(), x, 1.0, "next_up");
        assert!(std::panic::catch_unwind(|| assert_ulps(x.next_up(), x, 0.5, "half")).is_err());
        // A relative error of 1e-8 is some 6.0e7 ulps, never within half of one.
        let far = x * (1.0 + 1e-8);
        assert!(std::panic::catch_unwind(|| assert_ulps(far, x, 0.5, "1e-8")).is_err());
        // Subnormals: the spacing is 2^-1074.
        assert_ulps(5e-324, 1e-323, 1.0, "subnormal");
        assert!(std::panic::catch_unwind(|| assert_ulps(5e-324, 1.5e-323, 1.0, "2 ulps")).is_err());
    }
}
