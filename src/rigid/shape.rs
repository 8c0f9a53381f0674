//! Uniform bodies and their moments of inertia about the centre of mass (physics.md section 7):
//! rod `m L^2/12`, disk `m R^2/2`, ring `m R^2`, solid sphere `2/5 m R^2`, spherical shell
//! `2/3 m R^2`, box `m (b^2 + c^2)/12` about each axis.
//!
//! In the plane a body turns about z: a rod or door (seen from above) lies along y, a disk or
//! ring is in the plane, a box `(a, b)` has sides `a` along x and `b` along y. In space the
//! principal axes are the world's: a disk or ring lies in the xy plane (its axis z), a box has
//! sides `(a, b, c)` along x, y, z. A thin rod has no inertia about its own axis, so in space it
//! is refused (a box of small width does the job).

use crate::values::rational::{Q, int, ratio};

use super::algebra::{Mat, diag};
use super::units::{Measure, RigidUnitError, Typed, TypedVec};

/// Which uniform body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A thin rod (or a door seen from above) of length L, along y.
    Rod,
    /// A uniform disk (cylinder) of radius R.
    Disk,
    /// A thin ring (hoop) of radius R.
    Ring,
    /// A solid sphere of radius R.
    Sphere,
    /// A thin spherical shell of radius R.
    Shell,
    /// A rectangular box with sides (a, b) in the plane or (a, b, c) in space.
    Box,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::Rod => "rod",
            Kind::Disk => "disk",
            Kind::Ring => "ring",
            Kind::Sphere => "sphere",
            Kind::Shell => "shell",
            Kind::Box => "box",
        }
    }

    /// Whether its size is a radius (a round body).
    pub fn round(self) -> bool {
        matches!(self, Kind::Disk | Kind::Ring | Kind::Sphere | Kind::Shell)
    }
}

/// A shape as typed: `rod 1.2 m`, `door 0.9 m`, `disk 10 cm`, `box (0.2,0.1) m`.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeTyped {
    pub kind: Kind,
    /// One length, or a box's sides.
    pub sizes: TypedVec,
    pub text: String,
}

/// A shape with its lengths in the case's units.
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    pub kind: Kind,
    pub sizes: Vec<Q>,
}

/// Why a shape is not one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ShapeError {
    #[error(
        "shape '{0}': expected 'rod L', 'door L', 'disk R', 'ring R', 'sphere R', 'shell R' or \
         'box (a,b)' / 'box (a,b,c)', with a length unit or none"
    )]
    Syntax(String),
    #[error(transparent)]
    Unit(Box<RigidUnitError>),
    #[error("shape '{0}': every size must be > 0")]
    Size(String),
    #[error(
        "shape '{0}': a thin rod has no moment of inertia about its own axis, so in space it \
         cannot be a rigid body here: give a box '(a,b,c)' or an inertia tensor"
    )]
    RodInSpace(String),
    #[error("shape '{0}': a box in space needs three sides '(a,b,c)'")]
    BoxInSpace(String),
}

impl From<RigidUnitError> for ShapeError {
    fn from(e: RigidUnitError) -> ShapeError {
        ShapeError::Unit(Box::new(e))
    }
}

impl std::str::FromStr for ShapeTyped {
    type Err = ShapeError;
    fn from_str(s: &str) -> Result<ShapeTyped, ShapeError> {
        let t = s.trim();
        let (word, rest) = t
            .split_once(char::is_whitespace)
            .ok_or_else(|| ShapeError::Syntax(t.into()))?;
        let kind = match word.to_ascii_lowercase().as_str() {
            "rod" | "stick" | "door" | "bar" => Kind::Rod,
            "disk" | "disc" | "cylinder" => Kind::Disk,
            "ring" | "hoop" => Kind::Ring,
            "sphere" | "ball" => Kind::Sphere,
            "shell" => Kind::Shell,
            "box" | "block" => Kind::Box,
            _ => return Err(ShapeError::Syntax(t.into())),
        };
        let rest = rest.trim();
        let what = format!("shape '{t}'");
        let sizes = if kind == Kind::Box {
            TypedVec::parse(rest, Measure::Length, &what, &[2, 3])?
        } else {
            let one = Typed::parse(rest, Measure::Length, &what)?;
            TypedVec {
                parts: vec![one.number],
                unit: one.unit,
                measure: Measure::Length,
                text: one.text,
                angle: None,
            }
        };
        if sizes.angle.is_some() {
            return Err(ShapeError::Syntax(t.into()));
        }
        if sizes.parts.iter().any(|n| n.value() <= 0.0) {
            return Err(ShapeError::Size(t.into()));
        }
        Ok(ShapeTyped {
            kind,
            sizes,
            text: t.into(),
        })
    }
}

impl ShapeTyped {
    /// The lengths in the case's units, and whether they are rounded.
    pub fn resolve(&self, si: bool, exact: bool) -> Result<(Shape, bool), ShapeError> {
        let (sizes, rounded) = self.sizes.value(si, exact)?;
        Ok((
            Shape {
                kind: self.kind,
                sizes,
            },
            rounded,
        ))
    }
}

impl Shape {
    /// The radius of a round body, the half length of a rod, half of a box's side along x.
    pub fn radius(&self) -> Q {
        match self.kind {
            Kind::Rod => self.sizes[0].clone() * ratio(1, 2),
            _ if self.kind.round() => self.sizes[0].clone(),
            _ => self.sizes[0].clone() * ratio(1, 2),
        }
    }

