"""Exceptions raised by lrchain.

Invalid input raises :class:`InvalidParameterError` (a :class:`ValueError`) whose message names the
parameter and its valid range; ``err.parameter`` holds the name. A computation that fails for
numerical reasons (an integration blowing up, Newton not converging) raises
:class:`NumericalFailure`. A report of ``lrchain.reproduce`` with a failed step raises
:class:`StepsFailed`. Ctrl-C (SIGINT) during a long computation raises ``KeyboardInterrupt``.
"""


class InputError(ValueError):
    """Bad input (an option, a file): the message says what is allowed."""


class InvalidParameterError(InputError):
    """Invalid value of a named parameter; ``parameter`` is its name."""

    def __init__(self, message, parameter=None):
        super().__init__(message)
        self.parameter = parameter


class NumericalFailure(RuntimeError):
    """A computation that failed for numerical reasons (blow-up, Newton not converging)."""


class StepsFailed(RuntimeError):
    """``lrchain.reproduce`` wrote its report but some of its steps failed (exit code 1); ``result`` is
    the :class:`lrchain.ReproduceResult` (the report says why each failed)."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result
