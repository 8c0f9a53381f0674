//! `collide view`: the lecture's simulators as one self-contained web page.

use anyhow::{Result, bail};
use collide::scene::{AnyScene, Scene};
use collide::values::output::write_file;
use collide::view::page::{self, Focus, Setup};
use collide::view::stack::TrackInput;

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
    let html = page::html(&setup).map_err(|e| anyhow::anyhow!("{}", e.error))?;
    match &args.output {
        Some(path) => {
            write_file(path, html.as_bytes())?;
            Ok(Outcome::print(String::new()))
        }
        None => Ok(Outcome::print(html)),
    }
}

/// `a,b` as two trimmed texts.
fn two(text: &str, flag: &str, what: &str) -> Result<[String; 2]> {
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    match fields[..] {
        [a, b] => Ok([a.to_string(), b.to_string()]),
        _ => bail!(
            "{flag} '{}': expected {what}, two comma-separated values",
            text.trim()
        ),
    }
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
        AnyScene::Rigid(_) => bail!(
            "{}: rigid bodies at impact: the page has no panel for them; run it with collide \
             scene",
            path.display()
        ),
        AnyScene::Space(_) => bail!(
            "{}: a collision in the plane or in space: the page's panel for it is to come; run \
             it with collide scene",
            path.display()
        ),
        AnyScene::Special(_) | AnyScene::Contact(_) | AnyScene::Stages(_) => bail!(
            "{}: the page draws a collision of two movable bodies or a [track]; this scene is \
             another kind (a wall, a separation, contact forces or stages): run it with collide \
             scene",
            path.display()
        ),
    }
    Ok(())
}
