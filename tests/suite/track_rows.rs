//! Shared by the track tests: an inelastic collapse between walls worked in exact rationals (the
//! reference of `track::an_inelastic_collapse_between_walls_ends`), and bodies laid in a row.

use collide::line::inertia::Mass;
use collide::track::Body;

/// The collapse of three bodies between walls, e = 0.3, in exact rationals, to `collisions`.
pub(crate) fn collapse(collisions: usize) -> Collapse {
    use collide::values::rational::{Q, from_f64, int};
    let e = from_f64(0.3);
    let (zero, four) = (int(0), int(4));
    let mut x = vec![int(1), int(2), int(3)];
    let mut v = [int(1), int(0), int(-1)];
    let mut t = int(0);
    let mut out = Collapse {
        times: Vec::new(),
        who: Vec::new(),
        x: Vec::new(),
    };
    while out.times.len() < collisions {
        // Resolve what touches and approaches now, leftmost first: left wall (slot 0), pair i
        // (slot i + 1), right wall (slot 3).
        loop {
            let hit = if x[0] == zero && v[0] < zero {
                Some(0)
            } else if let Some(i) = (0..2).find(|&i| x[i] == x[i + 1] && v[i] > v[i + 1]) {
                Some(i + 1)
            } else if x[2] == four && v[2] > zero {
                Some(3)
            } else {
                None
            };
            let Some(slot) = hit else { break };
            match slot {
                0 => v[0] = -&e * &v[0],
                3 => v[2] = -&e * &v[2],
                s => {
                    let i = s - 1;
                    // Equal masses: v1' = v1 + (1 + e)/2 (v2 - v1), v2' = v2 - (1 + e)/2 (v2 - v1).
                    let k = (int(1) + &e) / int(2);
                    let d = &v[i + 1] - &v[i];
                    let (a, b) = (&v[i] + &k * &d, &v[i + 1] - &k * &d);
                    (v[i], v[i + 1]) = (a, b);
                }
            }
            out.times.push(t.clone());
            out.who
                .push(["left wall & 1", "1 & 2", "2 & 3", "3 & right wall"][slot]);
            if out.times.len() == collisions {
                break;
            }
        }
        if out.times.len() == collisions {
            break;
        }
        // The next contact: the first gap to close, at gap / closing speed.
        let mut waits: Vec<Q> = Vec::new();
        if v[0] < zero {
            waits.push(&x[0] / -&v[0]);
        }
        for i in 0..2 {
            if v[i] > v[i + 1] {
                waits.push((&x[i + 1] - &x[i]) / (&v[i] - &v[i + 1]));
            }
        }
        if v[2] > zero {
            waits.push((&four - &x[2]) / &v[2]);
        }
        let wait = waits.into_iter().min().expect("a collapse never stops");
        for i in 0..3 {
            x[i] = &x[i] + &v[i] * &wait;
        }
        t = &t + &wait;
    }
    out.x = x;
    out
}

/// Bodies `(mass, gap before, velocity, size)` laid left to right from `x`, and where the last
/// one ends.
pub(crate) fn in_a_row(bodies: &[(f64, f64, f64, f64)], mut x: f64) -> (Vec<Body>, f64) {
    let row = bodies
        .iter()
        .map(|&(m, gap, v, size)| {
            x += gap + size / 2.0;
            let b = Body {
                m: Mass::from_f64(m).unwrap(),
                x,
                v,
                size,
            };
            x += size / 2.0;
            b
        })
        .collect();
    (row, x)
}

/// An exact event-driven run of the collapse: three unit point masses at 1, 2, 3 moving at 1,
/// 0, -1 between walls at 0 and 4, restitution the binary64 0.3 for pairs and walls. At each
/// instant the leftmost contact that is touching and approaching is resolved first, with the
/// velocities the previous one left (the documented rule). Records every collision's time and
/// contact, and the positions at the last collision.
pub(crate) struct Collapse {
    pub(crate) times: Vec<collide::values::rational::Q>,
    pub(crate) who: Vec<&'static str>,
    pub(crate) x: Vec<collide::values::rational::Q>,
}
