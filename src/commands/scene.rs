//! `collide scene`: TOML scenes solved and checked against their `[expect]` numbers (or, for a
//! `[sweep]` scene run alone, its table written).

use anyhow::{Context, Result};
use clap::ValueEnum;
use collide::line::case::Case;
use collide::line::frame::Frame;
use collide::line::problem::Posed;
use collide::line::unknowns::Solved;
use collide::report::scene::{self as report, Checked, Listed};
use collide::report::special::Special;
use collide::report::stages::{Chain, StagePart};
use collide::report::{AnyReport, contact as contact_report, json, solved, track as track_report};
use collide::report::{Section, Sections};
use collide::scene::{
    About, AnyScene, ContactScene, RigidScene, Scene, SceneError, SpecialScene, StagesScene,
    TrackScene,
};
use collide::table::sweep::Shard;
use collide::track::TrackReport;

use super::{Outcome, plot, table};
use crate::cli::{Format, SceneArgs, TableArgs};

pub fn run(args: SceneArgs) -> Result<Outcome> {
    let stdin = args.files.iter().filter(|p| p.as_os_str() == "-").count();
    if stdin > 1 {
        anyhow::bail!("standard input ('-') is read once: give '-' once among the scene files");
    }
    // Each file is read once: a FIFO or a pipe (`<(cat x.toml)`, `/dev/stdin`) cannot be read
    // twice.
    let loaded: Vec<Result<AnyScene>> =
        args.files.iter().map(|p| Ok(Scene::load_any(p)?)).collect();
    // A [sweep] scene writes a table, and comes alone.
    if let [
        Ok(AnyScene::Case(
            scene @ Scene {
                sweep: Some(sw), ..
            },
        )),
    ] = loaded.as_slice()
    {
        if let Some(format) = args.format {
            anyhow::bail!(
                "{}: a [sweep] scene writes its table in the format its [sweep] names ({}); \
                 --format {} is for reports: set format = \"jsonl\" in [sweep] for JSON Lines",
                scene.about.path.display(),
                sw.format.name(),
                name(format)
            );
        }
        let table = TableArgs {
            columns: sw.columns.iter().map(|c| c.name.to_string()).collect(),
            format: Some(sw.format),
            output: None,
            skip_bad: sw.skip_bad,
            header: None,
        };
        return table::run_sweep(&scene.case, &sw.grid, Shard::WHOLE, &table);
    }
    let format = args.format.unwrap_or(Format::Text);
    let several = args.files.len() > 1;
    // Solve every scene. With several files a bad one is reported on stderr by name and the
    // others still run; the exit status is the worst (2 for a bad file).
    let mut listed = Vec::new();
    let mut checked = Vec::new();
    let mut bad = 0usize;
    for scene in loaded {
        let one = || -> Result<Option<Checked>> {
            Ok(match scene? {
                // Among several files a [sweep] scene is listed, not written.
                AnyScene::Case(Scene {
                    sweep: Some(sw),
                    about,
                    ..
                }) => {
                    listed.push(Listed {
                        path: about.path,
                        rows: sw.grid.total,
                        title: about.title,
                    });
                    None
                }
                AnyScene::Case(scene) => Some(solve(scene)?),
                AnyScene::Special(scene) => Some(solve_special(scene)?),
                AnyScene::Track(scene) => Some(solve_track(scene)?),
                AnyScene::Contact(scene) => Some(solve_contact(scene)?),
                AnyScene::Space(scene) => Some(solve_space(scene)?),
                AnyScene::Balls(scene) => Some(solve_balls(scene)?),
                AnyScene::Rigid(scene) => Some(solve_rigid(scene)?),
                AnyScene::Stages(scene) => Some(solve_stages(scene)?),
            })
        };
        match one() {
            Ok(c) => checked.extend(c),
            Err(e) if !several => return Err(e),
            Err(e) => {
                bad += 1;
                collide::values::output::diagnostic(format_args!("error: {e:#}"));
            }
        }
    }
    if bad > 0 && checked.is_empty() && listed.is_empty() {
        anyhow::bail!(
            "none of the {} scene files could be solved",
            args.files.len()
        );
    }
    let failed = checked.iter().any(Checked::failed);
    let stdout = match format {
        Format::Json if several => json::render(&several_json(&checked, &listed)),
        Format::Json => json::render(&report::json(&checked)),
        Format::Text if several => report::summary(&checked, &listed),
        Format::Text => report::text(&checked[0]),
    };
    let stdout = if bad > 0 && format == Format::Text && several {
        let files = if bad == 1 { "file" } else { "files" };
        stdout + &format!("{bad} scene {files} could not be solved (see stderr)\n")
    } else {
        stdout
    };
    Ok(Outcome {
        stdout,
        status: if bad > 0 {
            2
        } else if failed {
            1
        } else {
            0
        },
    })
}

