"""collide: two-body collisions on a rail and in the plane, exact or in binary64, with the
same numbers as the command line (`collide solve --format json`, `collide batch`, `collide
sweep`).

>>> import collide
>>> r = collide.solve(m=(4, 1), v=(60, 10), e=1)
>>> r.fin
[40.0, 90.0]
"""

from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

COLUMNS: List[str]
"""Every column `solve_many` can compute (`collide sweep --columns`), in the CLI's order."""

Number = Union[int, float, Fraction, str]
"""A number, or the command line's text for one (`"4 ton"`, `"60 mph"`, `"2/3"`)."""

Vector = Union[Tuple[Number, Number], str]
"""A vector in the plane: a pair, or text (`"(4,1)"`, `"6 m/s @ 30deg"`)."""

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
    """The report of one case: `collide solve --format json` for it."""

    def to_json(self) -> str:
        """The JSON text, as `collide solve --format json` prints it."""

def solve(
    m: Optional[Tuple[Number, Number]] = None,
    v: Optional[Tuple[Union[Number, Vector], Union[Number, Vector]]] = None,
    e: Optional[Number] = None,
    *,
    inertia: Optional[str] = None,
    normal: Optional[Union[Vector, Number]] = None,
    radii: Optional[Tuple[Number, Number]] = None,
    b: Optional[Number] = None,
    frame: str = "lab",
    reverse: bool = False,
    exact: bool = False,
) -> Report:
    """One collision, as `collide solve ... --format json` solves it.

    Values are numbers (`int`, `float`, `Fraction`) or the command line's text (`"4 ton"`,
    `"60 mph"`, `"2/3"`, `"elastic"`). `e` is elastic when omitted. Vector velocities, or a
    line of impact (`normal=`, or `radii=` with `b=`), make a case in the plane. `inertia`
    is a general tensor `"M11,M12;M21,M22"` instead of `m`. `frame` is the CLI's `--frame`
    (`"lab"`, `"com"`, `"rest-in:1"`, ...); `exact=True` is `--exact` (numbers as
    `Fraction`s).

    >>> solve(m=(6, 1), v=(3, -4), e="2/3", exact=True).fin
    [Fraction(4, 3), Fraction(6, 1)]

    Raises CollideError with the command line's message for a value it refuses.
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
