"""Type stubs of moving_hertz.dask."""

from typing import Any, Optional

import numpy as np

from . import ArrayIn, Method, Number, Precision

def chunk_points(precision: Precision) -> int: ...
def numbers(computed: np.ndarray, precision: Precision) -> np.ndarray: ...
def sweep_ellipses(nu: ArrayIn, *, speed: Optional[ArrayIn] = ..., gap: Optional[ArrayIn] = ...,
                   ratio: Optional[ArrayIn] = ..., precision: Precision = ...,
                   method: Method = ..., chunk: Optional[int] = ..., threads: int = ...) -> Any: ...
def sweep_contacts(nu: ArrayIn, *, speed: Optional[ArrayIn] = ..., gap: Optional[ArrayIn] = ...,
                   velocity: Optional[ArrayIn] = ..., radius_along: Optional[ArrayIn] = ...,
                   radius_across: Optional[ArrayIn] = ..., load: Optional[ArrayIn] = ...,
                   approach: Optional[ArrayIn] = ..., shear_modulus: Optional[ArrayIn] = ...,
                   youngs_modulus: Optional[ArrayIn] = ..., density: Optional[ArrayIn] = ...,
                   precision: Precision = ...,
                   method: Method = ..., chunk: Optional[int] = ..., threads: int = ...) -> Any: ...
