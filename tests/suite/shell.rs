//! `collide completions`, `collide man` and `--help`: generated from the clap definition, so they
//! must name every subcommand; the man page must render; every example a help page gives must
//! run; and the exit statuses and limits they state must be the guide's.

use std::collections::BTreeSet;

use crate::common;
use crate::readme::{Sandbox, Shown};

use common::{collide, stdout};

const SUBCOMMANDS: [&str; 13] = [
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
    "view",
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

/// The page rendered by groff as `man -l` would at `MANWIDTH=80`, overstriking (bold: "C\x08C")
/// dropped.
fn rendered(page: &str) -> String {
    use std::io::Write;
    let mut child = std::process::Command::new("groff")
        .args(["-man", "-Tutf8", "-ww", "-rLL=80n"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("groff renders the man page: install it (Debian: groff-base; .ci/run does)");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(page.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success());
    let warnings = String::from_utf8_lossy(&out.stderr);
    assert!(warnings.trim().is_empty(), "groff warns: {warnings}");
    let mut text = String::new();
    for c in String::from_utf8_lossy(&out.stdout).chars() {
        if c == '\x08' {
            text.pop();
        } else {
            text.push(c);
        }
    }
    text
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
    for section in ["EXIT STATUS", "SCENES", "EXAMPLES", "SEE ALSO"] {
        assert!(page.contains(&format!(".SH \"{section}\"")), "no {section}");
    }
    // Rendered, the text comes out whole (groff is required: CI installs it).
    let text = words(&rendered(&page));
    for heading in ["COLLIDE CONTACT", "EXIT STATUS", "EXAMPLES", "SEE ALSO"] {
        assert!(text.contains(heading), "rendered page has no {heading}");
    }
    assert!(text.contains("collide solve -m 6,1 -v 3,-4 -e 2/3"));
}

/// Runs of whitespace as one space: text compared whatever its wrapping.
fn words(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Examples as lines of text, each `collide ...` with its continuations (a line that ends with
/// ` \` goes on, indented further, on the next) joined into one command line.
fn joined(lines: &[&str]) -> Vec<String> {
    let mut examples: Vec<String> = Vec::new();
    let mut continued = false;
    for line in lines {
        let text = line.trim();
        if continued {
            let last = examples.last_mut().unwrap();
            last.truncate(last.len() - 1);
            last.push_str(text);
        } else {
            examples.push(text.to_string());
        }
        continued = text.ends_with(" \\");
    }
    examples
}

/// The `Examples:` of `collide SUB --help` (`SUB` may be `view track`), each on one line.
fn help_examples(sub: &str) -> Vec<String> {
    let mut args: Vec<&str> = sub.split(' ').collect();
    args.push("--help");
    let help = stdout(&args);
    let (_, examples) = help
        .split_once("\nExamples:\n")
        .unwrap_or_else(|| panic!("{sub} --help has no examples"));
    let lines: Vec<&str> = examples
        .lines()
        .take_while(|l| l.starts_with("  collide ") || l.starts_with("      "))
        .collect();
    joined(&lines)
}

#[test]
fn help_examples_fit_80_columns_and_continue_indented() {
    // Issue 45 §3: a wrapped example's tail sat at the indent of the next example and read as a
    // command of its own. At the default width every line of every `--help` fits 80 columns; in
    // Examples, a line is an example (`collide` at two spaces) or the indented continuation of
    // one whose line ends with ` \`; and the man page's EXAMPLES, as `man` lays them out at 80
    // columns, fit too.
    for sub in SUBCOMMANDS.iter().copied().chain(["view track"]) {
        let mut args: Vec<&str> = sub.split(' ').collect();
        args.push("--help");
        let out = common::collide_at_default_width()
            .args(&args)
            .output()
            .unwrap();
        let help = String::from_utf8(out.stdout).unwrap();
        for line in help.lines() {
            assert!(line.chars().count() <= 80, "{sub} --help: {line}");
        }
        let usage = help.lines().find(|l| l.starts_with("Usage: ")).unwrap();
        assert!(
            usage.starts_with(&format!("Usage: collide {sub} ")),
            "{usage}"
        );
        let (_, examples) = help.split_once("\nExamples:\n").unwrap();
        let mut continued = false;
        for line in examples.lines().take_while(|l| !l.is_empty()) {
            if continued {
                assert!(
                    line.starts_with("      ") && line.trim_start().starts_with("-")
                        || line.trim_start().starts_with("> "),
                    "{sub}: '{line}'"
                );
            } else {
                assert!(
                    line.starts_with("  collide "),
                    "{sub}: '{line}' is no example"
                );
            }
            continued = line.ends_with(" \\");
        }
        assert!(
            !continued,
            "{sub}: the last example ends with a continuation"
        );
    }
    // `collide view track`'s examples run (the man page lists the top subcommands' only).
    for example in help_examples("view track") {
        let run = Sandbox::new("view-track").run(&example);
        assert_eq!((run.status, run.stderr.as_str()), (0, ""), "{example}");
    }
    let page = rendered(&stdout(&["man"]));
    let (_, section) = page.split_once("\nEXAMPLES\n").unwrap();
    let section: Vec<&str> = section
        .lines()
        .take_while(|l| !l.starts_with("SEE ALSO"))
        .collect();
    assert!(section.len() > 20, "{}", section.join("\n"));
    for line in section {
        assert!(line.chars().count() <= 80, "man EXAMPLES: {line}");
    }
}

#[test]
fn every_help_example_runs_and_succeeds() {
    let mut all = Vec::new();
    for sub in SUBCOMMANDS {
        let examples = help_examples(sub);
        assert!(!examples.is_empty(), "{sub} --help has no examples");
        all.extend(examples);
    }
    // Each in its own folder, on two threads (the CI machine's cores; `scene scenarios/*.toml`
    // alone takes about 4 s): what it writes is counted, then removed. Checked in order after.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let runs: Vec<std::sync::Mutex<Option<(Shown, usize)>>> =
        all.iter().map(|_| std::sync::Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(example) = all.get(i) else { break };
                    let sandbox = Sandbox::new("help");
                    let run = sandbox.run(example);
                    let written = std::fs::read_dir(&sandbox.dir).unwrap().count() - 1;
                    *runs[i].lock().unwrap() = Some((run, written));
                }
            });
        }
    });
    for (example, run) in all.iter().zip(runs) {
        let (run, written) = run.into_inner().unwrap().expect("every example ran");
        assert_eq!(run.status, 0, "{example}: {}", run.stderr);
        assert!(
            !run.stdout.is_empty() || written > 0,
            "{example} printed nothing and wrote no file"
        );
    }
    // The man page's EXAMPLES are these, in the same order.
    let page = stdout(&["man"]);
    let section = page.split(".SH \"EXAMPLES\"\n.nf\n").nth(1).unwrap();
    let listed: Vec<String> = section
        .lines()
        .take_while(|l| *l != ".fi")
        .map(|l| l.replace("\\-", "-").replace("\\e", "\\"))
        .collect();
    let listed: Vec<&str> = listed.iter().map(String::as_str).collect();
    assert_eq!(joined(&listed), all);
}

