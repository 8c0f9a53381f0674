//! mu as the unknown (`--friction ?`): with Coulomb friction the impact is piecewise (Routh's
//! phases), so mu is found where the contact slides throughout (`P_t = mu P_n`, rational in
//! mu), and a given state the contact reaches only by sticking is reached by every mu from the
//! one at which the slip just stops (`mu >= X`).

use num_traits::Signed;

use crate::values::rational::{Q, from_f64, pow2, to_f64};

use super::{
    Given, Known, Range, Unknown, UnknownError, Value, holds, line_roots, outcome, pick, roots_of,
};
use crate::rigid::algebra::dot;
use crate::rigid::fin;
use crate::rigid::homework::Homework;
use crate::rigid::interpolate;
use crate::rigid::laws::Mode;
use crate::rigid::outcome::Outcome;

/// mu: where the contact slides throughout, the given value is rational in mu; a given value
/// only sticking reaches holds for every mu from the one at which the slip just stops.
pub(super) fn friction_of(
    hw: &Homework,
    given: &Given,
    si: bool,
) -> Result<(Value, Outcome), UnknownError> {
    let range: Range = (Some(Q::ZERO), None);
    let mut slides: Vec<(Q, Vec<Q>, Q)> = Vec::new();
    for k in 1..=60 {
        let mu = pow2(-k);
        if let Ok(o) = outcome(hw, Unknown::Friction, &mu, si)
            && o.impact.mode == Mode::Slip
        {
            let slip = final_slip(&o);
            slides.push((mu, given.residual(&o)?, slip));
        }
        if slides.len() == interpolate::SAMPLES {
            break;
        }
    }
    if slides.len() == interpolate::SAMPLES {
        let samples: Vec<(Q, Vec<Q>)> = slides
            .iter()
            .map(|(m, r, _)| (m.clone(), r.clone()))
            .collect();
        let found = roots_of(&samples, Unknown::Friction, &range).unwrap_or_default();
        // mu = 0 is the smooth contact.
        let sliding = |o: &Outcome| matches!(o.impact.mode, Mode::Slip | Mode::Smooth);
        if let Ok(v) = pick(hw, Unknown::Friction, given, si, &range, found, sliding) {
            return Ok(v);
        }
    }
    // Sticking: the given value is the one every large mu gives.
    let big = pow2(30);
    let stuck = outcome(hw, Unknown::Friction, &big, si)
        .map_err(|e| UnknownError::Impossible("mu".into(), e))?;
    let approx = !hw.exact || given.approx || stuck.approx();
    if !holds(&given.residual(&stuck)?, &given.scale(&stuck), approx) {
        return Err(UnknownError::None(format!(
            "no mu gives {}: sliding throughout gives other values, and sticking gives {}",
            given.text(),
            match &given.known {
                Known::Fin(f) => fin::gives(f, &stuck),
                _ => crate::values::quantity::significant(
                    &(&given.residual(&stuck)?[0] + &given.value),
                    15,
                ),
            }
        )));
    }
    if slides.len() < interpolate::SAMPLES {
        return Err(UnknownError::Many(
            "the contact does not slide, so friction plays no part: mu is not determined".into(),
        ));
    }
    // The least mu that sticks: where the slip after, rational in mu while it slides, is 0.
    let points: Vec<(Q, Q)> = slides
        .iter()
        .map(|(m, _, s)| (m.clone(), s.clone()))
        .collect();
    let least = interpolate::fit(&points)
        .and_then(|(n, _)| line_roots(&n, &range))
        .unwrap_or_default()
        .into_iter()
        .find(|r| r.x.is_positive());
    let Some(root) = least else {
        return Err(UnknownError::Many(
            "the given value needs the contact to stick, which every large enough mu gives: \
             mu is not determined (a bound was not found)"
                .into(),
        ));
    };
    if hw.exact && !root.exact {
        return Err(UnknownError::Irrational(
            "mu".into(),
            crate::values::quantity::significant(&root.x, 15),
        ));
    }
    let x = if hw.exact {
        root.x.clone()
    } else {
        to_f64(&root.x).map_or(root.x.clone(), from_f64)
    };
    let o = outcome(hw, Unknown::Friction, &x, si)
        .map_err(|e| UnknownError::Impossible("mu".into(), e))?;
    let approx = approx || !root.exact;
    if !holds(&given.residual(&o)?, &given.scale(&o), approx) {
        return Err(UnknownError::Many(
            "the given value needs the contact to stick, which every large enough mu gives: \
             mu is not determined (the least such mu was not found)"
                .into(),
        ));
    }
    Ok((
        Value {
            unknown: Unknown::Friction,
            value: x,
            approx: !root.exact || o.approx(),
            at_least: true,
        },
        o,
    ))
}

/// The slip after the impact: the tangential relative velocity of the contact points.
fn final_slip(o: &Outcome) -> Q {
    let pair = &o.problem.pair;
    dot(&pair.tangent(), &pair.relative_velocity(&o.fin))
}
