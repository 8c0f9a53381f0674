//! Parameter sweeps (`collide sweep`, `[sweep]` in a scene): `--vary NAME=FROM:TO:COUNT[:log]`
//! or `NAME=a,b,c`, combined as a cartesian product with the last `--vary` fastest.
//!
//! Linear steps are exact: the i-th value is `FROM + i (TO - FROM)/(COUNT - 1)` in rational
//! arithmetic, rounded once, so `e=0:1:11` gives 0, 0.1, 0.2, 0.3, ... as a user would type them
//! (never 0.30000000000000004). Log steps are rounded to 15 significant digits, so
//! `m2=1:100:3:log` gives exactly 1, 10, 100.

use std::fmt;
use std::str::FromStr;

use crate::values::rational::{IBig, Q, UBig, pow10, to_f64};
use num_traits::ToPrimitive;

use super::row::ValueProblem;
use crate::line::inertia::Mass;
use crate::line::restitution::Restitution;
use crate::values::number::{Number, NumberError};

/// The default cap on a sweep's rows (`--max-rows`, `max_rows` in a scene): 1e8 rows, about
/// 7 GB of CSV; more must be asked for.
pub const DEFAULT_MAX_ROWS: u64 = 100_000_000;

/// A parameter a sweep can vary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Param {
    M1,
    M2,
    V1,
    V2,
    E,
}

impl Param {
    pub const ALL: [Param; 5] = [Param::M1, Param::M2, Param::V1, Param::V2, Param::E];

    pub fn name(self) -> &'static str {
        match self {
            Param::M1 => "m1",
            Param::M2 => "m2",
            Param::V1 => "v1",
            Param::V2 => "v2",
            Param::E => "e",
        }
    }

    /// Checks a value this parameter may take, by the type that holds it.
    fn check(self, n: &Number) -> Result<(), ValueProblem> {
        match self {
            Param::M1 | Param::M2 => drop(Mass::new(n.clone())?),
            Param::E => drop(Restitution::new(n.clone())?),
            Param::V1 | Param::V2 => {}
        }
        Ok(())
    }
}

/// Why a `--vary` is refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VaryError {
    #[error("'{0}': {1}")]
    Form(String, String),
    #[error("'{0}' is not a parameter: {1}")]
    Param(String, String),
    #[error("{param}: {error}")]
    Value { param: String, error: ValueProblem },
    #[error("'{text}': COUNT '{count}' must be a whole number >= 1")]
    Count { text: String, count: String },
    #[error("'{0}': COUNT is 0, so the range is empty; use 1 or more")]
    Empty(String),
    #[error("'{0}': FROM equals TO, so {1} values would all be the same; use COUNT 1 or a list")]
    Same(String, u64),
    #[error("'{0}': a log range needs FROM and TO > 0")]
    LogSign(String),
    #[error("'{0}': the list is empty; {1}")]
    EmptyList(String, String),
    #[error(
        "'{0}': the list has an empty entry (two commas in a row, or one at an end); give a value between every two commas"
    )]
    EmptyEntry(String),
    /// `e=0-1`: one value that is no number, most likely a range typed another way.
    #[error(
        "'{text}': '{value}' is not a number; a range is FROM:TO:COUNT, e.g. {example}; {form}"
    )]
    NotARange {
        text: String,
        value: String,
        example: String,
        form: String,
    },
}

/// Values more numerous than this are computed when needed instead of stored (a huge --vary is
/// refused by --max-rows before any value is computed).
const STORED: u64 = 1 << 16;

/// The values of one `--vary`.
#[derive(Clone, Debug, PartialEq)]
pub enum Values {
    /// `FROM:TO:COUNT`, exact rational steps; `fast` is `(A, B, D)` with the i-th value
    /// `(A + B i) / D` when these fit in 128-bit integers.
    Linear {
        from: Q,
        to: Q,
        count: u64,
        fast: Option<(i128, i128, i128)>,
        stored: Vec<f64>,
    },
    /// `FROM:TO:COUNT:log`; `decades` is `K` when `TO/FROM = 10^K` exactly.
    Log {
        from: Q,
        to: Q,
        decades: Option<i64>,
        count: u64,
        stored: Vec<f64>,
    },
    /// `a,b,c`.
    List(Vec<f64>),
}

