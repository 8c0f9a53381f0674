//! Hostile tokens through every text input of `collide view`'s page (issue 41 §4): NaN, inf,
//! -0, 1e309, hex, digits of other scripts, empty, very long, typed into each field of the
//! two-body case, the superball stack and the plane in headless Chromium (view_tokens.py). Each
//! either greys its panel with a message naming the value, or is a value the command line takes:
//! the command the panel then shows runs with exit 0. No SVG ever holds NaN or Infinity, no page
//! or console error happens, and typing the field's own value back clears the message.

use std::path::Path;
use std::process::Command as StdCommand;

use serde_json::Value;

use crate::common::{collide, run, scratch};

/// The tokens typed into every field.
const TOKENS: [&str; 10] = [
    "NaN",
    "inf",
    "-inf",
    "-0",
    "1e309",
    "0x10",
    "\u{661}\u{662}",
    "\u{ff15}",
    "",
    "LONG",
];

/// A command as the page shows it (`collide solve -m 1,1 -v '(1,0),(0,0)' ...`), split as a
/// POSIX shell splits it: words apart at spaces, single quotes kept together.
fn words(command: &str) -> Vec<String> {
    let (mut out, mut word, mut quoted, mut any) = (Vec::new(), String::new(), false, false);
    for c in command.trim().chars() {
        match c {
            '\'' => (quoted, any) = (!quoted, true),
            ' ' if !quoted => {
                if any {
                    out.push(std::mem::take(&mut word));
                }
                any = false;
            }
            c => {
                word.push(c);
                any = true;
            }
        }
    }
    if any {
        out.push(word);
    }
    out
}

#[test]
fn page_commands_split_as_a_shell_splits_them() {
    assert_eq!(
        words("collide solve -m 1,1 -v '(1,0),(0,0)' -e -0"),
        [
            "collide",
            "solve",
            "-m",
            "1,1",
            "-v",
            "(1,0),(0,0)",
            "-e",
            "-0"
        ]
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_hostile_tokens_in_every_input_grey_the_panel_or_run_on_the_command_line() {
    let dir = scratch("tokens");
    let page = dir.join("view.html");
    collide()
        .args(["view", "-o", page.to_str().unwrap()])
        .assert()
        .success();
    let long = "9".repeat(400);
    let tokens: Vec<&str> = TOKENS
        .iter()
        .map(|t| if *t == "LONG" { long.as_str() } else { t })
        .collect();
    let file = dir.join("tokens.json");
    std::fs::write(&file, serde_json::to_string(&tokens).unwrap()).unwrap();
    let driver = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/suite/view_tokens.py");
    let out = StdCommand::new("python3")
        .arg(driver)
        .arg(&page)
        .arg(&file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "the driver failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let seen: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(seen["errors"], Value::Array(vec![]), "page errors");
    let all = seen["seen"].as_array().unwrap();
    // 6 inputs of the two-body case, 9 of the stack, 9 of the plane; each token in each.
    assert_eq!(all.len(), 24 * TOKENS.len());
    let (mut greyed, mut taken) = (0, 0);
    let mut commands = std::collections::BTreeSet::new();
    for s in all {
        let what = format!("{} = {:.40}", s["field"], s["token"]);
        assert_eq!(s["svg_bad"], 0, "{what}: NaN or Infinity in a picture");
        let state = s["state"].as_str().unwrap();
        assert!(
            !state.contains("NaN") && !state.contains("Infinity"),
            "{what}: {state}"
        );
        let error = s["error"].as_str().unwrap();
        if error.is_empty() {
            // Taken: a value the command line takes too (an optional field left empty, -0).
            assert_eq!(s["stale"], 0, "{what}: greyed without a message");
            if !state.is_empty() {
                let _: Value =
                    serde_json::from_str(state).unwrap_or_else(|e| panic!("{what}: {e}"));
            }
            commands.insert(s["command"].as_str().unwrap().to_string());
            taken += 1;
        } else {
            assert!(
                s["stale"].as_u64().unwrap() > 0,
                "{what}: {error}, not greyed"
            );
            greyed += 1;
        }
        let back = &s["back"];
        assert_eq!(
            (
                back["error"].as_str(),
                back["stale"].as_u64(),
                back["svg_bad"].as_u64()
            ),
            (Some(""), Some(0), Some(0)),
            "{what}: its own value typed back"
        );
    }
    // Measured: about 220 of 240 greyed with a message; the rest are -0 (a velocity, e, a
    // wall, gravity, a time) and an empty optional field.
    assert!(greyed >= 200, "{greyed} greyed, {taken} taken");
    for command in &commands {
        let w = words(command);
        assert_eq!(w[0], "collide", "{command}");
        let args: Vec<&str> = w[1..].iter().map(String::as_str).collect();
        let (code, _, err) = run(&args);
        // The stack's `-e -0`, `--wall-restitution -0` and `--gravity -0` were refused by the
        // command line as unknown arguments.
        assert_eq!(code, 0, "{command}: {err}");
    }
    // Last: the page's own check that its WebAssembly core and the binary agree logs an error
    // when they do not (a module not rebuilt after a change of the library: wasm/build.sh).
    let console: Vec<&Value> = seen["console"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c[0] == "error")
        .collect();
    assert!(console.is_empty(), "console errors: {console:?}");
}
