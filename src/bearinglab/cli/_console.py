"""The command line's consoles: any output encoding, and the width of a terminal or a pipe.

A redirection on Windows writes cp1252, a C locale or ``PYTHONIOENCODING=ascii`` writes ASCII; the
project's output has Greek letters (α, κ, µ, ψ), degree signs, superscripts, minus signs and box-drawing
characters. On a stream whose encoding cannot hold them, the command line writes what the encoding
holds and spells the rest the ASCII way (α -> alpha, ° -> deg, N·mm -> N*mm, m² -> m^2, ≤ -> <=, Cyrillic
in Latin letters, box lines as -, | and +), and ``?`` for a character it does not know: it never
crashes. Files the commands write (CSV, JSON, HTML reports) are UTF-8 whatever the console.

Two places do it, so that tables stay aligned:

* :class:`Console` (the consoles of ``cli/_common.py``) spells a string before rich measures and lays it
  out, and rich draws ASCII boxes on such a stream (``ascii_only``);
* :func:`setup_streams` (called by ``cli.main`` and the application's callback) sets the error handler
  :data:`ERRORS` on ``sys.stdout`` and ``sys.stderr``, for everything else (the help, error messages,
  plain prints).

Width: on a terminal, its width; otherwise (a pipe or a file) ``$COLUMNS`` if set, else 80 columns, so
that what a command writes to a file does not depend on the terminal it was started from.

Functions
---------
ascii_spelling   ``text`` with every character that ``encoding`` cannot hold spelled the ASCII way
needs_spelling   whether an encoding cannot hold the project's characters
setup_streams    the error handler on sys.stdout and sys.stderr where their encoding needs it
output_width     the width of output that goes to a pipe or a file ($COLUMNS, else 80)
Console          a rich Console that spells its strings for its stream, and is 80 wide on a pipe
"""

from __future__ import annotations

import codecs
import functools
import os
import re
import sys

from rich.console import Console as _RichConsole

__all__: list[str] = []  # private to the command line

#: The name of the codecs error handler registered here (``"text".encode("ascii", errors=ERRORS)``).
ERRORS = "bearinglab-ascii"

# Characters the project writes, spelled the ASCII way. A superscript is written after a '^' that a run
# of superscripts shares (m² -> m^2, 10⁻⁶ -> 10^-6); the micro sign is 'u' as in the unit names that
# bearinglab.units reads (um), the Greek mu of a friction coefficient is 'mu'.
_SPELLING = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "eps", "ζ": "zeta", "η": "eta",
    "θ": "theta", "ϑ": "theta", "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu",
    "ξ": "xi", "π": "pi", "ρ": "rho", "σ": "sigma", "ς": "sigma", "τ": "tau", "υ": "upsilon",
    "φ": "phi", "ϕ": "phi", "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi", "Σ": "Sigma",
    "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
    "µ": "u", "°": "deg", "·": "*", "×": "x", "÷": "/", "−": "-", "–": "-", "—": "-", "‐": "-",
    "±": "+/-", "∓": "-/+", "≤": "<=", "≥": ">=", "≠": "!=", "≈": "~", "∼": "~", "∞": "inf",
    "√": "sqrt", "∑": "sum", "∂": "d", "∫": "int", "→": "->", "←": "<-", "↔": "<->", "⇒": "=>",
    "′": "'", "″": '"', "‘": "'", "’": "'", "“": '"', "”": '"', "«": '"', "»": '"',
    # rich's own overflow mark in a laid-out cell (a long option name in --help): one character for one,
    # so that the row keeps the width rich gave it
    "…": ".",
    "§": "section ", "¶": "par. ", "©": "(c)", "®": "(R)", "™": "(TM)", "•": "*", "●": "*", "○": "o",
    "✓": "ok", "✗": "x", "½": "1/2", "¼": "1/4", "¾": "3/4", "⅓": "1/3", "⅔": "2/3", "\u00a0": " ",
    "\u2009": " ", "\u202f": " ", "ß": "ss", "æ": "ae", "Æ": "AE", "ø": "o", "Ø": "O", "ð": "d",
    "þ": "th", "ł": "l", "Ł": "L",
}
_SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺⁽⁾ⁿ", "0123456789-+()n"))
_SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉₋₊", "0123456789-+"))
# Russian letters, by the common scientific transliteration (ISO 9 without diacritics)
_CYRILLIC = dict(zip("абвгдезийклмнопрстуфы", "abvgdezijklmnoprstufy"))
_CYRILLIC.update({"ё": "e", "ж": "zh", "х": "kh", "ц": "ts", "ч": "ch", "ш": "sh", "щ": "shch",
                  "ъ": "", "ь": "'", "э": "e", "ю": "yu", "я": "ya"})
_CYRILLIC.update({k.upper(): v.capitalize() for k, v in list(_CYRILLIC.items()) if v})
_SPELLING.update(_CYRILLIC)
# whole patterns before single characters: the header of a degrees-minutes-seconds column
_PATTERNS = {"D°M′S″": "DdM'S\""}
_DMS = re.compile(r"(?<=\d)°(?=\d)")  # 14°28'03.97" -> 14d28'03.97"

# a sample of the characters above: an encoding that holds them needs no spelling
_PROBE = "αβδΔκµμψθ°·×−≤≥²³⁻′″—…─│┌в"


