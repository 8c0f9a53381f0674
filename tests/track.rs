//! `collide track` as a user runs it: exact pi counts (including whole-multiple mass ratios),
//! superball speeds, simultaneous events, the Zeno cut-off, long-run conservation, the log,
//! bad layouts.

mod common;

use collide::track::{Body, Limits, Stop, Track};
use common::collide;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = collide()
        .arg("track")
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn pi_billiards_counts_from_the_command_line() {
    // 100^N: the first N + 1 digits of pi (N = 0..6 here; the shipped scenes go to N = 8).
    for (n, digits) in [
        (0, 3),
        (1, 31),
        (2, 314),
        (3, 3141),
        (4, 31415),
        (5, 314159),
        (6, 3141592),
    ] {
        let big = format!("{}", 100f64.powi(n));
        let j = json(&[
            "-m",
            &format!("1,{big}"),
            "-x",
            "1,2",
            "-v",
            "0,-1",
            "--left-wall",
            "0",
        ]);
        assert_eq!(j["collisions"], digits, "N = {n}");
        assert_eq!(j["pi"]["theory"], digits);
        assert_eq!(j["pi"]["agrees"], true);
        assert_eq!(j["stop"]["reason"], "done");
    }
}

#[test]
fn whole_multiple_mass_ratios_are_exact() {
    // pi/theta whole: m/M = 1 (theta = pi/4): 3; M = 3m (pi/6): 5; M = m/3 (pi/3): 2.
    for (masses, count) in [
        ("1,1", 3),
        ("1,3", 5),
        ("3,1", 2),
        ("0.1,0.3", 5),
        ("2,2", 3),
    ] {
        let j = json(&["-m", masses, "-x", "1,2", "-v", "0,-1", "--left-wall", "0"]);
        assert_eq!(j["collisions"], count, "masses {masses}");
        assert_eq!(j["pi"]["theory"], count, "masses {masses}");
    }
    let j = json(&["-m", "3,1", "-x", "1,2", "-v", "0,-1", "--left-wall", "0"]);
    assert_eq!(
        j["v"][0], j["v"][1],
        "ratio 1/3: both blocks end at the same velocity"
    );
}

#[test]
fn superball_stacks_approach_3v_and_7v() {
    // Light upper balls: 1, 1e-8, 1e-16. Limits 3 and 7 (physics.md); finite ratios from the
    // two-body rule: (3 - r)/(1 + r) for two balls.
    let two = json(&[
        "-m",
        "1,1e-8",
        "--sizes",
        "1,1",
        "-x",
        "1.5,2.5",
        "-v",
        "-1,-1",
        "--left-wall",
        "0",
    ]);
    let top = two["v"][1].as_f64().unwrap();
    let r = 1e-8;
    assert!(
        (top - (3.0 - r) / (1.0 + r)).abs() <= 4.0 * f64::EPSILON * 3.0,
        "{top}"
    );
    let three = json(&[
        "-m",
        "1,1e-8,1e-16",
        "--sizes",
        "1,1,1",
        "-x",
        "1.5,2.5,3.5",
        "-v",
        "-1,-1,-1",
        "--left-wall",
        "0",
    ]);
    let top = three["v"][2].as_f64().unwrap();
    assert!((top - 7.0).abs() < 1e-6, "{top}");
    assert_eq!(
        three["simultaneous"], 2,
        "floor and two pairs at one instant"
    );
}

