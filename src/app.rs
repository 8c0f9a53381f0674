//! The commands: each turns validated arguments into the text to print and an exit status. Output
//! is built whole before anything is written, so an error never leaves half a report on stdout.

use anyhow::{Context, Result};
use serde::Serialize;

use crate::case::Case;
use crate::cli::{AccuracyArgs, CaseArgs, Command, Format, FramesArgs, SceneArgs, SolveArgs};
use crate::exact::ExactCollision;
use crate::expect::Check;
use crate::frame::{
    Frame, FrameInfo, FramesTable, Observed, restitution_exact, restitution_observed,
    reverse_equals_original, table,
};
use crate::inertia::InertiaTensor;
use crate::quantity::Exact;
use crate::report::{Report, Sections, json, text};
use crate::scene::{Scene, SceneError};

/// What a command prints and how it exits.
#[derive(Debug, PartialEq)]
pub struct Outcome {
    pub stdout: String,
    pub status: u8,
}

/// Runs a parsed command. `Err` is bad input: the caller prints it and exits 2.
pub fn run(command: Command) -> Result<Outcome> {
    match command {
        Command::Solve(args) => solve(args),
        Command::Scene(args) => scene(args),
        Command::Accuracy(args) => accuracy(args),
        Command::Frames(args) => frames(args),
    }
}

impl CaseArgs {
    pub fn into_case(self) -> Result<Case> {
        let inertia = match (self.inertia, self.masses) {
            (Some(t), _) => t,
            (None, Some([m1, m2])) => InertiaTensor::diagonal(&m1, &m2)?,
            (None, None) => anyhow::bail!("give --masses M1,M2 or --inertia 'M11,M12;M21,M22'"),
        };
        Ok(Case::new(inertia, self.velocities, self.restitution))
    }
}

fn solve(args: SolveArgs) -> Result<Outcome> {
    let case = args.case.into_case()?;
    let sections = Sections::new(args.show);
    let report = solve_case(&case, &args.frame, args.exact, &sections, args.reverse)?;
    let stdout = match args.format {
        Format::Text => report.text(&case, &sections),
        Format::Json => json::render(&report.json()),
    };
    Ok(Outcome { stdout, status: 0 })
}

/// Solves `case` seen from `frame`, in exact or binary64 arithmetic, with the time-reversed
/// collision when `reverse`.
pub fn solve_case(
    case: &Case,
    frame: &Frame,
    exact: bool,
    sections: &Sections,
    reverse: bool,
) -> Result<AnyReport> {
    if exact {
        let lab = ExactCollision::from_case(case);
        let w = frame.w_exact(&lab);
        let seen = lab.observed(&w);
        let mut r = Report::build(&seen, sections)?;
        r.frame = frame_info(frame, Exact::Rational(w.clone()));
        if reverse {
            r = r.with_reverse(&seen, reverse_equals_original(&lab, &w))?;
        }
        Ok(AnyReport::Exact(Box::new(r)))
    } else {
        let seen = Observed::new(&case.collision, frame);
        let mut r = Report::build(&seen, sections)?;
        r.frame = frame_info(frame, seen.w.value());
        if reverse {
            let lab = ExactCollision::from_binary64(&case.collision);
            let equal = reverse_equals_original(&lab, &frame.w_exact(&lab));
            r = r.with_reverse(&seen, equal)?;
        }
        Ok(AnyReport::Binary64(Box::new(r)))
    }
}

/// `"frame": {"name", "w"}` for any frame but the lab.
fn frame_info<N>(frame: &Frame, w: N) -> Option<FrameInfo<N>> {
    (*frame != Frame::Lab).then(|| FrameInfo {
        name: frame.to_string(),
        w,
    })
}

/// A report in the arithmetic that was asked for.
pub enum AnyReport {
    Binary64(Box<Report<f64>>),
    Exact(Box<Report<Exact>>),
}

impl AnyReport {
    pub fn json(&self) -> serde_json::Value {
        match self {
            AnyReport::Binary64(r) => serde_json::to_value(r),
            AnyReport::Exact(r) => serde_json::to_value(r),
        }
        .expect("reports serialize")
    }
    /// Text of the sections in `show` (others were computed only for a scene's checks).
    pub fn text(&self, case: &Case, show: &Sections) -> String {
        match self {
            AnyReport::Binary64(r) => text::render(case, &r.only(show)),
            AnyReport::Exact(r) => text::render(case, &r.only(show)),
        }
    }
}

