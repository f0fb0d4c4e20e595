"""``gles.compare`` is :mod:`gles.lab.compare` (the evaluation lab), under its public name."""

import sys

from .lab import compare as _module

sys.modules[__name__] = _module
