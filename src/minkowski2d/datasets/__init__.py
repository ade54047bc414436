"""Built-in data: the ESICUP 2-D irregular nesting instances (CC0), as
:func:`~minkowski2d.read_esicup` reads them.

The 25 instances of the EURO Special Interest Group on Cutting and Packing collection
(albano, blaz, dagli, dighe1-2, fu, gardeyn0-9, jakobs1-2, mao, marques, shapes0-1,
shirts, swim, trousers) ship with the package; their source, licence and the original
papers are in ``datasets/esicup/README.md``.

Examples
--------
>>> import minkowski2d as mk
>>> inst = mk.datasets.esicup("albano")
>>> inst["name"], len(inst["parts"]), inst["strip"]["height"]
('albano', 8, 4900)
>>> "dagli" in mk.datasets.esicup_names()
True
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..errors import OptionError

__all__ = ["esicup", "esicup_names", "esicup_path"]

_ESICUP = Path(__file__).resolve().parent / "esicup"


def esicup_names() -> list[str]:
    """The names of the built-in ESICUP instances, sorted.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.datasets.esicup_names()[:3]
    ['albano', 'blaz', 'dagli']
    """
    return sorted(p.stem for p in _ESICUP.glob("*.json"))


def esicup_path(name: str) -> Path:
    """The file of the built-in instance ``name`` (for the CLI and other readers).

    Raises
    ------
    OptionError
        No built-in instance has that name (the message lists them).

    Examples
    --------
    >>> import minkowski2d as mk
    >>> mk.datasets.esicup_path("fu").name
    'fu.json'
    """
    names = esicup_names()
    if not isinstance(name, str) or name not in names:
        raise OptionError(
            f"name: {name!r} is not a built-in ESICUP instance",
            argument="name",
            allowed=", ".join(names),
        )
    return _ESICUP / f"{name}.json"


def esicup(name: str) -> dict[str, Any]:
    """The built-in ESICUP instance ``name``, read by :func:`~minkowski2d.read_esicup`.

    Parameters
    ----------
    name : str
        One of :func:`esicup_names` (``"albano"``, ``"shirts"``, ...).

    Returns
    -------
    dict
        As :func:`~minkowski2d.read_esicup` returns it (``name``, ``ids``, ``parts``,
        ``rotations``, ``quantities``, ``strip``, ``properties``).

    Raises
    ------
    OptionError
        No built-in instance has that name.

    Examples
    --------
    >>> import minkowski2d as mk
    >>> sum(mk.datasets.esicup("shirts")["quantities"])
    99
    """
    from ..nesting import read_esicup

    return read_esicup(esicup_path(name))
