//! Pi billiards (Galperin 2003): the count of collisions a block makes between a wall and a
//! heavier block, against theory.

use serde::Serialize;

use super::{Run, Track};

/// Pi billiards (Galperin 2003): a block of mass `m` between a wall and a block of mass `M`
/// moving toward it makes `ceil(pi / theta) - 1` collisions, `theta = atan(sqrt(m / M))`.
/// `pi / theta` is a whole number only for `m / M` in {3, 1, 1/3} (theta = pi/3, pi/4, pi/6), so
/// those are exact; otherwise `pi / theta` is far enough from a whole number for binary64
/// (its fractional part would have to be within 1e-16 of it relative).
pub fn pi_count(m: f64, big_m: f64) -> u64 {
    let r = m / big_m;
    let exact = [(3.0, 2), (1.0, 3), (1.0 / 3.0, 5)];
    if let Some((_, k)) = exact
        .iter()
        .find(|(q, _)| m == q * big_m || (*q < 1.0 && m * 3.0 == big_m))
    {
        return *k;
    }
    let theta = r.sqrt().atan();
    (std::f64::consts::PI / theta).ceil() as u64 - 1
}

/// Pi billiards' theoretical count, when a run is that experiment.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PiTheory {
    /// `ceil(pi / theta) - 1`.
    pub theory: u64,
    /// `atan(sqrt(m1 / m2))`.
    pub theta: f64,
    /// Whether the simulation made exactly that many collisions.
    pub agrees: bool,
}

/// `collide track`'s output: the run, and the pi-billiards theory when it applies.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrackReport {
    #[serde(flatten)]
    pub run: Run,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pi: Option<PiTheory>,
}

impl TrackReport {
    pub fn new(track: &Track, run: Run) -> TrackReport {
        let b = &track.bodies;
        // Pi billiards: block 1 at rest between a wall and block 2 moving toward it, elastic.
        let is_pi = b.len() == 2
            && track.left_wall.is_some()
            && track.right_wall.is_none()
            && track.gravity == 0.0
            && track.e == 1.0
            && track.e_wall == 1.0
            && b[0].v == 0.0
            && b[1].v < 0.0;
        let pi = is_pi.then(|| {
            let theory = pi_count(b[0].m, b[1].m);
            PiTheory {
                theory,
                theta: (b[0].m / b[1].m).sqrt().atan(),
                agrees: theory == run.collisions,
            }
        });
        TrackReport { run, pi }
    }
}
