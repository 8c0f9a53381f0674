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

#[track_caller]
pub fn assert_pair(actual: [f64; 2], expected: [f64; 2], what: &str) {
    assert_close(actual[0], expected[0], REL, &format!("{what}[0]"));
    assert_close(actual[1], expected[1], REL, &format!("{what}[1]"));
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
