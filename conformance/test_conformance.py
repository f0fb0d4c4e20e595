"""The conformance suite under pytest: one test per (test, backend, profile,
visual, path level).

The default matrix keeps the run short: gles-fixed in both profiles at every
path level, the other backends in the Common profile at path levels 0 and 4,
and the C ABI (cabi-*: libEGL + libGLESv1_CM of each build, driven through
EGL like Mesa) at path level 0, cabi-fixed in both profiles. A cabi run must
give the same verdict and the same final image as the cffi binding's run of
the same job (the same compiled core behind two faces).
``GLES_CONFORMANCE_FULL=1`` runs every backend in both profiles at every
level (what ``python -m conformance`` does). A Mesa backend whose libraries
are missing is skipped with the reason ``gles.mesa.available()`` gives.

Deviations the suite has found and docs/conformance.md explains are listed
in :data:`KNOWN_DEVIATIONS` and expected to fail (strictly: a fixed deviation
makes its entry fail until it is removed). ``python -m conformance`` reports
them as failures, as it should.
"""

from __future__ import annotations

import os
from dataclasses import replace
from typing import NamedTuple

import pytest

from .backends import BACKENDS, PROFILES
from .harness import load_categories
from .paths import MAX_LEVEL
from .runner import Job, PathInvariance, plan, run_job, select_tests

FULL = os.environ.get("GLES_CONFORMANCE_FULL", "") not in ("", "0")
ALL_LEVELS = tuple(range(MAX_LEVEL + 1))

# backend -> (profiles, path levels) of the default run
MATRIX: dict[str, tuple[tuple[str, ...], tuple[int, ...]]] = {
    "gles-fixed": (PROFILES, ALL_LEVELS),
    "gles-float": (("common",), (0, MAX_LEVEL)),
    "gles-double": (("common",), (0, MAX_LEVEL)),
    "mesa-llvmpipe": (("common",), (0, MAX_LEVEL)),
    "mesa-softpipe": (("common",), (0, MAX_LEVEL)),
    "cabi-fixed": (PROFILES, (0,)),
    "cabi-float": (("common",), (0,)),
    "cabi-double": (("common",), (0,)),
    "library": (PROFILES, (0,)),      # only with GLES_CONFORMANCE_LIBRARY set
}


class Deviation(NamedTuple):
    """Runs expected to fail: the backend name starts with `backend`; None matches anything."""

    test: str
    backend: str
    visual: str | None
    path: int | None
    reason: str


KNOWN_DEVIATIONS: tuple[Deviation, ...] = (
    Deviation("BColor.msb", "mesa-softpipe", "rgb565", None,
              "softpipe: unsigned-byte colours are rounded to 5/6 bits, §2.12.8 wants their most "
              "significant bits (docs/conformance.md, Mesa results)"),
    Deviation("MatrixStack.texture", "mesa-", None, None,
              "Mesa: glActiveTexture accepts TEXTURE8..TEXTURE191 although MAX_TEXTURE_UNITS is 8; "
              "§2.10.2 wants INVALID_ENUM (docs/conformance.md, Mesa results)"),
    Deviation("APFunc", "mesa-", None, None,
              "Mesa: the alpha reference is not clamped to [0, 1]; §4.1.4 (docs/conformance.md)"),
    Deviation("APFunc.precision", "mesa-softpipe", None, None,
              "softpipe: alpha compared as floats, not at 8 bits; §4.1.4 (docs/conformance.md)"),
    Deviation("Fog", "mesa-", None, None,
              "Mesa: FOG_COLOR is not clamped to [0, 1] when specified; §3.8 (docs/conformance.md)"),
    Deviation("LogicOp", "mesa-softpipe", "rgb565", None,
              "softpipe: logic op on 8-bit values, then truncated to 5/6 bits; §4.1.9 (docs/conformance.md)"),
    Deviation("MipSelect.magswitch", "mesa-", None, None,
              "Mesa: the c = 0.5 magnification switch is ignored; §3.7.8 (docs/conformance.md)"),
    Deviation("TexPalet.errors", "mesa-", None, None,
              "Mesa: CompressedTexSubImage2D on a paletted texture gives INVALID_VALUE; §3.7.4 wants "
              "INVALID_OPERATION (docs/conformance.md)"),
    Deviation("TexETC1.errors", "mesa-", None, None,
              "Mesa: TexSubImage2D on an ETC1 texture gives INVALID_VALUE; OES_compressed_ETC1_RGB8_texture "
              "wants INVALID_OPERATION (docs/conformance.md)"),
    Deviation("TexBGRA", "mesa-", None, None,
              "Mesa: TexImage2D takes internalformat RGBA with format BGRA_EXT; EXT_texture_format_BGRA8888 "
              "pairs BGRA_EXT with BGRA_EXT only, and ES 1.1 (3.7.1) wants INVALID_OPERATION "
              "(docs/conformance.md)"),
    Deviation("TexAniso.state", "mesa-", None, None,
              "Mesa: GetTexParameterxv of TEXTURE_MAX_ANISOTROPY_EXT records INVALID_ENUM and gives 0; the "
              "x forms query every texture parameter (docs/conformance.md)"),
    Deviation("covgl", "mesa-", None, None,
              "Mesa: CompressedTexSubImage2D on a paletted texture gives INVALID_VALUE, not "
              "INVALID_OPERATION; §3.7.4 (docs/conformance.md)"),
    Deviation("Gets", "mesa-", None, None,
              "Mesa: GetFixedv scales enums, GetIntegerv maps matrix elements like colours; §6.1.2 "
              "(docs/conformance.md)"),
    Deviation("Gets.extensions", "mesa-", None, None,
              "Mesa: glTexGenxOES(TEXTURE_GEN_STR_OES, TEXTURE_GEN_MODE_OES, NORMAL_MAP_OES or "
              "REFLECTION_MAP_OES) records INVALID_ENUM and leaves the mode; OES_texture_cube_map 2.11.4 "
              "and its table 6.14 (docs/conformance.md)"),
    Deviation("MatrixGetTest", "mesa-", None, None,
              "Mesa: OES_matrix_get (*_FLOAT_AS_INT_BITS_OES) missing; Appendix C (docs/conformance.md)"),
    Deviation("PointRaster", "mesa-softpipe", None, None,
              "softpipe: aliased points centred by rounding, not floor(x) + 1/2; §3.3 (docs/conformance.md)"),
    Deviation("PointSizeArray", "mesa-softpipe", None, None,
              "softpipe: aliased points centred by rounding, not floor(x) + 1/2; §3.3 (docs/conformance.md)"),
    Deviation("PointSprite", "mesa-softpipe", None, None,
              "softpipe: sprite footprint off by one pixel; OES_point_sprite (docs/conformance.md)"),
    Deviation("LineRaster", "mesa-softpipe", None, None,
              "softpipe: a column's fragment one row off the line; §3.4.1 (docs/conformance.md)"),
    Deviation("TexCube.errors", "mesa-", None, None,
              "Mesa: with TEXTURE_CUBE_MAP_OES and TEXTURE_2D enabled and the cube map incomplete, the "
              "2D texture is sampled; OES_texture_cube_map wants texturing disabled (docs/conformance.md)"),
    Deviation("TexCube.wrap", "mesa-llvmpipe", None, None,
              "llvmpipe: cube map faces are sampled as CLAMP_TO_EDGE whatever the wrap modes; "
              "ARB_texture_cube_map applies every wrap mode per face (docs/conformance.md)"),
    Deviation("TexGen.normal", "mesa-", None, None,
              "Mesa: TEXTURE_GEN_MODE_OES NORMAL_MAP_OES generates the reflection vector, not the eye-space "
              "normal; OES_texture_cube_map 2.11.4 (docs/conformance.md)"),
    Deviation("Debug.insert", "mesa-", None, None,
              "Mesa: DebugMessageInsertKHR takes the PUSH_GROUP and POP_GROUP types, and records errors "
              "while DEBUG_OUTPUT is off; KHR_debug 5.5.5 and New Tokens (docs/conformance.md)"),
    Deviation("Debug.labellength", "mesa-", None, None,
              "Mesa: ObjectLabelKHR with a label of MAX_LABEL_LENGTH characters records INVALID_VALUE "
              "and still sets the label; 2.5: a command that records an error has no effect "
              "(docs/conformance.md)"),
    Deviation("Debug.vaolabel", "mesa-", None, None,
              "Mesa: OES_vertex_array_object has no ES 1 dispatch, so no vertex array object exists to "
              "label (docs/conformance.md, OES_vertex_array_object)"),
    Deviation("AmbLight.errors", "mesa-", None, None,
              "Mesa: scalar glLight/glLightModel accept vector pnames; §2.12.2 wants INVALID_ENUM "
              "(docs/conformance.md, Mesa results)"),
)