def _box(char):
    """A box-drawing or block character as ASCII: horizontal lines '-', vertical '|', the rest '+'."""
    import unicodedata

    words = set(unicodedata.name(char, "").split())
    if "HORIZONTAL" in words and not words & {"VERTICAL", "UP", "DOWN"}:
        return "-"
    if "VERTICAL" in words and not words & {"HORIZONTAL", "LEFT", "RIGHT"}:
        return "|"
    return "#" if 0x2580 <= ord(char) <= 0x259F else "+"


def _spell_char(text, i):
    """The ASCII spelling of ``text[i]``, given its neighbours (a superscript run shares one '^')."""
    char = text[i]
    if char in _SUPERSCRIPTS:
        lead = "" if i > 0 and text[i - 1] in _SUPERSCRIPTS else "^"
        return lead + _SUPERSCRIPTS[char]
    if char in _SUBSCRIPTS:
        return _SUBSCRIPTS[char]
    if char == "°" and 0 < i < len(text) - 1 and text[i - 1].isdigit() and text[i + 1].isdigit():
        return "d"
    if char in _SPELLING:
        return _SPELLING[char]
    if 0x2500 <= ord(char) <= 0x259F:
        return _box(char)
    import unicodedata

    # a Latin letter with an accent (Sjoväll, Hamrock–Brewe's é): the letter without it
    base = "".join(c for c in unicodedata.normalize("NFKD", char) if not unicodedata.combining(c))
    return base if base and base.isascii() and base.isprintable() else "?"


def _holds(char, encoding):
    try:
        char.encode(encoding)
    except (UnicodeError, LookupError):
        return False
    return True


def ascii_spelling(text, encoding="ascii"):
    """``text`` with every character that ``encoding`` cannot hold spelled the ASCII way.

    Parameters
    ----------
    text : str
        What is to be written.
    encoding : str, optional
        The stream's encoding; ``"ascii"`` spells every character outside ASCII.

    Returns
    -------
    str
        ``text`` itself when the encoding holds it; else a string the encoding holds.

    Examples
    --------
    >>> ascii_spelling("α = 14°28′03″, δ_a ≤ 12 µm, M [N·mm], 10⁻⁶ m²/s")
    'alpha = 14d28\\'03", delta_a <= 12 um, M [N*mm], 10^-6 m^2/s'
    >>> ascii_spelling("µm, 20 °C", "cp1252")
    'µm, 20 °C'
    """
    try:
        text.encode(encoding)
        return text
    except UnicodeError:
        pass
    except LookupError:
        encoding = "ascii"
    for pattern, spelled in _PATTERNS.items():
        text = text.replace(pattern, spelled)
    return "".join(c if c.isascii() or _holds(c, encoding) else _spell_char(text, i)
                   for i, c in enumerate(text))


def _handler(exc):
    """The codecs error handler :data:`ERRORS`: the characters an encoding cannot hold, spelled."""
    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    spelled = "".join(_spell_char(exc.object, i) for i in range(exc.start, exc.end))
    return spelled, exc.end


codecs.register_error(ERRORS, _handler)


@functools.lru_cache(maxsize=16)
def needs_spelling(encoding):
    """Whether ``encoding`` cannot hold the project's characters (cp1252, ASCII, Latin-1: yes; UTF-8: no)."""
    try:
        _PROBE.encode(encoding or "ascii")
    except UnicodeError:
        return True
    except LookupError:
        return True
    return False


def setup_streams():
    """Set the error handler :data:`ERRORS` on ``sys.stdout`` and ``sys.stderr`` where their encoding cannot
    hold the project's characters, so that no write raises UnicodeEncodeError. A stream that cannot be
    reconfigured (not a text file of the io module) is left as it is."""
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name, None)
        if stream is None or not needs_spelling(getattr(stream, "encoding", None)):
            continue
        if getattr(stream, "errors", None) == ERRORS:
            continue
        try:
            stream.reconfigure(errors=ERRORS)
        except (AttributeError, ValueError, OSError):
            pass


def output_width():
    """The width of output that goes to a pipe or a file: ``$COLUMNS`` if it is a number, else 80."""
    columns = os.environ.get("COLUMNS", "")
    return int(columns) if columns.isdigit() and int(columns) > 0 else 80


class Console(_RichConsole):
    """A rich Console for the command line: its strings spelled for its stream's encoding before rich lays
    them out (so that a table stays aligned, :func:`ascii_spelling`), no emoji codes (``:x:`` stays
    ``:x:``), and, when it does not write to a terminal, as wide as :func:`output_width`."""

    def __init__(self, **kwargs):
        kwargs.setdefault("emoji", False)
        super().__init__(**kwargs)

    @property
    def size(self):
        size = _RichConsole.size.fget(self)
        if self._width is None and not self.is_terminal:
            return size._replace(width=output_width())
        return size

    @size.setter
    def size(self, new_size):
        _RichConsole.size.fset(self, new_size)

    def spelled(self, text):
        """``text`` as this console writes it: spelled for its stream's encoding (:func:`ascii_spelling`)."""
        return ascii_spelling(text, self.encoding) if needs_spelling(self.encoding) else text

    def render_str(self, text, **kwargs):
        if needs_spelling(self.encoding):
            text = ascii_spelling(text, self.encoding)
        return super().render_str(text, **kwargs)
