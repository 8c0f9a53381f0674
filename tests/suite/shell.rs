//! `collide completions` and `collide man`: generated from the clap definition, so they must
//! name every subcommand; the man page must render.

use crate::common;

use common::{collide, stdout};

const SUBCOMMANDS: [&str; 12] = [
    "solve",
    "scene",
    "accuracy",
    "frames",
    "sweep",
    "batch",
    "track",
    "contact",
    "pi",
    "plot",
    "completions",
    "man",
];

#[test]
fn every_shell_completes_every_subcommand_and_value() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let script = stdout(&["completions", shell]);
        for sub in SUBCOMMANDS {
            assert!(script.contains(sub), "{shell}: no {sub}");
        }
        // Value enums are completed too (PowerShell's and Elvish's scripts list flags only).
        if ["bash", "zsh", "fish"].contains(&shell) {
            for value in ["hunt-crossley", "implicit-midpoint", "minkowski", "jsonl"] {
                assert!(script.contains(value), "{shell}: no {value}");
            }
        }
    }
    let out = collide().args(["completions", "tcsh"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bash"));
}

#[test]
fn the_man_page_renders_with_every_subcommand() {
    let page = stdout(&["man"]);
    assert!(
        page.starts_with(".ie") || page.starts_with(".TH"),
        "{}",
        &page[..80]
    );
    for sub in SUBCOMMANDS {
        assert!(
            page.contains(&format!(".SH \"COLLIDE {}\"", sub.to_uppercase())),
            "no section for {sub}"
        );
    }
    for section in ["EXIT STATUS", "SCENES", "EXAMPLES"] {
        assert!(page.contains(&format!(".SH \"{section}\"")), "no {section}");
    }
    // Render it where groff is installed (man -l uses it); the text must come out whole.
    let groff = std::process::Command::new("groff")
        .args(["-man", "-Tutf8", "-ww"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn();
    if let Ok(mut child) = groff {
        use std::io::Write;
        child
            .stdin
            .take()
            .unwrap()
            .write_all(page.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success());
        // Drop grotty's overstriking (bold: "C\x08C").
        let mut text = String::new();
        for c in String::from_utf8_lossy(&out.stdout).chars() {
            if c == '\x08' {
                text.pop();
            } else {
                text.push(c);
            }
        }
        let text = text.replace("\n", " ");
        assert!(text.contains("COLLIDE CONTACT") && text.contains("EXIT STATUS"));
        let warnings = String::from_utf8_lossy(&out.stderr);
        assert!(warnings.trim().is_empty(), "groff warns: {warnings}");
    }
}

#[test]
fn help_ends_with_examples() {
    for sub in SUBCOMMANDS.iter().filter(|s| **s != "man") {
        let help = stdout(&[sub, "--help"]);
        assert!(
            help.contains("Examples:\n  collide "),
            "{sub} --help has no examples"
        );
    }
}
