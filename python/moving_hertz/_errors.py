"""The exceptions of moving_hertz.

Every error the package raises is a :class:`MovingHertzError`:

* :class:`DomainError` (also a ``ValueError``): an input outside its domain (or outside the
  domain of the method that serves it), not a number of an accepted type, NaN or infinite,
  text that does not parse, or a method that cannot give what was asked for (``argument`` is
  then ``"method"``); raised before any work where the inputs decide it, naming the argument
  (``argument``) and quoting the value as given.
* :class:`ConvergenceError` (also an ``ArithmeticError``): an iteration or a series did not
  reach its tolerance within its work bound.
* :class:`ToleranceError`: a requested accuracy that no method and precision on offer reaches.
* :class:`MovingHertzError` itself: an internal error (a bug: a panic inside the Rust crate,
  caught before it could reach the interpreter, or a state the crate rules out), with its
  message.
"""

__all__ = ["MovingHertzError", "DomainError", "ConvergenceError", "ToleranceError"]


class MovingHertzError(Exception):
    """Base class of every error of moving_hertz; ``argument`` names the input concerned
    (a keyword of the call) or is ``None``."""

    def __init__(self, message, argument=None):
        super().__init__(message)
        self.argument = argument


class DomainError(MovingHertzError, ValueError):
    """An input outside its domain (or not a number of an accepted type), raised before any
    work; ``argument`` is the keyword it was given as."""


class ConvergenceError(MovingHertzError, ArithmeticError):
    """An iteration or series that did not reach its tolerance within its work bound."""


class ToleranceError(MovingHertzError):
    """A requested tolerance that no method and precision on offer can reach."""