/// Several scenes as JSON: an array of the solved ones, then one object for each [sweep] scene
/// (listed with its rows, not written; a [sweep] scene writes its table only when run alone).
fn several_json(checked: &[Checked], listed: &[Listed]) -> serde_json::Value {
    let mut all = match report::json(checked) {
        serde_json::Value::Array(a) => a,
        one => vec![one],
    };
    for t in listed {
        all.push(serde_json::json!({
            "scene": t.path.display().to_string(),
            "title": t.title,
            "table": {
                "rows": t.rows,
                "written": false,
                "note": "a [sweep] scene writes its table when run alone",
            },
            "checks": 0,
            "failed": [],
        }));
    }
    serde_json::Value::Array(all)
}

fn solve(scene: Scene) -> Result<Checked> {
    let (text, json) = render_case(
        &scene.case,
        &scene.frame,
        scene.exact,
        (&scene.show, scene.sections_needed()),
        scene.solved.as_ref(),
    )
    .with_context(|| format!("{}", scene.about.path.display()))?;
    // The floor's mu from a slide in `fin`: its line first, JSON `solved.mu`, as collide solve.
    let (mut text, json) = match &scene.floor {
        Some(mu) => {
            let mut json = json;
            if let Some(map) = json.as_object_mut() {
                let solved = map.entry("solved").or_insert_with(|| serde_json::json!({}));
                solved["mu"] = mu.json.clone();
            }
            (mu.line.clone() + &text, json)
        }
        None => (text, json),
    };
    if let Some(p) = &scene.plot {
        plot::draw(&scene.case, &scene.frame, p.kind, p.frames, &p.output)?;
        text.push_str(&format!("\nPlot: wrote {}\n", p.output.display()));
    }
    let mut checked = check(scene.about, text, json)?;
    checked.inconsistent = scene.solved.as_ref().is_some_and(|s| s.inconsistent());
    Ok(checked)
}

/// A collision's text (the sections in `show`) and JSON (those `needed`), with what its
/// unknowns came out as.
fn render_case(
    case: &Case,
    frame: &Frame,
    exact: bool,
    (show, mut sections): (&Sections, Sections),
    solved: Option<&Solved>,
) -> Result<(String, serde_json::Value)> {
    // energy_unit = "kJ": every energy in kJ, as the header says.
    sections.energy_scale = case.units.energy_scale();
    sections.force_scale = case.units.force_scale();
    let result = AnyReport::of(case, frame, exact, &sections, false)?;
    let text = result.text(case, show, solved);
    let mut json = result.json();
    solved::annotate(&mut json, &case.units, solved, exact);
    Ok((text, json))
}

fn solve_special(scene: SpecialScene) -> Result<Checked> {
    let (text, json) = render_special(
        scene.event.special(),
        (&scene.show, scene.sections_needed()),
        scene.exact,
        scene.solved.as_ref(),
    )
    .with_context(|| format!("{}", scene.about.path.display()))?;
    let mut checked = check(scene.about, text, json)?;
    checked.inconsistent = scene.solved.as_ref().is_some_and(|s| s.inconsistent());
    Ok(checked)
}

/// A separation's or wall's text (the sections in `show`) and JSON (those and the ones its
/// expectations read, `needed`: what `collide solve --show` with the same sections prints, one
/// answer on both paths), under what its unknowns came out as.
fn render_special(
    event: Special,
    (show, needed): (&Sections, Sections),
    exact: bool,
    solved: Option<&Solved>,
) -> Result<(String, serde_json::Value)> {
    let mut compute = needed;
    compute.energy_scale = event.units().energy_scale();
    let result = event.render(&compute, show, exact)?;
    let head = solved
        .map(|s| solved::text(s, exact, &event.units()))
        .unwrap_or_default();
    let mut json = result.json;
    solved::annotate(&mut json, &event.units(), solved, exact);
    Ok((head + &result.text, json))
}

