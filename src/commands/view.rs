//! `collide view`: the lecture's simulators as one self-contained web page.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use collide::scene::{AnyScene, Scene};
use collide::values::output::{diagnostic, write_file};
use collide::view::input::TrackInput;
use collide::view::page::{self, Focus, Setup};

use super::Outcome;
use crate::cli::{ViewArgs, ViewTrack, ViewTrackArgs};

pub fn run(args: ViewArgs) -> Result<Outcome> {
    let mut setup = Setup::lecture();
    match (&args.track, &args.scene) {
        (Some(ViewTrack::Track(t)), _) => {
            setup.track = track_input(t);
            setup.focus = Focus::Stack;
        }
        (None, Some(path)) => from_scene(&mut setup, path)?,
        (None, None) if planar(&args) => {
            from_flags_in_the_plane(&mut setup, &args)?;
            return write(&setup, &args);
        }
        (None, None) => {
            if let Some(v) = &args.velocities {
                let [v1, v2] = two(v, "--velocities", "V1,V2")?;
                setup.case.v1 = v1;
                setup.case.v2 = v2;
            }
            match (&args.masses, &args.inertia) {
                (Some(m), _) => {
                    let [m1, m2] = two(m, "--masses", "M1,M2")?;
                    (setup.case.m1, setup.case.m2) = (m1, m2);
                }
                (None, Some(t)) => setup.case.inertia = Some(t.trim().to_string()),
                (None, None) if args.velocities.is_some() => {
                    bail!("--velocities needs --masses M1,M2 or --inertia 'M11,M12;M21,M22'")
                }
                (None, None) => {}
            }
        }
    }
    if let Some(e) = &args.restitution {
        setup.case.e = e.trim().to_string();
    }
    if args.scene.is_none() || args.frame != collide::line::frame::Frame::Lab {
        setup.case.frame = args.frame.to_string();
    }
    setup.case.reverse |= args.reverse;
    write(&setup, &args)
}

/// Whether the flags give a case in the plane: a line of impact, or velocities as vectors.
fn planar(args: &ViewArgs) -> bool {
    args.normal.is_some()
        || args.radii.is_some()
        || args
            .velocities
            .as_deref()
            .is_some_and(collide::space::typed::is_spatial)
}

/// Two pucks in the plane from the flags: the page opens on the plane panel.
fn from_flags_in_the_plane(setup: &mut Setup, args: &ViewArgs) -> Result<()> {
    if args.inertia.is_some() {
        bail!("--inertia is a two-body tensor on a line: give --masses M1,M2 for the plane");
    }
    let (Some(m), Some(v)) = (&args.masses, &args.velocities) else {
        bail!(
            "the plane needs --masses M1,M2 and --velocities V1,V2, e.g. -m 1,1 -v '(1,0),(0,0)'"
        );
    };
    let [m1, m2] = two(m, "--masses", "M1,M2")?;
    let [v1, v2] = bodies(v)?;
    let p = &mut setup.plane;
    (p.m1, p.m2, p.v1, p.v2) = (m1, m2, v1, v2);
    (p.normal, p.r1, p.r2, p.b) = Default::default();
    if let Some(n) = &args.normal {
        p.normal = n.trim().to_string();
    }
    if let Some(r) = &args.radii {
        [p.r1, p.r2] = two(r, "--radii", "R1,R2")?;
        p.b = args
            .impact_parameter
            .as_deref()
            .unwrap_or_default()
            .trim()
            .to_string();
    }
    p.e = args
        .restitution
        .as_deref()
        .map_or_else(|| "elastic".to_string(), |e| e.trim().to_string());
    p.frame = args.frame.to_string();
    p.reverse = args.reverse;
    setup.focus = Focus::Plane;
    Ok(())
}

/// Two bodies' velocities, split at the commas outside parentheses.
fn bodies(text: &str) -> Result<[String; 2]> {
    let list = collide::space::typed::split_bodies(text)?;
    match list[..] {
        [a, b] => Ok([a.to_string(), b.to_string()]),
        _ => bail!(
            "--velocities '{}': the page's plane draws two bodies, this gives {}: run more \
             bodies with collide solve",
            text.trim(),
            list.len()
        ),
    }
}

/// The page, written to `-o FILE`, to stdout (`-o -`, or a pipe), or, on a terminal or with
/// `--open`, to [`DEFAULT_FILE`] in the current folder (saying so on stderr); `--open` then opens
/// the file in the default browser.
fn write(setup: &Setup, args: &ViewArgs) -> Result<Outcome> {
    let html = page::html(setup).map_err(|e| anyhow::anyhow!("{}", e.error))?;
    let path = match args.output.as_deref() {
        Some(p) if p == Path::new("-") => {
            if args.open {
                bail!("--open opens a file: give -o FILE.html (or no -o), not -o -");
            }
            return Ok(Outcome::print(html));
        }
        Some(p) => p.to_path_buf(),
        None if args.open || std::io::stdout().is_terminal() => {
            let (path, note) = default_file()?;
            write_file(&path, html.as_bytes())?;
            diagnostic(format_args!(
                "collide view: wrote the page to {} ({} KB){note}{}\n",
                path.display(),
                html.len().div_ceil(1000),
                if args.open {
                    ""
                } else {
                    "; open it in a browser, or run collide view --open"
                }
            ));
            return finish(&path, args.open);
        }
        None => return Ok(Outcome::print(html)),
    };
    write_file(&path, html.as_bytes())?;
    finish(&path, args.open)
}

