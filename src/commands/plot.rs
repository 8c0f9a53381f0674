//! `collide plot`: the lecture's pictures, as SVG or in the terminal; also `solve --plot` and a
//! scene's `[plot]`.

use std::path::Path;

use anyhow::Result;
use collide::line::case::Case;
use collide::line::frame::Frame;
use collide::plot::{self, Kind, Picture};
use collide::report::{Report, Section, Sections};
use collide::solver::binary64::Binary64;
use collide::values::output::write_file;

use super::Outcome;
use crate::cli::PlotArgs;

pub fn run(args: PlotArgs) -> Result<Outcome> {
    if args.rigid.active() {
        return rigid(&args);
    }
    if args.case.spatial() {
        return plane(&args);
    }
    args.frame.on_line()?;
    let kind = args.kind.unwrap_or(Kind::Velocity);
    if args.frames && kind != Kind::Velocity {
        anyhow::bail!(
            "--frames overlays the standard frames on the velocity diagram; --kind {} draws \
             world lines in one frame (choose it with --frame)",
            format!("{kind:?}").to_lowercase()
        );
    }
    if let Some(unit) = args.case.energy_unit {
        anyhow::bail!(
            "--energy-unit {}: a picture labels its energy ellipses in the case's own units (mass \
             unit x velocity unit^2); give the energies in {0} with collide solve",
            unit.name
        );
    }
    let case = args.case.into_case(false)?;
    check_drawable(&case, &args.frame)?;
    let stdout = match (&args.output, args.term) {
        (_, true) => draw(&case, &args.frame, kind, args.frames, Path::new("term"))?,
        (Some(path), false) => draw(&case, &args.frame, kind, args.frames, path)?,
        (None, false) => plot::svg(&case, &args.frame, kind, args.frames),
    };
    Ok(Outcome::print(stdout))
}

/// The picture of a collision in the plane: the paths through the point of impact and the
/// momentum triangles (`plot::plane`).
fn plane(args: &PlotArgs) -> Result<Outcome> {
    if args.kind.is_some() || args.frames || args.term || args.frame != Frame::Lab {
        anyhow::bail!(
            "--kind, --frames, --frame and --term draw two bodies on a line; a case in the \
             plane is drawn as its paths and momentum triangles (collide plot ... -o FILE.svg)"
        );
    }
    let svg = super::space_solve::plane_svg(&args.case)?;
    match &args.output {
        Some(path) => {
            write_file(path, svg.as_bytes())?;
            Ok(Outcome::print(String::new()))
        }
        None => Ok(Outcome::print(svg)),
    }
}

/// The picture of a rigid impact: the bodies with the contact, velocities and spins, and the
/// impulse plane of Routh's method (`plot::rigid`).
fn rigid(args: &PlotArgs) -> Result<Outcome> {
    if args.kind.is_some() || args.frames || args.term || args.frame != Frame::Lab {
        anyhow::bail!(
            "--kind, --frames, --frame and --term draw two bodies on a line; a rigid impact is \
             drawn as its bodies and its impulse plane (collide plot ... -o FILE.svg)"
        );
    }
    let svg = super::rigid_solve::svg(&args.case, &args.rigid)?;
    match &args.output {
        Some(path) => {
            write_file(path, svg.as_bytes())?;
            Ok(Outcome::print(String::new()))
        }
        None => Ok(Outcome::print(svg)),
    }
}

/// Draws to `target` (an SVG file, or `term`); returns what to print (the terminal picture, or
/// nothing).
pub fn draw(case: &Case, frame: &Frame, kind: Kind, frames: bool, target: &Path) -> Result<String> {
    if target == Path::new("term") {
        if kind != Kind::Velocity {
            anyhow::bail!(
                "the terminal plot draws the velocity diagram; use an SVG file for --kind {kind:?}"
            );
        }
        return Ok(format!(
            "\n{}",
            plot::term::render(
                &Picture::new(case, frame, frames),
                collide::values::terminal::width()
            )
        ));
    }
    write_file(target, plot::svg(case, frame, kind, frames).as_bytes())?;
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
    Report::build(&Binary64::new(&case.collision, frame), &needed)
        .map_err(|u| u.with_way_out("rescale the units"))?;
    let p = Picture::new(case, frame, false);
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
