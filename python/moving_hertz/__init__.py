"""moving_hertz: the Hertz contact problem for a rigid punch sliding without friction below the
Rayleigh wave speed over an elastic half-space, at f64, double-double and MPFR precision.

Python bindings of the Rust crate ``moving-hertz``, after the paper "Hertz problem for a rigid
punch moving across the surface of a semi-infinite elastic solid" (equation numbers below are
the paper's; docs/theory.md of the repository states every formula). Every number comes from
the crate; every result carries a bound on its error.

Conventions: the load moves along x; ``a`` is the semi-axis along the motion, ``b`` across,
``k = b/a``; A1 = 1/(2 R1) is the curvature along the motion, B1 = 1/(2 R2) across it, and
``ratio = A1/B1 = R2/R1``. Speeds are Rayleigh Mach numbers ``speed = M_R = V/c_R`` in [0, 1),
or their gap ``gap = 1 - M_R`` in (0, 1] for speeds near c_R.

Numbers in and out follow one rule (:mod:`moving_hertz._numbers`): floats are taken as the
binary values they are; int, str, Fraction, Decimal and mpmath.mpf exactly. Results are floats
at ``precision="f64"``; above it ``mpmath.mpf`` at the working precision (``decimal.Decimal``
without mpmath); ``as_text=True`` gives the decimal text of the command-line tool's ``--json``.
``precision`` is ``"f64"``, ``"dd"`` (double-double, 106 bits) or an int number of MPFR bits
(24 to 32768).
"""

from . import _native, _numbers, _results, _sweeps
from ._errors import ConvergenceError, DomainError, MovingHertzError, ToleranceError
from ._results import Contact, Ellipse, Integrals, Rayleigh
from ._sweeps import ROUTES, SweepResult

__all__ = [
    "rayleigh", "solve_ellipse", "solve_contact", "integrals", "symbolic_coefficients",
    "symbolic_moments", "sweep_ellipses", "sweep_contacts", "sweep_integrals",
    "Rayleigh", "Ellipse", "Contact", "Integrals", "SweepResult", "ROUTES",
    "MovingHertzError", "DomainError", "ConvergenceError", "ToleranceError",
]

__version__ = "0.1.0"

_scalar = _numbers.scalar
_ellipse_f64 = _native.ellipse_f64
_F = float


def _speed(speed, gap):
    """``(value, "speed" | "gap")``: exactly one of the two."""
    if (speed is None) == (gap is None):
        raise DomainError("give exactly one of speed= (M_R) and gap= (1 - M_R)", "speed")
    return (speed, "speed") if gap is None else (gap, "gap")


def _required(x, name):
    if x is None:
        raise DomainError(f"{name} is required", name)
    return x


def rayleigh(nu, *, precision="f64", as_text=False):
    """The roots of the Rayleigh cubic (section 3 of the paper) for Poisson's ratio ``nu``.

    ``nu``: Poisson's ratio, -1 < ν <= 1/2 (dimensionless). Returns :class:`Rayleigh`:
    ``m1 = (c_R/c2)^2``, ``cR_over_c2``, ``cR_over_c1`` and the three ``roots`` of
    (1-ν)x³ - 8(1-ν)x² + 8(2-ν)x - 8 = 0, x = (V/c2)², as (real, imaginary) pairs; each within
    4 units of the working precision's last place.
    """
    t = _native.rayleigh(_numbers.precision(precision), _scalar(nu, "nu"), as_text)
    text = as_text or t[1] != 53 or t[0] != "f64"
    head = _results.build(_Pre, t[:5], text, as_text)
    roots = tuple(zip(*(iter(t[5:]),) * 2))
    if text and not as_text:
        roots = tuple((_numbers.number(r, t[1]), _numbers.number(i, t[1])) for r, i in roots)
    return tuple.__new__(Rayleigh, (*head, roots))


_Pre = _results._make("_Pre", "precision bits m1 cR_over_c2 cR_over_c1", "")


