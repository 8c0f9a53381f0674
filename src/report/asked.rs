//! What a homework problem asks beyond the lecture's sections (issue 27 §1), each shown when
//! its flag is given: a spring between the bodies (`--spring K`: `spring`), a pendulum's swing
//! (`--length L`: `pendulum`), the slides on a rough floor after it (`--show slides --friction
//! MU`: `slides`). Values are in SI (metres, seconds, degrees), computed exactly
//! from the event in the lab and rounded once; irrational ones (roots, pi, angles) are taken to
//! 30 digits first, and marked approximate in exact mode.

use serde::{Deserialize, Serialize};

use super::text::Block;
use crate::line::pendulum::{Swing, swing};
use crate::values::quantity::{Scalar, significant};
use crate::values::rational::{Q, int};

/// What was asked, in SI, with the case's units in SI (1 when a case has none: masses are then
/// taken as kg and velocities as m/s).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Asked {
    /// A spring between the bodies: `k` in N/m, and as typed (`--spring`).
    pub spring: Option<(Q, String)>,
    /// The string a body at rest hangs on: `L` in metres, and as typed (`--length`).
    pub length: Option<(Q, String)>,
    /// The floor's coefficient of kinetic friction, for the slides after the event (`--show
    /// slides --friction MU`), and as typed.
    pub friction: Option<(Q, String)>,
    /// `g` in m/s^2.
    pub g: Q,
    /// The case's mass unit in kg.
    pub mass_si: Q,
    /// The case's velocity unit in m/s.
    pub velocity_si: Q,
    /// Whether the case had no units (so they were taken as kg and m/s).
    pub assumed: bool,
}

impl Default for Asked {
    fn default() -> Asked {
        Asked {
            spring: None,
            length: None,
            friction: None,
            g: crate::values::units::STANDARD_GRAVITY
                .parse::<crate::values::number::Number>()
                .map(|n| n.exact())
                .unwrap_or_default(),
            mass_si: int(1),
            velocity_si: int(1),
            assumed: true,
        }
    }
}

impl Asked {
    /// Nothing asked.
    pub fn is_empty(&self) -> bool {
        self.spring.is_none() && self.length.is_none() && self.friction.is_none()
    }

    /// For a case in `units`.
    pub fn in_units(units: &crate::values::units::Units) -> Asked {
        use crate::values::units::{Dimension, lookup};
        let si = |name: Option<&str>, d| name.and_then(|n| lookup(n, d).ok()).map(|u| u.si());
        let m = si(units.mass, Dimension::Mass);
        let v = si(units.velocity, Dimension::Velocity);
        Asked {
            assumed: m.is_none() || v.is_none(),
            mass_si: m.unwrap_or_else(|| int(1)),
            velocity_si: v.unwrap_or_else(|| int(1)),
            ..Asked::default()
        }
    }

    /// The note on units for a block's title.
    fn units_note(&self) -> &'static str {
        if self.assumed {
            "; masses taken as kg, velocities as m/s"
        } else {
            ""
        }
    }
}

/// The sections asked for. Field names are the JSON schema (top-level keys of `solve`).
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct AskedReport<N> {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spring: Option<SpringReport<N>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pendulum: Option<PendulumReport<N>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slides: Option<SlidesReport<N>>,
    /// What was asked, for the text (not part of the JSON schema).
    #[serde(skip)]
    pub asked: Option<Asked>,
}

/// `spring`: the spring constant, the compression at closest approach and the time of contact.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringReport<N> {
    /// `k` in N/m.
    pub k: N,
    /// `x_max = sqrt(2 crunch / k)` in metres.
    pub compression: N,
    /// `t = pi sqrt(mu / k)` in seconds.
    pub contact_time: N,
}

/// `pendulum`: the string, `g`, and the swing of each body that hung at rest when hit.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct PendulumReport<N> {
    /// `L` in metres.
    pub length: N,
    /// `g` in m/s^2.
    pub g: N,
    pub swings: Vec<SwingReport<N>>,
}

/// One bob's swing.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SwingReport<N> {
    /// 1 or 2.
    pub body: u8,
    /// `h = f^2 / 2g` in metres.
    pub height: N,
    /// `theta = acos(1 - h / L)`, from the vertical; none above `h = 2L`, where a rod would
    /// go over the top (the string goes slack: `peak`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_deg: Option<N>,
    /// `x = L sin(theta) = sqrt(h (2L - h))` in metres; none above `h = 2L`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub horizontal: Option<N>,
    /// `h > L`: a string goes slack before the bob gets there (a rod would).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub slack: bool,
    /// With `slack`, the highest point the bob reaches on a string, in metres: the string goes
    /// slack at `cos(theta) = 2 (L - h) / 3L` and the bob flies free (`line::pendulum::peak`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peak: Option<N>,
}

/// `slides`: how far each body slides after the event, `f^2 / (2 mu g)`, in metres.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SlidesReport<N> {
    pub mu: N,
    /// `g` in m/s^2.
    pub g: N,
    pub fin: [N; 2],
}

