"""Numbers in and out of moving_hertz: one rule, stated here and in docs/python.md.

In (:func:`scalar`): a ``float`` is taken as the binary value it is; ``int``, ``str`` (decimal
text such as ``"0.9999999999"`` or ``"1e-12"``, or a fraction ``"1/3"``), ``fractions.Fraction``,
``decimal.Decimal``, ``mpmath.mpf`` and numpy scalars are taken exactly, as text, and rounded
once to the working precision by the crate's parsers (as the command-line tool's arguments
are: the gap 1 - M_R is formed exactly from the text of a speed). NaN, infinities, ``bool``,
``None`` and any other type raise :class:`DomainError` before any work. A negative zero is
zero (valid where zero is: ν, M_R; refused where a positive value is needed).

Out (:func:`number`): at ``precision="f64"`` every value and bound is a Python ``float``; above
it, an ``mpmath.mpf`` at the working precision (53, 106 or the MPFR bits) when mpmath can be
imported, else a ``decimal.Decimal`` carrying every digit the crate printed; with
``as_text=True``, the decimal text itself, digit for digit the command-line tool's ``--json``.
"""

import decimal
import fractions
import math
import numbers

from ._errors import DomainError

try:  # optional: high-precision results as mpmath.mpf
    import mpmath as _mpmath
except ImportError:  # pragma: no cover - exercised by the Decimal fallback test
    _mpmath = None

ACCEPTED = "a float, int, str, fractions.Fraction, decimal.Decimal or mpmath.mpf"


def _is_mpf(x):
    t = type(x)
    return t.__name__ == "mpf" and t.__module__.startswith("mpmath")


def _refuse(name, x, why):
    raise DomainError(f"{name} = {x!r} {why}", name)


def scalar(x, name):
    """``x`` as the native module takes it: a finite float, or exact text."""
    t = type(x)
    if t is float:
        if not math.isfinite(x):
            _refuse(name, x, "is not finite")
        return x
    if t is str:
        return x
    if t is int:
        return str(x)
    if x is None or isinstance(x, bool):
        _refuse(name, x, f"is not a number ({ACCEPTED})")
    if isinstance(x, fractions.Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, decimal.Decimal):
        if not x.is_finite():
            _refuse(name, x, "is not finite")
        return str(x)
    if _is_mpf(x):
        if not _mpmath.isfinite(x):
            _refuse(name, x, "is not finite")
        man, exp = x.man_exp
        return str(man << exp) if exp >= 0 else f"{man}/{1 << -exp}"
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, numbers.Real) and hasattr(x, "as_integer_ratio"):
        f = float(x)
        if not math.isfinite(f):
            _refuse(name, x, "is not finite")
        if f == x:  # numpy float16/32/64: exactly a float
            return f
        p, q = x.as_integer_ratio()
        return f"{p}/{q}"
    _refuse(name, x, f"is not a number ({ACCEPTED})")


def text(x, name):
    """``x`` as exact text (a float as its exact decimal expansion)."""
    s = scalar(x, name)
    return str(decimal.Decimal(s)) if type(s) is float else s


def precision(p):
    """``"f64"``, ``"dd"`` or an int number of MPFR bits (24 to 32768) as the native text."""
    if isinstance(p, str):
        return p
    if isinstance(p, numbers.Integral) and not isinstance(p, bool):
        return str(int(p))
    raise DomainError(f"precision = {p!r} is not 'f64', 'dd' or an int number of bits", "precision")


def number(s, bits):
    """The decimal text ``s`` at ``bits`` bits: ``mpmath.mpf`` when mpmath can be imported,
    else ``decimal.Decimal`` (every digit); ``None`` stays ``None``."""
    if s is None or s == "":
        return None
    if _mpmath is None:
        return decimal.Decimal(s)
    with _mpmath.workprec(bits):
        return _mpmath.mpf(s)
