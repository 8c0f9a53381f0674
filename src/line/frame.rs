//! Galilean frames (lecture Sec. 4): an observer moving at `w` sees every velocity shifted by
//! `-w`, a 45-degree shift in the velocity plane. Crunch energy, `e` and the relative velocity are
//! the same in every frame; kinetic energies are not. The frames of interest are the lab (Earth),
//! COM, and "body i initially / finally at rest"; each solver turns a frame into its observer
//! velocity (`solver::binary64::observer_velocity`, `ExactCollision::observer_velocity`).

use std::fmt;
use std::str::FromStr;

use crate::values::number::Number;

/// A frame of reference (`--frame`, `frame = "..."` in a scene).
#[derive(Clone, Debug, PartialEq)]
pub enum Frame {
    /// The lab (the lecture's Earth frame), `w = 0`.
    Lab,
    /// Center of momentum, `w = V_COM`.
    Com,
    /// Body 1 or 2 initially at rest, `w = V_i^IN`.
    RestIn(usize),
    /// Body 1 or 2 finally at rest, `w = V_i^FIN`.
    RestFin(usize),
    /// An observer moving at this velocity.
    Velocity(Number),
    /// An observer moving at this vector velocity (the plane, space: `'(2,1)'`).
    Vector(Vec<Number>),
}

impl Frame {
    /// The lecture's standard frames (Figs. 2.5 and 3.4), in the order of the frames table.
    pub fn standard() -> [Frame; 6] {
        [
            Frame::Lab,
            Frame::RestIn(1),
            Frame::RestIn(2),
            Frame::Com,
            Frame::RestFin(1),
            Frame::RestFin(2),
        ]
    }

    /// What the frame is, for people.
    pub fn describe(&self) -> String {
        match self {
            Frame::Lab => "lab (Earth)".into(),
            Frame::Com => "COM".into(),
            Frame::RestIn(i) => format!("body {i} initially at rest"),
            Frame::RestFin(i) => format!("body {i} finally at rest"),
            Frame::Velocity(n) => format!("observer at {n}"),
            Frame::Vector(v) => format!("observer at {}", vector_text(v)),
        }
    }

    /// Refuses what a collision on a line cannot be seen from: a vector observer, or a body
    /// beyond the second.
    pub fn on_line(&self) -> Result<(), LineFrameError> {
        match self {
            Frame::Vector(_) => Err(LineFrameError(self.to_string())),
            Frame::RestIn(i) | Frame::RestFin(i) if !(1..=2).contains(i) => {
                Err(LineFrameError(self.to_string()))
            }
            _ => Ok(()),
        }
    }
}

/// `(2, 1)`.
fn vector_text(v: &[Number]) -> String {
    let parts: Vec<String> = v.iter().map(Number::to_string).collect();
    format!("({})", parts.join(", "))
}

impl fmt::Display for Frame {
    /// The word that names the frame on the command line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Frame::Lab => write!(f, "lab"),
            Frame::Com => write!(f, "com"),
            Frame::RestIn(i) => write!(f, "rest-in:{i}"),
            Frame::RestFin(i) => write!(f, "rest-fin:{i}"),
            Frame::Velocity(n) => write!(f, "{n}"),
            Frame::Vector(v) => write!(f, "{}", vector_text(v).replace(' ', "")),
        }
    }
}

/// Why a text is not a frame.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "frame '{}' is not a frame: expected lab, com, rest-in:1, rest-in:2, rest-fin:1, rest-fin:2, \
     or an observer velocity such as 2.5",
    crate::values::number::printable(.0)
)]
pub struct FrameError(pub String);

/// A frame a collision of two bodies on a line cannot be seen from.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "frame '{0}': two bodies on a line are seen from lab, com, rest-in:1, rest-in:2, rest-fin:1, \
     rest-fin:2, or an observer velocity such as 2.5 (vector observers and bodies beyond the \
     second are for the plane, space and N bodies)"
)]
pub struct LineFrameError(pub String);

impl FromStr for Frame {
    type Err = FrameError;
    fn from_str(s: &str) -> Result<Frame, FrameError> {
        let t = s.trim();
        Ok(match t {
            "lab" | "earth" => Frame::Lab,
            "com" => Frame::Com,
            "rest-in:1" => Frame::RestIn(1),
            "rest-in:2" => Frame::RestIn(2),
            _ if t.starts_with('(') && t.ends_with(')') => {
                let parts = t[1..t.len() - 1]
                    .split(',')
                    .map(str::parse::<Number>)
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|_| FrameError(t.to_string()))?;
                if !(2..=3).contains(&parts.len()) {
                    return Err(FrameError(t.to_string()));
                }
                Frame::Vector(parts)
            }
            _ => {
                let body = |rest: &str| rest.parse::<usize>().ok().filter(|i| *i >= 1);
                if let Some(i) = t.strip_prefix("rest-in:").and_then(body) {
                    Frame::RestIn(i)
                } else if let Some(i) = t.strip_prefix("rest-fin:").and_then(body) {
                    Frame::RestFin(i)
                } else {
                    Frame::Velocity(t.parse().map_err(|_| FrameError(t.to_string()))?)
                }
            }
        })
    }
}

/// Serde: a frame word (`"com"`) or an observer velocity (`2.5`, `"-4"`).
impl<'de> serde::Deserialize<'de> for Frame {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Frame, D::Error> {
        crate::values::number::deserialize_parsed(
            d,
            "a frame (\"lab\", \"com\", \"rest-in:1\", ...) or an observer velocity",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_words() {
        assert_eq!("com".parse::<Frame>().unwrap(), Frame::Com);
        assert_eq!("rest-fin:2".parse::<Frame>().unwrap(), Frame::RestFin(2));
        assert_eq!("-4".parse::<Frame>().unwrap().to_string(), "-4");
        // rest-in:3 is a frame of N bodies; on a line of two it is refused by `on_line`.
        let e = "rest-in:3"
            .parse::<Frame>()
            .unwrap()
            .on_line()
            .unwrap_err()
            .to_string();
        assert!(e.contains("'rest-in:3'") && e.contains("rest-in:2"), "{e}");
        assert!("rest-in:0".parse::<Frame>().is_err());
        let v = "(2,1)".parse::<Frame>().unwrap();
        assert_eq!(v.to_string(), "(2,1)");
        assert!(v.on_line().is_err());
    }
}
