//! Probes for the tools some integration tests need (tests/suite/view*.rs, sweeps.rs) and sets
//! a cfg for each one found, so that a test whose tool is missing is reported as ignored (with
//! its reason) by `#[cfg_attr(not(has_...), ignore = "...")]`, never as passed. Under CI (`CI`
//! set and not empty, `false` or `0`) every cfg is set whatever is found: `.ci/run` installs the
//! tools, and a test whose tool is missing then fails. The library's code uses none of them.
//!
//! - `has_node`: Node.js (`node`), which runs the committed WebAssembly module;
//! - `has_browser`: Chromium (`COLLIDE_CHROMIUM`, default /usr/bin/chromium) and Playwright for
//!   Python;
//! - `has_polars`: Polars for Python (reads Parquet back);
//! - `has_avx2_fma`: a processor with AVX2 and FMA, building for itself (the x86-64-v3 row loop
//!   of the table engine; hardware, so not forced under CI).
//!
//! Cargo reruns this when `CI` or `COLLIDE_CHROMIUM` changes (not `PATH`: maturin runs Cargo with
//! its own, and the library would build twice in CI); a tool installed since the last build is
//! seen after `touch build.rs`.

use std::path::Path;
use std::process::{Command, Stdio};

fn runs(program: &str, args: &[&str]) -> bool {
    Command::new(program)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// Whether this processor has AVX2 and FMA and the build is for it (the host).
fn avx2_fma() -> bool {
    let native = std::env::var("HOST").ok() == std::env::var("TARGET").ok();
    #[cfg(target_arch = "x86_64")]
    {
        native
            && std::arch::is_x86_feature_detected!("avx2")
            && std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = native;
        false
    }
}

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    for var in ["CI", "COLLIDE_CHROMIUM"] {
        println!("cargo::rerun-if-env-changed={var}");
    }
    // Only the tests read these: the WebAssembly module (wasm/build.sh) is built without them,
    // so its bytes do not depend on the tools of the machine that builds it.
    if std::env::var("TARGET").is_ok_and(|t| t.starts_with("wasm32")) {
        return;
    }
    let ci = std::env::var("CI").is_ok_and(|v| !v.is_empty() && v != "false" && v != "0");
    let chromium = std::env::var("COLLIDE_CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into());
    let tools = [
        ("has_node", runs("node", &["--version"])),
        (
            "has_browser",
            Path::new(&chromium).exists() && runs("python3", &["-c", "import playwright.sync_api"]),
        ),
        ("has_polars", runs("python3", &["-c", "import polars"])),
    ];
    println!("cargo::rustc-check-cfg=cfg(has_avx2_fma)");
    if avx2_fma() {
        println!("cargo::rustc-cfg=has_avx2_fma");
    }
    for (cfg, found) in tools {
        println!("cargo::rustc-check-cfg=cfg({cfg})");
        if ci || found {
            println!("cargo::rustc-cfg={cfg}");
        }
    }
}