def solve_ellipse(nu, *, speed=None, gap=None, ratio=None, precision="f64", method="auto",
                  as_text=False):
    """The shape of the contact ellipse: the root k = b/a of (33), I2(k)/I1(k) = A1/B1.

    ``nu``: Poisson's ratio, -1 < ν <= 1/2. ``speed``: M_R = V/c_R in [0, 1), or ``gap``:
    1 - M_R in (0, 1] (exactly one; text keeps every digit of a speed near c_R). ``ratio``:
    the curvature ratio A1/B1 = R2/R1 > 0, within [1e-100, 1e100] (all dimensionless).
    ``method``: "auto" (the fixed rules where they apply, else adaptive quadrature),
    "adaptive" or "fixed". Returns :class:`Ellipse`; ``k`` to a few units of the working
    precision's last place, within its bound ``k_error`` (relative), ``e`` within
    ``e_error`` (absolute). Raises :class:`DomainError` before any work for an input out of
    its domain, :class:`ConvergenceError` if the solve does not converge.
    """
    if (type(speed) is _F and type(nu) is _F and type(ratio) is _F and gap is None
            and precision == "f64" and not as_text):  # floats: the result made natively
        return _ellipse_f64(nu, speed, ratio, method)
    value, kind = _speed(speed, gap)
    t = _native.ellipse(_numbers.precision(precision), _scalar(nu, "nu"), _scalar(value, kind),
                        kind, _scalar(_required(ratio, "ratio"), "ratio"), method, as_text)
    return _results.build(Ellipse, t, as_text or t[0] != "f64", as_text)


def _contact_args(speed, gap, velocity, load, approach, shear_modulus, youngs_modulus,
                  density):
    """``(kind, speed, loading, size, modulus_kind, modulus)`` of a contact problem: exactly
    one speed, one size and one modulus, and a density with a velocity only."""
    given = [(n, v) for n, v in (("speed", speed), ("gap", gap), ("velocity", velocity))
             if v is not None]
    if len(given) != 1:
        raise DomainError("give exactly one of speed= (M_R), gap= (1 - M_R) and velocity= "
                          "(V in m/s)", "speed")
    (kind, value), = given
    if (load is None) == (approach is None):
        raise DomainError("give exactly one of load= (P) and approach= (d0)", "load")
    if (shear_modulus is None) == (youngs_modulus is None):
        raise DomainError("give exactly one of shear_modulus= (mu) and youngs_modulus= (E)",
                          "shear_modulus")
    if (density is None) == (kind == "velocity"):
        raise DomainError("density= (kg/m^3) goes with velocity= (V in m/s), and only with it",
                          "density")
    loading, size = ("load", load) if approach is None else ("approach", approach)
    modulus_kind, modulus = (("shear", shear_modulus) if youngs_modulus is None
                             else ("youngs", youngs_modulus))
    return kind, value, loading, size, modulus_kind, modulus


def solve_contact(nu, *, speed=None, gap=None, velocity=None, radius_along=None,
                  radius_across=None, load=None, approach=None, shear_modulus=None,
                  youngs_modulus=None, density=None, precision="f64", method="auto",
                  as_text=False):
    """The moving-punch Hertz contact of section 4: the ellipse (33), then a, b, p0, d0 and
    the load in closed form ((28)-(32), as corrected in docs/errata.md).

    ``nu`` as for :func:`solve_ellipse`; the speed as exactly one of ``speed`` (M_R),
    ``gap`` (1 - M_R) or ``velocity`` (V in m/s, below the Rayleigh speed c_R of the solid,
    which needs ``density``); the stiffness as exactly one of ``shear_modulus`` μ and
    ``youngs_modulus`` E (> 0, Pa; μ = E/(2(1 + ν))); ``density`` ρ (> 0, kg/m³; with
    ``velocity`` only: c2 = √(μ/ρ), c_R from the Rayleigh root of section 3, by the crate's
    ``Solid``); ``radius_along`` R1 and ``radius_across`` R2, the punch's radii of curvature
    along and across the motion (> 0, m); exactly one of ``load`` P (> 0, N) and
    ``approach`` d0 (> 0, m). SI in, SI out (any consistent units without ``velocity``).
    Returns :class:`Contact`, every quantity to a few units of the working precision's last
    place, each within its bound. Raises :class:`DomainError` before any work for an input
    out of its domain (a velocity at or above c_R names c_R).
    """
    kind, value, loading, size, modulus_kind, modulus = _contact_args(
        speed, gap, velocity, load, approach, shear_modulus, youngs_modulus, density)
    t = _native.contact(
        _numbers.precision(precision), _scalar(nu, "nu"), _scalar(value, kind), kind,
        _scalar(_required(radius_along, "radius_along"), "radius_along"),
        _scalar(_required(radius_across, "radius_across"), "radius_across"),
        loading, _scalar(size, loading), _scalar(modulus, modulus_kind + "_modulus"),
        modulus_kind, None if density is None else _scalar(density, "density"), method,
        as_text)
    return _results.build(Contact, t, as_text or t[0] != "f64", as_text)


