//! One row of a table: its inputs, the solver computing it, and why a row can be bad.

use crate::line::inertia::{InertiaError, Mass, MassError};
use crate::line::restitution::{Restitution, RestitutionError};
use crate::solver::Solver;
use crate::solver::binary64::Binary64;
use crate::values::number::{Number, NumberError};

/// The inputs of one row: `M = [[m11, m12], [m12, m22]]`, `V`, `e`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowCase {
    pub m11: f64,
    pub m12: f64,
    pub m22: f64,
    pub v: [f64; 2],
    pub e: f64,
}

impl RowCase {
    /// A row of two masses on a rail from binary64 values (`collide.solve_many` in Python),
    /// each checked as a batch checks its field ([`check`]): a bad one is the batch's
    /// `field 'm1': ...` (its number as [`Number`] prints it).
    pub fn masses(m1: f64, m2: f64, v: [f64; 2], e: f64) -> Result<RowCase, RowProblem> {
        let fields = [("m1", m1), ("m2", m2), ("v1", v[0]), ("v2", v[1]), ("e", e)];
        for (field, x) in fields {
            let checked = Number::from_f64(x)
                .map_err(ValueProblem::from)
                .and_then(|n| check(field, n));
            checked.map_err(|problem| RowProblem::Field { field, problem })?;
        }
        Ok(RowCase {
            m11: m1,
            m12: 0.0,
            m22: m2,
            v,
            e,
        })
    }
}

/// A row's value checked by the type that holds it, as a batch checks each field: `m1` and `m2`
/// as a `Mass`, `e` as a `Restitution` (velocities and tensor entries take any number).
pub fn check(field: &str, n: Number) -> Result<(), ValueProblem> {
    match field {
        "m1" | "m2" => drop(Mass::new(n)?),
        "e" => drop(Restitution::new(n)?),
        _ => {}
    }
    Ok(())
}

/// A row being computed: its inputs, its solver, and FIN once computed (several columns use it).
pub struct Row<'a> {
    pub case: &'a RowCase,
    pub seen: Binary64<'a>,
    fin: Option<[f64; 2]>,
}

impl<'a> Row<'a> {
    pub fn new(case: &'a RowCase, seen: Binary64<'a>) -> Row<'a> {
        Row {
            case,
            seen,
            fin: None,
        }
    }

    /// `V_FIN`, computed once.
    pub fn fin(&mut self) -> [f64; 2] {
        *self.fin.get_or_insert_with(|| self.seen.v_fin())
    }
}

/// A row that could not be given, and where it is.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{place}: {problem}")]
pub struct RowError {
    /// `line 17` (batch input) or `row 17` (sweep).
    pub place: String,
    pub problem: RowProblem,
}

/// What is wrong with a row.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RowProblem {
    #[error("field '{field}': {problem}")]
    Field {
        field: &'static str,
        problem: ValueProblem,
    },
    #[error("{got} fields, but the header names {named}")]
    FieldCount { got: usize, named: usize },
    #[error("not a CSV record: {0}")]
    NotCsv(String),
    #[error("cannot read: {0}")]
    Read(String),
    /// The input itself cannot be read any further (a directory, an I/O error, a line beyond
    /// the length limit): the run ends here, `--skip-bad` or not.
    #[error("the input cannot be read: {0}")]
    Unreadable(String),
    #[error("not JSON: {0}")]
    NotJson(String),
    #[error("expected a JSON object such as {{\"m1\": 4, \"m2\": 1, \"v1\": 60, \"v2\": 10}}")]
    NotObject,
    #[error("field '{0}': expected a number, got {1}")]
    NotNumber(String, String),
    #[error(transparent)]
    Layout(#[from] LayoutError),
    #[error("this object gives the tensor or the line of impact differently from the first line")]
    OtherLayout,
    #[error(transparent)]
    Number(#[from] NumberError),
    #[error(transparent)]
    Inertia(#[from] InertiaError),
    #[error(transparent)]
    Restitution(#[from] RestitutionError),
    #[error(
        "{0} is not representable in binary64 (beyond 2.2e-308 to 1.8e308); rescale the units or \
         use collide solve --exact"
    )]
    Unrepresentable(&'static str),
    /// A run of a sweep of runs failed (`table::runs`).
    #[error("{0}")]
    Run(String),
}

impl RowProblem {
    /// Whether the input ends here: nothing after it can be read.
    pub fn ends_input(&self) -> bool {
        matches!(self, RowProblem::Unreadable(_))
    }
}

/// What is wrong with one value of a row: a field of an input row, a value of a `--vary`.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ValueProblem {
    #[error("missing")]
    Missing,
    #[error(transparent)]
    Number(#[from] NumberError),
    #[error(transparent)]
    Mass(#[from] MassError),
    #[error(transparent)]
    Restitution(#[from] RestitutionError),
    /// Outside what a run's parameter may take (`stiffness` must be > 0, ...).
    #[error("{0}")]
    Range(String),
}

/// What is wrong with the names of an input's columns (a CSV header, a JSON object's keys).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LayoutError {
    #[error("unknown column '{0}': expected {KNOWN}")]
    Unknown(String),
    #[error("missing column '{0}': expected {KNOWN}")]
    Missing(&'static str),
    #[error("give m1, m2 or m11, m12, m22, not both")]
    Both,
    #[error("column '{0}' is given twice: give each column once")]
    Twice(String),
    #[error("unknown column '{0}' in the plane: expected {KNOWN_PLANE}")]
    UnknownInPlane(String),
    #[error("missing column '{0}' in the plane: expected {KNOWN_PLANE}")]
    MissingInPlane(&'static str),
    #[error("a batch in the plane needs the line of impact: expected {KNOWN_PLANE}")]
    PlaneLine,
    #[error("give the line of impact one way: normal_deg, or nx, ny, or b, r1, r2")]
    PlaneLines,
}

/// The columns an input in the plane may have.
pub const KNOWN_PLANE: &str = "m1, m2, v1x, v1y, v2x, v2y, optionally e, and the line of impact: \
    normal_deg (degrees from +x), or nx, ny, or b, r1, r2 (disks)";

/// The columns an input may have.
pub const KNOWN: &str = "m1, m2, v1, v2 and optionally e (or m11, m12, m22 for a general tensor)";
