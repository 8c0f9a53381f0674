//! Issue 41: a track's stop names its true reason (an energy that is not zero never prints as 0,
//! the binary64 horizon), a motion that never ends stops at its own cap, and the energy check's
//! one tolerance.

use crate::common;
use crate::track::json;

use collide::line::inertia::Mass;
use collide::track::{Body, Track};
use common::collide;
use serde_json::Value;

#[test]
fn collisions_that_spread_out_without_end_stop_at_the_binary64_horizon() {
    // Found by the random layouts (seed 474): a light body between a wall and a heavy one,
    // e = 0.6, bounces with geometrically slowing speeds, so collisions spread out without end;
    // after ~9,000 the next is near t = 1.3e308, where positions overflow. The run stops at the
    // last collision that binary64 can hold (it used to fail with "a position became inf").
    let out = collide()
        .args([
            "track",
            "-m",
            "5.006375867398605e23,1.388930052741735e25,1",
            "-x",
            "0.8274563377198182,3.2410893126556,4.4558620462120835",
            "-v",
            "0,-0.5408622992551558,1.3977458304722754",
            "--sizes",
            "0.6549126754396363,0.7085462603481193,0.9209992067734158",
            "--left-wall",
            "0",
            "-e",
            "0.5956118960784317",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["stop"]["reason"], "horizon", "{}", j["stop"]);
    let next = j["stop"]["next"].as_f64().unwrap();
    assert!(next > 1e300 && next.is_finite());
    assert!(j["time"].as_f64().unwrap() <= next);
}

// Issue 41 §1: a stop names its true reason; an energy that is not zero never prints as 0.

#[test]
fn bounces_slowing_without_end_stop_where_the_energy_would_underflow() {
    // A ball of mass 1 at 0 moving at 1 between walls at -1 and 1, e = 0.5: its speed halves at
    // each wall, v_k = 2^-k after bounce k, energy 2^-(2k+1). Bounce 1 at t = 1, then each
    // crossing of 2 at speed 2^-(k-1): t_k = 1 + sum_{j=1}^{k-1} 2^(j+1) = 2^(k+1) - 3. Bounce
    // k = 511 would leave the energy 2^-1023, below 2^-1022 (binary64's least normal): the run
    // stops after 510, at the left wall, with the energy 2^-1021 (it ran on to t = 9e307 and
    // printed the energy 2.5e-616 as 0, "no collision can happen any more").
    let args = [
        "-m",
        "1",
        "-x",
        "0",
        "-v",
        "1",
        "--left-wall",
        "-1",
        "--right-wall",
        "1",
        "-e",
        "0.5",
    ];
    let j = json(&args);
    assert_eq!(j["stop"]["reason"], "horizon", "{}", j["stop"]);
    assert_eq!(j["stop"]["beyond"], "energy");
    assert_eq!(j["collisions"], 510);
    // Powers of two: exact.
    assert_eq!(j["energy"]["end"].as_f64().unwrap(), 2f64.powi(-1021));
    assert_eq!(j["v"][0].as_f64().unwrap(), 2f64.powi(-510));
    assert_eq!(j["x"][0].as_f64().unwrap(), -1.0);
    // 2^511 - 3 and 2^512 - 3 round to the powers of two; each event time is a sum of them.
    let close = |got: &Value, want: f64| {
        let got = got.as_f64().unwrap();
        assert!(
            (got - want).abs() <= 4.0 * f64::EPSILON * want,
            "{got} vs {want}"
        );
    };
    close(&j["time"], 2f64.powi(511) - 3.0);
    close(&j["stop"]["next"], 2f64.powi(512) - 3.0);
    let out = collide().arg("track").args(args).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("energy    0.5  4.4501477170144e-308"),
        "{text}"
    );
    assert!(text.contains("below binary64's range (2.2e-308)"), "{text}");
}

