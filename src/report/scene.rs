//! `collide scene`'s report: each scene solved and checked against its `[expect]` numbers, for
//! people (one scene in full, several a line each) and as JSON.

use std::path::PathBuf;

use serde::Serialize;

use super::text::wrap;
use crate::expect::Check;

/// A scene solved and checked.
pub struct Checked {
    pub path: PathBuf,
    pub title: Option<String>,
    pub source: Option<String>,
    /// The report for people (what a single scene prints).
    pub text: String,
    pub json: serde_json::Value,
    pub checks: Vec<Check>,
    /// The given data contradict a law checked rather than used (`Check: ... does NOT hold`).
    pub inconsistent: bool,
}

impl Checked {
    pub fn failures(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| !c.passed)
    }

    pub fn failed(&self) -> bool {
        self.inconsistent || self.failures().next().is_some()
    }
}

/// A `[sweep]` scene among several: listed, not written.
pub struct Listed {
    pub path: PathBuf,
    pub rows: u64,
    pub title: Option<String>,
}

#[derive(Serialize)]
struct SceneJson<'a> {
    scene: String,
    title: Option<&'a str>,
    source: Option<&'a str>,
    report: &'a serde_json::Value,
    checks: usize,
    failed: Vec<FailedJson<'a>>,
}

#[derive(Serialize)]
struct FailedJson<'a> {
    key: &'a str,
    line: usize,
    expected: &'a str,
    actual: &'a str,
}

/// The JSON of one scene, or an array of them for several.
pub fn json(scenes: &[Checked]) -> serde_json::Value {
    let one = |s: &Checked| {
        serde_json::to_value(SceneJson {
            scene: s.path.display().to_string(),
            title: s.title.as_deref(),
            source: s.source.as_deref(),
            report: &s.json,
            checks: s.checks.len(),
            failed: failures(s)
                .into_iter()
                .map(|c| FailedJson {
                    key: &c.key,
                    line: c.line,
                    expected: &c.expected,
                    actual: &c.actual,
                })
                .collect(),
        })
        .expect("scene reports serialize")
    };
    match scenes {
        [s] => one(s),
        all => all.iter().map(one).collect(),
    }
}

/// The failed checks of a scene, in the order of their lines in the file, each wrapped.
fn failure_lines(s: &Checked, out: &mut String) {
    for c in failures(s) {
        out.push_str(&wrap(
            &format!(
                "  FAIL {}:{}: {}: expected {} ({}), got {}",
                s.path.display(),
                c.line,
                c.key,
                c.expected,
                c.tolerance,
                c.actual
            ),
            crate::values::terminal::width(),
            "       ",
        ));
    }
}

/// The failed checks in the order of their lines.
fn failures(s: &Checked) -> Vec<&Check> {
    let mut failed: Vec<&Check> = s.failures().collect();
    failed.sort_by_key(|c| c.line);
    failed
}

/// A row of the summary: `aligned` (padded to line up with the others) when it fits the terminal,
/// else `plain` wrapped under column 6 (a long path does not push the counts past the edge).
fn fitted(aligned: String, plain: &str) -> String {
    let width = crate::values::terminal::width();
    if aligned.chars().count() <= width {
        return aligned;
    }
    wrap(plain, width, "      ").trim_end().to_string()
}

/// `line`, then `title` beside it when both fit the terminal, else on the next line under
/// column `under` (wrapped).
fn with_title(line: String, title: &str, under: usize) -> String {
    let width = crate::values::terminal::width();
    let whole = format!("{line}  {title}");
    if title.is_empty() || whole.chars().count() <= width {
        return format!("{}\n", whole.trim_end());
    }
    let indent = " ".repeat(under);
    format!(
        "{line}\n{}",
        wrap(&format!("{indent}{title}"), width, &indent)
    )
}

/// One scene in full: title, report, checks.
pub fn text(s: &Checked) -> String {
    let mut out = String::new();
    if let Some(t) = &s.title {
        let title = match &s.source {
            Some(src) => format!("{t} ({src})"),
            None => t.clone(),
        };
        out.push_str(&wrap(&title, crate::values::terminal::width(), "  "));
    }
    out.push_str(&s.text);
    if !s.checks.is_empty() {
        let failed = s.failures().count();
        out.push_str(&format!(
            "\nChecks: {} of {} pass\n",
            s.checks.len() - failed,
            s.checks.len()
        ));
        failure_lines(s, &mut out);
    }
    out
}

/// Several scenes, a line each (failures listed under their scene), then the tally.
pub fn summary(checked: &[Checked], listed: &[Listed]) -> String {
    let mut out = String::new();
    let width = checked
        .iter()
        .map(|s| s.path.display().to_string().len())
        .chain(listed.iter().map(|t| t.path.display().to_string().len()))
        .max()
        .unwrap_or(0);
    for s in checked {
        let failed = s.failures().count();
        let verdict = if failed > 0 { "FAIL" } else { "ok  " };
        let (path, pass, of) = (s.path.display(), s.checks.len() - failed, s.checks.len());
        let line = fitted(
            format!("{verdict}  {path:<width$}  {pass:>3}/{of:<3} checks"),
            &format!("{verdict}  {path}  {pass}/{of} checks"),
        );
        out.push_str(&with_title(line, s.title.as_deref().unwrap_or(""), 6));
        failure_lines(s, &mut out);
    }
    for t in listed {
        let (path, rows) = (t.path.display(), format!("{} rows", t.rows));
        let line = fitted(
            format!("table {path:<width$}  {rows:>13}"),
            &format!("table {path}  {rows}"),
        );
        let title = format!(
            "{} (a [sweep] scene: run it alone to write it)",
            t.title.as_deref().unwrap_or("")
        );
        out.push_str(&with_title(line, title.trim_start(), 6));
    }
    let bad = checked.iter().filter(|s| s.failed()).count();
    out.push_str(&format!(
        "{} scenes: {} pass, {} fail\n",
        checked.len(),
        checked.len() - bad,
        bad
    ));
    out
}
