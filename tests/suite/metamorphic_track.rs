//! Metamorphic tests of whole runs (issue 24): `track` and `contact` with masses times 4,
//! mirrored layouts and a Galilean boost give the exactly related motion; JSON numbers read back
//! exactly.

use crate::invariants::{Layout, layout_json, num, nums};
use crate::metamorphic::*;

/// The layout mirrored: `x -> -x`, the bodies in the other order, the walls swapped.
fn mirrored(l: &Layout) -> Layout {
    let rev = |x: &[f64], s: f64| x.iter().rev().map(|v| s * v).collect::<Vec<_>>();
    let mut m = Layout::new(
        &rev(&l.m, 1.0),
        &rev(&l.x, -1.0),
        &rev(&l.v, -1.0),
        &rev(&l.sizes, 1.0),
    );
    m.left = l.right.map(|r| -r);
    m.right = l.left.map(|x| -x);
    m
}

/// Layouts for track and contact, with each's flags. None has simultaneous collisions: a track
/// resolves those one pair after another, in an order the mirror reverses (with e < 1 the
/// answers then differ; in contact they are one event).
fn layouts() -> Vec<(Layout, &'static [&'static str], &'static [&'static str])> {
    let cradle = Layout::new(
        &[1.0, 1.0, 1.0, 2.0],
        &[0.0, 2.0, 3.5, 5.5],
        &[1.0, 0.0, 0.0, -0.5],
        &[1.0; 4],
    );
    let boxed = Layout::new(
        &[1.0, 2.0, 1.0],
        &[0.0, 1.5, 3.25],
        &[1.0, 0.0, -1.0],
        &[1.0; 3],
    )
    .walls(Some(-2.0), Some(5.0));
    let light =
        Layout::new(&[0.25, 4.0], &[1.0, 3.0], &[0.0, -1.0], &[0.5, 1.0]).walls(Some(0.0), None);
    vec![
        (
            cradle.clone(),
            &["-e", "0.75"],
            &["--stiffness", "64", "--zeta", "0.25"],
        ),
        (
            boxed,
            &["-e", "0.5", "--until", "12"],
            &["--stiffness", "64", "--zeta", "0.125", "--until", "12"],
        ),
        (light, &[], &["--stiffness", "256", "--law", "hertz"]),
    ]
}

#[test]
fn track_and_contact_masses_times_4_scale_energies_exactly_and_keep_the_motion() {
    for (l, track_flags, contact_flags) in layouts() {
        let mut heavy = l.clone();
        heavy.m.iter_mut().for_each(|m| *m *= 4.0);
        let (a, b) = (
            layout_json("track", &l, track_flags),
            layout_json("track", &heavy, track_flags),
        );
        let f = |p: &str| {
            if p.starts_with("energy") || p.starts_with("momentum") {
                q("4")
            } else {
                q("1")
            }
        };
        alike(&a, &b, &f, 0, &[], &format!("track {l:?}"));
        // Contact: stiffness x 4 with the masses (the same k/m); damping given as zeta.
        let k = contact_flags
            .iter()
            .position(|f| *f == "--stiffness")
            .unwrap()
            + 1;
        let mut flags: Vec<String> = contact_flags.iter().map(|s| s.to_string()).collect();
        flags[k] = format!("{}", flags[k].parse::<f64>().unwrap() * 4.0);
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        let (a, b) = (
            layout_json("contact", &l, contact_flags),
            layout_json("contact", &heavy, &flags),
        );
        let f = |p: &str| {
            if p.starts_with("energy") {
                q("4")
            } else {
                q("1")
            }
        };
        alike(&a, &b, &f, 0, &["stats"], &format!("contact {l:?}"));
    }
}

