//! Every JSON output of collide against the invariant checker of `invariants`: solve reports,
//! frames tables, scenes, table rows, track runs with their logged events, contact runs, and
//! generated layouts (proptest).

use crate::common;
use crate::invariants::*;

use collide::contact::{self, Damping, LawKind, Laws, Settings, Setup};
use collide::line::inertia::Mass;
use collide::track::Body;
use common::{collide, proptest_config};
use proptest::prelude::*;
use serde_json::Value;

/// Runs `collide args`: a refusal (exit 2, nothing on stdout) is a fine answer to a hostile
/// input; a success must be JSON; anything else fails.
fn json_or_refused(args: &[&str]) -> Option<Value> {
    let out = collide().args(args).output().unwrap();
    match out.status.code() {
        Some(0) => {
            Some(serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{args:?}: {e}")))
        }
        Some(2) => {
            assert!(out.stdout.is_empty(), "{args:?} refused but printed");
            None
        }
        code => panic!(
            "{args:?}: exit {code:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
    }
}

#[track_caller]
fn holds(r: Result<(), String>, what: &dyn std::fmt::Debug) {
    if let Err(m) = r {
        panic!("{what:?}: {m}");
    }
}

/// Two-body cases: the lecture's (Figs. 1.3, 2.3), a general tensor, units, extreme masses,
/// tiny and superelastic e, and a receding pair.
const CASES: &[&[&str]] = &[
    &["-m", "4,1", "-v", "60,10"],
    &["-m", "6,1", "-v", "3,-4", "-e", "2/3"],
    &["-m", "6,1", "-v", "3,-4", "-e", "0"],
    &["-m", "6,1", "-v", "3,-4", "-e", "3/2"],
    &["--inertia", "4,0.5;0.5,1", "-v", "3,-1", "-e", "0.3"],
    &["-m", "1500 kg,1 t", "-v", "72 km/h,0", "-e", "0.2"],
    &["-m", "1e27,1", "-v", "1e-3,-7", "-e", "0.9"],
    &["-m", "1,2", "-v", "1,0", "-e", "1e-150"],
    &["-m", "1,3", "-v", "0,2", "-e", "1/2"],
    &["-m", "1e-300,1e-300", "-v", "1e150,-1e150", "-e", "1/7"],
];

#[test]
fn every_solve_report_satisfies_the_invariants() {
    for case in CASES {
        for extra in [
            &["--show", "all"][..],
            &["--show", "all", "--exact"],
            &["--show", "all", "--frame", "com", "--reverse"],
            &[
                "--show",
                "vectors,energy",
                "--frame",
                "rest-fin:2",
                "--exact",
            ],
        ] {
            let args = [&["solve"], *case, extra, &["--format", "json"]].concat();
            let Some(r) = json_or_refused(&args) else {
                continue;
            };
            holds(all_real(&r), &args);
            holds(two_body(&TwoBody::of_report(&r)), &args);
            if let Some(rev) = r.get("reverse") {
                let mut back = TwoBody::of_report(&r);
                back.v_in = nums(&rev["in"]).try_into().unwrap();
                back.fin = nums(&rev["fin"]).try_into().unwrap();
                back.e = num(&rev["restitution"]);
                back.v_com = None;
                back.energy = None;
                holds(two_body(&back), &("reverse", &args));
                let en = &rev["energy"];
                let gain = en.get("gained").or(en.get("lost")).map(num).unwrap();
                assert!(gain >= 0.0, "{args:?}: {en}");
            }
        }
    }
}

#[test]
fn walls_and_separations_create_no_energy_and_print_only_numbers() {
    for args in [
        "solve -m wall,0.5 -v 0,-3 -e 0.6 --show all",
        "solve -m 2,wall -v 5,1 -e 1 --show all --exact",
        "solve -m wall,1 -v 0,? --fin 0,2 -e 1/2 --show all",
        "solve -m 1,5 -v 0,0 --fin -5,1 --show all",
        "solve -m 1,5 -v 2,2 --fin ?,2.5 --show all --exact",
    ] {
        let args: Vec<&str> = args.split(' ').chain(["--format", "json"]).collect();
        let r = json(&args);
        holds(all_real(&r), &args);
        let en = &r["energy"];
        for k in ["lost", "released"] {
            if let Some(x) = en.get(k) {
                assert!(num(x) >= 0.0, "{args:?}: energy.{k} = {x}");
            }
        }
        if r["event"] == "separation" {
            // A separation: momentum kept, released = KE_FIN - KE_IN >= 0.
            let (m, v, f) = (nums(&r["masses"]), nums(&r["in"]), nums(&r["fin"]));
            let p = |u: &[f64]| m[0] * u[0] + m[1] * u[1];
            assert!(
                (p(&f) - p(&v)).abs() <= 16.0 * EPS * (m[0] * f[0].abs() + m[1] * f[1].abs()),
                "{args:?}"
            );
        }
    }
}

#[test]
fn every_frames_table_satisfies_the_invariants() {
    for case in CASES {
        for extra in [&[][..], &["--exact"], &["--reverse", "--frame", "2.5"]] {
            let args = [&["frames"], *case, extra, &["--format", "json"]].concat();
            let Some(t) = json_or_refused(&args) else {
                continue;
            };
            holds(all_real(&t), &args);
            // The tensor of the case, from solve (frames does not print it).
            let solve = [&["solve"], *case, &["--format", "json"]].concat();
            let inertia = TwoBody::of_report(&json(&solve)).inertia;
            holds(frames(inertia, &t), &args);
        }
    }
}

#[test]
fn every_scene_report_satisfies_the_invariants() {
    let mut paths: Vec<String> = std::fs::read_dir("scenarios")
        .unwrap()
        .map(|e| e.unwrap().path().display().to_string())
        .filter(|p| p.ends_with(".toml") && !p.contains("sweep") && !p.contains("pi-billiards-8"))
        .collect();
    paths.sort();
    let args: Vec<&str> = ["scene"]
        .into_iter()
        .chain(paths.iter().map(String::as_str))
        .chain(["--format", "json"])
        .collect();
    let out = collide().args(&args).output().unwrap();
    assert!(
        out.status.code().is_some_and(|c| c <= 1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let all: Value = serde_json::from_slice(&out.stdout).unwrap();
    for s in all.as_array().unwrap() {
        let r = &s["report"];
        holds(all_real(r), &s["scene"]);
        if r.get("inertia").is_some() {
            holds(two_body(&TwoBody::of_report(r)), &s["scene"]);
        } else if r["law"] == "newton-simultaneous" {
            // Several contacts at once: energy never created, no pair approaching after
            // (exact scenes print fractions, `≈` digits where irrational).
            let q = |v: &Value| -> f64 {
                v.as_f64().unwrap_or_else(|| {
                    let t = v.as_str().unwrap_or_default().trim_start_matches('≈');
                    let x: collide::values::rational::Q = t.parse().unwrap();
                    collide::values::rational::to_f64(&x).unwrap()
                })
            };
            let (a, b) = (q(&r["energy"]["in"]), q(&r["energy"]["fin"]));
            assert!(b <= a, "{}: energy {a} -> {b}", s["scene"]);
            for c in r["contacts"].as_array().unwrap() {
                assert!(
                    q(&c["normal_velocity"]["fin"]) >= 0.0,
                    "{}: {c}",
                    s["scene"]
                );
            }
        } else if r.get("contacts").is_some() || r.get("collisions").is_some() {
            // Track and contact: the centres in order, energy never created (every scene's
            // law and restitution dissipates or keeps it).
            let x = nums(&r["x"]);
            assert!(x.windows(2).all(|w| w[0] <= w[1]), "{}: {x:?}", s["scene"]);
            let (a, b) = (num(&r["energy"]["start"]), num(&r["energy"]["end"]));
            assert!(b <= a * (1.0 + 1e-8), "{}: energy {a} -> {b}", s["scene"]);
        }
    }
}

#[test]
fn every_table_row_satisfies_the_invariants() {
    let sweep = [
        "sweep -m 4,1 -v 60,10 --vary e=0:1:5 --vary m2=0.001:1000:7:log",
        "sweep --inertia 4,0.5;0.5,1 -v 3,-1 --vary e=0,1/3,1 --vary v2=-5:5:4",
        "sweep -m 1e-200,1e200 -v 1e100,-1e100 --vary e=0.5,1",
        "sweep -m 1e-100,1e100 -v 1e50,-1e50 --vary e=0.5,1",
    ];
    for line in sweep {
        let args: Vec<&str> = line.split(' ').chain(["--format", "jsonl"]).collect();
        let out = collide().args(&args).output().unwrap();
        // Refused (a row beyond binary64, named) or written: never a false row.
        if out.status.code() == Some(2) {
            assert!(out.stdout.is_empty(), "{args:?}");
            continue;
        }
        let text = String::from_utf8(out.stdout).unwrap();
        for row in text.lines() {
            let row: Value = serde_json::from_str(row).unwrap();
            holds(all_real(&row), &row);
            holds(table_row(&row), &(&args, &row));
        }
    }
    let rows = std::fs::read_to_string("scenarios/cases.csv").unwrap();
    let out = collide()
        .args([
            "batch",
            "--skip-bad",
            "--format",
            "jsonl",
            "--input-format",
            "csv",
        ])
        .write_stdin(rows)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.lines().count() >= 3, "{text}");
    for row in text.lines() {
        let row: Value = serde_json::from_str(row).unwrap();
        holds(all_real(&row), &row);
        holds(table_row(&row), &row);
    }
}

/// A scratch file name, unique to this process.
fn scratch(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("collide-invariants-{}-{name}", std::process::id()))
}

/// `collide track` on a layout with its `--log` as JSON Lines: the output and the events.
fn track_run(l: &Layout, extra: &[&str]) -> (Value, Vec<Value>) {
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let log = scratch(&format!("track-{n}.jsonl"));
    let log_text = log.display().to_string();
    let out = layout_json("track", l, &[extra, &["--log", &log_text]].concat());
    let events = std::fs::read_to_string(&log)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    std::fs::remove_file(&log).ok();
    (out, events)
}

#[test]
fn every_track_run_and_logged_event_satisfies_the_invariants() {
    let cradle = Layout::new(
        &[1.0, 1.0, 1.0, 1.0],
        &[0.0, 2.0, 3.0, 4.0],
        &[1.0, 0.0, 0.0, 0.0],
        &[1.0; 4],
    );
    let boxed = Layout::new(
        &[1.0, 2.0, 1.0],
        &[0.0, 2.0, 4.0],
        &[1.0, 0.0, -1.0],
        &[0.5; 3],
    )
    .walls(Some(-2.0), Some(6.0));
    let mixed = Layout::new(
        &[1e-3, 5.0, 0.2],
        &[-1.0, 0.5, 3.0],
        &[3.0, -0.5, -2.0],
        &[0.1, 1.0, 0.3],
    )
    .walls(Some(-3.0), None);
    let light =
        Layout::new(&[1.0, 100.0], &[1.0, 3.0], &[0.0, -1.0], &[0.0, 0.0]).walls(Some(0.0), None);
    for (l, e, extra) in [
        (&cradle, 1.0, &["-e", "1"][..]),
        (&cradle, 0.5, &["-e", "0.5"]),
        (&boxed, 1.0, &["--until", "30"]),
        (&boxed, 0.8, &["-e", "0.8", "--until", "30"]),
        (&mixed, 0.9, &["-e", "0.9", "--until", "20"]),
        (&light, 1.0, &[]),
    ] {
        let (out, log) = track_run(l, extra);
        assert_eq!(
            log.len() as u64,
            out["collisions"].as_u64().unwrap(),
            "{l:?}"
        );
        holds(track(l, (e, e), &out, &log), &(l, extra));
    }
    // Under gravity (the floor is the left wall; events replayed along parabolas).
    let mut stack =
        Layout::new(&[1.0, 0.1], &[0.5, 1.5], &[-1.0, -1.0], &[1.0, 1.0]).walls(Some(0.0), None);
    stack.gravity = 9.8;
    let (out, log) = track_run(&stack, &["--gravity", "9.8", "-e", "0.7", "--until", "2"]);
    holds(track(&stack, (0.7, 0.7), &out, &log), &stack);
}

/// Contact layouts run by the binary: both laws, damping, walls, stiff and soft.
#[test]
fn every_contact_run_satisfies_the_invariants() {
    let pair = Layout::new(&[1.0, 2.0], &[0.0, 1.0], &[1.0, -0.5], &[1.0, 1.0]);
    let fast = Layout::new(&[1.0, 1.0], &[0.0, 1.0], &[100000001.0, 1e8], &[1.0, 1.0]);
    let walls =
        Layout::new(&[1.0, 1.0], &[0.0, 1.0], &[1.0, 0.0], &[1.0, 1.0]).walls(None, Some(1.5));
    let cradle = Layout::new(
        &[1.0, 1.0, 1.0],
        &[0.0, 1.0, 2.0],
        &[1.0, 0.0, 0.0],
        &[1.0; 3],
    );
    let boxed = Layout::new(
        &[1.0, 2.0, 1.0],
        &[0.0, 1.5, 3.0],
        &[1.0, 0.0, -1.0],
        &[1.0; 3],
    )
    .walls(Some(-2.0), Some(5.0));
    for (l, extra) in [
        (&pair, "--zeta 0.2"),
        (&pair, "--law hertz --stiffness 100"),
        (&pair, "--law hunt-crossley --stiffness 100 --damping 0.3"),
        (&pair, "--zeta 1e6"),
        (&fast, "--zeta 0.2"),
        (
            &walls,
            "--stiffness 1 --damping 0.4 --wall-stiffness 1e6 --wall-zeta 1",
        ),
        (&cradle, "--law hertz --stiffness 100"),
        (&cradle, "--stiffness 100 --method verlet"),
        (&boxed, "--stiffness 100 --zeta 0.1 --until 20"),
        (
            &boxed,
            "--law hertz --stiffness 100 --until 20 --method sdirk",
        ),
    ] {
        let extra: Vec<&str> = extra.split(' ').collect();
        let out = layout_json("contact", l, &extra);
        holds(contact(l, &out, 1e-8), &extra);
    }
    // The work-precision data: numbers only.
    let w = json(&[
        "contact",
        "-m",
        "1,1",
        "-x",
        "0,1",
        "--sizes",
        "1,1",
        "-v",
        "1,0",
        "--zeta",
        "0.2",
        "--work-precision",
        "--methods",
        "rk4,bdf",
        "--format",
        "json",
    ]);
    holds(all_real(&w), &"work-precision");
}

#[test]
fn pi_and_accuracy_print_only_numbers() {
    for args in [
        &["pi", "3", "--format", "json"][..],
        &["pi", "40", "--format", "json"],
        &["accuracy", "--cases", "20", "--format", "json"],
    ] {
        let v = json(args);
        holds(all_real(&v), &args);
    }
}

/// A generated contact layout: 1 to 4 bodies with gaps, masses 0.1..10, speeds -2..2, a law,
/// stiffness 10..1e4, damping, walls; a horizon whenever both walls are there.
fn layouts() -> impl Strategy<Value = (Layout, Laws, Option<f64>)> {
    let bodies =
        proptest::collection::vec((0.1f64..10.0, 0.0f64..1.0, -2.0f64..2.0, 0.2f64..1.0), 1..5);
    let law = prop_oneof![
        Just(LawKind::Linear),
        Just(LawKind::Hertz),
        Just(LawKind::HuntCrossley)
    ];
    let walls = (proptest::bool::ANY, proptest::bool::ANY, 0.0f64..1.0);
    (bodies, law, 1.0f64..4.0, 0.0f64..1.5, walls, 0.5f64..10.0).prop_map(
        |(bodies, kind, log_k, damping, (left, right, gap), until)| {
            let mut x = 0.0;
            let mut l = Layout::new(&[], &[], &[], &[]);
            for (m, g, v, s) in bodies {
                x += g + s / 2.0;
                l.m.push(m);
                l.x.push(x);
                l.v.push(v);
                l.sizes.push(s);
                x += s / 2.0;
            }
            let l = l.walls(left.then_some(-gap), right.then_some(x + gap));
            let damping = match kind {
                LawKind::Hertz => None,
                LawKind::HuntCrossley => Some(Damping::Absolute(damping)),
                LawKind::Linear => Some(Damping::Zeta(damping)),
            };
            let laws = Laws {
                kind,
                k: 10f64.powf(log_k),
                damping,
                wall_k: None,
                wall_damping: None,
            };
            let until = (l.left.is_some() && l.right.is_some()).then_some(until);
            (l, laws, until)
        },
    )
}

proptest! {
    #![proptest_config(proptest_config(300))]
    /// Generated layouts through the library: whatever a run returns satisfies the invariants,
    /// its history (the `--plot` data) included: every sample's overlap short of the centres'
    /// meeting and its force a push; and what it refuses, it refuses by name.
    #[test]
    fn generated_contact_runs_satisfy_the_invariants((l, laws, until) in layouts()) {
        let bodies: Vec<Body> = (0..l.m.len())
            .map(|i| Body { m: Mass::from_f64(l.m[i]).unwrap(), x: l.x[i], v: l.v[i], size: l.sizes[i] })
            .collect();
        let setup = Setup::new(bodies, (l.left, l.right), laws);
        let settings = Settings {
            method: None,
            dt: None,
            tol: None,
            until,
            max_steps: 200_000,
            trace: true,
        };
        let run = match contact::simulate(&setup, &settings) {
            Ok(run) => run,
            Err(e) => {
                // A refusal names its reason; none may be a NaN.
                let m = e.to_string();
                prop_assert!(!m.contains("NaN") && !m.is_empty(), "{m}");
                return Ok(());
            }
        };
        let out = collide::report::contact::json(&run).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(contact(&l, &out, 1e-8).is_ok(), "{:?}: {:?}\n{out}", l, contact(&l, &out, 1e-8));
        let slots = setup.slots().unwrap();
        // A force is a push, to the rounding of the largest force its contact had.
        let mut largest = vec![0.0f64; slots.len()];
        for s in &run.history {
            largest[s.slot] = largest[s.slot].max(s.force.abs());
        }
        for s in &run.history {
            prop_assert!(s.overlap < slots[s.slot].reach, "{s:?}");
            prop_assert!(s.force >= -1e-6 * largest[s.slot], "a pull: {s:?}");
        }
    }
}
