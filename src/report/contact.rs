//! `collide contact`'s results: a run (bodies, contacts, energy, work, the impulse model beside
//! it) and the work-precision table.

use std::fmt::Write;

use super::text::{Block, duration, paragraph, wrap};
use super::track::Unrepresentable;
use crate::contact::work::{Row, Work};
use crate::contact::{ContactRun, Damping, LawKind, Setup, Spec};
use crate::values::number::num;

/// A run as JSON, refusing by name a quantity that is not a real result.
pub fn json(run: &ContactRun) -> Result<serde_json::Value, Unrepresentable> {
    checked(serde_json::to_value(run).expect("contact runs serialize"))
}

/// The work-precision data as JSON.
pub fn work_json(work: &Work) -> Result<serde_json::Value, Unrepresentable> {
    checked(serde_json::to_value(work).expect("work-precision rows serialize"))
}

fn checked(v: serde_json::Value) -> Result<serde_json::Value, Unrepresentable> {
    match super::first_unrepresentable(&v) {
        Some(quantity) => Err(Unrepresentable(quantity)),
        None => Ok(v),
    }
}

/// `linear, k = 1, zeta = 0.2`.
pub fn law(spec: &Spec) -> String {
    let damping = match (spec.kind, spec.damping) {
        (_, Damping::None) => String::new(),
        (LawKind::HuntCrossley, Damping::Absolute(c)) => format!(", chi = {}", num(c)),
        (_, Damping::Absolute(c)) => format!(", c = {}", num(c)),
        (_, Damping::Zeta(z)) => format!(", zeta = {}", num(z)),
        (_, Damping::Restitution(e)) => format!(", e = {}", num(e)),
    };
    format!("{}, k = {}{damping}", spec.kind.name(), num(spec.k))
}

fn layout(setup: &Setup) -> String {
    let n = setup.bodies.len();
    let walls = match (setup.left_wall, setup.right_wall) {
        (Some(l), Some(r)) => format!(", walls at {} and {}", num(l), num(r)),
        (Some(l), None) => format!(", a left wall at {}", num(l)),
        (None, Some(r)) => format!(", a right wall at {}", num(r)),
        (None, None) => String::new(),
    };
    let wall_law = if walls.is_empty() {
        String::new()
    } else {
        format!("; walls: {}", law(&setup.wall))
    };
    if n == 1 {
        return format!("1 body{walls}{wall_law}");
    }
    format!("{n} bodies{walls}; contacts: {}{wall_law}", law(&setup.law))
}

/// A run for people.
pub fn text(setup: &Setup, run: &ContactRun) -> String {
    let mut out = String::new();
    out.push_str(&paragraph(&layout(setup)));
    let step = match (run.dt, run.tol) {
        (Some(dt), _) => format!("dt = {}", num(dt)),
        (_, Some(tol)) => format!("tol = {}", num(tol)),
        _ => String::new(),
    };
    let why = if run.stop == "done" {
        "no contact is active and none can begin"
    } else {
        "reached --until"
    };
    out.push_str(&paragraph(&format!(
        "method {} ({step}); at t = {}, {why}",
        run.method,
        num(run.time)
    )));
    let mut bodies = Block::new("Bodies at the end");
    let impulse = run.impulse_model.as_ref();
    let mut head = vec!["body".to_string(), "x".into(), "v".into()];
    if impulse.is_some() {
        head.push("v, impulse model".into());
    }
    bodies.cell_vec(head);
    for i in 0..run.x.len() {
        let mut row = vec![(i + 1).to_string(), num(run.x[i]), num(run.v[i])];
        if let Some(m) = impulse {
            row.push(num(m.v[i]));
        }
        bodies.cell_vec(row);
    }
    bodies.render(&mut out);
    if let Some(m) = impulse {
        let n = setup.bodies.len();
        let pairs = (n > 1).then(|| format!("e = {} between bodies", num(m.e)));
        let walls = (setup.left_wall.is_some() || setup.right_wall.is_some())
            .then(|| format!("e = {} at walls", num(m.e_wall)));
        let es: Vec<String> = pairs.into_iter().chain(walls).collect();
        out.push_str(&wrap(
            &format!(
                "  impulse model: collide track with {} ({} {})",
                es.join(", "),
                m.collisions,
                if m.collisions == 1 {
                    "collision"
                } else {
                    "collisions"
                }
            ),
            crate::values::terminal::width(),
            "    ",
        ));
    }
    let mut contacts = Block::new(format!("Contacts ({})", run.contacts.len()));
    contacts.cells([
        "pair".to_string(),
        "start".into(),
        "duration".into(),
        "max overlap".into(),
        "speed in".into(),
        "e".into(),
    ]);
    let name = |v: &serde_json::Value| match v {
        serde_json::Value::String(s) => format!("{s} wall"),
        other => other.to_string(),
    };
    for c in &run.contacts {
        contacts.cells([
            format!("{} & {}", name(&c.between[0]), name(&c.between[1])),
            num(c.start),
            c.duration.map_or("(active)".into(), num),
            num(c.max_overlap),
            num(c.speed),
            c.restitution.map_or("-".into(), num),
        ]);
    }
    contacts.render(&mut out);
    let mut energy = Block::new("Energy");
    energy.row("start", num(run.energy.start), "");
    energy.row("end", num(run.energy.end), "");
    if run.energy.dissipated > 0.0 {
        energy.row("dissipated", num(run.energy.dissipated), "");
    }
    energy.render(&mut out);
    let s = run.stats;
    let work = format!(
        "Work: {} steps ({} rejected), {} right-hand sides, {} Jacobians",
        s.steps, s.rejected, s.rhs_evals, s.jacobians
    );
    out.push('\n');
    out.push_str(&wrap(&work, crate::values::terminal::width(), "  "));
    out
}

