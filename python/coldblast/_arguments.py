"""Checks of Python arguments before they reach the library, in the CLI's words (``--name = value ...``)."""
import numpy as np


def integer(value, name):
    """``value`` as an int if it is a Python or numpy integer (not a bool); else ValueError naming ``name``.

    ``int(2.5)`` would silently be 2: a float, even an integral one, is refused, as the CLI refuses
    ``--d 2.5``.
    """
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name} = {value!r} is not an integer")
    return int(value)


def number(value, name):
    """``value`` as a float if it is a real number (int, float or numpy; not a bool or a string)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} = {value!r} is not a number")
    return float(value)


def flag(value, name):
    """``value`` if it is True or False (or a numpy bool): ``bool("no")`` would be True."""
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{name} = {value!r} is not True or False")
    return bool(value)


def text(value, name):
    """``value`` if it is a string: ``str(None)`` would be the name "None"."""
    if not isinstance(value, str):
        raise ValueError(f"{name} = {value!r} is not a string")
    return value


def names(value, name):
    """A list of names from None (none), a string ("R_imp,C_imp", as on the command line) or a list of strings.

    ``list("R_imp")`` would be the letters R, _, i, m, p.
    """
    if value is None:
        return []
    if isinstance(value, str):
        return value.split(",")
    if isinstance(value, (list, tuple)) and all(isinstance(v, str) for v in value):
        return list(value)
    raise ValueError(f"{name} = {value!r} is not a name or a list of names")
