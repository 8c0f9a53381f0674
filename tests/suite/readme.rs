//! Every example in the README and in the guide (`docs/`) is real. In a ```console block each
//! `$ collide ...` line is run, in a fresh temporary folder whose `scenarios/` is the project's,
//! and must print exactly the lines below it: standard output, then (after a line `[stderr]`)
//! standard error, and a last line `[exit N]` when the exit status is not 0. Streams are compared
//! separately; trailing whitespace at the end of each is ignored. To refresh the examples after a
//! deliberate change of output: `UPDATE_README=1 cargo test --release --test suite readme`.
//!
//! The other tests here keep the documents honest as documents: links resolve, every guide page
//! is in the book's table of contents, prose fits 100 columns, and the architecture page's table
//! of tests names every test module.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::common::collide_at_default_width as collide;

/// The documents whose examples are run: the README and every page of the guide, sorted.
pub fn documents() -> Vec<PathBuf> {
    let mut docs = vec![PathBuf::from("README.md")];
    let mut pending = vec![PathBuf::from("docs")];
    while let Some(dir) = pending.pop() {
        for entry in std::fs::read_dir(&dir).expect("the guide is in docs/") {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                docs.push(path);
            }
        }
    }
    docs[1..].sort();
    docs
}

/// What an example shows, or what a run printed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shown {
    pub stdout: String,
    pub stderr: String,
    pub status: i32,
}

impl Shown {
    /// The lines of a console block below the command.
    fn lines(&self) -> Vec<String> {
        let mut lines: Vec<String> = self.stdout.lines().map(String::from).collect();
        if !self.stderr.is_empty() {
            lines.push(STDERR.to_string());
            lines.extend(self.stderr.lines().map(String::from));
        }
        if self.status != 0 {
            lines.push(format!("[exit {}]", self.status));
        }
        lines
    }

    /// Reads the lines below a command: stdout, `[stderr]` and stderr, `[exit N]`.
    fn parse(lines: &[&str]) -> Result<Shown, String> {
        let mut lines = lines.to_vec();
        let mut status = 0;
        if let Some(last) = lines.last()
            && let Some(n) = last
                .strip_prefix("[exit ")
                .and_then(|s| s.strip_suffix(']'))
        {
            status = n
                .parse()
                .map_err(|_| format!("'{last}': expected [exit N]"))?;
            if status == 0 {
                return Err("[exit 0] is the default: leave it out".into());
            }
            lines.pop();
        }
        if let Some(bad) = lines.iter().find(|l| l.starts_with("[exit ")) {
            return Err(format!("'{bad}' must be the example's last line"));
        }
        let (out, err) = match lines.iter().position(|l| *l == STDERR) {
            Some(i) => (&lines[..i], &lines[i + 1..]),
            None => (&lines[..], &[][..]),
        };
        Ok(Shown {
            stdout: out.join("\n").trim_end().to_string(),
            stderr: err.join("\n").trim_end().to_string(),
            status,
        })
    }
}

/// The line that separates an example's stdout from its stderr.
const STDERR: &str = "[stderr]";

/// A command line as a shell would split it: words, '...' and "..." quoting, a `dir/*.ext`
/// glob (sorted), `> FILE` for stdout, `| reader` (not run) and a `# comment` at the end.
#[derive(Debug, PartialEq, Eq)]
pub struct CommandLine {
    pub args: Vec<String>,
    pub stdout_to: Option<String>,
}