def _deviation(job: Job) -> Deviation | None:
    for d in KNOWN_DEVIATIONS:
        if (d.test == job.test.name and job.backend.name.startswith(d.backend)
                and d.visual in (None, job.visual) and d.path in (None, job.path)):
            return d
    return None


def _jobs() -> list[Job]:
    tests = select_tests(load_categories())
    jobs: list[Job] = []
    for name, spec in BACKENDS.items():
        if spec.kind == "library" and spec.available() is not None:
            continue                  # no library pair named: nothing to parametrise
        profiles, levels = (PROFILES, ALL_LEVELS) if FULL else MATRIX[name]
        jobs += plan(tests, [spec], profiles, levels)
    return jobs


def _params() -> list:
    out = []
    for job in _jobs():
        dev = _deviation(job)
        marks = [pytest.mark.xfail(reason=dev.reason, strict=True)] if dev else []
        out.append(pytest.param(job, id=job.id, marks=marks))
    return out


_INVARIANCE = PathInvariance()   # level 0 of a group runs before its other levels
# the cffi binding's results, for the C ABI's runs of the same jobs to match
_GLES_RESULTS: dict[tuple[str, str, str, str, int], tuple[str, str]] = {}


def _key(job: Job, numeric: str) -> tuple[str, str, str, str, int]:
    return (job.test.name, numeric, job.profile, job.visual, job.path)


def _gles_result(job: Job) -> tuple[str, str]:
    """(status, digest) of the cffi binding on the job a cabi backend ran."""
    numeric = job.backend.variant
    key = _key(job, numeric)
    if key not in _GLES_RESULTS:
        res = run_job(replace(job, backend=BACKENDS[f"gles-{numeric}"]))
        _GLES_RESULTS[key] = (res.status, res.digest)
    return _GLES_RESULTS[key]


@pytest.mark.parametrize("job", _params())
def test_conformance(job: Job) -> None:
    """One conformance run; skips where the backend or the feature is missing."""
    why = job.backend.available()
    if why is not None:
        pytest.skip(why)
    res = _INVARIANCE.check(run_job(job))
    if job.backend.kind == "gles":
        _GLES_RESULTS[_key(job, job.backend.variant)] = (res.status, res.digest)
    elif job.backend.kind == "cabi":
        ours = (res.status, res.digest)
        assert ours == _gles_result(job), \
            f"the C ABI gave {ours}, the cffi binding {_gles_result(job)} (status, image digest)"
    if res.status == "skip":
        pytest.skip(res.message)
    if res.status in ("fail", "error"):
        pytest.fail(f"{res.status}: {res.message}", pytrace=False)
