//! The commands: each turns validated arguments into the text to print and an exit status. Output
//! is built whole before anything is written, so an error never leaves half a report on stdout.

use anyhow::{Context, Result};
use serde::Serialize;

use crate::batch;
use crate::batch::InputFormat;
use crate::case::Case;
use crate::cli::{
    AccuracyArgs, BatchArgs, CaseArgs, Command, Format, FramesArgs, PlotArgs, SceneArgs, SolveArgs,
    SweepArgs, TableArgs, TrackArgs,
};
use crate::exact::ExactCollision;
use crate::expect::Check;
use crate::frame::{
    Frame, FrameInfo, FramesTable, Observed, restitution_exact, restitution_observed,
    reverse_equals_original, table,
};
use crate::inertia::InertiaTensor;
use crate::number::Number;
use crate::plot;
use crate::problem::Problem;
use crate::quantity::Exact;
use crate::report::{Report, Section, Sections, json, text};
use crate::rows::{
    CHUNK_ROWS, Column, Output, Progress, RowCase, RowWriter, RowsError, Summary, chunk,
    write_chunks,
};
use crate::scene::{AnyScene, Scene, SceneError, TrackScene};
use crate::sweep::{Grid, Param, Shard};
use crate::track::{Body, Event, Limits, Run, Track, TrackReport};
use crate::units::Pair;
use num_traits::Zero;
use std::io::Write;

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
        Command::Sweep(args) => sweep(args),
        Command::Batch(args) => batch(args),
        Command::Track(args) => track(args),
        Command::Plot(args) => plot(args),
    }
}

impl CaseArgs {
    /// The typed problem (masses or tensor, velocities, restitution, units).
    fn problem(&self, fin: Option<&Pair>) -> Problem {
        Problem {
            masses: self.masses.clone(),
            velocities: self.velocities.clone(),
            fin: fin.cloned(),
            restitution: self.restitution.as_ref().map(|r| r.0.clone()),
            si: self.si,
        }
    }

    /// The case, with units resolved; `?` (an unknown) is for `collide solve`.
    pub fn into_case(self) -> Result<Case> {
        let problem = self.problem(None);
        if problem.has_unknowns() {
            anyhow::bail!(
                "'?' marks an unknown: `collide solve` solves for unknowns (with --fin for final velocities)"
            );
        }
        Ok(problem.solve(self.inertia)?.0)
    }
}

fn solve(args: SolveArgs) -> Result<Outcome> {
    let problem = args.case.problem(args.fin.as_ref());
    let (case, solved) = problem.solve(args.case.inertia.clone())?;
    let sections = Sections::new(args.show);
    let report = solve_case(&case, &args.frame, args.exact, &sections, args.reverse)?;
    let mut stdout = match args.format {
        Format::Text => {
            let mut text = String::new();
            if let Some(s) = &solved {
                text.push_str(&solved_text(s, args.exact));
            }
            text + &report.text(&case, &sections)
        }
        Format::Json => {
            let mut json = report.json();
            decorate(&mut json, &case, solved.as_ref(), args.exact);
            json::render(&json)
        }
    };
    if let Some(target) = &args.plot {
        stdout.push_str(&draw(
            &case,
            &args.frame,
            plot::Kind::Velocity,
            false,
            target,
        )?);
    }
    Ok(Outcome { stdout, status: 0 })
}

/// Draws to `target` (an SVG file, or `term`); returns what to print (the terminal picture, or
/// nothing).
fn draw(
    case: &Case,
    frame: &Frame,
    kind: plot::Kind,
    frames: bool,
    target: &std::path::Path,
) -> Result<String> {
    if target == std::path::Path::new("term") {
        if kind != plot::Kind::Velocity {
            anyhow::bail!(
                "the terminal plot draws the velocity diagram; use an SVG file for --kind {kind:?}"
            );
        }
        return Ok(format!(
            "\n{}",
            plot::term::render(&plot::Picture::new(case, frame, frames), terminal_width())
        ));
    }
    let svg = plot::svg(case, frame, kind, frames);
    write_atomically(target, svg.as_bytes())?;
    Ok(String::new())
}

