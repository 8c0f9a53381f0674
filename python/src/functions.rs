//! The module's functions, one per command: `solve`, `frames`, `plot`, `track`, `contact`,
//! `pi` and `scene`. Each turns its arguments into the command's words (`command::words`), runs
//! the command with `--format json` (`command::run`) and returns its `Report`; the keyword names
//! are the command's long flags with underscores (`hit_at=` for `--hit-at`).

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::command::{run, words};
use crate::refused;
use crate::report::Report;

/// Flags given once per item of a list (`vary=["e=0:1:11", ...]`, `frame=["com", ...]`).
const REPEATED: [&str; 2] = ["vary", "frame"];

/// The words of `collide COMMAND ...` for `leading` (the positional `m`, `v`, `e`, ...: name and value) and `flags`.
pub(crate) fn words_of(
    py: Python<'_>,
    command: &str,
    leading: &[(&str, Option<&Bound<'_, PyAny>>)],
    flags: Option<&Bound<'_, PyDict>>,
) -> PyResult<Vec<String>> {
    let all = PyDict::new(py);
    for (name, value) in leading {
        all.set_item(name, value)?;
    }
    if let Some(flags) = flags {
        for (k, v) in flags.iter() {
            let key: String = k.extract()?;
            if ["format", "output", "log", "plot", "term"].contains(&key.as_str()) {
                return Err(refused(format!(
                    "{key}=: the module returns the report itself (JSON as Python values); \
                     write files with the command line"
                )));
            }
            if key == "vary" && !["sweep", "track", "contact"].contains(&command) {
                return Err(refused(format!(
                    "vary=: {command} gives one report; tables over a grid are collide.sweep, \
                     collide.track(vary=...) and collide.contact(vary=...)"
                )));
            }
            all.set_item(k, v)?;
        }
    }
    // `frames`' `frame=` is a list of extra rows (`solve`'s and `plot`'s is one frame), and
    // `sweep`'s `vary=` a list of parameters.
    let repeated: &[&str] = match command {
        "frames" | "sweep" | "track" | "contact" => &REPEATED,
        _ => &[],
    };
    let mut out = vec![command.to_string()];
    out.extend(words(Some(&all), repeated)?);
    Ok(out)
}

/// The report of `collide ARGS... --format json`.
fn report(py: Python<'_>, args: Vec<String>) -> PyResult<Py<Report>> {
    let mut full = args.clone();
    full.extend(["--format".to_string(), "json".to_string()]);
    let printed = run(py, &full)?;
    Report::new(py, args, printed)
}

/// The report of `collide COMMAND ...`, or, for `track` and `contact` with `vary=`, their table
/// of runs (`collide track --vary ...`) as a DataFrame: Polars, or `to="pandas"`, or
/// `to="numpy"` for a dict of NumPy arrays.
fn report_or_runs(
    py: Python<'_>,
    command: &str,
    leading: &[(&str, Option<&Bound<'_, PyAny>>)],
    flags: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyAny>> {
    let runs = ["track", "contact"].contains(&command);
    match flags {
        Some(flags) if runs && flags.contains("vary")? => {
            let flags = flags.copy()?;
            let to: String = match flags.get_item("to")? {
                Some(to) => {
                    flags.del_item("to")?;
                    to.extract()?
                }
                None => "polars".into(),
            };
            let frame = crate::sweep::frame_module(py, &to)?;
            let args = words_of(py, command, leading, Some(&flags))?;
            let cli = crate::command::parse(&args)?;
            Ok(crate::sweep::runs_frame(py, cli.command, frame)?.unbind())
        }
        _ => Ok(report(py, words_of(py, command, leading, flags)?)?.into_any()),
    }
}

/// A function of the module for `collide COMMAND`, whose report it returns, with three leading
/// values (the case's `m`, `v`, `e`, or a layout's `m`, `x`, `v`: Python's name, then the flag's)
/// and the command's other flags as keywords.
macro_rules! command {
    ($(#[$doc:meta])* $name:ident, $command:literal,
     $a:ident => $fa:literal, $b:ident => $fb:literal, $c:ident => $fc:literal) => {
        $(#[$doc])*
        #[pyfunction]
        #[pyo3(signature = ($a=None, $b=None, $c=None, **flags))]
        pub fn $name(
            py: Python<'_>,
            $a: Option<&Bound<'_, PyAny>>,
            $b: Option<&Bound<'_, PyAny>>,
            $c: Option<&Bound<'_, PyAny>>,
            flags: Option<&Bound<'_, PyDict>>,
        ) -> PyResult<Py<PyAny>> {
            let leading = [($fa, $a), ($fb, $b), ($fc, $c)];
            report_or_runs(py, $command, &leading, flags)
        }
    };
}

command!(
    /// One collision, as `collide solve ... --format json` solves it: on a rail, in the plane or
    /// space, N bodies, a homework problem with unknowns, or a rigid impact.
    ///
    /// `m`, `v` and `e` are `-m`, `-v` and `-e`; every other flag of `collide solve` is a keyword
    /// (`fin=`, `impulse=`, `released=`, `length=`, `target=`, `pivot=`, `hit_at=`, `spin=`,
    /// `friction=`, `law=`, `join=True`, `frame=`, `exact=True`, ...; `b=` is
    /// `--impact-parameter`). Values are numbers (`int`, `float`, `fractions.Fraction`), the
    /// command line's text (`"4 ton"`, `"60 mph"`, `"2/3"`, `"?"` for an unknown), and lists of
    /// them; a pair inside a list is a vector (`v=((1, 0), (0, 0))`).
    ///
    /// >>> r = solve(m=(4, 1), v=(60, 10), e=1)
    /// >>> r.fin, r.energy.crunch
    /// ([40.0, 90.0], 1000.0)
    /// >>> solve(m=(6, 1), v=(3, -4), e="2/3", exact=True).fin
    /// [Fraction(4, 3), Fraction(6, 1)]
    /// >>> solve(m=("4 ton", "1 ton"), v=("?", "10 mph"), fin=("40 mph", "90 mph")).solved.v1
    /// 60.0
    ///
    /// Raises `CollideError` (a `ValueError`) with the command line's message for a value
    /// `collide solve` refuses.
    solve, "solve", m => "m", v => "v", e => "e"
);

command!(
    /// One collision seen from the standard Galilean frames, as `collide frames ... --format
    /// json` prints it (lecture Figs. 2.5 and 3.4); `frame=` adds rows (one frame or a list).
    ///
    /// >>> [row.name for row in frames(m=(4, 1), v=(60, 10)).frames][:2]
    /// ['lab', 'rest-in:1']
    frames, "frames", m => "m", v => "v", e => "e"
);

command!(
    /// Repeated collisions of bodies on a track between walls, as `collide track ... --format
    /// json` runs them: `m`, `x` and `v` are the masses, positions and velocities (`-m`, `-x`,
    /// `-v`); `left_wall=`, `right_wall=`, `sizes=`, `e=`, `gravity=`, `until=`, ... the other
    /// flags. With `vary=` (`--vary`, one text or a list), the table of runs that `collide track
    /// --vary` writes, as a Polars DataFrame (`to="pandas"`, or `to="numpy"` for a dict of
    /// arrays), every value the command's.
    ///
    /// >>> track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0).collisions
    /// 31
    track, "track", m => "m", x => "positions", v => "v"
);

command!(
    /// Collisions in time with contact forces, as `collide contact ... --format json`
    /// integrates them: `m`, `x`, `v` as for `track`, and `sizes=`, `law=` (`"linear"`,
    /// `"hertz"`, ...), `stiffness=`, `zeta=`, `damping=`, `method=`, ... as the command's flags;
    /// with `vary=`, the table of runs of `collide contact --vary`, as `track`'s.
    contact, "contact", m => "m", x => "positions", v => "v"
);

/// The SVG that `collide plot` draws for the case (the velocity plane by default;
/// `kind="minkowski"`, `frame="com"`, `frames=True` as its flags).
///
/// >>> plot(m=(4, 1), v=(60, 10)).startswith("<svg")
/// True
#[pyfunction]
#[pyo3(signature = (m=None, v=None, e=None, **flags))]
pub fn plot(
    py: Python<'_>,
    m: Option<&Bound<'_, PyAny>>,
    v: Option<&Bound<'_, PyAny>>,
    e: Option<&Bound<'_, PyAny>>,
    flags: Option<&Bound<'_, PyDict>>,
) -> PyResult<String> {
    let args = words_of(py, "plot", &[("m", m), ("v", v), ("e", e)], flags)?;
    Ok(run(py, &args)?.stdout)
}

/// Pi from collisions, as `collide pi N --format json` counts them: the exact count for mass
/// ratio 100^N, and the simulation for N <= 10 (`no_simulate=True` for the count alone).
///
/// >>> pi(3, no_simulate=True).count
/// '3141'
#[pyfunction]
#[pyo3(signature = (n, **flags))]
pub fn pi(
    py: Python<'_>,
    n: &Bound<'_, PyAny>,
    flags: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<Report>> {
    let mut args = words_of(py, "pi", &[], flags)?;
    args.insert(1, crate::values::scalar(n, "n")?);
    report(py, args)
}

/// A TOML scene file solved and checked, as `collide scene FILE --format json` does it; the
/// report's `status` is 1 when one of its `[expect]` checks failed.
#[pyfunction]
#[pyo3(signature = (path, **flags))]
pub fn scene(
    py: Python<'_>,
    path: std::path::PathBuf,
    flags: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<Report>> {
    let mut args = words_of(py, "scene", &[], flags)?;
    args.insert(1, path.to_string_lossy().into_owned());
    report(py, args)
}
