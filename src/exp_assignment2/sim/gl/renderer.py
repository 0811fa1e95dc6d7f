"""The GL renderer's drawing half: a scene description drawn with OpenGL.

:class:`GLRenderer` owns an OpenGL context (:class:`~.context.GLContext`)
bound to the thread that constructs it: create it, render with it and close
it in that one thread (e.g. a render worker). Geometry is uploaded once; a
frame sets one 4x4 uniform per link, draws that link's index range and reads
BGR pixels back, top row first, into a reused buffer.

Camera convention: the camera looks along its frame's +x with +z up (the
package's ``camera_link``); pixels follow a pinhole with
f = width / (2 tan(hfov / 2)), cx = width / 2, cy = height / 2, as pybullet's
``computeViewMatrix`` + ``computeProjectionMatrixFOV`` give, sampled at pixel
centres (OpenGL's rule).
"""
import math

import numpy as np

from .context import GLContext
from .meshes import VERTEX_FORMAT
from ..rotations import pose_matrix


def view_projection(camera_pose, width, height, hfov_deg, near, far, flip_y=True):
    """4x4 world -> clip matrix of a camera looking along its +x, +z up.

    ``flip_y`` mirrors clip y so that GL's bottom-up framebuffer rows read
    back top row first (no flip copy after reading)."""
    cam = np.asarray(camera_pose, float)
    r, c = cam[:3, :3], cam[:3, 3]
    view = np.eye(4)
    view[:3, :3] = np.stack([-r[:, 1], r[:, 2], -r[:, 0]])   # GL eye: x right, y up, -z ahead
    view[:3, 3] = -view[:3, :3].dot(c)
    fx = 1.0 / math.tan(math.radians(hfov_deg) / 2.0)
    fy = fx * width / float(height)                          # square pixels
    proj = np.zeros((4, 4))
    proj[0, 0], proj[1, 1] = fx, -fy if flip_y else fy
    proj[2, 2], proj[2, 3] = (far + near) / (near - far), 2.0 * far * near / (near - far)
    proj[3, 2] = -1.0
    return proj.dot(view)


VERTEX_SHADER = '''
#version 330
// One draw per link with its pose in a plain uniform: llvmpipe runs a vertex
// shader that indexes a pose array per vertex (texture or uniform block) ~10x
// slower. Lighting per vertex: llvmpipe's cost is per fragment and per varying.
uniform mat4 model;   // row-major bytes of the link's world frame: p * model = M p
uniform mat4 view_proj;
uniform vec3 light_dir;   // unit, towards the light, world frame
uniform float ambient, diffuse;
in vec3 in_pos; in vec3 in_norm; in vec3 in_color;
out vec3 v_bgr; out vec2 v_xy; out float v_up;
void main() {
    vec3 world = (vec4(in_pos, 1.0) * model).xyz;
    vec3 n = normalize(in_norm * mat3(model));
    v_bgr = in_color.bgr * (ambient + diffuse * max(dot(n, light_dir), 0.0));   // BGR for OpenCV
    v_xy = world.xy;
    v_up = n.z > 0.5 ? 1.0 : 0.0;   // the grid goes on upward faces only
    gl_Position = view_proj * vec4(world, 1.0);
}
'''

PLAIN_FRAGMENT_SHADER = '''
#version 330
in vec3 v_bgr;
out vec4 f_bgra;
void main() { f_bgra = vec4(v_bgr, 1.0); }
'''

GRID_FRAGMENT_SHADER = '''
#version 330
uniform float grid_step, grid_half_width, grid_line_factor;
in vec3 v_bgr; in vec2 v_xy; in float v_up;
out vec4 f_bgra;
void main() {
    // box-filtered coverage of the nearest x and y lines over this pixel
    vec2 px = max(fwidth(v_xy), 1e-6);   // metres per pixel
    vec2 d = abs(fract(v_xy / grid_step + 0.5) - 0.5) * grid_step / px;
    vec2 h = grid_half_width / px;
    vec2 cover = clamp(min(d + 0.5, h) - max(d - 0.5, -h), 0.0, 1.0);
    f_bgra = vec4(v_bgr * mix(1.0, grid_line_factor, max(cover.x, cover.y) * v_up), 1.0);
}
'''


# a draw's grid (scene.NO_GRID, GRID, GUI_GRID_ONLY) -> its program: plain (0) or grid (1)
GRID_PROGRAM = (0, 1, 0)
GRID_PROGRAM_GUI = (0, 1, 1)


