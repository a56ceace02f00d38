"""Immutable result objects: named fields, each value beside its error bound ``NAME_error``."""

import collections

from . import _numbers


class _Result:
    """Shared behaviour of the results: ``to_dict()`` and a short ``repr``."""

    __slots__ = ()

    def to_dict(self):
        """The fields as a dict, in order (values as they are: float, mpf, Decimal or str)."""
        return dict(zip(self._fields, self))

    def __repr__(self):
        parts = []
        fields = self._fields
        for name, value in zip(fields, self):
            if name.endswith("_error") or value is None:
                continue
            err = f"{name}_error"
            if err in fields:
                bound = getattr(self, err)
                parts.append(f"{name}={value!s} (error <= {bound!s})")
            else:
                parts.append(f"{name}={value!r}")
        return f"{type(self).__name__}({', '.join(parts)})"


def _make(name, fields, doc, bits_index=1, numbers_from=None):
    base = collections.namedtuple("_" + name, fields)
    cls = type(name, (_Result, base), {"__slots__": (), "__doc__": doc, "__module__": "moving_hertz"})
    numeric = tuple(i for i, f in enumerate(base._fields) if f not in _LABELS)
    cls._numeric = numeric
    return cls


#: Fields that are labels or counts, never converted.
_LABELS = {"precision", "bits", "route", "major_axis", "iterations", "work"}


def build(cls, t, text_mode, as_text):
    """The result of class ``cls`` from the native tuple ``t``; numbers given as text are
    turned into mpf/Decimal at the working precision unless ``as_text``."""
    if text_mode and not as_text:
        bits = t[1]
        t = list(t)
        for i in cls._numeric:
            t[i] = _numbers.number(t[i], bits)
    return tuple.__new__(cls, t)


Rayleigh = _make(
    "Rayleigh",
    "precision bits m1 cR_over_c2 cR_over_c1 roots",
    """The Rayleigh cubic's roots (section 3 of the paper): ``m1 = (c_R/c2)^2`` (the Rayleigh
    root), ``cR_over_c2``, ``cR_over_c1`` and ``roots``, the three roots of
    (1-ν)x³ - 8(1-ν)x² + 8(2-ν)x - 8 = 0 as (real part, imaginary part) pairs, each within a few
    units of the working precision (``bits``).""",
)

Ellipse = _make(
    "Ellipse",
    "precision bits route k k_error e e_error major_axis I1 I1_error I2 I2_error iterations",
    """The contact ellipse's shape, the root of (33) I2(k)/I1(k) = A1/B1: ``k = b/a`` (relative
    error bound ``k_error``), the eccentricity ``e`` (absolute bound ``e_error``), which axis is
    the major one (``major_axis``: "along" or "across" the motion), I1 and I2 of (34) in the
    normalisation of (37) with relative bounds, the route of the last evaluation and the
    number of evaluations at the working precision.""",
)

Contact = _make(
    "Contact",
    "precision bits route a a_error b b_error k k_error e e_error major_axis "
    "p0 p0_error d0 d0_error load load_error",
    """The moving-punch Hertz solution of section 4: the semi-axes ``a`` (along the motion) and
    ``b`` (across), ``k = b/a``, the eccentricity ``e`` (absolute bound), the central pressure
    ``p0`` (30), the approach ``d0`` (32) and the load (31), each with a relative error bound;
    units as given (SI in, SI out: m, Pa, N).""",
)

Integrals = _make(
    "Integrals",
    "precision bits route I1 I1_error I2 I2_error dI1_dk dI1_dk_error dI2_dk dI2_dk_error "
    "J0 J0_error work",
    """I1, I2 of (34) in the normalisation of (37) (π times the paper's), with their relative
    error bounds; ``dI1_dk``, ``dI2_dk`` (when asked for) and ``J0`` of (32) (when asked for),
    else ``None``; the route that ran and its work (evaluations or terms).""",
)
