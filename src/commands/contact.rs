//! `collide contact`: contact forces integrated through each impact; `--work-precision` for the
//! error of each method against its run time.

use anyhow::Result;
use collide::contact::{self, Damping, Laws, Method, Settings, Setup};
use collide::report::{contact as report, json};
use collide::table::runs::contact::ContactSweep;
use collide::values::output::write_file;

use super::Outcome;
use crate::cli::{ContactArgs, Format, MethodArg, RunFormat};

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
        // The ladder runs each method at its own steps or tolerances, to its own step cap: a
        // method, step, tolerance or cap given for one run would be silently ignored.
        let one_run = [
            (args.method != MethodArg::Auto).then_some("--method"),
            args.dt.map(|_| "--dt"),
            args.tol.map(|_| "--tol"),
            (args.max_steps != contact::DEFAULT_MAX_STEPS).then_some("--max-steps"),
        ];
        if let Some(flag) = one_run.into_iter().flatten().next() {
            anyhow::bail!(
                "{flag} is for one run; --work-precision runs every method on its own ladder of \
                 steps and tolerances: choose the methods with --methods, or drop \
                 --work-precision"
            );
        }
        let methods: Vec<Method> = match &args.methods {
            Some(list) => list.iter().filter_map(|m| m.method()).collect(),
            None => Method::ALL.to_vec(),
        };
        if methods.is_empty() {
            anyhow::bail!("--methods lists no method to compare ('auto' is not one)");
        }
        let work = contact::work::work_precision(&setup, &methods, until)?;
        // Every number checked, whatever the format: none is NaN or infinite.
        let checked = report::work_json(&work)?;
        let stdout = match format {
            Format::Json => json::render(&checked),
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
    let checked = report::json(&run)?;
    let stdout = match format {
        Format::Json => json::render(&checked),
        Format::Text => report::text(&setup, &run),
    };
    if let Some(path) = &args.plot {
        write_file(path, collide::plot::work::history(&setup, &run).as_bytes())?;
    }
    Ok(Outcome::print(stdout))
}

/// `--vary`: a table of runs, one row each (`collide::table::runs::contact`).
fn sweep(args: ContactArgs) -> Result<Outcome> {
    super::table::run_table(&sweep_kind(&args)?, &args.table, args.format)
}

/// The base run that `--vary` changes (`collide::table::runs::contact`).
pub fn sweep_kind(args: &ContactArgs) -> Result<ContactSweep> {
    let damping = |c, z, e| Damping::given(c, z, e);
    let base = ContactSweep {
        bodies: args.layout.bodies()?,
        walls: (
            args.layout.left_wall.as_ref().map(|x| x.value()),
            args.layout.right_wall.as_ref().map(|x| x.value()),
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
            until: args.until.as_ref().map(|t| t.value()),
            max_steps: args.max_steps,
            trace: false,
        },
    };
    Ok(base)
}
