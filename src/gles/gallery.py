"""``gles.gallery`` is :mod:`gles.lab.gallery` (the evaluation lab), under its public name."""

import sys

from .lab import gallery as _module

sys.modules[__name__] = _module
