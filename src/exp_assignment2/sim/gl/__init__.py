"""The package's camera renderer: URDF visuals drawn with OpenGL (moderngl
over headless EGL), in a few milliseconds a frame on Mesa's llvmpipe.
:mod:`.scene` (what to draw, read from pybullet), :mod:`.renderer` (the
drawing), :mod:`.meshes` (shapes as triangles), :mod:`.context` (the EGL
context), :mod:`.backend` (behind the camera's capture/finish split)."""