/// A chain of stages: each stage's report in turn, each checked against its own
/// `[stage.expect]`, then what comes next, checked against the top-level `[expect]`.
fn solve_stages(scene: StagesScene) -> Result<Checked> {
    if scene.range.is_some() {
        return solve_range(scene);
    }
    let solved = scene.solve()?;
    let (parts, stage_checks, inconsistent) = stage_parts(&scene, &solved.runs)?;
    let chain = Chain {
        stages: parts,
        bodies: &scene.bodies,
        after: solved
            .after
            .iter()
            .map(|(v, i)| (v.clone(), scene.stages[*i].name.clone()))
            .collect(),
        meetings: &solved.meetings,
        velocity_unit: solved.velocity_unit,
        exact: scene.exact,
        fixed: &solved.fixed,
        range: None,
    };
    let mut checked = check(scene.about, chain.text(), chain.json())?;
    checked.checks.extend(stage_checks);
    checked.inconsistent = inconsistent;
    Ok(checked)
}

/// A chain asked for the range of one stage's `e'` (a `condition`): the stages before it in
/// full, the rest affine in `e'`, then the range, checked against the top-level `[expect]`.
fn solve_range(scene: StagesScene) -> Result<Checked> {
    use collide::report::range::Values;
    let solved = scene.solve_range()?;
    let (mut parts, stage_checks, inconsistent) = stage_parts(&scene, &solved.runs)?;
    let values = Values { exact: scene.exact };
    for (j, a) in solved.affine.iter().enumerate() {
        let i = solved.runs.len() + j;
        let stage = &scene.stages[i];
        parts.push(StagePart {
            name: stage.name.clone(),
            numbered: stage.name == format!("stage{}", i + 1),
            event: a.event,
            objects: stage.objects,
            takes: takes(stage),
            text: a.text(values),
            json: serde_json::Value::Null,
            affine: Some(a.json(values)),
        });
    }
    let chain = Chain {
        stages: parts,
        bodies: &scene.bodies,
        after: Vec::new(),
        meetings: &[],
        velocity_unit: solved.range.velocity_unit,
        exact: scene.exact,
        fixed: &[],
        range: Some(&solved.range),
    };
    let mut checked = check(scene.about, chain.text(), chain.json())?;
    checked.checks.extend(stage_checks);
    checked.inconsistent = inconsistent;
    Ok(checked)
}

/// The solved stages of a chain rendered, each `[stage.expect]` checked; and whether any
/// stage's solved values were inconsistent.
fn stage_parts(
    scene: &StagesScene,
    runs: &[collide::scene::StageRun],
) -> Result<(Vec<StagePart>, Vec<collide::expect::Check>, bool)> {
    let mut parts = Vec::new();
    let mut checks = Vec::new();
    let mut inconsistent = false;
    for (i, run) in runs.iter().enumerate() {
        let (part, stage_checks, odd) = stage_part(scene, i, run)?;
        parts.push(part);
        checks.extend(stage_checks);
        inconsistent |= odd;
    }
    Ok((parts, checks, inconsistent))
}

/// The velocities stage takes from earlier ones: `(body, "stage1.fin2")`.
fn takes(stage: &collide::scene::Stage) -> Vec<(usize, String)> {
    stage
        .takes
        .iter()
        .enumerate()
        .filter_map(|(b, t)| t.as_ref().map(|t| (b, t.text.clone())))
        .collect()
}

/// Stage `i` of a chain rendered from its run, its `[stage.expect]` checked; and whether its
/// solved values were inconsistent.
fn stage_part(
    scene: &StagesScene,
    i: usize,
    run: &collide::scene::StageRun,
) -> Result<(StagePart, Vec<collide::expect::Check>, bool)> {
    let at = || format!("{}", scene.about.path.display());
    let stage = &scene.stages[i];
    let mut inconsistent = false;
    let (event, (text, json)) = match &run.posed {
        Posed::Collision(case, solved) => {
            inconsistent |= solved.as_ref().is_some_and(Solved::inconsistent);
            let needed = stage.sections_needed(&run.show);
            let rendered = render_case(
                case,
                &Frame::Lab,
                scene.exact,
                (&run.show, needed),
                solved.as_ref(),
            );
            ("collision", rendered.with_context(at)?)
        }
        Posed::Wall(wall, solved) => {
            inconsistent |= solved.as_ref().is_some_and(Solved::inconsistent);
            let needed = stage.sections_needed(&run.show);
            let rendered = render_special(
                Special::Wall(wall),
                (&run.show, needed),
                scene.exact,
                solved.as_ref(),
            );
            ("wall", rendered.with_context(at)?)
        }
        Posed::Separation(s, solved) => {
            inconsistent |= solved.inconsistent();
            let needed = stage.sections_needed(&run.show);
            let rendered = render_special(
                Special::Separation(s),
                (&run.show, needed),
                scene.exact,
                Some(solved),
            );
            ("pass-through", rendered.with_context(at)?)
        }
        Posed::Separations(..) => {
            unreachable!("a separation is refused when solved")
        }
    };
    let mut checks = Vec::new();
    for e in &stage.expect {
        let mut c = e.check(&json).map_err(|message| SceneError {
            path: scene.about.path.clone(),
            at: Some((e.line, 1)),
            message: format!("[stage.expect] of {}: {message}", stage.name),
        })?;
        c.key = format!("{}.{}", stage.name, c.key);
        checks.push(c);
    }
    let part = StagePart {
        name: stage.name.clone(),
        numbered: stage.name == format!("stage{}", i + 1),
        event,
        objects: stage.objects,
        takes: takes(stage),
        text,
        json,
        affine: None,
    };
    Ok((part, checks, inconsistent))
}

