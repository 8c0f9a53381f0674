//! mu as the unknown of a slide after a collision on the rail (issue 42 section 5): `--fin
//! '?,slide 20 cm mu ?'`, or a bare `slide 20 cm` with the floor's `--friction ?` (and `--show
//! slides`). The slide's final velocity is left to the collision (it is read as `?`), and the
//! floor's kinetic friction follows from the work-energy theorem, `mu g d = f^2 / 2`:
//! `mu = f^2 / (2 g d)`, exact when `f` is (Serway & Jewett: a block that leaves at 3 m/s and
//! slides 1 m with g = 10 has mu = 9/20). All the slides are on one floor: one mu, which every
//! slide given must agree with.

use crate::values::heights::unknown_slide;
use crate::values::measure::QuantityError;
use crate::values::number::split_fields;
use crate::values::quantity::significant;
use crate::values::rational::{Q, from_f64, int};

/// A body's slide after the collision with the floor's mu unknown.
#[derive(Clone, Debug, PartialEq)]
pub struct Slide {
    /// The body, 0 or 1.
    pub body: usize,
    /// The distance in metres, signed as the body moves (`-slide 2 m mu ?` slides towards -x).
    pub metres: Q,
    /// Typed without `mu ?` (`slide 20 cm`): mu is the floor's `--friction ?`.
    pub bare: bool,
    /// As typed.
    pub typed: String,
}

/// Why mu does not follow from the slides.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SlideError {
    #[error(
        "'{typed}': body {body} stops at the collision (f{body} = 0), so no slide follows for any \
         mu"
    )]
    Stops { typed: String, body: usize },
    #[error(
        "'{typed}': body {body} leaves the collision at f{body} = {f} m/s, the other way: a \
         slide towards {towards} is '{sign}slide D mu ?'"
    )]
    Direction {
        typed: String,
        body: usize,
        f: String,
        towards: &'static str,
        sign: &'static str,
    },
    #[error(
        "the slides give two values of the one floor's mu: {first} from '{a}' and {second} from \
         '{b}' (mu = f^2 / (2 g d)); the data contradict each other"
    )]
    Disagree {
        a: String,
        first: String,
        b: String,
        second: String,
    },
}

/// The final velocities `F1,F2` as typed, with each slide whose mu is unknown read as `?` (the
/// collision solves that velocity); any other text is returned as it is.
pub fn masked(text: &str) -> String {
    let Ok(fields) = split_fields::<2>(text, "final velocities") else {
        return text.to_string();
    };
    if !fields.iter().any(|f| unknown_slide(f).is_some()) {
        return text.to_string();
    }
    fields
        .iter()
        .map(|f| if unknown_slide(f).is_some() { "?" } else { f })
        .collect::<Vec<_>>()
        .join(",")
}

/// The slides with mu unknown in the final velocities `F1,F2` as typed.
pub fn slides(text: &str) -> Result<Vec<Slide>, QuantityError> {
    let Ok(fields) = split_fields::<2>(text, "final velocities") else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for (body, field) in fields.iter().enumerate() {
        if let Some(slide) = unknown_slide(field) {
            let (metres, bare) = slide?;
            out.push(Slide {
                body,
                metres,
                bare,
                typed: field.to_string(),
            });
        }
    }
    Ok(out)
}