/// Where a page goes without `-o` on a terminal: this name in the current folder.
const DEFAULT_FILE: &str = "collide-view.html";

/// The file for a page without `-o`: [`DEFAULT_FILE`] when it is free or a page `collide view`
/// wrote (replaced, and said), else the first free or own `collide-view-N.html` (N from 2),
/// with a note on stderr that the file of that name was left alone: a file that is not ours is
/// never overwritten.
fn default_file() -> Result<(PathBuf, String)> {
    let ours = |p: &Path| -> Option<bool> {
        let mut head = [0u8; 2048];
        let n = std::io::Read::read(&mut std::fs::File::open(p).ok()?, &mut head).ok()?;
        Some(
            String::from_utf8_lossy(&head[..n])
                .contains("<meta name=\"generator\" content=\"collide view\">"),
        )
    };
    for n in 1..=99 {
        let path = PathBuf::from(if n == 1 {
            DEFAULT_FILE.to_string()
        } else {
            format!("collide-view-{n}.html")
        });
        let note = if n == 1 {
            String::new()
        } else {
            format!(" ({DEFAULT_FILE} is not a page of collide view's: left alone)")
        };
        match (path.symlink_metadata().is_ok(), ours(&path)) {
            (false, _) => return Ok((path, note)),
            (true, Some(true)) => return Ok((path, format!("{note}, replacing its last page"))),
            _ => {}
        }
    }
    bail!(
        "{DEFAULT_FILE} and collide-view-2.html to -99.html in this folder are not pages of \
         collide view's: give the file with -o FILE.html"
    )
}

/// After writing `path`: opened in the default browser with `--open`.
fn finish(path: &Path, open: bool) -> Result<Outcome> {
    if open {
        open_in_browser(path)?;
    }
    Ok(Outcome::print(String::new()))
}

/// Opens `path` with the program in `COLLIDE_OPENER`, else the system's own opener (xdg-open on
/// Linux and the BSDs, open on macOS, start on Windows); a failure names the program.
fn open_in_browser(path: &Path) -> Result<()> {
    let file = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    let (program, mut command) = match std::env::var_os("COLLIDE_OPENER") {
        Some(p) if !p.is_empty() => (
            p.to_string_lossy().into_owned(),
            std::process::Command::new(p),
        ),
        _ if cfg!(target_os = "macos") => ("open".into(), std::process::Command::new("open")),
        _ if cfg!(windows) => {
            let mut c = std::process::Command::new("cmd");
            c.args(["/C", "start", ""]);
            ("start".into(), c)
        }
        _ => ("xdg-open".into(), std::process::Command::new("xdg-open")),
    };
    let status = command
        .arg(&file)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .status();
    match status {
        Ok(s) if s.success() => Ok(()),
        Ok(s) => bail!(
            "wrote {}, but {program} could not open it ({s}): open it in a browser",
            path.display()
        ),
        Err(e) => bail!(
            "wrote {}, but cannot run {program} to open it ({e}): open it in a browser, or \
             name an opener in COLLIDE_OPENER",
            path.display()
        ),
    }
}

/// `a,b` as two trimmed texts.
fn two(text: &str, flag: &str, what: &str) -> Result<[String; 2]> {
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    match fields[..] {
        [a, b] => Ok([a.to_string(), b.to_string()]),
        _ => bail!(
            "{flag} '{}': expected {what}, two comma-separated values (collide view draws two \
             bodies; run more with collide solve or collide scene)",
            text.trim()
        ),
    }
}