/// A picture needs the vectors, energies and ellipse radii, and a data range binary64 can map:
/// refuse by name what it cannot hold.
fn check_drawable(case: &Case, frame: &Frame) -> Result<()> {
    let needed = Sections::new([
        Section::Vectors,
        Section::Momentum,
        Section::Energy,
        Section::Ellipses,
    ]);
    Report::build(&Observed::new(&case.collision, frame), &needed)?;
    let p = plot::Picture::new(case, frame, false);
    let fastest = [p.v_in.0, p.v_in.1, p.v_fin.0, p.v_fin.1]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    if !plot::velocity::Map::fit(&p, (0.0, 0.0), 1.0).is_finite() || fastest > f64::MAX / 8.0 {
        anyhow::bail!(
            "the picture's range is beyond binary64 (velocities and radii span more than 1e308): rescale the units"
        );
    }
    Ok(())
}

/// The terminal's width: `COLUMNS`, else 80.
fn terminal_width() -> usize {
    std::env::var("COLUMNS")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(80)
}

/// Writes a whole file through the same atomic output as tables.
fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    let mut out =
        Output::open(Some(path)).with_context(|| format!("cannot write {}", path.display()))?;
    out.write_all(bytes)
        .with_context(|| format!("cannot write {}", path.display()))?;
    out.commit()
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
}

fn plot(args: PlotArgs) -> Result<Outcome> {
    let case = args.case.into_case()?;
    check_drawable(&case, &args.frame)?;
    let stdout = match (&args.output, args.term) {
        (_, true) => draw(
            &case,
            &args.frame,
            args.kind,
            args.frames,
            std::path::Path::new("term"),
        )?,
        (Some(path), false) => draw(&case, &args.frame, args.kind, args.frames, path)?,
        (None, false) => plot::svg(&case, &args.frame, args.kind, args.frames),
    };
    Ok(Outcome { stdout, status: 0 })
}

pub fn solved_text(s: &crate::unknowns::Solved, exact: bool) -> String {
    let show = |q: &num_rational::BigRational| {
        use crate::quantity::Scalar;
        if exact {
            crate::quantity::Exact::Rational(q.clone()).show()
        } else {
            crate::report::text::num(crate::quantity::to_f64(q).unwrap_or(f64::NAN))
        }
    };
    let mut out = String::new();
    if !s.unknowns.is_empty() {
        let parts: Vec<String> = s
            .unknowns
            .iter()
            .map(|v| format!("{v} = {}", show(s.get(*v))))
            .collect();
        out.push_str(&format!("Solved: {}\n", parts.join(", ")));
    }
    for (law, residual) in &s.checks {
        if residual.is_zero() {
            out.push_str(&format!("Check: {law} holds exactly\n"));
        } else {
            out.push_str(&format!(
                "Check: {law} does NOT hold: it misses by {}\n",
                show(residual)
            ));
        }
    }
    out.push('\n');
    out
}

/// Adds `units` (when given), `solved` and `check` (when unknowns were solved) to a report.
fn decorate(
    json: &mut serde_json::Value,
    case: &Case,
    solved: Option<&crate::unknowns::Solved>,
    exact: bool,
) {
    let Some(o) = json.as_object_mut() else {
        return;
    };
    if case.units != crate::units::Units::default() {
        let u = &case.units;
        // Only the units given ("as given" values have none).
        let mut units = serde_json::Map::new();
        if let Some(m) = u.mass {
            units.insert("mass".into(), m.into());
        }
        if let Some(v) = u.velocity {
            units.insert("velocity".into(), v.into());
        }
        units.insert("energy".into(), u.energy().into());
        o.insert("units".into(), serde_json::Value::Object(units));
    }
    if let Some(s) = solved {
        for (k, v) in solved_json(s, exact) {
            o.insert(k, v);
        }
    }
}

pub fn solved_json(s: &crate::unknowns::Solved, exact: bool) -> Vec<(String, serde_json::Value)> {
    let value = |q: &num_rational::BigRational| {
        if exact {
            serde_json::Value::String(crate::quantity::fraction(q))
        } else {
            serde_json::json!(crate::quantity::to_f64(q))
        }
    };
    let solved: serde_json::Map<String, serde_json::Value> = s
        .unknowns
        .iter()
        .map(|v| (v.name().to_string(), value(s.get(*v))))
        .collect();
    let checks: serde_json::Map<String, serde_json::Value> = s
        .checks
        .iter()
        .map(|(law, r)| (law.to_string(), value(r)))
        .collect();
    let mut out = vec![("solved".to_string(), serde_json::Value::Object(solved))];
    if !checks.is_empty() {
        out.push(("check".to_string(), serde_json::Value::Object(checks)));
    }
    out
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
    path: std::path::PathBuf,
    title: Option<String>,
    source: Option<String>,
    /// The report for people (what a single scene prints).
    text: String,
    json: serde_json::Value,
    checks: Vec<Check>,
}

