//! `collide view`: one HTML page with the lecture's simulators, whose numbers come from this
//! library compiled to WebAssembly (the crate `wasm/`); the page's JavaScript only draws and
//! handles input.
//!
//! - `api`: what the page asks and what it is answered, as JSON text in and out (the one entry
//!   point of the WebAssembly module, and callable natively, which the tests do);
//! - `input`: the page's inputs as typed (a case, two pucks, a track), which the panels below
//!   solve and `shell` writes back as a command line and a scene;
//! - `two_body`: a collision for the velocity plane and the dual panel: the same report JSON as
//!   `collide solve --format json`, and the geometry to draw;
//! - `plane`: two pucks in the plane (issue 25's solver) for the third panel: the same JSON as
//!   `collide solve --format json` with vectors and a line of impact, and the pucks, arrows,
//!   momentum triangles and the velocity plane of the normal parts to draw;
//! - `nbody`: two to five pucks in the plane (N-body stick and explode, and touching balls with
//!   Newton's law at every contact at once) for the N-ball panel: the same JSON as `collide
//!   solve --format json`, and each puck's velocities and momenta before and after;
//! - `rigid`: a ball hits a rod, a door or a floor (`rigid`) for the rigid panel: the same JSON
//!   as `collide solve --format json` with the homework flags, and the bodies, arrows and spins
//!   at the instant of impact with the velocity plane of the contact points along the normal;
//! - `stack`: a track under gravity (the superball stack) for the animation: the run, its
//!   motion sampled in time, the velocity amplification;
//! - `shell`: the `collide` command line and the scene TOML of what is on screen;
//! - `page` (feature `cli`): the self-contained page, with the module embedded.

pub mod api;
pub mod input;
pub mod nbody;
#[cfg(feature = "cli")]
pub mod page;
pub mod plane;
pub mod rigid;
pub mod shell;
pub mod stack;
pub mod two_body;

use serde::Serialize;

/// A bad input, with the page's field it is in (`m1`, `v2`, `e`, `masses`, `gravity`, ...) and
/// the message the command line would give.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InputError {
    pub field: &'static str,
    pub error: String,
}

impl InputError {
    pub fn new(field: &'static str, error: impl std::fmt::Display) -> InputError {
        InputError {
            field,
            error: error.to_string(),
        }
    }
}

/// `message` with each command-line flag of `words` replaced by the page's words for it.
fn in_words(message: &str, words: &[(&str, &str)]) -> String {
    words
        .iter()
        .fold(message.to_string(), |m, (flag, w)| m.replace(flag, w))
}
