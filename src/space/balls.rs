//! Touching balls as typed (`--positions '(0,0),(1.732,1)' --radii 1,1`, or `--contacts '1-2 @
//! 30deg'`) posed for `super::contacts`: masses and velocities read as every planar case reads
//! them (`super::pose`: the binary64 values of what was typed, the typed values themselves
//! with `--exact`), positions and radii likewise, plain numbers in one length unit (only their
//! ratios matter), and the contacts found or named.

use num_traits::Signed;

use crate::values::number::{Given, Number};
use crate::values::rational::Q;
use crate::values::units::{Dimension, Quantity};

use super::contacts::{Contact, ContactsError, named, touching};
use super::pose::{Input, PoseError, Posed, q_of};
use super::solve::Velocity;
use super::typed::{Typed, parse_list, split_bodies};

/// What the problem gives besides masses, velocities and e (those are in `input`).
#[derive(Clone, Debug, Default)]
pub struct BallsInput {
    pub input: Input,
    /// `(x,y)` per body, as typed.
    pub positions: Option<String>,
    /// One radius per body, as typed (`parse_radii`).
    pub radii: Option<Radii>,
    /// Pairs with lines of impact, as typed.
    pub contacts: Option<String>,
}

/// Why touching balls cannot be posed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BallsError {
    #[error(transparent)]
    Pose(#[from] PoseError),
    #[error(transparent)]
    Contacts(#[from] ContactsError),
    #[error("--positions: {0}")]
    Position(String),
    #[error("--radii: {0}")]
    Radius(String),
    #[error(
        "several contacts at once take known masses, velocities and e: '?' and --fin are for \
         two bodies (drop them, or the contacts)"
    )]
    Unknown,
    #[error(
        "give the contacts: --positions with --radii (the touching pairs are found), or \
         --contacts 'A-B @ N,...' (pairs with their lines of impact), not both"
    )]
    Which,
    #[error(
        "--exact: a line of impact typed as an angle is irrational (its cosine and sine; \
         contacts {0}): give it as components, e.g. '1-2 @ (1,1)', or drop --exact"
    )]
    Irrational(String),
}

/// The problem as `super::contacts` solves it.
#[derive(Clone, Debug)]
pub struct Balls {
    pub posed: Posed,
    pub masses: Vec<Q>,
    pub v_in: Vec<Vec<Q>>,
    pub e: Q,
    pub positions: Option<Vec<Vec<Q>>>,
    pub radii: Option<Vec<Q>>,
    pub contacts: Vec<Contact>,
    /// A typed angle entered rounded (its cosine and sine).
    pub rounded: bool,
}

impl BallsInput {
    /// Poses the problem: every value known, the contacts found or named.
    pub fn pose(&self) -> Result<Balls, BallsError> {
        let given = &self.input;
        if given.fin.is_some() || given.normal.is_some() {
            return Err(BallsError::Unknown);
        }
        let posed = given.pose()?;
        let st = &posed.statement;
        let masses: Vec<Q> = st
            .masses
            .iter()
            .map(|m| m.known().cloned())
            .collect::<Option<_>>()
            .ok_or(BallsError::Unknown)?;
        let v_in: Vec<Vec<Q>> = st
            .v_in
            .iter()
            .map(Velocity::value)
            .collect::<Option<_>>()
            .ok_or(BallsError::Unknown)?;
        let e = match &st.e {
            None => Q::ONE,
            Some(Given::Known(q)) => q.clone(),
            Some(_) => return Err(BallsError::Unknown),
        };
        let (n, dim, typed) = (masses.len(), st.dim, given.exact);
        let (positions, radii, contacts, rounded) =
            match (&self.positions, &self.radii, &self.contacts) {
                (Some(p), Some(r), None) => {
                    let positions = read_positions(p, n, dim, typed)?;
                    let radii = read_radii(&r.0, n, typed)?;
                    let c = touching(&positions, &radii)?;
                    (Some(positions), Some(radii), c, false)
                }
                (None, None, Some(c)) => {
                    let (c, rounded) = named(c, n, dim, typed)?;
                    if rounded && typed {
                        return Err(BallsError::Irrational(
                            c.iter()
                                .map(|c| format!("{}-{}", c.a + 1, c.b + 1))
                                .collect::<Vec<_>>()
                                .join(", "),
                        ));
                    }
                    (None, None, c, rounded)
                }
                _ => return Err(BallsError::Which),
            };
        Ok(Balls {
            posed,
            masses,
            v_in,
            e,
            positions,
            radii,
            contacts,
            rounded,
        })
    }
}

/// `(x,y)` per body, every component a plain number, as many as the velocities have.
fn read_positions(
    text: &str,
    n: usize,
    dim: usize,
    typed: bool,
) -> Result<Vec<Vec<Q>>, BallsError> {
    let list = parse_list(text).map_err(|e| BallsError::Position(e.to_string()))?;
    if list.len() != n {
        return Err(ContactsError::Positions(list.len(), n).into());
    }
    list.iter()
        .enumerate()
        .map(|(i, t)| match t {
            Typed::Components { parts, unit: None } => {
                let v: Vec<Q> = parts
                    .iter()
                    .map(|p| p.known().map(|x| q_of(x, typed)))
                    .collect::<Option<_>>()
                    .ok_or_else(|| BallsError::Position(format!("body {}: '?'", i + 1)))?;
                if v.len() != dim {
                    return Err(
                        ContactsError::PositionSize(describe(t), i + 1, v.len(), dim).into(),
                    );
                }
                Ok(v)
            }
            _ => Err(BallsError::Position(format!(
                "body {}: '{}': give a centre as plain components '(x,y)' (positions and \
                 radii in one length unit)",
                i + 1,
                describe(t)
            ))),
        })
        .collect()
}

fn describe(t: &Typed) -> String {
    match t {
        Typed::Components { parts, .. } => format!(
            "({})",
            parts
                .iter()
                .map(|p| p.known().map_or("?".into(), Number::to_string))
                .collect::<Vec<_>>()
                .join(",")
        ),
        other => format!("{other:?}"),
    }
}

/// Radii as typed, one per body: numbers or lengths (`2.5 cm`).
#[derive(Clone, Debug, PartialEq)]
pub struct Radii(pub Vec<Quantity>);

/// Radii as typed, `R1,R2,...`.
pub fn parse_radii(text: &str) -> Result<Radii, String> {
    split_bodies(text)
        .map_err(|e| e.to_string())?
        .iter()
        .map(|t| crate::values::units::parse(t, Dimension::Length).map_err(|e| e.to_string()))
        .collect::<Result<_, _>>()
        .map(Radii)
}

/// One radius per body, each a plain number above 0 (in the positions' unit).
fn read_radii(list: &[Quantity], n: usize, typed: bool) -> Result<Vec<Q>, BallsError> {
    if list.len() != n {
        return Err(ContactsError::Radii(list.len(), n).into());
    }
    list.iter()
        .enumerate()
        .map(|(i, r)| {
            if r.unit.is_some() {
                return Err(BallsError::Radius(format!(
                    "'{}': give radii as plain numbers in the positions' length unit",
                    r.number
                )));
            }
            let q = q_of(&r.number, typed);
            if !q.is_positive() {
                return Err(ContactsError::Radius(r.number.to_string(), i + 1).into());
            }
            Ok(q)
        })
        .collect()
}