#[test]
fn collisions_beyond_binary64_times_stop_at_the_horizon_not_as_done() {
    // A ball at 0 moving at 1, elastic, between walls at -1e307 and 1e307: bounces at
    // t_k = 1e307 + 2e307 (k - 1), k = 1..9 (t_9 = 1.7e308), then t_10 = 1.9e308 is beyond
    // binary64 (1.8e308): the collisions go on, but not in binary64's time. It said "no
    // collision can happen any more".
    let j = json(&[
        "-m",
        "1",
        "-x",
        "0",
        "-v",
        "1",
        "--left-wall",
        "-1e307",
        "--right-wall",
        "1e307",
    ]);
    assert_eq!(j["stop"]["reason"], "horizon", "{}", j["stop"]);
    assert_eq!(j["stop"]["beyond"], "time");
    assert!(j["stop"].get("next").is_none(), "{}", j["stop"]);
    assert_eq!(j["collisions"], 9);
    let t = j["time"].as_f64().unwrap();
    assert!((t - 1.7e308).abs() <= 8.0 * f64::EPSILON * 1.7e308, "{t}");
    // The ninth bounce is at the right wall: back at speed 1.
    assert_eq!(
        (j["x"][0].as_f64(), j["v"][0].as_f64()),
        (Some(1e307), Some(-1.0))
    );
    assert_eq!(j["energy"]["end"], 0.5);
}

// Issue 41 §3: a motion that never ends, its stop, and the energy check's one tolerance.

const SUPERBALL_STACK: [&str; 12] = [
    "-m",
    "1,0.01",
    "-x",
    "1.5,2.25",
    "-v",
    "0,0",
    "--sizes",
    "1,0.5",
    "--left-wall",
    "0",
    "--gravity",
    "9.81",
];

#[test]
fn an_elastic_stack_keeps_its_energy_to_the_stated_tolerance() {
    use collide::track::{ENERGY_PER_COLLISION, ENERGY_TOLERANCE, energy_tolerance};
    // The page's superball stack bounces for ever (elastic, under gravity). It drifted by 1e-8
    // in a million collisions and failed its own check ("please report this case"), and by
    // -1.4e-9 in 300,000 where 1e-9 was promised: the bodies were put onto the floor and into
    // contact at event times rounded to an ulp of t, off their parabolas by up to |v| ulp(t).
    // The energy is E = 1/2 m v^2 + m g h summed: m1 g 1.5 + m2 g 2.25 = 9.81 (1.5 + 0.0225)
    // = 14.935725 at rest, exactly as the check's start.
    for n in [300_000u64, 1_000_000] {
        let mut args = SUPERBALL_STACK.to_vec();
        let cap = n.to_string();
        args.extend(["--max-collisions", &cap]);
        let j = json(&args);
        assert_eq!(j["stop"]["reason"], "max-collisions");
        assert_eq!(j["collisions"], n);
        let (e0, e1) = (
            j["energy"]["start"].as_f64().unwrap(),
            j["energy"]["end"].as_f64().unwrap(),
        );
        assert!((e0 - 14.935725).abs() <= 4.0 * f64::EPSILON * e0, "{e0}");
        let rel = (e1 - e0) / e0;
        assert!(rel.abs() <= energy_tolerance(n), "{n}: {rel:e}");
        // Measured: 8e-14 and 1.5e-14; within the flat 1e-9 by far.
        assert!(rel.abs() <= 1e-12, "{n}: {rel:e}");
    }
    // One tolerance: 1e-9, or 8 ulps a collision beyond 1e-9 / (8 eps) = 562,950 collisions,
    // the numbers docs/track.md states.
    assert_eq!(ENERGY_TOLERANCE, 1e-9);
    assert_eq!(ENERGY_PER_COLLISION, 8.0 * f64::EPSILON);
    assert_eq!(energy_tolerance(562_949), 1e-9);
    assert_eq!(energy_tolerance(1_000_000_000), 8e9 * f64::EPSILON);
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/track.md"))
        .unwrap()
        .replace("\n  ", " ");
    for stated in [
        "of at most 1e-9, or 8 ulps of 1 (1.8e-15) per collision",
        "beyond 562,950 collisions",
    ] {
        assert!(doc.contains(stated), "docs/track.md: {stated}");
    }
    // The cap says the motion had not ended and how to bound it.
    let mut args = vec!["track"];
    args.extend(SUPERBALL_STACK);
    args.extend(["--max-collisions", "1000"]);
    let out = collide().args(&args).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("at the --max-collisions cap of 1000, before the motion ended")
            && text.contains("give --until T for the state at a time T"),
        "{text}"
    );
}

