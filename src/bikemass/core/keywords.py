"""One keyword vocabulary: a renamed keyword still works for a while, with a DeprecationWarning.

The public functions name a thing the same way everywhere (``bicycle=``, ``stiffness=``); where
one used another name before (``sensitivity(S=...)``, ``uncertainty(bike=...)``) the old name is
still accepted, said to be deprecated, and passed on under the new one.
"""

import functools
import warnings


def renamed_keywords(**renames):
    """Decorator: accept each ``old=new`` keyword of ``renames`` as the old name of keyword ``new``.

    Calling with the old name warns (:class:`DeprecationWarning`, naming the new one) and passes the
    value on as ``new``; giving both is a :class:`TypeError`, as for any keyword given twice. The
    wrapped function keeps its signature (``inspect.signature`` shows the new names only).
    """
    def decorate(function):
        @functools.wraps(function)
        def call(*args, **kwargs):
            for old, new in renames.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(f"{function.__name__}() got both {old}= and {new}= (the same argument)")
                    warnings.warn(f"{function.__name__}({old}=...) is deprecated; use {new}=", DeprecationWarning,
                                  stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return function(*args, **kwargs)
        return call
    return decorate
