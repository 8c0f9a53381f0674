//! The columns a table can show, each declared once: the name (the `--columns` word, the scene's
//! `columns` key and the header), what it is (the CLI help), whether it is shown by default, and
//! how a row computes it. Adding a column is adding one entry to `COLUMNS`.

use std::fmt;
use std::str::FromStr;

use super::row::Row;
use crate::solver::Solver;
use Shown::{Always, Asked, Diagonal, General};

/// When a column is among the defaults.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shown {
    /// For masses (a diagonal tensor).
    Diagonal,
    /// For a general tensor.
    General,
    /// Always.
    Always,
    /// Only when asked for.
    Asked,
}

/// A quantity a table can show.
pub struct Column {
    pub name: &'static str,
    pub help: &'static str,
    shown: Shown,
    value: fn(&mut Row) -> f64,
}

impl Column {
    /// This column's value for `row`.
    pub fn value(&self, row: &mut Row) -> f64 {
        (self.value)(row)
    }

    /// The default columns: the inputs, then FIN, V_COM and the energies.
    pub fn defaults(general: bool) -> Vec<&'static Column> {
        let tensor = if general { General } else { Diagonal };
        COLUMNS
            .iter()
            .filter(|c| c.shown == tensor || c.shown == Always)
            .collect()
    }
}

impl PartialEq for Column {
    fn eq(&self, other: &Column) -> bool {
        self.name == other.name
    }
}

impl fmt::Debug for Column {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name)
    }
}

impl fmt::Display for Column {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name)
    }
}

/// `Column` as a one-line declaration.
const fn column(
    name: &'static str,
    help: &'static str,
    shown: Shown,
    value: fn(&mut Row) -> f64,
) -> Column {
    Column {
        name,
        help,
        shown,
        value,
    }
}

/// `V.M.V`-style forms of a row's vectors.
fn in_m_in(r: &mut Row) -> f64 {
    let v = r.seen.v_in();
    r.seen.form(&v, &v)
}

fn fin_m_in(r: &mut Row) -> f64 {
    let (f, v) = (r.fin(), r.seen.v_in());
    r.seen.form(&f, &v)
}

fn fin_m_fin(r: &mut Row) -> f64 {
    let f = r.fin();
    r.seen.form(&f, &f)
}

/// Every column, in the order `--help` lists them.
#[rustfmt::skip]
pub static COLUMNS: [Column; 22] = [
    column("m1", "mass of body 1 (M11)", Diagonal, |r| r.case.m11),
    column("m2", "mass of body 2 (M22)", Diagonal, |r| r.case.m22),
    column("m11", "tensor entry M11", General, |r| r.case.m11),
    column("m12", "tensor entry M12 = M21", General, |r| r.case.m12),
    column("m22", "tensor entry M22", General, |r| r.case.m22),
    column("v1", "initial velocity V1", Always, |r| r.case.v[0]),
    column("v2", "initial velocity V2", Always, |r| r.case.v[1]),
    column("e", "coefficient of restitution", Always, |r| r.case.e),
    column("fin1", "final velocity FIN1", Always, |r| r.fin()[0]),
    column("fin2", "final velocity FIN2", Always, |r| r.fin()[1]),
    column("v_com", "center-of-momentum velocity P_total / M_total", Always, |r| r.seen.v_com()),
    column("p_total", "total momentum u.M.V", Asked, |r| r.seen.total_momentum()),
    column("ke_in", "kinetic energy before, 1/2 V_IN.M.V_IN", Always, |r| r.seen.ke_in()),
    column("ke_fin", "kinetic energy after, KE_COM + e^2 crunch", Always, |r| r.seen.ke_fin()),
    column("ke_com", "kinetic energy of the center of momentum, 1/2 V_COM P_total", Asked, |r| r.seen.ke_com()),
    column("crunch", "crunch energy 1/2 mu (V1 - V2)^2", Always, |r| r.seen.crunch()),
    column("lost", "energy lost to heat, (1 - e^2) crunch", Always, |r| r.seen.lost()),
    column("mu", "reduced mass det M / M_total", Asked, |r| r.seen.reduced_mass()),
    column("in_m_in", "quadratic form V_IN.M.V_IN", Asked, in_m_in),
    column("fin_m_in", "quadratic form V_FIN.M.V_IN", Asked, fin_m_in),
    column("fin_m_fin", "quadratic form V_FIN.M.V_FIN", Asked, fin_m_fin),
    column("com_m_in", "quadratic form V_COM.M.V_IN = V_COM P_total", Asked, |r| r.seen.com_form()),
];

/// A name that is not a column.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("'{0}' is not a column: expected one of {names}", names = names().join(", "))]
pub struct ColumnError(pub String);

/// Every column's name.
pub fn names() -> Vec<&'static str> {
    COLUMNS.iter().map(|c| c.name).collect()
}

impl FromStr for &'static Column {
    type Err = ColumnError;
    fn from_str(s: &str) -> Result<&'static Column, ColumnError> {
        COLUMNS
            .iter()
            .find(|c| c.name == s.trim())
            .ok_or_else(|| ColumnError(s.trim().to_string()))
    }
}

/// Columns by name, for tests and benches.
pub fn by_names(names: &[&str]) -> Result<Vec<&'static Column>, ColumnError> {
    names.iter().map(|n| n.parse()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_defaults_are_the_inputs_then_the_results() {
        let mut seen = names();
        seen.sort();
        seen.dedup();
        assert_eq!(seen.len(), COLUMNS.len());
        let d: Vec<&str> = Column::defaults(false).iter().map(|c| c.name).collect();
        assert_eq!(
            d,
            [
                "m1", "m2", "v1", "v2", "e", "fin1", "fin2", "v_com", "ke_in", "ke_fin", "crunch",
                "lost"
            ]
        );
        let g: Vec<&str> = Column::defaults(true).iter().map(|c| c.name).collect();
        assert_eq!(&g[..6], ["m11", "m12", "m22", "v1", "v2", "e"]);
        let e = "fin3".parse::<&Column>().unwrap_err().to_string();
        assert!(
            e.starts_with("'fin3' is not a column: expected one of m1, m2,"),
            "{e}"
        );
    }
}