/// Why what was asked has no answer.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum AskedError {
    #[error(
        "--length {length}: body {body} would rise {height} m (f^2 / 2g), at least 5L/2 = \
         {five_halves_l} m: the string stays taut over the top (the speed left there, \
         u^2 = 2 g (h - 2L) >= g L, holds the bob on its circle), so it goes over the top and \
         loops, with no angle or highest point (a longer string, or a body that is not on one)"
    )]
    OverTheTop {
        length: String,
        body: usize,
        height: String,
        five_halves_l: String,
    },
    #[error(
        "--spring {spring}: the bodies move together (V1 = V2 = {v}), so they never touch and \
         the spring is never compressed: there is no compression or time of contact (give \
         velocities that differ, or drop --spring)"
    )]
    SpringNoContact { spring: String, v: String },
    #[error(
        "--spring {spring}: a spring between the bodies is ideal, it gives back all it stores \
         (e = 1), but here e = {e}: the bodies {what}, so its compression and time of contact \
         would describe another collision (drop -e, or give final velocities with e = 1, or \
         drop --spring)"
    )]
    SpringNotElastic {
        spring: String,
        e: String,
        what: &'static str,
    },
    #[error(transparent)]
    Unrepresentable(#[from] super::Unrepresentable),
}

/// The event the asked sections describe, exact, in the case's units, seen from the lab.
pub struct Motion {
    pub v_in: [Q; 2],
    pub fin: [Q; 2],
    /// `1/2 mu (v1 - v2)^2`.
    pub crunch: Q,
    /// `mu = det M / M_total`.
    pub mu: Q,
    /// The restitution of a collision (`None`: a separation or pass-through).
    pub e: Option<Q>,
}

/// An exact value or an approximation to 30 digits (`line::spring::root`), never 0 or a
/// subnormal in binary64 for a value that is not 0 (`Scalar::unless_underflow`).
fn either<N: Scalar>(x: Result<Q, Q>) -> N {
    match x {
        Ok(q) => N::of_rational(&q).unless_underflow(&q),
        Err(q) => N::of_approx(&q).unless_underflow(&q),
    }
}

/// An exact value, never 0 or a subnormal in binary64 for a value that is not 0.
fn nonzero<N: Scalar>(q: &Q) -> N {
    N::of_rational(q).unless_underflow(q)
}

impl<N: Scalar> AskedReport<N> {
    /// The sections of `asked` for the event `m`.
    pub fn of(m: &Motion, asked: &Asked) -> Result<AskedReport<N>, AskedError> {
        let spring = match &asked.spring {
            Some((k, typed)) => Some(Self::spring(m, asked, k, typed)?),
            None => None,
        };
        let pendulum = match &asked.length {
            Some((l, typed)) => Some(Self::pendulum(m, asked, l, typed)?),
            None => None,
        };
        let slides = asked.friction.as_ref().map(|(mu, _)| {
            let d = |f: &Q| {
                let f = f * &asked.velocity_si;
                nonzero(&(&f * &f / (int(2) * mu * &asked.g)))
            };
            SlidesReport {
                mu: N::of_rational(mu),
                g: N::of_rational(&asked.g),
                fin: [d(&m.fin[0]), d(&m.fin[1])],
            }
        });
        let report = AskedReport {
            spring,
            pendulum,
            slides,
            asked: Some(asked.clone()),
        };
        // Every number a real result, as the report's own (`heights.in[0]`): a slide beyond
        // binary64 is refused by name, not printed as NaN.
        let value = serde_json::to_value(&report).expect("a report serializes");
        if let Some(quantity) = super::first_unrepresentable(&value) {
            return Err(super::Unrepresentable::new(quantity).into());
        }
        Ok(report)
    }

    /// The spring between colliding bodies: refused when they never touch, or when the
    /// collision is not elastic (an ideal spring gives back all it stores).
    fn spring(
        m: &Motion,
        asked: &Asked,
        k: &Q,
        typed: &str,
    ) -> Result<SpringReport<N>, AskedError> {
        use crate::line::spring::{compression, contact_time};
        if m.v_in[0] == m.v_in[1] {
            return Err(AskedError::SpringNoContact {
                spring: typed.to_string(),
                v: significant(&m.v_in[0], 15),
            });
        }
        if let Some(e) = m.e.as_ref().filter(|e| **e != Q::ONE) {
            return Err(AskedError::SpringNotElastic {
                spring: typed.to_string(),
                e: significant(e, 15),
                what: if e.is_zero() {
                    "stick and never separate"
                } else if e < &Q::ONE {
                    "separate with energy lost"
                } else {
                    "separate with energy released"
                },
            });
        }
        let v2 = &asked.velocity_si * &asked.velocity_si;
        Ok(SpringReport {
            k: N::of_rational(k),
            compression: either(compression(&(&m.crunch * &asked.mass_si * &v2), k)),
            contact_time: N::of_approx(&contact_time(&(&m.mu * &asked.mass_si), k)),
        })
    }

