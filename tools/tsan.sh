#!/usr/bin/env bash
# ThreadSanitizer run of the threaded tests (tests/test_threads.py): the
# package installed into a fresh virtualenv with its cores built under
# -fsanitize=thread, libtsan preloaded into the interpreter. Exits non-zero
# on any race report. The interpreter must start under libtsan: some
# builds of CPython (pyenv's shared ones) do not; TSAN_PYTHON picks another
# (default: /usr/bin/python3 where it exists, else python3).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=${TSAN_PYTHON:-}
if [ -z "$py" ]; then
    if [ -x /usr/bin/python3 ]; then py=/usr/bin/python3; else py=python3; fi
fi
tsan_lib=$(gcc -print-file-name=libtsan.so)
"$py" -m venv "$work/venv"
# shellcheck disable=SC1091
. "$work/venv/bin/activate"
python -m pip install -q --upgrade pip
# (-fno-var-tracking-assignments: as in .ci/run's sanitizer build)
GLES_TARGET_CC=none GLES_CFLAGS="-O1 -g -fno-var-tracking-assignments -fno-omit-frame-pointer -fsanitize=thread" \
    python -m pip install -q --no-cache-dir ".[test]"
# -s: the reports go to stderr, past pytest's capture; TSan exits 66 after
# any. The fork test is left out: TSan cannot follow threads started in a
# child of a multi-threaded fork() (the sanitizer build of .ci/run runs it)
(cd "$work" && LD_PRELOAD="$tsan_lib" TSAN_OPTIONS=halt_on_error=1:exitcode=66 \
 python -m pytest -q -s -p no:cacheprovider -x -k "not fork_child" "$root/tests/test_threads.py")
