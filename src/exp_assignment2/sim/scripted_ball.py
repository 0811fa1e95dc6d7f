"""The simulator playing a ball script (:mod:`.ball_script`) in its world (no ROS).

:class:`ScriptedBall` is given the setting (:mod:`.ball_setting`) and told
of every model spawned. The ball is the model the setting names, else the
first one spawned that looks like the assignment's ball (:func:`is_ball`: a
sphere with no camera and no drive but planar_move's, as the grader's roles
find it). From its spawn (the script's time 0: the same seed gives the same
ball relative to its appearance, whatever the student's launch order) the
model is held (:meth:`~.model.Model.hold`): the engine puts it where the
script says before every physics step, and every command to it from anyone
else (its planar_move ``cmd_vel``, ``set_model_state``, ``set_link_state``)
is ignored, and counted for the ground truth (:mod:`.ground_truth`'s ``ignored``). Deleted and
spawned again, the ball takes up the same course where its clock has got to.

A seeded course is written for the world's arena (:func:`world_arena`): the
engine's bounds where it has them (the package's worlds), else the box the
standing scenery encloses (an SDF world's walls), else the course's arena;
the world's fixed objects (static models) are kept away from.
"""
import math

import numpy as np

from exp_assignment2 import arena as course
from exp_assignment2.sim import ball_script, ball_setting
from exp_assignment2.sim.model_facts import sphere

FLAT = 0.05            # m: scenery no higher than this is floor, not an obstacle
ARENA_SIDES = (4.0, 40.0)   # m: a box of standing scenery this size is the arena
DRIVE_WORDS = ('drive', 'steer', 'ros_control', 'tricycle')
PLANAR_MOVE = 'libgazebo_ros_planar_move.so'


def is_ball(model):
    """The assignment's ball: not static, drawn as one sphere, no camera and no
    drive but planar_move's."""
    urdf = model.urdf
    if model.static or sphere(urdf) is None:
        return False
    for decl in urdf.gazebo.plugins:
        if decl.sensor is not None and decl.sensor.type in ('camera', 'depth', 'multicamera'):
            return False
        if decl.filename != PLANAR_MOVE and any(w in decl.filename for w in DRIVE_WORDS):
            return False
    return True


def _visual_box(shape_pose, visual):
    """((x0, y0, z0), (x1, y1, z1)) around a primitive visual posed in the
    world (4x4), None for a mesh or an unknown shape."""
    params = visual.params
    if visual.kind == 'box':
        half = np.asarray(params['size'], float) / 2.0
    elif visual.kind in ('cylinder', 'capsule'):
        r, length = params['radius'], params['length']
        half = np.array([r, r, length / 2.0 + (r if visual.kind == 'capsule' else 0.0)])
    elif visual.kind == 'sphere':
        half = np.full(3, params['radius'])
    else:
        return None
    extent = np.abs(shape_pose[:3, :3]).dot(half)
    centre = shape_pose[:3, 3]
    return tuple(centre - extent), tuple(centre + extent)


def footprints(models):
    """The world's fixed objects: for every link of every static model, the
    box around its primitive visuals and its collisions, as
    ((x0, y0, z0), (x1, y1, z1))."""
    from exp_assignment2.sim.rotations import pose_matrix
    out = []
    for model in models:
        if not model.static:
            continue
        for name, link in model.urdf.links.items():
            if name not in model.body.links:
                continue
            frame = pose_matrix(*model.link_pose(name))
            boxes = [_visual_box(frame.dot(v.origin), v) for v in link.visuals]
            boxes.append(model.collision_box(name))
            boxes = [b for b in boxes if b is not None]
            if boxes:
                out.append((tuple(min(b[0][i] for b in boxes) for i in range(3)),
                            tuple(max(b[1][i] for b in boxes) for i in range(3))))
    return out


