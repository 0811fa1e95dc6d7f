"""The simulator node's own parameters, checked before anything starts (no ROS).

:func:`check_node_params` refuses the first bad value with one line naming the
parameter, the value and what is accepted (a :class:`ParameterError`), so a
bad launch argument stops the launch at once instead of running a blind dog
(``camera_width:=1``) or failing every frame (``camera_width:=100000``).

The camera's size is bounded by what its consumers and the renderer can do:

* at least :data:`MIN_CAMERA_SIZE` px: the smallest image in which the ball
  detector (blur 11x11, erode x2, radius > 10 px at 800 px, scaled) sees the
  ball as far as at 800 px. Measured with the package's renderer from the
  dog's spawn point along the arena's diagonal: seen up to 18 m (the wall) at
  240 px and above, 15.5 m at 200, 14 m at 160, 9 m at 100
  (test/unit/test_sim_limits.py keeps the 240 px half of that true);
* at most what this machine's OpenGL draws into (the smaller of
  GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS, asked of a probe context:
  16384 on Mesa's llvmpipe), or :data:`FALLBACK_MAX_SIZE` without OpenGL.
"""
import math
import numbers

MIN_CAMERA_SIZE = 240
FALLBACK_MAX_SIZE = 4096    # px, without OpenGL: TinyRenderer takes seconds per frame there
RENDERERS = ('gl', 'egl', 'tiny')


class ParameterError(ValueError):
    """A parameter refused: the message is the whole log line."""


def gl_max_image_size():
    """The largest image side (px) this machine's OpenGL renders into, or None
    when no OpenGL context can be made (a probe context, released at once)."""
    from exp_assignment2.sim.gl.context import GLContext
    try:
        context = GLContext()
    except RuntimeError:
        return None
    try:
        with context.current() as ctx:
            return int(min(ctx.info['GL_MAX_RENDERBUFFER_SIZE'],
                           *ctx.info['GL_MAX_VIEWPORT_DIMS']))
    finally:
        context.release()


def _refuse(name, value, accepted):
    shown = value if isinstance(value, str) and len(value) <= 80 else repr(value)[:80]
    raise ParameterError('~%s = %s is refused; accepted: %s' % (name, shown, accepted))


def _number(value):
    """``value`` as a float when it is a real number (not a bool), else None."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    return float(value)


def _real(params, name, low, high, accepted, low_open=False):
    value = params[name]
    x = _number(value)
    if x is None or not math.isfinite(x) or x < low or (low_open and x == low) or x > high:
        _refuse(name, value, accepted)
    return x


def _size(params, name, max_size):
    drawn = max_size()
    top = drawn or FALLBACK_MAX_SIZE
    value = params[name]
    x = _number(value)
    if x is None or not math.isfinite(x) or x != int(x) or not MIN_CAMERA_SIZE <= x <= top:
        _refuse(name, value, 'a whole number of pixels in [%d, %d] (%d: the smallest image in '
                'which the dog sees the ball across the arena; %d: the largest %s)'
                % (MIN_CAMERA_SIZE, top, MIN_CAMERA_SIZE, top, 'this machine\'s OpenGL draws'
                   if drawn else 'the renderers draw in time without OpenGL'))
    return int(x)


def _given(value):
    """A launch argument left empty ('') or a parameter not set (None) is not given."""
    return value is not None and value != ''


def check_node_params(params, max_size=gl_max_image_size):
    """The simulator node's ``params`` (``real_time_factor``, ``time_step``,
    ``renderer``, ``paused``, ``wait_for_camera``, ``cmd_timeout``,
    ``start_timeout``, ``camera_*``, gazebo_ros' ``pub_clock_frequency`` and
    ``enable_ros_network``; None or '': not given), checked and
    normalised; other keys are passed through.

    :param max_size: ``max_size()`` is the largest image side the renderer
        draws, or None (asked only when a camera size is given, at most once)
    :raises ParameterError: naming the first refused parameter
    """
    asked = []

    def largest():
        if not asked:
            asked.append(max_size())
        return asked[0]
    out = dict(params)
    out['real_time_factor'] = _real(params, 'real_time_factor', 0.0, math.inf,
                                    'a number >= 0 (1: real time, 0: as fast as possible)')
    if 'max_real_time_factor' in params:
        out['max_real_time_factor'] = _real(params, 'max_real_time_factor', 0.0, math.inf,
                                            'a number >= 0 (real_time_factor 0\'s ceiling; '
                                            '0: none)')
    out['time_step'] = _real(params, 'time_step', 0.0, 0.1, 'seconds in (0, 0.1]',
                             low_open=True)
    if params['renderer'] not in RENDERERS:
        _refuse('renderer', params['renderer'], ', '.join(RENDERERS))
    for name in ('paused', 'wait_for_camera', 'enable_ros_network'):
        if name in params and not isinstance(params[name], bool):
            _refuse(name, params[name], 'true or false')
    out['start_timeout'] = _real(params, 'start_timeout', 0.0, math.inf, 'seconds > 0',
                                 low_open=True)
    if _given(params['cmd_timeout']):
        out['cmd_timeout'] = _real(params, 'cmd_timeout', 0.0, math.inf,
                                   'seconds >= 0 (0: keep the last command)')
    for name in ('camera_width', 'camera_height'):
        if _given(params[name]):
            out[name] = _size(params, name, largest)
    if _given(params['camera_rate']):
        most = 1.0 / out['time_step']
        out['camera_rate'] = _real(params, 'camera_rate', 0.0, most,
                                   'frames per second in (0, %g] (one per time step at most)'
                                   % most, low_open=True)
    if _given(params.get('pub_clock_frequency')):
        out['pub_clock_frequency'] = _real(params, 'pub_clock_frequency', 0.0, math.inf,
                                           'a number >= 0 (Hz of simulated time; 0: every '
                                           'step)')
    if _given(params['camera_hfov']):
        out['camera_hfov'] = _real(params, 'camera_hfov', 1.0, 179.0,
                                   'degrees in [1, 179]')
    return out
