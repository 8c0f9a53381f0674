//! The floor's mu solved from the slides after a collision on the rail (`slide 20 cm mu ?` in
//! `--fin` or a scene's `fin`): `mu = f^2 / (2 g d)` from the solved final velocity
//! (`line::slide`), as printed (`Solved: mu = ...`) and as JSON (`solved.mu`). One computation
//! for `collide solve` and `collide scene`.

use serde_json::Value;

use crate::line::case::Case;
use crate::line::slide::{self, Slide, SlideError};
use crate::solver::exact::ExactCollision;
use crate::values::heights::HeightScale;
use crate::values::quantity::fraction;
use crate::values::rational::{Q, from_f64, to_f64};

/// The floor's mu, solved.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorFriction {
    pub value: Q,
    /// As printed: a fraction under --exact, else binary64's shortest digits.
    pub shown: String,
    /// `Solved: mu = ...` and how, a paragraph.
    pub line: String,
    pub json: Value,
}

/// Why the floor's mu is not given.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FloorError {
    #[error(transparent)]
    Slide(#[from] SlideError),
    #[error("mu = f^2 / (2 g d) is beyond binary64; --exact gives it")]
    Beyond,
}

/// `mu = f^2 / (2 g d)` from the solved final velocities of `case`, exact when the case is
/// (`None`: no slide given).
pub fn floor_friction(
    case: &Case,
    given: &[Slide],
    h: &HeightScale,
    exact: bool,
) -> Result<Option<FloorFriction>, FloorError> {
    if given.is_empty() {
        return Ok(None);
    }
    let exact_case = exact || (case.solved() && case.check_exact().is_ok());
    let fin = if exact_case {
        ExactCollision::from_case(case).v_fin_q()
    } else {
        let f = case.collision.v_fin();
        [f.x, f.y].map(from_f64)
    };
    let Some(value) = slide::friction(given, &fin, &h.g, &h.velocity_si, exact_case)? else {
        return Ok(None);
    };
    let (shown, json) = match to_f64(&value) {
        _ if exact => (fraction(&value), Value::String(fraction(&value))),
        Some(x) => (crate::values::number::num(x), serde_json::json!(x)),
        None => return Err(FloorError::Beyond),
    };
    let body = given[0].body + 1;
    let line = super::text::paragraph(&format!(
        "Solved: mu = {shown} (the floor's: mu = f{body}^2 / (2 g d), g = {} m/s^2)",
        h.g_text()
    ));
    Ok(Some(FloorFriction {
        value,
        shown,
        line,
        json,
    }))
}
