"""File plumbing shared by the readers and writers: reading text with file:line errors, atomic writes."""

from __future__ import annotations

import builtins
import contextlib
import math
import os
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Any

import numpy as np

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError


def read_text(path: Path) -> str:
    """The file's text (UTF-8; a leading byte order mark is dropped); InvalidInputError naming the file when
    missing, unreadable, not text or empty."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as e:
        raise InvalidInputError(f"{path}: cannot read the file ({e})") from None
    if not text or text.isspace():  # as `not text.strip()`, without copying the text
        raise InvalidInputError(f"{path}: the file is empty")
    return text


@dataclass
class Line:
    """One non-blank line of a text file, comments (from ``#``) removed, split on whitespace."""

    file: str
    number: int  # 1-based
    tokens: list[str]

    def error(self, message: str) -> InvalidInputError:
        return InvalidInputError(f"{self.file}:{self.number}: {message}")

    def need(self, n: int, what: str) -> Line:
        """Raise unless the line has at least ``n`` tokens."""
        if len(self.tokens) < n:
            found = " ".join(self.tokens)
            raise self.error(f"expected {what} ({n} values), found {len(self.tokens)}: '{found}'")
        return self

    def int(self, k: int, what: str) -> int:
        try:
            return int(self.tokens[k])
        except ValueError:
            raise self.error(f"{what} must be an integer, found '{self.tokens[k]}'") from None

    def float(self, k: builtins.int, what: str) -> builtins.float:
        """Token ``k`` as a float (NaN and infinity are accepted here and refused by validation)."""
        token = self.tokens[k]
        try:
            if "_" in token:  # Python's float() accepts 1_000; no mesh format does
                raise ValueError(token)
            return float(token)
        except ValueError:
            raise self.error(f"{what} must be a number, found '{token}'") from None

    def count(self, k: builtins.int, what: str) -> builtins.int:
        """Token ``k`` as a non-negative integer."""
        n = self.int(k, what)
        if n < 0:
            raise self.error(f"{what} must not be negative, found {n}")
        return n


class Lines:
    """The non-blank lines of a text file in order, for formats that count their items (Triangle's). Lines are
    split when asked for; :meth:`numbers` reads a block of plain numeric lines in one go."""

    def __init__(self, path: Path, text: str | None = None) -> None:
        self.file = str(path)
        text = read_text(path) if text is None else text
        self._raw = text.splitlines()
        self._i = 0  # index in _raw of the next line to look at
        self._last = len(self._raw)

    def _skip_blank(self) -> None:
        while self._i < len(self._raw) and not self._raw[self._i].split("#", 1)[0].split():
            self._i += 1

    def next(self, what: str) -> Line:
        """The next line; when the file has ended, InvalidInputError saying ``what`` was expected."""
        self._skip_blank()
        if self._i >= len(self._raw):
            raise InvalidInputError(f"{self.file}:{self._last}: the file ends early: expected {what}")
        self._i += 1
        return Line(self.file, self._i, self._raw[self._i - 1].split("#", 1)[0].split())

    def room_for(self, n: int) -> int:
        """How many of ``n`` announced one-line items the rest of the file can hold: the size to allocate for
        them, so that a header announcing 10^12 items allocates nothing big (reading the items then stops
        with "the file ends early" before the allocation is exceeded)."""
        return max(0, min(n, len(self._raw) - self._i))

    def at_end(self) -> bool:
        self._skip_blank()
        return self._i >= len(self._raw)

    def expect_end(self) -> None:
        if not self.at_end():
            raise self.next("").error("unexpected content after the last section (wrong counts?)")

    def numbers(
        self, n: int, width: int, integers: tuple[int, ...] = ()
    ) -> tuple[np.ndarray, np.ndarray] | None:
        """The fast path for the next ``n`` lines (:func:`numeric_rows`): their values (n, width) float64 and
        1-based line numbers (n,) int64, without consuming the lines (:meth:`skip` does); None when the lines
        are not plain numeric rows, and the caller reads them one by one, which names any problem by
        file:line. Cost: O(characters of the block) in numpy, in chunks of 65536 lines (temporaries of
        about 30 bytes per character of a chunk)."""
        if n == 0 or self._i + n > len(self._raw):
            return None
        values = np.empty((n, width), dtype=np.float64)
        for start in range(0, n, _CHUNK_ROWS):  # chunks bound the temporaries
            stop = min(n, start + _CHUNK_ROWS)
            chunk = numeric_rows(self._raw[self._i + start : self._i + stop], width, integers)
            if chunk is None:
                return None
            values[start:stop] = chunk
        return values, np.arange(self._i + 1, self._i + n + 1, dtype=np.int64)

    def skip(self, n: int) -> None:
        """Consume the ``n`` lines a successful :meth:`numbers` read."""
        self._i += n


_CHUNK_ROWS = 1 << 16


def numeric_rows(rows: list[str], width: int, integers: tuple[int, ...] = ()) -> np.ndarray | None:
    """``rows`` as an (len(rows), width) float64 array when every row holds exactly ``width`` whitespace
    separated plain decimal numbers (``float()`` gives the same values: both round correctly) and the columns
    ``integers`` hold integer literals (no ``.``/``e``) of magnitude < 2**53 (so read exactly); None for
    anything else (comments, blank rows, nan/inf, underscores, non-ASCII, ragged rows, a number that does not
    parse or overflows), for the caller's line-by-line reader to accept or name. Parsed in C++
    (:func:`nonobtuse._core.parse_numeric_rows`, ``cpp/include/nonobtuse/numeric_rows.h``). Cost: one pass
    over the characters, plus joining and encoding the rows."""
    text = "\n".join(rows)
    if not text.isascii():
        return None
    return _core.parse_numeric_rows(text.encode("ascii"), len(rows), width, list(integers))


def exact_float(value: object, where: str) -> float:
    """A JSON number as a float64, refusing booleans, strings and integers float64 cannot hold exactly."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InvalidInputError(f"{where} must be a number, found {value!r}")
    x = float(value)
    if isinstance(value, int) and (not math.isfinite(x) or int(x) != value):
        raise InvalidInputError(f"{where}: the integer {value} is not exactly representable as a float64")
    return x


def require_writable(path: Path) -> Path:
    """The folder of ``path``; InvalidInputError when ``path`` is a directory or its folder does not exist."""
    folder = path.parent
    if path.is_dir():
        raise InvalidInputError(f"{path}: cannot write the output: it is a directory")
    if not folder.is_dir():
        raise InvalidInputError(f"{path}: cannot write the output: the folder {folder} does not exist")
    return folder


def _umask() -> int:
    mask = os.umask(0o022)  # reading the umask means setting it; put it back at once
    os.umask(mask)
    return mask


@contextlib.contextmanager
def atomic_path(path: Path) -> Iterator[Path]:
    """A temporary path beside ``path`` (same suffix) to write to; on success it replaces ``path`` atomically
    (os.replace) with the mode a newly created file gets (0666 less the umask), on failure it is removed and
    ``path`` is untouched. InvalidInputError when ``path`` is a directory or its folder does not exist or is
    not writable."""
    path = Path(path)
    folder = require_writable(path)
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{path.name}.", suffix=path.suffix)
    except OSError as e:
        raise InvalidInputError(f"{path}: cannot write the output ({e.strerror})") from None
    try:
        os.fchmod(fd, 0o666 & ~_umask())  # mkstemp creates 0600
    finally:
        os.close(fd)
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


@contextlib.contextmanager
def atomic_text(path: Path) -> Iterator[IO[str]]:
    """A text stream whose content replaces ``path`` atomically when the block ends without an exception."""
    with atomic_path(path) as tmp, open(tmp, "w", encoding="utf-8") as f:
        yield f


def jsonable(x: Any) -> Any:
    """`x` with numpy arrays and scalars turned into lists and Python numbers, for json.dumps."""
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, dict):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [jsonable(v) for v in x]
    return x
