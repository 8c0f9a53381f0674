"""collide: two-body collisions on a rail and in the plane, exact or in binary64, with the
same numbers as the command line (`collide solve --format json`, `collide batch`, `collide
sweep`).

>>> import collide
>>> r = collide.solve(m=(4, 1), v=(60, 10), e=1)
>>> r.fin
[40.0, 90.0]
"""

from fractions import Fraction
from os import PathLike
from typing import Any, Dict, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

COLUMNS: List[str]
"""Every column `solve_many` can compute (`collide sweep --columns`), in the CLI's order."""

Number = Union[int, float, Fraction, str]
"""A number, or the command line's text for one (`"4 ton"`, `"60 mph"`, `"2/3"`)."""

Vector = Union[Tuple[Number, Number], Tuple[Number, Number, Number], str]
"""A vector in the plane or in space: a pair (a triple), or text (`"(4,1)"`, `"6 m/s @ 30deg"`)."""

Values = Union[Number, Vector, Sequence[Union[Number, Vector]]]
"""One value per body (`(4, 1)`, `("4 ton", "?")`, `((1, 0), "6 m/s @ 30deg")`), or the command
line's list as text (`"4,1"`)."""

Flag = Union[Number, Vector, Sequence[Union[Number, Vector]], bool, None]
"""A flag of the command: `name=value` is `--name VALUE` (underscores as dashes), `True` the bare
flag, `False` and `None` left out, a list comma-separated (a pair inside it a vector)."""

ArrayLike = Union[float, Sequence[float], npt.NDArray[np.float64]]

class CollideError(ValueError):
    """A value collide refuses, with the command line's message."""

class Section:
    """A part of a report (a JSON object of `collide solve --format json`).

    Its keys are attributes (`r.energy.crunch`) and items (`r["energy"]["crunch"]`); a key
    that is a Python keyword is also its name with a trailing `_` (`in_` for `in`). Objects
    within are `Section`s; with `exact=True` numbers are `fractions.Fraction`s.
    """

    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, key: str) -> Any: ...
    def __contains__(self, key: str) -> bool: ...
    def keys(self) -> List[str]:
        """The keys, in the JSON's order."""
    def to_dict(self) -> Dict[str, Any]:
        """This part as plain values: `json.loads` of the command's output (a copy)."""
    def _repr_html_(self) -> str: ...

class Report(Section):
    """The report of one command: its `--format json` output (`collide solve`, `frames`,
    `track`, `contact`, `pi`, `scene`)."""

    command: str
    """The command line that prints this report (`collide solve --masses 4,1 ...`)."""
    status: int
    """The command's exit status: 0, or 1 when a scene's check failed or given values
    contradict each other."""

    def to_json(self) -> str:
        """The JSON text, as the command prints it with `--format json`."""
    def _repr_svg_(self) -> Optional[str]:
        """What `collide plot` draws for the case of a `solve` or `frames` report; None for a
        report it does not draw (unknowns, knowns, a track, a scene)."""

def solve(
    m: Optional[Values] = None,
    v: Optional[Values] = None,
    e: Optional[Number] = None,
    *,
    inertia: Optional[str] = None,
    fin: Optional[Values] = None,
    normal: Optional[Union[Vector, Number]] = None,
    radii: Optional[Tuple[Number, Number]] = None,
    b: Optional[Number] = None,
    frame: str = "lab",
    reverse: bool = False,
    exact: bool = False,
    show: Optional[Union[str, Sequence[str]]] = None,
    impulse: Optional[Number] = None,
    released: Optional[Number] = None,
    pass_through: bool = False,
    length: Optional[Number] = None,
    spring: Optional[Number] = None,
    total_mass: Optional[Number] = None,
    separation_speed: Optional[Number] = None,
    gravity: Optional[Number] = None,
    target: Optional[str] = None,
    pivot: Optional[Union[str, Vector]] = None,
    hit_at: Optional[Number] = None,
    ball: Optional[str] = None,
    spin: Optional[Values] = None,
    friction: Optional[Number] = None,
    law: Optional[Literal["poisson", "newton", "stronge"]] = None,
    tangential_restitution: Optional[Number] = None,
    join: bool = False,
    **flags: Flag,
) -> Report:
    """One collision, as `collide solve ... --format json` solves it: on a rail, in the plane
    or space, N bodies, a homework problem with unknowns (`"?"`), or a rigid impact.

    `m`, `v`, `e` are `-m`, `-v`, `-e`; every other flag of `collide solve` is a keyword
    (`hit_at=` for `--hit-at`, `b=` for `--impact-parameter`). Values are numbers (`int`,
    `float`, `Fraction`) or the command line's text (`"4 ton"`, `"60 mph"`, `"2/3"`, `"?"`).
    `exact=True` is `--exact` (numbers as `Fraction`s).

    >>> solve(m=(6, 1), v=(3, -4), e="2/3", exact=True).fin
    [Fraction(4, 3), Fraction(6, 1)]
    >>> solve(m=("4 ton", "1 ton"), v=("?", "10 mph"), fin=("40 mph", "90 mph")).solved.v1
    60.0

    Raises CollideError with the command line's message for a value it refuses.
    """

def frames(
    m: Optional[Values] = None,
    v: Optional[Values] = None,
    e: Optional[Number] = None,
    *,
    frame: Optional[Union[str, Sequence[str]]] = None,
    reverse: bool = False,
    exact: bool = False,
    **flags: Flag,
) -> Report:
    """The collision in the standard Galilean frames, as `collide frames --format json`
    prints it; `frame=` adds rows (one frame or a list).

    >>> [row.name for row in frames(m=(4, 1), v=(60, 10)).frames][:2]
    ['lab', 'rest-in:1']
    """

