"""Former home of the runout error-file reader, now :mod:`bearinglab.runout.files` (kept for old imports).

The command line switches to the public names at the merge of the architecture refactor (issue 10).
"""

from .runout.files import _read_geometry as read_geometry
from .runout.files import load_error_file as read_error_file
from .runout.files import load_geometry_file as read_geometry_file

__all__ = [
    "read_error_file",
    "read_geometry",
    "read_geometry_file",
]  # as before, for the command line