/// Runs one of `collide SUB --help`'s examples (it must be listed there) in a sandbox, and
/// requires a clean run: exit 0, nothing on stderr.
fn run_help_example(sub: &str, example: &str) -> (Sandbox, Shown) {
    assert!(
        help_examples(sub).iter().any(|e| e == example),
        "{sub} --help no longer gives {example}"
    );
    let sandbox = Sandbox::new(sub);
    let run = sandbox.run(example);
    assert_eq!((run.status, run.stderr.as_str()), (0, ""), "{example}");
    (sandbox, run)
}

/// `n/d` in lowest terms as `--exact` prints it (`p` when whole).
fn fraction(n: i64, d: i64) -> String {
    let (mut a, mut b) = (n.abs(), d);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    match (n / a, d / a) {
        (p, 1) => p.to_string(),
        (p, q) => format!("{p}/{q}"),
    }
}

#[test]
fn frames_help_example_gives_the_exact_fractions() {
    // `collide frames -m 4,1 -v 60,10 -e 2/3 --exact`, by hand: V_COM = 250/5 = 50; FIN = (1 + e)
    // V_COM - e V_IN = (250/3 - 40, 250/3 - 20/3) = (130/3, 230/3); crunch = 1/2 (4/5) 50^2 =
    // 1000, lost = (1 - 4/9) 1000 = 5000/9. The frames' observers move at w = 0 (lab), 60 and 10
    // (a body initially at rest), 50 (COM), 130/3 and 230/3 (finally at rest); each sees every
    // velocity shifted by -w, and KE = 1/2 (4 a^2 + b^2) of its own velocities (a, b). In thirds:
    assert_eq!(
        (fraction(6, 3), fraction(-20, 3), fraction(9, 18)),
        ("2".into(), "-20/3".into(), "1/2".into())
    );
    let example = "collide frames -m 4,1 -v 60,10 -e 2/3 --exact";
    let (_, text) = run_help_example("frames", example);
    let (code, json, err) = common::run(&[
        "frames", "-m", "4,1", "-v", "60,10", "-e", "2/3", "--exact", "--format", "json",
    ]);
    assert_eq!((code, err.as_str()), (0, ""));
    let json: serde_json::Value = serde_json::from_str(&json).unwrap();
    let frames = json["frames"].as_array().unwrap();
    let names = [
        "lab",
        "rest-in:1",
        "rest-in:2",
        "com",
        "rest-fin:1",
        "rest-fin:2",
    ];
    let w3 = [0, 180, 30, 150, 130, 230];
    assert_eq!(frames.len(), names.len());
    let pair = |a3: i64, b3: i64| serde_json::json!([fraction(a3, 3), fraction(b3, 3)]);
    let ke = |a3: i64, b3: i64| fraction(4 * a3 * a3 + b3 * b3, 18);
    for ((frame, name), w3) in frames.iter().zip(names).zip(w3) {
        let (in1, in2, com, fin1, fin2) = (180 - w3, 30 - w3, 150 - w3, 130 - w3, 230 - w3);
        assert_eq!(frame["name"], name);
        assert_eq!(frame["w"], fraction(w3, 3), "{name}");
        assert_eq!(frame["in"], pair(in1, in2), "{name}");
        assert_eq!(frame["com"], pair(com, com), "{name}");
        assert_eq!(frame["fin"], pair(fin1, fin2), "{name}");
        let energy = &frame["energy"];
        assert_eq!(energy["in"], ke(in1, in2), "{name}");
        assert_eq!(energy["fin"], ke(fin1, fin2), "{name}");
        assert_eq!(energy["com"], ke(com, com), "{name}");
        assert_eq!(
            (&energy["crunch"], &energy["lost"]),
            (&"1000".into(), &"5000/9".into())
        );
        // The text the example prints shows the same fractions.
        for value in [fraction(fin1, 3), ke(fin1, fin2)] {
            assert!(
                text.stdout.contains(&value),
                "{example}: no {value} ({name})"
            );
        }
    }
    let invariants = &json["invariants"];
    assert_eq!(invariants["restitution"], "2/3");
    assert_eq!(invariants["relative_velocity"], "50");
}