def world_arena(bounds, boxes, radius):
    """The :class:`~.ball_script.Arena` of a world: ``bounds`` (x_min, x_max,
    y_min, y_max of a ball's centre) when finite, else the box the standing
    scenery (``boxes`` higher than :data:`FLAT`) encloses, less the ball's
    radius, when it is :data:`ARENA_SIDES` wide, else the course's arena;
    the standing boxes are its obstacles."""
    standing = [(b[0][0], b[1][0], b[0][1], b[1][1]) for b in boxes
                if b[1][2] > FLAT and all(math.isfinite(v) for v in b[0] + b[1])]
    if all(math.isfinite(v) for v in bounds):
        return ball_script.Arena(*bounds, obstacles=tuple(standing))
    if standing:
        box = (min(b[0] for b in standing) + radius, max(b[1] for b in standing) - radius,
               min(b[2] for b in standing) + radius, max(b[3] for b in standing) - radius)
        sides = (box[1] - box[0], box[3] - box[2])
        if all(ARENA_SIDES[0] <= side <= ARENA_SIDES[1] for side in sides):
            return ball_script.Arena(*box, obstacles=tuple(standing))
    limit = course.GOAL_LIMIT
    return ball_script.Arena(-limit, limit, -limit, limit, obstacles=tuple(standing))


def start(engine, setting):
    """The :class:`ScriptedBall` of ``setting`` (a :class:`~.ball_setting.BallSetting`,
    or its JSON or dict; :class:`~.ball_script.ScriptError` for a bad one) in
    ``engine``, None without one."""
    if setting is not None and not isinstance(setting, ball_setting.BallSetting):
        setting = ball_setting.parse(setting)
    return ScriptedBall(engine, setting) if setting is not None else None


class ScriptedBall(object):
    """Plays a :class:`~.ball_setting.BallSetting` in an engine's world (see
    the module docstring); the engine calls :meth:`spawned`, :meth:`deleted`,
    :meth:`before_physics` and :meth:`place`."""

    def __init__(self, engine, setting):
        self.engine, self.setting = engine, setting
        self.model, self.script, self.start, self.given_up = None, None, None, False
        if setting.legs is not None and all(math.isfinite(b) for b in engine.bounds):
            # places the world cannot hold: refused before anything runs
            ball_script.parse_legs(ball_script.to_json_legs(setting.legs),
                                   ball_script.Arena(*engine.bounds))

    def wants(self, model):
        """Whether ``model``, just spawned, is the ball to hold."""
        if self.model is not None or self.given_up:
            return False
        if self.setting.model is not None:
            return model.name == self.setting.model
        return is_ball(model)

    def spawned(self, model):
        """A model was spawned: the ball's script starts (or goes on) with it."""
        if not self.wants(model):
            return
        if self.script is None:
            try:
                self.script = self._make(model)
            except ball_script.ScriptError as exc:      # a world with no room for it
                self.engine.log.error('simulator: %s; the ball (model %s) is left to the '
                                      'nodes that move it' % (exc, model.name))
                self.given_up = True
                return
            self.start = self.engine.time
            self.engine.log.info('simulator: the ball (model %s) follows the course\'s script '
                                 '(%s) from %.2f s; commands to it are ignored'
                                 % (model.name, ball_script.summary(self.script), self.start))
        self.model = model
        model.hold(self.facts())
        self.place(self.engine.time)

    def _make(self, model):
        radius = sphere(model.urdf)
        radius = radius[0] if radius is not None else course.BALL_RADIUS
        # resting on the floor, wherever the student spawned it
        given = {'duration': self.setting.duration, 'radius': radius, 'ground_z': radius}
        if self.setting.legs is not None:
            return ball_script.from_legs(self.setting.legs, None, given)
        boxes = footprints(m for m in self.engine.models.values() if m is not model)
        arena = world_arena(self.engine.bounds, boxes, radius)
        return ball_script.make_script(self.setting.seed, arena, given)

    def facts(self):
        """What the ground truth's model record says of the script."""
        return {'seed': self.script.seed, 'start': round(self.start, 4),
                'duration': self.script.duration,
                'legs': ball_script.to_json_legs(self.script.legs)}

    def deleted(self, name):
        if self.model is not None and self.model.name == name:
            self.model = None

    def place(self, now):
        """Put the ball where the script has it at simulated time ``now``."""
        if self.model is None:
            return
        where = ball_script.play(self.script, now - self.start)
        self.model.play(where.x, where.y, where.z, where.hidden, (where.vx, where.vy))

    def before_physics(self):
        """Before a physics step (after the plugins applied their commands):
        where the script has the ball when the step ends."""
        self.place((self.engine.steps + 1) * self.engine.time_step)   # its time then