/// A scene in the plane opens the plane panel with its two bodies; what the panel cannot show
/// (more bodies, space, final velocities or unknowns to solve for) is refused by name.
fn in_the_plane(
    setup: &mut Setup,
    path: &std::path::Path,
    scene: &collide::scene::SpaceScene,
) -> Result<()> {
    let texts = &scene.texts;
    let why = if texts.masses.len() != 2 {
        Some(format!("it has {} bodies", texts.masses.len()))
    } else if scene.input.fin.is_some() {
        Some("it gives final velocities (`fin`) to solve from".to_string())
    } else if texts
        .masses
        .iter()
        .chain(&texts.velocities)
        .chain(&texts.restitution)
        .any(|t| t.contains('?'))
    {
        Some("it has unknowns ('?') to solve for".to_string())
    } else if scene.input.si || scene.energy_unit.is_some() {
        Some("it converts units (`si`, `energy_unit`), which the page does not".to_string())
    } else {
        None
    };
    if let Some(why) = why {
        bail!(
            "{}: the page's plane draws two bodies whose masses, velocities and e are all \
             given, and {why}: run it with collide scene",
            path.display()
        );
    }
    let p = &mut setup.plane;
    p.m1 = texts.masses[0].clone();
    p.m2 = texts.masses[1].clone();
    [p.v1, p.v2] = match &texts.velocities[..] {
        [a, b] => [a.clone(), b.clone()],
        _ => bail!("{}: velocities: give one per body (2)", path.display()),
    };
    p.normal = texts.normal.clone().unwrap_or_default();
    (p.r1, p.r2, p.b) = match (&texts.radii, &texts.impact_parameter) {
        (Some(r), Some(b)) if r.len() == 2 => (r[0].clone(), r[1].clone(), b.clone()),
        _ => Default::default(),
    };
    p.e = texts
        .restitution
        .clone()
        .unwrap_or_else(|| "elastic".to_string());
    p.frame = scene.frame.to_string();
    p.reverse = scene.reverse;
    p.exact = scene.input.exact;
    setup.focus = Focus::Plane;
    Ok(())
}

/// The layout as the page's inputs hold it.
fn track_input(t: &ViewTrackArgs) -> TrackInput {
    let list = |l: &collide::values::number::NumberList| {
        l.0.iter()
            .map(|n| n.to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    let text = |n: &Option<collide::values::number::Number>| n.as_ref().map(|n| n.to_string());
    let layout = &t.layout;
    TrackInput {
        masses: list(&layout.masses),
        positions: list(&layout.positions),
        velocities: list(&layout.velocities),
        sizes: layout.sizes.as_ref().map(list).unwrap_or_default(),
        left_wall: text(&layout.left_wall).unwrap_or_default(),
        right_wall: text(&layout.right_wall).unwrap_or_default(),
        e: if t.rules.restitution.is_elastic() {
            "elastic".into()
        } else {
            t.rules.restitution.to_string()
        },
        e_wall: t
            .rules
            .wall_restitution
            .as_ref()
            .map(|r| r.to_string())
            .unwrap_or_default(),
        gravity: t.rules.gravity.to_string(),
        until: text(&t.until).unwrap_or_default(),
    }
}

/// A two-body scene opens the velocity plane with its case; a `[track]` scene, the stack.
fn from_scene(setup: &mut Setup, path: &std::path::Path) -> Result<()> {
    match Scene::load_any(path)? {
        AnyScene::Case(scene) => {
            let case = &scene.case;
            if case.units != Default::default() {
                bail!(
                    "{}: the page takes the case as plain numbers, and this scene gives units; \
                     give it with collide view -m ... -v ... (units are read there)",
                    path.display()
                );
            }
            let m = case.inertia().entries();
            if case.inertia().is_diagonal() {
                (setup.case.m1, setup.case.m2) = (m[0][0].to_string(), m[1][1].to_string());
            } else {
                setup.case.inertia =
                    Some(format!("{},{};{},{}", m[0][0], m[0][1], m[1][0], m[1][1]));
            }
            setup.case.v1 = case.velocities[0].to_string();
            setup.case.v2 = case.velocities[1].to_string();
            setup.case.e = case.restitution().to_string();
            setup.case.frame = scene.frame.to_string();
        }
        AnyScene::Track(scene) => {
            let t = &scene.track;
            let list = |v: Vec<String>| v.join(",");
            let f = |x: f64| format!("{x:?}");
            setup.track = TrackInput {
                masses: list(t.bodies.iter().map(|b| b.m.number().to_string()).collect()),
                positions: list(t.bodies.iter().map(|b| f(b.x)).collect()),
                velocities: list(t.bodies.iter().map(|b| f(b.v)).collect()),
                sizes: list(t.bodies.iter().map(|b| f(b.size)).collect()),
                left_wall: t.left_wall.map(f).unwrap_or_default(),
                right_wall: t.right_wall.map(f).unwrap_or_default(),
                e: if t.e == 1.0 { "elastic".into() } else { f(t.e) },
                e_wall: if t.e_wall == t.e {
                    String::new()
                } else {
                    f(t.e_wall)
                },
                gravity: f(t.gravity),
                until: scene.limits.until.map(f).unwrap_or_default(),
            };
            setup.focus = Focus::Stack;
        }
        AnyScene::Balls(_) => bail!(
            "{}: touching balls (several contacts at once): the page has no panel for them; run \
             it with collide scene",
            path.display()
        ),
        AnyScene::Rigid(_) => bail!(
            "{}: rigid bodies at impact: the page has no panel for them; run it with collide \
             scene",
            path.display()
        ),
        AnyScene::Space(scene) => in_the_plane(setup, path, &scene)?,
        AnyScene::Special(_) | AnyScene::Contact(_) | AnyScene::Stages(_) => bail!(
            "{}: the page draws a collision of two movable bodies or a [track]; this scene is \
             another kind (a wall, a separation, contact forces or stages): run it with collide \
             scene",
            path.display()
        ),
    }
    Ok(())
}