impl Solved {
    fn failures(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| !c.passed)
    }

    /// Checks `expect` against `json`; a key that names nothing is an error with its line.
    fn check(
        path: &std::path::Path,
        (title, source): (Option<String>, Option<String>),
        text: String,
        json: serde_json::Value,
        expect: &[crate::expect::Expectation],
    ) -> Result<Solved> {
        let checks = expect
            .iter()
            .map(|e| {
                e.check(&json).map_err(|message| SceneError {
                    path: path.to_path_buf(),
                    at: Some((e.line, 1)),
                    message: format!("[expect] {message}"),
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Solved {
            path: path.to_path_buf(),
            title,
            source,
            text,
            json,
            checks,
        })
    }
}

fn solve_scene(scene: Scene) -> Result<Solved> {
    let sections = scene.sections_needed();
    let report = solve_case(&scene.case, &scene.frame, scene.exact, &sections, false)
        .with_context(|| format!("{}", scene.path.display()))?;
    let mut text = report.text(&scene.case, &scene.show);
    if let Some(s) = &scene.solved {
        text = solved_text(s, scene.exact) + &text;
    }
    if let Some(p) = &scene.plot {
        draw(&scene.case, &scene.frame, p.kind, p.frames, &p.output)?;
        text.push_str(&format!("\nPlot: wrote {}\n", p.output.display()));
    }
    let mut json = report.json();
    decorate(&mut json, &scene.case, scene.solved.as_ref(), scene.exact);
    Solved::check(
        &scene.path,
        (scene.title, scene.source),
        text,
        json,
        &scene.expect,
    )
}

fn solve_track_scene(scene: TrackScene) -> Result<Solved> {
    let report = TrackReport::new(&scene.track, scene.track.run(scene.limits, None));
    let json = serde_json::to_value(&report)?;
    if let Some(quantity) = crate::report::first_unrepresentable(&json) {
        anyhow::bail!(
            "{}: {}",
            scene.path.display(),
            track_unrepresentable(&quantity)
        );
    }
    let text = text::track(&scene.track, &report, scene.limits);
    Solved::check(
        &scene.path,
        (scene.title, scene.source),
        text,
        json,
        &scene.expect,
    )
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
    // A [sweep] scene writes a table, and comes alone.
    if let [path] = args.files.as_slice()
        && let AnyScene::Case(
            scene @ Scene {
                sweep: Some(sw), ..
            },
        ) = &Scene::load_any(path)?
    {
        let table = TableArgs {
            columns: sw.columns.clone(),
            format: sw.format,
            output: None,
            skip_bad: sw.skip_bad,
        };
        return run_sweep(&scene.case, &sw.grid, Shard::WHOLE, &table);
    }
    // Load and solve every scene first: a bad file is an error before anything is printed.
    let mut tables = Vec::new();
    let mut solved = Vec::new();
    for p in &args.files {
        match Scene::load_any(p)? {
            // Among several files a [sweep] scene is listed, not written.
            AnyScene::Case(Scene {
                sweep: Some(sw),
                path,
                title,
                ..
            }) => tables.push((path, sw.grid.total, title)),
            AnyScene::Case(scene) => solved.push(solve_scene(scene)?),
            AnyScene::Track(scene) => solved.push(solve_track_scene(scene)?),
        }
    }
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
        Format::Text => scene_summary(&solved, &tables),
    };
    Ok(Outcome {
        stdout,
        status: if failed { 1 } else { 0 },
    })
}

fn scene_json(s: &Solved) -> SceneJson<'_> {
    SceneJson {
        scene: s.path.display().to_string(),
        title: s.title.as_deref(),
        source: s.source.as_deref(),
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
            s.path.display(),
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
    if let Some(t) = &s.title {
        out.push_str(t);
        if let Some(src) = &s.source {
            out.push_str(&format!(" ({src})"));
        }
        out.push('\n');
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

fn scene_summary(
    solved: &[Solved],
    tables: &[(std::path::PathBuf, u64, Option<String>)],
) -> String {
    let mut out = String::new();
    let width = solved
        .iter()
        .map(|s| s.path.display().to_string().len())
        .chain(tables.iter().map(|t| t.0.display().to_string().len()))
        .max()
        .unwrap_or(0);
    for s in solved {
        let failed = s.failures().count();
        let verdict = if failed > 0 { "FAIL" } else { "ok  " };
        out.push_str(&format!(
            "{verdict}  {:<width$}  {:>3}/{:<3} checks  {}\n",
            s.path.display(),
            s.checks.len() - failed,
            s.checks.len(),
            s.title.as_deref().unwrap_or("")
        ));
        failure_lines(s, &mut out);
    }
    let bad = solved
        .iter()
        .filter(|s| s.failures().next().is_some())
        .count();
    for (path, rows, title) in tables {
        let rows = format!("{rows} rows");
        out.push_str(&format!(
            "table {:<width$}  {rows:>13}  {} (a [sweep] scene: run it alone to write it)\n",
            path.display(),
            title.as_deref().unwrap_or("")
        ));
    }
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
    if let Some(path) = &args.plot {
        write_atomically(path, plot::accuracy::svg(&rows, args.seed).as_bytes())?;
    }
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

fn sweep(args: SweepArgs) -> Result<Outcome> {
    let case = args.case.into_case()?;
    let grid = Grid::new(args.vary, args.max_rows).map_err(anyhow::Error::msg)?;
    run_sweep(&case, &grid, args.shard, &args.table)
}

/// Writes the table of a sweep of `case` over `grid` (the rows of `shard`).
pub fn run_sweep(case: &Case, grid: &Grid, shard: Shard, table: &TableArgs) -> Result<Outcome> {
    let general = !case.inertia().is_diagonal();
    if general && (grid.varies(Param::M1) || grid.varies(Param::M2)) {
        anyhow::bail!("--vary m1 or m2 needs --masses; with --inertia, vary v1, v2 or e");
    }
    let writer = RowWriter::new(columns(&table.columns, general), table.format);
    let mut out = Output::open(table.output.as_deref()).map_err(|e| output_error(table, e))?;
    let mut progress = Progress::new(Some(
        shard.rows(grid.total).end - shard.rows(grid.total).start,
    ));
    let result = write_sweep(
        case,
        grid,
        shard,
        &writer,
        table.skip_bad,
        &mut out,
        &mut progress,
    );
    finish_table(result, out, &progress, table)
}

/// Solves the rows of `shard` of a sweep and writes them (with the header when `shard` is the
/// first) to `out`: the engine of `collide sweep`, callable with any writer.
pub fn write_sweep(
    case: &Case,
    grid: &Grid,
    shard: Shard,
    writer: &RowWriter,
    skip_bad: bool,
    out: &mut dyn Write,
    progress: &mut Progress,
) -> Result<Summary, RowsError> {
    let m = case.inertia().matrix();
    // A tensor every row shares, when no mass varies (made from binary64 values: cloning it
    // allocates nothing).
    let shared = (!grid.varies(Param::M1) && !grid.varies(Param::M2)).then(|| {
        let n = |x: f64| Number::from_f64(x).expect("a validated tensor is finite");
        InertiaTensor::general([[n(m[(0, 0)]), n(m[(0, 1)])], [n(m[(1, 0)]), n(m[(1, 1)])]])
            .expect("the case's tensor is valid")
    });
    let c = &case.collision;
    let base = RowCase {
        m11: m[(0, 0)],
        m12: m[(0, 1)],
        m22: m[(1, 1)],
        v: [c.v_in.x, c.v_in.y],
        e: c.restitution.value(),
    };
    let rows = shard.rows(grid.total);
    if shard.k == 1 {
        let mut header = Vec::new();
        writer.header(&mut header);
        out.write_all(&header)?;
    }
    let chunk_ranges = (rows.start..rows.end)
        .step_by(CHUNK_ROWS)
        .map(move |s| s..(s + CHUNK_ROWS as u64).min(rows.end));
    let solve = |range: std::ops::Range<u64>| {
        let mut varied = [(Param::E, 0.0); 5];
        let varied = &mut varied[..grid.vary.len()];
        let items = range.map(|r| {
            grid.row(r, varied);
            let mut row = base;
            for &(p, x) in varied.iter() {
                match p {
                    Param::M1 => row.m11 = x,
                    Param::M2 => row.m22 = x,
                    Param::V1 => row.v[0] = x,
                    Param::V2 => row.v[1] = x,
                    Param::E => row.e = x,
                }
            }
            Ok((r + 1, row))
        });
        chunk(
            items,
            &|r| format!("row {r}"),
            shared.as_ref(),
            writer,
            skip_bad,
        )
    };
    write_chunks(batched(chunk_ranges), solve, out, progress)
}

fn batch(args: BatchArgs) -> Result<Outcome> {
    let input = batch::open(
        args.input.as_deref(),
        args.input_format,
        args.restitution.value(),
    )
    .map_err(anyhow::Error::msg)?;
    let writer = RowWriter::new(
        columns(&args.table.columns, input.general),
        args.table.format,
    );
    let mut out =
        Output::open(args.table.output.as_deref()).map_err(|e| output_error(&args.table, e))?;
    let mut header = Vec::new();
    writer.header(&mut header);
    out.write_all(&header)?;
    // Read a batch of chunks at a time: memory stays bounded whatever the input's size.
    let mut input = input.peekable();
    let chunks = std::iter::from_fn(move || {
        input.peek()?;
        Some(input.by_ref().take(CHUNK_ROWS).collect::<Vec<_>>())
    });
    let mut progress = Progress::new(None);
    let solve = |items: Vec<Result<(u64, RowCase), crate::rows::RowError>>| {
        chunk(
            items.into_iter(),
            &|l| format!("line {l}"),
            None,
            &writer,
            args.table.skip_bad,
        )
    };
    finish_table(
        write_chunks(batched(chunks), solve, &mut out, &mut progress),
        out,
        &progress,
        &args.table,
    )
}

/// Groups chunks into batches of a few per thread.
fn batched<C>(chunks: impl Iterator<Item = C>) -> impl Iterator<Item = Vec<C>> {
    let per_batch = 4 * rayon::current_num_threads().max(1);
    let mut chunks = chunks.peekable();
    std::iter::from_fn(move || {
        chunks.peek()?;
        Some(chunks.by_ref().take(per_batch).collect())
    })
}

fn columns(chosen: &[Column], general: bool) -> Vec<Column> {
    if chosen.is_empty() {
        Column::defaults(general)
    } else {
        chosen.to_vec()
    }
}

fn output_error(table: &TableArgs, e: std::io::Error) -> anyhow::Error {
    let path = table
        .output
        .as_ref()
        .map_or("stdout".into(), |p| p.display().to_string());
    anyhow::anyhow!("cannot write {path}: {e}")
}

/// Ends a table run: commits the output when complete (a bad row leaves no file behind), and
/// reports skipped rows.
fn finish_table(
    result: Result<Summary, RowsError>,
    out: Output,
    progress: &Progress,
    table: &TableArgs,
) -> Result<Outcome> {
    progress.finish();
    let summary = match result {
        Ok(s) => s,
        // `out` is dropped unfinished: a temporary file is removed, stdout keeps whole rows.
        Err(RowsError::Row(e)) => {
            let hint = if table.skip_bad {
                ""
            } else {
                " (--skip-bad reports bad rows and goes on)"
            };
            return Err(anyhow::anyhow!("{e}{hint}"));
        }
        Err(RowsError::Io(e)) => return Err(e.into()),
    };
    out.commit().map_err(|e| output_error(table, e))?;
    if summary.skipped > 0 {
        eprintln!(
            "{} rows written, {} bad rows skipped",
            summary.rows, summary.skipped
        );
    }
    Ok(Outcome {
        stdout: String::new(),
        status: 0,
    })
}

fn track(args: TrackArgs) -> Result<Outcome> {
    let n = args.masses.0.len();
    for (what, list) in [
        ("--positions", &args.positions),
        ("--velocities", &args.velocities),
    ] {
        if list.0.len() != n {
            anyhow::bail!(
                "{what} has {} values for {n} masses: give one per body",
                list.0.len()
            );
        }
    }
    let sizes = match &args.sizes {
        Some(s) if s.0.len() != n => {
            anyhow::bail!("--sizes has {} values for {n} masses", s.0.len())
        }
        Some(s) => s.0.clone(),
        None => vec![0.0; n],
    };
    let e = args.restitution.value();
    let track = Track {
        bodies: (0..n)
            .map(|i| Body {
                m: args.masses.0[i],
                x: args.positions.0[i],
                v: args.velocities.0[i],
                size: sizes[i],
            })
            .collect(),
        left_wall: args.left_wall.map(|x| x.value()),
        right_wall: args.right_wall.map(|x| x.value()),
        e,
        e_wall: args.wall_restitution.map_or(e, |r| r.value()),
        gravity: args.gravity.value(),
    };
    track.check()?;
    let limits = Limits {
        until: args.until.map(|t| t.value()),
        max_collisions: args.max_collisions,
    };
    let run = match &args.log {
        None => track.run(limits, None),
        Some(path) => run_logged(&track, limits, path, args.log_format)?,
    };
    let report = TrackReport::new(&track, run);
    if let Some(quantity) = crate::report::first_unrepresentable(&serde_json::to_value(&report)?) {
        anyhow::bail!("{}", track_unrepresentable(&quantity));
    }
    let stdout = match args.format {
        Format::Json => json::render(&report),
        Format::Text => text::track(&track, &report, limits),
    };
    Ok(Outcome { stdout, status: 0 })
}

fn track_unrepresentable(quantity: &str) -> String {
    format!(
        "{quantity} is not representable in binary64 (its magnitude is outside 2.2e-308 to 1.8e308): \
         rescale the units (e.g. tons and km/s instead of kg and m/s)"
    )
}

/// Runs `track`, writing each collision to `path` ('-': stderr) as CSV or JSON Lines.
fn run_logged(
    track: &Track,
    limits: Limits,
    path: &std::path::Path,
    format: Option<InputFormat>,
) -> Result<Run> {
    let jsonl = match format {
        Some(f) => f == InputFormat::Jsonl,
        None => path.extension().is_some_and(|e| e == "jsonl"),
    };
    let sink: Box<dyn Write> = if path == std::path::Path::new("-") {
        Box::new(std::io::stderr())
    } else {
        Box::new(
            std::fs::File::create(path)
                .with_context(|| format!("cannot write {}", path.display()))?,
        )
    };
    let out = std::io::BufWriter::new(sink);
    enum Log {
        Csv(Box<csv::Writer<std::io::BufWriter<Box<dyn Write>>>>),
        Jsonl(std::io::BufWriter<Box<dyn Write>>),
    }
    let mut log = if jsonl {
        Log::Jsonl(out)
    } else {
        Log::Csv(Box::new(csv::Writer::from_writer(out)))
    };
    let mut failed: Option<String> = None;
    if let Log::Csv(w) = &mut log {
        w.write_record(["n", "t", "who", "v_before", "v_after"])?;
    }
    let mut record = |ev: &Event| {
        if failed.is_some() {
            return;
        }
        let join = |v: &[f64]| {
            v.iter()
                .map(|x| ryu::Buffer::new().format(*x).to_string())
                .collect::<Vec<_>>()
                .join(" ")
        };
        let result = match &mut log {
            Log::Csv(w) => w
                .write_record([
                    ev.n.to_string(),
                    ryu::Buffer::new().format(ev.t).to_string(),
                    ev.who.clone(),
                    join(&ev.before),
                    join(&ev.after),
                ])
                .map_err(|e| e.to_string()),
            Log::Jsonl(w) => serde_json::to_writer(&mut *w, ev)
                .map_err(|e| e.to_string())
                .and_then(|()| w.write_all(b"\n").map_err(|e| e.to_string())),
        };
        failed = result.err();
    };
    let run = track.run(limits, Some(&mut record));
    if let Some(e) = failed {
        anyhow::bail!("cannot write the log {}: {e}", path.display());
    }
    match &mut log {
        Log::Csv(w) => w.flush()?,
        Log::Jsonl(w) => w.flush()?,
    }
    Ok(run)
}
