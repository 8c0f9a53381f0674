//! `collide view` (issue 29): the page, its answers against the command line's, the command and
//! scene it gives back, the committed WebAssembly module, and the page in a real browser.
//!
//! The browser tests drive headless Chromium through `view_browser.py` (Playwright for Python)
//! once, and each test checks a part of what it reports. Without Chromium and Playwright they are
//! reported as ignored (build.rs probes for the tools), except under CI (`CI` set), where they
//! run and a missing tool fails them: `.ci/run` installs both.

use std::path::{Path, PathBuf};
use std::process::Command as StdCommand;
use std::sync::OnceLock;

use serde_json::{Value, json};

use crate::common::{REL, assert_close, collide, run, stdout};

/// The inputs of the page for the lecture's cases and the edges of the brief (issue 29): lecture
/// A and B, a general tensor, e = 0, 2/3, 1, a huge mass ratio, units.
pub(crate) fn cases() -> Vec<Value> {
    vec![
        json!({"m1": "4", "m2": "1", "v1": "60", "v2": "10", "e": "elastic"}),
        json!({"m1": "6", "m2": "1", "v1": "3", "v2": "-4", "e": "1"}),
        json!({"m1": "6", "m2": "1", "v1": "3", "v2": "-4", "e": "2/3"}),
        json!({"m1": "6", "m2": "1", "v1": "3", "v2": "-4", "e": "0"}),
        json!({"inertia": "4,0.5;0.5,1", "v1": "60", "v2": "10", "e": "inelastic"}),
        json!({"m1": "1e12", "m2": "1", "v1": "1", "v2": "-1", "e": "0.9"}),
        json!({"m1": "1", "m2": "3e-9", "v1": "0", "v2": "-7.25", "e": "1"}),
        json!({"m1": "4 ton", "m2": "1 ton", "v1": "60 mph", "v2": "10 mph", "e": "elastic"}),
    ]
}

/// `collide solve` flags of a case as the page holds it.
pub(crate) fn solve_args(case: &Value) -> Vec<String> {
    let s = |k: &str| case[k].as_str().unwrap_or_default().to_string();
    let mut args = vec!["solve".to_string()];
    match case["inertia"].as_str() {
        Some(t) if !t.is_empty() => args.extend(["--inertia".into(), t.into()]),
        _ => args.extend(["-m".into(), format!("{},{}", s("m1"), s("m2"))]),
    }
    args.extend(["-v".into(), format!("{},{}", s("v1"), s("v2"))]);
    args.extend(["-e".into(), s("e")]);
    args.extend(["--format".into(), "json".into()]);
    args
}

