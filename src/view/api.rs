//! The page's one question to the physics: a request as JSON text, an answer as JSON text. The
//! WebAssembly module (`wasm/`) exports exactly this; natively it is an ordinary function, which
//! the tests call to compare the page's answers with the command line's.
//!
//! Requests are tagged by `op`: `{"op": "solve", "m1": "4", "m2": "1", "v1": "60", "v2": "10",
//! "e": "2/3", "frame": "com", "reverse": false}` (a `two_body::CaseInput`), `{"op": "plane",
//! "m1": "1", "m2": "1", "v1": "(1,0)", "v2": "(0,0)", "normal": "30deg", ...}` (a
//! `plane::PlaneInput`), or `{"op": "track", "masses": "1,0.01", ...}` (a `stack::TrackInput`) or `{"op": "rigid", "m1":
//! "1", "m2": "4", "v1": "3", "target": "rod 2", "hit_at": "end", ...}` (a `rigid::RigidInput`)
//! or `{"op": "nbody", "mode": "contacts", "masses": ["1", "1", "1"], ...}` (an
//! `input::NBodyInput`). Answers are `{"ok": true, ...}`
//! with the result's fields, or `{"ok": false, "field": "m1", "error": "..."}`.

use serde::{Deserialize, Serialize};

use super::InputError;
use super::input::{CaseInput, NBodyInput, PlaneInput, RigidInput, TrackInput};

/// What the page asks.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(tag = "op", rename_all = "kebab-case")]
pub enum Request {
    /// One collision: the velocity plane and the dual panel.
    Solve(CaseInput),
    /// Two pucks in the plane: the plane panel.
    Plane(PlaneInput),
    /// Bodies on a track, under gravity: the superball stack.
    Track(TrackInput),
    /// A ball hits a rod, a door or a floor: the rigid panel.
    Rigid(RigidInput),
    /// Two to five pucks in the plane: stuck, exploding or touching (the N-ball panel).
    Nbody(NBodyInput),
}

/// The answer to `request` (JSON text), as JSON text.
pub fn call(request: &str) -> String {
    let answer = match serde_json::from_str::<Request>(request) {
        Ok(r) => answer(&r),
        Err(e) => failure(&InputError::new("request", format!("bad request: {e}"))),
    };
    serde_json::to_string(&answer).expect("answers serialize")
}

/// The answer to a request, as a JSON value.
pub fn answer(request: &Request) -> serde_json::Value {
    let result = match request {
        Request::Solve(c) => c.solve().map(serde_json::to_value),
        Request::Plane(p) => p.solve().map(serde_json::to_value),
        Request::Track(t) => t.run().map(serde_json::to_value),
        Request::Rigid(r) => r.solve().map(serde_json::to_value),
        Request::Nbody(n) => n.solve().map(serde_json::to_value),
    };
    match result {
        Ok(Ok(mut v)) => {
            if let Some(o) = v.as_object_mut() {
                o.insert("ok".into(), true.into());
            }
            v
        }
        Ok(Err(e)) => failure(&InputError::new("request", e)),
        Err(e) => failure(&e),
    }
}

fn failure(e: &InputError) -> serde_json::Value {
    serde_json::json!({"ok": false, "field": e.field, "error": e.error})
}
