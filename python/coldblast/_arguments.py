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