fn solve_track(scene: TrackScene) -> Result<Checked> {
    let run = scene
        .track
        .run(scene.limits, None)
        .with_context(|| format!("{}", scene.about.path.display()))?;
    let result = TrackReport::new(&scene.track, run);
    let json =
        track_report::json(&result).with_context(|| format!("{}", scene.about.path.display()))?;
    let text = track_report::text(&scene.track, &result, scene.limits);
    check(scene.about, text, json)
}

fn solve_contact(scene: ContactScene) -> Result<Checked> {
    let at = || format!("{}", scene.about.path.display());
    let run = collide::contact::simulate(&scene.setup, &scene.settings).with_context(at)?;
    let json = contact_report::json(&run).with_context(at)?;
    let text = contact_report::text(&scene.setup, &run);
    check(scene.about, text, json)
}

fn solve_space(scene: collide::scene::SpaceScene) -> Result<Checked> {
    use collide::report::space::solved::{Options, render};
    let at = || format!("{}", scene.about.path.display());
    let posed = scene.input.pose().with_context(at)?;
    let solved = collide::space::solve::solve(&posed.statement).with_context(at)?;
    let rendered = render(
        &posed,
        &solved,
        &Options {
            frame: &scene.frame,
            show: scene.show,
            exact: scene.input.exact,
            reverse: scene.reverse,
            fin_given: scene.input.fin.is_some(),
            energy_unit: scene.energy_unit,
        },
    )
    .with_context(at)?;
    let mut checked = check(scene.about, rendered.text, rendered.json)?;
    checked.inconsistent = rendered.inconsistent;
    Ok(checked)
}

fn solve_balls(scene: collide::scene::BallsScene) -> Result<Checked> {
    let at = || format!("{}", scene.about.path.display());
    let r = collide::report::simultaneous::run(&scene.input, scene.sequential, None)
        .with_context(at)?;
    check(scene.about, r.text, r.json)
}

fn solve_rigid(scene: RigidScene) -> Result<Checked> {
    let at = || format!("{}", scene.about.path.display());
    let show = super::rigid_solve::show(&scene.show).with_context(at)?;
    let report = |show: &Sections, format| {
        super::rigid_solve::report_of(
            scene.problem.clone(),
            show,
            scene.exact,
            scene.energy_unit,
            format,
        )
        .with_context(at)
    };
    let (text, status) = report(&show, Format::Text)?;
    let (json, _) = report(&Sections::new([Section::All]), Format::Json)?;
    let json: serde_json::Value = serde_json::from_str(&json)?;
    let mut checked = check(scene.about, text, json)?;
    // Energy created (Kane's paradox) fails like a contradicted law: exit 1.
    checked.inconsistent = status != 0;
    Ok(checked)
}

/// Checks a scene's expectations against its report; a key that names nothing in the report is
/// an error with its line.
fn check(about: About, text: String, json: serde_json::Value) -> Result<Checked> {
    let checks = about
        .expect
        .iter()
        .map(|e| {
            e.check(&json).map_err(|message| SceneError {
                path: about.path.clone(),
                at: Some((e.line, 1)),
                message: format!("[expect] {message}"),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Checked {
        path: about.path,
        title: about.title,
        source: about.source,
        text,
        json,
        checks,
        inconsistent: false,
    })
}

/// A flag value's name as typed (`jsonl`, `json`).
fn name(value: impl ValueEnum) -> String {
    value
        .to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_string())
}