/// The floor's mu from the final velocities `fin` (in the case's velocity unit, `velocity_si`
/// m/s each): `mu = f^2 / (2 g d)` for each slide, all equal (exactly when `exact`, else to 1e-12
/// relative: the velocities were rounded to binary64 once).
pub fn friction(
    slides: &[Slide],
    fin: &[Q; 2],
    g: &Q,
    velocity_si: &Q,
    exact: bool,
) -> Result<Option<Q>, SlideError> {
    let mut found: Option<(Q, &Slide)> = None;
    for s in slides {
        let f = &fin[s.body] * velocity_si;
        let body = s.body + 1;
        if f == Q::ZERO {
            return Err(SlideError::Stops {
                typed: s.typed.clone(),
                body,
            });
        }
        if (f < Q::ZERO) != (s.metres < Q::ZERO) {
            let negative = s.metres < Q::ZERO;
            return Err(SlideError::Direction {
                typed: s.typed.clone(),
                body,
                f: significant(&f, 15),
                towards: if negative { "+x" } else { "-x" },
                sign: if negative { "" } else { "-" },
            });
        }
        let d = if s.metres < Q::ZERO {
            -s.metres.clone()
        } else {
            s.metres.clone()
        };
        let mu = &f * &f / (int(2) * g * d);
        if let Some((first, a)) = &found {
            let diff = num_traits::Signed::abs(&(first - &mu));
            let agree = if exact {
                diff == Q::ZERO
            } else {
                diff <= first * from_f64(1e-12)
            };
            if !agree {
                return Err(SlideError::Disagree {
                    a: a.typed.clone(),
                    first: significant(first, 15),
                    b: s.typed.clone(),
                    second: significant(&mu, 15),
                });
            }
        } else {
            found = Some((mu, s));
        }
    }
    Ok(found.map(|(mu, _)| mu))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(t: &str) -> Q {
        t.parse::<crate::values::number::Number>().unwrap().exact()
    }

    #[test]
    fn slides_with_mu_unknown_are_read_as_unknown_velocities() {
        assert_eq!(masked("?,slide 20 cm mu ?"), "?,?");
        assert_eq!(masked("-slide 1 m mu ?, 3"), "?,3");
        assert_eq!(masked("2,slide 5 cm mu 0.62"), "2,slide 5 cm mu 0.62");
        assert_eq!(masked("slide 7.5 m,0"), "?,0");
        let s = slides("-slide 2 ft mu ?,slide 20 cm").unwrap();
        assert_eq!(s[0].metres, q("-0.6096"));
        assert!(!s[0].bare);
        assert_eq!(
            (s[1].body, s[1].metres.clone(), s[1].bare),
            (1, q("0.2"), true)
        );
        assert!(slides("slide 0 m mu ?,0").is_err());
    }

    #[test]
    fn mu_is_f_squared_over_2_g_d() {
        // f = 3 m/s, d = 1 m, g = 10: mu = 9 / 20 exactly.
        let s = slides("0,slide 1 m mu ?").unwrap();
        let fin = [Q::ZERO, int(3)];
        let mu = friction(&s, &fin, &int(10), &int(1), true).unwrap();
        assert_eq!(mu, Some(q("9/20")));
        // The same in km/h (3 m/s = 10.8 km/h): the speed is taken in m/s.
        let fin = [Q::ZERO, q("10.8")];
        let mu = friction(&s, &fin, &int(10), &q("5/18"), true).unwrap();
        assert_eq!(mu, Some(q("9/20")));
        // Leaving the other way, or at rest, is refused by name.
        let back = [Q::ZERO, int(-3)];
        let e = friction(&s, &back, &int(10), &int(1), true).unwrap_err();
        assert!(e.to_string().contains("'-slide D mu ?'"), "{e}");
        let rest = [Q::ZERO, Q::ZERO];
        assert!(matches!(
            friction(&s, &rest, &int(10), &int(1), true),
            Err(SlideError::Stops { body: 2, .. })
        ));
        // Two slides on one floor: 2^2 / (2 g 1) and 4^2 / (2 g 4) agree; 4 m and 1 m do not.
        let two = slides("slide 1 m,slide 4 m").unwrap();
        let fin = [int(2), int(4)];
        assert_eq!(
            friction(&two, &fin, &int(10), &int(1), true).unwrap(),
            Some(q("1/5"))
        );
        let fin = [int(2), int(2)];
        assert!(matches!(
            friction(&two, &fin, &int(10), &int(1), true),
            Err(SlideError::Disagree { .. })
        ));
    }
}
