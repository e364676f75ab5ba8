"""Old names of the lab kept for one release (issue 10): they warn with DeprecationWarning.

warn_renamed      warn that a name is deprecated, naming its replacement
renamed_field     a read-only property under a NamedTuple field's old name
"""

from __future__ import annotations

import warnings

__all__ = ["renamed_field", "warn_renamed"]


def warn_renamed(old, new, *, stacklevel=3):
    """Warn that ``old`` is deprecated in favour of ``new``; the default stack level names the caller
    of the function that calls this one."""
    warnings.warn(f"{old} is deprecated; use {new}", DeprecationWarning, stacklevel=stacklevel)


def renamed_field(owner, old, new):
    """A property ``old`` of NamedTuple ``owner`` that warns and returns the field ``new``."""

    def get(self):
        warn_renamed(f"{owner}.{old}", new)
        return getattr(self, new)

    return property(get, doc=f"Deprecated name of :attr:`{new}` (warns with DeprecationWarning).")
