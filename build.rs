//! Probes for the tools some integration tests need (tests/suite/view*.rs, sweeps.rs) and sets
//! a cfg for each one found, so that a test whose tool is missing is reported as ignored (with
//! its reason) by `#[cfg_attr(not(has_...), ignore = "...")]`, never as passed. Under CI (`CI`
//! set and not empty, `false` or `0`) every cfg is set whatever is found: `.ci/run` installs the
//! tools, and a test whose tool is missing then fails. The library's code uses none of them.
//!
//! - `has_node`: Node.js (`node`), which runs the committed WebAssembly module;
//! - `has_browser`: Chromium (`COLLIDE_CHROMIUM`, default /usr/bin/chromium) and Playwright for
//!   Python;
//! - `has_wasm_target`: the wasm32-unknown-unknown target of the toolchain building this;
//! - `has_polars`: Polars for Python (reads Parquet back).
//!
//! Cargo reruns this when `CI`, `PATH` or `COLLIDE_CHROMIUM` changes; a tool installed since the
//! last build is seen after `touch build.rs`.

use std::path::{Path, PathBuf};
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

fn wasm_target() -> bool {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    Command::new(rustc)
        .args(["--print", "sysroot"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| PathBuf::from(String::from_utf8_lossy(&o.stdout).trim()))
        .is_some_and(|root| root.join("lib/rustlib/wasm32-unknown-unknown").exists())
}

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    for var in ["CI", "PATH", "COLLIDE_CHROMIUM"] {
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
        ("has_wasm_target", wasm_target()),
        ("has_polars", runs("python3", &["-c", "import polars"])),
    ];
    for (cfg, found) in tools {
        println!("cargo::rustc-check-cfg=cfg({cfg})");
        if ci || found {
            println!("cargo::rustc-cfg={cfg}");
        }
    }
}