#[test]
fn a_motion_that_never_ends_stops_at_its_own_cap_and_says_how_to_bound_it() {
    use collide::track::{ENDLESS_MAX_COLLISIONS, energy_tolerance};
    // The page's superball preset at the default --max-collisions ran for minutes (853 million
    // collisions, then "please report this case" where an ulp of t = 4.1e8 outgrew the spacing
    // of its collisions; issue 41). Elastic under gravity it cannot end: it stops at a million
    // collisions (0.5 s measured), exit 0, with the reason and how to bound it.
    assert_eq!(ENDLESS_MAX_COLLISIONS, 1_000_000);
    let started = std::time::Instant::now();
    let j = json(&SUPERBALL_STACK);
    let seconds = started.elapsed().as_secs_f64();
    assert!(seconds < 30.0, "{seconds} s");
    assert_eq!(j["stop"]["reason"], "endless");
    assert_eq!(j["stop"]["cap"], ENDLESS_MAX_COLLISIONS);
    assert_eq!(j["collisions"], ENDLESS_MAX_COLLISIONS);
    // E at rest = 9.81 (1 * 1.5 + 0.01 * 2.25) = 14.935725 (derived by hand); the change is
    // within the tolerance docs/track.md states (1e-9 up to 562,950 collisions, 8 ulps of 1 a
    // collision beyond: 1.78e-9 here). Measured -1.5e-14.
    let (e0, e1) = (
        j["energy"]["start"].as_f64().unwrap(),
        j["energy"]["end"].as_f64().unwrap(),
    );
    assert!((e0 - 14.935725).abs() <= 4.0 * f64::EPSILON * e0, "{e0}");
    let rel = (e1 - e0) / e0;
    assert!(
        rel.abs() <= energy_tolerance(ENDLESS_MAX_COLLISIONS),
        "{rel:e}"
    );
    let mut args = vec!["track"];
    args.extend(SUPERBALL_STACK);
    let out = collide().args(&args).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout).replace('\n', " ");
    for said in [
        "Stopped: the motion never ends (every collision elastic",
        "it stops at 1000000 collisions, the cap for such a run",
        "give --until T for the state at a time T, or a --max-collisions N to go further",
        "After 1000000 collisions",
    ] {
        assert!(text.contains(said), "{said}: {text}");
    }
    // An explicit cap is the user's, even at the default's value; --until still bounds by time.
    let mut capped = SUPERBALL_STACK.to_vec();
    capped.extend(["--max-collisions", "2000"]);
    let j = json(&capped);
    assert_eq!(j["stop"]["reason"], "max-collisions");
    assert_eq!(j["collisions"], 2000);
    let mut until = SUPERBALL_STACK.to_vec();
    until.extend(["--until", "10"]);
    assert_eq!(json(&until)["stop"]["reason"], "until");
    // Walls on both sides hold an elastic body as well; an open elastic track (pi billiards,
    // one wall) ends by itself and keeps the 1e9 default (31415 collisions for 100^4).
    let walls = json(&[
        "-m",
        "1",
        "-x",
        "0",
        "-v",
        "1",
        "--left-wall",
        "-1",
        "--right-wall",
        "1",
    ]);
    assert_eq!(walls["stop"]["reason"], "endless");
    assert_eq!(walls["collisions"], ENDLESS_MAX_COLLISIONS);
    // One bounce from wall to wall takes 2 (a distance 2 at speed 1); the first at t = 1.
    assert_eq!(walls["time"].as_f64().unwrap(), 1.0 + 2.0 * 999_999.0);
    let pi = json(&["-m", "1,1e8", "-x", "1,2", "-v", "0,-1", "--left-wall", "0"]);
    assert_eq!(
        (pi["stop"]["reason"].clone(), pi["collisions"].clone()),
        ("done".into(), 31415.into())
    );
}

#[test]
fn which_motions_never_end() {
    let track = |e: f64, e_wall: f64, gravity: f64, right: Option<f64>| Track {
        bodies: vec![Body {
            m: Mass::from_f64(1.0).unwrap(),
            x: 1.0,
            v: 0.0,
            size: 0.0,
        }],
        left_wall: Some(0.0),
        right_wall: right,
        e,
        e_wall,
        gravity,
    };
    // Elastic and held (gravity, or two walls): endless. Open, or losing energy: it ends.
    assert!(track(1.0, 1.0, 9.81, None).endless());
    assert!(track(1.0, 1.0, 0.0, Some(2.0)).endless());
    assert!(!track(1.0, 1.0, 0.0, None).endless());
    assert!(!track(1.0, 0.5, 9.81, None).endless());
    assert!(!track(0.9, 1.0, 0.0, Some(2.0)).endless());
}
