//! What a collision changes, in the shape homework problems ask for (issue 15): each body's change
//! of velocity `dv = f - v`, its impulse `dp = M.dv` (Newton's third law: the two are opposite for
//! a pair of point bodies), each body's kinetic energy before and after, `1/2 (m v) v`, and its
//! change `dke = 1/2 m dv (f + v)` (a product, never a difference of two energies); the fraction
//! of the kinetic energy lost, `lost / KE_IN`; the fraction transferred when one body was at rest,
//! `KE_FIN(hit) / KE_IN(hitter)`; and, over a contact time `T`, the average force `dp / T`.
//!
//! Every value is computed in exact rationals from the velocities it describes and rounded once
//! when printed in binary64: these are a few products per body, and exactness costs microseconds.

use crate::values::rational::{Q, half};
use num_traits::Signed;

/// The changes of a two-body event, exact. Per-body energies only for a diagonal tensor (bodies
/// on a rail): with a general tensor the kinetic energy has a cross term and belongs to no body.
#[derive(Clone, Debug, PartialEq)]
pub struct Changes {
    pub dv: [Q; 2],
    pub impulse: [Q; 2],
    pub ke_in: Option<[Q; 2]>,
    pub ke_fin: Option<[Q; 2]>,
    pub dke: Option<[Q; 2]>,
    /// `(KE_IN - KE_FIN) / KE_IN`, when energy is not gained and `KE_IN > 0`.
    pub lost_fraction: Option<Q>,
    /// `KE_FIN` of the body that was at rest over `KE_IN` of the other, when exactly one was.
    pub transferred_fraction: Option<Q>,
    /// `dp / T` for a contact time `T` in seconds.
    pub average_force: Option<[Q; 2]>,
}

/// The event: tensor `[[a, c], [c, b]]`, IN and FIN velocities.
pub struct Event<'a> {
    pub tensor: [[&'a Q; 2]; 2],
    pub v_in: &'a [Q; 2],
    pub fin: &'a [Q; 2],
}

impl Changes {
    /// The changes of `event`; `contact_time` in seconds (> 0), so the average force is in the
    /// case's impulse unit per second (newtons for kg and m/s).
    pub fn of(event: &Event, contact_time: Option<&Q>) -> Changes {
        let [[a, c], [_, b]] = event.tensor;
        let (v, f) = (event.v_in, event.fin);
        let dv = [&f[0] - &v[0], &f[1] - &v[1]];
        let impulse = [a * &dv[0] + c * &dv[1], c * &dv[0] + b * &dv[1]];
        let diagonal = c.is_zero();
        let m = [a, b];
        let ke = |x: &[Q; 2]| std::array::from_fn(|i| half() * (m[i] * &x[i]) * &x[i]);
        let (ke_in, ke_fin): ([Q; 2], [Q; 2]) = (ke(v), ke(f));
        let dke: [Q; 2] = std::array::from_fn(|i| half() * (m[i] * &dv[i]) * (&f[i] + &v[i]));
        let form = |x: &[Q; 2]| {
            half() * (&x[0] * (a * &x[0] + c * &x[1]) + &x[1] * (c * &x[0] + b * &x[1]))
        };
        let (total_in, total_fin) = (form(v), form(f));
        let lost_fraction = (total_in.is_positive() && total_fin <= total_in)
            .then(|| (&total_in - &total_fin) / &total_in);
        let transferred_fraction = if !diagonal {
            None
        } else if v[0].is_zero() && !v[1].is_zero() {
            Some(&ke_fin[0] / &ke_in[1])
        } else if v[1].is_zero() && !v[0].is_zero() {
            Some(&ke_fin[1] / &ke_in[0])
        } else {
            None
        };
        let average_force = contact_time.map(|t| [&impulse[0] / t, &impulse[1] / t]);
        Changes {
            dv,
            impulse,
            ke_in: diagonal.then_some(ke_in),
            ke_fin: diagonal.then_some(ke_fin),
            dke: diagonal.then_some(dke),
            lost_fraction,
            transferred_fraction,
            average_force,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Q {
        s.parse::<crate::values::number::Number>().unwrap().exact()
    }

    #[test]
    fn fig_1_3_elastic_by_hand() {
        // m = (4, 1), V = (60, 10), FIN = (40, 90): dv = (-20, 80), dp = (-80, 80);
        // KE: 7200 + 50 -> 3200 + 4050, no loss; T = 1/100 s gives F = (-8000, 8000).
        let (a, b, z) = (q("4"), q("1"), q("0"));
        let (v, f) = ([q("60"), q("10")], [q("40"), q("90")]);
        let e = Event {
            tensor: [[&a, &z], [&z, &b]],
            v_in: &v,
            fin: &f,
        };
        let c = Changes::of(&e, Some(&q("0.01")));
        assert_eq!(c.dv, [q("-20"), q("80")]);
        assert_eq!(c.impulse, [q("-80"), q("80")]);
        assert_eq!(c.ke_in, Some([q("7200"), q("50")]));
        assert_eq!(c.ke_fin, Some([q("3200"), q("4050")]));
        assert_eq!(c.dke, Some([q("-4000"), q("4000")]));
        assert_eq!(c.lost_fraction, Some(q("0")));
        assert_eq!(c.transferred_fraction, None);
        assert_eq!(c.average_force, Some([q("-8000"), q("8000")]));
    }

    #[test]
    fn transferred_when_one_body_was_at_rest_and_nothing_per_body_for_a_tensor() {
        // Equal masses, elastic, 2 at rest: all of the energy goes across.
        let (one, z) = (q("1"), q("0"));
        let (v, f) = ([q("3"), q("0")], [q("0"), q("3")]);
        let e = Event {
            tensor: [[&one, &z], [&z, &one]],
            v_in: &v,
            fin: &f,
        };
        assert_eq!(Changes::of(&e, None).transferred_fraction, Some(q("1")));
        let c = q("1/2");
        let e = Event {
            tensor: [[&one, &c], [&c, &one]],
            v_in: &v,
            fin: &f,
        };
        let ch = Changes::of(&e, None);
        assert_eq!((ch.ke_in, ch.transferred_fraction), (None, None));
        // M.dv with the cross term: (1 * -3 + 1/2 * 3, 1/2 * -3 + 1 * 3).
        assert_eq!(ch.impulse, [q("-3/2"), q("3/2")]);
    }
}
