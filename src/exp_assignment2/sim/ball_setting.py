"""The simulator's ``ball_script`` setting (no ROS): whether it plays a
course for the ball (:mod:`.ball_script`) and which.

The value is a JSON object (or the same as a dict, from a YAML parameter):

* ``{"seed": 3}``: the seeded course of :func:`~.ball_script.make_script`;
  ``"duration": S`` (s, default 200) is the run it is written for;
* ``{"legs": [...]}``: legs given by hand (:func:`~.ball_script.parse_legs`);
* ``"model": "ball"`` with either: the model it moves (default: the first
  sphere spawned with no camera and no drive but planar_move's).

It comes from the simulator's ``~ball_script`` parameter when given, else the
environment's :data:`ENV` (the grader sets it in each run's sandbox, whatever
the student's launch files do), else there is none (:func:`choose`).
"""
import json
import math
from collections import namedtuple

from exp_assignment2.sim import ball_script, node_setting

ENV = 'EXP2_BALL_SCRIPT'
KEYS = ('seed', 'legs', 'model', 'duration')


class BallSetting(namedtuple('BallSetting', 'seed legs model duration')):
    """A checked setting: ``seed`` (int) or ``legs`` (list of
    :class:`~.ball_script.Leg`), ``model`` (None: found by its role) and
    ``duration`` (s)."""

    def to_dict(self):
        """As JSON would say it (the ground truth's hello carries it)."""
        out = {'seed': self.seed} if self.legs is None else {
            'legs': ball_script.to_json_legs(self.legs)}
        if self.model is not None:
            out['model'] = self.model
        out['duration'] = self.duration
        return out

    def describe(self):
        """A few words for a log line."""
        return '%s%s' % ('seed %d, %g s' % (self.seed, self.duration) if self.legs is None
                         else '%d legs given' % len(self.legs),
                         ', model %s' % self.model if self.model else '')


def parse(value):
    """A :class:`BallSetting` from JSON text or a dict; None for None or ''.
    :class:`~.ball_script.ScriptError` (one line) for anything else."""
    if value is None or (isinstance(value, str) and not value.strip()):
        return None
    data = value
    if isinstance(value, str):
        try:
            data = json.loads(value)
        except ValueError as exc:
            raise ball_script.ScriptError('%s is not JSON (%s); expected e.g. {"seed": 3}'
                                          % (_shown(value), exc))
    if not isinstance(data, dict):
        raise ball_script.ScriptError('%s is refused: expected a JSON object such as '
                                      '{"seed": 3} or {"legs": [...]}' % _shown(value))
    unknown = sorted(set(data) - set(KEYS))
    if unknown:
        raise ball_script.ScriptError('%s is refused: unknown key %s (known: %s)' % (
            _shown(value), ', '.join(repr(k) for k in unknown), ', '.join(KEYS)))
    if ('seed' in data) == ('legs' in data):
        raise ball_script.ScriptError('%s is refused: give exactly one of seed or legs'
                                      % _shown(value))
    seed = data.get('seed')
    if 'seed' in data and (not isinstance(seed, int) or isinstance(seed, bool) or seed < 0):
        raise ball_script.ScriptError('%s is refused: the seed must be a whole number >= 0'
                                      % _shown(value))
    model = data.get('model')
    if model is not None and (not isinstance(model, str) or not model.strip()):
        raise ball_script.ScriptError('%s is refused: model must be a model\'s name'
                                      % _shown(value))
    duration = data.get('duration', ball_script.DEFAULT_DURATION)
    if (isinstance(duration, bool) or not isinstance(duration, (int, float))
            or not math.isfinite(duration) or duration <= 0):
        raise ball_script.ScriptError('%s is refused: duration must be a positive number of '
                                      'seconds' % _shown(value))
    legs = ball_script.parse_legs(data['legs']) if 'legs' in data else None
    return BallSetting(seed, legs, model.strip() if model else None, float(duration))


def _shown(value):
    text = value if isinstance(value, str) else json.dumps(value, default=repr)
    return text if len(text) <= 80 else text[:77] + '...'


def choose(parameter=None, environ=None):
    """The setting a simulator plays: its ``~ball_script`` parameter when
    given, else ``environ[ENV]``, else None. A bad one is a
    :class:`~.ball_script.ScriptError` naming where it came from."""
    return node_setting.chosen(parameter, '~ball_script', ENV, parse, environ)
