"""Keyword arguments that were renamed to the ``lrchain`` command's names for the same concept
(``sites`` for every lattice size, ``branch``, ``switch_off_time``, ``modulation_depth``): the old
name raises a TypeError naming the new one, never silently accepted."""

import functools


def renamed(table):
    """Decorator: calling the function with an old keyword of the config table ``table`` ("bright",
    "drive", "modulated", "dark": the table with the function's options, whose schema lists the
    renamed keys) raises TypeError naming the new one, and what changed besides the name; the
    signature and docstring are the function's own."""
    from ._lrchain import renamed_options

    renames = renamed_options(table)  # (old, new, "'new', <note>")

    def wrap(function):
        @functools.wraps(function)
        def call(*args, **kwargs):
            for old, new, replacement in renames:
                if old in kwargs:
                    raise TypeError(f"{function.__name__}() got the keyword argument '{old}', which is now "
                                    f"{replacement}; use {new}= (the lrchain command's name)")
            return function(*args, **kwargs)

        return call

    return wrap


def python_names(call):
    """``call()``, with an InvalidParameterError's parameter given its Python keyword's name. The jobs
    name their Config keys (t_end, switch_off_time), the Python keywords; a library check that still
    spells a key as its command-line option (the ring's packet-amplitude) has its hyphens read as
    underscores."""
    from .errors import InvalidParameterError

    try:
        return call()
    except InvalidParameterError as e:
        old = e.parameter
        if old is None:
            raise
        new = old.replace("-", "_")
        if new == old:
            raise
        message = str(e)
        if message.startswith(f"invalid {old}:"):
            message = f"invalid {new}:" + message[len(f"invalid {old}:"):]
        raise InvalidParameterError(message, new) from None


def checked_model(model):
    """``model`` if it is an :class:`lrchain.Model`, else InvalidParameterError naming ``model``."""
    from ._lrchain import Model
    from .errors import InvalidParameterError

    if not isinstance(model, Model):
        raise InvalidParameterError(f"invalid model: must be an lrchain.Model (lrchain.load_model(file or name)), "
                                    f"not {type(model).__name__}", "model")
    return model


def real_numbers(function):
    """Decorator: an argument of the function that is complex (a complex number, a numpy complex scalar
    or array, or a list/tuple holding one) raises InvalidParameterError naming it, before the call;
    numpy would otherwise drop the imaginary part with only a warning."""
    import inspect

    from ._lrchain import refuse_complex

    signature = inspect.signature(function)

    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            bound = signature.bind_partial(*args, **kwargs)
        except TypeError:
            return function(*args, **kwargs)  # the function's own message for a wrong call
        for name, value in bound.arguments.items():
            if signature.parameters[name].kind is inspect.Parameter.VAR_KEYWORD:
                for key, item in value.items():
                    refuse_complex(item, key)
            else:
                refuse_complex(value, name)
        return function(*args, **kwargs)

    return call


def schema_options(job):
    """The options of ``job`` ("bright", "regime map", ...: ``_lrchain.job_names()``) that Python
    offers, keyword -> option dict, from the job's one schema (lrchain/jobs/option_schema.hpp): the
    same defaults, ranges and documentation as the ``lrchain`` command's help."""
    from ._lrchain import job_options

    return {o["python"]: o for o in job_options(job) if o["python"]}


def schema_line(option):
    """One option as a docstring shows it: ````keyword``: doc [range; default D]``."""
    if option["default"] is not None:
        value = "default " + option["default_text"]
    else:
        value = "default: " + (option["default_text"] or "none")
    facts = "; ".join(part for part in (option["range"], value) if part)
    return f"``{option['python']}``: {option['doc']} [{facts}]"


def documented(*sections):
    """Decorator: appends to the function's docstring, per (job, heading) in ``sections``, the heading
    and one line per keyword of that job's schema the function takes (schema_line)."""
    import inspect

    def wrap(function):
        taken = inspect.signature(function).parameters
        text = function.__doc__ or ""
        for job, heading in sections:
            lines = [schema_line(o) for name, o in schema_options(job).items() if name in taken]
            text += f"\n\n    {heading}\n\n" + "\n".join(f"    - {line}" for line in lines)
        function.__doc__ = text
        return function

    return wrap
