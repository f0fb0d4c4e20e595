"""``python -m conformance``: run the OpenGL ES 1.1 conformance suite."""

from __future__ import annotations

import sys

from .runner import main

if __name__ == "__main__":
    sys.exit(main())