#[test]
fn simultaneous_collisions_follow_the_documented_rule() {
    // A body hit from both sides at once: 1 -> 2 <- 3, equal masses, touching at t = 1.
    // Left to right: (1,2) swap to (0, 1, -1), then (2,3) to (0, -1, 1), then (1,2) again:
    // (-1, 0, 1), each pair resolved with the velocities the previous one left.
    let j = json(&["-m", "1,1,1", "-x", "0,1,2", "-v", "1,0,-1"]);
    assert_eq!(j["collisions"], 3);
    assert_eq!(j["simultaneous"], 2);
    assert_eq!(j["v"], serde_json::json!([-1.0, 0.0, 1.0]));
    // Nothing passes through anything: positions stay ordered.
    let x: Vec<f64> = j["x"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert!(x.windows(2).all(|w| w[0] <= w[1]), "{x:?}");
}

#[test]
fn bouncing_ball_stops_at_the_zeno_time() {
    // Dropped from h under g: t0 = sqrt(2h/g); bounces with e accumulate at t0 (1+e)/(1-e).
    for (h, g, e) in [
        (1.0, 2.0, 0.5),
        (2.0, 9.81, 0.8),
        (0.5, 1.0, 0.3),
        (10.0, 3.0, 0.9),
    ] {
        let (hs, gs, es) = (h.to_string(), g.to_string(), e.to_string());
        let j = json(&[
            "-m",
            "1",
            "-x",
            &hs,
            "-v",
            "0",
            "--left-wall",
            "0",
            "--gravity",
            &gs,
            "--wall-restitution",
            &es,
        ]);
        assert_eq!(j["stop"]["reason"], "zeno", "h {h} g {g} e {e}");
        let t0 = (2.0f64 * h / g).sqrt();
        let expected = t0 * (1.0 + e) / (1.0 - e);
        let got = j["stop"]["accumulation"].as_f64().unwrap();
        assert!(
            (got - expected).abs() <= 1e-9 * expected,
            "h {h} g {g} e {e}: {got} vs {expected}"
        );
    }
    let out = collide()
        .args([
            "track",
            "-m",
            "1",
            "-x",
            "1",
            "-v",
            "0",
            "--left-wall",
            "0",
            "--gravity",
            "2",
            "-e",
            "0.5",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("infinitely many collisions in finite time"),
        "{text}"
    );
    let at: f64 = text
        .split("accumulate at t = ")
        .nth(1)
        .and_then(|r| r.split(';').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!((at - 3.0).abs() < 1e-9, "{text}");
}

#[test]
fn an_inelastic_collapse_between_walls_ends() {
    // Three balls with e = 0.3 between walls: it must end (collapse or rest), not hang.
    let j = json(&[
        "-m",
        "1,1,1",
        "-x",
        "1,2,3",
        "-v",
        "1,0,-1",
        "--left-wall",
        "0",
        "--right-wall",
        "4",
        "-e",
        "0.3",
    ]);
    assert!(j["collisions"].as_u64().unwrap() > 3);
    assert!(j["energy"]["end"].as_f64().unwrap() < j["energy"]["start"].as_f64().unwrap());
}

#[test]
fn elastic_runs_conserve_energy_over_millions_of_collisions() {
    // Pi billiards N = 6: 3,141,592 collisions.
    let t = Track::pi_billiards(1.0, 1e12);
    let r = t.run(
        Limits {
            until: None,
            max_collisions: u64::MAX,
        },
        None,
    );
    assert_eq!(r.collisions, 3_141_592);
    assert!(
        ((r.energy.end - r.energy.start) / r.energy.start).abs() < 1e-12,
        "{:?}",
        r.energy
    );
    // 200 bodies between walls, a million collisions, through the general event queue.
    let t = Track {
        bodies: (0..200)
            .map(|i| Body {
                m: 1.0 + (i % 3) as f64,
                x: i as f64 + 1.0,
                v: ((i * 37) % 11) as f64 - 5.0,
                size: 0.0,
            })
            .collect(),
        left_wall: Some(0.0),
        right_wall: Some(201.0),
        e: 1.0,
        e_wall: 1.0,
        gravity: 0.0,
    };
    let r = t.run(
        Limits {
            until: None,
            max_collisions: 1_000_000,
        },
        None,
    );
    assert_eq!(r.stop, Stop::MaxCollisions);
    assert!(
        ((r.energy.end - r.energy.start) / r.energy.start).abs() < 1e-12,
        "{:?}",
        r.energy
    );
    assert!(r.x.windows(2).all(|w| w[0] <= w[1]), "order kept");
}

#[test]
fn the_log_lists_every_collision() {
    let dir = std::env::temp_dir().join(format!("collide-track-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("log.csv");
    collide()
        .args([
            "track",
            "-m",
            "1,100",
            "-x",
            "1,2",
            "-v",
            "0,-1",
            "--left-wall",
            "0",
            "--log",
            csv.to_str().unwrap(),
        ])
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "n,t,who,v_before,v_after");
    assert_eq!(lines.len(), 1 + 31);
    assert!(
        lines[1].starts_with("1,1.0,1 & 2,0.0 -1.0,"),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].starts_with("2,") && lines[2].contains("left wall & 1"),
        "{}",
        lines[2]
    );
    let jsonl = dir.join("log.jsonl");
    collide()
        .args([
            "track",
            "-m",
            "1,1",
            "-x",
            "1,2",
            "-v",
            "0,-1",
            "--left-wall",
            "0",
            "--log",
            jsonl.to_str().unwrap(),
        ])
        .assert()
        .success();
    let events: Vec<Value> = std::fs::read_to_string(&jsonl)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(events.len(), 3);
    assert_eq!(events[0]["after"], serde_json::json!([-1.0, 0.0]));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn caps_and_bad_layouts() {
    let j = json(&[
        "-m",
        "1,10000",
        "-x",
        "1,2",
        "-v",
        "0,-1",
        "--left-wall",
        "0",
        "--max-collisions",
        "100",
    ]);
    assert_eq!(j["collisions"], 100);
    assert_eq!(j["stop"]["reason"], "max-collisions");
    let out = collide()
        .args([
            "track",
            "-m",
            "1,10000",
            "-x",
            "1,2",
            "-v",
            "0,-1",
            "--left-wall",
            "0",
            "--max-collisions",
            "100",
        ])
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stdout).contains("--max-collisions cap of 100"));
    for (args, needle) in [
        (vec!["-m", "1,1", "-x", "2,1", "-v", "0,0"], "out of order"),
        (
            vec!["-m", "1,1", "-x", "1,2", "-v", "0"],
            "--velocities has 1 values for 2 masses",
        ),
        (
            vec!["-m", "1,0", "-x", "1,2", "-v", "0,0"],
            "body 2: mass '0' must be greater than 0",
        ),
        (
            vec!["-m", "1", "-x", "1", "-v", "0", "--gravity", "1"],
            "left-wall",
        ),
        (
            vec!["-m", "1", "-x", "-1", "-v", "0", "--left-wall", "0"],
            "left of the left wall",
        ),
        (
            vec!["-m", "1,x", "-x", "1,2", "-v", "0,0"],
            "'x' is not a number",
        ),
    ] {
        let out = collide().arg("track").args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            out.stdout.is_empty() && err.contains(needle),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn unrepresentable_bookkeeping_is_refused_by_name() {
    let out = collide()
        .args([
            "track",
            "-m",
            "1e300,1e300",
            "-x",
            "1,2",
            "-v",
            "1e200,-1e200",
            "--left-wall",
            "0",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(
        err.contains("energy or momentum is beyond binary64") && err.contains("rescale"),
        "{err}"
    );
    assert!(!err.contains("inf"), "{err}");
}