impl CommandLine {
    /// Splits `collide ARGS...`; `None` if the line does not run collide.
    pub fn parse(line: &str, dir: &Path) -> Option<CommandLine> {
        let mut words = Vec::new();
        let mut word = String::new();
        let mut quote = None;
        let mut started = false;
        for ch in line.chars() {
            match (quote, ch) {
                (None, '#') if !started => break,
                (None, '\'' | '"') => {
                    quote = Some(ch);
                    started = true;
                }
                (Some(q), c) if c == q => quote = None,
                (None, ' ') => {
                    if started {
                        words.push(std::mem::take(&mut word));
                        started = false;
                    }
                }
                (_, c) => {
                    word.push(c);
                    started = true;
                }
            }
        }
        if started {
            words.push(word);
        }
        if words.first().map(String::as_str) != Some("collide") {
            return None;
        }
        let mut args = Vec::new();
        let mut stdout_to = None;
        let mut rest = words.into_iter().skip(1);
        while let Some(w) = rest.next() {
            match w.rsplit_once('/') {
                _ if w == ">" => stdout_to = rest.next(),
                // `collide man | man -l -`: what reads the output is not run.
                _ if w == "|" => break,
                // `folder/prefix*suffix`: the matching names, sorted.
                Some((folder, pattern)) if pattern.contains('*') => {
                    let (prefix, suffix) = pattern.split_once('*').unwrap();
                    let mut paths: Vec<String> = std::fs::read_dir(dir.join(folder))
                        .unwrap()
                        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                        .filter(|name| {
                            name.len() >= prefix.len() + suffix.len()
                                && name.starts_with(prefix)
                                && name.ends_with(suffix)
                        })
                        .map(|name| format!("{folder}/{name}"))
                        .collect();
                    paths.sort();
                    assert!(!paths.is_empty(), "{w} matches no file");
                    args.extend(paths);
                }
                _ => args.push(w),
            }
        }
        Some(CommandLine { args, stdout_to })
    }
}

/// A fresh folder under the system's temporary directory in which `scenarios/` is the
/// project's (a symbolic link), so examples that write files write them there; removed when
/// dropped.
pub struct Sandbox {
    pub dir: PathBuf,
}

