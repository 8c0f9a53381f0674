//! How the binary behaves as a user runs it: what it leaves out, bad input (exit 2, a message
//! naming the value, nothing on stdout), scene files, JSON schema keys, closed pipes.

use crate::common;

use std::io::Write;
use std::process::{Command as StdCommand, Stdio};

use common::collide;
use predicates::prelude::*;

/// Runs `collide args`, expects exit 2 with empty stdout and a stderr mentioning every `needle`.
#[track_caller]
fn refused(args: &[&str], needles: &[&str]) {
    let out = collide().args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} printed to stdout");
    for n in needles {
        assert!(err.contains(n), "{args:?}: stderr lacks {n:?}:\n{err}");
    }
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn bad_masses() {
    refused(
        &["solve", "-m", "0,1", "-v", "1,2"],
        &["'0'", "greater than 0"],
    );
    refused(
        &["solve", "-m", "-4,1", "-v", "1,2"],
        &["'-4'", "greater than 0"],
    );
    refused(
        &["solve", "-m", "4,abc", "-v", "1,2"],
        &["'abc'", "not a number", "fraction"],
    );
    refused(
        &["solve", "-m", "NaN,1", "-v", "1,2"],
        &["'NaN'", "not a number"],
    );
    // 'inf' is a wall (issue 15), but only for a mass.
    refused(
        &["solve", "-m", "4,1", "-v", "inf,2"],
        &["'inf'", "not a number"],
    );
    refused(
        &["solve", "-m", "1e999,1", "-v", "1,2"],
        &["'1e999'", "too large"],
    );
    refused(&["solve", "-m", "4", "-v", "1,2"], &["expected 2", "got 1"]);
    // Three masses are three bodies (the plane and N bodies): their velocities must match.
    refused(
        &["solve", "-m", "4,1,1", "-v", "1,2"],
        &["--masses has 3 values", "--velocities 2", "one per body"],
    );
}

#[test]
fn bad_velocities_and_restitution() {
    refused(&["solve", "-m", "4,1", "-v", "1"], &["expected 2", "got 1"]);
    refused(
        &["solve", "-m", "4,1", "-v", "1,x"],
        &["'x'", "not a number"],
    );
    refused(
        &["solve", "-m", "4,1", "-v", "1,2", "-e", "-0.5"],
        &["'-0.5'", "negative", ">= 0"],
    );
    // Above 1 is superelastic in solve, but collide track keeps e in [0, 1].
    refused(
        &["track", "-m", "1,1", "-x", "0,1", "-v", "1,0", "-e", "1.5"],
        &["'1.5'", "[0, 1]"],
    );
    refused(
        &["solve", "-m", "4,1", "-v", "1,2", "-e", "bouncy"],
        &["'bouncy'", "elastic"],
    );
    refused(&["solve", "-m", "4,1"], &["--velocities"]);
}

#[test]
fn bad_tensors() {
    refused(
        &["solve", "--inertia", "4,0.5;0.4,1", "-v", "1,2"],
        &["not symmetric", "0.5", "0.4"],
    );
    refused(
        &["solve", "--inertia", "1,2;2,1", "-v", "1,2"],
        &["not positive definite"],
    );
    refused(&["solve", "--inertia", "4,0.5", "-v", "1,2"], &["2 rows"]);
    refused(
        &["solve", "--inertia", "4,0;0,1", "-m", "4,1", "-v", "1,2"],
        &["--inertia", "--masses"],
    );
    refused(&["solve", "-v", "1,2"], &["--masses"]);
}

#[test]
fn unrepresentable_results_are_named_not_printed() {
    // KE ~ 1e400: beyond binary64.
    refused(
        &[
            "solve",
            "-m",
            "1,1",
            "-v",
            "1e200,-1e200",
            "--show",
            "energy",
        ],
        &["energy.in", "not representable"],
    );
    refused(
        &["solve", "-m", "1,1", "-v", "1e200,-1e200"],
        &["forms.fin_m_in", "not representable"],
    );
    // Asking only for vectors is fine: they are representable.
    collide()
        .args([
            "solve",
            "-m",
            "1,1",
            "-v",
            "1e200,-1e200",
            "--show",
            "vectors",
        ])
        .assert()
        .success()
        .stdout(predicate::str::contains("(-1e200, 1e200)"))
        .stdout(predicate::str::contains("inf").not());
}