impl Values {
    pub fn len(&self) -> u64 {
        match self {
            Values::Linear { count, .. } | Values::Log { count, .. } => *count,
            Values::List(v) => v.len() as u64,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `i`-th value.
    pub fn get(&self, i: u64) -> f64 {
        match self {
            Values::List(v) => v[i as usize],
            Values::Linear { stored, .. } | Values::Log { stored, .. } if !stored.is_empty() => {
                stored[i as usize]
            }
            Values::Linear {
                from,
                to,
                count,
                fast,
                ..
            } => linear(from, to, *count, *fast, i),
            Values::Log {
                from,
                to,
                decades,
                count,
                ..
            } => log(from, to, *decades, *count, i),
        }
    }
}

/// The `count` values `value(i)`, when few enough to store; none otherwise (they are computed
/// when needed).
fn store(count: u64, value: impl Fn(u64) -> f64) -> Vec<f64> {
    if count <= STORED {
        (0..count).map(value).collect()
    } else {
        Vec::new()
    }
}

/// `(A, B, D)` such that `FROM + i (TO - FROM)/(COUNT - 1) = (A + B i) / D`, in i128.
fn linear_fast(from: &Q, to: &Q, count: u64) -> Option<(i128, i128, i128)> {
    let (p1, q1) = (from.numerator().to_i128()?, from.denominator().to_i128()?);
    let (p2, q2) = (to.numerator().to_i128()?, to.denominator().to_i128()?);
    let steps = i128::from(count.max(2) - 1);
    let a = p1.checked_mul(q2)?.checked_mul(steps)?;
    let b = p2.checked_mul(q1)?.checked_sub(p1.checked_mul(q2)?)?;
    let d = q1.checked_mul(q2)?.checked_mul(steps)?;
    // The largest numerator, A + B (COUNT - 1), must fit too.
    a.checked_add(b.checked_mul(steps)?)?;
    Some((a, b, d))
}

/// The i-th linear value, rounded once. With `(A + B i) / D` in integers below 2^53, one binary64
/// division is the correctly rounded quotient; otherwise exact rationals decide.
fn linear(from: &Q, to: &Q, count: u64, fast: Option<(i128, i128, i128)>, i: u64) -> f64 {
    if count == 1 {
        return to_f64(from).unwrap_or(f64::NAN);
    }
    const EXACT: i128 = 1 << 53;
    if let Some((a, b, d)) = fast {
        let mut n = a + b * i as i128;
        let mut d = d;
        if n.abs() > EXACT || d > EXACT {
            let g = num_integer::gcd(n, d);
            (n, d) = (n / g, d / g);
        }
        if n.abs() <= EXACT && d <= EXACT {
            return n as f64 / d as f64;
        }
    }
    let step = (to - from) * Q::from_parts(i.into(), (count - 1).into());
    to_f64(&(from + step)).unwrap_or(f64::NAN)
}

/// `FROM (TO/FROM)^(i/(COUNT-1))`. When `TO/FROM = 10^K` and `iK/(COUNT-1)` is whole, the value
/// is `FROM 10^(iK/(COUNT-1))` exactly; otherwise it is rounded to 15 significant digits.
fn log(from: &Q, to: &Q, decades: Option<i64>, count: u64, i: u64) -> f64 {
    let f = |q: &Q| to_f64(q).unwrap_or(f64::NAN);
    if i == 0 || count == 1 {
        return f(from);
    }
    if i + 1 == count {
        return f(to);
    }
    let steps = (count - 1) as i64;
    if let Some(k) = decades.filter(|k| (i as i64 * k) % steps == 0) {
        let j = i as i64 * k / steps;
        let p = Q::from(pow10(j.unsigned_abs() as usize));
        return f(&if j >= 0 { from * p } else { from / p });
    }
    if let Some(k) = decades {
        // 10^(i k / steps) = 10^whole 10^r: the whole decades exactly, only 10^r (0 <= r < 1)
        // in binary64, so no ratio over- or underflows (1e-310 to 1e300) and the error stays
        // an ulp or two.
        let n = i as i64 * k;
        let (whole, rem) = (n.div_euclid(steps), n.rem_euclid(steps));
        let a = f(from);
        let base = if whole.abs() <= 22 && a.is_normal() {
            // 10^whole is exact in binary64 here: one rounding, no big numbers.
            if whole >= 0 {
                a * 10f64.powi(whole as i32)
            } else {
                a / 10f64.powi(-whole as i32)
            }
        } else {
            let p = Q::from(pow10(whole.unsigned_abs() as usize));
            f(&if whole >= 0 { from * p } else { from / p })
        };
        let x = base * 10f64.powf(rem as f64 / steps as f64);
        return format!("{x:.14e}").parse().unwrap_or(x);
    }
    let t = i as f64 / steps as f64;
    let (a, b) = (f(from), f(to));
    let ratio = b / a;
    let x = if ratio.is_normal() && a.is_normal() {
        a * ratio.powf(t)
    } else {
        // The ratio over- or underflows (1e-310 to 1e300): interpolate the exponents instead.
        // Whole decades apart from the fraction, so no power is taken of a large number.
        let (la, lb) = (a.log10(), b.log10());
        let e = la + t * (lb - la);
        let n = e.floor();
        let m = 10f64.powf(e - n);
        format!("{m:.16}e{n}").parse().unwrap_or(f64::NAN)
    };
    format!("{x:.14e}").parse().unwrap_or(x)
}

/// `K` when `q = 10^K` for a whole `K`.
fn power_of_ten(q: &Q) -> Option<i64> {
    let ten = UBig::from(10u8);
    let (mut n, mut d) = (q.numerator().clone(), q.denominator().clone());
    let mut k = 0i64;
    while n > IBig::ONE && (&n % &ten).is_zero() {
        n /= &ten;
        k += 1;
    }
    while d > UBig::ONE && (&d % &ten).is_zero() {
        d /= &ten;
        k -= 1;
    }
    (n.is_one() && d.is_one()).then_some(k)
}

/// One `--vary NAME=...`: of a two-body sweep's [`Param`], or of any parameter `P` of a run
/// (`table::runs`).
#[derive(Clone, Debug, PartialEq)]
pub struct Vary<P = Param> {
    pub param: P,
    pub values: Values,
    /// As typed, for messages.
    pub text: String,
}

impl<P> fmt::Display for Vary<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// The forms of a `--vary`, for messages.
pub const RANGE_FORMS: &str = "expected NAME=FROM:TO:COUNT, NAME=FROM:TO:COUNT:log or NAME=a,b,c";

const VARY_FORM: &str = "expected NAME=FROM:TO:COUNT, NAME=FROM:TO:COUNT:log or NAME=a,b,c with NAME one of m1, m2, v1, v2, e";

impl FromStr for Vary {
    type Err = VaryError;

    fn from_str(s: &str) -> Result<Vary, VaryError> {
        parse_vary(
            s,
            VARY_FORM,
            |name| Param::ALL.into_iter().find(|p| p.name() == name),
            |p, n| p.check(n),
        )
    }
}

/// `NAME=VALUE` where VALUE is no number: how a range is written, with FROM and TO read from
/// `VALUE` when it is two numbers joined by `-`, `..` or `to` (`e=0-1`: `e=0:1:11`).
fn not_a_range(text: &str, name: &str, value: &str, form: &str) -> VaryError {
    let ends = ["..", " to ", "-"].iter().find_map(|sep| {
        // `-` after the first character, so that `-1-2` reads as -1 to 2.
        let at = value.get(1..)?.find(sep)? + 1;
        let (from, to) = (value[..at].trim(), value[at + sep.len()..].trim());
        (from.parse::<Number>().is_ok() && to.parse::<Number>().is_ok()).then_some((from, to))
    });
    let example = match ends {
        Some((from, to)) => format!("{name}={from}:{to}:11 for 11 values from {from} to {to}"),
        None => format!("{name}=0:1:11 for 11 values from 0 to 1"),
    };
    VaryError::NotARange {
        text: text.to_string(),
        value: value.to_string(),
        example,
        form: form.to_string(),
    }
}

/// Parses `NAME=RANGE`: `name` resolves NAME to a parameter (`None`: not one, and `form` says
/// what is expected), `check` refuses a value it cannot take.
pub fn parse_vary<P: Copy + Named>(
    s: &str,
    form: &str,
    name: impl Fn(&str) -> Option<P>,
    check: impl Fn(P, &Number) -> Result<(), ValueProblem>,
) -> Result<Vary<P>, VaryError> {
    let text = s.trim().to_string();
    let (typed, spec) = text
        .split_once('=')
        .ok_or_else(|| VaryError::Form(text.clone(), form.to_string()))?;
    let param = name(typed.trim())
        .ok_or_else(|| VaryError::Param(typed.trim().to_string(), form.into()))?;
    let num = |t: &str| -> Result<Number, VaryError> {
        let value = |error| VaryError::Value {
            param: param.name(),
            error,
        };
        let n: Number = t.parse().map_err(|e: NumberError| value(e.into()))?;
        check(param, &n).map_err(value)?;
        Ok(n)
    };
    let parts: Vec<&str> = spec.split(':').collect();
    let values = match parts.as_slice() {
        [from, to, count] | [from, to, count, "log"] => {
            let count: u64 = count.trim().parse().map_err(|_| VaryError::Count {
                text: text.clone(),
                count: count.trim().to_string(),
            })?;
            if count == 0 {
                return Err(VaryError::Empty(text));
            }
            let (from, to) = (num(from)?, num(to)?);
            if count > 1 && from.same_value(&to) {
                return Err(VaryError::Same(text, count));
            }
            if parts.len() == 4 {
                if from.value() <= 0.0 || to.value() <= 0.0 {
                    return Err(VaryError::LogSign(text));
                }
                let (from, to) = (from.exact(), to.exact());
                let decades = power_of_ten(&(&to / &from));
                let stored = store(count, |i| log(&from, &to, decades, count, i));
                Values::Log {
                    from,
                    to,
                    decades,
                    count,
                    stored,
                }
            } else {
                let (from, to) = (from.exact(), to.exact());
                let fast = linear_fast(&from, &to, count);
                let stored = store(count, |i| linear(&from, &to, count, fast, i));
                Values::Linear {
                    from,
                    to,
                    count,
                    fast,
                    stored,
                }
            }
        }
        [list] if list.trim().is_empty() => {
            return Err(VaryError::EmptyList(text, form.to_string()));
        }
        [list] => {
            // `e=1,,2` dropped the empty entry: a typo, refused rather than guessed.
            if list.split(',').any(|t| t.trim().is_empty()) {
                return Err(VaryError::EmptyEntry(text));
            }
            // `e=0-1`, `e=0..1`: a range in another notation; say how ranges are written.
            if !list.contains(',') && list.trim().parse::<Number>().is_err() {
                return Err(not_a_range(&text, typed.trim(), list.trim(), form));
            }
            let values = list
                .split(',')
                .map(|t| num(t).map(|n| n.value()))
                .collect::<Result<Vec<f64>, VaryError>>()?;
            Values::List(values)
        }
        _ => return Err(VaryError::Form(text, form.to_string())),
    };
    Ok(Vary {
        param,
        values,
        text,
    })
}

/// A parameter's name as typed (`m2`, `stiffness`), for messages and column headers.
pub trait Named {
    fn name(&self) -> String;
}

impl Named for Param {
    fn name(&self) -> String {
        Param::name(*self).to_string()
    }
}

/// A slice `K/N` of the rows: the K-th of N contiguous, disjoint parts (K from 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub k: u64,
    pub n: u64,
}

impl Shard {
    pub const WHOLE: Shard = Shard { k: 1, n: 1 };

