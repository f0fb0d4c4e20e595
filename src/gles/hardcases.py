"""``gles.hardcases`` is :mod:`gles.lab.hardcases` (the evaluation lab), under its public name."""

import sys

from .lab import hardcases as _module

sys.modules[__name__] = _module
