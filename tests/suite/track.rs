//! `collide track` as a user runs it: exact pi counts (including whole-multiple mass ratios),
//! superball speeds, simultaneous events, the Zeno cut-off, long-run conservation, the log,
//! bad layouts.

use crate::common;

use collide::line::inertia::Mass;
use collide::track::{Body, Limits, Stop, Track};
use common::collide;
use serde_json::Value;

pub(crate) fn json(args: &[&str]) -> Value {
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
        assert_eq!(j["pi"]["theory"], digits.to_string());
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
        assert_eq!(j["pi"]["theory"], count.to_string(), "masses {masses}");
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
    // (3 - r)/(1 + r) with r = 1e-8 exactly, rounded once; two impulses, each rounded once.
    let r = collide::values::rational::ratio(1, 100_000_000);
    let three_r = common::rounded(
        &((collide::values::rational::int(3) - &r) / (collide::values::rational::int(1) + &r)),
    );
    common::assert_ulps(top, three_r, 2.0, "top speed of the two-ball stack");
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
    // Three balls: the floor reverses ball 1, ball 1 (at +1) and ball 2 (at -1) give ball 2
    // (3 - r)/(1 + r), and ball 2 and ball 3 (mass ratio r again) give ball 3
    // ((1 - r) + 2 (3 - r)/(1 + r))/(1 + r) = (7 - 2r - r^2)/(1 + r)^2; no pair approaches
    // after that. With r = 1e-8 exactly (the masses as typed), in exact arithmetic, rounded
    // once: each of the three impulses is rounded once, so the top speed is within a few ulps.
    let top = three["v"][2].as_f64().unwrap();
    let r = collide::values::rational::ratio(1, 100_000_000);
    let one = collide::values::rational::int(1);
    let seven = common::rounded(
        &((collide::values::rational::int(7) - collide::values::rational::int(2) * &r - &r * &r)
            / ((&one + &r) * (&one + &r))),
    );
    common::assert_ulps(top, seven, 4.0, "top speed of the three-ball stack");
    assert!(top < 7.0);
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
    // The same collapse in exact rational arithmetic (points on [0, 4], e the binary64 0.3):
    // event times are rational (gap / closing speed), so the sequence is exact. It collapses
    // onto the right wall: every body tends to x = 4 and the times to 119.18032978518282
    // (the exact time of collision 300 rounded, the same as collision 600's).
    let exact = crate::track_rows::collapse(300);
    let limit = common::rounded(exact.times.last().unwrap());
    assert_eq!(limit, 119.18032978518282);
    assert!(exact.x.iter().all(|x| common::rounded(x) == 4.0));
    // The run's own collisions, logged.
    let track = Track {
        bodies: (1..=3)
            .map(|i| Body {
                m: Mass::from_f64(1.0).unwrap(),
                x: f64::from(i),
                v: f64::from(2 - i),
                size: 0.0,
            })
            .collect(),
        left_wall: Some(0.0),
        right_wall: Some(4.0),
        e: 0.3,
        e_wall: 0.3,
        gravity: 0.0,
    };
    let mut log: Vec<(f64, String)> = Vec::new();
    let run = track
        .run(
            Limits {
                until: None,
                max_collisions: 1_000_000,
            },
            Some(&mut |e: &collide::track::Event| log.push((e.t, e.who.clone()))),
        )
        .unwrap();
    assert_eq!(run.collisions, j["collisions"].as_u64().unwrap());
    // Collision by collision, the same contacts in the same order as exact arithmetic for the
    // first 76 (measured: the first difference is at 77, where gaps of 1e-12 are below the
    // rounding slack of positions near 4 and binary64's times stop advancing), at the same
    // times to 1e-12 relative for the first 40 (measured: 8.5e-14).
    for (k, ((t, who), (x, name))) in log
        .iter()
        .zip(exact.times.iter().zip(&exact.who))
        .enumerate()
        .take(76)
    {
        assert_eq!(who, name, "collision {}", k + 1);
        if k < 40 {
            let x = common::rounded(x);
            assert!(
                (t - x).abs() <= 1e-12 * x,
                "collision {}: t = {t} against {x}",
                k + 1
            );
        }
    }
    // The stop: a Zeno sequence, at the first collision where the documented rule holds on the
    // run's own times (200 collisions of at most 8 contacts within 1e-12 of t: here the times
    // that binary64 can no longer tell apart), with every body at the limit x = 4. The
    // accumulation time is that of exact arithmetic to 1e-9 relative (measured: 8.3e-11, about
    // 1e-8 early: the last collisions' times are lost to rounding).
    let n = (199..log.len())
        .find(|&k| log[k].0 - log[k - 199].0 <= 1e-12 * log[k].0)
        .map(|k| k + 1);
    assert_eq!(
        n,
        Some(log.len()),
        "the window rule first holds at the last collision"
    );
    assert_eq!(
        run.stop,
        collide::track::Stop::Zeno {
            at: log[log.len() - 1].0,
            accumulation: log[log.len() - 1].0,
            who: log[log.len() - 1].1.clone(),
            x: 4.0,
        }
    );
    let accumulation = j["stop"]["accumulation"].as_f64().unwrap();
    assert!(
        (accumulation - limit).abs() <= 1e-9 * limit,
        "{accumulation} against {limit}"
    );
    assert_eq!(j["x"], serde_json::json!([4.0, 4.0, 4.0]));
    // The counts: pairs and walls add up; "simultaneous" counts the collisions at the same
    // time as the one before.
    let walls = log.iter().filter(|(_, w)| w.contains("wall")).count() as u64;
    assert_eq!(j["wall_collisions"], walls);
    assert_eq!(j["pair_collisions"], run.collisions - walls);
    let same = log.windows(2).filter(|w| w[0].0 == w[1].0).count() as u64;
    assert_eq!(j["simultaneous"], same);
}