    /// The rows of this shard out of `total`: `[(K-1) total / N, K total / N)`.
    pub fn rows(self, total: u64) -> std::ops::Range<u64> {
        let at = |k: u64| ((k as u128 * total as u128) / self.n as u128) as u64;
        at(self.k - 1)..at(self.k)
    }
}

/// A text that is not a shard.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("shard '{0}': expected K/N with 1 <= K <= N, e.g. 2/8")]
pub struct ShardError(pub String);

impl FromStr for Shard {
    type Err = ShardError;
    fn from_str(s: &str) -> Result<Shard, ShardError> {
        let bad = || ShardError(s.trim().to_string());
        let (k, n) = s.trim().split_once('/').ok_or_else(bad)?;
        let (k, n): (u64, u64) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if k == 0 || n == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { k, n })
    }
}

/// The grid of a sweep: the product of its `--vary`s, last fastest.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid<P = Param> {
    pub vary: Vec<Vary<P>>,
    pub total: u64,
}

/// Why a grid is refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GridError {
    #[error("a sweep needs at least one --vary NAME=FROM:TO:COUNT")]
    Empty,
    #[error("{0} is varied twice ('{1}'); give each parameter one --vary")]
    Twice(String, String),
    #[error(
        "the sweep has {rows:.3e} rows, more than --max-rows {max_rows}; raise --max-rows to run it"
    )]
    TooMany { rows: f64, max_rows: u64 },
}