impl Sandbox {
    pub fn new(tag: &str) -> Sandbox {
        static COUNT: AtomicUsize = AtomicUsize::new(0);
        let n = COUNT.fetch_add(1, Ordering::Relaxed);
        let dir =
            std::env::temp_dir().join(format!("collide-docs-{}-{tag}-{n}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let scenarios = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
        std::os::unix::fs::symlink(scenarios, dir.join("scenarios")).unwrap();
        Sandbox { dir }
    }

    /// Runs a `collide ...` line here (`COLUMNS` unset, so output does not depend on the
    /// terminal); a `> FILE` redirection writes stdout to FILE in this folder (`~/` is this
    /// folder too) and shows it as empty.
    pub fn run(&self, line: &str) -> Shown {
        let command = CommandLine::parse(line, &self.dir)
            .unwrap_or_else(|| panic!("'{line}' does not run collide"));
        let out = collide()
            .current_dir(&self.dir)
            .env_remove("COLUMNS")
            .args(&command.args)
            .output()
            .unwrap();
        let mut stdout = String::from_utf8(out.stdout).expect("stdout is UTF-8");
        if let Some(file) = command.stdout_to {
            let path = self.dir.join(file.trim_start_matches("~/"));
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, std::mem::take(&mut stdout)).unwrap();
        }
        Shown {
            stdout: stdout.trim_end().to_string(),
            stderr: String::from_utf8(out.stderr)
                .expect("stderr is UTF-8")
                .trim_end()
                .to_string(),
            status: out.status.code().unwrap_or(-1),
        }
    }
}

impl Drop for Sandbox {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// One `$ collide ...` example of a document.
struct Example {
    line: usize,
    command: String,
    shown: Shown,
}

/// A document as plain lines and console blocks (each held as its examples).
enum Part<'a> {
    Plain(&'a str),
    Console(Vec<Example>),
}

/// Splits a document into its parts; an error names the line of anything malformed: a console
/// block that runs something other than collide, a `$ collide` line outside a console block
/// (it would never be run), an unclosed fence.
fn parts(text: &str) -> Result<Vec<Part<'_>>, String> {
    let mut parts = Vec::new();
    let mut lines = text.lines().enumerate().peekable();
    let mut fence: Option<usize> = None;
    while let Some((i, line)) = lines.next() {
        parts.push(Part::Plain(line));
        if fence.is_some() {
            if line.trim_start().starts_with("```") {
                fence = None;
            } else if line.starts_with("$ collide") {
                return Err(format!(
                    "line {}: a `$ collide` example outside a ```console block is never run",
                    i + 1
                ));
            }
            continue;
        }
        if !line.trim_start().starts_with("```") {
            continue;
        }
        if line != "```console" {
            fence = Some(i);
            continue;
        }
        let mut block: Vec<(usize, &str)> = Vec::new();
        let mut closed = false;
        for (j, l) in lines.by_ref() {
            if l == "```" {
                closed = true;
                break;
            }
            block.push((j, l));
        }
        if !closed {
            return Err(format!("line {}: a console block is not closed", i + 1));
        }
        let mut examples = Vec::new();
        let mut k = 0;
        while k < block.len() {
            let (j, l) = block[k];
            let command = l
                .strip_prefix("$ ")
                .filter(|c| c.starts_with("collide "))
                .ok_or_else(|| {
                    format!(
                        "line {}: a console block holds `$ collide ...` lines and their output",
                        j + 1
                    )
                })?;
            let end = (k + 1..block.len())
                .find(|&m| block[m].1.starts_with("$ "))
                .unwrap_or(block.len());
            let output: Vec<&str> = block[k + 1..end].iter().map(|(_, l)| *l).collect();
            let shown = Shown::parse(&output).map_err(|e| format!("line {}: {e}", j + 1))?;
            examples.push(Example {
                line: j + 1,
                command: command.to_string(),
                shown,
            });
            k = end;
        }
        parts.push(Part::Console(examples));
        parts.push(Part::Plain("```"));
    }
    if let Some(i) = fence {
        return Err(format!("line {}: a fenced block is not closed", i + 1));
    }
    Ok(parts)
}

#[test]
fn every_example_prints_what_it_shows_and_exits_as_stated() {
    let update = std::env::var_os("UPDATE_README").is_some();
    let mut failures = Vec::new();
    let mut counts = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        let parts = parts(&text).unwrap_or_else(|e| panic!("{}: {e}", doc.display()));
        let mut rewritten = Vec::new();
        let mut count = 0;
        for part in &parts {
            match part {
                Part::Plain(line) => rewritten.push(line.to_string()),
                Part::Console(examples) => {
                    for example in examples {
                        let actual = Sandbox::new("readme").run(&example.command);
                        count += 1;
                        if actual != example.shown {
                            failures.push(format!(
                                "{}:{}: $ {}\n--- shown:\n{}\n--- printed:\n{}\n",
                                doc.display(),
                                example.line,
                                example.command,
                                example.shown.lines().join("\n"),
                                actual.lines().join("\n"),
                            ));
                        }
                        rewritten.push(format!("$ {}", example.command));
                        rewritten.extend(actual.lines());
                    }
                }
            }
        }
        counts.push((doc.clone(), count));
        let rewritten = rewritten.join("\n") + "\n";
        if update && rewritten != text {
            std::fs::write(&doc, rewritten).unwrap();
        }
    }
    // The README promises ten examples covering the subcommands; the guide holds the rest.
    let readme = counts[0].1;
    let total: usize = counts.iter().map(|(_, n)| n).sum();
    assert!(readme >= 10, "only {readme} examples in README.md");
    assert!(total >= 40, "only {total} examples in all: {counts:?}");
    if update {
        return;
    }
    assert!(
        failures.is_empty(),
        "{} of {total} examples out of date (UPDATE_README=1 refreshes them):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn examples_are_parsed_as_written() {
    // Quoting, globs and redirection as a shell would do them.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let line = "collide solve -m '4 ton,1 ton' -v \"?,10 mph\" --show vectors  # a comment";
    assert_eq!(
        CommandLine::parse(line, dir).unwrap().args,
        [
            "solve",
            "-m",
            "4 ton,1 ton",
            "-v",
            "?,10 mph",
            "--show",
            "vectors"
        ]
    );
    let glob = CommandLine::parse("collide scene scenarios/*.toml", dir).unwrap();
    assert!(glob.args.len() > 30 && glob.args[1] == "scenarios/bouncing-ball.toml");
    assert!(glob.args[1..].windows(2).all(|w| w[0] < w[1]));
    let glob = CommandLine::parse("collide scene scenarios/fig-2-3-*.toml", dir).unwrap();
    assert_eq!(
        glob.args[1..],
        [
            "scenarios/fig-2-3-elastic.toml",
            "scenarios/fig-2-3-inelastic.toml",
            "scenarios/fig-2-3-ka-whump-exact.toml",
            "scenarios/fig-2-3-ka-whump.toml"
        ]
    );
    let redirect = CommandLine::parse("collide completions zsh > ~/.zfunc/_collide", dir).unwrap();
    assert_eq!(redirect.args, ["completions", "zsh"]);
    assert_eq!(redirect.stdout_to.as_deref(), Some("~/.zfunc/_collide"));
    assert_eq!(CommandLine::parse("cargo run", dir), None);
    // What an example shows: stdout, then stderr after [stderr], then [exit N].
    let shown = Shown::parse(&["a", "b", "[stderr]", "error: c", "[exit 2]"]).unwrap();
    assert_eq!(
        shown,
        Shown {
            stdout: "a\nb".into(),
            stderr: "error: c".into(),
            status: 2
        }
    );
    assert_eq!(
        Shown::parse(&shown.lines().iter().map(String::as_str).collect::<Vec<_>>()),
        Ok(shown)
    );
    assert!(Shown::parse(&["[exit 0]"]).is_err());
    assert!(Shown::parse(&["[exit 1]", "late"]).is_err());
    // A malformed document is refused with its line.
    assert!(parts("```text\n$ collide pi 3\n```\n").is_err());
    assert!(parts("```console\n$ ls\n```\n").is_err());
    assert!(parts("```console\n$ collide pi 3\n").is_err());
}

/// GitHub's (and mdBook's) anchor for a heading: lower case, letters, digits, `-` and `_` kept,
/// spaces to `-`, everything else dropped.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// A document's lines outside fenced blocks, with their numbers.
fn prose(text: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut fenced = false;
    for (i, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            out.push((i + 1, line));
        }
    }
    out
}