pub(crate) fn cli_json(args: &[String]) -> String {
    stdout(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

/// The library's answer to a page request (what the WebAssembly module answers in the page).
pub(crate) fn ask(request: Value) -> Value {
    let text = collide::view::api::call(&request.to_string());
    serde_json::from_str(&text).unwrap()
}

fn solve_request(case: &Value) -> Value {
    let mut r = case.clone();
    r["op"] = "solve".into();
    r
}

/// The words of a command line as `view::shell` writes it (plain words and '...' quoting).
fn shell_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut quoted = false;
    let mut any = false;
    for c in line.chars() {
        match c {
            '\'' => {
                quoted = !quoted;
                any = true;
            }
            ' ' if !quoted => {
                if any || !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
                any = false;
            }
            c => word.push(c),
        }
    }
    if any || !word.is_empty() {
        words.push(word);
    }
    words
}

/// Runs a `collide ...` command line the page shows, with `--format json`.
pub(crate) fn run_shown(command: &str) -> String {
    let words = shell_words(command);
    assert_eq!(words[0], "collide", "{command}");
    let mut args: Vec<String> = words[1..].to_vec();
    args.extend(["--format".into(), "json".into()]);
    cli_json(&args)
}

/// `collide scene FILE --format json`'s report for a scene the page shows.
pub(crate) fn run_scene(scene: &str, tag: &str) -> Value {
    let file = scratch("scenes").join(format!("{tag}-{}.toml", std::process::id()));
    std::fs::write(&file, scene).unwrap();
    let out = stdout(&["scene", file.to_str().unwrap(), "--format", "json"]);
    let v: Value = serde_json::from_str(&out).unwrap();
    v["report"].clone()
}

/// A folder of this test module's under the target directory (kept after the run: the browser's
/// screenshots can be looked at there).
pub(crate) fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("view")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn answers_equal_solve_json_byte_for_byte() {
    for case in cases() {
        let a = ask(solve_request(&case));
        assert_eq!(a["ok"], true, "{case}: {a}");
        let cli = cli_json(&solve_args(&case));
        assert_eq!(a["state"].as_str().unwrap(), cli, "{case}");
    }
}

#[test]
fn the_command_and_scene_shown_reproduce_the_state() {
    for mut case in cases() {
        for (frame, reverse) in [("lab", false), ("com", true), ("rest-fin:2", false)] {
            case["frame"] = frame.into();
            case["reverse"] = reverse.into();
            let a = ask(solve_request(&case));
            if (case["e"] == "0" || case["e"] == "inelastic") && reverse {
                // The CLI refuses the time reverse of a collision that sticks; so does the page.
                assert_eq!(a["ok"], false, "{case}");
                assert_eq!(a["field"], "reverse");
                continue;
            }
            assert_eq!(a["ok"], true, "{case}: {a}");
            let state = a["state"].as_str().unwrap();
            let command = a["command"].as_str().unwrap();
            assert_eq!(run_shown(command), state, "{command}");
            // A scene has no time reverse (the scene says so in a comment) and keeps units as
            // the page typed them.
            let report = run_scene(a["scene"].as_str().unwrap(), "case");
            let mut expected: Value = serde_json::from_str(state).unwrap();
            expected.as_object_mut().unwrap().remove("reverse");
            assert_eq!(report, expected, "{}", a["scene"]);
        }
    }
}

#[test]
fn the_page_refuses_what_is_not_a_collision_by_name() {
    for (case, field, words) in [
        (
            json!({"m1": "4", "m2": "-1", "v1": "60", "v2": "10"}),
            "m2",
            "'-1'",
        ),
        (
            json!({"m1": "4", "m2": "1", "v1": "sixty", "v2": "10"}),
            "v1",
            "'sixty'",
        ),
        (
            json!({"m1": "4", "m2": "1", "v1": "60", "v2": "10", "e": "-2"}),
            "e",
            "'-2'",
        ),
        (
            json!({"m1": "4", "m2": "wall", "v1": "60", "v2": "0"}),
            "m1",
            "wall",
        ),
        (
            json!({"m1": "4", "m2": "?", "v1": "60", "v2": "10"}),
            "e",
            "'?'",
        ),
        (
            json!({"m1": "4", "m2": "1", "v1": "60", "v2": "10", "frame": "sideways"}),
            "frame",
            "'sideways'",
        ),
    ] {
        let a = ask(solve_request(&case));
        assert_eq!(a["ok"], false, "{case}");
        assert_eq!(a["field"], field, "{case}: {a}");
        assert!(
            a["error"].as_str().unwrap().contains(words),
            "{case}: {}",
            a["error"]
        );
    }
    // The same inputs as flags: exit 2, the bad value named, nothing on stdout.
    let (code, out, err) = run(&["view", "-m", "4,-1", "-v", "60,10"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("'-1'"), "{err}");
    let (code, out, err) = run(&["view", "scenarios/contact-superball.toml"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("collide scene"), "{err}");
}

/// The lecture's 2-ball stack as the page opens it: masses 1 and 1/100, touching, dropped from
/// rest onto the floor (`Setup::lecture`).
fn stack_request() -> Value {
    json!({"op": "track", "masses": "1,0.01", "positions": "1.5,2.25", "velocities": "0,0",
           "sizes": "1,0.5", "left_wall": "0", "gravity": "9.81"})
}

#[test]
fn the_stack_is_collide_track_at_every_sample() {
    let a = ask(stack_request());
    assert_eq!(a["ok"], true, "{a}");
    let state = a["state"].as_str().unwrap();
    let command = a["command"].as_str().unwrap();
    // Until 8 times the first bounce's time, sqrt(2 h / g) with h = 1: 0.4515 -> 3.6.
    assert!(command.ends_with("--until 3.6"), "{command}");
    assert_eq!(run_shown(command), state, "{command}");
    assert_eq!(
        run_scene(a["scene"].as_str().unwrap(), "stack"),
        serde_json::from_str::<Value>(state).unwrap()
    );
    // Each sample is the state `collide track --until t` gives, to the bit: check the first,
    // a collision's time, and the last.
    let t: Vec<f64> = serde_json::from_value(a["t"].clone()).unwrap();
    let x: Vec<Vec<f64>> = serde_json::from_value(a["x"].clone()).unwrap();
    assert!(t.len() > 240 && t.windows(2).all(|w| w[0] < w[1]));
    let bounce = a["events"][0]["t"].as_f64().unwrap();
    let words = shell_words(command);
    let base: Vec<String> = words[1..words.len() - 2].to_vec();
    for k in [0, t.iter().position(|s| *s == bounce).unwrap(), t.len() - 1] {
        let mut args = base.clone();
        args.extend([
            "--until".into(),
            format!("{:?}", t[k]),
            "--format".into(),
            "json".into(),
        ]);
        let run: Value = serde_json::from_str(&cli_json(&args)).unwrap();
        for (i, xs) in x.iter().enumerate() {
            assert_eq!(
                run["x"][i].as_f64().unwrap(),
                xs[k],
                "body {i} at t = {}",
                t[k]
            );
        }
    }
}

#[test]
fn stacks_amplify_the_drop_speed_as_harter_says() {
    // Touching balls, each 100 times lighter, resolved bottom to top at the instant of impact:
    // the top ball leaves at (3 m1 - m2)/(m1 + m2) = 299/101 of the drop speed for two balls and
    // 69799/10201 for three (scenarios/superball-2.toml and -3.toml, derived in exact arithmetic).
    let a = ask(stack_request());
    let amp = &a["amplification"];
    assert_close(
        amp["ratio"].as_f64().unwrap(),
        299.0 / 101.0,
        REL,
        "2 balls",
    );
    assert_eq!(amp["limit"], 3.0);
    // The drop speed is sqrt(2 g h) for the 1 m fall of the bottom ball.
    assert_close(
        amp["drop_speed"].as_f64().unwrap(),
        (2.0f64 * 9.81).sqrt(),
        REL,
        "sqrt(2 g h)",
    );
    let mut three = stack_request();
    three["masses"] = "1,0.01,0.0001".into();
    three["positions"] = "1.5,2.25,2.625".into();
    three["velocities"] = "0,0,0".into();
    three["sizes"] = "1,0.5,0.25".into();
    let a = ask(three);
    let amp = &a["amplification"];
    assert_close(
        amp["ratio"].as_f64().unwrap(),
        69799.0 / 10201.0,
        2.0 * REL,
        "3 balls",
    );
    assert_eq!(amp["limit"], 7.0);
}

#[test]
fn the_page_is_one_deterministic_file_under_a_megabyte() {
    let file = scratch("page").join("a.html");
    let (code, out, err) = run(&[
        "view",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "-e",
        "2/3",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert_eq!((code, out.as_str(), err.as_str()), (0, "", ""));
    let written = std::fs::read_to_string(&file).unwrap();
    let again = stdout(&["view", "-m", "6,1", "-v", "3,-4", "-e", "2/3"]);
    assert_eq!(written, again, "the same input gives the same bytes");
    assert!(written.len() < 1_000_000, "{} bytes", written.len());
    // Nothing is fetched: no external script, style, image or link, and a policy that forbids it.
    for outside in [
        "<link",
        " src=",
        "@import",
        "url(http",
        "fetch(",
        "XMLHttpRequest",
    ] {
        assert!(!written.contains(outside), "the page holds {outside}");
    }
    assert!(written.contains("content=\"default-src 'none';"));
    // The first case's JSON is in the page before any script runs.
    let cli = stdout(&[
        "solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--format", "json",
    ]);
    let escaped = cli
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    assert!(written.contains(&format!("<pre id=\"state\" class=\"json\">{escaped}</pre>")));
    // The embedded module is the committed one.
    let module = collide::view::page::base64(&collide::view::page::compressed(
        &std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("wasm/collide_view.wasm"))
            .unwrap(),
    ));
    assert!(written.contains(&module));
}

/// A tool a running test needs is missing: a failure. The tests that need a tool are ignored
/// where build.rs found it missing (outside CI), so one that runs must find it.
fn unavailable(what: &str) -> ! {
    panic!("{what} (build.rs found it, or CI is set; touch build.rs after installing a tool)");
}

/// The files `wasm/build.sh` recorded with their SHA-256 when it built the committed module
/// (`wasm/sources.sha256`: what cargo's dep-info names, the manifests, the lock file, the script)
/// are unchanged, and so is the rustc (`wasm/rustc-version`). The build is reproducible (the test
/// below rebuilds it byte for byte), so these sources build the committed bytes; a change to any
/// of them without a rebuild fails here, naming the file.
#[test]
fn the_committed_module_was_built_from_these_sources() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let recorded = std::fs::read_to_string(root.join("wasm/sources.sha256")).unwrap();
    let listed: Vec<(&str, &str)> = recorded
        .lines()
        .map(|l| {
            l.split_once("  ")
                .unwrap_or_else(|| panic!("not `HASH  FILE`: {l}"))
        })
        .collect();
    let files: Vec<&str> = listed.iter().map(|(_, f)| *f).collect();
    // The list is the module's: the library, the wasm crate, what pins the dependencies.
    for must in [
        "src/lib.rs",
        "src/view/api.rs",
        "wasm/src/lib.rs",
        "Cargo.lock",
        "wasm/build.sh",
    ] {
        assert!(
            files.contains(&must),
            "wasm/sources.sha256 does not list {must}"
        );
    }
    assert!(files.len() > 100, "{} files listed", files.len());
    let now = StdCommand::new("sha256sum")
        .arg("--")
        .args(&files)
        .current_dir(root)
        .output()
        .unwrap_or_else(|e| panic!("sha256sum (coreutils) cannot run: {e}"));
    let now = String::from_utf8(now.stdout).unwrap();
    let changed: Vec<&str> = listed
        .iter()
        .filter(|(hash, file)| !now.lines().any(|l| l == format!("{hash}  {file}")))
        .map(|(_, f)| *f)
        .collect();
    assert!(
        changed.is_empty(),
        "{} changed since wasm/collide_view.wasm was built: run wasm/build.sh (it rebuilds the \
         module and wasm/sources.sha256) and commit both",
        changed.join(", ")
    );
    let rustc = StdCommand::new("rustc").arg("--version").output().unwrap();
    let recorded = std::fs::read_to_string(root.join("wasm/rustc-version")).unwrap();
    assert_eq!(
        String::from_utf8_lossy(&rustc.stdout).trim(),
        recorded.trim(),
        "the committed module was built by another rustc: run wasm/build.sh and commit it"
    );
}

/// Rebuilds the module and requires the committed bytes (about a minute: not in CI, which checks
/// the sources' hashes above; run it after wasm/build.sh or a toolchain update).
#[test]
#[ignore = "rebuilds the module (about a minute): cargo test --release -- --ignored the_committed_module_"]
fn the_committed_module_is_what_the_sources_build() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let sysroot = StdCommand::new("rustc")
        .args(["--print", "sysroot"])
        .output()
        .unwrap();
    let sysroot = PathBuf::from(String::from_utf8(sysroot.stdout).unwrap().trim());
    if !sysroot.join("lib/rustlib/wasm32-unknown-unknown").exists() {
        unavailable(
            "the wasm32-unknown-unknown target is not installed (rustup target add wasm32-unknown-unknown)",
        );
    }
    let out = scratch("wasm").join("collide_view.wasm");
    let status = StdCommand::new(root.join("wasm/build.sh"))
        .arg(&out)
        .env_remove("CARGO_TARGET_DIR")
        .status()
        .unwrap();
    assert!(status.success(), "wasm/build.sh failed");
    let built = std::fs::read(&out).unwrap();
    let committed = std::fs::read(root.join("wasm/collide_view.wasm")).unwrap();
    let recorded = std::fs::read_to_string(root.join("wasm/rustc-version")).unwrap();
    let rustc = StdCommand::new("rustc").arg("--version").output().unwrap();
    assert!(
        built == committed,
        "wasm/build.sh gives other bytes than wasm/collide_view.wasm ({} against {} bytes): \
         rebuild it with wasm/build.sh and commit it (committed with {}, this is {})",
        built.len(),
        committed.len(),
        recorded.trim(),
        String::from_utf8_lossy(&rustc.stdout).trim()
    );
}

// ------------------------------------------------------------------ in a real browser

/// What the browser did, once for all the browser tests; `None` when it cannot run here.
pub(crate) fn browser() -> Option<&'static Value> {
    static RUN: OnceLock<Result<Value, String>> = OnceLock::new();
    match RUN.get_or_init(drive_browser) {
        Ok(v) => Some(v),
        Err(why) => unavailable(why),
    }
}

/// The drag of the brief: case A with e = 2/3, IN dragged along its momentum line 4 V1 + V2 =
/// 250 from (60, 10) to (55, 30).
const DRAG_FROM: [f64; 2] = [60.0, 10.0];
const DRAG_TO: [f64; 2] = [55.0, 30.0];

fn drive_browser() -> Result<Value, String> {
    let chromium = std::env::var("COLLIDE_CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into());
    if !Path::new(&chromium).exists() {
        return Err(format!(
            "no Chromium at {chromium} (apt-get install chromium)"
        ));
    }
    let python = StdCommand::new("python3")
        .args(["-c", "import playwright.sync_api"])
        .output();
    if !python.is_ok_and(|o| o.status.success()) {
        return Err("no Playwright for Python (pip install playwright)".into());
    }
    let dir = scratch("browser");
    let page = dir.join("view.html");
    collide()
        .args(["view", "-o", page.to_str().unwrap()])
        .assert()
        .success();
    let case_a = json!({"m1": "4", "m2": "1", "v1": "60", "v2": "10", "e": "elastic"});
    let plan = json!({
        "cases": cases(),
        "drag": {"case": {"m1": "4", "m2": "1", "v1": "60", "v2": "10", "e": "2/3"},
                 "from": DRAG_FROM, "to": DRAG_TO},
        "keys": ["ArrowUp", "ArrowUp", "ArrowUp", "ArrowLeft"],
        "frame": {"case": {"m1": "6", "m2": "1", "v1": "3", "v2": "-4", "e": "2/3"}, "to": "com"},
        "reverse": {"m1": "6", "m2": "1", "v1": "3", "v2": "-4", "e": "2/3"},
        "screenshot": {
            "case": case_a,
            "path": dir.join("plane.png"),
            "page": dir.join("page.png"),
            "colours": {"in": [220, 38, 38], "com": [5, 150, 105], "momentum": [37, 99, 235]},
            // Case A: IN ellipse radii 60.21 and 120.42, COM 55.90 and 111.80 (physics.md).
            "probes": [
                {"colour": "in", "at": [60.2080, 0.0]}, {"colour": "in", "at": [-60.2080, 0.0]},
                {"colour": "in", "at": [0.0, 120.4159]}, {"colour": "in", "at": [0.0, -120.4159]},
                {"colour": "com", "at": [55.9017, 0.0]}, {"colour": "com", "at": [0.0, -111.8034]},
                {"colour": "momentum", "at": [45.0, 70.0]}, {"colour": "momentum", "at": [70.0, -30.0]}
            ]
        },
        "plane": super::view_plane::browser_plan(&dir),
        "steps": super::view_hostile::steps(),
        "stack": [
            {},
            {"preset": "3"},
            {"fill": {"t-e": "0.9"}},
            {"preset": "ball"}
        ]
    });
    let plan_file = dir.join("plan.json");
    std::fs::write(&plan_file, plan.to_string()).unwrap();
    let driver = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/suite/view_browser.py");
    let out = StdCommand::new("python3")
        .arg(driver)
        .arg(&page)
        .arg(&plan_file)
        .output()
        .map_err(|e| format!("cannot run python3: {e}"))?;
    if !out.status.success() {
        panic!(
            "the browser driver failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    eprintln!(
        "browser: ready in {:.2} s, all steps in {:.1} s; page {} bytes",
        v["ready_s"].as_f64().unwrap_or(0.0),
        v["seconds"].as_f64().unwrap_or(0.0),
        std::fs::metadata(&page).map(|m| m.len()).unwrap_or(0)
    );
    Ok(v)
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_loads_from_file_with_no_request_and_no_console_error() {
    let Some(b) = browser() else { return };
    let requests: Vec<&str> = b["requests"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_str().unwrap())
        .collect();
    assert_eq!(requests.len(), 1, "{requests:?}");
    assert!(requests[0].starts_with("file://") && requests[0].ends_with("view.html"));
    assert_eq!(b["errors"], json!([]), "uncaught errors");
    let console: Vec<&Value> = b["console"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m[0] == "error" || m[0] == "warning")
        .collect();
    assert!(console.is_empty(), "console: {console:?}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_state_equals_solve_json_for_the_lecture_cases_and_edges() {
    let Some(b) = browser() else { return };
    for (case, seen) in cases().iter().zip(b["cases"].as_array().unwrap()) {
        assert_seen_is_solve(seen, &solve_args(case), case);
    }
}

/// A case the browser typed: no error, its JSON as `collide solve args` prints it, and the
/// command line shown prints it too.
#[track_caller]
pub(crate) fn assert_seen_is_solve(seen: &Value, args: &[String], case: &Value) {
    assert_eq!(seen["error"], "", "{case}");
    let cli = cli_json(args);
    assert_eq!(seen["state"].as_str().unwrap(), cli, "{case}");
    assert_eq!(run_shown(seen["command"].as_str().unwrap()), cli, "{case}");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_drag_moves_fin_along_the_momentum_line_as_the_formula_says() {
    let Some(b) = browser() else { return };
    let d = &b["drag"];
    let before: Value = serde_json::from_str(d["before"].as_str().unwrap()).unwrap();
    let after: Value = serde_json::from_str(d["after"].as_str().unwrap()).unwrap();
    let pair = |v: &Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
    assert_eq!(pair(&before["in"]), DRAG_FROM);
    // IN is where the mouse let go, to the step the page snaps to (a power of 10 at or above a
    // screen unit).
    let step = d["map"]["step"].as_f64().unwrap();
    let v_in = pair(&after["in"]);
    for k in 0..2 {
        assert!(
            (v_in[k] - DRAG_TO[k]).abs() <= step,
            "IN {v_in:?}, dragged to {DRAG_TO:?} (step {step})"
        );
    }
    // FIN = (1 + e) V_COM - e IN for the new IN (Sec. 1), exactly as `collide solve` gives it.
    let case = json!({"m1": "4", "m2": "1", "v1": v_in[0].to_string(), "v2": v_in[1].to_string(), "e": "2/3"});
    assert_eq!(d["after"].as_str().unwrap(), cli_json(&solve_args(&case)));
    let e = 2.0 / 3.0;
    let v_com = (4.0 * v_in[0] + v_in[1]) / 5.0;
    let fin = pair(&after["fin"]);
    for k in 0..2 {
        assert_close(
            fin[k],
            (1.0 + e) * v_com - e * v_in[k],
            8.0 * f64::EPSILON,
            "FIN",
        );
    }
    // FIN is on the momentum line through IN: 4 V1 + V2 the same at both (P conserved); and IN
    // moved along the line it started on, so FIN moved along it too, by -e times IN's move.
    let p = |v: [f64; 2]| 4.0 * v[0] + v[1];
    assert_close(p(fin), p(v_in), 4.0 * REL, "momentum at FIN");
    if p(v_in) == 250.0 {
        let fin0 = pair(&before["fin"]);
        for k in 0..2 {
            assert_close(
                fin[k] - fin0[k],
                -e * (v_in[k] - DRAG_FROM[k]),
                1e-12,
                "FIN's move",
            );
        }
    }
    drag_timings(&d["timings"], "drag");
}

/// The median of a drag's timed updates (recompute + redraw, ms), reported; there must be some.
pub(crate) fn drag_timings(timings: &Value, what: &str) -> f64 {
    let mut sorted: Vec<f64> = serde_json::from_value(timings.clone()).unwrap();
    assert!(!sorted.is_empty(), "no {what} update was timed");
    sorted.sort_by(f64::total_cmp);
    let median = sorted[sorted.len() / 2];
    eprintln!(
        "{what}: {} updates, recompute + redraw median {median:.2} ms, max {:.2} ms",
        sorted.len(),
        sorted[sorted.len() - 1]
    );
    median
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_arrow_keys_move_in_by_the_step() {
    let Some(b) = browser() else { return };
    // After the drag: IN at the drag's end; three steps up and one left.
    let drag: Value = serde_json::from_str(b["drag"]["after"].as_str().unwrap()).unwrap();
    let keys: Value = serde_json::from_str(b["keys"]["state"].as_str().unwrap()).unwrap();
    let step = b["keys"]["map"]["step"].as_f64().unwrap();
    let v = |s: &Value, k: usize| s["in"][k].as_f64().unwrap();
    assert_close(v(&keys, 0), v(&drag, 0) - step, REL, "V1 after Left");
    assert_close(v(&keys, 1), v(&drag, 1) + 3.0 * step, REL, "V2 after Up x3");
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_frame_change_animates_the_45_degree_shift() {
    let Some(b) = browser() else { return };
    // Case B, e = 2/3: from the lab (w = 0) to COM (w = V_COM = 2) through observers between.
    let ws: Vec<f64> = serde_json::from_value(b["frame"]["w"].clone()).unwrap();
    let between: Vec<f64> = ws
        .iter()
        .copied()
        .filter(|w| *w > 0.0 && *w < 2.0)
        .collect();
    assert!(between.len() >= 3, "no shift drawn in between: {ws:?}");
    assert!(ws.windows(2).all(|p| p[0] <= p[1]), "{ws:?}");
    assert_eq!(*ws.last().unwrap(), 2.0);
    let cli = stdout(&[
        "solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--frame", "com", "--format", "json",
    ]);
    assert_eq!(b["frame"]["state"].as_str().unwrap(), cli);
    assert!(
        b["frame"]["command"]
            .as_str()
            .unwrap()
            .ends_with("--frame com")
    );
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_time_reverse_equals_solve_reverse() {
    let Some(b) = browser() else { return };
    let cli = stdout(&[
        "solve",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "-e",
        "2/3",
        "--reverse",
        "--format",
        "json",
    ]);
    assert_eq!(b["reverse"]["state"].as_str().unwrap(), cli);
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_screenshot_shows_the_ellipses_and_the_momentum_line() {
    let Some(b) = browser() else { return };
    let s = &b["screenshot"];
    assert!(s["width"].as_u64().unwrap() >= 400, "{s}");
    // Not blank: many colours, and most of it is not white.
    let area = (s["width"].as_u64().unwrap() * s["height"].as_u64().unwrap()) as f64;
    assert!(s["colours"].as_u64().unwrap() > 40, "{s}");
    assert!(s["white"].as_f64().unwrap() < 0.97 * area, "{s}");
    for name in ["in", "com", "momentum"] {
        assert!(
            s["counts"][name].as_u64().unwrap() > 300,
            "too few {name} pixels: {s}"
        );
    }
    // The ellipses pass through their radii on the axes, and the line through COM: each probe
    // finds its colour within 3 pixels of where the lecture's numbers put it.
    for (k, d) in s["probes"].as_array().unwrap().iter().enumerate() {
        let d = d.as_f64().unwrap_or(f64::INFINITY);
        assert!(
            d <= 3.0,
            "probe {k}: nearest pixel of its colour {d} px away: {s}"
        );
    }
}

#[test]
#[cfg_attr(
    not(has_browser),
    ignore = "needs Chromium and Playwright for Python (.ci/run installs them)"
)]
fn browser_stack_equals_collide_track_and_prints_the_amplification() {
    let Some(b) = browser() else { return };
    let steps = b["stack"].as_array().unwrap();
    for step in steps {
        assert_eq!(step["error"], "", "{step}");
        let state = step["state"].as_str().unwrap();
        assert_eq!(
            run_shown(step["command"].as_str().unwrap()),
            state,
            "{}",
            step["command"]
        );
    }
    // The lecture's stacks: 299/101 = 2.960396 and 69799/10201 = 6.842368 shown (7 digits).
    assert!(
        steps[0]["numbers"].as_str().unwrap().contains("2.960396"),
        "{}",
        steps[0]["numbers"]
    );
    assert!(
        steps[1]["numbers"].as_str().unwrap().contains("6.842368"),
        "{}",
        steps[1]["numbers"]
    );
    assert!(steps[2]["command"].as_str().unwrap().contains(" -e 0.9 "));
    let ms: Vec<String> = steps[1..]
        .iter()
        .map(|s| format!("{:.1}", s["ms"].as_f64().unwrap_or(f64::NAN)))
        .collect();
    eprintln!(
        "stack: run + redraw {} ms (3 balls, e = 0.9, a ball)",
        ms.join(", ")
    );
    // The bouncing ball with e = 0.5 at the floor comes to rest: a Zeno sequence.
    assert!(
        steps[3]["state"]
            .as_str()
            .unwrap()
            .contains("\"reason\": \"zeno\"")
    );
}
