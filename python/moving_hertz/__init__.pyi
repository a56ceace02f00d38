"""Type stubs of moving_hertz (the docstrings are in the package)."""

import decimal
import fractions
from typing import Any, Callable, Literal, NamedTuple, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

Number = Union[float, int, str, fractions.Fraction, decimal.Decimal, Any]  # Any: mpmath.mpf
Value = Union[float, decimal.Decimal, str, Any]  # float at f64; mpf, Decimal or str above
Precision = Union[Literal["f64", "dd"], int]
Method = Literal["auto", "series", "adaptive", "adaptive-subtracted", "fixed"]
ArrayIn = Union[Number, npt.ArrayLike]
Progress = Union[None, bool, Callable[[int, int], Any]]

ROUTES: Tuple[str, ...]
__version__: str

class MovingHertzError(Exception):
    argument: Optional[str]
    def __init__(self, message: str, argument: Optional[str] = ...) -> None: ...

class DomainError(MovingHertzError, ValueError): ...
class ConvergenceError(MovingHertzError, ArithmeticError): ...
class ToleranceError(MovingHertzError): ...

class Rayleigh(NamedTuple):
    precision: str
    bits: int
    m1: Value
    cR_over_c2: Value
    cR_over_c1: Value
    roots: Tuple[Tuple[Value, Value], ...]
    def to_dict(self) -> dict: ...

class Ellipse(NamedTuple):
    precision: str
    bits: int
    route: str
    k: Value
    k_error: Value
    e: Value
    e_error: Value
    major_axis: str
    I1: Value
    I1_error: Value
    I2: Value
    I2_error: Value
    iterations: int
    def to_dict(self) -> dict: ...

class Contact(NamedTuple):
    precision: str
    bits: int
    route: str
    a: Value
    a_error: Value
    b: Value
    b_error: Value
    k: Value
    k_error: Value
    e: Value
    e_error: Value
    major_axis: str
    p0: Value
    p0_error: Value
    d0: Value
    d0_error: Value
    load: Value
    load_error: Value
    def to_dict(self) -> dict: ...

class Integrals(NamedTuple):
    precision: str
    bits: int
    route: str
    I1: Value
    I1_error: Value
    I2: Value
    I2_error: Value
    dI1_dk: Optional[Value]
    dI1_dk_error: Optional[Value]
    dI2_dk: Optional[Value]
    dI2_dk_error: Optional[Value]
    J0: Optional[Value]
    J0_error: Optional[Value]
    work: int
    def to_dict(self) -> dict: ...

class SweepResult:
    fields: Tuple[str, ...]
    ok: npt.NDArray[np.bool_]
    messages: npt.NDArray[np.object_]
    route: npt.NDArray[np.int8]
    precision: str
    bits: int
    @property
    def shape(self) -> Tuple[int, ...]: ...
    def to_dict(self) -> dict: ...
    def __getattr__(self, name: str) -> np.ma.MaskedArray: ...

def rayleigh(nu: Number, *, precision: Precision = ..., as_text: bool = ...) -> Rayleigh: ...
def solve_ellipse(nu: Number, *, speed: Optional[Number] = ..., gap: Optional[Number] = ...,
                  ratio: Optional[Number] = ..., precision: Precision = ...,
                  method: Method = ..., as_text: bool = ...) -> Ellipse: ...
def solve_contact(nu: Number, *, speed: Optional[Number] = ..., gap: Optional[Number] = ...,
                  velocity: Optional[Number] = ..., radius_along: Optional[Number] = ...,
                  radius_across: Optional[Number] = ..., load: Optional[Number] = ...,
                  approach: Optional[Number] = ..., shear_modulus: Optional[Number] = ...,
                  youngs_modulus: Optional[Number] = ..., density: Optional[Number] = ...,
                  precision: Precision = ..., method: Method = ...,
                  as_text: bool = ...) -> Contact: ...
def integrals(nu: Number, *, speed: Optional[Number] = ..., gap: Optional[Number] = ...,
              k: Optional[Number] = ..., precision: Optional[Precision] = ...,
              tol: Optional[Number] = ..., method: Method = ..., derivatives: bool = ...,
              j0: bool = ..., as_text: bool = ...) -> Integrals: ...
def symbolic_coefficients(n: int, *, format: str = ...) -> str: ...
def symbolic_moments(n: int, *, format: str = ...) -> str: ...
def sweep_ellipses(nu: ArrayIn, *, speed: Optional[ArrayIn] = ..., gap: Optional[ArrayIn] = ...,
                   ratio: Optional[ArrayIn] = ..., precision: Precision = ...,
                   method: Method = ..., threads: Optional[int] = ..., progress: Progress = ...,
                   as_text: bool = ...) -> SweepResult: ...
def sweep_contacts(nu: ArrayIn, *, speed: Optional[ArrayIn] = ..., gap: Optional[ArrayIn] = ...,
                   velocity: Optional[ArrayIn] = ..., radius_along: Optional[ArrayIn] = ...,
                   radius_across: Optional[ArrayIn] = ..., load: Optional[ArrayIn] = ...,
                   approach: Optional[ArrayIn] = ..., shear_modulus: Optional[ArrayIn] = ...,
                   youngs_modulus: Optional[ArrayIn] = ..., density: Optional[ArrayIn] = ...,
                   precision: Precision = ...,
                   method: Method = ..., threads: Optional[int] = ..., progress: Progress = ...,
                   as_text: bool = ...) -> SweepResult: ...
def sweep_integrals(nu: Number, *, speed: Optional[Number] = ..., gap: Optional[Number] = ...,
                    k: Optional[ArrayIn] = ..., precision: Precision = ...,
                    tol: Optional[Number] = ..., method: Method = ..., derivatives: bool = ...,
                    j0: bool = ..., threads: Optional[int] = ..., progress: Progress = ...,
                    as_text: bool = ...) -> SweepResult: ...
