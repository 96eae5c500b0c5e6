"""Arguments of the package's public calls, checked for their type before they reach the compiled module, so that
a wrong one is one line naming it (`spp: expected a whole number, got float`) instead of pybind11's
"incompatible function arguments" with every signature. Their ranges stay the compiled module's, the render
request's (docs/design.md §5): a whole number too large for a C int is clamped into one on the way
(`Clamp`), refused there as out of range, and the refusal is given back with the number as it was passed.

No typing or numpy import here (import costs count: bench/README.md).
"""

from __future__ import annotations

import operator

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from typing import Any, NoReturn

_INT_MIN, _INT_MAX = -(2**31), 2**31 - 1
_INT64_MIN, _INT64_MAX = -(2**63), 2**63 - 1


def _refuse(name: str, expected: str, value: object) -> NoReturn:
    raise TypeError(f"{name}: expected {expected}, got {type(value).__name__}")


def whole(name: str, value: object) -> int:
    """`value` as an int: an int or a numpy integer, not a bool (TypeError naming `name` otherwise)."""
    if isinstance(value, bool) or not hasattr(type(value), "__index__"):
        _refuse(name, "a whole number", value)
    return operator.index(value)  # type: ignore[arg-type]  # it has __index__


def optional_whole(name: str, value: object) -> int | None:
    """None, or `value` as whole() takes it."""
    return None if value is None else whole(name, value)


def real(name: str, value: object) -> float:
    """`value` as a float: a Python or numpy number, not a bool or a string (NaN passes, for the range check
    to refuse by name)."""
    if isinstance(value, (bool, str, bytes)) or not hasattr(type(value), "__float__"):
        _refuse(name, "a number", value)
    try:
        return float(value)  # type: ignore[arg-type]  # it has __float__
    except OverflowError:  # an int beyond a double
        return float("inf") if operator.index(value) > 0 else float("-inf")  # type: ignore[arg-type]


def optional_real(name: str, value: object) -> float | None:
    """None, or `value` as real() takes it."""
    return None if value is None else real(name, value)


def flag(name: str, value: object) -> bool:
    """True or False (a numpy bool too); anything else, even a truthy string, is a TypeError naming `name`."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    _refuse(name, "True or False", value)


def word(name: str, value: object) -> str:
    """A string (its word is the compiled module's to check, with the list of choices)."""
    if not isinstance(value, str):
        _refuse(name, "a string", value)
    return value


def path(name: str, value: object) -> str:
    """A path as a string: a str, bytes or os.PathLike (os.fspath), anything else a TypeError naming `name`."""
    import os  # already loaded by the interpreter at start-up: costs nothing

    if not isinstance(value, (str, bytes)) and not hasattr(type(value), "__fspath__"):
        _refuse(name, "a path (str or os.PathLike)", value)
    return os.fsdecode(os.fspath(value))  # type: ignore[call-overload]  # checked above


def optional_word(name: str, value: object) -> str | None:
    """None, or a string."""
    return None if value is None else word(name, value)


class Clamp:
    """Whole numbers as the compiled module takes them (C ints), remembering those that did not fit, so that its
    refusal of one (they are all far out of every range) names the number as it was given."""

    def __init__(self) -> None:
        self._wide: list[tuple[int, int]] = []

    def __call__(self, value: int) -> int:
        return self._clamp(value, _INT_MIN, _INT_MAX)

    def int64(self, value: int | None) -> int | None:
        """None, or `value` clamped into a 64-bit integer, for the arguments the compiled module takes as one
        (seed: its range is all 32-bit unsigned numbers, beyond a C int)."""
        return None if value is None else self._clamp(value, _INT64_MIN, _INT64_MAX)

    def _clamp(self, value: int, low: int, high: int) -> int:
        clamped = min(max(value, low), high)
        if clamped != value:
            self._wide.append((clamped, value))
        return clamped

    def reword(self, error: Exception) -> Exception | None:
        """The compiled module's refusal with the clamped numbers put back as given (in the order they were
        clamped, the order the request checks them); None when nothing was clamped."""
        if not self._wide:
            return None
        message = str(error)
        for clamped, value in self._wide:
            message = message.replace(str(clamped), str(value), 1)
        reworded: Exception = type(error)(message)
        return reworded


def call(clamp: Clamp, function: Any, *args: Any) -> Any:
    """function(*args), with a ValueError reworded by `clamp`."""
    try:
        return function(*args)
    except ValueError as e:
        reworded = clamp.reword(e)
        if reworded is None:
            raise
        raise reworded from None