/// A scene solved and checked.
struct Solved {
    scene: Scene,
    report: AnyReport,
    json: serde_json::Value,
    checks: Vec<Check>,
}

impl Solved {
    fn failures(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| !c.passed)
    }
}

fn solve_scene(scene: Scene) -> Result<Solved> {
    let sections = scene.sections_needed();
    let report = solve_case(&scene.case, &scene.frame, scene.exact, &sections, false)
        .with_context(|| format!("{}", scene.path.display()))?;
    let json = report.json();
    let checks = scene
        .expect
        .iter()
        .map(|e| {
            e.check(&json).map_err(|message| SceneError {
                path: scene.path.clone(),
                at: Some((e.line, 1)),
                message: format!("[expect] {message}"),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Solved {
        scene,
        report,
        json,
        checks,
    })
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

fn scene(args: SceneArgs) -> Result<Outcome> {
    // Load and solve every scene first: a bad file is an error before anything is printed.
    let solved = args
        .files
        .iter()
        .map(|p| solve_scene(Scene::load(p)?))
        .collect::<Result<Vec<_>>>()?;
    let failed = solved.iter().any(|s| s.failures().next().is_some());
    let stdout = match args.format {
        Format::Json => {
            let objects: Vec<SceneJson> = solved.iter().map(scene_json).collect();
            if objects.len() == 1 {
                json::render(&objects[0])
            } else {
                json::render(&objects)
            }
        }
        Format::Text if solved.len() == 1 => scene_text(&solved[0]),
        Format::Text => scene_summary(&solved),
    };
    Ok(Outcome {
        stdout,
        status: if failed { 1 } else { 0 },
    })
}

fn scene_json(s: &Solved) -> SceneJson<'_> {
    SceneJson {
        scene: s.scene.path.display().to_string(),
        title: s.scene.title.as_deref(),
        source: s.scene.source.as_deref(),
        report: &s.json,
        checks: s.checks.len(),
        failed: s
            .failures()
            .map(|c| FailedJson {
                key: &c.key,
                line: c.line,
                expected: &c.expected,
                actual: &c.actual,
            })
            .collect(),
    }
}

fn failure_lines(s: &Solved, out: &mut String) {
    for c in s.failures() {
        out.push_str(&format!(
            "  FAIL {}:{}: {}: expected {} ({}), got {}\n",
            s.scene.path.display(),
            c.line,
            c.key,
            c.expected,
            c.tolerance,
            c.actual
        ));
    }
}

fn scene_text(s: &Solved) -> String {
    let mut out = String::new();
    let sc = &s.scene;
    if let Some(t) = &sc.title {
        out.push_str(t);
        if let Some(src) = &sc.source {
            out.push_str(&format!(" ({src})"));
        }
        out.push('\n');
    }
    out.push_str(&s.report.text(&sc.case, &sc.show));
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

fn scene_summary(solved: &[Solved]) -> String {
    let mut out = String::new();
    let width = solved
        .iter()
        .map(|s| s.scene.path.display().to_string().len())
        .max()
        .unwrap_or(0);
    for s in solved {
        let failed = s.failures().count();
        let verdict = if failed > 0 { "FAIL" } else { "ok  " };
        out.push_str(&format!(
            "{verdict}  {:<width$}  {:>3}/{:<3} checks  {}\n",
            s.scene.path.display(),
            s.checks.len() - failed,
            s.checks.len(),
            s.scene.title.as_deref().unwrap_or("")
        ));
        failure_lines(s, &mut out);
    }
    let bad = solved
        .iter()
        .filter(|s| s.failures().next().is_some())
        .count();
    out.push_str(&format!(
        "{} scenes: {} pass, {} fail\n",
        solved.len(),
        solved.len() - bad,
        bad
    ));
    out
}

fn accuracy(args: AccuracyArgs) -> Result<Outcome> {
    use crate::accuracy::{Spread, families, report};
    let fams = families(args.seed, args.cases as usize);
    let rows = report(&fams, &args.methods, args.budget_ms);
    let stdout = match args.format {
        Format::Json => json::render(&serde_json::json!({
            "seed": args.seed,
            "families": fams.iter().map(|f| serde_json::json!({
                "name": f.name, "about": f.about, "cases": f.cases.len()})).collect::<Vec<_>>(),
            "rows": rows,
        })),
        Format::Text => {
            let mut out = format!(
                "Error against run time, seed {}: errors in ulps of each quantity's natural scale \
                 (FIN: max(|V1|, |V2|, |FIN1|, |FIN2|); crunch and lost: themselves), median / worst; \
                 time per solve, median (fastest-slowest pass).\n\
                 inf: no finite result (overflow), or a non-zero result where the exact value is 0.\n",
                args.seed
            );
            let u = |s: &Spread| format!("{} / {}", ulp_text(s.median), ulp_text(s.worst));
            let mut table = vec![[
                "family".to_string(),
                "method".into(),
                "cases".into(),
                "FIN ulps".into(),
                "crunch ulps".into(),
                "lost ulps".into(),
                "ns/solve".into(),
            ]];
            for r in &rows {
                table.push([
                    r.family.to_string(),
                    r.method.name().to_string(),
                    r.cases.to_string(),
                    u(&r.fin_ulps),
                    u(&r.crunch_ulps),
                    u(&r.lost_ulps),
                    format!("{:.1} ({:.1}-{:.1})", r.ns_median, r.ns_min, r.ns_max),
                ]);
            }
            let widths: Vec<usize> = (0..7)
                .map(|i| {
                    table
                        .iter()
                        .map(|r| r[i].chars().count())
                        .max()
                        .unwrap_or(0)
                })
                .collect();
            for (i, r) in table.iter().enumerate() {
                if i > 0 && table[i - 1][0] != r[0] {
                    out.push('\n');
                }
                let cells: Vec<String> = r
                    .iter()
                    .zip(&widths)
                    .enumerate()
                    .map(|(j, (c, w))| {
                        if (2..6).contains(&j) {
                            format!("{c:>w$}")
                        } else {
                            format!("{c:<w$}")
                        }
                    })
                    .collect();
                out.push_str(cells.join("  ").trim_end());
                out.push('\n');
            }
            out.push_str("\nFamilies:\n");
            for f in &fams {
                out.push_str(&format!("  {:<15} {}\n", f.name, f.about));
            }
            out
        }
    };
    Ok(Outcome { stdout, status: 0 })
}

/// An error in ulps for the table: `0`, `0.5`, `3`, `2.1e12`, or `inf`.
fn ulp_text(x: f64) -> String {
    if !x.is_finite() {
        "inf".into()
    } else if x == 0.0 {
        "0".into()
    } else if x < 100.0 {
        format!("{x:.2}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{x:.1e}")
    }
}

fn frames(args: FramesArgs) -> Result<Outcome> {
    let case = args.case.into_case()?;
    let stuck = case.restitution().is_totally_inelastic();
    let mut list: Vec<Frame> = Frame::standard()
        .into_iter()
        // e = 0: FIN = COM, so "finally at rest" is the COM frame again.
        .filter(|f| !(stuck && matches!(f, Frame::RestFin(_))))
        .collect();
    list.extend(args.frame);
    if args.reverse && stuck {
        return Err(crate::report::Irreversible.into());
    }
    let stdout = if args.exact {
        let lab = ExactCollision::from_case(&case);
        let rows = list
            .into_iter()
            .map(|f| {
                let w = f.w_exact(&lab);
                let reverse = args.reverse.then(|| reverse_equals_original(&lab, &w));
                (f, Exact::Rational(w.clone()), lab.observed(&w), reverse)
            })
            .collect();
        render_frames(&case, &table(rows, restitution_exact)?, args.format)
    } else {
        let lab = &case.collision;
        let exact_lab = args.reverse.then(|| ExactCollision::from_binary64(lab));
        let rows = list
            .into_iter()
            .map(|f| {
                let seen = Observed::new(lab, &f);
                let reverse = exact_lab
                    .as_ref()
                    .map(|x| reverse_equals_original(x, &f.w_exact(x)));
                (f, seen.w.value(), seen, reverse)
            })
            .collect();
        render_frames(&case, &table(rows, restitution_observed)?, args.format)
    };
    Ok(Outcome { stdout, status: 0 })
}

fn render_frames<N: crate::quantity::Scalar>(
    case: &Case,
    t: &FramesTable<N>,
    format: Format,
) -> String {
    match format {
        Format::Json => json::render(t),
        Format::Text => text::frames(case, t),
    }
}
