"""The OpenGL ES 1.1 conformance suite: runs against gles builds and Mesa."""