def plot(
    m: Optional[Values] = None,
    v: Optional[Values] = None,
    e: Optional[Number] = None,
    *,
    kind: Optional[Literal["velocity", "newton", "minkowski"]] = None,
    frame: str = "lab",
    frames: bool = False,
    **flags: Flag,
) -> str:
    """The SVG `collide plot` draws for the case.

    >>> plot(m=(4, 1), v=(60, 10)).startswith("<svg")
    True
    """

@overload
def track(
    m: Optional[Values] = None,
    x: Optional[Values] = None,
    v: Optional[Values] = None,
    *,
    vary: Union[str, Sequence[str]],
    to: Literal["polars", "pandas", "numpy"] = "polars",
    columns: Optional[Sequence[str]] = None,
    skip_bad: bool = False,
    **flags: Flag,
) -> Any: ...
@overload
def track(
    m: Optional[Values] = None,
    x: Optional[Values] = None,
    v: Optional[Values] = None,
    *,
    sizes: Optional[Values] = None,
    left_wall: Optional[Number] = None,
    right_wall: Optional[Number] = None,
    e: Optional[Number] = None,
    wall_restitution: Optional[Number] = None,
    gravity: Optional[Number] = None,
    until: Optional[Number] = None,
    max_collisions: Optional[int] = None,
    **flags: Flag,
) -> Report:
    """Repeated collisions on a track between walls, as `collide track --format json` runs
    them: `m`, `x`, `v` are the masses, positions and velocities. With `vary=` (the command's
    `--vary`), the table of runs `collide track --vary` writes, one row a run, as a Polars
    DataFrame (`to="pandas"`, or `to="numpy"` for a dict of arrays), every value the command's.

    >>> track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0).collisions
    31
    >>> track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0, vary="m2=1,100,10000",
    ...       columns=["m2", "collisions"], to="numpy")["collisions"]
    array([  3,  31, 314])
    """

@overload
def contact(
    m: Optional[Values] = None,
    x: Optional[Values] = None,
    v: Optional[Values] = None,
    *,
    vary: Union[str, Sequence[str]],
    to: Literal["polars", "pandas", "numpy"] = "polars",
    columns: Optional[Sequence[str]] = None,
    skip_bad: bool = False,
    **flags: Flag,
) -> Any: ...
@overload
def contact(
    m: Optional[Values] = None,
    x: Optional[Values] = None,
    v: Optional[Values] = None,
    *,
    sizes: Optional[Values] = None,
    law: Optional[str] = None,
    stiffness: Optional[float] = None,
    damping: Optional[float] = None,
    zeta: Optional[float] = None,
    method: Optional[str] = None,
    until: Optional[Number] = None,
    **flags: Flag,
) -> Report:
    """Collisions in time with contact forces, as `collide contact --format json` integrates
    them; with `vary=`, the table of runs of `collide contact --vary` as a DataFrame (as
    `track`)."""

def pi(n: int, *, simulate: bool = False, no_simulate: bool = False) -> Report:
    """Pi from collisions, as `collide pi N --format json` counts them.

    >>> pi(3, no_simulate=True).count
    '3141'
    """

def scene(path: Union[str, "PathLike[str]"]) -> Report:
    """A TOML scene solved and checked, as `collide scene FILE --format json`; `status` is 1
    when an `[expect]` check failed."""

@overload
def sweep(
    m: Optional[Values] = None,
    v: Optional[Values] = None,
    e: Optional[Number] = None,
    *,
    vary: Union[str, Sequence[str]],
    to: Literal["numpy"],
    **flags: Flag,
) -> Dict[str, npt.NDArray[np.float64]]: ...
@overload
def sweep(
    m: Optional[Values] = None,
    v: Optional[Values] = None,
    e: Optional[Number] = None,
    *,
    vary: Union[str, Sequence[str]],
    to: Literal["polars", "pandas"] = "polars",
    columns: Optional[Sequence[str]] = None,
    skip_bad: bool = False,
    **flags: Flag,
) -> Any:
    """A sweep, as `collide sweep --vary ...` computes it, as a Polars DataFrame (pandas with
    `to="pandas"`, a dict of NumPy arrays with `to="numpy"`), bit for bit the command's rows,
    with no text between: on a rail, or in the plane (vectors and `normal=`, or `radii=` and
    `b=`; its parameters `b`, `normal_deg`, `v1x`, ... and columns as the command's, with an
    `error` column for a run that failed).

    >>> df = sweep(m=(4, 1), v=(60, 10), vary="e=0:1:3", columns=["e", "fin1", "fin2"], to="numpy")
    >>> df["fin1"], df["fin2"]
    (array([50., 45., 40.]), array([50., 70., 90.]))
    """

def solve_many(
    m1: ArrayLike,
    m2: ArrayLike,
    v1: ArrayLike,
    v2: ArrayLike,
    e: Optional[ArrayLike] = None,
    *,
    columns: Optional[Sequence[str]] = None,
) -> Dict[str, npt.NDArray[Any]]:
    """Many collisions on a rail, as `collide batch` and `collide sweep` compute them.

    The inputs broadcast together as NumPy broadcasts them (read as float64; `e` elastic when
    omitted). Returns one float64 array of the broadcast shape per column (by default the
    sweep's: m1 m2 v1 v2 e fin1 fin2 v_com ke_in ke_fin crunch lost; any of `COLUMNS`), bit
    for bit what `collide batch` prints for the same rows, computed in parallel with the GIL
    released; and `error`, an object array: None for a good row, the command line's message
    for a bad one (whose columns are NaN).

    >>> import numpy as np
    >>> out = solve_many(4.0, 1.0, np.array([60.0, 30.0]), 10.0, 1.0)
    >>> out["fin1"], out["fin2"]
    (array([40., 22.]), array([90., 42.]))
    """