def integrals(nu, *, speed=None, gap=None, k=None, precision=None, tol=None, method="auto",
              derivatives=False, j0=False, as_text=False):
    """I1 and I2 of (34) in the normalisation of (37) at the axis ratio ``k``.

    ``nu``, ``speed`` | ``gap`` as for :func:`solve_ellipse`; ``k`` = b/a > 0. ``precision``
    (default "f64"): the working precision; ``tol``: a relative tolerance (decimal text or a
    number, any exponent: "1e-1000"), alone the lowest precision that reaches it is chosen
    (the inputs held exactly), with ``precision`` it is met there or :class:`ToleranceError`
    is raised. ``method``: "auto", "series", "adaptive", "adaptive-subtracted" (k <= 1) or
    "fixed" (k <= 2^180). ``derivatives``: also dI1/dk, dI2/dk; ``j0``: also J0 of (32).
    Returns :class:`Integrals`, each value within its relative bound.
    """
    value, kind = _speed(speed, gap)
    tol_text = None if tol is None else _numbers.text(tol, "tol")
    prec = None if precision is None else _numbers.precision(precision)
    t = _native.integrals_of(prec, _scalar(nu, "nu"), _scalar(value, kind), kind,
                             _scalar(_required(k, "k"), "k"), method, tol_text, derivatives, j0,
                             as_text)
    return _results.build(Integrals, t, as_text or t[0] != "f64", as_text)


def symbolic_coefficients(n, *, format="sympy"):
    """The coefficients f_n = F_n(ν) xⁿ (x = M2²), n = 0 … ``n`` (1 <= n <= 120), of the series
    (35)-(36) of the Green's function, exact rational functions of ν, as text: ``format``
    "sympy" (``name = expression`` lines for ``sympy.sympify``) or "text"."""
    return _native.symbolic("coefficients", _count(n), format)


def symbolic_moments(n, *, format="sympy"):
    """α_n, β_n, γ_n, δ_n(e²), n = 0 … ``n`` (1 <= n <= 150), of (40) and (42):
    L_n = α_n K + β_n E, M_n = γ_n K + δ_n E, e² = 1 - k², exact rational functions of e², as
    text in ``format`` ("sympy" or "text")."""
    return _native.symbolic("moments", _count(n), format)


def _count(n):
    if isinstance(n, bool) or not isinstance(n, int) or n < 0:
        raise DomainError(f"n = {n!r} is not a non-negative int", "n")
    return n


def sweep_ellipses(nu, *, speed=None, gap=None, ratio=None, precision="f64", method="auto",
                   threads=None, progress=None, as_text=False):
    """:func:`solve_ellipse` over arrays: ``nu``, ``speed`` | ``gap`` and ``ratio`` are scalars
    or array-likes (lists, numpy arrays of any float or int dtype, object arrays of the
    accepted numbers) that broadcast together as numpy does.

    The points run in parallel on every core (``threads``: a pool of that many threads) with
    the GIL released, sharing set-ups and starting each root from its neighbours'
    (``moving_hertz::sweep::ellipses``); each point's result is bit for bit the one its block
    gives in any sweep of the same flattened points. ``progress``: a callable
    ``(done, total)`` called between chunks, or ``True`` for a tqdm bar. Returns a
    :class:`SweepResult` with ``k``, ``e``, ``I1``, ``I2`` and their ``_error`` bounds,
    ``iterations``, ``route``, ``ok``, ``messages``: a bad point is a masked entry with its
    message, never an exception for the whole sweep.
    """
    value, kind = _speed(speed, gap)
    shape, cols = _sweeps.columns({"nu": nu, kind: value, "ratio": _required(ratio, "ratio")})
    prec = _numbers.precision(precision)
    info = _native.precision_info(prec)
    cb, bar = _sweeps.progress_callback(progress)
    try:
        native = _native.sweep_ellipses(prec, cols[0], cols[1], kind, cols[2], method,
                                        threads, cb, as_text)
    finally:
        if bar is not None:
            bar.close()
    fields = ("k", "e", "I1", "I2")
    return _sweeps.result(native, shape, fields, fields, "iterations", info, as_text)