impl<P: Copy + PartialEq + Named> Grid<P> {
    /// Refuses a product of more than `max_rows` rows, and a parameter varied twice.
    pub fn new(vary: Vec<Vary<P>>, max_rows: u64) -> Result<Grid<P>, GridError> {
        if vary.is_empty() {
            return Err(GridError::Empty);
        }
        for (i, v) in vary.iter().enumerate() {
            if vary[..i].iter().any(|u| u.param == v.param) {
                return Err(GridError::Twice(v.param.name(), v.text.clone()));
            }
        }
        let total = vary
            .iter()
            .try_fold(1u64, |acc, v| acc.checked_mul(v.values.len()));
        match total {
            Some(t) if t <= max_rows => Ok(Grid { vary, total: t }),
            _ => Err(GridError::TooMany {
                rows: vary.iter().map(|v| v.values.len() as f64).product(),
                max_rows,
            }),
        }
    }

    /// The varied values of row `r`, as `(param, value)`.
    pub fn row(&self, mut r: u64, out: &mut [(P, f64)]) {
        for (slot, v) in out.iter_mut().zip(&self.vary).rev() {
            let n = v.values.len();
            *slot = (v.param, v.values.get(r % n));
            r /= n;
        }
    }

    pub fn varies(&self, p: P) -> bool {
        self.vary.iter().any(|v| v.param == p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(s: &str) -> Vec<f64> {
        let v: Vary = s.parse().unwrap();
        (0..v.values.len()).map(|i| v.values.get(i)).collect()
    }

    #[test]
    fn exact_decimal_steps() {
        let e = values("e=0:1:11");
        assert_eq!(e, [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]);
        assert_ne!(
            0.1 * 3.0,
            0.3,
            "the naive step would give 0.30000000000000004"
        );
        assert_eq!(values("v1=0:1:4"), [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]);
        assert_eq!(values("v2=10:-10:3"), [10.0, 0.0, -10.0]);
        assert_eq!(values("m1=2/3:2/3:1"), [2.0 / 3.0]);
    }

    #[test]
    fn log_steps_and_lists() {
        assert_eq!(values("m2=1:100:3:log"), [1.0, 10.0, 100.0]);
        assert_eq!(
            values("m2=1e-3:1e3:7:log"),
            [1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1000.0]
        );
        assert_eq!(values("v1=1,2.5,-3"), [1.0, 2.5, -3.0]);
        // Not whole decades: 10^(1/2) to 15 significant digits.
        assert_eq!(values("m1=1:10:3:log"), [1.0, 3.16227766016838, 10.0]);
        assert_eq!(values("m1=2:2000:4:log"), [2.0, 20.0, 200.0, 2000.0]);
    }

    #[test]
    fn the_same_values_whether_stored_or_computed() {
        let from: Q = "0".parse::<Number>().unwrap().exact();
        let to = "1".parse::<Number>().unwrap().exact();
        assert_eq!(linear(&from, &to, 11, linear_fast(&from, &to, 11), 3), 0.3);
        assert_eq!(linear(&from, &to, 11, None, 3), 0.3);
        // The fast path and exact rationals agree on awkward steps.
        let (a, b) = (
            "-1.5e-3".parse::<Number>().unwrap().exact(),
            "7/3".parse::<Number>().unwrap().exact(),
        );
        let fast = linear_fast(&a, &b, 1001);
        assert!(fast.is_some());
        for i in 0..1001 {
            assert_eq!(
                linear(&a, &b, 1001, fast, i),
                linear(&a, &b, 1001, None, i),
                "value {i}"
            );
        }
        let hundred = "100".parse::<Number>().unwrap().exact();
        let one = "1".parse::<Number>().unwrap().exact();
        assert_eq!(log(&one, &hundred, Some(2), 3, 1), 10.0);
        assert_eq!(power_of_ten(&(hundred / one)), Some(2));
    }

    #[test]
    fn refusals_name_the_problem() {
        let err = |s: &str| s.parse::<Vary>().unwrap_err().to_string();
        assert!(err("e=0:1:0").contains("empty"));
        assert!(err("e=0:1:x").contains("COUNT 'x'"));
        assert!(err("e=-1:1:3").contains("'-1' is negative"));
        assert!(err("m1=0:2:3").contains("'0' must be greater than 0"));
        assert!(err("m1=1:1:5").contains("FROM equals TO"));
        assert!(err("v3=0:1:2").contains("'v3' is not a parameter"));
        assert!(err("v1=").contains("empty"));
        assert!(err("v1").contains("NAME=FROM:TO:COUNT"));
        assert!(err("v1=-1:1:3:log").contains("log range"));
        let big = Grid::new(
            vec![
                "v1=0:1:10000".parse().unwrap(),
                "v2=0:1:1000".parse().unwrap(),
            ],
            1_000_000,
        );
        assert!(big.unwrap_err().to_string().contains("--max-rows 1000000"));
        let twice = Grid::new(
            vec!["v1=0:1:2".parse().unwrap(), "v1=1,2".parse().unwrap()],
            100,
        );
        assert!(twice.unwrap_err().to_string().contains("varied twice"));
    }

    #[test]
    fn grid_order_last_fastest() {
        let g = Grid::new(
            vec!["v1=1,2".parse().unwrap(), "e=0:1:3".parse().unwrap()],
            100,
        )
        .unwrap();
        assert_eq!(g.total, 6);
        let mut row = [(Param::V1, 0.0); 2];
        let rows: Vec<(f64, f64)> = (0..6)
            .map(|r| {
                g.row(r, &mut row);
                (row[0].1, row[1].1)
            })
            .collect();
        assert_eq!(
            rows,
            [
                (1.0, 0.0),
                (1.0, 0.5),
                (1.0, 1.0),
                (2.0, 0.0),
                (2.0, 0.5),
                (2.0, 1.0)
            ]
        );
    }

    #[test]
    fn shards_partition_the_rows() {
        for total in [0u64, 1, 7, 100, 101] {
            for n in 1..=8 {
                let mut next = 0;
                for k in 1..=n {
                    let r = Shard { k, n }.rows(total);
                    assert_eq!(r.start, next);
                    next = r.end;
                }
                assert_eq!(next, total);
            }
        }
        assert!("0/3".parse::<Shard>().is_err());
        assert!("4/3".parse::<Shard>().is_err());
        assert_eq!("2/3".parse::<Shard>().unwrap(), Shard { k: 2, n: 3 });
    }
}
