"""``gles.report`` is :mod:`gles.lab.report` (the evaluation lab), under its public name."""

import sys

from .lab import report as _module

sys.modules[__name__] = _module