#[test]
fn mirrored_layouts_give_mirrored_motion() {
    for (l, track_flags, contact_flags) in layouts() {
        let m = mirrored(&l);
        for (cmd, flags, tol) in [
            ("track", track_flags, 1e-12),
            ("contact", contact_flags, 1e-8),
        ] {
            let (a, b) = (layout_json(cmd, &l, flags), layout_json(cmd, &m, flags));
            let what = format!("{cmd} {l:?}");
            let scale = l.x.iter().chain(&l.v).fold(1.0f64, |s, x| s.max(x.abs()));
            for (key, sign) in [("x", -1.0), ("v", -1.0)] {
                let (x, y) = (nums(&a[key]), nums(&b[key]));
                for (i, yi) in y.iter().enumerate() {
                    let xi = sign * x[x.len() - 1 - i];
                    assert!(
                        (xi - yi).abs() <= tol * scale * num(&a["time"]).max(1.0),
                        "{what}: {key} {x:?} {y:?}"
                    );
                }
            }
            let (ea, eb) = (num(&a["energy"]["end"]), num(&b["energy"]["end"]));
            assert!((ea - eb).abs() <= tol * ea, "{what}: energy {ea} {eb}");
            if cmd == "track" {
                assert_eq!(a["collisions"], b["collisions"], "{what}");
            } else {
                assert_eq!(
                    a["contacts"].as_array().unwrap().len(),
                    b["contacts"].as_array().unwrap().len(),
                    "{what}"
                );
            }
        }
    }
}

#[test]
fn a_boost_moves_track_and_contact_runs_along_and_changes_nothing_else() {
    // No walls (they would not move with the observer): every velocity + w, positions + w t.
    let l = layouts().remove(0);
    for w in [8.0, -0.5] {
        let mut boosted = l.0.clone();
        boosted.v.iter_mut().for_each(|v| *v += w);
        for (cmd, flags, tol) in [("track", l.1, 1e-12), ("contact", l.2, 1e-8)] {
            let (a, b) = (
                layout_json(cmd, &l.0, flags),
                layout_json(cmd, &boosted, flags),
            );
            let what = format!("{cmd}, boost {w}");
            let t = num(&a["time"]);
            assert!((num(&b["time"]) - t).abs() <= tol * t, "{what}: time");
            let scale = 1.0 + w.abs() * t;
            for (i, (x, y)) in nums(&a["x"]).iter().zip(nums(&b["x"])).enumerate() {
                assert!((y - x - w * t).abs() <= tol * scale, "{what}: x{}", i + 1);
            }
            for (i, (x, y)) in nums(&a["v"]).iter().zip(nums(&b["v"])).enumerate() {
                assert!(
                    (y - x - w).abs() <= tol * (1.0 + w.abs()),
                    "{what}: v{}",
                    i + 1
                );
            }
            if cmd == "contact" {
                let (da, db) = (
                    num(&a["energy"]["dissipated"]),
                    num(&b["energy"]["dissipated"]),
                );
                assert!(
                    (da - db).abs() <= tol * num(&a["energy"]["start"]),
                    "{what}: dissipated {da} {db}"
                );
                for (ca, cb) in a["contacts"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .zip(b["contacts"].as_array().unwrap())
                {
                    assert_eq!(ca["between"], cb["between"], "{what}");
                    assert!(
                        (num(&ca["max_overlap"]) - num(&cb["max_overlap"])).abs() <= tol,
                        "{what}: {ca} {cb}"
                    );
                }
            } else {
                assert_eq!(a["collisions"], b["collisions"], "{what}");
            }
        }
    }
}

#[test]
fn json_numbers_are_read_back_exactly() {
    // The comparisons above read the program's shortest round-trip output: serde_json's default
    // reader is best effort (0.19079863211663906, a track's energy, read 1 ulp low), so the
    // crate reads with `float_roundtrip`, and so do `collide batch`'s JSON Lines rows.
    for text in [
        "0.19079863211663906",
        "3.755555555555556",
        "2.5546754906461537e-25",
        "1e-323",
    ] {
        let read: f64 = serde_json::from_str(text).unwrap();
        assert_eq!(read, text.parse::<f64>().unwrap(), "{text}");
    }
}
