//! Collisions per second of `collide track` (issue 7): pi billiards (two blocks and a wall, the
//! tight loop) and a many-body track (the general event queue). `cargo bench --bench track`.

use std::time::Instant;

use collide::line::inertia::Mass;
use collide::track::{Body, Limits, Track};

fn main() {
    let forever = Limits {
        until: None,
        max_collisions: u64::MAX,
    };
    for n in [6, 7, 8] {
        let t = Track::pi_billiards(
            Mass::from_f64(1.0).unwrap(),
            Mass::from_f64(100f64.powi(n)).unwrap(),
        );
        let s = Instant::now();
        let r = t.run(forever, None).expect("pi billiards runs");
        let secs = s.elapsed().as_secs_f64();
        println!(
            "pi billiards N = {n}: {:>10} collisions in {secs:6.3} s: {:5.1} ns a collision, {:6.1} M/s; energy drift {:.1e}",
            r.collisions,
            secs * 1e9 / r.collisions as f64,
            r.collisions as f64 / secs / 1e6,
            (r.energy.end - r.energy.start) / r.energy.start
        );
    }
    for bodies in [10usize, 1000, 100_000] {
        // Bodies of masses 1 and 2 alternating, unit spacing, random-ish velocities, between walls.
        let t = Track {
            bodies: (0..bodies)
                .map(|i| Body {
                    m: Mass::from_f64(1.0 + (i % 2) as f64).unwrap(),
                    x: i as f64 + 1.0,
                    v: ((i * 7919) % 13) as f64 - 6.0,
                    size: 0.0,
                })
                .collect(),
            left_wall: Some(0.0),
            right_wall: Some(bodies as f64 + 1.0),
            e: 1.0,
            e_wall: 1.0,
            gravity: 0.0,
        };
        let limit = 5_000_000;
        let s = Instant::now();
        let r = t
            .run(
                Limits {
                    until: None,
                    max_collisions: limit,
                },
                None,
            )
            .expect("the track runs");
        let secs = s.elapsed().as_secs_f64();
        println!(
            "{bodies:>6} bodies between walls: {:>8} collisions in {secs:6.3} s: {:5.1} ns a collision; energy drift {:.1e}",
            r.collisions,
            secs * 1e9 / r.collisions as f64,
            (r.energy.end - r.energy.start) / r.energy.start
        );
    }
}