#[test]
fn scene_help_example_gives_one_json_object_per_scene() {
    // `collide scene scenarios/*.toml --format json`: an array in file order, one object per
    // scene; a scene that checks numbers has as many checks as its [expect] table has keys, all
    // passed, and a [sweep] scene says what table it wrote (`"table"`) instead.
    let (_, run) = run_help_example("scene", "collide scene scenarios/*.toml --format json");
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let reports = json.as_array().expect("an array for several scenes");
    let mut files: Vec<_> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let mut scenes = Vec::new();
    for file in files {
        let scene: toml::Table = std::fs::read_to_string(&file).unwrap().parse().unwrap();
        scenes.push((file, scene));
    }
    assert_eq!(reports.len(), scenes.len());
    for (report, (file, scene)) in reports.iter().zip(&scenes) {
        let name = file.display().to_string();
        if scene.contains_key("sweep") {
            assert!(
                report["table"]["rows"].as_u64().unwrap() > 0,
                "{name}: {report}"
            );
            continue;
        }
        assert_eq!(report["scene"], name.as_str());
        assert_eq!(report["title"], scene["title"].as_str().unwrap(), "{name}");
        // A scene of stages checks its own [expect] and each [stage.expect].
        let stages = scene.get("stage").and_then(toml::Value::as_array);
        let expected = scene["expect"].as_table().unwrap().len()
            + stages.map_or(0, |s| {
                s.iter()
                    .filter_map(|t| t.get("expect").and_then(toml::Value::as_table))
                    .map(toml::map::Map::len)
                    .sum()
            });
        assert_eq!(report["checks"], expected, "{name}");
        assert_eq!(report["failed"], serde_json::json!([]), "{name}");
        assert!(report["report"].is_object(), "{name}");
    }
}