fn sci(x: f64) -> String {
    format!("{x:.2e}")
}

/// The work-precision table for people.
pub fn work_text(setup: &Setup, work: &Work) -> String {
    let mut out = String::new();
    out.push_str(&paragraph(&layout(setup)));
    let r = &work.reference;
    let reference = match r.kind {
        "exact" => {
            "the exact final velocities (impulse form with the closed-form restitution)".to_string()
        }
        _ => format!(
            "runs of {} and {} at tol {} (they differ by {})",
            r.methods.map_or("?", |m| m[0]),
            r.methods.map_or("?", |m| m[1]),
            r.tol.map_or("?".into(), num),
            r.uncertainty.map_or("?".into(), sci)
        ),
    };
    out.push_str(&paragraph(&format!(
        "error = largest final-velocity difference / largest initial relative speed, against \
         {reference}; stiffness ratio {}",
        sci(work.stiffness_ratio)
    )));
    let _ = writeln!(out);
    let mut table = Block::table(&[2, 3, 4, 5, 6]);
    table.cells([
        "method".to_string(),
        "kind".into(),
        "tol / dt".into(),
        "error".into(),
        "time".into(),
        "steps".into(),
        "rhs evals".into(),
    ]);
    let step = |row: &Row| match (row.tol, row.dt) {
        (Some(t), _) => format!("tol {}", sci(t)),
        (_, Some(h)) => format!("dt {}", sci(h)),
        _ => String::new(),
    };
    let mut rows = work.rows.iter().peekable();
    let mut last = "";
    while let Some(row) = rows.next() {
        if !last.is_empty() && last != row.method {
            table.gap();
        }
        last = row.method;
        if row.unstable {
            // The run of unstable rungs, one line: how many, from which step to which, and why
            // the last (the nearest to stable) failed.
            let mut end = row;
            let mut count = 1;
            while let Some(next) = rows.next_if(|r| r.unstable && r.method == row.method) {
                end = next;
                count += 1;
            }
            let range = match (count, end.tol, end.dt) {
                (1, _, _) => format!("at {}", step(row)),
                (_, Some(t), _) => format!("at {count} tolerances, {} to {}", step(row), sci(t)),
                (_, _, Some(h)) => format!("at {count} steps, {} to {}", step(row), sci(h)),
                _ => format!("at {count} rungs"),
            };
            let why = end.why.as_deref().unwrap_or("no reason given");
            table.line(format!(
                "{} ({}): unstable {range}: {why}",
                row.method, row.kind
            ));
            continue;
        }
        table.cells([
            row.method.to_string(),
            row.kind.to_string(),
            step(row),
            row.error.map_or("-".into(), sci),
            row.ns.map_or("-".into(), |ns| duration(ns * 1e-9)),
            row.steps.to_string(),
            row.rhs_evals.to_string(),
        ]);
    }
    table.render(&mut out);
    out
}