/// The anchors of a document's headings.
fn anchors(text: &str) -> BTreeSet<String> {
    prose(text)
        .into_iter()
        .filter_map(|(_, l)| l.strip_prefix('#'))
        .map(|h| slug(h.trim_start_matches('#')))
        .collect()
}

/// The targets of a line's Markdown links and images, `](target)`.
fn links(line: &str) -> Vec<&str> {
    line.match_indices("](")
        .filter_map(|(i, _)| line[i + 2..].split_once(')').map(|(t, _)| t))
        .collect()
}

#[test]
fn links_resolve_and_every_page_is_in_the_summary() {
    let mut broken = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        let folder = doc.parent().unwrap();
        for (n, line) in prose(&text) {
            for target in links(line) {
                if target.contains("://") || target.starts_with("mailto:") {
                    continue;
                }
                let (file, anchor) = target.split_once('#').unwrap_or((target, ""));
                let path = if file.is_empty() {
                    doc.clone()
                } else {
                    folder.join(file)
                };
                if !path.exists() {
                    broken.push(format!("{}:{n}: no file {target}", doc.display()));
                } else if !anchor.is_empty()
                    && !anchors(&std::fs::read_to_string(&path).unwrap()).contains(anchor)
                {
                    broken.push(format!("{}:{n}: no heading for {target}", doc.display()));
                }
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    // mdBook's table of contents lists every page of the guide, and only those.
    let summary = std::fs::read_to_string("docs/SUMMARY.md").unwrap();
    let listed: BTreeSet<PathBuf> = summary
        .lines()
        .flat_map(links)
        .map(|t| Path::new("docs").join(t))
        .collect();
    let pages: BTreeSet<PathBuf> = documents()
        .into_iter()
        .filter(|d| d.starts_with("docs") && !d.ends_with("SUMMARY.md"))
        .collect();
    assert_eq!(listed, pages, "docs/SUMMARY.md against the pages in docs/");
}

#[test]
fn prose_lines_fit_100_columns() {
    let mut long = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        for (n, line) in prose(&text) {
            // Table rows cannot be wrapped; everything else can.
            let width = line.chars().count();
            if width > 100 && !line.starts_with('|') {
                long.push(format!("{}:{n}: {width} characters", doc.display()));
            }
        }
    }
    assert!(
        long.is_empty(),
        "prose lines over 100:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_readme_stays_a_short_tour() {
    // Issue 28: the README had grown to 1,372 lines; the rest belongs in the guide. (250 until
    // the plane, rigid bodies and the page joined the tour: a planar example and three rows.)
    let lines = std::fs::read_to_string("README.md")
        .unwrap()
        .lines()
        .count();
    assert!(
        lines < 300,
        "README.md has {lines} lines: move the detail to docs/"
    );
}

#[test]
fn the_architecture_page_lists_every_test_module() {
    let main = std::fs::read_to_string("tests/suite/main.rs").unwrap();
    let page = std::fs::read_to_string("docs/architecture.md").unwrap();
    let missing: Vec<&str> = main
        .lines()
        .filter_map(|l| l.strip_prefix("mod ")?.strip_suffix(';'))
        .filter(|m| !page.contains(&format!("`tests/suite/{m}.rs`")))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/architecture.md has no row for tests/suite/{{{}}}.rs",
        missing.join(",")
    );
}

#[test]
fn the_readme_starts_with_an_answer() {
    // Issue 45 §2: the first screen (24 lines) shows what collide does by doing it: a command and
    // its output, before the set-up.
    let readme = std::fs::read_to_string("README.md").unwrap();
    let first: Vec<&str> = readme.lines().take(24).collect();
    let command = first.iter().position(|l| l.starts_with("$ collide "));
    let setup = readme.lines().position(|l| l == "## Set-up");
    assert!(
        command.is_some_and(|c| setup.is_some_and(|s| c < s)),
        "no `$ collide` example in the README's first 24 lines, before its set-up"
    );
    let shown = first[command.unwrap() + 1..]
        .iter()
        .take_while(|l| !l.starts_with("```"))
        .count();
    assert!(
        (1..=8).contains(&shown),
        "the first example shows {shown} lines"
    );
}

/// `name version [(proc-macro)] features` for each crate a build compiles: `cargo tree` from the
/// lock file (no network), with the dependency `edges` of that build.
fn resolved_features(edges: &str) -> BTreeSet<String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = std::process::Command::new(cargo)
        .args([
            "tree",
            "--offline",
            "--locked",
            "-p",
            "collide",
            "--prefix",
            "none",
        ])
        .args(["-e", edges, "-f", "{p} {f}"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "cargo tree -e {edges}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| l.trim_end_matches(" (*)").trim_end().to_string())
        .filter(|l| !l.is_empty())
        .collect()
}

#[test]
fn the_two_setup_commands_share_one_build() {
    // Issue 45 §1: `cargo run --release` then `cargo test --release --locked` (the README's
    // set-up) compiled 44 crates twice, nalgebra and clap among them: Cargo's resolver 2 keeps
    // dev-dependencies' features out of the normal build, so a dev-dependency that switched on a
    // feature of a shared crate (approx's `default`, rustix's `fs` through proptest's `fork`)
    // gave that crate, and every crate above it, a second build. Every crate the binary's build
    // compiles must have the same features in the tests' build; the tests add crates of their
    // own (proptest, assert_cmd, ...), compiled once.
    let run = resolved_features("normal,build");
    let test = resolved_features("normal,build,dev");
    assert!(
        run.iter().any(|c| c.starts_with("nalgebra ")) && run.len() > 100,
        "cargo tree listed {} crates for the binary",
        run.len()
    );
    let twice: Vec<String> = run
        .iter()
        .filter(|c| !test.contains(*c))
        .map(|c| {
            let name = c.split(' ').take(2).collect::<Vec<_>>().join(" ");
            let other = test.iter().filter(|t| t.starts_with(&format!("{name} ")));
            format!(
                "{c}  ->  {}",
                other.cloned().collect::<Vec<_>>().join(" | ")
            )
        })
        .collect();
    assert!(
        twice.is_empty(),
        "the tests' build changes these crates' features (a second build of each; add the \
         feature to [dependencies] or drop it from [dev-dependencies]):\n{}",
        twice.join("\n")
    );
}