class GLRenderer(object):
    """Draws a :class:`~.scene.SceneDescription` with OpenGL into BGR images.

    The GL context is created in, and bound to, the constructing thread:
    :meth:`render` and :meth:`close` must run in that same thread. Raises
    RuntimeError with a one-line message when moderngl or an EGL OpenGL 3.3
    context is unavailable (the caller may fall back to pybullet's renderers).

    :param width, height: image size (px)
    :param background: clear colour (r, g, b) in 0..1 (pybullet's GL sky by default)
    :param samples: MSAA samples (0: none, as pybullet's renderers)
    :param light_dir: world direction towards the light; ambient + diffuse <= 1
    :param grid_line_width: floor grid line width (m); lines are the floor
        colour times ``grid_line_factor`` (pybullet's texture: 90 on 200)
    """

    def __init__(self, description, width, height, background=(0.7, 0.7, 0.8), samples=0,
                 light_dir=(0.4, 0.3, 0.87), ambient=0.45, diffuse=0.55,
                 grid_step=1.0, grid_line_width=0.06, grid_line_factor=0.45):
        self.gl = GLContext()
        try:
            import cv2
            self._cvt = lambda src, dst: cv2.cvtColor(src, cv2.COLOR_BGRA2BGR, dst=dst)
        except ImportError:
            self._cvt = None
        self.description, self.width, self.height = description, int(width), int(height)
        self.background = tuple(background)
        self.light_dir = np.asarray(light_dir, float) / np.linalg.norm(light_dir)
        settings = {'light_dir': tuple(self.light_dir), 'ambient': ambient,
                    'diffuse': diffuse, 'grid_step': grid_step,
                    'grid_half_width': grid_line_width / 2.0,
                    'grid_line_factor': grid_line_factor}
        self.programs, self.vaos, self.vbo, self.ibo = [], [], None, None
        with self.gl.current() as ctx:
            # two programs: the grid's fragment work is paid on grid floors only
            for fragment in (PLAIN_FRAGMENT_SHADER, GRID_FRAGMENT_SHADER):
                prog = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=fragment)
                for key, value in settings.items():
                    if key in prog:
                        prog[key].value = value
                self.programs.append(prog)
            self._upload(ctx, description)
            # RGBA colour buffer: Mesa reads 4 components back ~8x faster than 3,
            # and OpenCV drops the alpha in a fraction of that time.
            size, comps = (self.width, self.height), 4 if self._cvt else 3
            self.fbo = ctx.framebuffer(ctx.renderbuffer(size, comps, samples=samples),
                                       ctx.depth_renderbuffer(size, samples=samples))
            # MSAA renders into fbo and resolves into a plain one for reading.
            self.read_fbo = ctx.framebuffer(ctx.renderbuffer(size, comps)) if samples else self.fbo
        self._rgba = np.empty((self.height, self.width, comps), np.uint8)
        self._image = np.empty((self.height, self.width, 3), np.uint8)

    def _upload(self, ctx, description):
        """Geometry goes to the GPU here, once per scene; a frame only writes uniforms.
        (GL buffers cannot be empty: an empty scene gets a dummy triangle.)"""
        for obj in self.vaos + [self.vbo, self.ibo]:
            if obj is not None:
                obj.release()
        self.description = description
        self.vbo = ctx.buffer(np.ascontiguousarray(description.vertices, 'f4').tobytes()
                              or bytes(108))
        self.ibo = ctx.buffer(np.ascontiguousarray(description.indices, 'u4').tobytes()
                              or bytes(12))
        self.vaos = [ctx.vertex_array(prog, [(self.vbo, VERTEX_FORMAT, 'in_pos', 'in_norm',
                                              'in_color')], self.ibo, 4)
                     for prog in self.programs]

    def set_scene(self, description):
        """Draw another scene from now on (models were spawned or deleted)."""
        self.gl.check_thread('GLRenderer.set_scene')
        with self.gl.current() as ctx:
            self._upload(ctx, description)

    def render(self, poses, camera_pose, hfov_deg=80.0, near=0.05, far=40.0, hidden=(),
               out=None, gui=False):
        """Draw the scene at ``poses`` (a :meth:`~.scene.SceneReader.read_poses`
        snapshot) seen from ``camera_pose`` (4x4 world pose, or a (position,
        quaternion or 3x3 rotation) tuple); ``hidden``: model names or body
        ids not to draw; ``gui``: the camera is Gazebo's user camera, which
        sees the GUI's grid too (a sensor's does not).

        Returns a contiguous (height, width, 3) uint8 BGR image, row 0 at the
        top: ``out`` if given, else an internal buffer that the next call
        overwrites (encode or copy it before rendering again)."""
        self.gl.check_thread('GLRenderer.render')
        cam = pose_matrix(*camera_pose) if isinstance(camera_pose, tuple) else camera_pose
        vp = view_projection(cam, self.width, self.height, hfov_deg, near, far)
        poses = np.ascontiguousarray(poses, np.float32)
        skip = self.description.hidden_slots(hidden) if hidden else ()
        with self.gl.current():
            self._draw(poses, vp.T.astype(np.float32).tobytes(), skip,   # GL: column-major
                       GRID_PROGRAM_GUI if gui else GRID_PROGRAM)
            self.gl.finish()
            image = self._image if out is None else out
            if self._cvt is None:
                self.read_fbo.read_into(image, components=3, alignment=1)
                return image
            self.read_fbo.read_into(self._rgba, components=4, alignment=1)
        return self._cvt(self._rgba, image)

    def _draw(self, poses, view_proj, skip, program_of):
        ctx = self.gl.ctx
        for prog in self.programs:
            prog['view_proj'].write(view_proj)
        self.fbo.use()
        ctx.enable_only(ctx.DEPTH_TEST)
        ctx.front_face = 'cw'   # the y-flipped projection mirrors the winding
        r, g, b = self.background
        self.fbo.clear(b, g, r, 1.0, depth=1.0)   # the colour buffer holds BGR
        culling = False
        for slot, first, count, cull, grid in self.description.draws:
            if slot in skip:
                continue
            if cull != culling:
                (ctx.enable if cull else ctx.disable)(ctx.CULL_FACE)
                culling = cull
            program = program_of[grid]
            self.programs[program]['model'].write(poses[slot])
            self.vaos[program].render(first=first, vertices=count)
        if self.read_fbo is not self.fbo:
            ctx.copy_framebuffer(self.read_fbo, self.fbo)

    def close(self):
        """Release every GL object and the context (same thread as creation)."""
        if self.gl.ctx is None:   # closed already
            return
        with self.gl.current():
            for obj in self.vaos + self.programs + [self.vbo, self.ibo]:
                obj.release()
            for fbo in {self.fbo, self.read_fbo}:
                for att in list(fbo.color_attachments) + [fbo.depth_attachment]:
                    if att is not None:
                        att.release()
                fbo.release()
        self.gl.release()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
