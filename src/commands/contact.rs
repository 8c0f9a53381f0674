//! `collide contact`: contact forces integrated through each impact; `--work-precision` for the
//! error of each method against its run time.

use anyhow::Result;
use collide::contact::{self, Damping, Laws, Method, Settings, Setup};
use collide::output::write_file;
use collide::report::{contact as report, json};
use collide::table::runs::contact::ContactSweep;

use super::Outcome;
use crate::cli::{ContactArgs, Format, RunFormat};

pub fn run(args: ContactArgs) -> Result<Outcome> {
    if !args.table.vary.is_empty() {
        return sweep(args);
    }
    let format = RunFormat::report(args.format)?;
    let bodies = args.layout.bodies()?;
    let laws = Laws {
        kind: args.law,
        k: args.stiffness,
        damping: Damping::given(args.damping, args.zeta, args.restitution),
        wall_k: args.wall_stiffness,
        wall_damping: Damping::given(args.wall_damping, args.wall_zeta, args.wall_restitution),
    };
    let walls = (
        args.layout.left_wall.map(|x| x.value()),
        args.layout.right_wall.map(|x| x.value()),
    );
    let setup = Setup::new(bodies, walls, laws);
    let until = args.until.map(|t| t.value());
    if let Some(t) = until {
        collide::track::Limits {
            until: Some(t),
            max_collisions: 0,
        }
        .check()?;
    }
    if args.work_precision {
        let methods: Vec<Method> = match &args.methods {
            Some(list) => list.iter().filter_map(|m| m.method()).collect(),
            None => Method::ALL.to_vec(),
        };
        if methods.is_empty() {
            anyhow::bail!("--methods lists no method to compare ('auto' is not one)");
        }
        let work = contact::work::work_precision(&setup, &methods, until)?;
        let stdout = match format {
            Format::Json => json::render(&report::work_json(&work)?),
            Format::Text => report::work_text(&setup, &work),
        };
        if let Some(path) = &args.plot {
            write_file(path, collide::plot::work::svg(&work).as_bytes())?;
        }
        return Ok(Outcome::print(stdout));
    }
    let settings = Settings {
        method: args.method.method(),
        dt: args.dt,
        tol: args.tol,
        until,
        max_steps: args.max_steps,
        trace: args.plot.is_some(),
    };
    let run = contact::simulate(&setup, &settings)?;
    let stdout = match format {
        Format::Json => json::render(&report::json(&run)?),
        Format::Text => report::text(&setup, &run),
    };
    if let Some(path) = &args.plot {
        write_file(path, collide::plot::work::history(&setup, &run).as_bytes())?;
    }
    Ok(Outcome::print(stdout))
}

/// `--vary`: a table of runs, one row each (`collide::table::runs::contact`).
fn sweep(args: ContactArgs) -> Result<Outcome> {
    let damping = |c, z, e| Damping::given(c, z, e);
    let base = ContactSweep {
        bodies: args.layout.bodies()?,
        walls: (
            args.layout.left_wall.map(|x| x.value()),
            args.layout.right_wall.map(|x| x.value()),
        ),
        laws: Laws {
            kind: args.law,
            k: args.stiffness,
            damping: damping(args.damping, args.zeta, args.restitution),
            wall_k: args.wall_stiffness,
            wall_damping: damping(args.wall_damping, args.wall_zeta, args.wall_restitution),
        },
        settings: Settings {
            method: args.method.method(),
            dt: args.dt,
            tol: args.tol,
            until: args.until.map(|t| t.value()),
            max_steps: args.max_steps,
            trace: false,
        },
    };
    super::table::run_table(&base, &args.table, args.format)
}