    /// The bodies at rest at IN swing (both when neither or both were).
    fn pendulum(
        m: &Motion,
        asked: &Asked,
        l: &Q,
        typed: &str,
    ) -> Result<PendulumReport<N>, AskedError> {
        let at_rest: Vec<usize> = (0..2).filter(|i| m.v_in[*i].is_zero()).collect();
        let bodies = if at_rest.len() == 1 {
            at_rest
        } else {
            vec![0, 1]
        };
        let mut swings = Vec::new();
        for i in bodies {
            let f = &m.fin[i] * &asked.velocity_si;
            let h = &f * &f / (int(2) * &asked.g);
            match swing(&h, l) {
                Swing::OverTheTop => {
                    return Err(AskedError::OverTheTop {
                        length: typed.to_string(),
                        body: i + 1,
                        height: significant(&h, 6),
                        five_halves_l: significant(&(int(5) * l / int(2)), 6),
                    });
                }
                Swing::Slack { peak } => swings.push(SwingReport {
                    body: i as u8 + 1,
                    height: nonzero(&h),
                    angle_deg: None,
                    horizontal: None,
                    slack: true,
                    peak: Some(nonzero(&peak)),
                }),
                Swing::Angle {
                    degrees,
                    horizontal,
                    slack,
                    peak,
                } => swings.push(SwingReport {
                    body: i as u8 + 1,
                    height: nonzero(&h),
                    angle_deg: Some(either(degrees)),
                    horizontal: Some(either(horizontal)),
                    slack,
                    peak: peak.as_ref().map(nonzero),
                }),
            }
        }
        Ok(PendulumReport {
            length: N::of_rational(l),
            g: N::of_rational(&asked.g),
            swings,
        })
    }

    /// The text blocks.
    pub fn blocks(&self) -> Vec<Block> {
        let mut out = Vec::new();
        let Some(asked) = &self.asked else {
            return out;
        };
        if let (Some(s), Some((_, typed))) = (&self.spring, &asked.spring) {
            let mut b = Block::new(format!(
                "Spring between the bodies (k = {typed}{})",
                asked.units_note()
            ));
            b.row(
                "x_max = sqrt(2 crunch / k)",
                format!("{} m", s.compression.show()),
                "the compression at closest approach: the spring holds the crunch energy",
            );
            b.row(
                "t = pi sqrt(mu / k)",
                format!("{} s", s.contact_time.show()),
                "in contact half a period of the reduced mass on the spring (an ideal spring \
                 gives it all back: e = 1)",
            );
            out.push(b);
        }
        if let (Some(p), Some((_, typed))) = (&self.pendulum, &asked.length) {
            let mut b = Block::new(format!(
                "Pendulum (L = {typed}, g = {} m/s^2{}): {}",
                p.g.show(),
                asked.units_note(),
                match p.swings[..] {
                    [ref one] => format!("body {}, at rest when hit, swings", one.body),
                    _ => "each body swings".into(),
                }
            ));
            for s in &p.swings {
                let who = if p.swings.len() > 1 {
                    format!("body {}: ", s.body)
                } else {
                    String::new()
                };
                b.row(
                    format!("{who}h = f^2 / 2g"),
                    format!("{} m", s.height.show()),
                    if s.slack {
                        "the height energy alone would give: the string goes slack first"
                    } else {
                        "how high the bob rises"
                    },
                );
                if let Some(peak) = &s.peak {
                    b.row(
                        "peak, string slack",
                        format!("{} m", peak.show()),
                        "how high the bob rises: slack at cos(theta) = 2 (L - h) / 3L, it \
                         flies free to this height",
                    );
                }
                let (Some(angle), Some(horizontal)) = (&s.angle_deg, &s.horizontal) else {
                    b.row(
                        "theta = acos(1 - h / L)",
                        "none",
                        "h > 2L: a rod would go over the top; the string goes slack (peak)",
                    );
                    continue;
                };
                b.row(
                    "theta = acos(1 - h / L)",
                    format!("{} deg", angle.show()),
                    if s.slack {
                        "h > L: a string goes slack before this (only a rod swings past the \
                         horizontal)"
                    } else {
                        "the string's angle from the vertical"
                    },
                );
                b.row(
                    "x = L sin(theta)",
                    format!("{} m", horizontal.show()),
                    if s.slack {
                        "= sqrt(h (2L - h)), how far a rod's bob would move sideways"
                    } else {
                        "= sqrt(h (2L - h)), how far the bob moves sideways"
                    },
                );
            }
            out.push(b);
        }
        if let (Some(sl), Some((_, typed))) = (&self.slides, &asked.friction) {
            let mut b = Block::new(format!(
                "Slides afterwards (mu = {typed}, g = {} m/s^2{})",
                sl.g.show(),
                asked.units_note()
            ));
            b.row(
                "FIN  d = f^2 / (2 mu g)",
                format!("{} m", super::text::pair(&sl.fin)),
                "how far each body slides before friction stops it",
            );
            out.push(b);
        }
        out
    }
}