def sweep_contacts(nu, *, speed=None, gap=None, velocity=None, radius_along=None,
                   radius_across=None, load=None, approach=None, shear_modulus=None,
                   youngs_modulus=None, density=None, precision="f64", method="auto",
                   threads=None, progress=None, as_text=False):
    """:func:`solve_contact` over arrays that broadcast together (as :func:`sweep_ellipses`):
    the same inputs, each a scalar or an array — exactly one of ``speed``, ``gap`` and
    ``velocity`` (m/s, with ``density``), one of ``shear_modulus`` and ``youngs_modulus``,
    one of ``load`` and ``approach`` — each point made as :func:`solve_contact` makes it and
    solved by ``moving_hertz::sweep::contacts`` (a velocity at or above c_R is a masked point
    whose message names c_R). Returns a :class:`SweepResult` with ``a``, ``b``, ``k``, ``e``,
    ``p0``, ``d0``, ``load`` and their bounds, ``iterations``, ``route``, ``ok``,
    ``messages``."""
    kind, value, loading, size, modulus_kind, modulus = _contact_args(
        speed, gap, velocity, load, approach, shear_modulus, youngs_modulus, density)
    named = {"nu": nu, kind: value,
             "radius_along": _required(radius_along, "radius_along"),
             "radius_across": _required(radius_across, "radius_across"),
             loading: size, modulus_kind + "_modulus": modulus}
    if density is not None:
        named["density"] = density
    shape, cols = _sweeps.columns(named)
    prec = _numbers.precision(precision)
    info = _native.precision_info(prec)
    cb, bar = _sweeps.progress_callback(progress)
    try:
        native = _native.sweep_contacts(
            prec, cols[0], cols[1], kind, cols[2], cols[3], loading, cols[4], cols[5],
            modulus_kind, cols[6] if density is not None else None, method, threads, cb,
            as_text)
    finally:
        if bar is not None:
            bar.close()
    fields = ("a", "b", "k", "e", "p0", "d0", "load")
    return _sweeps.result(native, shape, fields, fields, "iterations", info, as_text)


def sweep_integrals(nu, *, speed=None, gap=None, k=None, precision="f64", tol=None,
                    method="auto", derivatives=False, j0=False, threads=None, progress=None,
                    as_text=False):
    """:func:`integrals` at one speed (``nu``, ``speed`` | ``gap`` scalars) over an array of
    ``k`` (``moving_hertz::sweep::integrals``, one set-up per block). Returns a
    :class:`SweepResult` with ``I1``, ``I2`` (and ``dI1_dk``, ``dI2_dk``, ``J0`` when asked
    for) with their bounds, ``work``, ``route``, ``ok``, ``messages``."""
    value, kind = _speed(speed, gap)
    shape, cols = _sweeps.columns({"k": _required(k, "k")})
    prec = _numbers.precision(precision)
    info = _native.precision_info(prec)
    tol_text = None if tol is None else _numbers.text(tol, "tol")
    cb, bar = _sweeps.progress_callback(progress)
    try:
        native = _native.sweep_integrals(prec, _scalar(nu, "nu"), _scalar(value, kind), kind,
                                         cols[0], method, tol_text, derivatives, j0, threads,
                                         cb, as_text)
    finally:
        if bar is not None:
            bar.close()
    keep = {"I1", "I2"} | ({"dI1_dk", "dI2_dk"} if derivatives else set()) | ({"J0"} if j0 else set())
    fields = ("I1", "I2", "dI1_dk", "dI2_dk", "J0")
    return _sweeps.result(native, shape, fields, keep, "work", info, as_text)
