"""``gles.mesa`` is :mod:`gles.lab.mesa` (the evaluation lab), under its public name."""

import sys

from .lab import mesa as _module

sys.modules[__name__] = _module
