"""The evaluation lab: what measures gles rather than what gles is.

* :mod:`gles.lab.compare` renders a scene on each build and peer and
  measures time against error (``gles.compare``, ``python -m gles compare``);
* :mod:`gles.lab.report` renders the gallery and the hard cases into an
  HTML and Markdown report (``python -m gles report``); its file stays at
  gles/report.py, where it was first written;
* :mod:`gles.lab.gallery` and :mod:`gles.lab.hardcases` hold those scenes;
* :mod:`gles.lab.mesa` is the Mesa peer, an independent ES 1.1 reached
  through EGL.

The product (Context, the commands, the range checks, the constants and
errors) never imports this package; ``import gles`` does not load it. Each
module is also reachable under its public name (``gles.compare``,
``gles.mesa``, ...), as the same module object, loaded on first use.
"""