#[test]
fn plot_help_example_writes_the_pinned_picture() {
    // `collide plot -m 4,1 -v 60,10 -o case-a.svg` writes exactly the README's picture
    // (examples/case-a.svg, whose geometry tests/suite/plot.rs checks) and prints nothing.
    let (sandbox, run) = run_help_example("plot", "collide plot -m 4,1 -v 60,10 -o case-a.svg");
    assert_eq!(run.stdout, "");
    let written = std::fs::read(sandbox.dir.join("case-a.svg")).unwrap();
    assert!(written == std::fs::read("examples/case-a.svg").unwrap());
}

/// The guide's exit-status table (docs/cli.md): `(status, meaning)`, Markdown removed.
fn guide_exit_statuses() -> Vec<(String, String)> {
    let page = std::fs::read_to_string("docs/cli.md").unwrap();
    let section = page
        .split("\n## Exit status\n")
        .nth(1)
        .expect("## Exit status");
    section
        .lines()
        .take_while(|l| !l.starts_with("## "))
        .filter_map(|l| {
            let cells: Vec<&str> = l.strip_prefix("| ")?.split(" | ").collect();
            let status = cells.first()?.trim();
            status.parse::<u8>().ok()?;
            let meaning = cells[1..].join(" | ");
            let meaning = meaning.trim_end_matches(" |").replace("\\|", "|");
            Some((status.to_string(), words(&meaning)))
        })
        .collect()
}

#[test]
fn help_and_man_page_state_the_guides_exit_statuses() {
    let guide = guide_exit_statuses();
    let statuses: BTreeSet<&str> = guide.iter().map(|(s, _)| s.as_str()).collect();
    assert_eq!(statuses, BTreeSet::from(["0", "1", "2", "130"]));
    // collide --help: after "Exit status:", the same lines, in the same order.
    let help = stdout(&["--help"]);
    let block = help.split_once("Exit status:\n").expect("Exit status:").1;
    let stated = words(block);
    let expected = guide
        .iter()
        .map(|(s, m)| format!("{s} {m}"))
        .collect::<Vec<_>>()
        .join(" ");
    assert_eq!(stated, expected, "collide --help against docs/cli.md");
    // The man page: one .TP paragraph per status, roff escapes undone.
    let page = stdout(&["man"]);
    let section = page.split(".SH \"EXIT STATUS\"\n").nth(1).unwrap();
    let section: Vec<String> = section
        .lines()
        .take_while(|l| !l.starts_with(".SH"))
        .filter(|l| *l != ".TP")
        .map(|l| {
            l.trim_start_matches(".B ")
                .replace("\\-", "-")
                .replace("\\e", "\\")
        })
        .collect();
    assert_eq!(
        words(&section.join(" ")),
        expected,
        "collide man against docs/cli.md"
    );
}

/// `1000000` as `1,000,000`.
fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

#[test]
fn the_guides_limits_give_the_helps_defaults() {
    // `--help` prints each cap's default from the constant the code uses; the limits table in
    // the guide must give the same number (it once said 1,000,000 where the code had 1e10).
    assert_eq!(grouped(10_000_000_000), "10,000,000,000");
    assert_eq!(grouped(100), "100");
    let page = std::fs::read_to_string("docs/accuracy.md").unwrap();
    for (sub, flag) in [
        ("sweep", "--max-rows"),
        ("track", "--max-collisions"),
        ("contact", "--max-steps"),
    ] {
        let help = stdout(&[sub, "--help"]);
        let after = help.split_once(&format!("{flag} <N>")).unwrap().1;
        let default: u64 = after
            .split_once("[default: ")
            .and_then(|(_, rest)| rest.split_once(']'))
            .and_then(|(n, _)| n.parse().ok())
            .unwrap_or_else(|| panic!("{sub} --help gives {flag} no default"));
        let row = page
            .lines()
            .find(|l| l.starts_with('|') && l.contains(&format!("`{flag}` (default")))
            .unwrap_or_else(|| panic!("docs/accuracy.md has no limits row for {flag}"));
        assert!(
            row.contains(&format!("`{flag}` (default {})", grouped(default))),
            "docs/accuracy.md says {row}; {sub} --help says {default}"
        );
    }
}
