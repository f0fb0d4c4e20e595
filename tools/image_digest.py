"""A pytest plugin that records a digest of every image the tests read back.

    GLES_DIGEST_OUT=before.json python -m pytest -p image_digest --hypothesis-seed=0 tests
    python tools/image_digest.py before.json after.json

With ``tools/`` on PYTHONPATH, ``-p image_digest`` wraps the Python calls
that read a framebuffer (``Context.color_buffer``, ``depth_buffer``,
``stencil_buffer`` and ``glReadPixels``) and records a SHA-1 of each result,
keyed by the test and the call's ordinal within it. Comparing two runs (one
on the code before a change, one after) lists every test whose pixels
changed: the check behind "bit-identical images" for changes meant to be
pure speed.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import sys
from collections import defaultdict
from typing import Any

_digests: dict[str, str] = {}
_counts: defaultdict[str, int] = defaultdict(int)


def _record(result: Any) -> None:
    test = os.environ.get("PYTEST_CURRENT_TEST", "?").rsplit(" (", 1)[0]
    n = _counts[test]
    _counts[test] += 1
    data = getattr(result, "tobytes", None)
    raw = data() if data else repr(result).encode()
    _digests[f"{test}#{n}"] = hashlib.sha1(raw).hexdigest()


def _wrap(cls: Any, name: str) -> None:
    orig = getattr(cls, name)

    @functools.wraps(orig)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        result = orig(*args, **kwargs)
        if result is not None:
            _record(result)
        return result

    setattr(cls, name, wrapper)


def pytest_configure(config: Any) -> None:
    from gles import context, gl

    for name in ("color_buffer", "depth_buffer", "stencil_buffer"):
        _wrap(context.Context, name)
    _wrap(gl.GLBase if hasattr(gl, "GLBase") else gl.GLCommon, "glReadPixels")


def pytest_unconfigure(config: Any) -> None:
    out = os.environ.get("GLES_DIGEST_OUT")
    if out:
        with open(out, "w") as f:
            json.dump(_digests, f, indent=0, sort_keys=True)


def compare(before: str, after: str) -> int:
    """Print the tests whose read-back images differ; 1 if any do."""
    with open(before) as f:
        a = json.load(f)
    with open(after) as f:
        b = json.load(f)
    changed = sorted(k for k in a.keys() & b.keys() if a[k] != b[k])
    only = sorted(a.keys() ^ b.keys())
    for k in changed:
        print("changed", k)
    for k in only:
        print("only in one run", k)
    print(f"{len(a.keys() & b.keys())} read-backs compared, {len(changed)} changed, {len(only)} unmatched")
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(compare(sys.argv[1], sys.argv[2]))
