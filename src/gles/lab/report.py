"""``gles.lab.report`` is :mod:`gles.report` (kept at its first path), under its lab name."""

import sys

from .. import report as _module

sys.modules[__name__] = _module
