"""Typed errors. Bad input is an :class:`InvalidInputError` (a ``ValueError``) naming the problem and where;
an expected outcome such as an exhausted Steiner budget is a status, never an exception."""

from __future__ import annotations


class NonobtuseError(Exception):
    """Base class of this package's errors."""


class InvalidInputError(NonobtuseError, ValueError):
    """The input is malformed or geometrically invalid. The message says what and where (index, coordinates,
    file and line)."""


class InternalError(NonobtuseError, RuntimeError):
    """An invariant of the algorithms failed: a bug in nonobtuse, never the user's fault. Please report it."""