    /// The extent along y from the centre (half a rod's length, half a box's side b, a radius).
    pub fn half_height(&self) -> Q {
        match self.kind {
            Kind::Box => self.sizes[1].clone() * ratio(1, 2),
            _ => self.radius(),
        }
    }

    /// The inertia tensor of mass `m` about the centre, in world axes: `1 x 1` in the plane
    /// (about z), `3 x 3` in space; `text` names the shape in errors.
    pub fn inertia(&self, m: &Q, dim: usize, text: &str) -> Result<Mat, ShapeError> {
        let s = &self.sizes;
        let sq = |x: &Q| x * x;
        let twelfth = |x: Q| m * x * ratio(1, 12);
        if dim == 2 {
            let i = match self.kind {
                Kind::Rod => twelfth(sq(&s[0])),
                Kind::Disk => m * sq(&s[0]) * ratio(1, 2),
                Kind::Ring => m * sq(&s[0]),
                Kind::Sphere => m * sq(&s[0]) * ratio(2, 5),
                Kind::Shell => m * sq(&s[0]) * ratio(2, 3),
                Kind::Box => twelfth(sq(&s[0]) + sq(&s[1])),
            };
            return Ok(vec![vec![i]]);
        }
        let axes = match self.kind {
            Kind::Rod => return Err(ShapeError::RodInSpace(text.into())),
            Kind::Disk => {
                let r2 = m * sq(&s[0]);
                [&r2 * ratio(1, 4), &r2 * ratio(1, 4), &r2 * ratio(1, 2)]
            }
            Kind::Ring => {
                let r2 = m * sq(&s[0]);
                [&r2 * ratio(1, 2), &r2 * ratio(1, 2), r2]
            }
            Kind::Sphere | Kind::Shell => {
                let k = if self.kind == Kind::Sphere {
                    ratio(2, 5)
                } else {
                    ratio(2, 3)
                };
                let i = m * sq(&s[0]) * k;
                return Ok(diag(3, &i));
            }
            Kind::Box => {
                let [a, b, c] = match s.as_slice() {
                    [a, b, c] => [sq(a), sq(b), sq(c)],
                    _ => return Err(ShapeError::BoxInSpace(text.into())),
                };
                [twelfth(&b + &c), twelfth(&a + &c), twelfth(a + b)]
            }
        };
        let mut t = diag(3, &int(0));
        for (k, x) in axes.into_iter().enumerate() {
            t[k][k] = x;
        }
        Ok(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(s: &str) -> Shape {
        s.parse::<ShapeTyped>()
            .unwrap()
            .resolve(false, true)
            .unwrap()
            .0
    }

    #[test]
    fn the_textbook_moments() {
        let m = int(6);
        // physics.md section 7: rod m L^2/12, disk m R^2/2, ring m R^2, sphere 2/5 m R^2,
        // shell 2/3 m R^2, box m (a^2 + b^2)/12 about z.
        let i = |s: &str| shape(s).inertia(&m, 2, s).unwrap()[0][0].clone();
        assert_eq!(i("rod 2"), int(2));
        assert_eq!(i("door 2"), int(2));
        assert_eq!(i("disk 2"), int(12));
        assert_eq!(i("ring 2"), int(24));
        assert_eq!(i("sphere 5"), int(60));
        assert_eq!(i("shell 1"), int(4));
        assert_eq!(i("box (1,2)"), ratio(5, 2));
        let b = shape("box (1,2,3)").inertia(&m, 3, "box").unwrap();
        assert_eq!(
            [b[0][0].clone(), b[1][1].clone(), b[2][2].clone()],
            [ratio(13, 2), int(5), ratio(5, 2)]
        );
        assert!(shape("rod 1").inertia(&m, 3, "rod 1").is_err());
        assert!(shape("box (1,2)").inertia(&m, 3, "box").is_err());
    }

    #[test]
    fn the_textbook_moments_in_space() {
        // physics.md section 7, about the principal axes (z the symmetry axis of a disk or a
        // ring): disk m R^2 (1/4, 1/4, 1/2), ring m R^2 (1/2, 1/2, 1), sphere and shell 2/5 and
        // 2/3 m R^2 about every axis. m = 6, R = 2: m R^2 = 24.
        let m = int(6);
        let axes = |s: &str| {
            let t = shape(s).inertia(&m, 3, s).unwrap();
            for (r, row) in t.iter().enumerate() {
                for (c, x) in row.iter().enumerate() {
                    assert!(r == c || *x == int(0), "{s}: off the diagonal {t:?}");
                }
            }
            [t[0][0].clone(), t[1][1].clone(), t[2][2].clone()]
        };
        assert_eq!(axes("disk 2"), [int(6), int(6), int(12)]);
        assert_eq!(axes("ring 2"), [int(12), int(12), int(24)]);
        assert_eq!(axes("sphere 2"), [ratio(48, 5), ratio(48, 5), ratio(48, 5)]);
        assert_eq!(axes("shell 2"), [int(16), int(16), int(16)]);
    }

    #[test]
    fn bad_shapes_are_named() {
        for bad in ["cone 1", "rod", "rod -1", "box 1", "disk 1 kg"] {
            assert!(bad.parse::<ShapeTyped>().is_err(), "{bad}");
        }
        let s: ShapeTyped = "rod 120 cm".parse().unwrap();
        assert_eq!(s.resolve(true, true).unwrap().0.sizes[0], ratio(6, 5));
    }
}