#[test]
fn scene_errors_name_file_and_line() {
    let dir = std::env::temp_dir().join(format!("collide-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::File::create(&p)
            .unwrap()
            .write_all(text.as_bytes())
            .unwrap();
        p.to_string_lossy().into_owned()
    };
    let unknown = write(
        "unknown.toml",
        "masses = [4, 1]\nvelocities = [60, 10]\nelasticity = 1\n",
    );
    refused(&["scene", &unknown], &["unknown.toml:3:", "elasticity"]);
    let wrong_type = write("type.toml", "masses = [4, 1]\nvelocities = \"fast\"\n");
    refused(&["scene", &wrong_type], &["type.toml:2:"]);
    let bad_expect = write(
        "expect.toml",
        "masses = [4, 1]\nvelocities = [60, 10]\n[expect]\n\"energy.crunsh\" = 1\n",
    );
    refused(
        &["scene", &bad_expect],
        &["expect.toml:4:", "energy.crunsh"],
    );
    refused(
        &["scene", "no/such/scene.toml"],
        &["no/such/scene.toml", "cannot read"],
    );
    // A wrong expectation is a failed check: exit 1, expected against actual.
    let wrong = write(
        "wrong.toml",
        "masses = [4, 1]\nvelocities = [60, 10]\n[expect]\nfin = [40, 91]\n\"energy.crunch\" = 1000\n",
    );
    let out = collide().args(["scene", &wrong]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Checks: 1 of 2 pass"), "{text}");
    assert!(
        text.contains("wrong.toml:4: fin: expected [40, 91] (rel 1e-12), got [40, 90]"),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn default_text_leaves_out_what_the_case_does_not_need() {
    let elastic = collide()
        .args(["solve", "-m", "4,1", "-v", "60,10"])
        .assert()
        .success();
    let text = String::from_utf8(elastic.get_output().stdout.clone()).unwrap();
    // The design card's default: vectors, forms, energy; nothing else.
    assert!(
        text.contains("Vectors") && text.contains("Quadratic forms") && text.contains("Energy (")
    );
    assert!(!text.contains("Momentum") && !text.contains("ellipses") && !text.contains("Products"));
    assert!(
        !text.contains("lost"),
        "no energy lost for an elastic collision:\n{text}"
    );
    assert!(
        text.contains("M = diag(4, 1)"),
        "no off-diagonal entries for a diagonal M:\n{text}"
    );
    assert!(
        text.contains("3625 - 2625"),
        "the lecture's quarter forms:\n{text}"
    );

    let stuck = collide()
        .args(["solve", "-m", "4,1", "-v", "60,10", "-e", "0"])
        .assert()
        .success();
    let text = String::from_utf8(stuck.get_output().stdout.clone()).unwrap();
    assert!(
        text.contains("FIN  V_FIN    = COM"),
        "no separate FIN numbers when e = 0:\n{text}"
    );
    assert!(!text.contains("(50, 50)  ="), "{text}");
    assert!(text.contains("lost = crunch"), "{text}");
}

#[test]
fn json_keeps_every_key_of_each_requested_section() {
    let out = collide()
        .args([
            "solve", "-m", "4,1", "-v", "60,10", "--show", "energy", "--format", "json",
        ])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(keys, ["restitution", "inertia", "energy"]);
    let energy: Vec<&str> = v["energy"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(
        energy,
        ["in", "fin", "com", "crunch", "lost"],
        "lost is present even when 0"
    );

    let out = collide()
        .args([
            "solve",
            "--inertia",
            "4,0.5;0.5,1",
            "-v",
            "60,10",
            "-e",
            "0",
            "--show",
            "all",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        [
            "restitution",
            "inertia",
            "in",
            "com",
            "fin",
            "v_com",
            "approaching",
            "momentum",
            "forms",
            "energy",
            "ellipses",
            "products",
            "changes"
        ]
    );
    // A general tensor: impulses, but no per-body energies (the cross term belongs to no body).
    let changes = v["changes"].as_object().unwrap();
    let keys: Vec<&str> = changes.keys().map(String::as_str).collect();
    assert_eq!(keys, ["dv", "impulse", "lost_fraction"]);
    for e in ["in", "fin", "com"] {
        assert!(
            v["ellipses"][e]["axes"].is_array(),
            "a general M gives the axes"
        );
    }
}

#[test]
fn general_tensor_numbers_derived_by_hand() {
    // M = [[4, 0.5], [0.5, 1]], V = (60, 10), e = 0: M_total = 6, P_total = 285, V_COM = 47.5,
    // mu = det/M_total = 3.75/6, crunch = 1/2 mu 50^2 = 781.25, KE_IN = 7550.
    let out = collide()
        .args([
            "solve",
            "--inertia",
            "4,0.5;0.5,1",
            "-v",
            "60,10",
            "-e",
            "0",
            "--show",
            "all",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    let r: collide::report::Report = serde_json::from_slice(&out.stdout).unwrap();
    let e = r.energy.unwrap();
    common::assert_close(r.vectors.unwrap().v_com, 47.5, common::REL, "V_COM");
    common::assert_close(e.crunch, 781.25, common::REL, "crunch");
    common::assert_close(e.ke_in, 7550.0, common::REL, "KE_IN");
    common::assert_close(e.com, 6768.75, common::REL, "KE_COM");
    // Ellipse radii along the eigenvectors: lambda = (5 -+ sqrt(10))/2.
    let el = r.ellipses.unwrap();
    let l_min = (5.0 - 10f64.sqrt()) / 2.0;
    let l_max = (5.0 + 10f64.sqrt()) / 2.0;
    common::assert_close(
        el.e_in.a,
        (2.0 * 7550.0 / l_min).sqrt(),
        8.0 * f64::EPSILON,
        "IN a",
    );
    common::assert_close(
        el.e_in.b,
        (2.0 * 7550.0 / l_max).sqrt(),
        8.0 * f64::EPSILON,
        "IN b",
    );
}

#[test]
fn closed_pipe_ends_quietly() {
    let mut child = StdCommand::new(assert_cmd::cargo::cargo_bin("collide"))
        .args(["solve", "-m", "4,1", "-v", "60,10", "--show", "all"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // the reader (`head`) is gone before anything is written
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn help_and_version() {
    collide()
        .arg("--help")
        .assert()
        .success()
        .stdout(predicate::str::contains("solve"));
    collide()
        .args(["solve", "--help"])
        .assert()
        .success()
        .stdout(predicate::str::contains("--restitution"));
    // The version Cargo builds with, as clap prints it: "collide 0.1.0".
    collide()
        .arg("--version")
        .assert()
        .success()
        .stdout(format!("collide {}\n", env!("CARGO_PKG_VERSION")));
}

// Issue 24: each message names the real limit and the real way out.

/// Runs `collide args`, expects exit 2 and nothing on stdout, returns stderr.
#[track_caller]
fn failure(args: &[&str]) -> String {
    refused(args, &[]);
    String::from_utf8_lossy(&collide().args(args).output().unwrap().stderr).into_owned()
}

#[test]
fn control_characters_in_a_bad_value_are_shown_escaped() {
    // "mass '5' is not a number": the BEL vanished from the quoted value.
    refused(
        &["solve", "-m", "5\u{7},1", "-v", "1,0"],
        &["mass '5\\u{7}' is not a number", "'5\\u{7},1'"],
    );
    let err = failure(&["solve", "-m", "1,1", "-v", "1,\u{1b}[31m"]);
    assert!(
        !err.contains('\u{1b}') && err.contains("'\\u{1b}[31m'"),
        "{err}"
    );
}

#[test]
fn numbers_out_of_range_name_the_limit_they_hit() {
    // "unknown length unit 'e9999 m'": the number was out of range, not the unit.
    refused(
        &["solve", "-m", "1,1", "-v", "height 1e9999 m,0"],
        &["'1e9999' is too large for binary64"],
    );
    refused(
        &["solve", "-m", "1e400 g,1 g", "-v", "1,0"],
        &["'1e400' is too large for binary64"],
    );
    // 1e100000/1e100000 is 1: the limit is on the fraction's parts, not binary64.
    let err = failure(&["solve", "-m", "1,1", "-v", "1e100000/1e100000,0"]);
    assert!(
        err.contains("decimal exponents of +-100000") && !err.contains("too large"),
        "{err}"
    );
    // pi 200 --simulate said "try smaller units": the limit is the time the collisions take.
    refused(
        &["pi", "200", "--simulate"],
        &["3.1e200 collisions", "N up to 10", "without --simulate"],
    );
    let out = collide()
        .args(["pi", "200", "--simulate"])
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&out.stderr).contains("units"));
}

#[test]
fn commands_without_show_do_not_suggest_it() {
    // frames and plot suggested --show, which they do not have.
    let err = failure(&["frames", "-m", "1e300,1e-300", "-v", "1e300,0"]);
    assert!(err.contains("--exact") && !err.contains("--show"), "{err}");
    let err = failure(&["plot", "-m", "1e300,1e-300", "-v", "1e300,0"]);
    assert!(!err.contains("--show") && !err.contains("--exact"), "{err}");
    // solve has both.
    refused(
        &["solve", "-m", "1e300,1e-300", "-v", "1e300,0"],
        &["--exact", "--show"],
    );
}

#[test]
fn energy_unit_is_refused_where_nothing_is_printed_in_it() {
    // sweep ignored it silently: its columns carry no unit.
    refused(
        &[
            "sweep",
            "-m",
            "1 kg,12 kg",
            "-v",
            "2 m/s,0",
            "--vary",
            "e=0,1",
            "--energy-unit",
            "kJ",
        ],
        &["--energy-unit kJ", "J"],
    );
    // plot labels its ellipses in the case's own units.
    refused(
        &[
            "plot",
            "-m",
            "1 kg,12 kg",
            "-v",
            "2 m/s,0",
            "--energy-unit",
            "eV",
        ],
        &["--energy-unit eV"],
    );
}

#[test]
fn usage_errors_say_what_was_meant() {
    // Issue 45 §3. A space after a comma ends the value: the rest of the list is named.
    refused(
        &["solve", "-m", "4,", "1", "-v", "60,10"],
        &[
            "unexpected argument '1'",
            "tip: no space after a comma in a list: -m 4,1",
        ],
    );
    refused(
        &["contact", "-m", "1,1", "-x", "0,", "1", "-v", "1,0"],
        &["tip: no space after a comma in a list: -x 0,1"],
    );
    refused(
        &["solve", "-m", "4,1", "-v", "1,", "2,", "3"],
        &["-v 1,2,3"],
    );
    // A case without its subcommand: the same words after `collide solve`, quoted for the shell.
    refused(
        &["-m", "4,1", "-v", "60,10"],
        &["tip: a collision is solved by a subcommand: collide solve -m 4,1 -v 60,10"],
    );
    refused(
        &["-m", "4 ton,1 ton", "-v", "60,10", "--exact"],
        &["collide solve -m '4 ton,1 ton' -v 60,10 --exact"],
    );
    // Not for a word no subcommand knows.
    let err = failure(&["--frobnicate"]);
    assert!(!err.contains("tip:"), "{err}");
    // A range typed another way: how ranges are written, with the typed ends.
    for (vary, example) in [
        ("e=0-1", "e=0:1:11 for 11 values from 0 to 1"),
        ("e=0..1", "e=0:1:11 for 11 values from 0 to 1"),
        ("v1=-2-3", "v1=-2:3:11 for 11 values from -2 to 3"),
        ("e=half", "e=0:1:11 for 11 values from 0 to 1"),
    ] {
        refused(
            &["sweep", "-m", "4,1", "-v", "60,10", "--vary", vary],
            &["is not a number", "FROM:TO:COUNT", example],
        );
    }
    refused(
        &[
            "contact",
            "-m",
            "1,1",
            "-x",
            "0,1",
            "--sizes",
            "1,1",
            "-v",
            "1,0",
            "--vary",
            "stiffness=1-10",
        ],
        &["stiffness=1:10:11"],
    );
    // A list still names its bad entry as before.
    refused(
        &["sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0,x"],
        &["'x'", "not a number"],
    );
    // `collide pi five`: what N is, not Rust's "invalid digit found in string".
    for n in ["five", "2.5", "", "1e3"] {
        let err = failure(&["pi", n]);
        assert!(
            err.contains("a whole number of digits after the point")
                && !err.contains("invalid digit"),
            "pi {n:?}: {err}"
        );
    }
    for n in ["10001", "99999999999999999999999"] {
        refused(&["pi", n], &["at most 10,000 digits after the point"]);
    }
}
