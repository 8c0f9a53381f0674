//! `collide track` runs that could end only at the collision cap, or never: jammed layouts,
//! periodic stacks, pi simulations beyond minutes, the exact collapse, scenes with bad values.

use crate::common;
use crate::track::{json, xs};

use serde_json::Value;

// Issue 24 §3: runs that ended only at the collision cap, or never.

#[test]
fn a_jammed_layout_is_refused_at_once() {
    use crate::resources::refused;
    // A body exactly filling the gap between the walls took 48 s to report 1e9 collisions at
    // t = 0 (74 s for two bodies): rigid bodies with no room collide without end.
    // Elastic (the command) or not: refused, not 1e9 collisions at t = 0 nor a
    // collapse reported at t = 0 with the bodies still moving.
    for (args, right) in [
        (vec!["-m", "1", "-x", "0.5", "-v", "1", "--sizes", "1"], "1"),
        (
            vec![
                "-m", "1", "-x", "0.5", "-v", "1", "--sizes", "1", "-e", "0.5",
            ],
            "1",
        ),
        (
            vec!["-m", "1,1", "-x", "0.5,1.5", "-v", "1,0", "--sizes", "1,1"],
            "2",
        ),
        (
            vec![
                "-m",
                "1,2,3",
                "-x",
                "0.05,0.2,0.65",
                "-v",
                "0,0,-2",
                "--sizes",
                "0.1,0.2,0.7",
            ],
            "1",
        ),
    ] {
        let mut all = vec!["track"];
        all.extend(&args);
        all.extend(["--left-wall", "0", "--right-wall", right]);
        refused(&all, "fill the space between the walls");
    }
    // At rest, nothing happens: no collision, exit 0.
    let j = json(&[
        "-m",
        "1",
        "-x",
        "0.5",
        "-v",
        "0",
        "--sizes",
        "1",
        "--left-wall",
        "0",
        "--right-wall",
        "1",
    ]);
    assert_eq!(j["collisions"], 0);
}

#[test]
fn an_elastic_stack_under_gravity_bounces_periodically() {
    use crate::resources::bounded;
    // Ball 1 (size 1) rests on the floor; ball 2 (size 1, equal mass) falls from rest through
    // d = 1 onto it. Derived by hand: it lands after t1 = sqrt(2 d / g) at u = sqrt(2 g d);
    // ball 1 takes u, bounces off the floor and gives it back at once (three collisions at one
    // instant), ball 2 rises at u and lands again 2 t1 later. By t = 100, landings at
    // t1 (2k + 1), k = 0..K with K = floor((100 - t1) / (2 t1)): 3 (K + 1) collisions; ball 2 is
    // then s = 100 - t1 (2K + 1) after its last landing, at 1.5 + u s - g s^2 / 2, speed u - g s.
    // Rounding left ball 1 hovering a few ulps above the floor: it micro-bounced 999,999,966
    // times at 1.3e-7 m/s (61 s to the 1e9 cap at t = 15.1).
    let f = bounded(&[
        "track",
        "-m",
        "1,1",
        "-x",
        "0.5,2.5",
        "-v",
        "0,0",
        "--sizes",
        "1,1",
        "--left-wall",
        "0",
        "--gravity",
        "9.8",
        "-e",
        "1",
        "--until",
        "100",
        "--format",
        "json",
    ]);
    assert!(!f.timed_out, "the stack micro-bounced");
    assert_eq!(f.code, Some(0), "{}", f.stderr);
    let j: Value = serde_json::from_str(&f.stdout).unwrap();
    let (g, d) = (9.8f64, 1.0f64);
    let t1 = (2.0 * d / g).sqrt();
    let u = (2.0 * g * d).sqrt();
    let k = ((100.0 - t1) / (2.0 * t1)).floor();
    assert_eq!(k, 110.0);
    assert_eq!(j["collisions"], 3 * 111);
    assert_eq!(j["stop"]["reason"], "until");
    let s = 100.0 - t1 * (2.0 * k + 1.0);
    let x = xs(&j);
    let v: Vec<f64> = j["v"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!((x[0], v[0]), (0.5, 0.0), "ball 1 rests on the floor");
    // Each of the 333 event times is rounded (a few ulps of t <= 100, 1.4e-14 each): the last
    // landing is off by at most about 333 x 4 x 1.4e-14 = 2e-11 s, which moves x2 and v2 by at
    // most u or g times that: 1e-10 relative.
    common::assert_close(x[1], 1.5 + u * s - g * s * s / 2.0, 1e-10, "x2");
    common::assert_close(v[1], u - g * s, 1e-10, "v2");
}

#[test]
fn pi_simulations_beyond_minutes_are_refused_with_their_time() {
    use crate::resources::refused;
    // `pi 20 --simulate` (any N from 11 to 153) ran for ever.
    for (n, says) in [
        ("11", "52.4 minutes"),
        ("20", "years"),
        ("10000", "3.1e10000"),
    ] {
        let f = refused(&["pi", n, "--simulate"], says);
        assert!(f.stderr.contains("N up to 10"), "{}", f.stderr);
    }
    // `--simulate --no-simulate` was accepted (the last one won).
    let (code, out, err) = common::run(&["pi", "3", "--simulate", "--no-simulate"]);
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("cannot be used with"),
        "{err}"
    );
}