#[test]
fn elastic_runs_conserve_energy_over_millions_of_collisions() {
    // Pi billiards N = 6: 3,141,592 collisions.
    let t = Track::pi_billiards("1".parse().unwrap(), "1e12".parse().unwrap());
    let r = t
        .run(
            Limits {
                until: None,
                max_collisions: u64::MAX,
            },
            None,
        )
        .unwrap();
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
                m: Mass::from_f64(1.0 + (i % 3) as f64).unwrap(),
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
    let r = t
        .run(
            Limits {
                until: None,
                max_collisions: 1_000_000,
            },
            None,
        )
        .unwrap();
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

/// Runs `collide track ARGS --format json`, with and without `--log`: both must print the same.
fn json_logged(args: &[&str]) -> Value {
    let plain = json(args);
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let log = std::env::temp_dir().join(format!("collide-log-{}-{k}.csv", std::process::id()));
    let mut with_log: Vec<&str> = args.to_vec();
    let path = log.to_string_lossy().into_owned();
    with_log.extend(["--log", &path]);
    let logged = json(&with_log);
    let lines = std::fs::read_to_string(&log).unwrap().lines().count() as u64;
    std::fs::remove_file(&log).ok();
    assert_eq!(plain, logged, "{args:?}: with and without --log");
    assert_eq!(
        lines,
        plain["collisions"].as_u64().unwrap() + 1,
        "one line a collision"
    );
    plain
}

pub(crate) fn xs(j: &Value) -> Vec<f64> {
    j["x"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn a_light_body_does_not_switch_collisions_off() {
    // Issue 12: a run-wide threshold made these pass through walls and each other.
    // Body 1 hits the wall at t = 1 and is at x = 4 at t = 5; body 2 flies freely to 10005.
    let j = json_logged(&[
        "-m",
        "1,1e-30",
        "-x",
        "1,5",
        "-v",
        "-1,2000",
        "--left-wall",
        "0",
        "--right-wall",
        "1e7",
        "--until",
        "5",
    ]);
    assert_eq!(j["collisions"], 1);
    assert_eq!(xs(&j), [4.0, 10005.0]);
    assert_eq!(j["time"], 5.0);
    // An idle light third body changes nothing for the other two: 3 collisions between them and
    // the wall (2 hits 1, 1 hits the wall, 1 hits 2), then 2 hits 3 at t = 5.
    let j = json_logged(&[
        "-m",
        "1,1,1e-30",
        "-x",
        "1,2,3",
        "-v",
        "0,-1,0",
        "--left-wall",
        "0",
    ]);
    assert_eq!(j["collisions"], 4);
    assert_eq!(j["v"][0], 0.0);
    assert_eq!(j["v"][1], 1.0);
    // Mass ratio 1e24: pi billiards with 3,141,592,653,589 collisions; the first thousand happen
    // (the light body bounces between the wall and the heavy one), in order, and the pi check
    // is not claimed for a run cut short.
    let j = json_logged(&[
        "-m",
        "1e-12,1e12",
        "-x",
        "1,2",
        "-v",
        "0,-0.5",
        "--left-wall",
        "0",
        "--max-collisions",
        "1000",
    ]);
    assert_eq!(j["collisions"], 1000);
    assert_eq!(j["stop"]["reason"], "max-collisions");
    assert_eq!(j["pi"]["theory"], "3141592653589");
    assert!(j["pi"].get("agrees").is_none(), "{j}");
    let x = xs(&j);
    assert!(0.0 <= x[0] && x[0] <= x[1], "{x:?}");
}

#[test]
fn an_elastic_run_never_stops_for_collapse() {
    // Issue 12: with --log this stopped at 14,695,637 collisions "(inelastic collapse)".
    let j = json_logged(&[
        "-m",
        "1,1e10",
        "-x",
        "1,2",
        "-v",
        "0,-1",
        "--left-wall",
        "0",
    ]);
    assert_eq!(j["collisions"], 314_159);
    assert_eq!(j["stop"]["reason"], "done");
    assert_eq!(j["pi"]["agrees"], true);
}

#[test]
fn until_gives_the_state_at_that_time() {
    // The collision at t = 1 swaps the velocities; at t = 10 body 2 is at 2 + 9 = 11.
    let j = json_logged(&["-m", "1,1", "-x", "1,2", "-v", "1,0", "--until", "10"]);
    assert_eq!(j["time"], 10.0);
    assert_eq!(xs(&j), [2.0, 11.0]);
    assert_eq!(j["collisions"], 1);
    for bad in ["-1", "-1e-300", "inf"] {
        let out = collide()
            .args([
                "track", "-m", "1,1", "-x", "1,2", "-v", "1,0", "--until", bad,
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "--until {bad}");
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(">= 0") || err.contains("not a number"),
            "{err}"
        );
    }
}

#[test]
fn a_body_resting_on_the_floor_is_hit_by_one_falling_on_it() {
    // Body 1 rests on the floor (size 1 at x = 0.5); body 2 falls from x = 3 under g = 1 and
    // meets it at x = 1.5 at t = sqrt(3) with speed sqrt(3). Equal masses, elastic: body 2
    // stops, body 1 bounces off the floor at once and gives body 2 its speed back upward. At
    // t = 2: body 2 at 1.5 + sqrt(3) s - s^2 / 2, speed sqrt(3) - s, with s = 2 - sqrt(3).
    let j = json_logged(&[
        "-m",
        "1,1",
        "-x",
        "0.5,3",
        "--sizes",
        "1,1",
        "-v",
        "0,0",
        "--left-wall",
        "0",
        "--gravity",
        "1",
        "--until",
        "2",
    ]);
    assert_eq!(j["collisions"], 3);
    assert_eq!(j["simultaneous"], 2);
    let s3 = 3f64.sqrt();
    let s = 2.0 - s3;
    let x = xs(&j);
    assert_eq!(x[0], 0.5);
    assert!((x[1] - (1.5 + s3 * s - s * s / 2.0)).abs() < 1e-15, "{x:?}");
    let v = j["v"][1].as_f64().unwrap();
    assert!((v - (s3 - s)).abs() < 1e-15, "{v}");
}

#[test]
fn the_log_is_replaced_only_when_the_command_succeeds() {
    let log = std::env::temp_dir().join(format!("collide-keep-{}.csv", std::process::id()));
    std::fs::write(&log, "old log\n").unwrap();
    // One collision at t = 1e-150, then body 2 flies to x = 1e150 * 1e300: beyond binary64.
    let out = collide()
        .args([
            "track", "-m", "1,1", "-x", "0,1", "-v", "1e150,0", "--until", "1e300",
        ])
        .args(["--log", &log.to_string_lossy()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&log).unwrap(), "old log\n");
    let dir = std::fs::read_dir(std::env::temp_dir()).unwrap();
    assert!(
        !dir.flatten()
            .any(|e| e.file_name().to_string_lossy().contains("collide-keep")
                && e.file_name().to_string_lossy().ends_with(".partial")),
        "no temporary file left"
    );
    std::fs::remove_file(&log).ok();
}

#[test]
fn one_body_is_one_body() {
    let out = collide()
        .args([
            "track",
            "-m",
            "1",
            "-x",
            "1",
            "-v",
            "-1",
            "--left-wall",
            "0",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.starts_with("1 body, "), "{text}");
    assert!(text.contains("After 1 collision at t = 1"), "{text}");
}

#[test]
fn collide_pi_gives_fifty_digits_and_simulates_small_n() {
    const PI: &str = "3.14159265358979323846264338327950288419716939937510";
    let out = collide()
        .args(["pi", "50", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["pi"], PI);
    assert!(j.get("simulation").is_none(), "N = 50 is not simulated");
    let out = collide()
        .args(["pi", "4", "--format", "json"])
        .output()
        .unwrap();
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["count"], "31415");
    assert_eq!(j["simulation"]["collisions"], 31415);
    assert_eq!(j["simulation"]["agrees"], true);
    let out = collide().args(["pi", "10001"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}