#[test]
fn a_track_without_walls_has_no_wall_restitution() {
    // Issue 28: "e = 1 between bodies, 1 at walls" with no walls.
    let out = common::stdout(&["track", "-m", "1,1", "-x", "0,1", "-v", "1,0"]);
    assert!(
        out.starts_with("2 bodies, no walls; e = 1 between bodies\n"),
        "{out}"
    );
    let out = common::stdout(&[
        "track",
        "-m",
        "1,1",
        "-x",
        "1,2",
        "-v",
        "0,-1",
        "--left-wall",
        "0",
    ]);
    assert!(out.contains("e = 1 between bodies, 1 at walls"), "{out}");
}

#[test]
fn bad_track_scenes_are_located_at_the_line_of_the_bad_value() {
    // Each bad value of a [track] scene is reported as file:line:column at that value (or its
    // list), with exit 2 and nothing on stdout.
    let dir = std::env::temp_dir().join(format!("collide-track-scene-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.toml");
    let good =
        "[track]\nmasses = [1, 2]\npositions = [1, 2]\nvelocities = [0, -1]\nleft_wall = 0\n";
    for (extra, place, needle) in [
        ("friction = 1", "6:1", "unknown field `friction`"),
        (
            "restitution = 1.5",
            "6:15",
            "restitution: restitution '1.5' is above 1",
        ),
        (
            "wall_restitution = 2",
            "6:20",
            "wall_restitution: restitution '2' is above 1",
        ),
        ("until = -1", "6:9", "(until) is -1"),
        ("gravity = \"x\"", "6:11", "'x' is not a number"),
        ("gravity = -1", "6:11", "gravity -1 must be finite and >= 0"),
        ("max_collisions = -3", "6:18", "expected u64"),
        ("sizes = [1]", "6:9", "sizes: 1 values for 2 bodies"),
        ("sizes = [1, -1]", "6:9", "body 2: size -1 must be finite"),
        (
            "sizes = [1, 5]",
            "3:13",
            "bodies 1 and 2 overlap or are out of order",
        ),
        (
            "right_wall = 1.5",
            "3:13",
            "body 2 is right of the right wall at 1.5",
        ),
    ] {
        std::fs::write(&path, format!("{good}{extra}\n")).unwrap();
        let (code, out, err) = common::run(&["scene", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{extra}: {err}");
        assert!(out.is_empty(), "{extra}");
        let at = format!("bad.toml:{place}: ");
        assert!(
            err.contains(&at) && err.contains(needle),
            "{extra}: {err} lacks {at}{needle}"
        );
    }
    for (text, place, needle) in [
        (
            "[track]\nmasses = [1, 2]\npositions = [2, 1]\nvelocities = [0, -1]\n",
            "3:13",
            "out of order",
        ),
        (
            "[track]\nmasses = [1, 0]\npositions = [1, 2]\nvelocities = [0, -1]\n",
            "2:10",
            "body 2: mass '0'",
        ),
        (
            "[track]\nmasses = [1, 2]\npositions = [1, 2]\nvelocities = [0]\n",
            "4:14",
            "velocities: 1 values",
        ),
        (
            "[track]\nmasses = [1]\npositions = [1]\nvelocities = [0]\ngravity = 1\n",
            "5:11",
            "give a --left-wall",
        ),
        (
            "[track]\nmasses = [1]\npositions = [-1]\nvelocities = [0]\nleft_wall = 0\n",
            "3:13",
            "left of the left wall",
        ),
    ] {
        std::fs::write(&path, text).unwrap();
        let (code, out, err) = common::run(&["scene", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{text}: {err}");
        assert!(out.is_empty());
        let at = format!("bad.toml:{place}: ");
        assert!(
            err.contains(&at) && err.contains(needle),
            "{text}: {err} lacks {at}{needle}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
